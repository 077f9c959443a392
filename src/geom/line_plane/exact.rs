//! The exact core of line ∩ plane (OPERATIONS.md §5.1, module doc of [`super`]): the
//! polynomials written once, generic over the ring (f64, double-double lanes, the exact
//! rings, rationals), the decision procedure, and the exact tiers (128-bit and 768-bit
//! integers, expansions, rationals) with their rounding.

use nalgebra::{Vector2, Vector3};
use rug::Rational;

use super::{LinePlane, LinePlanePoint};
use crate::certificate::Certified;
use crate::geom::data::{LineData, Linear, PlaneData};
use crate::geom::exact_tier::{ring_tier, ExactRing, Rounder, SmallInteger, WideInteger};
use crate::geom::objects::Plane;
use crate::num::expansion::Expansion;
use crate::num::ratio::Ratio;
use crate::num::ring::{cross3, dot3, each, sub3, Field, Ring, V2, V3};
use crate::num::round::Rounded;

/// The polynomials of the operation (written once for every ring).
pub(crate) struct Terms<R> {
    /// `N·c'`: the common denominator.
    pub den: R,
    /// `f(c₀)`.
    pub f0: R,
    /// Numerators of the point: `c₀ (N·c') − f(c₀) c'`.
    pub pnum: V3<R>,
    /// Numerators of `(u, v)`: `det(w, s₂, c')`, `det(s₁, w, c')`.
    pub uvnum: Option<V2<R>>,
}

#[cfg(test)] // the filter-constant tests; the kernel calls `terms_from` after its decision
#[inline(always)]
pub(crate) fn terms<R: Ring>(l: &LineData<R>, p: &PlaneData<R>) -> Terms<R> {
    let den = dot3(p.n(), &l.d);
    let f0 = p.value_at(&l.o);
    terms_from(l, p, den, f0)
}

/// The numerators given `N·c'` and `f(c₀)`.
#[inline(always)]
pub(crate) fn terms_from<R: Ring>(l: &LineData<R>, p: &PlaneData<R>, den: R, f0: R) -> Terms<R> {
    let pnum = each!(i in [0, 1, 2] => l.o[i].times(&den).minus(&f0.times(&l.d[i])));
    let uvnum = match p {
        PlaneData::Param { o, u, v, .. } | PlaneData::General { o, u, v, .. } => {
            let w = sub3(&l.o, o);
            // det(w, s₂, c') = w·(s₂ × c'), det(s₁, w, c') = w·(c' × s₁): the cross
            // products of inputs are exact products, one rounding each.
            Some([dot3(&w, &cross3(v, &l.d)), dot3(&w, &cross3(&l.d, u))])
        }
        PlaneData::Implicit { .. } => None,
    };
    Terms {
        den,
        f0,
        pnum,
        uvnum,
    }
}

/// The exact decision procedure, generic over the field (`f64`: plain; `Rational`: exact).
pub(crate) fn core<R: Field>(l: &LineData<R>, p: &PlaneData<R>) -> LinePlane<R> {
    let den = dot3(p.n(), &l.d);
    let f0 = p.value_at(&l.o);
    if den.is_zero() {
        return if f0.is_zero() {
            LinePlane::Contained
        } else {
            LinePlane::Parallel
        };
    }
    let tm = terms_from(l, p, den, f0);
    let t = tm.f0.negate().divide(&tm.den);
    let inside = l.contains(&t);
    let [x, y, z] = tm.pnum.map(|q| q.divide(&tm.den));
    let point = LinePlanePoint {
        point: Vector3::new(x, y, z),
        t,
        uv: tm
            .uvnum
            .map(|[u, v]| Vector2::new(u.divide(&tm.den), v.divide(&tm.den))),
    };
    if inside {
        LinePlane::Point(point)
    } else {
        LinePlane::OutsideDomain(point)
    }
}

/// The exact tiers in order of cost: 128-bit integers, 768-bit integers, expansions,
/// rationals (which always answer). Out of line, so that the filter's caller keeps a
/// small stack frame.
#[cold]
#[inline(never)]
pub(super) fn exact_tiers(line: Linear<f64>, plane: &Plane<f64>) -> Certified<LinePlane<Rounded>> {
    ring_tier_answer::<SmallInteger>(line, plane)
        .or_else(|| ring_tier_answer::<WideInteger>(line, plane))
        .or_else(|| ring_tier_answer::<Expansion>(line, plane))
        .unwrap_or_else(|| rational_tier(line, plane))
}

/// The last tier, in `rug::Rational`.
#[inline(never)]
pub(super) fn rational_tier(
    line: Linear<f64>,
    plane: &Plane<f64>,
) -> Certified<LinePlane<Rounded>> {
    let l: LineData<Rational> = line.data();
    let p: PlaneData<Rational> = PlaneData::new(plane);
    let mut rounder = Rounder::default();
    let r = core(&l, &p).map(|q| rounder.round(q));
    rounder.certify(r)
}

/// The exact decision in the ring `E` ([`ring_tier`]): `None` when `E` lost exactness.
#[inline(always)]
pub(super) fn ring_tier_answer<E: ExactRing>(
    line: Linear<f64>,
    plane: &Plane<f64>,
) -> Option<Certified<LinePlane<Rounded>>> {
    ring_tier::<E, _>(|r| {
        let l: LineData<Ratio<E>> = line.data();
        core(&l, &PlaneData::new(plane)).map(|q| r.round(q))
    })
}
