//! Walking a curve (OPERATIONS.md §2.1, §2.3): the step (2.1)
//! `Δt = Δα|c'|²/|c'×c''|` with the clamps and shortcuts of §2.1, the traversal
//! `t₀ = t_min`, `t_{k+1} = min(t_k + Δt_k, t_max)` as the iterator [`CurveWalk`]
//! (the last sample is exactly `t_max`), and for the certifier a step whose turning
//! angle is proven: [`proven_curve_step`], [`ProvenCurveWalk`].

use super::{turning_angle_step, StepClamps};
use crate::curve::{Curve, StepHint};
use crate::error::{require_finite, GeomError};
use crate::num::interval::directed::next_up;
use crate::num::vector::{cross_norm_sq, norm_sq};
use crate::num::IntervalLike;
use std::f64::consts::PI;

/// The parameters of a walk (§2.1; defaults of §2.1 and §12, impl).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct WalkOptions {
    /// The turning angle per step, `Δα` (default `Δα_scan = π/10`; `π/20` for marching).
    pub delta_alpha: f64,
    /// The relative equality tolerance `δ` of §12 (straight rule `|c'×c''| ≤ δ|c'|²`).
    pub delta: f64,
    /// The length tolerance `δ_len = δ·L` of §12 (special point rule `|c'| ≤ δ_len`);
    /// 0 by default, since the model scale `L` is the operation's to know.
    pub delta_len: f64,
}

impl Default for WalkOptions {
    fn default() -> Self {
        WalkOptions {
            delta_alpha: PI / 10.0,
            delta: 1e-10,
            delta_len: 0.0,
        }
    }
}

impl WalkOptions {
    /// Errors: `non_finite` / `invalid_value` (`delta_alpha`, `delta`, `delta_len`) for
    /// values that are not finite, `Δα ≤ 0`, or negative tolerances.
    pub fn validate(&self) -> Result<(), GeomError> {
        require_finite("delta_alpha", self.delta_alpha)?;
        require_finite("delta", self.delta)?;
        require_finite("delta_len", self.delta_len)?;
        let bad = |field: &str, reason: &str| {
            Err(GeomError::InvalidValue {
                field: field.into(),
                reason: reason.into(),
            })
        };
        if self.delta_alpha <= 0.0 {
            return bad("delta_alpha", "the turning angle per step must be positive");
        }
        if self.delta < 0.0 || self.delta_len < 0.0 {
            return bad("delta", "tolerances must not be negative");
        }
        Ok(())
    }
}

/// The bounded domain of a curve, or a typed error for an unbounded one.
fn bounded_domain<const D: usize>(curve: &impl Curve<D>) -> Result<(f64, f64), GeomError> {
    let (lo, hi) = curve.domain();
    if lo.is_finite() && hi.is_finite() {
        Ok((lo, hi))
    } else {
        Err(GeomError::Unsupported {
            field: "domain".into(),
            reason: "walking needs a bounded parameter domain (give the line a range)".into(),
        })
    }
}

/// The general rule (2.1) at `t`, ignoring analytic shortcuts: the clamps of §2.1
/// (`Δt_min = range·10⁻⁴`, `Δt_max = range/8`, further `≤ max_step`), the straight
/// rule (`|c'×c''| ≤ δ|c'|²` ⇒ `Δt_max`) and the special point rule (`|c'| ≤ δ_len` ⇒
/// `Δt_min`). The domain must be bounded.
pub fn turning_step_at<const D: usize>(
    curve: &impl Curve<D>,
    t: f64,
    options: &WalkOptions,
    max_step: Option<f64>,
) -> f64 {
    let (lo, hi) = curve.domain();
    let clamps = StepClamps::for_range(hi - lo);
    let jet = curve.jet(&t, 2);
    let speed_sq = norm_sq(&jet[1]);
    if speed_sq.sqrt() <= options.delta_len {
        return clamps.min;
    }
    let rate = cross_norm_sq(&jet[1], &jet[2]).sqrt();
    let step = turning_angle_step(options.delta_alpha, speed_sq, rate, options.delta, clamps);
    max_step.map_or(step, |m| step.min(m))
}

/// The walking step at `t` (§2.1): the curve's [`StepHint`] — one step for lines and
/// segments, `Δα` per unit of angular parameter for circles, arcs, ellipses and helices
/// (clamped by `Δt_max`), otherwise [`turning_step_at`] with the knot-span clamp.
pub fn curve_step<const D: usize>(curve: &impl Curve<D>, t: f64, options: &WalkOptions) -> f64 {
    let (lo, hi) = curve.domain();
    let clamps = StepClamps::for_range(hi - lo);
    match curve.step_hint(t) {
        StepHint::Whole => hi - lo,
        StepHint::Angular { rate } => (options.delta_alpha / rate).max(clamps.min).min(clamps.max),
        StepHint::Adaptive { max_step } => turning_step_at(curve, t, options, max_step),
    }
}

/// One sample of a walk: the parameter and the step `Δt` computed there (the
/// window of §3.2 (3.3) and the other initial-guess searches).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CurveSample {
    pub t: f64,
    pub step: f64,
}

/// The traversal of §2.3: `t₀ = t_min`, `t_{k+1} = min(t_k + Δt_k, t_max)`; the last
/// sample is exactly `t_max`.
pub struct CurveWalk<'a, C, const D: usize> {
    curve: &'a C,
    options: WalkOptions,
    next: Option<f64>,
    t_max: f64,
}

impl<'a, const D: usize, C: Curve<D>> CurveWalk<'a, C, D> {
    /// Errors: those of [`WalkOptions::validate`]; `unsupported` (`domain`) for an
    /// unbounded domain.
    pub fn new(curve: &'a C, options: WalkOptions) -> Result<Self, GeomError> {
        options.validate()?;
        let (lo, hi) = bounded_domain(curve)?;
        Ok(CurveWalk {
            curve,
            options,
            next: Some(lo),
            t_max: hi,
        })
    }
}

impl<const D: usize, C: Curve<D>> Iterator for CurveWalk<'_, C, D> {
    type Item = CurveSample;
    fn next(&mut self) -> Option<CurveSample> {
        let t = self.next?;
        let step = curve_step(self.curve, t, &self.options);
        self.next = if t >= self.t_max {
            None
        } else {
            // Always progress, even where t + Δt rounds back to t.
            Some((t + step).max(next_up(t)).min(self.t_max))
        };
        Some(CurveSample { t, step })
    }
}

/// A step `[t_start, t_end]` over which the tangent provably turns by at most
/// `turning_bound ≤ Δα`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ProvenStep {
    pub t_start: f64,
    pub t_end: f64,
    /// An upper bound of `∫|c'×c''|/|c'|² dt` over the step (rounded up).
    pub turning_bound: f64,
    /// A tangent break ([`Curve::tangent_breaks`]) the step stops at: its interval
    /// `(lo, hi)` with `lo = t_end`. The tangent may jump there; the next step starts at
    /// `hi`.
    pub corner: Option<(f64, f64)>,
}

/// The interval version of (2.1) for the certifier: the largest step from `t0` found
/// (starting from the float step and shrinking) such that, with `[t0, t_end]` split
/// into pieces `τ_i` evaluated in the interval type of `like`,
/// `Σ wid(τ_i) · sup(|c'×c''|(τ_i) / |c'|²(τ_i)) ≤ Δα` and `|c'|² > 0` on every piece.
/// Since the tangent's turning rate is `|c'×c''|/|c'|²`, the turning angle over the
/// step, `∫|c'×c''|/|c'|² dt`, is then proven to be at most `Δα`.
///
/// `None` when no step down to `range·2⁻⁴⁰` can be proven (the enclosure of `|c'|²`
/// contains 0: a special point) or `t0 ≥ t_max`.
pub fn proven_curve_step<const D: usize, T: IntervalLike>(
    curve: &impl Curve<D>,
    t0: f64,
    delta_alpha: f64,
    like: &T,
) -> Option<ProvenStep> {
    let (lo, hi) = curve.domain();
    let usable = lo.is_finite() && hi.is_finite() && t0 < hi && delta_alpha > 0.0;
    if !usable {
        return None;
    }
    let options = WalkOptions {
        delta_alpha,
        ..WalkOptions::default()
    };
    let smallest = (hi - lo) * 2f64.powi(-40);
    let breaks = curve.tangent_breaks();
    if breaks.iter().any(|&(a, b)| a <= t0 && t0 < b) {
        return None; // t0 inside a break's interval: every step would cross it
    }
    let corner = breaks.iter().copied().find(|&(a, _)| a > t0 && a < hi);
    let limit = corner.map_or(hi, |c| c.0);
    let mut h = curve_step(curve, t0, &options).min(limit - t0);
    loop {
        let t1 = (t0 + h).min(limit);
        if t1 <= t0 || t1.is_nan() {
            return None;
        }
        let (bound, regular) = turning_bound(curve, t0, t1, like);
        let sup = bound.sup();
        if regular && sup <= delta_alpha {
            return Some(ProvenStep {
                t_start: t0,
                t_end: t1,
                turning_bound: sup,
                corner: corner.filter(|_| t1 == limit),
            });
        }
        let factor = if regular && sup.is_finite() && sup > 0.0 {
            (0.9 * delta_alpha / sup).clamp(0.05, 0.95)
        } else {
            0.25
        };
        h = (t1 - t0) * factor;
        if h < smallest {
            return None;
        }
    }
}

/// The number of equal pieces a step is split into for [`turning_bound`]: smaller
/// pieces lose less to the dependency of interval evaluation (the bound of a circle's
/// step is within a few percent of the true angle with 4 pieces, ~35% above it with 1).
const PIECES: usize = 4;

/// An enclosure whose upper bound bounds `∫_{t0}^{t1} |c'×c''|/|c'|² dt`: the sum over
/// [`PIECES`] pieces `τ_i` of `wid(τ_i) · (|c'×c''|/|c'|²)(τ_i)`, each evaluated in the
/// interval type of `like`; and whether `|c'|² > 0` is proven on every piece.
fn turning_bound<const D: usize, T: IntervalLike>(
    curve: &impl Curve<D>,
    t0: f64,
    t1: f64,
    like: &T,
) -> (T, bool) {
    let mut total = like.zero_like();
    let mut regular = true;
    let mut a = t0;
    for i in 1..=PIECES {
        let b = if i == PIECES {
            t1
        } else {
            t0 + (t1 - t0) * (i as f64 / PIECES as f64)
        };
        let (a_i, b_i) = (a.min(b), b.max(a));
        let tau = like.with_bounds(a_i, b_i);
        let jet = curve.jet(&tau, 2);
        let speed_sq = norm_sq(&jet[1]);
        regular &= !speed_sq.is_empty() && speed_sq.inf() > 0.0;
        let rate = cross_norm_sq(&jet[1], &jet[2]).sqrt() / speed_sq;
        total = total + (like.lift(b_i) - like.lift(a_i)) * rate;
        a = b_i;
    }
    (total, regular)
}

/// Proven steps covering the whole domain, one after the other (see
/// [`proven_curve_step`]): each step starts where the previous one ended, or across
/// the tangent break it stopped at; an item `Err(t)` says no step from `t` could be
/// proven, and ends the walk.
pub struct ProvenCurveWalk<'a, C, T, const D: usize> {
    curve: &'a C,
    delta_alpha: f64,
    like: T,
    next: Option<f64>,
}

impl<'a, const D: usize, C: Curve<D>, T: IntervalLike> ProvenCurveWalk<'a, C, T, D> {
    /// Errors: `invalid_value` (`delta_alpha`), `unsupported` (`domain`) for an
    /// unbounded domain.
    pub fn new(curve: &'a C, delta_alpha: f64, like: T) -> Result<Self, GeomError> {
        WalkOptions {
            delta_alpha,
            ..WalkOptions::default()
        }
        .validate()?;
        let (lo, _) = bounded_domain(curve)?;
        Ok(ProvenCurveWalk {
            curve,
            delta_alpha,
            like,
            next: Some(lo),
        })
    }
}

impl<const D: usize, C: Curve<D>, T: IntervalLike> Iterator for ProvenCurveWalk<'_, C, T, D> {
    type Item = Result<ProvenStep, f64>;
    fn next(&mut self) -> Option<Self::Item> {
        let t0 = self.next?;
        match proven_curve_step(self.curve, t0, self.delta_alpha, &self.like) {
            Some(step) => {
                let (_, hi) = self.curve.domain();
                let next = step.corner.map_or(step.t_end, |c| c.1);
                self.next = (next < hi).then_some(next);
                Some(Ok(step))
            }
            None => {
                self.next = None;
                Some(Err(t0))
            }
        }
    }
}
