//! Surfaces of the case format (docs/FORMAT.md "Objects"), as written, and their
//! validation into [`AnySurface`].
//!
//! [`parse_surface`] reads the shape of one object (unknown fields are errors, every
//! error names its field path); [`SurfaceSpec::build`] validates it (zero or non-finite
//! radii and axes, knot vectors, weights, net shapes, domains) with errors naming the
//! field relative to the object — prefix them with [`GeomError::at`]. Numbers are JSON
//! numbers (exact doubles; strings are refused for curved objects, and JSON cannot hold
//! NaN or infinities). Specs serialize back to the same JSON (round trip).
//!
//! Extensions of the case format (docs/FORMAT.md; extend, never break): `elliptic_cylinder` (`a`, `b` instead
//! of `radius`) and `hyperbolic_paraboloid` (`center + a u X + b v Y + (u² − v²) Z`,
//! `domain` required). `revolution`, `extrusion` and `ruled` are read by
//! [`super::motion`] (they need the curve reader); a `plane` given by `normal` and `d`
//! has no parametrisation and is refused here.

use serde::{Deserialize, Serialize};

use super::motion::{parse_motion, ExtrusionSpec, MotionSpec, RevolutionSpec, RuledSpec};
use crate::error::{require_finite_all, GeomError};
use crate::io::de::{deserialize_at, take_type};
use crate::surface::bezier::BezierSurface;
use crate::surface::frame::Frame;
use crate::surface::nurbs::NurbsSurface;
use crate::surface::plane::{ParaboloidRect, Plane};
use crate::surface::quadrics::{
    Cone, Cylinder, Ellipsoid, Hyperboloid, Paraboloid, Sheets, Sphere,
};
use crate::surface::torus::Torus;
use crate::surface::validate::{positive, Domain};
use crate::surface::AnySurface;

type Vec3 = [f64; 3];
type Rect = [[f64; 2]; 2];

/// `plane` (parametric form): `origin + u·u + v·v`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PlaneSurfaceSpec {
    pub origin: Vec3,
    pub u: Vec3,
    pub v: Vec3,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub domain: Option<Rect>,
}

/// `sphere`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SphereSpec {
    pub center: Vec3,
    pub radius: f64,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub axis: Option<Vec3>,
    #[serde(rename = "ref", default, skip_serializing_if = "Option::is_none")]
    pub reference: Option<Vec3>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub domain: Option<Rect>,
}

/// `ellipsoid`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct EllipsoidSpec {
    pub center: Vec3,
    pub a: f64,
    pub b: f64,
    pub c: f64,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub axis: Option<Vec3>,
    #[serde(rename = "ref", default, skip_serializing_if = "Option::is_none")]
    pub reference: Option<Vec3>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub domain: Option<Rect>,
}

/// `hyperboloid1`, `hyperboloid2`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct HyperboloidSpec {
    pub center: Vec3,
    pub a: f64,
    pub b: f64,
    pub c: f64,
    pub axis: Vec3,
    #[serde(rename = "ref", default, skip_serializing_if = "Option::is_none")]
    pub reference: Option<Vec3>,
    pub range: [f64; 2],
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub domain: Option<Rect>,
}

/// `paraboloid` (polar form).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ParaboloidSpec {
    pub center: Vec3,
    pub a: f64,
    pub b: f64,
    pub axis: Vec3,
    #[serde(rename = "ref", default, skip_serializing_if = "Option::is_none")]
    pub reference: Option<Vec3>,
    pub range: [f64; 2],
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub domain: Option<Rect>,
}

/// `hyperbolic_paraboloid` (extension): `domain` is required.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct HyperbolicParaboloidSpec {
    pub center: Vec3,
    pub a: f64,
    pub b: f64,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub axis: Option<Vec3>,
    #[serde(rename = "ref", default, skip_serializing_if = "Option::is_none")]
    pub reference: Option<Vec3>,
    pub domain: Rect,
}

/// `cylinder` (circular, `radius`).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CylinderSpec {
    pub origin: Vec3,
    pub radius: f64,
    pub axis: Vec3,
    #[serde(rename = "ref", default, skip_serializing_if = "Option::is_none")]
    pub reference: Option<Vec3>,
    pub height: [f64; 2],
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub domain: Option<Rect>,
}

/// `elliptic_cylinder` (extension): semi-axes `a` (along X) and `b` (along Y).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct EllipticCylinderSpec {
    pub origin: Vec3,
    pub a: f64,
    pub b: f64,
    pub axis: Vec3,
    #[serde(rename = "ref", default, skip_serializing_if = "Option::is_none")]
    pub reference: Option<Vec3>,
    pub height: [f64; 2],
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub domain: Option<Rect>,
}

/// `cone`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ConeSpec {
    pub origin: Vec3,
    pub radius: f64,
    pub half_angle: f64,
    pub axis: Vec3,
    #[serde(rename = "ref", default, skip_serializing_if = "Option::is_none")]
    pub reference: Option<Vec3>,
    pub height: [f64; 2],
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub domain: Option<Rect>,
}

/// `torus`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct TorusSpec {
    pub center: Vec3,
    pub major: f64,
    pub minor: f64,
    pub axis: Vec3,
    #[serde(rename = "ref", default, skip_serializing_if = "Option::is_none")]
    pub reference: Option<Vec3>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub domain: Option<Rect>,
}

/// `bezier_surface`: rows of the net go with `v`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BezierSurfaceSpec {
    pub points: Vec<Vec<Vec3>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub weights: Option<Vec<Vec<f64>>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub domain: Option<Rect>,
}

/// `nurbs_surface`: full knot vectors, rows of the net go with `v`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct NurbsSurfaceSpec {
    pub degree_u: usize,
    pub degree_v: usize,
    pub knots_u: Vec<f64>,
    pub knots_v: Vec<f64>,
    pub points: Vec<Vec<Vec3>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub weights: Option<Vec<Vec<f64>>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub domain: Option<Rect>,
}

/// One surface object of a case, by its `type`.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(tag = "type", rename_all = "snake_case")]
pub enum SurfaceSpec {
    Plane(PlaneSurfaceSpec),
    Sphere(SphereSpec),
    Ellipsoid(EllipsoidSpec),
    Hyperboloid1(HyperboloidSpec),
    Hyperboloid2(HyperboloidSpec),
    Paraboloid(ParaboloidSpec),
    HyperbolicParaboloid(HyperbolicParaboloidSpec),
    Cylinder(CylinderSpec),
    EllipticCylinder(EllipticCylinderSpec),
    Cone(ConeSpec),
    Torus(TorusSpec),
    BezierSurface(BezierSurfaceSpec),
    NurbsSurface(NurbsSurfaceSpec),
    Revolution(RevolutionSpec),
    Extrusion(ExtrusionSpec),
    Ruled(RuledSpec),
}

/// The surface types [`parse_surface`] reads.
pub const SURFACE_TYPES: &[&str] = &[
    "plane",
    "sphere",
    "ellipsoid",
    "hyperboloid1",
    "hyperboloid2",
    "paraboloid",
    "hyperbolic_paraboloid",
    "cylinder",
    "elliptic_cylinder",
    "cone",
    "torus",
    "bezier_surface",
    "nurbs_surface",
    "revolution",
    "extrusion",
    "ruled",
];

/// Read one surface object, naming errors below `field` (`objects[1].radius`). Unknown
/// fields, missing fields, wrong types and out-of-range numbers are `format` errors.
pub fn parse_surface(value: &serde_json::Value, field: &str) -> Result<SurfaceSpec, GeomError> {
    let mut value = value.clone();
    let type_field = if field.is_empty() {
        "type".to_string()
    } else {
        format!("{field}.type")
    };
    let name = take_type(&mut value, field)?;
    if name == "plane" && (value.get("normal").is_some() || value.get("d").is_some()) {
        return Err(GeomError::Unsupported {
            field: field.to_string(),
            reason: "a plane given by normal and d has no parametrisation; \
                     a surface needs origin, u and v"
                .into(),
        });
    }
    let at = field;
    Ok(match name.as_str() {
        "plane" => SurfaceSpec::Plane(deserialize_at(value, at)?),
        "sphere" => SurfaceSpec::Sphere(deserialize_at(value, at)?),
        "ellipsoid" => SurfaceSpec::Ellipsoid(deserialize_at(value, at)?),
        "hyperboloid1" => SurfaceSpec::Hyperboloid1(deserialize_at(value, at)?),
        "hyperboloid2" => SurfaceSpec::Hyperboloid2(deserialize_at(value, at)?),
        "paraboloid" => SurfaceSpec::Paraboloid(deserialize_at(value, at)?),
        "hyperbolic_paraboloid" => SurfaceSpec::HyperbolicParaboloid(deserialize_at(value, at)?),
        "cylinder" => SurfaceSpec::Cylinder(deserialize_at(value, at)?),
        "elliptic_cylinder" => SurfaceSpec::EllipticCylinder(deserialize_at(value, at)?),
        "cone" => SurfaceSpec::Cone(deserialize_at(value, at)?),
        "torus" => SurfaceSpec::Torus(deserialize_at(value, at)?),
        "bezier_surface" => SurfaceSpec::BezierSurface(deserialize_at(value, at)?),
        "nurbs_surface" => SurfaceSpec::NurbsSurface(deserialize_at(value, at)?),
        "revolution" | "extrusion" | "ruled" => match parse_motion(value, at, &name)? {
            MotionSpec::Revolution(s) => SurfaceSpec::Revolution(s),
            MotionSpec::Extrusion(s) => SurfaceSpec::Extrusion(s),
            MotionSpec::Ruled(s) => SurfaceSpec::Ruled(s),
        },
        other => {
            return Err(GeomError::Unsupported {
                field: type_field,
                reason: format!(
                    "{other:?} is not a surface type read here; known: {}",
                    SURFACE_TYPES.join(", ")
                ),
            })
        }
    })
}

/// `[[u0, u1], [v0, v1]]` as a [`Domain`].
fn rect(d: &Rect) -> Domain {
    (d[0], d[1])
}

/// Apply an optional `domain` restriction.
fn restricted<S>(
    surface: S,
    domain: &Option<Rect>,
    with: impl FnOnce(S, Domain) -> Result<S, GeomError>,
) -> Result<S, GeomError> {
    match domain {
        Some(d) => with(surface, rect(d)),
        None => Ok(surface),
    }
}

impl SurfaceSpec {
    /// The `type` name as written in JSON.
    pub fn type_name(&self) -> &'static str {
        match self {
            SurfaceSpec::Plane(_) => "plane",
            SurfaceSpec::Sphere(_) => "sphere",
            SurfaceSpec::Ellipsoid(_) => "ellipsoid",
            SurfaceSpec::Hyperboloid1(_) => "hyperboloid1",
            SurfaceSpec::Hyperboloid2(_) => "hyperboloid2",
            SurfaceSpec::Paraboloid(_) => "paraboloid",
            SurfaceSpec::HyperbolicParaboloid(_) => "hyperbolic_paraboloid",
            SurfaceSpec::Cylinder(_) => "cylinder",
            SurfaceSpec::EllipticCylinder(_) => "elliptic_cylinder",
            SurfaceSpec::Cone(_) => "cone",
            SurfaceSpec::Torus(_) => "torus",
            SurfaceSpec::BezierSurface(_) => "bezier_surface",
            SurfaceSpec::NurbsSurface(_) => "nurbs_surface",
            SurfaceSpec::Revolution(_) => "revolution",
            SurfaceSpec::Extrusion(_) => "extrusion",
            SurfaceSpec::Ruled(_) => "ruled",
        }
    }

    /// The JSON value of the spec (with its `type`), which [`parse_surface`] reads back
    /// to an equal spec.
    pub fn to_json(&self) -> serde_json::Value {
        serde_json::to_value(self).unwrap_or(serde_json::Value::Null)
    }

    /// Validate into a surface; errors name the field relative to the object.
    pub fn build(&self) -> Result<AnySurface, GeomError> {
        Ok(match self {
            SurfaceSpec::Plane(s) => AnySurface::Plane(restricted(
                Plane::new(s.origin, s.u, s.v)?,
                &s.domain,
                Plane::with_domain,
            )?),
            SurfaceSpec::Sphere(s) => AnySurface::Sphere(restricted(
                Sphere::new(s.center, s.radius, s.axis, s.reference)?,
                &s.domain,
                Sphere::with_domain,
            )?),
            SurfaceSpec::Ellipsoid(s) => AnySurface::Ellipsoid(restricted(
                Ellipsoid::new(s.center, [s.a, s.b, s.c], s.axis, s.reference)?,
                &s.domain,
                Ellipsoid::with_domain,
            )?),
            SurfaceSpec::Hyperboloid1(s) | SurfaceSpec::Hyperboloid2(s) => {
                let sheets = match self {
                    SurfaceSpec::Hyperboloid1(_) => Sheets::One,
                    _ => Sheets::Two,
                };
                let h = Hyperboloid::new(
                    sheets,
                    s.center,
                    [s.a, s.b, s.c],
                    s.axis,
                    s.reference,
                    s.range,
                )?;
                AnySurface::Hyperboloid(restricted(h, &s.domain, Hyperboloid::with_domain)?)
            }
            SurfaceSpec::Paraboloid(s) => AnySurface::Paraboloid(restricted(
                Paraboloid::new(s.center, [s.a, s.b], s.axis, s.reference, s.range)?,
                &s.domain,
                Paraboloid::with_domain,
            )?),
            SurfaceSpec::HyperbolicParaboloid(s) => {
                require_finite_all("center", &s.center)?;
                let frame = Frame::new(s.center, s.axis.unwrap_or([0.0, 0.0, 1.0]), s.reference)?;
                AnySurface::ParaboloidRect(ParaboloidRect::hyperbolic(
                    frame,
                    [s.a, s.b],
                    rect(&s.domain),
                )?)
            }
            SurfaceSpec::Cylinder(s) => {
                positive("radius", s.radius)?;
                AnySurface::Cylinder(restricted(
                    Cylinder::new(s.origin, [s.radius; 2], s.axis, s.reference, s.height)?,
                    &s.domain,
                    Cylinder::with_domain,
                )?)
            }
            SurfaceSpec::EllipticCylinder(s) => AnySurface::Cylinder(restricted(
                Cylinder::new(s.origin, [s.a, s.b], s.axis, s.reference, s.height)?,
                &s.domain,
                Cylinder::with_domain,
            )?),
            SurfaceSpec::Cone(s) => AnySurface::Cone(restricted(
                Cone::new(
                    s.origin,
                    s.radius,
                    s.half_angle,
                    s.axis,
                    s.reference,
                    s.height,
                )?,
                &s.domain,
                Cone::with_domain,
            )?),
            SurfaceSpec::Torus(s) => AnySurface::Torus(restricted(
                Torus::new(s.center, s.major, s.minor, s.axis, s.reference)?,
                &s.domain,
                Torus::with_domain,
            )?),
            SurfaceSpec::BezierSurface(s) => AnySurface::Bezier(restricted(
                BezierSurface::new(&s.points, s.weights.as_deref())?,
                &s.domain,
                BezierSurface::with_domain,
            )?),
            SurfaceSpec::NurbsSurface(s) => AnySurface::Nurbs(restricted(
                NurbsSurface::new(
                    [s.degree_u, s.degree_v],
                    s.knots_u.clone(),
                    s.knots_v.clone(),
                    &s.points,
                    s.weights.as_deref(),
                )?,
                &s.domain,
                NurbsSurface::with_domain,
            )?),
            SurfaceSpec::Revolution(s) => s.build()?,
            SurfaceSpec::Extrusion(s) => s.build()?,
            SurfaceSpec::Ruled(s) => s.build()?,
        })
    }
}
