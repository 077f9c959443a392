//! Curve ∩ plane through the front door (issue 16): the framed conics and Bézier
//! curves are decided exactly. Families of random frames, planes and curves with a truth
//! computed at 300 bits by another route — the parametrisation substituted into the
//! plane's equation and solved in closed form (`A cos t + B sin t + C = 0` by
//! `atan2 ± acos`, the hyperbola through `u = eᵗ`, the parabola's quadratic), not the
//! solver's line ∩ implicit conic — compared bit for bit with every coordinate and
//! parameter; exact tangencies (multiplicity 2) and their 1-ulp neighbours (0 or 2
//! points, decided exactly), curves lying in the plane, arcs, magnitudes 1e±100.
//! `GEOCERT_CURVE_PLANE_CASES` sets the number of cases per family (default 200).

// Coordinates are compared by index against several parallel arrays.
#![allow(clippy::needless_range_loop)]

mod truth_support;

use geocert::curve::frame::Frame;
use geocert::curve::{Analytic, AnyCurve3, Bezier, Shape as CurveShape};
use geocert::geom::Plane;
use geocert::ops::{self, Answer, Linear, LinearObject, Options, Point, Shape};
use geocert::robust::rng::Rng;
use geocert::Status;
use nalgebra::Vector3;
use rug::float::{Constant, Round};
use rug::ops::Pow;
use rug::{Float, Rational};

const BITS: u32 = 300;

/// A curve's point at a parameter, at 300 bits.
type PointAt = Box<dyn Fn(&Float) -> [Float; 3]>;

fn cases() -> usize {
    std::env::var("GEOCERT_CURVE_PLANE_CASES")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(200)
}

fn f(x: f64) -> Float {
    Float::with_val(BITS, x)
}

fn dot(a: &[Float], b: &[Float]) -> Float {
    a.iter().zip(b).fold(f(0.0), |s, (x, y)| s + x.clone() * y)
}

/// The docs/FORMAT.md frame at 300 bits (`[X, Y, Z]`).
fn frame(axis: [f64; 3], reference: Option<[f64; 3]>) -> [[Float; 3]; 3] {
    truth_support::docs_frame(axis, reference, BITS)
}

/// The reported double is the correct rounding of the truth and its box holds it.
fn assert_rounds(value: &Float, reported: f64, bounds: [f64; 2], what: &str) {
    let r = value.to_f64_round(Round::Nearest);
    let tol = Float::with_val(BITS, reported.abs().max(f64::MIN_POSITIVE)) >> 200u32;
    if bounds[0] == bounds[1] {
        let err = Float::with_val(BITS, value - reported).abs();
        assert!(err <= tol, "{what}: exact {reported:e}, truth {value:.30e}");
        return;
    }
    assert_eq!(
        reported.to_bits(),
        r.to_bits(),
        "{what}: truth {value:.30e}"
    );
    assert!(
        f(bounds[0]) - &tol <= *value && *value <= f(bounds[1]) + &tol,
        "{what}: truth {value:.30e} outside {bounds:?}"
    );
}

fn plane(n: [f64; 3], d: f64) -> Shape {
    Shape::Linear(Linear::Double(LinearObject::Plane(
        Plane::implicit(Vector3::from(n), d).expect("a plane"),
    )))
}

fn conic(
    c: [f64; 3],
    axis: [f64; 3],
    r: Option<[f64; 3]>,
    s: CurveShape,
    dom: Option<(f64, f64)>,
) -> Shape {
    let fr = Frame::new(c, axis, r).expect("frame");
    Shape::Curve(AnyCurve3::Analytic(
        Analytic::new(fr, s, dom).expect("curve"),
    ))
}

/// The exact answer's points, curve first or plane first (params swapped back).
fn solve(curve: &Shape, pl: &Shape, curve_first: bool) -> (Answer, Vec<Point>) {
    let shapes = if curve_first {
        vec![curve.clone(), pl.clone()]
    } else {
        vec![pl.clone(), curve.clone()]
    };
    let c = ops::intersect(&shapes, &Options::default()).expect("answers");
    assert_eq!(c.status, Status::Exact, "{c:?}");
    assert!(c.complete);
    let pts = match &c.value {
        Answer::Empty => vec![],
        Answer::Points(p) => p
            .iter()
            .cloned()
            .map(|mut p| {
                if !curve_first {
                    p.params.swap(0, 1);
                    if let Some(b) = &mut p.param_box {
                        b.swap(0, 1);
                    }
                }
                p
            })
            .collect(),
        _ => vec![],
    };
    (c.value, pts)
}

/// Local point `(x, y)` of a conic placed in space.
fn place(c: [f64; 3], fr: &[[Float; 3]; 3], x: &Float, y: &Float) -> [Float; 3] {
    std::array::from_fn(|i| f(c[i]) + x.clone() * &fr[0][i] + y.clone() * &fr[1][i])
}

fn two_pi() -> Float {
    Float::with_val(BITS, Constant::Pi) * 2u32
}

/// Truth: parameters of `A cos t + B sin t + C = 0` in `[0, 2π)` (none, or two).
fn trig_roots(a: &Float, b: &Float, c: &Float) -> Vec<Float> {
    let rho = (a.clone().square() + b.clone().square()).sqrt();
    let q = Float::with_val(BITS, -c.clone() / &rho);
    if q.clone().abs() > 1 {
        return vec![];
    }
    let phi = b.clone().atan2(a);
    let alpha = q.acos();
    let wrap = |t: Float| {
        let mut t = t;
        while t < 0 {
            t += two_pi();
        }
        while t >= two_pi() {
            t -= two_pi();
        }
        t
    };
    let mut v = vec![wrap(phi.clone() + &alpha), wrap(phi - alpha)];
    v.sort_by(|x, y| x.partial_cmp(y).expect("finite"));
    v
}

fn check(points: &[Point], truth: &[(Float, [Float; 3])], what: &str) {
    assert_eq!(points.len(), truth.len(), "{what}: count, {points:?}");
    for (p, (t, x)) in points.iter().zip(truth) {
        for i in 0..3 {
            assert_rounds(&x[i], p.xyz[i], p.xyz_box[i], &format!("{what}: xyz[{i}]"));
        }
        let pb = p.param_box.as_ref().expect("boxes");
        assert_rounds(t, p.params[0][0], pb[0][0], &format!("{what}: t"));
        assert_eq!(p.multiplicity, 1, "{what}");
    }
}

fn rand_vec(rng: &mut Rng) -> [f64; 3] {
    loop {
        let v = [rng.generic(), rng.generic(), rng.generic()];
        if v.iter().any(|&x| x != 0.0) {
            return v;
        }
    }
}

/// Circles and ellipses in random frames against random planes through a chosen point
/// of the curve (so they usually cross), both orders, magnitudes 1e±100.
#[test]
fn ellipse_family() {
    let mut rng = Rng::new(16_001);
    for case in 0..cases() {
        let scale = [1.0, 1e100, 1e-100][case % 3];
        let c = rand_vec(&mut rng).map(|x| x * scale);
        let axis = rand_vec(&mut rng);
        let reference = if rng.coin() {
            Some(rand_vec(&mut rng))
        } else {
            None
        };
        let (a, b) = (
            (0.5 + rng.unit().abs()) * scale,
            if case % 2 == 0 {
                0.0
            } else {
                (0.5 + rng.unit().abs()) * scale
            },
        );
        let shape = if b == 0.0 {
            CurveShape::Circle { radius: a }
        } else {
            CurveShape::Ellipse { a, b }
        };
        let b = if b == 0.0 { a } else { b };
        let n = rand_vec(&mut rng);
        let fr = frame(axis, reference);
        // d through a point of the curve at a random angle, rounded: near 2 crossings.
        let t0 = rng.unit().abs() * 6.0;
        let p0 = place(c, &fr, &(f(a) * f(t0).cos()), &(f(b) * f(t0).sin()));
        let d = (-dot(&n.map(f), &p0)).to_f64_round(Round::Nearest);
        let nn = n.map(f);
        let big_a = dot(&nn, &fr[0]) * f(a);
        let big_b = dot(&nn, &fr[1]) * f(b);
        let big_c = dot(&nn, &c.map(f)) + f(d);
        let truth: Vec<(Float, [Float; 3])> = trig_roots(&big_a, &big_b, &big_c)
            .into_iter()
            .map(|t| {
                let x = place(c, &fr, &(f(a) * t.clone().cos()), &(f(b) * t.clone().sin()));
                (t, x)
            })
            .collect();
        let curve = conic(c, axis, reference, shape, None);
        let (_, pts) = solve(&curve, &plane(n, d), case % 2 == 0);
        let mut pts = pts;
        pts.sort_by(|x, y| x.params[0][0].total_cmp(&y.params[0][0]));
        check(&pts, &truth, &format!("case {case}"));
        // An arc over part of the domain keeps exactly the points inside it.
        let (lo, hi) = (-1.0 - rng.unit().abs(), 1.0 + 4.0 * rng.unit().abs());
        let arc = conic(c, axis, reference, shape, Some((lo, hi)));
        let (_, arc_pts) = solve(&arc, &plane(n, d), true);
        let mut want: Vec<(Float, [Float; 3])> = Vec::new();
        for (t, x) in &truth {
            for k in [-1i32, 0, 1] {
                let tk = t.clone() + two_pi() * k;
                if tk >= lo && tk <= hi {
                    want.push((tk, x.clone()));
                }
            }
        }
        want.sort_by(|x, y| x.0.partial_cmp(&y.0).expect("finite"));
        let mut arc_pts = arc_pts;
        arc_pts.sort_by(|x, y| x.params[0][0].total_cmp(&y.params[0][0]));
        check(&arc_pts, &want, &format!("arc case {case}"));
    }
}

/// A circle about +z touching the plane `3x + 4y + n₃z + d = 0` exactly (distance of the
/// centre's projection `= 5r`): one point of multiplicity 2; `d` one ulp either way:
/// no point or two simple ones, decided exactly. Magnitudes 2^±300.
#[test]
fn tangent_and_one_ulp_off() {
    let mut rng = Rng::new(16_002);
    for case in 0..cases() {
        let e = [0, 300, -300][case % 3];
        let s = 2f64.powi(e);
        let c = [
            rng.small_int() * s,
            rng.small_int() * s,
            rng.small_int() * s,
        ];
        let r = (1.0 + rng.below(8) as f64) * s;
        let n3 = rng.small_int();
        let n = [3.0, 4.0, n3];
        let side = if rng.coin() { 1.0 } else { -1.0 };
        let d = -(3.0 * c[0] + 4.0 * c[1] + n3 * c[2]) + side * 5.0 * r;
        let curve = conic(
            c,
            [0.0, 0.0, 1.0],
            None,
            CurveShape::Circle { radius: r },
            None,
        );
        let (_, pts) = solve(&curve, &plane(n, d), true);
        assert_eq!(pts.len(), 1, "case {case}: {pts:?}");
        assert_eq!(pts[0].multiplicity, 2);
        assert!(pts[0].tangent);
        // The touching point: centre − side·r·(3, 4)/5, exactly when representable.
        let t = [3.0, 4.0].map(|k| f(k) / 5 * f(r) * (-side));
        assert_rounds(&(f(c[0]) + &t[0]), pts[0].xyz[0], pts[0].xyz_box[0], "x");
        assert_rounds(&(f(c[1]) + &t[1]), pts[0].xyz[1], pts[0].xyz_box[1], "y");
        // One ulp towards the centre: two points; away: none.
        let inward = if side > 0.0 { next_down(d) } else { next_up(d) };
        let outward = if side > 0.0 { next_up(d) } else { next_down(d) };
        let (_, two) = solve(&curve, &plane(n, inward), true);
        assert_eq!(two.len(), 2, "case {case} inward");
        assert!(two.iter().all(|p| p.multiplicity == 1 && !p.tangent));
        let (kind, none) = solve(&curve, &plane(n, outward), false);
        assert!(none.is_empty(), "case {case} outward: {kind:?}");
    }
}

fn next_up(x: f64) -> f64 {
    if x == 0.0 {
        f64::from_bits(1)
    } else if x > 0.0 {
        f64::from_bits(x.to_bits() + 1)
    } else {
        f64::from_bits(x.to_bits() - 1)
    }
}

fn next_down(x: f64) -> f64 {
    -next_up(-x)
}

/// A conic in a plane with a parallel normal: `coincident` through its centre, `empty`
/// one ulp away.
#[test]
fn contained_and_parallel() {
    let mut rng = Rng::new(16_003);
    for case in 0..cases() {
        let c = [rng.small_int(), rng.small_int(), rng.small_int()];
        let axis = [rng.small_int(), rng.small_int(), 1.0 + rng.below(4) as f64];
        let k = [1.0, -2.0, 0.5][case % 3];
        let n = axis.map(|x| x * k);
        let d = -(n[0] * c[0] + n[1] * c[1] + n[2] * c[2]);
        let shapes = [
            CurveShape::Circle { radius: 2.0 },
            CurveShape::Ellipse { a: 3.0, b: 1.0 },
            CurveShape::Hyperbola {
                a: 1.0,
                b: 2.0,
                second_branch: case % 2 == 0,
            },
            CurveShape::Parabola { p: 0.75 },
        ];
        let dom = if case % 4 >= 2 {
            Some((-2.0, 3.0))
        } else {
            None
        };
        let s = shapes[case % 4];
        let curve = conic(c, axis, None, s, dom);
        let r = ops::intersect(&[curve.clone(), plane(n, d)], &Options::default()).unwrap();
        assert_eq!(r.status, Status::Exact);
        assert_eq!(r.value, Answer::Coincident, "case {case}");
        let r = ops::intersect(&[plane(n, next_up(d)), curve], &Options::default()).unwrap();
        assert_eq!(r.value.kind(), "empty", "case {case}");
        assert!(r.complete);
    }
}

/// Hyperbolas (both branches) and parabolas in random frames against random planes:
/// truth from `u = eᵗ` (`(σA+B)u² + 2Cu + (σA−B) = 0`, `u > 0`) and from the quadratic
/// `C + A t²/(2p) + B t = 0`.
#[test]
fn hyperbola_parabola_family() {
    let mut rng = Rng::new(16_004);
    for case in 0..cases() {
        let c = rand_vec(&mut rng);
        let axis = rand_vec(&mut rng);
        let reference = if rng.coin() {
            Some(rand_vec(&mut rng))
        } else {
            None
        };
        let fr = frame(axis, reference);
        let n = rand_vec(&mut rng);
        let nn = n.map(f);
        let (lo, hi) = (-2.0 - rng.unit().abs(), 2.0 + rng.unit().abs());
        let t0 = lo + (hi - lo) * rng.unit().abs();
        let (a, b) = (0.5 + rng.unit().abs(), 0.5 + rng.unit().abs());
        let parabola = case % 3 == 0;
        let sigma = if case % 3 == 1 { -1.0 } else { 1.0 };
        let (shape, point_at): (CurveShape, PointAt) = if parabola {
            let p = a;
            let fr2 = fr.clone();
            (
                CurveShape::Parabola { p },
                Box::new(move |t: &Float| place(c, &fr2, &(t.clone().square() / (2.0 * p)), t)),
            )
        } else {
            let fr2 = fr.clone();
            (
                CurveShape::Hyperbola {
                    a,
                    b,
                    second_branch: sigma < 0.0,
                },
                Box::new(move |t: &Float| {
                    place(
                        c,
                        &fr2,
                        &(f(sigma * a) * t.clone().cosh()),
                        &(f(b) * t.clone().sinh()),
                    )
                }),
            )
        };
        let d = (-dot(&nn, &point_at(&f(t0)))).to_f64_round(Round::Nearest);
        let nx = dot(&nn, &fr[0]);
        let ny = dot(&nn, &fr[1]);
        let cc = dot(&nn, &c.map(f)) + f(d);
        // Quadratic α z² + β z + γ = 0 and the map from its root z to t.
        let (alpha, beta, gamma) = if parabola {
            (nx.clone() / (2.0 * a), ny.clone(), cc.clone())
        } else {
            let (sa, bb) = (nx.clone() * (sigma * a), ny.clone() * b);
            ((sa.clone() + &bb) / 2u32, cc.clone(), (sa - bb) / 2u32)
        };
        let disc = beta.clone().square() - alpha.clone() * &gamma * 4u32;
        let mut ts: Vec<Float> = Vec::new();
        if disc >= 0 {
            let sq = disc.sqrt();
            for z in [
                (-beta.clone() + &sq) / (alpha.clone() * 2u32),
                (-beta.clone() - &sq) / (alpha.clone() * 2u32),
            ] {
                let t = if parabola {
                    z
                } else if z > 0 {
                    z.ln()
                } else {
                    continue;
                };
                if t >= lo && t <= hi {
                    ts.push(t);
                }
            }
        }
        ts.sort_by(|x, y| x.partial_cmp(y).expect("finite"));
        let truth: Vec<(Float, [Float; 3])> =
            ts.into_iter().map(|t| (t.clone(), point_at(&t))).collect();
        let curve = conic(c, axis, reference, shape, Some((lo, hi)));
        let (_, mut pts) = solve(&curve, &plane(n, d), case % 2 == 0);
        pts.sort_by(|x, y| x.params[0][0].total_cmp(&y.params[0][0]));
        check(&pts, &truth, &format!("case {case} ({shape:?})"));
    }
}

/// Exact rationals of a Bézier curve at `t` (de Casteljau).
fn bezier_at(pts: &[[f64; 3]], t: &Rational) -> [Rational; 3] {
    let mut v: Vec<[Rational; 3]> = pts
        .iter()
        .map(|p| p.map(|x| Rational::from_f64(x).expect("finite")))
        .collect();
    while v.len() > 1 {
        v = v
            .windows(2)
            .map(|w| {
                std::array::from_fn(|i| {
                    (&w[0][i] * (Rational::from(1) - t)) + Rational::from(&w[1][i] * t)
                })
            })
            .collect();
    }
    v.swap_remove(0)
}

/// Quadratic Béziers whose distance to the plane `z = h` is `(t − r₁)(t − r₂)`
/// (dyadic roots, dyadic Bernstein coefficients): the roots in `[0, 1]` exactly, a
/// double root as a tangency, the curve lying in the plane; x, y random.
#[test]
fn bezier_known_roots() {
    let mut rng = Rng::new(16_005);
    for case in 0..cases() {
        let r1 = rng.int(-4, 12) as f64 / 8.0;
        let r2 = if case % 5 == 0 {
            r1
        } else {
            rng.int(-4, 12) as f64 / 8.0
        };
        let h = rng.small_int();
        let k = [1.0, 3.0, 0.25][case % 3];
        // (t − r1)(t − r2) = t² − (r1+r2)t + r1r2; Bernstein: b0 = r1r2,
        // b1 = r1r2 − (r1+r2)/2, b2 = (1 − r1)(1 − r2).
        let b = [r1 * r2, r1 * r2 - (r1 + r2) / 2.0, (1.0 - r1) * (1.0 - r2)];
        let pts: Vec<[f64; 3]> = (0..3)
            .map(|i| [rng.generic(), rng.generic(), h + k * b[i]])
            .collect();
        let curve = Shape::Curve(AnyCurve3::Bezier(
            Bezier::new(pts.clone(), None, None).unwrap(),
        ));
        let (_, got) = solve(&curve, &plane([0.0, 0.0, 1.0], -h), case % 2 == 0);
        let mut want: Vec<f64> = [r1, r2]
            .into_iter()
            .filter(|r| (0.0..=1.0).contains(r))
            .collect();
        want.sort_by(f64::total_cmp);
        want.dedup();
        assert_eq!(got.len(), want.len(), "case {case}: {r1} {r2} {got:?}");
        for (p, &t) in got.iter().zip(&want) {
            assert_eq!(p.params[0][0], t);
            let x = bezier_at(&pts, &Rational::from_f64(t).unwrap());
            for i in 0..3 {
                assert_eq!(
                    p.xyz[i],
                    Float::with_val(1000, &x[i]).to_f64_round(Round::Nearest),
                    "case {case} xyz[{i}]"
                );
                let e = p.exact.as_ref().expect("exact values");
                assert_eq!(e.xyz[i], x[i]);
            }
            assert_eq!(p.multiplicity, if r1 == r2 { 2 } else { 1 });
        }
        let flat: Vec<[f64; 3]> = pts.iter().map(|p| [p[0], p[1], h]).collect();
        let flat = Shape::Curve(AnyCurve3::Bezier(Bezier::new(flat, None, None).unwrap()));
        let r = ops::intersect(
            &[flat, plane([0.0, 0.0, 2.0], -2.0 * h)],
            &Options::default(),
        );
        assert_eq!(r.unwrap().value, Answer::Coincident);
    }
}

/// Random cubic Béziers (rational, positive weights, too) against random planes: the
/// truth roots of `Σ wᵢ(n·Pᵢ + d)Bᵢ(t)` found by 300-bit bisection of sign changes on a
/// fine grid; every coordinate is the rounded `Σ wᵢPᵢBᵢ/Σ wᵢBᵢ` at the truth.
#[test]
fn bezier_random_family() {
    let mut rng = Rng::new(16_006);
    for case in 0..cases() {
        let pts: Vec<[f64; 3]> = (0..4).map(|_| rand_vec(&mut rng)).collect();
        let w: Option<Vec<f64>> =
            (case % 2 == 1).then(|| (0..4).map(|_| 0.5 + rng.unit().abs()).collect());
        let n = rand_vec(&mut rng);
        let mid = &pts[rng.below(4)];
        let d = -(n[0] * mid[0] + n[1] * mid[1] + n[2] * mid[2]);
        let ww: Vec<f64> = w.clone().unwrap_or_else(|| vec![1.0; 4]);
        let bern = |t: &Float, c: &[Float]| -> Float {
            let s = f(1.0) - t.clone();
            let binom = [1u32, 3, 3, 1];
            (0..4).fold(f(0.0), |acc, i| {
                acc + c[i].clone()
                    * binom[i]
                    * t.clone().pow(i as u32)
                    * s.clone().pow((3 - i) as u32)
            })
        };
        let g: Vec<Float> = (0..4)
            .map(|i| (dot(&n.map(f), &pts[i].map(f)) + f(d)) * ww[i])
            .collect();
        let mut roots = Vec::new();
        let steps = 4096;
        for k in 0..steps {
            let (mut a, mut b) = (f(k as f64) / steps, f((k + 1) as f64) / steps);
            let (fa, fb) = (bern(&a, &g), bern(&b, &g));
            if fa == 0 {
                roots.push(a.clone());
                continue;
            }
            if (fa < 0) == (fb < 0) || fb == 0 {
                continue;
            }
            for _ in 0..280 {
                let m = (a.clone() + &b) / 2u32;
                if (bern(&m, &g) < 0) == (fa < 0) {
                    a = m;
                } else {
                    b = m;
                }
            }
            roots.push(a);
        }
        if bern(&f(1.0), &g) == 0 {
            roots.push(f(1.0));
        }
        let curve = Shape::Curve(AnyCurve3::Bezier(
            Bezier::new(pts.clone(), w, None).unwrap(),
        ));
        let (_, mut got) = solve(&curve, &plane(n, d), case % 2 == 0);
        got.sort_by(|x, y| x.params[0][0].total_cmp(&y.params[0][0]));
        assert_eq!(got.len(), roots.len(), "case {case}: {got:?}");
        let wf: Vec<Float> = ww.iter().map(|&x| f(x)).collect();
        for (p, t) in got.iter().zip(&roots) {
            let pb = p.param_box.as_ref().unwrap();
            assert_rounds(t, p.params[0][0], pb[0][0], &format!("case {case} t"));
            let den = bern(t, &wf);
            for i in 0..3 {
                let c: Vec<Float> = (0..4).map(|j| f(pts[j][i]) * ww[j]).collect();
                let x = bern(t, &c) / &den;
                assert_rounds(&x, p.xyz[i], p.xyz_box[i], &format!("case {case} xyz[{i}]"));
            }
        }
    }
}

/// A parabola about +z cut by the plane `y = y₀` (either form of the plane): the
/// parameter is the rational `y₀` itself, reported exactly (a double), and the point
/// `(c + y₀²/(2p), c + y₀, c)` correctly rounded; with the domain ends on `y₀` exactly.
#[test]
fn parabola_exact_parameter() {
    let mut rng = Rng::new(16_007);
    for case in 0..cases() {
        let c = [rng.small_int(), rng.small_int(), rng.small_int()];
        let y0 = rng.int(-40, 40) as f64 / 16.0;
        let p = [0.5, 0.75, 3.0][case % 3];
        let dom = if case % 2 == 0 {
            (y0, y0 + 1.0)
        } else {
            (y0 - 1.0, y0)
        };
        let curve = conic(
            c,
            [0.0, 0.0, 1.0],
            None,
            CurveShape::Parabola { p },
            Some(dom),
        );
        let pl = if case % 4 < 2 {
            plane([0.0, 1.0, 0.0], -(c[1] + y0))
        } else {
            Shape::Linear(Linear::Double(LinearObject::Plane(
                Plane::parametric(
                    Vector3::new(0.0, c[1] + y0, 0.0),
                    Vector3::new(1.0, 0.0, 0.0),
                    Vector3::new(0.0, 0.0, 2.0),
                )
                .unwrap(),
            )))
        };
        let (_, pts) = solve(&curve, &pl, case % 3 == 0);
        assert_eq!(pts.len(), 1, "case {case}");
        let pb = pts[0].param_box.as_ref().unwrap();
        assert_eq!(pts[0].params[0][0], y0);
        assert_eq!(pb[0][0], [y0, y0]);
        let x = Rational::from_f64(c[0]).unwrap()
            + Rational::from_f64(y0).unwrap().square() / Rational::from_f64(2.0 * p).unwrap();
        assert_rounds(
            &Float::with_val(BITS, &x),
            pts[0].xyz[0],
            pts[0].xyz_box[0],
            "x",
        );
        assert_eq!(pts[0].xyz[1], c[1] + y0);
        assert_eq!(pts[0].xyz[2], c[2]);
    }
}
