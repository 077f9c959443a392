//! Independent truths for the curved tests (issue 21): cases solved in process through
//! the case format (`geocert::io`), truths computed in MPFR far beyond any proof's
//! precision, and the checks a strict reviewer asks for — strict containment of a
//! truth in a box (no slack), one box per truth and one truth per box.
#![allow(dead_code)]

pub mod conics;

use geocert::io::{read_cases, solve_case, CaseResult};
use rug::Float;

/// The precision of the truths: far above any precision a proof here uses (the
/// certifier escalates to a few hundred bits), so a truth is a point for every box.
pub const BITS: u32 = 1024;

/// A double (or any exact value) as a truth-precision float.
pub fn fl<T>(v: T) -> Float
where
    Float: rug::Assign<T>,
{
    Float::with_val(BITS, v)
}

/// Solve one case given as JSON text, in process.
pub fn solve(case: &str) -> CaseResult {
    if std::env::var_os("GEOCERT_TRACE").is_some() {
        eprintln!("solve {case}");
    }
    let mut read = read_cases(case);
    assert_eq!(read.len(), 1, "one case: {case}");
    solve_case(read.remove(0))
}

/// Solve one JSON case through the library front door (`ops::project` /
/// `ops::intersect` on shapes built by `io::shape`), as a library user would.
pub fn front_door(json: &str) -> geocert::Certified<geocert::ops::Answer> {
    use geocert::io::{options, position, shape};
    use geocert::ops::{self, ProjectOptions};
    let read = read_cases(json).pop().expect("one case");
    let case = read.case.expect("a valid case");
    let options = options(&case).expect("options");
    if let Some(p) = &case.point {
        let how = ProjectOptions {
            nearest: case.nearest,
            direction: None,
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

/// `CASES` scaled by `GEOCERT_CURVED_CASES` (a multiplier for long local runs; the
/// default 1 keeps each family within its share of the suite's time).
pub fn cases(default: usize) -> usize {
    let k: usize = std::env::var("GEOCERT_CURVED_CASES")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(1);
    default * k.max(1)
}

/// True if `lo ≤ x ≤ hi` exactly (doubles compared with the MPFR value, no slack).
pub fn holds(b: &[f64; 2], x: &Float) -> bool {
    *x >= b[0] && *x <= b[1]
}

/// True if every coordinate of `point` lies in the box.
pub fn box_holds(bx: &[[f64; 2]], point: &[Float]) -> bool {
    bx.len() == point.len() && bx.iter().zip(point).all(|(b, x)| holds(b, x))
}

/// Every box holds exactly one of the truths (`Err` names the first box that does not).
fn each_box_holds_one_truth(boxes: &[Vec<[f64; 2]>], truths: &[Vec<Float>]) -> Result<(), String> {
    for (i, b) in boxes.iter().enumerate() {
        let k = truths.iter().filter(|t| box_holds(b, t)).count();
        if k != 1 {
            return Err(format!("box {i} {b:?} holds {k} truths"));
        }
    }
    Ok(())
}

/// One box per truth and one truth per box: every box holds exactly one of the truths,
/// and every truth lies in exactly one box. `Err` says which failed.
pub fn one_to_one(boxes: &[Vec<[f64; 2]>], truths: &[Vec<Float>]) -> Result<(), String> {
    if boxes.len() != truths.len() {
        return Err(format!("{} boxes for {} truths", boxes.len(), truths.len()));
    }
    each_box_holds_one_truth(boxes, truths)?;
    for (i, t) in truths.iter().enumerate() {
        let k = boxes.iter().filter(|b| box_holds(b, t)).count();
        if k != 1 {
            return Err(format!("truth {i} ({}) in {k} boxes", show(t)));
        }
    }
    Ok(())
}

/// What an answer left incomplete by its box budget must still get right: it is not
/// `exact`, every reported box holds exactly one truth, and, when the answer is
/// `verified`, no truth lies in two boxes (a root reported twice, a seam copy). Truths may be missing from the boxes: their
/// part of the domain is among the undecided boxes the reason counts.
#[allow(dead_code)]
pub fn sound_but_incomplete(
    r: &CaseResult,
    boxes: &[Vec<[f64; 2]>],
    truths: &[Vec<Float>],
) -> Result<(), String> {
    if r.complete != Some(false) || r.status == "exact" {
        return Err(format!("complete {:?}, status {}", r.complete, r.status));
    }
    each_box_holds_one_truth(boxes, truths)?;
    // An `undecided` answer certifies none of its points one by one (an undecided
    // root may be the copy of a proven one); a `verified` one certifies each.
    for (i, t) in truths.iter().enumerate() {
        let k = boxes.iter().filter(|b| box_holds(b, t)).count();
        if k > 1 && r.status != "undecided" {
            return Err(format!("truth {i} ({}) in {k} boxes", show(t)));
        }
    }
    Ok(())
}

/// The answer is honestly incomplete at a knot point: it spent its box budget, or it is
/// `undecided` because a root box straddles a knot its across proof could not decide
/// (the NURBS circle's knot on a sphere's seam at 2^±500, issue 21). Either must still
/// be [`sound_but_incomplete`].
#[allow(dead_code)]
pub fn incomplete_at_a_knot(r: &CaseResult) -> bool {
    budget_spent(r)
        || (r.complete == Some(false)
            && r.status == "undecided"
            && r.reason
                .as_deref()
                .is_some_and(|s| s.contains("straddles the domain boundary")))
}

/// The answer stopped on its box budget (the reason says so), not on anything else.
#[allow(dead_code)]
pub fn budget_spent(r: &CaseResult) -> bool {
    r.complete == Some(false)
        && r.reason
            .as_deref()
            .is_some_and(|s| s.contains("box budget spent"))
}

/// A truth point, short.
pub fn show(t: &[Float]) -> String {
    let parts: Vec<String> = t.iter().map(|x| format!("{:.20e}", x.to_f64())).collect();
    format!("({})", parts.join(", "))
}

/// The `box` of every reported point.
pub fn point_boxes(r: &CaseResult) -> Vec<Vec<[f64; 2]>> {
    r.points
        .iter()
        .flatten()
        .map(|p| p.bounds.clone())
        .collect()
}

/// The `param_box` of object `k` of every reported point.
pub fn param_boxes(r: &CaseResult, k: usize) -> Vec<Vec<[f64; 2]>> {
    r.points
        .iter()
        .flatten()
        .map(|p| p.param_box.as_ref().expect("param_box")[k].clone())
        .collect()
}

/// The number of reported points.
pub fn count(r: &CaseResult) -> usize {
    r.points.as_ref().map_or(0, Vec::len)
}

/// `√x` of a truth.
pub fn sqrt(x: Float) -> Float {
    x.sqrt()
}

/// A number for the case format: the shortest text that reads back to the same double.
pub fn num(x: f64) -> String {
    let v = serde_json::to_value(x).expect("finite");
    v.to_string()
}

/// A list of doubles for the case format.
pub fn nums(xs: &[f64]) -> String {
    let parts: Vec<String> = xs.iter().map(|&x| num(x)).collect();
    format!("[{}]", parts.join(","))
}

/// The docs/FORMAT.md frame of an analytic object at `bits` (`[X, Y, Z]`): Z the unit
/// axis, X the reference (or the coordinate vector least aligned with Z, first on
/// ties) made orthogonal to Z and unit, Y = Z × X.
pub fn docs_frame(axis: [f64; 3], reference: Option<[f64; 3]>, bits: u32) -> [[Float; 3]; 3] {
    let f = |x: f64| Float::with_val(bits, x);
    let dot =
        |a: &[Float], b: &[Float]| a.iter().zip(b).fold(f(0.0), |s, (x, y)| s + x.clone() * y);
    let a: [Float; 3] = axis.map(f);
    let len = dot(&a, &a).sqrt();
    let z: [Float; 3] = std::array::from_fn(|i| a[i].clone() / &len);
    let e = reference.unwrap_or_else(|| {
        let mut k = 0;
        for i in 1..3 {
            if axis[i].abs() < axis[k].abs() {
                k = i;
            }
        }
        std::array::from_fn(|i| if i == k { 1.0 } else { 0.0 })
    });
    let e: [Float; 3] = e.map(f);
    let ez = dot(&e, &z);
    let w: [Float; 3] = std::array::from_fn(|i| e[i].clone() - ez.clone() * &z[i]);
    let wl = dot(&w, &w).sqrt();
    let x: [Float; 3] = std::array::from_fn(|i| w[i].clone() / &wl);
    let y: [Float; 3] = std::array::from_fn(|i| {
        let (j, k) = ((i + 1) % 3, (i + 2) % 3);
        z[j].clone() * &x[k] - z[k].clone() * &x[j]
    });
    [x, y, z]
}

/// A truth computed at `BITS` from data that make it a double exactly (a root placed on
/// a knot or at the end of a patch) carries a rounding error near `2^-BITS`; snapped
/// to the double it is within `2^-900` (relative) of, or to 0 below `2^-900` (every
/// scale used here is above `2^-600`). An irrational truth is that close to a double
/// with probability about `2^-847`, so the snap only undoes rounding.
pub fn snap(x: &Float) -> Float {
    let d = x.to_f64();
    if !d.is_finite() {
        return x.clone();
    }
    let tiny = Float::with_val(BITS, 1u32) >> 900u32;
    if x.clone().abs() < tiny {
        return fl(0.0);
    }
    let err = Float::with_val(BITS, x - d).abs();
    if err <= Float::with_val(BITS, x.clone().abs() >> 900u32) {
        fl(d)
    } else {
        x.clone()
    }
}

/// Every coordinate of every truth snapped ([`snap`]).
pub fn snap_all(ts: Vec<Vec<Float>>) -> Vec<Vec<Float>> {
    ts.into_iter()
        .map(|t| t.iter().map(snap).collect())
        .collect()
}

/// Failed cases of a family, gathered so that one run shows them all.
#[derive(Default)]
pub struct Failures(pub Vec<String>);

impl Failures {
    /// Record a failed check with its case and result.
    pub fn check(&mut self, result: Result<(), String>, case: &str, r: &CaseResult) {
        if let Err(e) = result {
            let id = case
                .find("\"id\":")
                .map_or("", |k| &case[k..(k + 9).min(case.len())]);
            eprintln!("FAIL {id} {}", e.lines().next().unwrap_or(""));
            self.0.push(format!("{e}\ncase: {case}\nresult: {r:?}"));
        }
    }

    /// Panic listing the failures (the first three in full), if any.
    pub fn finish(self, family: &str) {
        if !self.0.is_empty() {
            let first: Vec<&str> = self.0.iter().take(3).map(String::as_str).collect();
            let all: Vec<String> = self
                .0
                .iter()
                .map(|f| {
                    let id = f
                        .find("\"id\":")
                        .map_or("", |k| &f[k..(k + 9).min(f.len())]);
                    format!("{id} {}", f.lines().next().unwrap_or(""))
                })
                .collect();
            panic!(
                "{family}: {} failed cases\n{}\n===\n{}",
                self.0.len(),
                all.join("\n"),
                first.join("\n---\n")
            );
        }
    }
}

/// Defects of src/ that families here expose, left out of the default run by name
/// (they run with `GEOCERT_KNOWN_DEFECTS=1`); remove a name when its fix is merged.
pub const KNOWN_DEFECTS: &[&str] = &[
    // Lines parallel to the axis against the NURBS ring torus of tests/rational_patches.rs
    // (two transversal crossings), scaled by 2^-500: case 3 of
    // `axial_lines_across_a_nurbs_torus` ends undecided, "precision cap of 512 bits
    // reached" (two boxes). The other scales are decided since the Bézier-hull
    // enclosures of wide boxes (before them a third of the cases spent the box budget).
    "nurbs_torus_axial_lines_tiny",
    // Projection onto the NURBS sphere restricted to v ∈ [1/4, 7/4]: runs over a minute
    // per family. Split into knot rectangles it took seconds, but feet on the equator
    // knot `v = 1` (u irrational) stayed undecided, as above.
    "nurbs_sphere_zone_projection",
];

/// True if cases of the family `defect` run: not a known defect, or
/// `GEOCERT_KNOWN_DEFECTS` asks for them.
pub fn runs(defect: Option<&str>) -> bool {
    !defect.is_some_and(|d| KNOWN_DEFECTS.contains(&d))
        || std::env::var_os("GEOCERT_KNOWN_DEFECTS").is_some()
}

/// The point at `t` of the rational Bézier curve of plane control points `ctrl` and
/// weights `w`, by de Casteljau on the homogeneous points in MPFR (not the power basis
/// the library builds its polynomials in).
#[allow(dead_code)]
pub fn bezier2_at(ctrl: &[[f64; 2]], w: &[f64], t: &Float) -> [Float; 2] {
    let mut h: Vec<[Float; 3]> = ctrl
        .iter()
        .zip(w)
        .map(|(p, &wi)| [fl(p[0]) * wi, fl(p[1]) * wi, fl(wi)])
        .collect();
    let u = fl(1) - t;
    while h.len() > 1 {
        h = h
            .windows(2)
            .map(|ab| std::array::from_fn(|k| ab[0][k].clone() * &u + ab[1][k].clone() * t))
            .collect();
    }
    let [x, y, wt] = h.remove(0);
    [x / &wt, y / wt]
}
