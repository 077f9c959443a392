//! `verify`: another program's claimed answer against geocert's certified one
//! (docs/CERTIFICATES.md "Verifying another program's answer"; CASES.md "Claims").
//!
//! Each claimed point is a [`Region`] that holds it exactly (its coordinates, or the
//! image of its parameters on each object, [`params::image`]); each solution of the
//! truth is its exact point when the answer carries one, else its certified box. With
//! `tol` the claim's tolerance, and the distances between regions computed exactly
//! ([`Region::min_distance2`], [`Region::max_distance2`]):
//!
//! - **confirmed** when some solution proven to exist lies within `tol` of the claim:
//!   the *largest* distance from the claim's region to its box is `≤ tol` (for a claim
//!   by parameters, on every object it names);
//! - **refuted** when the answer is decided and complete and every box (singular boxes
//!   included: they hold every solution near them) is proven farther than `tol`: the
//!   *smallest* distance exceeds `tol` (on some object the claim names);
//! - **undecided** otherwise, with the reason.
//!
//! `missed` lists the solutions proven to exist that are proven farther than `tol` from
//! every claimed point (answers of kind `points`). A solution is proven to exist when
//! the answer is `exact` or `verified`, or for the simple (non-tangent) points of a
//! `verified_singular` answer; a singular box may hold no solution of the input.

mod arc;
mod params;
mod region;

pub use params::image;
pub use region::Region;

use rug::Rational;

use crate::certificate::{Certified, Status};
use crate::num::round::sqrt_rational;
use crate::ops::answer::{Answer, Point, SegmentAnswer};
use crate::ops::shape::Shape;

/// A claimed point: coordinates, or parameters per object (in the order of the
/// objects of the case; an empty list for an object the claim gives none on).
#[derive(Debug, Clone, PartialEq)]
pub enum ClaimedPoint {
    Xyz(Vec<Rational>),
    Params(Vec<Vec<Rational>>),
}

/// A claimed shared arc (kind `arc`): its two ends `a` and `b`, and where the claim
/// gives them, the exact parameters of each end on every object (`exact.params`, else
/// `params`), which let the arc be checked exactly (the private `arc` module).
#[derive(Debug, Clone, PartialEq)]
pub struct ClaimedArc {
    pub ends: [ClaimedPoint; 2],
    pub params: [Option<Vec<Vec<Rational>>>; 2],
}

/// A claimed answer in exact numbers.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Claim {
    /// The claimed kind (`points`, `empty`, `inside`, ...).
    pub kind: Option<String>,
    pub points: Vec<ClaimedPoint>,
    /// A claimed shared arc.
    pub arc: Option<ClaimedArc>,
    /// The tolerance, a distance in space (≥ 0).
    pub tolerance: Rational,
    /// Claimed items that are not compared (`line`, `segment`, `curves`).
    pub unchecked: Vec<String>,
}

/// The verdict on one claimed item.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Verdict {
    Confirmed,
    Refuted,
    Undecided,
}

impl Verdict {
    /// The name used in JSON.
    pub fn as_str(self) -> &'static str {
        match self {
            Verdict::Confirmed => "confirmed",
            Verdict::Refuted => "refuted",
            Verdict::Undecided => "undecided",
        }
    }
}

/// The verdict on one claimed item, and what it rests on.
#[derive(Debug, Clone, PartialEq)]
pub struct ItemVerdict {
    /// `kind`, `points[i]`, `line`, ...
    pub item: String,
    pub verdict: Verdict,
    /// The certificate level of the truth the verdict rests on.
    pub status: Status,
    /// The distance from the claimed point to the nearest solution: exact correctly
    /// rounded when both are exact points, an estimate from the boxes' points otherwise.
    pub distance: Option<f64>,
    pub reason: Option<String>,
}

/// The comparison of a claim with the truth.
#[derive(Debug, Clone, PartialEq)]
pub struct Verification {
    pub items: Vec<ItemVerdict>,
    /// The solutions the claim misses: points of the answer, or the ends of a shared
    /// arc that no claimed point or end lies within the tolerance of.
    pub missed: Vec<Point>,
}

/// A claimed point as regions: one (coordinates), or one per object it gives
/// parameters on; `Err` with the reason when it cannot be placed.
fn claim_regions(c: &ClaimedPoint, shapes: &[Shape]) -> Result<Vec<Region>, String> {
    match c {
        ClaimedPoint::Xyz(v) => Ok(vec![Region::point(v)]),
        ClaimedPoint::Params(ps) => {
            if ps.len() != shapes.len() {
                return Err(format!(
                    "the claim gives parameters on {} object(s), the case has {}",
                    ps.len(),
                    shapes.len()
                ));
            }
            let mut out = vec![];
            for (i, (s, p)) in shapes.iter().zip(ps).enumerate() {
                match image(s, p) {
                    Ok(Some(r)) => out.push(r),
                    Ok(None) => {}
                    Err(e) => return Err(format!("params[{i}]: {e}")),
                }
            }
            if out.is_empty() {
                return Err("the claim gives no parameters".into());
            }
            Ok(out)
        }
    }
}

/// Where a solution lies: its exact point when the answer has it, else its box.
fn truth_region(p: &Point) -> Region {
    match &p.exact {
        Some(e) if !e.xyz.is_empty() && e.xyz.len() == p.xyz_box.len() => Region::point(&e.xyz),
        _ => Region::from_bounds(&p.xyz_box),
    }
}

/// Whether the point is proven to be a solution (module doc).
fn exists(status: Status, p: &Point) -> bool {
    match status {
        Status::Exact | Status::Verified => true,
        Status::VerifiedSingular => !p.tangent && p.multiplicity == 1,
        Status::Undecided => false,
    }
}

/// How one claimed point relates to one solution.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Relation {
    /// Proven within the tolerance (every region's largest distance ≤ tol).
    Within,
    /// Proven beyond it (some region's smallest distance > tol).
    Beyond,
    /// Neither: the box straddles the tolerance sphere.
    Straddles,
    /// The dimensions differ.
    Incomparable,
}

fn relation(claim: &[Region], truth: &Region, tol2: &Rational) -> Relation {
    if claim.iter().any(|c| c.dim() != truth.dim()) {
        return Relation::Incomparable;
    }
    if claim.iter().any(|c| c.min_distance2(truth) > *tol2) {
        return Relation::Beyond;
    }
    let within = claim
        .iter()
        .all(|c| c.max_distance2(truth).is_some_and(|d| d <= *tol2));
    if within {
        Relation::Within
    } else {
        Relation::Straddles
    }
}

/// The distance from a claim to a solution: between their centers (exact points are
/// their own centers), correctly rounded; the largest over the claim's regions.
fn distance(claim: &[Region], truth: &Region) -> f64 {
    let t = truth.center();
    claim
        .iter()
        .map(|c| {
            let d2: Rational = c
                .center()
                .iter()
                .zip(&t)
                .map(|(a, b)| Rational::from(a - b).square())
                .sum();
            sqrt_rational(&d2).nearest
        })
        .fold(0.0, f64::max)
}

/// Compare `claim` with the certified answer `truth`; `shapes` are the objects whose
/// parameters a claim by `params` names, in order (the `objects` of `intersect`, the
/// `onto` of `project`, the `shell` of `classify`). `budget` bounds the work of the
/// checks that solve again (the projections of a claimed arc's ends).
pub fn verify(
    truth: &Certified<Answer>,
    shapes: &[Shape],
    claim: &Claim,
    budget: &crate::ops::Options,
) -> Verification {
    let mut items = vec![];
    if let Some(k) = &claim.kind {
        items.push(kind_verdict(truth, k));
    }
    for item in &claim.unchecked {
        items.push(ItemVerdict {
            item: item.clone(),
            verdict: Verdict::Undecided,
            status: Status::Undecided,
            distance: None,
            reason: Some(format!(
                "checking a claimed `{item}` is not implemented yet"
            )),
        });
    }
    let kind = truth.value.kind();
    let finite = matches!(kind, "points" | "empty" | "inside" | "outside" | "on");
    let truths: Vec<Region> = truth.value.points().iter().map(truth_region).collect();
    let tol2 = claim.tolerance.clone().square();
    // relations[k][j]: claimed point k against solution j (None: not placed).
    let mut relations: Vec<Option<Vec<Relation>>> = vec![];
    for (i, c) in claim.points.iter().enumerate() {
        let item = format!("points[{i}]");
        if !finite {
            items.push(undecided_item(
                item,
                format!("the answer is a `{kind}`; checking points against it is not implemented"),
            ));
            relations.push(None);
            continue;
        }
        let regions = match claim_regions(c, shapes) {
            Ok(r) => r,
            Err(reason) => {
                items.push(undecided_item(item, reason));
                relations.push(None);
                continue;
            }
        };
        let rel: Vec<Relation> = truths
            .iter()
            .map(|t| relation(&regions, t, &tol2))
            .collect();
        items.push(point_verdict(truth, item, &regions, &truths, &rel));
        relations.push(Some(rel));
    }
    if let Some(a) = &claim.arc {
        let (verdict, regions) = arc::arc_verdict(truth, shapes, a, &tol2, budget);
        items.push(verdict);
        for end in regions.map_or([None, None], |r| r.map(Some)) {
            relations.push(end.map(|r| truths.iter().map(|t| relation(&r, t, &tol2)).collect()));
        }
    }
    let missed = match &truth.value {
        Answer::Points(points) => (0..points.len())
            .filter(|&j| exists(truth.status, &points[j]))
            .filter(|&j| {
                relations
                    .iter()
                    .all(|r| r.as_ref().is_some_and(|r| r[j] == Relation::Beyond))
            })
            .map(|j| points[j].clone())
            .collect(),
        Answer::Arc(s) if truth.status != Status::Undecided => {
            missed_arc_ends(s, shapes, claim, &tol2)
        }
        _ => vec![],
    };
    Verification { items, missed }
}

/// The ends of the true shared arc `s` that every claimed point and claimed arc end
/// (placed) is proven beyond the tolerance of (none when one cannot be placed).
fn missed_arc_ends(
    s: &SegmentAnswer,
    shapes: &[Shape],
    claim: &Claim,
    tol2: &Rational,
) -> Vec<Point> {
    let mut placed: Vec<Vec<Region>> = vec![];
    let ends = claim.arc.iter().flat_map(|a| a.ends.iter());
    for c in claim.points.iter().chain(ends) {
        match claim_regions(c, shapes) {
            Ok(r) => placed.push(r),
            Err(_) => return vec![],
        }
    }
    [&s.a, &s.b]
        .into_iter()
        .filter(|e| {
            let t = truth_region(e);
            placed
                .iter()
                .all(|c| relation(c, &t, tol2) == Relation::Beyond)
        })
        .cloned()
        .collect()
}

fn undecided_item(item: String, reason: String) -> ItemVerdict {
    ItemVerdict {
        item,
        verdict: Verdict::Undecided,
        status: Status::Undecided,
        distance: None,
        reason: Some(reason),
    }
}

/// The claimed kind against the true kind: decided when the answer is complete.
fn kind_verdict(truth: &Certified<Answer>, claimed: &str) -> ItemVerdict {
    let kind = truth.value.kind();
    let same = claimed == kind;
    let decided = truth.complete && truth.status != Status::Undecided;
    ItemVerdict {
        item: "kind".into(),
        verdict: match (same, decided) {
            (_, false) => Verdict::Undecided,
            (true, true) => Verdict::Confirmed,
            (false, true) => Verdict::Refuted,
        },
        status: truth.status,
        distance: None,
        reason: (!same).then(|| format!("the answer is `{kind}`")),
    }
}

/// The verdict on one placed claimed point (module doc), with the reason when it is
/// not confirmed.
fn point_verdict(
    truth: &Certified<Answer>,
    item: String,
    regions: &[Region],
    truths: &[Region],
    rel: &[Relation],
) -> ItemVerdict {
    let points = truth.value.points();
    let decided = truth.status != Status::Undecided;
    let confirming =
        (0..points.len()).find(|&j| rel[j] == Relation::Within && exists(truth.status, &points[j]));
    let nearest = (0..points.len())
        .map(|j| (j, distance(regions, &truths[j])))
        .min_by(|a, b| a.1.total_cmp(&b.1));
    let distance = confirming
        .map(|j| distance(regions, &truths[j]))
        .or(nearest.map(|n| n.1));
    let all_beyond = rel.iter().all(|r| *r == Relation::Beyond);
    let (verdict, reason) = if confirming.is_some() && decided {
        (Verdict::Confirmed, None)
    } else if all_beyond && decided && truth.complete {
        let why = if points.is_empty() {
            format!("the answer has no point here (`{}`)", truth.value.kind())
        } else {
            "no solution lies within the tolerance".to_string()
        };
        (Verdict::Refuted, Some(why))
    } else {
        (Verdict::Undecided, Some(undecided_reason(truth, rel)))
    };
    ItemVerdict {
        item,
        verdict,
        status: truth.status,
        distance,
        reason,
    }
}

/// Why a claimed point is neither confirmed nor refuted.
fn undecided_reason(truth: &Certified<Answer>, rel: &[Relation]) -> String {
    if truth.status == Status::Undecided {
        let why = truth.reason.as_deref().unwrap_or("no reason given");
        return format!("the answer is undecided ({why})");
    }
    if rel.contains(&Relation::Incomparable) {
        return "the claimed point and the answer's points differ in dimension".into();
    }
    if rel.contains(&Relation::Within) {
        return "the solution within the tolerance is a singular box (a tangency of a \
                nearby input), not proven to hold a solution of this input"
            .into();
    }
    if rel.contains(&Relation::Straddles) {
        return "a solution's certified box straddles the tolerance: it is neither proven \
                within nor proven beyond it"
            .into();
    }
    "the answer is not complete: a solution not found may lie within the tolerance".into()
}
