//! Piecewise unknowns (issue 21): a NURBS is one rational map per knot span and only
//! `C^{p−m}` across a knot of multiplicity `m`, so a box straddling a knot is never
//! proven smooth ([`crate::certify::guarded`]) and a root on a knot, or a system whose
//! equation jumps there (the foot equation `(p − c)·c'` at a G1 knot), could not be
//! decided. Here each closed piece is solved on its own, with the system of that
//! piece's map continued analytically ([`crate::curve::Curve::pinned_at`]): on the
//! closed piece it is the true system, so
//!
//! * a box of the piece excluded for the continued system holds no root of the true
//!   one, and a verified root inside the closed piece is a true root (unique there);
//! * a root whose box straddles a piece end is placed by [`super::boundary`] (the exact
//!   candidate at the knot first), as at a true end of the domain: proven inside the
//!   closed piece it is an answer, proven outside it is the continuation's and dropped.
//!
//! Every root of the true system lies in some closed piece, so the union is complete
//! when every piece is. A root on a knot is found from both sides; the copies are
//! merged into one (the same thin box, or one box inside the other).

use super::{push_unique, shifted_inside, CertifiedRoot, Options, Unknowns};
use crate::certificate::{Certified, Status};
use crate::certify::{Root, System};
use crate::curve::Curve;
use crate::error::GeomError;
use crate::num::Interval;
use crate::surface::Surface;

/// The pinned pieces of a curve with interior breaks, each with its closed parameter
/// range; `None` when the curve is one piece (or its domain bounds are rounded).
pub fn curve_pieces<C: Curve<D>, const D: usize>(c: &C) -> Option<Vec<(C, [f64; 2])>> {
    let breaks = c.piece_breaks();
    if breaks.is_empty() || c.domain_rounded() {
        return None;
    }
    let (lo, hi) = c.domain();
    let mut ends = vec![lo];
    ends.extend(breaks);
    ends.push(hi);
    ends.windows(2)
        .map(|w| {
            let mid = 0.5 * w[0] + 0.5 * w[1];
            c.pinned_at(mid).map(|p| (p, [w[0], w[1]]))
        })
        .collect()
}

/// The unknowns of one piece: a closed range, not periodic, with exact (knot) ends.
pub fn piece_unknowns(range: [f64; 2]) -> Unknowns {
    Unknowns {
        domain: vec![range],
        periodic: vec![false],
        rounded: vec![false],
    }
}

/// Every root over `whole`, solved piece by piece (module doc): `pieces` are the
/// pinned systems with their unknowns, which tile `whole`; each gets an equal share
/// of the box budget and the guesses lying in its closed box; `not_an_answer` as in
/// [`super::certify_roots_with`].
pub fn certify_roots_in_pieces<S: System>(
    pieces: &[(S, Unknowns)],
    whole: &Unknowns,
    guesses: &[Vec<f64>],
    opts: &Options,
    not_an_answer: &dyn Fn(&Root) -> bool,
) -> Result<Certified<Vec<CertifiedRoot>>, GeomError> {
    let share = Options {
        max_boxes: (opts.max_boxes / pieces.len().max(1)).max(1),
        ..opts.clone()
    };
    let mut roots: Vec<CertifiedRoot> = Vec::new();
    let (mut complete, mut bits, mut reason) = (true, 53, None);
    for (sys, unknowns) in pieces {
        let mine: Vec<Vec<f64>> = guesses
            .iter()
            .filter(|g| {
                g.iter()
                    .zip(&unknowns.domain)
                    .all(|(x, [lo, hi])| lo <= x && x <= hi)
            })
            .cloned()
            .collect();
        let part = super::certify_roots_with(sys, unknowns, &mine, &share, not_an_answer)?;
        complete &= part.complete;
        bits = bits.max(part.bits);
        if reason.is_none() {
            reason = part.reason;
        }
        let before = roots.len();
        for root in part.value {
            merge(&mut roots, before, root, whole, &mut complete, &mut reason);
        }
    }
    Ok(assemble(roots, complete, bits, reason))
}

/// Add a root found in one piece: a copy of a kept root (one box inside the other,
/// up to whole periods) is merged by [`push_unique`]; a box that overlaps a kept one
/// otherwise may hold the same root (on a knot) or another, so the two are joined into
/// one undecided box (never reported as two verified roots). `roots[..earlier]` are
/// those of the earlier pieces.
fn merge(
    roots: &mut Vec<CertifiedRoot>,
    earlier: usize,
    root: CertifiedRoot,
    whole: &Unknowns,
    complete: &mut bool,
    reason: &mut Option<String>,
) {
    let nested = roots.iter().any(|r| {
        shifted_inside(&root.enclosure, &r.enclosure, whole)
            || shifted_inside(&r.enclosure, &root.enclosure, whole)
    });
    let overlap = roots[..earlier.min(roots.len())]
        .iter()
        .position(|r| meets_shifted(&root.enclosure, &r.enclosure, whole));
    match overlap {
        Some(i) if !nested => {
            let r = &mut roots[i];
            r.enclosure = r
                .enclosure
                .iter()
                .zip(&root.enclosure)
                .map(|(a, b)| a.hull(b))
                .collect();
            r.status = Status::Undecided;
            r.max_roots = r.max_roots.max(1) + root.max_roots.max(1);
            r.reason = Some("roots of two knot spans overlap at a knot".into());
            *complete = false;
            reason.get_or_insert_with(|| "roots of two knot spans overlap at a knot".into());
        }
        _ => push_unique(roots, root, whole),
    }
}

/// `a`, shifted by a whole number of periods in its periodic coordinates (by 0, +P or
/// −P, P an enclosure of the period), meets `b` (a root on a seam found in two pieces
/// at both ends of the period).
fn meets_shifted(a: &[Interval], b: &[Interval], whole: &Unknowns) -> bool {
    (0..a.len()).all(|i| {
        let shifts = if whole.periodic[i] {
            let p = whole.period(i);
            vec![Interval::point(0.0), p, -p]
        } else {
            vec![Interval::point(0.0)]
        };
        shifts
            .into_iter()
            .any(|s| !(a[i] + s).intersection(&b[i]).is_empty())
    })
}

/// The answer of the pieces together, with the status and completeness rules of
/// [`super::certify_roots_with`].
fn assemble(
    roots: Vec<CertifiedRoot>,
    mut complete: bool,
    bits: u32,
    reason: Option<String>,
) -> Certified<Vec<CertifiedRoot>> {
    let status = roots
        .iter()
        .fold(Status::Verified, |s, r| s.weakest(r.status));
    if roots.iter().any(|r| r.status == Status::Undecided) {
        complete = false;
    }
    super::answer(roots, status, complete, bits, reason)
}

/// A curve's parts for [`certify_roots_in_pieces`]: its pinned pieces (from
/// [`curve_pieces`], computed by the caller into `pinned`) with their unknowns, or the
/// curve itself with its own unknowns when it is one piece.
pub fn curve_parts<'a, C: Curve<D>, const D: usize>(
    c: &'a C,
    pinned: &'a Option<Vec<(C, [f64; 2])>>,
) -> Vec<(&'a C, Unknowns)> {
    match pinned {
        Some(parts) => parts
            .iter()
            .map(|(p, range)| (p, piece_unknowns(*range)))
            .collect(),
        None => vec![(c, super::curve_unknowns(c))],
    }
}

/// Pinned knot rectangles, each with its closed `[u, v]` ranges.
pub type SurfacePieces<S> = Vec<(S, [[f64; 2]; 2])>;

/// The pinned knot rectangles of a surface with interior breaks, each with its closed
/// `[u, v]` ranges; `None` when the surface is one piece (or a bound is rounded).
pub fn surface_pieces<S: Surface>(s: &S) -> Option<SurfacePieces<S>> {
    let breaks = s.piece_breaks();
    if breaks.iter().all(Vec::is_empty) || s.domain_rounded().iter().any(|&r| r) {
        return None;
    }
    let (du, dv) = s.domain();
    let ranges = |[lo, hi]: [f64; 2], inner: &[f64]| {
        let mut ends = vec![lo];
        ends.extend_from_slice(inner);
        ends.push(hi);
        ends.windows(2).map(|w| [w[0], w[1]]).collect::<Vec<_>>()
    };
    let (ru, rv) = (ranges(du, &breaks[0]), ranges(dv, &breaks[1]));
    let mut out = Vec::new();
    for v in &rv {
        for u in &ru {
            let mid = |[a, b]: [f64; 2]| 0.5 * a + 0.5 * b;
            out.push((s.pinned_at(mid(*u), mid(*v))?, [*u, *v]));
        }
    }
    Some(out)
}

/// A surface's parts for [`certify_roots_in_pieces`], as [`curve_parts`].
pub fn surface_parts<'a, S: Surface>(
    s: &'a S,
    pinned: &'a Option<SurfacePieces<S>>,
) -> Vec<(&'a S, Unknowns)> {
    match pinned {
        Some(parts) => parts
            .iter()
            .map(|(p, [u, v])| {
                let unknowns = Unknowns {
                    domain: vec![*u, *v],
                    periodic: vec![false, false],
                    rounded: vec![false, false],
                };
                (p, unknowns)
            })
            .collect(),
        None => vec![(s, super::surface_unknowns(s))],
    }
}
