//! Point → curve, all solutions (OPERATIONS.md §3.2), float path.
//!
//! A foot `t` satisfies (3.2) `f(t) = (p − c(t))·c'(t) = 0`. The search walks the
//! curve's samples and emits a guess where `f` changes sign over the sample's window
//! (3.3); Newton (3.4) refines it; results are filtered to the domain and merged (§0.4).

use crate::certify::System;
use crate::curve::Curve;
use crate::num::vector::{dot, lift, norm_f64, sub};
use crate::num::Real;
use crate::ops::float::merge::{merge_duplicates, ParamTolerance};
use crate::ops::float::{newton, Coordinate, NewtonOutcome, Precision};

/// One foot of a perpendicular from `p` to the curve.
#[derive(Debug, Clone, PartialEq)]
pub struct CurveFoot<const D: usize> {
    /// The curve parameter.
    pub t: f64,
    /// `c(t)`.
    pub point: [f64; D],
    /// `|c(t) − p|`.
    pub distance: f64,
}

/// The feet of the perpendiculars from a point (§3.2 "Output").
#[derive(Debug, Clone, PartialEq)]
pub enum CurveFeet<const D: usize> {
    /// Finitely many feet, in increasing `t`.
    Finite(Vec<CurveFoot<D>>),
    /// Every parameter is a foot (`p` at the centre of a circle, §3.2 "Degenerate input").
    Infinite,
}

/// (3.2) `f(t) = (p − c(t))·c'(t)` and, with `derivative`, the denominator of (3.4)
/// `f'(t) = (p − c)·c'' − c'·c'`, written once for every number type: in f64 for
/// Newton, over an interval `t` as an enclosure for the certifier.
pub fn foot_equation<T: Real, C: Curve<D>, const D: usize>(
    curve: &C,
    p: &[T; D],
    t: &T,
    derivative: bool,
) -> (T, Option<T>) {
    let jet = curve.jet(t, if derivative { 2 } else { 1 });
    let d = sub(p, &jet[0]);
    let f = dot(&d, &jet[1]);
    let df = derivative.then(|| dot(&d, &jet[2]) - dot(&jet[1], &jet[1]));
    (f, df)
}

/// All feet of the perpendiculars from `p` onto `curve` (§3.2), float only, from the
/// walk samples `samples = [(t_i, Δt_i)]` (§2.3).
///
/// `nearest` also adds the end points of an open curve as candidates and returns only
/// the nearest point (§3.2 "Nearest projection", exact mode).
pub fn project_point_curve_f64<C: Curve<D>, const D: usize>(
    curve: &C,
    p: &[f64; D],
    samples: &[(f64, f64)],
    precision: &Precision,
    nearest: bool,
) -> CurveFeet<D> {
    let (lo, hi) = curve.domain();
    let range = hi - lo;
    let closed = curve.is_closed();
    let f = |t: f64| foot_equation(curve, p, &t, false).0;
    // Scale of f: |p − c|·|c'| at the samples, so "f ≡ 0" is judged relatively.
    let mut all_zero = !samples.is_empty();
    let mut guesses = Vec::new();
    for &(t, dt) in samples {
        let (a_at, b_at) = if closed {
            (t - dt, t + dt)
        } else {
            ((t - dt).max(lo), (t + dt).min(hi))
        };
        let (a, b) = (f(a_at), f(b_at));
        let jet = curve.jet(&t, 1);
        let tol = precision.delta * norm_f64(&sub(p, &jet[0])) * norm_f64(&jet[1]);
        all_zero &= f(t).abs() <= tol;
        if changes_sign(a, b, tol) {
            guesses.push(t);
        }
    }
    if all_zero {
        return CurveFeet::Infinite;
    }
    let coord = [Coordinate {
        lo,
        hi,
        periodic: closed,
        eps: precision.eps * range.max(1.0),
        margin: range,
    }];
    let mut feet: Vec<CurveFoot<D>> = guesses
        .into_iter()
        .filter_map(|t0| {
            let system = |x: &[f64; 1]| {
                let (v, dv) = foot_equation(curve, p, &x[0], true);
                ([v], [[dv.unwrap_or(f64::NAN)]])
            };
            match newton(system, [t0], &coord, 32) {
                NewtonOutcome::Converged([t]) => accept(t, lo, hi, closed, precision.delta * range),
                _ => None,
            }
        })
        .map(|t| foot(curve, p, t))
        .collect();
    if nearest && !closed {
        feet.push(foot(curve, p, lo));
        feet.push(foot(curve, p, hi));
    }
    let tolerance = [ParamTolerance {
        delta: precision.delta * range.max(1.0),
        period: closed.then_some(range),
    }];
    let residual = |x: &CurveFoot<D>| foot_equation(curve, p, &x.t, false).0.abs();
    let mut feet = merge_duplicates(feet, &tolerance, |x| vec![x.t], residual);
    if nearest {
        feet.sort_by(|a, b| a.distance.total_cmp(&b.distance));
        feet.truncate(1);
    }
    feet.sort_by(|a, b| a.t.total_cmp(&b.t));
    CurveFeet::Finite(feet)
}

/// The event of (3.3)/(3.10): `a·b ≤ 0`, where a window end whose value is within
/// `tol` of zero counts as zero (a root exactly at a window end on the domain boundary,
/// such as a sphere's pole, must not be lost to rounding).
pub(crate) fn changes_sign(a: f64, b: f64, tol: f64) -> bool {
    a * b <= 0.0 || a.abs().min(b.abs()) <= tol
}

/// Keep a converged parameter in `[lo − δ, hi + δ]` (§0.4), clamped into the domain
/// (a closed curve's parameter is already wrapped by the Newton driver).
fn accept(t: f64, lo: f64, hi: f64, closed: bool, delta: f64) -> Option<f64> {
    if closed || (lo - delta..=hi + delta).contains(&t) {
        Some(t.clamp(lo, hi))
    } else {
        None
    }
}

fn foot<C: Curve<D>, const D: usize>(curve: &C, p: &[f64; D], t: f64) -> CurveFoot<D> {
    let point = curve.jet(&t, 0)[0];
    let distance = norm_f64(&sub(&point, &lift(&t, p)));
    CurveFoot { t, point, distance }
}

/// (3.2): `(p − c(t))·c'(t) = 0`, unknown `t`.
pub struct CurveFootSystem<'a, C, const D: usize> {
    pub curve: &'a C,
    pub point: [f64; D],
}

impl<C: Curve<D>, const D: usize> System for CurveFootSystem<'_, C, D> {
    fn dim(&self) -> usize {
        1
    }
    fn eval<T: Real>(&self, x: &[T]) -> Vec<T> {
        vec![foot_equation(self.curve, &lift(&x[0], &self.point), &x[0], false).0]
    }
}

/// All feet from `p` onto `curve` (§3.2), certified (docs/CERTIFICATES.md): each foot
/// a root of (3.2) in a verified box (`verified_singular` where `p` lies on the
/// evolute), `complete` when subdivision covered the domain. The float answers (from
/// `samples`) are certified individually when the search is incomplete.
///
/// A continuum of feet (the centre of a circle) cannot be enclosed by isolated boxes:
/// the search then spends its budget and the answer is `undecided`.
pub fn project_point_curve<C: Curve<D>, const D: usize>(
    curve: &C,
    p: &[f64; D],
    samples: &[(f64, f64)],
    precision: &Precision,
    opts: &crate::ops::certified::Options,
) -> Result<crate::Certified<Vec<crate::ops::certified::CertifiedPoint<D>>>, crate::GeomError> {
    use crate::ops::certified::{certify_roots, curve_points, curve_unknowns, pieces};
    let guesses: Vec<Vec<f64>> = match project_point_curve_f64(curve, p, samples, precision, false)
    {
        CurveFeet::Finite(f) => f.iter().map(|x| vec![x.t]).collect(),
        CurveFeet::Infinite => Vec::new(),
    };
    let roots = match pieces::curve_pieces(curve) {
        // A NURBS: span by span (issue 21, [`pieces`]).
        Some(parts) => {
            let systems: Vec<_> = parts
                .iter()
                .map(|(c, range)| {
                    let sys = CurveFootSystem {
                        curve: c,
                        point: *p,
                    };
                    (sys, pieces::piece_unknowns(*range))
                })
                .collect();
            pieces::certify_roots_in_pieces(
                &systems,
                &curve_unknowns(curve),
                &guesses,
                opts,
                &|_| false,
                None, // the foot equation uses c′, which jumps at a C⁰ knot
            )?
        }
        None => {
            let sys = CurveFootSystem { curve, point: *p };
            certify_roots(&sys, &curve_unknowns(curve), &guesses, opts)?
        }
    };
    Ok(curve_points(curve, roots))
}
