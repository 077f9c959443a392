//! Line ∩ line in space — lines, rays, ranged lines and segments in every pairing —
//! against CGAL's Epeck (`intersection` of `Line_3`/`Ray_3`/`Segment_3`) on every
//! family of `geocert::robust::line_line` (generic, crossing, parallel, collinear,
//! one ulp off, magnitudes 1e±150): kinds agree; points, overlap ends and ray sources
//! are equal rationals; every parameter puts its point on its object exactly (checked
//! here in rationals, not by geocert); empty answers say why, and the reason is
//! checked; the certified answer is the exact one correctly rounded, number by number.
//! `GEOCERT_DIFF_CASES` sets the number of cases (default 100,000).
#![cfg(feature = "cgal")]

mod diff_support;

use diff_support::*;
use geocert::geom::line_line::{
    intersect_line_line, intersect_line_line_exact, LineLine, LineLineEmpty, LineLinePoint,
};
use geocert::num::round::round_rational;
use geocert::oracle::{epeck, Intersection};
use geocert::robust::case::{q, same};
use geocert::robust::line_line::{case, Family, LineLineCase, Shape};
use rug::Rational;

/// The carrier `o + t·d` of a shape and its domain ends, in rationals.
struct Exact {
    o: Q3,
    d: Q3,
    lo: Option<Rational>,
    hi: Option<Rational>,
}

fn exact(s: &Shape) -> Exact {
    match s {
        Shape::Line { origin, dir, range } => Exact {
            o: q3(origin),
            d: q3(dir),
            lo: range[0].map(q),
            hi: range[1].map(q),
        },
        Shape::Segment { a, b } => {
            let (a, b) = (q3(a), q3(b));
            let d = sub(&b, &a);
            Exact {
                o: a,
                d: [d[0].clone(), d[1].clone(), d[2].clone()],
                lo: Some(Rational::from(0)),
                hi: Some(Rational::from(1)),
            }
        }
    }
}

impl Exact {
    fn at(&self, t: &Rational) -> Vec<Rational> {
        (0..3)
            .map(|i| self.o[i].clone() + Rational::from(t * &self.d[i]))
            .collect()
    }
    fn contains(&self, t: &Rational) -> bool {
        self.lo.as_ref().is_none_or(|lo| t >= lo) && self.hi.as_ref().is_none_or(|hi| t <= hi)
    }
    fn one_sided(&self) -> bool {
        self.lo.is_some() != self.hi.is_some()
    }
}

/// `x` is the point of both objects at the parameters `(t1, t2)`.
fn on_both(x: &[Rational], t1: &Rational, t2: &Rational, a: &Exact, b: &Exact) -> bool {
    a.at(t1) == x && b.at(t2) == x
}

/// The parameters of a point or overlap end put it on both objects, inside both domains.
fn check_point(p: &LineLinePoint<Rational>, a: &Exact, b: &Exact) -> Result<(), String> {
    ensure!(
        on_both(p.point.as_slice(), &p.t1, &p.t2, a, b),
        "({}, {}) misses the point {:?}",
        p.t1,
        p.t2,
        p.point
    );
    ensure!(
        a.contains(&p.t1) && b.contains(&p.t2),
        "a parameter is outside a domain"
    );
    Ok(())
}

fn check(c: &LineLineCase) -> Result<(), String> {
    let (af, ae) = (
        c.a.object(same).expect("valid"),
        c.a.object(q).expect("valid"),
    );
    let (bf, be) = (
        c.b.object(same).expect("valid"),
        c.b.object(q).expect("valid"),
    );
    let x = intersect_line_line_exact(ae.linear(), be.linear());
    let cert = intersect_line_line(af.linear(), bf.linear());
    certified_exact(&cert)?;
    ensure!(
        x.clone().map(|v| round_rational(&v)) == cert.value,
        "certified {:?} is not the exact {x:?} rounded",
        cert.value
    );
    let truth = epeck::intersect_line_line(&c.a.oracle(), &c.b.oracle())
        .map_err(|e| format!("Epeck refused: {e}"))?;
    let (a, b) = (exact(&c.a), exact(&c.b));
    let n = cross(&a.d, &b.d);
    let w = sub(&b.o, &a.o);
    match (&x, &truth) {
        (LineLine::Point(p), Intersection::Point(pt)) => {
            ensure!(
                p.point.as_slice() == pt.as_slice(),
                "point {:?} but Epeck {pt:?}",
                p.point
            );
            check_point(p, &a, &b)?;
        }
        (
            LineLine::Segment {
                a: xa,
                b: xb,
                a_params,
                b_params,
            },
            Intersection::Segment { source, target },
        ) => {
            let (xa, xb) = (xa.as_slice(), xb.as_slice());
            let same_ends = (xa == source.as_slice() && xb == target.as_slice())
                || (xa == target.as_slice() && xb == source.as_slice());
            ensure!(
                same_ends,
                "overlap {xa:?}-{xb:?} but Epeck {source:?}-{target:?}"
            );
            ensure!(
                a_params[0] < b_params[0],
                "the overlap's ends are not ordered by t1"
            );
            for (e, t) in [(xa, a_params), (xb, b_params)] {
                ensure!(
                    on_both(e, &t[0], &t[1], &a, &b),
                    "an overlap end misses its params"
                );
                ensure!(
                    a.contains(&t[0]) && b.contains(&t[1]),
                    "an overlap end outside"
                );
            }
        }
        (
            LineLine::Ray {
                a: start,
                a_params: t,
                increasing,
            },
            Intersection::Ray { source, direction },
        ) => {
            ensure!(
                start.as_slice() == source.as_slice(),
                "ray from {start:?} but Epeck {source:?}"
            );
            ensure!(
                on_both(start.as_slice(), &t[0], &t[1], &a, &b),
                "the ray's start misses its params"
            );
            ensure!(
                is_zero(&cross(direction, &a.d)),
                "Epeck's ray is not along the objects"
            );
            let along = dot(direction, &a.d).cmp0().is_gt();
            ensure!(
                along == increasing[0],
                "the ray runs the other way on the first object"
            );
            let along2 = dot(direction, &b.d).cmp0().is_gt();
            ensure!(
                along2 == increasing[1],
                "the ray runs the other way on the second object"
            );
        }
        // CGAL 5.5's Ray_3 ∩ Ray_3 answers the common source when each ray holds the
        // other's source, which is also the case for equal sources pointing the same
        // way: then the overlap is the whole ray. Checked here instead: both are rays
        // from that point, along the same direction.
        (
            LineLine::Ray {
                a: start,
                a_params: t,
                increasing,
            },
            Intersection::Point(pt),
        ) if a.one_sided() && b.one_sided() => {
            ensure!(
                start.as_slice() == pt.as_slice(),
                "ray from {start:?} but Epeck {pt:?}"
            );
            ensure!(
                on_both(start.as_slice(), &t[0], &t[1], &a, &b),
                "the ray's start misses its params"
            );
            let start_of = |e: &Exact, t: &Rational| match (&e.lo, &e.hi) {
                (Some(lo), None) => lo == t,
                (None, Some(hi)) => hi == t,
                _ => false,
            };
            ensure!(
                start_of(&a, &t[0]) && start_of(&b, &t[1]),
                "not the rays' common source"
            );
            let fwd = |e: &Exact| e.lo.is_some();
            ensure!(
                increasing[0] == fwd(&a) && increasing[1] == fwd(&b),
                "rays apart"
            );
        }
        (LineLine::Line, Intersection::Line { point, direction }) => {
            ensure!(
                same_line(&a.o, &a.d, point, direction),
                "Epeck's line is not the input"
            );
            ensure!(
                a.lo.is_none() && a.hi.is_none() && b.lo.is_none() && b.hi.is_none(),
                "bounded"
            );
        }
        (LineLine::Empty(why), Intersection::Empty) => match why {
            LineLineEmpty::Skew => ensure!(dot(&w, &n).cmp0().is_ne(), "coplanar, said skew"),
            LineLineEmpty::Parallel => ensure!(
                is_zero(&n) && !is_zero(&cross(&w, &a.d)),
                "not parallel and distinct"
            ),
            LineLineEmpty::CollinearDisjoint => {
                ensure!(is_zero(&n) && is_zero(&cross(&w, &a.d)), "not collinear")
            }
            LineLineEmpty::OutsideDomain(p) => {
                ensure!(
                    !is_zero(&n) && dot(&w, &n).cmp0().is_eq(),
                    "not crossing carriers"
                );
                ensure!(
                    on_both(p.point.as_slice(), &p.t1, &p.t2, &a, &b),
                    "carrier point off"
                );
                ensure!(
                    !(a.contains(&p.t1) && b.contains(&p.t2)),
                    "inside both domains"
                );
            }
        },
        _ => {
            return Err(format!(
                "kinds differ: geocert exact {x:?}, certified {:?}, Epeck {} ({truth:?})",
                cert.value,
                kind(&truth)
            ))
        }
    }
    Ok(())
}

#[test]
fn line_line_agrees_with_epeck() {
    run_seeded(
        &Family::ALL,
        |f, seed| format!("line-line/{}/{seed}", f.name()),
        case,
        |c, id| c.json_line(id),
        check,
    );
}

/// Every outcome kind is reached by the families (the comparison above is not vacuous
/// for any of them), with the exact answer's kinds and reasons counted over 3000 seeds
/// per family.
#[test]
fn families_reach_every_outcome() {
    let mut seen = std::collections::BTreeMap::new();
    for family in Family::ALL {
        for seed in 0..3000 {
            let c = case(family, seed);
            let (a, b) = (c.a.object(q).unwrap(), c.b.object(q).unwrap());
            let name = match intersect_line_line_exact(a.linear(), b.linear()) {
                LineLine::Empty(LineLineEmpty::Skew) => "skew",
                LineLine::Empty(LineLineEmpty::Parallel) => "parallel",
                LineLine::Empty(LineLineEmpty::CollinearDisjoint) => "collinear disjoint",
                LineLine::Empty(LineLineEmpty::OutsideDomain(_)) => "outside domain",
                other => other.kind(),
            };
            *seen.entry(name).or_insert(0u32) += 1;
        }
    }
    println!("{seen:?}");
    for kind in [
        "point",
        "segment",
        "ray",
        "line",
        "skew",
        "parallel",
        "collinear disjoint",
        "outside domain",
    ] {
        assert!(
            seen.get(kind).copied().unwrap_or(0) >= 50,
            "{kind}: {seen:?}"
        );
    }
}
