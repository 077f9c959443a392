//! The filter tier of line ∩ line: the crossing formulas of [`super::procedure`] in
//! double-double with static error bounds ([`crate::num::filter`]), for objects whose
//! directions are provably not parallel. A decided `w·n ≠ 0` is a skew verdict; an
//! undecided one (every crossing: coplanarity is an exact zero) is settled by the exact
//! sign of `w·n = det(w, d₁, d₂)` in exact rings of rising cost; then the point and
//! both parameters are rounded over the decided denominator `n_k`.

use nalgebra::Vector3;
use rug::Rational;
use std::cmp::Ordering;

use super::procedure::{carrier, coplanarity, crossing_terms, Carrier};
use super::{LineLine, LineLineEmpty, LineLinePoint};
use crate::certificate::{Arithmetic, Certified};
use crate::geom::data::Linear;
use crate::geom::exact_tier::{filter_certified, ExactRing, SmallInteger, WideInteger};
use crate::geom::raw::RawLine;
use crate::num::dd::{Dd, ProductMode, U};
use crate::num::expansion::{Expansion, Poison};
use crate::num::filter::{accepted, bound, round_over, sign_of, Denominator};
use crate::num::ratio::Ratio;
use crate::num::ring::{cross3, dot3, sub3, Field, V3};
use crate::num::round::Rounded;

/// Filter constants (`k·u²`), re-derived by `tests::filter_constants` with the rules
/// of [`crate::num::error_bound`], worst over lines and segments (a segment's
/// direction `b − a` is a difference of inputs): `n` (each component), `w·n`, the
/// parameter numerators, the point numerators.
const EPS_N: f64 = 155.0 * U * U;
const EPS_S: f64 = 2982.0 * U * U;
const EPS_T: f64 = 155.0 * U * U;
const EPS_P: f64 = 1109.0 * U * U;

/// The ends of a line's (ray's, segment's) domain as doubles, `None` for infinite.
fn bounds(l: Linear<f64>) -> (Option<f64>, Option<f64>) {
    match l {
        Linear::Line(l) => {
            let (lo, hi) = l.bounds();
            (lo.copied(), hi.copied())
        }
        Linear::Segment(_) => (Some(0.0), Some(1.0)),
    }
}

/// Whether the exact value of `t` lies in the domain of `l` (decided on the enclosure:
/// the domain's ends are doubles).
fn inside(t: &Rounded, l: Linear<f64>) -> bool {
    let (lo, hi) = bounds(l);
    lo.is_none_or(|lo| t.compare_f64(lo).is_ge()) && hi.is_none_or(|hi| t.compare_f64(hi).is_le())
}

/// The axis of the largest `|n_k.h|` (any axis gives exact formulas; the largest
/// keeps the denominator far from zero).
#[inline(always)]
fn largest<M: ProductMode>(n: &V3<Dd<M>>) -> usize {
    let [a, b, c] = [n[0].h.abs(), n[1].h.abs(), n[2].h.abs()];
    if a >= b && a >= c {
        0
    } else if b >= c {
        1
    } else {
        2
    }
}

/// The filter tier. Groups: positions `P` (origins, segment end points), directions
/// `L₁`, `L₂` (a segment's in `P`: its end points' scale). Degrees: `n`: `L₁L₂`; `w·n`:
/// `P L₁L₂`; `t₁`, `t₂` numerators: `P L₂`, `P L₁`; point numerators: `P L₁L₂`.
/// `None`: to the exact tiers (parallel or nearly, out of the filter's range, or an
/// output the bounds do not round).
#[inline(always)]
pub(super) fn fast<M: ProductMode>(
    a: Linear<f64>,
    b: Linear<f64>,
) -> Option<Certified<LineLine<Rounded>>> {
    let (pa, l1) = RawLine::new(a).scales();
    let (pb, l2) = RawLine::new(b).scales();
    let (mp, l1, l2) = (accepted(pa.max(pb))?, accepted(l1)?, accepted(l2)?);
    let x: Carrier<Dd<M>> = carrier(a);
    let y: Carrier<Dd<M>> = carrier(b);
    let n = cross3(&x.d, &y.d);
    let k = largest(&n);
    // Decided n_k ≠ 0: the directions are not parallel.
    let den = Denominator::new(&n[k], bound(EPS_N, &[l1, l2]))?;
    let w = sub3(&y.o, &x.o);
    let mut decided_by = None;
    match sign_of(&dot3(&w, &n), bound(EPS_S, &[mp, l1, l2])) {
        Some(Ordering::Equal) => {}
        Some(_) => return Some(filter_certified(LineLine::Empty(LineLineEmpty::Skew))),
        None => {
            let (sign, arithmetic, bits) = exact_coplanarity(a, b);
            if sign.is_ne() {
                let skew = LineLine::Empty(LineLineEmpty::Skew);
                return Some(Certified::exact(skew, arithmetic, bits));
            }
            decided_by = Some((arithmetic, bits));
        }
    }
    let tm = crossing_terms(&x, &y, &w, n[k], k);
    let t1 = round_over(&tm.t1n, bound(EPS_T, &[mp, l2]), &den)?;
    let t2 = round_over(&tm.t2n, bound(EPS_T, &[mp, l1]), &den)?;
    let e_p = bound(EPS_P, &[mp, l1, l2]);
    let point = Vector3::new(
        round_over(&tm.pnum[0], e_p, &den)?,
        round_over(&tm.pnum[1], e_p, &den)?,
        round_over(&tm.pnum[2], e_p, &den)?,
    );
    let p = LineLinePoint { point, t1, t2 };
    let value = if inside(&p.t1, a) && inside(&p.t2, b) {
        LineLine::Point(p)
    } else {
        LineLine::Empty(LineLineEmpty::OutsideDomain(p))
    };
    Some(match decided_by {
        None => filter_certified(value),
        Some((arithmetic, bits)) => Certified::exact(value, arithmetic, bits),
    })
}

/// The exact sign of `w·n = det(o₂ − o₁, d₁, d₂)` (degree 3), in the cheapest exact
/// ring that holds it: 128-bit integers, 768-bit integers, expansions, rationals;
/// with the arithmetic and the bit length that decided it.
#[cold]
#[inline(never)]
pub(super) fn exact_coplanarity(a: Linear<f64>, b: Linear<f64>) -> (Ordering, Arithmetic, u32) {
    sign_in::<SmallInteger>(a, b)
        .or_else(|| sign_in::<WideInteger>(a, b))
        .or_else(|| sign_in::<Expansion>(a, b))
        .unwrap_or_else(|| {
            let s: Rational = coplanarity(&carrier(a), &carrier(b));
            let bits = s.numer().significant_bits().max(1);
            (s.cmp0(), Arithmetic::Rational, bits)
        })
}

/// [`exact_coplanarity`] in the ring `E`: `None` when `E` lost exactness.
#[inline(always)]
fn sign_in<E: ExactRing>(a: Linear<f64>, b: Linear<f64>) -> Option<(Ordering, Arithmetic, u32)> {
    Poison::reset();
    let s: Ratio<E> = coplanarity(&carrier(a), &carrier(b));
    let sign = s.sign();
    (!Poison::is_set()).then(|| (sign, E::ARITHMETIC, s.num.bits()))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::num::error_bound::ErrorBound;
    use crate::num::ring::Ring;

    /// Derive the filter constants from the formulas (every axis `k`, lines and
    /// segments) and check the written ones cover them.
    #[test]
    fn filter_constants() {
        let i = ErrorBound::INPUT;
        let kinds = [[i; 3], [i.minus(&i); 3]];
        let mut worst = [ErrorBound::zero(); 4];
        for d1 in &kinds {
            for d2 in &kinds {
                let x = Carrier { o: [i; 3], d: *d1 };
                let y = Carrier { o: [i; 3], d: *d2 };
                let n = cross3(&x.d, &y.d);
                let w = sub3(&y.o, &x.o);
                for k in 0..3 {
                    let tm = crossing_terms(&x, &y, &w, n[k], k);
                    worst[0] = worst[0].max(tm.den);
                    worst[2] = worst[2].max(tm.t1n).max(tm.t2n);
                    for p in tm.pnum {
                        worst[3] = worst[3].max(p);
                    }
                }
                worst[1] = worst[1].max(coplanarity(&x, &y));
            }
        }
        println!("derived (u²): {:?}", worst.map(|w| w.e_in_u2()));
        for (w, c) in worst.iter().zip([EPS_N, EPS_S, EPS_T, EPS_P]) {
            assert!(
                c >= w.e,
                "constant {} u² below the derived {} u²",
                c / (U * U),
                w.e_in_u2()
            );
        }
    }
}
