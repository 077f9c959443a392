//! 2D lines and 2D segments (OPERATIONS.md §6.1, §6.2) against CGAL's Epeck on every
//! generator (collinear, touching, overlapping and parallel ones among them): kinds
//! agree, points are equal rationals, an overlap is Epeck's segment (end points as a
//! set), equal lines are the input line, certified coordinates are the correct rounding.
#![cfg(feature = "cgal")]

mod diff_support;

use diff_support::*;
use geocert::geom::lines2::{
    intersect_line2_line2, intersect_line2_line2_exact, Empty2, Intersection2,
};
use geocert::num::Interval;
use geocert::oracle::{epeck, Intersection};
use geocert::robust::case::{line2, q, same, segment2, Linear2In};
use geocert::robust::{Case, Construction};
use rug::Rational;

fn q2(v: &[f64; 2]) -> Vec<Rational> {
    vec![q(v[0]), q(v[1])]
}

/// CGAL's `Line_2 ∩ Line_2` (Intersections_2/Line_2_Line_2.h) answers "no
/// intersection" when `is_finite` fails on `nom1 = b₁c₂ − b₂c₁`, `nom2 = a₂c₁ − a₁c₂`
/// or on `nom1/den`, `nom2/den` (`den = a₁b₂ − a₂b₁`), with each line built as
/// `a = −d_y`, `b = d_x`, `c = p_x d_y − p_y d_x`. Epeck's lazy kernel runs this code
/// first on interval approximations and keeps the interval run's answer unless a
/// comparison was uncertain: when an interval overflows (huge inputs) or a quotient's
/// interval is unbounded because `den` is tiny beside the width of `nom` (e.g. the
/// direction `(−7.875, −5e-324)`, a one-ulp perturbation of a horizontal one), Epeck
/// says "empty" for crossing lines. This re-runs that interval computation with
/// geocert's outward-rounded intervals and is true when it would take that exit (or
/// come within a factor 2⁻²⁴ of the double range, to allow for CGAL's own rounding).
fn cgal_interval_exit(a: &Linear2In, b: &Linear2In) -> bool {
    let (
        Linear2In::Line {
            origin: p1,
            dir: d1,
        },
        Linear2In::Line {
            origin: p2,
            dir: d2,
        },
    ) = (a, b)
    else {
        return false;
    };
    let i = Interval::point;
    let coeffs = |p: &[f64; 2], d: &[f64; 2]| {
        let c = i(p[0]).mul(&i(d[1])).sub(&i(p[1]).mul(&i(d[0])));
        (i(-d[1]), i(d[0]), c)
    };
    let (a1, b1, c1) = coeffs(p1, d1);
    let (a2, b2, c2) = coeffs(p2, d2);
    let den = a1.mul(&b2).sub(&a2.mul(&b1));
    if den.lo() <= 0.0 && den.hi() >= 0.0 {
        return false; // uncertain: CGAL recomputes exactly
    }
    let nom1 = b1.mul(&c2).sub(&b2.mul(&c1));
    let nom2 = a2.mul(&c1).sub(&a1.mul(&c2));
    let limit = f64::MAX / 2f64.powi(24);
    [nom1, nom2, nom1.div(&den), nom2.div(&den)]
        .iter()
        .any(|x| !(x.lo().abs() < limit && x.hi().abs() < limit))
}

/// Whether `x` lies on the line `o + t d` (exactly).
fn on_line2(x: &[Rational], l: &Linear2In) -> bool {
    let Linear2In::Line { origin, dir } = l else {
        return false;
    };
    is_zero(&cross(&sub(x, &q2(origin)), &q2(dir)))
}

fn check(c: &Case) -> Result<(), String> {
    let Case::Linear2(a, b) = c else {
        return Err("not a 2D case".into());
    };
    let (af, ae) = (a.object(same).expect("valid"), a.object(q).expect("valid"));
    let (bf, be) = (b.object(same).expect("valid"), b.object(q).expect("valid"));
    let exact = intersect_line2_line2_exact(ae.linear(), be.linear());
    let cert = intersect_line2_line2(af.linear(), bf.linear());
    certified_exact(&cert)?;
    let truth = match (a, b) {
        (
            Linear2In::Line {
                origin: o1,
                dir: d1,
            },
            Linear2In::Line {
                origin: o2,
                dir: d2,
            },
        ) => epeck::intersect_line2_line2(&line2(*o1, *d1), &line2(*o2, *d2)),
        (Linear2In::Segment { a: a1, b: b1 }, Linear2In::Segment { a: a2, b: b2 }) => {
            epeck::intersect_segment2_segment2(&segment2(*a1, *b1), &segment2(*a2, *b2))
        }
        _ => return Err("mixed line and segment".into()),
    }
    .map_err(|e| format!("Epeck refused: {e}"))?;
    match (&exact, &truth, &cert.value) {
        (
            Intersection2::Point { point, .. },
            Intersection::Point(p),
            Intersection2::Point { point: rp, .. },
        ) => {
            ensure!(
                point.as_slice() == p.as_slice(),
                "point {point:?} but Epeck {p:?}"
            );
            ensure!(rounds_all(p.iter(), rp.iter()), "certified {rp:?} vs {p:?}");
        }
        (
            Intersection2::Segment { a: xa, b: xb, .. },
            Intersection::Segment { source, target },
            Intersection2::Segment { a: ra, b: rb, .. },
        ) => {
            let (xa, xb) = (xa.as_slice(), xb.as_slice());
            let same_ends = (xa == source.as_slice() && xb == target.as_slice())
                || (xa == target.as_slice() && xb == source.as_slice());
            ensure!(
                same_ends,
                "overlap {xa:?}-{xb:?} but Epeck {source:?}-{target:?}"
            );
            ensure!(
                rounds_all(xa.iter().chain(xb), ra.iter().chain(rb.iter())),
                "certified overlap {ra:?}-{rb:?}"
            );
        }
        // CGAL's interval exit (see `cgal_interval_exit`): geocert's point is checked
        // on both lines exactly instead, and the lines must cross.
        (
            Intersection2::Point { point, .. },
            Intersection::Empty,
            Intersection2::Point { point: rp, .. },
        ) if cgal_interval_exit(a, b) => {
            let (Linear2In::Line { dir: d1, .. }, Linear2In::Line { dir: d2, .. }) = (a, b) else {
                return Err("segments in the line-overflow exit".into());
            };
            let p = point.as_slice();
            ensure!(
                on_line2(p, a) && on_line2(p, b),
                "geocert's point {p:?} is off a line"
            );
            ensure!(
                !is_zero(&cross(&q2(d1), &q2(d2))),
                "parallel lines with a point"
            );
            ensure!(rounds_all(p.iter(), rp.iter()), "certified {rp:?} vs {p:?}");
        }
        (Intersection2::Line, Intersection::Line { point, direction }, Intersection2::Line) => {
            let Linear2In::Line { origin, dir } = a else {
                return Err("segments answered as a line".into());
            };
            ensure!(
                same_line(&q2(origin), &q2(dir), point, direction),
                "Epeck's line is not the input"
            );
        }
        (Intersection2::Empty(e), Intersection::Empty, Intersection2::Empty(r)) => {
            let same_reason = matches!(
                (e, r),
                (Empty2::Parallel, Empty2::Parallel)
                    | (Empty2::CollinearDisjoint, Empty2::CollinearDisjoint)
                    | (Empty2::OutsideDomain { .. }, Empty2::OutsideDomain { .. })
            );
            ensure!(
                same_reason,
                "empty for different reasons: {e:?} vs certified {r:?}"
            );
        }
        _ => {
            return Err(format!(
                "kinds differ: geocert exact {exact:?}, certified {:?}, Epeck {} ({truth:?})",
                cert.value,
                kind(&truth)
            ))
        }
    }
    Ok(())
}

#[test]
fn lines_2d_agree_with_epeck() {
    run(Construction::Lines2, check);
}

#[test]
fn segments_2d_agree_with_epeck() {
    run(Construction::Segments2, check);
}

/// The interval exit on a small case: a one-ulp perturbation of a horizontal
/// direction. The lines cross at (2, −13/8) (on both, exactly; directions not
/// parallel), geocert says so, and Epeck answers "empty".
#[test]
fn epeck_misses_a_crossing_when_its_interval_quotient_is_unbounded() {
    let a = Linear2In::Line {
        origin: [2.0, -1.625],
        dir: [-7.875, -5e-324],
    };
    let b = Linear2In::Line {
        origin: [10.859375, -1.625],
        dir: [-31.5, 0.0],
    };
    let crossing = vec![Rational::from(2), Rational::from((-13, 8))];
    assert!(on_line2(&crossing, &a) && on_line2(&crossing, &b));
    assert!(cgal_interval_exit(&a, &b));
    let epeck = epeck::intersect_line2_line2(
        &line2([2.0, -1.625], [-7.875, -5e-324]),
        &line2([10.859375, -1.625], [-31.5, 0.0]),
    );
    assert_eq!(epeck, Ok(Intersection::Empty));
    let (af, bf) = (a.object(same).unwrap(), b.object(same).unwrap());
    let cert = intersect_line2_line2(af.linear(), bf.linear());
    match cert.value {
        Intersection2::Point { point, .. } => {
            assert_eq!([point[0].nearest, point[1].nearest], [2.0, -1.625]);
            assert!(point.iter().all(|r| r.is_exact()));
        }
        other => panic!("{other:?}"),
    }
    // A less extreme perturbation keeps Epeck right: the exit needs the tiny one.
    let a2 = Linear2In::Line {
        origin: [2.0, -1.625],
        dir: [-7.875, -1e-300],
    };
    assert!(!cgal_interval_exit(&a2, &b));
}
