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
//!   closed piece it is an answer, proven outside it is the continuation's and dropped;
//! * a root exactly on a knot where no exact candidate exists (the other unknowns are
//!   irrational there) stays undecided in both pieces; when the system is continuous
//!   across the knot (a curve's point, not its derivative), it is proven across the
//!   knot instead ([`super::across`], [`crate::certify::joined`]): one root in a box that
//!   straddles the knot, which is all the answer needs.
//!
//! Every root of the true system lies in some closed piece, so the union is complete
//! when every piece is. A root on a knot is found from both sides; the copies are
//! merged into one (the same thin box, or one box inside the other).

use super::across::shifted_to_meet;
use super::{push_unique, shifted_inside, CertifiedRoot, Options, Unknowns};
use crate::certificate::{Certified, Status};
use crate::certify::{Root, System};
use crate::curve::Curve;
use crate::error::GeomError;
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
/// [`super::certify_roots_with`]. With `tiles` (the system is continuous across the
/// tiles' common faces: it uses the objects' points, not their derivatives; the tiles
/// are `pieces` themselves, or finer ones that also cut a NURBS patch at its knots), a
/// root left undecided on a knot is proven across it ([`super::across`]).
pub fn certify_roots_in_pieces<S: System>(
    pieces: &[(S, Unknowns)],
    whole: &Unknowns,
    guesses: &[Vec<f64>],
    opts: &Options,
    not_an_answer: &dyn Fn(&Root) -> bool,
    tiles: Option<&[(S, Unknowns)]>,
) -> Result<Certified<Vec<CertifiedRoot>>, GeomError> {
    f64_first(opts, |o| {
        in_pieces(pieces, whole, guesses, o, not_an_answer, tiles)
    })
}

/// Run `search` with f64 intervals only first, and keep that answer when it is
/// complete with every root `verified`; otherwise run it again with the caller's
/// precision ladder (issue 21: a root on a knot line straddles the knot in every box,
/// so no smooth Krawczyk test proves it at any precision, and the search escalated
/// such clusters to 512 bits — seconds per line of the NURBS sphere — before the
/// proof across the knot, which works on f64 intervals, decided them). The first
/// answer is sound on its own (the same search and proofs at one precision level);
/// it is dropped, not merged, when it falls short, so the second is exactly the
/// answer without this step. A singular box is not kept from the first run: higher
/// precision may still separate it into two verified roots.
fn f64_first(
    opts: &Options,
    search: impl Fn(&Options) -> Result<Certified<Vec<CertifiedRoot>>, GeomError>,
) -> Result<Certified<Vec<CertifiedRoot>>, GeomError> {
    if opts.max_bits > 53 {
        let quick = Options {
            max_bits: 53,
            ..opts.clone()
        };
        let r = search(&quick)?;
        if r.complete && r.value.iter().all(|x| x.status == Status::Verified) {
            return Ok(r);
        }
    }
    search(opts)
}

fn in_pieces<S: System>(
    pieces: &[(S, Unknowns)],
    whole: &Unknowns,
    guesses: &[Vec<f64>],
    opts: &Options,
    not_an_answer: &dyn Fn(&Root) -> bool,
    tiles: Option<&[(S, Unknowns)]>,
) -> Result<Certified<Vec<CertifiedRoot>>, GeomError> {
    let share = Options {
        max_boxes: (opts.max_boxes / pieces.len().max(1)).max(1),
        ..opts.clone()
    };
    let mut roots: Vec<CertifiedRoot> = Vec::new();
    let mut undecided = Vec::new();
    let (mut searched, mut bits, mut reason) = (true, 53, None);
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
        let part = super::find_roots(sys, unknowns, &mine, &share, not_an_answer)?;
        searched &= part.searched;
        undecided.extend(part.undecided);
        bits = bits.max(part.bits);
        if reason.is_none() {
            reason = part.reason;
        }
        let before = roots.len();
        for root in part.roots {
            merge(&mut roots, before, root, whole);
        }
    }
    let search = Search {
        undecided,
        searched,
        bits,
        reason,
    };
    Ok(finish(roots, tiles, whole, search))
}

/// Every root of `sys` over `whole`, searched as one system (not split), whose roots
/// left undecided on a face between two `tiles` (a knot line of a NURBS patch) are
/// proven across it ([`super::across`]): `sys` must be continuous there, and equal to each
/// tile's system on the tile.
pub fn certify_roots_across<S: System>(
    sys: &S,
    tiles: &[(S, Unknowns)],
    whole: &Unknowns,
    guesses: &[Vec<f64>],
    opts: &Options,
) -> Result<Certified<Vec<CertifiedRoot>>, GeomError> {
    f64_first(opts, |o| {
        let found = super::find_roots(sys, whole, guesses, o, |_| false)?;
        let search = Search {
            undecided: found.undecided,
            searched: found.searched,
            bits: found.bits,
            reason: found.reason,
        };
        Ok(finish(found.roots, Some(tiles), whole, search))
    })
}

/// What the searches of the pieces left: their undecided boxes, whether they covered
/// their boxes (`searched`: no undecided box), the precision and the first reason.
struct Search {
    undecided: Vec<crate::certify::UndecidedBox>,
    searched: bool,
    bits: u32,
    reason: Option<String>,
}

/// The roots and the undecided boxes of the search proven across `tiles` where given
/// ([`super::across`]), then the answer: complete when every box the search left is
/// decided and no root is undecided.
fn finish<S: System>(
    mut roots: Vec<CertifiedRoot>,
    tiles: Option<&[(S, Unknowns)]>,
    whole: &Unknowns,
    search: Search,
) -> Certified<Vec<CertifiedRoot>> {
    let Search {
        undecided,
        mut searched,
        bits,
        mut reason,
    } = search;
    if let Some(tiles) = tiles {
        super::across::across(tiles, whole, &mut roots);
        let before = undecided.len();
        let left = super::across::decide_boxes(tiles, whole, &mut roots, undecided);
        // The search's incompleteness is exactly its undecided boxes.
        searched = left.is_empty();
        if left.len() < before {
            reason = left
                .first()
                .map(|b| format!("{} undecided box(es); first: {}", left.len(), b.reason));
        }
    }
    if let Some(r) = roots.iter().find(|r| r.status == Status::Undecided) {
        reason.get_or_insert_with(|| {
            r.reason
                .clone()
                .unwrap_or_else(|| "a root straddles the domain boundary".into())
        });
    }
    assemble(roots, searched, bits, reason)
}

/// Add a root found in one piece: a copy of a kept root (one box inside the other,
/// up to whole periods) is merged by [`push_unique`]; a box that overlaps a kept one
/// otherwise may hold the same root (on a knot) or another, so the two are joined into
/// one undecided box (never reported as two verified roots). `roots[..earlier]` are
/// those of the earlier pieces.
fn merge(roots: &mut Vec<CertifiedRoot>, earlier: usize, root: CertifiedRoot, whole: &Unknowns) {
    let nested = roots.iter().any(|r| {
        shifted_inside(&root.enclosure, &r.enclosure, whole)
            || shifted_inside(&r.enclosure, &root.enclosure, whole)
    });
    let overlap = roots[..earlier.min(roots.len())]
        .iter()
        .enumerate()
        .find_map(|(i, r)| shifted_to_meet(&root.enclosure, &r.enclosure, whole).map(|a| (i, a)));
    match overlap {
        Some((i, shifted)) if !nested => {
            let r = &mut roots[i];
            r.enclosure = r
                .enclosure
                .iter()
                .zip(&shifted)
                .map(|(a, b)| a.hull(b))
                .collect();
            r.status = Status::Undecided;
            r.max_roots = r.max_roots.max(1) + root.max_roots.max(1);
            r.reason = Some("roots of two knot spans overlap at a knot".into());
        }
        _ => push_unique(roots, root, whole),
    }
}

/// The answer of the pieces together, with the status and completeness rules of
/// [`super::certify_roots_with`]: complete when every piece was searched and no root
/// is undecided.
fn assemble(
    roots: Vec<CertifiedRoot>,
    searched: bool,
    bits: u32,
    reason: Option<String>,
) -> Certified<Vec<CertifiedRoot>> {
    let status = roots
        .iter()
        .fold(Status::Verified, |s, r| s.weakest(r.status));
    let complete = searched && roots.iter().all(|r| r.status != Status::Undecided);
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

/// The tiles of a curve–surface system for [`super::across`]: every knot rectangle of the
/// surface (or the whole surface) with every piece of the curve (or the whole curve),
/// the surface's two unknowns first. `system` builds the system of a surface and a
/// curve.
pub fn surface_curve_tiles<'a, Sf: Surface, C: Curve<3>, S>(
    surface: &'a Sf,
    spieces: &'a Option<SurfacePieces<Sf>>,
    curve_parts: &[(&'a C, Unknowns)],
    system: impl Fn(&'a Sf, &'a C) -> S,
) -> Vec<(S, Unknowns)> {
    let surface_parts: Vec<(&Sf, Unknowns)> = match spieces {
        Some(parts) => parts
            .iter()
            .map(|(s, [u, v])| {
                let unknowns = Unknowns {
                    domain: vec![*u, *v],
                    periodic: vec![false, false],
                    rounded: vec![false, false],
                };
                (s, unknowns)
            })
            .collect(),
        None => vec![(surface, super::surface_unknowns(surface))],
    };
    let mut tiles = Vec::new();
    for (s, us) in &surface_parts {
        for (c, uc) in curve_parts {
            tiles.push((system(s, c), Unknowns::concat(&[us.clone(), uc.clone()])));
        }
    }
    tiles
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::certificate::Arithmetic;
    use crate::num::interval::Interval;
    use std::cell::RefCell;

    fn root(status: Status) -> CertifiedRoot {
        CertifiedRoot {
            params: vec![0.5],
            enclosure: vec![Interval::new("t", 0.25, 0.75).expect("interval")],
            status,
            max_roots: 1 + u32::from(status == Status::VerifiedSingular),
            bits: 53,
            perturbation: None,
            reason: None,
        }
    }

    /// An answer of the search at `bits` with these root statuses, complete or not.
    fn answer(statuses: &[Status], complete: bool, bits: u32) -> Certified<Vec<CertifiedRoot>> {
        let roots = statuses.iter().map(|s| root(*s)).collect();
        let mut c = Certified::exact(roots, Arithmetic::of_interval_bits(bits), bits);
        c.status = Status::Verified;
        c.complete = complete;
        c
    }

    /// The wrapper's whole contract, on a scripted search that records the precision of
    /// each call: the 53-bit answer is kept only when complete with every root verified;
    /// otherwise the full ladder's answer is returned unchanged (never merged); a caller
    /// already at 53 bits is searched once.
    #[test]
    fn the_f64_pass_is_kept_only_when_it_decides_everything() {
        use Status::{Undecided, Verified, VerifiedSingular};
        let cases: [(&[Status], bool, usize); 6] = [
            (&[Verified, Verified], true, 1),
            (&[], true, 1), // proven empty
            (&[Verified], false, 2),
            (&[Verified, VerifiedSingular], true, 2),
            (&[Undecided], true, 2),
            (&[], false, 2),
        ];
        for (statuses, complete, calls) in cases {
            let seen = RefCell::new(Vec::new());
            let opts = Options {
                max_bits: 512,
                ..Options::default()
            };
            let r = f64_first(&opts, |o| {
                seen.borrow_mut().push(o.max_bits);
                Ok(if o.max_bits == 53 {
                    answer(statuses, complete, 53)
                } else {
                    answer(&[Verified, Verified, Verified], true, 512)
                })
            })
            .expect("search");
            let seen = seen.into_inner();
            assert_eq!(seen.len(), calls, "{statuses:?} {complete}");
            assert_eq!(seen[0], 53);
            if calls == 1 {
                assert_eq!(r, answer(statuses, complete, 53));
            } else {
                assert_eq!(seen[1], 512);
                assert_eq!(r, answer(&[Verified, Verified, Verified], true, 512));
            }
        }
        // At 53 bits already: one search at the caller's options, whatever it answers.
        let calls = RefCell::new(0);
        let opts = Options {
            max_bits: 53,
            ..Options::default()
        };
        let r = f64_first(&opts, |_| {
            *calls.borrow_mut() += 1;
            Ok(answer(&[Undecided], false, 53))
        })
        .expect("search");
        assert_eq!(*calls.borrow(), 1);
        assert!(!r.complete);
        // An error of the first pass is the caller's error.
        let opts = Options {
            max_bits: 512,
            ..Options::default()
        };
        let r = f64_first(&opts, |_| {
            Err(GeomError::ZeroDirection { field: "x".into() })
        });
        assert!(r.is_err());
    }
}
