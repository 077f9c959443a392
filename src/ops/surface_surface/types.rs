//! The result types of surface ∩ surface (OPERATIONS.md §1.9, §9.1): intersection curves
//! as ordered point sets with the parameters on both surfaces, the ends of open curves,
//! singular points, and their certified counterparts (spec/CERTIFICATION.md).

use crate::certificate::Status;
use crate::num::Interval;

/// One point of an intersection curve (§1.9): the parameters `(u, v)` on the first
/// surface `r` and `(a, b)` on the second `s`, the space point (1.21)
/// `½[r(u, v) + s(a, b)]`, and the curve parameter `t` (the cumulative chord length).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CurvePoint {
    /// `[u, v, a, b]`, periodic parameters wrapped into their domain.
    pub params: [f64; 4],
    /// The space point (1.21).
    pub xyz: [f64; 3],
    /// The cumulative chord length from the first point (§1.9 (impl)).
    pub t: f64,
    /// The index of the singular point this vertex is (a crossing the curve passes
    /// through, §9.5), if it is one.
    pub singular: Option<usize>,
}

/// How an open end of an intersection curve ends (§9.1 end kinds).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum CurveEnd {
    /// On the boundary of a parameter domain (§9.4 "Boundary", status `OnBoundary`).
    Boundary,
    /// At the singular point with this index (a crossing or touching of branches, §9.5).
    Singular(usize),
    /// The surfaces became tangent and no singular point was resolved there (§9.3:
    /// `r₀ < r_min` with nearly collinear normals).
    Tangency,
    /// The float march stopped (no convergence, or the point budget was spent).
    Unfinished,
    /// Both ends of a closed curve.
    Closed,
}

/// One traced intersection curve (§1.9) of the float path.
#[derive(Debug, Clone, PartialEq)]
pub struct IntersectionCurve {
    /// The ordered points; for a closed curve the last point repeats the first.
    pub points: Vec<CurvePoint>,
    /// The curve is a closed loop.
    pub closed: bool,
    /// How the first and the last point end the curve ([`CurveEnd::Closed`] twice for a
    /// closed curve).
    pub ends: [CurveEnd; 2],
}

impl IntersectionCurve {
    /// The length of the polyline (the last `t`).
    pub fn polyline_length(&self) -> f64 {
        self.points.last().map_or(0.0, |p| p.t)
    }
}

/// How the branches meet at a singular point.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SingularKind {
    /// Traced branches pass through or end at it (the surfaces touch where branches cross
    /// or meet: Villarceau circles, Steinmetz curves, a cone cut through its apex).
    Crossing,
    /// An isolated contact point: no branch reaches it (two tangent spheres).
    Contact,
}

/// A singular point of the float path: the surfaces touch (`n̂_r × n̂_s = 0`, §9.5), or
/// the intersection passes through a singular point of a surface (a cone's apex).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SingularPoint {
    /// `[u, v, a, b]`.
    pub params: [f64; 4],
    /// The point.
    pub xyz: [f64; 3],
    pub kind: SingularKind,
    /// The gap between the surfaces along their common normal there (0 for a true
    /// contact; the float path accepts it within δ_len).
    pub gap: f64,
}

/// The float answer of surface ∩ surface (§9, §10): curves and singular points.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct SurfaceIntersectionF64 {
    pub curves: Vec<IntersectionCurve>,
    pub singular_points: Vec<SingularPoint>,
}

/// A proven bound for one vertex of a certified curve.
#[derive(Debug, Clone, PartialEq)]
pub struct VertexBound {
    /// An enclosure of the true curve point with the same fixed parameter as the vertex
    /// (`[u, v, a, b]`, outward rounded): the curve passes through this box.
    pub param_box: [Interval; 4],
    /// An enclosure of that true curve point in space.
    pub xyz_box: [Interval; 3],
    /// A proven upper bound of the distance from the vertex's `xyz` to that point of the
    /// curve (so to the curve).
    pub distance: f64,
}

/// One box of a certified chain (module doc of `chain`): over every value of the fixed
/// parameter in its slab, exactly one point of the intersection in the box, so the curve
/// in the box is a single smooth arc entering and leaving through the two faces of the
/// slab.
#[derive(Debug, Clone, PartialEq)]
pub struct ChainBox {
    /// The box `[u, v, a, b]` (periodic sides may reach beyond the domain by part of a
    /// period).
    pub params: [Interval; 4],
    /// The fixed parameter (0 = u, 1 = v, 2 = a, 3 = b).
    pub fixed: usize,
}

/// A certified intersection curve: the float curve with its proof.
#[derive(Debug, Clone, PartialEq)]
pub struct CertifiedCurve {
    /// The float curve (points, `closed`, ends).
    pub curve: IntersectionCurve,
    /// `Verified` when the box chain covers the whole component: consecutive boxes are
    /// proven to hold the same arc, a closed chain closes on itself, and each open end
    /// is proven to lie on the domain boundary or inside a singular point's box;
    /// `Undecided` otherwise (with `reason`).
    pub status: Status,
    /// One bound per point of `curve.points` (empty when undecided).
    pub bounds: Vec<VertexBound>,
    /// The chain of boxes.
    pub chain: Vec<ChainBox>,
    pub reason: Option<String>,
}

/// A certified singular point.
#[derive(Debug, Clone, PartialEq)]
pub struct CertifiedSingularPoint {
    /// The float estimate.
    pub point: SingularPoint,
    /// The certified box `[u, v, a, b]` of the singular point (for `VerifiedSingular`:
    /// the box of its proof, see `status`; else the region).
    pub param_box: [Interval; 4],
    /// An enclosure of that box's points in space.
    pub xyz_box: [Interval; 3],
    /// The region `[u, v, a, b]` around it in which the intersection is not resolved:
    /// chains that end at this point end inside it, and every component of the
    /// intersection not covered by a chain meets it.
    pub region: [Interval; 4],
    /// An enclosure of the region in space.
    pub region_xyz: [Interval; 3],
    /// `VerifiedSingular`: the common-normal system has a verified root in `param_box`,
    /// so the surfaces touch there after moving one of them along that normal by at most
    /// `perturbation` (a contact of a perturbed input; for a singular point of a surface,
    /// such as a cone's apex, the implicit form offset by at most `perturbation`).
    /// `Undecided` when that could not be proven (reason).
    pub status: Status,
    /// Bound of the displacement that makes the surfaces touch in the box.
    pub perturbation: Option<f64>,
    /// How many certified curve ends lie in the box.
    pub branch_ends: usize,
    pub reason: Option<String>,
}

/// The certified answer of surface ∩ surface: every component, with `complete` (in the
/// enclosing [`crate::Certified`]) when it is proven that no other exists.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct SurfaceIntersection {
    pub curves: Vec<CertifiedCurve>,
    pub singular_points: Vec<CertifiedSingularPoint>,
}

impl SurfaceIntersection {
    /// No curve and no singular point (proven empty when the result is `complete`).
    pub fn is_empty(&self) -> bool {
        self.curves.is_empty() && self.singular_points.is_empty()
    }
}
