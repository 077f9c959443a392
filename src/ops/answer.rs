//! What the front door answers ([`Answer`], inside a [`crate::Certified`]): the typed
//! form of a result of the case format (points with their parameters and enclosures,
//! a line, a segment, coincidence, a side of a shell).
//!
//! Every reported number is an estimate (the exact value correctly rounded when the
//! status is `exact`) with a certified enclosure; exact answers may carry the exact
//! rationals as well ([`ExactPoint`], on request: `Options::exact`).

use rug::Rational;

use super::classify::Side;

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

/// The answer of an operation.
#[derive(Debug, Clone, PartialEq)]
pub enum Answer {
    /// No solution (the certificate's `reason` may say why: `parallel`, ...).
    Empty,
    /// Isolated points.
    Points(Vec<Point>),
    /// A line (two planes, three planes through one line, a line lying in a plane).
    Line(LineAnswer),
    /// A segment (overlapping collinear segments, a ranged line lying in a plane).
    Segment(SegmentAnswer),
    /// Three coincident planes.
    Plane,
    /// The two shapes coincide.
    Coincident,
    /// Two conics share a component (a line of a degenerate conic).
    CommonComponent,
    /// `classify`: the side of the shell, and its nearest point when it is proven.
    Side(Side, Option<Point>),
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
            Answer::Plane => "plane",
            Answer::Coincident => "coincident",
            Answer::CommonComponent => "common_component",
            Answer::Side(side, _) => side.as_str(),
        }
    }

    /// The reported points (none for lines, segments, coincidence).
    pub fn points(&self) -> &[Point] {
        match self {
            Answer::Points(p) => p,
            Answer::Side(_, Some(p)) => std::slice::from_ref(p),
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
