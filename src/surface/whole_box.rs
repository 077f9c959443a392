//! Certified boxes of a whole curve or surface: the point over the whole parameter
//! domain, enclosed by interval evaluation on a grid of parameter pieces (used to
//! bound searches: seeding and clipping of unbounded lines in `ops`, the reach of
//! visibility rays).

use crate::curve::Curve;
use crate::num::vector::hull;
use crate::num::Interval;
use crate::surface::Surface;

/// Pieces per parameter direction in [`curve_box`] and [`surface_box`].
const BOX_PIECES: usize = 32;

/// `n` consecutive pieces `[x_k, x_{k+1}]` of `[lo, hi]`: `x_0 = lo`, `x_n = hi`, and
/// each inner `x_k` is used as the upper end of one piece and the lower end of the
/// next, so the pieces cover `[lo, hi]` whatever the rounding of `x_k`.
fn pieces(lo: f64, hi: f64, n: usize) -> Vec<Interval> {
    if !(lo.is_finite() && hi.is_finite()) || lo >= hi {
        return vec![Interval::from_bounds(lo, hi)];
    }
    let x = |k: usize| match k {
        0 => lo,
        k if k == n => hi,
        k => (lo + (hi - lo) * (k as f64 / n as f64)).clamp(lo, hi),
    };
    (0..n)
        .map(|k| Interval::from_bounds(x(k), x(k + 1)))
        .collect()
}

/// The intersection of two enclosures of the same set (both hold it, so does their
/// common part).
fn meet<const D: usize>(a: [Interval; D], b: &[Interval; D]) -> [Interval; D] {
    std::array::from_fn(|i| a[i].intersection(&b[i]))
}

/// A certified box of the whole surface (its point over the whole parameter domain):
/// the hull of its boxes over a grid of parameter pieces, met with its box over the
/// whole domain. One interval evaluation over a wide domain can be unbounded where a
/// rational form's denominator is not proven positive (NURBS); the pieces keep it tight.
pub fn surface_box<S: Surface>(s: &S) -> [Interval; 3] {
    let ([u0, u1], [v0, v1]) = s.domain();
    let point = |u: &Interval, v: &Interval| s.jet(u, v, 0).swap_remove(0);
    let whole = point(
        &Interval::from_bounds(u0, u1),
        &Interval::from_bounds(v0, v1),
    );
    let n = BOX_PIECES / 2;
    let (us, vs) = (pieces(u0, u1, n), pieces(v0, v1, n));
    let hull = us
        .iter()
        .flat_map(|u| vs.iter().map(move |v| (u, v)))
        .map(|(u, v)| point(u, v))
        .reduce(|a, b| hull(&a, &b));
    hull.map_or(whole, |h| meet(h, &whole))
}

/// A certified box of a whole curve (pieces as in [`surface_box`]).
pub fn curve_box<const D: usize, C: Curve<D>>(c: &C) -> [Interval; D] {
    let (lo, hi) = c.domain();
    let point = |t: &Interval| c.jet(t, 0).swap_remove(0);
    let whole = point(&Interval::from_bounds(lo, hi));
    let hull = pieces(lo, hi, BOX_PIECES)
        .iter()
        .map(point)
        .reduce(|a, b| hull(&a, &b));
    hull.map_or(whole, |h| meet(h, &whole))
}
