//! Certified curve ∩ surface on NURBS surfaces against independent truths (issue 21,
//! families 3 and 4; the plane-curve families are in tests/curved_forms.rs):
//!
//! * the graph `z = x² + y²` over `[−1, 1]²` as a polynomial NURBS of degree (2, 2)
//!   with the interior knot `1/2` in both directions (control abscissae the Greville
//!   points `−1, −1/2, 1/2, 1`; heights `a_i + a_j`, `a = (1, 0, 0, 1)`, the knot
//!   insertion of the Bézier form `(1, −1, 1)` of `x²`): lines along `(1, 1, 0)` at
//!   height `z₀` are tangent to it at `z₀ = (x₀ − y₀)²/2`, and are tested at gaps
//!   `10^-k`, `3 ≤ k ≤ 15`, on both sides.
//!
//! (Vertical lines through the graph, whose truth is the exact `z = x₀² + y₀²`, are
//! not here: on the knot line `x = 0` the answer is undecided at the 512-bit cap after
//! 5 s, and even at a generic point one case ran beyond 40 s; reported to the lead.)
//!
//! Truths are closed forms in MPFR at 1024 bits, parameters by the inverse maps
//! (`u = (x + 1)/2`; on the circle `s = y/(1 + x)`); every answer must be complete,
//! boxes one-to-one with the truths, containment strict. Near tangency the answer must
//! be two verified points, one singular box holding both, or a proven miss (nothing,
//! or one singular box) — with a `perturbation` never below the closed-form least
//! shift of the line that makes it tangent.

mod truth_support;

use geocert::io::CaseResult;
use rug::Float;
use truth_support::*;

/// The graph `z = S·((x/S)² + (y/S)²)` over `[−S, S]²` as a NURBS surface.
fn graph(scale: f64) -> String {
    let xs = [-1.0, -0.5, 0.5, 1.0];
    let a = [1.0, 0.0, 0.0, 1.0];
    let rows: Vec<String> = (0..4)
        .map(|i| {
            let row: Vec<String> = (0..4)
                .map(|j| nums(&[xs[j] * scale, xs[i] * scale, (a[i] + a[j]) * scale]))
                .collect();
            format!("[{}]", row.join(","))
        })
        .collect();
    let knots = "[0,0,0,0.5,1,1,1]";
    format!(
        r#"{{"type":"nurbs_surface","degree_u":2,"degree_v":2,"knots_u":{knots},"knots_v":{knots},"points":[{}]}}"#,
        rows.join(",")
    )
}

fn line(o: [f64; 3], d: [f64; 3], range: f64) -> String {
    format!(
        r#"{{"type":"line","origin":{},"dir":{},"range":{}}}"#,
        nums(&o),
        nums(&d),
        nums(&[-range, range])
    )
}

fn intersect(a: &str, b: &str) -> (String, CaseResult) {
    let case = format!(r#"{{"id":0,"op":"intersect","objects":[{a},{b}]}}"#);
    let r = solve(&case);
    (case, r)
}

/// A dyadic `k/2^bits` in `[lo, hi]` from the project's generator.
fn dyadic(g: &mut geocert::num::rng::Rng, lo: f64, hi: f64, bits: i32) -> f64 {
    let s = 2f64.powi(bits);
    g.int((lo * s).ceil() as i64, (hi * s).floor() as i64) as f64 / s
}

/// The line `(x₀, y₀, z₀) + t(1, 1, 0)` against the graph: `2t² + 2(x₀ + y₀)t + x₀² +
/// y₀² − z₀ = 0`, tangent at `z₀ = (x₀ − y₀)²/2`; the least shift of the line (along z,
/// or along x or y, which moves the lowest height) that makes it tangent.
fn diagonal_truth(o: [f64; 3]) -> (Vec<[Float; 4]>, Float) {
    let (x0, y0, z0) = (fl(o[0]), fl(o[1]), fl(o[2]));
    let b = Float::with_val(BITS, &x0 + &y0);
    let c = Float::with_val(BITS, x0.square_ref()) + Float::with_val(BITS, y0.square_ref()) - &z0;
    // t = (−b ± √(b² − 2c))/2
    let disc = Float::with_val(BITS, b.square_ref()) - Float::with_val(BITS, &c * 2u32);
    let mut out = Vec::new();
    if disc >= 0 {
        let h = disc.clone().sqrt();
        for sign in [-1i32, 1] {
            let t = (Float::with_val(BITS, -&b) + Float::with_val(BITS, &h * sign)) / 2u32;
            let x = Float::with_val(BITS, &x0 + &t);
            let y = Float::with_val(BITS, &y0 + &t);
            out.push([t, x, y, z0.clone()]);
            if disc == 0 {
                break;
            }
        }
    }
    let diff = Float::with_val(BITS, &x0 - &y0);
    let low = Float::with_val(BITS, diff.square_ref()) / 2u32;
    let mut least = Float::with_val(BITS, &z0 - &low).abs();
    if z0 >= 0 {
        let w = Float::with_val(BITS, &z0 * 2u32).sqrt();
        for s in [-1i32, 1] {
            let e = (Float::with_val(BITS, &w * s) - &diff).abs();
            least = least.min(&e);
        }
    }
    (out, least)
}

/// The near-tangency verdict: complete; two verified points one-to-one with the
/// truths, one singular box holding all of them, or (no truth) nothing or one singular
/// box; a stated perturbation never below `least`.
fn tangency_verdict(r: &CaseResult, truths: &[Vec<Float>], least: &Float) -> Result<(), String> {
    if r.complete != Some(true) {
        return Err(format!("not complete: {:?}", r.reason));
    }
    if let Some(e) = r.perturbation {
        if *least > e {
            return Err(format!("perturbation {e:e} below the least {least:.6e}"));
        }
    }
    let boxes = point_boxes(r);
    match r.status {
        "verified" => one_to_one(&boxes, truths),
        "verified_singular" if boxes.len() == 1 => {
            if truths.iter().all(|t| box_holds(&boxes[0], t)) {
                Ok(())
            } else {
                Err("a singular box misses a true point".into())
            }
        }
        other => Err(format!("status {other} with {} boxes", boxes.len())),
    }
}

/// Lines along `(1, 1, 0)` at gaps `10^-k` (3 ≤ k ≤ 15) above and below tangency with
/// the NURBS graph, tangent points off the knot lines.
#[test]
fn diagonal_lines_near_tangency_with_the_nurbs_graph() {
    let mut g = geocert::num::rng::Rng::new(2104);
    for i in 0..cases(26) {
        let x0 = dyadic(&mut g, -0.5, 0.5, 6);
        let y0 = dyadic(&mut g, -0.5, 0.5, 6);
        if x0 == y0 {
            continue; // the tangent point would sit on both knot lines
        }
        let k = 3 + (i as i32 % 13);
        let gap = 10f64.powi(-k) * if g.coin() { 1.0 } else { -1.0 };
        let z0 = (x0 - y0) * (x0 - y0) / 2.0 + gap;
        let o = [x0, y0, z0];
        let (truths, least) = diagonal_truth(o);
        let pts: Vec<Vec<Float>> = truths
            .iter()
            .map(|t| vec![t[1].clone(), t[2].clone(), t[3].clone()])
            .collect();
        let (case, r) = intersect(&line(o, [1.0, 1.0, 0.0], 2.0), &graph(1.0));
        if let Err(e) = tangency_verdict(&r, &pts, &least) {
            panic!("{e}\n{case}\n{r:?}");
        }
    }
}
