//! Two space curves (OPERATIONS.md §6.5), certified as far as floating point can:
//! `c₁(t₁) = c₂(t₂)` is three equations in two unknowns, so a crossing is not a
//! transversal root that interval Newton could prove — two generic space curves miss
//! each other, and a computed "intersection" is a near miss until the gap is shown to
//! be exactly zero, which needs exact arithmetic on algebraic data.
//!
//! What is proven here: subdivision of the `(t₁, t₂)` domain with exclusion — a box is
//! discarded when some coordinate of `c₁(T₁) − c₂(T₂)` excludes 0 (centred form
//! `c(m) + c'(T)(T − m)`, each piece an interval enclosure) — so `complete` with no
//! point means *proven disjoint*. Boxes that cannot be excluded down to the width
//! limit are merged into clusters and reported `undecided`, each with its parameter
//! and point boxes and an upper bound of the gap there: the curves come that close,
//! and whether they touch is not decided.

use crate::certificate::{Arithmetic, Certified, Status};
use crate::curve::Curve;
use crate::num::Interval;
use crate::ops::certified::{curve_unknowns, CertifiedPoint, CertifiedRoot, Options};

/// A centred-form enclosure of `c` over `t` (each coordinate `c(m) + c'(t)(t − m)`,
/// intersected with the direct enclosure).
fn enclose<C: Curve<3>>(c: &C, t: &Interval) -> [Interval; 3] {
    let m = Interval::point(t.midpoint());
    let at_m = c.jet(&m, 0).swap_remove(0);
    let j = c.jet(t, 1);
    let dt = *t - m;
    std::array::from_fn(|i| {
        let centred = at_m[i] + j[1][i] * dt;
        let both = centred.intersection(&j[0][i]);
        if both.is_empty() {
            j[0][i]
        } else {
            both
        }
    })
}

/// The gap `c₁ − c₂` over a parameter box.
fn gap<A: Curve<3>, B: Curve<3>>(a: &A, b: &B, x: &[Interval; 2]) -> [Interval; 3] {
    let (p, q) = (enclose(a, &x[0]), enclose(b, &x[1]));
    std::array::from_fn(|i| p[i] - q[i])
}

/// All points where two space curves may meet (module doc).
pub fn intersect_curve_curve<A: Curve<3>, B: Curve<3>>(
    a: &A,
    b: &B,
    opts: &Options,
) -> Certified<Vec<CertifiedPoint<3>>> {
    let search = [
        curve_unknowns(a).search_box(),
        curve_unknowns(b).search_box(),
    ];
    let start = [
        Interval::from_bounds(search[0][0][0], search[0][0][1]),
        Interval::from_bounds(search[1][0][0], search[1][0][1]),
    ];
    let scale = [start[0].width().max(1.0), start[1].width().max(1.0)];
    let min_width = 1e-12;
    let mut stack = vec![start];
    let mut left: Vec<[Interval; 2]> = Vec::new();
    let mut boxes = 0usize;
    let mut complete = true;
    let mut stopped = "the box budget ran out";
    while let Some(x) = stack.pop() {
        boxes += 1;
        if gap(a, b, &x).iter().any(|g| !g.contains_zero()) {
            continue;
        }
        let rel = [x[0].width() / scale[0], x[1].width() / scale[1]];
        if rel[0].max(rel[1]) <= min_width {
            left.push(x);
            continue;
        }
        // The deadline is checked every 64 boxes (issue 20), as the budget is.
        let late = boxes.is_multiple_of(64) && opts.late();
        if boxes >= opts.max_boxes || late {
            if late {
                stopped = crate::certify::TIME_LIMIT;
            }
            complete = false;
            left.push(x);
            left.append(&mut stack);
            break;
        }
        let k = usize::from(rel[1] > rel[0]);
        let (lo, hi) = x[k].bisect();
        let (mut first, mut second) = (x, x);
        first[k] = lo;
        second[k] = hi;
        stack.push(first);
        stack.push(second);
    }
    let periods = [
        curve_unknowns(a).periodic[0].then(|| start[0].width()),
        curve_unknowns(b).periodic[0].then(|| start[1].width()),
    ];
    let mut points: Vec<CertifiedPoint<3>> =
        drop_seam_copies(clusters(left, &|| opts.late()), periods)
            .into_iter()
            .map(|x| candidate(a, b, x))
            .collect();
    points.sort_by(|p, q| p.root.params[0].total_cmp(&q.root.params[0]));
    let undecided = !points.is_empty();
    Certified {
        value: points,
        status: if undecided || !complete {
            Status::Undecided
        } else {
            Status::Verified
        },
        complete: complete && !undecided,
        arithmetic: Arithmetic::Interval,
        bits: 53,
        reason: if !complete {
            Some(format!("{stopped} before every box was excluded"))
        } else if undecided {
            Some("the curves come within the reported boxes of each other; a gap of exactly zero cannot be proven in floating point".into())
        } else {
            None
        },
        perturbation: None,
    }
}

/// Merge boxes that touch into their hulls (repeated until no two touch). Quadratic or
/// worse in the boxes: once `stop` says so (past the deadline, issue 20) and more than
/// [`LATE_BOXES`] are left, they are merged into one hull at once (coarser, still
/// covering every box).
fn clusters(mut boxes: Vec<[Interval; 2]>, stop: &dyn Fn() -> bool) -> Vec<[Interval; 2]> {
    let meets = |p: &[Interval; 2], q: &[Interval; 2]| {
        (0..2).all(|i| p[i].lo() <= q[i].hi() && q[i].lo() <= p[i].hi())
    };
    let mut out: Vec<[Interval; 2]> = Vec::new();
    while let Some(mut x) = boxes.pop() {
        if boxes.len() > LATE_BOXES && stop() {
            for y in boxes.drain(..) {
                x = [x[0].hull(&y[0]), x[1].hull(&y[1])];
            }
            out.push(x);
            break;
        }
        loop {
            let before = boxes.len();
            let mut rest = Vec::with_capacity(boxes.len());
            for y in boxes.drain(..) {
                if meets(&x, &y) {
                    x = [x[0].hull(&y[0]), x[1].hull(&y[1])];
                } else {
                    rest.push(y);
                }
            }
            boxes = rest;
            if boxes.len() == before {
                break;
            }
        }
        out.push(x);
    }
    out
}

/// More boxes than this left to merge after the deadline are merged into one hull.
const LATE_BOXES: usize = 256;

/// A cluster that, shifted by one period of a closed curve (`periods[i]`, the
/// parameter range's width, padded by an ulp-sized margin), meets an earlier cluster is
/// the same place seen across the seam: dropped (both are undecided candidates; the
/// kept box covers the place up to the period).
fn drop_seam_copies(boxes: Vec<[Interval; 2]>, periods: [Option<f64>; 2]) -> Vec<[Interval; 2]> {
    let near = |p: &Interval, q: &Interval, shift: f64| {
        let pad = 4.0 * f64::EPSILON * shift.abs().max(1.0);
        p.lo() + shift <= q.hi() + pad && q.lo() <= p.hi() + shift + pad
    };
    let mut out: Vec<[Interval; 2]> = Vec::new();
    for x in boxes {
        let copy = out.iter().any(|y| {
            let shifts = |i: usize| -> Vec<f64> {
                match periods[i] {
                    Some(p) => vec![0.0, p, -p],
                    None => vec![0.0],
                }
            };
            let across = |i: usize| shifts(i).into_iter().any(|s| near(&x[i], &y[i], s));
            (periods[0].is_some() || periods[1].is_some()) && across(0) && across(1)
        });
        if !copy {
            out.push(x);
        }
    }
    out
}

fn candidate<A: Curve<3>, B: Curve<3>>(a: &A, b: &B, x: [Interval; 2]) -> CertifiedPoint<3> {
    let params = vec![x[0].midpoint(), x[1].midpoint()];
    let point = a.jet(&params[0], 0)[0];
    let point_box = enclose(a, &x[0]);
    let g = gap(a, b, &x);
    let gap_upper = g.iter().map(|v| v.mag()).fold(0.0, f64::max);
    CertifiedPoint {
        root: CertifiedRoot {
            params,
            enclosure: x.to_vec(),
            status: Status::Undecided,
            max_roots: 0,
            bits: 53,
            perturbation: None,
            reason: Some(format!(
                "the gap |c₁ − c₂| is at most {gap_upper:e} per coordinate here; whether it is zero is not decided"
            )),
        },
        point,
        point_box,
    }
}
