//! The one formula behind every analytic surface of OPERATIONS.md §1.6 whose `u` is an
//! angle: in the local frame,
//!
//! `s(u, v) = (a·f(v)·cos u, b·f(v)·sin u, c·g(v))`,
//!
//! with the profile `(f, g)`: sphere and ellipsoid `(cos v, sin v)`, hyperboloids
//! `(cosh v, sinh v)` and `(sinh v, cosh v)`, paraboloid `(v, v²)`, cylinder `(1, v)`,
//! cone `(r + v tan α, v)`, torus `(R + r cos v, r sin v)`. Its derivatives:
//!
//! ```text
//! s_u  = (−a f sin u,  b f cos u,  0)      s_v  = (a f' cos u, b f' sin u, c g')
//! s_uu = (−a f cos u, −b f sin u,  0)      s_uv = (−a f' sin u, b f' cos u, 0)
//! s_vv = (a f'' cos u, b f'' sin u, c g'')
//! ```
//!
//! Interval evaluation encloses the exact jet: each entry is a composition of enclosing
//! [`Real`] operations on exact constants.

use super::frame::Frame;
use crate::num::Real;

/// The profile `[f, f', f'']` and `[g, g', g'']` at one `v` (entries beyond the
/// requested order are not read).
pub(crate) struct Profile<T> {
    pub f: [T; 3],
    pub g: [T; 3],
}

/// The jet of `s(u, v)` in world coordinates, given the profile at `v` (module doc).
pub(crate) fn rotational_jet<T: Real>(
    frame: &Frame,
    [a, b, c]: [f64; 3],
    u: &T,
    profile: &Profile<T>,
    order: usize,
) -> Vec<[T; 3]> {
    let (a, b, c) = (u.lift(a), u.lift(b), u.lift(c));
    let (cu, su) = (u.cos(), u.sin());
    let zero = u.zero_like();
    let [f, f1, f2] = &profile.f;
    let [g, g1, g2] = &profile.g;
    let af = a.clone() * f;
    let bf = b.clone() * f;
    let mut local = vec![[af.clone() * &cu, bf.clone() * &su, c.clone() * g]];
    if order >= 1 {
        let af1 = a.clone() * f1;
        let bf1 = b.clone() * f1;
        local.push([-(af.clone() * &su), bf.clone() * &cu, zero.clone()]);
        local.push([af1.clone() * &cu, bf1.clone() * &su, c.clone() * g1]);
        if order >= 2 {
            local.push([-(af * &cu), -(bf * &su), zero.clone()]);
            local.push([-(af1 * &su), bf1 * &cu, zero]);
            local.push([a * f2 * &cu, b * f2 * &su, c * g2]);
        }
    }
    frame.place_jet(&local)
}
