//! Small dense linear algebra for the certifier: approximate (midpoint) inverses for
//! preconditioning — nalgebra in f64, Gauss–Jordan at MPFR precision — and interval
//! matrix–vector products. Matrices are row-major `Vec<Vec<_>>` of size `n ≤ 12`.
//!
//! Approximate inverses prove nothing and need not be accurate: Krawczyk's theorem holds
//! for any preconditioner, whose quality only decides whether the test succeeds. Interval
//! products enclose the exact products of all matrices and vectors in the operands
//! (each entry is a sum of interval products).

use nalgebra::DMatrix;

use crate::num::IntervalLike;

/// The inverse of an f64 matrix by LU with partial pivoting (nalgebra); `None` if singular
/// or not finite.
pub fn inverse_f64(a: &[Vec<f64>]) -> Option<Vec<Vec<f64>>> {
    let n = a.len();
    let m = DMatrix::from_fn(n, n, |i, j| a[i][j]);
    let inv = m.try_inverse()?;
    let out: Vec<Vec<f64>> = (0..n)
        .map(|i| (0..n).map(|j| inv[(i, j)]).collect())
        .collect();
    out.iter().flatten().all(|v| v.is_finite()).then_some(out)
}

/// The approximate inverse of a point matrix by Gauss–Jordan elimination with partial
/// pivoting, in the precision of the entries, every intermediate replaced by its
/// midpoint (so it is ordinary floating-point elimination at that precision).
pub fn inverse_gauss_jordan<I: IntervalLike>(a: &[Vec<I>]) -> Option<Vec<Vec<I>>> {
    let n = a.len();
    let zero = a.first()?.first()?.zero_like();
    let mut m: Vec<Vec<I>> = a
        .iter()
        .enumerate()
        .map(|(i, row)| {
            let mut r: Vec<I> = row.iter().map(|x| x.mid_interval()).collect();
            r.extend((0..n).map(|j| {
                if i == j {
                    zero.one_like()
                } else {
                    zero.clone()
                }
            }));
            r
        })
        .collect();
    for col in 0..n {
        let pivot = (col..n).max_by(|&i, &j| m[i][col].mag().total_cmp(&m[j][col].mag()))?;
        let p = m[pivot][col].mag();
        if !(p > 0.0 && p.is_finite()) {
            return None;
        }
        m.swap(col, pivot);
        let inv = (zero.one_like() / &m[col][col]).mid_interval();
        for x in m[col].iter_mut() {
            *x = (x.clone() * &inv).mid_interval();
        }
        for i in 0..n {
            if i == col {
                continue;
            }
            let f = m[i][col].clone();
            let pivot_row = m[col].clone();
            for (x, p) in m[i].iter_mut().zip(&pivot_row) {
                let t = (p.clone() * &f).mid_interval();
                *x = (x.clone() - &t).mid_interval();
            }
        }
    }
    Some(m.into_iter().map(|r| r[n..].to_vec()).collect())
}

/// The midpoint matrix (point intervals).
pub fn mid_matrix<I: IntervalLike>(a: &[Vec<I>]) -> Vec<Vec<I>> {
    a.iter()
        .map(|r| r.iter().map(|x| x.mid_interval()).collect())
        .collect()
}

/// `a·x` in interval arithmetic.
pub fn mat_vec<I: IntervalLike>(a: &[Vec<I>], x: &[I]) -> Vec<I> {
    a.iter()
        .map(|row| {
            let mut acc = x[0].zero_like();
            for (aij, xj) in row.iter().zip(x) {
                acc = acc + aij.clone() * xj;
            }
            acc
        })
        .collect()
}

/// `I − y·j` in interval arithmetic.
pub fn identity_minus_product<I: IntervalLike>(y: &[Vec<I>], j: &[Vec<I>]) -> Vec<Vec<I>> {
    let n = y.len();
    let cols = j.first().map_or(0, |r| r.len());
    (0..n)
        .map(|r| {
            (0..cols)
                .map(|c| {
                    let mut acc = if r == c {
                        y[r][0].one_like()
                    } else {
                        y[r][0].zero_like()
                    };
                    for (k, jk) in j.iter().enumerate() {
                        acc = acc - y[r][k].clone() * &jk[c];
                    }
                    acc
                })
                .collect()
        })
        .collect()
}

/// An upper bound of the ∞-norm `max_i Σ_j |a_ij|` over all matrices in `a`
/// (magnitudes and sums rounded up).
pub fn norm_inf_upper<I: IntervalLike>(a: &[Vec<I>]) -> f64 {
    use crate::num::interval::directed::add_up;
    a.iter()
        .map(|row| row.iter().fold(0.0, |s, x| add_up(s, x.mag())))
        .fold(0.0, f64::max)
}

/// The right and left singular vectors of the smallest singular value of an f64 matrix
/// (approximate null vectors `J v ≈ 0`, `uᵀ J ≈ 0`, unit length), and that value.
pub fn null_vectors(a: &[Vec<f64>]) -> Option<(Vec<f64>, Vec<f64>, f64)> {
    let n = a.len();
    let m = DMatrix::from_fn(n, n, |i, j| a[i][j]);
    if !m.iter().all(|v| v.is_finite()) {
        return None;
    }
    let svd = m.svd(true, true);
    let (u, vt) = (svd.u?, svd.v_t?);
    let k = (0..n).min_by(|&i, &j| svd.singular_values[i].total_cmp(&svd.singular_values[j]))?;
    let right = (0..n).map(|j| vt[(k, j)]).collect();
    let left = (0..n).map(|i| u[(i, k)]).collect();
    Some((right, left, svd.singular_values[k]))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::num::{Interval, MpfrInterval, Real};

    #[test]
    fn inverses_invert() {
        let a = vec![
            vec![4.0, 1.0, 0.5],
            vec![1.0, 3.0, -1.0],
            vec![0.0, 2.0, 5.0],
        ];
        let inv = inverse_f64(&a).unwrap();
        let ai: Vec<Vec<MpfrInterval>> = a
            .iter()
            .map(|r| r.iter().map(|&v| MpfrInterval::point(v, 200)).collect())
            .collect();
        let inv_m = inverse_gauss_jordan(&ai).unwrap();
        for i in 0..3 {
            for j in 0..3 {
                let s: f64 = (0..3).map(|k| a[i][k] * inv[k][j]).sum();
                assert!((s - f64::from(u8::from(i == j))).abs() < 1e-15);
                assert!((inv_m[i][j].mid() - inv[i][j]).abs() < 1e-15);
            }
        }
        // the 200-bit product is the identity to far below f64 resolution
        let c = identity_minus_product(&inv_m, &ai);
        assert!(norm_inf_upper(&c) < 1e-55);
        assert!(inverse_f64(&[vec![1.0, 2.0], vec![2.0, 4.0]]).is_none());
    }

    #[test]
    fn products_enclose() {
        let a = vec![
            vec![Interval::from_bounds(1.0, 2.0), Interval::point(-1.0)],
            vec![Interval::point(0.5), Interval::from_bounds(-1.0, 1.0)],
        ];
        let x = vec![Interval::point(3.0), Interval::from_bounds(0.0, 2.0)];
        let y = mat_vec(&a, &x);
        assert_eq!(y[0], Interval::from_bounds(1.0, 6.0));
        assert_eq!(y[1], Interval::from_bounds(-0.5, 3.5));
        assert_eq!(norm_inf_upper(&a), 3.0);
    }

    #[test]
    fn null_vectors_of_a_rank_one_matrix() {
        let (v, u, s) = null_vectors(&[vec![1.0, 2.0], vec![2.0, 4.0]]).unwrap();
        assert!(s < 1e-15);
        assert!((v[0] * 1.0 + v[1] * 2.0).abs() < 1e-15);
        assert!((u[0] * 1.0 + u[1] * 2.0).abs() < 1e-15);
    }
}
