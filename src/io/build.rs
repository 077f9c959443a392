//! Specs of the case format → the typed shapes of the front door (docs/FORMAT.md "Objects",
//! "Numbers"), with every error's field path prefixed by the object's place in the
//! case (`objects[1].dir[2]`).
//!
//! A linear object keeps its numbers exactly: doubles when every number is one (the
//! certified, filtered kernel), `rug::Rational` when a string holds a number that no
//! double equals. A query point likewise.

use nalgebra::{Vector2, Vector3};
use rug::Rational;

use super::number::Num;
use super::objects::{
    Line2Spec, LineSpec, ObjectSpec, PlaneSpec, PolyhedronSpec, Segment2Spec, SegmentSpec,
};
use super::shapes::PlaneShape;
use crate::error::GeomError;
use crate::geom::{Coord, Line, Line2, ParamRange, Plane, Segment, Segment2};
use crate::num::parse::parse_rational;
use crate::num::round::round_rational;
use crate::ops::{Linear, LinearObject, Polyhedron, Position, Shape};
use crate::surface::implicit::ImplicitQuadric;

/// Why an object could not be built in the requested coordinate type.
#[derive(Debug)]
enum BuildError {
    /// The input is invalid.
    Geom(GeomError),
    /// A number is exact text that no double equals: use rationals.
    NeedsRational,
}

impl From<GeomError> for BuildError {
    fn from(e: GeomError) -> Self {
        BuildError::Geom(e)
    }
}

/// A coordinate type that case numbers convert into exactly.
trait FromNum: Coord + Sized {
    /// `field` names the number in an error (built only then: this runs for every
    /// coordinate of every case).
    fn from_num(n: &Num, field: &dyn Fn() -> String) -> Result<Self, BuildError>;
}

impl FromNum for f64 {
    /// A double as is; a string only when its exact value is a double.
    fn from_num(n: &Num, field: &dyn Fn() -> String) -> Result<f64, BuildError> {
        match n {
            Num::Double(v) => Ok(*v),
            Num::Text(t) => {
                let q = parse_rational(&field(), t)?;
                let r = round_rational(&q);
                if r.is_exact() && !r.overflowed() {
                    Ok(r.nearest)
                } else {
                    Err(BuildError::NeedsRational)
                }
            }
        }
    }
}

impl FromNum for Rational {
    fn from_num(n: &Num, field: &dyn Fn() -> String) -> Result<Rational, BuildError> {
        match n {
            Num::Double(v) => Ok(crate::num::parse::rational_from_f64(&field(), *v)?),
            Num::Text(t) => Ok(parse_rational(&field(), t)?),
        }
    }
}

fn vec3<T: FromNum>(v: &[Num], field: &str) -> Result<Vector3<T>, BuildError> {
    if v.len() != 3 {
        return Err(GeomError::Format {
            field: field.to_string(),
            message: format!("expected 3 coordinates, found {}", v.len()),
        }
        .into());
    }
    let c = |i: usize| T::from_num(&v[i], &|| format!("{field}[{i}]"));
    Ok(Vector3::new(c(0)?, c(1)?, c(2)?))
}

fn vec2<T: FromNum>(v: &[Num; 2], field: &str) -> Result<Vector2<T>, BuildError> {
    let c = |i: usize| T::from_num(&v[i], &|| format!("{field}[{i}]"));
    Ok(Vector2::new(c(0)?, c(1)?))
}

/// A line's `range`: closed `[t0, t1]`, one-sided with `null` for the infinite end (a
/// ray), or `[null, null]`, the whole line (as no `range`).
fn range<T: FromNum>(
    r: &Option<[Option<Num>; 2]>,
    field: &str,
) -> Result<Option<ParamRange<T>>, BuildError> {
    let end = |n: &Option<Num>, i: usize| {
        n.as_ref()
            .map(|n| T::from_num(n, &|| format!("{field}[{i}]")))
            .transpose()
    };
    let Some([a, b]) = r else {
        return Ok(None);
    };
    Ok(match (end(a, 0)?, end(b, 1)?) {
        (Some(lo), Some(hi)) => Some(ParamRange::Closed([lo, hi])),
        (Some(lo), None) => Some(ParamRange::AtLeast(lo)),
        (None, Some(hi)) => Some(ParamRange::AtMost(hi)),
        (None, None) => None,
    })
}

/// One object of a case as a shape; errors name fields below `prefix`.
pub fn shape(spec: &ObjectSpec, prefix: &str) -> Result<Shape, GeomError> {
    let at = |e: GeomError| e.at(prefix);
    Ok(match spec {
        ObjectSpec::Curve3(c) => Shape::Curve(c.build().map_err(at)?),
        ObjectSpec::Curve2(c) => match c.build().map_err(at)? {
            PlaneShape::Curve(c) => Shape::Curve2(c),
            PlaneShape::Conic(c) => Shape::Conic2(c),
        },
        ObjectSpec::Surface(s) => Shape::Surface(s.build().map_err(at)?),
        ObjectSpec::Polyhedron(p) => Shape::Polyhedron(polyhedron(p).map_err(at)?),
        ObjectSpec::Quadric(q) => Shape::Quadric(ImplicitQuadric::new(q.matrix).map_err(at)?),
        linear => Shape::Linear(match linear_object::<f64>(linear) {
            Ok(o) => Linear::Double(o),
            Err(BuildError::NeedsRational) => match linear_object::<Rational>(linear) {
                Ok(o) => Linear::Exact(o),
                Err(BuildError::Geom(e)) => return Err(at(e)),
                Err(BuildError::NeedsRational) => return Err(at(unreachable_rational())),
            },
            Err(BuildError::Geom(e)) => return Err(at(e)),
        }),
    })
}

/// A query point: doubles, or rationals when a coordinate is exact text that no double
/// equals; errors name `field[i]`.
pub fn position(v: &[Num], field: &str) -> Result<Position, GeomError> {
    let doubles: Result<Vec<f64>, BuildError> = v
        .iter()
        .enumerate()
        .map(|(i, n)| f64::from_num(n, &|| format!("{field}[{i}]")))
        .collect();
    match doubles {
        Ok(d) => Ok(Position::Double(d)),
        Err(BuildError::Geom(e)) => Err(e),
        Err(BuildError::NeedsRational) => v
            .iter()
            .enumerate()
            .map(
                |(i, n)| match Rational::from_num(n, &|| format!("{field}[{i}]")) {
                    Ok(q) => Ok(q),
                    Err(BuildError::Geom(e)) => Err(e),
                    Err(BuildError::NeedsRational) => Err(unreachable_rational()),
                },
            )
            .collect::<Result<_, _>>()
            .map(Position::Exact),
    }
}

fn linear_object<T: FromNum>(spec: &ObjectSpec) -> Result<LinearObject<T>, BuildError> {
    Ok(match spec {
        ObjectSpec::Line(LineSpec {
            origin,
            dir,
            range: r,
        }) => LinearObject::Line(Line::with_param_range(
            vec3(origin, "origin")?,
            vec3(dir, "dir")?,
            range(r, "range")?,
        )?),
        ObjectSpec::Segment(SegmentSpec { a, b }) => {
            LinearObject::Segment(Segment::new(vec3(a, "a")?, vec3(b, "b")?)?)
        }
        ObjectSpec::Plane(p) => LinearObject::Plane(plane(p)?),
        ObjectSpec::Line2(Line2Spec {
            origin,
            dir,
            range: r,
        }) => LinearObject::Line2(Line2::with_param_range(
            vec2(origin, "origin")?,
            vec2(dir, "dir")?,
            range(r, "range")?,
        )?),
        ObjectSpec::Segment2(Segment2Spec { a, b }) => {
            LinearObject::Segment2(Segment2::new(vec2(a, "a")?, vec2(b, "b")?)?)
        }
        ObjectSpec::Polyhedron(_)
        | ObjectSpec::Curve3(_)
        | ObjectSpec::Curve2(_)
        | ObjectSpec::Surface(_)
        | ObjectSpec::Quadric(_) => {
            return Err(GeomError::Unsupported {
                field: "type".into(),
                reason: "not a linear object".into(),
            }
            .into())
        }
    })
}

/// A plane is parametric (`origin`, `u`, `v`) or implicit (`normal`, `d`): exactly one
/// complete set of fields.
fn plane<T: FromNum>(p: &PlaneSpec) -> Result<Plane<T>, BuildError> {
    let parametric = p.origin.is_some() || p.u.is_some() || p.v.is_some();
    let implicit = p.normal.is_some() || p.d.is_some();
    if let Some(points) = &p.points {
        if parametric || implicit {
            return Err(GeomError::Format {
                field: "points".into(),
                message: "a plane is given by origin, u, v, or normal, d, or points, not \
                          by two of them"
                    .into(),
            }
            .into());
        }
        return through_points(points);
    }
    let missing = |field: &str, form: &str| GeomError::Format {
        field: field.to_string(),
        message: format!("missing field `{field}` of a {form} plane"),
    };
    match (parametric, implicit) {
        (true, true) => Err(GeomError::Format {
            field: if p.normal.is_some() { "normal" } else { "d" }.into(),
            message: "a plane is either parametric (origin, u, v) or implicit (normal, d), \
                      not both"
                .into(),
        }
        .into()),
        (true, false) => {
            let origin = p
                .origin
                .as_ref()
                .ok_or_else(|| missing("origin", "parametric"))?;
            let u = p.u.as_ref().ok_or_else(|| missing("u", "parametric"))?;
            let v = p.v.as_ref().ok_or_else(|| missing("v", "parametric"))?;
            Ok(Plane::parametric(
                vec3(origin, "origin")?,
                vec3(u, "u")?,
                vec3(v, "v")?,
            )?)
        }
        (false, true) => {
            let normal = p
                .normal
                .as_ref()
                .ok_or_else(|| missing("normal", "implicit"))?;
            let d = p.d.as_ref().ok_or_else(|| missing("d", "implicit"))?;
            Ok(Plane::implicit(
                vec3(normal, "normal")?,
                T::from_num(d, &|| "d".into())?,
            )?)
        }
        (false, false) => Err(GeomError::Format {
            field: String::new(),
            message: "a plane needs origin, u, v (parametric) or normal, d (implicit)".into(),
        }
        .into()),
    }
}

/// The plane through three points (OPERATIONS.md §13.1), exactly: `n·x + d = 0` with
/// `n = (M₁ − M₀) × (M₂ − M₀)`; collinear points are an error naming `points[i]`.
fn through_points<T: FromNum>(points: &[[Num; 3]; 3]) -> Result<Plane<T>, BuildError> {
    let mut exact: [[Rational; 3]; 3] = Default::default();
    for (i, p) in points.iter().enumerate() {
        let v: Vector3<Rational> = vec3(p, &format!("points[{i}]"))?;
        exact[i] = [v[0].clone(), v[1].clone(), v[2].clone()];
    }
    let plane = crate::ops::section::plane_through_points_exact(&exact)?;
    let as_t =
        |q: &Rational, field: &str| T::from_num(&Num::Text(q.to_string()), &|| field.to_string());
    let n = &plane.normal;
    Ok(Plane::implicit(
        Vector3::new(
            as_t(&n[0], "points")?,
            as_t(&n[1], "points")?,
            as_t(&n[2], "points")?,
        ),
        as_t(&plane.d, "points")?,
    )?)
}

/// Validate a polyhedron (exact vertices); errors name fields below the object.
fn polyhedron(spec: &PolyhedronSpec) -> Result<Polyhedron, GeomError> {
    let vertices = spec
        .vertices
        .iter()
        .enumerate()
        .map(|(i, v)| {
            let v: Vector3<Rational> = vec3(v, &format!("vertices[{i}]")).map_err(|e| match e {
                BuildError::Geom(g) => g,
                BuildError::NeedsRational => unreachable_rational(),
            })?;
            Ok([v[0].clone(), v[1].clone(), v[2].clone()])
        })
        .collect::<Result<Vec<_>, GeomError>>()?;
    Polyhedron::new(vertices, spec.faces.clone())
}

/// Rationals take every number; kept as a typed error rather than a panic.
fn unreachable_rational() -> GeomError {
    GeomError::Unsupported {
        field: String::new(),
        reason: "internal: a rational coordinate was refused".into(),
    }
}
