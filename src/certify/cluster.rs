//! Deciding a small region where subdivision got stuck — a cluster of narrow boxes
//! around a (nearly) singular root — in one go (docs/CERTIFICATES.md
//! "verified_singular"): a proven near miss (no root), two proven transversal roots, or a
//! `verified_singular` box (a double root of a perturbed problem, at most two roots of
//! the exact one).
//!
//! The proofs are [`super::count`] (at most two roots, or none, in a region covering the
//! cluster), [`super::krawczyk`] (each of two roots) and [`super::deflate`] (the double
//! root of the perturbed problem). Newton from points along the null direction supplies
//! the candidate roots; it only guides, never proves.

use super::boxes::{self, IBox};
use super::count::{at_most_two_roots, no_root, Local};
use super::deflate::{double_root, DoubleRoot};
use super::krawczyk::{verify_near, VerifiedRoot};
use super::level::CertInterval;
use super::linalg::null_vectors;
use super::newton::newton_point;
use super::system::System;

/// What was proven about a cluster's box.
#[derive(Debug, Clone)]
pub enum ClusterVerdict<I> {
    /// No root in the box.
    NoRoot,
    /// Exactly two roots in a region containing the box, each verified (they may lie
    /// outside the box itself).
    TwoRoots(Vec<VerifiedRoot<I>>),
    /// At most two roots, counted with multiplicity, in `enclosure` (which contains the
    /// box), and a double root of a perturbed problem in `enclosure`.
    Singular {
        enclosure: IBox<I>,
        double_root: DoubleRoot<I>,
    },
}

/// Decide the box `hull` (module doc), or `None` if nothing could be proven. A
/// `Singular` verdict is the weakest: a caller may try a higher precision for a
/// `NoRoot` or `TwoRoots` one.
pub fn decide_cluster<S: System, I: CertInterval>(
    sys: &S,
    hull: &[I],
) -> Option<ClusterVerdict<I>> {
    let m0 = boxes::midpoint_f64(hull);
    let (v0, u0, _) = null_vectors(&sys.jacobian(&m0))?;
    // the double root may lie a width away, or (a side of the hull narrowed to a few
    // ulps) a few ulps of this precision away
    let bits = hull.first()?.precision_bits();
    let near = boxes::inflate_scaled(hull, 1.0, (-(f64::from(bits) - 8.0)).exp2());
    let dr = double_root(sys, &boxes::midpoint(hull), &v0, &u0, 1.0)
        .filter(|d| boxes::is_subset(&d.x, &near));
    // Near a double root the two roots lie about symmetrically about it, and subdivision
    // may have left a cluster around one of them only (its partner stuck in a second
    // cluster, or proven): the target is made symmetric about the double root, so that a
    // count region covering it holds both and `two_roots` can prove both — else each
    // cluster's singular box held one root and the two met at the double root, which
    // proves nothing (issue 14; CERTIFICATION.md "Tangency and near-tangency").
    let (target, m) = match &dr {
        Some(d) => {
            let c = boxes::midpoint(&d.x);
            let both = boxes::hull(hull, &boxes::reflect(hull, &c));
            (boxes::hull(&both, &d.x), boxes::midpoint_f64(&d.x))
        }
        None => (hull.to_vec(), m0),
    };
    let (v, u, _) = null_vectors(&sys.jacobian(&m))?;
    // A perturbation enclosure containing 0 means the roots (if two) are closer than this
    // precision resolves: skip the Newton search, the caller escalates.
    let resolvable = dr.as_ref().is_none_or(|d| !d.e.contains_zero());
    let mut singular = None;
    // The target, then grown: a cluster between two close roots (around the double
    // root, holding neither) has them outside its count region, and was called singular
    // beside the two verified roots (issue 14). The smallest singular box is kept.
    for grow in TARGET_GROWTH {
        let region = boxes::inflate(&target, grow, 0.0);
        let local = Local::new(sys, &m, &v, &u)?;
        let Some(count) = at_most_two_roots(local, &region) else {
            break;
        };
        if no_root(&count, 0.0) {
            return Some(ClusterVerdict::NoRoot);
        }
        if resolvable {
            if let Some(two) = two_roots(sys, &count, &region) {
                return Some(ClusterVerdict::TwoRoots(two));
            }
        }
        if singular.is_none() {
            singular = dr.as_ref().and_then(|d| {
                (count.covers(&region) && boxes::is_subset(&d.x, &region)).then(|| {
                    ClusterVerdict::Singular {
                        enclosure: region.clone(),
                        double_root: d.clone(),
                    }
                })
            });
        }
        if !resolvable {
            break;
        }
    }
    singular
}

/// How far [`decide_cluster`] grows its target (each side by this many widths) when the
/// count proves at most two roots but Newton finds them outside the count region.
const TARGET_GROWTH: [f64; 3] = [0.0, 1.0, 4.0];

/// Two verified roots inside the count region, found by Newton from points along the
/// null direction on both sides of the centre (each candidate proven by Krawczyk with
/// epsilon-inflation; a candidate inside the uniqueness region of an earlier one is the
/// same root).
fn two_roots<S: System, I: CertInterval>(
    sys: &S,
    count: &super::count::CountRegion<'_, S, I>,
    target: &[I],
) -> Option<Vec<VerifiedRoot<I>>> {
    let n = target.len();
    let reach = count.region[n - 1].mag();
    let bits = target[0].precision_bits();
    let ulps = (-(f64::from(bits) - 8.0)).exp2();
    let zero = target[0].zero_like();
    let mut roots: Vec<VerifiedRoot<I>> = Vec::new();
    for j in [1, 3, 5, 8, 12, 17, 24, 33, 45] {
        for sign in [1.0, -1.0] {
            let s = sign * reach * (-f64::from(j)).exp2();
            let mut w = vec![zero.clone(); n];
            w[n - 1] = zero.lift(s);
            let start: IBox<I> = count
                .local
                .to_global(&w)
                .iter()
                .map(|x| x.mid_interval())
                .collect();
            let Some((x, _)) = newton_point(sys, &start, 100) else {
                continue;
            };
            if !count.covers(&x) || roots.iter().any(|r| boxes::is_subset(&x, &r.region)) {
                continue;
            }
            let radius: Vec<f64> = x.iter().map(|v| ulps * v.mag().max(1.0)).collect();
            let Some(v) = verify_near(sys, &x, &radius, reach) else {
                continue;
            };
            if !count.covers(&v.enclosure)
                || roots
                    .iter()
                    .any(|r| boxes::meets(&r.enclosure, &v.enclosure))
            {
                continue;
            }
            roots.push(v);
            if roots.len() == 2 {
                return Some(roots);
            }
        }
    }
    None
}
