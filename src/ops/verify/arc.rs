//! A claimed `arc` (two curves sharing an arc, docs/FORMAT.md "Claims"): its two ends,
//! each a claimed point, optionally with exact parameters on both curves.
//!
//! - **confirmed, exactly**: the claim gives exact parameters `(t, s)` of both ends on
//!   both curves, and the solver's exact test ([`shares_arc`]: the affine map through
//!   the two pairs and the polynomial identities on every stretch) proves that
//!   `A([t₀, t₁])` and `B([s₀, s₁])` are one point set; a claimed end given by `xyz`
//!   must also lie within the tolerance of its exact point `A(t)`. This holds for a
//!   part of the shared arc too, whatever the solver found.
//! - **confirmed**: the answer is a decided `arc` and each claimed end lies within the
//!   tolerance of a different end of it (the point tests of the module above).
//! - **refuted**: the answer is decided and complete, and either has no arc (`points`
//!   or `empty`: finitely many common points), or is an `arc` from which a claimed end
//!   is proven beyond the tolerance — every box of a cover of the true arc
//!   ([`off_arc`]) lies beyond it.
//! - **confirmed** also when the answer is `coincident` (every arc of one curve is
//!   shared) and each claimed end is proven within the tolerance of the curve: a
//!   certified projection of the end (an exact point) has a proven foot within it;
//!   **refuted** when a claimed end is proven beyond the tolerance of one of the curves
//!   (every foot of its projection and every end of that curve lie beyond it).
//! - **undecided** otherwise, with the reason.

use rug::Rational;

use super::region::Region;
use super::{claim_regions, distance, relation, truth_region, ItemVerdict, Relation, Verdict};
use crate::certificate::{Certified, Status};
use crate::curve::Curve;
use crate::num::round::round_rational;
use crate::num::Interval;
use crate::ops::algebraic::overlap::{exact_point, shares_arc};
use crate::ops::answer::{Answer, SegmentAnswer};
use crate::ops::shape::Shape;
use crate::ops::{Options, ProjectOptions};

use super::{ClaimedArc, ClaimedPoint};

const ENDS: [&str; 2] = ["a", "b"];

/// The verdict on a claimed arc, and the regions of its ends where they could be
/// placed (for `missed`).
pub(super) fn arc_verdict(
    truth: &Certified<Answer>,
    shapes: &[Shape],
    arc: &ClaimedArc,
    tol2: &Rational,
    budget: &Options,
) -> (ItemVerdict, Option<[Vec<Region>; 2]>) {
    let placed = place(arc, shapes);
    let regions = placed.as_ref().ok().cloned();
    let verdict = |verdict, status, distance, reason: Option<String>| ItemVerdict {
        item: "arc".into(),
        verdict,
        status,
        distance,
        reason,
    };
    if proven_exactly(shapes, arc, tol2) {
        let why = "the claimed arc lies on both curves (exact test of the affine change of \
                   parameter through its ends)";
        return (
            verdict(
                Verdict::Confirmed,
                Status::Exact,
                Some(0.0),
                Some(why.into()),
            ),
            regions,
        );
    }
    let placed = match placed {
        Ok(p) => p,
        Err(reason) => {
            return (
                verdict(Verdict::Undecided, Status::Undecided, None, Some(reason)),
                None,
            )
        }
    };
    if truth.status == Status::Undecided {
        let why = truth.reason.as_deref().unwrap_or("no reason given");
        let reason = format!("the answer is undecided ({why})");
        return (
            verdict(Verdict::Undecided, Status::Undecided, None, Some(reason)),
            regions,
        );
    }
    let status = truth.status;
    let kind = truth.value.kind();
    let out = match &truth.value {
        Answer::Arc(s) => {
            let ends = [truth_region(&s.a), truth_region(&s.b)];
            let rel = |i: usize, j: usize| relation(&placed[i], &ends[j], tol2);
            let pairings = [[0, 1], [1, 0]];
            let within = pairings
                .iter()
                .find(|p| (0..2).all(|i| rel(i, p[i]) == Relation::Within));
            let dist = |p: &[usize; 2]| {
                (0..2)
                    .map(|i| distance(&placed[i], &ends[p[i]]))
                    .fold(0.0, f64::max)
            };
            let nearest = pairings.iter().map(dist).fold(f64::INFINITY, f64::min);
            if let Some(p) = within {
                verdict(Verdict::Confirmed, status, Some(dist(p)), None)
            } else if let Some(k) =
                (0..2).find(|&k| truth.complete && off_arc(shapes, s, &placed[k], tol2))
            {
                let why = format!(
                    "the claimed end `{}` lies beyond the tolerance of the shared arc",
                    ENDS[k]
                );
                verdict(Verdict::Refuted, status, Some(nearest), Some(why))
            } else {
                let why = if truth.complete {
                    "the claimed ends are neither proven within the tolerance of the shared \
                     arc's ends nor beyond the tolerance of the arc (a part of the arc is \
                     checked from exact parameters of its ends on both curves)"
                } else {
                    "the claimed ends are not within the tolerance of the shared arc's ends, \
                     and the answer is not complete (other common points were not searched)"
                };
                verdict(Verdict::Undecided, status, Some(nearest), Some(why.into()))
            }
        }
        Answer::Coincident => {
            // Every arc of one curve is shared: the claim holds when both ends are
            // proven within the tolerance of the curve.
            let on: Vec<Near> = placed
                .iter()
                .map(|r| near_curves(shapes, r, tol2, budget))
                .collect();
            if let Some(k) = on.iter().position(|n| *n == Near::Beyond) {
                let why = format!(
                    "the curves coincide, and the claimed end `{}` is proven beyond the \
                     tolerance of them (every foot of its projection and every end of the \
                     curve lie beyond it)",
                    ENDS[k]
                );
                verdict(Verdict::Refuted, status, None, Some(why))
            } else if let [Near::Within(a, ea), Near::Within(b, eb)] = on[..] {
                let why = "the curves coincide, and both claimed ends are proven within the \
                           tolerance of them (each by a certified point of the curve)";
                // No stronger than the weakest proof used (the answer's, the feet's).
                let status = if status == Status::Exact && ea && eb {
                    Status::Exact
                } else {
                    Status::Verified
                };
                verdict(Verdict::Confirmed, status, Some(a.max(b)), Some(why.into()))
            } else {
                let why = "the curves coincide, but a claimed end is not proven within the \
                           tolerance of them";
                verdict(Verdict::Undecided, status, None, Some(why.into()))
            }
        }
        Answer::Points(_) | Answer::Empty if truth.complete => {
            let why = format!("the curves share no arc: the answer is `{kind}`");
            verdict(Verdict::Refuted, status, None, Some(why))
        }
        _ => {
            let why = if truth.complete {
                format!("the answer is `{kind}`; a claimed arc is not compared with it")
            } else {
                format!("the answer (`{kind}`) is not complete")
            };
            verdict(Verdict::Undecided, status, None, Some(why))
        }
    };
    (out, regions)
}

/// Where a claimed end lies against coincident curves.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Near {
    /// Proven within the tolerance of every curve: the largest distance to the proven
    /// point used, and whether every proof used was exact.
    Within(f64, bool),
    /// Proven beyond the tolerance of some curve (so of the arcs they share).
    Beyond,
    /// Neither could be proven.
    Unknown,
}

/// Whether a claimed end (its regions: each a single exact point, or nothing is
/// decided) is proven within the tolerance of the shared point set of coincident
/// curves, or beyond it.
///
/// `coincident` means one shape lies in the other (the same curve, a Bézier on a line
/// or a conic, a curve in a plane or on a quadric), so the shared set lies in every
/// parametric curve among the shapes: the end must be within the tolerance of each of
/// them ([`near_one`]), and it is beyond the shared set when it is beyond one of them.
/// With no parametric curve among the shapes nothing is decided.
fn near_curves(shapes: &[Shape], claim: &[Region], tol2: &Rational, budget: &Options) -> Near {
    let curves: Vec<&Shape> = shapes
        .iter()
        .filter(|s| matches!(s, Shape::Curve(_) | Shape::Curve2(_)))
        .collect();
    if curves.is_empty() || claim.iter().any(|r| r.max_distance2(r) != Some(0.into())) {
        return Near::Unknown; // a box: the projection takes a point
    }
    let mut out = Near::Within(0.0, true);
    for curve in curves {
        out = match (out, near_one(curve, claim, tol2, budget)) {
            (_, Near::Beyond) | (Near::Beyond, _) => return Near::Beyond,
            (Near::Within(a, ea), Near::Within(b, eb)) => Near::Within(a.max(b), ea && eb),
            _ => Near::Unknown,
        };
    }
    out
}

/// One curve against a claimed end whose regions are exact points. **Within**: each
/// point projected onto the curve (the certified projection, every foot: any proven
/// foot is a point of the curve, and the nearest-only search may leave a tie at
/// distance 0 undecided) has a proven foot, or an end of the curve ([`curve_ends`]),
/// within the tolerance. **Beyond**: the distance to a curve is smallest at a foot or
/// at an end of an open curve (OPERATIONS.md §3.2; the argument of `ops::nearest`), so
/// when the feet are complete and every foot's box and every end's enclosure lies
/// beyond the tolerance of the point, the whole curve does. A curve whose domain ends
/// are rounded (an irrational angle) is never proven beyond unless it is closed.
fn near_one(curve: &Shape, claim: &[Region], tol2: &Rational, budget: &Options) -> Near {
    let how = ProjectOptions {
        nearest: false,
        direction: None,
        options: budget.clone(),
    };
    let closed = match curve {
        Shape::Curve(c) => c.is_closed(),
        Shape::Curve2(c) => c.is_closed(),
        _ => false,
    };
    let ends = curve_ends(curve);
    let (mut worst, mut exact, mut within) = (0.0f64, true, true);
    for region in claim {
        let one = std::slice::from_ref(region);
        let at = crate::ops::Position::Exact(region.center());
        let Ok(feet) = crate::ops::project(&at, curve, &how) else {
            return Near::Unknown;
        };
        let foot_exact = feet.status == Status::Exact;
        let points = feet.value.points();
        let proven = points
            .iter()
            .filter(|p| super::exists(feet.status, p))
            .map(|p| (super::truth_region(p), foot_exact));
        let near = proven
            .chain(ends.iter().map(|r| (r.clone(), false)))
            .find(|(t, _)| relation(one, t, tol2) == Relation::Within);
        if let Some((t, e)) = near {
            worst = worst.max(distance(one, &t));
            exact &= e;
            continue;
        }
        within = false;
        let all_feet = feet.complete
            && feet.status != Status::Undecided
            && matches!(feet.value, Answer::Points(_) | Answer::Empty);
        let ends_known = closed || ends.len() == 2;
        let beyond = |t: &Region| relation(one, t, tol2) == Relation::Beyond;
        if all_feet
            && ends_known
            && points.iter().all(|p| beyond(&super::truth_region(p)))
            && (closed || ends.iter().all(beyond))
        {
            return Near::Beyond;
        }
    }
    if within {
        Near::Within(worst, exact)
    } else {
        Near::Unknown
    }
}

/// Enclosures of the curve's two domain ends (points of the curve that are no foot
/// when the perpendicular from a point near an end falls outside the domain): the
/// curve evaluated in intervals at each end parameter; none when the domain's ends are
/// rounded.
fn curve_ends(shape: &Shape) -> Vec<Region> {
    let ends = |(lo, hi): (f64, f64), at: &dyn Fn(&Interval) -> Vec<Interval>| {
        [lo, hi]
            .iter()
            .map(|&t| at(&Interval::point(t)))
            .filter(|v| v.iter().all(|x| !x.is_empty() && x.is_bounded()))
            .map(|v| Region::from_bounds(&v.iter().map(|x| [x.lo(), x.hi()]).collect::<Vec<_>>()))
            .collect()
    };
    // A rounded domain end (an angle) may lie just outside the true domain: its point
    // would be the continuation's, not the curve's.
    match shape {
        Shape::Curve(c) if !c.domain_rounded() => ends(c.domain(), &|t| c.point(t).to_vec()),
        Shape::Curve2(c) if !c.domain_rounded() => ends(c.domain(), &|t| c.point(t).to_vec()),
        _ => vec![],
    }
}

/// The claimed ends as regions, or why one cannot be placed.
fn place(arc: &ClaimedArc, shapes: &[Shape]) -> Result<[Vec<Region>; 2], String> {
    let end = |k: usize| {
        claim_regions(&arc.ends[k], shapes).map_err(|r| format!("end `{}`: {r}", ENDS[k]))
    };
    Ok([end(0)?, end(1)?])
}

/// The exact route of the module doc: exact parameters on both curves at both ends,
/// the arc proven shared, and every end claimed by `xyz` within the tolerance of its
/// exact point.
fn proven_exactly(shapes: &[Shape], arc: &ClaimedArc, tol2: &Rational) -> bool {
    let [a, b] = shapes else {
        return false;
    };
    let pair = |k: usize| -> Option<(Rational, Rational)> {
        match arc.params[k].as_deref()? {
            [t, s] if t.len() == 1 && s.len() == 1 => Some((t[0].clone(), s[0].clone())),
            _ => None,
        }
    };
    let (Some(p), Some(q)) = (pair(0), pair(1)) else {
        return false;
    };
    if shares_arc(a, b, &p, &q) != Some(true) {
        return false;
    }
    [(&arc.ends[0], &p.0), (&arc.ends[1], &q.0)]
        .iter()
        .all(|(end, t)| match end {
            ClaimedPoint::Params(_) => true,
            ClaimedPoint::Xyz(v) => exact_point(a, t).is_some_and(|x| {
                relation(&[Region::point(v)], &Region::point(&x), tol2) == Relation::Within
            }),
        })
}

/// Whether the claimed end (its regions) is proven beyond the tolerance of the whole
/// true arc `A([t_a, t_b])` on the first curve: the parameter interval (rounded
/// outward from the exact parameters) is bisected, and each piece's interval
/// evaluation — an enclosure of the arc over it ([`Curve::point`] encloses the curve
/// over an interval parameter, across knots too) — must be beyond the tolerance of
/// some region of the claim, or is bisected again (at most 4096 evaluations).
fn off_arc(shapes: &[Shape], arc: &SegmentAnswer, claim: &[Region], tol2: &Rational) -> bool {
    let param =
        |p: &crate::ops::answer::Point| Some(p.exact.as_ref()?.params.first()?.first()?.clone());
    let (Some(ta), Some(tb), Some(shape)) = (param(&arc.a), param(&arc.b), shapes.first()) else {
        return false;
    };
    let (lo, hi) = if ta <= tb { (ta, tb) } else { (tb, ta) };
    let enclose = |l: f64, h: f64| -> Option<Region> {
        let t = Interval::new("t", l, h).ok()?;
        let v: Vec<Interval> = match shape {
            Shape::Curve(c) => c.point(&t).to_vec(),
            Shape::Curve2(c) => c.point(&t).to_vec(),
            _ => return None,
        };
        if v.iter().any(|x| x.is_empty() || !x.is_bounded()) {
            return None;
        }
        let q = |x: f64| Rational::from_f64(x);
        Some(Region::from_ends(
            v.iter().map(|x| q(x.lo())).collect(),
            v.iter().map(|x| q(x.hi())).collect(),
        ))
    };
    let mut work = vec![(round_rational(&lo).lo, round_rational(&hi).hi)];
    let mut budget = 4096;
    while let Some((l, h)) = work.pop() {
        budget -= 1;
        let Some(cover) = enclose(l, h) else {
            return false;
        };
        if claim.iter().any(|c| c.min_distance2(&cover) > *tol2) {
            continue;
        }
        let m = 0.5 * l + 0.5 * h;
        if budget == 0 || !(l < m && m < h) {
            return false;
        }
        work.extend([(l, m), (m, h)]);
    }
    true
}
