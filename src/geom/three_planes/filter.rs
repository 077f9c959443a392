//! The filter tier of three planes (OPERATIONS.md §7.1, point case only): the exact
//! core's polynomials in double-double, each output decided against its proven error
//! bound (the constants below), written once for one case (`F = f64`) and for lane
//! groups.

use nalgebra::{Vector2, Vector3};

use super::exact::{det_terms, terms_at, terms_from, Terms};
use super::ThreePlanes;
use crate::geom::data::PlaneData;
use crate::geom::objects::Plane;
use crate::geom::raw::RawPlane;
use crate::num::dd::{Dd, ProductMode, U};
use crate::num::filter::{bound, decide_over, Decided, Denominator, SCALE_MIN};
use crate::num::lane::Lane;
use crate::num::ring::{each, V3};
use crate::num::round::Rounded;

/// Filter constants (`k·u²`), re-derived by `tests::filter_constants` with
/// [`crate::num::error_bound::ErrorBound`] over all eight kind combinations (rules as in
/// `line_plane`): `D` (degree 6), point numerators (7), parameter numerators (6).
pub(super) const EPS_DET: f64 = 5598.0 * U * U;
pub(super) const EPS_PNUM: f64 = 66138.0 * U * U;
pub(super) const EPS_PARAM: f64 = 20027.0 * U * U;

/// The filter's decisions for one case or a lane group: `ok` where `D` and every output
/// were decided.
pub(super) struct Decisions<F: Lane> {
    pub(super) ok: F::Mask,
    pub(super) point: [Decided<F>; 3],
    pub(super) params: [Option<[Decided<F>; 2]>; 3],
}

/// The filter tier (point case only), written once for one case (`F = f64`) and lane
/// groups (`F4`, `F8`). Groups `P` (origins, `|d|/m_n`), `G_0`, `G_1`, `G_2`; with
/// `S_i = m_i^k_i` (`k = 2` parametric, 1 implicit) the degrees are: `D`: `S₀S₁S₂`;
/// point numerators: `P S₀S₁S₂`; parameter numerators of plane `k`: `P S_i S_j m_k`.
/// `MIXED`: some plane is [`RawPlane::Mixed`] (the numerators from [`terms_mixed`],
/// which computes each lane's shape's values, so the same bounds hold); a constant, so
/// that the uniform groups and the scalar path are compiled without that branch.
#[inline(always)]
pub(super) fn decide<M: ProductMode, F: Lane, const MIXED: bool>(
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
pub(super) fn fast<M: ProductMode>(p: &[Plane<f64>; 3]) -> Option<ThreePlanes<Rounded>> {
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

/// [`terms_from`] for lane groups of mixed kinds (`implicit`: each plane's implicit
/// lanes): `x_r` is chosen lane by lane (the first parametric origin, else 0) and
/// every `f_i(x_r)` is computed — `f_k0(x_r) = N·(o − o) + 0` is an exact zero, so
/// its term changes no value — and each plane's parameters evaluate the other two
/// planes at its origin, as `terms_from` does for the planes after `k0` and computes,
/// at `x_r = o_k0`, for `k0`. Each lane therefore computes the values of its own
/// shape.
#[inline(always)]
pub(super) fn terms_mixed<M: ProductMode, F: Lane>(
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
