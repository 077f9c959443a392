//! Algebraic intersections decided exactly (issue 6): line ∩ sphere, cone, quadrics,
//! torus; line ∩ conic; conic ∩ conic. Expected values are derived by hand (closed
//! forms), rounded independently: IEEE-754 `sqrt` and `/` are correctly rounded, and
//! closed forms are enclosed at 600 bits with MPFR intervals whose two ends must round
//! to the same double.

use geocert::certificate::{Arithmetic, Status};
use geocert::num::MpfrInterval;
use geocert::ops::algebraic::{
    intersect_conic_conic, intersect_line_conic, intersect_line_quadric, intersect_line_torus,
    Conic, ConicCut, LineCut, QuadricForm, TorusData,
};
use proptest::prelude::*;
use rug::Rational;

mod poly_support;
use poly_support::Poly;

const P: u32 = 600;

fn mp(x: f64) -> MpfrInterval {
    MpfrInterval::point(x, P)
}

/// The double nearest to the value enclosed by `v` (both ends must agree).
fn nearest_of(v: &MpfrInterval) -> f64 {
    let (a, b) = (v.lo().to_f64(), v.hi().to_f64());
    assert_eq!(a, b, "600 bits do not decide the rounding");
    a
}

fn pow2(k: i32) -> f64 {
    2f64.powi(k)
}

fn line_points<const D: usize>(cut: &LineCut<D>) -> Vec<([f64; D], u32)> {
    cut.points()
        .iter()
        .map(|h| (h.nearest(), h.multiplicity))
        .collect()
}

fn identity3() -> [[f64; 3]; 3] {
    [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]
}

fn identity2() -> [[f64; 2]; 2] {
    [[1.0, 0.0], [0.0, 1.0]]
}

#[test]
fn line_and_sphere_worked_examples_16_4() {
    let sphere = QuadricForm::sphere([0.0; 3], 2.0).unwrap();
    // Tangency: exactly one point, t = 3, (0, 2, 0), a double root.
    let r = intersect_line_quadric([-3.0, 2.0, 0.0], [1.0, 0.0, 0.0], &sphere).unwrap();
    assert_eq!(
        (r.status, r.complete, r.arithmetic),
        (Status::Exact, true, Arithmetic::Rational)
    );
    let hits = r.value.points();
    assert_eq!(hits.len(), 1);
    assert_eq!(hits[0].t.exact(), Some(&Rational::from(3)));
    assert_eq!(hits[0].nearest(), [0.0, 2.0, 0.0]);
    assert!(hits[0].point.iter().all(|c| c.is_exact()));
    assert!(hits[0].is_tangent() && !hits[0].singular);

    // Two transversal points t = 3 ∓ √(4 − 0.25 − z²), z the double 0.2.
    let z = 0.2f64;
    let r = intersect_line_quadric([-3.0, 0.5, z], [1.0, 0.0, 0.0], &sphere).unwrap();
    let hits = r.value.points();
    assert_eq!(hits.len(), 2);
    let root = mp(4.0).sub(&mp(0.25)).sub(&mp(z).sqr()).sqrt();
    for (h, sign) in hits.iter().zip([-1.0, 1.0]) {
        let s = if sign < 0.0 { root.neg() } else { root.clone() };
        assert_eq!(h.multiplicity, 1);
        assert!(!h.t.is_rational());
        assert_eq!(h.t.nearest(), nearest_of(&mp(3.0).add(&s)));
        assert_eq!(h.point[0].nearest, nearest_of(&s));
        assert_eq!((h.point[1].nearest, h.point[2].nearest), (0.5, z));
        assert!(h.point[1].is_exact() && h.point[2].is_exact());
    }
    assert!((hits[0].t.nearest() - 1.0738639716).abs() < 1e-9);
    assert!((hits[1].nearest()[0] - 1.9261360284).abs() < 1e-9);
}

#[test]
fn sphere_at_huge_and_tiny_magnitudes() {
    // Tangency at 2^500 with a direction of size 2^-490: t = 5·2^10.
    let c = [pow2(500), 3.0 * pow2(500), 0.0];
    let sphere = QuadricForm::sphere(c, pow2(497)).unwrap();
    let o = [pow2(500), 3.0 * pow2(500) + pow2(497), -5.0 * pow2(-480)];
    let r = intersect_line_quadric(o, [0.0, 0.0, pow2(-490)], &sphere).unwrap();
    let hits = r.value.points();
    assert_eq!(hits.len(), 1);
    assert_eq!(hits[0].t.exact(), Some(&Rational::from(5120)));
    assert_eq!(hits[0].multiplicity, 2);
    assert_eq!(hits[0].nearest(), [o[0], o[1], 0.0]);
    // Tiny sphere r = 1e-150: the line along x meets it exactly at x = ±r.
    let sphere = QuadricForm::sphere([0.0; 3], 1e-150).unwrap();
    let r = intersect_line_quadric([-1e-149, 0.0, 0.0], [1e-150, 0.0, 0.0], &sphere).unwrap();
    let pts = line_points(&r.value);
    assert_eq!(pts, vec![([-1e-150, 0.0, 0.0], 1), ([1e-150, 0.0, 0.0], 1)]);
    // Huge offset 1e150 with an irrational crossing: x = 1e150 ± √(r² − 1).
    let sphere = QuadricForm::sphere([1e150, 0.0, 0.0], 3.0).unwrap();
    let r = intersect_line_quadric([0.0, 1.0, 0.0], [1.0, 0.0, 0.0], &sphere).unwrap();
    let hits = r.value.points();
    assert_eq!(hits.len(), 2);
    let s8 = mp(8.0).sqrt();
    assert_eq!(hits[0].point[0].nearest, nearest_of(&mp(1e150).sub(&s8)));
    assert_eq!(hits[1].t.nearest(), nearest_of(&mp(1e150).add(&s8)));
}

#[test]
fn cone_apex_generator_and_tangent() {
    // x² + y² = z² (apex 0, axis z, tan α = 1).
    let cone = QuadricForm::circular_cone([0.0; 3], [0.0, 0.0, 1.0], 1.0).unwrap();
    // Through the apex in a generic direction: F(t) = −3(t − 1)², a double root at a
    // singular point, reported as such (not a tangency).
    let r = intersect_line_quadric([-1.0, 0.0, -2.0], [1.0, 0.0, 2.0], &cone).unwrap();
    let hits = r.value.points();
    assert_eq!(hits.len(), 1);
    assert_eq!((hits[0].multiplicity, hits[0].singular), (2, true));
    assert!(!hits[0].is_tangent());
    assert_eq!(hits[0].nearest(), [0.0, 0.0, 0.0]);
    // Along a generator: the whole line.
    let r = intersect_line_quadric([-1.0, 0.0, -1.0], [1.0, 0.0, 1.0], &cone).unwrap();
    assert!(matches!(r.value, LineCut::Contained));
    // Tangent at the regular point (1, 0, 1) along (0, 1, 0).
    let r = intersect_line_quadric([1.0, -3.0, 1.0], [0.0, 1.0, 0.0], &cone).unwrap();
    let hits = r.value.points();
    assert_eq!(hits.len(), 1);
    assert!(hits[0].is_tangent());
    assert_eq!(hits[0].t.exact(), Some(&Rational::from(3)));
    // Axis of length 2, tan α = 1/2: x² + y² = z²/4; the line x = 1 ∥ axis: z = ±2.
    let cone = QuadricForm::circular_cone([0.0; 3], [0.0, 0.0, 2.0], 0.5).unwrap();
    let r = intersect_line_quadric([1.0, 0.0, -10.0], [0.0, 0.0, 1.0], &cone).unwrap();
    assert_eq!(
        line_points(&r.value),
        vec![([1.0, 0.0, -2.0], 1), ([1.0, 0.0, 2.0], 1)]
    );
}

#[test]
fn quadrics_in_exact_frames() {
    let e = QuadricForm::ellipsoid([0.0; 3], identity3(), [3.0, 2.0, 1.0])
        .unwrap()
        .unwrap();
    let r = intersect_line_quadric([-5.0, 0.0, 0.0], [1.0, 0.0, 0.0], &e).unwrap();
    assert_eq!(
        line_points(&r.value),
        vec![([-3.0, 0.0, 0.0], 1), ([3.0, 0.0, 0.0], 1)]
    );
    // A permuted frame: the local x axis is the world y axis, so along x the radius is 2.
    let frame = [[0.0, 1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, -1.0]];
    let e = QuadricForm::ellipsoid([0.0; 3], frame, [3.0, 2.0, 1.0])
        .unwrap()
        .unwrap();
    let r = intersect_line_quadric([-5.0, 0.0, 0.0], [1.0, 0.0, 0.0], &e).unwrap();
    assert_eq!(
        line_points(&r.value),
        vec![([-2.0, 0.0, 0.0], 1), ([2.0, 0.0, 0.0], 1)]
    );
    // A rotated frame of doubles is not exactly orthonormal: no exact form.
    let rotated = [[0.6, 0.8, 0.0], [-0.8, 0.6, 0.0], [0.0, 0.0, 1.0]];
    assert!(QuadricForm::ellipsoid([0.0; 3], rotated, [3.0, 2.0, 1.0])
        .unwrap()
        .is_none());
    // Rulings lie on the one-sheet hyperboloid and on the hyperbolic paraboloid.
    let h1 = QuadricForm::hyperboloid_one_sheet([0.0; 3], identity3(), [1.0, 1.0, 1.0])
        .unwrap()
        .unwrap();
    let r = intersect_line_quadric([1.0, 0.0, 0.0], [0.0, 1.0, 1.0], &h1).unwrap();
    assert!(matches!(r.value, LineCut::Contained));
    let hp = QuadricForm::hyperbolic_paraboloid([0.0; 3], identity3(), 2.0, 3.0)
        .unwrap()
        .unwrap();
    let r = intersect_line_quadric([0.0; 3], [2.0, 3.0, 0.0], &hp).unwrap();
    assert!(matches!(r.value, LineCut::Contained));
    let h2 = QuadricForm::hyperboloid_two_sheets([0.0; 3], identity3(), [1.0, 1.0, 1.0])
        .unwrap()
        .unwrap();
    let r = intersect_line_quadric([0.0, 0.0, -4.0], [0.0, 0.0, 1.0], &h2).unwrap();
    assert_eq!(
        line_points(&r.value),
        vec![([0.0, 0.0, -1.0], 1), ([0.0, 0.0, 1.0], 1)]
    );
    // Paraboloid z = x² + y²: along the axis one simple point; at z = 4 two.
    let p = QuadricForm::elliptic_paraboloid([0.0; 3], identity3(), 1.0, 1.0)
        .unwrap()
        .unwrap();
    let r = intersect_line_quadric([0.0, 0.0, -1.0], [0.0, 0.0, 1.0], &p).unwrap();
    assert_eq!(line_points(&r.value), vec![([0.0, 0.0, 0.0], 1)]);
    let r = intersect_line_quadric([0.0, 0.0, 4.0], [1.0, 0.0, 0.0], &p).unwrap();
    assert_eq!(
        line_points(&r.value),
        vec![([-2.0, 0.0, 4.0], 1), ([2.0, 0.0, 4.0], 1)]
    );
    // Cylinder of radius 1 about the axis (1, 1, 0): the parallel line through
    // (0, 0, 1) lies on it; the z axis meets it at z = ±1.
    let cyl = QuadricForm::circular_cylinder([0.0; 3], [1.0, 1.0, 0.0], 1.0).unwrap();
    let r = intersect_line_quadric([0.0, 0.0, 1.0], [1.0, 1.0, 0.0], &cyl).unwrap();
    assert!(matches!(r.value, LineCut::Contained));
    let r = intersect_line_quadric([0.0, 0.0, -3.0], [0.0, 0.0, 1.0], &cyl).unwrap();
    assert_eq!(
        line_points(&r.value),
        vec![([0.0, 0.0, -1.0], 1), ([0.0, 0.0, 1.0], 1)]
    );
    let ec = QuadricForm::elliptic_cylinder([1.0, 0.0, 0.0], identity3(), 2.0, 1.0)
        .unwrap()
        .unwrap();
    let r = intersect_line_quadric([-5.0, 1.0, 7.0], [1.0, 0.0, 0.0], &ec).unwrap();
    assert_eq!(line_points(&r.value), vec![([1.0, 1.0, 7.0], 2)]);
}

#[test]
fn bad_input_is_a_typed_error() {
    let sphere = QuadricForm::sphere([0.0; 3], 1.0).unwrap();
    let e = intersect_line_quadric([0.0; 3], [0.0; 3], &sphere).unwrap_err();
    assert_eq!((e.kind(), e.field()), ("zero_direction", "line.direction"));
    let e = intersect_line_quadric([0.0, f64::NAN, 0.0], [1.0, 0.0, 0.0], &sphere).unwrap_err();
    assert_eq!((e.kind(), e.field()), ("non_finite", "line.origin[1]"));
    let e = QuadricForm::sphere([0.0; 3], -1.0).unwrap_err();
    assert_eq!((e.kind(), e.field()), ("invalid_value", "radius"));
    let e = TorusData::new([0.0; 3], [0.0; 3], 2.0, 1.0).unwrap_err();
    assert_eq!(e.kind(), "zero_direction");
    let e = TorusData::new([0.0; 3], [0.0, 0.0, 1.0], 2.0, 0.0).unwrap_err();
    assert_eq!((e.kind(), e.field()), ("invalid_value", "minor_radius"));
    let e = Conic::conic([0.0; 6]).unwrap_err();
    assert_eq!(e.kind(), "invalid_value");
    let e = QuadricForm::<2>::from_f64([[1.0, 2.0], [0.0, 1.0]], [0.0; 2], 0.0).unwrap_err();
    assert_eq!((e.kind(), e.field()), ("invalid_value", "a[0][1]"));
    let e = QuadricForm::<3>::from_f64([[0.0; 3]; 3], [0.0; 3], 0.0).unwrap_err();
    assert_eq!((e.kind(), e.field()), ("invalid_value", "quadric"));
    // The exact data round-trips: the sphere about (1, 2, 3) of radius 2 is
    // x·x − 2(1, 2, 3)·x + 14 − 4.
    let s = QuadricForm::sphere([1.0, 2.0, 3.0], 2.0).unwrap();
    assert_eq!(
        s.linear(),
        &[Rational::from(-1), Rational::from(-2), Rational::from(-3)]
    );
    assert_eq!(s.constant(), &Rational::from(10));
    assert_eq!(s.matrix()[1][1], 1);
}

#[test]
fn lines_through_a_torus_hit_0_2_3_4_times() {
    // R = 2, r = 1 about the z axis: in the plane z = 0 the torus is 1 ≤ ρ ≤ 3.
    let torus = TorusData::new([0.0; 3], [0.0, 0.0, 1.0], 2.0, 1.0).unwrap();
    let along_x = |y: f64, z: f64| {
        intersect_line_torus([-5.0, y, z], [1.0, 0.0, 0.0], &torus)
            .unwrap()
            .value
    };
    assert_eq!(
        line_points(&along_x(0.0, 0.0)),
        vec![
            ([-3.0, 0.0, 0.0], 1),
            ([-1.0, 0.0, 0.0], 1),
            ([1.0, 0.0, 0.0], 1),
            ([3.0, 0.0, 0.0], 1)
        ]
    );
    // y = 1 touches the inner equator at x = 0 and crosses the outer at ±√8.
    let s8 = 8f64.sqrt();
    let three = along_x(1.0, 0.0);
    assert_eq!(
        line_points(&three),
        vec![
            ([-s8, 1.0, 0.0], 1),
            ([0.0, 1.0, 0.0], 2),
            ([s8, 1.0, 0.0], 1)
        ]
    );
    assert!(three.points()[1].is_tangent());
    // y = 3 touches the outer equator only; y = 4 misses.
    assert_eq!(line_points(&along_x(3.0, 0.0)), vec![([0.0, 3.0, 0.0], 2)]);
    assert!(along_x(4.0, 0.0).points().is_empty());
    assert!(matches!(along_x(4.0, 0.0), LineCut::Points(_)));
    // z = 1 is bitangent: two double points x = ±2.
    assert_eq!(
        line_points(&along_x(0.0, 1.0)),
        vec![([-2.0, 0.0, 1.0], 2), ([2.0, 0.0, 1.0], 2)]
    );
    // The same at 1e150 (D the double 1e150, R = 2D, r = D): x = ±D and ±3D, the
    // latter correctly rounded as IEEE's product 3·D is; at 1e-150 likewise.
    for big in [1e150, 1e-150] {
        let t = TorusData::new([0.0; 3], [0.0, 0.0, 1.0], 2.0 * big, big).unwrap();
        let r = intersect_line_torus([-5.0 * big, 0.0, 0.0], [big, 0.0, 0.0], &t).unwrap();
        let xs: Vec<(f64, u32)> = line_points(&r.value)
            .iter()
            .map(|(p, m)| (p[0], *m))
            .collect();
        assert_eq!(
            xs,
            vec![(-3.0 * big, 1), (-big, 1), (big, 1), (3.0 * big, 1)]
        );
    }
    // A line parallel to the axis at ρ = 2 crosses the tube at z = ±1.
    let r = intersect_line_torus([2.0, 0.0, -4.0], [0.0, 0.0, 1.0], &torus).unwrap();
    assert_eq!(
        line_points(&r.value),
        vec![([2.0, 0.0, -1.0], 1), ([2.0, 0.0, 1.0], 1)]
    );
}

#[test]
fn torus_with_unnormalised_and_tilted_axes() {
    // Centre (1, 2, 3), axis (0, 0, 3): the y = 1 case moved; x = 1 ± √8 and 1 (double).
    let torus = TorusData::new([1.0, 2.0, 3.0], [0.0, 0.0, 3.0], 2.0, 1.0).unwrap();
    let r = intersect_line_torus([-9.0, 3.0, 3.0], [1.0, 0.0, 0.0], &torus).unwrap();
    let hits = r.value.points();
    assert_eq!(hits.len(), 3);
    let s8 = mp(8.0).sqrt();
    assert_eq!(hits[0].point[0].nearest, nearest_of(&mp(1.0).sub(&s8)));
    assert_eq!(hits[2].point[0].nearest, nearest_of(&mp(1.0).add(&s8)));
    assert_eq!(hits[2].t.nearest(), nearest_of(&mp(10.0).add(&s8)));
    assert_eq!(
        (hits[1].nearest(), hits[1].multiplicity),
        ([1.0, 3.0, 3.0], 2)
    );
    // Axis (1, 1, 0): the line through the centre along (1, −1, 0) lies in the
    // equatorial plane and meets the tube at distances 1 and 3: t = ±√(1/2), ±√(9/2).
    let tilted = TorusData::new([0.0; 3], [1.0, 1.0, 0.0], 2.0, 1.0).unwrap();
    let r = intersect_line_torus([0.0; 3], [1.0, -1.0, 0.0], &tilted).unwrap();
    let ts: Vec<f64> = r.value.points().iter().map(|h| h.t.nearest()).collect();
    let (a, b) = (0.5f64.sqrt(), 4.5f64.sqrt());
    assert_eq!(ts, vec![-b, -a, a, b]);
    for h in r.value.points() {
        assert_eq!(h.multiplicity, 1);
        assert_eq!(h.point[0].nearest, h.t.nearest());
        assert_eq!(h.point[1].nearest, -h.t.nearest());
    }
    // The axis itself passes through the hole.
    let r = intersect_line_torus([0.0; 3], [1.0, 1.0, 0.0], &tilted).unwrap();
    assert!(r.value.points().is_empty());
    // Horn torus R = r = 1: its centre is a singular point (t = 0, double, singular).
    let horn = TorusData::new([0.0; 3], [0.0, 0.0, 1.0], 1.0, 1.0).unwrap();
    let r = intersect_line_torus([0.0; 3], [1.0, 0.0, 0.0], &horn).unwrap();
    let hits = r.value.points();
    assert_eq!(hits.len(), 3);
    assert_eq!(
        (hits[1].multiplicity, hits[1].singular, hits[1].nearest()),
        (2, true, [0.0; 3])
    );
    assert!(!hits[0].singular && !hits[2].singular);
}

#[test]
fn degenerate_tori() {
    // Spindle R = 1, r = 2: along x through the centre the quartic has x = ±1 and ±3,
    // but ±1 lie on the inner sheet (|q|² + R² − r² = −2 < 0), outside the surface.
    let spindle = TorusData::new([0.0; 3], [0.0, 0.0, 1.0], 1.0, 2.0).unwrap();
    let r = intersect_line_torus([-5.0, 0.0, 0.0], [1.0, 0.0, 0.0], &spindle).unwrap();
    assert_eq!(
        line_points(&r.value),
        vec![([-3.0, 0.0, 0.0], 1), ([3.0, 0.0, 0.0], 1)]
    );
    assert!(r.reason.is_some());
    // Along the axis: the two singular apexes z = ±√3, where both sheets meet.
    let r = intersect_line_torus([0.0, 0.0, -5.0], [0.0, 0.0, 1.0], &spindle).unwrap();
    let s3 = 3f64.sqrt();
    assert_eq!(
        line_points(&r.value),
        vec![([0.0, 0.0, -s3], 2), ([0.0, 0.0, s3], 2)]
    );
    assert!(r.value.points().iter().all(|h| h.singular));
    // R = 0 is the sphere of radius r: simple crossings, not squared ones.
    let ball = TorusData::new([0.0; 3], [0.0, 0.0, 1.0], 0.0, 2.0).unwrap();
    let r = intersect_line_torus([-5.0, 0.0, 0.0], [1.0, 0.0, 0.0], &ball).unwrap();
    assert_eq!(
        line_points(&r.value),
        vec![([-2.0, 0.0, 0.0], 1), ([2.0, 0.0, 0.0], 1)]
    );
}

/// `T(o + t·d)` for the torus about z with R = 2, r = 1, in MPFR at 300 bits.
fn torus_sign(o: [f64; 3], d: [f64; 3], t: &Rational) -> std::cmp::Ordering {
    let t = MpfrInterval::from_rational(t, 300);
    let q: Vec<MpfrInterval> = (0..3)
        .map(|i| MpfrInterval::point(o[i], 300).add(&t.mul(&MpfrInterval::point(d[i], 300))))
        .collect();
    let qq = q[0].sqr().add(&q[1].sqr()).add(&q[2].sqr());
    let rho2 = q[0].sqr().add(&q[1].sqr());
    let s = qq.add(&MpfrInterval::point(3.0, 300));
    let v = s.sqr().sub(&rho2.mul(&MpfrInterval::point(16.0, 300)));
    if *v.lo() > 0 {
        std::cmp::Ordering::Greater
    } else if *v.hi() < 0 {
        std::cmp::Ordering::Less
    } else {
        panic!("300 bits cannot decide")
    }
}

#[test]
fn generic_line_through_a_torus_rounds_every_coordinate() {
    let torus = TorusData::new([0.0; 3], [0.0, 0.0, 1.0], 2.0, 1.0).unwrap();
    let (o, d) = ([-4.0, 0.3, 0.1], [1.0, 0.1, 0.05]);
    let r = intersect_line_torus(o, d, &torus).unwrap();
    assert_eq!(r.value.points().len(), 4);
    for h in r.value.points() {
        assert_eq!(h.multiplicity, 1);
        // Each coordinate xᵢ = oᵢ + t dᵢ rounds to c iff the root t lies between the
        // parameters of c's two rounding boundaries: the quartic changes sign there.
        for i in 0..3 {
            let c = h.point[i].nearest;
            let lo = (Rational::from_f64(geocert::num::round::next_down(c)).unwrap()
                + Rational::from_f64(c).unwrap())
                / 2u32;
            let hi = (Rational::from_f64(geocert::num::round::next_up(c)).unwrap()
                + Rational::from_f64(c).unwrap())
                / 2u32;
            let to_t = |x: Rational| {
                (x - Rational::from_f64(o[i]).unwrap()) / Rational::from_f64(d[i]).unwrap()
            };
            assert_ne!(torus_sign(o, d, &to_t(lo)), torus_sign(o, d, &to_t(hi)));
        }
    }
}

#[test]
fn line_and_conic() {
    let circle = Conic::circle([0.0, 0.0], 2.0).unwrap();
    let r = intersect_line_conic([-7.0, 2.0], [1.0, 0.0], &circle).unwrap();
    assert_eq!(line_points(&r.value), vec![([0.0, 2.0], 2)]);
    let r = intersect_line_conic([-7.0, 1.0], [1.0, 0.0], &circle).unwrap();
    let s3 = 3f64.sqrt();
    assert_eq!(line_points(&r.value), vec![([-s3, 1.0], 1), ([s3, 1.0], 1)]);
    // xy = 1: a line parallel to an asymptote meets it once (α = 0), the asymptote never.
    let hyperbola = Conic::conic([0.0, 1.0, 0.0, 0.0, 0.0, -1.0]).unwrap();
    let r = intersect_line_conic([-3.0, 1.0], [1.0, 0.0], &hyperbola).unwrap();
    assert_eq!(line_points(&r.value), vec![([1.0, 1.0], 1)]);
    let r = intersect_line_conic([-3.0, 0.0], [1.0, 0.0], &hyperbola).unwrap();
    assert!(r.value.points().is_empty());
    // y² = 2x (parabola, f = 1) touched by the y axis at the vertex.
    let parabola = Conic::parabola([0.0, 0.0], identity2(), 1.0)
        .unwrap()
        .unwrap();
    let r = intersect_line_conic([0.0, -3.0], [0.0, 1.0], &parabola).unwrap();
    assert_eq!(line_points(&r.value), vec![([0.0, 0.0], 2)]);
}

fn conic_points(c: &ConicCut) -> Vec<([f64; 2], u32)> {
    c.points()
        .iter()
        .map(|h| (h.nearest(), h.multiplicity))
        .collect()
}

fn ellipse(a: f64, b: f64) -> Conic {
    Conic::ellipse([0.0, 0.0], identity2(), a, b)
        .unwrap()
        .unwrap()
}

#[test]
fn circle_and_ellipse_16_6() {
    // Four transversal points (±√(27/8), ±√(5/8)).
    let r = intersect_conic_conic(&Conic::circle([0.0, 0.0], 2.0).unwrap(), &ellipse(3.0, 1.0))
        .unwrap();
    assert_eq!((r.status, r.complete), (Status::Exact, true));
    let (x, y) = ((27.0f64 / 8.0).sqrt(), (5.0f64 / 8.0).sqrt());
    assert_eq!(
        conic_points(&r.value),
        vec![([-x, -y], 1), ([-x, y], 1), ([x, -y], 1), ([x, y], 1)]
    );
    // r = 1: two tangencies (0, ±1) sharing the abscissa 0.
    let r = intersect_conic_conic(&Conic::circle([0.0, 0.0], 1.0).unwrap(), &ellipse(3.0, 1.0))
        .unwrap();
    assert_eq!(
        conic_points(&r.value),
        vec![([0.0, -1.0], 2), ([0.0, 1.0], 2)]
    );
    // Scaled by 2^±500: the same points scaled (exact scaling of the roundings).
    for k in [500, -500] {
        let s = pow2(k);
        let c = Conic::circle([0.0, 0.0], 2.0 * s).unwrap();
        let e = Conic::ellipse([0.0, 0.0], identity2(), 3.0 * s, s)
            .unwrap()
            .unwrap();
        let r = intersect_conic_conic(&c, &e).unwrap();
        assert_eq!(conic_points(&r.value)[3], ([x * s, y * s], 1));
    }
}

#[test]
fn conic_tangencies_and_contact_orders() {
    // (x − 1)² + y² = 4 and x²/9 + y²/4 = 1: tangent at (3, 0), crossing at
    // (3/5, ±4√6/5).
    let c = Conic::circle([1.0, 0.0], 2.0).unwrap();
    let r = intersect_conic_conic(&c, &ellipse(3.0, 2.0)).unwrap();
    let y = nearest_of(&mp(96.0).sqrt().div(&mp(5.0)));
    assert_eq!(
        conic_points(&r.value),
        vec![([0.6, -y], 1), ([0.6, y], 1), ([3.0, 0.0], 2)]
    );
    assert!(r.value.points()[2].x.is_rational());
    // x² + (y − 1)² = 1 against y = x²/2: one point of contact order 4.
    let circle = Conic::circle([0.0, 1.0], 1.0).unwrap();
    let parabola = Conic::conic([0.5, 0.0, 0.0, 0.0, -1.0, 0.0]).unwrap();
    let r = intersect_conic_conic(&circle, &parabola).unwrap();
    assert_eq!(conic_points(&r.value), vec![([0.0, 0.0], 4)]);
    // Two unit circles touching externally at (1, 0); two far apart miss.
    let a = Conic::circle([0.0, 0.0], 1.0).unwrap();
    let b = Conic::circle([2.0, 0.0], 1.0).unwrap();
    assert_eq!(
        conic_points(&intersect_conic_conic(&a, &b).unwrap().value),
        vec![([1.0, 0.0], 2)]
    );
    let far = Conic::circle([5.0, 0.0], 1.0).unwrap();
    assert!(intersect_conic_conic(&a, &far)
        .unwrap()
        .value
        .points()
        .is_empty());
}

#[test]
fn hyperbola_and_circle_meet_in_four_irrational_points() {
    // xy = 1, x² + y² = 4: x² = 2 ± √3, y = 1/x.
    let h = Conic::conic([0.0, 1.0, 0.0, 0.0, 0.0, -1.0]).unwrap();
    let c = Conic::circle([0.0, 0.0], 2.0).unwrap();
    let r = intersect_conic_conic(&h, &c).unwrap();
    let s3 = mp(3.0).sqrt();
    let big = mp(2.0).add(&s3).sqrt();
    let small = mp(2.0).sub(&s3).sqrt();
    let one = mp(1.0);
    let want = [
        (big.neg(), one.div(&big).neg()),
        (small.neg(), one.div(&small).neg()),
        (small.clone(), one.div(&small)),
        (big.clone(), one.div(&big)),
    ];
    let got = conic_points(&r.value);
    assert_eq!(got.len(), 4);
    for ((p, m), (x, y)) in got.iter().zip(&want) {
        assert_eq!(*m, 1);
        assert_eq!(*p, [nearest_of(x), nearest_of(y)]);
    }
}

#[test]
fn coincident_and_common_components() {
    let c = Conic::circle([1.0, 2.0], 3.0).unwrap();
    let twice = Conic::conic({
        let k = c.coefficients();
        std::array::from_fn(|i| 2.0 * k[i].to_f64())
    })
    .unwrap();
    let r = intersect_conic_conic(&c, &twice).unwrap();
    assert!(matches!(r.value, ConicCut::Coincident));
    assert_eq!((r.status, r.complete), (Status::Exact, true));
    // xy and x(x + y − 1) share the line x = 0.
    let a = Conic::conic([0.0, 1.0, 0.0, 0.0, 0.0, 0.0]).unwrap();
    let b = Conic::conic([1.0, 1.0, 0.0, -1.0, 0.0, 0.0]).unwrap();
    let r = intersect_conic_conic(&a, &b).unwrap();
    assert!(matches!(r.value, ConicCut::CommonComponent));
    assert!(!r.complete);
    // Degenerate conics: the point conic x² + y² = 0 meets the line y = x twice at the
    // origin (once per complex line); the double lines x² = 0 and y² = 0 four times.
    let point = Conic::conic([1.0, 0.0, 1.0, 0.0, 0.0, 0.0]).unwrap();
    let diagonal = Conic::conic([0.0, 0.0, 0.0, 1.0, -1.0, 0.0]).unwrap();
    assert_eq!(
        conic_points(&intersect_conic_conic(&point, &diagonal).unwrap().value),
        vec![([0.0, 0.0], 2)]
    );
    let xx = Conic::conic([1.0, 0.0, 0.0, 0.0, 0.0, 0.0]).unwrap();
    let yy = Conic::conic([0.0, 0.0, 1.0, 0.0, 0.0, 0.0]).unwrap();
    assert_eq!(
        conic_points(&intersect_conic_conic(&xx, &yy).unwrap().value),
        vec![([0.0, 0.0], 4)]
    );
    // Two line pairs through the origin meet only there, four times; a circle through
    // the node of x² − y² meets it twice there and once at (±1, 1).
    let pair = Conic::conic([1.0, 0.0, -1.0, 0.0, 0.0, 0.0]).unwrap();
    let cross = Conic::conic([0.0, 1.0, 0.0, 0.0, 0.0, 0.0]).unwrap();
    let r = intersect_conic_conic(&pair, &cross).unwrap();
    assert_eq!((r.status, r.complete), (Status::Exact, true));
    assert_eq!(conic_points(&r.value), vec![([0.0, 0.0], 4)]);
    let circle = Conic::circle([0.0, 1.0], 1.0).unwrap();
    let r = intersect_conic_conic(&pair, &circle).unwrap();
    assert_eq!((r.status, r.complete), (Status::Exact, true));
    assert_eq!(
        conic_points(&r.value),
        vec![([-1.0, 1.0], 1), ([0.0, 0.0], 2), ([1.0, 1.0], 1)]
    );
    // The empty conic x² + y² + 1 = 0 meets nothing.
    let empty = Conic::conic([1.0, 0.0, 1.0, 0.0, 0.0, 1.0]).unwrap();
    assert!(
        intersect_conic_conic(&empty, &Conic::circle([0.0, 0.0], 1.0).unwrap())
            .unwrap()
            .value
            .points()
            .is_empty()
    );
    // A line (degree-1 "conic") through a circle.
    let line = Conic::conic([0.0, 0.0, 0.0, 1.0, -1.0, 0.0]).unwrap(); // x = y
    let unit = Conic::circle([0.0, 0.0], 1.0).unwrap();
    let h = 0.5f64.sqrt();
    assert_eq!(
        conic_points(&intersect_conic_conic(&line, &unit).unwrap().value),
        vec![([-h, -h], 1), ([h, h], 1)]
    );
}

/// Integer points on the sphere of radius `d` about the origin.
fn sphere_points(d: i64) -> Vec<[i64; 3]> {
    let mut v = Vec::new();
    for x in -d..=d {
        for y in -d..=d {
            for z in -d..=d {
                if x * x + y * y + z * z == d * d {
                    v.push([x, y, z]);
                }
            }
        }
    }
    v
}

/// `a x + b y + c = 0` through two points.
fn line_through(p: [i64; 2], q: [i64; 2]) -> [i64; 3] {
    [q[1] - p[1], p[0] - q[0], q[0] * p[1] - p[0] * q[1]]
}

/// The conic `l·m` of two lines, as `[a, b, c, d, e, f]`.
fn line_pair(l: [i64; 3], m: [i64; 3]) -> [i64; 6] {
    [
        l[0] * m[0],
        l[0] * m[1] + l[1] * m[0],
        l[1] * m[1],
        l[0] * m[2] + l[2] * m[0],
        l[1] * m[2] + l[2] * m[1],
        l[2] * m[2],
    ]
}

fn on_line(l: [i64; 3], p: [i64; 2]) -> bool {
    l[0] * p[0] + l[1] * p[1] + l[2] == 0
}

/// `λA + μB` in coordinates scaled by `2^k`: `C(x/2ᵏ, y/2ᵏ)`, vanishing at `2ᵏ·p`.
fn pencil_member(a: [i64; 6], b: [i64; 6], l: i64, m: i64, k: i32) -> Conic {
    let s = [
        pow2(-2 * k),
        pow2(-2 * k),
        pow2(-2 * k),
        pow2(-k),
        pow2(-k),
        1.0,
    ];
    Conic::conic(std::array::from_fn(|i| (l * a[i] + m * b[i]) as f64 * s[i])).unwrap()
}

fn scaled(p: [i64; 2], k: i32) -> [f64; 2] {
    [p[0] as f64 * pow2(k), p[1] as f64 * pow2(k)]
}

/// The points of a line cut against the real roots of `F(t)`, counted independently:
/// as many points as distinct real roots (Sturm), and the multiplicities summing to the
/// roots counted with multiplicity (Sturm on gcd(F, F′, …)). A zero `F`: the line lies
/// on the surface.
fn count_matches<const D: usize>(cut: &LineCut<D>, big_f: &Poly) -> Result<(), TestCaseError> {
    count_matches_where(cut, big_f, None)
}

/// [`count_matches`] over the roots where `keep ≥ 0` (all roots for `None`).
fn count_matches_where<const D: usize>(
    cut: &LineCut<D>,
    big_f: &Poly,
    keep: Option<&Poly>,
) -> Result<(), TestCaseError> {
    if big_f.is_zero() {
        prop_assert!(matches!(cut, LineCut::Contained), "F ≡ 0 but {:?}", cut);
        return Ok(());
    }
    let one = Poly::constant(Rational::from(1));
    let keep = keep.unwrap_or(&one);
    let hits = cut.points();
    let (distinct, total) = if big_f.degree() == Some(0) {
        (0, 0)
    } else {
        (
            big_f.real_roots_where_nonnegative(keep),
            big_f.real_roots_with_multiplicity_where_nonnegative(keep),
        )
    };
    prop_assert_eq!(hits.len(), distinct, "distinct roots of {:?}", big_f);
    let m: u32 = hits.iter().map(|h| h.multiplicity).sum();
    prop_assert_eq!(m as usize, total, "multiplicities of {:?}", big_f);
    Ok(())
}

/// Conic ∩ conic against the resultant `R(x) = Res_y(A, B)` (both conics quadratic in
/// y, so no common point lies at infinity in the y direction): a simple real root of
/// R lies under exactly one common point, of multiplicity 1 and real (its conjugate
/// lies over the same x), so there are at least as many transversal points as simple
/// real roots; and the multiplicities never exceed R's real roots counted with
/// multiplicity.
fn resultant_bounds(
    a: [i64; 6],
    b: [i64; 6],
    points: &[geocert::ops::algebraic::ConicHit],
) -> Result<(), TestCaseError> {
    if a[2] == 0 || b[2] == 0 {
        return Ok(());
    }
    let x = Poly::linear(Rational::new(), Rational::from(1));
    let c = |v: i64| Poly::constant(Rational::from(v));
    // coefficients of y², y, 1 as polynomials in x
    let coeffs = |k: [i64; 6]| {
        let p0 = c(k[0]).mul(&x).mul(&x).add(&c(k[3]).mul(&x)).add(&c(k[5]));
        [c(k[2]), c(k[1]).mul(&x).add(&c(k[4])), p0]
    };
    let ([p2, p1, p0], [q2, q1, q0]) = (coeffs(a), coeffs(b));
    let u = p2.mul(&q0).sub(&p0.mul(&q2));
    let res = u.mul(&u).sub(
        &p2.mul(&q1)
            .sub(&p1.mul(&q2))
            .mul(&p1.mul(&q0).sub(&p0.mul(&q1))),
    );
    if res.is_zero() {
        return Ok(());
    }
    let simple = res.real_roots() - res.gcd(&res.derivative()).real_roots_or_zero();
    let transversal = points.iter().filter(|p| p.multiplicity == 1).count();
    prop_assert!(
        transversal >= simple,
        "{} transversal points, {} simple real roots of {:?}",
        transversal,
        simple,
        res
    );
    let m: u32 = points.iter().map(|p| p.multiplicity).sum();
    prop_assert!(m as usize <= res.real_roots_with_multiplicity());
    Ok(())
}

/// `ALGEBRAIC_CASES` or 256 (each case is microseconds).
fn algebraic_cases() -> u32 {
    std::env::var("ALGEBRAIC_CASES")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(256)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(algebraic_cases()))]

    /// A line through two integer points of a sphere meets it exactly there, at the
    /// chosen parameters, for any power-of-two scaling of the direction.
    #[test]
    fn line_through_two_points_of_a_sphere(
        d in prop::sample::select(vec![3i64, 7, 9, 11]),
        i in 0usize..1000, j in 0usize..1000,
        center in prop::array::uniform3(-50i64..50),
        k in -3i64..3, s in -40i32..40,
    ) {
        let pts = sphere_points(d);
        let (p1, p2) = (pts[i % pts.len()], pts[j % pts.len()]);
        prop_assume!(p1 != p2);
        let c: [f64; 3] = std::array::from_fn(|n| center[n] as f64);
        let sphere = QuadricForm::sphere(c, d as f64).unwrap();
        let dir: [f64; 3] = std::array::from_fn(|n| (p2[n] - p1[n]) as f64 * pow2(s));
        let origin: [f64; 3] = std::array::from_fn(|n| (center[n] + p1[n] - k * (p2[n] - p1[n])) as f64);
        let r = intersect_line_quadric(origin, dir, &sphere).unwrap();
        let hits = r.value.points();
        prop_assert_eq!(hits.len(), 2);
        let want_t = [Rational::from(k) >> s, Rational::from(k + 1) >> s];
        for (h, (p, t)) in hits.iter().zip([(p1, &want_t[0]), (p2, &want_t[1])]) {
            prop_assert_eq!(h.t.exact(), Some(t));
            prop_assert_eq!(h.multiplicity, 1);
            let want: [f64; 3] = std::array::from_fn(|n| (center[n] + p[n]) as f64);
            prop_assert_eq!(h.nearest(), want);
        }
    }

    /// A line through the centre of a sphere meets it at `c ± r·v/|v|` (irrational
    /// unless |v|² is a square), at any magnitude 2^m: each coordinate is the correctly
    /// rounded closed form (MPFR at 600 bits).
    #[test]
    fn diameters_at_any_magnitude(
        center in prop::array::uniform3(-20i64..20), r in 1i64..20,
        v in prop::array::uniform3(-6i64..6), k in -5i64..5, m in -500i32..500,
    ) {
        prop_assume!(v != [0, 0, 0]);
        let s = pow2(m);
        let c: [f64; 3] = center.map(|x| x as f64 * s);
        let sphere = QuadricForm::sphere(c, r as f64 * s).unwrap();
        let origin: [f64; 3] = std::array::from_fn(|n| (center[n] - k * v[n]) as f64 * s);
        let dir = v.map(|x| x as f64);
        let hits = intersect_line_quadric(origin, dir, &sphere).unwrap().value;
        let hits = hits.points();
        prop_assert_eq!(hits.len(), 2);
        let vv: i64 = v.iter().map(|x| x * x).sum();
        let root = mp(vv as f64).sqrt();
        let is_square = (vv as f64).sqrt().fract() == 0.0;
        for (h, sign) in hits.iter().zip([-1.0, 1.0]) {
            prop_assert_eq!(h.multiplicity, 1);
            prop_assert_eq!(h.t.is_rational(), is_square);
            // t = 2^m (k ± r/|v|)
            let t = mp(k as f64).add(&mp(sign * r as f64).div(&root)).mul(&mp(s));
            prop_assert_eq!(h.t.nearest(), nearest_of(&t));
            for n in 0..3 {
                let x = mp(c[n]).add(&mp(sign * (r * v[n]) as f64 * s).div(&root));
                prop_assert_eq!(h.point[n].nearest, nearest_of(&x));
            }
        }
    }

    /// A line tangent to a sphere at an integer point: one double root there.
    #[test]
    fn tangent_lines_to_a_sphere(
        d in prop::sample::select(vec![3i64, 7, 9]),
        i in 0usize..1000, w in prop::array::uniform3(-5i64..5), s in 1i64..9,
    ) {
        let pts = sphere_points(d);
        let p = pts[i % pts.len()];
        let v = [p[1] * w[2] - p[2] * w[1], p[2] * w[0] - p[0] * w[2], p[0] * w[1] - p[1] * w[0]];
        prop_assume!(v != [0, 0, 0]);
        let sphere = QuadricForm::sphere([0.0; 3], d as f64).unwrap();
        let origin: [f64; 3] = std::array::from_fn(|n| (p[n] - s * v[n]) as f64);
        let dir: [f64; 3] = std::array::from_fn(|n| v[n] as f64);
        let r = intersect_line_quadric(origin, dir, &sphere).unwrap();
        let hits = r.value.points();
        prop_assert_eq!(hits.len(), 1);
        prop_assert_eq!(hits[0].multiplicity, 2);
        prop_assert!(hits[0].is_tangent());
        prop_assert_eq!(hits[0].t.exact(), Some(&Rational::from(s)));
        prop_assert_eq!(hits[0].nearest(), [p[0] as f64, p[1] as f64, p[2] as f64]);
    }

    /// Two members of the pencil of conics through four integer points in general
    /// position meet exactly in those four points, each simple.
    #[test]
    fn conics_through_four_points(
        pts in prop::array::uniform4(prop::array::uniform2(-12i64..12)),
        (l1, m1, l2, m2) in (-4i64..5, -4i64..5, -4i64..5, -4i64..5),
        k in -30i32..30,
    ) {
        let [p1, p2, p3, p4] = pts;
        let lines = |a, b| line_through(a, b);
        for (a, b, c) in [(p1, p2, p3), (p1, p2, p4), (p1, p3, p4), (p2, p3, p4)] {
            prop_assume!(!on_line(lines(a, b), c) && a != b);
        }
        prop_assume!(l1 * m2 != l2 * m1);
        let a = line_pair(lines(p1, p2), lines(p3, p4));
        let b = line_pair(lines(p1, p3), lines(p2, p4));
        let r = intersect_conic_conic(&pencil_member(a, b, l1, m1, k), &pencil_member(a, b, l2, m2, k)).unwrap();
        prop_assert_eq!((r.status, r.complete), (Status::Exact, true));
        let mut want: Vec<([f64; 2], u32)> = pts.iter().map(|&p| (scaled(p, k), 1)).collect();
        want.sort_by(|x, y| x.0.partial_cmp(&y.0).unwrap());
        prop_assert_eq!(conic_points(&r.value), want);
    }

    /// Random integer quadric forms and tori against random integer lines: exact, at most
    /// 2 (resp. 4) intersections with multiplicity, and each parameter interval holds a
    /// zero of the restricted equation's MPFR enclosure.
    #[test]
    fn random_lines_against_quadrics_and_tori(
        m in prop::array::uniform6(-3i64..=3), bc in prop::array::uniform4(-3i64..=3),
        o in prop::array::uniform3(-4i64..=4), d in prop::array::uniform3(-3i64..=3),
        (big_r, small_r) in (0i64..4, 1i64..4), axis in prop::array::uniform3(-2i64..=2),
    ) {
        prop_assume!(d != [0, 0, 0]);
        let f = |v: i64| v as f64;
        let a = [[f(m[0]), f(m[1]), f(m[2])], [f(m[1]), f(m[3]), f(m[4])], [f(m[2]), f(m[4]), f(m[5])]];
        let on_line = |t: &Rational| -> [MpfrInterval; 3] {
            let ti = MpfrInterval::from_rational(t, P);
            std::array::from_fn(|i| mp(f(o[i])).add(&ti.mul(&mp(f(d[i])))))
        };
        let contains_zero = |v: &MpfrInterval| *v.lo() <= 0 && *v.hi() >= 0;
        // x(t) = o + t·d as exact polynomials, for the independent root counts
        let x: [Poly; 3] = std::array::from_fn(|i| Poly::linear(Rational::from(o[i]), Rational::from(d[i])));
        let q = |v: i64| Rational::from(v);
        if let Ok(quadric) = QuadricForm::from_f64(a, [f(bc[0]), f(bc[1]), f(bc[2])], f(bc[3])) {
            let r = intersect_line_quadric(o.map(f), d.map(f), &quadric).unwrap();
            prop_assert_eq!(r.status, Status::Exact);
            prop_assert!(r.value.points().iter().map(|h| h.multiplicity).sum::<u32>() <= 2);
            // F(t) = xᵀAx + 2b·x + c: its real roots counted by Sturm sequences
            let aa = [[m[0], m[1], m[2]], [m[1], m[3], m[4]], [m[2], m[4], m[5]]];
            let mut big_f = Poly::constant(q(bc[3]));
            for i in 0..3 {
                big_f = big_f.add(&x[i].scale(&q(2 * bc[i])));
                for j in 0..3 {
                    big_f = big_f.add(&x[i].mul(&x[j]).scale(&q(aa[i][j])));
                }
            }
            count_matches(&r.value, &big_f)?;
            for h in r.value.points() {
                let (lo, hi) = h.t.interval();
                let ti = MpfrInterval::from_rational(&lo, P).hull(&MpfrInterval::from_rational(&hi, P));
                let x: [MpfrInterval; 3] = std::array::from_fn(|i| mp(f(o[i])).add(&ti.mul(&mp(f(d[i])))));
                let mut v = mp(f(bc[3]));
                for i in 0..3 {
                    v = v.add(&mp(2.0 * f(bc[i])).mul(&x[i]));
                    for j in 0..3 {
                        v = v.add(&mp(a[i][j]).mul(&x[i]).mul(&x[j]));
                    }
                }
                prop_assert!(contains_zero(&v));
            }
        }
        if axis != [0, 0, 0] {
            let torus = TorusData::new([0.0; 3], axis.map(f), f(big_r), f(small_r)).unwrap();
            let r = intersect_line_torus(o.map(f), d.map(f), &torus).unwrap();
            prop_assert_eq!(r.status, Status::Exact);
            prop_assert!(r.value.points().iter().map(|h| h.multiplicity).sum::<u32>() <= 4);
            // aa·(|x|² + R² − r²)² − 4R²(aa·|x|² − (x·a)²), or |x|² − r² when R = 0
            let xx = x[0].mul(&x[0]).add(&x[1].mul(&x[1])).add(&x[2].mul(&x[2]));
            let xa = x[0].scale(&q(axis[0])).add(&x[1].scale(&q(axis[1]))).add(&x[2].scale(&q(axis[2])));
            let na: i64 = axis.iter().map(|v| v * v).sum();
            let s = xx.add(&Poly::constant(q(big_r * big_r - small_r * small_r)));
            if big_r == 0 {
                count_matches(&r.value, &s)?;
            } else {
                let big_f = s.mul(&s).scale(&q(na)).sub(&xx.scale(&q(na)).sub(&xa.mul(&xa)).scale(&q(4 * big_r * big_r)));
                // a spindle torus (r > R) is the points at distance r from the core
                // circle: the quartic's inner sheet, where |x|² + R² − r² < 0, is not
                // on it (src/ops/algebraic/line_surface.rs); counted by Tarski queries
                let keep = if small_r > big_r { Some(&s) } else { None };
                count_matches_where(&r.value, &big_f, keep)?;
            }
            let aa = axis.iter().map(|x| f(x * x)).sum::<f64>();
            for h in r.value.points() {
                let (lo, hi) = h.t.interval();
                let q = on_line(&lo).iter().zip(on_line(&hi).iter()).map(|(x, y)| x.hull(y)).collect::<Vec<_>>();
                let qq = q[0].sqr().add(&q[1].sqr()).add(&q[2].sqr());
                let qa = q[0].mul(&mp(f(axis[0]))).add(&q[1].mul(&mp(f(axis[1])))).add(&q[2].mul(&mp(f(axis[2]))));
                let k = mp(f(big_r * big_r - small_r * small_r));
                let s = qq.add(&k);
                let v = mp(aa).mul(&s.sqr()).sub(&mp(f(4 * big_r * big_r)).mul(&mp(aa).mul(&qq).sub(&qa.sqr())));
                let v = if big_r == 0 { s } else { v };
                prop_assert!(contains_zero(&v));
            }
        }
    }

    /// Random small integer conics (often degenerate: line pairs, double lines, points,
    /// empty ones, shared lines): never undecided, at most four points counted with
    /// multiplicity, and each reported box holds a common zero's enclosure — both
    /// equations, evaluated in MPFR intervals over the box, contain 0.
    #[test]
    fn random_integer_conics(a in prop::array::uniform6(-3i64..=3), b in prop::array::uniform6(-3i64..=3)) {
        prop_assume!(a.iter().any(|&x| x != 0) && b.iter().any(|&x| x != 0));
        let conic = |c: [i64; 6]| Conic::conic(c.map(|x| x as f64)).unwrap();
        let r = intersect_conic_conic(&conic(a), &conic(b)).unwrap();
        prop_assert_eq!(r.status, Status::Exact);
        if let ConicCut::Points(points) = &r.value {
            prop_assert!(r.complete);
            prop_assert!(points.iter().map(|p| p.multiplicity).sum::<u32>() <= 4);
            resultant_bounds(a, b, points)?;
            for p in points {
                let iv = |root: &geocert::certify::univariate::RealRoot| {
                    let (lo, hi) = root.interval();
                    MpfrInterval::from_rational(&lo, P).hull(&MpfrInterval::from_rational(&hi, P))
                };
                let (x, y) = (iv(&p.x), iv(&p.y));
                for c in [a, b] {
                    let k = c.map(|v| mp(v as f64));
                    let v = k[0].mul(&x.sqr()).add(&k[1].mul(&x.mul(&y))).add(&k[2].mul(&y.sqr()))
                        .add(&k[3].mul(&x)).add(&k[4].mul(&y)).add(&k[5]);
                    prop_assert!(*v.lo() <= 0 && *v.hi() >= 0);
                }
            }
        }
    }

    /// Conics of the pencil tangent to a line ℓ at P₁ and through P₃, P₄ meet with
    /// multiplicity 2 at P₁ and 1 at P₃, P₄.
    #[test]
    fn conics_tangent_at_a_point(
        pts in prop::array::uniform3(prop::array::uniform2(-12i64..12)),
        dir in prop::array::uniform2(-5i64..5),
        (l1, m1, l2, m2) in (1i64..5, -4i64..5, -4i64..5, -4i64..5),
        k in -30i32..30,
    ) {
        let [p1, p3, p4] = pts;
        let q = [p1[0] + dir[0], p1[1] + dir[1]];
        prop_assume!(dir != [0, 0] && p1 != p3 && p1 != p4 && p3 != p4);
        let ell = line_through(p1, q);
        prop_assume!(!on_line(ell, p3) && !on_line(ell, p4) && !on_line(line_through(p3, p4), p1));
        prop_assume!(l2 != 0 && l1 * m2 != l2 * m1);
        let a = line_pair(ell, line_through(p3, p4));
        let b = line_pair(line_through(p1, p3), line_through(p1, p4));
        let r = intersect_conic_conic(&pencil_member(a, b, l1, m1, k), &pencil_member(a, b, l2, m2, k)).unwrap();
        let mut want = vec![(scaled(p1, k), 2), (scaled(p3, k), 1), (scaled(p4, k), 1)];
        want.sort_by(|x, y| x.0.partial_cmp(&y.0).unwrap());
        prop_assert_eq!(conic_points(&r.value), want);
    }
}

#[test]
fn ellipsoid_in_any_frame_agrees_with_the_orthonormal_one_and_vanishes_on_it() {
    use geocert::ops::algebraic::QuadricForm;
    use rug::Rational;
    let standard = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    let a = QuadricForm::ellipsoid([1.0, 2.0, 3.0], standard, [3.0, 2.0, 0.5])
        .expect("valid")
        .expect("orthonormal");
    let b =
        QuadricForm::ellipsoid_in_frame([1.0, 2.0, 3.0], [0.0, 0.0, 7.0], None, [3.0, 2.0, 0.5])
            .expect("valid");
    assert_eq!(a, b);
    // Axis (3, 4, 0), c = 5 along it: (3, 4, 0) lies on the surface; X = +z with a = 3:
    // (0, 0, 3) too; Y = (−4, 3, 0)/5·... with b = 5: (−4, 3, 0).
    let e = QuadricForm::ellipsoid_in_frame([0.0; 3], [3.0, 4.0, 0.0], None, [3.0, 5.0, 5.0])
        .expect("valid");
    let at = |x: [i32; 3]| e.eval(&x.map(Rational::from));
    assert_eq!(at([3, 4, 0]), 0);
    assert_eq!(at([0, 0, 3]), 0);
    assert_eq!(at([-4, 3, 0]), 0);
    assert!(at([0, 0, 0]) < 0);
}
