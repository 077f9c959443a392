//! `verify` of a claimed `arc` (issue 20), a generated family with exact truth: curve B
//! is the exact piece of curve A over `[a, b]` (de Casteljau in rationals, dyadic `a`,
//! `b` and integer control points, so the doubles of the input are the exact values),
//! possibly reversed. The shared arc is then known from the construction — from
//! `(t, s) = (a, 0)` to `(b, 1)` (or `(a, 1)`, `(b, 0)` reversed), all of B — and:
//!
//! - a true claim with exact parameters is confirmed exactly, and one by coordinates
//!   only (the ends rounded) is confirmed within the tolerance, nothing missed;
//! - a claim with an end moved along A outward past the arc (exact parameters, so the
//!   moved point is on A but off B) or moved off the curve in space is refuted, and the
//!   true end it hides is listed as missed;
//! - the same claim against a wrong curve (B translated, or the piece over another
//!   interval) is never confirmed, and refuted whenever the answer is decided and
//!   complete.

use geocert::io::{read_cases, verify_case};
use geocert::num::rng::Rng;
mod exact_bezier_support;
use exact_bezier_support::*;
use rug::Rational;
use serde_json::{json, Value};

fn verify(case: &Value) -> Value {
    let read = read_cases(&case.to_string()).into_iter().next().unwrap();
    serde_json::from_str(&verify_case(read).to_json_line()).unwrap()
}

fn text(x: &Rational) -> String {
    x.to_string()
}

/// A claimed end by its exact point and exact parameters `(t, s)`.
fn exact_end(p: &Poly, t: &Rational, s: &Rational) -> Value {
    let xyz: Vec<String> = at(p, t).iter().map(text).collect();
    json!({"xyz": at(p, t).iter().map(Rational::to_f64).collect::<Vec<_>>(),
           "exact": {"xyz": xyz, "params": [[text(t)], [text(s)]]}})
}

/// A claimed end by rounded coordinates only.
fn xyz_end(v: &[Rational]) -> Value {
    json!({"xyz": v.iter().map(Rational::to_f64).collect::<Vec<_>>()})
}

fn arc_item(r: &Value) -> &Value {
    r["claims"]
        .as_array()
        .unwrap()
        .iter()
        .find(|c| c["item"] == "arc")
        .unwrap_or_else(|| panic!("no arc verdict: {r}"))
}

fn missed(r: &Value) -> usize {
    r["missed"].as_array().map_or(usize::MAX, Vec::len)
}

const TOL: f64 = 1e-9;

#[test]
fn arc_claims_are_confirmed_and_refuted_against_exact_truth() {
    let mut rng = Rng::new(2040);
    let mut counts = [0usize; 6];
    for i in 0..240 {
        let dim = 2 + i % 2;
        let deg = 1 + (i / 2) % 5;
        let p: Poly = (0..=deg)
            .map(|_| (0..dim).map(|_| Rational::from(rng.int(-64, 64))).collect())
            .collect();
        // A random dyadic sub-interval, not all of [0, 1].
        let (a, b) = loop {
            let x = rng.int(0, 8);
            let y = rng.int(0, 8);
            if x < y && (x, y) != (0, 8) {
                break (Rational::from((x, 8)), Rational::from((y, 8)));
            }
        };
        let reversed = rng.coin();
        let mut sub = piece(&p, &a, &b);
        if reversed {
            sub.reverse();
        }
        let (sa, sb) = if reversed {
            (Rational::from(1), Rational::from(0))
        } else {
            (Rational::from(0), Rational::from(1))
        };
        let objects = json!([bezier(&p), bezier(&sub)]);
        let case = |claim: Value| json!({"op": "intersect", "objects": objects, "claim": claim});

        // 1. True, with exact parameters: confirmed exactly, nothing missed.
        let claim = json!({"kind": "arc", "tolerance": TOL,
            "arc": {"a": exact_end(&p, &a, &sa), "b": exact_end(&p, &b, &sb)}});
        let r = verify(&case(claim));
        assert_eq!(r["kind"], "arc", "{r}");
        assert_eq!(arc_item(&r)["verdict"], "confirmed", "{r}");
        assert_eq!(arc_item(&r)["status"], "exact", "{r}");
        assert_eq!(r["claims"][0]["verdict"], "confirmed", "kind: {r}");
        assert_eq!(missed(&r), 0, "{r}");
        counts[0] += 1;

        // 2. True, by rounded coordinates (ends swapped): confirmed within the tolerance.
        let claim = json!({"tolerance": TOL,
            "arc": {"a": xyz_end(&at(&p, &b)), "b": xyz_end(&at(&p, &a))}});
        let r = verify(&case(claim));
        assert_eq!(arc_item(&r)["verdict"], "confirmed", "{r}");
        assert_eq!(missed(&r), 0, "{r}");
        counts[1] += 1;

        // 3. An end moved outward along A by 1/16 in parameter (on A, off B): the exact
        // test fails, and the moved end lies beyond the tolerance of the arc.
        let sixteenth = Rational::from((1, 16));
        let (ma, mb) = if a >= sixteenth {
            (Rational::from(&a - &sixteenth), b.clone())
        } else {
            (a.clone(), Rational::from(&b + &sixteenth))
        };
        let claim = json!({"tolerance": TOL,
            "arc": {"a": exact_end(&p, &ma, &sa), "b": exact_end(&p, &mb, &sb)}});
        let r = verify(&case(claim));
        let v = arc_item(&r);
        assert_eq!(v["verdict"], "refuted", "{r}");
        assert_eq!(missed(&r), 1, "the true end the moved one hides: {r}");
        counts[2] += 1;

        // 4. An end moved off the curve by 1e-4 along a normal of A at it (tolerance
        // 1e-9): beyond the tolerance of the arc (it bends far less over 1e-4), refuted.
        let fwd = piece(&p, &a, &b);
        let tangent: Vec<Rational> = (0..dim)
            .map(|k| Rational::from(&fwd[1][k] - &fwd[0][k]))
            .collect();
        let normal: Vec<Rational> = if dim == 2 {
            vec![-tangent[1].clone(), tangent[0].clone()]
        } else {
            // T × e_k with e_k the axis where |T_k| is least.
            let k = (0..3)
                .min_by(|&x, &y| tangent[x].clone().abs().cmp(&tangent[y].clone().abs()))
                .unwrap();
            let mut e = vec![Rational::new(); 3];
            e[k] = Rational::from(1);
            let c = |i: usize, j: usize| {
                Rational::from(&tangent[i] * &e[j]) - Rational::from(&tangent[j] * &e[i])
            };
            vec![c(1, 2), c(2, 0), c(0, 1)]
        };
        let big = normal.iter().map(|x| x.clone().abs()).max().unwrap();
        if big == 0 {
            continue; // a degenerate first leg: no tangent to move along
        }
        let delta = Rational::from((1, 10000)) / big;
        let off: Vec<Rational> = at(&p, &a)
            .iter()
            .zip(&normal)
            .map(|(x, n)| x + Rational::from(n * &delta))
            .collect();
        let claim =
            json!({"tolerance": TOL, "arc": {"a": xyz_end(&off), "b": xyz_end(&at(&p, &b))}});
        let r = verify(&case(claim));
        assert_eq!(arc_item(&r)["verdict"], "refuted", "{r}");
        counts[3] += 1;

        // 5. The right claim, the wrong second curve: the piece translated by one unit
        // along x, or the piece over another interval. Never confirmed; refuted when the
        // answer is decided and complete, the proven points the claim hides missed.
        let wrong = if i % 2 == 0 {
            let mut t = sub.clone();
            for v in &mut t {
                v[0] += 1;
            }
            t
        } else {
            // The piece beyond the claimed arc (sharing one end of it at most).
            let one = Rational::from(1);
            let c = if b < one {
                piece(&p, &b, &one)
            } else {
                piece(&p, &Rational::new(), &a)
            };
            if reversed {
                c.into_iter().rev().collect()
            } else {
                c
            }
        };
        let claim = json!({"kind": "arc", "tolerance": TOL,
            "arc": {"a": exact_end(&p, &a, &sa), "b": exact_end(&p, &b, &sb)}});
        let r = verify(
            &json!({"op": "intersect", "objects": [bezier(&p), bezier(&wrong)], "claim": claim}),
        );
        let v = arc_item(&r);
        assert_ne!(v["verdict"], "confirmed", "{r}");
        let decided = r["status"] != "undecided" && r["complete"] == true;
        if decided && r["kind"] != "coincident" {
            assert_eq!(v["verdict"], "refuted", "{r}");
            counts[4] += 1;
            if r["kind"] == "points" && r["status"] != "verified_singular" {
                let n = r["points"].as_array().unwrap().len();
                assert_eq!(missed(&r), n, "{r}");
                counts[5] += n.min(1);
            }
        }
    }
    assert!(counts[3] >= 230, "{counts:?}");
    assert!(counts[4] >= 200, "{counts:?}");
    eprintln!("arc claims: {counts:?}");
}
