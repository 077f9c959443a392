//! geocert beside CGAL in one criterion run (feature `cgal`): three planes, line–plane
//! and plane–plane, on generic and on exactly degenerate input (the seeded generators
//! of `geocert::robust`), timed as plain f64 (`_f64`), geocert certified, geocert exact
//! rationals (`_exact`, inputs already rational), CGAL Epick, CGAL Epeck with
//! `to_double` (lazy approximation) and CGAL Epeck with `to_double(exact(x))`; and
//! geocert certified through the batch entry points (`*_batch`, four or eight cases
//! at a time in AVX or AVX-512 lanes, shapes pooled as `geom::batch` describes).
//! Each iteration runs a batch of 64 cases; the tier deciding each case (filter on
//! generic, integers on degenerate input) is checked before timing. BENCHMARKS.md has
//! the ratios.

use criterion::{black_box, criterion_group, criterion_main, Criterion};
use geocert::geom::line_plane::{
    intersect_line_plane, intersect_line_plane_batch, intersect_line_plane_exact,
    intersect_line_plane_f64, LinePlaneCase,
};
use geocert::geom::plane_plane::{
    intersect_plane_plane, intersect_plane_plane_batch, intersect_plane_plane_exact,
    intersect_plane_plane_f64, PlanePlaneCase,
};
use geocert::geom::three_planes::{
    intersect_three_planes, intersect_three_planes_batch, intersect_three_planes_exact,
    intersect_three_planes_f64,
};
use geocert::geom::Plane;
use geocert::oracle::{epeck_f64, epick, EpeckToDouble, LineInput, PlaneInput, SegmentInput};
use geocert::robust::case::{q, same, LinearIn, LinearObj};
use geocert::robust::methods::epick_safe;
use geocert::robust::{case, Case, Construction, Generator};
use rug::Rational;
use std::time::Duration;

const BATCH: usize = 64;

/// 64 cases of a construction and generator, inside Epick's safe window (so the
/// scaled degenerate cases, which Epick cannot be asked, are left out for everyone).
fn cases(c: Construction, g: Generator) -> Vec<Case> {
    (0u64..)
        .map(|s| case(c, g, s * 7 + 3))
        .filter(epick_safe)
        .take(BATCH)
        .collect()
}

type Methods<'a> = Vec<(&'static str, Box<dyn Fn() + 'a>)>;

/// The tier that decides a case on geocert's certified path.
fn tier(c: &Case) -> geocert::Arithmetic {
    match c {
        Case::ThreePlanes(p) => {
            intersect_three_planes(&p.map(|x| x.object(same).unwrap())).arithmetic
        }
        Case::LinePlane(l, p) => {
            let (l, p) = (l.object(same).unwrap(), p.object(same).unwrap());
            intersect_line_plane(l.linear(), &p).arithmetic
        }
        Case::PlanePlane(a, b) => {
            intersect_plane_plane(&a.object(same).unwrap(), &b.object(same).unwrap()).arithmetic
        }
        _ => unreachable!(),
    }
}

fn three_planes(data: &[Case]) -> Methods<'_> {
    let p: Vec<[geocert::robust::case::PlaneIn; 3]> = data
        .iter()
        .map(|c| match c {
            Case::ThreePlanes(p) => *p,
            _ => unreachable!(),
        })
        .collect();
    let f: Vec<[Plane<f64>; 3]> = p
        .iter()
        .map(|p| p.map(|x| x.object(same).unwrap()))
        .collect();
    let e: Vec<[Plane<Rational>; 3]> = p.iter().map(|p| p.map(|x| x.object(q).unwrap())).collect();
    let o: Vec<[PlaneInput; 3]> = p.iter().map(|p| p.map(|x| x.oracle())).collect();
    let mode = |m| {
        let o = o.clone();
        Box::new(move || {
            for [a, b, c] in &o {
                black_box(epeck_f64::intersect_three_planes(m, a, b, c).ok());
            }
        }) as Box<dyn Fn()>
    };
    vec![
        (
            "f64",
            Box::new({
                let f = f.clone();
                move || {
                    for x in &f {
                        black_box(intersect_three_planes_f64(x));
                    }
                }
            }),
        ),
        (
            "certified",
            Box::new({
                let f = f.clone();
                move || {
                    for x in &f {
                        black_box(intersect_three_planes(x));
                    }
                }
            }),
        ),
        (
            "certified_batch",
            Box::new({
                let f = f.clone();
                let out = std::cell::RefCell::new(Vec::with_capacity(BATCH));
                move || {
                    let mut out = out.borrow_mut();
                    out.clear();
                    intersect_three_planes_batch(black_box(&f), &mut out);
                    black_box(&*out);
                }
            }),
        ),
        (
            "exact",
            Box::new(move || {
                for x in &e {
                    black_box(intersect_three_planes_exact(x));
                }
            }),
        ),
        (
            "epick",
            Box::new({
                let o = o.clone();
                move || {
                    for [a, b, c] in &o {
                        black_box(epick::intersect_three_planes(a, b, c).ok());
                    }
                }
            }),
        ),
        ("epeck_to_double", mode(EpeckToDouble::Approx)),
        ("epeck_exact", mode(EpeckToDouble::Exact)),
    ]
}

enum OracleLinear {
    Line(LineInput),
    Segment(SegmentInput),
}

fn line_plane(data: &[Case]) -> Methods<'_> {
    let lp: Vec<(LinearIn, geocert::robust::case::PlaneIn)> = data
        .iter()
        .map(|c| match c {
            Case::LinePlane(l, p) => (*l, *p),
            _ => unreachable!(),
        })
        .collect();
    let f: Vec<(LinearObj<f64>, Plane<f64>)> = lp
        .iter()
        .map(|(l, p)| (l.object(same).unwrap(), p.object(same).unwrap()))
        .collect();
    let e: Vec<(LinearObj<Rational>, Plane<Rational>)> = lp
        .iter()
        .map(|(l, p)| (l.object(q).unwrap(), p.object(q).unwrap()))
        .collect();
    let o: std::rc::Rc<Vec<(OracleLinear, PlaneInput)>> = std::rc::Rc::new(
        lp.iter()
            .map(|(l, p)| {
                let l = match *l {
                    LinearIn::Line { origin, dir } => OracleLinear::Line(LineInput {
                        point: origin,
                        direction: dir,
                    }),
                    LinearIn::Segment { a, b } => OracleLinear::Segment(SegmentInput {
                        source: a,
                        target: b,
                    }),
                };
                (l, p.oracle())
            })
            .collect(),
    );
    let f = std::rc::Rc::new(f);
    let mode = |m| {
        let o = o.clone();
        Box::new(move || {
            for (l, p) in o.iter() {
                black_box(match l {
                    OracleLinear::Line(l) => epeck_f64::intersect_line_plane(m, l, p).ok(),
                    OracleLinear::Segment(s) => epeck_f64::intersect_segment_plane(m, s, p).ok(),
                });
            }
        }) as Box<dyn Fn()>
    };
    vec![
        (
            "f64",
            Box::new({
                let f = f.clone();
                move || {
                    for (l, p) in f.iter() {
                        black_box(intersect_line_plane_f64(l.linear(), p));
                    }
                }
            }),
        ),
        (
            "certified",
            Box::new({
                let f = f.clone();
                move || {
                    for (l, p) in f.iter() {
                        black_box(intersect_line_plane(l.linear(), p));
                    }
                }
            }),
        ),
        (
            "certified_batch",
            Box::new({
                // (the cases borrow the objects: leaked, once per bench, to build them once)
                let f: &'static Vec<(LinearObj<f64>, Plane<f64>)> =
                    Box::leak(Box::new((*f).clone()));
                let cases: Vec<LinePlaneCase> = f.iter().map(|(l, p)| (l.linear(), p)).collect();
                let out = std::cell::RefCell::new(Vec::with_capacity(BATCH));
                move || {
                    let mut out = out.borrow_mut();
                    out.clear();
                    intersect_line_plane_batch(black_box(&cases), &mut out);
                    black_box(&*out);
                }
            }),
        ),
        (
            "exact",
            Box::new(move || {
                for (l, p) in &e {
                    black_box(intersect_line_plane_exact(l.linear(), p));
                }
            }),
        ),
        (
            "epick",
            Box::new({
                let o = o.clone();
                move || {
                    for (l, p) in o.iter() {
                        black_box(match l {
                            OracleLinear::Line(l) => epick::intersect_line_plane(l, p).ok(),
                            OracleLinear::Segment(s) => epick::intersect_segment_plane(s, p).ok(),
                        });
                    }
                }
            }),
        ),
        ("epeck_to_double", mode(EpeckToDouble::Approx)),
        ("epeck_exact", mode(EpeckToDouble::Exact)),
    ]
}

fn plane_plane(data: &[Case]) -> Methods<'_> {
    let pp: Vec<[geocert::robust::case::PlaneIn; 2]> = data
        .iter()
        .map(|c| match c {
            Case::PlanePlane(a, b) => [*a, *b],
            _ => unreachable!(),
        })
        .collect();
    let f: std::rc::Rc<Vec<[Plane<f64>; 2]>> = std::rc::Rc::new(
        pp.iter()
            .map(|p| p.map(|x| x.object(same).unwrap()))
            .collect(),
    );
    let e: Vec<[Plane<Rational>; 2]> = pp.iter().map(|p| p.map(|x| x.object(q).unwrap())).collect();
    let o: std::rc::Rc<Vec<[PlaneInput; 2]>> =
        std::rc::Rc::new(pp.iter().map(|p| p.map(|x| x.oracle())).collect());
    let mode = |m| {
        let o = o.clone();
        Box::new(move || {
            for [a, b] in o.iter() {
                black_box(epeck_f64::intersect_plane_plane(m, a, b).ok());
            }
        }) as Box<dyn Fn()>
    };
    vec![
        (
            "f64",
            Box::new({
                let f = f.clone();
                move || {
                    for [a, b] in f.iter() {
                        black_box(intersect_plane_plane_f64(a, b));
                    }
                }
            }),
        ),
        (
            "certified",
            Box::new({
                let f = f.clone();
                move || {
                    for [a, b] in f.iter() {
                        black_box(intersect_plane_plane(a, b));
                    }
                }
            }),
        ),
        (
            "certified_batch",
            Box::new({
                let f: &'static Vec<[Plane<f64>; 2]> = Box::leak(Box::new((*f).clone()));
                let cases: Vec<PlanePlaneCase> = f.iter().map(|[a, b]| (a, b)).collect();
                let out = std::cell::RefCell::new(Vec::with_capacity(BATCH));
                move || {
                    let mut out = out.borrow_mut();
                    out.clear();
                    intersect_plane_plane_batch(black_box(&cases), &mut out);
                    black_box(&*out);
                }
            }),
        ),
        (
            "exact",
            Box::new(move || {
                for [a, b] in &e {
                    black_box(intersect_plane_plane_exact(a, b));
                }
            }),
        ),
        (
            "epick",
            Box::new({
                let o = o.clone();
                move || {
                    for [a, b] in o.iter() {
                        black_box(epick::intersect_plane_plane(a, b).ok());
                    }
                }
            }),
        ),
        ("epeck_to_double", mode(EpeckToDouble::Approx)),
        ("epeck_exact", mode(EpeckToDouble::Exact)),
    ]
}

fn compare(c: &mut Criterion) {
    for (name, construction, methods) in [
        (
            "three_planes",
            Construction::ThreePlanes,
            three_planes as fn(&[Case]) -> Methods<'_>,
        ),
        ("line_plane", Construction::LinePlane, line_plane),
        ("plane_plane", Construction::PlanePlane, plane_plane),
    ] {
        for (input, generator) in [
            ("generic", Generator::Generic),
            ("degenerate", Generator::Degenerate),
        ] {
            let data = cases(construction, generator);
            // The batch is decided where it claims: generic input by the filter, exactly
            // degenerate input by the integer tier.
            let expected = match generator {
                Generator::Generic => geocert::Arithmetic::Filter,
                _ => geocert::Arithmetic::Integer,
            };
            for case in &data {
                assert_eq!(tier(case), expected, "{name}/{input}");
            }
            let mut g = c.benchmark_group(format!("{name}/{input}"));
            for (method, run) in methods(&data) {
                g.bench_function(method, |b| b.iter(&run));
            }
            g.finish();
        }
    }
}

criterion_group! {
    name = benches;
    config = Criterion::default()
        .warm_up_time(Duration::from_millis(700))
        .measurement_time(Duration::from_secs(2))
        .sample_size(20);
    targets = compare
}
criterion_main!(benches);
