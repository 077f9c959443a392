//! The exact core of three planes (OPERATIONS.md §7.1, module doc of [`super`]): the
//! polynomials written once, generic over the ring (f64, double-double lanes, the exact
//! rings, rationals), the decision procedure with every degenerate outcome, and the
//! exact tiers (128-bit and 768-bit integers, expansions, rationals) with their rounding.

use nalgebra::{Vector2, Vector3};
use rug::Rational;

use super::ThreePlanes;
use crate::certificate::Certified;
use crate::geom::data::PlaneData;
use crate::geom::exact_tier::{ring_tier, ExactRing, Rounder, SmallInteger, WideInteger};
use crate::geom::objects::Plane;
use crate::geom::plane_plane::{
    coincide_parallel, finish, round_line, round_line_ring, terms_from as terms_from_pair,
};
use crate::num::expansion::Expansion;
use crate::num::ratio::Ratio;
use crate::num::ring::{cross3, dot3, each, is_zero3, Field, Ring, V2, V3};
use crate::num::round::Rounded;

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

/// The numerators from the reference point `x_r` and `f_i(x_r)`; `skip` names the
/// plane with origin `x_r` (left out of the point, and its parameters reuse `f`).
#[inline(always)]
pub(super) fn terms_at<R: Ring>(
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
pub(super) fn plane_params<R: Ring>(
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

/// The exact tiers in order of cost: 128-bit integers, 768-bit integers, expansions,
/// rationals (which always answer). Out of line, so that the filter's caller keeps a
/// small stack frame.
#[cold]
#[inline(never)]
pub(super) fn exact_tiers(p: &[Plane<f64>; 3]) -> Certified<ThreePlanes<Rounded>> {
    ring_tier_answer::<SmallInteger>(p)
        .or_else(|| ring_tier_answer::<WideInteger>(p))
        .or_else(|| ring_tier_answer::<Expansion>(p))
        .unwrap_or_else(|| rational_tier(p))
}

/// The last tier, in `rug::Rational`.
#[inline(never)]
pub(super) fn rational_tier(p: &[Plane<f64>; 3]) -> Certified<ThreePlanes<Rounded>> {
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
pub(super) fn ring_tier_answer<E: ExactRing>(
    p: &[Plane<f64>; 3],
) -> Option<Certified<ThreePlanes<Rounded>>> {
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
