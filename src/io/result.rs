//! Results of the case format (docs/FORMAT.md "Results"), written as JSON Lines.
//!
//! Doubles are printed in the shortest form that reads back to the same bits
//! (serde_json uses ryu). A value that has no finite double (an exact coordinate
//! beyond the f64 range, correctly rounded to ±∞) is written `"inf"` or `"-inf"`
//! ([`super::number::Doubles`]), never `null`, and its point carries its exact
//! rationals in `exact` (docs/FORMAT.md "Numbers beyond the double range").

use super::number::doubles;
use crate::certificate::Certified;
use crate::error::GeomError;
use serde::Serialize;
use serde_json::Value;

/// An enclosure `[lo, hi]` of one coordinate.
pub type Bounds = [f64; 2];

/// Exact rationals of a point, as `"p/q"` strings (on request: `options.exact`).
#[derive(Debug, Clone, Default, PartialEq, Serialize)]
pub struct ExactOut {
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub xyz: Vec<String>,
    /// One array per input object; empty for objects without parameters.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub params: Vec<Vec<String>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub distance_squared: Option<String>,
}

/// One reported point (`points[]`).
#[derive(Debug, Clone, Default, PartialEq, Serialize)]
pub struct PointOut {
    #[serde(serialize_with = "doubles")]
    pub xyz: Vec<f64>,
    /// One array per input object, in input order (empty for objects without
    /// parameters, such as implicit planes).
    #[serde(serialize_with = "doubles")]
    pub params: Vec<Vec<f64>>,
    #[serde(rename = "box", serialize_with = "doubles")]
    pub bounds: Vec<Bounds>,
    #[serde(skip_serializing_if = "Option::is_none", serialize_with = "doubles")]
    pub param_box: Option<Vec<Vec<Bounds>>>,
    pub multiplicity: u32,
    pub tangent: bool,
    /// Projections: the distance from the query point (correctly rounded).
    #[serde(skip_serializing_if = "Option::is_none", serialize_with = "doubles")]
    pub distance: Option<f64>,
    /// Projections onto planes: the signed distance along the normal (u × v or n).
    #[serde(skip_serializing_if = "Option::is_none", serialize_with = "doubles")]
    pub signed_distance: Option<f64>,
    /// Projections: `true` for the nearest of the reported points.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub nearest: Option<bool>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub exact: Option<ExactOut>,
    /// Surface ∩ surface contacts: the region in which the intersection is not
    /// resolved (docs/FORMAT.md "Curves").
    #[serde(skip_serializing_if = "Option::is_none", serialize_with = "doubles")]
    pub region: Option<Vec<Bounds>>,
}

/// A line in the parameter plane of a parametric plane: `origin + t·dir` (§8 eq. (8.4)).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ParamLineOut {
    #[serde(serialize_with = "doubles")]
    pub origin: Vec<f64>,
    #[serde(serialize_with = "doubles")]
    pub dir: Vec<f64>,
}

/// `line` of a result: a point and a direction (exact where the inputs are linear).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct LineOut {
    #[serde(serialize_with = "doubles")]
    pub point: Vec<f64>,
    #[serde(serialize_with = "doubles")]
    pub dir: Vec<f64>,
    /// The line in the parameters of each input object, in input order (§8 eq. (8.4));
    /// `null` for objects without parameters.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub params: Vec<Option<ParamLineOut>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub exact: Option<ExactLineOut>,
}

/// Exact rationals of a line.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ExactLineOut {
    pub point: Vec<String>,
    pub dir: Vec<String>,
}

/// `segment` of a result (the overlap of collinear segments).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SegmentOut {
    pub a: PointOut,
    pub b: PointOut,
}

/// `ray` of a result: the points `start + s·dir`, `s ≥ 0` (collinear objects
/// overlapping in a ray, a ray lying in a plane).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RayOut {
    pub start: PointOut,
    #[serde(serialize_with = "doubles")]
    pub dir: Vec<f64>,
    /// For each input object in input order: whether its parameter grows along the
    /// ray (`null` for objects without one parameter).
    pub increasing: Vec<Option<bool>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub exact: Option<ExactRayOut>,
}

/// Exact rationals of a ray's direction (its start's are in `start.exact`).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ExactRayOut {
    pub dir: Vec<String>,
}

/// How one end of a curve ends (`ends[]` of `curves[]`): `closed`, `boundary` (a
/// domain edge), `singular` (at `singular_points[index]`), `tangency` or `unfinished`
/// (float trace only).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct CurveEndOut {
    pub kind: &'static str,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub index: Option<usize>,
}

/// One vertex of a curve's polyline.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct CurveVertexOut {
    pub xyz: Vec<f64>,
    /// One array per input object, in input order.
    pub params: Vec<Vec<f64>>,
    /// The exact vertex (`"p/q"` strings), when it is rational (polyhedron sections).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub exact: Option<Vec<String>>,
}

/// One curve of `curves[]` (kind `curves`).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct CurveOut {
    pub closed: bool,
    pub points: Vec<CurveVertexOut>,
    /// The singular points the curve ends at (copies of entries of the result's
    /// `singular_points`, which `ends[].index` refers to).
    pub singular_points: Vec<SingularPointOut>,
    /// How the first and the last point end the curve.
    pub ends: [CurveEndOut; 2],
    /// `verified` (a proven chain of single-arc boxes covers it) or `undecided`.
    pub status: &'static str,
    /// A proven bound of the distance from every vertex to the curve (verified curves).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub distance_bound: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub reason: Option<String>,
}

/// One singular point of `singular_points[]`: a point with its certified box, the
/// status of its proof and the perturbation of a proven contact.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SingularPointOut {
    #[serde(flatten)]
    pub point: PointOut,
    pub status: &'static str,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub perturbation: Option<f64>,
    /// How many certified curve ends meet it.
    pub branches: usize,
}

/// The blend of a `fillet` / `chamfer` record (docs/FORMAT.md "Blends").
/// The sampled blend surface of one component.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct GridOut {
    #[serde(serialize_with = "doubles")]
    pub t: Vec<f64>,
    #[serde(serialize_with = "doubles")]
    pub z: Vec<f64>,
    /// `points[i][j] = f(t[i], z[j])`.
    #[serde(serialize_with = "doubles")]
    pub points: Vec<Vec<[f64; 3]>>,
    #[serde(rename = "box", serialize_with = "doubles")]
    pub boxes: Vec<Vec<[Bounds; 3]>>,
}

/// One component: the contacts on each face at the stations of `curves[i]`, and the grid.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ComponentOut {
    pub contacts: [Vec<PointOut>; 2],
    pub grid: GridOut,
    pub status: &'static str,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub reason: Option<String>,
}

/// `blend` of a record of kind `surface`.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct BlendOut {
    #[serde(rename = "type")]
    pub kind: &'static str,
    /// A number, or the radius law (docs/FORMAT.md "Blends").
    #[serde(skip_serializing_if = "Option::is_none")]
    pub radius: Option<serde_json::Value>,
    /// Each a number or a law.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub legs: Option<[serde_json::Value; 2]>,
    pub sector: u8,
    pub components: Vec<ComponentOut>,
}

/// `error` of a result.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ErrorOut {
    pub kind: &'static str,
    pub field: String,
    pub message: String,
}

/// The version of the result format written in every record's `format` field
/// (docs/FORMAT.md); it changes only when a field changes meaning or is removed.
pub const FORMAT_VERSION: u32 = 1;

/// One line of output.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct CaseResult {
    pub id: Value,
    /// The result format's version ([`FORMAT_VERSION`]).
    pub format: u32,
    pub status: &'static str,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub kind: Option<&'static str>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub complete: Option<bool>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub bits: Option<u32>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub arithmetic: Option<&'static str>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub micros: Option<u64>,
    /// Why the answer is empty or undecided (`parallel`, `extensions_meet`, ...).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub reason: Option<String>,
    #[serde(skip_serializing_if = "Option::is_none", serialize_with = "doubles")]
    pub perturbation: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub points: Option<Vec<PointOut>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub line: Option<LineOut>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub segment: Option<SegmentOut>,
    /// Kind `arc`: the arc two curves share, its ends `a` and `b` (issue 20).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub arc: Option<SegmentOut>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub ray: Option<RayOut>,
    /// Kind `curves`: the intersection curves.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub curves: Option<Vec<CurveOut>>,
    /// Kind `curves`: where branches cross or touch.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub singular_points: Option<Vec<SingularPointOut>>,
    /// Kind `curves` of a plane ∩ quadric: the exact conic (docs/FORMAT.md "Sections").
    #[serde(skip_serializing_if = "Option::is_none")]
    pub conic: Option<super::section_out::ConicOut>,
    /// Kind `surface` (`fillet`, `chamfer`): the blend (docs/FORMAT.md "Blends").
    #[serde(skip_serializing_if = "Option::is_none")]
    pub blend: Option<BlendOut>,
    /// `visibility`, kind `hidden`: the index in `objects` of the surface proven to hide
    /// the point (0: the surface itself).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub blocker: Option<usize>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub error: Option<ErrorOut>,
    /// `verify`: the verdict on each claimed item.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub claims: Option<Vec<ClaimOut>>,
    /// `verify`: certified solutions that no claimed point is within the tolerance of.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub missed: Option<Vec<PointOut>>,
}

/// The verdict of `verify` on one claimed item (docs/FORMAT.md "Claims").
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ClaimOut {
    /// `kind`, or `points[i]` of the claim.
    pub item: String,
    /// `confirmed` | `refuted` | `undecided`.
    pub verdict: &'static str,
    /// The certificate level of the truth the verdict rests on.
    pub status: &'static str,
    /// The distance from the claimed point to the nearest true solution (rounded).
    #[serde(skip_serializing_if = "Option::is_none", serialize_with = "doubles")]
    pub distance: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub reason: Option<String>,
}

impl CaseResult {
    /// A result for a case that could not be read or solved.
    pub fn error(id: Value, error: &GeomError) -> Self {
        CaseResult {
            id,
            format: FORMAT_VERSION,
            status: "error",
            kind: None,
            complete: None,
            bits: None,
            arithmetic: None,
            micros: None,
            reason: None,
            perturbation: None,
            points: None,
            line: None,
            segment: None,
            arc: None,
            ray: None,
            curves: None,
            singular_points: None,
            conic: None,
            blend: None,
            blocker: None,
            claims: None,
            missed: None,
            error: Some(ErrorOut {
                kind: error.kind(),
                field: error.field().to_string(),
                message: error.to_string(),
            }),
        }
    }

    /// A result of the given kind carrying the certificate of `certified`.
    pub fn certified<T>(id: Value, kind: &'static str, certified: &Certified<T>) -> Self {
        CaseResult {
            id,
            format: FORMAT_VERSION,
            status: certified.status.as_str(),
            kind: Some(kind),
            complete: Some(certified.complete),
            bits: Some(certified.bits),
            arithmetic: Some(certified.arithmetic.as_str()),
            micros: None,
            reason: certified.reason.clone(),
            perturbation: certified.perturbation,
            points: None,
            line: None,
            segment: None,
            arc: None,
            ray: None,
            curves: None,
            singular_points: None,
            conic: None,
            blend: None,
            blocker: None,
            error: None,
            claims: None,
            missed: None,
        }
    }

    /// The result as one JSON line.
    pub fn to_json_line(&self) -> String {
        // Serialising these plain structs cannot fail; keep a readable fallback anyway.
        serde_json::to_string(self).unwrap_or_else(|e| {
            format!(
                "{{\"status\":\"error\",\"error\":{{\"kind\":\"internal\",\"message\":{:?}}}}}",
                e.to_string()
            )
        })
    }
}
