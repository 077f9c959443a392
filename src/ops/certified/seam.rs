//! Seam copies of one root (module doc of [`super`]): a root on the seam of a periodic
//! parameter can be certified at both ends of the domain, in boxes too different in
//! width for one to contain the other shifted by the period (a box of width 1e-59 at
//! `u = 0` against one of width 1e-15 at `u = 2π`, whose shift by the period enclosure
//! is ~1e-15 wide).
//!
//! Two verified boxes `A` (unique root `a`) and `B` (unique root `b`) are proven to hold
//! the same root when, for a shift `s` by whole periods in the periodic coordinates
//! (an enclosure of the exact shift `p`), `A + s` meets `B` and one Krawczyk step
//! proves a unique root in a box `H ⊇ hull(A + s, B)`: the system is periodic, so
//! `a + p` is a root in `A + s ⊆ H` and `b` is one in `B ⊆ H`; uniqueness in `H` gives
//! `a + p = b`. The step runs in f64 intervals, then (when that is inconclusive) in
//! MPFR intervals at the roots' precision (at least [`SEAM_BITS`]).
//!
//! The shift may be 0, in periodic and non-periodic coordinates alike: two verified
//! boxes that overlap without either holding the other (the search proved one root
//! from two neighbouring boxes, e.g. on a sphere's re-poled chart) are one root when
//! the same step proves it; otherwise both stay (two roots may be that close).

use super::{CertifiedRoot, Unknowns};
use crate::certificate::Status;
use crate::certify::boxes;
use crate::certify::krawczyk::{krawczyk, Krawczyk};
use crate::certify::System;
use crate::num::{Interval, MpfrInterval};

/// The least precision of the MPFR retry of [`same_root`] (the roots' own when higher).
const SEAM_BITS: u32 = 128;

/// Drop verified roots proven to be copies of another kept root (across a seam, or
/// overlapping); the copy kept is the one whose estimate lies inside the domain (the
/// first found on ties).
pub fn drop_copies<S: System>(sys: &S, roots: &mut Vec<CertifiedRoot>, unknowns: &Unknowns) {
    let mut i = 0;
    while i < roots.len() {
        let copy_of = (0..roots.len()).find(|&j| {
            j != i
                && roots[i].status == Status::Verified
                && roots[j].status == Status::Verified
                && inside_domain(&roots[j], unknowns) >= inside_domain(&roots[i], unknowns)
                && same_root(
                    sys,
                    &roots[i].enclosure,
                    &roots[j].enclosure,
                    unknowns,
                    SEAM_BITS.max(roots[i].bits).max(roots[j].bits),
                )
        });
        if copy_of.is_some() {
            roots.remove(i);
        } else {
            i += 1;
        }
    }
    drop_covered_undecided(sys, roots, unknowns);
}

/// Drop an undecided box that holds a verified root's box (up to whole periods) when
/// one Krawczyk step proves a single root in it ([`same_root`]): its only root is then
/// the verified one. Otherwise both stay (the box may hold another root).
fn drop_covered_undecided<S: System>(sys: &S, roots: &mut Vec<CertifiedRoot>, unknowns: &Unknowns) {
    let mut i = 0;
    while i < roots.len() {
        let u = &roots[i];
        let covered = u.status == Status::Undecided
            && roots.iter().any(|v| {
                v.status == Status::Verified
                    && super::shifted_inside(&v.enclosure, &u.enclosure, unknowns)
                    && same_root(
                        sys,
                        &v.enclosure,
                        &u.enclosure,
                        unknowns,
                        SEAM_BITS.max(u.bits).max(v.bits),
                    )
            });
        if covered {
            roots.remove(i);
        } else {
            i += 1;
        }
    }
}

/// How many of the root's estimate coordinates lie inside the domain (prefer those).
fn inside_domain(r: &CertifiedRoot, unknowns: &Unknowns) -> usize {
    r.params
        .iter()
        .zip(&unknowns.domain)
        .filter(|(x, [lo, hi])| lo <= *x && *x <= hi)
        .count()
}

/// The boxes `a` and `b` hold the same root, up to whole periods (module doc).
fn same_root<S: System>(
    sys: &S,
    a: &[Interval],
    b: &[Interval],
    unknowns: &Unknowns,
    bits: u32,
) -> bool {
    let mut hull = Vec::with_capacity(a.len());
    for i in 0..a.len() {
        let shifts = if unknowns.periodic[i] {
            let p = unknowns.period(i);
            vec![Interval::point(0.0), p, -p]
        } else {
            vec![Interval::point(0.0)]
        };
        let Some(s) = shifts
            .into_iter()
            .map(|s| a[i] + s)
            .find(|s| !s.intersection(&b[i]).is_empty())
        else {
            return false;
        };
        hull.push(s.hull(&b[i]));
    }
    // Room for the Krawczyk image: grow the hull by a relative margin.
    let h = boxes::inflate_scaled(&hull, 0.5, 1e-12);
    if matches!(krawczyk(sys, &h), Krawczyk::Unique(_)) {
        return true;
    }
    // In f64 the rounding of `F` at the midpoint can exceed that margin (coordinates
    // far larger than the shapes, e.g. a circle of radius 0.01 at x = −12: the two
    // copies of a seam root stayed apart). The same box in MPFR intervals: every
    // operation rounded outward at `bits`, so the step is as sound and its rounding
    // far below the margin.
    let hm: Vec<MpfrInterval> = h
        .iter()
        .map(|x| MpfrInterval::from_interval(x, bits))
        .collect();
    matches!(krawczyk(sys, &hm), Krawczyk::Unique(_))
}
