//! The contour's answer types (OPERATIONS.md §13.5): below `contour` and `complete`,
//! which both use them.

use crate::certificate::Status;
use crate::num::Interval;

/// How an end of a contour curve ends.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ContourEnd {
    /// Both ends of a closed curve.
    Closed,
    /// On the boundary of the parameter domain.
    Boundary,
}

/// A proven bound of one vertex.
#[derive(Debug, Clone, PartialEq)]
pub struct ContourBound {
    /// An enclosure of the contour point with the vertex's fixed parameter (`[u, v]`,
    /// outward rounded; shifted by whole periods like the vertex).
    pub param_box: [Interval; 2],
    /// An enclosure of that point in space.
    pub xyz_box: [Interval; 3],
    /// A proven upper bound of the distance from the vertex's `xyz` to the contour.
    pub distance: f64,
}

/// One vertex of a contour polyline.
#[derive(Debug, Clone, PartialEq)]
pub struct ContourVertex {
    /// `[u, v]`, periodic parameters wrapped into the domain.
    pub params: [f64; 2],
    /// `s(u, v)`.
    pub xyz: [f64; 3],
    /// The proof (certified curves only).
    pub bound: Option<ContourBound>,
}

/// One component of the contour: an ordered polyline (closed: the last vertex repeats
/// the first).
#[derive(Debug, Clone, PartialEq)]
pub struct ContourCurve {
    pub points: Vec<ContourVertex>,
    pub closed: bool,
    pub ends: [ContourEnd; 2],
    /// `Verified`: covered by a proven chain of boxes, each holding one smooth arc of
    /// the contour, closed on itself or ending on the domain boundary; else `Undecided`.
    pub status: Status,
    pub reason: Option<String>,
    /// The boxes `[u, v]` of the chain (unwrapped parameters).
    pub chain: Vec<[Interval; 2]>,
}

/// The contour of a surface in a view: its components; `complete` (in the enclosing
/// [`crate::certificate::Certified`]) when it is proven that there is no other.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Contour {
    pub curves: Vec<ContourCurve>,
}
