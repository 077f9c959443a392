//! The filter tier of line ∩ line: the crossing formulas of [`super::procedure`] in
//! double-double with static error bounds ([`crate::num::filter`]), for objects whose
//! directions are provably not parallel. A decided `w·n ≠ 0` is a skew verdict; an
//! undecided one (every crossing: coplanarity is an exact zero) is settled by the exact
//! sign of `w·n = det(w, d₁, d₂)` in exact rings of rising cost; then the point and
//! both parameters are rounded over the decided denominator `n_k`.

use nalgebra::Vector3;
use rug::Rational;
use std::cmp::Ordering;

#[cfg(test)]
use super::procedure::coplanarity;
use super::procedure::{carrier, coplanarity_terms, crossing_terms, Carrier};
use super::{LineLine, LineLineEmpty, LineLinePoint};
use crate::certificate::{Arithmetic, Certified};
use crate::geom::data::Linear;
use crate::geom::exact_tier::{filter_certified, ExactRing, SmallInteger, WideInteger};
use crate::geom::raw::RawLine;
use crate::num::dd::{Dd, ProductMode, U};
use crate::num::expansion::{Expansion, Poison};
use crate::num::filter::{accepted, bound, round_over, sign_of, Denominator};
use crate::num::ratio::Ratio;
use crate::num::ring::{cross3, dot3, sub3, Field, Ring, V3};
use crate::num::round::Rounded;

/// Filter constants (`k·u²`), re-derived by `tests::filter_constants` with the rules
/// of [`crate::num::error_bound`], worst over lines and segments (a segment's
/// direction `b − a` is a difference of inputs): `n` (each component), `w·n`, the
/// parameter numerators, the point numerators.
const EPS_N: f64 = 155.0 * U * U;
const EPS_S: f64 = 2982.0 * U * U;
const EPS_T: f64 = 155.0 * U * U;
const EPS_P: f64 = 1109.0 * U * U;

/// The crossing point of both carriers: a point, or outside a domain.
fn answer(p: LineLinePoint<Rounded>, a: Linear<f64>, b: Linear<f64>) -> LineLine<Rounded> {
    if a.bounds_contain(&p.t1) && b.bounds_contain(&p.t2) {
        LineLine::Point(p)
    } else {
        LineLine::Empty(LineLineEmpty::OutsideDomain(p))
    }
}

/// The points an object gives as doubles, with their parameters: a line's origin
/// (`t = 0`), a segment's ends (`t = 0`, `1`).
fn given_points(l: Linear<'_, f64>) -> [Option<(f64, &Vector3<f64>)>; 2] {
    match l {
        Linear::Line(l) => [Some((0.0, l.origin())), None],
        Linear::Segment(s) => [Some((0.0, s.a())), Some((1.0, s.b()))],
    }
}

/// A point given by both objects (equal as doubles, hence exactly), with its
/// parameters on each; `+0` for a zero coordinate. Of objects with non-parallel
/// directions, at most one point is common, so the first found is their crossing.
fn shared_point(a: Linear<f64>, b: Linear<f64>) -> Option<(Vector3<f64>, f64, f64)> {
    for (t1, p) in given_points(a).into_iter().flatten() {
        for (t2, q) in given_points(b).into_iter().flatten() {
            if p == q {
                return Some((p.map(|x| x + 0.0), t1, t2));
            }
        }
    }
    None
}

/// Whether every input double has at most 42 significant bits (its odd integer
/// significand), so that a product of three may fit the 128-bit tier; otherwise
/// that tier is skipped (it would only overflow).
fn short_data(a: Linear<f64>, b: Linear<f64>) -> bool {
    let short = |x: &f64| {
        let bits = x.to_bits();
        let m = if bits & (0x7ff << 52) == 0 {
            bits & ((1 << 52) - 1)
        } else {
            (bits & ((1 << 52) - 1)) | (1 << 52)
        };
        m == 0 || 64 - m.leading_zeros() - m.trailing_zeros() <= 42
    };
    let all = |l: Linear<f64>| match l {
        Linear::Line(l) => l.origin().iter().chain(l.dir().iter()).all(short),
        Linear::Segment(s) => s.a().iter().chain(s.b().iter()).all(short),
    };
    all(a) && all(b)
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

/// What the filter tier leaves to the exact tiers.
#[allow(clippy::large_enum_variant)] // returned once, inlined: boxing would allocate
pub(super) enum Filtered {
    /// Decided: by the filter alone, or with the coplanarity decided exactly.
    Done(Certified<LineLine<Rounded>>),
    /// Coplanar carriers (proven) with `n_k ≠ 0` (proven) whose point or parameters the
    /// filter did not round (a value that may be a double, or out of its range): the
    /// crossing formulas alone in the exact tiers, from `from` on (the cheaper ones
    /// already failed on the coplanarity, of the same degree).
    Crossing { k: usize, from: Tier },
    /// Nothing that helps: the whole procedure in the exact tiers.
    Undecided,
}

/// The exact rings in order of cost.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub(super) enum Tier {
    Small,
    Wide,
    Expansion,
    Rational,
}

impl Tier {
    fn arithmetic(self) -> Arithmetic {
        match self {
            Tier::Small | Tier::Wide => Arithmetic::Integer,
            Tier::Expansion => Arithmetic::Expansion,
            Tier::Rational => Arithmetic::Rational,
        }
    }
}

/// The filter tier. Groups: positions `P` (origins, segment end points), directions
/// `L₁`, `L₂` (a segment's in `P`: its end points' scale). Degrees: `n`: `L₁L₂`; `w·n`:
/// `P L₁L₂`; `t₁`, `t₂` numerators: `P L₂`, `P L₁`; point numerators: `P L₁L₂`.
/// Parallel or nearly parallel directions and data out of the filter's range are
/// [`Filtered::Undecided`].
#[inline(always)]
pub(super) fn fast<M: ProductMode>(a: Linear<f64>, b: Linear<f64>) -> Filtered {
    let (pa, l1) = RawLine::new(a).scales();
    let (pb, l2) = RawLine::new(b).scales();
    let (Some(mp), Some(l1), Some(l2)) = (accepted(pa.max(pb)), accepted(l1), accepted(l2)) else {
        return Filtered::Undecided;
    };
    let x: Carrier<Dd<M>> = carrier(a);
    let y: Carrier<Dd<M>> = carrier(b);
    let n = cross3(&x.d, &y.d);
    let k = largest(&n);
    // Decided n_k ≠ 0: the directions are not parallel.
    let Some(den) = Denominator::new(&n[k], bound(EPS_N, &[l1, l2])) else {
        return Filtered::Undecided;
    };
    let w = sub3(&y.o, &x.o);
    let mut decided_by = None;
    match sign_of(&dot3(&w, &n), bound(EPS_S, &[mp, l1, l2])) {
        Some(Ordering::Equal) => {}
        Some(_) => {
            let skew = LineLine::Empty(LineLineEmpty::Skew);
            return Filtered::Done(filter_certified(skew));
        }
        None => {
            // Objects sharing an input point (segments of a mesh with a common vertex):
            // with the directions not parallel, that point is the crossing.
            if let Some((point, t1, t2)) = shared_point(a, b) {
                let p = LineLinePoint {
                    point: point.map(Rounded::exact),
                    t1: Rounded::exact(t1),
                    t2: Rounded::exact(t2),
                };
                return Filtered::Done(filter_certified(answer(p, a, b)));
            }
            let (sign, tier, bits) = exact_coplanarity(a, b);
            let skew = LineLine::Empty(LineLineEmpty::Skew);
            if sign.is_ne() {
                return Filtered::Done(Certified::exact(skew, tier.arithmetic(), bits));
            }
            decided_by = Some((tier, bits));
        }
    }
    let tm = crossing_terms(&x, &y, &w, n[k], k);
    let e_p = bound(EPS_P, &[mp, l1, l2]);
    let rounded = (|| {
        let t1 = round_over(&tm.t1n, bound(EPS_T, &[mp, l2]), &den)?;
        let t2 = round_over(&tm.t2n, bound(EPS_T, &[mp, l1]), &den)?;
        let point = Vector3::new(
            round_over(&tm.pnum[0], e_p, &den)?,
            round_over(&tm.pnum[1], e_p, &den)?,
            round_over(&tm.pnum[2], e_p, &den)?,
        );
        Some(LineLinePoint { point, t1, t2 })
    })();
    let Some(p) = rounded else {
        let from = decided_by.map_or(Tier::Small, |(tier, _)| tier);
        return Filtered::Crossing { k, from };
    };
    let value = answer(p, a, b);
    Filtered::Done(match decided_by {
        None => filter_certified(value),
        Some((tier, bits)) => Certified::exact(value, tier.arithmetic(), bits),
    })
}

/// The exact sign of `w·n = det(o₂ − o₁, d₁, d₂)` (degree 3), in the cheapest exact
/// ring that holds it: 128-bit integers (for short data, see [`short_data`]), 768-bit
/// integers, expansions, rationals; with the tier and the bit length (of the largest
/// term) that decided it.
#[cold]
#[inline(never)]
pub(super) fn exact_coplanarity(a: Linear<f64>, b: Linear<f64>) -> (Ordering, Tier, u32) {
    short_data(a, b)
        .then(|| sign_in::<SmallInteger>(a, b, Tier::Small))
        .flatten()
        .or_else(|| sign_in::<WideInteger>(a, b, Tier::Wide))
        .or_else(|| sign_in::<Expansion>(a, b, Tier::Expansion))
        .unwrap_or_else(|| {
            let [p, q, r]: [Rational; 3] = coplanarity_terms(&carrier(a), &carrier(b));
            let bits = [&p, &q, &r]
                .iter()
                .map(|x| x.numer().significant_bits())
                .max()
                .unwrap_or(0);
            let s = p + q + r;
            (s.cmp0(), Tier::Rational, bits.max(1))
        })
}

/// [`exact_coplanarity`] in the ring `E`: `None` when `E` lost exactness.
#[inline(always)]
fn sign_in<E: ExactRing>(
    a: Linear<f64>,
    b: Linear<f64>,
    tier: Tier,
) -> Option<(Ordering, Tier, u32)> {
    Poison::reset();
    let [p, q, r]: [Ratio<E>; 3] = coplanarity_terms(&carrier(a), &carrier(b));
    let bits = p.num.bits().max(q.num.bits()).max(r.num.bits()).max(1);
    let sign = p.plus(&q).plus(&r).sign();
    (!Poison::is_set()).then_some((sign, tier, bits))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::num::error_bound::ErrorBound;

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
                for (k, &nk) in n.iter().enumerate() {
                    let tm = crossing_terms(&x, &y, &w, nk, k);
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
