//! Analytic curve primitives of OPERATIONS.md §1.5 (docs/FORMAT.md parametrisations):
//! the framed curves circle, ellipse, hyperbola, parabola and cylindrical helix,
//! `c = p + x(t) X + y(t) Y + z(t) Z` in the frame of
//! [`Frame`]; their 2D versions `circle2`, `ellipse2`; circular and elliptic arcs
//! (§1.5 `p + r cos(t₀+σt) i₁ + r sin(t₀+σt) i₂`, `t ∈ [0, φ]`).
//!
//! Each local formula `(x, y, z)(t)` and its derivatives is written once, generic over
//! [`Real`]; the interval versions of `sin`, `cos`, `sinh`, `cosh` enclose, so an
//! interval parameter gives an enclosure of every derivative.

use super::derived::Reparametrised;
use super::domain::Domain;
use super::frame::Frame;
use super::{Curve, StepHint};
use crate::error::{require_finite, require_finite_all, GeomError};
use crate::num::Real;
use std::f64::consts::TAU;

/// The shape of an analytic curve in its local coordinates (docs/FORMAT.md parametrisations).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Shape {
    /// `r(cos t, sin t, 0)`.
    Circle { radius: f64 },
    /// `(a cos t, b sin t, 0)`.
    Ellipse { a: f64, b: f64 },
    /// `(±a cosh t, b sinh t, 0)`; `second_branch` takes `−a` (§1.5 "2nd branch").
    Hyperbola { a: f64, b: f64, second_branch: bool },
    /// `(t²/(2p), t, 0)`: `y² = 2p·x`.
    Parabola { p: f64 },
    /// `(r cos t, r sin t, pitch·t/(2π))`.
    Helix { radius: f64, pitch: f64 },
}

impl Shape {
    /// Check the shape's numbers (positive radii and semi-axes, finite pitch).
    fn validate(&self) -> Result<(), GeomError> {
        let positive = |field: &str, v: f64| -> Result<(), GeomError> {
            require_finite(field, v)?;
            if v > 0.0 {
                Ok(())
            } else {
                Err(GeomError::InvalidValue {
                    field: field.into(),
                    reason: format!("{v} must be positive"),
                })
            }
        };
        match *self {
            Shape::Circle { radius } => positive("radius", radius),
            Shape::Ellipse { a, b } | Shape::Hyperbola { a, b, .. } => {
                positive("a", a)?;
                positive("b", b)
            }
            Shape::Parabola { p } => positive("p", p),
            Shape::Helix { radius, pitch } => {
                positive("radius", radius)?;
                require_finite("pitch", pitch).map(|_| ())
            }
        }
    }

    /// Whether the shape is a closed trigonometric curve (circle, ellipse).
    fn is_trigonometric_closed(&self) -> bool {
        matches!(self, Shape::Circle { .. } | Shape::Ellipse { .. })
    }

    /// The local jet `[x, y, z]` per derivative order, up to `order` (≤ 3).
    pub fn local_jet<T: Real>(&self, t: &T, order: usize) -> Vec<[T; 3]> {
        let zero = t.zero_like();
        let planar = |x: Vec<T>, y: Vec<T>| -> Vec<[T; 3]> {
            x.into_iter()
                .zip(y)
                .map(|(x, y)| [x, y, zero.clone()])
                .collect()
        };
        match *self {
            Shape::Circle { radius } => {
                let (x, y) = trig_pair(t, radius, radius, order);
                planar(x, y)
            }
            Shape::Ellipse { a, b } => {
                let (x, y) = trig_pair(t, a, b, order);
                planar(x, y)
            }
            Shape::Hyperbola {
                a,
                b,
                second_branch,
            } => {
                let a = if second_branch { -a } else { a };
                let (c, s) = (t.cosh(), t.sinh());
                // d/dt cosh = sinh, d/dt sinh = cosh: the pair alternates.
                let x = (0..=order)
                    .map(|k| t.lift(a) * if k % 2 == 0 { &c } else { &s })
                    .collect();
                let y = (0..=order)
                    .map(|k| t.lift(b) * if k % 2 == 0 { &s } else { &c })
                    .collect();
                planar(x, y)
            }
            Shape::Parabola { p } => {
                let two_p = t.lift(2.0 * p); // exact: a doubling
                let x = [
                    t.sqr() / &two_p,
                    t.clone() / t.lift(p),
                    t.one_like() / t.lift(p),
                    zero.clone(),
                ];
                let y = [t.clone(), t.one_like(), zero.clone(), zero.clone()];
                planar(x[..=order].to_vec(), y[..=order].to_vec())
            }
            Shape::Helix { radius, pitch } => {
                let (x, y) = trig_pair(t, radius, radius, order);
                let rise = t.lift(pitch) / (t.lift(2.0) * t.pi_like());
                let z = [t.clone() * &rise, rise, zero.clone(), zero.clone()];
                x.into_iter()
                    .zip(y)
                    .zip(z)
                    .map(|((x, y), z)| [x, y, z])
                    .collect()
            }
        }
    }

    /// The walking rule of §2.1: angular parameters step by `Δα`.
    fn step_hint(&self) -> StepHint {
        match self {
            Shape::Circle { .. } | Shape::Ellipse { .. } | Shape::Helix { .. } => {
                StepHint::Angular { rate: 1.0 }
            }
            _ => StepHint::Adaptive { max_step: None },
        }
    }
}

/// `(a cos t, b sin t)` and its derivatives up to `order`, as two lists.
fn trig_pair<T: Real>(t: &T, a: f64, b: f64, order: usize) -> (Vec<T>, Vec<T>) {
    let (c, s) = (t.cos(), t.sin());
    let (a, b) = (t.lift(a), t.lift(b));
    // The k-th derivative of cos is (cos, −sin, −cos, sin)[k mod 4], of sin likewise shifted.
    let cos_k = |k: usize| match k % 4 {
        0 => c.clone(),
        1 => -s.clone(),
        2 => -c.clone(),
        _ => s.clone(),
    };
    let x = (0..=order).map(|k| a.clone() * cos_k(k)).collect();
    let y = (0..=order).map(|k| b.clone() * cos_k(k + 3)).collect();
    (x, y)
}

/// A framed analytic space curve: circle, ellipse, hyperbola, parabola or helix
/// (§1.5, [Y 2.2.6–2.2.12]).
#[derive(Debug, Clone, PartialEq)]
pub struct Analytic {
    pub(crate) frame: Frame,
    pub(crate) shape: Shape,
    pub(crate) domain: Domain,
    pub(crate) closed: bool,
}

/// The domain of a shape: circles and ellipses default to `[0, 2π]` (closed, periodic;
/// any other domain is an arc), the other shapes need one.
fn shape_domain(shape: &Shape, domain: Option<(f64, f64)>) -> Result<(Domain, bool), GeomError> {
    shape.validate()?;
    let domain = match (domain, shape.is_trigonometric_closed()) {
        (Some((a, b)), _) => Domain::new("domain", a, b)?,
        (None, true) => Domain { lo: 0.0, hi: TAU },
        (None, false) => {
            return Err(GeomError::Format {
                field: "range".into(),
                message: "missing field `range` (this curve has no default domain)".into(),
            })
        }
    };
    let closed = shape.is_trigonometric_closed() && domain.hi - domain.lo == TAU;
    Ok((domain, closed))
}

impl Analytic {
    /// Errors: those of [`Frame::new`]; `non_finite` / `invalid_value` for a radius,
    /// semi-axis or focal parameter that is not finite and positive (`radius`, `a`,
    /// `b`, `p`), a non-finite `pitch`; `empty_domain` (`domain`); a missing domain for
    /// the hyperbola, parabola and helix (`format`, `range`).
    pub fn new(frame: Frame, shape: Shape, domain: Option<(f64, f64)>) -> Result<Self, GeomError> {
        let (domain, closed) = shape_domain(&shape, domain)?;
        Ok(Analytic {
            frame,
            shape,
            domain,
            closed,
        })
    }
    pub fn frame(&self) -> &Frame {
        &self.frame
    }
    pub fn shape(&self) -> Shape {
        self.shape
    }
}

impl Curve<3> for Analytic {
    fn domain(&self) -> (f64, f64) {
        self.domain.pair()
    }
    fn is_closed(&self) -> bool {
        self.closed
    }
    fn is_periodic(&self) -> bool {
        self.closed
    }
    /// A closed circle or ellipse runs over `[0, 2π]`, whose end is rounded.
    fn domain_rounded(&self) -> bool {
        self.closed
    }
    fn jet<T: Real>(&self, t: &T, order: usize) -> Vec<[T; 3]> {
        self.frame.place_jet(&self.shape.local_jet(t, order.min(3)))
    }
    fn step_hint(&self, _t: f64) -> StepHint {
        self.shape.step_hint()
    }
}

/// `circle2` / `ellipse2`: `center + (a cos t, b sin t)` (docs/FORMAT.md; a circle has
/// `a = b = r`), no frame.
#[derive(Debug, Clone, PartialEq)]
pub struct Analytic2 {
    pub(crate) center: [f64; 2],
    pub(crate) shape: Shape,
    pub(crate) domain: Domain,
    pub(crate) closed: bool,
}

impl Analytic2 {
    /// Only [`Shape::Circle`] and [`Shape::Ellipse`] are plane curves without a frame.
    /// Errors as [`Analytic::new`], `non_finite` (`center[i]`), `unsupported` (`type`)
    /// for another shape.
    pub fn new(
        center: [f64; 2],
        shape: Shape,
        domain: Option<(f64, f64)>,
    ) -> Result<Self, GeomError> {
        require_finite_all("center", &center)?;
        if !shape.is_trigonometric_closed() {
            return Err(GeomError::Unsupported {
                field: "type".into(),
                reason: "only circles and ellipses have 2D versions".into(),
            });
        }
        let (domain, closed) = shape_domain(&shape, domain)?;
        Ok(Analytic2 {
            center,
            shape,
            domain,
            closed,
        })
    }
    pub fn center(&self) -> [f64; 2] {
        self.center
    }
    pub fn shape(&self) -> Shape {
        self.shape
    }
}

impl Curve<2> for Analytic2 {
    fn domain(&self) -> (f64, f64) {
        self.domain.pair()
    }
    fn is_closed(&self) -> bool {
        self.closed
    }
    fn is_periodic(&self) -> bool {
        self.closed
    }
    /// A closed circle or ellipse runs over `[0, 2π]`, whose end is rounded.
    fn domain_rounded(&self) -> bool {
        self.closed
    }
    fn jet<T: Real>(&self, t: &T, order: usize) -> Vec<[T; 2]> {
        let local = self.shape.local_jet(t, order.min(3));
        local
            .into_iter()
            .enumerate()
            .map(|(k, [x, y, _])| {
                if k == 0 {
                    [x + t.lift(self.center[0]), y + t.lift(self.center[1])]
                } else {
                    [x, y]
                }
            })
            .collect()
    }
    fn step_hint(&self, _t: f64) -> StepHint {
        self.shape.step_hint()
    }
}

/// The circular arc of §1.5 [Y 2.2.10]: `p + r cos(t₀+σt) i₁ + r sin(t₀+σt) i₂`,
/// `t ∈ [0, φ]`, `σ = ±1` (+1 counter-clockwise seen against `i₃`).
/// Errors as [`Analytic::new`]; `invalid_value` (`sigma`) unless ±1, `non_finite`
/// (`t0`), `empty_domain` (`phi`) unless `φ > 0`.
pub fn circular_arc(
    frame: Frame,
    radius: f64,
    t0: f64,
    sigma: f64,
    phi: f64,
) -> Result<Reparametrised<Analytic>, GeomError> {
    let circle = Analytic::new(frame, Shape::Circle { radius }, None)?;
    Reparametrised::trimmed(circle, t0, sigma, 0.0, phi)
}

/// The elliptic arc of §1.5 [Y 2.2.11]: `p + a cos(t₀+σt) i₁ + b sin(t₀+σt) i₂`,
/// `t ∈ [0, φ]`. Errors as [`circular_arc`].
pub fn elliptic_arc(
    frame: Frame,
    a: f64,
    b: f64,
    t0: f64,
    sigma: f64,
    phi: f64,
) -> Result<Reparametrised<Analytic>, GeomError> {
    let ellipse = Analytic::new(frame, Shape::Ellipse { a, b }, None)?;
    Reparametrised::trimmed(ellipse, t0, sigma, 0.0, phi)
}
