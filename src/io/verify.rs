//! `geocert verify`: certify or refute another program's answer (docs/FORMAT.md
//! "Claims"; docs/CERTIFICATES.md "Verifying another program's answer").
//!
//! The case is solved exactly (`options.exact`, so every reported point carries its
//! exact rationals), and each claimed item is compared with the truth in exact
//! arithmetic: a claimed point is `confirmed` when some true solution lies within the
//! tolerance of it (Euclidean distance of `xyz`, or of the parameters on each object
//! when `xyz` is absent), `refuted` when none does — a proof, since every solution of
//! the exact input is known. `missed` lists the true solutions no claimed point is
//! within the tolerance of. A claimed `kind` (`empty`, `inside`, ...) is compared
//! with the true kind. Answers that are not finite point sets (a line, a segment, a
//! plane) make point claims `undecided` with the reason, and so do true points known
//! only by their certified boxes (numerically certified answers carry no exact values):
//! they are neither matched nor listed as `missed`.
//!
//! A claim is another program's output, so fields of the result format that do not
//! take part in the comparison (`box`, `multiplicity`, `status`, ...) are accepted and
//! ignored; a claim field that is not of the result format is an error.

use rug::Rational;
use serde::Deserialize;

use super::case::ReadCase;
use super::de::deserialize_at;
use super::number::{Double, Num};
use super::result::{CaseResult, ClaimOut, PointOut};
use super::solve::solve_case;
use crate::error::GeomError;
use crate::num::parse::parse_rational;
use crate::num::round::sqrt_rational;

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct Claim {
    kind: Option<String>,
    #[serde(default)]
    points: Vec<ClaimPoint>,
    tolerance: Option<Double>,
    /// Claimed curves, lines and segments: not yet checked (reported `undecided`).
    line: Option<serde_json::Value>,
    segment: Option<serde_json::Value>,
    curves: Option<serde_json::Value>,
    // Result-format fields that take no part in the comparison.
    #[serde(default, rename = "id")]
    _id: serde::de::IgnoredAny,
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
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct ClaimPoint {
    xyz: Option<Vec<Num>>,
    params: Option<Vec<Vec<Num>>>,
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
    #[serde(default, rename = "exact")]
    _exact: serde::de::IgnoredAny,
}

/// A claimed point in exact numbers: coordinates, or parameters per object.
enum Where {
    Xyz(Vec<Rational>),
    Params(Vec<Vec<Rational>>),
}

/// Verify one case that carries a `claim`.
pub fn verify_case(read: ReadCase) -> CaseResult {
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
    let id = case.id.clone();
    let mut truth = solve_case(ReadCase {
        id: id.clone(),
        case: Ok(case),
    });
    if truth.error.is_some() {
        return truth;
    }
    match compare(&truth, &claim) {
        Ok((claims, missed)) => {
            truth.claims = Some(claims);
            truth.missed = Some(missed);
        }
        Err(e) => return CaseResult::error(id, &e),
    }
    if !keep_exact {
        for p in truth.points.iter_mut().flatten() {
            p.exact = None;
        }
        for p in truth.missed.iter_mut().flatten() {
            p.exact = None;
        }
    }
    truth
}

struct ReadClaim {
    kind: Option<String>,
    /// Claimed items that are not points (`line`, `segment`, `curves`).
    unchecked: Vec<&'static str>,
    points: Vec<Where>,
    tolerance: Rational,
}

fn read_claim(value: serde_json::Value, fallback: Option<Double>) -> Result<ReadClaim, GeomError> {
    let claim: Claim = deserialize_at(value, "claim")?;
    let tolerance = claim.tolerance.or(fallback).map(|d| d.0).unwrap_or(0.0);
    // NaN is not a tolerance either.
    let valid = tolerance >= 0.0;
    if !valid {
        return Err(GeomError::InvalidValue {
            field: "claim.tolerance".into(),
            reason: format!("a tolerance must be ≥ 0, found {tolerance}"),
        });
    }
    let num = |n: &Num, field: String| match n {
        Num::Double(v) => Ok(Rational::from_f64(*v).unwrap_or_default()),
        Num::Text(t) => parse_rational(&field, t),
    };
    let points = claim
        .points
        .iter()
        .enumerate()
        .map(|(i, p)| {
            let f = format!("claim.points[{i}]");
            if let Some(xyz) = &p.xyz {
                let v = xyz
                    .iter()
                    .enumerate()
                    .map(|(k, n)| num(n, format!("{f}.xyz[{k}]")))
                    .collect::<Result<_, _>>()?;
                Ok(Where::Xyz(v))
            } else if let Some(params) = &p.params {
                let v = params
                    .iter()
                    .enumerate()
                    .map(|(j, ps)| {
                        ps.iter()
                            .enumerate()
                            .map(|(k, n)| num(n, format!("{f}.params[{j}][{k}]")))
                            .collect::<Result<Vec<_>, _>>()
                    })
                    .collect::<Result<_, _>>()?;
                Ok(Where::Params(v))
            } else {
                Err(GeomError::Format {
                    field: f,
                    message: "a claimed point needs `xyz` or `params`".into(),
                })
            }
        })
        .collect::<Result<_, _>>()?;
    let unchecked = [
        ("line", claim.line.is_some()),
        ("segment", claim.segment.is_some()),
        ("curves", claim.curves.is_some()),
    ]
    .into_iter()
    .filter_map(|(name, present)| present.then_some(name))
    .collect();
    Ok(ReadClaim {
        kind: claim.kind,
        unchecked,
        points,
        tolerance: Rational::from_f64(tolerance).unwrap_or_default(),
    })
}

fn exact_vec(texts: &[String]) -> Result<Vec<Rational>, GeomError> {
    texts.iter().map(|t| parse_rational("exact", t)).collect()
}

/// Squared distance between a claimed point and a true one, or `None` when the two
/// are not comparable (dimension or parameter layout differ).
fn distance2(claimed: &Where, truth: &PointOut) -> Result<Option<Rational>, GeomError> {
    let Some(exact) = &truth.exact else {
        return Ok(None);
    };
    let d2 = |a: &[Rational], b: &[Rational]| -> Option<Rational> {
        (a.len() == b.len()).then(|| {
            a.iter()
                .zip(b)
                .map(|(x, y)| {
                    let d = Rational::from(x - y);
                    d.clone() * d
                })
                .sum()
        })
    };
    match claimed {
        Where::Xyz(c) => Ok(d2(c, &exact_vec(&exact.xyz)?)),
        Where::Params(c) => {
            if c.len() != exact.params.len() {
                return Ok(None);
            }
            let mut total = Rational::new();
            for (a, b) in c.iter().zip(&exact.params) {
                match d2(a, &exact_vec(b)?) {
                    Some(d) => total += d,
                    None => return Ok(None),
                }
            }
            Ok(Some(total))
        }
    }
}

fn compare(
    truth: &CaseResult,
    claim: &ReadClaim,
) -> Result<(Vec<ClaimOut>, Vec<PointOut>), GeomError> {
    let kind = truth.kind.unwrap_or("");
    let status = truth.status;
    let tol2 = claim.tolerance.clone() * &claim.tolerance;
    let mut claims = vec![];
    if let Some(k) = &claim.kind {
        let same = k == kind;
        let decided = truth.complete == Some(true) && status != "undecided";
        claims.push(ClaimOut {
            item: "kind".into(),
            verdict: match (same, decided) {
                (_, false) => "undecided",
                (true, true) => "confirmed",
                (false, true) => "refuted",
            },
            status,
            distance: None,
            reason: (!same).then(|| format!("the answer is `{kind}`")),
        });
    }
    for item in &claim.unchecked {
        claims.push(ClaimOut {
            item: item.to_string(),
            verdict: "undecided",
            status: "undecided",
            distance: None,
            reason: Some(format!(
                "checking a claimed `{item}` is not implemented yet"
            )),
        });
    }
    let true_points: &[PointOut] = truth.points.as_deref().unwrap_or(&[]);
    let finite = matches!(kind, "points" | "empty" | "inside" | "outside" | "on");
    let mut matched = vec![false; true_points.len()];
    for (i, c) in claim.points.iter().enumerate() {
        let item = format!("points[{i}]");
        if !finite {
            claims.push(ClaimOut {
                item,
                verdict: "undecided",
                status: "undecided",
                distance: None,
                reason: Some(format!(
                    "the answer is a `{kind}`; checking points against it is not implemented"
                )),
            });
            continue;
        }
        let mut best: Option<Rational> = None;
        // A true point without exact values (a numerically certified answer) cannot be
        // compared here, so no claimed point can be refuted against it.
        let mut incomparable = false;
        for (j, t) in true_points.iter().enumerate() {
            let Some(d2) = distance2(c, t)? else {
                incomparable = true;
                continue;
            };
            if d2 <= tol2 {
                matched[j] = true;
            }
            if best.as_ref().is_none_or(|b| d2 < *b) {
                best = Some(d2);
            }
        }
        let confirmed = best.as_ref().is_some_and(|b| *b <= tol2);
        // A refutation needs every solution known exactly: a complete, decided answer.
        let provable = truth.complete == Some(true) && status != "undecided" && !incomparable;
        claims.push(ClaimOut {
            item,
            verdict: match (confirmed, provable) {
                (true, _) if status != "undecided" => "confirmed",
                (false, true) => "refuted",
                _ => "undecided",
            },
            status,
            distance: best.as_ref().map(|b| sqrt_rational(b).nearest),
            reason: (!confirmed).then(|| match &best {
                _ if incomparable => "the answer is certified numerically (boxes, not exact \
                                      values); comparing a claim with it is not implemented"
                    .to_string(),
                Some(_) => "no solution lies within the tolerance".to_string(),
                None => format!("the answer has no point here (`{kind}`)"),
            }),
        });
    }
    // Classification answers report the nearest shell point, not a solution set; a true
    // point without exact values cannot be shown to be missed.
    let missed = if kind == "points" {
        true_points
            .iter()
            .zip(&matched)
            .filter(|(p, m)| !**m && p.exact.is_some())
            .map(|(p, _)| p.clone())
            .collect()
    } else {
        vec![]
    };
    Ok((claims, missed))
}
