//! Two 2D lines, ranged lines or segments (OPERATIONS.md §6.1 eq. (6.1), §6.2 eq. (6.2)).
//!
//! `l₁(t₁) = p₁ + t₁c₁'`, `l₂(t₂) = p₂ + t₂c₂'` (a segment `(a, b)` is `a + t(b − a)`,
//! `t ∈ [0, 1]`, so (6.2)'s `p₃ = b₁`, `p₄ = b₂`), `d = p₂ − p₁`, `Δ = c₁' × c₂'`:
//! `t₁ = (d × c₂')/Δ`, `t₂ = (d × c₁')/Δ`, `p = (p₁Δ + (d × c₂')c₁')/Δ` — (6.1) with the
//! unit normals cancelled (and (6.2) up to the sign convention of `Δ`).
//!
//! `Δ = 0` exactly: parallel (`Empty(Parallel)`) unless `d × c₁' = 0` (collinear). Collinear
//! unbounded lines coincide (`Line`). Otherwise the second domain is mapped onto the
//! first line's parameter, `t₁(t₂) = (d·c₁' + t₂ c₂'·c₁')/|c₁'|²`, and intersected with the
//! first domain: empty (`CollinearDisjoint`), one point (touching at an end point), or
//! the overlap `Segment` with the parameters of its ends on both inputs
//! (`t₂(t₁) = (t₁c₁' − d)·c₂'/|c₂'|²`). Touching at an end point of a crossing is a
//! `Point` with `t = 0` or `1`.

use nalgebra::{Scalar, Vector2};
use rug::Rational;
use std::cmp::Ordering;

use super::data::{Line2Data, Linear2};
use super::exact_tier::{
    filter_certified, ring_tier, ExactRing, Rounder, SmallInteger, WideInteger,
};
use crate::certificate::Certified;
use crate::num::dd::{Dd, ProductMode, U};
use crate::num::expansion::Expansion;
use crate::num::filter::{bound, dispatch_fma, group_scale, round_over, Denominator};
use crate::num::ratio::Ratio;
use crate::num::ring::{cross2, dot2, each, sub2, Field, Ring, V2};
use crate::num::round::Rounded;

/// Why two 2D linear objects do not meet.
#[derive(Debug, Clone, PartialEq)]
pub enum Empty2<S: Scalar> {
    /// Parallel, distinct carriers.
    Parallel,
    /// Collinear, with disjoint domains.
    CollinearDisjoint,
    /// The carriers meet at `point` (parameters `t1`, `t2`) outside a domain.
    OutsideDomain { point: Vector2<S>, t1: S, t2: S },
}

/// The result of two 2D linear objects.
#[derive(Debug, Clone, PartialEq)]
pub enum Intersection2<S: Scalar> {
    /// One point (a crossing, or collinear objects touching at an end point).
    Point {
        point: Vector2<S>,
        t1: S,
        t2: S,
    },
    /// Collinear overlap from `a` to `b`; `a_params = (t1, t2)` of `a`, likewise `b`
    /// (`a` has the smaller `t1`).
    Segment {
        a: Vector2<S>,
        b: Vector2<S>,
        a_params: Vector2<S>,
        b_params: Vector2<S>,
    },
    /// Two coincident unbounded lines.
    Line,
    Empty(Empty2<S>),
}

impl<S: Scalar> Intersection2<S> {
    /// Apply `f` to every number.
    pub fn map<T: Scalar>(self, mut f: impl FnMut(S) -> T) -> Intersection2<T> {
        match self {
            Intersection2::Point { point, t1, t2 } => Intersection2::Point {
                point: point.map(&mut f),
                t1: f(t1),
                t2: f(t2),
            },
            Intersection2::Segment {
                a,
                b,
                a_params,
                b_params,
            } => Intersection2::Segment {
                a: a.map(&mut f),
                b: b.map(&mut f),
                a_params: a_params.map(&mut f),
                b_params: b_params.map(&mut f),
            },
            Intersection2::Line => Intersection2::Line,
            Intersection2::Empty(Empty2::OutsideDomain { point, t1, t2 }) => {
                Intersection2::Empty(Empty2::OutsideDomain {
                    point: point.map(&mut f),
                    t1: f(t1),
                    t2: f(t2),
                })
            }
            Intersection2::Empty(Empty2::Parallel) => Intersection2::Empty(Empty2::Parallel),
            Intersection2::Empty(Empty2::CollinearDisjoint) => {
                Intersection2::Empty(Empty2::CollinearDisjoint)
            }
        }
    }
}

/// The polynomials of the crossing case.
pub(crate) struct Terms<R> {
    pub delta: R,
    pub t1n: R,
    pub t2n: R,
    pub pnum: V2<R>,
}

#[cfg(test)] // the filter-constant tests; the kernel calls `terms_from` after its decision
#[inline(always)]
pub(crate) fn terms<R: Ring>(a: &Line2Data<R>, b: &Line2Data<R>) -> Terms<R> {
    terms_from(a, b, cross2(&a.d, &b.d))
}

/// The numerators given `Δ`.
#[inline(always)]
pub(crate) fn terms_from<R: Ring>(a: &Line2Data<R>, b: &Line2Data<R>, delta: R) -> Terms<R> {
    let d = sub2(&b.o, &a.o);
    let t1n = cross2(&d, &b.d);
    let t2n = cross2(&d, &a.d);
    let pnum = each!(i in [0, 1] => a.o[i].times(&delta).plus(&t1n.times(&a.d[i])));
    Terms {
        delta,
        t1n,
        t2n,
        pnum,
    }
}

fn in_range<R: Field>(t: &R, range: &Option<[R; 2]>) -> bool {
    range
        .as_ref()
        .is_none_or(|[a, b]| t.compare(a).is_ge() && t.compare(b).is_le())
}

/// The exact decision procedure, generic over the field.
pub(crate) fn core<R: Field>(a: &Line2Data<R>, b: &Line2Data<R>) -> Intersection2<R> {
    let delta = cross2(&a.d, &b.d);
    if !delta.is_zero() {
        let tm = terms_from(a, b, delta);
        let t1 = tm.t1n.divide(&tm.delta);
        let t2 = tm.t2n.divide(&tm.delta);
        let point = Vector2::new(tm.pnum[0].divide(&tm.delta), tm.pnum[1].divide(&tm.delta));
        return if in_range(&t1, &a.range) && in_range(&t2, &b.range) {
            Intersection2::Point { point, t1, t2 }
        } else {
            Intersection2::Empty(Empty2::OutsideDomain { point, t1, t2 })
        };
    }
    let d = sub2(&b.o, &a.o);
    if !cross2(&d, &a.d).is_zero() {
        return Intersection2::Empty(Empty2::Parallel);
    }
    if a.range.is_none() && b.range.is_none() {
        return Intersection2::Line;
    }
    let aa = dot2(&a.d, &a.d);
    let bb = dot2(&b.d, &b.d);
    let ab = dot2(&a.d, &b.d);
    let da = dot2(&d, &a.d);
    let to_t1 = |t2: &R| da.plus(&t2.times(&ab)).divide(&aa);
    let to_t2 = |t1: &R| dot2(&sub2(&[t1.times(&a.d[0]), t1.times(&a.d[1])], &d), &b.d).divide(&bb);
    // The second domain on the first line, ordered.
    let second = b.range.as_ref().map(|[lo, hi]| {
        let (x, y) = (to_t1(lo), to_t1(hi));
        if ab.sign() == Ordering::Less {
            (y, x)
        } else {
            (x, y)
        }
    });
    let (lo, hi) = match (&a.range, second) {
        (Some([a0, a1]), Some((b0, b1))) => {
            let lo = if a0.compare(&b0).is_ge() {
                a0.clone()
            } else {
                b0
            };
            let hi = if a1.compare(&b1).is_le() {
                a1.clone()
            } else {
                b1
            };
            (lo, hi)
        }
        (Some([a0, a1]), None) => (a0.clone(), a1.clone()),
        (None, Some((b0, b1))) => (b0, b1),
        (None, None) => return Intersection2::Line,
    };
    let at = |t: &R| {
        Vector2::new(
            a.o[0].plus(&t.times(&a.d[0])),
            a.o[1].plus(&t.times(&a.d[1])),
        )
    };
    match lo.compare(&hi) {
        Ordering::Greater => Intersection2::Empty(Empty2::CollinearDisjoint),
        Ordering::Equal => Intersection2::Point {
            point: at(&lo),
            t2: to_t2(&lo),
            t1: lo,
        },
        Ordering::Less => Intersection2::Segment {
            a: at(&lo),
            b: at(&hi),
            a_params: Vector2::new(lo.clone(), to_t2(&lo)),
            b_params: Vector2::new(hi.clone(), to_t2(&hi)),
        },
    }
}

/// Plain f64 (uncertified; `Δ == 0.0` decides parallelism).
pub fn intersect_line2_line2_f64(a: Linear2<f64>, b: Linear2<f64>) -> Intersection2<f64> {
    core::<f64>(&a.data(), &b.data())
}

/// Exact, on rational inputs.
pub fn intersect_line2_line2_exact(
    a: Linear2<Rational>,
    b: Linear2<Rational>,
) -> Intersection2<Rational> {
    core::<Rational>(&a.data(), &b.data())
}

/// Certified: exact verdict, correctly rounded point and parameters.
pub fn intersect_line2_line2(
    a: Linear2<f64>,
    b: Linear2<f64>,
) -> Certified<Intersection2<Rounded>> {
    dispatch_fma!(certified(a: Linear2<f64>, b: Linear2<f64>) -> Certified<Intersection2<Rounded>>)
}

/// The filter, then the exact tiers (instantiated once per product mode, so that the
/// answer is built in place).
#[inline(always)]
fn certified<M: ProductMode>(
    a: Linear2<f64>,
    b: Linear2<f64>,
) -> Certified<Intersection2<Rounded>> {
    match fast::<M>(a, b) {
        Some(r) => filter_certified(r),
        None => exact_tiers(a, b),
    }
}

/// The exact tiers in order of cost: 128-bit integers, 768-bit integers, expansions,
/// rationals (which always answer). Out of line, so that the filter's caller keeps a
/// small stack frame.
#[cold]
#[inline(never)]
fn exact_tiers(a: Linear2<f64>, b: Linear2<f64>) -> Certified<Intersection2<Rounded>> {
    ring_tier_answer::<SmallInteger>(a, b)
        .or_else(|| ring_tier_answer::<WideInteger>(a, b))
        .or_else(|| ring_tier_answer::<Expansion>(a, b))
        .unwrap_or_else(|| rational_tier(a, b))
}

/// The last tier, in `rug::Rational`.
#[inline(never)]
fn rational_tier(a: Linear2<f64>, b: Linear2<f64>) -> Certified<Intersection2<Rounded>> {
    let mut r = Rounder::default();
    let value = core::<Rational>(&a.data(), &b.data()).map(|q| r.round(q));
    r.certify(value)
}

/// The exact decision in the ring `E` ([`ring_tier`]): `None` when `E` lost exactness.
#[inline(always)]
fn ring_tier_answer<E: ExactRing>(
    a: Linear2<f64>,
    b: Linear2<f64>,
) -> Option<Certified<Intersection2<Rounded>>> {
    ring_tier::<E, _>(|r| core::<Ratio<E>>(&a.data(), &b.data()).map(|q| r.round(q)))
}

/// Filter constants (`k·u²`), re-derived by `tests::filter_constants` (rules as in
/// `line_plane`, worst over lines and segments): `Δ`, the `t` numerators, the point
/// numerators.
const EPS_DELTA: f64 = 155.0 * U * U;
const EPS_T: f64 = 155.0 * U * U;
const EPS_P: f64 = 1109.0 * U * U;

/// Scales `(positions, direction)` of a 2D linear object.
fn scales(l: &Linear2<f64>) -> Option<(f64, f64)> {
    match l {
        Linear2::Line(l) => Some((
            group_scale(l.origin().as_slice())?,
            group_scale(l.dir().as_slice())?,
        )),
        Linear2::Segment(s) => {
            let m = group_scale(s.a().as_slice())?.max(group_scale(s.b().as_slice())?);
            Some((m, m))
        }
    }
}

fn range_of(l: &Linear2<f64>) -> Option<[f64; 2]> {
    match l {
        Linear2::Line(l) => l.range().copied(),
        Linear2::Segment(_) => Some([0.0, 1.0]),
    }
}

/// The filter tier (crossing case). Groups `P`, `L₁`, `L₂`; degrees `Δ`: `L₁L₂`;
/// `t₁` numerator: `P L₂`; `t₂`: `P L₁`; point numerators: `P L₁ L₂`.
#[inline(always)]
fn fast<M: ProductMode>(a: Linear2<f64>, b: Linear2<f64>) -> Option<Intersection2<Rounded>> {
    let (pa, l1) = scales(&a)?;
    let (pb, l2) = scales(&b)?;
    let mp = pa.max(pb);
    let da: Line2Data<Dd<M>> = a.data();
    let db: Line2Data<Dd<M>> = b.data();
    // The decision first: preparing Δ proves Δ ≠ 0.
    let d = cross2(&da.d, &db.d);
    let e_delta = bound(EPS_DELTA, &[l1, l2]);
    let delta = Denominator::new(&d, e_delta)?;
    let tm = terms_from(&da, &db, d);
    let t1 = round_over(&tm.t1n, bound(EPS_T, &[mp, l2]), &delta)?;
    let t2 = round_over(&tm.t2n, bound(EPS_T, &[mp, l1]), &delta)?;
    let e_p = bound(EPS_P, &[mp, l1, l2]);
    let point = Vector2::new(
        round_over(&tm.pnum[0], e_p, &delta)?,
        round_over(&tm.pnum[1], e_p, &delta)?,
    );
    let inside = |t: &Rounded, r: Option<[f64; 2]>| {
        r.is_none_or(|[lo, hi]| t.compare_f64(lo).is_ge() && t.compare_f64(hi).is_le())
    };
    Some(if inside(&t1, range_of(&a)) && inside(&t2, range_of(&b)) {
        Intersection2::Point { point, t1, t2 }
    } else {
        Intersection2::Empty(Empty2::OutsideDomain { point, t1, t2 })
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::num::error_bound::ErrorBound;

    #[test]
    fn filter_constants() {
        let i = ErrorBound::INPUT;
        let kinds = [[i; 2], [i.minus(&i); 2]];
        let mut w = [ErrorBound::zero(); 3];
        for d1 in &kinds {
            for d2 in &kinds {
                let a = Line2Data {
                    o: [i; 2],
                    d: *d1,
                    range: None,
                };
                let b = Line2Data {
                    o: [i; 2],
                    d: *d2,
                    range: None,
                };
                let t = terms(&a, &b);
                w[0] = w[0].max(t.delta);
                w[1] = w[1].max(t.t1n).max(t.t2n);
                w[2] = w[2].max(t.pnum[0]).max(t.pnum[1]);
            }
        }
        println!("derived (u²): {:?}", w.map(|x| x.e_in_u2()));
        for (x, c) in w.iter().zip([EPS_DELTA, EPS_T, EPS_P]) {
            assert!(
                c >= x.e,
                "constant {} u² below the derived {} u²",
                c / (U * U),
                x.e_in_u2()
            );
        }
    }
}
