//! Variable-radius fillets and variable-leg chamfers between two planes (OPERATIONS.md
//! §11.3, §11.5 (11.11); issue 18): generated plane pairs (integer normals, dyadic
//! offsets, all four sectors) with random piecewise-linear and cubic-Hermite laws.
//! The truth is computed in 256-bit MPFR by another route than the code's: the edge
//! point `q(ℓ)` by Cramer's rule on `m·q = h₁, n·q = h₂, ê·q = ℓ`, the centre
//! `q + ρ(σ₁(m − (m·n)n) + σ₂(n − (m·n)m))/(1 − (m·n)²)` (the station equations
//! (11.2)–(11.3) solved by hand), the law by the Hermite basis functions (the code uses
//! Bernstein form), the chamfer's transversals by (11.9)'s `((m·n)m − n)/|m × n|`.
//! Every reported box must hold its truth; the fillet's cross-sections are checked to
//! be arcs of radius `ρ(ℓ)` about the centre in the station plane; bad laws are typed
//! errors naming the field.

#[path = "fillet_support/mod.rs"]
mod fillet_support;

use fillet_support::*;
use geocert::num::rng::Rng;
use geocert::num::MpfrInterval;
use geocert::ops::fillet::{Face, Law};
use geocert::ops::Options;
use geocert::Status;

/// The law at `l` in MPFR: linear interpolation, or the cubic Hermite basis
/// `h₀₀ = 2s³ − 3s² + 1`, `h₁₀ = s³ − 2s² + s`, `h₀₁ = −2s³ + 3s²`, `h₁₁ = s³ − s²`.
fn law_truth(law: &Law, l: f64) -> MpfrInterval {
    let piece = |xs: Vec<f64>| {
        let i = xs
            .windows(2)
            .position(|w| l <= w[1])
            .unwrap_or(xs.len() - 2);
        i.min(xs.len() - 2)
    };
    match law {
        Law::Constant(r) => m(*r),
        Law::Linear(at) => {
            let i = piece(at.iter().map(|p| p[0]).collect());
            let ([l0, r0], [l1, r1]) = (at[i], at[i + 1]);
            m(r0) + (m(l) - m(l0)) * (m(r1) - m(r0)) / (m(l1) - m(l0))
        }
        Law::Cubic(at) => {
            let i = piece(at.iter().map(|p| p[0]).collect());
            let ([l0, r0, d0], [l1, r1, d1]) = (at[i], at[i + 1]);
            let h = m(l1) - m(l0);
            let s = (m(l) - m(l0)) / h.clone();
            let (s2, s3) = (s.sqr(), s.powi(3));
            let h00 = m(2.0) * s3.clone() - m(3.0) * s2.clone() + m(1.0);
            let h10 = s3.clone() - m(2.0) * s2.clone() + s.clone();
            let h01 = m(3.0) * s2.clone() - m(2.0) * s3.clone();
            let h11 = s3 - s2;
            h00 * m(r0) + h10 * h.clone() * m(d0) + h01 * m(r1) + h11 * h * m(d1)
        }
    }
}

/// A random law over `[l0, l1]`: linear (3–5 stations, values in `[0.25, 2.25]`) or
/// cubic with slopes small enough that its Bernstein coefficients stay positive.
fn random_law(rng: &mut Rng, l0: f64, l1: f64) -> Law {
    let n = 3 + rng.below(3);
    let ls: Vec<f64> = (0..n)
        .map(|i| l0 + (l1 - l0) * i as f64 / (n - 1) as f64)
        .collect();
    let value = |rng: &mut Rng| 0.25 + rng.int(0, 16) as f64 / 8.0;
    if rng.coin() {
        Law::linear(ls.iter().map(|&l| [l, value(rng)]).collect(), "radius").unwrap()
    } else {
        let h = (l1 - l0) / (n - 1) as f64;
        Law::cubic(
            ls.iter()
                .map(|&l| {
                    let r = value(rng);
                    [l, r, rng.unit() * 0.2 * r / h]
                })
                .collect(),
            "radius",
        )
        .unwrap()
    }
}

/// Two planes `nᵢ·x + dᵢ = 0` with small integer normals, not parallel.
fn random_planes(rng: &mut Rng) -> [([f64; 3], f64); 2] {
    loop {
        let mut normal = || [0; 3].map(|_| rng.int(-3, 3) as f64);
        let (a, b) = (normal(), normal());
        let c = [
            a[1] * b[2] - a[2] * b[1],
            a[2] * b[0] - a[0] * b[2],
            a[0] * b[1] - a[1] * b[0],
        ];
        if c.iter().any(|&x| x != 0.0) {
            return [(a, rng.dyadic()), (b, rng.dyadic())];
        }
    }
}

/// The exact geometry of two planes in MPFR: unit normals, `hᵢ = −dᵢ/|nᵢ|`, the edge
/// direction `ê` and the edge point `q(ℓ)` (Cramer's rule on `m·q = h₁`, `n·q = h₂`,
/// `ê·q = ℓ`).
struct PlanePair {
    normals: [[MpfrInterval; 3]; 2],
    h: [MpfrInterval; 2],
    e: [MpfrInterval; 3],
}

impl PlanePair {
    fn new(planes: &[([f64; 3], f64); 2]) -> PlanePair {
        let normals = planes.map(|(n, _)| unit(&lift3(n)));
        let h = planes.map(|(n, d)| -m(d) / norm(&lift3(n)));
        let e = unit(&cross(&normals[0], &normals[1]));
        PlanePair { normals, h, e }
    }

    fn q(&self, l: f64) -> [MpfrInterval; 3] {
        let [mm, n] = &self.normals;
        let det = dot(mm, &cross(n, &self.e));
        let terms = [
            (self.h[0].clone(), cross(n, &self.e)),
            (self.h[1].clone(), cross(&self.e, mm)),
            (m(l), cross(mm, n)),
        ];
        let mut q = [m(0.0), m(0.0), m(0.0)];
        for (s, v) in &terms {
            q = axpy(&q, &(s.clone() / det.clone()), v);
        }
        q
    }

    fn cos(&self) -> MpfrInterval {
        dot(&self.normals[0], &self.normals[1])
    }

    /// The fillet centre at `ℓ` for the signed offsets `d₁`, `d₂`.
    fn centre(&self, l: f64, d: &[MpfrInterval; 2]) -> [MpfrInterval; 3] {
        let [mm, n] = &self.normals;
        let c = self.cos();
        let den = m(1.0) - c.sqr();
        let alpha = (d[0].clone() - c.clone() * d[1].clone()) / den.clone();
        let beta = (d[1].clone() - c * d[0].clone()) / den;
        axpy(&axpy(&self.q(l), &alpha, mm), &beta, n)
    }
}

/// Random plane pairs, sectors and laws: every station's centre, both contacts and
/// every grid point hold the MPFR truth; the spine vertices are within their bounds;
/// the grid points lie at distance `ρ(ℓ)` from the centre in the station plane.
#[test]
fn variable_radius_fillets_of_plane_pairs_hold_the_truth() {
    let mut rng = Rng::new(1803);
    let mut checked = 0;
    for case in 0..60 {
        let planes = random_planes(&mut rng);
        let pair = PlanePair::new(&planes);
        let shapes = planes.map(|(n, d)| implicit_plane(n, d));
        let (l0, l1) = (rng.dyadic(), 0.0);
        let (l0, l1) = (l0.min(l1) - 1.0, l0.max(l1) + 1.0);
        let law = random_law(&mut rng, l0, l1);
        let signs = [0, 1].map(|_| if rng.coin() { 1.0 } else { -1.0 });
        // half the cases on the whole span (the default range), half on a part of it
        let range = (case % 2 == 1).then_some([l0 + 0.25, l1 - 0.125]);
        let (ans, status) = blend_law(
            &shapes[0],
            &shapes[1],
            &law,
            &spec(sector_of(signs), range, [9, 5]),
        );
        assert_eq!(status, Status::Verified, "case {case}");
        let k = &ans.components[0];
        assert_eq!(k.grid.t[0], range.map_or(l0, |r| r[0]));
        for (i, &t) in k.grid.t.iter().enumerate() {
            let rho = law_truth(&law, t);
            let d = signs.map(|s| m(s) * rho.clone());
            let c = pair.centre(t, &d);
            let contacts = [0, 1].map(|j| axpy(&c, &-d[j].clone(), &pair.normals[j]));
            assert!(dist(&k.spine.points[i].xyz, &c) <= k.spine.points[i].bound.unwrap());
            for (j, truth) in contacts.iter().enumerate() {
                assert_box_contains(&k.contacts[j][i].xyz_box, truth, "contact");
            }
            // the arc (11.7) from the truth: p_m = c − (d₁m + d₂n)/(1 + cos φ)
            let cos_phi = m(signs[0] * signs[1]) * pair.cos();
            let opc = m(1.0) + cos_phi;
            let pull = axpy(
                &axpy(&[m(0.0), m(0.0), m(0.0)], &d[0], &pair.normals[0]),
                &d[1],
                &pair.normals[1],
            );
            let pm = axpy(&c, &(m(-1.0) / opc.clone()), &pull);
            let w = (opc / m(2.0)).sqrt();
            let q = pair.q(t);
            for (j, &z) in k.grid.z.iter().enumerate() {
                let (y, zz) = (m(1.0) - m(z), m(z));
                let (a, b, cc) = (y.sqr(), m(2.0) * zz.clone() * y * w.clone(), zz.sqr());
                let den = a.clone() + b.clone() + cc.clone();
                let f = [0, 1, 2].map(|x| {
                    (a.clone() * contacts[0][x].clone()
                        + b.clone() * pm[x].clone()
                        + cc.clone() * contacts[1][x].clone())
                        / den.clone()
                });
                assert_box_contains(&k.grid.boxes[i][j], &f, "grid");
                // on the circle of radius ρ(ℓ) about c, in the station plane through q
                let r = [0, 1, 2].map(|x| f[x].clone() - c[x].clone());
                let off = norm(&r) - rho.clone();
                assert!(off.contains(0.0) && off.width() < 1e-60, "case {case}");
                let along = dot(&[0, 1, 2].map(|x| f[x].clone() - q[x].clone()), &pair.e);
                assert!(along.contains(0.0) && along.width() < 1e-60);
            }
            checked += 1;
        }
    }
    assert_eq!(checked, 60 * 9);
}

/// The code's own formula in 256-bit MPFR intervals at random `ℓ` inside pieces and
/// across stations: `(c − q)·ê` and `(pᵢ − q)·ê` enclose 0 (the station plane
/// (11.3)), `|c − pᵢ| − ρ(ℓ)` encloses 0, and `c` agrees with the truth.
#[test]
fn variable_radius_stations_satisfy_the_station_equations() {
    let mut rng = Rng::new(1804);
    for _ in 0..40 {
        let planes = random_planes(&mut rng);
        let pair = PlanePair::new(&planes);
        let faces =
            planes.map(|(n, d)| Face::of_shape(&implicit_plane(n, d), "objects[0]").unwrap());
        let law = random_law(&mut rng, -2.0, 2.0);
        let signs = [0, 1].map(|_| if rng.coin() { 1.0 } else { -1.0 });
        let curve = geocert::ops::fillet::CentreCurve::new(faces, signs, law.clone(), None)
            .unwrap()
            .remove(0);
        assert_eq!(curve.range, [-2.0, 2.0]);
        for _ in 0..8 {
            let l = 2.0 * rng.unit();
            let st = curve.station(&m(l));
            let rho = law_truth(&law, l);
            let q = pair.q(l);
            let tight = |x: &MpfrInterval| x.contains(0.0) && x.width() < 1e-60;
            let rel = |p: &[MpfrInterval; 3]| [0, 1, 2].map(|x| p[x].clone() - q[x].clone());
            assert!(tight(&dot(&rel(&st.centre), &pair.e)));
            for j in 0..2 {
                assert!(tight(&dot(&rel(&st.contact[j]), &pair.e)));
                let r = [0, 1, 2].map(|x| st.centre[x].clone() - st.contact[j][x].clone());
                assert!(tight(&(norm(&r) - rho.clone())));
            }
            let truth = pair.centre(l, &signs.map(|s| m(s) * rho.clone()));
            for (x, value) in truth.iter().enumerate() {
                assert!(tight(&(st.centre[x].clone() - value.clone())));
            }
        }
    }
}

/// Variable chamfer legs (11.11), each leg its own law (or a constant): the contact
/// lines `q(ℓ) − dᵢ(ℓ)τᵢ` with `d₁ = σ₂k₁`, `d₂ = σ₁k₂` and the ruled surface between
/// them hold the truth at every station.
#[test]
fn variable_leg_chamfers_hold_the_truth() {
    let mut rng = Rng::new(1805);
    for case in 0..40 {
        let planes = random_planes(&mut rng);
        let pair = PlanePair::new(&planes);
        let shapes = planes.map(|(n, d)| implicit_plane(n, d));
        let legs = [0, 1].map(|k| {
            if (case + k) % 3 == 0 {
                Law::Constant(0.5 + rng.int(0, 8) as f64 / 4.0)
            } else {
                random_law(&mut rng, -4.0 + k as f64, 3.0 + k as f64)
            }
        });
        let signs = [0, 1].map(|_| if rng.coin() { 1.0 } else { -1.0 });
        let range = (case % 3 == 2).then_some([-1.5, 1.5]);
        let (ans, status) = chamfer_laws(
            &shapes[0],
            &shapes[1],
            &legs,
            &spec(sector_of(signs), range, [7, 3]),
        );
        assert_eq!(status, Status::Verified);
        let k = &ans.components[0];
        // default range: the common span of the variable legs
        let span = legs
            .iter()
            .filter_map(Law::span)
            .reduce(|a, b| [a[0].max(b[0]), a[1].min(b[1])]);
        let expected = range.or(span).unwrap_or([-1.5, 1.5]);
        assert_eq!([k.grid.t[0], k.grid.t[6]], expected, "case {case}");
        let c = pair.cos();
        let sin = (m(1.0) - c.sqr()).sqrt();
        let [mm, n] = &pair.normals;
        let tau = [
            axpy(
                &[0, 1, 2].map(|x| c.clone() * mm[x].clone() / sin.clone()),
                &(m(-1.0) / sin.clone()),
                n,
            ),
            axpy(
                &[0, 1, 2].map(|x| c.clone() * n[x].clone() / sin.clone()),
                &(m(-1.0) / sin.clone()),
                mm,
            ),
        ];
        for (i, &t) in k.grid.t.iter().enumerate() {
            let d = [
                m(signs[1]) * law_truth(&legs[0], t),
                m(signs[0]) * law_truth(&legs[1], t),
            ];
            let q = pair.q(t);
            let lines = [0, 1].map(|j| axpy(&q, &-d[j].clone(), &tau[j]));
            for (j, line) in lines.iter().enumerate() {
                assert_box_contains(&k.contacts[j][i].xyz_box, line, "chamfer contact");
            }
            assert!(dist(&k.spine.points[i].xyz, &q) <= k.spine.points[i].bound.unwrap());
            let mid = [0, 1, 2].map(|x| (lines[0][x].clone() + lines[1][x].clone()) / m(2.0));
            assert_box_contains(&k.grid.boxes[i][1], &mid, "chamfer midpoint");
        }
    }
}

/// A constant law written as a linear law with equal values, and as a cubic with zero
/// slopes, gives the §16.13 fillet: the boxes hold the exact centre `(−1, y, −1)`,
/// contacts `(−1, y, 0)`, `(0, y, −1)` and `f(·, ½) = (1/√2 − 1)(1, 0, 1) + (0, y, 0)`.
#[test]
fn constant_laws_reproduce_the_16_13_example() {
    let r = plane([0.0; 3], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]);
    let s = plane([0.0; 3], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]);
    let laws = [
        Law::linear(vec![[-2.0, 1.0], [0.5, 1.0], [2.0, 1.0]], "radius").unwrap(),
        Law::cubic(vec![[-2.0, 1.0, 0.0], [2.0, 1.0, 0.0]], "radius").unwrap(),
    ];
    for law in &laws {
        let (b, status) = blend_law(&r, &s, law, &spec(3, None, [5, 3]));
        assert_eq!(status, Status::Verified);
        let c = &b.components[0];
        assert_eq!(c.grid.t, vec![-2.0, -1.0, 0.0, 1.0, 2.0]);
        let half = m(0.5).sqrt() - m(1.0);
        for (i, &y) in c.grid.t.iter().enumerate() {
            assert!(
                dist(&c.spine.points[i].xyz, &lift3([-1.0, y, -1.0]))
                    <= c.spine.points[i].bound.unwrap()
            );
            assert_box_contains(&c.contacts[0][i].xyz_box, &lift3([-1.0, y, 0.0]), "p1");
            assert_box_contains(&c.contacts[1][i].xyz_box, &lift3([0.0, y, -1.0]), "p2");
            assert_box_contains(
                &c.grid.boxes[i][1],
                &[half.clone(), m(y), half.clone()],
                "f(½)",
            );
        }
    }
}

/// Bad laws through the command line: typed errors naming the entry; a cubic that
/// dips below zero between positive stations is refused (field `radius`); a variable
/// radius between curved faces is `unsupported`.
#[test]
fn bad_laws_are_typed_errors_naming_the_field() {
    let planes = r#""objects": [{"type": "plane", "normal": [0,0,1], "d": 0}, {"type": "plane", "normal": [1,0,0], "d": 0}], "sector": 3"#;
    let cases = [
        (
            r#""radius": {"law": "linear", "at": [[0, 1], [1, -1]]}"#,
            "invalid_value",
            "radius.at[1][1]",
        ),
        (
            r#""radius": {"law": "linear", "at": [[0, 1], [1, 0]]}"#,
            "invalid_value",
            "radius.at[1][1]",
        ),
        (
            r#""radius": {"law": "linear", "at": [[0, 1], [2, 1], [1, 1]]}"#,
            "invalid_value",
            "radius.at[2][0]",
        ),
        (
            r#""radius": {"law": "linear", "at": [[0, 1], [0, 1]]}"#,
            "invalid_value",
            "radius.at[1][0]",
        ),
        (
            r#""radius": {"law": "linear", "at": [[0, 1]]}"#,
            "count_mismatch",
            "radius.at",
        ),
        (
            r#""radius": {"law": "cubic", "at": [[0, 1], [1, 1]]}"#,
            "count_mismatch",
            "radius.at[0]",
        ),
        (
            r#""radius": {"law": "cubic", "at": [[0, 0.1, -5], [1, 0.1, 5]]}"#,
            "invalid_value",
            "radius",
        ),
        (
            r#""radius": {"law": "quadratic", "at": [[0, 1], [1, 1]]}"#,
            "format",
            "radius.law",
        ),
        (
            r#""radius": {"law": "linear", "at": [[0, 1], [1, "x"]]}"#,
            "format",
            "radius.at[1][1]",
        ),
        (
            r#""radius": {"law": "linear", "at": [[0, 1], [1, 2]]}, "range": [-1, 1]"#,
            "invalid_value",
            "range",
        ),
        (
            r#""radius": -2, "range": [0, 1]"#,
            "invalid_value",
            "radius",
        ),
    ];
    for (fields, kind, field) in cases {
        let r = solve(&format!(r#"{{"op": "fillet", {planes}, {fields}}}"#));
        assert_eq!(
            (r["error"]["kind"].as_str(), r["error"]["field"].as_str()),
            (Some(kind), Some(field)),
            "{fields}: {r}"
        );
    }
    // an unknown field of a law: a format error within `radius`
    let r = solve(&format!(
        r#"{{"op": "fillet", {planes}, "radius": {{"law": "linear", "at": [[0, 1], [1, 1]], "extra": 1}}}}"#
    ));
    assert_eq!(r["error"]["kind"], "format", "{r}");
    assert!(
        r["error"]["field"].as_str().unwrap().starts_with("radius"),
        "{r}"
    );
    let legs = [
        (
            r#""legs": [1, {"law": "linear", "at": [[0, 1], [1, -1]]}]"#,
            "invalid_value",
            "legs[1].at[1][1]",
        ),
        (
            r#""legs": [{"law": "cubic", "at": [[0, 0.1, -5], [1, 0.1, 5]]}, 1]"#,
            "invalid_value",
            "legs[0]",
        ),
        (
            r#""legs": [{"law": "linear", "at": [[0, 1], [1, 1]]}, {"law": "linear", "at": [[2, 1], [3, 1]]}]"#,
            "invalid_value",
            "range",
        ),
    ];
    for (fields, kind, field) in legs {
        let r = solve(&format!(r#"{{"op": "chamfer", {planes}, {fields}}}"#));
        assert_eq!(
            (r["error"]["kind"].as_str(), r["error"]["field"].as_str()),
            (Some(kind), Some(field)),
            "{fields}: {r}"
        );
    }
    // NaN and infinity cannot be written in JSON; through the API they name the entry
    let nan = Law::linear(vec![[0.0, 1.0], [1.0, f64::NAN]], "radius");
    assert_eq!(
        error_kind(nan),
        ("invalid_value".into(), "radius.at[1][1]".into())
    );
    let inf = Law::cubic(vec![[0.0, 1.0, 0.0], [f64::INFINITY, 1.0, 0.0]], "radius");
    assert_eq!(
        error_kind(inf),
        ("invalid_value".into(), "radius.at[1][0]".into())
    );
    let ground = plane([0.0; 3], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]);
    let pipe = cylinder([0.0, 0.0, -5.0], 2.0, [0.0, 0.0, 1.0], [0.0, 10.0]);
    let law = Law::linear(vec![[0.0, 0.5], [1.0, 0.75]], "radius").unwrap();
    let got = geocert::ops::fillet::fillet_law(
        &ground,
        &pipe,
        &law,
        &spec(2, None, [5, 3]),
        &Options::default(),
    );
    assert_eq!(error_kind(got), ("unsupported".into(), "radius".into()));
}

/// The command line echoes the law and answers `verified` over the law's span.
#[test]
fn cli_variable_radius_case() {
    let r = solve(
        r#"{"op": "fillet", "objects": [{"type": "plane", "normal": [0,0,1], "d": 0}, {"type": "plane", "normal": [1,0,0], "d": 0}], "sector": 3, "radius": {"law": "linear", "at": [[0, 1], [2, 0.5], [4, 1.5]]}, "grid": [5, 3]}"#,
    );
    assert_eq!(r["status"], "verified", "{r}");
    assert_eq!(
        r["blend"]["radius"],
        serde_json::json!({"law": "linear", "at": [[0.0, 1.0], [2.0, 0.5], [4.0, 1.5]]})
    );
    assert_eq!(
        r["blend"]["components"][0]["grid"]["t"],
        serde_json::json!([0.0, 1.0, 2.0, 3.0, 4.0])
    );
    // the centre at ℓ = 2 is (−ρ, 2, −ρ) with ρ = 0.5 (normals (0,0,1), (1,0,0), sector 3)
    let centre = &r["curves"][0]["points"][2]["xyz"];
    assert_eq!(centre, &serde_json::json!([-0.5, 2.0, -0.5]), "{r}");
    let r = solve(
        r#"{"op": "chamfer", "objects": [{"type": "plane", "normal": [0,0,1], "d": 0}, {"type": "plane", "normal": [1,0,0], "d": 0}], "sector": 3, "legs": [1, {"law": "cubic", "at": [[0, 1, 0], [4, 2, 0]]}], "grid": [3, 3]}"#,
    );
    assert_eq!(r["status"], "verified", "{r}");
    assert_eq!(r["blend"]["legs"][0], 1.0);
    // ℓ = 2: the second leg is 1.5; the contact on the second face (x = 0) is (0, 2, −1.5)
    let p = &r["blend"]["components"][0]["contacts"][1][1]["xyz"];
    assert_eq!(p, &serde_json::json!([0.0, 2.0, -1.5]), "{r}");
}
