//! The motion surfaces of the case format (docs/FORMAT.md "Surfaces"; CASES.md table of
//! surfaces; OPERATIONS.md §1.6): `revolution` (`profile`, `origin`, `axis`),
//! `extrusion` (`profile`, `dir`) and `ruled` (`a`, `b`). Their curves are any bounded
//! space curve of the format, read by [`parse_curve3`] with errors below the curve's
//! field (`objects[0].profile.radius`).
//!
//! `domain` (`[[u0, u1], [v0, v1]]`) restricts a revolution's angle `u`; every other part
//! of a `domain` must equal the natural one (a profile or guide is restricted by its own
//! `domain`), else `unsupported` naming `domain[k]`.

use serde::{Deserialize, Serialize, Serializer};
use serde_json::Value;

use super::curve::{parse_curve3, Curve3Spec};
use crate::curve::{AnyCurve3, Curve};
use crate::error::GeomError;
use crate::io::de::deserialize_at;
use crate::surface::motion::{Extrusion, Revolution, Ruled};
use crate::surface::validate::{restrict, FULL_TURN};
use crate::surface::AnySurface;

type Vec3 = [f64; 3];
type Rect = [[f64; 2]; 2];

/// `revolution`: the profile point at `v` turned by the angle `u` about the axis
/// through `origin`.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RevolutionSpec {
    #[serde(serialize_with = "curve_json")]
    pub profile: Curve3Spec,
    pub origin: Vec3,
    pub axis: Vec3,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub domain: Option<Rect>,
}

/// `extrusion`: `profile(u) + v·dir`, `v ∈ [0, 1]`.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ExtrusionSpec {
    #[serde(serialize_with = "curve_json")]
    pub profile: Curve3Spec,
    pub dir: Vec3,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub domain: Option<Rect>,
}

/// `ruled`: `(1−v)·a(u) + v·b(u)`, both guides over `u ∈ [0, 1]`, `v ∈ [0, 1]`.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RuledSpec {
    #[serde(serialize_with = "curve_json")]
    pub a: Curve3Spec,
    #[serde(serialize_with = "curve_json")]
    pub b: Curve3Spec,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub domain: Option<Rect>,
}

fn curve_json<S: Serializer>(c: &Curve3Spec, s: S) -> Result<S::Ok, S::Error> {
    c.to_json().serialize(s)
}

/// The fields as written, curves still JSON.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct Raw {
    profile: Option<Value>,
    a: Option<Value>,
    b: Option<Value>,
    origin: Option<Vec3>,
    axis: Option<Vec3>,
    dir: Option<Vec3>,
    domain: Option<Rect>,
}

fn join(field: &str, name: &str) -> String {
    if field.is_empty() {
        name.to_string()
    } else {
        format!("{field}.{name}")
    }
}

fn required<T>(value: Option<T>, field: &str, name: &str, kind: &str) -> Result<T, GeomError> {
    value.ok_or_else(|| GeomError::Format {
        field: join(field, name),
        message: format!("missing field `{name}` of a {kind}"),
    })
}

/// A field the type does not take (the fields of the three types share one reader).
fn refuse(present: bool, field: &str, name: &str, kind: &str) -> Result<(), GeomError> {
    if present {
        return Err(GeomError::Format {
            field: join(field, name),
            message: format!("unknown field `{name}` for type {kind}"),
        });
    }
    Ok(())
}

fn curve(
    value: Option<Value>,
    field: &str,
    name: &str,
    kind: &str,
) -> Result<Curve3Spec, GeomError> {
    parse_curve3(required(value, field, name, kind)?, &join(field, name))
}

/// One motion surface as written.
#[derive(Debug, Clone, PartialEq)]
pub enum MotionSpec {
    Revolution(RevolutionSpec),
    Extrusion(ExtrusionSpec),
    Ruled(RuledSpec),
}

/// Read a `revolution`, `extrusion` or `ruled` (its `type` already removed, given as
/// `kind`), naming errors below `field`.
pub fn parse_motion(value: Value, field: &str, kind: &str) -> Result<MotionSpec, GeomError> {
    let raw: Raw = deserialize_at(value, field)?;
    Ok(match kind {
        "revolution" => {
            refuse(raw.a.is_some(), field, "a", kind)?;
            refuse(raw.b.is_some(), field, "b", kind)?;
            refuse(raw.dir.is_some(), field, "dir", kind)?;
            MotionSpec::Revolution(RevolutionSpec {
                profile: curve(raw.profile, field, "profile", kind)?,
                origin: required(raw.origin, field, "origin", kind)?,
                axis: required(raw.axis, field, "axis", kind)?,
                domain: raw.domain,
            })
        }
        "extrusion" => {
            refuse(raw.a.is_some(), field, "a", kind)?;
            refuse(raw.b.is_some(), field, "b", kind)?;
            refuse(raw.origin.is_some(), field, "origin", kind)?;
            refuse(raw.axis.is_some(), field, "axis", kind)?;
            MotionSpec::Extrusion(ExtrusionSpec {
                profile: curve(raw.profile, field, "profile", kind)?,
                dir: required(raw.dir, field, "dir", kind)?,
                domain: raw.domain,
            })
        }
        _ => {
            refuse(raw.profile.is_some(), field, "profile", kind)?;
            refuse(raw.origin.is_some(), field, "origin", kind)?;
            refuse(raw.axis.is_some(), field, "axis", kind)?;
            refuse(raw.dir.is_some(), field, "dir", kind)?;
            MotionSpec::Ruled(RuledSpec {
                a: curve(raw.a, field, "a", kind)?,
                b: curve(raw.b, field, "b", kind)?,
                domain: raw.domain,
            })
        }
    })
}

/// The built curve, which must be bounded (an unbounded line sweeps an unbounded
/// surface): errors name `name` (`profile`, `a`, `b`).
fn bounded(spec: &Curve3Spec, name: &str) -> Result<AnyCurve3, GeomError> {
    let c = spec.build().map_err(|e| e.at(name))?;
    let (lo, hi) = c.domain();
    if !(lo.is_finite() && hi.is_finite()) {
        return Err(GeomError::InvalidValue {
            field: format!("{name}.range"),
            reason: "the curve of a motion surface must be bounded (give a line a `range`)".into(),
        });
    }
    Ok(c)
}

/// Direction `k` of a requested `domain` must be the natural one.
fn natural_only(
    domain: &Option<Rect>,
    k: usize,
    natural: [f64; 2],
    how: &str,
) -> Result<(), GeomError> {
    match domain {
        Some(d) if d[k] != natural => Err(GeomError::Unsupported {
            field: format!("domain[{k}]"),
            reason: format!(
                "this direction of the surface is restricted by {how}, not by `domain` \
                 (its natural range is [{}, {}])",
                natural[0], natural[1]
            ),
        }),
        _ => Ok(()),
    }
}

impl RevolutionSpec {
    /// Validate; errors name the field relative to the object.
    pub fn build(&self) -> Result<AnySurface, GeomError> {
        let profile = bounded(&self.profile, "profile")?;
        let (lo, hi) = profile.domain();
        natural_only(&self.domain, 1, [lo, hi], "the profile's own `domain`")?;
        let angle = restrict("domain[0]", FULL_TURN, self.domain.map(|d| d[0]))?;
        let s = Revolution::new(profile, self.origin, self.axis)?;
        let s = if angle == FULL_TURN {
            s
        } else {
            s.with_angle(angle)?
        };
        Ok(AnySurface::Revolution(Box::new(s)))
    }
}

impl ExtrusionSpec {
    /// Validate; errors name the field relative to the object.
    pub fn build(&self) -> Result<AnySurface, GeomError> {
        let profile = bounded(&self.profile, "profile")?;
        let (lo, hi) = profile.domain();
        natural_only(&self.domain, 0, [lo, hi], "the profile's own `domain`")?;
        natural_only(&self.domain, 1, [0.0, 1.0], "the length of `dir`")?;
        Ok(AnySurface::Extrusion(Box::new(Extrusion::new(
            profile, self.dir,
        )?)))
    }
}

impl RuledSpec {
    /// Validate; errors name the field relative to the object.
    pub fn build(&self) -> Result<AnySurface, GeomError> {
        let a = bounded(&self.a, "a")?;
        let b = bounded(&self.b, "b")?;
        natural_only(&self.domain, 0, [0.0, 1.0], "the guides' own `domain`")?;
        natural_only(&self.domain, 1, [0.0, 1.0], "the guides")?;
        Ok(AnySurface::Ruled(Box::new(Ruled::new(a, b))))
    }
}
