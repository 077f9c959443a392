//! Curves lying on surfaces and three spheres, answered exactly (issue 14 items 8–9).
//! Families of dyadic data built to lie exactly on the surface through Pythagorean
//! triples and quadruples (so every number is a double and the truth is a rational
//! identity): circles on spheres, meridian, parallel and Villarceau circles on tori,
//! parallel circles of cylinders inside and outside their height, rulings of
//! cylinders (rational and irrational `|axis|`) and of hyperboloids of one sheet; and
//! three spheres with random centres, tangent triples and one-ulp perturbations of
//! them. Truths are computed here independently: exact rationals, and 300-bit MPFR
//! for irrational ends (`t = (ζ|Z̃| − (o − o_s)·Z̃)/(d·Z̃)`) and for three spheres by
//! the Gram system of `u = c₂ − c₁`, `v = c₃ − c₁` (not the radical-plane cross
//! products the solver uses). The one-ulp perturbations that must not lie on the
//! surface are in the unit tests of `ops::algebraic::on_surface_tests` (here they
//! would be left to the numeric certifier).

mod cli_support;

use cli_support::{json_lines, run};
use geocert::num::rng::Rng;
use rug::{Float, Rational};
use serde_json::{json, Value};

const BITS: u32 = 300;

fn q(x: f64) -> Rational {
    Rational::from_f64(x).unwrap()
}

fn solve_all(cases: &[Value]) -> Vec<Value> {
    let input: Vec<String> = cases.iter().map(|c| c.to_string()).collect();
    let out = json_lines(&run("solve", &[], input.join("\n").as_bytes()));
    assert_eq!(out.len(), cases.len());
    out
}

/// Pythagorean quadruples `(a, b, c; |v|)`: rational unit directions.
const QUADS: [([i64; 3], i64); 6] = [
    ([0, 0, 1], 1),
    ([1, 2, 2], 3),
    ([2, 3, 6], 7),
    ([1, 4, 8], 9),
    ([4, 4, 7], 9),
    ([2, 6, 9], 11),
];
/// Pythagorean triples `(x, y; z)`.
const TRIPLES: [(i64, i64, i64); 5] = [
    (3, 4, 5),
    (5, 12, 13),
    (8, 15, 17),
    (7, 24, 25),
    (20, 21, 29),
];

/// A random signed permutation of a quadruple: `(v, |v|)`.
fn direction(rng: &mut Rng) -> ([f64; 3], f64) {
    let (v, n) = QUADS[rng.below(QUADS.len())];
    let p = rng.below(6);
    let perm = [
        [0, 1, 2],
        [0, 2, 1],
        [1, 0, 2],
        [1, 2, 0],
        [2, 0, 1],
        [2, 1, 0],
    ][p];
    let d = std::array::from_fn(|i| {
        let s = if rng.coin() { -1.0 } else { 1.0 };
        s * v[perm[i]] as f64
    });
    (d, n as f64)
}

fn scale(rng: &mut Rng) -> f64 {
    (2.0f64).powi(rng.int(-6, 6) as i32)
}

fn centre(rng: &mut Rng) -> [f64; 3] {
    std::array::from_fn(|_| rng.int(-64, 64) as f64 / 8.0)
}

fn reference(rng: &mut Rng) -> Value {
    if rng.coin() {
        Value::Null
    } else {
        json!([rng.int(-5, 5), rng.int(-5, 5), rng.int(1, 5)])
    }
}

/// `v` with `ref: r` unless `r` is null or parallel to `v`'s axis.
fn with_ref(mut v: Value, r: Value) -> Value {
    let a = &v["axis"];
    let parallel = !r.is_null() && {
        let (a, r): (Vec<f64>, Vec<f64>) = (0..3)
            .map(|i| (a[i].as_f64().unwrap_or(0.0), r[i].as_f64().unwrap()))
            .unzip();
        (0..3).all(|i| a[(i + 1) % 3] * r[(i + 2) % 3] == a[(i + 2) % 3] * r[(i + 1) % 3])
    };
    if !r.is_null() && !parallel {
        v["ref"] = r;
    }
    v
}

fn assert_coincident(r: &Value) {
    assert_eq!(r["status"], "exact", "{r}");
    assert_eq!(r["kind"], "coincident", "{r}");
    assert_eq!(r["complete"], true, "{r}");
}

#[test]
fn circles_on_spheres_are_coincident() {
    let mut rng = Rng::new(1401);
    let mut cases = vec![];
    for id in 0..300 {
        // |a| k·(x, y, z): distance k|a|x·s, radius k|a|y·s, sphere k|a|z·s.
        let (a, n) = direction(&mut rng);
        let (x, y, z) = TRIPLES[rng.below(TRIPLES.len())];
        let (x, y) = if rng.coin() { (x, y) } else { (y, x) };
        let s = scale(&mut rng) * if rng.coin() { 1.0 } else { -1.0 };
        let c = centre(&mut rng);
        let pc: Vec<f64> = (0..3).map(|i| c[i] + a[i] * x as f64 * s).collect();
        let circle = with_ref(
            json!({"type": "circle", "center": pc, "radius": n * y as f64 * s.abs(), "axis": a}),
            reference(&mut rng),
        );
        let sphere = with_ref(
            json!({"type": "sphere", "center": c, "radius": n * z as f64 * s.abs(),
                   "axis": direction(&mut rng).0}),
            reference(&mut rng),
        );
        let objects = if rng.coin() {
            json!([circle, sphere])
        } else {
            json!([sphere, circle])
        };
        cases.push(json!({"id": id, "op": "intersect", "objects": objects}));
    }
    for r in solve_all(&cases) {
        assert_coincident(&r);
    }
}

/// Meridians, parallels and Villarceau circles of tori `R = 13s`, `r = 5s` (so
/// `√(R² − r²) = 12s`) about a coordinate axis, centred anywhere.
#[test]
fn circles_on_tori_are_coincident() {
    let mut rng = Rng::new(1402);
    let mut cases = vec![];
    for id in 0..300 {
        let s = scale(&mut rng);
        let (big, small) = (13.0 * s, 5.0 * s);
        let c = centre(&mut rng);
        let k = rng.below(3);
        let e = |i: usize| -> [f64; 3] { std::array::from_fn(|j| f64::from(u8::from(j == i))) };
        let (z, x, y) = (e(k), e((k + 1) % 3), e((k + 2) % 3));
        let at = |v: [[f64; 3]; 3], w: [f64; 3]| -> Vec<f64> {
            (0..3)
                .map(|i| c[i] + w[0] * v[0][i] + w[1] * v[1][i] + w[2] * v[2][i])
                .collect()
        };
        let circle = match rng.below(3) {
            // Meridian through the X axis direction: centre c + R·X, axis Y.
            0 => json!({"type": "circle", "center": at([x, y, z], [big, 0.0, 0.0]),
                        "radius": small, "axis": y}),
            // Parallel at height r·sin θ, (cos θ, sin θ) = (3/5, 4/5) or (−4/5, 3/5): radius R + r cos θ.
            1 => {
                // r·(cos θ, sin θ) = s·(3, 4) or s·(−4, 3).
                let (rc, rs) = if rng.coin() {
                    (3.0 * s, 4.0 * s)
                } else {
                    (-4.0 * s, 3.0 * s)
                };
                let sign = if rng.coin() { 1.0 } else { -1.0 };
                json!({"type": "circle", "center": at([x, y, z], [0.0, 0.0, sign * rs]),
                       "radius": big + rc, "axis": z})
            }
            // Villarceau: centre ±r·Y, radius R, plane normal (∓r, 0, √(R² − r²)).
            _ => {
                let sy = if rng.coin() { 1.0 } else { -1.0 };
                let sx = if rng.coin() { 1.0 } else { -1.0 };
                let normal: Vec<f64> = (0..3).map(|i| sx * -5.0 * x[i] + 12.0 * z[i]).collect();
                json!({"type": "circle", "center": at([x, y, z], [0.0, sy * small, 0.0]),
                       "radius": big, "axis": normal})
            }
        };
        let circle = with_ref(circle, reference(&mut rng));
        let torus = json!({"type": "torus", "center": c, "major": big, "minor": small, "axis": z});
        cases.push(json!({"id": id, "op": "intersect", "objects": [circle, torus]}));
    }
    for r in solve_all(&cases) {
        assert_coincident(&r);
    }
}

/// Parallel circles of a cylinder about a rational-length axis: coincident inside the
/// height (ends included), an exact empty outside.
#[test]
fn parallel_circles_of_cylinders_inside_and_outside_the_height() {
    let mut rng = Rng::new(1403);
    let mut cases = vec![];
    let mut inside = vec![];
    for id in 0..300 {
        let (a, n) = direction(&mut rng);
        let s = scale(&mut rng);
        let o = centre(&mut rng);
        let radius = rng.int(1, 40) as f64 * s;
        // Heights multiples of |a|/8, so the centre o + ζ·a/|a| is exact; the ends too.
        let h = [n * rng.int(-8, 0) as f64, n * rng.int(1, 8) as f64];
        let zeta = match rng.below(4) {
            0 => h[0],
            1 => h[1],
            _ => n * rng.int(-80, 80) as f64 / 8.0,
        };
        inside.push(h[0] <= zeta && zeta <= h[1]);
        let pc: Vec<f64> = (0..3).map(|i| o[i] + zeta / n * a[i]).collect();
        let k = rng.int(1, 4) as f64;
        let axis: Vec<f64> = a.iter().map(|v| v * k).collect();
        cases.push(json!({"id": id, "op": "intersect", "objects": [
            {"type": "circle", "center": pc, "radius": radius, "axis": axis},
            {"type": "cylinder", "origin": o, "radius": radius, "axis": a, "height": h}]}));
    }
    for ((r, inside), c) in solve_all(&cases).iter().zip(inside).zip(&cases) {
        assert_eq!(r["status"], "exact", "{c} {r}");
        let kind = if inside { "coincident" } else { "empty" };
        assert_eq!(r["kind"], kind, "{c} {r}");
    }
}

/// The exact segment end `t` and point `o + t·d`, checked against a 300-bit truth:
/// the reported doubles are the truth correctly rounded and the boxes hold it.
fn check_end(p: &Value, t: &Float, o: &[f64; 3], d: &[f64; 3]) {
    let tr = p["params"][0][0].as_f64().unwrap();
    assert_eq!(tr, t.to_f64(), "t {p}");
    let b = &p["param_box"][0][0];
    assert!(
        b[0].as_f64().unwrap() <= *t && *t <= b[1].as_f64().unwrap(),
        "{p}"
    );
    for i in 0..3 {
        let x = Float::with_val(BITS, t * d[i]) + o[i];
        assert_eq!(p["xyz"][i].as_f64().unwrap(), x.to_f64(), "x[{i}] {p}");
        let b = &p["box"][i];
        assert!(
            b[0].as_f64().unwrap() <= x && x <= b[1].as_f64().unwrap(),
            "{p}"
        );
    }
}

/// `t` of the height `ζ` on `o + t·d`: `(ζ|a| − (o − o_s)·a)/(d·a)`.
fn t_at(zeta: &Float, a: &[f64; 3], o: &[f64; 3], os: &[f64; 3], d: &[f64; 3]) -> Float {
    let aa: f64 = a.iter().map(|x| x * x).sum();
    let n0: Rational = (0..3).map(|i| (q(o[i]) - q(os[i])) * q(a[i])).sum();
    let n1: Rational = (0..3).map(|i| q(d[i]) * q(a[i])).sum();
    let len = Float::with_val(BITS, aa).sqrt();
    (Float::with_val(BITS, zeta * &len) - n0) / n1
}

/// Rulings of cylinders (axes of rational and irrational length) and of hyperboloids of
/// one sheet: the covered segment with correctly rounded ends.
#[test]
fn rulings_are_segments_with_correctly_rounded_ends() {
    let mut rng = Rng::new(1404);
    let mut cases = vec![];
    let mut setups = vec![];
    for id in 0..300 {
        let os = centre(&mut rng);
        let s = scale(&mut rng);
        let hyperboloid = rng.coin();
        // Axis a, and a unit-free radial w ⟂ a with |w| = 1 exactly.
        let (a, w) = match rng.below(3) {
            0 => ([0.0, 0.0, 1.0], [1.0, 0.0, 0.0]),
            1 => ([1.0, 1.0, 0.0], [0.0, 0.0, 1.0]),
            _ => ([0.0, 3.0, 4.0], [-1.0, 0.0, 0.0]),
        };
        let radius = rng.int(1, 20) as f64 * s;
        let o: [f64; 3] = std::array::from_fn(|i| os[i] + radius * w[i]);
        let v = [-(rng.int(0, 16) as f64) / 8.0, rng.int(1, 16) as f64 / 8.0];
        let k = rng.int(1, 3) as f64;
        let (surface, d) = if hyperboloid {
            // a = b = c = radius; through o along (a × w)/|a| ± a/|a|: exact when |a| ∈ ℚ,
            // so keep the rational axes here.
            let (a, w) = ([0.0, 0.0, 1.0], [1.0, 0.0, 0.0]);
            let o: [f64; 3] = std::array::from_fn(|i| os[i] + radius * w[i]);
            let sign = if rng.coin() { 1.0 } else { -1.0 };
            let d = [0.0, k, sign * k];
            setups.push((o, d, os, a, Some(radius), v));
            (
                json!({"type": "hyperboloid1", "center": os, "a": radius, "b": radius,
                    "c": radius, "axis": a, "range": v}),
                d,
            )
        } else {
            let k = k * if rng.coin() { 1.0 } else { -1.0 };
            let d: [f64; 3] = std::array::from_fn(|i| a[i] * k);
            let h = [v[0] * 4.0, v[1] * 4.0];
            setups.push((o, d, os, a, None, h));
            (
                json!({"type": "cylinder", "origin": os, "radius": radius, "axis": a, "height": h}),
                d,
            )
        };
        let o = setups.last().unwrap().0;
        let range = [rng.int(-40, 0) as f64 / 4.0, rng.int(0, 40) as f64 / 4.0];
        let line = if rng.coin() {
            json!({"type": "line", "origin": o, "dir": d})
        } else {
            json!({"type": "line", "origin": o, "dir": d, "range": range})
        };
        cases.push(json!({"id": id, "op": "intersect", "objects": [line, surface]}));
    }
    for ((r, (o, d, os, a, c, v)), case) in solve_all(&cases).iter().zip(&setups).zip(&cases) {
        assert_eq!(r["status"], "exact", "{case} {r}");
        let zeta = |x: f64| match c {
            Some(c) => Float::with_val(BITS, x).sinh() * *c,
            None => Float::with_val(BITS, x),
        };
        let mut lo = t_at(&zeta(v[0]), a, o, os, d);
        let mut hi = t_at(&zeta(v[1]), a, o, os, d);
        if lo > hi {
            std::mem::swap(&mut lo, &mut hi);
        }
        if let Some(range) = case["objects"][0]["range"].as_array() {
            let (r0, r1) = (range[0].as_f64().unwrap(), range[1].as_f64().unwrap());
            if lo < r0 {
                lo = Float::with_val(BITS, r0);
            }
            if hi > r1 {
                hi = Float::with_val(BITS, r1);
            }
        }
        match lo.partial_cmp(&hi).unwrap() {
            std::cmp::Ordering::Greater => assert_eq!(r["kind"], "empty", "{case} {r}"),
            std::cmp::Ordering::Equal => {
                assert_eq!(r["kind"], "points", "{case} {r}");
                check_end(&r["points"][0], &lo, o, d);
            }
            std::cmp::Ordering::Less => {
                assert_eq!(r["kind"], "segment", "{case} {r}");
                check_end(&r["segment"]["a"], &lo, o, d);
                check_end(&r["segment"]["b"], &hi, o, d);
            }
        }
    }
}

/// The truth of three spheres by the Gram system (module doc): `x = c₁ + λu + μv + νw`,
/// `w = u × v`; `None` when the centres are collinear.
fn three_truth(c: &[[f64; 3]; 3], r: &[f64; 3]) -> Option<Vec<Vec<Float>>> {
    let cq: Vec<Vec<Rational>> = c
        .iter()
        .map(|p| p.iter().map(|&x| q(x)).collect())
        .collect();
    let sub = |a: &Vec<Rational>, b: &Vec<Rational>| -> Vec<Rational> {
        (0..3).map(|i| Rational::from(&a[i] - &b[i])).collect()
    };
    let dot = |a: &Vec<Rational>, b: &Vec<Rational>| -> Rational {
        (0..3).map(|i| Rational::from(&a[i] * &b[i])).sum()
    };
    let (u, v) = (sub(&cq[1], &cq[0]), sub(&cq[2], &cq[0]));
    let w: Vec<Rational> = (0..3)
        .map(|i| {
            let (j, k) = ((i + 1) % 3, (i + 2) % 3);
            Rational::from(&u[j] * &v[k]) - Rational::from(&u[k] * &v[j])
        })
        .collect();
    let ww = dot(&w, &w);
    if ww == 0 {
        return None;
    }
    let r2: Vec<Rational> = r.iter().map(|&x| q(x).square()).collect();
    // u·x' = (|u|² + r₁² − r₂²)/2 with x' = x − c₁, likewise v.
    let a = (dot(&u, &u) + &r2[0] - &r2[1]) / 2u32;
    let b = (dot(&v, &v) + &r2[0] - &r2[2]) / 2u32;
    let (uu, uv, vv) = (dot(&u, &u), dot(&u, &v), dot(&v, &v));
    let det = Rational::from(&uu * &vv) - Rational::from(&uv * &uv);
    let lambda = (Rational::from(&vv * &a) - Rational::from(&uv * &b)) / &det;
    let mu = (Rational::from(&uu * &b) - Rational::from(&uv * &a)) / &det;
    let base: Vec<Rational> = (0..3)
        .map(|i| Rational::from(&lambda * &u[i]) + Rational::from(&mu * &v[i]))
        .collect();
    let nu2 = (r2[0].clone() - dot(&base, &base)) / &ww;
    let at = |nu: &Float| -> Vec<Float> {
        (0..3)
            .map(|i| Float::with_val(BITS, &w[i]) * nu + &base[i] + &cq[0][i])
            .collect()
    };
    Some(match nu2.cmp0() {
        std::cmp::Ordering::Less => vec![],
        std::cmp::Ordering::Equal => vec![at(&Float::new(BITS))],
        std::cmp::Ordering::Greater => {
            let nu = Float::with_val(BITS, &nu2).sqrt();
            vec![at(&Float::with_val(BITS, -&nu)), at(&nu)]
        }
    })
}

fn spheres_case(id: usize, c: &[[f64; 3]; 3], r: &[f64; 3]) -> Value {
    let objects: Vec<Value> = (0..3)
        .map(|k| json!({"type": "sphere", "center": c[k], "radius": r[k]}))
        .collect();
    json!({"id": id, "op": "intersect", "objects": objects})
}

fn check_three(case: &Value, r: &Value, truth: &[Vec<Float>]) {
    assert_eq!(r["status"], "exact", "{case} {r}");
    assert_eq!(r["complete"], true, "{case} {r}");
    let pts = r["points"].as_array().cloned().unwrap_or_default();
    assert_eq!(pts.len(), truth.len(), "{case} {r}");
    for (p, t) in pts.iter().zip(truth) {
        assert_eq!(p["tangent"], truth.len() == 1, "{case} {r}");
        for i in 0..3 {
            assert_eq!(p["xyz"][i].as_f64().unwrap(), t[i].to_f64(), "{case} {r}");
            let b = &p["box"][i];
            assert!(b[0].as_f64().unwrap() <= t[i] && t[i] <= b[1].as_f64().unwrap());
        }
        assert_eq!(p["params"].as_array().unwrap().len(), 3, "{r}");
    }
}

/// Random dyadic triples (mostly 0 or 2 points), tangent triples (centres coplanar with
/// a common point, radii from Pythagorean vectors) and the tangent triples with one
/// radius one ulp up or down (0 or 2 points, never a tangency).
#[test]
fn three_spheres_exactly() {
    let mut rng = Rng::new(1405);
    let vecs2 = [
        (3, 4, 5),
        (-4, 3, 5),
        (5, -12, 13),
        (-12, -5, 13),
        (8, -6, 10),
        (0, 5, 5),
        (-7, 24, 25),
    ];
    let mut cases = vec![];
    let mut truths = vec![];
    for id in 0..400 {
        let (c, r) = if id % 2 == 0 {
            let c: [[f64; 3]; 3] = std::array::from_fn(|_| centre(&mut rng));
            let r: [f64; 3] = std::array::from_fn(|_| rng.int(4, 80) as f64 / 8.0);
            (c, r)
        } else {
            // Tangent: P, centres P + s·(x, y, 0) permuted, radius s·z.
            let p = centre(&mut rng);
            let s = scale(&mut rng);
            let k = rng.below(3);
            let mut picks = vec![];
            while picks.len() < 3 {
                let i = rng.below(vecs2.len());
                if !picks.contains(&i) {
                    picks.push(i);
                }
            }
            let mut c = [[0.0; 3]; 3];
            let mut r = [0.0; 3];
            for (j, &i) in picks.iter().enumerate() {
                let (x, y, z) = vecs2[i];
                let off = [x as f64 * s, y as f64 * s, 0.0];
                for (m, cm) in c[j].iter_mut().enumerate() {
                    *cm = p[m] + off[(m + 3 - k) % 3];
                }
                r[j] = z as f64 * s;
            }
            match id % 6 {
                3 => r[2] = geocert::num::round::next_up(r[2]),
                5 => r[2] = geocert::num::round::next_down(r[2]),
                _ => {}
            }
            (c, r)
        };
        let Some(t) = three_truth(&c, &r) else {
            continue;
        };
        if id % 6 == 1 {
            assert_eq!(t.len(), 1, "the tangent construction");
        }
        cases.push(spheres_case(id, &c, &r));
        truths.push(t);
    }
    let counts: Vec<usize> = truths.iter().map(Vec::len).collect();
    assert!(
        (0..3).all(|n| counts.contains(&n)),
        "every count appears: {counts:?}"
    );
    for ((r, t), c) in solve_all(&cases).iter().zip(&truths).zip(&cases) {
        check_three(c, r, t);
    }
}
