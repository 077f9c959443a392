//! Newton's method (OPERATIONS.md §0.4 "Newton driver"), in f64 and at any interval
//! precision (on point intervals, taking midpoints: ordinary floating-point Newton at that
//! precision). It only produces estimates; the certificates come from [`super::krawczyk`].

use nalgebra::{DMatrix, DVector};

use super::boxes::IBox;
use super::level::CertInterval;
use super::linalg::{mat_vec, mid_matrix};
use super::system::System;

/// Newton in f64 from `x0`: the last iterate and the size of the last step (∞-norm), or
/// `None` if the Jacobian became singular or the iterates non-finite. Stops when a step
/// is below `4·ε·max(1, |x|)` in every coordinate, or after `max_iter` steps.
pub fn newton_f64<S: System>(sys: &S, x0: &[f64], max_iter: usize) -> Option<(Vec<f64>, f64)> {
    let n = x0.len();
    let mut x = x0.to_vec();
    let mut last = f64::INFINITY;
    for _ in 0..max_iter {
        let (f, j) = sys.eval_with_jacobian(&x);
        if f.len() != n || j.len() != n {
            return None;
        }
        let a = DMatrix::from_fn(n, n, |r, c| j[r][c]);
        let b = DVector::from_fn(n, |r, _| -f[r]);
        let step = a.lu().solve(&b)?;
        last = step.amax();
        for (xi, si) in x.iter_mut().zip(step.iter()) {
            *xi += si;
        }
        if !x.iter().all(|v| v.is_finite()) || !last.is_finite() {
            return None;
        }
        let small = step
            .iter()
            .zip(&x)
            .all(|(s, xi)| s.abs() <= 4.0 * f64::EPSILON * xi.abs().max(1.0));
        if small {
            break;
        }
    }
    Some((x, last))
}

/// Newton at the precision of the point box `x0` (every iterate rounded to a point of
/// that precision). Returns the last iterate and whether it settled: the steps fell below
/// `2^-(bits-8)·max(1, |x|)`, or stopped shrinking twice in a row once below
/// `2^-(bits/2)·max(1, |x|)` (the rounding noise of an ill-conditioned root).
pub fn newton_point<S: System, I: CertInterval>(
    sys: &S,
    x0: &[I],
    max_iter: usize,
) -> Option<(IBox<I>, bool)> {
    let n = x0.len();
    let bits = x0.first()?.precision_bits();
    let tol = (-(f64::from(bits) - 8.0)).exp2();
    let noise = (-f64::from(bits) / 2.0).exp2();
    let mut x: IBox<I> = x0.iter().map(|v| v.mid_interval()).collect();
    let (mut previous, mut stalls) = (f64::INFINITY, 0);
    for _ in 0..max_iter {
        let (f, j) = sys.eval_with_jacobian(&x);
        if f.len() != n || j.len() != n {
            return None;
        }
        let y = I::approx_inverse(&mid_matrix(&j))?;
        let fm: Vec<I> = f.iter().map(|v| v.mid_interval()).collect();
        let step = mat_vec(&y, &fm);
        let (mut small, mut relative) = (true, 0.0f64);
        for (xi, si) in x.iter_mut().zip(&step) {
            let s = si.mid_interval();
            if s.is_empty() || !s.mid().is_finite() {
                return None;
            }
            let scale = xi.mag().max(1.0);
            small &= s.mag() <= tol * scale;
            relative = relative.max(s.mag() / scale);
            *xi = (xi.clone() - &s).mid_interval();
        }
        if x.iter().any(|v| v.is_empty() || !v.mid().is_finite()) {
            return None;
        }
        stalls = if relative <= noise && relative > previous / 1.5 {
            stalls + 1
        } else {
            0
        };
        previous = relative;
        if small || stalls >= 2 {
            return Some((x, true));
        }
    }
    Some((x, false))
}
