//! The foot equations of point → surface (OPERATIONS.md §3.4, (3.9) and (3.11)), written
//! once over `Real` for the float path, the certifier and the pole test.

use crate::num::vector::{dot, sub};
use crate::num::Real;
use crate::surface::Surface;

/// (3.9) `[F₁, F₂]` and, with `jacobian`, the matrix of (3.11)
/// `[[(p−s)·s_uu − s_u·s_u, (p−s)·s_uv − s_v·s_u], [(p−s)·s_uv − s_u·s_v, (p−s)·s_vv − s_v·s_v]]`,
/// written once for every number type.
pub fn surface_foot_equations<T: Real, S: Surface>(
    surface: &S,
    p: &[T; 3],
    u: &T,
    v: &T,
    jacobian: bool,
) -> ([T; 2], Option<[[T; 2]; 2]>) {
    let jet = surface.jet(u, v, if jacobian { 2 } else { 1 });
    let d = sub(p, &jet[0]);
    let f = [dot(&d, &jet[1]), dot(&d, &jet[2])];
    let j = jacobian.then(|| {
        let (su, sv) = (&jet[1], &jet[2]);
        let uv = dot(&d, &jet[4]) - dot(su, sv);
        [
            [dot(&d, &jet[3]) - dot(su, su), uv.clone()],
            [uv, dot(&d, &jet[5]) - dot(sv, sv)],
        ]
    });
    (f, j)
}
