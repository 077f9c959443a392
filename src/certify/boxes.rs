//! Boxes (vectors of intervals of one type) and the set operations the certifier needs.
//! Every operation returns a box containing the exact result (inflation and hull only
//! grow; intersection of enclosures contains every point in both).

use crate::num::IntervalLike;

/// A box `X₁ × … × Xₙ`.
pub type IBox<I> = Vec<I>;

/// The midpoint of each side, as point intervals (Krawczyk's `m`).
pub fn midpoint<I: IntervalLike>(x: &[I]) -> IBox<I> {
    x.iter().map(|v| v.mid_interval()).collect()
}

/// The midpoint as doubles.
pub fn midpoint_f64<I: IntervalLike>(x: &[I]) -> Vec<f64> {
    x.iter().map(|v| v.mid()).collect()
}

/// The widths of the sides (rounded up).
pub fn widths<I: IntervalLike>(x: &[I]) -> Vec<f64> {
    x.iter().map(|v| v.wid()).collect()
}

/// The index of the widest side.
pub fn widest<I: IntervalLike>(x: &[I]) -> usize {
    let w = widths(x);
    (0..w.len())
        .max_by(|&i, &j| w[i].total_cmp(&w[j]))
        .unwrap_or(0)
}

/// The two halves of `x` split at the midpoint of its widest side; `None` if that side
/// cannot be split at the box's precision (a half would equal the whole).
pub fn bisect<I: IntervalLike>(x: &[I]) -> Option<(IBox<I>, IBox<I>)> {
    let k = widest(x);
    let (a, b) = x[k].bisect();
    if a == x[k] || b == x[k] || a.is_empty() || b.is_empty() {
        return None;
    }
    let mut left = x.to_vec();
    let mut right = x.to_vec();
    left[k] = a;
    right[k] = b;
    Some((left, right))
}

/// The mirror image `{2c − p : p ∈ x}` of `x` through the point `c` (interval
/// arithmetic in the type of `x`: the result contains the exact mirror image, and any box
/// will do where it is used — it only widens a region to be proven).
pub fn reflect<I: IntervalLike>(x: &[I], c: &[I]) -> IBox<I> {
    x.iter()
        .zip(c)
        .map(|(v, m)| m.clone() * &m.lift(2.0) - v)
        .collect()
}

/// `x` grown on every side by `rel·width + abs` (computed in the interval arithmetic of
/// `x`, so the result contains `x`).
pub fn inflate<I: IntervalLike>(x: &[I], rel: f64, abs: f64) -> IBox<I> {
    x.iter()
        .map(|v| {
            let d = rel * v.wid() + abs;
            let d = if d.is_finite() { d } else { f64::MAX };
            v.clone() + v.with_bounds(-d, d)
        })
        .collect()
}

/// `x` grown on every side by `rel·width + abs·max(1, |x|)` (relative to magnitude).
pub fn inflate_scaled<I: IntervalLike>(x: &[I], rel: f64, abs: f64) -> IBox<I> {
    x.iter()
        .map(|v| {
            let d = rel * v.wid() + abs * v.mag().max(1.0);
            let d = if d.is_finite() { d } else { f64::MAX };
            v.clone() + v.with_bounds(-d, d)
        })
        .collect()
}

/// `x ⊆ interior(y)` side by side (false if any side of `x` is empty).
pub fn is_interior<I: IntervalLike>(x: &[I], y: &[I]) -> bool {
    x.len() == y.len()
        && x.iter()
            .zip(y)
            .all(|(a, b)| !a.is_empty() && a.is_interior_subset(b))
}

/// `x ⊆ y` side by side (false if any side of `x` is empty).
pub fn is_subset<I: IntervalLike>(x: &[I], y: &[I]) -> bool {
    x.len() == y.len()
        && x.iter()
            .zip(y)
            .all(|(a, b)| !a.is_empty() && a.is_subset(b))
}

/// `x ∩ y`, or `None` if empty.
pub fn intersection<I: IntervalLike>(x: &[I], y: &[I]) -> Option<IBox<I>> {
    let out: IBox<I> = x.iter().zip(y).map(|(a, b)| a.intersection(b)).collect();
    (!out.iter().any(|v| v.is_empty())).then_some(out)
}

/// True if the closed boxes share a point.
pub fn meets<I: IntervalLike>(x: &[I], y: &[I]) -> bool {
    intersection(x, y).is_some()
}

/// The smallest box containing both.
pub fn hull<I: IntervalLike>(x: &[I], y: &[I]) -> IBox<I> {
    x.iter().zip(y).map(|(a, b)| a.hull(b)).collect()
}

/// The volume (product of widths; an f64 estimate for reporting, not a bound).
pub fn volume<I: IntervalLike>(x: &[I]) -> f64 {
    x.iter().map(|v| v.wid()).product()
}

/// Every side has width at most `tol(side)`.
pub fn all_narrow<I: IntervalLike>(x: &[I], tol: impl Fn(&I) -> f64) -> bool {
    x.iter().all(|v| v.wid() <= tol(v))
}

/// For the tests: the f64 interval box of the sides `(lo, hi)`.
#[cfg(test)]
pub(crate) fn test_box(s: &[(f64, f64)]) -> IBox<crate::num::Interval> {
    s.iter()
        .map(|&(l, h)| crate::num::Interval::from_bounds(l, h))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::test_box as b;
    use super::*;

    #[test]
    fn bisect_splits_the_widest_side() {
        let x = b(&[(0.0, 1.0), (0.0, 4.0)]);
        let (l, r) = bisect(&x).unwrap();
        assert_eq!(l, b(&[(0.0, 1.0), (0.0, 2.0)]));
        assert_eq!(r, b(&[(0.0, 1.0), (2.0, 4.0)]));
        let tiny = b(&[(1.0, 1.0 + f64::EPSILON)]);
        assert!(bisect(&tiny).is_none());
    }

    #[test]
    fn set_operations() {
        let x = b(&[(0.0, 1.0), (0.0, 1.0)]);
        let y = inflate(&x, 0.5, 0.0);
        assert_eq!(y, b(&[(-0.5, 1.5), (-0.5, 1.5)]));
        assert!(is_interior(&x, &y) && !is_interior(&y, &x) && is_subset(&x, &x));
        assert_eq!(
            intersection(&x, &b(&[(1.0, 2.0), (0.5, 3.0)])),
            Some(b(&[(1.0, 1.0), (0.5, 1.0)]))
        );
        assert!(intersection(&x, &b(&[(1.5, 2.0), (0.5, 3.0)])).is_none());
        assert_eq!(
            hull(&x, &b(&[(2.0, 3.0), (0.5, 0.6)])),
            b(&[(0.0, 3.0), (0.0, 1.0)])
        );
        assert_eq!(volume(&y), 4.0);
    }
}
