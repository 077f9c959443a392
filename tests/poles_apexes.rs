//! Poles and apexes (issue 14 item 4): lines through a cone's apex or a paraboloid's
//! vertex, exactly and 1 ulp / 1e-15 / 1e-9 / 1e-3 off, and projections along a
//! direction through the poles of spheres and ellipsoids. Every answer must be decided
//! and `complete`, with one box per truth and one truth per box; the truths come from
//! the surfaces' implicit equations evaluated in MPFR at 4000 bits (a cone's `tan α` at
//! 4000 bits), independently of the library's rational polynomials in `tan α`, and for
//! lines through the apex from the closed form (the apex alone, a double root).

#![allow(
    clippy::needless_range_loop,
    clippy::cmp_owned,
    clippy::useless_conversion
)]

use geocert::certificate::Status;
use geocert::io::{position, read_cases, shape};
use geocert::num::rng::Rng;
use geocert::ops::{self, Answer, Point, ProjectOptions};
use geocert::Certified;
use rug::{Float, Rational};

const BITS: u32 = 4000;

fn solve(json: &str, direction: Option<[f64; 3]>) -> Certified<Answer> {
    let read = read_cases(json).pop().expect("one case");
    let case = read.case.expect("a valid case");
    let options = geocert::io::options(&case).expect("options");
    if let Some(p) = &case.point {
        let how = ProjectOptions {
            nearest: false,
            direction: direction.map(|d| geocert::ops::Position::Double(d.to_vec())),
            options,
        };
        let onto = shape(case.onto.as_ref().expect("onto"), "onto").expect("shape");
        ops::project(&position(p, "point").expect("point"), &onto, &how).expect("solves")
    } else {
        let shapes: Vec<_> = case
            .objects
            .iter()
            .map(|o| shape(o, "objects").expect("shape"))
            .collect();
        ops::intersect(&shapes, &options).expect("solves")
    }
}

fn points(a: &Answer) -> &[Point] {
    match a {
        Answer::Points(p) => p,
        Answer::Empty => &[],
        other => panic!("expected points, got {other:?}"),
    }
}

fn f(x: f64) -> Float {
    Float::with_val(BITS, x)
}

/// The real roots `t` of `A t² + 2B t + C` in MPFR (by increasing `t`); a
/// discriminant below the 4000-bit noise of the coefficients (2⁻³⁶⁵⁰ relative) is a
/// double root (true discriminants here exceed 1e-700 relative).
fn quadratic(a: &Float, b: &Float, c: &Float) -> Vec<Float> {
    let d = Float::with_val(BITS, b * b) - Float::with_val(BITS, a * c);
    let scale = Float::with_val(BITS, b * b).abs() + Float::with_val(BITS, a * c).abs();
    if d.clone().abs() <= Float::with_val(BITS, &scale >> 3650u32) {
        return vec![-Float::with_val(BITS, b / a)];
    }
    if d < 0 {
        return Vec::new();
    }
    let s = d.sqrt();
    let mut r = vec![
        (-Float::with_val(BITS, b) - &s) / a,
        (-Float::with_val(BITS, b) + &s) / a,
    ];
    r.sort_by(|x, y| x.partial_cmp(y).expect("finite"));
    r
}

/// The same with exact rational coefficients: the discriminant's sign is exact, and
/// rational roots (a square discriminant) are given exactly, for exact comparisons.
fn quadratic_q(a: &Rational, b: &Rational, c: &Rational) -> Vec<(Float, Option<Rational>)> {
    let d = Rational::from(b * b) - Rational::from(a * c);
    let fq = |x: &Rational| Float::with_val(BITS, x);
    let exact = |x: Rational| (fq(&x), Some(x));
    if d == 0 {
        return vec![exact(-Rational::from(b / a))];
    }
    if d < 0 {
        return Vec::new();
    }
    let (n, m) = (d.numer().clone(), d.denom().clone());
    let mut r = if n.is_perfect_square() && m.is_perfect_square() {
        let s = Rational::from((n.sqrt(), m.sqrt()));
        vec![exact((-b.clone() - &s) / a), exact((-b.clone() + &s) / a)]
    } else {
        // 4000 bits: a subnormal offset (1 ulp of 0) moves a root by ~1e-647
        let g = |x: &Rational| Float::with_val(4000, x);
        let s = g(&d).sqrt();
        vec![
            (Float::with_val(BITS, (-g(b) - &s) / g(a)), None),
            (Float::with_val(BITS, (-g(b) + &s) / g(a)), None),
        ]
    };
    r.sort_by(|x, y| x.0.partial_cmp(&y.0).expect("finite"));
    r
}

/// `z₀ + z₁t` in `[lo, hi]`, exactly when `t` is rational.
fn within(t: &(Float, Option<Rational>), z: [&Rational; 2], lo: f64, hi: f64) -> bool {
    match &t.1 {
        Some(x) => {
            let v = Rational::from(z[1] * x) + z[0];
            v >= Rational::from_f64(lo).unwrap() && v <= Rational::from_f64(hi).unwrap()
        }
        None => {
            let v = Float::with_val(BITS, z[1] * &t.0) + z[0];
            v >= lo && v <= hi
        }
    }
}

/// The line parameters of the points (the line is the second shape), each truth in
/// exactly one box and each box holding exactly one truth.
fn one_to_one(pts: &[Point], truths: &[Float], what: &str) {
    assert_eq!(
        pts.len(),
        truths.len(),
        "{what}: count: {pts:?} vs {truths:?}"
    );
    let holds = |p: &Point, t: &Float| {
        let [lo, hi] = p.param_box.as_ref().expect("boxes")[1][0];
        lo <= *t && *t <= hi
    };
    for t in truths {
        let n = pts.iter().filter(|p| holds(p, t)).count();
        assert_eq!(n, 1, "{what}: truth {t} in {n} boxes of {pts:?}");
    }
    for p in pts {
        let n = truths.iter().filter(|t| holds(p, t)).count();
        assert_eq!(n, 1, "{what}: box {:?} holds {n} truths", p.param_box);
    }
}

fn decided(c: &Certified<Answer>, what: &str) {
    assert_ne!(c.status, Status::Undecided, "{what}: {:?}", c.reason);
    assert!(c.complete, "{what}: not complete: {:?}", c.reason);
}

/// Axes with a rational length (the exact route needs `|Z̃|` rational).
const AXES: [[f64; 3]; 5] = [
    [0.0, 0.0, 1.0],
    [0.0, 0.0, -1.0],
    [1.0, 0.0, 0.0],
    [0.0, -2.0, 0.0],
    [3.0, 4.0, 0.0],
];

fn dir(rng: &mut Rng) -> [f64; 3] {
    loop {
        let d = [rng.small_int(), rng.small_int(), rng.small_int()];
        if d.iter().any(|&x| x != 0.0) {
            return d;
        }
    }
}

fn dot(a: &[Float; 3], b: &[Float; 3]) -> Float {
    let mut s = f(0.0);
    for i in 0..3 {
        s += Float::with_val(BITS, &a[i] * &b[i]);
    }
    s
}

/// The cone `x²+y² = (r + kζ)²` in local terms on the line `o + t d`: the truths in
/// the height range, from MPFR (the module doc).
fn cone_truths(
    origin: [f64; 3],
    axis: [f64; 3],
    r: f64,
    alpha: f64,
    height: [f64; 2],
    o: [f64; 3],
    d: [f64; 3],
) -> Vec<Float> {
    let len = dot(&axis.map(f), &axis.map(f)).sqrt();
    let z: [Float; 3] = axis.map(|x| f(x) / &len);
    let w: [Float; 3] = std::array::from_fn(|i| f(o[i]) - f(origin[i]));
    let dd: [Float; 3] = d.map(f);
    let k = f(alpha).tan();
    let (z0, z1) = (dot(&z, &w), dot(&z, &dd));
    // q(t)·q(t) − ζ² − (r + kζ)²
    let (r, k2) = (f(r), Float::with_val(BITS, &k * &k));
    let a = dot(&dd, &dd) - Float::with_val(BITS, &z1 * &z1) * (f(1.0) + &k2);
    let b = dot(&w, &dd)
        - Float::with_val(BITS, &z0 * &z1) * (f(1.0) + &k2)
        - Float::with_val(BITS, &r * &k) * &z1;
    let c = dot(&w, &w)
        - Float::with_val(BITS, &z0 * &z0) * (f(1.0) + &k2)
        - Float::with_val(BITS, &r * &k) * &z0 * 2u32
        - Float::with_val(BITS, &r * &r);
    quadratic(&a, &b, &c)
        .into_iter()
        .filter(|t| {
            let zeta = Float::with_val(BITS, &z1 * t) + &z0;
            zeta >= height[0] && zeta <= height[1]
        })
        .collect()
}

fn cone_json(origin: [f64; 3], axis: [f64; 3], r: f64, alpha: f64, h: [f64; 2]) -> String {
    format!(
        r#"{{"type":"cone","origin":{origin:?},"radius":{r:?},"half_angle":{alpha:?},"axis":{axis:?},"height":{h:?}}}"#
    )
}

fn line_json(o: [f64; 3], d: [f64; 3]) -> String {
    format!(r#"{{"type":"line","origin":{o:?},"dir":{d:?}}}"#)
}

fn intersect(a: &str, b: &str) -> Certified<Answer> {
    solve(
        &format!(r#"{{"id":"t","op":"intersect","objects":[{a},{b}]}}"#),
        None,
    )
}

const HEIGHTS: [[f64; 2]; 4] = [[0.0, 2.0], [-2.0, 2.0], [-3.0, 0.0], [0.5, 2.0]];

#[test]
fn lines_through_a_cone_apex_meet_it_only_there() {
    let mut rng = Rng::new(1401);
    for case in 0..240 {
        let apex = [rng.dyadic(), rng.dyadic(), rng.dyadic()];
        let axis = AXES[rng.below(AXES.len())];
        let alpha = (0.05 + 1.4 * rng.unit().abs()) * if rng.coin() { 1.0 } else { -1.0 };
        let h = HEIGHTS[rng.below(HEIGHTS.len())];
        let d = dir(&mut rng);
        let s = rng.dyadic();
        let o: [f64; 3] = std::array::from_fn(|i| apex[i] - s * d[i]);
        let what = format!("case {case}: apex {apex:?} axis {axis:?} α {alpha} h {h:?} d {d:?}");
        let r = intersect(&cone_json(apex, axis, 0.0, alpha, h), &line_json(o, d));
        decided(&r, &what);
        let pts = points(&r.value);
        if h[0] > 0.0 {
            assert!(
                pts.is_empty(),
                "{what}: the apex is outside the height: {pts:?}"
            );
            continue;
        }
        assert_eq!(pts.len(), 1, "{what}: {pts:?}");
        let p = &pts[0];
        assert_eq!(p.multiplicity, 2, "{what}");
        assert!(!p.tangent, "{what}: the apex is singular, not a tangency");
        let exact = p.exact.as_ref().expect("the apex exactly");
        for i in 0..3 {
            assert_eq!(exact.xyz[i], Rational::from_f64(apex[i]).unwrap(), "{what}");
        }
        one_to_one(pts, &[f(s)], &what);
        // every u is a parameter of the apex; v = 0
        let b = &p.param_box.as_ref().unwrap()[0];
        assert!(
            b[0][0] <= 0.0 && b[0][1] >= std::f64::consts::TAU,
            "{what}: u {b:?}"
        );
        assert!(b[1][0] <= 0.0 && b[1][1] >= 0.0, "{what}: v {b:?}");
    }
}

#[test]
fn lines_near_a_cone_apex_and_elsewhere_against_mpfr_truth() {
    let mut rng = Rng::new(1402);
    let offsets = [0.0, 1e-3, 1e-9, 1e-15, f64::EPSILON];
    for case in 0..400 {
        let origin = [rng.dyadic(), rng.dyadic(), rng.dyadic()];
        let axis = AXES[rng.below(AXES.len())];
        let radius = if rng.coin() { 0.0 } else { 0.5 };
        let alpha = (0.05 + 1.4 * rng.unit().abs()) * if rng.coin() { 1.0 } else { -1.0 };
        let h = HEIGHTS[rng.below(HEIGHTS.len())];
        let d = dir(&mut rng);
        let s = rng.dyadic();
        let delta = offsets[case % offsets.len()];
        let mut o: [f64; 3] = std::array::from_fn(|i| origin[i] - s * d[i]);
        let k = rng.below(3);
        o[k] = if delta == f64::EPSILON {
            geocert::num::round::next_up(o[k])
        } else {
            o[k] + delta
        };
        let what = format!("case {case}: origin {origin:?} axis {axis:?} r {radius} α {alpha} h {h:?} o {o:?} d {d:?}");
        let r = intersect(&cone_json(origin, axis, radius, alpha, h), &line_json(o, d));
        decided(&r, &what);
        let q = |x: f64| Rational::from_f64(x).unwrap();
        let w: [Rational; 3] = std::array::from_fn(|i| q(origin[i]) - q(o[i]));
        let cross = (0..3).all(|i| {
            let (j, l) = ((i + 1) % 3, (i + 2) % 3);
            Rational::from(&w[j] * q(d[l])) == Rational::from(&w[l] * q(d[j]))
        });
        let truths = if radius == 0.0 && cross {
            // through the apex (the offset absorbed): the double root, in closed form
            let dd: Rational = d.iter().map(|&x| q(x * x)).sum();
            let t: Rational = (0..3)
                .map(|i| Rational::from(&w[i] * q(d[i])))
                .sum::<Rational>()
                / dd;
            if h[0] <= 0.0 && h[1] >= 0.0 {
                vec![Float::with_val(BITS, &t)]
            } else {
                Vec::new()
            }
        } else {
            cone_truths(origin, axis, radius, alpha, h, o, d)
        };
        one_to_one(points(&r.value), &truths, &what);
    }
}

#[test]
fn lines_through_and_near_a_paraboloid_vertex() {
    let mut rng = Rng::new(1403);
    let offsets = [0.0, 1e-3, 1e-9, 1e-15, f64::EPSILON];
    for case in 0..300 {
        let centre = [rng.dyadic(), rng.dyadic(), rng.dyadic()];
        let a = [0.5, 1.0, 2.0, 3.0][rng.below(4)];
        let range = [[0.0, 2.0], [-2.0, 0.0], [0.25, 2.0]][rng.below(3)];
        let d = dir(&mut rng);
        let s = rng.dyadic();
        let delta = offsets[case % offsets.len()];
        let mut o: [f64; 3] = std::array::from_fn(|i| centre[i] - s * d[i]);
        let k = rng.below(3);
        o[k] = if delta == f64::EPSILON {
            geocert::num::round::next_down(o[k])
        } else {
            o[k] - delta
        };
        let what = format!("case {case}: centre {centre:?} a {a} range {range:?} o {o:?} d {d:?}");
        let json = format!(
            r#"{{"type":"paraboloid","center":{centre:?},"a":{a:?},"b":{a:?},"axis":[0.0,0.0,1.0],"range":{range:?}}}"#
        );
        let r = intersect(&json, &line_json(o, d));
        decided(&r, &what);
        // ρ²/a² − ζ on the line, local ζ the z offset, in exact rationals
        let q = |x: f64| Rational::from_f64(x).unwrap();
        let w: [Rational; 3] = std::array::from_fn(|i| q(o[i]) - q(centre[i]));
        let dq = d.map(q);
        let a2 = q(a * a);
        let (z0, z1) = (w[2].clone(), dq[2].clone());
        let rho = |x: &[Rational; 3], y: &[Rational; 3]| {
            Rational::from(&x[0] * &y[0]) + Rational::from(&x[1] * &y[1])
        };
        let qa = rho(&dq, &dq) / &a2;
        let qb = rho(&w, &dq) / &a2 - Rational::from(&z1 / 2u32);
        let qc = rho(&w, &w) / &a2 - &z0;
        let truths = if qa == 0 {
            // a line parallel to the axis: linear
            if qb == 0 {
                Vec::new()
            } else {
                let t = -Rational::from(&qc / &qb) / 2u32;
                vec![(Float::with_val(BITS, &t), Some(t))]
            }
        } else {
            quadratic_q(&qa, &qb, &qc)
        };
        let [v0, v1] = range;
        let (lo, hi) = if v0 >= 0.0 {
            (v0 * v0, v1 * v1)
        } else {
            (v1 * v1, v0 * v0)
        };
        let truths: Vec<Float> = truths
            .into_iter()
            .filter(|t| within(t, [&z0, &z1], lo, hi))
            .map(|t| t.0)
            .collect();
        one_to_one(points(&r.value), &truths, &what);
    }
}

#[test]
fn projections_along_directions_through_poles_of_spheres_and_ellipsoids() {
    let mut rng = Rng::new(1404);
    let offsets = [0.0, 1e-9, 1e-15, f64::EPSILON];
    for case in 0..240 {
        let c = [rng.dyadic(), rng.dyadic(), rng.dyadic()];
        let abc = if rng.coin() {
            let r = [1.0, 2.0, 0.75][rng.below(3)];
            [r, r, r]
        } else {
            [[1.0, 2.0, 3.0], [2.0, 1.0, 0.5], [3.0, 3.0, 1.0]][rng.below(3)]
        };
        let h = rng.dyadic() * 2.0;
        let delta = offsets[case % offsets.len()];
        let mut p = [c[0], c[1], c[2] + h];
        p[0] = if delta == f64::EPSILON {
            geocert::num::round::next_up(p[0])
        } else {
            p[0] + delta
        };
        let down = if rng.coin() { 1.0 } else { -1.0 };
        let d = [0.0, 0.0, down];
        let onto = format!(
            r#"{{"type":"ellipsoid","center":{c:?},"a":{:?},"b":{:?},"c":{:?}}}"#,
            abc[0], abc[1], abc[2]
        );
        let json = format!(r#"{{"id":"t","op":"project","point":{p:?},"onto":{onto}}}"#);
        let what = format!("case {case}: {json} along {d:?}");
        let r = solve(&json, Some(d));
        decided(&r, &what);
        // Σ (pᵢ − cᵢ + t dᵢ)²/aᵢ² = 1, in exact rationals
        let q = |x: f64| Rational::from_f64(x).unwrap();
        let w: [Rational; 3] = std::array::from_fn(|i| q(p[i]) - q(c[i]));
        let inv: [Rational; 3] = abc.map(|x| Rational::from(1) / q(x * x));
        let mut qa = Rational::new();
        let mut qb = Rational::new();
        let mut qc = Rational::from(-1);
        for i in 0..3 {
            qa += q(d[i] * d[i]) * &inv[i];
            qb += Rational::from(&w[i] * q(d[i])) * &inv[i];
            qc += Rational::from(&w[i] * &w[i]) * &inv[i];
        }
        let truths: Vec<Float> = quadratic_q(&qa, &qb, &qc)
            .into_iter()
            .map(|t| t.0)
            .collect();
        let pts = points(&r.value);
        one_to_one(pts, &truths, &what);
        if delta == 0.0 {
            // through the poles: every u is a parameter
            for q in pts {
                let u = q.param_box.as_ref().unwrap()[0][0];
                assert!(
                    u[0] <= 0.0 && u[1] >= std::f64::consts::TAU,
                    "{what}: u {u:?}"
                );
            }
        }
    }
}

/// Feet of `p = centre + (δ, 0, h)`-like points on the axis of an ellipsoid (local
/// frame = world axes): the poles `(0, 0, ±c)` and, per equatorial axis `i` with
/// `aᵢ ≠ c`, `q_z = h c²/(c² − aᵢ²)`, `R = 1 − q_z²/c²`, two feet `±aᵢ√R` when
/// `R > 0` (closed forms of the foot condition `qᵢ = pᵢ/(1 + λ/aᵢ²)`).
fn ellipsoid_axis_feet(abc: [f64; 3], h: f64) -> Vec<[Float; 3]> {
    let g = |x: f64| Float::with_val(BITS, x);
    let c = g(abc[2]);
    let mut out = vec![[g(0.0), g(0.0), c.clone()], [g(0.0), g(0.0), -c.clone()]];
    for i in 0..2 {
        if abc[i] == abc[2] {
            continue;
        }
        let ai2 = g(abc[i] * abc[i]);
        let c2 = Float::with_val(BITS, &c * &c);
        let qz = g(h) * &c2 / (c2.clone() - &ai2);
        let r = g(1.0) - Float::with_val(BITS, &qz * &qz) / Float::with_val(BITS, &c * &c);
        if r > 0 {
            let x = g(abc[i]) * r.sqrt();
            for s in [-1.0, 1.0] {
                let mut q = [g(0.0), g(0.0), qz.clone()];
                q[i] = Float::with_val(BITS, &x * s);
                out.push(q);
            }
        }
    }
    out
}

/// Each truth near exactly one box and each box near exactly one truth (within
/// `tol`; 0: containment).
fn one_to_one_xyz(pts: &[Point], truths: &[[Float; 3]], centre: [f64; 3], tol: f64, what: &str) {
    assert_eq!(pts.len(), truths.len(), "{what}: count {pts:?}");
    let near = |p: &Point, t: &[Float; 3]| {
        (0..3).all(|i| {
            let x = Float::with_val(BITS, &t[i] + centre[i]);
            p.xyz_box[i][0] - tol <= x && x <= p.xyz_box[i][1] + tol
        })
    };
    for t in truths {
        let n = pts.iter().filter(|p| near(p, t)).count();
        assert_eq!(n, 1, "{what}: truth {t:?} near {n} boxes of {pts:?}");
    }
    for p in pts {
        let n = truths.iter().filter(|t| near(p, t)).count();
        assert_eq!(n, 1, "{what}: box {:?} near {n} truths", p.xyz_box);
    }
}

#[test]
fn projections_of_points_on_and_near_the_axis_of_ellipsoids() {
    let mut rng = Rng::new(1405);
    let shapes = [
        [1.0, 2.0, 3.0],
        [3.0, 2.0, 1.0],
        [2.0, 0.5, 1.0],
        [1.0, 1.5, 0.75],
    ];
    for case in 0..200 {
        let c = [rng.dyadic(), rng.dyadic(), rng.dyadic()];
        let abc = shapes[rng.below(shapes.len())];
        let h = rng.dyadic() / 2.0;
        let delta = [0.0, 1e-9, 1e-12][case % 3];
        let p = [c[0] + delta, c[1], c[2] + h];
        if p[0] - c[0] != delta {
            continue;
        }
        let onto = format!(
            r#"{{"type":"ellipsoid","center":{c:?},"a":{:?},"b":{:?},"c":{:?}}}"#,
            abc[0], abc[1], abc[2]
        );
        let json = format!(r#"{{"id":"t","op":"project","point":{p:?},"onto":{onto}}}"#);
        let what = format!("case {case}: {json}");
        let truths = ellipsoid_axis_feet(abc, h);
        // skip the degenerate heights (p at a centre of curvature of a pole, R = 0)
        let degenerate = (0..2).any(|i| {
            let qz = h * abc[2] * abc[2] / (abc[2] * abc[2] - abc[i] * abc[i]);
            (qz.abs() - abc[2]).abs() < 1e-6
        });
        if degenerate {
            continue;
        }
        let r = solve(&json, None);
        decided(&r, &what);
        let pts = points(&r.value);
        // on the axis: containment; 1e-9 off: within 1e-6 of the axis feet
        let tol = if delta == 0.0 { 0.0 } else { 1e-6 };
        one_to_one_xyz(pts, &truths, c, tol, &what);
        if delta == 0.0 {
            // the poles: every u is a parameter
            for q in pts.iter().filter(|q| q.xyz[0] == c[0] && q.xyz[1] == c[1]) {
                let u = q.param_box.as_ref().unwrap()[0][0];
                assert!(
                    u[0] <= 0.0 && u[1] >= std::f64::consts::TAU,
                    "{what}: u {u:?}"
                );
            }
        }
    }
}

#[test]
fn projections_of_points_on_the_axis_of_paraboloids() {
    let mut rng = Rng::new(1406);
    for case in 0..200 {
        let c = [rng.dyadic(), rng.dyadic(), rng.dyadic()];
        let (a, b) = [(1.0, 2.0), (0.5, 1.0), (2.0, 0.75)][rng.below(3)];
        let h = rng.dyadic() / 2.0;
        let range = [0.0, 2.0];
        let p = [c[0], c[1], c[2] + h];
        let onto = format!(
            r#"{{"type":"paraboloid","center":{c:?},"a":{a:?},"b":{b:?},"axis":[0.0,0.0,1.0],"range":{range:?}}}"#
        );
        let json = format!(r#"{{"id":"t","op":"project","point":{p:?},"onto":{onto}}}"#);
        let what = format!("case {case}: {json}");
        // the vertex, and per axis i: ζ = h − aᵢ²/2, two feet ±aᵢ√ζ when 0 < ζ ≤ 4
        let g = |x: f64| Float::with_val(BITS, x);
        let mut truths = vec![[g(0.0), g(0.0), g(0.0)]];
        for (i, ai) in [a, b].into_iter().enumerate() {
            let zeta = h - ai * ai / 2.0; // exact for these dyadics
            if zeta == 0.0 {
                truths.clear(); // degenerate: the vertex is a multiple foot; skip
                break;
            }
            if zeta > 0.0 && zeta <= 4.0 {
                let x = g(ai) * g(zeta).sqrt();
                for s in [-1.0, 1.0] {
                    let mut q = [g(0.0), g(0.0), g(zeta)];
                    q[i] = Float::with_val(BITS, &x * s);
                    truths.push(q);
                }
            }
        }
        if truths.is_empty() {
            continue;
        }
        let r = solve(&json, None);
        decided(&r, &what);
        one_to_one_xyz(points(&r.value), &truths, c, 0.0, &what);
    }
}
