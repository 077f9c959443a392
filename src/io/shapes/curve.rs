//! Curve objects of docs/FORMAT.md: `line`, `segment`, `circle`, `ellipse`, `hyperbola`,
//! `parabola`, `helix`, `bezier`, `nurbs_curve` and the 2D `line2`, `segment2`,
//! `circle2`, `ellipse2`, `bezier2`, `nurbs_curve2`, `conic2`; and, as an extension,
//! `polyline` / `polyline2` (`points`, optional `params`, OPERATIONS.md §1.5) and the
//! derived curves of [`super::derived`] (`offset_curve`, `composite_curve`,
//! `extended_curve` and their 2D forms).
//!
//! Every curve may carry `domain` (docs/FORMAT.md "Domains");
//! `range` and `domain` are the same field where docs/FORMAT.md writes `range`. A circle or
//! ellipse with a `domain` is an arc (§1.5 circular and elliptic arcs). Rational
//! Bézier curves and conic arcs are `bezier` with `weights`.

pub use super::curve_fields::{
    Analytic2Spec, AnalyticSpec, BezierSpec, Conic2Spec, LineSpec, NurbsCurveSpec, PolylineSpec,
    SegmentSpec,
};

pub use super::derived::{CompositeSpec, ExtendedSpec, Offset2Spec, Offset3Spec};

use super::curve_fields::{pair, P2, P3};
use super::derived::{self, build_parts};
use super::{parse_fields, take_type, to_json_with_type};
use crate::curve::{
    AnyCurve2, AnyCurve3, Bezier, Composite, Conic2, Extended, Line, NurbsCurve, Offset2, Offset3,
    Polyline, Segment,
};
use crate::error::GeomError;
use serde_json::{json, Value};

/// A space curve as written.
#[derive(Debug, Clone, PartialEq)]
pub enum Curve3Spec {
    Line(LineSpec<P3>),
    Segment(SegmentSpec<P3>),
    Circle(AnalyticSpec),
    Ellipse(AnalyticSpec),
    Hyperbola(AnalyticSpec),
    Parabola(AnalyticSpec),
    Helix(AnalyticSpec),
    Bezier(BezierSpec<P3>),
    Nurbs(NurbsCurveSpec<P3>),
    Polyline(PolylineSpec<P3>),
    Offset(Offset3Spec<Curve3Spec>),
    Composite(CompositeSpec<Curve3Spec>),
    Extended(ExtendedSpec<Curve3Spec>),
}

/// A plane curve as written (parametric, or the implicit `conic2`).
#[derive(Debug, Clone, PartialEq)]
pub enum Curve2Spec {
    Line(LineSpec<P2>),
    Segment(SegmentSpec<P2>),
    Circle(Analytic2Spec),
    Ellipse(Analytic2Spec),
    Bezier(BezierSpec<P2>),
    Nurbs(NurbsCurveSpec<P2>),
    Polyline(PolylineSpec<P2>),
    Conic(Conic2Spec),
    Offset(Offset2Spec<Curve2Spec>),
    Composite(CompositeSpec<Curve2Spec>),
    Extended(ExtendedSpec<Curve2Spec>),
}

/// A built plane curve: parametric or implicit.
#[derive(Debug, Clone, PartialEq)]
pub enum PlaneShape {
    Curve(AnyCurve2),
    Conic(Conic2),
}

/// The space curve types, as written in `type`.
pub const CURVE3_TYPES: &[&str] = &[
    "line",
    "segment",
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

/// The plane curve types, as written in `type`.
pub const CURVE2_TYPES: &[&str] = &[
    "line2",
    "segment2",
    "circle2",
    "ellipse2",
    "bezier2",
    "nurbs_curve2",
    "polyline2",
    "conic2",
    "offset_curve2",
    "composite_curve2",
    "extended_curve2",
];

impl Curve3Spec {
    /// The `type` name as written in JSON.
    pub fn type_name(&self) -> &'static str {
        match self {
            Curve3Spec::Line(_) => "line",
            Curve3Spec::Segment(_) => "segment",
            Curve3Spec::Circle(_) => "circle",
            Curve3Spec::Ellipse(_) => "ellipse",
            Curve3Spec::Hyperbola(_) => "hyperbola",
            Curve3Spec::Parabola(_) => "parabola",
            Curve3Spec::Helix(_) => "helix",
            Curve3Spec::Bezier(_) => "bezier",
            Curve3Spec::Nurbs(_) => "nurbs_curve",
            Curve3Spec::Polyline(_) => "polyline",
            Curve3Spec::Offset(_) => "offset_curve",
            Curve3Spec::Composite(_) => "composite_curve",
            Curve3Spec::Extended(_) => "extended_curve",
        }
    }

    /// Build and validate the curve; errors name fields relative to the object.
    pub fn build(&self) -> Result<AnyCurve3, GeomError> {
        let name = self.type_name();
        Ok(match self {
            Curve3Spec::Line(s) => AnyCurve3::Line(Line::new(s.origin, s.dir, pair(s.range))?),
            Curve3Spec::Segment(s) => AnyCurve3::Segment(Segment::new(s.a, s.b, pair(s.domain))?),
            Curve3Spec::Circle(s)
            | Curve3Spec::Ellipse(s)
            | Curve3Spec::Hyperbola(s)
            | Curve3Spec::Parabola(s)
            | Curve3Spec::Helix(s) => AnyCurve3::Analytic(s.build(name)?),
            Curve3Spec::Bezier(s) => AnyCurve3::Bezier(Bezier::new(
                s.points.clone(),
                s.weights.clone(),
                pair(s.domain),
            )?),
            Curve3Spec::Nurbs(s) => AnyCurve3::Nurbs(NurbsCurve::new(
                s.degree,
                s.knots.clone(),
                s.points.clone(),
                s.weights.clone(),
                pair(s.domain),
            )?),
            Curve3Spec::Polyline(s) => {
                AnyCurve3::Polyline(Polyline::new(s.points.clone(), s.params.clone())?)
            }
            Curve3Spec::Offset(s) => {
                let base = s.base.build().map_err(|e| e.at("base"))?;
                AnyCurve3::Offset(Box::new(Offset3::new(base, s.offset)?))
            }
            Curve3Spec::Composite(s) => {
                let pieces = build_parts(&s.named(), Curve3Spec::build)?;
                AnyCurve3::Composite(Box::new(Composite::new(pieces)?))
            }
            Curve3Spec::Extended(s) => {
                let base = s.base.build().map_err(|e| e.at("base"))?;
                let [before, after] = s.extend;
                AnyCurve3::Extended(Box::new(Extended::new(base, before, after)?))
            }
        })
    }

    /// The spec as a JSON object with its `type`.
    pub fn to_json(&self) -> Value {
        let name = self.type_name();
        match self {
            Curve3Spec::Line(s) => to_json_with_type(name, s),
            Curve3Spec::Segment(s) => to_json_with_type(name, s),
            Curve3Spec::Circle(s) | Curve3Spec::Ellipse(s) => to_json_with_type(name, s),
            Curve3Spec::Hyperbola(s) | Curve3Spec::Helix(s) => {
                rename_key(to_json_with_type(name, s), "domain", "range")
            }
            Curve3Spec::Parabola(s) => {
                let v = rename_key(to_json_with_type(name, s), "domain", "range");
                rename_key(v, "center", "vertex")
            }
            Curve3Spec::Bezier(s) => to_json_with_type(name, s),
            Curve3Spec::Nurbs(s) => to_json_with_type(name, s),
            Curve3Spec::Polyline(s) => to_json_with_type(name, s),
            Curve3Spec::Offset(s) => {
                json!({"type": name, "base": s.base.to_json(), "offset": s.offset})
            }
            Curve3Spec::Composite(s) => s.to_json(name, Curve3Spec::to_json),
            Curve3Spec::Extended(s) => {
                json!({"type": name, "base": s.base.to_json(), "extend": s.extend})
            }
        }
    }
}

/// Write a field under the name docs/FORMAT.md uses for this type.
fn rename_key(mut v: Value, from: &str, to: &str) -> Value {
    if let Some(map) = v.as_object_mut() {
        if let Some(x) = map.remove(from) {
            map.insert(to.into(), x);
        }
    }
    v
}

impl Curve2Spec {
    /// The `type` name as written in JSON.
    pub fn type_name(&self) -> &'static str {
        match self {
            Curve2Spec::Line(_) => "line2",
            Curve2Spec::Segment(_) => "segment2",
            Curve2Spec::Circle(_) => "circle2",
            Curve2Spec::Ellipse(_) => "ellipse2",
            Curve2Spec::Bezier(_) => "bezier2",
            Curve2Spec::Nurbs(_) => "nurbs_curve2",
            Curve2Spec::Polyline(_) => "polyline2",
            Curve2Spec::Conic(_) => "conic2",
            Curve2Spec::Offset(_) => "offset_curve2",
            Curve2Spec::Composite(_) => "composite_curve2",
            Curve2Spec::Extended(_) => "extended_curve2",
        }
    }

    /// Build and validate the curve; errors name fields relative to the object.
    pub fn build(&self) -> Result<PlaneShape, GeomError> {
        let name = self.type_name();
        let curve = match self {
            Curve2Spec::Line(s) => AnyCurve2::Line(Line::new(s.origin, s.dir, pair(s.range))?),
            Curve2Spec::Segment(s) => AnyCurve2::Segment(Segment::new(s.a, s.b, pair(s.domain))?),
            Curve2Spec::Circle(s) | Curve2Spec::Ellipse(s) => AnyCurve2::Analytic(s.build(name)?),
            Curve2Spec::Bezier(s) => AnyCurve2::Bezier(Bezier::new(
                s.points.clone(),
                s.weights.clone(),
                pair(s.domain),
            )?),
            Curve2Spec::Nurbs(s) => AnyCurve2::Nurbs(NurbsCurve::new(
                s.degree,
                s.knots.clone(),
                s.points.clone(),
                s.weights.clone(),
                pair(s.domain),
            )?),
            Curve2Spec::Polyline(s) => {
                AnyCurve2::Polyline(Polyline::new(s.points.clone(), s.params.clone())?)
            }
            Curve2Spec::Conic(s) => return Ok(PlaneShape::Conic(Conic2::new(s.coeffs)?)),
            Curve2Spec::Offset(s) => {
                let base = s.base.parametric().map_err(|e| e.at("base"))?;
                AnyCurve2::Offset(Box::new(Offset2::new(base, s.distance)?))
            }
            Curve2Spec::Composite(s) => {
                let pieces = build_parts(&s.named(), Curve2Spec::parametric)?;
                AnyCurve2::Composite(Box::new(Composite::new(pieces)?))
            }
            Curve2Spec::Extended(s) => {
                let base = s.base.parametric().map_err(|e| e.at("base"))?;
                let [before, after] = s.extend;
                AnyCurve2::Extended(Box::new(Extended::new(base, before, after)?))
            }
        };
        Ok(PlaneShape::Curve(curve))
    }

    /// Build a parametric curve (the part of a derived curve). Errors as
    /// [`Curve2Spec::build`]; `unsupported` (`type`) for the implicit `conic2`.
    pub fn parametric(&self) -> Result<AnyCurve2, GeomError> {
        match self.build()? {
            PlaneShape::Curve(c) => Ok(c),
            PlaneShape::Conic(_) => Err(GeomError::Unsupported {
                field: "type".into(),
                reason: "conic2 is implicit; a derived curve needs a parametric curve".into(),
            }),
        }
    }

    /// The spec as a JSON object with its `type`.
    pub fn to_json(&self) -> Value {
        let name = self.type_name();
        match self {
            Curve2Spec::Line(s) => to_json_with_type(name, s),
            Curve2Spec::Segment(s) => to_json_with_type(name, s),
            Curve2Spec::Circle(s) | Curve2Spec::Ellipse(s) => to_json_with_type(name, s),
            Curve2Spec::Bezier(s) => to_json_with_type(name, s),
            Curve2Spec::Nurbs(s) => to_json_with_type(name, s),
            Curve2Spec::Polyline(s) => to_json_with_type(name, s),
            Curve2Spec::Conic(s) => to_json_with_type(name, s),
            Curve2Spec::Offset(s) => {
                json!({"type": name, "base": s.base.to_json(), "distance": s.distance})
            }
            Curve2Spec::Composite(s) => s.to_json(name, Curve2Spec::to_json),
            Curve2Spec::Extended(s) => {
                json!({"type": name, "base": s.base.to_json(), "extend": s.extend})
            }
        }
    }
}

/// An unknown type, or one of the other dimension.
fn unknown_type(
    field: &str,
    found: &str,
    expected: &[&str],
    other: &[&str],
    what: &str,
) -> GeomError {
    let reason = if other.contains(&found) {
        format!("{found:?} is not a {what}")
    } else {
        format!(
            "unknown {what} type {found:?}; this build knows {}",
            expected.join(", ")
        )
    };
    GeomError::Unsupported {
        field: if field.is_empty() {
            "type".into()
        } else {
            format!("{field}.type")
        },
        reason,
    }
}

/// Read a space curve from its JSON value and validate it, naming errors below
/// `field` (`objects[1]` → `objects[1].knots[3]`).
pub fn parse_curve3(mut value: Value, field: &str) -> Result<Curve3Spec, GeomError> {
    let type_name = take_type(&mut value, field)?;
    let spec = match type_name.as_str() {
        "line" => Curve3Spec::Line(parse_fields(value, field)?),
        "segment" => Curve3Spec::Segment(parse_fields(value, field)?),
        "circle" | "ellipse" | "hyperbola" | "parabola" | "helix" => {
            // One struct holds the framed curves; each type takes only its docs/FORMAT.md names.
            let forbidden: &[(&str, &str)] = match type_name.as_str() {
                "parabola" => &[("center", "vertex")],
                "circle" | "ellipse" => &[("vertex", "center"), ("range", "domain")],
                _ => &[("vertex", "center")],
            };
            if let Some((name, instead)) = forbidden.iter().find(|(k, _)| value.get(*k).is_some()) {
                return Err(GeomError::Format {
                    field: if field.is_empty() {
                        name.to_string()
                    } else {
                        format!("{field}.{name}")
                    },
                    message: format!(
                        "unknown field `{name}` for type {type_name} (write `{instead}`)"
                    ),
                });
            }
            let spec: AnalyticSpec = parse_fields(value, field)?;
            match type_name.as_str() {
                "circle" => Curve3Spec::Circle(spec),
                "ellipse" => Curve3Spec::Ellipse(spec),
                "hyperbola" => Curve3Spec::Hyperbola(spec),
                "parabola" => Curve3Spec::Parabola(spec),
                _ => Curve3Spec::Helix(spec),
            }
        }
        "bezier" => Curve3Spec::Bezier(parse_fields(value, field)?),
        "nurbs_curve" => Curve3Spec::Nurbs(parse_fields(value, field)?),
        "polyline" => Curve3Spec::Polyline(parse_fields(value, field)?),
        "offset_curve" => Curve3Spec::Offset(derived::offset3(value, field, &parse_curve3)?),
        "composite_curve" => {
            Curve3Spec::Composite(derived::composite(value, field, &parse_curve3)?)
        }
        "extended_curve" => Curve3Spec::Extended(derived::extended(value, field, &parse_curve3)?),
        other => {
            return Err(unknown_type(
                field,
                other,
                CURVE3_TYPES,
                CURVE2_TYPES,
                "space curve",
            ))
        }
    };
    spec.build().map_err(|e| e.at(field))?;
    Ok(spec)
}

/// Read a plane curve (or `conic2`) from its JSON value and validate it, naming
/// errors below `field`.
pub fn parse_curve2(mut value: Value, field: &str) -> Result<Curve2Spec, GeomError> {
    let type_name = take_type(&mut value, field)?;
    let spec = match type_name.as_str() {
        "line2" => Curve2Spec::Line(parse_fields(value, field)?),
        "segment2" => Curve2Spec::Segment(parse_fields(value, field)?),
        "circle2" => Curve2Spec::Circle(parse_fields(value, field)?),
        "ellipse2" => Curve2Spec::Ellipse(parse_fields(value, field)?),
        "bezier2" => Curve2Spec::Bezier(parse_fields(value, field)?),
        "nurbs_curve2" => Curve2Spec::Nurbs(parse_fields(value, field)?),
        "polyline2" => Curve2Spec::Polyline(parse_fields(value, field)?),
        "conic2" => Curve2Spec::Conic(parse_fields(value, field)?),
        "offset_curve2" => Curve2Spec::Offset(derived::offset2(value, field, &parse_curve2)?),
        "composite_curve2" => {
            Curve2Spec::Composite(derived::composite(value, field, &parse_curve2)?)
        }
        "extended_curve2" => Curve2Spec::Extended(derived::extended(value, field, &parse_curve2)?),
        other => {
            return Err(unknown_type(
                field,
                other,
                CURVE2_TYPES,
                CURVE3_TYPES,
                "plane curve",
            ))
        }
    };
    spec.build().map_err(|e| e.at(field))?;
    Ok(spec)
}

/// Read and build a space curve in one step.
pub fn curve3_from_json(value: Value, field: &str) -> Result<AnyCurve3, GeomError> {
    parse_curve3(value, field)?.build().map_err(|e| e.at(field))
}
