//! Seeding of the curved operations: initial guesses come from the walks of
//! OPERATIONS.md §2 (curve samples `(t, Δt)`, surface nodes `(u, v, Δu, Δv)`), and an
//! unbounded line is clipped to the parameters that can meet a bounded shape at all,
//! so that the certifier's search domain is finite and `complete` covers every hit.

use std::f64::consts::PI;

use crate::certify;
use crate::curve::Curve;
use crate::error::GeomError;
use crate::num::Interval;
use crate::ops::options::Options;
pub(crate) use crate::surface::whole_box::{curve_box, surface_box};
use crate::surface::Surface;
use crate::walk::surface::{SurfaceWalk, SurfaceWalkOptions};
use crate::walk::{CurveWalk, WalkOptions};

/// The turning angle Δα of the surface walks that seed the curved operations.
pub(crate) const TURN: f64 = PI / 10.0;

/// The most walk nodes (or samples) kept for seeding (issue 20): a legitimate walk
/// takes a few hundred; a degenerate one (a coordinate line of zero speed everywhere
/// takes the smallest step, `range·10⁻⁴`, in both directions) would take 10⁸ and
/// gigabytes. Beyond it the seeds are a [`GRID`] × [`GRID`] grid instead.
pub(crate) const MAX_SEEDS: usize = 1 << 16;

/// The side of the fallback grid of seeds.
pub(crate) const GRID: usize = 64;

/// Up to [`MAX_SEEDS`] items of `walk`, stopping early when `deadline` passes (checked
/// every 256 items); `Err(partial)` when the walk did not end.
fn bounded<T>(
    walk: impl Iterator<Item = T>,
    deadline: Option<std::time::Instant>,
) -> Result<Vec<T>, Vec<T>> {
    let mut out = Vec::new();
    for (i, x) in walk.enumerate() {
        if i >= MAX_SEEDS || (i % 256 == 0 && certify::past(deadline)) {
            return Err(out);
        }
        out.push(x);
    }
    Ok(out)
}

/// The curve's walk samples `(t, Δt)` (§2.1); a walk cut short by [`MAX_SEEDS`] or the
/// deadline gives [`GRID`]² evenly spaced samples instead. Seeds only propose
/// candidates: completeness comes from the certifier's subdivision, so fewer seeds
/// never make an answer wrong (at worst `undecided`).
pub(crate) fn curve_samples<const D: usize, C: Curve<D>>(
    c: &C,
    opts: &Options,
) -> Result<Vec<(f64, f64)>, GeomError> {
    let walk = CurveWalk::new(c, WalkOptions::default())?.map(|s| (s.t, s.step));
    Ok(bounded(walk, opts.deadline).unwrap_or_else(|_| {
        let (lo, hi) = c.domain();
        let n = GRID * GRID;
        let step = (hi - lo) / n as f64;
        (0..=n)
            .map(|i| ((lo + step * i as f64).min(hi), step))
            .collect()
    }))
}

/// The surface's walk nodes `(u, v, Δu, Δv)` (§2.2–§2.3); a walk cut short by
/// [`MAX_SEEDS`] or the deadline gives a [`GRID`] × [`GRID`] grid of nodes instead
/// (as [`curve_samples`]: seeds only).
pub(crate) fn surface_nodes<S: Surface>(s: &S, opts: &Options) -> Result<Vec<[f64; 4]>, GeomError> {
    let walk = SurfaceWalk::new(s, SurfaceWalkOptions::new(TURN))?.map(|n| [n.u, n.v, n.du, n.dv]);
    Ok(bounded(walk, opts.deadline).unwrap_or_else(|_| {
        let ([u0, u1], [v0, v1]) = s.domain();
        let (du, dv) = ((u1 - u0) / GRID as f64, (v1 - v0) / GRID as f64);
        (0..=GRID)
            .flat_map(|j| {
                (0..=GRID).map(move |i| {
                    let u = (u0 + du * i as f64).min(u1);
                    let v = (v0 + dv * j as f64).min(v1);
                    [u, v, du, dv]
                })
            })
            .collect()
    }))
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
