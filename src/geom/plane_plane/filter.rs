//! The filter tier of plane ∩ plane (OPERATIONS.md §8): the exact core's polynomials
//! in double-double, each output decided against its proven error bound (the
//! constants below), written once for one case (`F = f64`) and for lane groups.

use nalgebra::{Vector2, Vector3};

use super::exact::{terms_at, terms_from, AtOrigin, ParamTerms, Terms};
use super::{ParamLine, PlaneLine};
use crate::geom::data::PlaneData;
use crate::geom::objects::Plane;
use crate::geom::raw::RawPlane;
use crate::num::dd::{Dd, ProductMode, U};
use crate::num::filter::{bound, decide_over, decide_value, Decided, Denominator};
use crate::num::lane::Lane;
use crate::num::ring::{cross3, dot3, each, V3};
use crate::num::round::Rounded;

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
pub(super) struct Decisions<F: Lane> {
    pub(super) ok: F::Mask,
    pub(super) dir: [Decided<F>; 3],
    pub(super) point: [Decided<F>; 3],
    pub(super) on_a: Option<ParamDecisions<F>>,
    pub(super) on_b: Option<ParamDecisions<F>>,
}

/// A parameter line's decided origin and direction.
pub(super) struct ParamDecisions<F: Lane> {
    pub(super) origin: [Decided<F>; 2],
    pub(super) dir: [Decided<F>; 2],
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
pub(super) fn decide<M: ProductMode, F: Lane, const MIXED: bool>(
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
pub(super) const DIR_MIN: f64 = 1.8665272370064378e-301;
pub(super) const DIR_MAX: f64 = 5.357543035931337e300;

/// A plane's parameter line (§8 eq. (8.4)), decided (`None`: the plane has no
/// parameters); `ok` is narrowed to the lanes where every part was decided. `scales`
/// are `[m_p, m, k_q, k_o]`: origin scale, this plane's group scale, its degree and the
/// other plane's; in the `implicit` lanes (of a mixed group) the plane has no
/// parameters and `ok` is left as it is.
#[inline(always)]
pub(super) fn param_line<M: ProductMode, F: Lane>(
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
pub(super) fn fast<M: ProductMode>(a: &Plane<f64>, b: &Plane<f64>) -> Option<PlaneLine<Rounded>> {
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

/// [`terms_from`] for lane groups of mixed kinds (`implicit_b`: the lanes where `b` is
/// implicit): `x_r` lane by lane (`o_b`, else `o_a`, else 0: an implicit lane's origin
/// is zero), both values `f(x_r)` computed — the one of the plane with origin `x_r` is
/// an exact zero, its term changes no value — and the parameters from
/// [`AtOrigin::Any`]. Each lane computes the values of its own shape.
#[inline(always)]
pub(super) fn terms_mixed<M: ProductMode, F: Lane>(
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

/// The position scale before any origin is seen.
pub(super) const SCALE_FLOOR: f64 = crate::num::filter::SCALE_MIN;

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
