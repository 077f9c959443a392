//! Surface steps whose turning-angle bound is proven (the interval version of §2.2).
//!
//! Over a window `W = [u, u+Δu] × [v, v+Δv]` the unit normal `n̂ = N/|N|`,
//! `N = s_u × s_v`, changes along `u` at the rate `|n̂_u| = |N × N_u|/|N|²` (the
//! component of `N_u` orthogonal to `N`, divided by `|N|`), with
//! `N_u = s_uu × s_v + s_u × s_uv` and `N_v = s_uv × s_v + s_u × s_vv`. (Dropping the
//! `N ×` would also bound it, but the radial part of `N_u` blows up where `|N| → 0`, at
//! poles, while the true rate stays bounded.) Hence the normal turns by at most
//! `θ_u = Δu·sup_W |N × N_u|/|N|²` along any `u`-line in the window and `θ_v` likewise;
//! any two normals of the window differ by at most `θ_u + θ_v` (a path along `u` then
//! `v` stays in the rectangle). The suprema come from interval evaluations of the jet
//! over sub-boxes that cover `W`, so the bounds are proven; where `N` may vanish in `W`
//! they are infinite.

use crate::num::vector::{add, cross, norm_sq};
use crate::num::IntervalLike;
use crate::surface::Surface;

/// At most `2⁴ = 16`-fold smaller steps than the float walk's.
pub const MAX_HALVINGS: usize = 4;

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

/// `sup |N × N_d|/|N|²` for `d = u, v` over one box, from one interval jet (`+∞` where
/// `N` may vanish).
fn rate_sups<S: Surface, T: IntervalLike>(surface: &S, wu: &T, wv: &T) -> [f64; 2] {
    let jet = surface.jet(wu, wv, 2);
    let n = cross(&jet[1], &jet[2]);
    let n_sq = norm_sq(&n);
    let n_u = add(&cross(&jet[3], &jet[2]), &cross(&jet[1], &jet[4]));
    let n_v = add(&cross(&jet[4], &jet[2]), &cross(&jet[1], &jet[5]));
    [n_u, n_v].map(|n_d| {
        let rate = norm_sq(&cross(&n, &n_d)).sqrt() / n_sq.clone();
        let sup = rate.sup();
        if rate.is_empty() || sup.is_nan() {
            f64::INFINITY
        } else {
            sup.max(0.0)
        }
    })
}

/// Proven turning bounds `[θ_u, θ_v]` over the window `[u, u+Δu] × [v, v+Δv]` (clipped
/// to the domain), evaluated in the interval type of `like` on `splits × splits`
/// sub-boxes that cover it (the suprema are the largest over the sub-boxes; more splits,
/// less overestimation) (module doc).
pub fn turning_bounds<S: Surface, T: IntervalLike>(
    surface: &S,
    like: &T,
    [u, v]: [f64; 2],
    [du, dv]: [f64; 2],
    splits: usize,
) -> [f64; 2] {
    let (dom_u, dom_v) = surface.domain();
    let (u1, v1) = ((u + du).min(dom_u[1]).max(u), (v + dv).min(dom_v[1]).max(v));
    let k = splits.max(1);
    // Sub-box ends computed once, so neighbours share them exactly: the boxes cover W.
    let cuts = |a: f64, b: f64| -> Vec<f64> {
        (0..=k)
            .map(|i| {
                if i == k {
                    b
                } else {
                    a + (b - a) * (i as f64 / k as f64)
                }
            })
            .collect()
    };
    let (cu, cv) = (cuts(u, u1), cuts(v, v1));
    let mut rate = [0.0f64; 2];
    for i in 0..k {
        for j in 0..k {
            let r = rate_sups(
                surface,
                &like.with_bounds(cu[i], cu[i + 1]),
                &like.with_bounds(cv[j], cv[j + 1]),
            );
            rate = [rate[0].max(r[0]), rate[1].max(r[1])];
        }
    }
    // θ = Δ·rate, with Δ the window's width rounded up and the product rounded up.
    let theta = |a: f64, b: f64, r: f64| {
        if r.is_infinite() {
            return f64::INFINITY;
        }
        let width = like.lift(b) - like.lift(a);
        (width * like.lift(r)).sup().max(0.0)
    };
    [theta(u, u1, rate[0]), theta(v, v1, rate[1])]
}

/// [`turning_bounds`] refined on 2 × 2 and 4 × 4 sub-boxes while a bound exceeds `Δα`
/// (each is proven, so the smaller one is kept).
fn refined_bounds<S: Surface, T: IntervalLike>(
    surface: &S,
    like: &T,
    at: [f64; 2],
    steps: [f64; 2],
    delta_alpha: f64,
) -> [f64; 2] {
    let mut bound = turning_bounds(surface, like, at, steps, 1);
    for splits in [2] {
        if bound[0] <= delta_alpha && bound[1] <= delta_alpha {
            break;
        }
        let finer = turning_bounds(surface, like, at, steps, splits);
        bound = [bound[0].min(finer[0]), bound[1].min(finer[1])];
    }
    bound
}

/// Shrink the steps `[Δu, Δv]` at `(u, v)` until both turning bounds are proven
/// `≤ Δα`: a direction whose bound exceeds `Δα` is halved, at most [`MAX_HALVINGS`] times
/// and not below `min_steps`. Where that is not enough — a window that contains a
/// singular point of the parametrisation, such as a pole, keeps an unbounded rate however
/// small it is — the smallest steps tried are returned with `within = false`.
pub fn proven_surface_steps<S: Surface, T: IntervalLike>(
    surface: &S,
    like: &T,
    at: [f64; 2],
    steps: [f64; 2],
    delta_alpha: f64,
    min_steps: [f64; 2],
) -> ProvenSteps {
    let mut steps = steps;
    let mut halvings = [0; 2];
    loop {
        let bound = refined_bounds(surface, like, at, steps, delta_alpha);
        let halve: [bool; 2] = std::array::from_fn(|d| {
            bound[d] > delta_alpha && steps[d] / 2.0 >= min_steps[d] && halvings[d] < MAX_HALVINGS
        });
        if !halve[0] && !halve[1] {
            return ProvenSteps {
                du: steps[0],
                dv: steps[1],
                angle_bound: bound,
                within: bound[0] <= delta_alpha && bound[1] <= delta_alpha,
            };
        }
        for d in 0..2 {
            if halve[d] {
                steps[d] /= 2.0;
                halvings[d] += 1;
            }
        }
    }
}
