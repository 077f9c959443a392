//! Curve ∩ implicit surface by bisection (OPERATIONS.md §13.4, equation (13.8)), the
//! "spatial" variant: `g(σ) = F(x(σ))`, with `F` the surface's own implicit equation
//! (§1.4: `F > 0` outside, `F < 0` inside) and `x(σ)` the curve.
//!
//! * Brackets: `g` is sampled at the curve's walk samples (§2.1), each step cut into
//!   equal parts so that no two samples are more than [`SPACING`] of the domain apart;
//!   every pair of consecutive samples with opposite signs of `g` is a bracket, and a
//!   sample where `g` is exactly 0 is a root (13.8: "`F(x(σ_M)) = 0` ends the loop").
//! * (13.8) halves each bracket, keeping the half whose ends have opposite signs, until
//!   `|σ₂ − σ₁| ≤ e` ([`bisect`]).
//!
//! The float path proves nothing and sees only sign changes: a tangential root (even
//! multiplicity, no sign change) and two roots between neighbouring samples are not
//! found by it (§13.4: "robust for tangential crossings only if a sign change
//! exists"). The certified operation [`intersect_curve_implicit_bisection`] therefore
//! hands the bisection roots as guesses to the certifier, which subdivides the whole
//! parameter domain of `g` ([`crate::ops::certified::certify_roots`]): a root the float
//! path missed is still found (a tangency as `verified_singular`) or the answer is
//! `undecided` / not `complete` — never silently lost.
//!
//! `g` is written once, generic over [`Real`] ([`curve_implicit_value`]): the float
//! path evaluates it in `f64`, the certifier in intervals, where every operation
//! encloses the exact value (the curve's jet and the implicit form are enclosures in
//! interval arithmetic, [`crate::num::real`]), so the interval value of `g` over a
//! parameter box holds `g` of every point of the box.

use crate::certificate::Certified;
use crate::certify::System;
use crate::curve::Curve;
use crate::error::GeomError;
use crate::num::Real;
use crate::ops::certified::{certify_roots, curve_points, curve_unknowns, CertifiedPoint, Options};
use crate::ops::float::Precision;
use crate::surface::Implicit;

/// The largest distance between two samples of `g`, as a fraction of the curve's
/// parameter range (impl): a line is one step of §2.1, which sees no sign change across
/// a chord through a sphere, so each §2.1 step is cut into parts no longer than this.
pub const SPACING: f64 = 1.0 / 256.0;

/// The most halvings of one bracket: a double interval cannot be halved more often
/// than its ends have bits apart (2·1074 + 53 bounds it for any finite ends).
const MAX_HALVINGS: usize = 2200;

/// `g(σ) = F(x(σ))` (§13.4, spatial variant), in any number type.
pub fn curve_implicit_value<T: Real, C: Curve<3>, G: Implicit<3>>(curve: &C, g: &G, t: &T) -> T {
    let x = curve.jet(t, 0).swap_remove(0);
    g.implicit_jet(&x, 0).value
}

/// A bracket of (13.8): `g(lo)` and `g(hi)` have opposite signs, neither 0.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Bracket {
    pub lo: f64,
    pub hi: f64,
}

/// Where the samples `(σ, g(σ))` (increasing `σ`) say a root is: brackets between
/// consecutive samples of opposite signs, and the samples where `g` is exactly 0. A
/// NaN value neither makes nor breaks a bracket (it is skipped).
pub fn brackets(samples: &[(f64, f64)]) -> (Vec<Bracket>, Vec<f64>) {
    let mut out = Vec::new();
    let mut zeros = Vec::new();
    let mut last: Option<(f64, f64)> = None;
    for &(t, v) in samples {
        if v.is_nan() {
            continue;
        }
        if v == 0.0 {
            zeros.push(t);
            last = None;
            continue;
        }
        if let Some((s, w)) = last {
            if (w > 0.0) != (v > 0.0) {
                out.push(Bracket { lo: s, hi: t });
            }
        }
        last = Some((t, v));
    }
    (out, zeros)
}

/// (13.8): halve `bracket` until `|σ₂ − σ₁| ≤ e` (or until the doubles between its
/// ends run out), keeping the half whose ends have opposite signs of `g`; a midpoint
/// where `g` is exactly 0 is the root. Returns the last midpoint `σ_M`.
pub fn bisect(g: impl Fn(f64) -> f64, bracket: Bracket, e: f64) -> f64 {
    let (mut s1, mut s2) = (bracket.lo, bracket.hi);
    let positive_at_s1 = g(s1) > 0.0;
    let mut mid = 0.5 * (s1 + s2);
    for _ in 0..MAX_HALVINGS {
        mid = s1 + 0.5 * (s2 - s1);
        // (`e` is finite and the ends are finite: the width is never NaN.)
        if s2 - s1 <= e || mid <= s1 || mid >= s2 {
            break;
        }
        let v = g(mid);
        if v == 0.0 {
            break;
        }
        // A NaN value is taken as the sign of σ₁'s side: the bracket still shrinks.
        if (v > 0.0) == positive_at_s1 || v.is_nan() {
            s1 = mid;
        } else {
            s2 = mid;
        }
    }
    mid
}

/// The sample parameters of `g`: the walk samples `[(t, Δt)]` of §2.1 (increasing),
/// each step cut into equal parts no longer than [`SPACING`] of the range.
pub fn sample_parameters(curve_samples: &[(f64, f64)], range: [f64; 2]) -> Vec<f64> {
    let most = SPACING * (range[1] - range[0]);
    let mut out = Vec::new();
    for pair in curve_samples.windows(2) {
        let (a, b) = (pair[0].0, pair[1].0);
        let parts = if most > 0.0 {
            ((b - a) / most).ceil().clamp(1.0, 1.0 / SPACING) as usize
        } else {
            1
        };
        out.extend((0..parts).map(|k| a + (b - a) * k as f64 / parts as f64));
    }
    if let Some(&(t, _)) = curve_samples.last() {
        out.push(t);
    }
    out
}

/// Every root of `g(σ) = F(x(σ))` that the float path finds (module doc): one per
/// bracket and per exact zero of a sample, increasing. `e = ε·max(1, range)` with the
/// operation tolerance ε (§12). Proves nothing.
pub fn intersect_curve_implicit_bisection_f64<C: Curve<3>, G: Implicit<3>>(
    curve: &C,
    g: &G,
    curve_samples: &[(f64, f64)],
    precision: &Precision,
) -> Vec<f64> {
    let (lo, hi) = curve.domain();
    let value = |t: f64| curve_implicit_value(curve, g, &t);
    let values: Vec<(f64, f64)> = sample_parameters(curve_samples, [lo, hi])
        .into_iter()
        .map(|t| (t, value(t)))
        .collect();
    let (found, mut roots) = brackets(&values);
    let e = precision.eps * (hi - lo).max(1.0);
    roots.extend(found.into_iter().map(|b| bisect(value, b, e)));
    roots.sort_by(f64::total_cmp);
    roots.dedup();
    roots
}

/// `g(σ) = F(x(σ))` as a system of one equation in the curve's parameter.
pub struct CurveImplicitSystem<'a, C, G> {
    pub curve: &'a C,
    pub g: &'a G,
}

impl<C: Curve<3>, G: Implicit<3>> System for CurveImplicitSystem<'_, C, G> {
    fn dim(&self) -> usize {
        1
    }
    fn eval<T: Real>(&self, x: &[T]) -> Vec<T> {
        vec![curve_implicit_value(self.curve, self.g, &x[0])]
    }
}

/// Every root of `F(x(σ)) = 0` over the curve's domain, certified (module doc): the
/// float bisection roots seed the certifier, whose subdivision of the whole domain
/// makes the answer `complete` (no other root exists, tangential ones included) or
/// says what it could not decide. Points are ordered along the curve; each root's
/// parameters are `[σ]`.
pub fn intersect_curve_implicit_bisection<C: Curve<3>, G: Implicit<3>>(
    curve: &C,
    g: &G,
    curve_samples: &[(f64, f64)],
    precision: &Precision,
    opts: &Options,
) -> Result<Certified<Vec<CertifiedPoint<3>>>, GeomError> {
    let guesses: Vec<Vec<f64>> =
        intersect_curve_implicit_bisection_f64(curve, g, curve_samples, precision)
            .into_iter()
            .map(|t| vec![t])
            .collect();
    let sys = CurveImplicitSystem { curve, g };
    let roots = certify_roots(&sys, &curve_unknowns(curve), &guesses, opts)?;
    Ok(curve_points(curve, roots))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bisection_halves_to_the_root_of_a_cubic() {
        // g(σ) = σ³ − 2: the real root 2^(1/3).
        let root = bisect(|s| s * s * s - 2.0, Bracket { lo: 0.0, hi: 2.0 }, 1e-15);
        assert!((root - 2f64.cbrt()).abs() < 4e-15, "{root}");
    }

    #[test]
    fn an_exact_zero_ends_the_loop() {
        // The first midpoint is the root 1.
        assert_eq!(
            bisect(|s| s - 1.0, Bracket { lo: 0.0, hi: 2.0 }, 1e-12),
            1.0
        );
    }

    #[test]
    fn brackets_are_the_sign_changes() {
        let v = [
            (0.0, 1.0),
            (1.0, -1.0),
            (2.0, -2.0),
            (3.0, 0.0),
            (4.0, 1.0),
            (5.0, f64::NAN),
            (6.0, -1.0),
        ];
        let (b, zeros) = brackets(&v);
        assert_eq!(
            b,
            vec![Bracket { lo: 0.0, hi: 1.0 }, Bracket { lo: 4.0, hi: 6.0 }]
        );
        assert_eq!(zeros, vec![3.0]);
    }

    #[test]
    fn samples_are_no_farther_apart_than_the_spacing() {
        let s = sample_parameters(&[(0.0, 10.0), (10.0, 10.0)], [0.0, 10.0]);
        assert_eq!(s.len(), 257);
        assert_eq!((s[0], s[256]), (0.0, 10.0));
        assert!(s
            .windows(2)
            .all(|w| w[1] - w[0] <= 10.0 * SPACING * (1.0 + 1e-12)));
    }
}
