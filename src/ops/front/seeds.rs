//! Seeding of the curved operations: initial guesses come from the walks of
//! OPERATIONS.md §2 (curve samples `(t, Δt)`, surface nodes `(u, v, Δu, Δv)`), and an
//! unbounded line is clipped to the parameters that can meet a bounded shape at all,
//! so that the certifier's search domain is finite and `complete` covers every hit.

use std::f64::consts::PI;

use crate::curve::Curve;
use crate::error::GeomError;
use crate::num::Interval;
use crate::surface::Surface;
use crate::walk::surface::{SurfaceWalk, SurfaceWalkOptions};
use crate::walk::{CurveWalk, WalkOptions};

/// The turning angle Δα of the surface walks that seed the curved operations.
pub(crate) const TURN: f64 = PI / 10.0;

/// The curve's walk samples `(t, Δt)` (§2.1).
pub(crate) fn curve_samples<const D: usize, C: Curve<D>>(
    c: &C,
) -> Result<Vec<(f64, f64)>, GeomError> {
    Ok(CurveWalk::new(c, WalkOptions::default())?
        .map(|s| (s.t, s.step))
        .collect())
}

/// The surface's walk nodes `(u, v, Δu, Δv)` (§2.2–§2.3).
pub(crate) fn surface_nodes<S: Surface>(s: &S) -> Result<Vec<[f64; 4]>, GeomError> {
    Ok(SurfaceWalk::new(s, SurfaceWalkOptions::new(TURN))?
        .map(|n| [n.u, n.v, n.du, n.dv])
        .collect())
}

/// The parameters of `o + t·d` inside the box `bound` (slab method), widened outward so
/// that rounding cannot cut a hit off: every point of the line in the box has its `t`
/// in the range. A tiny range for a miss is fine (the solver then proves there is
/// nothing). `None` when the box is unbounded.
pub(crate) fn reach<const D: usize>(
    o: &[f64; D],
    d: &[f64; D],
    bound: &[Interval; D],
) -> Option<(f64, f64)> {
    let (mut lo, mut hi) = (f64::NEG_INFINITY, f64::INFINITY);
    for i in 0..D {
        if !(bound[i].lo().is_finite() && bound[i].hi().is_finite()) {
            return None;
        }
        if d[i] == 0.0 {
            continue;
        }
        let di = Interval::point(d[i]);
        let t1 = (Interval::point(bound[i].lo()) - Interval::point(o[i])) / di;
        let t2 = (Interval::point(bound[i].hi()) - Interval::point(o[i])) / di;
        let span = t1.hull(&t2);
        lo = lo.max(span.lo());
        hi = hi.min(span.hi());
    }
    if !(lo.is_finite() && hi.is_finite()) {
        return None;
    }
    let pad = 1e-9 * (hi - lo).abs().max(lo.abs()).max(hi.abs()).max(1.0);
    Some(if lo <= hi {
        (lo - pad, hi + pad)
    } else {
        (lo - pad, lo + pad)
    })
}

/// A certified box of the whole surface (its point over the whole parameter domain).
pub(crate) fn surface_box<S: Surface>(s: &S) -> [Interval; 3] {
    let ([u0, u1], [v0, v1]) = s.domain();
    let mut b = s.jet(
        &Interval::from_bounds(u0, u1),
        &Interval::from_bounds(v0, v1),
        0,
    );
    b.swap_remove(0)
}

/// A certified box of a whole curve.
pub(crate) fn curve_box<const D: usize, C: Curve<D>>(c: &C) -> [Interval; D] {
    let (lo, hi) = c.domain();
    c.jet(&Interval::from_bounds(lo, hi), 0).swap_remove(0)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_reach_of_a_line_covers_the_box() {
        let b = [Interval::from_bounds(-1.0, 1.0); 3];
        let (lo, hi) = reach(&[-5.0, 0.0, 0.0], &[2.0, 0.0, 0.0], &b).expect("bounded");
        assert!(lo <= 2.0 && hi >= 3.0 && hi - lo < 1.1);
    }

    #[test]
    fn only_finite_boxes_bound_a_line() {
        let b = [
            Interval::from_bounds(f64::NEG_INFINITY, 1.0),
            Interval::from_bounds(0.0, 1.0),
            Interval::from_bounds(0.0, 1.0),
        ];
        assert_eq!(reach(&[0.0; 3], &[1.0, 0.0, 0.0], &b), None);
    }
}
