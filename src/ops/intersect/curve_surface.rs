//! Curve ∩ surface, all points (OPERATIONS.md §5.2), float path.
//!
//! Unknowns `(u, v, t)` of (5.2) `s(u, v) − c(t) = 0`. Initial guesses come from
//! intersecting tangent lines with tangent planes at pairs of walk samples (5.3);
//! Newton (5.4) refines them; where the tangent line is (nearly) parallel to the
//! tangent plane the tangency system (5.5)/(5.6) takes over and its solutions are
//! verified (`|d| ≤ δ_len`) and classified (`Tangent` when `|N̂·ĉ'| < δ_tan`).

use crate::certify::system::value_and_rows;
use crate::certify::System;
use crate::curve::Curve;
use crate::num::vector::{cross, dot, norm_f64, sub};
use crate::num::Real;
use crate::ops::float::merge::{merge_duplicates, ParamTolerance};
use crate::ops::float::{newton, newton_with, Coordinate, NewtonOutcome, Precision};
use crate::surface::Surface;

/// One intersection point of a curve and a surface.
#[derive(Debug, Clone, PartialEq)]
pub struct CurveSurfacePoint {
    /// `(u, v)` on the surface.
    pub surface_params: [f64; 2],
    /// `t` on the curve.
    pub t: f64,
    /// `c(t)` (equal to `s(u, v)` within δ_len).
    pub point: [f64; 3],
    /// `|N̂·ĉ'| < δ_tan` (§5.2 "Verification").
    pub tangent: bool,
}

/// (5.2) `F = s(u, v) − c(t)` with, on request, its Jacobian `[s_u | s_v | −c']`,
/// written once for every number type (x = `[u, v, t]`).
pub fn curve_surface_equations<T: Real, S: Surface, C: Curve<3>>(
    surface: &S,
    curve: &C,
    x: &[T; 3],
    jacobian: bool,
) -> ([T; 3], Option<[[T; 3]; 3]>) {
    let order = usize::from(jacobian);
    let s = surface.jet(&x[0], &x[1], order);
    let c = curve.jet(&x[2], order);
    let f = sub(&s[0], &c[0]);
    let j = jacobian
        .then(|| std::array::from_fn(|i| [s[1][i].clone(), s[2][i].clone(), -c[1][i].clone()]));
    (f, j)
}

/// The tangency system (5.5) `G = [d·s_u, d·s_v, d·c']` (`d = s − c`) with its
/// Jacobian (5.6), written once for every number type.
pub fn curve_surface_tangency_equations<T: Real, S: Surface, C: Curve<3>>(
    surface: &S,
    curve: &C,
    x: &[T; 3],
) -> ([T; 3], [[T; 3]; 3]) {
    let s = surface.jet(&x[0], &x[1], 2);
    let c = curve.jet(&x[2], 2);
    let d = sub(&s[0], &c[0]);
    let (su, sv, c1) = (&s[1], &s[2], &c[1]);
    let g = [dot(&d, su), dot(&d, sv), dot(&d, c1)];
    let j = [
        [
            dot(su, su) + dot(&d, &s[3]),
            dot(sv, su) + dot(&d, &s[4]),
            -dot(c1, su),
        ],
        [
            dot(su, sv) + dot(&d, &s[4]),
            dot(sv, sv) + dot(&d, &s[5]),
            -dot(c1, sv),
        ],
        [dot(su, c1), dot(sv, c1), dot(&d, &c[2]) - dot(c1, c1)],
    ];
    (g, j)
}

/// All intersection points of `curve` and `surface` (§5.2), float only, from the
/// curve samples `[(t, Δt)]` and surface nodes `[(u, v, Δu, Δv)]` of the walks (§2.3);
/// `turn` is the walk's Δα (used by the tangency-candidate test).
pub fn intersect_curve_surface_f64<S: Surface, C: Curve<3>>(
    surface: &S,
    curve: &C,
    curve_samples: &[(f64, f64)],
    surface_nodes: &[[f64; 4]],
    turn: f64,
    precision: &Precision,
) -> Vec<CurveSurfacePoint> {
    let seeds = Seeds {
        curve_samples,
        surface_nodes,
        turn,
    };
    intersect_curve_surface_until(surface, curve, &seeds, precision, &|| false)
}

/// The most initial guesses kept (issue 20: a curve lying in a surface makes one at
/// nearly every pair of samples). Guesses only seed the float search; the certified
/// operation's completeness comes from subdivision.
pub const MAX_GUESSES: usize = 1 << 14;

/// The walk samples of both objects and the walk's Δα.
pub(crate) struct Seeds<'a> {
    pub curve_samples: &'a [(f64, f64)],
    pub surface_nodes: &'a [[f64; 4]],
    pub turn: f64,
}

/// [`intersect_curve_surface_f64`] that stops once `stop` says so (asked once per
/// curve sample and once per guess; it may count work as well as watch a deadline):
/// the points found by then.
pub(crate) fn intersect_curve_surface_until<S: Surface, C: Curve<3>>(
    surface: &S,
    curve: &C,
    seeds: &Seeds,
    precision: &Precision,
    stop: &dyn Fn() -> bool,
) -> Vec<CurveSurfacePoint> {
    let ([u0, u1], [v0, v1]) = surface.domain();
    let (t0, t1) = curve.domain();
    let closed = surface.is_closed();
    let coords = [
        Coordinate::new(u0, u1, closed[0], precision),
        Coordinate::new(v0, v1, closed[1], precision),
        Coordinate::new(t0, t1, curve.is_closed(), precision),
    ];
    let (guesses, length) = initial_guesses(surface, curve, seeds, precision, stop);
    let sin_sw = precision.sin_switch();
    let delta_len = precision.delta * length.max(1.0);
    let mut found: Vec<(CurveSurfacePoint, f64)> = Vec::new();
    for x0 in guesses {
        if stop() {
            break;
        }
        let system = |x: &[f64; 3]| {
            let (f, j) = curve_surface_equations(surface, curve, x, true);
            (f, j.unwrap_or([[f64::NAN; 3]; 3]))
        };
        let transversal = match newton(system, x0, &coords, 32) {
            NewtonOutcome::Converged(x) if !near_parallel(surface, curve, &x, sin_sw) => Some(x),
            _ => None,
        };
        let x = match transversal {
            Some(x) => x,
            None => {
                let fallback = |x: &[f64; 3]| curve_surface_tangency_equations(surface, curve, x);
                // The fallback converges only linearly and its Jacobian becomes
                // numerically singular near the tangency (§5.2): the last iterate is
                // the candidate, and the verification below decides.
                match newton_with(fallback, x0, &coords, 200, 0.0) {
                    NewtonOutcome::Converged(x)
                    | NewtonOutcome::Singular(x)
                    | NewtonOutcome::NotConverged(x) => x,
                    NewtonOutcome::Diverged(_) => continue,
                }
            }
        };
        if let Some(p) = accept(surface, curve, x, &coords, delta_len, precision) {
            found.push(p);
        }
    }
    // Tangential solutions are located only to about √ε (§5.2, §12): they are merged
    // with δ_tan, transversal ones with δ.
    let (tangent, transversal): (Vec<_>, Vec<_>) = found.into_iter().partition(|(p, _)| p.tangent);
    let mut merged = merge(transversal, &coords, precision.delta, delta_len);
    merged.extend(merge(
        tangent,
        &coords,
        precision.delta_tan(),
        delta_len.max(precision.delta_tan()),
    ));
    let mut points: Vec<CurveSurfacePoint> = merged.into_iter().map(|(p, _)| p).collect();
    points.sort_by(|a, b| a.t.total_cmp(&b.t));
    points
}

/// The initial guesses (5.3) at every pair of a curve sample and a surface node (the
/// surface's jets computed once per node), at most [`MAX_GUESSES`], and the largest
/// coordinate seen (the model scale of `δ_len`).
fn initial_guesses<S: Surface, C: Curve<3>>(
    surface: &S,
    curve: &C,
    seeds: &Seeds,
    precision: &Precision,
    stop: &dyn Fn() -> bool,
) -> (Vec<[f64; 3]>, f64) {
    let sin_sw = precision.sin_switch();
    let jets: Vec<Vec<[f64; 3]>> = seeds
        .surface_nodes
        .iter()
        .map(|&[u, v, _, _]| surface.jet(&u, &v, 1))
        .collect();
    let mut length = jets.iter().map(|s| norm_f64(&s[0])).fold(0.0f64, f64::max);
    let mut guesses = Vec::new();
    for &(t, dt) in seeds.curve_samples {
        if guesses.len() >= MAX_GUESSES || stop() {
            break;
        }
        let c = curve.jet(&t, 1);
        length = length.max(norm_f64(&c[0]));
        for (&[u, v, du, dv], s) in seeds.surface_nodes.iter().zip(&jets) {
            let window = [du, dv, dt];
            if let Some([x, y, z]) = pair_guess(s, &c, window, seeds.turn, sin_sw) {
                guesses.push([u + x, v + y, t + z]);
            }
        }
    }
    guesses.truncate(MAX_GUESSES);
    (guesses, length)
}

/// The guess of (5.3) at one pair of samples, as an offset `(Δu, Δv, Δt)` inside the
/// windows `[du, dv, dt]`: where the tangent line meets the tangent plane, or, where
/// they are (nearly) parallel, the tangency candidate.
fn pair_guess(
    s: &[[f64; 3]],
    c: &[[f64; 3]],
    [du, dv, dt]: [f64; 3],
    turn: f64,
    sin_sw: f64,
) -> Option<[f64; 3]> {
    let n = cross(&s[1], &s[2]);
    let f = sub(&s[0], &c[0]);
    let nc = dot(&n, &c[1]);
    let parallel = nc.abs() < sin_sw * norm_f64(&n) * norm_f64(&c[1]);
    if !parallel {
        // (5.4) at the pair of samples: the tangent line meets the tangent plane.
        let x = [
            -dot(&f, &cross(&s[2], &c[1])) / nc,
            dot(&f, &cross(&s[1], &c[1])) / nc,
            dot(&f, &n) / nc,
        ];
        return (x[0].abs() <= du && x[1].abs() <= dv && x[2].abs() <= dt).then_some(x);
    }
    // Tangency candidate (§5.2, reconstructed): the point of the tangent line nearest
    // to the node, c* = c + τ·c', within the curve window; the foot of c* on the
    // tangent plane within the surface windows; and the line close to the plane.
    let tau = dot(&f, &c[1]) / dot(&c[1], &c[1]);
    let near = std::array::from_fn(|i| c[0][i] + tau * c[1][i]);
    let w = sub(&near, &s[0]);
    let h = dot(&w, &n) / dot(&n, &n).sqrt();
    let (g11, g12, g22) = (dot(&s[1], &s[1]), dot(&s[1], &s[2]), dot(&s[2], &s[2]));
    let det = g11 * g22 - g12 * g12;
    let (a, b) = (dot(&s[1], &w), dot(&s[2], &w));
    let (x, y) = ((g22 * a - g12 * b) / det, (g11 * b - g12 * a) / det);
    let reach = turn
        * (g11.sqrt() * du)
            .min(g22.sqrt() * dv)
            .min(norm_f64(&c[1]) * dt);
    (tau.abs() <= dt && x.abs() <= du && y.abs() <= dv && h.abs() <= reach).then_some([x, y, tau])
}

/// Merge duplicates (§0.4) with the relative tolerance `delta` on every parameter, then
/// points that coincide in space within `delta_len` at the same curve parameter
/// (poles: several `(u, v)`, one point).
fn merge(
    found: Vec<(CurveSurfacePoint, f64)>,
    coords: &[Coordinate; 3],
    delta: f64,
    delta_len: f64,
) -> Vec<(CurveSurfacePoint, f64)> {
    let tolerances = coords.map(|c| ParamTolerance {
        delta: delta * (c.hi - c.lo).max(1.0),
        period: c.periodic.then_some(c.hi - c.lo),
    });
    let params =
        |(p, _): &(CurveSurfacePoint, f64)| vec![p.surface_params[0], p.surface_params[1], p.t];
    let merged = merge_duplicates(found, &tolerances, params, |(_, r)| *r);
    let length = ParamTolerance {
        delta: delta_len,
        period: None,
    };
    let space = [length, length, length, tolerances[2]];
    let in_space =
        |(p, _): &(CurveSurfacePoint, f64)| vec![p.point[0], p.point[1], p.point[2], p.t];
    merge_duplicates(merged, &space, in_space, |(_, r)| *r)
}

/// `|N̂·ĉ'| < sin θ_sw` at `x = (u, v, t)`: Newton on (5.2) is abandoned for (5.5).
fn near_parallel<S: Surface, C: Curve<3>>(
    surface: &S,
    curve: &C,
    x: &[f64; 3],
    sin_sw: f64,
) -> bool {
    sine(surface, curve, x) < sin_sw
}

/// `|N̂·ĉ'|` at `x = (u, v, t)`.
fn sine<S: Surface, C: Curve<3>>(surface: &S, curve: &C, x: &[f64; 3]) -> f64 {
    let s = surface.jet(&x[0], &x[1], 1);
    let c = curve.jet(&x[2], 1);
    let n = cross(&s[1], &s[2]);
    dot(&n, &c[1]).abs() / (norm_f64(&n) * norm_f64(&c[1]))
}

/// §5.2 "Verification": keep a converged `x` inside the (δ-extended) domain whose gap
/// `|s − c|` is at most δ_len; classify it as tangent when `|N̂·ĉ'| < δ_tan`.
fn accept<S: Surface, C: Curve<3>>(
    surface: &S,
    curve: &C,
    x: [f64; 3],
    coords: &[Coordinate; 3],
    delta_len: f64,
    precision: &Precision,
) -> Option<(CurveSurfacePoint, f64)> {
    let mut y = x;
    for (value, c) in y.iter_mut().zip(coords) {
        let slack = precision.delta * (c.hi - c.lo);
        if !c.periodic && !(c.lo - slack..=c.hi + slack).contains(value) {
            return None;
        }
        *value = value.clamp(c.lo, c.hi);
    }
    let (f, _) = curve_surface_equations(surface, curve, &y, false);
    let gap = norm_f64(&f);
    if gap > delta_len {
        return None;
    }
    let point = curve.jet(&y[2], 0)[0];
    let tangent = sine(surface, curve, &y) < precision.delta_tan();
    Some((
        CurveSurfacePoint {
            surface_params: [y[0], y[1]],
            t: y[2],
            point,
            tangent,
        },
        gap,
    ))
}

/// (5.2): `s(u, v) − c(t) = 0`, unknowns `(u, v, t)`.
pub struct CurveSurfaceSystem<'a, S, C> {
    pub surface: &'a S,
    pub curve: &'a C,
}

impl<S: Surface, C: Curve<3>> System for CurveSurfaceSystem<'_, S, C> {
    fn dim(&self) -> usize {
        3
    }
    fn eval<T: Real>(&self, x: &[T]) -> Vec<T> {
        let x = [x[0].clone(), x[1].clone(), x[2].clone()];
        curve_surface_equations(self.surface, self.curve, &x, false)
            .0
            .to_vec()
    }
    /// The Jacobian `[s_u | s_v | −c']` of (5.2) from the jets (one surface jet of
    /// order 1 instead of a jet over dual numbers, which for interval boxes takes the
    /// fast centred form of the patch).
    fn eval_with_jacobian<T: Real>(&self, x: &[T]) -> (Vec<T>, Vec<Vec<T>>) {
        let x = [x[0].clone(), x[1].clone(), x[2].clone()];
        let (f, j) = curve_surface_equations(self.surface, self.curve, &x, true);
        value_and_rows(f, j)
    }
    /// The surface's implicit form at the curve's point, `F(c(t))`: it vanishes at
    /// every root (`c(t) = s(u, v)` lies on the surface), and excludes a box by its
    /// `t`-range alone, whatever its `(u, v)` (a curve near a sphere along an arc left
    /// thousands of boxes wide in `u, v` to the subdivision, issue 21).
    fn implied<T: Real>(&self, x: &[T]) -> Vec<T> {
        self.surface
            .implicit_value(&self.curve.point(&x[2]))
            .into_iter()
            .collect()
    }
}

/// All intersection points of `curve` and `surface` (§5.2), certified: transversal
/// points in verified boxes of (5.2), tangential ones `verified_singular` (at most two
/// roots, a double root of a perturbed input), `complete` when the subdivision of the
/// `(u, v, t)` domain finished. Near-misses are proven by exclusion.
pub fn intersect_curve_surface<S: Surface, C: Curve<3>>(
    surface: &S,
    curve: &C,
    curve_samples: &[(f64, f64)],
    surface_nodes: &[[f64; 4]],
    turn: f64,
    precision: &Precision,
    opts: &crate::ops::certified::Options,
) -> Result<crate::Certified<Vec<crate::ops::certified::CertifiedPoint<3>>>, crate::GeomError> {
    use crate::ops::certified::{
        certify_roots, curve_point, curve_unknowns, meet, pieces, surface_point, surface_unknowns,
        CertifiedPoint, Unknowns,
    };
    let seeds = Seeds {
        curve_samples,
        surface_nodes,
        turn,
    };
    let guesses: Vec<Vec<f64>> =
        intersect_curve_surface_until(surface, curve, &seeds, precision, &|| opts.late())
            .iter()
            .map(|p| vec![p.surface_params[0], p.surface_params[1], p.t])
            .collect();
    let unknowns = Unknowns::concat(&[surface_unknowns(surface), curve_unknowns(curve)]);
    let pinned = pieces::curve_pieces(curve);
    let spieces = pieces::surface_pieces(surface);
    let system = |surface, curve| CurveSurfaceSystem { surface, curve };
    // The system uses the points of both objects only, so it is continuous across
    // knots: roots left undecided on a knot (line) are proven across it (issue 21).
    let tiles = pieces::surface_curve_tiles(
        surface,
        &spieces,
        &pieces::curve_parts(curve, &pinned),
        system,
    );
    let roots = if pinned.is_some() {
        // A NURBS curve: span by span (issue 21, [`pieces`]). The surface is not split
        // for the search (knot rectangles of a NURBS patch each with a share of the box
        // budget ran out of it on the NURBS torus), only for proofs across its knots.
        let systems: Vec<_> = pieces::curve_parts(curve, &pinned)
            .into_iter()
            .map(|(curve, uc)| {
                let u = Unknowns::concat(&[surface_unknowns(surface), uc]);
                (system(surface, curve), u)
            })
            .collect();
        pieces::certify_roots_in_pieces(
            &systems,
            &unknowns,
            &guesses,
            opts,
            &|_| false,
            Some(&tiles),
        )?
    } else if spieces.is_some() {
        let sys = system(surface, curve);
        pieces::certify_roots_across(&sys, &tiles, &unknowns, &guesses, opts)?
    } else {
        let sys = CurveSurfaceSystem { surface, curve };
        certify_roots(&sys, &unknowns, &guesses, opts)?
    };
    Ok(roots
        .map(|rs| {
            rs.into_iter()
                .map(|root| {
                    let (point, on_curve) = curve_point(curve, root.params[2], &root.enclosure[2]);
                    let uv = [root.params[0], root.params[1]];
                    let (_, on_surface) =
                        surface_point(surface, uv, &root.enclosure[0], &root.enclosure[1]);
                    let point_box = meet(on_curve, &on_surface);
                    CertifiedPoint {
                        root,
                        point,
                        point_box,
                    }
                })
                .collect::<Vec<_>>()
        })
        .map(|mut ps| {
            // Ordered along the curve, like the float path.
            ps.sort_by(|a, b| a.root.params[2].total_cmp(&b.root.params[2]));
            ps
        }))
}
