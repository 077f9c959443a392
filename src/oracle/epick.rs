//! CGAL's `Exact_predicates_inexact_constructions_kernel`, in doubles: the fast
//! kernel a CGAL user would otherwise pick. Predicates are exact on the doubles they
//! see, but constructions round (the cross product of a parametric plane, its `d`,
//! the plane–plane line), so the kind can be wrong on degenerate input, e.g. three
//! exactly dependent planes (tests/oracle_smoke.rs). Kinds: see [`super::Intersection`].

use super::convert::{self, only_point};
use super::ffi::bridge;
use super::{
    FloatResult, FloatResult2, Line2Input, LineInput, Linear3Input, OracleError, PlaneInput,
    Segment2Input, SegmentInput,
};
use crate::error::GeomError;

/// Line ∩ plane (OPERATIONS.md §5.1): `Empty`, `Point` or `Line`.
pub fn intersect_line_plane(
    line: &LineInput,
    plane: &PlaneInput,
) -> Result<FloatResult, OracleError> {
    window(
        &[
            ("line", &[line.point, line.direction].concat()),
            ("plane", &plane_values(plane)),
        ],
        WINDOW_BITS_3D,
    )?;
    let (l, p) = (
        convert::line(line, "line")?,
        convert::plane(plane, "plane")?,
    );
    convert::float(bridge::epick_line_plane(&l, &p))
}

/// Segment ∩ plane: `Empty`, `Point` or `Segment`.
pub fn intersect_segment_plane(
    segment: &SegmentInput,
    plane: &PlaneInput,
) -> Result<FloatResult, OracleError> {
    window(
        &[
            ("segment", &[segment.source, segment.target].concat()),
            ("plane", &plane_values(plane)),
        ],
        WINDOW_BITS_3D,
    )?;
    let (s, p) = (
        convert::segment(segment, "segment")?,
        convert::plane(plane, "plane")?,
    );
    convert::float(bridge::epick_segment_plane(&s, &p))
}

/// Plane ∩ plane (OPERATIONS.md §8): `Empty`, `Line` or `Plane`.
pub fn intersect_plane_plane(a: &PlaneInput, b: &PlaneInput) -> Result<FloatResult, OracleError> {
    window(
        &[("a", &plane_values(a)), ("b", &plane_values(b))],
        WINDOW_BITS_3D,
    )?;
    let (a, b) = (convert::plane(a, "a")?, convert::plane(b, "b")?);
    convert::float(bridge::epick_plane_plane(&a, &b))
}

/// Three planes (OPERATIONS.md §7.1): `Empty`, `Point`, `Line` or `Plane`.
pub fn intersect_three_planes(
    a: &PlaneInput,
    b: &PlaneInput,
    c: &PlaneInput,
) -> Result<FloatResult, OracleError> {
    window(
        &[
            ("a", &plane_values(a)),
            ("b", &plane_values(b)),
            ("c", &plane_values(c)),
        ],
        WINDOW_BITS_3D,
    )?;
    let (a, b, c) = (
        convert::plane(a, "a")?,
        convert::plane(b, "b")?,
        convert::plane(c, "c")?,
    );
    convert::float(bridge::epick_three_planes(&a, &b, &c))
}

/// The orthogonal projection of `point` onto `line` (OPERATIONS.md §3.1).
pub fn project_point_line(point: &[f64; 3], line: &LineInput) -> Result<[f64; 3], OracleError> {
    window(
        &[
            ("point", point),
            ("line", &[line.point, line.direction].concat()),
        ],
        WINDOW_BITS_3D,
    )?;
    let (q, l) = (
        convert::point(point, "point")?,
        convert::line(line, "line")?,
    );
    only_point(convert::float(bridge::epick_project_point_line(&q, &l)))
}

/// The orthogonal projection of `point` onto `plane` (OPERATIONS.md §3.3).
pub fn project_point_plane(point: &[f64; 3], plane: &PlaneInput) -> Result<[f64; 3], OracleError> {
    window(
        &[("point", point), ("plane", &plane_values(plane))],
        WINDOW_BITS_3D,
    )?;
    let (q, p) = (
        convert::point(point, "point")?,
        convert::plane(plane, "plane")?,
    );
    only_point(convert::float(bridge::epick_project_point_plane(&q, &p)))
}

/// 2D line ∩ line (OPERATIONS.md §6.1): `Empty`, `Point` or `Line`.
pub fn intersect_line2_line2(a: &Line2Input, b: &Line2Input) -> Result<FloatResult2, OracleError> {
    window(
        &[
            ("a", &[a.point, a.direction].concat()),
            ("b", &[b.point, b.direction].concat()),
        ],
        WINDOW_BITS_2D,
    )?;
    let (a, b) = (convert::line2(a, "a")?, convert::line2(b, "b")?);
    convert::float(bridge::epick_lines_2d(&a, &b))
}

/// 2D segment ∩ segment (OPERATIONS.md §6.2): `Empty`, `Point` or `Segment`.
pub fn intersect_segment2_segment2(
    a: &Segment2Input,
    b: &Segment2Input,
) -> Result<FloatResult2, OracleError> {
    window(
        &[
            ("a", &[a.source, a.target].concat()),
            ("b", &[b.source, b.target].concat()),
        ],
        WINDOW_BITS_2D,
    )?;
    let (a, b) = (convert::segment2(a, "a")?, convert::segment2(b, "b")?);
    convert::float(bridge::epick_segments_2d(&a, &b))
}

/// Line ∩ line for lines, rays, ranged lines and segments: `Empty`, `Point`,
/// `Segment`, `Ray` or `Line`.
pub fn intersect_line_line(a: &Linear3Input, b: &Linear3Input) -> Result<FloatResult, OracleError> {
    window(
        &[("a", &linear3_values(a)), ("b", &linear3_values(b))],
        WINDOW_BITS_3D,
    )?;
    let (a, b) = (convert::linear3(a, "a")?, convert::linear3(b, "b")?);
    convert::float(bridge::epick_line_line(&a, &b))
}

/// The numbers of a line ∩ line argument (open range ends are infinite, not numbers).
fn linear3_values(l: &Linear3Input) -> Vec<f64> {
    match l {
        Linear3Input::Line {
            point,
            direction,
            lo,
            hi,
        } => [*point, *direction]
            .concat()
            .into_iter()
            .chain([*lo, *hi].into_iter().filter(|x| x.is_finite()))
            .collect(),
        Linear3Input::Segment(s) => [s.source, s.target].concat(),
    }
}

/// The magnitude window Epick is asked within. Epick's double constructions (a plane's
/// normal `u × v` and offset, the plane–plane line, a 2D line's coefficients) overflow
/// or underflow for large and tiny inputs; its exact fallback then converts an infinite
/// double with GMP's `mpq_set_d`, which raises SIGFPE and kills the process (found by
/// tests/diff_*.rs). Non-zero magnitudes in `[2^-60, 2^60]` (3D; `2^±200` in 2D) keep
/// every construction of these operations finite, so inputs outside are refused with
/// an error instead of an abort.
pub const WINDOW_BITS_3D: i32 = 60;
/// See [`WINDOW_BITS_3D`].
pub const WINDOW_BITS_2D: i32 = 200;

fn window(args: &[(&str, &[f64])], bits: i32) -> Result<(), OracleError> {
    let (lo, hi) = (2f64.powi(-bits), 2f64.powi(bits));
    for (field, values) in args {
        for (i, x) in values.iter().enumerate() {
            let m = x.abs();
            if m != 0.0 && !(lo..=hi).contains(&m) {
                return Err(OracleError::Input(GeomError::Unsupported {
                    field: format!("{field}[{i}]"),
                    reason: format!(
                        "Epick is only asked within magnitudes 2^-{bits}..2^{bits} (beyond, \
                         an overflowing construction makes GMP raise SIGFPE)"
                    ),
                }));
            }
        }
    }
    Ok(())
}

fn plane_values(p: &PlaneInput) -> Vec<f64> {
    match p {
        PlaneInput::Parametric { origin, u, v } => [*origin, *u, *v].concat(),
        PlaneInput::Implicit { a, b, c, d } => vec![*a, *b, *c, *d],
    }
}
