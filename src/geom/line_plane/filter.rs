//! The filter tier of line ∩ plane (OPERATIONS.md §5.1): the exact core's polynomials
//! in double-double, each output decided against its proven error bound (the constants
//! below), written once for one case (`F = f64`) and for lane groups.

use nalgebra::{Vector2, Vector3};

use super::exact::terms_from;
use super::{LinePlane, LinePlanePoint};
use crate::geom::data::{LineData, Linear, PlaneData};
use crate::geom::objects::Plane;
use crate::geom::raw::{RawLine, RawPlane};
use crate::num::dd::{Dd, ProductMode, U};
use crate::num::filter::{bound, decide_over, Decided, Denominator};
use crate::num::lane::Lane;
use crate::num::ring::{dot3, each, Ring};
use crate::num::round::Rounded;

/// Filter constants, as `k·u²`, re-derived by `tests::filter_constants`: each is the
/// [`crate::num::error_bound::ErrorBound`] bound of the formula in [`terms`] for inputs
/// bounded by 1, maximised over a line or a segment and a parametric or implicit plane,
/// rounded up. Derivation of the first, to first order in u, with the rules of
/// `error_bound` (worst case: parametric plane, segment): a product of two inputs has
/// `e' = u`, `|l| ≤ u`, error `u·u + u·u + 3u² = 5u²`; `N = u × v`: the subtraction adds
/// `u(2u + u) + u·4u = 7u²`, so `e_N = 17u²`, `|N_i| ≤ 2`, `|l| ≤ 4u`; the segment's
/// `c' = b − a`: `|c'_i| ≤ 2`, `|l| ≤ 2u`, `e = 4u²`; each product `N_i c'_i` propagates
/// `17u²·2 + 4u²·2 = 42u²` and adds `u·2·2u + u·e' + u·4u·2 + u·l + 8u² + 3u²` with
/// `e' = 4u + 4u`, `l = 8u + 8u`, i.e. `4 + 8 + 8 + 16 + 8 + 3 = 47u²`: 89u² each, with
/// `|·| ≤ 4`, `|l| ≤ 16u`; the two additions add `u(4u·… )` terms for the remaining
/// `451 − 3·89 = 184u²`. The test evaluates exactly these rules.
pub(super) const EPS_DEN: f64 = 452.0 * U * U;
pub(super) const EPS_PNUM: f64 = 2580.0 * U * U;
pub(super) const EPS_UVNUM: f64 = 1198.0 * U * U;

/// The filter's scales of one case or a lane group, `[m_P, m_L, m_G, m_G^k]`. Groups:
/// positions `P` (the line's origin or end points, the plane's origin, an implicit
/// plane's `|d|/m_n`), the line direction `L` (`P` for a segment, whose direction is
/// `b − a`), the plane vectors `G` (`u`, `v`, or the normal). Degrees (`k = 2`
/// parametric, `1` implicit): `N·c'`: `G^k L`; point numerators: `P G^k L`; `(u, v)`
/// numerators: `P G L` over `G² L`. `+∞` outside the filter's range (see
/// [`crate::num::filter::scale_of`]).
#[inline(always)]
pub(super) fn scales<F: Lane>(line: &RawLine<F>, plane: &RawPlane<F>) -> [F; 4] {
    let (mp, ml) = line.scales();
    let (mg, gk, mp) = plane.scales(mp);
    [mp, ml, mg, gk]
}

/// The filter's decisions for one case or a lane group: `ok` where `N·c'` and every
/// output were decided.
pub(super) struct Decisions<F: Lane> {
    pub(super) ok: F::Mask,
    pub(super) t: Decided<F>,
    pub(super) point: [Decided<F>; 3],
    pub(super) uv: Option<[Decided<F>; 2]>,
}

/// The filter tier, written once for one case (`F = f64`) and lane groups (`F4`, `F8`): the
/// formulas of [`terms_from`] in double-double, `N·c'` prepared as the denominator (its
/// sign decided: the verdict), every output's correct rounding decided against the
/// bounds `ε·scales` of the constants above. `implicit`: the lanes whose plane is
/// implicit (in a group of mixed kinds, [`PlaneData::General`], whose parameters are
/// left undecided there: the plane has none).
#[inline(always)]
pub(super) fn decide<M: ProductMode, F: Lane>(
    l: &LineData<Dd<M, F>>,
    p: &PlaneData<Dd<M, F>>,
    [mp, ml, mg, gk]: [F; 4],
    implicit: F::Mask,
) -> Option<Decisions<F>> {
    let d = dot3(p.n(), &l.d);
    let (den_ok, den) = Denominator::prepare(&d, bound(EPS_DEN, &[gk, ml]));
    // Exactly degenerate (or out-of-range) input leaves here, before the numerators.
    if !F::any(den_ok) {
        return None;
    }
    let tm = terms_from(l, p, d, p.value_at(&l.o));
    let t = decide_over(&tm.f0.negate(), bound(EPS_PNUM, &[mp, gk]), &den);
    let e_pnum = bound(EPS_PNUM, &[mp, gk, ml]);
    let point = each!(i in [0, 1, 2] => decide_over(&tm.pnum[i], e_pnum, &den));
    let mut ok = den_ok & t.ok & point[0].ok & point[1].ok & point[2].ok;
    let uv = match &tm.uvnum {
        Some([un, vn]) => {
            let e_uv = bound(EPS_UVNUM, &[mp, mg, ml]);
            let uv = [decide_over(un, e_uv, &den), decide_over(vn, e_uv, &den)];
            ok = ok & (uv[0].ok & uv[1].ok | implicit);
            Some(uv)
        }
        None => None,
    };
    Some(Decisions { ok, t, point, uv })
}

/// The answer from the correctly rounded outputs: the point, or the carrier's point
/// outside the line's domain (decided on the rounded `t`: the range ends are doubles,
/// so comparing with the exact `t` is comparing with its enclosure).
#[inline(always)]
pub(super) fn answer(
    line: Linear<f64>,
    t: Rounded,
    point: [Rounded; 3],
    uv: Option<[Rounded; 2]>,
) -> LinePlane<Rounded> {
    let inside = line.bounds_contain(&t);
    let pt = LinePlanePoint {
        point: Vector3::from(point),
        t,
        uv: uv.map(Vector2::from),
    };
    if inside {
        LinePlane::Point(pt)
    } else {
        LinePlane::OutsideDomain(pt)
    }
}

/// The filter tier for one case.
#[allow(clippy::manual_map)] // `match`, not a closure: see below
#[inline(always)]
pub(super) fn fast<M: ProductMode>(
    line: Linear<f64>,
    plane: &Plane<f64>,
) -> Option<LinePlane<Rounded>> {
    let (l, p) = (RawLine::new(line), RawPlane::new(plane));
    let dc = decide(
        &l.data::<M>(),
        &p.data(),
        scales(&l, &p),
        p.implicit_lanes(),
    )?;
    if !dc.ok {
        return None;
    }
    // (no array `map`: its closure may be compiled out of line)
    let uv = match dc.uv {
        Some([u, v]) => Some([u.value(), v.value()]),
        None => None,
    };
    let [x, y, z] = dc.point;
    Some(answer(
        line,
        dc.t.value(),
        [x.value(), y.value(), z.value()],
        uv,
    ))
}
