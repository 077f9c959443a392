//! The curve walk of OPERATIONS.md §2.1/§2.3: the step values of §16.1, the clamps
//! and shortcuts, the traversal, and the proven step's bound against the turning angle
//! measured independently.

mod curve_support;

use curve_support::*;
use geocert::curve::{
    Analytic, Bezier, Curve, Frame, Line, NurbsCurve, Segment, Shape, SpaceCurve,
};
use geocert::num::{Interval, MpfrInterval};
use geocert::walk::{
    curve_step, proven_curve_step, turning_angle_step, turning_step_at, CurveWalk, ProvenCurveWalk,
    StepClamps, WalkOptions,
};
use std::f64::consts::{PI, TAU};

fn circle(radius: f64) -> Analytic {
    let f = Frame::new([1.0, 2.0, -1.0], [0.0, 1.0, 2.0], None).unwrap();
    Analytic::new(f, Shape::Circle { radius }, None).unwrap()
}

fn opts(delta_alpha: f64) -> WalkOptions {
    WalkOptions {
        delta_alpha,
        ..WalkOptions::default()
    }
}

/// §16.1: a circle of any radius, angular parameter: (2.1) gives Δt = Δα
/// (R = 3, t = 0.7, Δα = π/10 → 0.3141592654); the shortcut gives it exactly.
#[test]
fn ops_16_1_circle_step_is_delta_alpha() {
    let c = circle(3.0);
    let by_formula = turning_step_at(&c, 0.7, &opts(PI / 10.0), None);
    assert!((by_formula - 0.3141592654).abs() < 1e-9, "{by_formula}");
    assert_eq!(curve_step(&c, 0.7, &opts(PI / 10.0)), PI / 10.0);
    // The documented range [π/20, π/10] = [0.1570796327, 0.3141592654].
    for (alpha, expected) in [(PI / 20.0, 0.1570796327), (PI / 10.0, 0.3141592654)] {
        for r in [0.01, 1.0, 3.0, 250.0] {
            let s = turning_step_at(&circle(r), 0.7, &opts(alpha), None);
            assert!((s - expected).abs() < 1e-9, "r = {r}: {s}");
        }
    }
}

/// (2.1) is exact for any parametrisation of a circle: on the rational quadratic
/// NURBS circle (speed not constant) `Δt = Δα/(k|c'|)` with k = 1/R.
#[test]
fn formula_step_on_a_rational_circle_turns_by_delta_alpha() {
    let w = std::f64::consts::FRAC_1_SQRT_2;
    let r = 2.0;
    let c = NurbsCurve::new(
        2,
        vec![0.0, 0.0, 0.0, 1.0, 1.0, 2.0, 2.0, 3.0, 3.0, 4.0, 4.0, 4.0],
        vec![
            [r, 0.0],
            [r, r],
            [0.0, r],
            [-r, r],
            [-r, 0.0],
            [-r, -r],
            [0.0, -r],
            [r, -r],
            [r, 0.0],
        ],
        Some(vec![1.0, w, 1.0, w, 1.0, w, 1.0, w, 1.0]),
        None,
    )
    .unwrap();
    let mut rng = Rng::new(7);
    for _ in 0..50 {
        let t = rng.range(0.0, 4.0);
        let speed = {
            let d = &c.jet(&t, 1)[1];
            (d[0] * d[0] + d[1] * d[1]).sqrt()
        };
        let expected = (PI / 10.0) / (speed / r);
        let s = turning_step_at(&c, t, &opts(PI / 10.0), None);
        assert!(
            (s - expected.min(0.5)).abs() < 1e-12 * expected,
            "{t}: {s} vs {expected}"
        );
        // With the knot clamp: at most half of the unit knot span.
        assert!(curve_step(&c, t, &opts(PI / 10.0)) <= 0.5);
    }
}

#[test]
fn clamps_straight_and_special_point_rules() {
    // Collinear control points: straight, so Δt_max = range/8 ...
    let straight = Bezier::new(vec![[0.0, 0.0], [1.0, 1.0], [3.0, 3.0]], None, None).unwrap();
    assert_eq!(
        curve_step(&straight, 0.3, &WalkOptions::default()),
        1.0 / 8.0
    );
    // ... and a NURBS is further clamped to half its knot span.
    let nurbs = NurbsCurve::new(
        2,
        vec![0.0, 0.0, 0.0, 0.1, 1.0, 1.0, 1.0],
        vec![[0.0, 0.0], [1.0, 1.0], [2.0, 2.0], [4.0, 4.0]],
        None,
        None,
    )
    .unwrap();
    assert_eq!(curve_step(&nurbs, 0.05, &WalkOptions::default()), 0.05);
    assert_eq!(curve_step(&nurbs, 0.5, &WalkOptions::default()), 0.125);
    // A cusp (c'(½) = 0): the special point rule gives Δt_min = range·10⁻⁴.
    let cusp = Bezier::new(
        vec![[0.0, 0.0], [1.0, 1.0], [0.0, 1.0], [1.0, 0.0]],
        None,
        None,
    )
    .unwrap();
    let o = WalkOptions {
        delta_len: 1e-9,
        ..WalkOptions::default()
    };
    assert_eq!(curve_step(&cusp, 0.5, &o), 1e-4);
    // Sharp turn: the formula step falls below Δt_min and is clamped up to it.
    let clamps = StepClamps::for_range(2.0);
    assert_eq!(turning_angle_step(0.1, 1.0, 1e9, 1e-10, clamps), 2e-4);
    assert_eq!(turning_angle_step(0.1, 1.0, 0.0, 1e-10, clamps), 0.25);
    assert_eq!(turning_angle_step(0.1, 1.0, 1.0, 1e-10, clamps), 0.1);
}

#[test]
fn shortcuts_for_lines_segments_and_helices() {
    let seg = Segment::new([0.0, 0.0, 0.0], [1.0, 2.0, 3.0], None).unwrap();
    let samples: Vec<f64> = CurveWalk::new(&seg, WalkOptions::default())
        .unwrap()
        .map(|s| s.t)
        .collect();
    assert_eq!(samples, vec![0.0, 1.0]);
    let line = Line::new([0.0, 0.0], [1.0, 0.0], Some((-3.0, 5.0))).unwrap();
    assert_eq!(curve_step(&line, 0.0, &WalkOptions::default()), 8.0);
    let f = Frame::new([0.0; 3], [0.0, 0.0, 1.0], None).unwrap();
    let helix = Analytic::new(
        f,
        Shape::Helix {
            radius: 2.0,
            pitch: 3.0,
        },
        Some((0.0, 20.0)),
    )
    .unwrap();
    assert_eq!(curve_step(&helix, 4.0, &opts(PI / 20.0)), PI / 20.0);
}

#[test]
fn traversal_starts_at_t_min_and_ends_exactly_at_t_max() {
    for (name, c) in space_curves() {
        let (lo, hi) = c.domain();
        let samples: Vec<_> = CurveWalk::new(&c, WalkOptions::default())
            .unwrap()
            .collect();
        assert_eq!(samples[0].t, lo, "{name}");
        assert_eq!(samples.last().unwrap().t, hi, "{name}");
        for w in samples.windows(2) {
            assert_eq!(w[1].t, (w[0].t + w[0].step).min(hi), "{name}");
            assert!(
                w[0].step <= (hi - lo) / 8.0 || w[0].step == hi - lo,
                "{name}"
            );
            assert!(
                w[0].step >= (hi - lo) * 1e-4 * (1.0 - 1e-12)
                    || matches!(c, geocert::curve::AnyCurve3::Nurbs(_)),
                "{name}"
            );
        }
    }
    // A full circle at Δα = π/10: twenty steps of exactly π/10 (plus at most a rounding
    // remnant), the last sample exactly 2π.
    let c = circle(5.0);
    let samples: Vec<_> = CurveWalk::new(&c, opts(PI / 10.0)).unwrap().collect();
    assert!(
        samples.len() == 21 || samples.len() == 22,
        "{}",
        samples.len()
    );
    assert!(samples.iter().all(|s| s.step == PI / 10.0));
    assert_eq!(samples.last().unwrap().t, TAU);
}

#[test]
fn walk_errors_are_typed() {
    let line = Line::new([0.0, 0.0, 0.0], [1.0, 0.0, 0.0], None).unwrap();
    let e = CurveWalk::new(&line, WalkOptions::default()).err().unwrap();
    assert_eq!((e.kind(), e.field()), ("unsupported", "domain"));
    let e = CurveWalk::new(&circle(1.0), opts(0.0)).err().unwrap();
    assert_eq!((e.kind(), e.field()), ("invalid_value", "delta_alpha"));
    let e = CurveWalk::new(&circle(1.0), opts(f64::NAN)).err().unwrap();
    assert_eq!((e.kind(), e.field()), ("non_finite", "delta_alpha"));
}

/// The tangent's turning between two parameters, measured from below by the sum of
/// the angles between tangents at many points (each ≤ the turning in between).
fn measured_turning(c: &impl SpaceCurve, a: f64, b: f64) -> f64 {
    let n = 400;
    let tan = |t: f64| c.unit_tangent_at(&t);
    let mut sum = 0.0;
    // Inside the open step only: a tangent break may sit at either end.
    let at = |i: usize| a + (b - a) * (i as f64 + 0.5) / n as f64;
    let mut prev = tan(at(0));
    for i in 1..n {
        let cur = tan(at(i));
        let dot: f64 = (0..3).map(|k| prev[k] * cur[k]).sum();
        let cross = [
            prev[1] * cur[2] - prev[2] * cur[1],
            prev[2] * cur[0] - prev[0] * cur[2],
            prev[0] * cur[1] - prev[1] * cur[0],
        ];
        let sin = (cross[0] * cross[0] + cross[1] * cross[1] + cross[2] * cross[2]).sqrt();
        sum += sin.atan2(dot);
        prev = cur;
    }
    sum
}

#[test]
fn proven_steps_bound_the_true_turning_angle() {
    let alpha = PI / 10.0;
    // A circle turns by exactly the parameter step: a proven step cannot exceed Δα.
    let c = circle(3.0);
    let s = proven_curve_step(&c, 0.7, alpha, &Interval::ZERO).unwrap();
    assert!(
        s.t_end - s.t_start <= alpha && s.t_end - s.t_start > 0.5 * alpha,
        "{s:?}"
    );
    assert!(s.turning_bound <= alpha);
    for (name, c) in space_curves() {
        let mut steps = 0;
        let mut t = c.domain().0;
        for step in ProvenCurveWalk::new(&c, alpha, Interval::ZERO).unwrap() {
            let step = step.unwrap_or_else(|t| panic!("{name}: no proven step from {t}"));
            assert_eq!(step.t_start, t, "{name}");
            if let Some((lo, hi)) = step.corner {
                assert_eq!(lo, step.t_end, "{name}");
                assert!(c.tangent_breaks().contains(&(lo, hi)), "{name}");
            }
            assert!(step.turning_bound <= alpha, "{name}");
            let m = measured_turning(&c, step.t_start, step.t_end);
            assert!(
                m <= step.turning_bound + 1e-9,
                "{name}: turned {m} > bound {}",
                step.turning_bound
            );
            t = step.corner.map_or(step.t_end, |c| c.1);
            steps += 1;
            assert!(steps < 10_000, "{name}: too many steps");
        }
        assert_eq!(t, c.domain().1, "{name}: the proven walk covers the domain");
    }
    // In MPFR intervals as well.
    let c = circle(0.5);
    let s = proven_curve_step(&c, 1.0, alpha, &MpfrInterval::point(0.0, 128)).unwrap();
    assert!(s.t_end - s.t_start <= alpha);
}

#[test]
fn no_step_is_proven_from_a_cusp() {
    let cusp = Bezier::new(
        vec![
            [0.0, 0.0, 0.0],
            [1.0, 1.0, 0.0],
            [0.0, 1.0, 0.0],
            [1.0, 0.0, 0.0],
        ],
        None,
        None,
    )
    .unwrap();
    assert_eq!(
        proven_curve_step(&cusp, 0.5, PI / 10.0, &Interval::ZERO),
        None
    );
    let walk: Vec<_> = ProvenCurveWalk::new(&cusp, PI / 10.0, Interval::ZERO)
        .unwrap()
        .collect();
    assert!(
        matches!(walk.last(), Some(Err(t)) if *t < 0.5 && *t > 0.49),
        "{walk:?}"
    );
}

/// Proven steps stop at the corners of a polyline, also through a reparametrisation
/// whose image of a corner is not a double (then the corner lies strictly inside the
/// break interval the walk steps across).
#[test]
fn proven_steps_stop_at_corners() {
    use geocert::curve::{Polyline, Reparametrised};
    let poly = Polyline::new(
        vec![
            [0.0, 0.0, 0.0],
            [1.0, 1.0, 0.0],
            [2.0, 0.0, 1.0],
            [2.0, -1.0, 3.0],
        ],
        Some(vec![0.0, 0.5, 2.0, 2.25]),
    )
    .unwrap();
    let corners = |c: &dyn Fn() -> Vec<Result<geocert::walk::ProvenStep, f64>>| {
        c().iter()
            .filter_map(|s| s.as_ref().unwrap().corner)
            .collect::<Vec<_>>()
    };
    let direct = corners(&|| {
        ProvenCurveWalk::new(&poly, PI / 10.0, Interval::ZERO)
            .unwrap()
            .collect()
    });
    assert_eq!(direct, vec![(0.5, 0.5), (2.0, 2.0)]);
    let re = Reparametrised::reparametrised(poly, 0.0, 3.0).unwrap();
    let mapped = corners(&|| {
        ProvenCurveWalk::new(&re, PI / 10.0, Interval::ZERO)
            .unwrap()
            .collect()
    });
    assert_eq!(mapped.len(), 2);
    // 0.5 · 3/2.25 = 2/3 is not a double: an interval of one ulp around it.
    // 2/3 and 8/3 lie strictly inside the intervals, which are one ulp wide.
    for ((lo, hi), (num, den)) in mapped.into_iter().zip([(2, 3), (8, 3)]) {
        let exact = rug::Rational::from((num, den));
        let (qlo, qhi) = (
            rug::Rational::from_f64(lo).unwrap(),
            rug::Rational::from_f64(hi).unwrap(),
        );
        assert!(qlo < exact && exact < qhi, "{lo} {hi}");
        assert_eq!(f64::from_bits(lo.to_bits() + 1), hi);
    }
}
