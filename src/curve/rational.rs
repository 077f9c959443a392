//! Derivatives of a rational curve `c = A/W` from the jets of its homogeneous
//! numerator `A` and weight `W` by the quotient rule of OPERATIONS.md §1.5:
//! `c' = (A' − W'c)/W`, `c'' = (A'' − 2W'c' − W''c)/W`, and in general (Leibniz)
//! `c⁽ᵏ⁾ = (A⁽ᵏ⁾ − Σ_{j=1..k} C(k,j) W⁽ʲ⁾ c⁽ᵏ⁻ʲ⁾) / W`.
//! Shared by rational Bézier and NURBS curves. For interval jets each step is an
//! enclosing operation, so the results enclose the exact derivatives wherever the
//! weight enclosure excludes 0 (positive weights make `W > 0` on the domain).

use crate::num::Real;

/// `numerator[k] = A⁽ᵏ⁾`, `weight[k] = W⁽ᵏ⁾` (same length) → `c⁽ᵏ⁾` for every `k`.
pub fn quotient_jet<T: Real, const D: usize>(numerator: &[[T; D]], weight: &[T]) -> Vec<[T; D]> {
    let point = numerator[0].clone().map(|a| a / &weight[0]);
    quotient_jet_from(point, numerator, weight)
}

/// [`quotient_jet`] with the point `c` given: any enclosure of `A/W` (a tighter one than
/// the quotient of the enclosures, e.g. the hull of the projected control points of
/// `curve::span_hull`) is used in every later step.
pub fn quotient_jet_from<T: Real, const D: usize>(
    point: [T; D],
    numerator: &[[T; D]],
    weight: &[T],
) -> Vec<[T; D]> {
    let w0 = &weight[0];
    let mut out: Vec<[T; D]> = Vec::with_capacity(numerator.len());
    out.push(point);
    for k in 1..numerator.len() {
        let mut binom = 1.0f64;
        let mut acc = numerator[k].clone();
        for j in 1..=k {
            binom = binom * (k + 1 - j) as f64 / j as f64; // C(k, j), exact for k ≤ 3
            let wj = w0.lift(binom) * &weight[j];
            for (a, c) in acc.iter_mut().zip(out[k - j].iter()) {
                *a = a.clone() - wj.clone() * c;
            }
        }
        out.push(acc.map(|a| a / w0));
    }
    out
}
