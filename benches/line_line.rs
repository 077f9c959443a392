//! Line ∩ line in space beside CGAL in one criterion run (feature `cgal`): lines, rays,
//! ranged lines and segments mixed, from the seeded families of
//! `geocert::robust::line_line` — generic (skew), crossing (coplanar, 24-bit data),
//! parallel, collinear — and segments sharing a vertex (53-bit data, as in a mesh),
//! timed as plain f64 (`_f64`), geocert certified, geocert
//! exact rationals (`_exact`, inputs already rational), CGAL Epick, CGAL Epeck with
//! `to_double` (lazy approximation) and with `to_double(exact(x))`. Each iteration runs
//! a batch of 64 cases; the deciding tiers of the certified path are printed per family
//! before timing.

use criterion::{black_box, criterion_group, criterion_main, Criterion};
use geocert::geom::line_line::{
    intersect_line_line, intersect_line_line_exact, intersect_line_line_f64,
};
use geocert::oracle::{epeck_f64, epick, EpeckToDouble, Linear3Input};
use geocert::robust::case::{q, same, LinearObj};
use geocert::robust::line_line::{case, Family, LineLineCase, Shape};
use geocert::robust::rng::Rng;
use rug::Rational;
use std::rc::Rc;
use std::time::Duration;

const BATCH: u64 = 64;

type Methods = Vec<(&'static str, Box<dyn Fn()>)>;

fn methods(data: &[LineLineCase]) -> Methods {
    let f: Rc<Vec<[LinearObj<f64>; 2]>> = Rc::new(
        data.iter()
            .map(|c| [c.a.object(same).unwrap(), c.b.object(same).unwrap()])
            .collect(),
    );
    let e: Vec<[LinearObj<Rational>; 2]> = data
        .iter()
        .map(|c| [c.a.object(q).unwrap(), c.b.object(q).unwrap()])
        .collect();
    let o: Rc<Vec<[Linear3Input; 2]>> =
        Rc::new(data.iter().map(|c| [c.a.oracle(), c.b.oracle()]).collect());
    let mode = |m| {
        let o = o.clone();
        Box::new(move || {
            for [a, b] in o.iter() {
                black_box(epeck_f64::intersect_line_line(m, a, b).ok());
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
                        black_box(intersect_line_line_f64(a.linear(), b.linear()));
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
                        black_box(intersect_line_line(a.linear(), b.linear()));
                    }
                }
            }),
        ),
        (
            "exact",
            Box::new(move || {
                for [a, b] in &e {
                    black_box(intersect_line_line_exact(a.linear(), b.linear()));
                }
            }),
        ),
        (
            "epick",
            Box::new({
                let o = o.clone();
                move || {
                    for [a, b] in o.iter() {
                        black_box(epick::intersect_line_line(a, b).ok());
                    }
                }
            }),
        ),
        ("epeck_to_double", mode(EpeckToDouble::Approx)),
        ("epeck_exact", mode(EpeckToDouble::Exact)),
    ]
}

/// Pairs of segments with a common end point, generic doubles, in both orientations.
fn shared_vertex() -> Vec<LineLineCase> {
    let mut rng = Rng::new(17);
    (0..BATCH)
        .map(|i| {
            let mut v = || [rng.generic(), rng.generic(), rng.generic()];
            let (p, a, b) = (v(), v(), v());
            let (a, b) = (Shape::Segment { a: p, b: a }, Shape::Segment { a: b, b: p });
            if i % 2 == 0 {
                LineLineCase { a, b }
            } else {
                LineLineCase { a: b, b: a }
            }
        })
        .collect()
}

fn compare(c: &mut Criterion) {
    let families = [
        Family::Generic,
        Family::Crossing,
        Family::Parallel,
        Family::Collinear,
    ];
    let sets = families
        .iter()
        .map(|&f| (f.name(), (0..BATCH).map(|s| case(f, s * 7 + 3)).collect()))
        .chain([("shared vertex", shared_vertex())]);
    for (name, data) in sets {
        let data: Vec<LineLineCase> = data;
        let mut tiers = std::collections::BTreeMap::new();
        for c in &data {
            let (a, b) = (c.a.object(same).unwrap(), c.b.object(same).unwrap());
            let r = intersect_line_line(a.linear(), b.linear());
            *tiers.entry(r.arithmetic.as_str()).or_insert(0) += 1;
        }
        println!("line_line/{name}: certified tiers {tiers:?}");
        let mut g = c.benchmark_group(format!("line_line/{name}"));
        for (method, run) in methods(&data) {
            g.bench_function(method, |b| b.iter(&run));
        }
        g.finish();
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
