//! Objects of the case format (docs/FORMAT.md "Objects"), as written. Validation into
//! geometric objects (zero directions, collinear plane vectors, ...) happens when a
//! case is solved, with the field path prefixed by the object's position.

use super::de::{deserialize_at, take_type};
use super::number::Num;
use crate::error::GeomError;
use serde::Deserialize;

/// `line`: `c(t) = origin + t·dir`, t ∈ ℝ or `range` (alias `domain`); an end written
/// `null` is infinite, so `[t0, null]` and `[null, t1]` are rays (docs/FORMAT.md).
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LineSpec {
    pub origin: [Num; 3],
    pub dir: [Num; 3],
    #[serde(alias = "domain")]
    pub range: Option<[Option<Num>; 2]>,
}

/// `segment`: `c(t) = (1−t)·a + t·b`, t ∈ [0, 1].
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SegmentSpec {
    pub a: [Num; 3],
    pub b: [Num; 3],
}

/// `plane`: parametric `origin + u·u + v·v`, or implicit `normal·x + d = 0`
/// (exactly one of the two field sets).
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PlaneSpec {
    pub origin: Option<[Num; 3]>,
    pub u: Option<[Num; 3]>,
    pub v: Option<[Num; 3]>,
    pub normal: Option<[Num; 3]>,
    pub d: Option<Num>,
    /// Three points the plane passes through (OPERATIONS.md §13.1; not collinear).
    pub points: Option<[[Num; 3]; 3]>,
}

/// `line2`: `origin + t·dir` in the plane; `range` as for `line`.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Line2Spec {
    pub origin: [Num; 2],
    pub dir: [Num; 2],
    #[serde(alias = "domain")]
    pub range: Option<[Option<Num>; 2]>,
}

/// `segment2`: `(1−t)·a + t·b` in the plane.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Segment2Spec {
    pub a: [Num; 2],
    pub b: [Num; 2],
}

/// `polyhedron`: a closed shell; faces are vertex index lists, counter-clockwise seen
/// from outside (validated when the case is solved).
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PolyhedronSpec {
    pub vertices: Vec<[Num; 3]>,
    pub faces: Vec<Vec<usize>>,
}

/// `quadric`: the implicit surface `[x 1]ᵀ Q [x 1] = 0` of a symmetric 4×4 `matrix`
/// (doubles; validated when the case is solved: symmetric, finite, not all zero).
#[derive(Debug, Clone, PartialEq, Deserialize, serde::Serialize)]
#[serde(deny_unknown_fields)]
pub struct QuadricSpec {
    pub matrix: [[f64; 4]; 4],
}

/// One object of a case, by its `type`.
#[derive(Debug, Clone, PartialEq)]
#[allow(clippy::large_enum_variant)] // parsed once per object; boxing buys nothing
pub enum ObjectSpec {
    Line(LineSpec),
    Segment(SegmentSpec),
    Plane(PlaneSpec),
    Line2(Line2Spec),
    Segment2(Segment2Spec),
    Polyhedron(PolyhedronSpec),
    /// A space curve other than a line or segment (doubles only).
    Curve3(crate::io::shapes::Curve3Spec),
    /// A plane curve other than `line2` / `segment2`, or `conic2` (doubles only).
    Curve2(crate::io::shapes::Curve2Spec),
    /// A surface other than a plane (doubles only).
    Surface(crate::io::shapes::surface::SurfaceSpec),
    /// The implicit `quadric` (doubles only).
    Quadric(QuadricSpec),
}

/// The curve types read by [`crate::io::shapes::parse_curve3`].
const CURVE3_TYPES: &[&str] = &[
    "circle",
    "ellipse",
    "hyperbola",
    "parabola",
    "helix",
    "bezier",
    "nurbs_curve",
    "polyline",
    "offset_curve",
    "composite_curve",
    "extended_curve",
];

/// The object types this build understands, as written in `type`.
pub const OBJECT_TYPES: &[&str] = &[
    "line",
    "segment",
    "plane",
    "line2",
    "segment2",
    "polyhedron",
    "circle, ellipse, hyperbola, parabola, helix, bezier, nurbs_curve, polyline",
    "offset_curve, composite_curve, extended_curve",
    "circle2, ellipse2, bezier2, nurbs_curve2, polyline2, conic2",
    "offset_curve2, composite_curve2, extended_curve2",
    "sphere, ellipsoid, hyperboloid1, hyperboloid2, paraboloid, cylinder, cone, torus",
    "bezier_surface, nurbs_surface",
    "revolution, extrusion, ruled",
    "quadric",
];

impl ObjectSpec {
    /// The `type` name as written in JSON.
    pub fn type_name(&self) -> &'static str {
        match self {
            ObjectSpec::Line(_) => "line",
            ObjectSpec::Segment(_) => "segment",
            ObjectSpec::Plane(_) => "plane",
            ObjectSpec::Line2(_) => "line2",
            ObjectSpec::Segment2(_) => "segment2",
            ObjectSpec::Polyhedron(_) => "polyhedron",
            ObjectSpec::Curve3(c) => c.type_name(),
            ObjectSpec::Curve2(c) => c.type_name(),
            ObjectSpec::Surface(c) => c.type_name(),
            ObjectSpec::Quadric(_) => "quadric",
        }
    }
}

/// Read one object from its JSON value, naming errors below `prefix`
/// (`objects[1].dir[2]`). The `type` field selects the fields that are allowed.
pub fn parse_object(mut value: serde_json::Value, prefix: &str) -> Result<ObjectSpec, GeomError> {
    let original = value.clone();
    let type_field = format!("{prefix}.type");
    let type_name = take_type(&mut value, prefix)?;
    match type_name.as_str() {
        "line" => deserialize_at(value, prefix).map(ObjectSpec::Line),
        "segment" => deserialize_at(value, prefix).map(ObjectSpec::Segment),
        // A bounded plane patch (`domain` over the (origin, u, v) parametrisation) is a
        // surface; the linear kernel takes the unbounded plane.
        "plane" if value.get("domain").is_some() => {
            crate::io::shapes::surface::parse_surface(&original, prefix).map(ObjectSpec::Surface)
        }
        "plane" => deserialize_at(value, prefix).map(ObjectSpec::Plane),
        "line2" => deserialize_at(value, prefix).map(ObjectSpec::Line2),
        "segment2" => deserialize_at(value, prefix).map(ObjectSpec::Segment2),
        "polyhedron" => deserialize_at(value, prefix).map(ObjectSpec::Polyhedron),
        "quadric" => {
            crate::io::shapes::refuse_exact_strings(&value, prefix)?;
            deserialize_at(value, prefix).map(ObjectSpec::Quadric)
        }
        other if crate::io::shapes::surface::SURFACE_TYPES.contains(&other) => {
            crate::io::shapes::surface::parse_surface(&original, prefix).map(ObjectSpec::Surface)
        }
        other if other.ends_with('2') => {
            crate::io::shapes::parse_curve2(original, prefix).map(ObjectSpec::Curve2)
        }
        _ if CURVE3_TYPES.contains(&type_name.as_str()) => {
            crate::io::shapes::parse_curve3(original, prefix).map(ObjectSpec::Curve3)
        }
        other => Err(GeomError::Unsupported {
            field: type_field,
            reason: format!(
                "unknown object type {other:?}; this build knows {}",
                OBJECT_TYPES.join(", ")
            ),
        }),
    }
}
