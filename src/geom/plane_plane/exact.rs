//! The exact core of plane ∩ plane (OPERATIONS.md §8, module doc of
//! [`super`]): the polynomials written once, generic over the ring (f64, double-double
//! lanes, the exact rings, rationals), the decision procedure, and the exact tiers
//! (128-bit and 768-bit integers, expansions, rationals) with their rounding.

use nalgebra::{Vector2, Vector3};
use rug::Rational;

use super::{ParamLine, PlaneLine, PlanePlane};
use crate::certificate::Certified;
use crate::geom::data::PlaneData;
use crate::geom::exact_tier::{
    ring_tier, ExactRing, RingRounder, Rounder, SmallInteger, WideInteger,
};
use crate::geom::objects::Plane;
use crate::num::expansion::Expansion;
use crate::num::ratio::Ratio;
use crate::num::ring::{cross3, dot3, each, is_zero3, scale3, sub3, Field, Ring, V2, V3};
use crate::num::round::{exponent_of, Rounded};

/// Numerators (over `|n|²`) of a point's parameters and the direction's parameters.
pub(crate) struct ParamTerms<R> {
    pub num: V2<R>,
    pub dir: V2<R>,
}

/// The polynomials of the operation.
pub(crate) struct Terms<R> {
    pub n: V3<R>,
    pub nn: R,
    pub pnum: V3<R>,
    pub on_a: Option<ParamTerms<R>>,
    pub on_b: Option<ParamTerms<R>>,
}

/// The reference point `x_r` (see the module documentation).
pub(crate) fn reference<R: Ring>(a: &PlaneData<R>, b: &PlaneData<R>) -> V3<R> {
    b.origin()
        .or(a.origin())
        .cloned()
        .unwrap_or_else(|| [R::zero(), R::zero(), R::zero()])
}

/// How a parameter line on plane `q` (origin `o`) finds `e = −f_other(o)` and
/// `g = n·(x_r − o)`.
pub(super) enum AtOrigin<'a, R> {
    /// `x_r = o`: `g = 0`, and `f_other(x_r)` is known.
    Known(&'a R),
    /// The other plane's origin is `x_r`: `−f_other(o) = N_o·(x_r − o)`, one
    /// difference serves `e` and `g`.
    OtherAtReference,
    /// Mixed lanes ([`terms_mixed`]): `e` and `g` from their definitions, which in each
    /// lane is the value one of the other two computes (in `Known` lanes `g` is an exact
    /// zero; in `OtherAtReference` lanes `f_other(o) = N_o·(o − x_r)`, whose
    /// differences of doubles and products are the exact negations).
    Any,
}

// (by hand: derived, they would ask `R: Copy`)
impl<R> Clone for AtOrigin<'_, R> {
    fn clone(&self) -> Self {
        *self
    }
}
impl<R> Copy for AtOrigin<'_, R> {}

impl<'a, R> AtOrigin<'a, R> {
    /// In [`terms_from`]: `Known` when `x_r = o` (`f`: the other plane's value there),
    /// else `OtherAtReference` (a parametric plane without its origin at `x_r` has the
    /// other's there).
    #[inline(always)]
    fn of(here: bool, f: &'a R) -> Self {
        if here {
            AtOrigin::Known(f)
        } else {
            AtOrigin::OtherAtReference
        }
    }
}

/// Parameters on parametric plane `q` of the line of `q ∩ other`, with `n = N_q × N_o`
/// when `on_a` (`q` is plane `a`), `n = N_o × N_q` otherwise.
#[inline(always)]
pub(super) fn param_terms<R: Ring>(
    q: &PlaneData<R>,
    other: &PlaneData<R>,
    n: &V3<R>,
    x_r: &V3<R>,
    on_a: bool,
    at: AtOrigin<R>,
) -> Option<ParamTerms<R>> {
    let (PlaneData::Param { o, u, v, .. } | PlaneData::General { o, u, v, .. }) = q else {
        return None;
    };
    let no = other.n();
    let (nu, nv) = (dot3(no, u), dot3(no, v));
    let (n_u, n_v) = (dot3(n, u), dot3(n, v));
    let (e, g) = match at {
        AtOrigin::Known(f) => (f.negate(), None),
        AtOrigin::OtherAtReference => {
            let w = sub3(x_r, o);
            (dot3(no, &w), Some(dot3(n, &w)))
        }
        AtOrigin::Any => (other.value_at(o).negate(), Some(dot3(n, &sub3(x_r, o)))),
    };
    let (un, vn) = match g {
        None => (e.times(&n_v), e.times(&n_u).negate()),
        Some(g) => (
            e.times(&n_v).minus(&nv.times(&g)),
            nu.times(&g).minus(&e.times(&n_u)),
        ),
    };
    Some(if on_a {
        ParamTerms {
            num: [un, vn],
            dir: [nv.negate(), nu],
        }
    } else {
        ParamTerms {
            num: [un.negate(), vn.negate()],
            dir: [nv, nu.negate()],
        }
    })
}

#[cfg(test)] // the filter-constant tests; the kernel calls `terms_from` with its `n`
#[inline(always)]
pub(crate) fn terms<R: Ring>(a: &PlaneData<R>, b: &PlaneData<R>) -> Terms<R> {
    let n = cross3(a.n(), b.n());
    let nn = dot3(&n, &n);
    terms_from(a, b, n, nn)
}

/// The line's numerators given its direction `n = N_a × N_b` and `|n|²`.
#[inline(always)]
pub(crate) fn terms_from<R: Ring>(a: &PlaneData<R>, b: &PlaneData<R>, n: V3<R>, nn: R) -> Terms<R> {
    let x_r = reference(a, b);
    // The plane whose origin is x_r vanishes there: its term of the point is left out,
    // and its parameters reuse the other plane's value at x_r.
    let at_b = b.origin().is_some();
    let at_a = !at_b && a.origin().is_some();
    let fa = if at_a { R::zero() } else { a.value_at(&x_r) };
    let fb = if at_b { R::zero() } else { b.value_at(&x_r) };
    let (on_a, on_b) = (AtOrigin::of(at_a, &fb), AtOrigin::of(at_b, &fa));
    terms_at(a, b, n, nn, &x_r, [&fa, &fb], [at_a, at_b], [on_a, on_b])
}

/// The numerators from the reference point `x_r` and `[f_a(x_r), f_b(x_r)]`; `skip`
/// marks the plane whose origin is `x_r` (left out of the point), `at` how each
/// parameter line finds its values.
#[allow(clippy::too_many_arguments)]
#[inline(always)]
pub(super) fn terms_at<R: Ring>(
    a: &PlaneData<R>,
    b: &PlaneData<R>,
    n: V3<R>,
    nn: R,
    x_r: &V3<R>,
    [fa, fb]: [&R; 2],
    skip: [bool; 2],
    at: [AtOrigin<R>; 2],
) -> Terms<R> {
    let ta = (!skip[0]).then(|| cross3(b.n(), &n));
    let tb = (!skip[1]).then(|| cross3(&n, a.n()));
    let pnum = each!(i in [0, 1, 2] => {
        let mut acc = x_r[i].times(&nn);
        if let Some(ta) = &ta {
            acc = acc.minus(&fa.times(&ta[i]));
        }
        if let Some(tb) = &tb {
            acc = acc.minus(&fb.times(&tb[i]));
        }
        acc
    });
    let on_a = param_terms(a, b, &n, x_r, true, at[0]);
    let on_b = param_terms(b, a, &n, x_r, false, at[1]);
    Terms {
        n,
        nn,
        pnum,
        on_a,
        on_b,
    }
}

/// The exact decision procedure, generic over the field.
pub(crate) fn core<R: Field>(a: &PlaneData<R>, b: &PlaneData<R>) -> PlanePlane<R> {
    let n = cross3(a.n(), b.n());
    if is_zero3(&n) {
        return if coincide_parallel(a, b) {
            PlanePlane::Coincident
        } else {
            PlanePlane::Parallel
        };
    }
    let nn = dot3(&n, &n);
    PlanePlane::Line(finish(terms_from(a, b, n, nn)))
}

/// Whether two planes with parallel normals (`N_a × N_b = 0`) are the same plane: they
/// are iff they share one point, so when one of them has an origin the test is that
/// the other vanishes there (`f_a(o_b) = 0`, degree 3), otherwise (two implicit planes
/// `N·x = h`) that `h_a N_b = h_b N_a`.
pub(crate) fn coincide_parallel<R: Field>(a: &PlaneData<R>, b: &PlaneData<R>) -> bool {
    match (a.origin(), b.origin()) {
        (_, Some(o)) => a.value_at(o).is_zero(),
        (Some(o), None) => b.value_at(o).is_zero(),
        (None, None) => is_zero3(&sub3(
            &scale3(&a.offset(), b.n()),
            &scale3(&b.offset(), a.n()),
        )),
    }
}

/// The line from its polynomials (the divisions by `|n|²`).
pub(crate) fn finish<R: Field>(tm: Terms<R>) -> PlaneLine<R> {
    let nn = tm.nn;
    let div = |q: &R| q.divide(&nn);
    let pl = |p: ParamTerms<R>| ParamLine {
        origin: Vector2::new(div(&p.num[0]), div(&p.num[1])),
        dir: Vector2::from(p.dir),
    };
    PlaneLine {
        point: Vector3::new(div(&tm.pnum[0]), div(&tm.pnum[1]), div(&tm.pnum[2])),
        dir: Vector3::from(tm.n),
        dir_exponent: 0,
        on_a: tm.on_a.map(pl),
        on_b: tm.on_b.map(pl),
    }
}

/// The scale exponent of a direction (see [`PlaneLine`]), from its exact components.
pub(crate) fn dir_exponent(dir: &[Rational]) -> i32 {
    let e = dir.iter().filter_map(exponent_of).max().unwrap_or(0);
    if (-1000..1000).contains(&e) {
        0
    } else {
        -(e as i32)
    }
}

/// Round an exact plane line, scaling its directions (see [`PlaneLine`]).
pub(crate) fn round_line(l: PlaneLine<Rational>, r: &mut Rounder) -> PlaneLine<Rounded> {
    let k = dir_exponent(l.dir.as_slice());
    let pl = |p: ParamLine<Rational>, r: &mut Rounder| ParamLine {
        origin: p.origin.map(|x| r.round(x)),
        dir: p.dir.map(|x| r.round_scaled(x, k)),
    };
    PlaneLine {
        point: l.point.map(|x| r.round(x)),
        dir: l.dir.map(|x| r.round_scaled(x, k)),
        dir_exponent: k,
        on_a: l.on_a.map(|p| pl(p, r)),
        on_b: l.on_b.map(|p| pl(p, r)),
    }
}

/// Round an exact plane line from an exact-ring tier (unscaled directions only).
pub(crate) fn round_line_ring<E: ExactRing>(
    l: PlaneLine<Ratio<E>>,
    r: &mut RingRounder<E>,
) -> PlaneLine<Rounded> {
    r.check_unscaled(l.dir.as_slice());
    l.map(|x| r.round(x))
}

/// The exact decision in the ring `E` ([`ring_tier`]): `None` when `E` lost exactness.
#[inline(always)]
pub(super) fn ring_tier_answer<E: ExactRing>(
    a: &Plane<f64>,
    b: &Plane<f64>,
) -> Option<Certified<PlanePlane<Rounded>>> {
    ring_tier::<E, _>(
        |r| match core::<Ratio<E>>(&PlaneData::new(a), &PlaneData::new(b)) {
            PlanePlane::Line(l) => PlanePlane::Line(round_line_ring(l, r)),
            PlanePlane::Parallel => PlanePlane::Parallel,
            PlanePlane::Coincident => PlanePlane::Coincident,
        },
    )
}

/// The exact tiers in order of cost: 128-bit integers, 768-bit integers, expansions,
/// rationals (which always answer). Out of line, so that the filter's caller keeps a
/// small stack frame.
#[cold]
#[inline(never)]
pub(super) fn exact_tiers(a: &Plane<f64>, b: &Plane<f64>) -> Certified<PlanePlane<Rounded>> {
    ring_tier_answer::<SmallInteger>(a, b)
        .or_else(|| ring_tier_answer::<WideInteger>(a, b))
        .or_else(|| ring_tier_answer::<Expansion>(a, b))
        .unwrap_or_else(|| rational_tier(a, b))
}

/// The last tier, in `rug::Rational`.
#[inline(never)]
pub(super) fn rational_tier(a: &Plane<f64>, b: &Plane<f64>) -> Certified<PlanePlane<Rounded>> {
    let mut r = Rounder::default();
    let res = match core::<Rational>(&PlaneData::new(a), &PlaneData::new(b)) {
        PlanePlane::Line(l) => PlanePlane::Line(round_line(l, &mut r)),
        PlanePlane::Parallel => PlanePlane::Parallel,
        PlanePlane::Coincident => PlanePlane::Coincident,
    };
    r.certify(res)
}
