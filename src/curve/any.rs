//! One enum over every space curve ([`AnyCurve3`]) and every plane curve
//! ([`AnyCurve2`]), so operations and the JSON layer can hold any curve; each
//! implements [`Curve`] by forwarding to the primitive.

use super::analytic::{Analytic, Analytic2};
use super::bezier::Bezier;
use super::derived::Reparametrised;
use super::lines::{Line, Segment};
use super::nurbs::NurbsCurve;
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
        }
    };
}

impl Curve<3> for AnyCurve3 {
    fn piece_breaks(&self) -> Vec<f64> {
        match self {
            AnyCurve3::Nurbs(c) => c.piece_breaks(),
            _ => Vec::new(),
        }
    }
    fn pinned_at(&self, t: f64) -> Option<Self> {
        match self {
            AnyCurve3::Nurbs(c) => c.pinned_at(t).map(AnyCurve3::Nurbs),
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
            _ => Vec::new(),
        }
    }
    fn pinned_at(&self, t: f64) -> Option<Self> {
        match self {
            AnyCurve2::Nurbs(c) => c.pinned_at(t).map(AnyCurve2::Nurbs),
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
