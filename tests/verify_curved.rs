//! `verify` against numerically certified answers (issue 14 item 6, issue 21 "Families"
//! 1): for every curved operation — line × sphere, ellipsoid, cylinder, torus; two
//! plane circles; a circle × a sphere; point → circle, sphere, torus; three spheres —
//! families of random cases whose solutions are known in closed form in MPFR at 256
//! bits (tests/verify_support), checked as follows:
//!
//! - the answer is complete and decided, one certified box holding each true solution
//!   (so the truth is known);
//! - the closed-form points claimed at tolerance 1e-9 are `confirmed` wherever the
//!   solution's box is narrower than half the tolerance (a wider box cannot be proven
//!   within it: then `undecided`, never `refuted`), and nothing is `missed`;
//! - the same claims as parameters on every object are `confirmed`;
//! - claims moved by 10 × tolerance in a random direction are `refuted` (where the box is
//!   narrower than the tolerance; never `confirmed`) and those solutions `missed`;
//! - a claim omitting one solution has that solution — and only it — in `missed`;
//! - geocert's own answer fed back as the claim is `confirmed` point by point (boxes
//!   narrower than the tolerance);
//! - a claim placed so that a solution's certified box straddles the tolerance sphere
//!   is `undecided`, never refuted;
//! - every verdict agrees with the MPFR truth: `confirmed` only when a true solution
//!   lies within the tolerance, `refuted` only when none does.
//!
//! Boxes wider than the tolerance are counted, and must stay rare (under 10% of the
//! solutions). Cases per family: `GEOCERT_VERIFY_CASES` (default 20, ten families).

mod cli_support;
mod verify_support;

use geocert::robust::rng::Rng;
use rug::float::Round;
use rug::{Float, Rational};
use serde_json::{json, Value};
use verify_support::{
    claiming, count, diameter, doubles, families, holds, point_claim, solve, sound, truth_known,
    unit, verify, Case,
};

const TOL: f64 = 1e-9;

fn verdicts(r: &Value) -> Vec<String> {
    r["claims"]
        .as_array()
        .unwrap_or_else(|| panic!("no claims: {r}"))
        .iter()
        .map(|c| c["verdict"].as_str().unwrap().to_string())
        .collect()
}

/// Boxes wider than `limit` are rare: under 10% of `total`.
fn assert_rare(what: &str, wide: usize, total: usize) {
    assert!(
        wide * 10 < total,
        "{what}: {wide} of {total} boxes are wide"
    );
}

/// The cases of every family whose answer is decided and complete (the truth is then
/// known and every assertion applies); the others — where the certifier could not
/// prove completeness — must be rare, and their claims are never refuted.
fn cases() -> Vec<(String, Case)> {
    let mut out = vec![];
    let mut incomplete = 0;
    for (k, (name, family)) in families().into_iter().enumerate() {
        let mut rng = Rng::new(1400 + k as u64);
        for i in 0..count(20) {
            let name = format!("{name} #{i}");
            let c = family(&mut rng);
            let r = solve(&c.case);
            if r["complete"] == true && r["status"] != "undecided" {
                out.push((name, c));
            } else {
                let claimed: Vec<Vec<f64>> = c.truths.iter().map(|t| doubles(t)).collect();
                let v = verify(&claiming(&c.case, point_claim(&claimed, TOL)));
                assert!(!verdicts(&v).iter().any(|x| x == "refuted"), "{name}: {v}");
                incomplete += 1;
            }
        }
    }
    assert!(
        incomplete * 10 < out.len(),
        "{incomplete} incomplete answers"
    );
    out
}

#[test]
fn closed_form_claims_are_confirmed_and_nothing_is_missed() {
    let (mut wide, mut total) = (0, 0);
    for (name, c) in cases() {
        let claimed: Vec<Vec<f64>> = c.truths.iter().map(|t| doubles(t)).collect();
        let r = verify(&claiming(&c.case, point_claim(&claimed, TOL)));
        let widths = truth_known(&name, &r, &c.truths);
        sound(&name, &r, &claimed, &c.truths, TOL);
        for (i, w) in widths.iter().enumerate() {
            let v = &r["claims"][i]["verdict"];
            if *w <= TOL / 2.0 {
                assert_eq!(v, "confirmed", "{name}: points[{i}]: {r}");
                assert!(r["claims"][i]["distance"].as_f64().unwrap() <= TOL);
            } else {
                assert_ne!(v, "refuted", "{name}: points[{i}]: {r}");
                wide += 1;
            }
            total += 1;
        }
        assert_eq!(r["missed"], json!([]), "{name}");
    }
    assert_rare("closed-form claims", wide, total);
}

#[test]
fn claims_by_parameters_are_confirmed() {
    let (mut wide, mut total) = (0, 0);
    for (name, c) in cases() {
        let Some(params) = &c.params else { continue };
        let points: Vec<Value> = params.iter().map(|p| json!({"params": p})).collect();
        let r = verify(&claiming(
            &c.case,
            json!({"points": points, "tolerance": TOL}),
        ));
        let widths = truth_known(&name, &r, &c.truths);
        for (i, w) in widths.iter().enumerate() {
            let v = &r["claims"][i]["verdict"];
            if *w <= TOL / 2.0 {
                assert_eq!(v, "confirmed", "{name}: points[{i}]: {r}");
            } else {
                assert_ne!(v, "refuted", "{name}: points[{i}]: {r}");
                wide += 1;
            }
            total += 1;
        }
        assert_eq!(r["missed"], json!([]), "{name}");
    }
    assert!(total >= 2 * 8 * count(20), "{total}");
    assert_rare("claims by parameters", wide, total);
}

#[test]
fn claims_moved_by_ten_tolerances_are_refuted_and_the_solutions_missed() {
    let mut rng = Rng::new(99);
    let (mut wide, mut total) = (0, 0);
    for (name, c) in cases() {
        let claimed: Vec<Vec<f64>> = c
            .truths
            .iter()
            .map(|t| {
                let w = unit(&mut rng, t.len());
                doubles(t)
                    .iter()
                    .zip(&w)
                    .map(|(x, w)| x + 10.0 * TOL * w)
                    .collect()
            })
            .collect();
        let r = verify(&claiming(&c.case, point_claim(&claimed, TOL)));
        let widths = truth_known(&name, &r, &c.truths);
        sound(&name, &r, &claimed, &c.truths, TOL);
        let mut narrow = 0;
        for (i, w) in widths.iter().enumerate() {
            let v = &r["claims"][i]["verdict"];
            if *w <= TOL {
                assert_eq!(v, "refuted", "{name}: points[{i}]: {r}");
                narrow += 1;
            } else {
                assert_ne!(v, "confirmed", "{name}: points[{i}]: {r}");
                wide += 1;
            }
            total += 1;
        }
        let missed = r["missed"].as_array().unwrap().len();
        assert!(missed >= narrow && missed <= c.truths.len(), "{name}: {r}");
    }
    assert_rare("moved claims", wide, total);
}

#[test]
fn a_claim_omitting_a_solution_lists_it_as_missed() {
    let mut rng = Rng::new(7);
    for (name, c) in cases() {
        let gone = rng.below(c.truths.len());
        let claimed: Vec<Vec<f64>> = (0..c.truths.len())
            .filter(|&j| j != gone)
            .map(|j| doubles(&c.truths[j]))
            .collect();
        let r = verify(&claiming(&c.case, point_claim(&claimed, TOL)));
        sound(&name, &r, &claimed, &c.truths, TOL);
        assert!(!verdicts(&r).iter().any(|v| v == "refuted"), "{name}: {r}");
        let missed = r["missed"].as_array().unwrap();
        assert_eq!(missed.len(), 1, "{name}: {r}");
        assert!(holds(&missed[0], &c.truths[gone]), "{name}: {r}");
    }
}

#[test]
fn geocert_s_own_answer_fed_back_is_confirmed() {
    for (name, c) in cases() {
        let mut own = solve(&c.case);
        own["tolerance"] = json!(TOL);
        let points = own["points"].as_array().unwrap().clone();
        let r = verify(&claiming(&c.case, own));
        // The record's `kind` is a claimed item too.
        assert_eq!(r["claims"][0]["item"], "kind");
        assert_eq!(r["claims"][0]["verdict"], "confirmed", "{name}: {r}");
        assert_eq!(verdicts(&r).len(), points.len() + 1, "{name}: {r}");
        for (i, p) in points.iter().enumerate() {
            let v = &r["claims"][i + 1]["verdict"];
            if diameter(p) <= TOL {
                assert_eq!(v, "confirmed", "{name}: points[{i}]: {r}");
            } else {
                assert_ne!(v, "refuted", "{name}: points[{i}]: {r}");
            }
        }
        assert_eq!(r["missed"], json!([]), "{name}");
    }
}

/// A double at or above the rational `q`.
fn up(q: &Rational) -> f64 {
    Float::with_val_round(53, q, Round::Up).0.to_f64()
}

/// Per solution, a claim just outside its certified box along a coordinate where the
/// box has width, with the tolerance the exact gap rounded up: the box is then
/// partly within and partly beyond the tolerance.
#[test]
fn claims_whose_box_straddles_the_tolerance_are_undecided_never_refuted() {
    let mut straddled = 0;
    for (name, c) in cases() {
        let own = solve(&c.case);
        for p in own["points"].as_array().unwrap() {
            let b: Vec<[f64; 2]> = p["box"]
                .as_array()
                .unwrap()
                .iter()
                .map(|x| [x[0].as_f64().unwrap(), x[1].as_f64().unwrap()])
                .collect();
            let Some(k) = (0..b.len()).find(|&k| b[k][0] < b[k][1]) else {
                continue;
            };
            if diameter(p) > TOL / 4.0 {
                continue;
            }
            let mut claim: Vec<f64> = b.iter().map(|[lo, hi]| lo + (hi - lo) / 2.0).collect();
            claim[k] = b[k][0] - TOL / 2.0;
            let gap = Rational::from_f64(b[k][0]).unwrap() - Rational::from_f64(claim[k]).unwrap();
            let tol = up(&gap);
            let r = verify(&claiming(&c.case, point_claim(&[claim.clone()], tol)));
            sound(&name, &r, &[claim], &c.truths, tol);
            assert_eq!(verdicts(&r), ["undecided"], "{name}: {r}");
            let reason = r["claims"][0]["reason"].as_str().unwrap();
            assert!(reason.contains("straddles"), "{name}: {reason}");
            straddled += 1;
        }
    }
    assert!(straddled >= 8 * count(20), "{straddled}");
}

/// Through the command line (`geocert verify`, README "Exit status"): a file of
/// confirmed curved claims exits 0; one moved claim among them sets bit 4 (disputed),
/// and its record says `refuted`.
#[test]
fn the_exit_status_says_whether_curved_claims_hold() {
    let mut rng = Rng::new(5);
    let mut good = vec![];
    for (_, family) in families() {
        let c = family(&mut rng);
        let claimed: Vec<Vec<f64>> = c.truths.iter().map(|t| doubles(t)).collect();
        good.push(claiming(&c.case, point_claim(&claimed, TOL)));
    }
    let text = |cases: &[Value]| -> String { cases.iter().map(|c| format!("{c}\n")).collect() };
    let out = cli_support::run("verify", &[], text(&good).as_bytes());
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stdout)
    );
    let mut bad = good.clone();
    let moved = &mut bad[3]["claim"]["points"][0]["xyz"][0];
    *moved = json!(moved.as_f64().unwrap() + 10.0 * TOL);
    let out = cli_support::run("verify", &[], text(&bad).as_bytes());
    assert_eq!(out.status.code(), Some(4));
    let records = cli_support::json_lines(&out);
    assert_eq!(
        records[3]["claims"][0]["verdict"], "refuted",
        "{}",
        records[3]
    );
    assert_eq!(records[3]["missed"].as_array().unwrap().len(), 1);
}
