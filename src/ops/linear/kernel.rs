//! The two linear kernels behind one interface ([`Kernel`]): certified on doubles
//! (exact verdict, correctly rounded output, [`crate::geom`]) and exact on rationals.
//! Both return numbers as [`Q`]: correctly rounded with an enclosure, and the exact
//! rational when the caller asked for it.

use std::cell::Cell;

use nalgebra::Vector3;
use rug::Rational;

use crate::certificate::{Arithmetic, Certified};
use crate::geom::line_line::{self, LineLine};
use crate::geom::line_plane::{self, LinePlane};
use crate::geom::lines2::{self, Intersection2};
use crate::geom::plane_plane::{self, dir_exponent, PlaneLine, PlanePlane};
use crate::geom::project::{self, ExactLength, LineFoot, LineProjection, PlaneProjection};
use crate::geom::three_planes::{self, ThreePlanes};
use crate::geom::{Coord, Linear, Linear2, Plane};
use crate::num::round::{round_rational, scale_pow2, Rounded};

/// An output number: the correctly rounded value with its enclosure, and the exact
/// rational when asked for.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Q {
    pub r: Rounded,
    pub exact: Option<Rational>,
}

impl From<Rounded> for Q {
    fn from(r: Rounded) -> Q {
        Q { r, exact: None }
    }
}

impl Q {
    /// An exact rational, rounded; kept when `keep`.
    pub fn rational(q: &Rational, keep: bool) -> Q {
        Q {
            r: round_rational(q),
            exact: keep.then(|| q.clone()),
        }
    }
    pub fn bounds(&self) -> [f64; 2] {
        [self.r.lo, self.r.hi]
    }
}

/// A distance: correctly rounded, and the exact square on request.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Len {
    pub value: Rounded,
    pub squared: Option<Rational>,
}

impl From<Rounded> for Len {
    fn from(value: Rounded) -> Len {
        Len {
            value,
            squared: None,
        }
    }
}

impl Len {
    fn exact(l: ExactLength, keep: bool) -> Len {
        Len {
            value: l.rounded,
            squared: keep.then_some(l.squared),
        }
    }
}

/// The two kernels behind one interface: certified on doubles, exact on rationals.
pub(crate) trait Kernel: Coord {
    fn line_plane(l: Linear<'_, Self>, p: &Plane<Self>, keep: bool) -> Certified<LinePlane<Q>>;
    fn line_line(a: Linear<'_, Self>, b: Linear<'_, Self>, keep: bool) -> Certified<LineLine<Q>>;
    fn plane_plane(a: &Plane<Self>, b: &Plane<Self>, keep: bool) -> Certified<PlanePlane<Q>>;
    fn three_planes(p: &[Plane<Self>; 3], keep: bool) -> Certified<ThreePlanes<Q>>;
    fn lines2(
        a: Linear2<'_, Self>,
        b: Linear2<'_, Self>,
        keep: bool,
    ) -> Certified<Intersection2<Q>>;
    fn project_line(
        p: &Vector3<Self>,
        l: Linear<'_, Self>,
        keep: bool,
    ) -> Certified<LineProjection<Q, Len>>;
    fn project_plane(
        p: &Vector3<Self>,
        plane: &Plane<Self>,
        keep: bool,
    ) -> Certified<PlaneProjection<Q, Len>>;
}

fn map_line_projection<S: nalgebra::Scalar, L, S2: nalgebra::Scalar, L2>(
    v: LineProjection<S, L>,
    mut s: impl FnMut(S) -> S2,
    mut l: impl FnMut(L) -> L2,
) -> LineProjection<S2, L2> {
    let mut foot = |f: LineFoot<S, L>| LineFoot {
        foot: f.foot.map(&mut s),
        t: s(f.t),
        distance: l(f.distance),
    };
    LineProjection {
        stationary: v.stationary.map(&mut foot),
        nearest: foot(v.nearest),
    }
}

fn map_plane_projection<S: nalgebra::Scalar, L, S2: nalgebra::Scalar, L2>(
    v: PlaneProjection<S, L>,
    mut s: impl FnMut(S) -> S2,
    l: impl FnOnce(L) -> L2,
) -> PlaneProjection<S2, L2> {
    PlaneProjection {
        foot: v.foot.map(&mut s),
        uv: v.uv.map(|uv| uv.map(&mut s)),
        distance: l(v.distance),
    }
}

impl Kernel for f64 {
    fn line_plane(l: Linear<'_, f64>, p: &Plane<f64>, _: bool) -> Certified<LinePlane<Q>> {
        line_plane::intersect_line_plane(l, p).map(|v| v.map(Q::from))
    }
    fn line_line(a: Linear<'_, f64>, b: Linear<'_, f64>, _: bool) -> Certified<LineLine<Q>> {
        line_line::intersect_line_line(a, b).map(|v| v.map(Q::from))
    }
    fn plane_plane(a: &Plane<f64>, b: &Plane<f64>, _: bool) -> Certified<PlanePlane<Q>> {
        plane_plane::intersect_plane_plane(a, b).map(|v| v.map(Q::from))
    }
    fn three_planes(p: &[Plane<f64>; 3], _: bool) -> Certified<ThreePlanes<Q>> {
        three_planes::intersect_three_planes(p).map(|v| v.map(Q::from))
    }
    fn lines2(a: Linear2<'_, f64>, b: Linear2<'_, f64>, _: bool) -> Certified<Intersection2<Q>> {
        lines2::intersect_line2_line2(a, b).map(|v| v.map(Q::from))
    }
    fn project_line(
        p: &Vector3<f64>,
        l: Linear<'_, f64>,
        _: bool,
    ) -> Certified<LineProjection<Q, Len>> {
        project::project_point_line(p, l).map(|v| map_line_projection(v, Q::from, Len::from))
    }
    fn project_plane(
        p: &Vector3<f64>,
        plane: &Plane<f64>,
        _: bool,
    ) -> Certified<PlaneProjection<Q, Len>> {
        project::project_point_plane(p, plane).map(|v| map_plane_projection(v, Q::from, Len::from))
    }
}

/// Rounds exact results and records the largest bit length seen (the `bits` of a
/// rational answer: docs/CERTIFICATES.md "Escalation", the bit length of the largest
/// numerator or denominator).
struct ExactRounder {
    keep: bool,
    bits: Cell<u32>,
}

impl ExactRounder {
    fn new(keep: bool) -> Self {
        ExactRounder {
            keep,
            bits: Cell::new(53),
        }
    }
    fn q(&self, x: Rational) -> Q {
        let b = x
            .numer()
            .significant_bits()
            .max(x.denom().significant_bits());
        self.bits.set(self.bits.get().max(b));
        Q::rational(&x, self.keep)
    }
    fn done<T>(self, value: T) -> Certified<T> {
        Certified::exact(value, Arithmetic::Rational, self.bits.get())
    }
    /// A plane line whose direction (and parameter directions) are scaled by a power
    /// of two so that they round to finite normal doubles (as the certified path does).
    fn line(&self, l: PlaneLine<Rational>) -> PlaneLine<Q> {
        let k = dir_exponent(l.dir.as_slice());
        let scaled = |x: Rational| self.q(scale_pow2(&x, k));
        let param = |p: plane_plane::ParamLine<Rational>| plane_plane::ParamLine {
            origin: p.origin.map(|x| self.q(x)),
            dir: p.dir.map(scaled),
        };
        PlaneLine {
            point: l.point.map(|x| self.q(x)),
            dir: l.dir.map(scaled),
            dir_exponent: k,
            on_a: l.on_a.map(param),
            on_b: l.on_b.map(param),
        }
    }
}

impl Kernel for Rational {
    fn line_plane(
        l: Linear<'_, Rational>,
        p: &Plane<Rational>,
        keep: bool,
    ) -> Certified<LinePlane<Q>> {
        let r = ExactRounder::new(keep);
        let v = line_plane::intersect_line_plane_exact(l, p).map(|x| r.q(x));
        r.done(v)
    }
    fn line_line(
        a: Linear<'_, Rational>,
        b: Linear<'_, Rational>,
        keep: bool,
    ) -> Certified<LineLine<Q>> {
        let r = ExactRounder::new(keep);
        let v = line_line::intersect_line_line_exact(a, b).map(|x| r.q(x));
        r.done(v)
    }
    fn plane_plane(
        a: &Plane<Rational>,
        b: &Plane<Rational>,
        keep: bool,
    ) -> Certified<PlanePlane<Q>> {
        let r = ExactRounder::new(keep);
        let v = match plane_plane::intersect_plane_plane_exact(a, b) {
            PlanePlane::Line(l) => PlanePlane::Line(r.line(l)),
            PlanePlane::Parallel => PlanePlane::Parallel,
            PlanePlane::Coincident => PlanePlane::Coincident,
        };
        r.done(v)
    }
    fn three_planes(p: &[Plane<Rational>; 3], keep: bool) -> Certified<ThreePlanes<Q>> {
        let r = ExactRounder::new(keep);
        let v = match three_planes::intersect_three_planes_exact(p) {
            ThreePlanes::Line { line, pair } => ThreePlanes::Line {
                line: r.line(line),
                pair,
            },
            other => other.map(|x| r.q(x)),
        };
        r.done(v)
    }
    fn lines2(
        a: Linear2<'_, Rational>,
        b: Linear2<'_, Rational>,
        keep: bool,
    ) -> Certified<Intersection2<Q>> {
        let r = ExactRounder::new(keep);
        let v = lines2::intersect_line2_line2_exact(a, b).map(|x| r.q(x));
        r.done(v)
    }
    fn project_line(
        p: &Vector3<Rational>,
        l: Linear<'_, Rational>,
        keep: bool,
    ) -> Certified<LineProjection<Q, Len>> {
        let r = ExactRounder::new(keep);
        let v = map_line_projection(
            project::project_point_line_exact(p, l),
            |x| r.q(x),
            |d| Len::exact(d, keep),
        );
        r.done(v)
    }
    fn project_plane(
        p: &Vector3<Rational>,
        plane: &Plane<Rational>,
        keep: bool,
    ) -> Certified<PlaneProjection<Q, Len>> {
        let r = ExactRounder::new(keep);
        let v = map_plane_projection(
            project::project_point_plane_exact(p, plane),
            |x| r.q(x),
            |d| Len::exact(d, keep),
        );
        r.done(v)
    }
}
