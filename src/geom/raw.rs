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
use crate::num::lane::{Lane, Wide, MAX_LANES};
use crate::num::ring::{cross3, each, V3};

/// A line (origin, direction) or a segment (end points), coordinates as they are given;
/// or, in a lane group only (the witness `F::Group` is uninhabited for one case), lines
/// and segments together.
#[derive(Debug, Clone, Copy)]
pub(crate) enum RawLine<F: Lane> {
    Line { o: V3<F>, d: V3<F> },
    Segment { a: V3<F>, b: V3<F> },
    Mixed(MixedLines<F>, F::Group),
}

/// Lines and segments in lanes: `o` is a line's origin or a segment's first end, `d` a
/// line's direction (zero for a segment), `b` a segment's second end (zero for a
/// line); `segment` marks the segment lanes.
#[derive(Debug, Clone, Copy)]
pub(crate) struct MixedLines<F: Lane> {
    pub o: V3<F>,
    pub d: V3<F>,
    pub b: V3<F>,
    pub segment: F::Mask,
}

/// A parametric (origin, spanning vectors) or implicit (normal, `d`) plane; or, in a
/// lane group only (the witness `F::Group` is uninhabited for one case), planes of both
/// kinds.
#[derive(Debug, Clone, Copy)]
pub(crate) enum RawPlane<F: Lane> {
    Param { o: V3<F>, u: V3<F>, v: V3<F> },
    Implicit { n: V3<F>, d: F },
    Mixed(MixedPlanes<F>, F::Group),
}

/// Planes of both kinds in lanes: `implicit` marks the implicit lanes; in each lane the
/// other kind's fields are zero.
#[derive(Debug, Clone, Copy)]
pub(crate) struct MixedPlanes<F: Lane> {
    pub o: V3<F>,
    pub u: V3<F>,
    pub v: V3<F>,
    pub n: V3<F>,
    pub d: F,
    pub implicit: F::Mask,
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
    /// `F::N` lines or segments in lanes (object of lane `i`: `l(i)`): `Line` or
    /// `Segment` when they are all of one kind, else `Mixed`.
    #[inline(always)]
    pub(crate) fn gather<'a>(l: impl Fn(usize) -> Linear<'a, f64>) -> Self {
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
            return RawLine::Line {
                o: gather3(|i| q(i).origin()),
                d: gather3(|i| q(i).dir()),
            };
        } else if (0..F::N).all(|i| segment(i).is_some()) {
            let q = |i: usize| segment(i).expect("checked");
            return RawLine::Segment {
                a: gather3(|i| q(i).a()),
                b: gather3(|i| q(i).b()),
            };
        }
        // One pass over the lanes, a column each: 0–2 o, 3–5 d, 6–8 b, 9 the segment
        // lanes as 1.0 (the other kind's entries stay zero).
        let mut cols = [[0.0; 10]; MAX_LANES];
        for (i, col) in cols.iter_mut().enumerate().take(F::N) {
            match l(i) {
                Linear::Line(x) => {
                    col[..3].copy_from_slice(x.origin().as_slice());
                    col[3..6].copy_from_slice(x.dir().as_slice());
                }
                Linear::Segment(x) => {
                    col[..3].copy_from_slice(x.a().as_slice());
                    col[6..9].copy_from_slice(x.b().as_slice());
                    col[9] = 1.0;
                }
            }
        }
        let row = |r: usize| F::from_fn(|i| cols[i][r]);
        let v3 = |r: usize| [row(r), row(r + 1), row(r + 2)];
        let mixed = MixedLines {
            o: v3(0),
            d: v3(3),
            b: v3(6),
            segment: row(9).equal(F::splat(1.0)),
        };
        RawLine::Mixed(mixed, F::group())
    }
}

/// The scales of a line (see [`RawLine::scales`]).
#[inline(always)]
fn line_scales<F: Lane>(o: &V3<F>, d: &V3<F>) -> (F, F) {
    (scale_of(o), scale_of(d))
}

/// The scales of a segment (see [`RawLine::scales`]).
#[inline(always)]
fn segment_scales<F: Lane>(a: &V3<F>, b: &V3<F>) -> (F, F) {
    let m = scale_of(a).max(scale_of(b));
    (m, m)
}

impl<F: Lane> MixedLines<F> {
    /// Each lane's scales of its kind (see [`RawLine::scales`]).
    #[inline(always)]
    pub(crate) fn scales(&self) -> (F, F) {
        let (lp, ll) = line_scales(&self.o, &self.d);
        let (sp, sl) = segment_scales(&self.o, &self.b);
        (
            F::select(self.segment, sp, lp),
            F::select(self.segment, sl, ll),
        )
    }
    /// Each lane's line in double-double: a line's `d`, a segment's `b − a` (as
    /// [`LineData::segment`] computes it).
    #[inline(always)]
    pub(crate) fn data<M: ProductMode>(&self) -> LineData<Dd<M, F>> {
        let (o, d) = (lift3(&self.o), lift3::<M, F>(&self.d));
        let ba = LineData::segment(o, lift3(&self.b)).d;
        LineData {
            o,
            d: each!(k in [0, 1, 2] => Dd::select(self.segment, &ba[k], &d[k])),
            ends: [None, None],
        }
    }
}

impl<F: Lane> RawLine<F> {
    /// The filter scales `(m_P, m_L)` of positions and direction (a segment's direction
    /// `b − a` is in the position group: both are its end points' scale).
    #[inline(always)]
    pub(crate) fn scales(&self) -> (F, F) {
        match self {
            RawLine::Line { o, d } => line_scales(o, d),
            RawLine::Segment { a, b } => segment_scales(a, b),
            RawLine::Mixed(m, _) => m.scales(),
        }
    }
    /// The line in double-double: `o + t·d` (a segment: `a + t(b − a)`), range left out.
    #[inline(always)]
    pub(crate) fn data<M: ProductMode>(&self) -> LineData<Dd<M, F>> {
        match self {
            RawLine::Line { o, d } => LineData {
                o: lift3(o),
                d: lift3(d),
                ends: [None, None],
            },
            RawLine::Segment { a, b } => LineData::segment(lift3(a), lift3(b)),
            RawLine::Mixed(m, _) => m.data(),
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
    /// `F::N` planes in lanes (plane of lane `i`: `p(i)`): `Param` or `Implicit` when
    /// they are all of one kind, else `Mixed`.
    #[inline(always)]
    pub(crate) fn gather<'a>(p: impl Fn(usize) -> &'a Plane<f64>) -> Self {
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
            return RawPlane::Param {
                o: gather3(|i| q(i).0),
                u: gather3(|i| q(i).1),
                v: gather3(|i| q(i).2),
            };
        } else if (0..F::N).all(|i| implicit(i).is_some()) {
            let q = |i: usize| implicit(i).expect("checked");
            return RawPlane::Implicit {
                n: gather3(|i| q(i).0),
                d: F::from_fn(|i| q(i).1),
            };
        }
        // One pass over the lanes, a column each: 0–8 origin, u, v; 9–11 normal; 12 d;
        // 13 the implicit lanes as 1.0 (the other kind's entries stay zero).
        let mut cols = [[0.0; 14]; MAX_LANES];
        let mut implicit = 0;
        for (i, col) in cols.iter_mut().enumerate().take(F::N) {
            match p(i) {
                Plane::Parametric { origin, u, v } => {
                    col[..3].copy_from_slice(origin.as_slice());
                    col[3..6].copy_from_slice(u.as_slice());
                    col[6..9].copy_from_slice(v.as_slice());
                }
                Plane::Implicit { normal, d } => {
                    col[9..12].copy_from_slice(normal.as_slice());
                    col[12] = *d;
                    col[13] = 1.0;
                    implicit += 1;
                }
            }
        }
        let row = |r: usize| F::from_fn(|i| cols[i][r]);
        let v3 = |r: usize| [row(r), row(r + 1), row(r + 2)];
        if implicit == 0 {
            RawPlane::Param {
                o: v3(0),
                u: v3(3),
                v: v3(6),
            }
        } else if implicit == F::N {
            RawPlane::Implicit {
                n: v3(9),
                d: row(12),
            }
        } else {
            let mixed = MixedPlanes {
                o: v3(0),
                u: v3(3),
                v: v3(6),
                n: v3(9),
                d: row(12),
                implicit: row(13).equal(F::splat(1.0)),
            };
            RawPlane::Mixed(mixed, F::group())
        }
    }
}

/// The scales of a parametric plane (see [`RawPlane::scales`]).
#[inline(always)]
fn param_scales<F: Lane>(o: &V3<F>, u: &V3<F>, v: &V3<F>, mp: F) -> (F, F, F) {
    let m = scale_of(u).max(scale_of(v));
    (m, m * m, mp.max(scale_of(o)))
}

/// The scales of an implicit plane (see [`RawPlane::scales`]).
#[inline(always)]
fn implicit_scales<F: Lane>(n: &V3<F>, d: F, mp: F) -> (F, F, F) {
    let m = scale_of(n);
    (m, m, extend_scale_of(mp, d, m))
}

impl<F: Lane> MixedPlanes<F> {
    /// Each lane's scales of its kind (see [`RawPlane::scales`]).
    #[inline(always)]
    pub(crate) fn scales(&self, mp: F) -> (F, F, F) {
        let p = param_scales(&self.o, &self.u, &self.v, mp);
        let i = implicit_scales(&self.n, self.d, mp);
        let m = self.implicit;
        (
            F::select(m, i.0, p.0),
            F::select(m, i.1, p.1),
            F::select(m, i.2, p.2),
        )
    }
    /// [`PlaneData::General`], with each lane's normal of its kind.
    #[inline(always)]
    pub(crate) fn data<M: ProductMode>(&self) -> PlaneData<Dd<M, F>> {
        let (u, v, n) = (lift3(&self.u), lift3(&self.v), lift3::<M, F>(&self.n));
        let uv = cross3(&u, &v);
        PlaneData::General {
            o: lift3(&self.o),
            n: each!(k in [0, 1, 2] => Dd::select(self.implicit, &n[k], &uv[k])),
            u,
            v,
            d: Dd::exact(self.d),
        }
    }
}

impl<F: Lane> RawPlane<F> {
    /// The filter scales of a plane: `(m_G, m_G^k)` (`k = 2` parametric, `1` implicit)
    /// and the position scale `mp` extended by its origin (parametric) or by `|d|/m_n`
    /// (implicit: `d` is in the units of normal × position); mixed lanes take their
    /// kind's.
    #[inline(always)]
    pub(crate) fn scales(&self, mp: F) -> (F, F, F) {
        match self {
            RawPlane::Param { o, u, v } => param_scales(o, u, v, mp),
            RawPlane::Implicit { n, d } => implicit_scales(n, *d, mp),
            RawPlane::Mixed(m, _) => m.scales(mp),
        }
    }
    /// The lanes holding an implicit plane.
    #[inline(always)]
    pub(crate) fn implicit_lanes(&self) -> F::Mask {
        let (zero, one) = (F::splat(0.0), F::splat(1.0));
        match self {
            RawPlane::Param { .. } => one.less(zero),
            RawPlane::Implicit { .. } => zero.less(one),
            RawPlane::Mixed(m, _) => m.implicit,
        }
    }
    /// True for planes of mixed kinds.
    #[inline(always)]
    pub(crate) fn is_mixed(&self) -> bool {
        matches!(self, RawPlane::Mixed(..))
    }
    /// The plane in double-double with its normal (`u × v` or the given normal; mixed
    /// lanes: [`PlaneData::General`], each lane's normal of its kind).
    #[inline(always)]
    pub(crate) fn data<M: ProductMode>(&self) -> PlaneData<Dd<M, F>> {
        match self {
            RawPlane::Param { o, u, v } => PlaneData::parametric(lift3(o), lift3(u), lift3(v)),
            RawPlane::Implicit { n, d } => PlaneData::Implicit {
                n: lift3(n),
                d: Dd::exact(*d),
            },
            RawPlane::Mixed(m, _) => m.data(),
        }
    }
}

#[cfg(test)]
impl MixedPlanes<f64> {
    /// One plane as a lane of a mixed group (its kind's fields, the other kind's zero),
    /// for the tests that mixed lanes compute the values of each lane's kind.
    pub(crate) fn of(p: &Plane<f64>) -> Self {
        let zero = [0.0; 3];
        match RawPlane::new(p) {
            RawPlane::Param { o, u, v } => MixedPlanes {
                o,
                u,
                v,
                n: zero,
                d: 0.0,
                implicit: false,
            },
            RawPlane::Implicit { n, d } => MixedPlanes {
                o: zero,
                u: zero,
                v: zero,
                n,
                d,
                implicit: true,
            },
        }
    }
}

#[cfg(test)]
impl MixedLines<f64> {
    /// One line or segment as a lane of a mixed group, for the tests that mixed lanes
    /// compute the values of each lane's kind.
    pub(crate) fn of(l: Linear<f64>) -> Self {
        let zero = [0.0; 3];
        match RawLine::new(l) {
            RawLine::Line { o, d } => MixedLines {
                o,
                d,
                b: zero,
                segment: false,
            },
            RawLine::Segment { a, b } => MixedLines {
                o: a,
                d: zero,
                b,
                segment: true,
            },
        }
    }
}
