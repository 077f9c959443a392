//! The inputs of the filter tier as numbers of a [`Lane`] type: one case (`f64`) or
//! four cases of the same kind in lanes (`F4`, the batch kernels). From them, written
//! once for both: the filter's group scales ([`crate::num::filter::scale_of`]) and the
//! data in double-double ([`LineData`], [`PlaneData`], as `Linear::data` and
//! `PlaneData::new` build them for one case).

use nalgebra::Vector3;

use super::data::{unit_range, LineData, Linear, PlaneData};
use super::objects::Plane;
use crate::num::dd::{Dd, ProductMode};
use crate::num::filter::{extend_scale_of, scale_of};
use crate::num::lane::{Lane, F4};
use crate::num::ring::{cross3, each, sub3, V3};

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

/// Four vectors in lanes (coordinate `k` of case `i` in lane `i`).
#[inline(always)]
fn gather3(vs: [&Vector3<f64>; 4]) -> V3<F4> {
    each!(k in [0, 1, 2] => F4::new([vs[0][k], vs[1][k], vs[2][k], vs[3][k]]))
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

impl RawLine<F4> {
    /// Four lines, or four segments, in lanes; `None` when the kinds differ.
    #[inline(always)]
    pub(crate) fn gather(ls: [Linear<f64>; 4]) -> Option<Self> {
        use Linear::{Line as L, Segment as S};
        match ls {
            [L(a), L(b), L(c), L(d)] => Some(RawLine::Line {
                o: gather3([a.origin(), b.origin(), c.origin(), d.origin()]),
                d: gather3([a.dir(), b.dir(), c.dir(), d.dir()]),
            }),
            [S(a), S(b), S(c), S(d)] => Some(RawLine::Segment {
                a: gather3([a.a(), b.a(), c.a(), d.a()]),
                b: gather3([a.b(), b.b(), c.b(), d.b()]),
            }),
            _ => None,
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
            RawLine::Segment { a, b } => {
                let o = lift3(a);
                let d = sub3(&lift3(b), &o);
                LineData {
                    o,
                    d,
                    range: Some(unit_range()),
                }
            }
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

impl RawPlane<F4> {
    /// Four parametric, or four implicit, planes in lanes; `None` when the kinds differ.
    #[inline(always)]
    pub(crate) fn gather(ps: [&Plane<f64>; 4]) -> Option<Self> {
        use Plane::{Implicit as I, Parametric as P};
        match ps {
            [P {
                origin: o0,
                u: u0,
                v: v0,
            }, P {
                origin: o1,
                u: u1,
                v: v1,
            }, P {
                origin: o2,
                u: u2,
                v: v2,
            }, P {
                origin: o3,
                u: u3,
                v: v3,
            }] => Some(RawPlane::Param {
                o: gather3([o0, o1, o2, o3]),
                u: gather3([u0, u1, u2, u3]),
                v: gather3([v0, v1, v2, v3]),
            }),
            [I { normal: n0, d: d0 }, I { normal: n1, d: d1 }, I { normal: n2, d: d2 }, I { normal: n3, d: d3 }] => {
                Some(RawPlane::Implicit {
                    n: gather3([n0, n1, n2, n3]),
                    d: F4::new([*d0, *d1, *d2, *d3]),
                })
            }
            _ => None,
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
            RawPlane::Param { o, u, v } => {
                let (u, v) = (lift3(u), lift3(v));
                let n = cross3(&u, &v);
                PlaneData::Param {
                    o: lift3(o),
                    u,
                    v,
                    n,
                }
            }
            RawPlane::Implicit { n, d } => PlaneData::Implicit {
                n: lift3(n),
                d: Dd::exact(*d),
            },
        }
    }
}
