//! The cxx bridge to oracle/*.cpp. Private: the safe API is in [`super::epeck`],
//! [`super::epick`] and [`super::epeck_f64`].
//!
//! Every function returns `Result`, so a C++ exception (CGAL's own, or the
//! `std::invalid_argument("geocert:<kind>:<field>")` thrown for degenerate input)
//! becomes an `Err` instead of an abort.

#[cxx::bridge(namespace = "geocert_oracle")]
pub(crate) mod bridge {
    /// What the result is, which says how to read `v`:
    /// Empty: nothing; Point: x y [z]; Line: point then direction;
    /// Segment: source then target; Plane: a b c d of a x + b y + c z + d = 0;
    /// Ray: source then direction.
    #[derive(Debug)]
    enum Kind {
        Empty,
        Point,
        Line,
        Segment,
        Plane,
        Ray,
    }

    /// Implicit: `v[0..4]` = a, b, c, d. Parametric: `v[0..3]` origin, `v[3..6]` u,
    /// `v[6..9]` v.
    struct PlaneIn {
        implicit: bool,
        v: [f64; 9],
    }

    /// Line: point `a`, direction `b`. Segment: source `a`, target `b`.
    struct Two3 {
        a: [f64; 3],
        b: [f64; 3],
    }

    /// A line, ray or segment of line ∩ line. `segment`: from `a` to `b`. Otherwise the
    /// line through `a` with direction `b`, restricted to `t ∈ [lo, hi]` (`lo = −∞`,
    /// `hi = +∞` for open ends: both open a line, one open a ray, none a segment).
    struct Linear3 {
        segment: bool,
        a: [f64; 3],
        b: [f64; 3],
        lo: f64,
        hi: f64,
    }

    /// As [`Two3`], in the plane.
    struct Two2 {
        a: [f64; 2],
        b: [f64; 2],
    }

    /// Epeck's exact answer: canonical "p/q" or "p" strings.
    struct ExactOut {
        kind: Kind,
        v: Vec<String>,
    }

    /// A double answer; the first as many values as the kind needs are set.
    struct FloatOut {
        kind: Kind,
        v: [f64; 6],
    }

    unsafe extern "C++" {
        include!("geocert/oracle/oracle.h");

        fn epeck_line_plane(line: &Two3, plane: &PlaneIn) -> Result<ExactOut>;
        fn epeck_segment_plane(segment: &Two3, plane: &PlaneIn) -> Result<ExactOut>;
        fn epeck_plane_plane(a: &PlaneIn, b: &PlaneIn) -> Result<ExactOut>;
        fn epeck_three_planes(a: &PlaneIn, b: &PlaneIn, c: &PlaneIn) -> Result<ExactOut>;
        fn epeck_project_point_line(point: &[f64; 3], line: &Two3) -> Result<ExactOut>;
        fn epeck_project_point_plane(point: &[f64; 3], plane: &PlaneIn) -> Result<ExactOut>;
        fn epeck_lines_2d(a: &Two2, b: &Two2) -> Result<ExactOut>;
        fn epeck_segments_2d(a: &Two2, b: &Two2) -> Result<ExactOut>;
        fn epeck_line_line(a: &Linear3, b: &Linear3) -> Result<ExactOut>;

        fn epeck_line_plane_f64(
            force_exact: bool,
            line: &Two3,
            plane: &PlaneIn,
        ) -> Result<FloatOut>;
        fn epeck_segment_plane_f64(
            force_exact: bool,
            segment: &Two3,
            plane: &PlaneIn,
        ) -> Result<FloatOut>;
        fn epeck_plane_plane_f64(force_exact: bool, a: &PlaneIn, b: &PlaneIn) -> Result<FloatOut>;
        fn epeck_three_planes_f64(
            force_exact: bool,
            a: &PlaneIn,
            b: &PlaneIn,
            c: &PlaneIn,
        ) -> Result<FloatOut>;
        fn epeck_project_point_line_f64(
            force_exact: bool,
            point: &[f64; 3],
            line: &Two3,
        ) -> Result<FloatOut>;
        fn epeck_project_point_plane_f64(
            force_exact: bool,
            point: &[f64; 3],
            plane: &PlaneIn,
        ) -> Result<FloatOut>;
        fn epeck_lines_2d_f64(force_exact: bool, a: &Two2, b: &Two2) -> Result<FloatOut>;
        fn epeck_segments_2d_f64(force_exact: bool, a: &Two2, b: &Two2) -> Result<FloatOut>;
        fn epeck_line_line_f64(force_exact: bool, a: &Linear3, b: &Linear3) -> Result<FloatOut>;

        fn epick_line_plane(line: &Two3, plane: &PlaneIn) -> Result<FloatOut>;
        fn epick_segment_plane(segment: &Two3, plane: &PlaneIn) -> Result<FloatOut>;
        fn epick_plane_plane(a: &PlaneIn, b: &PlaneIn) -> Result<FloatOut>;
        fn epick_three_planes(a: &PlaneIn, b: &PlaneIn, c: &PlaneIn) -> Result<FloatOut>;
        fn epick_project_point_line(point: &[f64; 3], line: &Two3) -> Result<FloatOut>;
        fn epick_project_point_plane(point: &[f64; 3], plane: &PlaneIn) -> Result<FloatOut>;
        fn epick_lines_2d(a: &Two2, b: &Two2) -> Result<FloatOut>;
        fn epick_segments_2d(a: &Two2, b: &Two2) -> Result<FloatOut>;
        fn epick_line_line(a: &Linear3, b: &Linear3) -> Result<FloatOut>;
    }
}
