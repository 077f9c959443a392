//! The CGAL oracle (feature `cgal`): CGAL 5.5's answers for the linear operations,
//! for differential tests and side-by-side benchmarks. See oracle/README.md.
//!
//! Three ways to ask, one module each, with the same eight functions:
//!
//! * [`epeck`] — `Exact_predicates_exact_constructions_kernel`, the reference:
//!   every coordinate is CGAL's exact rational, returned as a [`rug::Rational`];
//! * [`epick`] — `Exact_predicates_inexact_constructions_kernel`, the fast double
//!   kernel a CGAL user would otherwise pick: exact predicates on rounded
//!   constructions, so its kind can be wrong on degenerate input;
//! * [`epeck_f64`] — Epeck's computation returned as doubles, either the lazy
//!   approximation or the forced exact value rounded ([`EpeckToDouble`]); for benchmarks.
//!
//! The operations (OPERATIONS.md §3.1, §3.3, §5.1, §6.1, §6.2, §7.1, §8):
//! `intersect_line_plane`, `intersect_segment_plane`, `intersect_plane_plane`,
//! `intersect_three_planes`, `project_point_line`, `project_point_plane`,
//! `intersect_line2_line2`, `intersect_segment2_segment2`; and `intersect_line_line`
//! for any two of lines, rays, ranged lines and segments in space ([`Linear3Input`]).
//!
//! Inputs are doubles, taken exactly by Epeck. A non-finite input is refused in Rust
//! ([`GeomError::NonFinite`] naming the component, e.g. `plane.origin[1]`). A
//! degenerate one is refused by the C++ side, decided by the kernel itself (exactly
//! for Epeck, on its rounded objects for Epick): a zero line direction
//! ([`GeomError::ZeroDirection`]), a zero implicit normal ([`GeomError::ZeroNormal`]),
//! collinear plane vectors ([`GeomError::CollinearPlaneVectors`]), a segment whose end
//! points coincide ([`GeomError::InvalidValue`]). The argument names used in the
//! fields are those of the functions' parameters.
//!
//! Every call builds its own CGAL objects, so calls may run on several threads.

mod convert;
pub mod epeck;
pub mod epeck_f64;
pub mod epick;
mod ffi;

use crate::GeomError;
use rug::Rational;
use thiserror::Error;

pub use convert::EpeckToDouble;

/// A plane, as geocert's cases give it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum PlaneInput {
    /// `origin + s·u + t·v` (OPERATIONS.md §1.6); the oracle builds it as CGAL's
    /// `Plane_3(origin, u × v)`, exactly for Epeck.
    Parametric {
        origin: [f64; 3],
        u: [f64; 3],
        v: [f64; 3],
    },
    /// `a x + b y + c z + d = 0`.
    Implicit { a: f64, b: f64, c: f64, d: f64 },
}

/// The line `point + t·direction` (OPERATIONS.md §1.5).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LineInput {
    pub point: [f64; 3],
    pub direction: [f64; 3],
}

/// The segment from `source` to `target`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SegmentInput {
    pub source: [f64; 3],
    pub target: [f64; 3],
}

/// An argument of line ∩ line: the line `point + t·direction` restricted to
/// `t ∈ [lo, hi]` (`lo = −∞` and `hi = +∞` for open ends: both open is CGAL's `Line_3`,
/// one open a `Ray_3` from the finite end, none a `Segment_3` between the ends — end
/// points constructed in the kernel's arithmetic, exactly in Epeck), or a segment.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Linear3Input {
    Line {
        point: [f64; 3],
        direction: [f64; 3],
        lo: f64,
        hi: f64,
    },
    Segment(SegmentInput),
}

/// The 2D line `point + t·direction`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Line2Input {
    pub point: [f64; 2],
    pub direction: [f64; 2],
}

/// The 2D segment from `source` to `target`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Segment2Input {
    pub source: [f64; 2],
    pub target: [f64; 2],
}

/// What CGAL answered, in dimension `D`, with coordinates of type `T`
/// ([`Rational`] for Epeck, `f64` otherwise).
///
/// Which kinds each operation can give:
///
/// | operation | kinds |
/// |---|---|
/// | line ∩ plane | `Empty`, `Point`, `Line` (the line lies in the plane) |
/// | segment ∩ plane | `Empty`, `Point`, `Segment` (the segment lies in the plane) |
/// | plane ∩ plane | `Empty` (parallel), `Line`, `Plane` (coincident) |
/// | three planes | `Empty`, `Point`, `Line`, `Plane` |
/// | 2D line ∩ line | `Empty` (parallel), `Point`, `Line` (equal) |
/// | 2D segment ∩ segment | `Empty`, `Point`, `Segment` (collinear overlap) |
/// | line/ray/segment ∩ line/ray/segment | `Empty`, `Point`, `Segment`, `Ray`, `Line` (collinear overlap) |
///
/// Lines and planes are CGAL's representatives, not unique: compare them as sets.
#[derive(Debug, Clone, PartialEq)]
pub enum Intersection<T, const D: usize> {
    /// The objects do not meet.
    Empty,
    /// A single point.
    Point([T; D]),
    /// A whole line: CGAL's `point()` on it (`point(0)` in 2D) and its
    /// `to_vector()`, a non-zero direction of arbitrary length and sign.
    Line { point: [T; D], direction: [T; D] },
    /// A segment, as CGAL orients it.
    Segment { source: [T; D], target: [T; D] },
    /// A ray (3D only): CGAL's `source()` and `to_vector()` (a non-zero direction of
    /// arbitrary length).
    Ray { source: [T; D], direction: [T; D] },
    /// A whole plane (3D only): the coefficients `[a, b, c, d]` of
    /// `a x + b y + c z + d = 0` (CGAL returns one of the input planes).
    Plane([T; 4]),
}

/// Epeck's exact answer in space.
pub type ExactResult = Intersection<Rational, 3>;
/// Epeck's exact answer in the plane.
pub type ExactResult2 = Intersection<Rational, 2>;
/// A double answer (Epick, or Epeck rounded) in space.
pub type FloatResult = Intersection<f64, 3>;
/// A double answer in the plane.
pub type FloatResult2 = Intersection<f64, 2>;

/// Why the oracle gave no answer.
#[derive(Debug, Clone, PartialEq, Eq, Error)]
pub enum OracleError {
    /// Bad input: non-finite, or degenerate as decided by the kernel.
    #[error(transparent)]
    Input(#[from] GeomError),
    /// CGAL (or the C++ runtime) threw; the message is the exception's `what()`.
    #[error("CGAL threw: {0}")]
    Cgal(String),
    /// The C++ side returned something the bridge cannot read (a bug in the bridge).
    #[error("the oracle bridge returned {0}")]
    Bridge(String),
}
