//! Walking the parameter rectangle of a surface (OPERATIONS.md §2.2–§2.3).
//!
//! [`SurfaceStepper`] computes the steps `(Δu, Δv)` at a node: the normal-curvature
//! steps (2.2) of the coordinate lines, or the surface's analytic shortcut
//! ([`StepRule`]), with the clamps of §2.1 per direction: `Δ_max = range/8` (for
//! B-splines also `≤ ½·` the current knot span), `Δ_min = range·10⁻⁴`; a flat coordinate
//! line (`|b_ii| ≤ δ·√g_ii`) takes `Δ_max`, a degenerate one (`√g_ii ≤ δ_len`, or a
//! step that cannot be computed) takes `Δ_min`.
//!
//! [`SurfaceWalk`] visits the nodes row by row (§2.3): a row walks `u` from `u_min` to
//! exactly `u_max`; the next row starts at `v + mean Δv` of the row (exactly `v_max`
//! last). Its proven mode ([`SurfaceWalk::proven`]) uses [`proven_surface_steps`]: each
//! node's window carries a proven bound on the turning of the normal, and rows advance by
//! the smallest `Δv` of the row (not the mean), so the windows cover every cell.

mod proven;

pub use proven::{proven_surface_steps, turning_bounds, ProvenSteps, MAX_HALVINGS};

use crate::error::GeomError;
use crate::num::vector::{cross, norm_f64};
use crate::num::Interval;
use crate::surface::{FundamentalForms, StepRule, Surface};

/// Parameters of the walk (§2.1–§2.2, §12).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SurfaceWalkOptions {
    /// `Δα`, the turning angle per step (`π/10` for initial-guess scans, `π/20` for
    /// marching; any value in `(0, π]`).
    pub delta_alpha: f64,
    /// `δ`, the relative flatness tolerance (§12 default `1e-10`).
    pub delta: f64,
    /// `δ_len`, the length below which a tangent counts as zero; `None`: `δ·L` with `L`
    /// the diagonal of the bounding box of a 5 × 5 grid of surface points.
    pub delta_len: Option<f64>,
}

impl SurfaceWalkOptions {
    /// `Δα` with the §12 defaults for the rest.
    pub fn new(delta_alpha: f64) -> Self {
        SurfaceWalkOptions {
            delta_alpha,
            delta: 1e-10,
            delta_len: None,
        }
    }
}

impl Default for SurfaceWalkOptions {
    /// `Δα_scan = π/10`.
    fn default() -> Self {
        SurfaceWalkOptions::new(std::f64::consts::PI / 10.0)
    }
}

/// The validated step computation for one surface.
#[derive(Debug, Clone)]
pub struct SurfaceStepper<'a, S> {
    surface: &'a S,
    domain: [[f64; 2]; 2],
    rules: [StepRule; 2],
    delta_alpha: f64,
    delta: f64,
    delta_len: f64,
}

impl<'a, S: Surface> SurfaceStepper<'a, S> {
    /// Errors: `delta_alpha` outside `(0, π]`, `delta`/`delta_len` negative or not finite,
    /// an unbounded `domain`.
    pub fn new(surface: &'a S, options: SurfaceWalkOptions) -> Result<Self, GeomError> {
        let a = options.delta_alpha;
        if !(a > 0.0 && a <= std::f64::consts::PI) {
            return Err(GeomError::InvalidValue {
                field: "delta_alpha".into(),
                reason: format!("{a} must lie in (0, π]"),
            });
        }
        let non_negative = |field: &str, x: f64| {
            if x.is_finite() && x >= 0.0 {
                Ok(x)
            } else {
                Err(GeomError::InvalidValue {
                    field: field.into(),
                    reason: format!("{x} must be finite and not negative"),
                })
            }
        };
        let delta = non_negative("delta", options.delta)?;
        let (du, dv) = surface.domain();
        let domain = [du, dv];
        if domain.iter().flatten().any(|x| !x.is_finite()) {
            return Err(GeomError::Unsupported {
                field: "domain".into(),
                reason: "walking needs a bounded parameter domain (restrict it)".into(),
            });
        }
        let delta_len = match options.delta_len {
            Some(d) => non_negative("delta_len", d)?,
            None => delta * model_scale(surface, &domain),
        };
        Ok(SurfaceStepper {
            surface,
            domain,
            rules: surface.step_rules(),
            delta_alpha: a,
            delta,
            delta_len,
        })
    }

    /// The parameter rectangle walked.
    pub fn domain(&self) -> [[f64; 2]; 2] {
        self.domain
    }

    /// `Δα`.
    pub fn delta_alpha(&self) -> f64 {
        self.delta_alpha
    }

    /// `[Δ_min, Δ_max]` in `direction` at parameter `t` (module doc).
    pub fn clamps(&self, direction: usize, t: f64) -> [f64; 2] {
        let [lo, hi] = self.domain[direction];
        let range = hi - lo;
        let mut max = range / 8.0;
        if let Some((a, b)) = self.surface.knot_span(direction, t) {
            max = max.min(0.5 * (b - a));
        }
        [(range * 1e-4).min(max), max]
    }

    /// The steps `[Δu, Δv]` at `(u, v)`: the surface's [`StepRule`] per direction, clamped.
    pub fn steps(&self, u: f64, v: f64) -> [f64; 2] {
        let jet = self.surface.jet(&u, &v, 2);
        let forms = FundamentalForms::from_jet(&jet);
        std::array::from_fn(|d| {
            let t = if d == 0 { u } else { v };
            let [lo, hi] = self.domain[d];
            match self.rules[d] {
                StepRule::WholeRange => hi - lo,
                StepRule::Angle => self.clamp(d, t, self.delta_alpha),
                StepRule::Curvature => self.clamp_formula(d, t, self.curvature_step(&forms, d)),
                StepRule::CoordinateCurve => {
                    self.clamp_formula(d, t, self.curve_step(&jet[1 + d], &jet[3 + 2 * d]))
                }
            }
        })
    }

    /// The steps (2.2) at `(u, v)` whatever the surface's shortcut, clamped.
    pub fn curvature_steps(&self, u: f64, v: f64) -> [f64; 2] {
        let forms = self.surface.fundamental_forms(&u, &v);
        let t = [u, v];
        std::array::from_fn(|d| self.clamp_formula(d, t[d], self.curvature_step(&forms, d)))
    }

    /// (2.2): `Δα·√g_ii/|b_ii|`, or the degenerate cases as `Err(use_max)`.
    fn curvature_step(&self, f: &FundamentalForms<f64>, d: usize) -> Result<f64, bool> {
        let (g, b) = if d == 0 {
            (f.g11, f.b11)
        } else {
            (f.g22, f.b22)
        };
        let speed = g.sqrt();
        if speed.is_nan() || speed <= self.delta_len {
            return Err(false);
        }
        if b.abs() <= self.delta * speed {
            return Err(true);
        }
        Ok(self.delta_alpha * speed / b.abs())
    }

    /// (2.1) on the coordinate line: `Δα|c'|²/|c'×c''|`, or `Err(use_max)`.
    fn curve_step(&self, d1: &[f64; 3], d2: &[f64; 3]) -> Result<f64, bool> {
        let speed = norm_f64(d1);
        if speed.is_nan() || speed <= self.delta_len {
            return Err(false);
        }
        let turn = norm_f64(&cross(d1, d2));
        if turn <= self.delta * speed * speed {
            return Err(true);
        }
        Ok(self.delta_alpha * speed * speed / turn)
    }

    fn clamp_formula(&self, d: usize, t: f64, step: Result<f64, bool>) -> f64 {
        let [min, max] = self.clamps(d, t);
        match step {
            Ok(s) if s.is_finite() => s.clamp(min, max),
            Err(true) => max,
            _ => min,
        }
    }

    fn clamp(&self, d: usize, t: f64, step: f64) -> f64 {
        let [min, max] = self.clamps(d, t);
        step.clamp(min, max)
    }

    pub(crate) fn surface(&self) -> &'a S {
        self.surface
    }
}

/// `L`: the diagonal of the bounding box of a 5 × 5 grid of points (§12 model scale).
fn model_scale<S: Surface>(surface: &S, domain: &[[f64; 2]; 2]) -> f64 {
    let mut lo = [f64::INFINITY; 3];
    let mut hi = [f64::NEG_INFINITY; 3];
    for i in 0..5 {
        for j in 0..5 {
            let at = |d: usize, k: usize| {
                domain[d][0] + (domain[d][1] - domain[d][0]) * (k as f64 / 4.0)
            };
            let p = surface.jet(&at(0, i), &at(1, j), 0)[0];
            for c in 0..3 {
                lo[c] = lo[c].min(p[c]);
                hi[c] = hi[c].max(p[c]);
            }
        }
    }
    let d: [f64; 3] = std::array::from_fn(|c| hi[c] - lo[c]);
    let l = norm_f64(&d);
    if l.is_finite() {
        l
    } else {
        0.0
    }
}

/// One visited node (§2.3) with its own steps, the test window of the operations.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SurfaceNode {
    pub u: f64,
    pub v: f64,
    pub du: f64,
    pub dv: f64,
    /// The row number (0 at `v_min`).
    pub row: usize,
    /// Proven mode: the proven bound on the turning of the normal over the window.
    pub proven: Option<ProvenSteps>,
}

/// The §2.3 row traversal as an iterator of [`SurfaceNode`]s.
#[derive(Debug, Clone)]
pub struct SurfaceWalk<'a, S> {
    stepper: SurfaceStepper<'a, S>,
    proven: bool,
    next: Option<(f64, f64)>,
    row: usize,
    row_dv: (f64, f64, usize), // (sum, min, count)
}

impl<'a, S: Surface> SurfaceWalk<'a, S> {
    /// The float walk of §2.3 (errors as [`SurfaceStepper::new`]).
    pub fn new(surface: &'a S, options: SurfaceWalkOptions) -> Result<Self, GeomError> {
        let stepper = SurfaceStepper::new(surface, options)?;
        let [du, dv] = stepper.domain();
        Ok(SurfaceWalk {
            stepper,
            proven: false,
            next: Some((du[0], dv[0])),
            row: 0,
            row_dv: (0.0, f64::INFINITY, 0),
        })
    }

    /// The proven walk: every node's window `[u, u+Δu] × [v, v+Δv]` carries a proven
    /// bound of the normal's turning (f64 intervals), and rows advance by the smallest
    /// `Δv` of the row so that the windows cover the rectangle.
    pub fn proven(surface: &'a S, options: SurfaceWalkOptions) -> Result<Self, GeomError> {
        let mut walk = SurfaceWalk::new(surface, options)?;
        walk.proven = true;
        Ok(walk)
    }
}

impl<S: Surface> Iterator for SurfaceWalk<'_, S> {
    type Item = SurfaceNode;

    fn next(&mut self) -> Option<SurfaceNode> {
        let (u, v) = self.next?;
        let [[u_min, u_max], [_, v_max]] = self.stepper.domain();
        let [mut du, mut dv] = self.stepper.steps(u, v);
        let mut proven = None;
        if self.proven {
            let mins = [self.stepper.clamps(0, u)[0], self.stepper.clamps(1, v)[0]];
            let p = proven_surface_steps(
                self.stepper.surface(),
                &Interval::ZERO,
                [u, v],
                [du, dv],
                self.stepper.delta_alpha(),
                mins,
            );
            du = p.du;
            dv = p.dv;
            proven = Some(p);
        }
        let node = SurfaceNode {
            u,
            v,
            du,
            dv,
            row: self.row,
            proven,
        };
        let (sum, min, count) = self.row_dv;
        self.row_dv = (sum + dv, min.min(dv), count + 1);
        self.next = if u < u_max {
            Some(((u + du).min(u_max), v))
        } else if v < v_max {
            let (sum, min, count) = self.row_dv;
            let advance = if self.proven { min } else { sum / count as f64 };
            self.row += 1;
            self.row_dv = (0.0, f64::INFINITY, 0);
            Some((u_min, (v + advance).min(v_max)))
        } else {
            None
        };
        Some(node)
    }
}
