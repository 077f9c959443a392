//! Walking parameter domains with curvature-adaptive steps (OPERATIONS.md §2):
//! the samples that operations use to find initial guesses, and an interval version
//! whose turning-angle bound is proven over each step, for the certifier.
//!
//! * [`turning_angle_step`] — the step rule shared by curves (2.1) and surfaces (2.2);
//! * [`curve`] — the curve step (2.1) with its clamps and analytic shortcuts, the
//!   traversal of §2.3 as the iterator [`CurveWalk`], and the proven step
//!   [`proven_curve_step`] / [`ProvenCurveWalk`];
//! * [`surface`] — the surface steps (2.2) and the row traversal of §2.3.

pub mod curve;
pub mod surface;

pub use curve::{
    curve_step, proven_curve_step, turning_step_at, CurveSample, CurveWalk, ProvenCurveWalk,
    ProvenStep, WalkOptions,
};

/// The clamps of §2.1: `Δt_min = range·10⁻⁴`, `Δt_max = range/8` (defaults, impl).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StepClamps {
    pub min: f64,
    pub max: f64,
}

impl StepClamps {
    /// The default clamps of §2.1 for a parameter range `t_max − t_min`.
    pub fn for_range(range: f64) -> StepClamps {
        StepClamps {
            min: range * 1e-4,
            max: range / 8.0,
        }
    }
}

/// The step that turns a direction by at most `Δα`, assuming a locally constant
/// turning rate: `Δ = Δα · scale / rate`, clamped to `[clamps.min, clamps.max]`
/// (OPERATIONS.md §2.1 (2.1) with `scale = |c'|²`, `rate = |c'×c''|`; §2.2 (2.2) with
/// `scale = |s_i|`, `rate = |n̂·s_ii|`).
///
/// Straight rule of §2.1: `rate ≤ δ·scale` (no turning to speak of) gives `clamps.max`.
/// A NaN rate or scale (an undefined direction) gives `clamps.min`, the cautious step.
pub fn turning_angle_step(
    delta_alpha: f64,
    scale: f64,
    rate: f64,
    delta: f64,
    clamps: StepClamps,
) -> f64 {
    if rate.is_nan() || scale.is_nan() {
        return clamps.min;
    }
    if rate <= delta * scale {
        return clamps.max;
    }
    (delta_alpha * scale / rate).max(clamps.min).min(clamps.max)
}
