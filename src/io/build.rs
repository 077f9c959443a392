//! Specs of the case format → validated geometric objects (CASES.md "Objects",
//! "Numbers"), with every error's field path prefixed by the object's place in the
//! case (`objects[1].dir[2]`).
//!
//! The coordinate type is chosen per case: `f64` when every number is a double (the
//! certified, filtered path), `rug::Rational` when a string holds a number that no
//! double equals, or when `options.exact` asks for the exact rationals.

use nalgebra::{Vector2, Vector3};
use rug::Rational;

use super::number::Num;
use super::objects::{
    Line2Spec, LineSpec, ObjectSpec, PlaneSpec, PolyhedronSpec, Segment2Spec, SegmentSpec,
};
use crate::error::GeomError;
use crate::geom::{Coord, Line, Line2, Linear, Linear2, Plane, Segment, Segment2};
use crate::num::parse::parse_rational;
use crate::num::round::round_rational;
use crate::ops::Polyhedron;

/// Why an object could not be built in the requested coordinate type.
#[derive(Debug)]
pub(crate) enum BuildError {
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
pub(crate) trait FromNum: Coord + Sized {
    fn from_num(n: &Num, field: &str) -> Result<Self, BuildError>;
}

impl FromNum for f64 {
    /// A double as is; a string only when its exact value is a double.
    fn from_num(n: &Num, field: &str) -> Result<f64, BuildError> {
        match n {
            Num::Double(v) => Ok(*v),
            Num::Text(t) => {
                let q = parse_rational(field, t)?;
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
    fn from_num(n: &Num, field: &str) -> Result<Rational, BuildError> {
        match n {
            Num::Double(v) => Ok(crate::num::parse::rational_from_f64(field, *v)?),
            Num::Text(t) => Ok(parse_rational(field, t)?),
        }
    }
}

pub(crate) fn vec3<T: FromNum>(v: &[Num], field: &str) -> Result<Vector3<T>, BuildError> {
    if v.len() != 3 {
        return Err(GeomError::Format {
            field: field.to_string(),
            message: format!("expected 3 coordinates, found {}", v.len()),
        }
        .into());
    }
    let c = |i: usize| T::from_num(&v[i], &format!("{field}[{i}]"));
    Ok(Vector3::new(c(0)?, c(1)?, c(2)?))
}

fn vec2<T: FromNum>(v: &[Num; 2], field: &str) -> Result<Vector2<T>, BuildError> {
    let c = |i: usize| T::from_num(&v[i], &format!("{field}[{i}]"));
    Ok(Vector2::new(c(0)?, c(1)?))
}

fn range<T: FromNum>(r: &Option<[Num; 2]>, field: &str) -> Result<Option<[T; 2]>, BuildError> {
    r.as_ref()
        .map(|[a, b]| {
            Ok([
                T::from_num(a, &format!("{field}[0]"))?,
                T::from_num(b, &format!("{field}[1]"))?,
            ])
        })
        .transpose()
}

/// A linear object, validated.
#[derive(Debug, Clone)]
pub(crate) enum Object<T: Coord> {
    Line(Line<T>),
    Segment(Segment<T>),
    Plane(Plane<T>),
    Line2(Line2<T>),
    Segment2(Segment2<T>),
}

impl<T: Coord> Object<T> {
    /// The object as a 3D line or segment.
    pub fn linear(&self) -> Option<Linear<'_, T>> {
        match self {
            Object::Line(l) => Some(Linear::Line(l)),
            Object::Segment(s) => Some(Linear::Segment(s)),
            _ => None,
        }
    }
    /// The object as a 2D line or segment.
    pub fn linear2(&self) -> Option<Linear2<'_, T>> {
        match self {
            Object::Line2(l) => Some(Linear2::Line(l)),
            Object::Segment2(s) => Some(Linear2::Segment(s)),
            _ => None,
        }
    }
    pub fn plane(&self) -> Option<&Plane<T>> {
        match self {
            Object::Plane(p) => Some(p),
            _ => None,
        }
    }
}

/// Validate one object; errors name fields below `prefix`.
pub(crate) fn build<T: FromNum>(spec: &ObjectSpec, prefix: &str) -> Result<Object<T>, BuildError> {
    build_inner(spec).map_err(|e| match e {
        BuildError::Geom(g) => BuildError::Geom(g.at(prefix)),
        other => other,
    })
}

fn build_inner<T: FromNum>(spec: &ObjectSpec) -> Result<Object<T>, BuildError> {
    Ok(match spec {
        ObjectSpec::Line(LineSpec {
            origin,
            dir,
            range: r,
        }) => Object::Line(Line::with_range(
            vec3(origin, "origin")?,
            vec3(dir, "dir")?,
            range(r, "range")?,
        )?),
        ObjectSpec::Segment(SegmentSpec { a, b }) => {
            Object::Segment(Segment::new(vec3(a, "a")?, vec3(b, "b")?)?)
        }
        ObjectSpec::Plane(p) => Object::Plane(plane(p)?),
        ObjectSpec::Line2(Line2Spec {
            origin,
            dir,
            range: r,
        }) => Object::Line2(Line2::with_range(
            vec2(origin, "origin")?,
            vec2(dir, "dir")?,
            range(r, "range")?,
        )?),
        ObjectSpec::Segment2(Segment2Spec { a, b }) => {
            Object::Segment2(Segment2::new(vec2(a, "a")?, vec2(b, "b")?)?)
        }
        ObjectSpec::Polyhedron(_) => {
            return Err(GeomError::Unsupported {
                field: "type".into(),
                reason: "a polyhedron is used as the `shell` of `classify` in this build".into(),
            }
            .into())
        }
        // Curved objects are solved by `io::curved`, never by the linear kernel.
        ObjectSpec::Curve3(_) | ObjectSpec::Curve2(_) | ObjectSpec::Surface(_) => {
            return Err(GeomError::Unsupported {
                field: "type".into(),
                reason: "this operation does not take curved objects in this build".into(),
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
                T::from_num(d, "d")?,
            )?)
        }
        (false, false) => Err(GeomError::Format {
            field: String::new(),
            message: "a plane needs origin, u, v (parametric) or normal, d (implicit)".into(),
        }
        .into()),
    }
}

/// Validate a polyhedron (exact vertices); errors name fields below `prefix`.
pub(crate) fn polyhedron(spec: &PolyhedronSpec, prefix: &str) -> Result<Polyhedron, GeomError> {
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
        .collect::<Result<Vec<_>, GeomError>>()
        .map_err(|e| e.at(prefix))?;
    Polyhedron::new(vertices, spec.faces.clone()).map_err(|e| e.at(prefix))
}

/// Rationals take every number; kept as a typed error rather than a panic.
pub(crate) fn unreachable_rational() -> GeomError {
    GeomError::Unsupported {
        field: String::new(),
        reason: "internal: a rational coordinate was refused".into(),
    }
}
