//! Facts about the curve primitives that hold independently of the code (OPERATIONS.md
//! §1.1–§1.2, §1.5; CASES.md frames and parametrisations): the rational NURBS circle
//! stays on the circle, a Bézier curve equals its NURBS form, de Boor and Cox–de Boor
//! agree, the frame rule, curvature and torsion of analytic curves, the implicit
//! equations of the conics, derived curves, periodic and closed NURBS, conic2.

mod curve_support;

use curve_support::*;
use geocert::curve::bspline::{cox_de_boor, cox_de_boor_derivative};
use geocert::curve::{
    conic_arc, Analytic, Analytic2, AnyCurve3, Bezier, Conic2, ConicKind, Curve, Frame, Line,
    NurbsCurve, PlaneCurve, Reparametrised, Segment, Shape, SpaceCurve, StepHint,
};
use geocert::num::{Arith, IntervalLike, MpfrInterval, Real};
use geocert::surface::Implicit;
use std::f64::consts::{FRAC_1_SQRT_2, PI, TAU};

fn nurbs_circle() -> NurbsCurve<2> {
    let w = FRAC_1_SQRT_2;
    NurbsCurve::new(
        2,
        vec![0.0, 0.0, 0.0, 1.0, 1.0, 2.0, 2.0, 3.0, 3.0, 4.0, 4.0, 4.0],
        vec![
            [1.0, 0.0],
            [1.0, 1.0],
            [0.0, 1.0],
            [-1.0, 1.0],
            [-1.0, 0.0],
            [-1.0, -1.0],
            [0.0, -1.0],
            [1.0, -1.0],
            [1.0, 0.0],
        ],
        Some(vec![1.0, w, 1.0, w, 1.0, w, 1.0, w, 1.0]),
        None,
    )
    .unwrap()
}

#[test]
fn rational_quadratic_nurbs_circle_stays_at_radius_one() {
    let c = nurbs_circle();
    assert!(c.is_closed() && !c.is_periodic());
    let mut rng = Rng::new(3);
    for i in 0..=400 {
        let t = if i < 9 {
            i as f64 * 0.5
        } else {
            rng.range(0.0, 4.0)
        };
        let p = c.point(&t);
        let r = (p[0] * p[0] + p[1] * p[1]).sqrt();
        assert!((r - 1.0).abs() <= 4e-16, "t = {t}: radius {r}");
        // The rounding comes from the weight √2/2 only: at 200 bits |c|² − 1 is as small.
        let m = c.point(&MpfrInterval::point(t, 200));
        let dev = (m[0].sqr() + m[1].sqr() - m[0].lift(1.0)).mag();
        assert!(dev <= 4e-16, "t = {t}: |c|² − 1 = {dev}");
        // The curve is a circle, so c' ⟂ c.
        let d = &c.jet(&t, 1)[1];
        assert!((p[0] * d[0] + p[1] * d[1]).abs() <= 1e-15 * (d[0].abs() + d[1].abs()));
    }
    // The conic arc with w = cos(φ/2) and P₁ at the tangents' intersection is circular.
    let arc = conic_arc([1.0, 0.0], [1.0, 1.0], [0.0, 1.0], FRAC_1_SQRT_2).unwrap();
    for i in 0..=50 {
        let p = arc.point(&(i as f64 / 50.0));
        assert!(((p[0] * p[0] + p[1] * p[1]).sqrt() - 1.0).abs() <= 4e-16);
    }
}

/// A Bézier curve of degree n is the NURBS curve with knots 0ⁿ⁺¹ 1ⁿ⁺¹ on the same
/// points and weights; at 200 bits the two evaluations (de Casteljau and Cox–de Boor)
/// of every derivative overlap.
#[test]
fn bezier_equals_its_nurbs_form() {
    for (name, c) in space_curves() {
        let AnyCurve3::Bezier(b) = c else { continue };
        let n = b.degree();
        let knots = [vec![0.0; n + 1], vec![1.0; n + 1]].concat();
        let nurbs = NurbsCurve::new(
            n,
            knots,
            b.points().to_vec(),
            b.weights().map(<[f64]>::to_vec),
            None,
        )
        .unwrap();
        let mut rng = Rng::new(11);
        for _ in 0..50 {
            let t = rng.range(0.0, 1.0);
            let (jb, jn) = (b.jet(&t, 3), nurbs.jet(&t, 3));
            let (mb, mn) = (
                b.jet(&MpfrInterval::point(t, 200), 3),
                nurbs.jet(&MpfrInterval::point(t, 200), 3),
            );
            for k in 0..=3 {
                for i in 0..3 {
                    let scale = 1.0 + jb[k][i].abs();
                    assert!(
                        (jb[k][i] - jn[k][i]).abs() <= 1e-12 * scale,
                        "{name} jet[{k}][{i}] at {t}"
                    );
                    assert!(
                        !mb[k][i].intersection(&mn[k][i]).is_empty(),
                        "{name} 200-bit jet[{k}][{i}] at {t}"
                    );
                    assert!(mb[k][i].wid() < 1e-50 * scale);
                }
            }
        }
    }
}

#[test]
fn de_boor_and_cox_de_boor_agree() {
    for (name, c) in space_curves() {
        let AnyCurve3::Nurbs(n) = c else { continue };
        let (knots, p) = (n.knots(), n.degree());
        let weights = n
            .weights()
            .map_or(vec![1.0; n.points().len()], <[f64]>::to_vec);
        let mut rng = Rng::new(5);
        let (lo, hi) = n.domain();
        for _ in 0..100 {
            let t = rng.range(lo, hi);
            // Point: literal (1.11), de Boor, and the basis of the evaluator.
            let mut num = [0.0; 3];
            let mut den = 0.0;
            let mut unity = 0.0;
            for (i, pt) in n.points().iter().enumerate() {
                let b = cox_de_boor(knots, i, p + 1, t);
                unity += b;
                den += b * weights[i];
                for k in 0..3 {
                    num[k] += b * weights[i] * pt[k];
                }
            }
            assert!(
                (unity - 1.0).abs() < 1e-14,
                "{name}: partition of unity at {t}: {unity}"
            );
            let by_cox = num.map(|x| x / den);
            let by_de_boor = n.point_de_boor(&t);
            let by_jet = n.point(&t);
            for k in 0..3 {
                assert!(
                    (by_cox[k] - by_de_boor[k]).abs() < 1e-13 * (1.0 + by_cox[k].abs()),
                    "{name} at {t}"
                );
                assert!(
                    (by_cox[k] - by_jet[k]).abs() < 1e-13 * (1.0 + by_cox[k].abs()),
                    "{name} at {t}"
                );
            }
            // Basis derivatives: (1.12) literally against the evaluator's table.
            let kv = n.knot_vector();
            let s = kv.find_span(t);
            let ders = kv.basis_derivatives(s, &t, 1);
            for (j, i) in (s - p..=s).enumerate() {
                assert!((ders[0][j] - cox_de_boor(knots, i, p + 1, t)).abs() < 1e-14);
                let d = cox_de_boor_derivative(knots, i, p + 1, t);
                assert!(
                    (ders[1][j] - d).abs() < 1e-12 * (1.0 + d.abs()),
                    "{name}: N'_{i} at {t}"
                );
            }
            // In 200-bit intervals the basis sums to an interval containing 1.
            let m = kv.basis_derivatives(s, &MpfrInterval::point(t, 200), 0);
            let sum = m[0].iter().skip(1).fold(m[0][0].clone(), |a, b| a + b);
            assert!(sum.contains_value(1.0), "{name}: {sum:?}");
        }
    }
}

#[test]
fn frame_rule_of_cases_md() {
    let axes =
        |axis: [f64; 3], r: Option<[f64; 3]>| Frame::new([0.0; 3], axis, r).unwrap().axes(&0.0f64);
    assert_eq!(
        axes([0.0, 0.0, 1.0], None),
        [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]
    );
    assert_eq!(
        axes([0.0, 0.0, 7.0], None),
        [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]
    );
    assert_eq!(
        axes([0.0, 0.0, -1.0], None),
        [[1.0, 0.0, 0.0], [0.0, -1.0, 0.0], [0.0, 0.0, -1.0]]
    );
    // Ties: x and z are both least aligned with +y; x comes first.
    assert_eq!(
        axes([0.0, 2.0, 0.0], None),
        [[1.0, 0.0, 0.0], [0.0, 0.0, -1.0], [0.0, 1.0, 0.0]]
    );
    // ref is made orthogonal to Z and normalised.
    assert_eq!(
        axes([0.0, 0.0, 3.0], Some([2.0, 0.0, 5.0])),
        [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]
    );
    assert_eq!(
        axes([0.0, 0.0, 1.0], Some([0.0, 4.0, 0.0])),
        [[0.0, 1.0, 0.0], [-1.0, 0.0, 0.0], [0.0, 0.0, 1.0]]
    );
    // Axis (1,1,1): X = (2,−1,−1)/√6 from e = x; at 200 bits the frame encloses the exact
    // orthonormal one.
    let f = Frame::new([0.0; 3], [1.0, 1.0, 1.0], None).unwrap();
    let [x, y, z] = f.axes(&MpfrInterval::point(0.0, 200));
    let exact_x = [2.0, -1.0, -1.0].map(|v: f64| v / 6f64.sqrt());
    for i in 0..3 {
        assert!((x[i].mid() - exact_x[i]).abs() < 4e-16);
    }
    let dot = |a: &[MpfrInterval; 3], b: &[MpfrInterval; 3]| {
        a[0].clone() * &b[0] + a[1].clone() * &b[1] + a[2].clone() * &b[2]
    };
    for (a, b, v) in [
        (&x, &x, 1.0),
        (&y, &y, 1.0),
        (&z, &z, 1.0),
        (&x, &y, 0.0),
        (&y, &z, 0.0),
        (&x, &z, 0.0),
    ] {
        let d = dot(a, b);
        assert!(d.contains_value(v) && d.wid() < 1e-55, "{d:?}");
    }
    // Y = Z × X (right-handed): det[X, Y, Z] = 1.
    let det = x[0].clone() * (y[1].clone() * &z[2] - y[2].clone() * &z[1])
        - x[1].clone() * (y[0].clone() * &z[2] - y[2].clone() * &z[0])
        + x[2].clone() * (y[0].clone() * &z[1] - y[1].clone() * &z[0]);
    assert!(det.contains_value(1.0));
}

#[test]
fn analytic_curves_satisfy_their_equations() {
    let std = Frame::standard([0.0; 3]).unwrap();
    let mut rng = Rng::new(9);
    let make = |s: Shape, d: Option<(f64, f64)>| Analytic::new(std.clone(), s, d).unwrap();
    let ellipse = make(Shape::Ellipse { a: 3.0, b: 2.0 }, None);
    let hyp = make(
        Shape::Hyperbola {
            a: 2.0,
            b: 0.5,
            second_branch: false,
        },
        Some((-2.0, 2.0)),
    );
    let hyp2 = make(
        Shape::Hyperbola {
            a: 2.0,
            b: 0.5,
            second_branch: true,
        },
        Some((-2.0, 2.0)),
    );
    let par = make(Shape::Parabola { p: 0.75 }, Some((-3.0, 3.0)));
    for _ in 0..100 {
        let t = rng.range(-2.0, 2.0);
        let e = ellipse.point(&t);
        assert!((e[0] * e[0] / 9.0 + e[1] * e[1] / 4.0 - 1.0).abs() < 1e-15 && e[2] == 0.0);
        let h = hyp.point(&t);
        assert!((h[0] * h[0] / 4.0 - h[1] * h[1] / 0.25 - 1.0).abs() < 1e-13 * (1.0 + h[0] * h[0]));
        assert!(h[0] > 0.0 && hyp2.point(&t)[0] < 0.0 && hyp2.point(&t)[1] == h[1]);
        let p = par.point(&t);
        assert!((p[1] * p[1] - 2.0 * 0.75 * p[0]).abs() < 1e-14 * (1.0 + p[0].abs()));
    }
    // Foci of the ellipse: distances sum to 2a.
    let f = (9.0f64 - 4.0).sqrt();
    for i in 0..20 {
        let e = ellipse.point(&(i as f64 * 0.3));
        let d =
            ((e[0] - f).powi(2) + e[1] * e[1]).sqrt() + ((e[0] + f).powi(2) + e[1] * e[1]).sqrt();
        assert!((d - 6.0).abs() < 1e-14);
    }
    // A full circle is closed and periodic; an arc of it is neither.
    let circle = make(Shape::Circle { radius: 2.0 }, None);
    assert!(circle.is_closed() && circle.is_periodic() && circle.domain() == (0.0, TAU));
    let arc = make(Shape::Circle { radius: 2.0 }, Some((0.5, 2.0)));
    assert!(!arc.is_closed() && !arc.is_periodic());
}

#[test]
fn curvature_and_torsion_of_analytic_curves() {
    let f = Frame::new([1.0, 2.0, 3.0], [1.0, -2.0, 0.5], Some([0.0, 1.0, 1.0])).unwrap();
    let circle = Analytic::new(f.clone(), Shape::Circle { radius: 2.0 }, None).unwrap();
    // k = 1/2 exactly representable: the 200-bit enclosure contains it.
    let k = circle.curvature(&MpfrInterval::point(0.9, 200));
    assert!(k.contains_value(0.5) && k.wid() < 1e-50);
    // c(0) = center + r X.
    let [x, _, _] = f.axes(&0.0f64);
    let p0 = circle.point(&0.0f64);
    for i in 0..3 {
        assert!((p0[i] - ([1.0, 2.0, 3.0][i] + 2.0 * x[i])).abs() < 1e-15);
    }
    // Helix: k = r/(r² + c²), ϰ = c/(r² + c²), c = pitch/2π; the Darboux vector is
    // constant, of length √(k² + ϰ²) = 1/√(r² + c²).
    let (r, pitch) = (1.5, 4.0);
    let helix = Analytic::new(f, Shape::Helix { radius: r, pitch }, Some((0.0, 20.0))).unwrap();
    let c = pitch / TAU;
    for t in [0.1, 2.0, 7.5] {
        assert!((helix.curvature(&t) - r / (r * r + c * c)).abs() < 1e-15);
        assert!((helix.torsion_at(&t) - c / (r * r + c * c)).abs() < 1e-15);
        let w = helix.darboux_at(&t);
        assert!(
            ((w[0] * w[0] + w[1] * w[1] + w[2] * w[2]).sqrt() - 1.0 / (r * r + c * c).sqrt()).abs()
                < 1e-15
        );
        // Frenet frame is orthonormal: n̂ ⟂ t̂, b̂.
        let (tt, n, b) = (
            helix.unit_tangent_at(&t),
            helix.principal_normal_at(&t),
            helix.binormal_at(&t),
        );
        let dot = |a: [f64; 3], b: [f64; 3]| a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
        assert!(
            dot(tt, n).abs() < 1e-15 && dot(n, b).abs() < 1e-15 && (dot(n, n) - 1.0).abs() < 1e-15
        );
    }
    // 2D: the counter-clockwise circle2 has signed curvature +1/r and its normal (1.4)
    // points to the center.
    let c2 = Analytic2::new([1.0, -1.0], Shape::Circle { radius: 4.0 }, None).unwrap();
    assert_eq!(c2.signed_curvature_at(&0.0f64), 0.25);
    assert_eq!(c2.unit_normal_at(&0.0f64), [-1.0, 0.0]);
    let rev = Reparametrised::reversed(c2).unwrap();
    assert_eq!(rev.signed_curvature_at(&1.0f64), -0.25);
}

#[test]
fn derived_curves_map_parameters() {
    let f = Frame::new([0.0; 3], [0.0, 1.0, 1.0], None).unwrap();
    let circle = Analytic::new(f, Shape::Circle { radius: 3.0 }, None).unwrap();
    // Trimmed across the seam of a closed curve: the base parameter wraps.
    let trimmed = Reparametrised::restricted(circle.clone(), 5.0, 8.0).unwrap();
    assert!(!trimmed.is_closed());
    for t in [5.0, 6.0, 6.5, 8.0] {
        let (a, b) = (trimmed.point(&t), circle.point(&(t - TAU)));
        assert!((0..3).all(|i| (a[i] - b[i]).abs() < 1e-14));
    }
    // Reversed: c(t_min + t_max − τ), first derivative negated, second unchanged; closed
    // stays closed.
    let rev = Reparametrised::reversed(circle.clone()).unwrap();
    assert!(rev.is_closed() && rev.is_periodic());
    let (j, jb) = (rev.jet(&1.0f64, 2), circle.jet(&(TAU - 1.0), 2));
    for i in 0..3 {
        assert_eq!(j[0][i], jb[0][i]);
        assert_eq!(j[1][i], -jb[1][i]);
        assert_eq!(j[2][i], jb[2][i]);
    }
    // Reparametrised onto [0, 1]: derivatives scale by (t_max − t_min).
    let re = Reparametrised::reparametrised(circle.clone(), 0.0, 1.0).unwrap();
    let (j, jb) = (re.jet(&0.25f64, 1), circle.jet(&(TAU / 4.0), 1));
    assert!((0..3).all(|i| (j[1][i] - TAU * jb[1][i]).abs() < 1e-14));
    assert!(re.is_closed());
    assert_eq!(re.step_hint(0.3), StepHint::Angular { rate: TAU });
    // A trim outside a non-periodic base is rejected, naming the end.
    let seg = Segment::new([0.0, 0.0, 0.0], [1.0, 1.0, 1.0], None).unwrap();
    let e = Reparametrised::trimmed(seg, 0.5, 1.0, 0.0, 0.75).unwrap_err();
    assert_eq!(
        (e.kind(), e.field()),
        ("parameter_outside_domain", "domain[1]")
    );
    // Lines: unbounded by default, one walking step.
    let line = Line::new([0.0, 0.0, 0.0], [1.0, 0.0, 0.0], None).unwrap();
    assert_eq!(line.domain(), (f64::NEG_INFINITY, f64::INFINITY));
    assert_eq!(line.step_hint(0.0), StepHint::Whole);
}

#[test]
fn periodic_nurbs_is_smooth_across_its_seam() {
    let c = space_curves()
        .into_iter()
        .find(|(n, _)| *n == "periodic-nurbs")
        .unwrap()
        .1;
    assert!(c.is_closed() && c.is_periodic());
    let (lo, hi) = c.domain();
    assert_eq!((lo, hi), (3.0, 9.0));
    // Degree 3: value, first and second derivatives match at the ends.
    let (a, b) = (c.jet(&lo, 2), c.jet(&hi, 2));
    for k in 0..=2 {
        for i in 0..3 {
            assert!(
                (a[k][i] - b[k][i]).abs() < 1e-12 * (1.0 + a[k][i].abs()),
                "jet[{k}][{i}]"
            );
        }
    }
    for t in [3.3, 5.0, 8.9] {
        let (x, y) = (c.point(&t), c.point(&(t + 6.0)));
        assert!((0..3).all(|i| (x[i] - y[i]).abs() < 1e-12));
    }
    // A clamped B-spline whose ends meet is closed, not periodic.
    let clamped = NurbsCurve::new(
        2,
        vec![0.0, 0.0, 0.0, 1.0, 2.0, 2.0, 2.0],
        vec![[0.0, 0.0], [1.0, 1.0], [2.0, 0.0], [0.0, 0.0]],
        None,
        None,
    )
    .unwrap();
    assert!(clamped.is_closed() && !clamped.is_periodic());
}

#[test]
fn conic2_invariants_and_jet() {
    let circle = Conic2::new([1.0, 0.0, 1.0, 0.0, 0.0, -1.0]).unwrap();
    assert_eq!(circle.kind(), ConicKind::Elliptic { imaginary: false });
    let j = circle.implicit_jet(&[3.0, 4.0], 2);
    assert_eq!(j.value, 24.0);
    assert_eq!(j.gradient, Some([6.0, 8.0]));
    assert_eq!(j.hessian, Some([[2.0, 0.0], [0.0, 2.0]]));
    // Side convention of §1.4: negative inside.
    assert!(circle.implicit_jet(&[0.1, 0.2], 0).value < 0.0);
    let imaginary = Conic2::new([1.0, 0.0, 1.0, 0.0, 0.0, 1.0]).unwrap();
    assert_eq!(imaginary.kind(), ConicKind::Elliptic { imaginary: true });
    assert_eq!(
        Conic2::new([0.0, 1.0, 0.0, 0.0, 0.0, -1.0]).unwrap().kind(),
        ConicKind::Hyperbolic
    );
    assert_eq!(
        Conic2::new([0.0, 0.0, 1.0, -1.0, 0.0, 0.0]).unwrap().kind(),
        ConicKind::Parabolic
    );
    // x² − y² = 0 is two lines: Δ = 0 exactly; x² − y² − 10⁻³⁰⁰ is not degenerate.
    assert!(Conic2::new([1.0, 0.0, -1.0, 0.0, 0.0, 0.0])
        .unwrap()
        .is_degenerate());
    assert!(!Conic2::new([1.0, 0.0, -1.0, 0.0, 0.0, -1e-300])
        .unwrap()
        .is_degenerate());
    // Intervals enclose: over the box [0.9, 1.1]² the value encloses every F(x, y).
    let b = MpfrInterval::from_bounds(0.9, 1.1, 128);
    let j = circle.implicit_jet(&[b.clone(), b], 1);
    for (x, y) in [(0.9, 0.9), (1.1, 1.0), (1.0, 1.1), (1.1, 1.1)] {
        assert!(j.value.contains_value(x * x + y * y - 1.0));
    }
    // (I, δ, Δ) = (2, 1, −1) for the unit circle.
    let (i, d, big) = circle.invariants(&0.0f64);
    assert_eq!((i, d, big), (2.0, 1.0, -1.0));
    let _ = PI;
}

#[test]
fn bezier_sub_domain_and_conic_arc_weights() {
    let b = Bezier::new(
        vec![[0.0, 0.0], [1.0, 1.0], [2.0, 0.0]],
        None,
        Some((0.25, 0.75)),
    )
    .unwrap();
    assert_eq!(b.domain(), (0.25, 0.75));
    // The quadratic through (0,0),(1,1),(2,0) has its apex (1, ½) at t = ½.
    assert_eq!(b.point(&0.5f64), [1.0, 0.5]);
    assert_eq!(b.jet(&0.5f64, 2)[2], [0.0, -4.0]);
    // w = 1 makes the conic arc the parabola of the polynomial Bézier.
    let arc = conic_arc([0.0, 0.0], [1.0, 1.0], [2.0, 0.0], 1.0).unwrap();
    let j = arc.jet(&0.3f64, 3);
    let jp = b.jet(&0.3f64, 3);
    assert!((0..4).all(|k| (0..2).all(|i| (j[k][i] - jp[k][i]).abs() < 1e-14)));
}
