//! One enum over every space curve ([`AnyCurve3`]) and every plane curve
//! ([`AnyCurve2`]), so operations and the JSON layer can hold any curve; each
//! implements [`Curve`] by forwarding to the primitive.

use super::analytic::{Analytic, Analytic2};
use super::bezier::Bezier;
use super::composite::Composite;
use super::derived::Reparametrised;
use super::extended::Extended;
use super::lines::{Line, Segment};
use super::nurbs::NurbsCurve;
use super::offset::{Offset2, Offset3};
use super::polyline::Polyline;
use super::{Curve, StepHint};
use crate::num::Real;

/// Any space curve.
#[derive(Debug, Clone, PartialEq)]
pub enum AnyCurve3 {
    Line(Line<3>),
    Segment(Segment<3>),
    /// Circle, ellipse, hyperbola, parabola, helix (and arcs of them by domain).
    Analytic(Analytic),
    Bezier(Bezier<3>),
    Nurbs(NurbsCurve<3>),
    Polyline(Polyline<3>),
    /// Trimmed, reversed or reparametrised curve.
    Reparametrised(Box<Reparametrised<AnyCurve3>>),
    /// `c + t̂ × d` (§1.5).
    Offset(Box<Offset3<AnyCurve3>>),
    /// Pieces joined end to end (§1.5).
    Composite(Box<Composite<AnyCurve3>>),
    /// Continued along the end tangents (§1.5).
    Extended(Box<Extended<AnyCurve3>>),
}

/// Any plane curve (parametric; the implicit `conic2` is [`super::Conic2`]).
#[derive(Debug, Clone, PartialEq)]
pub enum AnyCurve2 {
    Line(Line<2>),
    Segment(Segment<2>),
    /// `circle2`, `ellipse2`.
    Analytic(Analytic2),
    Bezier(Bezier<2>),
    Nurbs(NurbsCurve<2>),
    Polyline(Polyline<2>),
    Reparametrised(Box<Reparametrised<AnyCurve2>>),
    /// `c + a·n` (§1.2).
    Offset(Box<Offset2<AnyCurve2>>),
    Composite(Box<Composite<AnyCurve2>>),
    Extended(Box<Extended<AnyCurve2>>),
}

/// Forward one call to the primitive held by the enum.
macro_rules! forward {
    ($enum:ident, $self:expr, $c:ident => $call:expr) => {
        match $self {
            $enum::Line($c) => $call,
            $enum::Segment($c) => $call,
            $enum::Analytic($c) => $call,
            $enum::Bezier($c) => $call,
            $enum::Nurbs($c) => $call,
            $enum::Polyline($c) => $call,
            $enum::Reparametrised($c) => $call,
            $enum::Offset($c) => $call,
            $enum::Composite($c) => $call,
            $enum::Extended($c) => $call,
        }
    };
}

impl Curve<3> for AnyCurve3 {
    fn piece_breaks(&self) -> Vec<f64> {
        match self {
            AnyCurve3::Nurbs(c) => c.piece_breaks(),
            AnyCurve3::Offset(c) => c.piece_breaks(),
            AnyCurve3::Composite(c) => c.piece_breaks(),
            AnyCurve3::Extended(c) => c.piece_breaks(),
            _ => Vec::new(),
        }
    }
    fn pinned_at(&self, t: f64) -> Option<Self> {
        match self {
            AnyCurve3::Nurbs(c) => c.pinned_at(t).map(AnyCurve3::Nurbs),
            AnyCurve3::Offset(c) => c.pinned_at(t).map(|p| AnyCurve3::Offset(Box::new(p))),
            AnyCurve3::Composite(c) => c.pinned_at(t).map(|p| AnyCurve3::Composite(Box::new(p))),
            AnyCurve3::Extended(c) => c.pinned_at(t).map(|p| AnyCurve3::Extended(Box::new(p))),
            _ => None,
        }
    }
    fn domain(&self) -> (f64, f64) {
        forward!(AnyCurve3, self, c => c.domain())
    }
    fn is_closed(&self) -> bool {
        forward!(AnyCurve3, self, c => c.is_closed())
    }
    fn is_periodic(&self) -> bool {
        forward!(AnyCurve3, self, c => c.is_periodic())
    }
    fn domain_rounded(&self) -> bool {
        forward!(AnyCurve3, self, c => c.domain_rounded())
    }
    fn jet<T: Real>(&self, t: &T, order: usize) -> Vec<[T; 3]> {
        forward!(AnyCurve3, self, c => c.jet(t, order))
    }
    fn tangent_breaks(&self) -> Vec<(f64, f64)> {
        forward!(AnyCurve3, self, c => c.tangent_breaks())
    }
    fn step_hint(&self, t: f64) -> StepHint {
        forward!(AnyCurve3, self, c => c.step_hint(t))
    }
}

impl Curve<2> for AnyCurve2 {
    fn piece_breaks(&self) -> Vec<f64> {
        match self {
            AnyCurve2::Nurbs(c) => c.piece_breaks(),
            AnyCurve2::Offset(c) => c.piece_breaks(),
            AnyCurve2::Composite(c) => c.piece_breaks(),
            AnyCurve2::Extended(c) => c.piece_breaks(),
            _ => Vec::new(),
        }
    }
    fn pinned_at(&self, t: f64) -> Option<Self> {
        match self {
            AnyCurve2::Nurbs(c) => c.pinned_at(t).map(AnyCurve2::Nurbs),
            AnyCurve2::Offset(c) => c.pinned_at(t).map(|p| AnyCurve2::Offset(Box::new(p))),
            AnyCurve2::Composite(c) => c.pinned_at(t).map(|p| AnyCurve2::Composite(Box::new(p))),
            AnyCurve2::Extended(c) => c.pinned_at(t).map(|p| AnyCurve2::Extended(Box::new(p))),
            _ => None,
        }
    }
    fn domain(&self) -> (f64, f64) {
        forward!(AnyCurve2, self, c => c.domain())
    }
    fn is_closed(&self) -> bool {
        forward!(AnyCurve2, self, c => c.is_closed())
    }
    fn is_periodic(&self) -> bool {
        forward!(AnyCurve2, self, c => c.is_periodic())
    }
    fn domain_rounded(&self) -> bool {
        forward!(AnyCurve2, self, c => c.domain_rounded())
    }
    fn jet<T: Real>(&self, t: &T, order: usize) -> Vec<[T; 2]> {
        forward!(AnyCurve2, self, c => c.jet(t, order))
    }
    fn tangent_breaks(&self) -> Vec<(f64, f64)> {
        forward!(AnyCurve2, self, c => c.tangent_breaks())
    }
    fn step_hint(&self, t: f64) -> StepHint {
        forward!(AnyCurve2, self, c => c.step_hint(t))
    }
}
