//! OPERATIONS.md §16 worked examples of the linear kernel, asserted exactly: rationals
//! compared exactly, rounded values against the correctly rounded truth computed here
//! independently (rug::Float at 300 bits, then rounded once to a double).

use geocert::geom::line_plane::{intersect_line_plane, intersect_line_plane_exact, LinePlane};
use geocert::geom::lines2::{
    intersect_line2_line2, intersect_line2_line2_exact, Empty2, Intersection2,
};
use geocert::geom::plane_plane::{intersect_plane_plane, intersect_plane_plane_exact, PlanePlane};
use geocert::geom::project::{project_point_plane, project_point_plane_exact};
use geocert::geom::three_planes::{
    intersect_three_planes, intersect_three_planes_exact, ThreePlanes,
};
use geocert::geom::{Line, Linear, Linear2, Plane, Segment2};
use geocert::num::Rounded;
use geocert::{Arithmetic, Status};
use nalgebra::{Vector2, Vector3};
use rug::{Float, Rational};

fn v3(x: f64, y: f64, z: f64) -> Vector3<f64> {
    Vector3::new(x, y, z)
}
fn q3(x: i64, y: i64, z: i64) -> Vector3<Rational> {
    Vector3::new(Rational::from(x), Rational::from(y), Rational::from(z))
}
fn q(n: i64, d: i64) -> Rational {
    Rational::from((n, d))
}
fn exact(x: f64) -> Rounded {
    Rounded::exact(x)
}

/// Independent truth: √(n/d) (negated if `neg`) at 300 bits, rounded once to nearest.
fn sqrt_truth(n: u32, d: u32, neg: bool) -> f64 {
    let x = Float::with_val(300, n) / Float::with_val(300, d);
    let r = x.sqrt().to_f64();
    if neg {
        -r
    } else {
        r
    }
}

fn plane(o: [f64; 3], u: [f64; 3], v: [f64; 3]) -> Plane<f64> {
    Plane::parametric(o.into(), u.into(), v.into()).unwrap()
}
fn qplane(o: [i64; 3], u: [i64; 3], v: [i64; 3]) -> Plane<Rational> {
    Plane::parametric(
        q3(o[0], o[1], o[2]),
        q3(u[0], u[1], u[2]),
        q3(v[0], v[1], v[2]),
    )
    .unwrap()
}

/// §16.2: projection onto a skew plane.
#[test]
fn s16_2_projection_onto_a_skew_plane() {
    let pl = plane([1.0, 2.0, 3.0], [2.0, 0.0, 1.0], [1.0, 1.0, 0.0]);
    let c = project_point_plane(&v3(4.0, -1.0, 5.0), &pl);
    assert_eq!(c.status, Status::Exact);
    let r = &c.value;
    let third = |n: i64| Rational::from((n, 3));
    let round = |x: Rational| geocert::num::round::round_rational(&x);
    assert_eq!(
        r.foot,
        Vector3::new(round(third(11)), round(third(-2)), round(third(17)))
    );
    assert_eq!(r.uv, Some(Vector2::new(round(third(8)), round(third(-8)))));
    assert_eq!(r.distance.nearest, sqrt_truth(2, 3, true));
    assert_eq!(r.distance.nearest, -0.816496580927726);
    assert!(r.distance.lo < r.distance.hi);

    let qp = qplane([1, 2, 3], [2, 0, 1], [1, 1, 0]);
    let e = project_point_plane_exact(&q3(4, -1, 5), &qp);
    assert_eq!(e.foot, Vector3::new(q(11, 3), q(-2, 3), q(17, 3)));
    assert_eq!(e.uv, Some(Vector2::new(q(8, 3), q(-8, 3))));
    // l_s = −2/√6: squared 4/6 = 2/3, negative.
    assert_eq!(e.distance.squared, q(2, 3));
    assert!(e.distance.negative);
    assert_eq!(e.distance.rounded.nearest, sqrt_truth(2, 3, true));
}

/// §16.5: segments crossing, and segments whose extensions meet at (2, 2).
#[test]
fn s16_5_segments_and_extensions() {
    let seg = |a: [f64; 2], b: [f64; 2]| Segment2::new(a.into(), b.into()).unwrap();
    let (s1, s2) = (seg([0.0, 0.0], [4.0, 4.0]), seg([0.0, 4.0], [4.0, 0.0]));
    let c = intersect_line2_line2(Linear2::Segment(&s1), Linear2::Segment(&s2));
    assert_eq!(c.status, Status::Exact);
    assert_eq!(
        c.value,
        Intersection2::Point {
            point: Vector2::new(exact(2.0), exact(2.0)),
            t1: exact(0.5),
            t2: exact(0.5)
        }
    );
    let s3 = seg([0.0, 0.0], [1.0, 1.0]);
    let c = intersect_line2_line2(Linear2::Segment(&s3), Linear2::Segment(&s2));
    assert_eq!(
        c.value,
        Intersection2::Empty(Empty2::OutsideDomain {
            point: Vector2::new(exact(2.0), exact(2.0)),
            t1: exact(2.0),
            t2: exact(0.5)
        })
    );
    let qs = |a: [i64; 2], b: [i64; 2]| {
        Segment2::new(
            Vector2::new(Rational::from(a[0]), Rational::from(a[1])),
            Vector2::new(Rational::from(b[0]), Rational::from(b[1])),
        )
        .unwrap()
    };
    let e = intersect_line2_line2_exact(
        Linear2::Segment(&qs([0, 0], [1, 1])),
        Linear2::Segment(&qs([0, 4], [4, 0])),
    );
    assert_eq!(
        e,
        Intersection2::Empty(Empty2::OutsideDomain {
            point: Vector2::new(q(2, 1), q(2, 1)),
            t1: q(2, 1),
            t2: q(1, 2)
        })
    );
}

/// §16.7: three planes, parameters through (3.7)–(3.8) on the skew third plane.
#[test]
fn s16_7_three_planes() {
    let r = plane([0.0; 3], [1.0, 0.0, 0.0], [0.0, 1.0, 1.0]);
    let s = plane([1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]);
    let qq = plane([0.0, 0.0, 2.0], [1.0, 0.0, 0.0], [1.0, 1.0, 0.0]);
    let c = intersect_three_planes(&[r, s, qq]);
    assert_eq!(c.status, Status::Exact);
    let pr = |a: f64, b: f64| Some(Vector2::new(exact(a), exact(b)));
    assert_eq!(
        c.value,
        ThreePlanes::Point {
            point: Vector3::new(exact(1.0), exact(2.0), exact(2.0)),
            params: [pr(1.0, 2.0), pr(2.0, 2.0), pr(-1.0, 2.0)]
        }
    );
    let e = intersect_three_planes_exact(&[
        qplane([0, 0, 0], [1, 0, 0], [0, 1, 1]),
        qplane([1, 0, 0], [0, 1, 0], [0, 0, 1]),
        qplane([0, 0, 2], [1, 0, 0], [1, 1, 0]),
    ]);
    let qp = |a: i64, b: i64| Some(Vector2::new(Rational::from(a), Rational::from(b)));
    assert_eq!(
        e,
        ThreePlanes::Point {
            point: q3(1, 2, 2),
            params: [qp(1, 2), qp(2, 2), qp(-1, 2)]
        }
    );
}

/// §16.8: plane–plane, with the unnormalised direction `n = N_r × N_s = (0, 1, 0)`
/// (the spec's `(0, 1/√2, 0)` is this divided by `|N_r||N_s| = √2`).
#[test]
fn s16_8_plane_plane() {
    let r = plane([0.0; 3], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]);
    let s = plane([2.0, 0.0, 0.0], [0.0, 1.0, 0.0], [-1.0, 0.0, 1.0]);
    let c = intersect_plane_plane(&r, &s);
    assert_eq!(c.status, Status::Exact);
    let PlanePlane::Line(l) = c.value else {
        panic!("expected a line")
    };
    assert_eq!(l.point, Vector3::new(exact(2.0), exact(0.0), exact(0.0)));
    assert_eq!(l.dir, Vector3::new(exact(0.0), exact(1.0), exact(0.0)));
    assert_eq!(l.dir_exponent, 0);
    let on_a = l.on_a.unwrap();
    let on_b = l.on_b.unwrap();
    // l_uv(t) = (2, t), l_ab(t) = (t, 0): the spec's with t scaled by √2.
    assert_eq!(
        (on_a.origin, on_a.dir),
        (
            Vector2::new(exact(2.0), exact(0.0)),
            Vector2::new(exact(0.0), exact(1.0))
        )
    );
    assert_eq!(
        (on_b.origin, on_b.dir),
        (
            Vector2::new(exact(0.0), exact(0.0)),
            Vector2::new(exact(1.0), exact(0.0))
        )
    );
    // s₀ = r₀ = 0 (plane x + z = 0): (8.2) is 0/0, (8.3) gives p = 0.
    let s0 = plane([0.0; 3], [0.0, 1.0, 0.0], [-1.0, 0.0, 1.0]);
    let PlanePlane::Line(l) = intersect_plane_plane(&r, &s0).value else {
        panic!()
    };
    assert_eq!(l.point, Vector3::new(exact(0.0), exact(0.0), exact(0.0)));
    let e = intersect_plane_plane_exact(
        &qplane([0, 0, 0], [1, 0, 0], [0, 1, 0]),
        &qplane([2, 0, 0], [0, 1, 0], [-1, 0, 1]),
    );
    let PlanePlane::Line(l) = e else { panic!() };
    assert_eq!((l.point, l.dir), (q3(2, 0, 0), q3(0, 1, 0)));
}

/// §5.1 on a skew plane: the line (0,0,0) + t(1,1,1) meets z = 1 at t = 1 (CASES.md lp-1).
#[test]
fn line_plane_case_lp1() {
    let line = Line::new(v3(0.0, 0.0, 0.0), v3(1.0, 1.0, 1.0)).unwrap();
    let pl = plane([0.0, 0.0, 1.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]);
    let c = intersect_line_plane(Linear::Line(&line), &pl);
    assert_eq!(c.status, Status::Exact);
    // Results that are doubles cannot be certified as such by the filter: the integer
    // tier decides them exactly.
    assert_eq!(c.arithmetic, Arithmetic::Integer);
    let LinePlane::Point(p) = c.value else {
        panic!()
    };
    assert_eq!(
        (p.t, p.point),
        (exact(1.0), Vector3::new(exact(1.0), exact(1.0), exact(1.0)))
    );
    assert_eq!(p.uv, Some(Vector2::new(exact(1.0), exact(1.0))));
    let ql = Line::new(q3(0, 0, 0), q3(1, 1, 3)).unwrap();
    let LinePlane::Point(p) =
        intersect_line_plane_exact(Linear::Line(&ql), &qplane([0, 0, 1], [1, 0, 0], [0, 1, 0]))
    else {
        panic!()
    };
    assert_eq!(
        (p.t, p.point),
        (q(1, 3), Vector3::new(q(1, 3), q(1, 3), q(1, 1)))
    );
}

/// Which tier decides: generic input in the filter, exactly degenerate small-integer
/// input in fixed-width integers, an exponent spread too wide for their 768 bits in
/// expansions, and magnitudes beyond the expansions' range in rationals — with the same
/// (exact) answer.
#[test]
fn tiers_escalate_and_agree() {
    let a = plane([0.1, 0.2, 0.3], [1.0, 0.3, -0.2], [0.25, 1.0, 0.5]);
    let b = plane([0.7, -0.1, 0.2], [0.0, 1.0, 0.9], [1.0, -0.5, 0.3]);
    let c = plane([0.3, 0.3, -0.6], [0.6, 0.2, 1.0], [-0.4, 0.8, 0.1]);
    assert_eq!(
        intersect_three_planes(&[a, b, c]).arithmetic,
        Arithmetic::Filter
    );
    // Three planes through the z axis: a line, decided exactly in integers.
    let p1 = plane([0.0; 3], [0.0, 0.0, 1.0], [1.0, 0.0, 0.0]);
    let p2 = plane([0.0, 0.0, 5.0], [0.0, 0.0, 1.0], [0.0, 1.0, 0.0]);
    let p3 = plane([0.0, 0.0, -3.0], [1.0, 1.0, 0.0], [0.0, 0.0, 2.0]);
    let c = intersect_three_planes(&[p1.clone(), p2.clone(), p3]);
    assert_eq!(c.arithmetic, Arithmetic::Integer);
    let ThreePlanes::Line { line, pair } = c.value else {
        panic!("expected a line")
    };
    assert_eq!(pair, (0, 1));
    // (8.3): the projection of the second plane's origin (0, 0, 5) onto the line.
    assert_eq!(line.point, Vector3::new(exact(0.0), exact(0.0), exact(5.0)));
    // n = N₀ × N₁ with N₀ = (0,0,1)×(1,0,0) = (0,1,0), N₁ = (0,0,1)×(0,1,0) = (−1,0,0)
    assert_eq!(line.dir, Vector3::new(exact(0.0), exact(0.0), exact(1.0)));
    // The same line with origins at 1e150 and 1e-150: the line test aligns numbers
    // ~1000 bits apart, beyond the integers' 768 bits; expansions decide.
    let w2 = plane([0.0, 0.0, 1e150], [0.0, 0.0, 1.0], [0.0, 1.0, 0.0]);
    let w3 = plane([0.0, 0.0, 1e-150], [1.0, 1.0, 0.0], [0.0, 0.0, 2.0]);
    let c = intersect_three_planes(&[p1.clone(), w2, w3]);
    assert_eq!(c.arithmetic, Arithmetic::Expansion);
    let ThreePlanes::Line { line, pair } = c.value else {
        panic!("expected a line")
    };
    assert_eq!(pair, (0, 1));
    assert_eq!(
        line.point,
        Vector3::new(exact(0.0), exact(0.0), exact(1e150))
    );
    // The same configuration with tiny vectors (products below 2^-969 are not
    // error-free in doubles): rationals.
    let t = 1e-170;
    let q1 = plane([0.0; 3], [0.0, 0.0, t], [t, 0.0, 0.0]);
    let q2 = plane([0.0, 0.0, 5.0], [0.0, 0.0, t], [0.0, t, 0.0]);
    let q3 = plane([0.0, 0.0, -3.0], [t, t, 0.0], [0.0, 0.0, t]);
    let c = intersect_three_planes(&[q1, q2, q3]);
    assert_eq!(c.arithmetic, Arithmetic::Rational);
    let ThreePlanes::Line { line, .. } = c.value else {
        panic!("expected a line")
    };
    assert_eq!(line.point, Vector3::new(exact(0.0), exact(0.0), exact(5.0)));
    // dir = N₀ × N₁ = (0, 0, t⁴) ≈ 1e-680: scaled by 2^k into [1, 2) (PlaneLine docs).
    assert!(line.dir_exponent > 2000);
    let d = rug::Rational::from_f64(t).unwrap();
    let d4 = (d.clone() * &d) * (d.clone() * &d);
    let scaled = geocert::num::round::scale_pow2(&d4, line.dir_exponent);
    assert_eq!(line.dir[2], geocert::num::round::round_rational(&scaled));
    assert!(line.dir[2].nearest >= 1.0 && line.dir[2].nearest < 2.0);
    assert_eq!((line.dir[0], line.dir[1]), (exact(0.0), exact(0.0)));
}
