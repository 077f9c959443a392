//! The inputs of the filter tier as numbers of a [`Lane`] type: one case (`f64`) or
//! four cases of the same kind in lanes (`F4`, the batch kernels). From them, written
//! once for both: the filter's group scales ([`crate::num::filter::scale_of`]) and the
//! data in double-double ([`LineData`], [`PlaneData`], as `Linear::data` and
//! `PlaneData::new` build them for one case).

use nalgebra::Vector3;

use super::data::{LineData, Linear, PlaneData};
use super::objects::Plane;
use crate::num::dd::{Dd, ProductMode};
use crate::num::filter::{extend_scale_of, scale_of};
use crate::num::lane::{Lane, Wide};
use crate::num::ring::{each, V3};

/// A line (origin, direction) or a segment (end points), coordinates as they are given.
#[derive(Debug, Clone, Copy)]
pub(crate) enum RawLine<F> {
    Line { o: V3<F>, d: V3<F> },
    Segment { a: V3<F>, b: V3<F> },
}

/// A parametric (origin, spanning vectors) or implicit (normal, `d`) plane.
#[derive(Debug, Clone, Copy)]
pub(crate) enum RawPlane<F> {
    Param { o: V3<F>, u: V3<F>, v: V3<F> },
    Implicit { n: V3<F>, d: F },
}

#[inline(always)]
fn v3(v: &Vector3<f64>) -> V3<f64> {
    [v[0], v[1], v[2]]
}

/// Vectors in lanes (coordinate `k` of case `i` in lane `i`), `v(i)` for lane `i`.
#[inline(always)]
fn gather3<'a, F: Wide>(v: impl Fn(usize) -> &'a Vector3<f64>) -> V3<F> {
    each!(k in [0, 1, 2] => F::from_fn(|i| v(i)[k]))
}

#[inline(always)]
fn lift3<M: ProductMode, F: Lane>(v: &V3<F>) -> V3<Dd<M, F>> {
    each!(k in [0, 1, 2] => Dd::exact(v[k]))
}

impl RawLine<f64> {
    /// One case (the range, if any, is tested by the caller on the rounded parameter).
    #[inline(always)]
    pub(crate) fn new(l: Linear<f64>) -> Self {
        match l {
            Linear::Line(l) => RawLine::Line {
                o: v3(l.origin()),
                d: v3(l.dir()),
            },
            Linear::Segment(s) => RawLine::Segment {
                a: v3(s.a()),
                b: v3(s.b()),
            },
        }
    }
}

impl<F: Wide> RawLine<F> {
    /// `F::N` lines, or `F::N` segments, in lanes (object of lane `i`: `l(i)`); `None`
    /// when the kinds differ.
    #[inline(always)]
    pub(crate) fn gather<'a>(l: impl Fn(usize) -> Linear<'a, f64>) -> Option<Self> {
        let line = |i: usize| match l(i) {
            Linear::Line(x) => Some(x),
            Linear::Segment(_) => None,
        };
        let segment = |i: usize| match l(i) {
            Linear::Segment(x) => Some(x),
            Linear::Line(_) => None,
        };
        if (0..F::N).all(|i| line(i).is_some()) {
            let q = |i: usize| line(i).expect("checked");
            Some(RawLine::Line {
                o: gather3(|i| q(i).origin()),
                d: gather3(|i| q(i).dir()),
            })
        } else if (0..F::N).all(|i| segment(i).is_some()) {
            let q = |i: usize| segment(i).expect("checked");
            Some(RawLine::Segment {
                a: gather3(|i| q(i).a()),
                b: gather3(|i| q(i).b()),
            })
        } else {
            None
        }
    }
}

impl<F: Lane> RawLine<F> {
    /// The filter scales `(m_P, m_L)` of positions and direction (a segment's direction
    /// `b − a` is in the position group: both are its end points' scale).
    #[inline(always)]
    pub(crate) fn scales(&self) -> (F, F) {
        match self {
            RawLine::Line { o, d } => (scale_of(o), scale_of(d)),
            RawLine::Segment { a, b } => {
                let m = scale_of(a).max(scale_of(b));
                (m, m)
            }
        }
    }
    /// The line in double-double: `o + t·d` (a segment: `a + t(b − a)`), range left out.
    #[inline(always)]
    pub(crate) fn data<M: ProductMode>(&self) -> LineData<Dd<M, F>> {
        match self {
            RawLine::Line { o, d } => LineData {
                o: lift3(o),
                d: lift3(d),
                range: None,
            },
            RawLine::Segment { a, b } => LineData::segment(lift3(a), lift3(b)),
        }
    }
}

impl RawPlane<f64> {
    /// One plane.
    #[inline(always)]
    pub(crate) fn new(p: &Plane<f64>) -> Self {
        match p {
            Plane::Parametric { origin, u, v } => RawPlane::Param {
                o: v3(origin),
                u: v3(u),
                v: v3(v),
            },
            Plane::Implicit { normal, d } => RawPlane::Implicit {
                n: v3(normal),
                d: *d,
            },
        }
    }
}

impl<F: Wide> RawPlane<F> {
    /// `F::N` parametric, or `F::N` implicit, planes in lanes (plane of lane `i`:
    /// `p(i)`); `None` when the kinds differ.
    #[inline(always)]
    pub(crate) fn gather<'a>(p: impl Fn(usize) -> &'a Plane<f64>) -> Option<Self> {
        let param = |i: usize| match p(i) {
            Plane::Parametric { origin, u, v } => Some((origin, u, v)),
            Plane::Implicit { .. } => None,
        };
        let implicit = |i: usize| match p(i) {
            Plane::Implicit { normal, d } => Some((normal, *d)),
            Plane::Parametric { .. } => None,
        };
        if (0..F::N).all(|i| param(i).is_some()) {
            let q = |i: usize| param(i).expect("checked");
            Some(RawPlane::Param {
                o: gather3(|i| q(i).0),
                u: gather3(|i| q(i).1),
                v: gather3(|i| q(i).2),
            })
        } else if (0..F::N).all(|i| implicit(i).is_some()) {
            let q = |i: usize| implicit(i).expect("checked");
            Some(RawPlane::Implicit {
                n: gather3(|i| q(i).0),
                d: F::from_fn(|i| q(i).1),
            })
        } else {
            None
        }
    }
}

impl<F: Lane> RawPlane<F> {
    /// The filter scales of a plane: `(m_G, m_G^k)` (`k = 2` parametric, `1` implicit)
    /// and the position scale `mp` extended by its origin (parametric) or by `|d|/m_n`
    /// (implicit: `d` is in the units of normal × position).
    #[inline(always)]
    pub(crate) fn scales(&self, mp: F) -> (F, F, F) {
        match self {
            RawPlane::Param { o, u, v } => {
                let m = scale_of(u).max(scale_of(v));
                (m, m * m, mp.max(scale_of(o)))
            }
            RawPlane::Implicit { n, d } => {
                let m = scale_of(n);
                (m, m, extend_scale_of(mp, *d, m))
            }
        }
    }
    /// The plane in double-double with its normal (`u × v` or the given normal).
    #[inline(always)]
    pub(crate) fn data<M: ProductMode>(&self) -> PlaneData<Dd<M, F>> {
        match self {
            RawPlane::Param { o, u, v } => PlaneData::parametric(lift3(o), lift3(u), lift3(v)),
            RawPlane::Implicit { n, d } => PlaneData::Implicit {
                n: lift3(n),
                d: Dd::exact(*d),
            },
        }
    }
}
