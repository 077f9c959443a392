//! Offset, composite and extended curves (OPERATIONS.md §1.2, §1.5) against closed forms
//! computed by an independent route, over seeded families:
//!
//! * the plane offset of a circle of radius `r` at distance `a` is the circle of radius
//!   `r − a` (the normal (1.4) points inward); the space offset `c + t̂ × d` of a circle
//!   is, in MPFR at 300 bits, `C + r(cos X + sin Y) + (−sin X + cos Y) × d` (frame by
//!   the docs rule), a circle of radius `r + h|axis|` when `d = h·axis` — values and
//!   derivatives in f64, f64-interval and MPFR-interval boxes (the truth at the box's
//!   points inside every enclosure; an MPFR point evaluation a tight enclosure);
//! * a cubic Bézier split at dyadic parameters by de Casteljau in rationals and joined
//!   again as a composite equals the original under the §1.5 global parameter: points
//!   and derivatives at dyadic parameters (exact rational truth inside MPFR
//!   enclosures), boxes straddling the joints enclosing both sides and both one-sided
//!   derivatives;
//! * an extended segment / Bézier is the tangent line beyond its ends (rational truth);
//! * every malformed input is its typed error naming the field.

mod truth_support;

use geocert::curve::{
    Analytic, Analytic2, Bezier, Composite, Curve, Extended, Frame, Line, Offset2, Offset3,
    Polyline, Segment, Shape,
};
use geocert::num::rng::Rng;
use geocert::num::{Interval, MpfrInterval};
use rug::{Float, Rational};

const BITS: u32 = 300;

fn f(x: f64) -> Float {
    Float::with_val(BITS, x)
}

fn dyadic(g: &mut Rng, lo: f64, hi: f64, bits: i32) -> f64 {
    let s = 2f64.powi(bits);
    g.int((lo * s).ceil() as i64, (hi * s).floor() as i64) as f64 / s
}

/// `v` lies in the f64 interval (exactly, no slack).
fn in_f(x: &Interval, v: &Float) -> bool {
    *v >= x.lo() && *v <= x.hi()
}

/// `v` lies in the MPFR interval.
fn in_m(x: &MpfrInterval, v: &Float) -> bool {
    v >= x.lo() && v <= x.hi()
}

/// `(cos, sin)` of `t + kπ/2`: the `k`-th derivatives of `cos t`, `sin t`.
fn trig(t: f64, k: usize) -> (Float, Float) {
    let pi = Float::with_val(BITS, rug::float::Constant::Pi);
    let ph = f(t) + pi * (k as f64 / 2.0);
    (ph.clone().cos(), ph.sin())
}

/// Check a jet of order 2 at the parameter box `[a, b]` against `truth(s, k)` at the
/// box's ends and middle: f64 near, f64/MPFR interval boxes and MPFR points enclosing.
fn check_jet<const D: usize>(
    name: &str,
    c: &impl Curve<D>,
    a: f64,
    b: f64,
    truth: &dyn Fn(f64, usize) -> [Float; D],
) {
    let enc_f = c.jet(&Interval::from_bounds(a, b), 2);
    let enc_m = c.jet(&MpfrInterval::from_bounds(a, b, 200), 2);
    for s in [a, 0.5 * a + 0.5 * b, b] {
        let pt_f = c.jet(&s, 2);
        let pt_m = c.jet(&MpfrInterval::point(s, 200), 2);
        for k in 0..=2 {
            let tr = truth(s, k);
            for i in 0..D {
                let ctx = format!("{name}: box [{a}, {b}], s = {s}, jet[{k}][{i}]");
                let scale = 1.0 + tr[i].to_f64().abs();
                assert!(
                    (pt_f[k][i] - tr[i].to_f64()).abs() <= 1e-12 * scale * 8.0,
                    "{ctx}: f64 {} vs {}",
                    pt_f[k][i],
                    tr[i]
                );
                assert!(
                    in_f(&enc_f[k][i], &tr[i]),
                    "{ctx}: {:?} misses {}",
                    enc_f[k][i],
                    tr[i]
                );
                assert!(
                    in_m(&enc_m[k][i], &tr[i]),
                    "{ctx}: MPFR box misses {}",
                    tr[i]
                );
                assert!(
                    in_m(&pt_m[k][i], &tr[i]),
                    "{ctx}: MPFR point misses {}",
                    tr[i]
                );
                let w = Float::with_val(BITS, pt_m[k][i].hi() - pt_m[k][i].lo());
                assert!(w < 1e-45 * scale, "{ctx}: MPFR point {} wide", w);
            }
        }
    }
    // The base jets stop at order 3, so an offset's third derivative is unknown.
    let j3 = c.jet(&Interval::from_bounds(a, b), 3);
    assert_eq!(j3.len(), 4);
}

#[test]
fn plane_offset_of_a_circle_is_the_circle_of_radius_r_minus_a() {
    let mut g = Rng::new(1601);
    for i in 0..300 {
        let c = [dyadic(&mut g, -2.0, 2.0, 3), dyadic(&mut g, -2.0, 2.0, 3)];
        let r = dyadic(&mut g, 0.5, 3.0, 4);
        let a = dyadic(&mut g, -2.0, 2.0, 5);
        let circle = Analytic2::new(c, Shape::Circle { radius: r }, None).unwrap();
        let off = Offset2::new(circle, a).unwrap();
        let rho = f(r) - a;
        let truth = |s: f64, k: usize| {
            let (co, si) = trig(s, k);
            let base = if k == 0 {
                [f(c[0]), f(c[1])]
            } else {
                [f(0.0), f(0.0)]
            };
            [base[0].clone() + co * &rho, base[1].clone() + si * &rho]
        };
        let t0 = dyadic(&mut g, 0.0, 6.0, 10);
        let w = [0.0, 1e-9, 1e-3, 0.3][i % 4];
        check_jet("offset2", &off, t0, t0 + w, &truth);
        let j3 = off.jet(&t0, 3);
        assert!(j3[3].iter().all(|x| x.is_nan()), "f64 order 3 is unknown");
        let j3 = off.jet(&Interval::point(t0), 3);
        assert!(
            j3[3].iter().all(|x| x.is_entire()),
            "interval order 3 is the whole line"
        );
    }
}

#[test]
fn space_offset_of_a_circle_against_mpfr() {
    let mut g = Rng::new(1602);
    for i in 0..200 {
        let axis = loop {
            let v = [0; 3].map(|_| dyadic(&mut g, -1.0, 1.0, 3));
            if v.iter().any(|x| x.abs() >= 0.25) {
                break v;
            }
        };
        let center = [0; 3].map(|_| dyadic(&mut g, -2.0, 2.0, 3));
        let r = dyadic(&mut g, 0.5, 3.0, 4);
        // every other case d along the axis: the planar offset, a circle of radius r + h|axis|
        let normal = i % 2 == 0;
        let h = dyadic(&mut g, -0.4, 2.0, 4);
        let d = if normal {
            axis.map(|x| x * h)
        } else {
            [0; 3].map(|_| dyadic(&mut g, -2.0, 2.0, 4))
        };
        let frame = Frame::new(center, axis, None).unwrap();
        let circle = Analytic::new(frame, Shape::Circle { radius: r }, None).unwrap();
        let off = Offset3::new(circle, d).unwrap();
        let [x, y, _] = truth_support::docs_frame(axis, None, BITS);
        let truth = |s: f64, k: usize| -> [Float; 3] {
            let (co, si) = trig(s, k);
            let tan: [Float; 3] =
                std::array::from_fn(|j| -(si.clone() * &x[j]) + co.clone() * &y[j]);
            let cr: [Float; 3] = std::array::from_fn(|j| {
                let (a, b) = ((j + 1) % 3, (j + 2) % 3);
                tan[a].clone() * d[b] - tan[b].clone() * d[a]
            });
            std::array::from_fn(|j| {
                let base = if k == 0 { f(center[j]) } else { f(0.0) };
                base + (co.clone() * &x[j] + si.clone() * &y[j]) * r + &cr[j]
            })
        };
        let t0 = dyadic(&mut g, 0.0, 6.0, 10);
        let w = [0.0, 1e-9, 1e-3, 0.3][i % 4];
        check_jet("offset3", &off, t0, t0 + w, &truth);
        if normal {
            let p = off.point(&t0);
            let q: [f64; 3] = std::array::from_fn(|j| p[j] - center[j]);
            let len = axis.iter().map(|v| v * v).sum::<f64>().sqrt();
            let radius = (r + h * len).abs();
            let got = q.iter().map(|v| v * v).sum::<f64>().sqrt();
            assert!(
                (got - radius).abs() < 1e-12 * (1.0 + radius),
                "{got} vs {radius}"
            );
            let along: f64 = q.iter().zip(axis).map(|(a, b)| a * b).sum();
            assert!(
                along.abs() < 1e-12 * (1.0 + radius),
                "in the circle's plane"
            );
        }
    }
}

fn q(x: f64) -> Rational {
    Rational::from_f64(x).unwrap()
}

type P3 = [Rational; 3];

/// De Casteljau at `s` in rationals: (left control points, right control points).
fn split(p: &[P3], s: &Rational) -> (Vec<P3>, Vec<P3>) {
    let (mut left, mut right) = (vec![p[0].clone()], vec![p[p.len() - 1].clone()]);
    let mut v = p.to_vec();
    while v.len() > 1 {
        v = v
            .windows(2)
            .map(|w| std::array::from_fn(|i| w[0][i].clone() + (w[1][i].clone() - &w[0][i]) * s))
            .collect();
        left.push(v[0].clone());
        right.push(v[v.len() - 1].clone());
    }
    right.reverse();
    (left, right)
}

/// The point of the Bézier `p` at `s`, and its first derivative (rationals).
fn bezier_at(p: &[P3], s: &Rational) -> (P3, P3) {
    let (l, _) = split(p, s);
    let n = p.len() - 1;
    if *s == 0 {
        let (_, r) = split(p, s);
        let d0 = std::array::from_fn(|i| (r[1][i].clone() - &r[0][i]) * n as u32);
        return (r[0].clone(), d0);
    }
    let (last, prev) = (&l[n], &l[n - 1]);
    let d = std::array::from_fn(|i| (last[i].clone() - &prev[i]) * n as u32 / s.clone());
    (last.clone(), d)
}

fn exact(p: &P3) -> [f64; 3] {
    p.clone().map(|x| {
        let d = x.to_f64();
        assert_eq!(q(d), x, "control point exact in f64");
        d
    })
}

fn fq(x: &Rational) -> Float {
    Float::with_val(BITS, x)
}

#[test]
fn composite_of_a_split_bezier_is_the_bezier() {
    let mut g = Rng::new(1603);
    for case in 0..150 {
        let ctrl: Vec<P3> = (0..4)
            .map(|_| [0; 3].map(|_| q(dyadic(&mut g, -2.0, 2.0, 3))))
            .collect();
        let s1 = g.int(1, 7);
        let s2 = g.int(s1 + 1, 15);
        let cuts = [
            q(0.0),
            Rational::from((s1, 16)),
            Rational::from((s2, 16)),
            q(1.0),
        ];
        let (a, rest) = split(&ctrl, &cuts[1]);
        let u = (cuts[2].clone() - &cuts[1]) / (q(1.0) - &cuts[1]);
        let (b, c) = split(&rest, &u);
        let pieces: Vec<Bezier<3>> = [a, b, c]
            .iter()
            .map(|p| Bezier::new(p.iter().map(exact).collect(), None, None).unwrap())
            .collect();
        let comp = Composite::new(pieces).unwrap();
        assert_eq!(comp.domain(), (0.0, 3.0));
        assert_eq!(comp.piece_breaks(), vec![1.0, 2.0]);
        assert_eq!(comp.tangent_breaks(), vec![(1.0, 1.0), (2.0, 2.0)]);
        assert!(!comp.is_closed());
        // global t (dyadic) → (piece k, original parameter s, scale Δs_k)
        let at = |t: f64| {
            let k = (t.floor() as usize).min(2);
            let ds = cuts[k + 1].clone() - &cuts[k];
            (k, cuts[k].clone() + (q(t) - k as u32) * &ds, ds)
        };
        for _ in 0..20 {
            let t = dyadic(&mut g, 0.0, 3.0, 8);
            let (_, s, ds) = at(t);
            let (p, d) = bezier_at(&ctrl, &s);
            let pf = comp.point(&t);
            let jm = comp.jet(&MpfrInterval::point(t, 200), 1);
            for i in 0..3 {
                let ctx = format!("case {case}, t = {t}, coordinate {i}");
                assert!((pf[i] - p[i].to_f64()).abs() < 1e-13, "{ctx}");
                assert!(in_m(&jm[0][i], &fq(&p[i])), "{ctx}: point");
                if t.fract() != 0.0 {
                    let dt = d[i].clone() * &ds;
                    assert!(in_m(&jm[1][i], &fq(&dt)), "{ctx}: derivative");
                }
            }
        }
        // boxes straddling a joint hold both sides and both one-sided derivatives
        for k in 1..=2usize {
            let (w1, w2) = (dyadic(&mut g, 0.0, 0.5, 9), dyadic(&mut g, 0.0, 0.5, 9));
            let (lo, hi) = (k as f64 - w1, k as f64 + w2);
            let ef = comp.jet(&Interval::from_bounds(lo, hi), 1);
            let em = comp.jet(&MpfrInterval::from_bounds(lo, hi, 200), 1);
            for t in [lo, k as f64, hi] {
                let (_, s, _) = at(t);
                let (p, _) = bezier_at(&ctrl, &s);
                for i in 0..3 {
                    assert!(in_f(&ef[0][i], &fq(&p[i])), "case {case}: joint box point");
                    assert!(in_m(&em[0][i], &fq(&p[i])), "case {case}: joint box point");
                }
            }
            let (_, d) = bezier_at(&ctrl, &cuts[k]);
            for j in [k - 1, k] {
                let ds = cuts[j + 1].clone() - &cuts[j];
                for i in 0..3 {
                    let dt = fq(&(d[i].clone() * &ds));
                    assert!(in_f(&ef[1][i], &dt), "case {case}: one-sided derivative");
                    assert!(in_m(&em[1][i], &dt), "case {case}: one-sided derivative");
                }
            }
        }
    }
}

#[test]
fn extended_curves_continue_along_the_end_tangents() {
    let mut g = Rng::new(1604);
    for case in 0..100 {
        let ctrl: Vec<P3> = (0..3)
            .map(|_| [0; 3].map(|_| q(dyadic(&mut g, -2.0, 2.0, 3))))
            .collect();
        let pts: Vec<[f64; 3]> = ctrl.iter().map(exact).collect();
        let (before, after) = (dyadic(&mut g, 0.0, 1.0, 4), dyadic(&mut g, 0.0, 1.0, 4));
        let bez = Bezier::new(pts.clone(), None, None).unwrap();
        let ext = Extended::new(bez, before, after).unwrap();
        assert_eq!(ext.domain(), (-before, 1.0 + after));
        let truth = |t: f64| -> P3 {
            let e = if t < 0.0 {
                q(0.0)
            } else if t > 1.0 {
                q(1.0)
            } else {
                q(t)
            };
            let (p, d) = bezier_at(&ctrl, &e);
            std::array::from_fn(|i| p[i].clone() + d[i].clone() * (q(t) - &e))
        };
        for _ in 0..10 {
            let t = dyadic(&mut g, -before, 1.0 + after, 8);
            let p = truth(t);
            let m = ext.jet(&MpfrInterval::point(t, 200), 0);
            for i in 0..3 {
                assert!(in_m(&m[0][i], &fq(&p[i])), "case {case}, t = {t}");
            }
        }
        // a box straddling the end t = 1 holds the curve on both sides
        let (lo, hi) = (1.0 - dyadic(&mut g, 0.0, 0.5, 8), 1.0 + after);
        let e = ext.jet(&Interval::from_bounds(lo, hi), 0);
        for t in [lo, 1.0, hi] {
            let p = truth(t);
            for i in 0..3 {
                assert!(in_f(&e[0][i], &fq(&p[i])), "case {case}: box at the end");
            }
        }
        // an extended segment is its line
        let seg = Segment::new(pts[0], pts[1], None).unwrap();
        let ext = Extended::new(seg, before, after).unwrap();
        let t = -before;
        let m = ext.jet(&MpfrInterval::point(t, 200), 0);
        for i in 0..3 {
            let v = ctrl[0][i].clone() + (ctrl[1][i].clone() - &ctrl[0][i]) * q(t);
            assert!(in_m(&m[0][i], &fq(&v)), "case {case}: extended segment");
        }
    }
}

/// The kind and field of an error.
fn kf<T: std::fmt::Debug>(r: Result<T, geocert::GeomError>) -> (String, String) {
    let e = r.expect_err("an error");
    (e.kind().to_string(), e.field().to_string())
}

#[test]
fn malformed_derived_curves_name_the_field() {
    let circle2 = || Analytic2::new([0.0, 0.0], Shape::Circle { radius: 1.0 }, None).unwrap();
    let seg = |a: [f64; 3], b: [f64; 3]| Segment::new(a, b, None).unwrap();
    let bad = [f64::NAN, f64::INFINITY, f64::NEG_INFINITY];
    for (i, &x) in bad.iter().enumerate() {
        assert_eq!(
            kf(Offset2::new(circle2(), x)),
            ("non_finite".into(), "distance".into())
        );
        let mut d = [1.0, 2.0, 3.0];
        d[i] = x;
        let frame = Frame::new([0.0; 3], [0.0, 0.0, 1.0], None).unwrap();
        let c = Analytic::new(frame, Shape::Circle { radius: 1.0 }, None).unwrap();
        assert_eq!(
            kf(Offset3::new(c, d)),
            ("non_finite".into(), format!("offset[{i}]"))
        );
        let s = seg([0.0; 3], [1.0, 0.0, 0.0]);
        let k = i % 2;
        let ext = if k == 0 {
            Extended::new(s, x, 1.0)
        } else {
            Extended::new(s, 1.0, x)
        };
        assert_eq!(kf(ext), ("non_finite".into(), format!("extend[{k}]")));
    }
    // zero distance is the base curve
    let z = Offset2::new(circle2(), 0.0).unwrap();
    assert_eq!(z.point(&0.5), circle2().point(&0.5));
    // a tangent that jumps: the offset would be discontinuous
    let poly = Polyline::new(vec![[0.0, 0.0], [1.0, 0.0], [1.0, 1.0]], None).unwrap();
    assert_eq!(
        kf(Offset2::new(poly, 0.1)),
        ("unsupported".into(), "base".into())
    );
    // composites
    let empty: Vec<Segment<3>> = Vec::new();
    assert_eq!(
        kf(Composite::new(empty)),
        ("invalid_value".into(), "pieces".into())
    );
    for n in 2..6usize {
        for gap in 0..n - 1 {
            let mut pieces: Vec<Segment<3>> = (0..n)
                .map(|k| seg([k as f64, 0.0, 0.0], [k as f64 + 1.0, 0.0, 0.0]))
                .collect();
            let start = f64::from_bits((gap as f64 + 1.0).to_bits() + 1);
            pieces[gap + 1] = seg([start, 0.0, 0.0], [gap as f64 + 2.0, 0.0, 0.0]);
            let e = kf(Composite::new(pieces));
            assert_eq!(e, ("invalid_value".into(), format!("pieces[{gap}]")));
        }
    }
    let line = Line::new([0.0; 3], [1.0, 0.0, 0.0], None).unwrap();
    let e = kf(Composite::new(vec![line]));
    assert_eq!(e, ("unsupported".into(), "pieces[0]".into()));
    // a piece length that is no double: [0.1, 1] has length 0.9 − ulp-ish, not exact
    let short = Segment::new([0.0; 3], [1.0, 0.0, 0.0], Some((1e-30, 1.0))).unwrap();
    let e = kf(Composite::new(vec![short]));
    assert_eq!(e, ("unsupported".into(), "pieces[0].domain".into()));
    // extended: negative lengths, closed bases
    let s = seg([0.0; 3], [1.0, 0.0, 0.0]);
    assert_eq!(
        kf(Extended::new(s, -1.0, 0.0)),
        ("invalid_value".into(), "extend[0]".into())
    );
    assert_eq!(
        kf(Extended::new(circle2(), 1.0, 0.0)),
        ("unsupported".into(), "base".into())
    );
}
