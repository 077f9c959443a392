//! Point → circle and point → ellipse of space, decided exactly (issue 14 item 9): every
//! foot correctly rounded (coordinates, parameter, distance), `complete`, the evolute's
//! cusp a triple foot, one ulp either side of it four or two simple feet, and a point on
//! a circle's axis (or a plane circle's centre) answered at once as a continuum.
//!
//! The truth is independent of the solver's chart and Apollonius conic: the frame of
//! docs/FORMAT.md "Frames" is built here in 256-bit MPFR, the curve is parametrised,
//! and the feet are the roots of `f(t) = (q(t) − p)·q′(t)` on `[0, 2π)`, found by
//! sampling sign changes and bisection (random points, far from the evolute), or in
//! closed form on the major axis (`sin t = 0`, or `cos t = s·a/(a² − b²)`).
//! Magnitudes: unit scale, 2^-500, 1e150 and 1e-150.

use geocert::io::{read_cases, solve_case};
use geocert::num::rng::Rng;
use rug::float::Constant;
use rug::Float;
use serde_json::{json, Value};

const PREC: u32 = 256;

fn f(x: f64) -> Float {
    Float::with_val(PREC, x)
}

fn solve(case: &Value) -> Value {
    let read = read_cases(&case.to_string()).into_iter().next().unwrap();
    serde_json::from_str(&solve_case(read).to_json_line()).unwrap()
}

type V = [Float; 3];

fn dot(a: &V, b: &V) -> Float {
    a[0].clone() * &b[0] + a[1].clone() * &b[1] + a[2].clone() * &b[2]
}

fn unit(a: &V) -> V {
    let n = dot(a, a).sqrt();
    a.clone().map(|x| x / &n)
}

/// The frame `X, Y` of docs/FORMAT.md for `axis` and `ref` (or the coordinate vector
/// least aligned with the axis, first on ties), in MPFR.
fn frame(axis: [f64; 3], reference: Option<[f64; 3]>) -> (V, V) {
    let z = unit(&axis.map(f));
    let e = reference.unwrap_or_else(|| {
        let mut k = 0;
        for i in 1..3 {
            if axis[i].abs() < axis[k].abs() {
                k = i;
            }
        }
        std::array::from_fn(|i| if i == k { 1.0 } else { 0.0 })
    });
    let e = e.map(f);
    let along = dot(&e, &z);
    let x = unit(&std::array::from_fn(|i| {
        e[i].clone() - along.clone() * &z[i]
    }));
    let y = [
        z[1].clone() * &x[2] - z[2].clone() * &x[1],
        z[2].clone() * &x[0] - z[0].clone() * &x[2],
        z[0].clone() * &x[1] - z[1].clone() * &x[0],
    ];
    (x, y)
}

/// A whole circle or ellipse of space and the query point, in MPFR.
struct Conic {
    c: V,
    x: V,
    y: V,
    a: Float,
    b: Float,
}

impl Conic {
    fn at(&self, t: &Float) -> V {
        let (ct, st) = cos_sin(t);
        std::array::from_fn(|i| {
            self.c[i].clone()
                + self.a.clone() * &ct * &self.x[i]
                + self.b.clone() * &st * &self.y[i]
        })
    }

    /// `f(t) = (q(t) − p)·q′(t)`.
    fn g(&self, p: &V, t: &Float) -> Float {
        let q = self.at(t);
        let (ct, st) = cos_sin(t);
        let d: V = std::array::from_fn(|i| {
            -(self.a.clone() * &st * &self.x[i]) + self.b.clone() * &ct * &self.y[i]
        });
        let w: V = std::array::from_fn(|i| q[i].clone() - &p[i]);
        dot(&w, &d)
    }

    /// The roots of `f` on `[0, 2π)` by sign changes over `n` samples (simple roots
    /// only: two roots closer than the sample step would be missed, so a count that
    /// differs from the answer's is checked again with more samples).
    fn feet(&self, p: &V, n: u32) -> Vec<Float> {
        let two_pi = Float::with_val(PREC, Constant::Pi) * 2u32;
        let at = |k: u32| two_pi.clone() * k / n;
        let mut roots = Vec::new();
        let mut prev = self.g(p, &at(0));
        if prev.is_zero() {
            roots.push(f(0.0));
        }
        for k in 1..=n {
            let t = at(k);
            let v = self.g(p, &t);
            if !prev.is_zero() && !v.is_zero() && prev.is_sign_negative() != v.is_sign_negative() {
                let (mut lo, mut hi) = (at(k - 1), t.clone());
                let neg = prev.is_sign_negative();
                for _ in 0..240 {
                    let m = (lo.clone() + &hi) / 2u32;
                    if self.g(p, &m).is_sign_negative() == neg {
                        lo = m;
                    } else {
                        hi = m;
                    }
                }
                roots.push(lo);
            } else if v.is_zero() && k < n {
                roots.push(t.clone());
            }
            prev = v;
        }
        roots
    }

    fn distance(&self, p: &V, t: &Float) -> Float {
        let q = self.at(t);
        let w: V = std::array::from_fn(|i| q[i].clone() - &p[i]);
        dot(&w, &w).sqrt()
    }
}

/// `(cos t, sin t)`, exact at `t = 0` and at the 256-bit π (which stands for π).
fn cos_sin(t: &Float) -> (Float, Float) {
    if *t == Float::with_val(PREC, Constant::Pi) {
        return (f(-1.0), f(0.0));
    }
    (t.clone().cos(), t.clone().sin())
}

/// Checks each point of `answer` against the truth parameters `ts` one to one (sorted
/// both ways): the parameter, coordinates and distance are the truth correctly rounded.
fn check_points(case: &str, answer: &Value, conic: &Conic, p: &V, ts: &[Float], mult: &[u64]) {
    let pts = answer["points"].as_array().unwrap();
    assert_eq!(pts.len(), ts.len(), "{case}: {answer}");
    for (k, (pt, t)) in pts.iter().zip(ts).enumerate() {
        let got = pt["params"][0][0].as_f64().unwrap();
        let b = &pt["param_box"][0][0];
        assert_eq!(got, t.to_f64(), "{case}: parameter {k}: {answer}");
        assert!(
            *t >= b[0].as_f64().unwrap() && *t <= b[1].as_f64().unwrap(),
            "{case}: parameter {k} not in its box: {answer}"
        );
        let q = conic.at(t);
        for i in 0..3 {
            assert_eq!(
                pt["xyz"][i].as_f64().unwrap(),
                q[i].to_f64(),
                "{case}: xyz {k}.{i}: {answer}"
            );
            let bb = &pt["box"][i];
            assert!(
                q[i] >= bb[0].as_f64().unwrap() && q[i] <= bb[1].as_f64().unwrap(),
                "{case}: xyz {k}.{i} not in its box: {answer}"
            );
        }
        let d = conic.distance(p, t).to_f64();
        assert_eq!(
            pt["distance"].as_f64().unwrap(),
            d,
            "{case}: distance {k}: {answer}"
        );
        assert_eq!(
            pt["multiplicity"].as_u64().unwrap(),
            mult[k],
            "{case}: multiplicity {k}: {answer}"
        );
    }
}

const SCALES: [f64; 4] = [1.0, 1.0, 1e150, 1e-150];

fn axis_of(rng: &mut Rng) -> [f64; 3] {
    loop {
        let a = [0; 3].map(|_| rng.int(-3, 3) as f64);
        if a.iter().any(|&x| x != 0.0) {
            return a;
        }
    }
}

#[test]
fn feet_on_space_circles_and_ellipses_are_correctly_rounded() {
    let mut rng = Rng::new(0xf0073);
    let (mut exact, mut feet_seen, mut four) = (0, 0, 0);
    let n = 160;
    for case in 0..n {
        let m = SCALES[case % 4] * if case % 8 == 5 { 2f64.powi(-500) } else { 1.0 };
        let axis = axis_of(&mut rng);
        let reference = (case % 3 == 0).then(|| loop {
            let r = axis_of(&mut rng);
            let cross = [
                axis[1] * r[2] - axis[2] * r[1],
                axis[2] * r[0] - axis[0] * r[2],
                axis[0] * r[1] - axis[1] * r[0],
            ];
            if cross.iter().any(|&x| x != 0.0) {
                break r;
            }
        });
        let circle = case % 2 == 0;
        let a = (1.0 + 2.0 * rng.unit().abs()) * m;
        let b = if circle {
            a
        } else {
            (0.3 + 0.6 * rng.unit().abs()) * a
        };
        let c = [0; 3].map(|_| rng.generic() * m);
        let p: [f64; 3] = std::array::from_fn(|i| c[i] + rng.generic() * m * 0.15);
        let mut curve = if circle {
            json!({"type": "circle", "center": c, "radius": a, "axis": axis})
        } else {
            json!({"type": "ellipse", "center": c, "a": a, "b": b, "axis": axis})
        };
        if let Some(r) = reference {
            curve["ref"] = json!(r);
        }
        let (x, y) = frame(axis, reference);
        let conic = Conic {
            c: c.map(f),
            x,
            y,
            a: f(a),
            b: f(b),
        };
        let pm = p.map(f);
        let mut ts = conic.feet(&pm, 2000);
        let first = solve(&json!({"id": case, "op": "project", "point": p, "onto": curve}));
        if first["points"].as_array().map(Vec::len) != Some(ts.len()) {
            ts = conic.feet(&pm, 200_000);
        }
        four += usize::from(ts.len() == 4);
        for nearest in [false, true] {
            let answer = solve(&json!({"id": case, "op": "project", "point": p,
                "nearest": nearest, "onto": curve}));
            let tag = format!("case {case} nearest {nearest}");
            assert!(answer["complete"] == json!(true), "{tag}: {answer}");
            match answer["status"].as_str().unwrap() {
                "exact" => exact += 1,
                "verified" => continue,
                _ => panic!("{tag}: {answer}"),
            }
            let want: Vec<Float> = if nearest {
                let d: Vec<Float> = ts.iter().map(|t| conic.distance(&pm, t)).collect();
                let best = (0..ts.len()).min_by(|&i, &j| d[i].partial_cmp(&d[j]).unwrap());
                best.map(|i| vec![ts[i].clone()]).unwrap_or_default()
            } else {
                ts.clone()
            };
            check_points(&tag, &answer, &conic, &pm, &want, &vec![1; want.len()]);
            feet_seen += want.len();
        }
    }
    assert!(exact * 10 >= 2 * n * 9, "only {exact} exact answers");
    assert!(
        feet_seen >= 3 * n && four >= 20,
        "{feet_seen} feet, {four} with four"
    );
}

/// On an ellipse's major axis at `s` from the centre: the cusp of the evolute
/// `s = (a² − b²)/a` is a triple foot (and the far vertex a simple one); one ulp inside,
/// four simple feet (`cos t = s·a/(a² − b²)` close to the vertex); one ulp outside, two.
#[test]
fn the_evolute_cusp_of_a_space_ellipse_and_one_ulp_either_side() {
    let mut rng = Rng::new(0xc05b);
    let mut seen = [0; 3];
    for case in 0..60 {
        let (a, b) = [(2.0, 1.0), (2.0, 0.5), (2.0, 1.5), (4.0, 2.0)][case % 4];
        let s0: f64 = (a * a - b * b) / a;
        let side = case / 4 % 3;
        let s = [s0, s0.next_up(), s0.next_down()][side];
        // Axis in the xy plane, ref = z: X = (0, 0, 1) exactly.
        let axis = loop {
            let v = [rng.int(-3, 3) as f64, rng.int(-3, 3) as f64, 0.0];
            if v != [0.0; 3] {
                break v;
            }
        };
        let c = [rng.small_int(), rng.small_int(), 0.0];
        let lambda = rng.dyadic();
        let p = [c[0] + lambda * axis[0], c[1] + lambda * axis[1], s];
        let curve = json!({"type": "ellipse", "center": c, "a": a, "b": b, "axis": axis,
            "ref": [0, 0, 1]});
        let answer = solve(&json!({"id": case, "op": "project", "point": p, "onto": curve}));
        let tag = format!("case {case} side {side}");
        assert_eq!(answer["status"], json!("exact"), "{tag}: {answer}");
        assert_eq!(answer["complete"], json!(true), "{tag}: {answer}");
        let (x, y) = frame(axis, Some([0.0, 0.0, 1.0]));
        let conic = Conic {
            c: c.map(f),
            x,
            y,
            a: f(a),
            b: f(b),
        };
        let pi = Float::with_val(PREC, Constant::Pi);
        let cos = f(s) * a / (a * a - b * b);
        let (ts, mult): (Vec<Float>, Vec<u64>) = match side {
            0 => (vec![f(0.0), pi], vec![3, 1]),
            1 => (vec![f(0.0), pi], vec![1, 1]),
            _ => {
                let t = cos.acos();
                let two_pi = pi.clone() * 2u32;
                (vec![f(0.0), t.clone(), pi, two_pi - t], vec![1; 4])
            }
        };
        seen[side] += 1;
        check_points(&tag, &answer, &conic, &p.map(f), &ts, &mult);
    }
    assert!(seen.iter().all(|&k| k >= 15), "{seen:?}");
}

/// A point on a circle's axis (and a plane circle's centre): every point is a foot, at
/// the distance `√(r² + h²)` — `coincident` at once, the distance correctly rounded.
#[test]
fn a_point_on_a_circles_axis_has_every_point_as_a_foot() {
    let mut rng = Rng::new(0xa715);
    for case in 0..80 {
        let axis = axis_of(&mut rng);
        let c = [0; 3].map(|_| rng.small_int());
        let r = rng.dyadic().abs() + 0.125;
        let lambda = if case % 4 == 0 { 0.0 } else { rng.dyadic() };
        let p: [f64; 3] = std::array::from_fn(|i| c[i] + lambda * axis[i]);
        let want = (f(r) * r + f(lambda) * lambda * dot(&axis.map(f), &axis.map(f))).sqrt();
        let curve = json!({"type": "circle", "center": c, "radius": r, "axis": axis});
        let plane = json!({"type": "circle2", "center": [c[0], c[1]], "radius": r});
        for (nearest, onto, q, d) in [
            (false, &curve, json!(p), want.clone()),
            (true, &curve, json!(p), want.clone()),
            (false, &plane, json!([c[0], c[1]]), f(r)),
        ] {
            let answer = solve(
                &json!({"id": case, "op": "project", "point": q, "nearest": nearest, "onto": onto}),
            );
            assert_eq!(answer["status"], json!("exact"), "case {case}: {answer}");
            assert_eq!(answer["kind"], json!("coincident"), "case {case}: {answer}");
            let reason = answer["reason"].as_str().unwrap();
            let shown: f64 = reason
                .split("distance ")
                .nth(1)
                .and_then(|s| s.split_whitespace().next())
                .and_then(|s| s.parse().ok())
                .unwrap_or_else(|| panic!("case {case}: {reason}"));
            assert_eq!(shown, d.to_f64(), "case {case}: {answer}");
        }
    }
}

/// Projection along a direction onto a curve is the ray `p + t·d`, `t ≥ 0`, against the
/// curve (the direction was once ignored and the feet reported instead). Plane circles
/// against random rays (truth: the quadratic `|p + t d − c|² = r²` in MPFR), and space
/// circles against rays through one of their rational points, parallel to the axis
/// (one hit) or pointing away (none).
#[test]
fn projection_along_a_direction_onto_curves_follows_the_ray() {
    let mut rng = Rng::new(0xd1ec7);
    let (mut hits, mut empty) = (0, 0);
    for case in 0..120 {
        let c = [rng.small_int(), rng.small_int()];
        let r = rng.dyadic().abs() + 0.5;
        let p = [c[0] + rng.generic() * 0.5, c[1] + rng.generic() * 0.5];
        let d = loop {
            let d = [rng.small_int(), rng.small_int()];
            if d != [0.0, 0.0] {
                break d;
            }
        };
        let w = [f(p[0]) - c[0], f(p[1]) - c[1]];
        let (a, b) = (
            f(d[0] * d[0] + d[1] * d[1]),
            w[0].clone() * d[0] + w[1].clone() * d[1],
        );
        let cc = w[0].clone().square() + w[1].clone().square() - f(r) * r;
        let disc = b.clone().square() - a.clone() * &cc;
        let mut ts: Vec<Float> = Vec::new();
        if disc > 0 {
            for s in [-1, 1] {
                let t = (-b.clone() + disc.clone().sqrt() * s) / &a;
                if t >= 0 {
                    ts.push(t);
                }
            }
        }
        for nearest in [false, true] {
            let answer = solve(
                &json!({"id": case, "op": "project", "point": p, "direction": d,
                "nearest": nearest, "onto": {"type": "circle2", "center": c, "radius": r}}),
            );
            assert_eq!(answer["complete"], json!(true), "case {case}: {answer}");
            let want = if nearest { ts.len().min(1) } else { ts.len() };
            let pts = answer["points"].as_array().unwrap();
            assert_eq!(pts.len(), want, "case {case} nearest {nearest}: {answer}");
            for (pt, t) in pts.iter().zip(&ts) {
                let b = &pt["param_box"][1][0];
                assert!(
                    *t >= b[0].as_f64().unwrap() && *t <= b[1].as_f64().unwrap(),
                    "case {case}: ray parameter {} not in its box: {answer}",
                    t.to_f64()
                );
                for i in 0..2 {
                    let x = t.clone() * d[i] + p[i];
                    let bb = &pt["box"][i];
                    assert!(
                        x >= bb[0].as_f64().unwrap() && x <= bb[1].as_f64().unwrap(),
                        "case {case}: coordinate {i} not in its box: {answer}"
                    );
                }
                let dist = (t.clone() * a.clone().sqrt()).to_f64();
                let got = pt["distance"].as_f64().unwrap();
                // An estimate from the rounded point: cancellation error of its coordinates.
                let scale = dist + p[0].abs().max(p[1].abs()) + 2.0 * r;
                assert!(
                    (got - dist).abs() <= 8.0 * f64::EPSILON * scale,
                    "case {case}: distance {dist}: {answer}"
                );
            }
            if want == 0 {
                empty += 1;
            } else {
                hits += 1;
            }
        }
        // The same circle as a `conic2` (met by the whole line, hits behind dropped).
        let coeffs = [
            1.0,
            0.0,
            1.0,
            -2.0 * c[0],
            -2.0 * c[1],
            c[0] * c[0] + c[1] * c[1] - r * r,
        ];
        let answer = solve(
            &json!({"id": case, "op": "project", "point": p, "direction": d,
            "onto": {"type": "conic2", "coeffs": coeffs}}),
        );
        assert_eq!(answer["status"], json!("exact"), "case {case}: {answer}");
        let pts = answer["points"].as_array().unwrap();
        assert_eq!(pts.len(), ts.len(), "case {case}: conic2: {answer}");
        for (pt, t) in pts.iter().zip(&ts) {
            let b = &pt["param_box"][1][0];
            assert!(
                *t >= b[0].as_f64().unwrap() && *t <= b[1].as_f64().unwrap(),
                "case {case}: {answer}"
            );
        }
        // Space: a circle of radius 5 about the axis z through its point (3, 4)·s.
        let s = [1.0, -1.0][case % 2];
        let h = rng.dyadic().abs() + 0.125;
        let cz = [rng.small_int(), rng.small_int(), rng.small_int()];
        let q = [cz[0] + 3.0 * s, cz[1] + 4.0 * s, cz[2] + h];
        let circle = json!({"type": "circle", "center": cz, "radius": 5, "axis": [0, 0, 1]});
        for (dz, n) in [(-1.0, 1), (1.0, 0)] {
            let answer = solve(&json!({"id": case, "op": "project", "point": q,
                "direction": [0, 0, dz], "onto": circle}));
            assert_eq!(answer["status"], json!("exact"), "case {case}: {answer}");
            let pts = answer["points"].as_array().unwrap();
            assert_eq!(pts.len(), n, "case {case}: {answer}");
            if n == 1 {
                assert_eq!(
                    pts[0]["xyz"],
                    json!([q[0], q[1], cz[2]]),
                    "case {case}: {answer}"
                );
                assert_eq!(pts[0]["distance"], json!(h), "case {case}: {answer}");
            }
        }
    }
    assert!(hits >= 60 && empty >= 20, "{hits} hits, {empty} empty");
}
