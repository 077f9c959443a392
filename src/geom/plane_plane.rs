//! Plane ∩ plane, OPERATIONS.md §8 with the correction (8.3), unnormalised.
//!
//! With `N_a`, `N_b` the unnormalised normals (`u × v` or the given normal), the
//! direction is `n = N_a × N_b` (eq. (8.1) without the unit normals: its length is
//! `|N_a||N_b| sin θ`, not `sin θ`). The point is (8.3) generalised to any reference
//! point `x_r` (`b`'s origin when `b` is parametric — then it is exactly (8.3) — else
//! `a`'s origin, else the coordinate origin) with `F = f(x_r)` the planes' values there:
//! `p = x_r − (F_a (N_b × n) + F_b (n × N_a))/|n|²`, the projection of `x_r` onto the line.
//!
//! The parameter lines (8.4) on a parametric plane are `l(t) = (u_p, v_p) + t(du, dv)`
//! for the points `p + t n`. `(du, dv)` are the coordinates of `n` in the plane's basis,
//! which simplify exactly (`n × s₂ = N_a(N_b·s₂)`-type identities) to polynomials:
//! on `a`: `(du, dv) = (−N_b·a₂, N_b·a₁)`; on `b`: `(N_a·b₂, −N_a·b₁)`. `(u_p, v_p)` solves
//! `p = a₀ + u a₁ + v a₂` via the two conditions `f_b(p) = 0`, `n·(p − x_r) = 0`, whose
//! determinant is `|n|²`: `u = (e (n·a₂) − (N_b·a₂) g)/|n|²`, `v = ((N_b·a₁) g − e (n·a₁))/|n|²`
//! with `e = −f_b(a₀)`, `g = n·(x_r − a₀)`; on `b` the same with the roles swapped and
//! determinant `−|n|²`.
//!
//! `n = 0` exactly: `Coincident` if the planes share a point (`f_a(o_b) = 0`, or
//! `h_a N_b = h_b N_a` for two implicit planes `N·x = h`), else `Parallel`.

use std::mem::MaybeUninit;

use nalgebra::{Scalar, Vector2, Vector3};
use rug::Rational;

use super::batch::{self, lane_kernel};
use super::data::PlaneData;
use super::exact_tier::{
    filter_certified, ring_tier, ExactRing, RingRounder, Rounder, SmallInteger, WideInteger,
};
use super::objects::Plane;
use super::raw::RawPlane;
use crate::certificate::Certified;
use crate::num::dd::{Dd, ProductMode, U};
use crate::num::expansion::Expansion;
use crate::num::filter::{
    bound, decide_over, decide_value, dispatch_fma, Decided, Denominator, RoundedLanes,
};
use crate::num::lane::{Lane, Wide};
use crate::num::ratio::Ratio;
use crate::num::ring::{cross3, dot3, each, is_zero3, scale3, sub3, Field, Ring, V2, V3};
use crate::num::round::{exponent_of, Rounded};

/// A line in a plane's parameter space: `l(t) = origin + t·dir` (OPERATIONS.md eq. (8.4)).
#[derive(Debug, Clone, PartialEq)]
pub struct ParamLine<S: Scalar> {
    pub origin: Vector2<S>,
    pub dir: Vector2<S>,
}

/// The intersection line `p(t) = point + t·dir` with its parameter lines on each
/// parametric plane (`on_a(t)`, `on_b(t)` are the parameters of `p(t)`).
///
/// `dir = 2^dir_exponent · (N_a × N_b)`, and the parameter-line directions are scaled
/// alike. `dir_exponent` is 0 unless the largest component of `N_a × N_b` lies outside
/// `[2⁻¹⁰⁰⁰, 2¹⁰⁰⁰)`; then it brings that component into `[1, 2)`, so that it rounds
/// to a finite normal double (certified path only: `_f64` and `_exact` use 0).
#[derive(Debug, Clone, PartialEq)]
pub struct PlaneLine<S: Scalar> {
    pub point: Vector3<S>,
    pub dir: Vector3<S>,
    pub dir_exponent: i32,
    pub on_a: Option<ParamLine<S>>,
    pub on_b: Option<ParamLine<S>>,
}

/// The result of plane ∩ plane.
#[derive(Debug, Clone, PartialEq)]
pub enum PlanePlane<S: Scalar> {
    Line(PlaneLine<S>),
    /// Parallel and distinct: empty.
    Parallel,
    /// The same plane.
    Coincident,
}

impl<S: Scalar> ParamLine<S> {
    fn map<T: Scalar>(self, mut f: impl FnMut(S) -> T) -> ParamLine<T> {
        ParamLine {
            origin: self.origin.map(&mut f),
            dir: self.dir.map(&mut f),
        }
    }
}

impl<S: Scalar> PlaneLine<S> {
    /// Apply `f` to every number.
    pub fn map<T: Scalar>(self, mut f: impl FnMut(S) -> T) -> PlaneLine<T> {
        PlaneLine {
            point: self.point.map(&mut f),
            dir: self.dir.map(&mut f),
            dir_exponent: self.dir_exponent,
            on_a: self.on_a.map(|l| l.map(&mut f)),
            on_b: self.on_b.map(|l| l.map(&mut f)),
        }
    }
}

impl<S: Scalar> PlanePlane<S> {
    /// Apply `f` to every number.
    pub fn map<T: Scalar>(self, f: impl FnMut(S) -> T) -> PlanePlane<T> {
        match self {
            PlanePlane::Line(l) => PlanePlane::Line(l.map(f)),
            PlanePlane::Parallel => PlanePlane::Parallel,
            PlanePlane::Coincident => PlanePlane::Coincident,
        }
    }
}

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
enum AtOrigin<'a, R> {
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
fn param_terms<R: Ring>(
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

/// [`terms_from`] for lane groups of mixed kinds (`implicit_b`: the lanes where `b` is
/// implicit): `x_r` lane by lane (`o_b`, else `o_a`, else 0: an implicit lane's origin
/// is zero), both values `f(x_r)` computed — the one of the plane with origin `x_r` is
/// an exact zero, its term changes no value — and the parameters from
/// [`AtOrigin::Any`]. Each lane computes the values of its own shape.
#[inline(always)]
fn terms_mixed<M: ProductMode, F: Lane>(
    a: &PlaneData<Dd<M, F>>,
    b: &PlaneData<Dd<M, F>>,
    n: V3<Dd<M, F>>,
    nn: Dd<M, F>,
    implicit_b: F::Mask,
) -> Terms<Dd<M, F>> {
    let (oa, ob) = (a.origin_or_zero(), b.origin_or_zero());
    let x_r = each!(m in [0, 1, 2] => Dd::select(implicit_b, &oa[m], &ob[m]));
    let (fa, fb) = (a.value_at(&x_r), b.value_at(&x_r));
    let any = AtOrigin::Any;
    terms_at(a, b, n, nn, &x_r, [&fa, &fb], [false, false], [any, any])
}

/// The numerators from the reference point `x_r` and `[f_a(x_r), f_b(x_r)]`; `skip`
/// marks the plane whose origin is `x_r` (left out of the point), `at` how each
/// parameter line finds its values.
#[allow(clippy::too_many_arguments)]
#[inline(always)]
fn terms_at<R: Ring>(
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

/// Plain f64 (uncertified; `n == 0.0` decides parallelism).
pub fn intersect_plane_plane_f64(a: &Plane<f64>, b: &Plane<f64>) -> PlanePlane<f64> {
    core::<f64>(&PlaneData::new(a), &PlaneData::new(b))
}

/// Exact, on rational inputs.
pub fn intersect_plane_plane_exact(
    a: &Plane<Rational>,
    b: &Plane<Rational>,
) -> PlanePlane<Rational> {
    core::<Rational>(&PlaneData::new(a), &PlaneData::new(b))
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
fn ring_tier_answer<E: ExactRing>(
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

/// Certified: exact verdict, correctly rounded point, direction and parameter lines.
pub fn intersect_plane_plane(a: &Plane<f64>, b: &Plane<f64>) -> Certified<PlanePlane<Rounded>> {
    dispatch_fma!(certified(a: &Plane<f64>, b: &Plane<f64>) -> Certified<PlanePlane<Rounded>>)
}

/// The filter, then the exact tiers (instantiated once per product mode, so that the
/// answer is built in place).
#[inline(always)]
fn certified<M: ProductMode>(a: &Plane<f64>, b: &Plane<f64>) -> Certified<PlanePlane<Rounded>> {
    match fast::<M>(a, b) {
        Some(l) => filter_certified(PlanePlane::Line(l)),
        None => exact_tiers(a, b),
    }
}

/// The exact tiers in order of cost: 128-bit integers, 768-bit integers, expansions,
/// rationals (which always answer). Out of line, so that the filter's caller keeps a
/// small stack frame.
#[cold]
#[inline(never)]
fn exact_tiers(a: &Plane<f64>, b: &Plane<f64>) -> Certified<PlanePlane<Rounded>> {
    ring_tier_answer::<SmallInteger>(a, b)
        .or_else(|| ring_tier_answer::<WideInteger>(a, b))
        .or_else(|| ring_tier_answer::<Expansion>(a, b))
        .unwrap_or_else(|| rational_tier(a, b))
}

/// The last tier, in `rug::Rational`.
#[inline(never)]
fn rational_tier(a: &Plane<f64>, b: &Plane<f64>) -> Certified<PlanePlane<Rounded>> {
    let mut r = Rounder::default();
    let res = match core::<Rational>(&PlaneData::new(a), &PlaneData::new(b)) {
        PlanePlane::Line(l) => PlanePlane::Line(round_line(l, &mut r)),
        PlanePlane::Parallel => PlanePlane::Parallel,
        PlanePlane::Coincident => PlanePlane::Coincident,
    };
    r.certify(res)
}

/// Filter constants (`k·u²`), re-derived by `tests::filter_constants` with
/// [`crate::num::error_bound::ErrorBound`] over all four kind combinations (rules as in
/// `line_plane`): `n` (degree 4), `|n|²` (8), point numerators (9), parameter
/// numerators (8), parameter directions (3).
pub(crate) const EPS_N: f64 = 347.0 * U * U;
pub(crate) const EPS_NN: f64 = 37226.0 * U * U;
pub(crate) const EPS_PNUM: f64 = 271491.0 * U * U;
pub(crate) const EPS_PARAM: f64 = 134081.0 * U * U;
pub(crate) const EPS_PDIR: f64 = 173.0 * U * U;

/// The filter's decisions for one case or a lane group: `ok` where `|n|²` and every output
/// were decided.
struct Decisions<F: Lane> {
    ok: F::Mask,
    dir: [Decided<F>; 3],
    point: [Decided<F>; 3],
    on_a: Option<ParamDecisions<F>>,
    on_b: Option<ParamDecisions<F>>,
}

/// A parameter line's decided origin and direction.
struct ParamDecisions<F: Lane> {
    origin: [Decided<F>; 2],
    dir: [Decided<F>; 2],
}

impl ParamDecisions<f64> {
    /// The rounded parameter line (meaningful where decided).
    #[allow(clippy::manual_map)] // `match`, not a closure (see `fast`)
    #[inline(always)]
    fn value(p: Option<Self>) -> Option<ParamLine<Rounded>> {
        match p {
            Some(p) => Some(ParamLine {
                origin: Vector2::new(p.origin[0].value(), p.origin[1].value()),
                dir: Vector2::new(p.dir[0].value(), p.dir[1].value()),
            }),
            None => None,
        }
    }
}

/// The filter tier, written once for one case (`F = f64`) and lane groups (`F4`, `F8`): groups
/// `P` (origins, `|d|/m_n`), `G_a`, `G_b`; degrees (`k = 2` parametric, 1 implicit):
/// `n`: `G_a^ka G_b^kb`; `|n|²`: twice that; point numerators: `P G_a^2ka G_b^2kb`;
/// parameter numerators on `a`: `P G_a^(ka+1) G_b^2kb` (on `b` symmetrically);
/// parameter directions on `a`: `G_a G_b^kb`. The direction `n` is accepted only when
/// its largest component is in `[2⁻⁹⁹⁹, 2⁹⁹⁹)` (else the exact tiers scale it).
/// `MIXED`: a plane is [`RawPlane::Mixed`] (the numerators from [`terms_mixed`], which
/// computes each lane's shape's values, so the same bounds hold); a constant, so that
/// the uniform groups and the scalar path are compiled without that branch.
#[inline(always)]
fn decide<M: ProductMode, F: Lane, const MIXED: bool>(
    a: &RawPlane<F>,
    b: &RawPlane<F>,
) -> Option<Decisions<F>> {
    let (ma, ka, mp) = a.scales(F::splat(SCALE_FLOOR));
    let (mb, kb, mp) = b.scales(mp);
    let (pa, pb) = (a.data::<M>(), b.data::<M>());
    // The decision: preparing |n|² proves n ≠ 0.
    let n = cross3(pa.n(), pb.n());
    let nn2 = dot3(&n, &n);
    let (mut ok, nn) = Denominator::prepare(&nn2, bound(EPS_NN, &[ka, ka, kb, kb]));
    // Exactly degenerate (or out-of-range) input leaves here, before the numerators.
    if !F::any(ok) {
        return None;
    }
    let implicit = [a.implicit_lanes(), b.implicit_lanes()];
    let tm = if MIXED {
        terms_mixed(&pa, &pb, n, nn2, implicit[1])
    } else {
        terms_from(&pa, &pb, n, nn2)
    };
    let e_n = bound(EPS_N, &[ka, kb]);
    let dir = each!(i in [0, 1, 2] => decide_value(&tm.n[i], e_n));
    let big = dir[0].c.abs().max(dir[1].c.abs()).max(dir[2].c.abs());
    ok = ok
        & dir[0].ok
        & dir[1].ok
        & dir[2].ok
        & F::splat(DIR_MIN).less_eq(big)
        & big.less(F::splat(DIR_MAX));
    let e_p = bound(EPS_PNUM, &[mp, ka, ka, kb, kb]);
    let point = each!(i in [0, 1, 2] => decide_over(&tm.pnum[i], e_p, &nn));
    ok = ok & point[0].ok & point[1].ok & point[2].ok;
    let on_a = param_line(&tm.on_a, &nn, [mp, ma, ka, kb], implicit[0], &mut ok);
    let on_b = param_line(&tm.on_b, &nn, [mp, mb, kb, ka], implicit[1], &mut ok);
    Some(Decisions {
        ok,
        dir,
        point,
        on_a,
        on_b,
    })
}

/// `2⁻⁹⁹⁹` and `2⁹⁹⁹`: the accepted range of the direction's largest component.
const DIR_MIN: f64 = 1.8665272370064378e-301;
const DIR_MAX: f64 = 5.357543035931337e300;

/// A plane's parameter line (§8 eq. (8.4)), decided (`None`: the plane has no
/// parameters); `ok` is narrowed to the lanes where every part was decided. `scales`
/// are `[m_p, m, k_q, k_o]`: origin scale, this plane's group scale, its degree and the
/// other plane's; in the `implicit` lanes (of a mixed group) the plane has no
/// parameters and `ok` is left as it is.
#[inline(always)]
fn param_line<M: ProductMode, F: Lane>(
    t: &Option<ParamTerms<Dd<M, F>>>,
    nn: &Denominator<M, F>,
    [mp, m, kq, ko]: [F; 4],
    implicit: F::Mask,
    ok: &mut F::Mask,
) -> Option<ParamDecisions<F>> {
    let t = t.as_ref()?;
    let e_num = bound(EPS_PARAM, &[mp, kq, m, ko, ko]);
    let e_dir = bound(EPS_PDIR, &[m, ko]);
    let d = ParamDecisions {
        origin: [
            decide_over(&t.num[0], e_num, nn),
            decide_over(&t.num[1], e_num, nn),
        ],
        dir: [
            decide_value(&t.dir[0], e_dir),
            decide_value(&t.dir[1], e_dir),
        ],
    };
    *ok = *ok & (d.origin[0].ok & d.origin[1].ok & d.dir[0].ok & d.dir[1].ok | implicit);
    Some(d)
}

/// The filter tier for one case.
#[inline(always)]
fn fast<M: ProductMode>(a: &Plane<f64>, b: &Plane<f64>) -> Option<PlaneLine<Rounded>> {
    let dc = decide::<M, f64, false>(&RawPlane::new(a), &RawPlane::new(b))?;
    if !dc.ok {
        return None;
    }
    // (no array `map`: its closure may be compiled out of line)
    let v3 = |[x, y, z]: [Decided<f64>; 3]| Vector3::new(x.value(), y.value(), z.value());
    Some(PlaneLine {
        point: v3(dc.point),
        dir: v3(dc.dir),
        dir_exponent: 0,
        on_a: ParamDecisions::value(dc.on_a),
        on_b: ParamDecisions::value(dc.on_b),
    })
}

/// A parameter line's roundings in lanes.
struct ParamLanes {
    origin: [RoundedLanes; 2],
    dir: [RoundedLanes; 2],
}

impl ParamLanes {
    #[allow(clippy::manual_map)] // `match`, not a closure: see below
    #[inline(always)]
    fn new<F: Wide>(p: &Option<ParamDecisions<F>>) -> Option<ParamLanes> {
        match p {
            Some(p) => Some(ParamLanes {
                origin: [p.origin[0].lanes(), p.origin[1].lanes()],
                dir: [p.dir[0].lanes(), p.dir[1].lanes()],
            }),
            None => None,
        }
    }
    #[inline(always)]
    fn get(&self, i: usize) -> ParamLine<Rounded> {
        ParamLine {
            origin: Vector2::new(self.origin[0].get(i), self.origin[1].get(i)),
            dir: Vector2::new(self.dir[0].get(i), self.dir[1].get(i)),
        }
    }
}

/// A case of the batch entry point.
pub type PlanePlaneCase<'a> = (&'a Plane<f64>, &'a Plane<f64>);

/// The filter tier for `F::N` cases of one shape ([`batch_shape`]) or of mixed shapes
/// in lanes: writes the answers of the decided lanes to `out` (see
/// [`batch::LaneKernel`]).
#[inline(always)]
fn fast_lanes<M: ProductMode, F: Wide>(
    cases: &[PlanePlaneCase],
    idx: &[usize],
    real: usize,
    out: &mut [MaybeUninit<Certified<PlanePlane<Rounded>>>],
) -> u32 {
    let c = |i: usize| cases[idx[i]];
    let (a, b) = (
        RawPlane::<F>::gather(|i| c(i).0),
        RawPlane::<F>::gather(|i| c(i).1),
    );
    // (two instances: the uniform groups' straight-line code stays as it was)
    let dc = if a.is_mixed() || b.is_mixed() {
        decide::<M, F, true>(&a, &b)
    } else {
        decide::<M, F, false>(&a, &b)
    };
    let Some(dc) = dc else {
        return 0;
    };
    let ok = F::bits(dc.ok) & ((1 << real) - 1);
    // (no closures over lanes: they may be compiled without the target features)
    let point = [
        dc.point[0].lanes(),
        dc.point[1].lanes(),
        dc.point[2].lanes(),
    ];
    let dir = [dc.dir[0].lanes(), dc.dir[1].lanes(), dc.dir[2].lanes()];
    let (on_a, on_b) = (ParamLanes::new(&dc.on_a), ParamLanes::new(&dc.on_b));
    for (i, &j) in idx.iter().enumerate().take(real) {
        if ok >> i & 1 == 1 {
            out[j].write(filter_certified(PlanePlane::Line(PlaneLine {
                point: Vector3::new(point[0].get(i), point[1].get(i), point[2].get(i)),
                dir: Vector3::new(dir[0].get(i), dir[1].get(i), dir[2].get(i)),
                dir_exponent: 0,
                // (in a mixed group, only the parametric lanes have parameters)
                on_a: match (&on_a, c(i).0) {
                    (Some(p), Plane::Parametric { .. }) => Some(p.get(i)),
                    _ => None,
                },
                on_b: match (&on_b, c(i).1) {
                    (Some(p), Plane::Parametric { .. }) => Some(p.get(i)),
                    _ => None,
                },
            })));
        }
    }
    ok
}

/// The batch shape: the kinds of the two planes (parametric or implicit), as bits.
fn batch_shape((a, b): &PlanePlaneCase) -> usize {
    let implicit = |q: &Plane<f64>| usize::from(matches!(q, Plane::Implicit { .. }));
    implicit(a) | implicit(b) << 1
}

/// Certified plane ∩ plane for many cases: appends to `out`, in order, exactly the
/// answer [`intersect_plane_plane`] gives for each pair (see `geom::batch`: lane groups
/// through the lane filter, one shape each, then what is left of the shapes mixed).
/// `out` only allocates when it grows.
pub fn intersect_plane_plane_batch(
    cases: &[PlanePlaneCase],
    out: &mut Vec<Certified<PlanePlane<Rounded>>>,
) {
    let lanes = lane_kernel!(fast_lanes, PlanePlaneCase, Certified<PlanePlane<Rounded>>);
    batch::run(
        cases,
        out,
        batch_shape,
        lanes,
        |&(a, b)| intersect_plane_plane(a, b),
        |&(a, b)| exact_tiers(a, b),
    );
}

/// The position scale before any origin is seen.
const SCALE_FLOOR: f64 = crate::num::filter::SCALE_MIN;

/// Worst-case [`crate::num::error_bound::ErrorBound`] inputs for a plane of either kind.
#[cfg(test)]
pub(crate) fn bound_planes() -> [PlaneData<crate::num::error_bound::ErrorBound>; 2] {
    use crate::num::error_bound::ErrorBound;
    let i = ErrorBound::INPUT;
    [
        PlaneData::Param {
            o: [i; 3],
            u: [i; 3],
            v: [i; 3],
            n: cross3(&[i; 3], &[i; 3]),
        },
        PlaneData::Implicit { n: [i; 3], d: i },
    ]
}

/// For `robust`'s tests, which drive it with every robustness generator: the
/// four-lane (AVX) kernel end to end, whatever the CPU's widest — `batch::run` answers
/// `cases` as the scalar path does (nothing to run on a CPU without AVX and FMA).
#[cfg(test)]
pub(crate) fn assert_four_lane_run_equals_scalar(cases: &[PlanePlaneCase]) {
    let lanes = lane_kernel!(
        fast_lanes,
        PlanePlaneCase,
        Certified<PlanePlane<Rounded>>,
        4
    );
    if lanes.is_none() {
        return; // no AVX/FMA
    }
    batch::testing::assert_run_equals_scalar(
        cases,
        batch_shape,
        lanes,
        |&(a, b)| intersect_plane_plane(a, b),
        |&(a, b)| exact_tiers(a, b),
    );
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::num::error_bound::ErrorBound;
    use crate::num::lane::MAX_LANES;

    /// The lane kernel decides a lane group of generic pairs of one shape and writes the scalar
    /// answers; a lane of two parallel planes is left to the scalar path.
    #[test]
    fn lane_kernel_decides_generic_lanes() {
        let planes: Vec<Plane<f64>> = (0..2 * MAX_LANES)
            .map(|i| {
                let s = 0.41 + 1.37 * i as f64;
                // the pair of lane 1 (mod 4) is parallel: planes 2 and 3 (mod 8) share a normal
                let n = if i % 8 == 3 { s - 1.37 } else { s };
                Plane::implicit(Vector3::new(1.7 / n, n, 0.3 - n * 1.37), s).unwrap()
            })
            .collect();
        let cases: Vec<PlanePlaneCase> = (0..MAX_LANES)
            .map(|i| (&planes[2 * i], &planes[2 * i + 1]))
            .collect();
        for kernel in
            batch::test_lane_kernels!(fast_lanes, PlanePlaneCase, Certified<PlanePlane<Rounded>>)
        {
            let w = kernel.width;
            let (bits, out) =
                batch::testing::run_once(&kernel, &cases, filter_certified(PlanePlane::Parallel));
            for i in 0..w {
                assert_eq!(bits >> i & 1, u32::from(i % 4 != 1), "lane {i}");
                if i % 4 != 1 {
                    assert_eq!(out[i], intersect_plane_plane(cases[i].0, cases[i].1));
                    assert!(matches!(out[i].value, PlanePlane::Line(_)));
                }
            }
        }
    }

    /// Mixed lanes compute the values of each lane's own shape (so the bounds derived
    /// for the shapes hold for them): for every shape, the scales, `n`, `|n|²`, the point
    /// numerators and the parameter lines of the parametric planes of a mixed lane
    /// ([`terms_mixed`] on [`PlaneData::General`]) equal those of the shape's own
    /// formulas, double-double part by part.
    #[test]
    fn mixed_terms_are_the_shapes_terms() {
        use crate::geom::raw::MixedPlanes;
        type D = Dd<crate::num::dd::WithFma>;
        for shape in 0..4u64 {
            for seed in 0..40 {
                let plane = |j: u64| {
                    batch::testing::generic_plane(100 * seed + 2 * shape + j, shape >> j & 1 == 1)
                };
                let (a, b) = (plane(0), plane(1));
                let (ua, ub) = (RawPlane::new(&a), RawPlane::new(&b));
                let (ma, mb) = (MixedPlanes::of(&a), MixedPlanes::of(&b));
                let (sa, sb) = (ua.scales(SCALE_FLOOR), ma.scales(SCALE_FLOOR));
                assert_eq!(sa, sb);
                assert_eq!(ub.scales(sa.2), mb.scales(sb.2));
                let (pa, pb): (PlaneData<D>, PlaneData<D>) = (ua.data(), ub.data());
                let (qa, qb): (PlaneData<D>, PlaneData<D>) = (ma.data(), mb.data());
                let (n, m) = (cross3(pa.n(), pb.n()), cross3(qa.n(), qb.n()));
                assert_eq!(n, m);
                let (nn, mm) = (dot3(&n, &n), dot3(&m, &m));
                let tu = terms_from(&pa, &pb, n, nn);
                let tm = terms_mixed(&qa, &qb, m, mm, mb.implicit);
                assert_eq!((tu.nn, tu.pnum), (tm.nn, tm.pnum), "shape {shape}");
                for (u, m, implicit) in [
                    (&tu.on_a, &tm.on_a, ma.implicit),
                    (&tu.on_b, &tm.on_b, mb.implicit),
                ] {
                    if !implicit {
                        let (u, m) = (u.as_ref().unwrap(), m.as_ref().unwrap());
                        assert_eq!((u.num, u.dir), (m.num, m.dir), "shape {shape}");
                    }
                }
            }
        }
    }

    /// A lane group of mixed kinds (every pair of parametric and implicit planes, in
    /// turn) is decided in every lane, with the scalar answers (parameter lines only on
    /// the parametric planes of each lane).
    #[test]
    fn lane_kernel_decides_mixed_lanes() {
        let plane = batch::testing::generic_plane;
        let planes: Vec<(Plane<f64>, Plane<f64>)> = (0..MAX_LANES as u64)
            .map(|i| (plane(2 * i, i & 1 == 1), plane(2 * i + 1, i & 2 == 2)))
            .collect();
        let cases: Vec<PlanePlaneCase> = planes.iter().map(|(a, b)| (a, b)).collect();
        for kernel in
            batch::test_lane_kernels!(fast_lanes, PlanePlaneCase, Certified<PlanePlane<Rounded>>)
        {
            batch::testing::assert_kernel_decides_all(
                &kernel,
                &cases,
                filter_certified(PlanePlane::Parallel),
                |&(a, b)| intersect_plane_plane(a, b),
            );
        }
    }

    #[test]
    fn direction_range_constants() {
        assert_eq!(DIR_MIN, 2f64.powi(-999));
        assert_eq!(DIR_MAX, 2f64.powi(999));
    }

    #[test]
    fn filter_constants() {
        let mut w = [ErrorBound::zero(); 5];
        for a in &bound_planes() {
            for b in &bound_planes() {
                let t = terms(a, b);
                w[0] = t.n.iter().fold(w[0], |m, x| m.max(*x));
                w[1] = w[1].max(t.nn);
                w[2] = t.pnum.iter().fold(w[2], |m, x| m.max(*x));
                for p in [&t.on_a, &t.on_b].into_iter().flatten() {
                    w[3] = p.num.iter().fold(w[3], |m, x| m.max(*x));
                    w[4] = p.dir.iter().fold(w[4], |m, x| m.max(*x));
                }
            }
        }
        println!("derived (u²): {:?}", w.map(|x| x.e_in_u2()));
        for (x, c) in w.iter().zip([EPS_N, EPS_NN, EPS_PNUM, EPS_PARAM, EPS_PDIR]) {
            assert!(
                c >= x.e,
                "constant {} u² below the derived {} u²",
                c / (U * U),
                x.e_in_u2()
            );
        }
    }
}
