//! The shapes every operation of the front door takes ([`Shape`]), and the query
//! points of projections and classification ([`Position`]).
//!
//! One type per concept: a sphere is a [`crate::surface::quadrics::Sphere`] inside
//! [`Shape::Surface`]; its implicit form, exact quadric form and closed-shell view are
//! conversions of it ([`crate::surface::AnySurface::implicit`],
//! [`crate::ops::algebraic::QuadricForm::of_surface`], [`crate::ops::closed_surface`]).
//! Linear objects keep their numbers exactly as given: doubles (the certified filtered
//! kernel), or rationals when some number is not a double (a `"1/3"` string of the
//! case format).

use nalgebra::{Vector2, Vector3};
use rug::Rational;

use super::polyhedron::Polyhedron;
use crate::curve::lines::{Line as CurveLine, Segment as CurveSegment};
use crate::curve::{AnyCurve2, AnyCurve3, Conic2};
use crate::error::GeomError;
use crate::geom::{
    Coord, Line, Line2, Linear as LinearRef, Linear2, ParamRange, Plane, Segment, Segment2,
};
use crate::surface::AnySurface;

/// A linear object over one coordinate type (`f64` or `rug::Rational`).
#[derive(Debug, Clone, PartialEq)]
pub enum LinearObject<T: Coord> {
    Line(Line<T>),
    Segment(Segment<T>),
    Plane(Plane<T>),
    Line2(Line2<T>),
    Segment2(Segment2<T>),
}

/// A linear object with its numbers as given: all doubles, or exact rationals.
#[derive(Debug, Clone, PartialEq)]
// Shapes are built once per call: their size does not matter.
#[allow(clippy::large_enum_variant)]
pub enum Linear {
    Double(LinearObject<f64>),
    Exact(LinearObject<Rational>),
}

/// Every shape an operation takes (OPERATIONS.md §1; the objects of the case format).
#[derive(Debug, Clone, PartialEq)]
pub enum Shape {
    /// Lines (with an optional range), segments and planes, in 3D and 2D.
    Linear(Linear),
    /// A space curve other than a plain line or segment.
    Curve(AnyCurve3),
    /// A parametric plane curve other than a plain 2D line or segment.
    Curve2(AnyCurve2),
    /// The implicit plane conic `conic2`.
    Conic2(Conic2),
    /// A parametric surface (a plane with a parametrisation and domain included).
    Surface(AnySurface),
    /// A closed polyhedral shell.
    Polyhedron(Polyhedron),
    /// The implicit quadric `[x 1]ᵀ Q [x 1] = 0` (no parametrisation: its points carry
    /// no parameters).
    Quadric(crate::surface::implicit::ImplicitQuadric),
}

/// A query point of `project` and `classify`: doubles, or exact rationals.
#[derive(Debug, Clone, PartialEq)]
pub enum Position {
    Double(Vec<f64>),
    Exact(Vec<Rational>),
}

impl<T: Coord> LinearObject<T> {
    /// The name of the shape's kind in the case format (`line`, `segment`, ...).
    pub fn type_name(&self) -> &'static str {
        match self {
            LinearObject::Line(_) => "line",
            LinearObject::Segment(_) => "segment",
            LinearObject::Plane(_) => "plane",
            LinearObject::Line2(_) => "line2",
            LinearObject::Segment2(_) => "segment2",
        }
    }
    /// The object as a 3D line or segment.
    pub fn linear(&self) -> Option<LinearRef<'_, T>> {
        match self {
            LinearObject::Line(l) => Some(LinearRef::Line(l)),
            LinearObject::Segment(s) => Some(LinearRef::Segment(s)),
            _ => None,
        }
    }
    /// The object as a 2D line or segment.
    pub fn linear2(&self) -> Option<Linear2<'_, T>> {
        match self {
            LinearObject::Line2(l) => Some(Linear2::Line(l)),
            LinearObject::Segment2(s) => Some(Linear2::Segment(s)),
            _ => None,
        }
    }
    /// The object as a plane.
    pub fn plane(&self) -> Option<&Plane<T>> {
        match self {
            LinearObject::Plane(p) => Some(p),
            _ => None,
        }
    }
}

/// The same object with every number mapped by `f` (an exact conversion: the object
/// stays valid, since the numbers are equal).
fn convert<T: Coord, U: Coord>(o: &LinearObject<T>, f: impl Fn(&T) -> U) -> LinearObject<U> {
    let v3 = |v: &Vector3<T>| Vector3::new(f(&v[0]), f(&v[1]), f(&v[2]));
    let v2 = |v: &Vector2<T>| Vector2::new(f(&v[0]), f(&v[1]));
    // The range as given: a ray keeps its one-sided range.
    let param_range = |r: Option<&ParamRange<T>>| {
        r.map(|r| match r {
            ParamRange::Closed([a, b]) => ParamRange::Closed([f(a), f(b)]),
            ParamRange::AtLeast(a) => ParamRange::AtLeast(f(a)),
            ParamRange::AtMost(b) => ParamRange::AtMost(f(b)),
        })
    };
    let built = match o {
        LinearObject::Line(l) => {
            Line::with_param_range(v3(l.origin()), v3(l.dir()), param_range(l.param_range()))
                .map(LinearObject::Line)
        }
        LinearObject::Segment(s) => Segment::new(v3(s.a()), v3(s.b())).map(LinearObject::Segment),
        LinearObject::Plane(Plane::Parametric { origin, u, v }) => {
            Plane::parametric(v3(origin), v3(u), v3(v)).map(LinearObject::Plane)
        }
        LinearObject::Plane(Plane::Implicit { normal, d }) => {
            Plane::implicit(v3(normal), f(d)).map(LinearObject::Plane)
        }
        LinearObject::Line2(l) => {
            Line2::with_param_range(v2(l.origin()), v2(l.dir()), param_range(l.param_range()))
                .map(LinearObject::Line2)
        }
        LinearObject::Segment2(s) => {
            Segment2::new(v2(s.a()), v2(s.b())).map(LinearObject::Segment2)
        }
    };
    built.expect("an exact conversion keeps a valid object valid")
}

impl LinearObject<f64> {
    /// The same object with its doubles as exact rationals.
    pub fn to_rational(&self) -> LinearObject<Rational> {
        convert(self, Coord::to_rational)
    }
}

impl Linear {
    /// The name of the shape's kind in the case format.
    pub fn type_name(&self) -> &'static str {
        match self {
            Linear::Double(o) => o.type_name(),
            Linear::Exact(o) => o.type_name(),
        }
    }

    /// The object in exact rationals.
    pub fn exact(&self) -> LinearObject<Rational> {
        match self {
            Linear::Double(o) => o.to_rational(),
            Linear::Exact(o) => o.clone(),
        }
    }

    /// A 3D line or segment as a curve of the curved operations (doubles only); `None`
    /// for planes and 2D objects. An unbounded line gets the range `reach` computes
    /// for it (`None`: the line needs a range, an `unsupported` error naming `range`).
    pub fn to_curve3(
        &self,
        reach: impl FnOnce(&[f64; 3], &[f64; 3]) -> Option<(f64, f64)>,
    ) -> Result<Option<AnyCurve3>, GeomError> {
        if !matches!(self.type_name(), "line" | "segment") {
            return Ok(None);
        }
        Ok(Some(match self.doubles()? {
            LinearObject::Line(l) => {
                let (o, d) = (arr3(l.origin()), arr3(l.dir()));
                let range = span(l.bounds(), || reach(&o, &d))?;
                AnyCurve3::Line(CurveLine::new(o, d, Some(range))?)
            }
            LinearObject::Segment(s) => {
                AnyCurve3::Segment(CurveSegment::new(arr3(s.a()), arr3(s.b()), None)?)
            }
            _ => return Ok(None),
        }))
    }

    /// A 2D line or segment as a plane curve (doubles only); `None` for other objects.
    /// An unbounded line gets the range `reach` computes for it, as in
    /// [`Linear::to_curve3`].
    pub fn to_curve2(
        &self,
        reach: impl FnOnce(&[f64; 2], &[f64; 2]) -> Option<(f64, f64)>,
    ) -> Result<Option<AnyCurve2>, GeomError> {
        if !matches!(self.type_name(), "line2" | "segment2") {
            return Ok(None);
        }
        Ok(match self.doubles()? {
            LinearObject::Line2(l) => {
                let (o, d) = ([l.origin()[0], l.origin()[1]], [l.dir()[0], l.dir()[1]]);
                let range = span(l.bounds(), || reach(&o, &d))?;
                Some(AnyCurve2::Line(CurveLine::new(o, d, Some(range))?))
            }
            LinearObject::Segment2(s) => Some(AnyCurve2::Segment(CurveSegment::new(
                [s.a()[0], s.a()[1]],
                [s.b()[0], s.b()[1]],
                None,
            )?)),
            _ => None,
        })
    }

    /// The object with every number rounded to the nearest double (for pictures: never
    /// for a computation whose answer is certified).
    pub fn rounded(&self) -> LinearObject<f64> {
        match self {
            Linear::Double(o) => o.clone(),
            Linear::Exact(o) => convert(o, Rational::to_f64),
        }
    }

    /// The object on doubles; an exact object is refused (`unsupported`, naming the
    /// object: curved operations take doubles).
    pub fn doubles(&self) -> Result<LinearObject<f64>, GeomError> {
        match self {
            Linear::Double(o) => Ok(o.clone()),
            Linear::Exact(o) => match o.first_inexact() {
                None => Ok(convert(o, Rational::to_f64)),
                Some(field) => Err(not_doubles(&field)),
            },
        }
    }
}

impl LinearObject<Rational> {
    /// The field path of the first number that is not a double (`origin[1]`).
    fn first_inexact(&self) -> Option<String> {
        let fields: Vec<(&str, Vec<&Rational>)> = match self {
            LinearObject::Line(l) => {
                let (lo, hi) = l.bounds();
                vec![
                    ("origin", l.origin().iter().collect()),
                    ("dir", l.dir().iter().collect()),
                    ("range", lo.into_iter().chain(hi).collect()),
                ]
            }
            LinearObject::Segment(s) => {
                vec![("a", s.a().iter().collect()), ("b", s.b().iter().collect())]
            }
            LinearObject::Plane(Plane::Parametric { origin, u, v }) => vec![
                ("origin", origin.iter().collect()),
                ("u", u.iter().collect()),
                ("v", v.iter().collect()),
            ],
            LinearObject::Plane(Plane::Implicit { normal, d }) => {
                vec![("normal", normal.iter().collect()), ("d", vec![d])]
            }
            LinearObject::Line2(l) => {
                let (lo, hi) = l.bounds();
                vec![
                    ("origin", l.origin().iter().collect()),
                    ("dir", l.dir().iter().collect()),
                    ("range", lo.into_iter().chain(hi).collect()),
                ]
            }
            LinearObject::Segment2(s) => {
                vec![("a", s.a().iter().collect()), ("b", s.b().iter().collect())]
            }
        };
        for (name, values) in fields {
            if let Some(i) = values.iter().position(|q| !is_double(q)) {
                return Some(if name == "d" {
                    name.into()
                } else {
                    format!("{name}[{i}]")
                });
            }
        }
        None
    }
}

/// The rational is exactly a finite double.
fn is_double(q: &Rational) -> bool {
    let r = crate::num::round::round_rational(q);
    r.is_exact() && !r.overflowed()
}

fn not_doubles(field: &str) -> GeomError {
    GeomError::Unsupported {
        field: field.into(),
        reason: "curved operations take doubles, not exact strings".into(),
    }
}

/// The parameter span a line is cut to as a curve: its closed range, or for an
/// unbounded end the part `reach` (a certified cover of the parameters that can meet
/// the other object) keeps of it. A ray whose reach is empty or one point (its end
/// beyond the cover, or on its edge) is cut to `[lo, next_up(lo)]` (`[next_down(hi),
/// hi]`): a part of the ray that holds every point the cover allows, so the answer
/// is the ray's, never the whole carrier's.
fn span(
    (lo, hi): (Option<&f64>, Option<&f64>),
    reach: impl FnOnce() -> Option<(f64, f64)>,
) -> Result<(f64, f64), GeomError> {
    if let (Some(&a), Some(&b)) = (lo, hi) {
        return Ok((a, b));
    }
    let (a, b) = reach().ok_or_else(needs_range)?;
    Ok(match (lo, hi) {
        (Some(&lo), _) if lo.max(a) < b => (lo.max(a), b),
        (Some(&lo), _) => (lo, lo.next_up()),
        (_, Some(&hi)) if a < hi.min(b) => (a, hi.min(b)),
        (_, Some(&hi)) => (hi.next_down(), hi),
        (None, None) => (a, b),
    })
}

fn needs_range() -> GeomError {
    GeomError::Unsupported {
        field: "range".into(),
        reason: "the line needs a `range` here: the other object is unbounded".into(),
    }
}

fn arr3(v: &Vector3<f64>) -> [f64; 3] {
    [v[0], v[1], v[2]]
}

impl Shape {
    /// The name of the shape's kind, as the case format writes it (`line`, `sphere`,
    /// `nurbs_surface`, ...), for messages.
    pub fn kind_name(&self) -> &'static str {
        match self {
            Shape::Linear(l) => l.type_name(),
            Shape::Curve(_) => "curve",
            Shape::Curve2(_) => "plane curve",
            Shape::Conic2(_) => "conic2",
            Shape::Surface(_) => "surface",
            Shape::Polyhedron(_) => "polyhedron",
            Shape::Quadric(_) => "quadric",
        }
    }

    /// Whether the shape lies in the plane (2D: `line2`, `segment2`, plane curves and
    /// conics), so that its points have two coordinates.
    pub fn is_2d(&self) -> bool {
        match self {
            Shape::Curve2(_) | Shape::Conic2(_) => true,
            Shape::Linear(l) => matches!(l.type_name(), "line2" | "segment2"),
            _ => false,
        }
    }

    /// Whether the shape is curved (a curve, a conic or a surface).
    pub fn is_curved(&self) -> bool {
        matches!(
            self,
            Shape::Curve(_)
                | Shape::Curve2(_)
                | Shape::Conic2(_)
                | Shape::Surface(_)
                | Shape::Quadric(_)
        )
    }
}

impl Position {
    /// The number of coordinates.
    pub fn dim(&self) -> usize {
        match self {
            Position::Double(v) => v.len(),
            Position::Exact(v) => v.len(),
        }
    }

    /// The coordinates as doubles (curved operations); an exact coordinate is refused
    /// naming `field[i]`.
    pub fn doubles<const D: usize>(&self, field: &str) -> Result<[f64; D], GeomError> {
        if self.dim() != D {
            return Err(GeomError::CountMismatch {
                field: field.into(),
                expected: format!("{D} coordinates"),
                found: self.dim().to_string(),
            });
        }
        match self {
            Position::Double(v) => Ok(std::array::from_fn(|i| v[i])),
            Position::Exact(v) => match v.iter().position(|q| !is_double(q)) {
                None => Ok(std::array::from_fn(|i| v[i].to_f64())),
                Some(i) => Err(not_doubles(&format!("{field}[{i}]"))),
            },
        }
    }

    /// The exact coordinates.
    pub fn exact(&self) -> Vec<Rational> {
        match self {
            Position::Double(v) => v.iter().map(|x| x.to_rational()).collect(),
            Position::Exact(v) => v.clone(),
        }
    }
}

// Conversions, so that a library caller writes `Shape::from(sphere)` (or passes
// `sphere.into()`) instead of spelling out the enum nesting.

macro_rules! shape_from {
    ($($ty:ty => |$v:ident| $body:expr),* $(,)?) => {
        $(impl From<$ty> for Shape {
            fn from($v: $ty) -> Shape {
                $body
            }
        })*
    };
}

macro_rules! surface_shape_from {
    ($($variant:ident($ty:ty)),* $(,)?) => {
        $(impl From<$ty> for Shape {
            fn from(s: $ty) -> Shape {
                Shape::Surface(AnySurface::$variant(s))
            }
        })*
    };
}

shape_from! {
    Line<f64> => |l| Shape::Linear(Linear::Double(LinearObject::Line(l))),
    Segment<f64> => |s| Shape::Linear(Linear::Double(LinearObject::Segment(s))),
    Plane<f64> => |p| Shape::Linear(Linear::Double(LinearObject::Plane(p))),
    Line2<f64> => |l| Shape::Linear(Linear::Double(LinearObject::Line2(l))),
    Segment2<f64> => |s| Shape::Linear(Linear::Double(LinearObject::Segment2(s))),
    Line<Rational> => |l| Shape::Linear(Linear::Exact(LinearObject::Line(l))),
    Segment<Rational> => |s| Shape::Linear(Linear::Exact(LinearObject::Segment(s))),
    Plane<Rational> => |p| Shape::Linear(Linear::Exact(LinearObject::Plane(p))),
    Line2<Rational> => |l| Shape::Linear(Linear::Exact(LinearObject::Line2(l))),
    Segment2<Rational> => |s| Shape::Linear(Linear::Exact(LinearObject::Segment2(s))),
    AnySurface => |s| Shape::Surface(s),
    AnyCurve3 => |c| Shape::Curve(c),
    AnyCurve2 => |c| Shape::Curve2(c),
    Conic2 => |c| Shape::Conic2(c),
    Polyhedron => |p| Shape::Polyhedron(p),
    crate::curve::Analytic => |c| Shape::Curve(AnyCurve3::Analytic(c)),
    crate::curve::Analytic2 => |c| Shape::Curve2(AnyCurve2::Analytic(c)),
}

surface_shape_from! {
    Sphere(crate::surface::quadrics::Sphere),
    Ellipsoid(crate::surface::quadrics::Ellipsoid),
    Hyperboloid(crate::surface::quadrics::Hyperboloid),
    Paraboloid(crate::surface::quadrics::Paraboloid),
    ParaboloidRect(crate::surface::plane::ParaboloidRect),
    Plane(crate::surface::plane::Plane),
    Cylinder(crate::surface::quadrics::Cylinder),
    Cone(crate::surface::quadrics::Cone),
    Torus(crate::surface::torus::Torus),
    Bilinear(crate::surface::bilinear::Bilinear),
    Bezier(crate::surface::bezier::BezierSurface),
    Nurbs(crate::surface::nurbs::NurbsSurface),
}
