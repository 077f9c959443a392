//! What one call of [`super::solve`] has proven so far (CERTIFICATION.md "verified",
//! "verified_singular", "Completeness"): the roots, the boxes proven root-free, the boxes
//! left undecided, the box budget and the highest precision that decided anything —
//! written to by the subdivision and the cluster tests, turned into the result at the end.
//!
//! Roots found twice (a root near a bisection plane is seen from both sides, a cluster's
//! root may also be found by a neighbour) are merged by the uniqueness regions of their
//! Krawczyk proofs: a root unique in `X` whose twin's enclosure lies in `X` is that twin.

use super::boxes;
use super::deflate::DoubleRoot;
use super::krawczyk::VerifiedRoot;
use super::level::{box_to_f64, box_to_mpfr, levels, CertInterval};

/// What replaces a singular box in [`Ledger::replace_singular`]: two verified roots,
/// or a singular box (its enclosure and double root).
pub(super) type Replacement<I> = Result<Vec<VerifiedRoot<I>>, (Vec<I>, DoubleRoot<I>)>;
use super::{Options, Root, Solutions, UndecidedBox};
use crate::certificate::{Arithmetic, Certified, Status};
use crate::num::MpfrInterval;

/// Why two verified boxes that meet are reported undecided.
pub(super) const CONFLICT: &str = "two proven roots could not be told apart or identified";

/// What one call of [`super::solve`] has proven so far (module doc).
#[derive(Debug)]
pub struct Ledger {
    /// The caller's narrowest split width.
    pub min_width: f64,
    /// The precisions of the escalation, lowest first ([`levels`]).
    pub(super) levels: Vec<u32>,
    budget: usize,
    used: usize,
    deadline: Option<std::time::Instant>,
    found: Vec<Found>,
    /// Pairs of verified enclosures that meet without either proof identifying the
    /// other's root ([`Ledger::take_conflicts`]).
    conflicts: Vec<[Vec<MpfrInterval>; 2]>,
    undecided: Vec<UndecidedBox>,
    excluded_volume: f64,
    bits: u32,
}

/// A proven root (or singular box), stored exactly as MPFR intervals.
#[derive(Debug, Clone)]
struct Found {
    enclosure: Vec<MpfrInterval>,
    /// Boxes in which this root is the only one (none for a singular box).
    regions: Vec<Vec<MpfrInterval>>,
    estimate: Vec<f64>,
    status: Status,
    bits: u32,
    perturbation: Option<f64>,
    /// A singular box already tried against its proven neighbours ([`Ledger::untried_singular`]).
    tried: bool,
}

impl Found {
    fn is_same_as(&self, other: &Found) -> bool {
        let inside = |e: &[MpfrInterval], regions: &[Vec<MpfrInterval>]| {
            regions.iter().any(|r| boxes::is_subset(e, r))
        };
        inside(&self.enclosure, &other.regions) || inside(&other.enclosure, &self.regions)
    }

    fn to_root(&self) -> Root {
        Root {
            enclosure: box_to_f64(&self.enclosure),
            enclosure_mpfr: self.enclosure.clone(),
            estimate: self.estimate.clone(),
            status: self.status,
            bits: self.bits,
            perturbation: self.perturbation,
            max_roots: if self.status == Status::Verified {
                1
            } else {
                2
            },
        }
    }
}

impl Ledger {
    pub(super) fn new(opts: &Options) -> Self {
        Ledger {
            min_width: opts.min_width,
            levels: levels(opts.max_bits),
            budget: opts.max_boxes,
            used: 0,
            deadline: opts.deadline,
            found: Vec::new(),
            conflicts: Vec::new(),
            undecided: Vec::new(),
            excluded_volume: 0.0,
            bits: 53,
        }
    }

    /// Count one box against the budget; false once it is spent or the deadline has
    /// passed ([`Ledger::spent`] says which).
    pub fn take_box(&mut self) -> bool {
        self.take(1)
    }

    pub(super) fn take(&mut self, k: usize) -> bool {
        if self.used + k > self.budget || self.late() {
            return false;
        }
        self.used += k;
        true
    }

    /// Whether the deadline has passed ([`super::past`]).
    pub(super) fn late(&self) -> bool {
        super::past(self.deadline)
    }

    /// Why [`Ledger::take_box`] refused: the reason recorded with the boxes left.
    pub fn spent(&self) -> &'static str {
        if self.late() {
            super::TIME_LIMIT
        } else {
            "box budget spent"
        }
    }

    /// Record an undecided box (outward in doubles) and why.
    pub fn undecided<I: CertInterval>(&mut self, x: &[I], reason: &str) {
        self.undecided.push(UndecidedBox {
            enclosure: box_to_f64(x),
            reason: reason.to_string(),
        });
    }

    /// Record that a part of the domain of volume `vol` holds no root.
    pub fn exclude(&mut self, vol: f64, bits: u32) {
        self.excluded_volume += vol;
        self.bits = self.bits.max(bits);
    }

    /// Record a verified root, merging it with an earlier proof of the same root.
    pub fn root<I: CertInterval>(&mut self, v: VerifiedRoot<I>, bits: u32) {
        let enclosure = box_to_mpfr(&v.enclosure);
        let f = Found {
            estimate: boxes::midpoint_f64(&enclosure),
            enclosure,
            regions: vec![box_to_mpfr(&v.region)],
            status: Status::Verified,
            bits,
            perturbation: None,
            tried: false,
        };
        self.bits = self.bits.max(bits);
        for i in 0..self.found.len() {
            let e = &mut self.found[i];
            if e.status != Status::Verified {
                continue;
            }
            if e.is_same_as(&f) {
                if let Some(both) = boxes::intersection(&e.enclosure, &f.enclosure) {
                    e.estimate = boxes::midpoint_f64(&both);
                    e.enclosure = both;
                }
                e.regions.extend(f.regions);
                e.bits = e.bits.min(f.bits);
                return;
            }
            if boxes::meets(&e.enclosure, &f.enclosure) {
                // neither proof covers the other's root: one root or two, for the
                // caller to decide ([`Ledger::take_conflicts`])
                let e = self.found.remove(i);
                self.conflicts.push([e.enclosure, f.enclosure]);
                return;
            }
        }
        self.found.push(f);
    }

    /// The pairs of verified enclosures recorded so far that meet without either proof
    /// identifying the other's root (a root proven twice, from different boxes or at
    /// different precisions, or two roots closer than both enclosures): each holds a
    /// root, and the caller either proves one root unique in a box holding both (then
    /// it is one root, in their intersection) or records their hull undecided.
    pub(super) fn take_conflicts(&mut self) -> Vec<[Vec<MpfrInterval>; 2]> {
        std::mem::take(&mut self.conflicts)
    }

    /// Record a `verified_singular` box.
    pub fn singular<I: CertInterval>(&mut self, enclosure: &[I], d: &DoubleRoot<I>, bits: u32) {
        self.bits = self.bits.max(bits);
        self.found.push(Found {
            enclosure: box_to_mpfr(enclosure),
            regions: Vec::new(),
            estimate: boxes::midpoint_f64(&d.x),
            status: Status::VerifiedSingular,
            bits,
            perturbation: Some(d.perturbation()),
            tried: false,
        });
    }

    /// The first singular box not yet tried that has verified roots near it (meeting it
    /// grown by its own width on each side): its index and the hull of it and them —
    /// the region in which the cluster tests may separate a pair of close roots of
    /// which subdivision proved one and called the other's neighbourhood singular.
    pub(super) fn untried_singular(&mut self) -> Option<(usize, Vec<MpfrInterval>)> {
        loop {
            let i = self
                .found
                .iter()
                .position(|f| f.status == Status::VerifiedSingular && !f.tried)?;
            self.found[i].tried = true;
            let hull = self.with_nearby_roots(&self.found[i].enclosure.clone());
            if hull != self.found[i].enclosure {
                return Some((i, hull));
            }
        }
    }

    /// Replace entry `i` (a singular box) by the two roots or the singular box that the
    /// cluster tests proved on a region containing it.
    pub(super) fn replace_singular<I: CertInterval>(
        &mut self,
        i: usize,
        by: Replacement<I>,
        bits: u32,
    ) {
        self.found.remove(i);
        match by {
            Ok(roots) => {
                for r in roots {
                    self.root(r, bits);
                }
            }
            Err((enclosure, d)) => {
                self.singular(&enclosure, &d, bits);
                if let Some(last) = self.found.last_mut() {
                    last.tried = true;
                }
            }
        }
    }

    /// `hull` grown to hold the enclosures of the verified roots that meet it grown by
    /// its own width on each side: the neighbourhood in which a cluster may be one half
    /// of a pair of close roots whose other half is already proven.
    pub(super) fn with_nearby_roots(&self, hull: &[MpfrInterval]) -> Vec<MpfrInterval> {
        let near = boxes::inflate(hull, 1.0, 0.0);
        self.found
            .iter()
            .filter(|f| f.status == Status::Verified && boxes::meets(&f.enclosure, &near))
            .fold(hull.to_vec(), |h, f| boxes::hull(&h, &f.enclosure))
    }

    /// Make the reported boxes pairwise disjoint with every root counted once
    /// (CERTIFICATION.md "Tangency and near-tangency"). A singular box `S` holds at most
    /// two roots counted with multiplicity: two verified roots inside it are all of its
    /// roots, so `S` is dropped; one verified root inside it is one of them, so that box
    /// is dropped and `S` (which counts it) stays; a singular box inside another is
    /// counted by the outer one. Boxes that meet without either of these containments
    /// prove nothing about each other: their hull becomes undecided.
    fn reconcile(&mut self) {
        let mut i = 0;
        while i < self.found.len() {
            if self.found[i].status != Status::VerifiedSingular {
                i += 1;
                continue;
            }
            let s = self.found[i].enclosure.clone();
            let others: Vec<usize> = (0..self.found.len())
                .filter(|&j| j != i && boxes::meets(&self.found[j].enclosure, &s))
                .collect();
            if others.is_empty() {
                i += 1;
                continue;
            }
            let drop: Vec<usize> = if others
                .iter()
                .any(|&j| boxes::is_subset(&s, &self.found[j].enclosure))
            {
                // inside a verified box (one root) or a singular one (which counts it)
                vec![i]
            } else {
                self.drop_around(i, &others)
            };
            let mut drop = drop;
            drop.sort_unstable();
            for &j in drop.iter().rev() {
                self.found.remove(j);
            }
            // the list changed: start over (each pass removes at least one entry)
            i = 0;
        }
    }

    /// [`Self::reconcile`] for the singular box `i` and the boxes `others` that meet it
    /// (none of which holds it): which entries to drop.
    fn drop_around(&mut self, i: usize, others: &[usize]) -> Vec<usize> {
        let s = self.found[i].enclosure.clone();
        let inside = |f: &Found| boxes::is_subset(&f.enclosure, &s);
        let all_inside = others.iter().all(|&j| inside(&self.found[j]));
        let simple = others
            .iter()
            .filter(|&&j| self.found[j].status == Status::Verified)
            .count();
        if all_inside && simple == others.len() && simple >= 2 {
            vec![i]
        } else if all_inside {
            others.to_vec()
        } else {
            let hull = others
                .iter()
                .fold(s.clone(), |h, &j| boxes::hull(&h, &self.found[j].enclosure));
            self.undecided(&hull, "close roots could not be separated or counted");
            let mut all = others.to_vec();
            all.push(i);
            all
        }
    }

    /// The result of a finished run over the domain `dom`: the roots found inside it,
    /// those straddling its boundary, and the certificate (`complete` exactly when
    /// nothing is undecided; the status the weakest of the roots').
    pub(super) fn finish(mut self, dom: &[MpfrInterval]) -> Certified<Solutions> {
        for [a, b] in self.take_conflicts() {
            self.undecided(&boxes::hull(&a, &b), CONFLICT);
        }
        self.reconcile();
        let mut roots = Vec::new();
        let mut boundary_roots = Vec::new();
        for f in &self.found {
            if boxes::is_subset(&f.enclosure, dom) {
                roots.push(f.to_root());
            } else if boxes::meets(&f.enclosure, dom) {
                boundary_roots.push(f.to_root());
            }
        }
        let status = roots
            .iter()
            .chain(&boundary_roots)
            .fold(Status::Verified, |s, r| s.weakest(r.status));
        let perturbation = roots
            .iter()
            .chain(&boundary_roots)
            .filter_map(|r| r.perturbation)
            .reduce(f64::max);
        let complete = self.undecided.is_empty();
        let reason = self.undecided.first().map(|u| {
            format!(
                "{} undecided box(es); first: {}",
                self.undecided.len(),
                u.reason
            )
        });
        let bits = self.bits;
        let value = Solutions {
            roots,
            boundary_roots,
            undecided: self.undecided,
            excluded_volume: self.excluded_volume,
            domain_volume: boxes::volume(dom),
            boxes: self.used,
        };
        Certified {
            value,
            status,
            complete,
            arithmetic: Arithmetic::of_interval_bits(bits),
            bits,
            reason,
            perturbation,
        }
    }
}
