//! CGAL's `Exact_predicates_exact_constructions_kernel`: the reference. Every
//! coordinate is CGAL's exact rational (`CGAL::exact(x)`, a GMP `mpq`), so a
//! comparison with geocert is equality of rationals. Kinds: see [`super::Intersection`].

use super::convert::{self, only_point};
use super::ffi::bridge;
use super::{
    ExactResult, ExactResult2, Line2Input, LineInput, Linear3Input, OracleError, PlaneInput,
    Segment2Input, SegmentInput,
};
use rug::Rational;

/// Line ∩ plane (OPERATIONS.md §5.1): `Empty`, `Point` or `Line`.
pub fn intersect_line_plane(
    line: &LineInput,
    plane: &PlaneInput,
) -> Result<ExactResult, OracleError> {
    let (l, p) = (
        convert::line(line, "line")?,
        convert::plane(plane, "plane")?,
    );
    convert::exact(bridge::epeck_line_plane(&l, &p))
}

/// Segment ∩ plane: `Empty`, `Point` or `Segment`.
pub fn intersect_segment_plane(
    segment: &SegmentInput,
    plane: &PlaneInput,
) -> Result<ExactResult, OracleError> {
    let (s, p) = (
        convert::segment(segment, "segment")?,
        convert::plane(plane, "plane")?,
    );
    convert::exact(bridge::epeck_segment_plane(&s, &p))
}

/// Plane ∩ plane (OPERATIONS.md §8): `Empty`, `Line` or `Plane`.
pub fn intersect_plane_plane(a: &PlaneInput, b: &PlaneInput) -> Result<ExactResult, OracleError> {
    let (a, b) = (convert::plane(a, "a")?, convert::plane(b, "b")?);
    convert::exact(bridge::epeck_plane_plane(&a, &b))
}

/// Three planes (OPERATIONS.md §7.1): `Empty`, `Point`, `Line` or `Plane`.
pub fn intersect_three_planes(
    a: &PlaneInput,
    b: &PlaneInput,
    c: &PlaneInput,
) -> Result<ExactResult, OracleError> {
    let (a, b, c) = (
        convert::plane(a, "a")?,
        convert::plane(b, "b")?,
        convert::plane(c, "c")?,
    );
    convert::exact(bridge::epeck_three_planes(&a, &b, &c))
}

/// The orthogonal projection of `point` onto `line` (OPERATIONS.md §3.1).
pub fn project_point_line(
    point: &[f64; 3],
    line: &LineInput,
) -> Result<[Rational; 3], OracleError> {
    let (q, l) = (
        convert::point(point, "point")?,
        convert::line(line, "line")?,
    );
    only_point(convert::exact(bridge::epeck_project_point_line(&q, &l)))
}

/// The orthogonal projection of `point` onto `plane` (OPERATIONS.md §3.3).
pub fn project_point_plane(
    point: &[f64; 3],
    plane: &PlaneInput,
) -> Result<[Rational; 3], OracleError> {
    let (q, p) = (
        convert::point(point, "point")?,
        convert::plane(plane, "plane")?,
    );
    only_point(convert::exact(bridge::epeck_project_point_plane(&q, &p)))
}

/// 2D line ∩ line (OPERATIONS.md §6.1): `Empty`, `Point` or `Line`.
pub fn intersect_line2_line2(a: &Line2Input, b: &Line2Input) -> Result<ExactResult2, OracleError> {
    let (a, b) = (convert::line2(a, "a")?, convert::line2(b, "b")?);
    convert::exact(bridge::epeck_lines_2d(&a, &b))
}

/// 2D segment ∩ segment (OPERATIONS.md §6.2): `Empty`, `Point` or `Segment`.
pub fn intersect_segment2_segment2(
    a: &Segment2Input,
    b: &Segment2Input,
) -> Result<ExactResult2, OracleError> {
    let (a, b) = (convert::segment2(a, "a")?, convert::segment2(b, "b")?);
    convert::exact(bridge::epeck_segments_2d(&a, &b))
}

/// Line ∩ line for any two of lines, rays, ranged lines and segments in space:
/// `Empty`, `Point`, `Segment`, `Ray` or `Line` (CGAL's `intersection` of the
/// `Line_3`/`Ray_3`/`Segment_3` pair, see [`Linear3Input`]).
pub fn intersect_line_line(a: &Linear3Input, b: &Linear3Input) -> Result<ExactResult, OracleError> {
    let (a, b) = (convert::linear3(a, "a")?, convert::linear3(b, "b")?);
    convert::exact(bridge::epeck_line_line(&a, &b))
}
