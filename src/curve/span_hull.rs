//! A tight enclosure of a Bézier or B-spline (NURBS) curve piece over a wide parameter
//! interval, from the convex hull of its Bézier form there (OPERATIONS.md §1.5
//! "Bézier", "NURBS" (1.11)–(1.12); the convex-hull property [Y 2.5], [Y 2.7.2]).
//!
//! Why: evaluating the basis functions at an interval parameter uses the parameter many
//! times (dependency), so a whole knot span of a rational curve gets a weight enclosure
//! that holds 0 and a point enclosure that is unbounded, and a search by subdivision
//! cannot exclude anything there.
//!
//! How, on `[a, b]` inside one span `s` (or continued beyond it, for a pinned piece):
//! the homogeneous piece `(wP, w)` is a polynomial of degree `p`, and its Bézier control
//! points on `[a, b]` are the blossom values `b_k = f(a^{p−k}, b^k)`
//! ([`super::bspline::blossom`]). With `τ = (t − a)/(b − a) ∈ [0, 1]` the Bernstein
//! polynomials are `≥ 0` and sum to 1, so for every `t ∈ [a, b]`:
//! - the homogeneous value lies in the hull of the `b_k`, and its `j`-th derivative,
//!   `p!/(p−j)!·(b − a)^{−j}·Σ Δʲb_k B_{k,p−j}(τ)`, in `p!/(p−j)!·(b − a)^{−j}·hull(Δʲb_k)`;
//! - when every weight `w_k` of the `b_k` is positive (checked on its enclosure), the
//!   point `Σ (B_k w_k / Σ B_i w_i)·(wP)_k/w_k` is a convex combination of the projected
//!   control points: it lies in their hull;
//! - the derivatives follow by the quotient rule (`super::rational`), each term an
//!   enclosure of its value at the same `t`.
//!
//! Every step is f64 interval arithmetic rounded outward from the exact knots, control
//! data and bounds, so each result encloses the exact value. The hull of the point is
//! the true range plus `O((b − a)²)`; the derivative hulls divide differences by
//! `(b − a)ʲ` and are poor on narrow intervals, which is why the curves intersect this
//! enclosure with the basis evaluation rather than replace it ([`meet`]), and only on
//! [`wide`] intervals.

use super::bspline::blossom;
use super::rational::quotient_jet_from;
use crate::num::{Interval, Real};

/// The jet (orders `0..=order`) of the piece on span `s` of `knots` (degree `p`), whose
/// control points `s−p … s` are `rows` (homogeneous `(wP, w)` when `rational`, else
/// `P`), over `t ∈ [a, b]`. `None` when `[a, b]` is not a finite interval of positive
/// width, or a weight of the Bézier form is not proven positive.
pub(crate) fn hull_jet<const D: usize>(
    knots: &[f64],
    p: usize,
    s: usize,
    rows: &[Vec<Interval>],
    rational: bool,
    [a, b]: [f64; 2],
    order: usize,
) -> Option<Vec<[Interval; D]>> {
    if !(a < b && a.is_finite() && b.is_finite()) {
        return None;
    }
    let (ia, ib) = (Interval::point(a), Interval::point(b));
    let ctrl: Vec<Vec<Interval>> = (0..=p)
        .map(|k| {
            let xs: Vec<Interval> = (0..p).map(|r| if r < p - k { ia } else { ib }).collect();
            blossom(knots, p, s, &xs, rows.to_vec())
        })
        .collect();
    if rational && !ctrl.iter().all(|c| c[D].lo() > 0.0) {
        return None;
    }
    let m = ctrl[0].len();
    let hull_of = |pts: &[Vec<Interval>], c: usize| {
        pts.iter()
            .map(|q| q[c])
            .reduce(|x, y| x.hull(&y))
            .unwrap_or(Interval::EMPTY)
    };
    let width = ib - ia;
    let mut homogeneous: Vec<Vec<Interval>> = vec![(0..m).map(|c| hull_of(&ctrl, c)).collect()];
    let (mut diff, mut factor) = (ctrl.clone(), Interval::point(1.0));
    for j in 1..=order {
        if j > p {
            homogeneous.push(vec![Interval::point(0.0); m]);
            continue;
        }
        diff = diff
            .windows(2)
            .map(|w| (0..m).map(|c| w[1][c] - w[0][c]).collect())
            .collect();
        factor = factor * Interval::point((p + 1 - j) as f64) / width;
        homogeneous.push((0..m).map(|c| hull_of(&diff, c) * factor).collect());
    }
    let numerator: Vec<[Interval; D]> = homogeneous
        .iter()
        .map(|row| std::array::from_fn(|c| row[c]))
        .collect();
    if !rational {
        return Some(numerator);
    }
    let weight: Vec<Interval> = homogeneous.iter().map(|row| row[D]).collect();
    let projected: Vec<Vec<Interval>> = ctrl
        .iter()
        .map(|q| (0..D).map(|c| q[c] / q[D]).collect())
        .collect();
    let point = std::array::from_fn(|c| hull_of(&projected, c));
    Some(quotient_jet_from(point, &numerator, &weight))
}

/// `jet ∩ hull`, entry by entry, when the parameter `t` is [`wide`] and `hull` (given
/// `[a, b]`, the f64 bounds of `t`, outward for MPFR intervals) has an enclosure;
/// otherwise `jet` unchanged. Both enclose the same values over `[a, b] ⊇ t`, so the
/// intersection does; an entry whose intersection comes out empty (it cannot for a
/// non-empty `t`) keeps the basis value. Only the value of each entry is narrowed
/// ([`Real::restrict_to`]), so its bookkeeping stays: the certifier's smoothness flag,
/// and the gradient of a `Dual` number (the derivative with respect to the variables
/// is that of the same function).
pub(crate) fn meet<T: Real, const D: usize>(
    mut jet: Vec<[T; D]>,
    t: &T,
    hull: impl FnOnce([f64; 2]) -> Option<Vec<[Interval; D]>>,
) -> Vec<[T; D]> {
    let (a, b) = t.bounds();
    let Some(h) = wide(a, b).then(|| hull([a, b])).flatten() else {
        return jet;
    };
    for (row, hrow) in jet.iter_mut().zip(&h) {
        for (x, hx) in row.iter_mut().zip(hrow) {
            narrow(x, hx);
        }
    }
    jet
}

/// An interval parameter wide enough for the hull to pay: on narrower ones (Krawczyk's
/// boxes, MPFR point evaluations) the basis evaluation's overestimate, linear in the
/// width, is already negligible, and the hull's derivatives, differences divided by
/// powers of the width, are not.
pub(crate) fn wide(a: f64, b: f64) -> bool {
    b - a > 1e-6 * (1.0 + a.abs().max(b.abs()))
}

/// `x ∩ h` into `x`, unless that is empty (then `x` stays): for two enclosures of the
/// same value, of which `x` carries the bookkeeping (shared with `surface::patch_hull`).
pub(crate) fn narrow<T: Real>(x: &mut T, h: &Interval) {
    let narrowed = x.restrict_to(h.lo(), h.hi());
    let (lo, hi) = narrowed.bounds();
    if lo <= hi {
        *x = narrowed;
    }
}
