//! Subdivision of a parameter box at one precision (docs/CERTIFICATES.md "Completeness"):
//! every box is excluded (its image misses 0, or its Krawczyk image misses it), decided
//! by a unique root (Krawczyk on the box grown by a sixteenth, so that roots on a
//! bisection plane are still caught), narrowed by `X ∩ K(X)`, or bisected — until it is
//! too narrow for the precision, when it is handed back as *stuck* (for cluster
//! analysis and escalation), or the box budget is spent.

use super::boxes::{self, IBox};
use super::krawczyk::{excluded_by_image, image, krawczyk, narrow_unique, Krawczyk, VerifiedRoot};
use super::ledger::Ledger;
use super::level::CertInterval;
use super::system::System;
use crate::num::IntervalLike;

/// The width below which a side is too narrow to split at `bits` bits, relative to
/// `max(1, |x|)`: `2^-(bits/4 + 3)` (about 1e-5 for f64 intervals, 3e-11 at 128 bits). Near
/// a double root, the undecided region of width `w` holds about `w^-1/2` boxes, so a
/// quarter of the precision keeps the count small; what is still undecided goes to the
/// cluster tests, which work at any width.
pub fn stuck_width(bits: u32) -> f64 {
    (-(f64::from(bits) / 4.0 + 3.0)).exp2()
}

/// Subdivide `start` at the precision of `I`. Roots, exclusions and undecided boxes go to
/// the ledger; the stuck boxes are returned.
pub fn subdivide<S: System, I: CertInterval>(
    sys: &S,
    start: Vec<IBox<I>>,
    bits: u32,
    ledger: &mut Ledger,
) -> Vec<IBox<I>> {
    let n = sys.dim();
    let rel = stuck_width(bits);
    let min_width = ledger.min_width;
    let narrow = |v: &I| min_width.max(rel * v.mag().max(1.0));
    let mut stack = start;
    let mut stuck = Vec::new();
    while let Some(x) = stack.pop() {
        if !ledger.take_box() {
            ledger.undecided(&x, ledger.spent());
            for rest in stack.drain(..) {
                ledger.undecided(&rest, ledger.spent());
            }
            break;
        }
        let vol = boxes::volume(&x);
        if excluded_by_image(&image(sys, &x), n) || excluded_by_implied(sys, &x) {
            ledger.exclude(vol, bits);
            continue;
        }
        let Some(x) = krawczyk_test(sys, x, bits, ledger) else {
            continue;
        };
        if boxes::all_narrow(&x, narrow) {
            stuck.push(x);
            continue;
        }
        match boxes::bisect(&x) {
            Some((a, b)) => {
                stack.push(a);
                stack.push(b);
            }
            None => stuck.push(x),
        }
    }
    stuck
}

/// One of [`System::implied`]'s values is proven nonzero over `x`: no root there.
fn excluded_by_implied<S: System, I: CertInterval>(sys: &S, x: &[I]) -> bool {
    sys.implied(x)
        .iter()
        .any(|v| v.is_empty() || !v.contains_zero())
}

/// Krawczyk on `x` grown by a sixteenth (then on `x` itself if the system is not smooth
/// on the grown box). Returns the part of `x` still undecided, or `None` if `x` is
/// decided (a root recorded, or no root).
fn krawczyk_test<S: System, I: CertInterval>(
    sys: &S,
    x: IBox<I>,
    bits: u32,
    ledger: &mut Ledger,
) -> Option<IBox<I>> {
    let vol = boxes::volume(&x);
    let ulps = (-(f64::from(bits) - 4.0)).exp2();
    let grown = boxes::inflate_scaled(&x, 1.0 / 16.0, ulps);
    let (region, verdict) = match krawczyk(sys, &grown) {
        Krawczyk::Inconclusive => {
            let v = krawczyk(sys, &x);
            (x.clone(), v)
        }
        v => (grown, v),
    };
    match verdict {
        Krawczyk::Unique(k) => {
            // exactly one root in `region ⊇ x`; it lies in `x` or not
            let enclosure = narrow_unique(sys, &region, k);
            if boxes::meets(&enclosure, &x) {
                ledger.root(VerifiedRoot { region, enclosure }, bits);
            } else {
                ledger.exclude(vol, bits);
            }
            None
        }
        Krawczyk::Image(k) => match boxes::intersection(&x, &k) {
            None => {
                ledger.exclude(vol, bits);
                None
            }
            Some(narrowed) => {
                ledger.exclude((vol - boxes::volume(&narrowed)).max(0.0), bits);
                Some(narrowed)
            }
        },
        Krawczyk::Inconclusive => Some(x),
    }
}

/// Group boxes into clusters of boxes that touch (closed boxes sharing a point), by a
/// sweep along the coordinate where the boxes spread most.
pub fn clusters<I: IntervalLike>(bxs: Vec<IBox<I>>) -> Vec<Vec<IBox<I>>> {
    clusters_until(bxs, &|| false)
}

/// [`clusters`] that gives up once `stop` says so (asked every 256 boxes of the sweep;
/// issue 20): then all the boxes are one cluster, a coarser grouping that is still
/// sound (a cluster is a union of touching groups). The sweep is quadratic where many
/// boxes share a coordinate range — thousands of undecided boxes along the common
/// arc of two nearly overlapping curves took seconds after the deadline had passed.
pub fn clusters_until<I: IntervalLike>(
    bxs: Vec<IBox<I>>,
    stop: &dyn Fn() -> bool,
) -> Vec<Vec<IBox<I>>> {
    let count = bxs.len();
    if count == 0 {
        return Vec::new();
    }
    let n = bxs[0].len();
    let axis = (0..n)
        .max_by(|&a, &b| {
            let spread = |k: usize| {
                let lo = bxs.iter().map(|x| x[k].inf()).fold(f64::INFINITY, f64::min);
                let hi = bxs
                    .iter()
                    .map(|x| x[k].sup())
                    .fold(f64::NEG_INFINITY, f64::max);
                let w = bxs.iter().map(|x| x[k].wid()).fold(0.0, f64::max);
                (hi - lo) / w.max(f64::MIN_POSITIVE)
            };
            spread(a).total_cmp(&spread(b))
        })
        .unwrap_or(0);
    let mut order: Vec<usize> = (0..count).collect();
    order.sort_by(|&a, &b| bxs[a][axis].inf().total_cmp(&bxs[b][axis].inf()));
    let mut parent: Vec<usize> = (0..count).collect();
    fn find(p: &mut [usize], mut i: usize) -> usize {
        while p[i] != i {
            p[i] = p[p[i]];
            i = p[i];
        }
        i
    }
    for (pos, &i) in order.iter().enumerate() {
        if pos % 256 == 255 && stop() {
            return vec![bxs];
        }
        for &j in &order[pos + 1..] {
            if bxs[j][axis].inf() > bxs[i][axis].sup() {
                break;
            }
            if boxes::meets(&bxs[i], &bxs[j]) {
                let (a, b) = (find(&mut parent, i), find(&mut parent, j));
                parent[a] = b;
            }
        }
    }
    let mut groups: Vec<Vec<IBox<I>>> = Vec::new();
    let mut slot = vec![usize::MAX; count];
    for (i, x) in bxs.into_iter().enumerate() {
        let r = find(&mut parent, i);
        if slot[r] == usize::MAX {
            slot[r] = groups.len();
            groups.push(Vec::new());
        }
        groups[slot[r]].push(x);
    }
    groups
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::certify::boxes::test_box as b;

    #[test]
    fn touching_boxes_form_one_cluster() {
        let bx = vec![
            b(&[(0.0, 1.0), (0.0, 1.0)]),
            b(&[(5.0, 6.0), (0.0, 1.0)]),
            b(&[(1.0, 2.0), (1.0, 2.0)]), // touches the first at a corner
            b(&[(2.0, 3.0), (5.0, 6.0)]),
            b(&[(4.0, 5.0), (0.5, 0.7)]), // touches the second
        ];
        let mut sizes: Vec<usize> = clusters(bx).iter().map(|c| c.len()).collect();
        sizes.sort_unstable();
        assert_eq!(sizes, vec![1, 2, 2]);
    }
}
