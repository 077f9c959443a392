//! Sphere ∩ sphere is decided exactly through the radical plane (ops::section, issue
//! 16): disjoint and nested spheres are an exact `empty`, equal ones `coincident`, and
//! a circle comes with its exact centre and correctly rounded radius. Families of
//! dyadic spheres — random, exactly tangent (outside and inside) and one ulp either
//! side of tangency — against a truth computed here with exact rationals and 300-bit
//! MPFR, by the closed form `t = (d² + r₁² − r₂²)/(2d²)`, `ρ² = r₁² − t²d²`.

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
            // One touching point, proven in its box (the tracer's singular certificate).
            assert_ne!(r["kind"], "empty", "{r}");
            assert_ne!(r["kind"], "curves", "{r}");
            let pts = r["points"].as_array().expect("points");
            assert_eq!(pts.len(), 1, "{r}");
            for (i, x) in point.iter().enumerate() {
                assert!(holds(&pts[0]["box"][i], x), "{r}");
            }
        }
        Truth::Circle(centre, rho2) => {
            assert_eq!(r["kind"], "curves", "{r}");
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
    let pairs: Vec<Pair> = (0..30)
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
    for k in 0..4 {
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
