//! Roots whose verified box straddles a true (non-periodic) end of the domain
//! (CERTIFICATION.md "Completeness"; issue 14 item 3): a segment and a Bézier arc
//! that share an end point, a curve that ends on a surface. The box `B` holds exactly
//! one root `x*` (Krawczyk), so it is enough to decide where `x*` lies:
//!
//! 1. **At an exact point.** A candidate `x̂ ∈ B` is built from exact values: the
//!    domain ends that `B` reaches, `0` (the seam of a periodic coordinate, also when
//!    `B` reaches it only shifted by a whole period), the estimate and the dyadic
//!    rational of fewest bits in `B`. The system is
//!    evaluated at `x̂` in MPFR intervals of [`EXACT_BITS`] bits over point inputs: when
//!    every component is the thin interval `[0, 0]`, `F(x̂) = 0` exactly (an MPFR
//!    interval operation on exact inputs whose result is representable returns it
//!    exactly, and any rounding would widen the interval). Then `x̂` is a root in
//!    `B` (up to whole periods), so `x* ≡ x̂`, and `x̂` lies in the closed domain: the
//!    root is reported at `x̂` with a thin box.
//! 2. **By precision.** Otherwise the root is certified again at 128, 256, … bits from
//!    its estimate ([`certify::certify_root_at`]); a new box inside `B` holds the same
//!    root `x*`, and once the new box lies inside the domain (or outside it, in some
//!    coordinate) the root is decided. A root exactly on an end that no exact candidate
//!    hits stays undecided.

use super::{CertifiedRoot, Unknowns};
use crate::certificate::Status;
use crate::certify::level::levels;
use crate::certify::{self, Root, System};
use crate::num::round::{next_down, next_up};
use crate::num::{Interval, MpfrInterval};

/// The MPFR precision of the exact-point test: point inputs are doubles, and a
/// polynomial or trigonometric system of moderate degree evaluated at them is exact at
/// this precision when its value is representable (otherwise the test just fails).
pub const EXACT_BITS: u32 = 2048;

/// The most exact candidates tried for one root.
const MAX_CANDIDATES: usize = 64;

/// Where a straddling root was found to lie.
#[derive(Debug, Clone, PartialEq)]
pub enum Decided {
    /// In the closed domain: the root, now `verified`, with a box inside the domain.
    Inside(CertifiedRoot),
    /// Proven outside the domain: not an answer.
    Outside,
    /// Not decided: the root as it was, `undecided`.
    Open,
}

/// Decide a `verified` root `r` whose box straddles a non-periodic end of the domain
/// (module doc). `max_bits` caps the escalation.
pub fn decide_boundary<S: System>(
    sys: &S,
    r: &Root,
    unknowns: &Unknowns,
    max_bits: u32,
) -> Decided {
    if r.status != Status::Verified {
        return Decided::Open;
    }
    if let Some(x) = exact_root(sys, &r.enclosure, &r.estimate, unknowns) {
        return Decided::Inside(at_point(&x, r.bits.max(53)));
    }
    for bits in levels(max_bits).into_iter().filter(|&b| b > 53) {
        let Ok(Some(again)) = certify::certify_root_at(sys, &r.estimate, bits) else {
            continue;
        };
        let same = again
            .enclosure
            .iter()
            .zip(&r.enclosure)
            .all(|(a, b)| a.is_subset(b));
        if !same {
            continue;
        }
        match side(&again.enclosure_mpfr, unknowns) {
            Side::Inside => {
                let mut root = again;
                root.bits = root.bits.max(r.bits);
                return Decided::Inside(CertifiedRoot::from_root(&root, false));
            }
            Side::Outside => return Decided::Outside,
            Side::Across => {}
        }
    }
    Decided::Open
}

/// A root at a thin point.
fn at_point(x: &[f64], bits: u32) -> CertifiedRoot {
    CertifiedRoot {
        params: x.to_vec(),
        enclosure: x.iter().map(|&v| Interval::point(v)).collect(),
        status: Status::Verified,
        max_roots: 1,
        bits,
        perturbation: None,
        reason: None,
    }
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Side {
    Inside,
    Outside,
    Across,
}

/// Where an MPFR box lies against the domain in its non-periodic coordinates. A
/// rounded end (an irrational bound within one ulp of its double) counts as inside only
/// one ulp in, as outside only one ulp out.
fn side(x: &[MpfrInterval], unknowns: &Unknowns) -> Side {
    let mut across = false;
    for (i, xi) in x.iter().enumerate() {
        if unknowns.periodic[i] {
            continue;
        }
        let [lo, hi] = unknowns.domain[i];
        let (inner, outer) = if unknowns.rounded[i] {
            ([next_up(lo), next_down(hi)], [next_down(lo), next_up(hi)])
        } else {
            ([lo, hi], [lo, hi])
        };
        if *xi.hi() < outer[0] || *xi.lo() > outer[1] {
            return Side::Outside;
        }
        across |= *xi.lo() < inner[0] || *xi.hi() > inner[1];
    }
    if across {
        Side::Across
    } else {
        Side::Inside
    }
}

/// An exact root `x̂` of `sys` in the box `b` up to whole periods, inside the closed
/// domain (module doc, step 1); `None` when no candidate is proven a root.
pub fn exact_root<S: System>(
    sys: &S,
    b: &[Interval],
    estimate: &[f64],
    unknowns: &Unknowns,
) -> Option<Vec<f64>> {
    let choices: Vec<Vec<f64>> = (0..b.len())
        .map(|i| candidates(i, &b[i], estimate[i], unknowns))
        .collect();
    let total = choices.iter().map(Vec::len).product::<usize>();
    if total == 0 || total > MAX_CANDIDATES {
        return None;
    }
    (0..total).find_map(|mut k| {
        let x: Vec<f64> = choices
            .iter()
            .map(|c| {
                let v = c[k % c.len()];
                k /= c.len();
                v
            })
            .collect();
        is_exact_root(sys, &x).then_some(x)
    })
}

/// The exact values coordinate `i` may take in the box `bi` (module doc), each inside
/// the closed domain.
fn candidates(i: usize, bi: &Interval, estimate: f64, unknowns: &Unknowns) -> Vec<f64> {
    let [lo, hi] = unknowns.domain[i];
    let mut out: Vec<f64> = Vec::new();
    let mut add = |v: f64| {
        if !out.contains(&v) {
            out.push(v);
        }
    };
    if unknowns.periodic[i] {
        // The seam: `lo` itself or `lo + P` (`P` an enclosure of the exact period).
        let p = unknowns.period(i);
        let at_lo = Interval::point(lo);
        let exact_lo = !unknowns.rounded[i] || lo == 0.0;
        if exact_lo && (bi.contains(lo) || (at_lo + p).is_subset(bi) || (at_lo - p).is_subset(bi)) {
            add(lo);
        }
    } else if !unknowns.rounded[i] {
        for end in [lo, hi] {
            if bi.contains(end) {
                add(end);
            }
        }
    }
    let inside = |v: f64| {
        let (l, h) = if unknowns.rounded[i] {
            (next_up(lo), next_down(hi))
        } else {
            (lo, hi)
        };
        unknowns.periodic[i] || (l <= v && v <= h)
    };
    let simplest = simplest_dyadic(bi.lo(), bi.hi());
    for v in [0.0, estimate].into_iter().chain(simplest) {
        if bi.contains(v) && inside(v) && (!unknowns.periodic[i] || (lo <= v && v <= hi)) {
            add(v);
        }
    }
    out
}

/// The dyadic rational with the fewest significant bits in `[lo, hi]` (a root at a
/// short rational such as `3/16` has it as its coordinate); `None` for an empty or
/// unbounded interval. Multiples of powers of two are exact in doubles.
fn simplest_dyadic(lo: f64, hi: f64) -> Option<f64> {
    if !(lo <= hi && lo.is_finite() && hi.is_finite()) {
        return None;
    }
    if lo <= 0.0 && 0.0 <= hi {
        return Some(0.0);
    }
    let top = lo.abs().max(hi.abs()).log2().ceil() as i32 + 1;
    (-1074..=top.min(1023)).rev().find_map(|e| {
        let step = pow2(e);
        let m = (lo / step).ceil();
        let v = m * step;
        (v <= hi && v >= lo).then_some(v)
    })
}

/// `2^e` for `−1074 ≤ e ≤ 1023`, exactly (subnormal below `−1022`).
fn pow2(e: i32) -> f64 {
    if e >= -1022 {
        f64::from_bits(((e + 1023) as u64) << 52)
    } else {
        f64::from_bits(1u64 << (e + 1074))
    }
}

/// `F(x) = 0` exactly: every component of the MPFR evaluation at the point `x` is the
/// thin interval `[0, 0]` (module doc).
fn is_exact_root<S: System>(sys: &S, x: &[f64]) -> bool {
    let xs: Vec<MpfrInterval> = x
        .iter()
        .map(|&v| MpfrInterval::point(v, EXACT_BITS))
        .collect();
    sys.eval(&xs)
        .iter()
        .all(|f| !f.is_empty() && *f.lo() == 0 && *f.hi() == 0)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::num::Real;

    /// `(t·(t − 1), s − t)`: the roots `(0, 0)` and `(1, 1)` sit on the domain's corners.
    struct Corners;
    impl System for Corners {
        fn dim(&self) -> usize {
            2
        }
        fn eval<T: Real>(&self, x: &[T]) -> Vec<T> {
            let one = x[0].lift(1.0);
            vec![x[0].clone() * &(x[0].clone() - &one), x[1].clone() - &x[0]]
        }
    }

    fn square() -> Unknowns {
        Unknowns {
            domain: vec![[0.0, 1.0]; 2],
            periodic: vec![false; 2],
            rounded: vec![false; 2],
        }
    }

    #[test]
    fn an_exact_root_on_a_corner_is_found() {
        let b = vec![Interval::from_bounds(-1e-16, 1e-16); 2];
        let x = exact_root(&Corners, &b, &[1e-17, -1e-17], &square());
        assert_eq!(x, Some(vec![0.0, 0.0]));
        let b = vec![Interval::from_bounds(1.0 - 1e-15, 1.0 + 1e-15); 2];
        let x = exact_root(&Corners, &b, &[1.0, 1.0], &square());
        assert_eq!(x, Some(vec![1.0, 1.0]));
    }

    #[test]
    fn a_point_that_is_not_a_root_is_not_taken() {
        let b = vec![Interval::from_bounds(0.4, 0.6); 2];
        assert_eq!(exact_root(&Corners, &b, &[0.5, 0.5], &square()), None);
    }

    #[test]
    fn the_simplest_dyadic_of_an_interval() {
        assert_eq!(
            simplest_dyadic(0.18749999999999842, 0.1875000000000011),
            Some(0.1875)
        );
        assert_eq!(simplest_dyadic(-1e-16, 1e-16), Some(0.0));
        assert_eq!(simplest_dyadic(2.9, 3.1), Some(3.0));
        assert_eq!(simplest_dyadic(5e-324, 5e-324), Some(5e-324));
    }

    #[test]
    fn the_side_of_an_mpfr_box() {
        let at = |lo: f64, hi: f64| vec![MpfrInterval::from_bounds(lo, hi, 128); 2];
        assert_eq!(side(&at(0.1, 0.2), &square()), Side::Inside);
        assert_eq!(side(&at(-0.1, 0.2), &square()), Side::Across);
        assert_eq!(side(&at(1.1, 1.2), &square()), Side::Outside);
    }
}
