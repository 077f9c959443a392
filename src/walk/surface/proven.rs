//! Surface steps whose turning-angle bound is proven (the interval version of §2.2).
//!
//! Over a window `W = [u, u+Δu] × [v, v+Δv]` the unit normal `n̂ = N/|N|`,
//! `N = s_u × s_v`, changes along `u` at the rate `|n̂_u| ≤ |N_u|/|N|` (the component of
//! `N_u` orthogonal to `n̂`, divided by `|N|`), with `N_u = s_uu × s_v + s_u × s_uv` and
//! `N_v = s_uv × s_v + s_u × s_vv`. Hence the normal turns by at most
//! `θ_u = Δu·sup_W |N_u|/inf_W |N|` along any `u`-line in the window and `θ_v` likewise;
//! any two normals of the window differ by at most `θ_u + θ_v` (a path along `u` then
//! `v` stays in the rectangle). The suprema come from one interval evaluation of the
//! jet over `W`, so the bounds are proven; where `N` may vanish in `W` they are infinite.

use crate::num::IntervalLike;
use crate::surface::vector::{add, cross, norm_sq};
use crate::surface::Surface;

/// Steps with their proven turning bounds.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ProvenSteps {
    /// The step in `u` (the window is clipped to the domain).
    pub du: f64,
    /// The step in `v`.
    pub dv: f64,
    /// `[θ_u, θ_v]`: proven upper bounds (radians) of the normal's turning along the
    /// coordinate lines of the window (`+∞` if unbounded).
    pub angle_bound: [f64; 2],
    /// Both bounds are at most `Δα`.
    pub within: bool,
}

/// Proven turning bounds over the window `[u, u+Δu] × [v, v+Δv]` (clipped to the
/// domain), evaluated in the interval type of `like` (module doc).
pub fn turning_bounds<S: Surface, T: IntervalLike>(
    surface: &S,
    like: &T,
    [u, v]: [f64; 2],
    [du, dv]: [f64; 2],
) -> [f64; 2] {
    let (dom_u, dom_v) = surface.domain();
    let (u1, v1) = ((u + du).min(dom_u[1]), (v + dv).min(dom_v[1]));
    let (wu, wv) = (
        like.with_bounds(u, u1.max(u)),
        like.with_bounds(v, v1.max(v)),
    );
    let jet = surface.jet(&wu, &wv, 2);
    let n_len = norm_sq(&cross(&jet[1], &jet[2])).sqrt();
    let n_u = add(&cross(&jet[3], &jet[2]), &cross(&jet[1], &jet[4]));
    let n_v = add(&cross(&jet[4], &jet[2]), &cross(&jet[1], &jet[5]));
    // θ = Δ·|N_d|/|N| with Δ an upper bound of the window's width.
    let bound = |rate_num: &[T; 3], width: f64| -> f64 {
        let theta = like.lift(width) * norm_sq(rate_num).sqrt() / n_len.clone();
        if theta.is_empty() {
            return f64::INFINITY;
        }
        let sup = theta.sup();
        if sup.is_nan() {
            f64::INFINITY
        } else {
            sup.max(0.0)
        }
    };
    // The widths u1 − u, v1 − v rounded up.
    let width = |a: f64, b: f64| (like.lift(b) - like.lift(a)).sup();
    [bound(&n_u, width(u, u1)), bound(&n_v, width(v, v1))]
}

/// Shrink the steps `[Δu, Δv]` at `(u, v)` (halving the direction whose proven bound
/// exceeds `Δα`, not below `min_steps`) until both turning bounds are proven `≤ Δα`,
/// or no step can shrink further (`within = false`).
pub fn proven_surface_steps<S: Surface, T: IntervalLike>(
    surface: &S,
    like: &T,
    at: [f64; 2],
    steps: [f64; 2],
    delta_alpha: f64,
    min_steps: [f64; 2],
) -> ProvenSteps {
    let mut steps = steps;
    loop {
        let bound = turning_bounds(surface, like, at, steps);
        let mut shrunk = false;
        for d in 0..2 {
            if bound[d] > delta_alpha && steps[d] / 2.0 >= min_steps[d] {
                steps[d] /= 2.0;
                shrunk = true;
            }
        }
        if !shrunk {
            return ProvenSteps {
                du: steps[0],
                dv: steps[1],
                angle_bound: bound,
                within: bound[0] <= delta_alpha && bound[1] <= delta_alpha,
            };
        }
    }
}
