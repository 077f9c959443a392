//! All roots of a system in a parameter box (docs/CERTIFICATES.md "verified",
//! "verified_singular", "Completeness", "Escalation"): subdivision at f64 interval
//! precision; the boxes it cannot decide are grouped into clusters, each tried by the
//! cluster tests at rising precision; a cluster that stays undecided is subdivided again
//! at the next precision, up to the cap. What is left is reported as undecided, and
//! `complete` is claimed only when nothing is.
//!
//! What is proven is recorded in a [`Ledger`] (`super::ledger`), which merges roots
//! found twice.

use super::boxes::{self, IBox};
use super::cluster::{decide_cluster, ClusterVerdict};
use super::deflate::DoubleRoot;
use super::krawczyk::{krawczyk, Krawczyk, VerifiedRoot};
use super::ledger::Ledger;
use super::level::{box_at, box_to_mpfr, CertInterval};
use super::subdivide::{clusters_until, subdivide};
use super::system::{check_domain, check_system, System};
use super::{Options, Solutions};
use crate::certificate::Certified;
use crate::error::GeomError;
use crate::num::{Interval, MpfrInterval};

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
    separate(sys, &mut ledger);
    identify(sys, &mut ledger);
    Ok(ledger.finish(&dom))
}

/// Decide the boxes `bxs` starting at precision level `level` (module doc).
fn decide<S: System>(sys: &S, bxs: Vec<Vec<MpfrInterval>>, level: usize, ledger: &mut Ledger) {
    let bits = ledger.levels[level];
    let stuck = if bits == 53 {
        run::<S, Interval>(sys, bxs, bits, ledger)
    } else {
        run::<S, MpfrInterval>(sys, bxs, bits, ledger)
    };
    // Past the deadline many boxes left are one undecided region (issue 20).
    let groups = clusters_until(stuck, &|| ledger.late());
    for cluster in groups.into_iter().filter(|c| !c.is_empty()) {
        let hull = cluster[1..]
            .iter()
            .fold(cluster[0].clone(), |h, x| boxes::hull(&h, x));
        // A near-double root whose other half subdivision already proved: the cluster
        // tests must see both roots, or they call the one they see singular (a singular
        // box over a verified one, one root counted twice: issue 14).
        let hull = ledger.with_nearby_roots(&hull);
        if !ledger.take(CLUSTER_COST) {
            ledger.undecided(&hull, ledger.spent());
            continue;
        }
        let top = ledger.levels.len();
        let mut singular = None;
        let mut decided = false;
        for l in level..top {
            if ledger.late() {
                break;
            }
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
                // Nothing proven at this precision, not even a singular box: the
                // cluster is most often a simple root that subdivision at the next
                // precision decides at once, where the cluster tests at every higher
                // precision cost seconds to fail (issue 14: a circle 1e-9 from a
                // torus tube spent 3 s in them); subdivide at the next level, which
                // tries its own clusters again.
                None if singular.is_none() => break,
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
        } else if ledger.late() {
            ledger.undecided(&hull, super::TIME_LIMIT);
        } else if level + 1 < top {
            decide(sys, cluster, level + 1, ledger);
        } else {
            let reason = format!("precision cap of {} bits reached", ledger.levels[top - 1]);
            ledger.undecided(&hull, &reason);
        }
    }
}

/// Singular boxes next to proven roots, tried again together with them (issue 14: a
/// cluster holding one of two roots 1e-5 apart, whose other root subdivision had
/// proven, came back `verified_singular` at every precision, since its count region
/// held only one root): the cluster tests on the hull of both, at rising precision
/// (CERTIFICATION.md: raise the precision to separate close roots before falling back
/// to a singular box). Two proven roots replace the singular box; a singular verdict on
/// the hull (which then holds the proven root, counted by it) replaces it as well;
/// otherwise it stays, and [`Ledger`] reconciles what overlaps.
fn separate<S: System>(sys: &S, ledger: &mut Ledger) {
    while let Some((i, hull)) = ledger.untried_singular() {
        let mut singular = None;
        // the hull, then grown (a count region may cover a rounder box more easily)
        'grow: for grow in [0.0] {
            let region = boxes::inflate(&hull, grow, 0.0);
            for l in 0..ledger.levels.len() {
                if ledger.late() {
                    // the singular box stays as proven
                    break;
                }
                let bits = ledger.levels[l];
                match cluster_at(sys, &region, bits) {
                    Some(Decision::TwoRoots(roots)) => {
                        ledger.replace_singular(i, Ok(roots), bits);
                        singular = None;
                        break 'grow;
                    }
                    Some(Decision::Singular(e, d)) => {
                        singular.get_or_insert((e, d, bits));
                    }
                    // `NoRoot` cannot hold (a proven root is inside): nothing concluded
                    _ => {}
                }
            }
            if singular.is_some() {
                break;
            }
        }
        if let Some((e, d, bits)) = singular {
            ledger.replace_singular::<MpfrInterval>(i, Err((e, d)), bits);
        }
    }
}

/// Verified boxes that meet without either proof identifying the other's root
/// ([`Ledger::take_conflicts`]; issue 14: a root of a near tangency proven from two
/// clusters at once, its enclosures offset by less than their widths): Krawczyk on the
/// hull of both, grown by a sixteenth, at rising precision. `Unique` there proves that
/// both boxes hold the same root (each holds a root, and the grown hull holds only one),
/// which then lies in both enclosures and in the Krawczyk image: one root, recorded
/// once. Otherwise the hull is undecided. A merged root may meet another one in turn,
/// hence the passes (bounded; what is left is undecided by [`Ledger::finish`]).
fn identify<S: System>(sys: &S, ledger: &mut Ledger) {
    for _ in 0..4 {
        let pairs = ledger.take_conflicts();
        if pairs.is_empty() {
            return;
        }
        for [a, b] in pairs {
            let hull = boxes::hull(&a, &b);
            let levels = ledger.levels.clone();
            let late = || ledger.late();
            let proven = levels.into_iter().take_while(|_| !late()).find_map(|bits| {
                let v = if bits == 53 {
                    one_root_in::<S, Interval>(sys, &hull, bits)
                } else {
                    one_root_in::<S, MpfrInterval>(sys, &hull, bits)
                };
                v.map(|v| (v, bits))
            });
            match proven {
                Some((v, bits)) => {
                    let both = boxes::intersection(&v.enclosure, &a)
                        .and_then(|e| boxes::intersection(&e, &b))
                        .unwrap_or(v.enclosure);
                    ledger.root(
                        VerifiedRoot {
                            region: v.region,
                            enclosure: both,
                        },
                        bits,
                    );
                }
                None if ledger.late() => ledger.undecided(&hull, super::TIME_LIMIT),
                None => ledger.undecided(&hull, super::ledger::CONFLICT),
            }
        }
    }
}

/// Krawczyk on `hull` grown by a sixteenth (plus a few ulps) at `bits`: a root unique
/// there (region the grown box, enclosure the Krawczyk image), as MPFR boxes.
fn one_root_in<S: System, I: CertInterval>(
    sys: &S,
    hull: &[MpfrInterval],
    bits: u32,
) -> Option<VerifiedRoot<MpfrInterval>> {
    let h: IBox<I> = box_at(hull, bits);
    let ulps = (-(f64::from(bits) - 4.0)).exp2();
    let grown = boxes::inflate_scaled(&h, 1.0 / 16.0, ulps);
    match krawczyk(sys, &grown) {
        Krawczyk::Unique(k) => Some(VerifiedRoot {
            region: box_to_mpfr(&grown),
            enclosure: box_to_mpfr(&k),
        }),
        _ => None,
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
