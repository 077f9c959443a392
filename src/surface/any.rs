//! One type for every surface primitive that does not depend on a curve type
//! ([`AnySurface`]), and for every implicit form ([`AnyImplicit`]), so that heterogeneous
//! collections and the JSON reader need no trait objects (the traits are generic, hence
//! not object-safe). The motion surfaces (§1.6: extrusion, revolution, ruled) hold their
//! curves as [`AnyCurve3`], boxed (a curve enum is large).

use super::bezier::BezierSurface;
use super::bilinear::Bilinear;
use super::implicit::ImplicitQuadric;
use super::motion::{Extrusion, Revolution, Ruled};
use super::nurbs::NurbsSurface;
use super::plane::{ParaboloidRect, Plane};
use super::quadrics::{Cone, Cylinder, Ellipsoid, Hyperboloid, Paraboloid, Sphere};
use super::torus::Torus;
use super::{Implicit, ImplicitJet, StepRule, Surface};
use crate::curve::AnyCurve3;
use crate::num::Real;

/// A parametric surface primitive.
#[derive(Debug, Clone, PartialEq)]
pub enum AnySurface {
    Plane(Plane),
    Sphere(Sphere),
    Ellipsoid(Ellipsoid),
    Hyperboloid(Hyperboloid),
    Paraboloid(Paraboloid),
    ParaboloidRect(ParaboloidRect),
    Cylinder(Cylinder),
    Cone(Cone),
    Torus(Torus),
    Bilinear(Bilinear),
    Bezier(BezierSurface),
    Nurbs(NurbsSurface),
    /// `extrusion` (1.13): a profile swept along a vector.
    Extrusion(Box<Extrusion<AnyCurve3>>),
    /// `revolution` (1.14): a profile turned about an axis.
    Revolution(Box<Revolution<AnyCurve3>>),
    /// `ruled` (1.17): the segments between two guides.
    Ruled(Box<Ruled<AnyCurve3, AnyCurve3>>),
}

macro_rules! each_surface {
    ($value:expr, $s:ident => $body:expr) => {
        match $value {
            AnySurface::Plane($s) => $body,
            AnySurface::Sphere($s) => $body,
            AnySurface::Ellipsoid($s) => $body,
            AnySurface::Hyperboloid($s) => $body,
            AnySurface::Paraboloid($s) => $body,
            AnySurface::ParaboloidRect($s) => $body,
            AnySurface::Cylinder($s) => $body,
            AnySurface::Cone($s) => $body,
            AnySurface::Torus($s) => $body,
            AnySurface::Bilinear($s) => $body,
            AnySurface::Bezier($s) => $body,
            AnySurface::Nurbs($s) => $body,
            AnySurface::Extrusion($s) => $body,
            AnySurface::Revolution($s) => $body,
            AnySurface::Ruled($s) => $body,
        }
    };
}

impl Surface for AnySurface {
    fn domain(&self) -> ([f64; 2], [f64; 2]) {
        each_surface!(self, s => s.domain())
    }
    fn is_closed(&self) -> [bool; 2] {
        each_surface!(self, s => s.is_closed())
    }
    fn domain_rounded(&self) -> [bool; 2] {
        each_surface!(self, s => s.domain_rounded())
    }
    fn v_poles(&self) -> [bool; 2] {
        each_surface!(self, s => s.v_poles())
    }
    fn jet<T: Real>(&self, u: &T, v: &T, order: usize) -> Vec<[T; 3]> {
        each_surface!(self, s => s.jet(u, v, order))
    }
    fn implicit_value<T: Real>(&self, x: &[T; 3]) -> Option<T> {
        each_surface!(self, s => s.implicit_value(x))
    }
    fn step_rules(&self) -> [StepRule; 2] {
        each_surface!(self, s => s.step_rules())
    }
    fn piece_breaks(&self) -> [Vec<f64>; 2] {
        each_surface!(self, s => s.piece_breaks())
    }
    fn pinned_at(&self, u: f64, v: f64) -> Option<Self> {
        match self {
            AnySurface::Nurbs(s) => s.pinned_at(u, v).map(AnySurface::Nurbs),
            AnySurface::Extrusion(s) => s.pinned_at(u, v).map(|p| AnySurface::Extrusion(p.into())),
            AnySurface::Revolution(s) => {
                s.pinned_at(u, v).map(|p| AnySurface::Revolution(p.into()))
            }
            _ => None,
        }
    }
    fn knot_span(&self, direction: usize, t: f64) -> Option<(f64, f64)> {
        each_surface!(self, s => s.knot_span(direction, t))
    }
}

/// Each primitive as an [`AnySurface`]: one type for all, so that generic operations are
/// instantiated once, not once per pair of surface types (and the non-generic entry
/// points, e.g. `intersect_surface_surface(&a.into(), &b.into(), …)`, are compiled in this
/// library, not again in the caller's crate).
macro_rules! into_any_surface {
    ($($t:ident => $v:ident),*) => {$(
        impl From<$t> for AnySurface {
            fn from(s: $t) -> AnySurface {
                AnySurface::$v(s)
            }
        }
    )*};
}
into_any_surface!(Plane => Plane, Sphere => Sphere, Ellipsoid => Ellipsoid,
    Hyperboloid => Hyperboloid, Paraboloid => Paraboloid, ParaboloidRect => ParaboloidRect,
    Cylinder => Cylinder, Cone => Cone, Torus => Torus, Bilinear => Bilinear,
    BezierSurface => Bezier, NurbsSurface => Nurbs);

impl AnySurface {
    /// The implicit form of the surface (§1.6), if it has one (not for bilinear, Bézier
    /// and NURBS patches, nor for the motion surfaces, whose implicit form depends on
    /// their curves).
    pub fn implicit(&self) -> Option<AnyImplicit> {
        Some(match self {
            AnySurface::Plane(s) => AnyImplicit::Plane(s.clone()),
            AnySurface::Sphere(s) => AnyImplicit::Sphere(s.clone()),
            AnySurface::Ellipsoid(s) => AnyImplicit::Ellipsoid(s.clone()),
            AnySurface::Hyperboloid(s) => AnyImplicit::Hyperboloid(s.clone()),
            AnySurface::Paraboloid(s) => AnyImplicit::Paraboloid(s.clone()),
            AnySurface::ParaboloidRect(s) => AnyImplicit::ParaboloidRect(s.clone()),
            AnySurface::Cylinder(s) => AnyImplicit::Cylinder(s.clone()),
            AnySurface::Cone(s) => AnyImplicit::Cone(s.clone()),
            AnySurface::Torus(s) => AnyImplicit::Torus(s.clone()),
            AnySurface::Bilinear(_)
            | AnySurface::Bezier(_)
            | AnySurface::Nurbs(_)
            | AnySurface::Extrusion(_)
            | AnySurface::Revolution(_)
            | AnySurface::Ruled(_) => return None,
        })
    }
}

/// An implicit surface `F(x) = 0`.
#[derive(Debug, Clone, PartialEq)]
pub enum AnyImplicit {
    Quadric(ImplicitQuadric),
    Plane(Plane),
    Sphere(Sphere),
    Ellipsoid(Ellipsoid),
    Hyperboloid(Hyperboloid),
    Paraboloid(Paraboloid),
    ParaboloidRect(ParaboloidRect),
    Cylinder(Cylinder),
    Cone(Cone),
    Torus(Torus),
}

impl Implicit<3> for AnyImplicit {
    fn implicit_jet<T: Real>(&self, x: &[T; 3], order: usize) -> ImplicitJet<T, 3> {
        match self {
            AnyImplicit::Quadric(s) => s.implicit_jet(x, order),
            AnyImplicit::Plane(s) => s.implicit_jet(x, order),
            AnyImplicit::Sphere(s) => s.implicit_jet(x, order),
            AnyImplicit::Ellipsoid(s) => s.implicit_jet(x, order),
            AnyImplicit::Hyperboloid(s) => s.implicit_jet(x, order),
            AnyImplicit::Paraboloid(s) => s.implicit_jet(x, order),
            AnyImplicit::ParaboloidRect(s) => s.implicit_jet(x, order),
            AnyImplicit::Cylinder(s) => s.implicit_jet(x, order),
            AnyImplicit::Cone(s) => s.implicit_jet(x, order),
            AnyImplicit::Torus(s) => s.implicit_jet(x, order),
        }
    }
}
