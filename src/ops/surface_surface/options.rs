//! Options of surface ∩ surface: the float tolerances of §12, the tracer (§9.3 marching,
//! §10.5 Dragilev integration, §10.6 stepping without an ODE), the chord tolerance of the
//! polylines, and the certifier's limits.

use crate::error::GeomError;
use crate::ops::float::Precision;

/// How the float path steps along a curve.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Method {
    /// §9.3: predictor (9.4), fixed parameter (9.5), Newton on (9.6).
    Marching,
    /// §10.5: RK4 on the Dragilev form of the pair — (10.4) for two implicit surfaces,
    /// (10.9) for one implicit, (10.5)–(10.6) otherwise — with the corrector (10.13).
    Dragilev,
    /// §10.6: the next point on the plane `Π_k` at chord `h` along the tangent, (10.11).
    PlaneStep,
}

/// Which Dragilev form to use (§10.2–§10.4); `Auto` takes the implicit forms the operands
/// have.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum DragilevForm {
    Auto,
    /// (10.5)–(10.6): both parametric.
    Parametric,
    /// (10.9): the first surface parametric, the other implicit (either way round).
    ParametricImplicit,
    /// (10.4): both implicit.
    Implicit,
}

/// Options of [`super::intersect_surface_surface`] and its float variants.
#[derive(Debug, Clone, PartialEq)]
pub struct Options {
    /// ε and δ of §12.
    pub precision: Precision,
    pub method: Method,
    pub form: DragilevForm,
    /// `Δα_march` (§2.1; default `π/20`): the normal of either surface turns by at most
    /// this per step, (9.3).
    pub delta_alpha: f64,
    /// The largest distance between a polyline chord and the curve (estimated from the
    /// curve's curvature, float); `None`: `10⁻⁴·L`.
    pub chord_tolerance: Option<f64>,
    /// `r_min / L` (§9.3 clamp; default `10⁻⁹`, below the spec's `10⁻⁶` so that loops of
    /// radius `~10⁻⁶ L` can be traced).
    pub min_step: f64,
    /// The most points per traced direction.
    pub max_points: usize,
    /// Limits of the certifier (box budget and precision cap of each solve).
    pub certify: crate::certify::Options,
    /// Prove completeness (boundary and height-critical systems over the whole domain);
    /// without it `complete` is false.
    pub completeness: bool,
}

impl Default for Options {
    fn default() -> Self {
        Options {
            precision: Precision::default(),
            method: Method::Marching,
            form: DragilevForm::Auto,
            delta_alpha: std::f64::consts::PI / 20.0,
            chord_tolerance: None,
            min_step: 1e-9,
            max_points: 20_000,
            certify: crate::certify::Options {
                max_boxes: 200_000,
                ..crate::certify::Options::default()
            },
            completeness: true,
        }
    }
}

impl Options {
    /// Typed errors naming `options.<field>`.
    pub fn check(&self) -> Result<(), GeomError> {
        let bad = |field: &str, reason: String| {
            Err(GeomError::InvalidValue {
                field: format!("options.{field}"),
                reason,
            })
        };
        let p = &self.precision;
        if !(p.eps > 0.0 && p.eps.is_finite() && p.delta > 0.0 && p.delta.is_finite()) {
            return bad(
                "tolerance",
                format!("ε = {} and δ = {} must be positive", p.eps, p.delta),
            );
        }
        let a = self.delta_alpha;
        if !(a > 0.0 && a <= std::f64::consts::PI) {
            return bad("delta_alpha", format!("{a} must lie in (0, π]"));
        }
        if let Some(c) = self.chord_tolerance {
            if !(c > 0.0 && c.is_finite()) {
                return bad("chord_tolerance", format!("{c} must be positive"));
            }
        }
        if !(self.min_step > 0.0 && self.min_step < 1.0) {
            return bad("min_step", format!("{} must lie in (0, 1)", self.min_step));
        }
        if self.max_points < 2 {
            return bad("max_points", "at least 2 points".into());
        }
        self.certify.check()
    }
}
