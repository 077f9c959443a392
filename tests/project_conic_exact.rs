//! Point → `circle2` / `ellipse2` projections are decided exactly (issue 14, item 9):
//! every foot, its multiplicity and its correctly rounded distance and parameter.
//!
//! The truth is computed by a different route than the code (which intersects the
//! implicit conic with its Apollonius conic): the feet are the roots in `[0, 2π)` of the
//! parametric foot equation `g(t) = (a² − b²) sin t cos t − a X sin t + b Y cos t`
//! (`X, Y` the point relative to the centre), bracketed on a fine grid and bisected at
//! 300 bits. Families: random ellipses and circles with random points inside and outside
//! (two or four feet), points on the axes (the Apollonius conic splits into two lines),
//! the evolute's cusp (a triple foot) and 2⁻⁴⁰ either side of it (four feet / two feet),
//! points on the curve (distance exactly 0), and the same cases scaled by 2^±400.
//! `GEOCERT_FOOT_CASES` sets the number of random cases (default 150).

use geocert::curve::analytic::{Analytic2, Shape as CurveShape};
use geocert::curve::AnyCurve2;
use geocert::ops::{self, Answer, Options, Point, Position, ProjectOptions, Shape};
use geocert::robust::rng::Rng;
use geocert::Status;
use rug::float::{Constant, Round};
use rug::Float;

const BITS: u32 = 300;

fn cases() -> usize {
    std::env::var("GEOCERT_FOOT_CASES")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(150)
}

fn f(x: f64) -> Float {
    Float::with_val(BITS, x)
}

struct Ellipse {
    center: [f64; 2],
    a: f64,
    b: f64,
}

impl Ellipse {
    fn shape(&self) -> Shape {
        let s = if self.a == self.b {
            CurveShape::Circle { radius: self.a }
        } else {
            CurveShape::Ellipse {
                a: self.a,
                b: self.b,
            }
        };
        Shape::Curve2(AnyCurve2::Analytic(
            Analytic2::new(self.center, s, None).expect("a whole conic"),
        ))
    }

    /// `g(t)` of the module documentation at 300 bits.
    fn g(&self, p: [f64; 2], t: &Float) -> Float {
        let (x, y) = (f(p[0]) - self.center[0], f(p[1]) - self.center[1]);
        let (s, c) = (t.clone().sin(), t.clone().cos());
        (f(self.a).square() - f(self.b).square()) * s.clone() * &c - x * self.a * s + y * self.b * c
    }

    /// The feet's parameters in `[0, 2π)` by sign changes of `g` on a grid of `n`
    /// cells shifted by half a cell (so that the roots at 0 and π of points on an axis
    /// are inside cells), bisected to 290 bits; a root within 2⁻²⁰⁰ of 0 is 0.
    fn feet(&self, p: [f64; 2], n: usize) -> Vec<Float> {
        let two_pi = Float::with_val(BITS, Constant::Pi) * 2u32;
        let h = two_pi.clone() / n as u32;
        let node = |k: usize| h.clone() * k as u32 - h.clone() / 2u32;
        let mut roots = Vec::new();
        let mut prev = self.g(p, &node(0));
        for k in 0..n {
            let (lo, hi) = (node(k), node(k + 1));
            let next = self.g(p, &hi);
            if prev.is_sign_negative() != next.is_sign_negative() {
                let mut t = bisect(|t| self.g(p, t), lo, hi);
                if t.clone().abs() < Float::with_val(BITS, Float::i_exp(1, -200)) {
                    t = f(0.0);
                } else if t.is_sign_negative() {
                    t += &two_pi;
                }
                roots.push(t);
            }
            prev = next;
        }
        roots
    }

    /// The feet of a point on an axis of an ellipse (not a circle) in closed form:
    /// on the x axis `g = sin t·((a² − b²) cos t − aX)`, so `t ∈ {0, π}` and
    /// `cos t = aX/(a² − b²)`; on the y axis `g = cos t·((a² − b²) sin t + bY)`.
    fn feet_on_axis(&self, p: [f64; 2]) -> Option<Vec<Float>> {
        let pi = Float::with_val(BITS, Constant::Pi);
        let (x, y) = (f(p[0]) - self.center[0], f(p[1]) - self.center[1]);
        let c2 = f(self.a).square() - f(self.b).square();
        let wrap = |t: Float| {
            if t.is_sign_negative() {
                t + pi.clone() * 2u32
            } else {
                t
            }
        };
        if self.a == self.b || (!y.is_zero() && !x.is_zero()) {
            return None;
        }
        let mut roots = Vec::new();
        if y.is_zero() {
            roots.extend([f(0.0), pi.clone()]);
            let c = x * self.a / &c2;
            if c.clone().abs() < 1 {
                let t = c.acos();
                roots.extend([t.clone(), wrap(-t)]);
            }
        } else {
            roots.extend([pi.clone() / 2u32, pi.clone() * 3u32 / 2u32]);
            let s = -(y * self.b / &c2);
            if s.clone().abs() < 1 {
                let t = s.asin();
                roots.extend([wrap(t.clone()), pi.clone() - t]);
            }
        }
        Some(roots)
    }

    /// The point at `t`; at the vertices (`t` within 2⁻²⁰⁰ of a multiple of π/2) the
    /// exact vertex, since sin and cos of a rounded π are not exactly 0.
    fn at(&self, t: &Float) -> [Float; 2] {
        let half_pi = Float::with_val(BITS, Constant::Pi) / 2u32;
        let k = Float::with_val(BITS, t / &half_pi).round();
        let near = Float::with_val(BITS, t - half_pi * &k).abs()
            < Float::with_val(BITS, Float::i_exp(1, -200));
        if near {
            let (c, s) = match k.to_f64() as i64 % 4 {
                0 => (1.0, 0.0),
                1 => (0.0, 1.0),
                2 => (-1.0, 0.0),
                _ => (0.0, -1.0),
            };
            return [
                f(self.a) * c + self.center[0],
                f(self.b) * s + self.center[1],
            ];
        }
        [
            f(self.a) * t.clone().cos() + self.center[0],
            f(self.b) * t.clone().sin() + self.center[1],
        ]
    }
}

fn bisect(g: impl Fn(&Float) -> Float, mut lo: Float, mut hi: Float) -> Float {
    let neg_lo = g(&lo).is_sign_negative();
    for _ in 0..290 {
        let mid = (lo.clone() + &hi) / 2u32;
        let gm = g(&mid);
        if gm.is_zero() {
            return mid;
        }
        if gm.is_sign_negative() == neg_lo {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    lo
}

fn project(e: &Ellipse, p: [f64; 2], nearest: bool) -> geocert::Certified<Answer> {
    let how = ProjectOptions {
        nearest,
        direction: None,
        options: Options::default(),
    };
    ops::project(&Position::Double(p.to_vec()), &e.shape(), &how).expect("answers")
}

fn points(r: &geocert::Certified<Answer>) -> Vec<Point> {
    assert_eq!(r.status, Status::Exact, "{r:?}");
    assert!(r.complete, "{r:?}");
    match &r.value {
        Answer::Points(p) => p.clone(),
        Answer::Empty => vec![],
        other => panic!("unexpected {other:?}"),
    }
}

fn inside(x: &Float, b: [f64; 2]) -> bool {
    b[0] <= *x && *x <= b[1]
}

/// Every truth in exactly one reported box and every box holding exactly one truth;
/// the distance and the parameter correctly rounded.
fn check(e: &Ellipse, p: [f64; 2], what: &str) -> Vec<Point> {
    let truths = e.feet_on_axis(p).unwrap_or_else(|| e.feet(p, 4096));
    let pts = points(&project(e, p, false));
    assert_eq!(
        pts.len(),
        truths.len(),
        "{what}: feet {pts:?} vs truths {truths:?}"
    );
    for t in &truths {
        let q = e.at(t);
        let holding: Vec<&Point> = pts
            .iter()
            .filter(|pt| inside(&q[0], pt.xyz_box[0]) && inside(&q[1], pt.xyz_box[1]))
            .collect();
        assert_eq!(
            holding.len(),
            1,
            "{what}: truth t = {t} at {q:?} in {} boxes of {pts:?}",
            holding.len()
        );
        let pt = holding[0];
        let d = ((f(p[0]) - &q[0]).square() + (f(p[1]) - &q[1]).square()).sqrt();
        assert_eq!(
            pt.distance,
            Some(d.to_f64_round(Round::Nearest)),
            "{what}: distance"
        );
        let pb = pt.param_box.as_ref().expect("param box")[0][0];
        assert!(inside(t, pb), "{what}: t = {t} outside {pb:?}");
        assert_eq!(
            pt.params[0][0],
            t.to_f64_round(Round::Nearest),
            "{what}: t rounding"
        );
    }
    pts
}

/// A foot as compared: the point, its distance, its box.
type Foot = (Vec<f64>, Option<f64>, Vec<[f64; 2]>);

fn random_ellipse(rng: &mut Rng, circle: bool) -> Ellipse {
    let a = 0.5 + 3.5 * rng.unit().abs();
    Ellipse {
        center: [rng.dyadic(), rng.dyadic()],
        a,
        b: if circle {
            a
        } else {
            0.5 + 3.5 * rng.unit().abs()
        },
    }
}

#[test]
fn random_points_against_ellipses_and_circles() {
    let mut rng = Rng::new(41);
    let mut four = 0;
    for k in 0..cases() {
        let e = random_ellipse(&mut rng, k % 4 == 0);
        let scale = if k % 2 == 0 { 1.5 } else { 0.6 };
        let p = [
            e.center[0] + rng.unit() * e.a.max(e.b) * scale,
            e.center[1] + rng.unit() * e.a.max(e.b) * scale,
        ];
        if check(&e, p, &format!("case {k}")).len() == 4 {
            four += 1;
        }
    }
    assert!(four > cases() / 20, "points inside the evolute: {four}");
}

#[test]
fn points_on_the_axes_and_on_the_curve() {
    let mut rng = Rng::new(43);
    for k in 0..cases() / 4 {
        let e = random_ellipse(&mut rng, false);
        let on_x = [e.center[0] + rng.unit() * 2.0 * e.a, e.center[1]];
        let on_y = [e.center[0], e.center[1] + rng.unit() * 2.0 * e.b];
        check(&e, on_x, &format!("x axis {k}"));
        check(&e, on_y, &format!("y axis {k}"));
    }
    // Points exactly on a circle (3-4-5 triangles): one foot at distance 0.
    let e = Ellipse {
        center: [1.0, -2.0],
        a: 5.0,
        b: 5.0,
    };
    for p in [[4.0, 2.0], [-2.0, -6.0], [6.0, -2.0]] {
        // The feet are the point itself and its antipode, both exact doubles here.
        let antipode = [2.0 * e.center[0] - p[0], 2.0 * e.center[1] - p[1]];
        let mut got: Vec<Foot> = points(&project(&e, p, false))
            .into_iter()
            .map(|q| (q.xyz, q.distance, q.xyz_box))
            .collect();
        got.sort_by(|a, b| a.1.partial_cmp(&b.1).expect("distances"));
        let exact = |x: [f64; 2]| vec![[x[0], x[0]], [x[1], x[1]]];
        assert_eq!(
            got,
            vec![
                (p.to_vec(), Some(0.0), exact(p)),
                (antipode.to_vec(), Some(10.0), exact(antipode))
            ]
        );
    }
}

#[test]
fn the_evolute_cusp_is_a_triple_foot() {
    // a = 2, b = 1: the centre of curvature of the vertex (2, 0) is ((a² − b²)/a, 0).
    let e = Ellipse {
        center: [0.0, 0.0],
        a: 2.0,
        b: 1.0,
    };
    let pts = points(&project(&e, [1.5, 0.0], false));
    let mut m: Vec<(Vec<f64>, u32)> = pts
        .iter()
        .map(|p| (p.xyz.clone(), p.multiplicity))
        .collect();
    m.sort_by(|a, b| a.0[0].total_cmp(&b.0[0]));
    assert_eq!(m, vec![(vec![-2.0, 0.0], 1), (vec![2.0, 0.0], 3)]);
    // Inside the cusp: four simple feet (two of them 2^-20 apart); outside: two.
    let inner = check(&e, [1.5 - 2f64.powi(-40), 0.0], "inside the cusp");
    assert_eq!(inner.len(), 4);
    assert!(inner.iter().all(|p| p.multiplicity == 1));
    assert_eq!(
        check(&e, [1.5 + 2f64.powi(-40), 0.0], "outside the cusp").len(),
        2
    );
}

#[test]
fn nearest_is_the_nearest_truth_and_magnitudes_scale() {
    let mut rng = Rng::new(47);
    for k in 0..cases() / 2 {
        let mut e = random_ellipse(&mut rng, false);
        let mut p = [
            e.center[0] + rng.unit() * 3.0 * e.a,
            e.center[1] + rng.unit() * 3.0 * e.b,
        ];
        if k % 3 != 0 {
            // Powers of two scale exactly: the same problem at 1e±120.
            let s = if k % 3 == 1 {
                2f64.powi(400)
            } else {
                2f64.powi(-400)
            };
            e = Ellipse {
                center: [e.center[0] * s, e.center[1] * s],
                a: e.a * s,
                b: e.b * s,
            };
            p = [p[0] * s, p[1] * s];
        }
        let feet = check(&e, p, &format!("scaled case {k}"));
        let best = feet
            .iter()
            .map(|q| q.distance.expect("distance"))
            .fold(f64::INFINITY, f64::min);
        let r = project(&e, p, true);
        if r.status == Status::Exact {
            let n = points(&r);
            assert_eq!(n.len(), 1);
            assert_eq!(n[0].distance, Some(best), "case {k}");
            assert_eq!(n[0].nearest, Some(true));
        }
    }
}
