//! Enclosures (issue 5): for random parameter boxes of every curve primitive, the f64
//! interval and the 200-bit MPFR interval evaluations of the value and of every
//! derivative up to the third contain the 200-bit MPFR evaluation at points of the box,
//! and the f64 interval evaluation contains the f64 evaluation there (the 200-bit box
//! is tighter than f64 rounding: it holds the f64 value up to that rounding) — its ends, random interior points and the knots
//! and vertices it straddles — including boxes across the seam of periodic curves.

mod curve_support;
mod truth_support;

use curve_support::*;
use geocert::curve::{AnyCurve3, Bezier, Curve, NurbsCurve};
use geocert::num::{Interval, IntervalLike, MpfrInterval, Real};
use truth_support::conics::{KNOTS, OFFSETS, WEIGHTS};

/// Check every containment at the points `pts` of the box `[a, b]`.
fn check_box<const D: usize>(name: &str, c: &impl Curve<D>, a: f64, b: f64, pts: &[f64]) {
    let enc_f = c.jet(&Interval::from_bounds(a, b), 3);
    let enc_m = c.jet(&MpfrInterval::from_bounds(a, b, 200), 3);
    for &s in pts {
        let f = c.jet(&s, 3);
        let m = c.jet(&MpfrInterval::point(s, 200), 3);
        for k in 0..=3 {
            for i in 0..D {
                let ctx = || format!("{name}: box [{a}, {b}], t = {s}, jet[{k}][{i}]");
                assert!(
                    !enc_f[k][i].is_empty() && !enc_m[k][i].is_empty(),
                    "{} empty",
                    ctx()
                );
                assert!(
                    enc_f[k][i].contains_value(f[k][i]),
                    "{}: f64 {} not in {:?}",
                    ctx(),
                    f[k][i],
                    enc_f[k][i]
                );
                // The 200-bit box is tighter than the f64 evaluation's own rounding:
                // there the f64 value lies within its rounding error of the box.
                let (lo, hi) = enc_m[k][i].bounds();
                let slack = 1e-12 * (1.0 + lo.abs().max(hi.abs()));
                assert!(
                    lo - slack <= f[k][i] && f[k][i] <= hi + slack,
                    "{}: f64 off the MPFR box",
                    ctx()
                );
                assert!(
                    m[k][i].is_subset(&enc_m[k][i]),
                    "{}: MPFR point not in the MPFR box",
                    ctx()
                );
                assert!(
                    m[k][i].to_interval().is_subset(&enc_f[k][i]),
                    "{}: MPFR point {:?} not in {:?}",
                    ctx(),
                    m[k][i],
                    enc_f[k][i]
                );
            }
        }
    }
}

/// Random boxes inside the domain, of widths from the whole range down to 10⁻⁶ of
/// it, tested at their ends, 4 interior points and the breaks inside.
fn check_curve<const D: usize>(name: &str, c: &impl Curve<D>, breaks: &[f64], seed: u64) {
    let mut rng = Rng::new(seed);
    let (lo, hi) = c.domain();
    for _ in 0..25 {
        let w = (hi - lo) * 10f64.powf(-rng.range(0.0, 6.0));
        let center = rng.range(lo, hi);
        let a = (center - w / 2.0).max(lo);
        let b = (center + w / 2.0).min(hi);
        let mut pts = vec![a, b];
        pts.extend((0..4).map(|_| rng.range(a, b)));
        pts.extend(breaks.iter().filter(|&&k| a <= k && k <= b));
        check_box(name, c, a, b, &pts);
    }
    check_box(name, c, lo, hi, &[lo, hi, 0.5 * (lo + hi)]);
}

#[test]
fn space_curve_enclosures_contain_point_evaluations() {
    for (seed, (name, c)) in space_curves().into_iter().enumerate() {
        check_curve(name, &c, &breaks3(&c), 1000 + seed as u64);
    }
    for (seed, (name, c)) in arcs().into_iter().enumerate() {
        check_curve(name, &c, &[], 1100 + seed as u64);
    }
}

#[test]
fn plane_curve_enclosures_contain_point_evaluations() {
    for (seed, (name, c)) in plane_curves().into_iter().enumerate() {
        check_curve(name, &c, &breaks2(&c), 1200 + seed as u64);
    }
}

/// Periodic curves take any parameter: boxes across the seam, beyond the domain and
/// wider than a period enclose the wrapped values.
#[test]
fn periodic_enclosures_wrap_across_the_seam() {
    let mut periodic = 0;
    for (name, c) in space_curves() {
        if !c.is_periodic() {
            continue;
        }
        periodic += 1;
        let (lo, hi) = c.domain();
        let p = hi - lo;
        let mut rng = Rng::new(77);
        for (a, b) in [
            (hi - 0.1 * p, hi + 0.05 * p),
            (hi - 0.001 * p, hi + 0.3 * p),
            (lo - 0.3 * p, lo + 0.001 * p),
            (lo - 0.2 * p, lo + 0.01 * p),
            (hi + 1.3 * p, hi + 1.45 * p),
            (lo - 0.5 * p, hi + 0.7 * p),
            (lo - 7.0 * p, lo + 2.5 * p),
        ] {
            let mut pts = vec![a, b, lo, hi];
            pts.retain(|&s| a <= s && s <= b);
            pts.extend((0..6).map(|_| rng.range(a, b)));
            check_box(name, &c, a, b, &pts);
        }
    }
    assert_eq!(periodic, 3, "circle, ellipse and the periodic NURBS");
}

/// Unbounded or astronomically large parameters of a periodic curve terminate and
/// enclose every point of the curve.
#[test]
fn huge_parameters_of_periodic_curves_enclose_the_whole_curve() {
    let c = space_curves()
        .into_iter()
        .find(|(n, _)| *n == "periodic-nurbs")
        .unwrap()
        .1;
    let (lo, hi) = c.domain();
    for t in [
        Interval::ENTIRE,
        Interval::point(1e300),
        Interval::from_bounds(-1e20, 1e20),
    ] {
        let enc = c.jet(&t, 2);
        for k in 0..=10 {
            let s = lo + (hi - lo) * k as f64 / 10.0;
            let f = c.jet(&s, 2);
            for d in 0..=2 {
                for i in 0..3 {
                    assert!(
                        enc[d][i].contains_value(f[d][i]),
                        "{t:?}: jet[{d}][{i}] at {s}"
                    );
                }
            }
        }
    }
    assert!(c.point(&1e300).iter().all(|x| x.is_finite()));
}

/// Wide boxes of rational curves are tight (the hull of the Bézier form on the box,
/// `curve::span_hull`): the f64 interval point enclosure of a NURBS circle (radius `r`,
/// nine control points, a quadrant per span) and of a rational Bézier quarter circle
/// over random boxes — up to a whole span — is finite and exceeds the sampled range of
/// the curve by at most `r·(b − a)²` per coordinate (the hull of an arc of angle φ
/// exceeds it by `r(1/cos(φ/2) − 1) ≤ 0.42 r` for φ ≤ π/2). The basis sums alone gave a
/// weight enclosure holding 0 over a whole span, hence an unbounded point.
#[test]
fn wide_boxes_of_rational_curves_are_tight() {
    let r = 3.0;
    let h = std::f64::consts::FRAC_1_SQRT_2;
    let circle = NurbsCurve::new(
        2,
        KNOTS.to_vec(),
        OFFSETS.iter().map(|&(x, y)| [r * x, r * y, 0.5]).collect(),
        Some(WEIGHTS.to_vec()),
        None,
    )
    .unwrap();
    let quarter = Bezier::new(
        vec![[r, 0.0, 0.5], [r, r, 0.5], [0.0, r, 0.5]],
        Some(vec![1.0, h, 1.0]),
        None,
    )
    .unwrap();
    let mut rng = Rng::new(4242);
    let mut checked = 0;
    for (name, c, span) in [
        ("nurbs circle", AnyCurve3::Nurbs(circle), 1.0),
        ("bezier quarter", AnyCurve3::Bezier(quarter), 1.0),
    ] {
        let (lo, hi) = c.domain();
        for i in 0..200 {
            let w = span * 10f64.powf(-rng.range(0.0, 3.0));
            let (a, b) = if i % 10 == 0 {
                // a whole span
                let k = (rng.range(lo, hi - 1e-9) / span).floor() * span;
                (k, k + span)
            } else {
                let a = rng.range(lo, hi - w);
                (a, a + w)
            };
            let enc = c.jet(&Interval::from_bounds(a, b), 0);
            for (j, e) in enc[0].iter().enumerate() {
                let (elo, ehi) = (e.lo(), e.hi());
                assert!(
                    elo.is_finite() && ehi.is_finite(),
                    "{name} [{a}, {b}] coord {j}: {e:?}"
                );
                let samples: Vec<f64> = (0..=400)
                    .map(|k| c.jet(&(a + (b - a) * k as f64 / 400.0), 0)[0][j])
                    .collect();
                let smin = samples.iter().cloned().fold(f64::INFINITY, f64::min);
                let smax = samples.iter().cloned().fold(f64::NEG_INFINITY, f64::max);
                // (f64 samples: within their rounding of the enclosure)
                let slack = 1e-12 * r;
                assert!(
                    elo <= smin + slack && smax - slack <= ehi,
                    "{name} [{a}, {b}] coord {j}: samples out"
                );
                let allowed = (smax - smin) + r * (b - a) * (b - a) + 1e-12 * r;
                assert!(
                    ehi - elo <= allowed,
                    "{name} [{a}, {b}] coord {j}: width {} > {allowed}",
                    ehi - elo
                );
                checked += 1;
            }
        }
    }
    assert_eq!(checked, 2 * 200 * 3);
}
