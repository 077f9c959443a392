//! All roots of a system in a parameter box (docs/CERTIFICATES.md "verified",
//! "verified_singular", "Completeness", "Escalation"): subdivision at f64 interval
//! precision; the boxes it cannot decide are grouped into clusters, each tried by the
//! cluster tests at rising precision; a cluster that stays undecided is subdivided again
//! at the next precision, up to the cap. What is left is reported as undecided, and
//! `complete` is claimed only when nothing is.
//!
//! Roots found twice (a root near a bisection plane is seen from both sides, a cluster's
//! root may also be found by a neighbour) are merged by the uniqueness regions of their
//! Krawczyk proofs: a root unique in `X` whose twin's enclosure lies in `X` is that twin.

use super::boxes::{self, IBox};
use super::cluster::{decide_cluster, ClusterVerdict};
use super::deflate::DoubleRoot;
use super::krawczyk::VerifiedRoot;
use super::level::{box_at, box_to_f64, box_to_mpfr, levels, CertInterval};
use super::subdivide::{clusters, subdivide};
use super::system::{check_domain, check_system, System};
use super::{Options, Root, Solutions, UndecidedBox};
use crate::certificate::{Arithmetic, Certified, Status};
use crate::error::GeomError;
use crate::num::{Interval, MpfrInterval};

/// What one call of [`solve`] has proven so far.
#[derive(Debug)]
pub struct Ledger {
    /// The caller's narrowest split width.
    pub min_width: f64,
    levels: Vec<u32>,
    budget: usize,
    used: usize,
    found: Vec<Found>,
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
    fn new(opts: &Options) -> Self {
        Ledger {
            min_width: opts.min_width,
            levels: levels(opts.max_bits),
            budget: opts.max_boxes,
            used: 0,
            found: Vec::new(),
            undecided: Vec::new(),
            excluded_volume: 0.0,
            bits: 53,
        }
    }

    /// Count one box against the budget; false once it is spent.
    pub fn take_box(&mut self) -> bool {
        self.take(1)
    }

    fn take(&mut self, k: usize) -> bool {
        if self.used + k > self.budget {
            return false;
        }
        self.used += k;
        true
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
                // neither proof covers the other's root: one root or two, undecided
                let e = self.found.remove(i);
                let hull = boxes::hull(&e.enclosure, &f.enclosure);
                self.undecided(
                    &hull,
                    "two proven roots could not be told apart or identified",
                );
                return;
            }
        }
        self.found.push(f);
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
        });
    }
}

/// Every root of `sys` in the box `domain` (module doc), with the certificate of
/// docs/CERTIFICATES.md: each root `verified` (unique in its box) or `verified_singular`;
/// `complete` exactly when no part of the domain is left undecided.
///
/// Errors: a system of size 0 or above [`super::system::MAX_DIM`], or one whose `eval`
/// returns the wrong number of values; a domain of the wrong length, with a non-finite or
/// inverted side; invalid options.
pub fn solve<S: System>(
    sys: &S,
    domain: &[[f64; 2]],
    opts: &Options,
) -> Result<Certified<Solutions>, GeomError> {
    opts.check()?;
    check_domain(domain, sys.dim())?;
    let centre: Vec<f64> = domain.iter().map(|[lo, hi]| 0.5 * lo + 0.5 * hi).collect();
    check_system(sys, &centre)?;
    let dom: Vec<MpfrInterval> = domain
        .iter()
        .map(|&[lo, hi]| MpfrInterval::from_bounds(lo, hi, 53))
        .collect();
    let mut ledger = Ledger::new(opts);
    decide(sys, vec![dom.clone()], 0, &mut ledger);

    let mut roots = Vec::new();
    let mut boundary_roots = Vec::new();
    for f in &ledger.found {
        if boxes::is_subset(&f.enclosure, &dom) {
            roots.push(f.to_root());
        } else if boxes::meets(&f.enclosure, &dom) {
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
    let complete = ledger.undecided.is_empty();
    let reason = ledger.undecided.first().map(|u| {
        format!(
            "{} undecided box(es); first: {}",
            ledger.undecided.len(),
            u.reason
        )
    });
    let bits = ledger.bits;
    let value = Solutions {
        roots,
        boundary_roots,
        undecided: ledger.undecided,
        excluded_volume: ledger.excluded_volume,
        domain_volume: boxes::volume(&dom),
        boxes: ledger.used,
    };
    Ok(Certified {
        value,
        status,
        complete,
        arithmetic: if bits > 53 {
            Arithmetic::Mpfr
        } else {
            Arithmetic::Interval
        },
        bits,
        reason,
        perturbation,
    })
}

/// Decide the boxes `bxs` starting at precision level `level` (module doc).
fn decide<S: System>(sys: &S, bxs: Vec<Vec<MpfrInterval>>, level: usize, ledger: &mut Ledger) {
    let bits = ledger.levels[level];
    let stuck = if bits == 53 {
        run::<S, Interval>(sys, bxs, bits, ledger)
    } else {
        run::<S, MpfrInterval>(sys, bxs, bits, ledger)
    };
    for cluster in clusters(stuck) {
        let hull = cluster[1..]
            .iter()
            .fold(cluster[0].clone(), |h, x| boxes::hull(&h, x));
        if !ledger.take(CLUSTER_COST) {
            ledger.undecided(&hull, "box budget spent");
            continue;
        }
        let top = ledger.levels.len();
        let mut singular = None;
        let mut decided = false;
        for l in level..top {
            let bits = ledger.levels[l];
            match cluster_at(sys, &hull, bits) {
                Some(Decision::NoRoot) => {
                    let undecided: f64 = cluster.iter().map(|x| boxes::volume(x)).sum();
                    ledger.exclude(undecided, bits);
                    decided = true;
                }
                Some(Decision::TwoRoots(roots)) => {
                    for r in roots {
                        ledger.root(r, bits);
                    }
                    decided = true;
                }
                Some(Decision::Singular(enclosure, d)) => {
                    // keep the lowest precision's; a higher one may still split it
                    singular.get_or_insert((enclosure, d, bits));
                }
                None => {}
            }
            if decided {
                break;
            }
        }
        if decided {
            continue;
        }
        if let Some((enclosure, d, bits)) = singular {
            ledger.singular(&enclosure, &d, bits);
        } else if level + 1 < top {
            decide(sys, cluster, level + 1, ledger);
        } else {
            let reason = format!("precision cap of {} bits reached", ledger.levels[top - 1]);
            ledger.undecided(&hull, &reason);
        }
    }
}

/// What one attempt at a cluster costs from the box budget.
const CLUSTER_COST: usize = 16;

fn run<S: System, I: CertInterval>(
    sys: &S,
    bxs: Vec<Vec<MpfrInterval>>,
    bits: u32,
    ledger: &mut Ledger,
) -> Vec<Vec<MpfrInterval>> {
    let start: Vec<IBox<I>> = bxs.iter().map(|x| box_at(x, bits)).collect();
    subdivide(sys, start, bits, ledger)
        .iter()
        .map(|x| box_to_mpfr(x))
        .collect()
}

/// A cluster verdict with its boxes as MPFR intervals.
enum Decision {
    NoRoot,
    TwoRoots(Vec<VerifiedRoot<MpfrInterval>>),
    Singular(IBox<MpfrInterval>, DoubleRoot<MpfrInterval>),
}

/// The cluster tests on `hull` at `bits` bits.
fn cluster_at<S: System>(sys: &S, hull: &[MpfrInterval], bits: u32) -> Option<Decision> {
    if bits == 53 {
        cluster_in::<S, Interval>(sys, hull, bits)
    } else {
        cluster_in::<S, MpfrInterval>(sys, hull, bits)
    }
}

fn cluster_in<S: System, I: CertInterval>(
    sys: &S,
    hull: &[MpfrInterval],
    bits: u32,
) -> Option<Decision> {
    let h: IBox<I> = box_at(hull, bits);
    let up = |v: &VerifiedRoot<I>| VerifiedRoot {
        region: box_to_mpfr(&v.region),
        enclosure: box_to_mpfr(&v.enclosure),
    };
    Some(match decide_cluster(sys, &h)? {
        ClusterVerdict::NoRoot => Decision::NoRoot,
        ClusterVerdict::TwoRoots(roots) => Decision::TwoRoots(roots.iter().map(up).collect()),
        ClusterVerdict::Singular {
            enclosure,
            double_root,
        } => Decision::Singular(
            box_to_mpfr(&enclosure),
            DoubleRoot {
                x: box_to_mpfr(&double_root.x),
                e: double_root.e.to_mpfr(),
                kappa: double_root.kappa,
            },
        ),
    })
}
