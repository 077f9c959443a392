//! A tight enclosure of a (rational) B-spline patch's point over a wide parameter box,
//! from the convex hull of its Bézier net there (OPERATIONS.md §1.6 (1.18); the
//! convex-hull property of tensor-product Bézier patches [Y 3.11]).
//!
//! On the span pair `(s_u, s_v)` the homogeneous patch `(wP, w)` is a tensor-product
//! polynomial of degrees `(p, q)`. Its Bézier net on `[a, b] × [c, d]` is the blossom
//! values `b_kl = f(a^{p−k} b^k; c^{q−l} d^l)`: each row's blossom in `u`
//! ([`crate::curve::bspline::blossom`]), then each resulting column's blossom in `v`.
//! The tensor Bernstein products are `≥ 0` and sum to 1 on the box, so the
//! homogeneous point lies in the hull of the `b_kl`, and when every weight `w_kl` is
//! proven positive the point is a convex combination of the projected points
//! `(wP)_kl / w_kl`: it lies in their hull. The arithmetic is f64 intervals rounded
//! outward from the exact knots, net and bounds, so the hull encloses the exact patch.
//! The centred form of `super::taylor` stays the enclosure of the derivatives and of
//! small boxes; this one only narrows the point of wide boxes ([`meet_point`]).

use super::tensor::Net;
use crate::curve::bspline::blossom;
use crate::curve::span_hull::{narrow, wide};
use crate::num::{Interval, Real};

/// The knots and degrees of a patch and the span pair to enclose.
pub(crate) struct SpanPair<'a> {
    pub knots: [&'a [f64]; 2],
    pub degrees: [usize; 2],
    pub spans: [usize; 2],
}

/// The blossom arguments `a^{p−k} b^k`.
fn arguments(p: usize, k: usize, [a, b]: [Interval; 2]) -> Vec<Interval> {
    (0..p).map(|r| if r < p - k { a } else { b }).collect()
}

/// The hull of the patch's point over `u ∈ [a, b]`, `v ∈ [c, d]` on the span pair (module
/// doc); `None` for non-finite bounds or a Bézier weight not proven positive.
pub(crate) fn point_hull(
    net: &Net,
    sp: &SpanPair,
    u: [f64; 2],
    v: [f64; 2],
) -> Option<[Interval; 3]> {
    if !u.iter().chain(&v).all(|x| x.is_finite()) || u[0] > u[1] || v[0] > v[1] {
        return None;
    }
    let [p, q] = sp.degrees;
    let [su, sv] = sp.spans;
    let iu = u.map(Interval::point);
    let iv = v.map(Interval::point);
    let homogeneous = |i: usize, j: usize| -> Vec<Interval> {
        let k = i * net.cols + j;
        let pt = net.points[k].map(Interval::point);
        match &net.weights {
            None => pt.to_vec(),
            Some(w) => {
                let w = Interval::point(w[k]);
                vec![pt[0] * w, pt[1] * w, pt[2] * w, w]
            }
        }
    };
    // Row i of the net (v index), its Bézier points in u on [a, b].
    let in_u: Vec<Vec<Vec<Interval>>> = (sv - q..=sv)
        .map(|i| {
            let rows: Vec<Vec<Interval>> = (su - p..=su).map(|j| homogeneous(i, j)).collect();
            (0..=p)
                .map(|k| blossom(sp.knots[0], p, su, &arguments(p, k, iu), rows.clone()))
                .collect()
        })
        .collect();
    let mut hull: Option<[Interval; 3]> = None;
    for k in 0..=p {
        let column: Vec<Vec<Interval>> = in_u.iter().map(|row| row[k].clone()).collect();
        for l in 0..=q {
            let b = blossom(sp.knots[1], q, sv, &arguments(q, l, iv), column.clone());
            let point: [Interval; 3] = match net.weights {
                None => [b[0], b[1], b[2]],
                Some(_) if b[3].lo() > 0.0 => [b[0] / b[3], b[1] / b[3], b[2] / b[3]],
                Some(_) => return None,
            };
            hull = Some(match hull {
                None => point,
                Some(h) => std::array::from_fn(|c| h[c].hull(&point[c])),
            });
        }
    }
    hull
}

/// The point of `jet` intersected with `hull(u, v)` (given the f64 bounds of `u` and `v`,
/// outward for MPFR intervals) when one of the parameters is [`wide`]; otherwise `jet`
/// unchanged. Both enclose the patch over the box, so the intersection does; a
/// coordinate whose intersection comes out empty keeps the jet's value. Only values are
/// narrowed ([`Real::restrict_to`]): the certifier's smoothness flag and a `Dual`
/// number's gradient stay those of the same function on the same span pair.
pub(crate) fn meet_point<T: Real>(
    mut jet: Vec<[T; 3]>,
    u: &T,
    v: &T,
    hull: impl FnOnce([f64; 2], [f64; 2]) -> Option<[Interval; 3]>,
) -> Vec<[T; 3]> {
    let (bu, bv) = (u.bounds(), v.bounds());
    if !(wide(bu.0, bu.1) || wide(bv.0, bv.1)) || jet.is_empty() {
        return jet;
    }
    let (bu, bv) = ([bu.0, bu.1], [bv.0, bv.1]);
    let Some(h) = hull(bu, bv) else {
        return jet;
    };
    for (x, hx) in jet[0].iter_mut().zip(&h) {
        narrow(x, hx);
    }
    jet
}
