//! Point → surface, all solutions (OPERATIONS.md §3.4), float path.
//!
//! A foot `(u, v)` satisfies (3.9) `F₁ = (p − s)·s_u = 0`, `F₂ = (p − s)·s_v = 0`. The
//! search tests sign changes of `F₁` along `u` and of `F₂` along `v` over each node's
//! window (3.10); Newton (3.11) refines; results are filtered to the domain and merged
//! (§0.4, including points that coincide in space at poles). For `nearest` on a
//! surface with an open direction the boundary curves are projected too (§3.4
//! "Nearest", exact mode).

use super::curve::{changes_sign, project_point_curve_f64, CurveFeet};
use super::equations::surface_foot_equations;
use crate::certify::system::value_and_rows;
use crate::certify::System;
use crate::curve::Curve;
use crate::num::vector::{lift, norm_f64, sub};
use crate::num::Real;
use crate::ops::float::merge::{merge_duplicates, ParamTolerance};
use crate::ops::float::{newton, Coordinate, NewtonOutcome, Precision};
use crate::surface::Surface;

/// One foot of a perpendicular from `p` to a surface.
#[derive(Debug, Clone, PartialEq)]
pub struct SurfaceFoot {
    /// `(u, v)`.
    pub params: [f64; 2],
    /// `s(u, v)`.
    pub point: [f64; 3],
    /// `|s(u, v) − p|`.
    pub distance: f64,
    /// The 2×2 system (3.11) is singular here (a pole, a focal point).
    pub singular: bool,
}

/// The feet from a point (§3.4 "Output").
#[derive(Debug, Clone, PartialEq)]
pub enum SurfaceFeet {
    /// Finitely many feet, ordered by `(u, v)`.
    Finite(Vec<SurfaceFoot>),
    /// A continuum of feet (the centre of a sphere, §3.4).
    Infinite,
}

/// All feet of the perpendiculars from `p` onto `surface` (§3.4), float only, from the
/// walk nodes `nodes = [(u, v, Δu, Δv)]` (§2.3). With `nearest`, only the nearest point
/// of the closed domain (boundary curves included) is returned.
pub fn project_point_surface_f64<S: Surface>(
    surface: &S,
    p: &[f64; 3],
    nodes: &[[f64; 4]],
    precision: &Precision,
    nearest: bool,
) -> SurfaceFeet {
    let ([u0, u1], [v0, v1]) = surface.domain();
    let closed = surface.is_closed();
    let f = |u: f64, v: f64| surface_foot_equations(surface, p, &u, &v, false).0;
    let window = |x: f64, dx: f64, lo: f64, hi: f64, periodic: bool| {
        if periodic {
            (x - dx, x + dx)
        } else {
            ((x - dx).max(lo), (x + dx).min(hi))
        }
    };
    let mut all_zero = !nodes.is_empty();
    let mut guesses = Vec::new();
    for &[u, v, du, dv] in nodes {
        let (ua, ub) = window(u, du, u0, u1, closed[0]);
        let (va, vb) = window(v, dv, v0, v1, closed[1]);
        let (a, b) = (f(ua, v)[0], f(ub, v)[0]);
        let (c, d) = (f(u, va)[1], f(u, vb)[1]);
        let jet = surface.jet(&u, &v, 1);
        let dist = norm_f64(&sub(p, &jet[0]));
        let tol = [1, 2].map(|k| precision.delta * dist * norm_f64(&jet[k]));
        let at = f(u, v);
        all_zero &= at[0].abs() <= tol[0] && at[1].abs() <= tol[1];
        if changes_sign(a, b, tol[0]) && changes_sign(c, d, tol[1]) {
            guesses.push([u, v]);
        }
    }
    if all_zero {
        return SurfaceFeet::Infinite;
    }
    let coords = [
        Coordinate::new(u0, u1, closed[0], precision),
        Coordinate::new(v0, v1, closed[1], precision),
    ];
    let scale = norm_f64(p)
        .max(norm_f64(&surface.jet(&u0, &v0, 0)[0]))
        .max(1.0);
    let mut feet: Vec<SurfaceFoot> = guesses
        .into_iter()
        .filter_map(|x0| {
            let system = |x: &[f64; 2]| {
                let (f, j) = surface_foot_equations(surface, p, &x[0], &x[1], true);
                (f, j.unwrap_or([[f64::NAN; 2]; 2]))
            };
            let (x, singular) = match newton(system, x0, &coords, 32) {
                NewtonOutcome::Converged(x) => (x, false),
                // A pole or focal point: keep it if it solves (3.9).
                NewtonOutcome::Singular(x) => (x, true),
                _ => return None,
            };
            let inside = |c: &Coordinate, t: f64| {
                c.periodic
                    || (c.lo - precision.delta * (c.hi - c.lo)
                        ..=c.hi + precision.delta * (c.hi - c.lo))
                        .contains(&t)
            };
            if !(inside(&coords[0], x[0]) && inside(&coords[1], x[1])) {
                return None;
            }
            let x = [x[0].clamp(u0, u1), x[1].clamp(v0, v1)];
            let foot = surface_foot(surface, p, x, singular);
            let r = f(x[0], x[1]);
            let jet = surface.jet(&x[0], &x[1], 1);
            let tol = precision.delta * scale * (foot.distance + scale);
            let solves = r[0].abs() <= tol * norm_f64(&jet[1]).max(1.0)
                && r[1].abs() <= tol * norm_f64(&jet[2]).max(1.0);
            (!singular || solves).then_some(foot)
        })
        .collect();
    if nearest {
        feet.extend(boundary_candidates(surface, p, precision));
    }
    let tolerances = [
        ParamTolerance {
            delta: precision.delta * (u1 - u0).max(1.0),
            period: closed[0].then_some(u1 - u0),
        },
        ParamTolerance {
            delta: precision.delta * (v1 - v0).max(1.0),
            period: closed[1].then_some(v1 - v0),
        },
    ];
    let residual = |x: &SurfaceFoot| {
        let r = f(x.params[0], x.params[1]);
        r[0].abs() + r[1].abs()
    };
    let feet = merge_duplicates(feet, &tolerances, |x| x.params.to_vec(), residual);
    // Feet that coincide in space (poles: many (u, v), one point) are one foot.
    let space = [ParamTolerance {
        delta: precision.delta * scale,
        period: None,
    }; 3];
    let mut feet = merge_duplicates(feet, &space, |x| x.point.to_vec(), residual);
    if nearest {
        feet.sort_by(|a, b| a.distance.total_cmp(&b.distance));
        feet.truncate(1);
    }
    feet.sort_by(|a, b| {
        a.params
            .partial_cmp(&b.params)
            .unwrap_or(std::cmp::Ordering::Equal)
    });
    SurfaceFeet::Finite(feet)
}

fn surface_foot<S: Surface>(surface: &S, p: &[f64; 3], x: [f64; 2], singular: bool) -> SurfaceFoot {
    let point = surface.jet(&x[0], &x[1], 0)[0];
    let distance = norm_f64(&sub(&point, &lift(&x[0], p)));
    SurfaceFoot {
        params: x,
        point,
        distance,
        singular,
    }
}

/// The nearest points of the boundary curves of every open direction (§3.4 "Nearest").
fn boundary_candidates<S: Surface>(
    surface: &S,
    p: &[f64; 3],
    precision: &Precision,
) -> Vec<SurfaceFoot> {
    let ([u0, u1], [v0, v1]) = surface.domain();
    let closed = surface.is_closed();
    let mut out = Vec::new();
    for (direction, ends, open) in [(0, [v0, v1], !closed[1]), (1, [u0, u1], !closed[0])] {
        if !open {
            continue;
        }
        for fixed in ends {
            let iso = IsoCurve {
                surface,
                direction,
                fixed,
            };
            let (lo, hi) = iso.domain();
            let n = 32;
            let dt = (hi - lo) / n as f64;
            let samples: Vec<(f64, f64)> = (0..=n).map(|i| (lo + i as f64 * dt, dt)).collect();
            if let CurveFeet::Finite(feet) =
                project_point_curve_f64(&iso, p, &samples, precision, true)
            {
                out.extend(feet.into_iter().map(|f| {
                    let params = if direction == 0 {
                        [f.t, fixed]
                    } else {
                        [fixed, f.t]
                    };
                    surface_foot(surface, p, params, false)
                }));
            }
        }
    }
    out
}

/// The coordinate line of a surface through a fixed `v` (`direction = 0`, parameter
/// `u`) or a fixed `u` (`direction = 1`, parameter `v`), as a curve.
pub struct IsoCurve<'a, S> {
    pub surface: &'a S,
    pub direction: usize,
    pub fixed: f64,
}

impl<S: Surface> Curve<3> for IsoCurve<'_, S> {
    fn domain(&self) -> (f64, f64) {
        let d = self.surface.domain();
        let r = if self.direction == 0 { d.0 } else { d.1 };
        (r[0], r[1])
    }

    fn is_closed(&self) -> bool {
        self.surface.is_closed()[self.direction]
    }

    fn jet<T: Real>(&self, t: &T, order: usize) -> Vec<[T; 3]> {
        let fixed = t.lift(self.fixed);
        let order = order.min(2);
        if self.direction == 0 {
            let j = self.surface.jet(t, &fixed, order);
            [0, 1, 3]
                .iter()
                .take(order + 1)
                .map(|&k| j[k].clone())
                .collect()
        } else {
            let j = self.surface.jet(&fixed, t, order);
            [0, 2, 5]
                .iter()
                .take(order + 1)
                .map(|&k| j[k].clone())
                .collect()
        }
    }
}

/// (3.9): `(p − s)·s_u = (p − s)·s_v = 0`, unknowns `(u, v)`.
pub struct SurfaceFootSystem<'a, S> {
    pub surface: &'a S,
    pub point: [f64; 3],
}

impl<S: Surface> System for SurfaceFootSystem<'_, S> {
    fn dim(&self) -> usize {
        2
    }
    fn eval<T: Real>(&self, x: &[T]) -> Vec<T> {
        let p = lift(&x[0], &self.point);
        surface_foot_equations(self.surface, &p, &x[0], &x[1], false)
            .0
            .to_vec()
    }
    /// The Jacobian of (3.9) from the surface's own second derivatives (one jet of
    /// order 2 instead of a jet over dual numbers, which for interval boxes takes the
    /// fast centred form of the patch).
    fn eval_with_jacobian<T: Real>(&self, x: &[T]) -> (Vec<T>, Vec<Vec<T>>) {
        let p = lift(&x[0], &self.point);
        let (f, j) = surface_foot_equations(self.surface, &p, &x[0], &x[1], true);
        value_and_rows(f, j)
    }
}

/// All feet from `p` onto `surface` (§3.4), certified like
/// [`super::curve::project_point_curve`]: roots of (3.9) in verified boxes,
/// `complete` when the subdivision covered the domain; roots at a pole whose point is
/// no foot are not feet ([`super::pole`]).
pub fn project_point_surface<S: Surface>(
    surface: &S,
    p: &[f64; 3],
    nodes: &[[f64; 4]],
    precision: &Precision,
    opts: &crate::ops::certified::Options,
) -> Result<crate::Certified<Vec<crate::ops::certified::CertifiedPoint<3>>>, crate::GeomError> {
    use crate::ops::certified::{
        certify_roots_with, surface_point, surface_unknowns, CertifiedPoint,
    };
    let guesses: Vec<Vec<f64>> =
        match project_point_surface_f64(surface, p, nodes, precision, false) {
            SurfaceFeet::Finite(f) => f.iter().map(|x| x.params.to_vec()).collect(),
            SurfaceFeet::Infinite => Vec::new(),
        };
    let sys = SurfaceFootSystem { surface, point: *p };
    // Roots on a pole edge whose point is no foot are dropped (`super::pole`).
    let not_a_foot = |r: &crate::certify::Root| super::pole::spurious_pole_root(surface, p, r);
    let roots = certify_roots_with(&sys, &surface_unknowns(surface), &guesses, opts, not_a_foot)?;
    Ok(roots.map(|rs| {
        rs.into_iter()
            .map(|root| {
                let uv = [root.params[0], root.params[1]];
                let (point, point_box) =
                    surface_point(surface, uv, &root.enclosure[0], &root.enclosure[1]);
                CertifiedPoint {
                    root,
                    point,
                    point_box,
                }
            })
            .collect()
    }))
}
