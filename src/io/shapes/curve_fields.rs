//! The fields of each curve type of docs/FORMAT.md, as written (serde structs that
//! refuse unknown fields), and the checks that depend on the type (the framed curves
//! share one struct; each type takes only its own fields).

use crate::curve::{Analytic, Analytic2, Domain, Frame, Shape};
use crate::error::{require_finite_all, GeomError};
use serde::{Deserialize, Serialize};

pub(crate) type P3 = [f64; 3];
pub(crate) type P2 = [f64; 2];

/// `line` / `line2`: `origin + t·dir`, `t ∈ ℝ` or `range`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LineSpec<P> {
    pub origin: P,
    pub dir: P,
    #[serde(alias = "domain", default, skip_serializing_if = "Option::is_none")]
    pub range: Option<[f64; 2]>,
}

/// `segment` / `segment2`: `(1−t)·a + t·b`, `t ∈ [0, 1]` or a sub-`domain`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SegmentSpec<P> {
    pub a: P,
    pub b: P,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub domain: Option<[f64; 2]>,
}

/// The frame fields of a framed analytic curve (docs/FORMAT.md "Frames").
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct AnalyticSpec {
    /// `center` (`vertex` for the parabola).
    #[serde(alias = "vertex")]
    pub center: P3,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub radius: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub a: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub b: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub p: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub pitch: Option<f64>,
    pub axis: P3,
    #[serde(rename = "ref", default, skip_serializing_if = "Option::is_none")]
    pub reference: Option<P3>,
    /// `domain` (`range` for hyperbola, parabola, helix).
    #[serde(alias = "range", default, skip_serializing_if = "Option::is_none")]
    pub domain: Option<[f64; 2]>,
}

/// `circle2` / `ellipse2`: `center + (a cos t, b sin t)`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Analytic2Spec {
    pub center: P2,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub radius: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub a: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub b: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub domain: Option<[f64; 2]>,
}

/// `bezier` / `bezier2`: (rational) Bézier on `[0, 1]`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BezierSpec<P> {
    pub points: Vec<P>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub weights: Option<Vec<f64>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub domain: Option<[f64; 2]>,
}

/// `nurbs_curve` / `nurbs_curve2`: full knot vector (`n + p + 1` knots).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct NurbsCurveSpec<P> {
    pub degree: usize,
    pub knots: Vec<f64>,
    pub points: Vec<P>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub weights: Option<Vec<f64>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub domain: Option<[f64; 2]>,
}

/// `polyline` / `polyline2` (extension): points at `params` (default `0, 1, …`).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PolylineSpec<P> {
    pub points: Vec<P>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub params: Option<Vec<f64>>,
}

/// `conic2`: `a x² + b xy + c y² + d x + e y + f = 0`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Conic2Spec {
    pub coeffs: [f64; 6],
}

pub(crate) fn pair(d: Option<[f64; 2]>) -> Option<(f64, f64)> {
    d.map(|[a, b]| (a, b))
}

/// A required field that is missing (the fields of framed curves depend on the type).
pub(crate) fn missing(field: &str) -> GeomError {
    GeomError::Format {
        field: field.into(),
        message: format!("missing field `{field}`"),
    }
}

/// Refuse a field that this type does not have.
fn refuse(field: &str, present: bool, type_name: &str) -> Result<(), GeomError> {
    if present {
        Err(GeomError::Format {
            field: field.into(),
            message: format!("unknown field `{field}` for type {type_name}"),
        })
    } else {
        Ok(())
    }
}

impl AnalyticSpec {
    /// The shape of `type_name`, checking that exactly its fields are present.
    fn shape(&self, type_name: &str) -> Result<Shape, GeomError> {
        let need = |v: Option<f64>, f: &str| v.ok_or_else(|| missing(f));
        let allowed: &[&str] = match type_name {
            "circle" => &["radius"],
            "ellipse" | "hyperbola" => &["a", "b"],
            "parabola" => &["p"],
            _ => &["radius", "pitch"],
        };
        for (f, v) in [
            ("radius", self.radius),
            ("a", self.a),
            ("b", self.b),
            ("p", self.p),
            ("pitch", self.pitch),
        ] {
            refuse(f, v.is_some() && !allowed.contains(&f), type_name)?;
        }
        Ok(match type_name {
            "circle" => Shape::Circle {
                radius: need(self.radius, "radius")?,
            },
            "ellipse" => Shape::Ellipse {
                a: need(self.a, "a")?,
                b: need(self.b, "b")?,
            },
            "hyperbola" => Shape::Hyperbola {
                a: need(self.a, "a")?,
                b: need(self.b, "b")?,
                second_branch: false,
            },
            "parabola" => Shape::Parabola {
                p: need(self.p, "p")?,
            },
            _ => Shape::Helix {
                radius: need(self.radius, "radius")?,
                pitch: need(self.pitch, "pitch")?,
            },
        })
    }

    pub(crate) fn build(&self, type_name: &str) -> Result<Analytic, GeomError> {
        let center_name = if type_name == "parabola" {
            "vertex"
        } else {
            "center"
        };
        require_finite_all(center_name, &self.center)?;
        let shape = self.shape(type_name)?;
        let frame = Frame::new(self.center, self.axis, self.reference)?;
        let domain = match (self.domain, type_name) {
            (Some([a, b]), "hyperbola" | "parabola" | "helix") => {
                Some(Domain::new("range", a, b)?.pair())
            }
            (None, "hyperbola" | "parabola" | "helix") => return Err(missing("range")),
            (d, _) => pair(d),
        };
        Analytic::new(frame, shape, domain)
    }
}

impl Analytic2Spec {
    pub(crate) fn build(&self, type_name: &str) -> Result<Analytic2, GeomError> {
        let shape = if type_name == "circle2" {
            refuse("a", self.a.is_some(), type_name)?;
            refuse("b", self.b.is_some(), type_name)?;
            Shape::Circle {
                radius: self.radius.ok_or_else(|| missing("radius"))?,
            }
        } else {
            refuse("radius", self.radius.is_some(), type_name)?;
            Shape::Ellipse {
                a: self.a.ok_or_else(|| missing("a"))?,
                b: self.b.ok_or_else(|| missing("b"))?,
            }
        };
        Analytic2::new(self.center, shape, pair(self.domain))
    }
}
