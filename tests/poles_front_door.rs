//! Curves through the poles of spheres and ellipsoids at the front door (issue 14 item
//! 4; OPERATIONS.md §14): `geocert solve` answers them on a chart with new poles, so
//! a root at a pole is found, `verified`, and the answer `complete`.
//!
//! Seeded families — helices and Bézier curves through the north pole, the south pole,
//! 1e-9 from a pole, through a pole and along the seam's meridian plane, and far from
//! both poles — on spheres and ellipsoids with random centres, sizes and axes. The truth
//! is computed independently with MPFR at 300 bits from the input doubles: the frame of
//! docs/FORMAT.md "Frames", the implicit equation `F(t) = |q(c(t))|² − 1` with
//! `q = diag(a, b, c)⁻¹ · local(x)`, its roots bracketed by sign changes on a fine grid
//! and refined by bisection. Each answer must be `verified`, `complete`, with exactly
//! the true number of roots, and every certified box (`t`, the point, `u` modulo 2π,
//! `v`) must hold its true root's values.

use geocert::io::{read_cases, solve_case};
use geocert::num::rng::Rng;
use rug::float::Constant;
use rug::Float;
use serde_json::{json, Value};

const BITS: u32 = 300;
/// Grid of the sign-change search for the true roots.
const GRID: usize = 4000;

fn f(x: f64) -> Float {
    Float::with_val(BITS, x)
}

fn dot(a: &[Float; 3], b: &[Float; 3]) -> Float {
    Float::with_val(BITS, &a[0] * &b[0]) + Float::with_val(BITS, &a[1] * &b[1]) + &a[2] * &b[2]
}

fn unit(a: &[Float; 3]) -> [Float; 3] {
    let n = dot(a, a).sqrt();
    std::array::from_fn(|i| Float::with_val(BITS, &a[i] / &n))
}

/// The frame `X, Y, Z` of docs/FORMAT.md "Frames" for `axis` (no `ref`), exactly as
/// written there, at 300 bits.
fn frame(axis: [f64; 3]) -> [[Float; 3]; 3] {
    let z = unit(&axis.map(f));
    let k = (0..3)
        .min_by(|&i, &j| axis[i].abs().total_cmp(&axis[j].abs()))
        .unwrap();
    let e: [Float; 3] = std::array::from_fn(|i| f(if i == k { 1.0 } else { 0.0 }));
    let ez = dot(&e, &z);
    let x = unit(&std::array::from_fn(|i| {
        Float::with_val(BITS, &e[i] - Float::with_val(BITS, &ez * &z[i]))
    }));
    let y = [
        Float::with_val(BITS, &z[1] * &x[2]) - Float::with_val(BITS, &z[2] * &x[1]),
        Float::with_val(BITS, &z[2] * &x[0]) - Float::with_val(BITS, &z[0] * &x[2]),
        Float::with_val(BITS, &z[0] * &x[1]) - Float::with_val(BITS, &z[1] * &x[0]),
    ];
    [x, y, z]
}

/// A whole sphere or ellipsoid: centre, semi-axes, axis.
#[derive(Clone)]
struct Quadric {
    center: [f64; 3],
    abc: [f64; 3],
    axis: [f64; 3],
}

impl Quadric {
    fn json(&self) -> Value {
        if self.abc[0] == self.abc[1] && self.abc[1] == self.abc[2] {
            json!({"type": "sphere", "center": self.center, "radius": self.abc[0], "axis": self.axis})
        } else {
            json!({"type": "ellipsoid", "center": self.center, "a": self.abc[0], "b": self.abc[1],
                   "c": self.abc[2], "axis": self.axis})
        }
    }
    /// `q` of a world point (exact frame at 300 bits).
    fn unit_coords(&self, x: &[Float; 3]) -> [Float; 3] {
        let fr = frame(self.axis);
        let d: [Float; 3] = std::array::from_fn(|i| Float::with_val(BITS, &x[i] - self.center[i]));
        std::array::from_fn(|i| dot(&d, &fr[i]) / self.abc[i])
    }
    /// The pole `v = ±π/2` in doubles (rounded: the curves pass within rounding of it).
    fn pole(&self, north: bool) -> [f64; 3] {
        let z = unit(&self.axis.map(f));
        let s = if north { 1.0 } else { -1.0 };
        std::array::from_fn(|i| self.center[i] + s * self.abc[2] * z[i].to_f64())
    }
    fn frame_f64(&self) -> [[f64; 3]; 3] {
        frame(self.axis).map(|v| v.map(|x| x.to_f64()))
    }
}

/// The curves of the families, evaluated at 300 bits.
#[derive(Clone)]
enum TestCurve {
    /// `center + r (cos t X + sin t Y) + pitch t/(2π) Z`, frame of `axis`.
    Helix {
        center: [f64; 3],
        radius: f64,
        pitch: f64,
        axis: [f64; 3],
        range: [f64; 2],
    },
    Bezier(Vec<[f64; 3]>),
}

impl TestCurve {
    fn json(&self) -> Value {
        match self {
            TestCurve::Helix {
                center,
                radius,
                pitch,
                axis,
                range,
            } => json!({"type": "helix", "center": center, "radius": radius, "pitch": pitch,
                        "axis": axis, "range": range}),
            TestCurve::Bezier(p) => json!({"type": "bezier", "points": p}),
        }
    }
    fn domain(&self) -> [f64; 2] {
        match self {
            TestCurve::Helix { range, .. } => *range,
            TestCurve::Bezier(_) => [0.0, 1.0],
        }
    }
    fn at(&self, t: &Float) -> [Float; 3] {
        match self {
            TestCurve::Helix {
                center,
                radius,
                pitch,
                axis,
                ..
            } => {
                let [x, y, z] = frame(*axis);
                let (c, s) = (
                    Float::with_val(BITS, t.cos_ref()),
                    Float::with_val(BITS, t.sin_ref()),
                );
                let two_pi = Float::with_val(BITS, Constant::Pi) * 2u32;
                let h = Float::with_val(BITS, t * *pitch) / two_pi;
                std::array::from_fn(|i| {
                    let r = Float::with_val(BITS, &c * &x[i]) + Float::with_val(BITS, &s * &y[i]);
                    Float::with_val(BITS, &r * *radius)
                        + Float::with_val(BITS, &h * &z[i])
                        + center[i]
                })
            }
            TestCurve::Bezier(p) => {
                let mut pts: Vec<[Float; 3]> = p.iter().map(|q| q.map(f)).collect();
                let s = Float::with_val(BITS, 1 - t.clone());
                while pts.len() > 1 {
                    pts = pts
                        .windows(2)
                        .map(|w| {
                            std::array::from_fn(|i| {
                                Float::with_val(BITS, &s * &w[0][i])
                                    + Float::with_val(BITS, t * &w[1][i])
                            })
                        })
                        .collect();
                }
                pts.swap_remove(0)
            }
        }
    }
}

fn residual(q: &Quadric, c: &TestCurve, t: &Float) -> Float {
    let u = q.unit_coords(&c.at(t));
    dot(&u, &u) - 1u32
}

/// The true roots `t` of `F` on the curve's domain: sign changes on a grid, refined by
/// bisection to 2⁻²⁰⁰ of the domain. The families keep `F ≠ 0` at the grid points and
/// the ends (asserted) and their roots simple.
fn true_roots(q: &Quadric, c: &TestCurve) -> Vec<Float> {
    let [lo, hi] = c.domain();
    let t_at = |k: usize| f(lo) + Float::with_val(BITS, f(hi - lo) * k as u32) / GRID as u32;
    let vals: Vec<Float> = (0..=GRID).map(|k| residual(q, c, &t_at(k))).collect();
    assert!(
        vals.iter().all(|v| !v.is_zero()),
        "a grid point on the surface"
    );
    let mut roots = Vec::new();
    for k in 0..GRID {
        if vals[k].is_sign_negative() == vals[k + 1].is_sign_negative() {
            continue;
        }
        let (mut a, mut b) = (t_at(k), t_at(k + 1));
        let neg_a = vals[k].is_sign_negative();
        for _ in 0..200 {
            let m = Float::with_val(BITS, &a + &b) / 2u32;
            if residual(q, c, &m).is_sign_negative() == neg_a {
                a = m;
            } else {
                b = m;
            }
        }
        roots.push(a);
    }
    roots
}

fn solve(id: &str, q: &Quadric, c: &TestCurve, surface_first: bool) -> Value {
    let objects = if surface_first {
        vec![q.json(), c.json()]
    } else {
        vec![c.json(), q.json()]
    };
    let case = json!({"id": id, "op": "intersect", "objects": objects});
    let read = read_cases(&case.to_string()).into_iter().next().unwrap();
    serde_json::from_str(&solve_case(read).to_json_line()).unwrap()
}

fn in_box(x: &Float, b: &Value) -> bool {
    let (lo, hi) = (b[0].as_f64().unwrap(), b[1].as_f64().unwrap());
    *x >= lo && *x <= hi
}

/// `x` in the box up to `2⁻²⁵⁰·|x|`: the truth's own rounding at 300 bits. A coordinate
/// that is a double exactly (a curve in the plane `y = c`, every control point with
/// `y = c`) comes out of the 300-bit evaluation `c ± 2⁻³⁰⁰|c|`, and the exact path's box
/// is then the point `[c, c]`. A box that misses the truth by more is still caught.
fn in_box_up_to_rounding(x: &Float, b: &Value) -> bool {
    let slack = Float::with_val(BITS, x.clone().abs() >> 250u32);
    let (lo, hi) = (b[0].as_f64().unwrap(), b[1].as_f64().unwrap());
    Float::with_val(BITS, x + &slack) >= lo && Float::with_val(BITS, x - &slack) <= hi
}

/// `u` modulo 2π in its box (a box straddling 0 is the arc across the seam), up to
/// `2⁻²⁵⁰` (the truth's rounding: an angle that is exactly 0, a curve in the meridian
/// plane, comes out of `atan2` at 300 bits as `±10⁻⁹⁰`).
fn angle_in_box(u: &Float, b: &Value) -> bool {
    let two_pi = Float::with_val(BITS, Constant::Pi) * 2u32;
    let slack = Float::with_val(BITS, 1u32) >> 250u32;
    let (lo, hi) = (b[0].as_f64().unwrap(), b[1].as_f64().unwrap());
    [-1i32, 0, 1].iter().any(|&k| {
        let x = Float::with_val(BITS, u + Float::with_val(BITS, &two_pi * k));
        Float::with_val(BITS, &x + &slack) >= lo && Float::with_val(BITS, &x - &slack) <= hi
    })
}

/// Solve and check against the truth (module doc); returns the answer's points for
/// further checks, with the true `(t, u, v)` of each.
fn check(id: &str, q: &Quadric, c: &TestCurve, surface_first: bool) -> Vec<(Value, [Float; 3])> {
    let r = solve(id, q, c, surface_first);
    let truth = true_roots(q, c);
    assert!(
        r["status"] == "verified" || r["status"] == "exact",
        "{id}: {r}"
    );
    assert_eq!(r["complete"], true, "{id}: {r}");
    let points = r["points"].as_array().cloned().unwrap_or_default();
    assert_eq!(points.len(), truth.len(), "{id}: {r}");
    let (s, cv) = if surface_first { (0, 1) } else { (1, 0) };
    let mut out = Vec::new();
    for t in truth {
        let hits: Vec<&Value> = points
            .iter()
            .filter(|p| in_box(&t, &p["param_box"][cv][0]))
            .collect();
        assert_eq!(hits.len(), 1, "{id}: true root t = {t:.20} in one box: {r}");
        let p = hits[0];
        let x = c.at(&t);
        for i in 0..3 {
            assert!(
                in_box_up_to_rounding(&x[i], &p["box"][i]),
                "{id}: point {i} of t = {t:.20}: {p}"
            );
        }
        let uq = q.unit_coords(&x);
        let rho = Float::with_val(BITS, uq[0].clone().hypot(&uq[1]));
        let u = Float::with_val(BITS, uq[1].atan2_ref(&uq[0]));
        let v = Float::with_val(BITS, uq[2].atan2_ref(&rho));
        let pb = &p["param_box"][s];
        assert!(
            angle_in_box(&u, &pb[0]),
            "{id}: u = {u:.20} of t = {t:.20}: {p}"
        );
        assert!(in_box(&v, &pb[1]), "{id}: v = {v:.20} of t = {t:.20}: {p}");
        assert_eq!(p["tangent"], false, "{id}: {p}");
        out.push((p.clone(), [t, u, v]));
    }
    out
}

fn quadric(rng: &mut Rng, sphere: bool, tilted: bool) -> Quadric {
    let center = [rng.dyadic(), rng.dyadic(), rng.dyadic()];
    let size = |rng: &mut Rng| 0.5 + 2.5 * (rng.unit() + 1.0) / 2.0;
    let abc = if sphere {
        [size(rng); 3]
    } else {
        [size(rng), size(rng), size(rng)]
    };
    let axis = if tilted {
        [rng.unit(), rng.unit(), 1.0 + rng.unit().abs()]
    } else {
        [0.0, 0.0, 1.0]
    };
    Quadric { center, abc, axis }
}

/// A helix whose point at `t = 0` is `through` (its own axis random).
fn helix_through(rng: &mut Rng, through: [f64; 3], scale: f64) -> TestCurve {
    let axis = [rng.unit(), rng.unit(), rng.unit() + 2.5];
    let radius = scale * (0.2 + 0.3 * (rng.unit() + 1.0));
    let fr = frame(axis).map(|v| v.map(|x| x.to_f64()));
    let center = std::array::from_fn(|i| through[i] - radius * fr[0][i]);
    TestCurve::Helix {
        center,
        radius,
        pitch: scale * (0.5 + rng.unit().abs()),
        axis,
        range: [-1.0 - rng.unit().abs(), 1.0 + rng.unit().abs()],
    }
}

/// A quadratic Bézier with `B(1/2) = through` (up to rounding), ends random around it.
fn bezier_through(rng: &mut Rng, through: [f64; 3], scale: f64) -> TestCurve {
    let p0: [f64; 3] = std::array::from_fn(|i| through[i] + scale * 1.5 * rng.unit());
    let p2: [f64; 3] = std::array::from_fn(|i| through[i] + scale * 1.5 * rng.unit());
    let p1 = std::array::from_fn(|i| 2.0 * through[i] - (p0[i] + p2[i]) / 2.0);
    TestCurve::Bezier(vec![p0, p1, p2])
}

fn curve_through(rng: &mut Rng, k: usize, through: [f64; 3], scale: f64) -> TestCurve {
    if k.is_multiple_of(2) {
        helix_through(rng, through, scale)
    } else {
        bezier_through(rng, through, scale)
    }
}

/// The roots within `10⁻¹²` (in latitude) of a pole.
fn pole_roots(points: &[(Value, [Float; 3])]) -> usize {
    let half_pi = Float::with_val(BITS, Constant::Pi) / 2u32;
    points
        .iter()
        .filter(|(_, [_, _, v])| Float::with_val(BITS, &half_pi - v.clone().abs()) < 1e-12)
        .count()
}

/// The points whose `u` box is the whole turn (the pole convention): each must report
/// `u = 0` and be a true pole root (`|v|` within 1e-12 of π/2).
fn pole_convention(points: &[(Value, [Float; 3])], surface_first: bool, id: &str) -> usize {
    let s = usize::from(!surface_first);
    let half_pi = Float::with_val(BITS, Constant::Pi) / 2u32;
    let mut whole = 0;
    for (p, [_, _, v]) in points {
        let ub = &p["param_box"][s][0];
        if ub[0].as_f64().unwrap() <= 0.0 && ub[1].as_f64().unwrap() >= std::f64::consts::TAU {
            whole += 1;
            assert_eq!(
                p["params"][s][0], 0.0,
                "{id}: u at a pole is reported 0: {p}"
            );
            let gap = Float::with_val(BITS, &half_pi - v.clone().abs());
            assert!(gap < 1e-12, "{id}: a whole turn away from a pole: {p}");
        }
    }
    whole
}

#[test]
fn curves_through_a_pole_answer_complete_with_the_pole_root() {
    let mut rng = Rng::new(1414);
    for k in 0..12 {
        let (sphere, tilted, north) = (k % 3 == 0, k % 4 >= 2, k % 5 < 3);
        let q = quadric(&mut rng, sphere, tilted);
        let pole = q.pole(north);
        let scale = q.abc.iter().cloned().fold(f64::INFINITY, f64::min);
        let c = curve_through(&mut rng, k, pole, scale);
        let id = format!("pole{k}");
        let first = rng.coin();
        let points = check(&id, &q, &c, first);
        // An axis-aligned pole is a double, so the curve passes through it: its box
        // holds it. A tilted pole is rounded: the curve passes within 1e-16 of it, and
        // the root's box holds the axis or not (either way the truth is inside).
        // On the exact path (a Bézier or NURBS curve against a whole sphere or
        // ellipsoid) the root's coordinates are correctly rounded: the box holds the
        // pole only when the curve passes exactly through it, else `u` is determined.
        let whole = pole_convention(&points, first, &id);
        assert!(whole <= 1, "{id}: {whole}");
        assert_eq!(pole_roots(&points), 1, "{id}: one root at the pole");
    }
}

#[test]
fn curves_1e9_from_a_pole_answer_complete() {
    let mut rng = Rng::new(1415);
    for k in 0..8 {
        let q = quadric(&mut rng, k % 2 == 0, k % 3 == 0);
        let fr = q.frame_f64();
        let pole = q.pole(k % 4 < 2);
        let side = 1e-9 * q.abc[0];
        let near: [f64; 3] = std::array::from_fn(|i| pole[i] + side * fr[0][i]);
        let scale = q.abc.iter().cloned().fold(f64::INFINITY, f64::min);
        let c = curve_through(&mut rng, k, near, scale);
        let points = check(&format!("near{k}"), &q, &c, true);
        // 1e-9 from the pole u is determined: no root reports the whole turn.
        assert_eq!(pole_convention(&points, true, "near"), 0);
    }
}

/// A Bézier curve in the meridian plane `y = 0` of an axis-aligned sphere or ellipsoid
/// (every point of it has `y` exactly the centre's): it enters across the seam `u = 0`
/// (`x > 0`, so `u` is exactly 0 there) and leaves through the north pole, at
/// `B(1/2)`.
#[test]
fn curves_through_a_pole_and_the_seam_answer_each_root_once() {
    let mut rng = Rng::new(1416);
    for k in 0..8 {
        let q = quadric(&mut rng, k % 2 == 0, false);
        let [a, _, c] = q.abc;
        let o = q.center;
        let north = [o[0], o[1], o[2] + c];
        let p0 = [
            o[0] + a * (1.4 + 0.2 * rng.unit()),
            o[1],
            o[2] + c * 0.3 * rng.unit(),
        ];
        let p2 = [
            o[0] - a * (0.5 + 0.2 * rng.unit()),
            o[1],
            o[2] + c * (1.6 + 0.2 * rng.unit()),
        ];
        let p1 = std::array::from_fn(|i| 2.0 * north[i] - (p0[i] + p2[i]) / 2.0);
        let curve = TestCurve::Bezier(vec![p0, p1, p2]);
        let id = format!("seam{k}");
        let first = k % 3 != 0;
        let points = check(&id, &q, &curve, first);
        assert!(pole_convention(&points, first, &id) <= 1, "{id}");
        assert_eq!(pole_roots(&points), 1, "{id}: one root at the pole");
        // The seam root: u = 0 (up to the 300-bit rounding of the truth; its box holds
        // it mod 2π: checked above), once.
        let seam = points
            .iter()
            .filter(|(_, [_, u, v])| u.clone().abs() < 1e-30 && v.clone().abs() < 1.5)
            .count();
        assert_eq!(seam, 1, "{id}: one root on the seam");
    }
}

/// Far from both poles nothing changes: every root in its box, complete.
#[test]
fn curves_far_from_the_poles_answer_as_before() {
    let mut rng = Rng::new(1417);
    for k in 0..8 {
        let q = quadric(&mut rng, k % 2 == 1, k % 3 == 1);
        let fr = q.frame_f64();
        // A point of the equator, at longitude w.
        let w = 3.0 * (rng.unit() + 1.0);
        let on: [f64; 3] = std::array::from_fn(|i| {
            q.center[i] + q.abc[0] * w.cos() * fr[0][i] + q.abc[1] * w.sin() * fr[1][i]
        });
        let scale = 0.3 * q.abc.iter().cloned().fold(f64::INFINITY, f64::min);
        let c = curve_through(&mut rng, k, on, scale);
        let points = check(&format!("far{k}"), &q, &c, k % 2 == 0);
        assert!(!points.is_empty());
        assert_eq!(pole_convention(&points, k % 2 == 0, "far"), 0);
    }
}
