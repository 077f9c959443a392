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
    let w0 = &weight[0];
    let mut out: Vec<[T; D]> = Vec::with_capacity(numerator.len());
    for k in 0..numerator.len() {
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
