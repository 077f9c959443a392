//! Projection of a point onto a line, ranged line or segment (OPERATIONS.md §3.1 eq. (3.1))
//! and onto a plane (§3.3 eqs. (3.6)–(3.8)).
//!
//! Line `c(t) = c₀ + t c'`, `w = p − c₀`: `t = (w·c')/|c'|²`, foot
//! `(c₀|c'|² + (w·c')c')/|c'|²`, squared distance `|w × c'|²/|c'|²`. On a bounded domain
//! the stationary foot is reported only if `t` lies in it (docs/FORMAT.md "Projections"), and
//! `nearest` clamps `t` to the closed domain (then the squared distance is `|p − c(t)|²`).
//!
//! Plane with normal `N`, `f(p) = N·(p − s₀)` (or `n·p + d`): foot
//! `(p|N|² − N f(p))/|N|²`, signed distance `l_s = f(p)/|N|` (positive on the side `N`
//! points to), and for a parametric plane the metric-tensor recovery (3.7)–(3.8) with
//! `w = p − s₀`, `g_ij = s_i·s_j`: `u = (g₂₂ s₁·w − g₁₂ s₂·w)/G`, `v = (g₁₁ s₂·w − g₁₂ s₁·w)/G`,
//! `G = g₁₁g₂₂ − g₁₂²`.
//!
//! Distances are irrational: the certified path reports the correctly rounded square
//! root of the exact squared distance with its enclosure ([`crate::num::round`]); the
//! exact path also gives the exact squared distance ([`ExactLength`]).

use nalgebra::{Scalar, Vector2, Vector3};
use rug::float::Round;
use rug::{Float, Rational};

use super::data::{Lift, LineData, Linear, PlaneData};
use super::exact_tier::{filter_certified, Rounder};
use super::objects::Plane;
use super::raw::{RawLine, RawPlane};
use crate::certificate::Certified;
use crate::num::dd::{Dd, ProductMode, U};
use crate::num::filter::{
    accepted, bound, dispatch_fma, round_over, scale_of, sign_of, Denominator,
};
use crate::num::ring::{cross3, dot3, each, sub3, Field, Ring, V2, V3};
use crate::num::round::{sqrt_rational, Rounded};

/// A length known exactly: its square, its sign, and its correctly rounded value.
#[derive(Debug, Clone, PartialEq)]
pub struct ExactLength {
    pub squared: Rational,
    /// The signed distance to a plane is negative (on the side opposite the normal).
    pub negative: bool,
    /// `±√squared`, correctly rounded.
    pub rounded: Rounded,
}

/// A foot on a line: the point, its parameter, the distance.
#[derive(Debug, Clone, PartialEq)]
pub struct LineFoot<S: Scalar, L> {
    pub foot: Vector3<S>,
    pub t: S,
    pub distance: L,
}

/// Projection onto a line: the stationary foot (`None` when it lies outside a bounded
/// domain) and the nearest point of the closed domain (the stationary foot when it is
/// inside, else the nearer domain end).
#[derive(Debug, Clone, PartialEq)]
pub struct LineProjection<S: Scalar, L> {
    pub stationary: Option<LineFoot<S, L>>,
    pub nearest: LineFoot<S, L>,
}

/// Projection onto a plane: foot, parameters (parametric planes), signed distance.
#[derive(Debug, Clone, PartialEq)]
pub struct PlaneProjection<S: Scalar, L> {
    pub foot: Vector3<S>,
    pub uv: Option<Vector2<S>>,
    pub distance: L,
}

/// The polynomials of point → line.
pub(crate) struct LineTerms<R> {
    /// `w·c'` (numerator of `t`).
    pub tnum: R,
    /// `|c'|²`.
    pub dd: R,
    pub footnum: V3<R>,
    /// `|w × c'|²`.
    pub dist2num: R,
}

#[inline(always)]
pub(crate) fn line_terms<R: Ring>(p: &V3<R>, l: &LineData<R>) -> LineTerms<R> {
    let w = sub3(p, &l.o);
    let tnum = dot3(&w, &l.d);
    let dd = dot3(&l.d, &l.d);
    let footnum = each!(i in [0, 1, 2] => l.o[i].times(&dd).plus(&tnum.times(&l.d[i])));
    let c = cross3(&w, &l.d);
    LineTerms {
        tnum,
        dd,
        footnum,
        dist2num: dot3(&c, &c),
    }
}

/// The polynomials of point → plane.
pub(crate) struct PlaneTerms<R> {
    /// `f(p)`.
    pub f: R,
    /// `|N|²`.
    pub nn: R,
    pub footnum: V3<R>,
    /// `(u, v)` numerators and `G` (3.7)–(3.8).
    pub uv: Option<(V2<R>, R)>,
}

#[inline(always)]
pub(crate) fn plane_terms<R: Ring>(p: &V3<R>, q: &PlaneData<R>) -> PlaneTerms<R> {
    let n = q.n();
    let f = q.value_at(p);
    let nn = dot3(n, n);
    let footnum = each!(i in [0, 1, 2] => p[i].times(&nn).minus(&n[i].times(&f)));
    let uv = match q {
        PlaneData::Param { o, u, v, .. } | PlaneData::General { o, u, v, .. } => {
            let w = sub3(p, o);
            let (g11, g12, g22) = (dot3(u, u), dot3(u, v), dot3(v, v));
            let (a, b) = (dot3(u, &w), dot3(v, &w));
            let un = g22.times(&a).minus(&g12.times(&b));
            let vn = g11.times(&b).minus(&g12.times(&a));
            Some(([un, vn], g11.times(&g22).minus(&g12.times(&g12))))
        }
        PlaneData::Implicit { .. } => None,
    };
    PlaneTerms { f, nn, footnum, uv }
}

/// The exact procedure for point → line, generic over the field; distances squared.
pub(crate) fn line_core<R: Field>(p: &V3<R>, l: &LineData<R>) -> LineProjection<R, R> {
    let tm = line_terms(p, l);
    let t = tm.tnum.divide(&tm.dd);
    let stationary = LineFoot {
        foot: Vector3::from(tm.footnum.map(|x| x.divide(&tm.dd))),
        t: t.clone(),
        distance: tm.dist2num.divide(&tm.dd),
    };
    let clamp = match &l.ends {
        [Some(a), _] if t.compare(a).is_lt() => Some(a.clone()),
        [_, Some(b)] if t.compare(b).is_gt() => Some(b.clone()),
        _ => None,
    };
    match clamp {
        None => LineProjection {
            stationary: Some(stationary.clone()),
            nearest: stationary,
        },
        Some(tc) => {
            let foot = [0, 1, 2].map(|i| l.o[i].plus(&tc.times(&l.d[i])));
            let diff = sub3(p, &foot);
            LineProjection {
                stationary: None,
                nearest: LineFoot {
                    foot: Vector3::from(foot),
                    t: tc,
                    distance: dot3(&diff, &diff),
                },
            }
        }
    }
}

/// The exact procedure for point → plane; the distance as `(f², f)` over `|N|²`.
pub(crate) fn plane_core<R: Field>(p: &V3<R>, q: &PlaneData<R>) -> PlaneProjection<R, (R, R)> {
    let tm = plane_terms(p, q);
    PlaneProjection {
        foot: Vector3::from(tm.footnum.map(|x| x.divide(&tm.nn))),
        uv: tm
            .uv
            .map(|([u, v], g)| Vector2::new(u.divide(&g), v.divide(&g))),
        distance: (tm.f.times(&tm.f).divide(&tm.nn), tm.f),
    }
}

fn map_foot<S: Scalar, L, T: Scalar, K>(
    x: LineFoot<S, L>,
    f: &mut impl FnMut(S) -> T,
    g: &mut impl FnMut(L) -> K,
) -> LineFoot<T, K> {
    LineFoot {
        foot: x.foot.map(&mut *f),
        t: f(x.t),
        distance: g(x.distance),
    }
}

fn map_line<S: Scalar, L, T: Scalar, K>(
    x: LineProjection<S, L>,
    mut f: impl FnMut(S) -> T,
    mut g: impl FnMut(L) -> K,
) -> LineProjection<T, K> {
    LineProjection {
        stationary: x.stationary.map(|s| map_foot(s, &mut f, &mut g)),
        nearest: map_foot(x.nearest, &mut f, &mut g),
    }
}

/// Plain f64 point → line / ranged line / segment.
pub fn project_point_line_f64(p: &Vector3<f64>, line: Linear<f64>) -> LineProjection<f64, f64> {
    let p = [p[0], p[1], p[2]];
    map_line(line_core::<f64>(&p, &line.data()), |x| x, f64::sqrt)
}

/// Exact point → line / ranged line / segment on rational inputs.
pub fn project_point_line_exact(
    p: &Vector3<rug::Rational>,
    line: Linear<Rational>,
) -> LineProjection<Rational, ExactLength> {
    let p: V3<Rational> = [p[0].clone(), p[1].clone(), p[2].clone()];
    map_line(
        line_core::<Rational>(&p, &line.data()),
        |x| x,
        |d| ExactLength {
            rounded: sqrt_rational(&d),
            squared: d,
            negative: false,
        },
    )
}

/// Certified point → line / ranged line / segment.
pub fn project_point_line(
    p: &Vector3<f64>,
    line: Linear<f64>,
) -> Certified<LineProjection<Rounded, Rounded>> {
    if let Some(r) = fast_line_dispatch(p, line) {
        return filter_certified(r);
    }
    let pq: V3<Rational> = [p[0].lift(), p[1].lift(), p[2].lift()];
    let exact = line_core::<Rational>(&pq, &line.data());
    let r = std::cell::RefCell::new(Rounder::default());
    let value = map_line(
        exact,
        |x| r.borrow_mut().round(x),
        |d| r.borrow_mut().sqrt(&d),
    );
    let c = r.borrow().certify(value);
    c
}

/// Plain f64 point → plane (signed distance).
pub fn project_point_plane_f64(p: &Vector3<f64>, plane: &Plane<f64>) -> PlaneProjection<f64, f64> {
    let pr = plane_core::<f64>(&[p[0], p[1], p[2]], &PlaneData::new(plane));
    let (d2, f) = pr.distance;
    PlaneProjection {
        foot: pr.foot,
        uv: pr.uv,
        distance: d2.sqrt().copysign(f),
    }
}

/// Exact point → plane on rational inputs.
pub fn project_point_plane_exact(
    p: &Vector3<Rational>,
    plane: &Plane<Rational>,
) -> PlaneProjection<Rational, ExactLength> {
    let pq: V3<Rational> = [p[0].clone(), p[1].clone(), p[2].clone()];
    let pr = plane_core::<Rational>(&pq, &PlaneData::new(plane));
    let (d2, f) = pr.distance;
    PlaneProjection {
        foot: pr.foot,
        uv: pr.uv,
        distance: signed_length(d2, f.cmp0().is_lt()),
    }
}

fn signed_length(squared: Rational, negative: bool) -> ExactLength {
    let mut rounded = sqrt_rational(&squared);
    if negative {
        rounded = Rounded {
            nearest: -rounded.nearest,
            lo: -rounded.hi,
            hi: -rounded.lo,
        };
    }
    ExactLength {
        squared,
        negative,
        rounded,
    }
}

/// Certified point → plane.
pub fn project_point_plane(
    p: &Vector3<f64>,
    plane: &Plane<f64>,
) -> Certified<PlaneProjection<Rounded, Rounded>> {
    if let Some(r) = fast_plane_dispatch(p, plane) {
        return filter_certified(r);
    }
    let pq: V3<Rational> = [p[0].lift(), p[1].lift(), p[2].lift()];
    let pr = plane_core::<Rational>(&pq, &PlaneData::new(plane));
    let mut r = Rounder::default();
    let (d2, f) = pr.distance;
    let mut dist = r.sqrt(&d2);
    if f.cmp0().is_lt() {
        dist = Rounded {
            nearest: -dist.nearest,
            lo: -dist.hi,
            hi: -dist.lo,
        };
    }
    let value = PlaneProjection {
        foot: pr.foot.map(|x| r.round(x)),
        uv: pr.uv.map(|uv| uv.map(|x| r.round(x))),
        distance: dist,
    };
    r.certify(value)
}

/// The correctly rounded `√(A/B)` (or `√(A²/B)` when `square`) from double-double
/// enclosures `A ± ea`, `B ± eb` (B > 0): MPFR at 128 bits with directed rounding gives
/// `lo ≤ √· ≤ hi`; accepted when both round to the same double `c` and `c` lies outside
/// `[lo, hi]` (so the side, hence the enclosure, is known).
fn sqrt_enclosure<M: ProductMode>(
    a: &Dd<M>,
    ea: f64,
    b: &Dd<M>,
    eb: f64,
    square: bool,
) -> Option<Rounded> {
    let prec = 128;
    // x ± e with outward rounding: [(h + l)↓ − e↓, (h + l)↑ + e↑].
    let enclose = |x: &Dd<M>, e: f64| {
        let h = Float::with_val(prec, x.h);
        let lo = Float::with_val_round(prec, &h + x.l, Round::Down).0;
        let hi = Float::with_val_round(prec, &h + x.l, Round::Up).0;
        (
            Float::with_val_round(prec, &lo - e, Round::Down).0,
            Float::with_val_round(prec, &hi + e, Round::Up).0,
        )
    };
    let (mut a_lo, mut a_hi) = enclose(a, ea);
    if square {
        let (x, y) = (a_lo.clone().abs(), a_hi.clone().abs());
        if a_lo.is_sign_negative() && a_hi.is_sign_positive() {
            return None;
        }
        let (small, big) = if x < y { (x, y) } else { (y, x) };
        a_lo = Float::with_val_round(prec, small.square_ref(), Round::Down).0;
        a_hi = Float::with_val_round(prec, big.square_ref(), Round::Up).0;
    }
    if a_lo.is_sign_negative() || a_lo.is_zero() {
        return None;
    }
    let (b_lo, b_hi) = enclose(b, eb);
    if !b_lo.is_sign_positive() || b_lo.is_zero() {
        return None;
    }
    let mut lo = Float::with_val_round(prec, &a_lo / &b_hi, Round::Down).0;
    lo.sqrt_round(Round::Down);
    let mut hi = Float::with_val_round(prec, &a_hi / &b_lo, Round::Up).0;
    hi.sqrt_round(Round::Up);
    let c = lo.to_f64_round(Round::Nearest);
    let c_hi = hi.to_f64_round(Round::Nearest);
    // Normal range only (to_f64 of a float below 2^-1022 would need subnormal care).
    if c != c_hi || !(c.abs() >= f64::MIN_POSITIVE && c.is_finite()) {
        return None;
    }
    if Float::with_val(prec, c) < lo {
        Some(Rounded::inexact(c, std::cmp::Ordering::Greater))
    } else if Float::with_val(prec, c) > hi {
        Some(Rounded::inexact(c, std::cmp::Ordering::Less))
    } else {
        None
    }
}

/// Filter constants (`k·u²`), re-derived by `tests::filter_constants` (rules as in
/// `line_plane`): line `t` numerator, `|c'|²`, foot numerators, `|w × c'|²`; plane `f`,
/// `|N|²`, foot numerators, `(u, v)` numerators, `G`.
const EPS_L: [f64; 4] = [
    306.0 * U * U,
    306.0 * U * U,
    1986.0 * U * U,
    20202.0 * U * U,
];
const EPS_P: [f64; 5] = [
    452.0 * U * U,
    622.0 * U * U,
    3286.0 * U * U,
    2597.0 * U * U,
    1062.0 * U * U,
];

fn fast_line_dispatch(
    p: &Vector3<f64>,
    line: Linear<f64>,
) -> Option<LineProjection<Rounded, Rounded>> {
    dispatch_fma!(fast_line(p: &Vector3<f64>, line: Linear<f64>,) -> Option<LineProjection<Rounded, Rounded>>)
}

fn fast_plane_dispatch(
    p: &Vector3<f64>,
    plane: &Plane<f64>,
) -> Option<PlaneProjection<Rounded, Rounded>> {
    dispatch_fma!(fast_plane(p: &Vector3<f64>, plane: &Plane<f64>,) -> Option<PlaneProjection<Rounded, Rounded>>)
}

/// Filter tier for point → line when the stationary foot is inside the domain. Groups:
/// positions `P` (the point, the origin or end points), direction `L` (`P` for a
/// segment). Degrees: `t`: `P L / L²`; foot: `P L² / L²`; squared distance: `P² L² / L²`.
#[inline(always)]
fn fast_line<M: ProductMode>(
    p: &Vector3<f64>,
    line: Linear<f64>,
) -> Option<LineProjection<Rounded, Rounded>> {
    let (mp, ml) = RawLine::new(line).scales();
    let (mp, ml) = (accepted(mp.max(scale_of(p.as_slice())))?, accepted(ml)?);
    let ml = if line_is_segment(&line) {
        ml.max(mp)
    } else {
        ml
    };
    let l: LineData<Dd<M>> = line.data();
    let pd: V3<Dd<M>> = [p[0].lift(), p[1].lift(), p[2].lift()];
    let tm = line_terms(&pd, &l);
    let e_dd = bound(EPS_L[1], &[ml, ml]);
    let dd = Denominator::new(&tm.dd, e_dd)?;
    let t = round_over(&tm.tnum, bound(EPS_L[0], &[mp, ml]), &dd)?;
    let inside = line.bounds_contain(&t);
    if !inside {
        return None;
    }
    let e_f = bound(EPS_L[2], &[mp, ml, ml]);
    let foot = each!(i in [0, 1, 2] => round_over(&tm.footnum[i], e_f, &dd));
    let [Some(f0), Some(f1), Some(f2)] = foot else {
        return None;
    };
    let distance = sqrt_enclosure(
        &tm.dist2num,
        bound(EPS_L[3], &[mp, mp, ml, ml]),
        &tm.dd,
        e_dd,
        false,
    )?;
    let foot = LineFoot {
        foot: Vector3::new(f0, f1, f2),
        t,
        distance,
    };
    Some(LineProjection {
        stationary: Some(foot.clone()),
        nearest: foot,
    })
}

fn line_is_segment(l: &Linear<f64>) -> bool {
    matches!(l, Linear::Segment(_))
}

/// Filter tier for point → plane. Groups `P` (the point, the origin, `|d|/m_n`) and
/// `G`; with `S = m^k`: `f`: `P S`; `|N|²`: `S²`; foot: `P S²`; `(u, v)`: `P G³ / G⁴`.
#[inline(always)]
fn fast_plane<M: ProductMode>(
    p: &Vector3<f64>,
    plane: &Plane<f64>,
) -> Option<PlaneProjection<Rounded, Rounded>> {
    let (mg, s, mp) = RawPlane::new(plane).scales(scale_of(p.as_slice()));
    let (mg, s, mp) = (accepted(mg)?, accepted(s)?, accepted(mp)?);
    let q: PlaneData<Dd<M>> = PlaneData::new(plane);
    let pd: V3<Dd<M>> = [p[0].lift(), p[1].lift(), p[2].lift()];
    let tm = plane_terms(&pd, &q);
    let e_nn = bound(EPS_P[1], &[s, s]);
    let nn = Denominator::new(&tm.nn, e_nn)?;
    let e_foot = bound(EPS_P[2], &[mp, s, s]);
    let foot = each!(i in [0, 1, 2] => round_over(&tm.footnum[i], e_foot, &nn));
    let [Some(f0), Some(f1), Some(f2)] = foot else {
        return None;
    };
    let uv = match &tm.uv {
        Some(([un, vn], g)) => {
            let e_g = bound(EPS_P[4], &[mg, mg, mg, mg]);
            let g = Denominator::new(g, e_g)?;
            let e = bound(EPS_P[3], &[mp, mg, mg, mg]);
            Some(Vector2::new(round_over(un, e, &g)?, round_over(vn, e, &g)?))
        }
        None => None,
    };
    let e_f = bound(EPS_P[0], &[mp, s]);
    let negative = sign_of(&tm.f, e_f)?.is_lt();
    let mut distance = sqrt_enclosure(&tm.f, e_f, &tm.nn, e_nn, true)?;
    if negative {
        distance = Rounded {
            nearest: -distance.nearest,
            lo: -distance.hi,
            hi: -distance.lo,
        };
    }
    Some(PlaneProjection {
        foot: Vector3::new(f0, f1, f2),
        uv,
        distance,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geom::plane_plane::bound_planes;
    use crate::num::error_bound::ErrorBound;

    #[test]
    fn filter_constants() {
        let i = ErrorBound::INPUT;
        let mut wl = [ErrorBound::zero(); 4];
        for d in [[i; 3], [i.minus(&i); 3]] {
            let t = line_terms(
                &[i; 3],
                &LineData {
                    o: [i; 3],
                    d,
                    ends: [None, None],
                },
            );
            let all = [
                t.tnum,
                t.dd,
                t.footnum.iter().fold(ErrorBound::zero(), |m, x| m.max(*x)),
                t.dist2num,
            ];
            for k in 0..4 {
                wl[k] = wl[k].max(all[k]);
            }
        }
        let mut wp = [ErrorBound::zero(); 5];
        for q in &bound_planes() {
            let t = plane_terms(&[i; 3], q);
            let foot = t.footnum.iter().fold(ErrorBound::zero(), |m, x| m.max(*x));
            let (uv, g) =
                t.uv.map(|(n, g)| (n[0].max(n[1]), g))
                    .unwrap_or((ErrorBound::zero(), ErrorBound::zero()));
            let all = [t.f, t.nn, foot, uv, g];
            for k in 0..5 {
                wp[k] = wp[k].max(all[k]);
            }
        }
        println!("derived line (u²): {:?}", wl.map(|x| x.e_in_u2()));
        println!("derived plane (u²): {:?}", wp.map(|x| x.e_in_u2()));
        for (x, c) in wl.iter().zip(EPS_L).chain(wp.iter().zip(EPS_P)) {
            assert!(
                c >= x.e,
                "constant {} u² below the derived {} u²",
                c / (U * U),
                x.e_in_u2()
            );
        }
    }
}
