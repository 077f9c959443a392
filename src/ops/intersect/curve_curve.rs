//! Curve ∩ curve (OPERATIONS.md §6.4 in 2D, §6.5 in 3D), float path.
//!
//! Guesses come from the closest points of the tangent lines at pairs of samples
//! ((6.1) in 2D, (6.11) in general), accepted inside the sample windows (6.6). In 2D
//! Newton runs on (6.5) `c₁(t₁) − c₂(t₂) = 0`, switching to the closest-approach system
//! (6.8) when the tangents are nearly parallel; in 3D (6.10) is the system. Solutions
//! are verified (`|c₁ − c₂| ≤ δ_len`) and classified (`Tangent` when
//! `|ĉ₁' × ĉ₂'| < δ_tan`).

use crate::certify::System;
use crate::curve::Curve;
use crate::num::vector::{dot, norm_f64, sub};
use crate::num::Real;
use crate::ops::float::merge::{merge_duplicates, ParamTolerance};
use crate::ops::float::{newton, newton_with, Coordinate, NewtonOutcome, Precision};

/// One intersection point of two curves.
#[derive(Debug, Clone, PartialEq)]
pub struct CurveCurvePoint<const D: usize> {
    /// `(t₁, t₂)`.
    pub params: [f64; 2],
    /// `c₁(t₁)`.
    pub point: [f64; D],
    /// `|ĉ₁' × ĉ₂'| < δ_tan`.
    pub tangent: bool,
}

/// (6.10) / (6.8) `G = [(c₁ − c₂)·c₁', (c₂ − c₁)·c₂']` with the Jacobian (6.9), written
/// once for every number type and dimension (x = `[t₁, t₂]`).
pub fn closest_approach_equations<T: Real, A: Curve<D>, B: Curve<D>, const D: usize>(
    a: &A,
    b: &B,
    x: &[T; 2],
) -> ([T; 2], [[T; 2]; 2]) {
    let c1 = a.jet(&x[0], 2);
    let c2 = b.jet(&x[1], 2);
    let d = sub(&c1[0], &c2[0]);
    let cross_term = -dot(&c1[1], &c2[1]);
    let g = [dot(&d, &c1[1]), -dot(&d, &c2[1])];
    let j = [
        [dot(&c1[1], &c1[1]) + dot(&d, &c1[2]), cross_term.clone()],
        [cross_term, dot(&c2[1], &c2[1]) - dot(&d, &c2[2])],
    ];
    (g, j)
}

/// All intersection points of two curves (§6.4, §6.5), float only, from their walk
/// samples `[(t, Δt)]` (§2.3).
pub fn intersect_curve_curve_f64<A: Curve<D>, B: Curve<D>, const D: usize>(
    a: &A,
    b: &B,
    a_samples: &[(f64, f64)],
    b_samples: &[(f64, f64)],
    precision: &Precision,
) -> Vec<CurveCurvePoint<D>> {
    intersect_curve_curve_until(a, b, a_samples, b_samples, precision, &|| false)
}

/// [`intersect_curve_curve_f64`] that stops once `stop` says so (issue 20; asked once
/// per sample of `a` and once per guess): the points found by then. Two nearly
/// overlapping curves give a guess at almost every pair of samples, each a Newton run.
pub(crate) fn intersect_curve_curve_until<A: Curve<D>, B: Curve<D>, const D: usize>(
    a: &A,
    b: &B,
    a_samples: &[(f64, f64)],
    b_samples: &[(f64, f64)],
    precision: &Precision,
    stop: &dyn Fn() -> bool,
) -> Vec<CurveCurvePoint<D>> {
    let coords = [
        Coordinate::of_curve(a, precision),
        Coordinate::of_curve(b, precision),
    ];
    let sin_sw = precision.sin_switch();
    let mut length = 0.0f64;
    let mut guesses = Vec::new();
    let b_jets: Vec<_> = b_samples
        .iter()
        .map(|&(t, dt)| (t, dt, b.jet(&t, 1)))
        .collect();
    for &(t1, dt1) in a_samples {
        if stop() {
            break;
        }
        let c1 = a.jet(&t1, 1);
        length = length.max(norm_f64(&c1[0]));
        for (t2, dt2, c2) in &b_jets {
            let (t2, dt2) = (*t2, *dt2);
            let w = sub(&c1[0], &c2[0]);
            let (aa, bb, cc) = (
                dot(&c1[1], &c1[1]),
                dot(&c1[1], &c2[1]),
                dot(&c2[1], &c2[1]),
            );
            let (wa, wb) = (dot(&w, &c1[1]), dot(&w, &c2[1]));
            let gram = aa * cc - bb * bb;
            // (6.11); nearly parallel tangents: t₁' = −(w·c₁')/A, t₂' = 0.
            let (s1, s2) = if gram > sin_sw * sin_sw * aa * cc {
                ((bb * wb - cc * wa) / gram, (aa * wb - bb * wa) / gram)
            } else {
                (-wa / aa, 0.0)
            };
            let gap: [f64; D] = std::array::from_fn(|i| w[i] + s1 * c1[1][i] - s2 * c2[1][i]);
            let reach = (aa.sqrt() * dt1).max(cc.sqrt() * dt2);
            if s1.abs() <= dt1 && s2.abs() <= dt2 && norm_f64(&gap) <= reach {
                guesses.push([t1 + s1, t2 + s2]);
            }
        }
    }
    for (_, _, c2) in &b_jets {
        length = length.max(norm_f64(&c2[0]));
    }
    let delta_len = precision.delta * length.max(1.0);
    let mut found = Vec::new();
    for x0 in guesses {
        if stop() {
            break;
        }
        let direct = if D == 2 {
            let system = |x: &[f64; 2]| {
                let (c1, c2) = (a.jet(&x[0], 1), b.jet(&x[1], 1));
                let f = [c1[0][0] - c2[0][0], c1[0][1] - c2[0][1]];
                (f, [[c1[1][0], -c2[1][0]], [c1[1][1], -c2[1][1]]])
            };
            match newton(system, x0, &coords, 32) {
                NewtonOutcome::Converged(x) if sine(a, b, &x) >= sin_sw => Some(x),
                _ => None,
            }
        } else {
            None
        };
        let x = match direct {
            Some(x) => x,
            None => {
                let system = |x: &[f64; 2]| closest_approach_equations(a, b, x);
                // Linear convergence and a numerically singular Jacobian at a
                // tangency (§6.4): the last iterate is verified below.
                match newton_with(system, x0, &coords, 200, 0.0) {
                    NewtonOutcome::Converged(x)
                    | NewtonOutcome::Singular(x)
                    | NewtonOutcome::NotConverged(x) => x,
                    NewtonOutcome::Diverged(_) => continue,
                }
            }
        };
        if let Some(p) = accept(a, b, x, &coords, delta_len, precision) {
            found.push(p);
        }
    }
    let (tangent, transversal): (Vec<_>, Vec<_>) = found.into_iter().partition(|(p, _)| p.tangent);
    let mut points = merge(transversal, &coords, precision.delta);
    points.extend(merge(tangent, &coords, precision.delta_tan()));
    points.sort_by(|p, q| p.params[0].total_cmp(&q.params[0]));
    points
}

/// `|ĉ₁' × ĉ₂'|` at `(t₁, t₂)`, from the Gram determinant (any dimension).
fn sine<A: Curve<D>, B: Curve<D>, const D: usize>(a: &A, b: &B, x: &[f64; 2]) -> f64 {
    let (c1, c2) = (a.jet(&x[0], 1), b.jet(&x[1], 1));
    let (aa, bb, cc) = (
        dot(&c1[1], &c1[1]),
        dot(&c1[1], &c2[1]),
        dot(&c2[1], &c2[1]),
    );
    ((aa * cc - bb * bb).max(0.0) / (aa * cc)).sqrt()
}

/// Keep `x` inside the δ-extended domains with `|c₁ − c₂| ≤ δ_len` (§6.4, §6.5).
fn accept<A: Curve<D>, B: Curve<D>, const D: usize>(
    a: &A,
    b: &B,
    x: [f64; 2],
    coords: &[Coordinate; 2],
    delta_len: f64,
    precision: &Precision,
) -> Option<(CurveCurvePoint<D>, f64)> {
    let mut y = x;
    for (value, c) in y.iter_mut().zip(coords) {
        let slack = precision.delta * (c.hi - c.lo);
        if !c.periodic && !(c.lo - slack..=c.hi + slack).contains(value) {
            return None;
        }
        *value = value.clamp(c.lo, c.hi);
    }
    let point = a.jet(&y[0], 0)[0];
    let gap = norm_f64(&sub(&point, &b.jet(&y[1], 0)[0]));
    (gap <= delta_len).then(|| {
        let tangent = sine(a, b, &y) < precision.delta_tan();
        (
            CurveCurvePoint {
                params: y,
                point,
                tangent,
            },
            gap,
        )
    })
}

/// Merge duplicates (§0.4) with relative tolerance `delta` on both parameters.
fn merge<const D: usize>(
    found: Vec<(CurveCurvePoint<D>, f64)>,
    coords: &[Coordinate; 2],
    delta: f64,
) -> Vec<CurveCurvePoint<D>> {
    let tolerances = coords.map(|c| ParamTolerance {
        delta: delta * (c.hi - c.lo).max(1.0),
        period: c.periodic.then_some(c.hi - c.lo),
    });
    merge_duplicates(found, &tolerances, |(p, _)| p.params.to_vec(), |(_, r)| *r)
        .into_iter()
        .map(|(p, _)| p)
        .collect()
}

/// (6.5) in 2D: `c₁(t₁) − c₂(t₂) = 0`, unknowns `(t₁, t₂)`.
pub struct CurveCurve2System<'a, A, B> {
    pub a: &'a A,
    pub b: &'a B,
}

impl<A: Curve<2>, B: Curve<2>> System for CurveCurve2System<'_, A, B> {
    fn dim(&self) -> usize {
        2
    }
    fn eval<T: Real>(&self, x: &[T]) -> Vec<T> {
        let (p, q) = (&self.a.jet(&x[0], 0)[0], &self.b.jet(&x[1], 0)[0]);
        vec![p[0].clone() - &q[0], p[1].clone() - &q[1]]
    }
}

/// (6.10): the closest-approach system of two space curves, unknowns `(t₁, t₂)`. Its
/// roots are intersections only where the gap `|c₁ − c₂|` vanishes; the caller proves
/// that separately.
pub struct ClosestApproachSystem<'a, A, B> {
    pub a: &'a A,
    pub b: &'a B,
}

impl<A: Curve<3>, B: Curve<3>> System for ClosestApproachSystem<'_, A, B> {
    fn dim(&self) -> usize {
        2
    }
    fn eval<T: Real>(&self, x: &[T]) -> Vec<T> {
        let x = [x[0].clone(), x[1].clone()];
        closest_approach_equations(self.a, self.b, &x).0.to_vec()
    }
}

/// Distinct float points with parallel tangents (merged at `δ_tan`) from which two
/// curves are taken to overlap: two distinct plane algebraic curves of degrees `m`, `n`
/// meet in at most `mn` points, at most `mn/2` of them tangencies, so this many is a
/// shared arc or two curves within rounding of one another along a stretch (impl).
pub const OVERLAP_TANGENCIES: usize = 6;

/// The reason to answer `undecided` at once when the float points suggest a shared arc
/// ([`OVERLAP_TANGENCIES`] tangential points or more): the parameter ranges they span.
fn suspected_overlap<const D: usize>(float: &[CurveCurvePoint<D>]) -> Option<String> {
    let tangent: Vec<&CurveCurvePoint<D>> = float.iter().filter(|p| p.tangent).collect();
    if tangent.len() < OVERLAP_TANGENCIES {
        return None;
    }
    let span = |k: usize| {
        tangent
            .iter()
            .fold([f64::INFINITY, f64::NEG_INFINITY], |[lo, hi], p| {
                [lo.min(p.params[k]), hi.max(p.params[k])]
            })
    };
    let (s, t) = (span(0), span(1));
    Some(format!(
        "suspected overlap: the curves run together (within the float tolerance, with \
         parallel tangents) at {} points over parameters [{:e}, {:e}] of the first and \
         [{:e}, {:e}] of the second; a shared arc is not decided for these curves",
        tangent.len(),
        s[0],
        s[1],
        t[0],
        t[1]
    ))
}

/// All intersection points of two plane curves (§6.4), certified: roots of (6.5) in
/// verified boxes, tangencies `verified_singular`, `complete` when the subdivision of
/// the `(t₁, t₂)` domain finished.
pub fn intersect_curve2_curve2<A: Curve<2>, B: Curve<2>>(
    a: &A,
    b: &B,
    a_samples: &[(f64, f64)],
    b_samples: &[(f64, f64)],
    precision: &Precision,
    opts: &crate::ops::certified::Options,
) -> Result<crate::Certified<Vec<crate::ops::certified::CertifiedPoint<2>>>, crate::GeomError> {
    use crate::ops::certified::{
        certify_roots, curve_point, curve_unknowns, meet, pieces, CertifiedPoint, Unknowns,
    };
    let stop = || opts.late();
    let float = intersect_curve_curve_until(a, b, a_samples, b_samples, precision, &stop);
    if let Some(reason) = suspected_overlap(&float) {
        // Every box along a shared arc holds common points: subdivision would only
        // spend the budget, and the float points along it are no answer (issue 20).
        return Ok(crate::Certified {
            value: Vec::new(),
            status: crate::certificate::Status::Undecided,
            complete: false,
            arithmetic: crate::certificate::Arithmetic::Interval,
            bits: 53,
            reason: Some(reason),
            perturbation: None,
        });
    }
    let guesses: Vec<Vec<f64>> = float.iter().map(|p| p.params.to_vec()).collect();
    let unknowns = Unknowns::concat(&[curve_unknowns(a), curve_unknowns(b)]);
    let (pa, pb) = (pieces::curve_pieces(a), pieces::curve_pieces(b));
    let roots = if pa.is_some() || pb.is_some() {
        // A NURBS: span by span (issue 21, [`pieces`]).
        let mut systems = Vec::new();
        for (a, ua) in pieces::curve_parts(a, &pa) {
            for (b, ub) in pieces::curve_parts(b, &pb) {
                let u = Unknowns::concat(&[ua.clone(), ub]);
                systems.push((CurveCurve2System { a, b }, u));
            }
        }
        pieces::certify_roots_in_pieces(
            &systems,
            &unknowns,
            &guesses,
            opts,
            &|_| false,
            Some(&systems), // the system uses the curves' points only: continuous
        )?
    } else {
        certify_roots(&CurveCurve2System { a, b }, &unknowns, &guesses, opts)?
    };
    Ok(roots.map(|rs| {
        rs.into_iter()
            .map(|root| {
                let (point, on_a) = curve_point(a, root.params[0], &root.enclosure[0]);
                let (_, on_b) = curve_point(b, root.params[1], &root.enclosure[1]);
                let point_box = meet(on_a, &on_b);
                CertifiedPoint {
                    root,
                    point,
                    point_box,
                }
            })
            .collect()
    }))
}
