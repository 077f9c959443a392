//! Linear objects (docs/FORMAT.md "Objects"; OPERATIONS.md §3.1, §3.3, §5.1, §6.1–6.2, §7.1, §8),
//! generic over the coordinate type: `f64` (each double taken as an exact value) or
//! `rug::Rational` (exact inputs, e.g. from `"p/q"` strings). Constructors validate and
//! never normalise or round: a zero direction, collinear plane vectors (decided exactly),
//! a zero normal, an inverted range, a degenerate segment and non-finite numbers are
//! typed errors naming the field.

use nalgebra::{SVector, Vector3};
use rug::Rational;
use std::fmt::Debug;

use crate::error::{require_finite, GeomError};
use crate::num::dd::{ProductMode, WithoutFma};
use crate::num::ring::{cross3, Field};

/// A coordinate type of the public API: `f64` or `rug::Rational`.
pub trait Coord: Clone + PartialEq + Debug + 'static {
    /// Reject NaN and infinities (always fine for rationals).
    fn check_finite(&self, field: &str) -> Result<(), GeomError>;
    /// The exact value.
    fn to_rational(&self) -> Rational;
    /// Exactly zero.
    fn is_zero(&self) -> bool;
    /// The number 0.
    fn zero_coord() -> Self;
    /// Exactly `self ≤ other`.
    fn le(&self, other: &Self) -> bool;
    /// Whether the cross product of two vectors is exactly zero.
    fn cross_is_zero(a: &Vector3<Self>, b: &Vector3<Self>) -> bool;
}

impl Coord for f64 {
    fn check_finite(&self, field: &str) -> Result<(), GeomError> {
        require_finite(field, *self).map(|_| ())
    }
    fn to_rational(&self) -> Rational {
        <Rational as Field>::from_f64(*self)
    }
    fn is_zero(&self) -> bool {
        *self == 0.0
    }
    fn zero_coord() -> Self {
        0.0
    }
    fn le(&self, other: &Self) -> bool {
        self <= other
    }
    /// Exact: `a_i b_j == a_j b_i` compared as error-free products `(p, e)` (unique
    /// representations of the exact products) when every factor lies in
    /// `[2⁻⁴⁸⁰, 2⁴⁸⁰]` or is zero; in rationals otherwise.
    fn cross_is_zero(a: &Vector3<f64>, b: &Vector3<f64>) -> bool {
        let safe =
            |x: f64| x == 0.0 || (x.abs() >= 1.0 / 2f64.powi(480) && x.abs() <= 2f64.powi(480));
        if a.iter().chain(b.iter()).all(|&x| safe(x)) {
            let eq = |i: usize, j: usize| {
                WithoutFma::two_prod(a[i], b[j]) == WithoutFma::two_prod(a[j], b[i])
            };
            eq(1, 2) && eq(2, 0) && eq(0, 1)
        } else {
            let q = |v: &Vector3<f64>| [v[0].to_rational(), v[1].to_rational(), v[2].to_rational()];
            cross3(&q(a), &q(b)).iter().all(|x| x.cmp0().is_eq())
        }
    }
}

impl Coord for Rational {
    fn check_finite(&self, _field: &str) -> Result<(), GeomError> {
        Ok(())
    }
    fn to_rational(&self) -> Rational {
        self.clone()
    }
    fn is_zero(&self) -> bool {
        self.cmp0().is_eq()
    }
    fn zero_coord() -> Self {
        Rational::new()
    }
    fn le(&self, other: &Self) -> bool {
        self <= other
    }
    fn cross_is_zero(a: &Vector3<Rational>, b: &Vector3<Rational>) -> bool {
        let q = |v: &Vector3<Rational>| [v[0].clone(), v[1].clone(), v[2].clone()];
        cross3(&q(a), &q(b)).iter().all(|x| x.cmp0().is_eq())
    }
}

fn check_vec<T: Coord>(field: &str, v: &[T]) -> Result<(), GeomError> {
    for (i, x) in v.iter().enumerate() {
        // The field path is formatted only for the error (no allocation otherwise).
        if x.check_finite("").is_err() {
            x.check_finite(&format!("{field}[{i}]"))?;
        }
    }
    Ok(())
}

fn nonzero<T: Coord>(field: &str, v: &[T]) -> Result<(), GeomError> {
    if v.iter().all(|x| x.is_zero()) {
        Err(GeomError::ZeroDirection {
            field: field.to_string(),
        })
    } else {
        Ok(())
    }
}

fn check_range<T: Coord>(range: &Option<[T; 2]>) -> Result<(), GeomError> {
    if let Some([lo, hi]) = range {
        lo.check_finite("range[0]")?;
        hi.check_finite("range[1]")?;
        if !lo.le(hi) {
            return Err(GeomError::EmptyDomain {
                field: "range".into(),
                lo: format!("{lo:?}"),
                hi: format!("{hi:?}"),
            });
        }
    }
    Ok(())
}

/// The parameter range of a line (CASES.md `range`, extended by one-sided ranges):
/// closed `[lo, hi]`, or one-sided, `[lo, +∞)` or `(−∞, hi]`, which makes the line a
/// ray. An infinite end has no number (rationals have none): it is the missing end.
#[derive(Debug, Clone, PartialEq)]
pub enum ParamRange<T> {
    /// `t ∈ [lo, hi]`.
    Closed([T; 2]),
    /// `t ∈ [lo, +∞)`: a ray running towards increasing `t`.
    AtLeast(T),
    /// `t ∈ (−∞, hi]`: a ray running towards decreasing `t`.
    AtMost(T),
}

impl<T> ParamRange<T> {
    /// The lower end, `None` for `−∞`.
    pub fn lo(&self) -> Option<&T> {
        match self {
            ParamRange::Closed([lo, _]) | ParamRange::AtLeast(lo) => Some(lo),
            ParamRange::AtMost(_) => None,
        }
    }
    /// The upper end, `None` for `+∞`.
    pub fn hi(&self) -> Option<&T> {
        match self {
            ParamRange::Closed([_, hi]) | ParamRange::AtMost(hi) => Some(hi),
            ParamRange::AtLeast(_) => None,
        }
    }
}

fn check_param_range<T: Coord>(range: &Option<ParamRange<T>>) -> Result<(), GeomError> {
    match range {
        None => Ok(()),
        Some(ParamRange::Closed([lo, hi])) => check_range(&Some([lo.clone(), hi.clone()])),
        Some(ParamRange::AtLeast(lo)) => lo.check_finite("range[0]"),
        Some(ParamRange::AtMost(hi)) => hi.check_finite("range[1]"),
    }
}

/// A line `c(t) = origin + t·dir` in `D` dimensions (OPERATIONS.md §3.1; 3D unless
/// said otherwise, [`Line2`] in the plane), optionally restricted to `t ∈ range`
/// (closed, or one-sided: a ray, see [`ParamRange`]).
#[derive(Debug, Clone, PartialEq)]
pub struct Line<T: Coord, const D: usize = 3> {
    origin: SVector<T, D>,
    dir: SVector<T, D>,
    range: Option<ParamRange<T>>,
}

/// A 2D line `c(t) = origin + t·dir`, optionally restricted to `t ∈ range`.
pub type Line2<T> = Line<T, 2>;

impl<T: Coord, const D: usize> Line<T, D> {
    /// An unbounded line. Errors: `non_finite` (`origin[i]`, `dir[i]`), `zero_direction` (`dir`).
    pub fn new(origin: SVector<T, D>, dir: SVector<T, D>) -> Result<Self, GeomError> {
        Self::with_param_range(origin, dir, None)
    }
    /// A line restricted to `t ∈ [range[0], range[1]]`; also `empty_domain` (`range`)
    /// when `range[0] > range[1]`.
    pub fn with_range(
        origin: SVector<T, D>,
        dir: SVector<T, D>,
        range: Option<[T; 2]>,
    ) -> Result<Self, GeomError> {
        Self::with_param_range(origin, dir, range.map(ParamRange::Closed))
    }
    /// A line restricted to a closed or one-sided range (errors as [`Line::with_range`];
    /// `non_finite` names the finite end of a one-sided range, `range[0]` or `range[1]`).
    pub fn with_param_range(
        origin: SVector<T, D>,
        dir: SVector<T, D>,
        range: Option<ParamRange<T>>,
    ) -> Result<Self, GeomError> {
        check_vec("origin", origin.as_slice())?;
        check_vec("dir", dir.as_slice())?;
        nonzero("dir", dir.as_slice())?;
        check_param_range(&range)?;
        Ok(Line { origin, dir, range })
    }
    /// The ray `origin + t·dir`, `t ≥ 0` (CGAL's `Ray_3(origin, dir)`).
    pub fn ray(origin: SVector<T, D>, dir: SVector<T, D>) -> Result<Self, GeomError> {
        Self::with_param_range(origin, dir, Some(ParamRange::AtLeast(T::zero_coord())))
    }
    pub fn origin(&self) -> &SVector<T, D> {
        &self.origin
    }
    pub fn dir(&self) -> &SVector<T, D> {
        &self.dir
    }
    /// The closed range `[lo, hi]`, if the line has one. `None` for an unbounded line
    /// **and for a ray**: code that must honour rays reads [`Line::param_range`] or
    /// [`Line::bounds`] (and code that reads only this must refuse rays, see
    /// [`Line::is_ray`]).
    pub fn range(&self) -> Option<&[T; 2]> {
        match &self.range {
            Some(ParamRange::Closed(r)) => Some(r),
            _ => None,
        }
    }
    /// The range as given: closed, one-sided or none.
    pub fn param_range(&self) -> Option<&ParamRange<T>> {
        self.range.as_ref()
    }
    /// The ends of the range, `None` for an infinite end.
    pub fn bounds(&self) -> (Option<&T>, Option<&T>) {
        match &self.range {
            None => (None, None),
            Some(r) => (r.lo(), r.hi()),
        }
    }
    /// Whether the range is one-sided.
    pub fn is_ray(&self) -> bool {
        matches!(
            self.range,
            Some(ParamRange::AtLeast(_) | ParamRange::AtMost(_))
        )
    }
}

/// A segment `c(t) = (1 − t)·a + t·b`, `t ∈ [0, 1]`, in `D` dimensions (3D unless said
/// otherwise, [`Segment2`] in the plane).
#[derive(Debug, Clone, PartialEq)]
pub struct Segment<T: Coord, const D: usize = 3> {
    a: SVector<T, D>,
    b: SVector<T, D>,
}

/// A 2D segment `(1 − t)·a + t·b`, `t ∈ [0, 1]`.
pub type Segment2<T> = Segment<T, 2>;

impl<T: Coord, const D: usize> Segment<T, D> {
    /// Errors: `non_finite` (`a[i]`, `b[i]`), `zero_direction` (`b`) when `a == b`.
    pub fn new(a: SVector<T, D>, b: SVector<T, D>) -> Result<Self, GeomError> {
        check_vec("a", a.as_slice())?;
        check_vec("b", b.as_slice())?;
        if a == b {
            return Err(GeomError::ZeroDirection { field: "b".into() });
        }
        Ok(Segment { a, b })
    }
    pub fn a(&self) -> &SVector<T, D> {
        &self.a
    }
    pub fn b(&self) -> &SVector<T, D> {
        &self.b
    }
}

/// A plane: parametric `s(u, v) = origin + u·u + v·v` (OPERATIONS.md §3.3; any
/// non-collinear basis) or implicit `normal·x + d = 0` (no parameters reported).
#[derive(Debug, Clone, PartialEq)]
pub enum Plane<T: Coord> {
    Parametric {
        origin: Vector3<T>,
        u: Vector3<T>,
        v: Vector3<T>,
    },
    Implicit {
        normal: Vector3<T>,
        d: T,
    },
}

impl<T: Coord> Plane<T> {
    /// Errors: `non_finite` (`origin[i]`, `u[i]`, `v[i]`), `zero_direction` (`u` or `v`),
    /// `collinear_plane_vectors` (`v`) when `u × v = 0` exactly.
    pub fn parametric(origin: Vector3<T>, u: Vector3<T>, v: Vector3<T>) -> Result<Self, GeomError> {
        check_vec("origin", origin.as_slice())?;
        check_vec("u", u.as_slice())?;
        check_vec("v", v.as_slice())?;
        nonzero("u", u.as_slice())?;
        nonzero("v", v.as_slice())?;
        if T::cross_is_zero(&u, &v) {
            return Err(GeomError::CollinearPlaneVectors { field: "v".into() });
        }
        Ok(Plane::Parametric { origin, u, v })
    }
    /// Errors: `non_finite` (`normal[i]`, `d`), `zero_normal` (`normal`).
    pub fn implicit(normal: Vector3<T>, d: T) -> Result<Self, GeomError> {
        check_vec("normal", normal.as_slice())?;
        d.check_finite("d")?;
        if normal.iter().all(|x| x.is_zero()) {
            return Err(GeomError::ZeroNormal {
                field: "normal".into(),
            });
        }
        Ok(Plane::Implicit { normal, d })
    }
}
