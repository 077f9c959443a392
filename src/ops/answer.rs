//! What the front door answers ([`Answer`], inside a [`crate::Certified`]): the typed
//! form of a result of the case format (points with their parameters and enclosures,
//! a line, a segment, coincidence, a side of a shell).
//!
//! Every reported number is an estimate (the exact value correctly rounded when the
//! status is `exact`) with a certified enclosure; exact answers may carry the exact
//! rationals as well ([`ExactPoint`], on request: `Options::exact`).

use rug::Rational;

use super::classify::Side;
use crate::certificate::Status;

/// An enclosure `[lo, hi]` of one number.
pub type Bounds = [f64; 2];

/// One reported point.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Point {
    /// The point (2 or 3 coordinates).
    pub xyz: Vec<f64>,
    /// A certified enclosure of each coordinate.
    pub xyz_box: Vec<Bounds>,
    /// The parameters on each input shape, in input order (empty for shapes without
    /// parameters, such as implicit planes).
    pub params: Vec<Vec<f64>>,
    /// Certified enclosures of the parameters, shaped like `params`.
    pub param_box: Option<Vec<Vec<Bounds>>>,
    /// 1 for a simple solution, 2 for a tangency (a proven double root or the most
    /// roots a singular box can hold).
    pub multiplicity: u32,
    pub tangent: bool,
    /// Projections: the distance from the query point.
    pub distance: Option<f64>,
    /// Projections onto planes: the signed distance along the normal.
    pub signed_distance: Option<f64>,
    /// Projections: whether this is the nearest point.
    pub nearest: Option<bool>,
    /// The exact values (exact answers, on request).
    pub exact: Option<ExactPoint>,
    /// Surface ∩ surface contacts only: an enclosure in space of the region around the
    /// point in which the intersection is not resolved (the exact input's intersection
    /// there — a touching point, a small loop, crossing branches or nothing — lies in
    /// it; OPERATIONS.md §9.5, [`crate::ops::surface_surface::CertifiedSingularPoint`]).
    pub region: Option<Vec<Bounds>>,
}

/// The exact rationals of a point.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct ExactPoint {
    pub xyz: Vec<Rational>,
    /// One list per input shape; empty for shapes without parameters or where the
    /// exact parameter is not rational.
    pub params: Vec<Vec<Rational>>,
    pub distance_squared: Option<Rational>,
}

/// A line in the parameters of an input shape: `origin + t·dir` (OPERATIONS.md §8
/// eq. (8.4)).
#[derive(Debug, Clone, PartialEq)]
pub struct ParamLine {
    pub origin: Vec<f64>,
    pub dir: Vec<f64>,
}

/// A line of an answer: a point and a direction.
#[derive(Debug, Clone, PartialEq)]
pub struct LineAnswer {
    pub point: Vec<f64>,
    pub dir: Vec<f64>,
    /// The line in the parameters of each input shape (`None`: no parameters); empty
    /// when not reported.
    pub params: Vec<Option<ParamLine>>,
    /// The exact point and direction, on request.
    pub exact: Option<(Vec<Rational>, Vec<Rational>)>,
}

/// The common part of two collinear segments, or the part of a ranged line lying in a
/// plane: its two end points.
#[derive(Debug, Clone, PartialEq)]
pub struct SegmentAnswer {
    pub a: Point,
    pub b: Point,
}

/// A collinear overlap that is a ray (a ray against a collinear line or ray going the
/// same way), or a ray lying in a plane: the points `start + s·dir`, `s ≥ 0`.
#[derive(Debug, Clone, PartialEq)]
pub struct RayAnswer {
    /// The ray's start point, with its parameters on each input shape.
    pub start: Point,
    /// A direction of the ray (its length means nothing): the first input's own
    /// direction or its opposite, each coordinate correctly rounded.
    pub dir: Vec<f64>,
    /// For each input shape in input order: whether its parameter grows along the ray
    /// (`None`: a shape without one parameter, such as a plane).
    pub increasing: Vec<Option<bool>>,
    /// The exact direction, on request.
    pub exact_dir: Option<Vec<Rational>>,
}

/// How one end of an intersection curve ends (OPERATIONS.md §9.1 end kinds).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum CurveEnd {
    /// A closed curve (both ends).
    Closed,
    /// On the boundary of a parameter domain.
    Boundary,
    /// At the singular point with this index in [`CurvesAnswer::singular_points`].
    Singular(usize),
    /// The surfaces became tangent there and no singular point was resolved (float).
    Tangency,
    /// The float trace stopped (no convergence, or its point budget was spent).
    Unfinished,
}

impl CurveEnd {
    /// The name the case format uses (`closed`, `boundary`, `singular`, ...).
    pub fn as_str(self) -> &'static str {
        match self {
            CurveEnd::Closed => "closed",
            CurveEnd::Boundary => "boundary",
            CurveEnd::Singular(_) => "singular",
            CurveEnd::Tangency => "tangency",
            CurveEnd::Unfinished => "unfinished",
        }
    }
}

/// One vertex of an intersection curve's polyline.
#[derive(Debug, Clone, PartialEq)]
pub struct CurveVertex {
    /// The point (OPERATIONS.md (1.21): the mean of the two surfaces' points).
    pub xyz: Vec<f64>,
    /// The parameters on each input shape, in input order (empty for shapes without
    /// parameters, such as implicit planes).
    pub params: Vec<Vec<f64>>,
    /// A proven upper bound of the distance from `xyz` to the true curve (`None` when the
    /// curve is not certified).
    pub bound: Option<f64>,
    /// The exact vertex, when it is rational (polyhedron sections).
    pub exact: Option<Vec<Rational>>,
}

/// One intersection curve: an ordered polyline (for a closed curve the last vertex
/// repeats the first).
#[derive(Debug, Clone, PartialEq)]
pub struct CurveAnswer {
    pub points: Vec<CurveVertex>,
    pub closed: bool,
    /// How the first and the last vertex end the curve.
    pub ends: [CurveEnd; 2],
    /// The largest vertex bound: every vertex lies within it of the curve (proven;
    /// `None` when the curve is not certified).
    pub distance_bound: Option<f64>,
    /// `Verified`: the curve is covered by a proven chain of boxes, each holding a single
    /// smooth arc, and its ends are proven; `Undecided` otherwise (`reason`).
    pub status: Status,
    pub reason: Option<String>,
}

/// A singular point of an intersection: branches cross or touch there.
#[derive(Debug, Clone, PartialEq)]
pub struct SingularPointAnswer {
    /// The point, its certified box and parameters (multiplicity 2, tangent).
    pub point: Point,
    /// `VerifiedSingular`: a contact of the surfaces perturbed by at most `perturbation`
    /// lies in the box; `Undecided` otherwise.
    pub status: Status,
    pub perturbation: Option<f64>,
    /// How many certified curve ends meet it.
    pub branches: usize,
}

/// The answer of surface ∩ surface (OPERATIONS.md §9, §10): curves, the singular points
/// where they cross or touch, and isolated contact points.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct CurvesAnswer {
    pub curves: Vec<CurveAnswer>,
    pub singular_points: Vec<SingularPointAnswer>,
    /// Isolated points of the intersection (two spheres touching from outside).
    pub points: Vec<Point>,
    /// The exact conic of a plane ∩ quadric (OPERATIONS.md §13.2).
    pub conic: Option<crate::ops::rational::Section>,
}

/// Which blend a [`BlendAnswer`] describes.
#[derive(Debug, Clone, PartialEq)]
pub enum BlendKind {
    /// A rolling-ball fillet of this radius or radius law (OPERATIONS.md §11.2–§11.3).
    Fillet { radius: crate::ops::blend_law::Law },
    /// A chamfer with these legs (or leg laws) on the first and the second face (§11.5).
    Chamfer {
        legs: [crate::ops::blend_law::Law; 2],
    },
}

/// The blend surface sampled on a grid `f(t_i, z_j)` (rows along `z`, one per `t_i`).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct BlendGrid {
    pub t: Vec<f64>,
    pub z: Vec<f64>,
    /// `points[i][j] = f(t[i], z[j])` (float estimates).
    pub points: Vec<Vec<[f64; 3]>>,
    /// Certified enclosures of `points`, shaped like it.
    pub boxes: Vec<Vec<[Bounds; 3]>>,
}

/// One component of a blend: its spine (the ball-centre curve of a fillet, the edge
/// line of a chamfer), whose vertices carry the contact parameters on both faces; the
/// contact points on each face at the same stations; and the surface grid.
#[derive(Debug, Clone, PartialEq)]
pub struct BlendComponent {
    pub spine: CurveAnswer,
    /// `contacts[k][i]`: the contact on face `k` at station `i` (params on face `k` only).
    pub contacts: [Vec<Point>; 2],
    pub grid: BlendGrid,
}

/// The answer of `fillet` and `chamfer` (OPERATIONS.md §11).
#[derive(Debug, Clone, PartialEq)]
pub struct BlendAnswer {
    pub kind: BlendKind,
    /// The sector of §11.1 (1–4) the blend lies in.
    pub sector: u8,
    pub components: Vec<BlendComponent>,
}

/// The visibility of a surface point in a view (OPERATIONS.md (13.11), with occlusion:
/// [`crate::ops::view::visibility`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Visibility {
    Visible,
    Hidden,
    OnContour,
}

impl Visibility {
    /// The name the case format uses.
    pub fn as_str(self) -> &'static str {
        match self {
            Visibility::Visible => "visible",
            Visibility::Hidden => "hidden",
            Visibility::OnContour => "on_contour",
        }
    }
}

/// The answer of `visibility`: the verdict, the surface point, and which input surface
/// hides it (its index among the case's objects) when it is hidden.
#[derive(Debug, Clone, PartialEq)]
pub struct VisibilityPoint {
    pub visibility: Visibility,
    pub point: Point,
    pub blocker: Option<usize>,
}

/// The answer of an operation.
#[derive(Debug, Clone, PartialEq)]
// One answer per operation call: its size does not matter, boxing would only add noise.
#[allow(clippy::large_enum_variant)]
pub enum Answer {
    /// No solution (the certificate's `reason` may say why: `parallel`, ...).
    Empty,
    /// Isolated points.
    Points(Vec<Point>),
    /// A line (two planes, three planes through one line, a line lying in a plane).
    Line(LineAnswer),
    /// A segment (overlapping collinear segments, a ranged line lying in a plane).
    Segment(SegmentAnswer),
    /// A ray (collinear objects overlapping in a ray, a ray lying in a plane).
    Ray(RayAnswer),
    /// Two curves sharing an arc (issue 20): the arc of both from `a` to `b`, each end
    /// with its parameters on both curves (the format of a segment, not straight).
    Arc(SegmentAnswer),
    /// Three coincident planes.
    Plane,
    /// The two shapes coincide.
    Coincident,
    /// Two conics share a component (a line of a degenerate conic).
    CommonComponent,
    /// `classify`: the side of the shell, and its nearest point when it is proven.
    Side(Side, Option<Point>),
    /// Intersection curves with their singular and isolated points (surface ∩ surface).
    Curves(CurvesAnswer),
    /// A fillet or chamfer surface (kind `surface`).
    Blend(BlendAnswer),
    /// `visibility`: a surface point `visible`, `hidden` or `on_contour`.
    Visibility(VisibilityPoint),
}

impl Answer {
    /// The kind as the case format names it (`empty`, `points`, `line`, ...).
    pub fn kind(&self) -> &'static str {
        match self {
            Answer::Empty => "empty",
            Answer::Points(p) if p.is_empty() => "empty",
            Answer::Points(_) => "points",
            Answer::Line(_) => "line",
            Answer::Segment(_) => "segment",
            Answer::Arc(_) => "arc",
            Answer::Ray(_) => "ray",
            Answer::Plane => "plane",
            Answer::Coincident => "coincident",
            Answer::CommonComponent => "common_component",
            Answer::Side(side, _) => side.as_str(),
            Answer::Curves(_) => "curves",
            Answer::Blend(b) if b.components.is_empty() => "empty",
            Answer::Blend(_) => "surface",
            Answer::Visibility(v) => v.visibility.as_str(),
        }
    }

    /// The reported points (none for lines, segments, coincidence).
    pub fn points(&self) -> &[Point] {
        match self {
            Answer::Points(p) => p,
            Answer::Side(_, Some(p)) => std::slice::from_ref(p),
            Answer::Curves(c) => &c.points,
            Answer::Visibility(v) => std::slice::from_ref(&v.point),
            _ => &[],
        }
    }

    /// Points, or `Empty` when there are none.
    pub fn from_points(points: Vec<Point>) -> Answer {
        if points.is_empty() {
            Answer::Empty
        } else {
            Answer::Points(points)
        }
    }
}
