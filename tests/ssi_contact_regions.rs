//! Surface ∩ surface contacts and what the exact input has near them (OPERATIONS.md
//! §9.5; docs/CERTIFICATES.md `verified_singular`): a plane at, or a few ulps in front
//! of or behind, a tangent plane of a torus. One ulp in front, the exact plane cuts the
//! torus in a loop about 1e-7 across, which the proven contact box (1e-15 wide) does not
//! hold — the answer used to be that box alone, `complete`: a certificate that missed
//! every point of the input's intersection. Now every contact reports its `region`, and
//! the family checks that the loop lies in it.
//!
//! Family: ring tori about the z axis (several radii), normals `(h cos φ, h sin φ, c)`
//! with Pythagorean triples so that the tangent value `e = hR + r|n|` (the largest
//! `n·x` on the torus) is a double, scaled by powers of two; planes `n·x = e′` with `e′`
//! from `e − 2` ulps to `e + 2` ulps, as implicit planes and, where a
//! double point of the plane exists, as parametric ones. The truth, in 256-bit MPFR and
//! closed form on the torus `((ρ − R)² + z² = r²)`: no point when `e′ > e`; the contact
//! point when `e′ = e`; else the loop's two ends in the angle `θ` about the axis
//! (`hR cos θ + r√(h² cos² θ + c²) = e′`, by bisection) and its two points on the
//! meridian through the contact.

use geocert::io::{read_cases, solve_case, verify_case};
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

/// The torus `major`, `minor` about z through 0 and the plane `n·x = e′`.
struct Case {
    major: f64,
    minor: f64,
    /// `(h, c)` and the direction angle of `(n_x, n_y)`.
    n: [f64; 3],
    e: f64,
}

impl Case {
    fn h(&self) -> Float {
        (f(self.n[0]).square() + f(self.n[1]).square()).sqrt()
    }

    fn norm(&self) -> Float {
        (self.h().square() + f(self.n[2]).square()).sqrt()
    }

    /// The largest `n·x` on the torus (exact for this family's numbers).
    fn top(&self) -> Float {
        self.h() * self.major + self.norm() * self.minor
    }

    /// The point at angle `θ` from the normal's direction and meridian angle `β`.
    fn point(&self, theta: &Float, beta: &Float) -> [Float; 3] {
        let phi = f(self.n[1]).atan2(&f(self.n[0])) + theta;
        let rho = f(self.major) + f(self.minor) * beta.clone().cos();
        [
            rho.clone() * phi.clone().cos(),
            rho * phi.sin(),
            f(self.minor) * beta.clone().sin(),
        ]
    }

    /// Points of the exact intersection near the contact (module doc): none, the
    /// contact, or four points of the loop.
    fn truth(&self) -> Vec<[Float; 3]> {
        let (h, c, r) = (self.h(), f(self.n[2]), f(self.minor));
        let e = f(self.e);
        let top = self.top();
        let beta0 = c.clone().atan2(&h);
        let zero = f(0.0);
        if e > top {
            return Vec::new();
        }
        if e == top {
            return vec![self.point(&zero, &beta0)];
        }
        // Meridian through the contact: hR + r|n| cos(β − β0) = e′.
        let cos = (e.clone() - h.clone() * self.major) / (r.clone() * self.norm());
        let a = cos.acos();
        let mut pts = vec![
            self.point(&zero, &(beta0.clone() + &a)),
            self.point(&zero, &(beta0.clone() - &a)),
        ];
        // The loop's ends in θ: the largest n·x on the parallel at θ equals e′.
        let reach = |t: &Float| {
            let hc = h.clone() * t.clone().cos();
            hc.clone() * self.major + (hc.square() + c.clone().square()).sqrt() * &r - &e
        };
        let (mut lo, mut hi) = (f(0.0), Float::with_val(PREC, Constant::Pi) / 2u32);
        for _ in 0..240 {
            let m = (lo.clone() + &hi) / 2u32;
            if reach(&m) > 0 {
                lo = m;
            } else {
                hi = m;
            }
        }
        let hc = h.clone() * lo.clone().cos();
        let beta = c.clone().atan2(&hc);
        pts.push(self.point(&lo, &beta));
        pts.push(self.point(&(-lo.clone()), &beta));
        pts
    }
}

fn inside(p: &[Float; 3], b: &Value) -> bool {
    (0..3).all(|k| p[k] >= b[k][0].as_f64().unwrap() && p[k] <= b[k][1].as_f64().unwrap())
}

/// Every region and box of the contacts of an answer, and its curves' vertices.
fn regions(a: &Value) -> Vec<Value> {
    let mut out = Vec::new();
    for list in ["points", "singular_points"] {
        for p in a[list].as_array().into_iter().flatten() {
            assert!(p.get("region").is_some(), "a contact without a region: {a}");
            out.push(p["region"].clone());
        }
    }
    out
}

/// The smallest box around a curve's vertices, widened by its distance bound and the
/// longest edge.
fn curve_boxes(a: &Value) -> Vec<Value> {
    let mut out = Vec::new();
    for c in a["curves"].as_array().into_iter().flatten() {
        let pts: Vec<Vec<f64>> = c["points"]
            .as_array()
            .unwrap()
            .iter()
            .map(|p| {
                p["xyz"]
                    .as_array()
                    .unwrap()
                    .iter()
                    .map(|x| x.as_f64().unwrap())
                    .collect()
            })
            .collect();
        let edge = pts
            .windows(2)
            .map(|w| {
                (0..3)
                    .map(|k| (w[0][k] - w[1][k]).abs())
                    .fold(0.0, f64::max)
            })
            .fold(0.0, f64::max);
        let pad = edge + c["distance_bound"].as_f64().unwrap_or(0.0);
        out.push(json!((0..3)
            .map(|k| {
                let lo = pts.iter().map(|p| p[k]).fold(f64::INFINITY, f64::min);
                let hi = pts.iter().map(|p| p[k]).fold(f64::NEG_INFINITY, f64::max);
                [lo - pad, hi + pad]
            })
            .collect::<Vec<_>>()));
    }
    out
}

/// `x` moved by `k` ulps.
fn ulps(mut x: f64, k: i32) -> f64 {
    for _ in 0..k.abs() {
        x = if k > 0 { x.next_up() } else { x.next_down() };
    }
    x
}

#[test]
fn the_exact_intersection_near_a_torus_contact_lies_in_its_region() {
    // (n_x, n_y, n_z) with |n| and √(n_x² + n_y²) integers.
    let normals = [
        [3.0, 0.0, 4.0],
        [0.0, 5.0, 12.0],
        [9.0, 12.0, 20.0],
        [-12.0, 9.0, 20.0],
    ];
    let tori = [(3.0, 1.0), (2.5, 0.75), (5.0, 0.5)];
    let (mut checked, mut loops, mut at_contact) = (0, 0, 0);
    for (i, n0) in normals.iter().enumerate() {
        for (j, &(major, minor)) in tori.iter().enumerate() {
            let scale = [1.0, 0.5, 8.0][(i + j) % 3];
            let n = n0.map(|x| x * scale);
            let base = Case {
                major,
                minor,
                n,
                e: 0.0,
            };
            let e = base.top().to_f64();
            assert_eq!(f(e), base.top(), "the tangent value is a double");
            let shifts: Vec<f64> = (-2..=2).map(|k| ulps(e, k)).collect();
            for (k, &e1) in shifts.iter().enumerate() {
                let case = Case { e: e1, ..base };
                let truth = case.truth();
                let torus = json!({"type": "torus", "center": [0, 0, 0], "major": major,
                    "minor": minor, "axis": [0, 0, 1]});
                let mut planes = vec![json!({"type": "plane", "normal": n, "d": -e1})];
                // A parametric plane where z = e′/n_z is a double point of it.
                let z0 = e1 / n[2];
                if f(z0) * n[2] == f(e1) {
                    planes.push(json!({"type": "plane", "origin": [0, 0, z0],
                        "u": [n[2], 0, -n[0]], "v": [0, n[2], -n[1]]}));
                }
                for (m, plane) in planes.into_iter().enumerate() {
                    let id = format!("n{i} t{j} e{k} p{m}");
                    let objects = if (k + m) % 2 == 0 {
                        json!([torus.clone(), plane])
                    } else {
                        json!([plane, torus.clone()])
                    };
                    let a = solve(&json!({"id": id, "op": "intersect", "objects": objects}));
                    let status = a["status"].as_str().unwrap();
                    assert_ne!(status, "error", "{id}: {a}");
                    if status == "undecided" {
                        continue;
                    }
                    if a["kind"] == "empty" {
                        assert!(
                            truth.is_empty(),
                            "{id}: empty, but the plane meets the torus: {a}"
                        );
                        checked += 1;
                        continue;
                    }
                    let holders: Vec<Value> =
                        regions(&a).into_iter().chain(curve_boxes(&a)).collect();
                    for p in &truth {
                        assert!(
                            holders.iter().any(|b| inside(p, b)),
                            "{id}: the input's point {:?} is in no region or curve box: {a}",
                            p.iter().map(Float::to_f64).collect::<Vec<_>>()
                        );
                    }
                    if truth.len() == 1 {
                        // At the contact itself the proven box holds it.
                        let held = ["points", "singular_points"].iter().any(|l| {
                            a[*l]
                                .as_array()
                                .into_iter()
                                .flatten()
                                .any(|q| inside(&truth[0], &q["box"]))
                        });
                        assert!(held, "{id}: the contact is in no box: {a}");
                        at_contact += 1;
                    }
                    loops += usize::from(truth.len() == 4);
                    checked += 1;
                }
            }
        }
    }
    eprintln!("{checked} decided, {loops} loops, {at_contact} at the contact");
    assert!(
        checked >= 50 && loops >= 15 && at_contact >= 20,
        "{checked} {loops} {at_contact}"
    );
}

/// geocert's own answer with a contact (and its `region`) reads back as a claim: a
/// `verify` of it is a verdict, not a format error.
#[test]
fn an_answer_with_a_region_verifies_as_a_claim() {
    let case = json!({"op": "intersect", "objects": [
        {"type": "torus", "center": [0, 0, 0], "major": 3, "minor": 1, "axis": [0, 0, 1]},
        {"type": "plane", "normal": [3, 0, 4], "d": -14}]});
    let answer = solve(&case);
    assert!(answer["points"][0].get("region").is_some(), "{answer}");
    let mut claimed = case.clone();
    claimed["claim"] = answer.clone();
    let read = read_cases(&claimed.to_string()).into_iter().next().unwrap();
    let r: Value = serde_json::from_str(&verify_case(read).to_json_line()).unwrap();
    assert_ne!(r["status"], "error", "{r}");
}
