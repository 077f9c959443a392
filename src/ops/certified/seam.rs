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
//! `a + p = b`.

use super::{CertifiedRoot, Unknowns};
use crate::certificate::Status;
use crate::certify::boxes;
use crate::certify::krawczyk::{krawczyk, Krawczyk};
use crate::certify::System;
use crate::num::Interval;

/// Drop verified roots proven to be seam copies of another kept root; the copy kept
/// is the one whose estimate lies inside the domain (the first found on ties).
pub fn drop_seam_copies<S: System>(sys: &S, roots: &mut Vec<CertifiedRoot>, unknowns: &Unknowns) {
    if !unknowns.periodic.iter().any(|&p| p) {
        return;
    }
    let mut i = 0;
    while i < roots.len() {
        let copy_of = (0..roots.len()).find(|&j| {
            j != i
                && roots[i].status == Status::Verified
                && roots[j].status == Status::Verified
                && inside_domain(&roots[j], unknowns) >= inside_domain(&roots[i], unknowns)
                && same_root(sys, &roots[i].enclosure, &roots[j].enclosure, unknowns)
        });
        if copy_of.is_some() {
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

/// The boxes `a` and `b` hold the same root up to whole periods (module doc).
fn same_root<S: System>(sys: &S, a: &[Interval], b: &[Interval], unknowns: &Unknowns) -> bool {
    let mut hull = Vec::with_capacity(a.len());
    let mut shifted_any = false;
    for i in 0..a.len() {
        let shifts = if unknowns.periodic[i] {
            let p = unknowns.period(i);
            vec![Interval::point(0.0), p, -p]
        } else {
            vec![Interval::point(0.0)]
        };
        let Some((k, s)) = shifts
            .into_iter()
            .enumerate()
            .map(|(k, s)| (k, a[i] + s))
            .find(|(_, s)| !s.intersection(&b[i]).is_empty())
        else {
            return false;
        };
        shifted_any |= k > 0;
        hull.push(s.hull(&b[i]));
    }
    if !shifted_any {
        // Overlapping boxes without a shift are the subdivision's business.
        return false;
    }
    // Room for the Krawczyk image: grow the hull by a relative margin.
    let h = boxes::inflate_scaled(&hull, 0.5, 1e-12);
    matches!(krawczyk(sys, &h), Krawczyk::Unique(_))
}
