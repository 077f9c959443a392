//! Composite surface of two pieces joined along their intersection (OPERATIONS.md §14.3,
//! (14.8) with the corrected map (14.9)), union type: `R` is kept on `u ≤ u_c(v)`, `G`
//! between its intersection `t_c(v)` and its far end `t_far`:
//!
//! `S(u, v) = R(u, v)` for `f = u − u_c(v) ≤ 0`, else `G(t(u, v), v)` with
//! `t = t_c(v) + (t_far − t_c(v)) (u − u_c(v))/(u_p − u_c(v))`.
//!
//! The seam `u = u_c(v)` goes to `t = t_c(v)`, so `S` is continuous when the pieces meet
//! there, `G(t_c(v), v) = R(u_c(v), v)` (the caller's [`Seam`] says so: `G`'s second
//! parameter is synchronised with `R`'s `v`, as §14.3 requires after the poles were
//! re-assigned so that the intersection is a graph on both). \[S\]'s map
//! `t = t_c (u − u_c)/(u_p − u_c)` sends the seam to `t = 0` instead, which is a jump
//! unless `t_c = 0`.
//!
//! Enclosures: over an interval box on which the indicator `f` is surely `≤ 0` (or
//! surely `> 0`) the value is that piece's enclosure; where `f`'s enclosure straddles 0
//! both pieces are evaluated over the whole box and joined ([`Real::hull_with`]), which
//! contains the value of either piece on its part of the box.

use super::Surface;
use crate::error::GeomError;
use crate::num::vector::hull;
use crate::num::Real;

/// The intersection of the pieces as graphs `u = u_c(v)` on `R` and `t = t_c(v)` on `G`.
/// Interval arguments: each function encloses its exact value over the box.
pub trait Seam {
    fn u_c<T: Real>(&self, v: &T) -> T;
    fn t_c<T: Real>(&self, v: &T) -> T;
}

/// The union-type composite (module doc).
#[derive(Debug, Clone, PartialEq)]
pub struct Composite<R, G, C> {
    r: R,
    g: G,
    seam: C,
    /// `u_p`, the end of `R`'s `u` range that the `G` piece is mapped onto.
    u_p: f64,
    t_far: f64,
}

impl<R: Surface, G: Surface, C: Seam> Composite<R, G, C> {
    /// `t_far` must be an end of `G`'s first parameter range (its far pole); errors name
    /// `t_far`.
    pub fn new(r: R, g: G, seam: C, t_far: f64) -> Result<Self, GeomError> {
        let [t0, t1] = g.domain().0;
        if t_far != t0 && t_far != t1 {
            return Err(GeomError::InvalidValue {
                field: "t_far".into(),
                reason: format!("{t_far} is not an end of G's parameter range [{t0}, {t1}]"),
            });
        }
        let u_p = r.domain().0[1];
        Ok(Composite {
            r,
            g,
            seam,
            u_p,
            t_far,
        })
    }

    /// `G`'s first parameter (14.9) at `(u, v)` of the `G` piece.
    pub fn g_parameter<T: Real>(&self, u: &T, v: &T) -> T {
        let (uc, tc) = (self.seam.u_c(v), self.seam.t_c(v));
        let span = u.lift(self.u_p) - &uc;
        tc.clone() + (u.lift(self.t_far) - &tc) * (u.clone() - &uc) / span
    }

    /// `S(u, v)` (14.8).
    pub fn point<T: Real>(&self, u: &T, v: &T) -> [T; 3] {
        let f = u.clone() - self.seam.u_c(v);
        let (lo, hi) = f.bounds();
        let on_r = || self.r.jet(u, v, 0).swap_remove(0);
        let on_g = || self.g.jet(&self.g_parameter(u, v), v, 0).swap_remove(0);
        if hi <= 0.0 {
            on_r()
        } else if lo > 0.0 {
            on_g()
        } else {
            hull(&on_r(), &on_g())
        }
    }
}
