//! `geocert verify`: certify or refute another program's answer (docs/FORMAT.md
//! "Claims"; docs/CERTIFICATES.md "Verifying another program's answer").
//!
//! This module only translates: the claim's JSON into a typed [`Claim`], the case into
//! shapes and its certified answer (solved with `options.exact`, so exact answers
//! carry their rationals), and the comparison of [`crate::ops::verify`] back into the
//! record's `claims` and `missed`.
//!
//! A claim is another program's output, so fields of the result format that do not
//! take part in the comparison (`box`, `multiplicity`, `status`, ...) are accepted and
//! ignored; a claim field that is not of the result format is an error.

use std::time::Instant;

use rug::Rational;
use serde::Deserialize;

use super::answer_out;
use super::build::shape;
use super::case::{Case, Op, ReadCase};
use super::de::deserialize_at;
use super::number::{Double, Num};
use super::result::{CaseResult, ClaimOut};
use super::solve::answer;
use crate::error::GeomError;
use crate::num::parse::parse_rational;
use crate::ops::verify::{verify, Claim, ClaimedArc, ClaimedPoint};
use crate::ops::Shape;

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct ClaimIn {
    kind: Option<String>,
    #[serde(default)]
    points: Vec<ClaimPoint>,
    tolerance: Option<Double>,
    /// A claimed shared arc: its ends `a` and `b`, points of the result format.
    arc: Option<ArcIn>,
    /// Claimed curves, lines, segments and rays: not yet checked (reported `undecided`).
    line: Option<serde_json::Value>,
    segment: Option<serde_json::Value>,
    ray: Option<serde_json::Value>,
    curves: Option<serde_json::Value>,
    // Result-format fields that take no part in the comparison.
    #[serde(default, rename = "id")]
    _id: serde::de::IgnoredAny,
    #[serde(default, rename = "format")]
    _format: serde::de::IgnoredAny,
    #[serde(default, rename = "status")]
    _status: serde::de::IgnoredAny,
    #[serde(default, rename = "complete")]
    _complete: serde::de::IgnoredAny,
    #[serde(default, rename = "bits")]
    _bits: serde::de::IgnoredAny,
    #[serde(default, rename = "arithmetic")]
    _arithmetic: serde::de::IgnoredAny,
    #[serde(default, rename = "micros")]
    _micros: serde::de::IgnoredAny,
    #[serde(default, rename = "reason")]
    _reason: serde::de::IgnoredAny,
    #[serde(default, rename = "perturbation")]
    _perturbation: serde::de::IgnoredAny,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct ClaimPoint {
    xyz: Option<Vec<Num>>,
    params: Option<Vec<Vec<Num>>>,
    /// Its `xyz`, when present, is the claimed point (exact values).
    exact: Option<ClaimExact>,
    #[serde(default, rename = "box")]
    _box: serde::de::IgnoredAny,
    #[serde(default, rename = "param_box")]
    _param_box: serde::de::IgnoredAny,
    #[serde(default, rename = "multiplicity")]
    _multiplicity: serde::de::IgnoredAny,
    #[serde(default, rename = "tangent")]
    _tangent: serde::de::IgnoredAny,
    #[serde(default, rename = "distance")]
    _distance: serde::de::IgnoredAny,
    #[serde(default, rename = "signed_distance")]
    _signed_distance: serde::de::IgnoredAny,
    #[serde(default, rename = "nearest")]
    _nearest: serde::de::IgnoredAny,
    #[serde(default, rename = "region")]
    _region: serde::de::IgnoredAny,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct ArcIn {
    a: ClaimPoint,
    b: ClaimPoint,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct ClaimExact {
    xyz: Option<Vec<Num>>,
    /// Read for the ends of a claimed arc (their exact parameters on both curves).
    params: Option<Vec<Vec<Num>>>,
    #[serde(default, rename = "distance_squared")]
    _distance_squared: serde::de::IgnoredAny,
}

/// Verify one case that carries a `claim`.
pub fn verify_case(read: ReadCase) -> CaseResult {
    let start = Instant::now();
    let ReadCase { id, case } = read;
    let mut case = match case {
        Ok(c) => c,
        Err(e) => return CaseResult::error(id, &e),
    };
    let Some(claim_value) = case.claim.take() else {
        let e = GeomError::Format {
            field: "claim".into(),
            message: "`verify` needs a `claim` (the answer to check)".into(),
        };
        return CaseResult::error(case.id, &e);
    };
    let claim = match read_claim(claim_value, case.options.equal_tolerance) {
        Ok(c) => c,
        Err(e) => return CaseResult::error(case.id, &e),
    };
    let keep_exact = case.options.exact;
    case.options.exact = true;
    // The checks' budget: the case's, its time limit counted from here.
    let budget = match super::solve::options(&case) {
        Ok(o) => o.started(),
        Err(e) => return CaseResult::error(case.id.clone(), &e),
    };
    let solved = answer(&case).and_then(|truth| objects(&case).map(|shapes| (shapes, truth)));
    let (shapes, mut truth) = match solved {
        Ok(t) => t,
        Err(e) => return CaseResult::error(case.id.clone(), &e),
    };
    if let Err(e) = dimensions(&claim, &shapes) {
        return CaseResult::error(case.id.clone(), &e);
    }
    let checked = verify(&truth, &shapes, &claim, &budget);
    if !keep_exact {
        crate::ops::beyond_range::keep_exact_beyond_range(&mut truth.value);
    }
    let mut record = answer_out::result(case.id.clone(), &truth);
    record.missed = Some(checked.missed.iter().map(answer_out::point).collect());
    record.claims = Some(
        checked
            .items
            .into_iter()
            .map(|v| ClaimOut {
                item: v.item,
                verdict: v.verdict.as_str(),
                status: v.status.as_str(),
                distance: v.distance,
                reason: v.reason,
            })
            .collect(),
    );
    record.micros = Some(start.elapsed().as_micros() as u64);
    record
}

/// A claimed point by coordinates has as many as the case's points (2 for plane
/// objects, else 3): a claim of the wrong dimension is malformed, not refuted.
fn dimensions(claim: &Claim, shapes: &[Shape]) -> Result<(), GeomError> {
    let dim = if !shapes.is_empty() && shapes.iter().all(Shape::is_2d) {
        2
    } else {
        3
    };
    let points = claim
        .points
        .iter()
        .enumerate()
        .map(|(i, p)| (format!("claim.points[{i}]"), p));
    let ends = claim.arc.iter().flat_map(|a| {
        a.ends
            .iter()
            .zip(["a", "b"])
            .map(|(p, k)| (format!("claim.arc.{k}"), p))
    });
    for (field, p) in points.chain(ends) {
        if let ClaimedPoint::Xyz(v) = p {
            if v.len() != dim {
                return Err(GeomError::CountMismatch {
                    field: format!("{field}.xyz"),
                    expected: format!("{dim} coordinates (the case's objects are {dim}D)"),
                    found: v.len().to_string(),
                });
            }
        }
    }
    Ok(())
}

/// The objects a claim's `params` refer to: the operands of `intersect`, the `onto` of
/// `project`, the `shell` of `classify`.
fn objects(case: &Case) -> Result<Vec<Shape>, GeomError> {
    match case.op {
        Op::Project => case.onto.iter().map(|o| shape(o, "onto")).collect(),
        Op::Classify => case.shell.iter().map(|s| shape(s, "shell")).collect(),
        _ => case
            .objects
            .iter()
            .enumerate()
            .map(|(i, s)| shape(s, &format!("objects[{i}]")))
            .collect(),
    }
}

fn number(n: &Num, field: String) -> Result<Rational, GeomError> {
    match n {
        Num::Double(v) => Ok(Rational::from_f64(*v).unwrap_or_default()),
        Num::Text(t) => parse_rational(&field, t),
    }
}

/// A coordinate beyond the double range, as results write it (docs/FORMAT.md
/// "Numbers beyond the double range").
fn is_infinite(n: &Num) -> bool {
    matches!(n, Num::Text(t) if t == "inf" || t == "-inf")
}

fn numbers(v: &[Num], field: &str) -> Result<Vec<Rational>, GeomError> {
    v.iter()
        .enumerate()
        .map(|(k, n)| number(n, format!("{field}[{k}]")))
        .collect()
}

/// One claimed point: its `exact.xyz` when present (the exact values a result carries,
/// needed where `xyz` holds `"inf"`), else `xyz`, else `params`.
fn claimed_point(p: &ClaimPoint, f: &str) -> Result<ClaimedPoint, GeomError> {
    if let Some(e) = p.exact.as_ref().and_then(|e| e.xyz.as_ref()) {
        return Ok(ClaimedPoint::Xyz(numbers(e, &format!("{f}.exact.xyz"))?));
    }
    if let Some(xyz) = &p.xyz {
        if xyz.iter().any(is_infinite) {
            return Err(GeomError::Format {
                field: format!("{f}.xyz"),
                message: "a coordinate written \"inf\" needs the exact value in `exact.xyz`".into(),
            });
        }
        return Ok(ClaimedPoint::Xyz(numbers(xyz, &format!("{f}.xyz"))?));
    }
    if let Some(params) = &p.params {
        let v = params
            .iter()
            .enumerate()
            .map(|(j, ps)| numbers(ps, &format!("{f}.params[{j}]")))
            .collect::<Result<_, _>>()?;
        return Ok(ClaimedPoint::Params(v));
    }
    Err(GeomError::Format {
        field: f.to_string(),
        message: "a claimed point needs `xyz` or `params`".into(),
    })
}

/// The exact parameters of a claimed arc's end on every object: `exact.params`, else
/// `params`.
fn end_params(p: &ClaimPoint, f: &str) -> Result<Option<Vec<Vec<Rational>>>, GeomError> {
    let (given, field) = match p.exact.as_ref().and_then(|e| e.params.as_ref()) {
        Some(e) => (e, format!("{f}.exact.params")),
        None => match &p.params {
            Some(ps) => (ps, format!("{f}.params")),
            None => return Ok(None),
        },
    };
    let v = given
        .iter()
        .enumerate()
        .map(|(j, ps)| numbers(ps, &format!("{field}[{j}]")))
        .collect::<Result<_, _>>()?;
    Ok(Some(v))
}

fn claimed_arc(arc: &ArcIn) -> Result<ClaimedArc, GeomError> {
    let (a, b) = (&arc.a, &arc.b);
    Ok(ClaimedArc {
        ends: [
            claimed_point(a, "claim.arc.a")?,
            claimed_point(b, "claim.arc.b")?,
        ],
        params: [end_params(a, "claim.arc.a")?, end_params(b, "claim.arc.b")?],
    })
}

fn read_claim(value: serde_json::Value, fallback: Option<Double>) -> Result<Claim, GeomError> {
    let claim: ClaimIn = deserialize_at(value, "claim")?;
    let tolerance = claim.tolerance.or(fallback).map(|d| d.0).unwrap_or(0.0);
    // NaN is not a tolerance either.
    let valid = tolerance >= 0.0;
    if !valid {
        return Err(GeomError::InvalidValue {
            field: "claim.tolerance".into(),
            reason: format!("a tolerance must be ≥ 0, found {tolerance}"),
        });
    }
    let points = claim
        .points
        .iter()
        .enumerate()
        .map(|(i, p)| claimed_point(p, &format!("claim.points[{i}]")))
        .collect::<Result<_, _>>()?;
    let unchecked = [
        ("line", claim.line.is_some()),
        ("segment", claim.segment.is_some()),
        ("ray", claim.ray.is_some()),
        ("curves", claim.curves.is_some()),
    ]
    .into_iter()
    .filter(|(_, present)| *present)
    .map(|(name, _)| name.to_string())
    .collect();
    let arc = claim.arc.as_ref().map(claimed_arc).transpose()?;
    Ok(Claim {
        kind: claim.kind,
        points,
        arc,
        tolerance: Rational::from_f64(tolerance).unwrap_or_default(),
        unchecked,
    })
}
