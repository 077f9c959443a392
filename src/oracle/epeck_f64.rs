//! Epeck's computation returned as doubles, for benchmarks: the same kinds (decided
//! exactly) as [`super::epeck`], the coordinates rounded as [`EpeckToDouble`] says.
//! Kinds: see [`super::Intersection`].

use super::convert::{self, only_point};
use super::ffi::bridge;
use super::{
    EpeckToDouble, FloatResult, FloatResult2, Line2Input, LineInput, Linear3Input, OracleError,
    PlaneInput, Segment2Input, SegmentInput,
};

/// Line ∩ plane (OPERATIONS.md §5.1): `Empty`, `Point` or `Line`.
pub fn intersect_line_plane(
    to_double: EpeckToDouble,
    line: &LineInput,
    plane: &PlaneInput,
) -> Result<FloatResult, OracleError> {
    let (l, p) = (
        convert::line(line, "line")?,
        convert::plane(plane, "plane")?,
    );
    convert::float(bridge::epeck_line_plane_f64(
        to_double.force_exact(),
        &l,
        &p,
    ))
}

/// Segment ∩ plane: `Empty`, `Point` or `Segment`.
pub fn intersect_segment_plane(
    to_double: EpeckToDouble,
    segment: &SegmentInput,
    plane: &PlaneInput,
) -> Result<FloatResult, OracleError> {
    let (s, p) = (
        convert::segment(segment, "segment")?,
        convert::plane(plane, "plane")?,
    );
    convert::float(bridge::epeck_segment_plane_f64(
        to_double.force_exact(),
        &s,
        &p,
    ))
}

/// Plane ∩ plane (OPERATIONS.md §8): `Empty`, `Line` or `Plane`.
pub fn intersect_plane_plane(
    to_double: EpeckToDouble,
    a: &PlaneInput,
    b: &PlaneInput,
) -> Result<FloatResult, OracleError> {
    let (a, b) = (convert::plane(a, "a")?, convert::plane(b, "b")?);
    convert::float(bridge::epeck_plane_plane_f64(
        to_double.force_exact(),
        &a,
        &b,
    ))
}

/// Three planes (OPERATIONS.md §7.1): `Empty`, `Point`, `Line` or `Plane`.
pub fn intersect_three_planes(
    to_double: EpeckToDouble,
    a: &PlaneInput,
    b: &PlaneInput,
    c: &PlaneInput,
) -> Result<FloatResult, OracleError> {
    let (a, b, c) = (
        convert::plane(a, "a")?,
        convert::plane(b, "b")?,
        convert::plane(c, "c")?,
    );
    convert::float(bridge::epeck_three_planes_f64(
        to_double.force_exact(),
        &a,
        &b,
        &c,
    ))
}

/// The orthogonal projection of `point` onto `line` (OPERATIONS.md §3.1).
pub fn project_point_line(
    to_double: EpeckToDouble,
    point: &[f64; 3],
    line: &LineInput,
) -> Result<[f64; 3], OracleError> {
    let (q, l) = (
        convert::point(point, "point")?,
        convert::line(line, "line")?,
    );
    only_point(convert::float(bridge::epeck_project_point_line_f64(
        to_double.force_exact(),
        &q,
        &l,
    )))
}

/// The orthogonal projection of `point` onto `plane` (OPERATIONS.md §3.3).
pub fn project_point_plane(
    to_double: EpeckToDouble,
    point: &[f64; 3],
    plane: &PlaneInput,
) -> Result<[f64; 3], OracleError> {
    let (q, p) = (
        convert::point(point, "point")?,
        convert::plane(plane, "plane")?,
    );
    only_point(convert::float(bridge::epeck_project_point_plane_f64(
        to_double.force_exact(),
        &q,
        &p,
    )))
}

/// 2D line ∩ line (OPERATIONS.md §6.1): `Empty`, `Point` or `Line`.
pub fn intersect_line2_line2(
    to_double: EpeckToDouble,
    a: &Line2Input,
    b: &Line2Input,
) -> Result<FloatResult2, OracleError> {
    let (a, b) = (convert::line2(a, "a")?, convert::line2(b, "b")?);
    convert::float(bridge::epeck_lines_2d_f64(to_double.force_exact(), &a, &b))
}

/// 2D segment ∩ segment (OPERATIONS.md §6.2): `Empty`, `Point` or `Segment`.
pub fn intersect_segment2_segment2(
    to_double: EpeckToDouble,
    a: &Segment2Input,
    b: &Segment2Input,
) -> Result<FloatResult2, OracleError> {
    let (a, b) = (convert::segment2(a, "a")?, convert::segment2(b, "b")?);
    convert::float(bridge::epeck_segments_2d_f64(
        to_double.force_exact(),
        &a,
        &b,
    ))
}

/// Line ∩ line for lines, rays, ranged lines and segments: `Empty`, `Point`,
/// `Segment`, `Ray` or `Line`.
pub fn intersect_line_line(
    to_double: EpeckToDouble,
    a: &Linear3Input,
    b: &Linear3Input,
) -> Result<FloatResult, OracleError> {
    let (a, b) = (convert::linear3(a, "a")?, convert::linear3(b, "b")?);
    convert::float(bridge::epeck_line_line_f64(to_double.force_exact(), &a, &b))
}
