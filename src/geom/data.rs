//! The objects lifted into a ring (`f64`, double-double, error bounds, rationals): the
//! form every formula of the kernel reads. A segment becomes the line `a + t(b − a)`,
//! `t ∈ [0, 1]`; a parametric plane gets its normal `N = u × v` (unnormalised,
//! OPERATIONS.md §3.3 eq. (3.5) before the division), an implicit plane keeps `normal`.

use nalgebra::{Vector2, Vector3};
use rug::Rational;

use super::objects::{Coord, Line, Line2, Plane, Segment, Segment2};
use crate::num::dd::{Dd, ProductMode};
use crate::num::ratio::{Ratio, SignedRing};
use crate::num::ring::{cross3, dot3, scale3, sub2, sub3, Field, Ring, V2, V3};

/// Conversion of an input coordinate into a ring (exact for every pair used).
pub trait Lift<R> {
    fn lift(&self) -> R;
}
impl Lift<f64> for f64 {
    #[inline(always)]
    fn lift(&self) -> f64 {
        *self
    }
}
impl Lift<Rational> for f64 {
    fn lift(&self) -> Rational {
        <Rational as Field>::from_f64(*self)
    }
}
impl Lift<Rational> for Rational {
    fn lift(&self) -> Rational {
        self.clone()
    }
}
impl<E: SignedRing> Lift<Ratio<E>> for f64 {
    #[inline(always)]
    fn lift(&self) -> Ratio<E> {
        <Ratio<E> as Field>::from_f64(*self)
    }
}
impl<M: ProductMode> Lift<Dd<M>> for f64 {
    #[inline(always)]
    fn lift(&self) -> Dd<M> {
        Dd::from_f64(*self)
    }
}

#[inline(always)]
pub(crate) fn lift3<T: Lift<R>, R>(v: &Vector3<T>) -> V3<R> {
    [v[0].lift(), v[1].lift(), v[2].lift()]
}
#[inline(always)]
pub(crate) fn lift2<T: Lift<R>, R>(v: &Vector2<T>) -> V2<R> {
    [v[0].lift(), v[1].lift()]
}

/// A 3D line in a ring: `o + t·d`, `t` between the two `ends` (`None`: that end is
/// infinite, so `[None, None]` is the whole line and one `None` a ray).
#[derive(Debug, Clone)]
pub(crate) struct LineData<R> {
    pub o: V3<R>,
    pub d: V3<R>,
    pub ends: [Option<R>; 2],
}

impl<R: Field> LineData<R> {
    /// Whether `t` lies in the domain (both ends closed).
    pub(crate) fn contains(&self, t: &R) -> bool {
        let [lo, hi] = &self.ends;
        lo.as_ref().is_none_or(|a| t.compare(a).is_ge())
            && hi.as_ref().is_none_or(|b| t.compare(b).is_le())
    }
}

/// A 2D line in a ring.
#[derive(Debug, Clone)]
pub(crate) struct Line2Data<R> {
    pub o: V2<R>,
    pub d: V2<R>,
    pub range: Option<[R; 2]>,
}

/// A 3D linear object with a parameter: a line (maybe ranged) or a segment.
#[derive(Debug)]
pub enum Linear<'a, T: Coord> {
    Line(&'a Line<T>),
    Segment(&'a Segment<T>),
}

/// A 2D linear object with a parameter.
#[derive(Debug)]
pub enum Linear2<'a, T: Coord> {
    Line(&'a Line2<T>),
    Segment(&'a Segment2<T>),
}

// Copy for every coordinate type (the enums only hold references).
impl<T: Coord> Clone for Linear<'_, T> {
    fn clone(&self) -> Self {
        *self
    }
}
impl<T: Coord> Copy for Linear<'_, T> {}
impl<T: Coord> Clone for Linear2<'_, T> {
    fn clone(&self) -> Self {
        *self
    }
}
impl<T: Coord> Copy for Linear2<'_, T> {}

impl<'a, T: Coord> Linear<'a, T> {
    #[inline(always)]
    pub(crate) fn data<R: Ring>(&self) -> LineData<R>
    where
        T: Lift<R>,
    {
        match self {
            Linear::Line(l) => {
                let (lo, hi) = l.bounds();
                LineData {
                    o: lift3(l.origin()),
                    d: lift3(l.dir()),
                    ends: [lo.map(Lift::lift), hi.map(Lift::lift)],
                }
            }
            Linear::Segment(s) => LineData::segment(lift3(s.a()), lift3(s.b())),
        }
    }
}

impl Linear<'_, f64> {
    /// The ends of the parameter domain as doubles, `None` for an infinite end (a ray's
    /// open end, both ends of a line; a segment's are `0`, `1`).
    pub(crate) fn ends_f64(&self) -> [Option<f64>; 2] {
        match self {
            Linear::Line(l) => {
                let (lo, hi) = l.bounds();
                [lo.copied(), hi.copied()]
            }
            Linear::Segment(_) => [Some(0.0), Some(1.0)],
        }
    }

    /// Whether the exact value of `t` lies in the domain, decided on its enclosure:
    /// the domain's ends are doubles, so comparing `t` with them is exact.
    pub(crate) fn bounds_contain(&self, t: &crate::num::round::Rounded) -> bool {
        let [lo, hi] = self.ends_f64();
        lo.is_none_or(|lo| t.compare_f64(lo).is_ge())
            && hi.is_none_or(|hi| t.compare_f64(hi).is_le())
    }
}

impl<R: Ring> LineData<R> {
    /// The segment `a + t(b − a)`, `t ∈ [0, 1]`.
    #[inline(always)]
    pub(crate) fn segment(a: V3<R>, b: V3<R>) -> Self {
        let d = sub3(&b, &a);
        let [zero, one] = unit_range();
        LineData {
            o: a,
            d,
            ends: [Some(zero), Some(one)],
        }
    }
}

impl<'a, T: Coord> Linear2<'a, T> {
    #[inline(always)]
    pub(crate) fn data<R: Ring>(&self) -> Line2Data<R>
    where
        T: Lift<R>,
    {
        match self {
            Linear2::Line(l) => Line2Data {
                o: lift2(l.origin()),
                d: lift2(l.dir()),
                range: l.range().map(|[a, b]| [a.lift(), b.lift()]),
            },
            Linear2::Segment(s) => {
                let a = lift2(s.a());
                let d = sub2(&lift2(s.b()), &a);
                Line2Data {
                    o: a,
                    d,
                    range: Some(unit_range()),
                }
            }
        }
    }
}

/// `[0, 1]` in any ring (built from the additive identity and `0 − (0 − 1)`-free ops).
#[inline(always)]
pub(crate) fn unit_range<R: Ring>() -> [R; 2] {
    [R::zero(), one::<R>()]
}

/// 1 in any ring the kernel uses (only rings with exact small integers reach here).
#[inline(always)]
pub(crate) fn one<R: Ring>() -> R {
    R::one()
}

/// A plane in a ring with its normal `n` (`u × v` or the given normal).
#[derive(Debug, Clone)]
pub(crate) enum PlaneData<R> {
    Param {
        o: V3<R>,
        u: V3<R>,
        v: V3<R>,
        n: V3<R>,
    },
    Implicit {
        n: V3<R>,
        d: R,
    },
    /// Lane groups of mixed kinds ([`super::raw::MixedPlanes`]): both forms at once,
    /// `f(x) = N·(x − o) + d`, with `o`, `u`, `v` zero in the implicit lanes and `d`
    /// zero in the parametric ones. Adding or subtracting those exact zeros changes no
    /// value (only, possibly, the sign of a zero), so each lane computes the value its
    /// own kind computes.
    General {
        o: V3<R>,
        u: V3<R>,
        v: V3<R>,
        n: V3<R>,
        d: R,
    },
}

impl<R: Ring> PlaneData<R> {
    #[inline(always)]
    pub(crate) fn new<T: Coord + Lift<R>>(p: &Plane<T>) -> Self {
        match p {
            Plane::Parametric { origin, u, v } => {
                PlaneData::parametric(lift3(origin), lift3(u), lift3(v))
            }
            Plane::Implicit { normal, d } => PlaneData::Implicit {
                n: lift3(normal),
                d: d.lift(),
            },
        }
    }
    /// The parametric plane `o + s·u + t·v` with its normal `N = u × v`.
    #[inline(always)]
    pub(crate) fn parametric(o: V3<R>, u: V3<R>, v: V3<R>) -> Self {
        let n = cross3(&u, &v);
        PlaneData::Param { o, u, v, n }
    }
    /// The (unnormalised) normal `N`.
    #[inline(always)]
    pub(crate) fn n(&self) -> &V3<R> {
        match self {
            PlaneData::Param { n, .. }
            | PlaneData::Implicit { n, .. }
            | PlaneData::General { n, .. } => n,
        }
    }
    /// `f(x) = N·(x − o)` or `n·x + d`: zero exactly on the plane, `N·x − h`.
    #[inline(always)]
    pub(crate) fn value_at(&self, x: &V3<R>) -> R {
        match self {
            PlaneData::Param { o, n, .. } => dot3(n, &sub3(x, o)),
            PlaneData::Implicit { n, d } => dot3(n, x).plus(d),
            PlaneData::General { o, n, d, .. } => dot3(n, &sub3(x, o)).plus(d),
        }
    }
    /// `w·f(x/w)` for the point given by homogeneous coordinates `(x, w)`, `w ≠ 0`: zero
    /// exactly when `x/w` lies on the plane, and a polynomial (no division).
    #[inline(always)]
    pub(crate) fn value_at_homogeneous(&self, x: &V3<R>, w: &R) -> R {
        match self {
            PlaneData::Param { o, n, .. } => dot3(n, &sub3(x, &scale3(w, o))),
            PlaneData::Implicit { n, d } => dot3(n, x).plus(&d.times(w)),
            PlaneData::General { o, n, d, .. } => {
                dot3(n, &sub3(x, &scale3(w, o))).plus(&d.times(w))
            }
        }
    }
    /// `h` with the plane `N·x = h`.
    pub(crate) fn offset(&self) -> R {
        match self {
            PlaneData::Param { o, n, .. } => dot3(n, o),
            PlaneData::Implicit { d, .. } => d.negate(),
            PlaneData::General { o, n, d, .. } => dot3(n, o).minus(d),
        }
    }
    /// The origin of a parametric plane (`None` for mixed lanes, whose kind is per
    /// lane: their formulas take the reference point lane by lane).
    #[inline(always)]
    pub(crate) fn origin(&self) -> Option<&V3<R>> {
        match self {
            PlaneData::Param { o, .. } => Some(o),
            PlaneData::Implicit { .. } | PlaneData::General { .. } => None,
        }
    }
    /// The origin, zero for an implicit plane and in the implicit lanes of mixed ones.
    #[inline(always)]
    pub(crate) fn origin_or_zero(&self) -> V3<R> {
        match self {
            PlaneData::Param { o, .. } | PlaneData::General { o, .. } => o.clone(),
            PlaneData::Implicit { .. } => [R::zero(), R::zero(), R::zero()],
        }
    }
}
