//! Three planes, OPERATIONS.md §7.1, with every degenerate outcome (CGAL's result kinds:
//! a point, a line, a plane, or nothing).
//!
//! With unnormalised normals `N_i` and `D = N₀·(N₁ × N₂)` (eq. (7.2)'s denominator with
//! the normalisations cancelled), a reference point `x_r` (the first parametric plane's
//! origin, else the coordinate origin) and `F_i = f_i(x_r)`:
//! `p = x_r − (F₀ N₁×N₂ + F₁ N₂×N₀ + F₂ N₀×N₁)/D` (Cramer on `N_i·(p − x_r) = −F_i`).
//! Parameters on a parametric plane `k` (with `i, j` the next two, cyclically) solve the
//! 2×2 system `f_i(o_k + u u_k + v v_k) = 0`, `f_j(...) = 0`, whose determinant is
//! `(N_i × N_j)·(u_k × v_k) = D`: `u = (F_j (N_i·v_k) − F_i (N_j·v_k))/D`,
//! `v = (F_i (N_j·u_k) − F_j (N_i·u_k))/D`, `F = f(o_k)`. This is (3.7)–(3.8) for the
//! point, of lower degree (§16.7's `(t, τ) = (−1, 2)` needs no orthogonal basis).
//!
//! `D = 0` exactly: if every `N_i × N_j = 0`, all normals are parallel: `Plane` when all
//! three coincide (plane 0 shares a point with each other, see
//! `plane_plane::coincide_parallel`), else `Empty`. Otherwise the first pair `(i, j)`
//! (in the order (0,1), (0,2), (1,2)) with `N_i × N_j ≠ 0` gives the line of §8; it is
//! the answer if it lies in the third plane (`f_k(p) = 0`; its direction is orthogonal to
//! `N_k` because `D = 0`), else `Empty`. This covers two coincident planes crossed by a
//! third, three planes through one line, two parallel planes and a third crossing them,
//! and the prism of three pairwise crossing planes with parallel lines.

use std::mem::MaybeUninit;

use nalgebra::{Scalar, Vector2, Vector3};
use rug::Rational;

use super::batch::{self, lane_kernel};
use super::data::PlaneData;
use super::exact_tier::{
    filter_certified, ring_tier, ExactRing, Rounder, SmallInteger, WideInteger,
};
use super::objects::Plane;
use super::plane_plane::{
    coincide_parallel, finish, round_line, round_line_ring, terms_from as terms_from_pair,
    PlaneLine,
};
use super::raw::RawPlane;
use crate::certificate::Certified;
use crate::num::dd::{Dd, ProductMode, U};
use crate::num::expansion::Expansion;
use crate::num::filter::{bound, decide_over, dispatch_fma, Decided, Denominator, SCALE_MIN};
use crate::num::lane::{Lane, Wide};
use crate::num::ratio::Ratio;
use crate::num::ring::{cross3, dot3, each, is_zero3, Field, Ring, V2, V3};
use crate::num::round::Rounded;

/// The result of three planes.
#[derive(Debug, Clone, PartialEq)]
pub enum ThreePlanes<S: Scalar> {
    /// One point, with its parameters on each parametric plane (input order).
    Point {
        point: Vector3<S>,
        params: [Option<Vector2<S>>; 3],
    },
    /// A common line (see [`PlaneLine`]; `pair` names the two planes it was computed
    /// from, whose parameter lines `on_a`, `on_b` it carries).
    Line {
        line: PlaneLine<S>,
        pair: (usize, usize),
    },
    /// All three planes coincide.
    Plane,
    /// No common point.
    Empty,
}

impl<S: Scalar> ThreePlanes<S> {
    /// Apply `f` to every number.
    pub fn map<T: Scalar>(self, mut f: impl FnMut(S) -> T) -> ThreePlanes<T> {
        match self {
            ThreePlanes::Point { point, params } => ThreePlanes::Point {
                point: point.map(&mut f),
                params: params.map(|p| p.map(|p| p.map(&mut f))),
            },
            ThreePlanes::Line { line, pair } => ThreePlanes::Line {
                line: line.map(f),
                pair,
            },
            ThreePlanes::Plane => ThreePlanes::Plane,
            ThreePlanes::Empty => ThreePlanes::Empty,
        }
    }
}

/// The polynomials of the point case.
pub(crate) struct Terms<R> {
    pub det: R,
    pub pnum: V3<R>,
    pub params: [Option<V2<R>>; 3],
}

/// `[N₁×N₂, N₂×N₀, N₀×N₁]` and `D = N₀·(N₁×N₂)`: the decision of §7.1.
#[inline(always)]
pub(crate) fn det_terms<R: Ring>(p: &[PlaneData<R>; 3]) -> ([V3<R>; 3], R) {
    let n = [p[0].n(), p[1].n(), p[2].n()];
    let c = [cross3(n[1], n[2]), cross3(n[2], n[0]), cross3(n[0], n[1])];
    let det = dot3(n[0], &c[0]);
    (c, det)
}

#[cfg(test)] // the filter-constant tests; the kernel calls `terms_from` after its decision
#[inline(always)]
pub(crate) fn terms<R: Ring>(p: &[PlaneData<R>; 3]) -> Terms<R> {
    let (c, det) = det_terms(p);
    terms_from(p, &c, det)
}

/// The point-case numerators, given [`det_terms`].
#[inline(always)]
pub(crate) fn terms_from<R: Ring>(p: &[PlaneData<R>; 3], c: &[V3<R>; 3], det: R) -> Terms<R> {
    // x_r is the origin of plane k0 (the first parametric one), where f_k0 vanishes:
    // its term is left out, and its parameters reuse the other two values f_i(x_r).
    let k0 = p.iter().position(|q| q.origin().is_some());
    let x_r = k0
        .and_then(|k| p[k].origin())
        .cloned()
        .unwrap_or_else(|| [R::zero(), R::zero(), R::zero()]);
    let f = each!(i in [0, 1, 2] => {
        if k0 == Some(i) {
            R::zero()
        } else {
            p[i].value_at(&x_r)
        }
    });
    terms_at(p, c, det, &x_r, &f, k0)
}

/// [`terms_from`] for lane groups of mixed kinds (`implicit`: each plane's implicit
/// lanes): `x_r` is chosen lane by lane (the first parametric origin, else 0) and
/// every `f_i(x_r)` is computed — `f_k0(x_r) = N·(o − o) + 0` is an exact zero, so
/// its term changes no value — and each plane's parameters evaluate the other two
/// planes at its origin, as `terms_from` does for the planes after `k0` and computes,
/// at `x_r = o_k0`, for `k0`. Each lane therefore computes the values of its own
/// shape.
#[inline(always)]
fn terms_mixed<M: ProductMode, F: Lane>(
    p: &[PlaneData<Dd<M, F>>; 3],
    c: &[V3<Dd<M, F>>; 3],
    det: Dd<M, F>,
    implicit: [F::Mask; 3],
) -> Terms<Dd<M, F>> {
    let o = [
        p[0].origin_or_zero(),
        p[1].origin_or_zero(),
        p[2].origin_or_zero(),
    ];
    // (an implicit lane's origin is zero: o₂ there is 0 when all three are implicit)
    let x_r = each!(m in [0, 1, 2] => Dd::select(
        implicit[0],
        &Dd::select(implicit[1], &o[2][m], &o[1][m]),
        &o[0][m],
    ));
    let f = each!(i in [0, 1, 2] => p[i].value_at(&x_r));
    terms_at(p, c, det, &x_r, &f, None)
}

/// The numerators from the reference point `x_r` and `f_i(x_r)`; `skip` names the
/// plane with origin `x_r` (left out of the point, and its parameters reuse `f`).
#[inline(always)]
fn terms_at<R: Ring>(
    p: &[PlaneData<R>; 3],
    c: &[V3<R>; 3],
    det: R,
    x_r: &V3<R>,
    f: &[R; 3],
    skip: Option<usize>,
) -> Terms<R> {
    let n = [p[0].n(), p[1].n(), p[2].n()];
    let pnum = each!(m in [0, 1, 2] => {
        let mut acc = x_r[m].times(&det);
        for i in 0..3 {
            if skip != Some(i) {
                acc = acc.minus(&f[i].times(&c[i][m]));
            }
        }
        acc
    });
    let params = each!(k in [0, 1, 2] => plane_params(p, &n, k, (skip == Some(k)).then_some(f)));
    Terms { det, pnum, params }
}

/// Numerators (over `D`) of the parameters of the point on parametric plane `k`;
/// `f_at_origin`: the planes' values at `o_k` when already computed.
#[inline(always)]
fn plane_params<R: Ring>(
    p: &[PlaneData<R>; 3],
    n: &[&V3<R>; 3],
    k: usize,
    f_at_origin: Option<&[R; 3]>,
) -> Option<V2<R>> {
    let (PlaneData::Param { o, u, v, .. } | PlaneData::General { o, u, v, .. }) = &p[k] else {
        return None;
    };
    let (i, j) = ((k + 1) % 3, (k + 2) % 3);
    let (fi, fj) = match f_at_origin {
        Some(f) => (f[i].clone(), f[j].clone()),
        None => (p[i].value_at(o), p[j].value_at(o)),
    };
    let un = fj.times(&dot3(n[i], v)).minus(&fi.times(&dot3(n[j], v)));
    let vn = fi.times(&dot3(n[j], u)).minus(&fj.times(&dot3(n[i], u)));
    Some([un, vn])
}

/// The exact decision procedure, generic over the field.
pub(crate) fn core<R: Field>(p: &[PlaneData<R>; 3]) -> ThreePlanes<R> {
    let (c, det) = det_terms(p);
    if !det.is_zero() {
        let tm = terms_from(p, &c, det);
        let d = &tm.det;
        let [x, y, z] = tm.pnum.map(|q| q.divide(d));
        return ThreePlanes::Point {
            point: Vector3::new(x, y, z),
            params: tm
                .params
                .map(|q| q.map(|[u, v]| Vector2::new(u.divide(d), v.divide(d)))),
        };
    }
    // N_i × N_j for the pairs (0,1), (0,2), (1,2) are c[2], −c[1], c[0]: the line's
    // direction is taken from them rather than recomputed.
    for (i, j, k, cij, flip) in [
        (0, 1, 2, &c[2], false),
        (0, 2, 1, &c[1], true),
        (1, 2, 0, &c[0], false),
    ] {
        if !is_zero3(cij) {
            let n = if flip {
                [cij[0].negate(), cij[1].negate(), cij[2].negate()]
            } else {
                cij.clone()
            };
            // The line lies in plane k iff its point p = pnum/|n|² does: tested on the
            // numerators (|n|²·f_k(p), a polynomial), before any division.
            let nn = dot3(&n, &n);
            let tm = terms_from_pair(&p[i], &p[j], n, nn);
            return if p[k].value_at_homogeneous(&tm.pnum, &tm.nn).is_zero() {
                ThreePlanes::Line {
                    line: finish(tm),
                    pair: (i, j),
                }
            } else {
                ThreePlanes::Empty
            };
        }
    }
    if coincide_parallel(&p[0], &p[1]) && coincide_parallel(&p[0], &p[2]) {
        ThreePlanes::Plane
    } else {
        ThreePlanes::Empty
    }
}

/// Plain f64 (uncertified; `D == 0.0` decides degeneracy, like CGAL's Epick).
pub fn intersect_three_planes_f64(p: &[Plane<f64>; 3]) -> ThreePlanes<f64> {
    core::<f64>(&[
        PlaneData::new(&p[0]),
        PlaneData::new(&p[1]),
        PlaneData::new(&p[2]),
    ])
}

/// Exact, on rational inputs.
pub fn intersect_three_planes_exact(p: &[Plane<Rational>; 3]) -> ThreePlanes<Rational> {
    core::<Rational>(&[
        PlaneData::new(&p[0]),
        PlaneData::new(&p[1]),
        PlaneData::new(&p[2]),
    ])
}

/// Certified: exact verdict, correctly rounded coordinates and parameters.
pub fn intersect_three_planes(p: &[Plane<f64>; 3]) -> Certified<ThreePlanes<Rounded>> {
    dispatch_fma!(certified(p: &[Plane<f64>; 3]) -> Certified<ThreePlanes<Rounded>>)
}

/// The filter, then the exact tiers (instantiated once per product mode, so that the
/// answer is built in place).
#[inline(always)]
fn certified<M: ProductMode>(p: &[Plane<f64>; 3]) -> Certified<ThreePlanes<Rounded>> {
    match fast::<M>(p) {
        Some(r) => filter_certified(r),
        None => exact_tiers(p),
    }
}

/// The exact tiers in order of cost: 128-bit integers, 768-bit integers, expansions,
/// rationals (which always answer). Out of line, so that the filter's caller keeps a
/// small stack frame.
#[cold]
#[inline(never)]
fn exact_tiers(p: &[Plane<f64>; 3]) -> Certified<ThreePlanes<Rounded>> {
    ring_tier_answer::<SmallInteger>(p)
        .or_else(|| ring_tier_answer::<WideInteger>(p))
        .or_else(|| ring_tier_answer::<Expansion>(p))
        .unwrap_or_else(|| rational_tier(p))
}

/// The last tier, in `rug::Rational`.
#[inline(never)]
fn rational_tier(p: &[Plane<f64>; 3]) -> Certified<ThreePlanes<Rounded>> {
    let data: [PlaneData<Rational>; 3] = [
        PlaneData::new(&p[0]),
        PlaneData::new(&p[1]),
        PlaneData::new(&p[2]),
    ];
    let mut r = Rounder::default();
    let res = match core(&data) {
        ThreePlanes::Line { line, pair } => ThreePlanes::Line {
            line: round_line(line, &mut r),
            pair,
        },
        other => other.map(|q| r.round(q)),
    };
    r.certify(res)
}

/// The exact decision in the ring `E` ([`ring_tier`]): `None` when `E` lost exactness.
#[inline(always)]
fn ring_tier_answer<E: ExactRing>(p: &[Plane<f64>; 3]) -> Option<Certified<ThreePlanes<Rounded>>> {
    ring_tier::<E, _>(|r| {
        let data: [PlaneData<Ratio<E>>; 3] = [
            PlaneData::new(&p[0]),
            PlaneData::new(&p[1]),
            PlaneData::new(&p[2]),
        ];
        match core(&data) {
            ThreePlanes::Line { line, pair } => ThreePlanes::Line {
                line: round_line_ring(line, r),
                pair,
            },
            other => other.map(|q| r.round(q)),
        }
    })
}

/// Filter constants (`k·u²`), re-derived by `tests::filter_constants` with
/// [`crate::num::error_bound::ErrorBound`] over all eight kind combinations (rules as in
/// `line_plane`): `D` (degree 6), point numerators (7), parameter numerators (6).
const EPS_DET: f64 = 5598.0 * U * U;
const EPS_PNUM: f64 = 66138.0 * U * U;
const EPS_PARAM: f64 = 20027.0 * U * U;

/// The filter's decisions for one case or a lane group: `ok` where `D` and every output
/// were decided.
struct Decisions<F: Lane> {
    ok: F::Mask,
    point: [Decided<F>; 3],
    params: [Option<[Decided<F>; 2]>; 3],
}

/// The filter tier (point case only), written once for one case (`F = f64`) and lane
/// groups (`F4`, `F8`). Groups `P` (origins, `|d|/m_n`), `G_0`, `G_1`, `G_2`; with
/// `S_i = m_i^k_i` (`k = 2` parametric, 1 implicit) the degrees are: `D`: `S₀S₁S₂`;
/// point numerators: `P S₀S₁S₂`; parameter numerators of plane `k`: `P S_i S_j m_k`.
/// `MIXED`: some plane is [`RawPlane::Mixed`] (the numerators from [`terms_mixed`],
/// which computes each lane's shape's values, so the same bounds hold); a constant, so
/// that the uniform groups and the scalar path are compiled without that branch.
#[inline(always)]
fn decide<M: ProductMode, F: Lane, const MIXED: bool>(
    raw: &[RawPlane<F>; 3],
) -> Option<Decisions<F>> {
    let (m0, s0, mp) = raw[0].scales(F::splat(SCALE_MIN));
    let (m1, s1, mp) = raw[1].scales(mp);
    let (m2, s2, mp) = raw[2].scales(mp);
    let (m, s) = ([m0, m1, m2], [s0, s1, s2]);
    let data: [PlaneData<Dd<M, F>>; 3] = [raw[0].data(), raw[1].data(), raw[2].data()];
    // The decision: preparing D proves D ≠ 0 (|D̂| > its error bound).
    let (c, d) = det_terms(&data);
    let (mut ok, det) = Denominator::prepare(&d, bound(EPS_DET, &s));
    // Exactly degenerate (or out-of-range) input leaves here, before the numerators.
    if !F::any(ok) {
        return None;
    }
    let implicit = [
        raw[0].implicit_lanes(),
        raw[1].implicit_lanes(),
        raw[2].implicit_lanes(),
    ];
    let tm = if MIXED {
        terms_mixed(&data, &c, d, implicit)
    } else {
        terms_from(&data, &c, d)
    };
    let e_p = bound(EPS_PNUM, &[mp, s0, s1, s2]);
    let point = each!(i in [0, 1, 2] => decide_over(&tm.pnum[i], e_p, &det));
    ok = ok & point[0].ok & point[1].ok & point[2].ok;
    let params = each!(k in [0, 1, 2] => match &tm.params[k] {
        Some([un, vn]) => {
            let e = bound(EPS_PARAM, &[mp, s[(k + 1) % 3], s[(k + 2) % 3], m[k]]);
            let q = [decide_over(un, e, &det), decide_over(vn, e, &det)];
            // (mixed lanes: an implicit plane has no parameters to decide)
            ok = ok & (q[0].ok & q[1].ok | implicit[k]);
            Some(q)
        }
        None => None,
    });
    Some(Decisions { ok, point, params })
}

/// The filter tier for one case.
#[allow(clippy::manual_map)] // `match`, not a closure: see below
#[inline(always)]
fn fast<M: ProductMode>(p: &[Plane<f64>; 3]) -> Option<ThreePlanes<Rounded>> {
    let raw = [
        RawPlane::new(&p[0]),
        RawPlane::new(&p[1]),
        RawPlane::new(&p[2]),
    ];
    let dc = decide::<M, f64, false>(&raw)?;
    if !dc.ok {
        return None;
    }
    // (no array `map`: its closure may be compiled out of line, here a measured 1.6×)
    let [x, y, z] = dc.point;
    Some(ThreePlanes::Point {
        point: Vector3::new(x.value(), y.value(), z.value()),
        params: each!(k in [0, 1, 2] => match &dc.params[k] {
            Some([u, v]) => Some(Vector2::new(u.value(), v.value())),
            None => None,
        }),
    })
}

/// The filter tier for `F::N` cases of one shape ([`batch_shape`]) or of mixed shapes
/// in lanes: writes the answers of the decided lanes to `out` (see
/// [`batch::LaneKernel`]).
#[allow(clippy::manual_map)] // `match`, not a closure: see below
#[inline(always)]
fn fast_lanes<M: ProductMode, F: Wide>(
    cases: &[[Plane<f64>; 3]],
    idx: &[usize],
    real: usize,
    out: &mut [MaybeUninit<Certified<ThreePlanes<Rounded>>>],
) -> u32 {
    let c = |i: usize| &cases[idx[i]];
    let r0 = RawPlane::<F>::gather(|i| &c(i)[0]);
    let r1 = RawPlane::<F>::gather(|i| &c(i)[1]);
    let r2 = RawPlane::<F>::gather(|i| &c(i)[2]);
    let raw = [r0, r1, r2];
    // (two instances: the uniform groups' straight-line code stays as it was)
    let dc = if raw.iter().any(RawPlane::is_mixed) {
        decide::<M, F, true>(&raw)
    } else {
        decide::<M, F, false>(&raw)
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
    let params = each!(k in [0, 1, 2] => match &dc.params[k] {
        Some([u, v]) => Some([u.lanes(), v.lanes()]),
        None => None,
    });
    for (i, &j) in idx.iter().enumerate().take(real) {
        if ok >> i & 1 == 1 {
            out[j].write(filter_certified(ThreePlanes::Point {
                point: Vector3::new(point[0].get(i), point[1].get(i), point[2].get(i)),
                params: each!(k in [0, 1, 2] => match &params[k] {
                    // (in a mixed group, only the parametric lanes have parameters)
                    Some([u, v]) if matches!(c(i)[k], Plane::Parametric { .. }) => {
                        Some(Vector2::new(u.get(i), v.get(i)))
                    }
                    _ => None,
                }),
            }));
        }
    }
    ok
}

/// The batch shape: the kinds of the three planes (parametric or implicit), as bits.
fn batch_shape(p: &[Plane<f64>; 3]) -> usize {
    let implicit = |q: &Plane<f64>| usize::from(matches!(q, Plane::Implicit { .. }));
    implicit(&p[0]) | implicit(&p[1]) << 1 | implicit(&p[2]) << 2
}

/// Certified three planes for many cases: appends to `out`, in order, exactly the
/// answer [`intersect_three_planes`] gives for each triple (see `geom::batch`: lane
/// groups through the lane filter, one shape each, then what is left of the shapes
/// mixed). `out` only allocates when it grows.
pub fn intersect_three_planes_batch(
    cases: &[[Plane<f64>; 3]],
    out: &mut Vec<Certified<ThreePlanes<Rounded>>>,
) {
    let lanes = lane_kernel!(fast_lanes, [Plane<f64>; 3], Certified<ThreePlanes<Rounded>>);
    batch::run(
        cases,
        out,
        batch_shape,
        lanes,
        intersect_three_planes,
        exact_tiers,
    );
}

/// For `robust`'s tests, which drive it with every robustness generator: the
/// four-lane (AVX) kernel end to end, whatever the CPU's widest — `batch::run` answers
/// `cases` as the scalar path does (nothing to run on a CPU without AVX and FMA).
#[cfg(test)]
pub(crate) fn assert_four_lane_run_equals_scalar(cases: &[[Plane<f64>; 3]]) {
    let lanes = lane_kernel!(
        fast_lanes,
        [Plane<f64>; 3],
        Certified<ThreePlanes<Rounded>>,
        4
    );
    if lanes.is_none() {
        return; // no AVX/FMA
    }
    batch::testing::assert_run_equals_scalar(
        cases,
        batch_shape,
        lanes,
        intersect_three_planes,
        exact_tiers,
    );
}

#[cfg(test)]
mod tests {
    use super::*;

    fn plane(seed: f64, implicit: bool) -> Plane<f64> {
        let v = |a: f64, b: f64, c: f64| Vector3::new(a * seed, b + seed, c - seed);
        if implicit {
            Plane::implicit(v(1.3, -0.2, 0.7), 0.9 * seed).unwrap()
        } else {
            Plane::parametric(v(0.3, 1.1, -2.0), v(1.7, 0.4, 0.2), v(-0.6, 1.9, 0.8)).unwrap()
        }
    }

    /// Mixed lanes compute the values of each lane's own shape (what makes the
    /// filter's bounds, derived for the shapes, hold for them): for every shape, the
    /// scales, `D`, the point numerators and the parameter numerators of the parametric
    /// planes of a mixed lane ([`terms_mixed`] on [`PlaneData::General`]) equal those of
    /// the shape's own formulas, double-double part by part.
    #[test]
    fn mixed_terms_are_the_shapes_terms() {
        use crate::geom::raw::MixedPlanes;
        type D = Dd<crate::num::dd::WithFma>;
        for shape in 0..8u64 {
            for seed in 0..40 {
                let p: [Plane<f64>; 3] = each!(j in [0, 1, 2] => batch::testing::generic_plane(
                    100 * seed + 3 * shape + j as u64,
                    shape >> j & 1 == 1,
                ));
                let uniform = p.clone().map(|q| RawPlane::new(&q));
                let mixed = p.clone().map(|q| MixedPlanes::of(&q));
                let mut mp = (SCALE_MIN, SCALE_MIN);
                for (u, m) in uniform.iter().zip(&mixed) {
                    let (a, b) = (u.scales(mp.0), m.scales(mp.1));
                    assert_eq!(a, b);
                    mp = (a.2, b.2);
                }
                let du: [PlaneData<D>; 3] = uniform.map(|r| r.data());
                let dm: [PlaneData<D>; 3] = mixed.map(|r| r.data());
                let ((cu, det_u), (cm, det_m)) = (det_terms(&du), det_terms(&dm));
                assert_eq!(det_u, det_m);
                let tu = terms_from(&du, &cu, det_u);
                let implicit = mixed.map(|m| m.implicit);
                let tm = terms_mixed(&dm, &cm, det_m, implicit);
                assert_eq!(tu.pnum, tm.pnum, "shape {shape}");
                for (k, ((u, m), implicit)) in
                    tu.params.iter().zip(&tm.params).zip(implicit).enumerate()
                {
                    if !implicit {
                        assert_eq!(u, m, "shape {shape}, plane {k}");
                    }
                }
            }
        }
    }

    /// A lane group of mixed kinds (lane `i` has shape `i mod 8`: every combination of
    /// parametric and implicit planes) is decided in every lane, with the scalar answers
    /// (parameters only on the parametric planes of each lane).
    #[test]
    fn lane_kernel_decides_mixed_lanes() {
        for kernel in
            batch::test_lane_kernels!(fast_lanes, [Plane<f64>; 3], Certified<ThreePlanes<Rounded>>)
        {
            let cases: Vec<[Plane<f64>; 3]> = (0..8)
                .map(|k| {
                    let p =
                        |j: u64, bit: u64| batch::testing::generic_plane(3 * k + j, k & bit != 0);
                    [p(0, 1), p(1, 2), p(2, 4)]
                })
                .collect();
            // (four lanes: the first four shapes, then the other four)
            for group in [&cases[..], &cases[4..]] {
                batch::testing::assert_kernel_decides_all(
                    &kernel,
                    group,
                    filter_certified(ThreePlanes::Empty),
                    intersect_three_planes,
                );
                if kernel.width == 8 {
                    break;
                }
            }
        }
    }

    /// The lane kernel decides a lane group of generic triples of one shape and writes the scalar
    /// answers; an exactly degenerate lane (three times the same plane) is left to the
    /// scalar path.
    #[test]
    fn lane_kernel_decides_generic_lanes() {
        for kernel in
            batch::test_lane_kernels!(fast_lanes, [Plane<f64>; 3], Certified<ThreePlanes<Rounded>>)
        {
            let w = kernel.width;
            let cases: Vec<[Plane<f64>; 3]> = (0..w)
                .map(|i| {
                    let s = 0.37 + i as f64;
                    if i % 4 == 1 {
                        [plane(2.0, false), plane(3.0, true), plane(2.0, false)]
                    } else {
                        [plane(s, false), plane(s * 1.9, true), plane(-s, false)]
                    }
                })
                .collect();
            let (bits, out) =
                batch::testing::run_once(&kernel, &cases, filter_certified(ThreePlanes::Empty));
            for i in 0..w {
                assert_eq!(bits >> i & 1, u32::from(i % 4 != 1), "lane {i}");
                if i % 4 != 1 {
                    assert_eq!(out[i], intersect_three_planes(&cases[i]));
                    assert!(matches!(out[i].value, ThreePlanes::Point { .. }));
                }
            }
        }
    }
    use crate::geom::plane_plane::bound_planes;
    use crate::num::error_bound::ErrorBound;

    #[test]
    fn filter_constants() {
        let kinds = bound_planes();
        let mut w = [ErrorBound::zero(); 3];
        for a in &kinds {
            for b in &kinds {
                for c in &kinds {
                    let t = terms(&[a.clone(), b.clone(), c.clone()]);
                    w[0] = w[0].max(t.det);
                    w[1] = t.pnum.iter().fold(w[1], |m, x| m.max(*x));
                    for q in t.params.iter().flatten() {
                        w[2] = q.iter().fold(w[2], |m, x| m.max(*x));
                    }
                }
            }
        }
        println!("derived (u²): {:?}", w.map(|x| x.e_in_u2()));
        for (x, c) in w.iter().zip([EPS_DET, EPS_PNUM, EPS_PARAM]) {
            assert!(
                c >= x.e,
                "constant {} u² below the derived {} u²",
                c / (U * U),
                x.e_in_u2()
            );
        }
    }
}
