//! Sphere ∩ sphere is decided exactly through the radical plane (ops::section, issue
//! 16): disjoint and nested spheres are an exact `empty`, equal ones `coincident`, and
//! a circle comes with its exact centre and correctly rounded radius. Families of
//! dyadic spheres — random, exactly tangent (outside and inside) and one ulp either
//! side of tangency — against a truth computed here with exact rationals and 300-bit
//! MPFR, by the closed form `t = (d² + r₁² − r₂²)/(2d²)`, `ρ² = r₁² − t²d²`. A circle
//! is never `undecided` and every polyline vertex lies within its proven bound of the
//! true circle; a touching point is the exact point correctly rounded, a double contact,
//! with each sphere's parameters enclosed (at the poles too: the tangency axis is a
//! coordinate axis, the z axis one time in three).

mod cli_support;

use cli_support::{json_lines, run};
use geocert::num::rng::Rng;
use rug::{Float, Rational};
use serde_json::{json, Value};

struct Pair {
    c1: [f64; 3],
    r1: f64,
    c2: [f64; 3],
    r2: f64,
}

fn q(x: f64) -> Rational {
    Rational::from_f64(x).unwrap()
}

fn case(id: usize, p: &Pair) -> String {
    json!({"id": id, "op": "intersect", "objects": [
        {"type": "sphere", "center": p.c1, "radius": p.r1},
        {"type": "sphere", "center": p.c2, "radius": p.r2}]})
    .to_string()
}

/// The exact verdict, with the touching point or the circle's centre and `ρ²`.
enum Truth {
    Empty,
    Same,
    Tangent([Rational; 3]),
    Circle([Rational; 3], Rational),
}

fn truth(p: &Pair) -> Truth {
    let w: Vec<Rational> = (0..3).map(|i| q(p.c2[i]) - q(p.c1[i])).collect();
    let d2: Rational = w.iter().map(|x| Rational::from(x * x)).sum();
    let (r1, r2) = (q(p.r1), q(p.r2));
    if d2 == 0 {
        return if r1 == r2 { Truth::Same } else { Truth::Empty };
    }
    let sum2 = Rational::from(&r1 + &r2).square();
    let diff2 = Rational::from(&r1 - &r2).square();
    if d2 > sum2 || d2 < diff2 {
        return Truth::Empty;
    }
    let t = (d2.clone() + r1.clone().square() - r2.square()) / (Rational::from(2) * &d2);
    let centre: [Rational; 3] = std::array::from_fn(|i| q(p.c1[i]) + Rational::from(&t * &w[i]));
    if d2 == sum2 || d2 == diff2 {
        return Truth::Tangent(centre);
    }
    let rho2 = r1.square() - t.square() * d2;
    Truth::Circle(centre, rho2)
}

/// The double nearest `x` (ties to even; `Rational::to_f64` truncates).
fn nearest(x: &Rational) -> f64 {
    Float::with_val(53, x).to_f64()
}

fn exact_of(v: &Value) -> Rational {
    let s = v.as_str().expect("an exact string");
    s.parse::<Rational>().expect("a rational")
}

fn holds(b: &Value, x: &Rational) -> bool {
    q(b[0].as_f64().unwrap()) <= *x && *x <= q(b[1].as_f64().unwrap())
}

fn check(p: &Pair, r: &Value) {
    match truth(p) {
        Truth::Empty => {
            assert_eq!(r["status"], "exact", "{r}");
            assert_eq!(r["kind"], "empty", "{r}");
            assert_eq!(r["complete"], true);
        }
        Truth::Same => {
            assert_eq!(r["status"], "exact", "{r}");
            assert_eq!(r["kind"], "coincident", "{r}");
        }
        Truth::Tangent(point) => {
            // One touching point, exact: correctly rounded, a double contact, and each
            // sphere's (u, v) enclosed.
            assert_eq!(r["kind"], "points", "{r}");
            assert_eq!(r["complete"], true, "{r}");
            assert!(
                matches!(r["status"].as_str(), Some("exact" | "verified")),
                "{r}"
            );
            let pts = r["points"].as_array().expect("points");
            assert_eq!(pts.len(), 1, "{r}");
            for (i, x) in point.iter().enumerate() {
                assert!(holds(&pts[0]["box"][i], x), "{r}");
                assert_eq!(pts[0]["xyz"][i].as_f64().unwrap(), nearest(x), "{r}");
            }
            assert_eq!(pts[0]["multiplicity"], 2, "{r}");
            assert_eq!(pts[0]["tangent"], true, "{r}");
            check_sphere_params(&pts[0], &[(p.c1, p.r1), (p.c2, p.r2)], &point, r);
        }
        Truth::Circle(centre, rho2) => {
            assert_eq!(r["kind"], "curves", "{r}");
            // Never undecided: the exact conic is the whole intersection.
            assert_eq!(r["status"], "verified", "{r}");
            assert_eq!(r["complete"], true, "{r}");
            let axis: [Rational; 3] = std::array::from_fn(|i| q(p.c2[i]) - q(p.c1[i]));
            check_polylines(r, &centre, &rho2, &axis);
            let conic = &r["conic"];
            assert_eq!(conic["type"], "circle", "{r}");
            for (i, x) in centre.iter().enumerate() {
                assert_eq!(exact_of(&conic["center"]["exact"][i]), *x, "{r}");
            }
            let rho = Float::with_val(300, &rho2).sqrt();
            for axis in conic["axes"].as_array().unwrap() {
                let len = &axis["length"];
                assert_eq!(len["value"][0].as_f64().unwrap(), rho.to_f64(), "{r}");
                let b = &len["box"][0];
                assert!(
                    b[0].as_f64().unwrap() <= rho && rho <= b[1].as_f64().unwrap(),
                    "{r}"
                );
            }
        }
    }
}

/// The polyline vertices lie within their bounds of the true circle (centre `c`,
/// radius² `rho2`, in the plane through `c` normal to `normal`), checked at 300 bits.
fn check_polylines(r: &Value, c: &[Rational; 3], rho2: &Rational, normal: &[Rational; 3]) {
    let curves = r["curves"].as_array().expect("curves");
    assert_eq!(curves.len(), 1, "one circle: {r}");
    let k = &curves[0];
    assert_eq!(k["closed"], true, "{r}");
    let normal: Vec<Float> = normal.iter().map(|x| Float::with_val(300, x)).collect();
    let nn = normal
        .iter()
        .fold(Float::new(300), |a, x| a + Float::with_val(300, x * x));
    let nlen = nn.sqrt();
    let rho = Float::with_val(300, rho2).sqrt();
    let pts = k["points"].as_array().expect("points");
    assert!(pts.len() >= 17, "{r}");
    let bound = k["distance_bound"]
        .as_f64()
        .expect("a proven distance bound");
    for v in pts {
        let w: Vec<Float> = (0..3)
            .map(|i| {
                Float::with_val(300, v["xyz"][i].as_f64().unwrap()) - Float::with_val(300, &c[i])
            })
            .collect();
        let along = w
            .iter()
            .zip(&normal)
            .fold(Float::new(300), |a, (x, y)| a + Float::with_val(300, x * y))
            / &nlen;
        let ww = w
            .iter()
            .fold(Float::new(300), |a, x| a + Float::with_val(300, x * x));
        let radial = (ww - Float::with_val(300, &along * &along)).sqrt();
        let dist = (Float::with_val(300, &radial - &rho).square() + along.square()).sqrt();
        assert!(
            dist <= bound,
            "vertex {v} is {dist} from the circle, bound {bound}"
        );
    }
}

/// Each sphere's `(u, v)` box holds the true parameters of the exact point (default
/// frame: `u = atan2(y, x)` in `[0, 2π)`, `v = atan2(z, ρ)`; at a pole every `u`).
fn check_sphere_params(pt: &Value, spheres: &[([f64; 3], f64)], x: &[Rational; 3], r: &Value) {
    let boxes = pt["param_box"].as_array().expect("param_box");
    for (k, (c, _)) in spheres.iter().enumerate() {
        let w: Vec<Float> = (0..3).map(|i| Float::with_val(300, &x[i]) - c[i]).collect();
        let rho = Float::with_val(300, &w[0] * &w[0]) + Float::with_val(300, &w[1] * &w[1]);
        let rho = rho.sqrt();
        let v = Float::with_val(300, w[2].atan2_ref(&rho));
        let b = &boxes[k];
        let inside =
            |b: &Value, t: &Float| b[0].as_f64().unwrap() <= *t && *t <= b[1].as_f64().unwrap();
        assert!(
            inside(&b[1], &v),
            "sphere {k}: v = {v} not in {}: {r}",
            b[1]
        );
        if rho.is_zero() {
            continue; // a pole: every u
        }
        let mut u = Float::with_val(300, w[1].atan2_ref(&w[0]));
        if u < 0 {
            u += Float::with_val(300, rug::float::Constant::Pi) * 2u32;
        }
        assert!(
            inside(&b[0], &u),
            "sphere {k}: u = {u} not in {}: {r}",
            b[0]
        );
    }
}

fn solve_all(pairs: &[Pair]) {
    let input: Vec<String> = pairs.iter().enumerate().map(|(i, p)| case(i, p)).collect();
    let out = json_lines(&run("solve", &[], input.join("\n").as_bytes()));
    assert_eq!(out.len(), pairs.len());
    for (p, r) in pairs.iter().zip(&out) {
        check(p, r);
    }
}

fn dyadic_point(rng: &mut Rng) -> [f64; 3] {
    std::array::from_fn(|_| rng.int(-4096, 4096) as f64 / 512.0)
}

fn radius(rng: &mut Rng) -> f64 {
    rng.int(256, 2048) as f64 / 256.0
}

#[test]
fn random_dyadic_spheres_are_decided_exactly() {
    let mut rng = Rng::new(0x5ee5_0001);
    let pairs: Vec<Pair> = (0..120)
        .map(|_| Pair {
            c1: dyadic_point(&mut rng),
            r1: radius(&mut rng),
            c2: dyadic_point(&mut rng),
            r2: radius(&mut rng),
        })
        .collect();
    solve_all(&pairs);
}

#[test]
fn tangency_and_one_ulp_either_side() {
    let mut rng = Rng::new(0x5ee5_0002);
    let mut pairs = Vec::new();
    for k in 0..24 {
        let c1 = dyadic_point(&mut rng);
        let (r1, r2) = (radius(&mut rng), radius(&mut rng));
        let axis = k % 3;
        // Outside (d = r₁ + r₂) and inside (d = |r₁ − r₂|) along a coordinate axis: the
        // touching point is rational.
        for d in [r1 + r2, (r1 - r2).abs()] {
            if d == 0.0 {
                continue;
            }
            let mut c2 = c1;
            c2[axis] += if k % 2 == 0 { d } else { -d };
            for r in [r2, r2.next_up(), r2.next_down()] {
                pairs.push(Pair { c1, r1, c2, r2: r });
            }
        }
    }
    // Equal and concentric spheres.
    let c = dyadic_point(&mut rng);
    pairs.push(Pair {
        c1: c,
        r1: 2.0,
        c2: c,
        r2: 2.0,
    });
    pairs.push(Pair {
        c1: c,
        r1: 2.0,
        c2: c,
        r2: 2.0f64.next_up(),
    });
    solve_all(&pairs);
}

/// A plane `n·x + d = 0` against a sphere: `n` from a Pythagorean quadruple (so `|n|` is
/// rational and a tangent plane touches at a rational point).
struct PlaneCase {
    c: [f64; 3],
    r: f64,
    n: [i64; 3],
    len: i64,
    d: f64,
}

const NORMALS: [([i64; 3], i64); 6] = [
    ([1, 0, 0], 1),
    ([0, 0, 1], 1),
    ([1, 2, 2], 3),
    ([2, 3, 6], 7),
    ([-1, 4, 8], 9),
    ([0, -3, 4], 5),
];

/// Truth: `h = (n·c + d)/|n|`, empty when `h² > r²`, the touching point `c − h n̂` when
/// equal, else the circle of centre `c − h n̂` and radius² `r² − h²`.
fn plane_truth(p: &PlaneCase) -> Truth {
    let n: Vec<Rational> = p.n.iter().map(|&x| Rational::from(x)).collect();
    let len = Rational::from(p.len);
    let nc: Rational = (0..3).map(|i| Rational::from(&n[i] * &q(p.c[i]))).sum();
    let h = (nc + q(p.d)) / &len;
    let (h2, r2) = (h.clone().square(), q(p.r).square());
    if h2 > r2 {
        return Truth::Empty;
    }
    let foot: [Rational; 3] =
        std::array::from_fn(|i| q(p.c[i]) - Rational::from(&h * &n[i]) / &len);
    if h2 == r2 {
        Truth::Tangent(foot)
    } else {
        Truth::Circle(foot, r2 - h2)
    }
}

fn check_plane(p: &PlaneCase, r: &Value) {
    match plane_truth(p) {
        Truth::Empty => {
            assert_eq!(r["kind"], "empty", "{r}");
            assert_eq!(r["status"], "exact", "{r}");
        }
        Truth::Same => unreachable!("a plane is never a sphere"),
        Truth::Tangent(point) => {
            assert_eq!(r["kind"], "points", "{r}");
            assert_eq!(r["complete"], true, "{r}");
            assert!(
                matches!(r["status"].as_str(), Some("exact" | "verified")),
                "{r}"
            );
            let pts = r["points"].as_array().expect("points");
            assert_eq!(pts.len(), 1, "{r}");
            for (i, x) in point.iter().enumerate() {
                assert_eq!(pts[0]["xyz"][i].as_f64().unwrap(), nearest(x), "{r}");
            }
            assert_eq!(pts[0]["multiplicity"], 2, "{r}");
            check_sphere_params(&pts[0], &[(p.c, p.r)], &point, r);
        }
        Truth::Circle(centre, rho2) => {
            assert_eq!(r["kind"], "curves", "{r}");
            assert_eq!(r["status"], "verified", "{r}");
            assert_eq!(r["complete"], true, "{r}");
            assert_eq!(r["conic"]["type"], "circle", "{r}");
            for (i, x) in centre.iter().enumerate() {
                assert_eq!(exact_of(&r["conic"]["center"]["exact"][i]), *x, "{r}");
            }
            let n: [Rational; 3] = std::array::from_fn(|i| Rational::from(p.n[i]));
            check_polylines(r, &centre, &rho2, &n);
        }
    }
}

#[test]
fn planes_against_spheres_tangent_one_ulp_off_and_crossing() {
    let mut rng = Rng::new(0x5ee5_0003);
    let mut cases = Vec::new();
    for k in 0..60 {
        let (c, r) = (dyadic_point(&mut rng), radius(&mut rng));
        let (n, len) = NORMALS[k % NORMALS.len()];
        let nc: f64 = (0..3).map(|i| n[i] as f64 * c[i]).sum();
        // Tangent on both sides: d = −n·c ± r|n| (exact: small integers times dyadics).
        for side in [1.0, -1.0] {
            let d = -nc + side * r * len as f64;
            for d in [d, d.next_up(), d.next_down()] {
                cases.push(PlaneCase { c, r, n, len, d });
            }
        }
        // Crossing: the plane through a point strictly inside.
        let t = rng.int(-200, 200) as f64 / 256.0;
        cases.push(PlaneCase {
            c,
            r,
            n,
            len,
            d: -nc + t * r * len as f64,
        });
    }
    let input: Vec<String> = cases
        .iter()
        .enumerate()
        .map(|(i, p)| {
            json!({"id": i, "op": "intersect", "objects": [
                {"type": "sphere", "center": p.c, "radius": p.r},
                {"type": "plane", "normal": p.n, "d": p.d}]})
            .to_string()
        })
        .collect();
    let out = json_lines(&run("solve", &[], input.join("\n").as_bytes()));
    assert_eq!(out.len(), cases.len());
    let mut kinds = std::collections::BTreeMap::new();
    for (p, r) in cases.iter().zip(&out) {
        check_plane(p, r);
        *kinds
            .entry(r["kind"].as_str().unwrap().to_string())
            .or_insert(0) += 1;
    }
    // Every kind occurs (no family collapsed into one answer).
    for k in ["empty", "points", "curves"] {
        assert!(kinds.get(k).copied().unwrap_or(0) >= 10, "{kinds:?}");
    }
}

/// Three spheres with centres on one axis, each touching the next at one point: the
/// exact point with every sphere's parameters, not a curve answer.
#[test]
fn three_collinear_spheres_touching_at_one_point() {
    let mut rng = Rng::new(0x5ee5_0004);
    let mut input = Vec::new();
    let mut truths = Vec::new();
    for k in 0..30 {
        let c = dyadic_point(&mut rng);
        let (r1, r2, r3) = (radius(&mut rng), radius(&mut rng), radius(&mut rng));
        let axis = k % 3;
        let (mut c2, mut c3) = (c, c);
        c2[axis] += r1 + r2; // outside, touching at c + r₁e
        c3[axis] += r1 + r3;
        let mut point: [Rational; 3] = std::array::from_fn(|i| q(c[i]));
        point[axis] += q(r1);
        input.push(
            json!({"id": k, "op": "intersect", "objects": [
                {"type": "sphere", "center": c, "radius": r1},
                {"type": "sphere", "center": c2, "radius": r2},
                {"type": "sphere", "center": c3, "radius": r3}]})
            .to_string(),
        );
        truths.push((point, [(c, r1), (c2, r2), (c3, r3)]));
    }
    let out = json_lines(&run("solve", &[], input.join("\n").as_bytes()));
    for ((point, spheres), r) in truths.iter().zip(&out) {
        assert_eq!(r["kind"], "points", "{r}");
        assert_eq!(r["complete"], true, "{r}");
        let pts = r["points"].as_array().expect("points");
        assert_eq!(pts.len(), 1, "{r}");
        for (i, x) in point.iter().enumerate() {
            assert_eq!(pts[0]["xyz"][i].as_f64().unwrap(), nearest(x), "{r}");
        }
        assert_eq!(pts[0]["tangent"], true, "{r}");
        check_sphere_params(&pts[0], spheres, point, r);
    }
}
