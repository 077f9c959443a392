//! The tensor-product (rational) patch (1.18) on one pair of spans: the homogeneous
//! sums `A = Σ N_i(v) N_j(u) w_ij P_ij`, `W = Σ N_i(v) N_j(u) w_ij` and their partial
//! derivatives, then the quotient rule of §1.5 extended to two variables:
//!
//! ```text
//! s    = A/W
//! s_u  = (A_u − W_u s)/W                    s_v  = (A_v − W_v s)/W
//! s_uu = (A_uu − 2W_u s_u − W_uu s)/W       s_vv = (A_vv − 2W_v s_v − W_vv s)/W
//! s_uv = (A_uv − W_u s_v − W_v s_u − W_uv s)/W
//! ```
//!
//! Rows of the net go with `v`, positions in a row with `u` (§1.6). The sum runs row by
//! row: first `R_k(row) = Σ_j N_j^{(k)}(u) P_row,j`, then `Σ_i N_i^{(l)}(v) R_k(i)`, so
//! the second derivatives cost about three times the point. Interval evaluation
//! encloses: every step is an enclosing operation on exact (lifted) data.

use super::basis::BasisJet;
use super::validate::positive;
use crate::error::{require_finite_all, GeomError};
use crate::num::vector::lift;
use crate::num::Real;
use std::ops::{Add, Div, Mul, Sub};

/// A control net: `rows × cols` points stored row by row, optional weights.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Net {
    pub rows: usize,
    pub cols: usize,
    pub points: Vec<[f64; 3]>,
    pub weights: Option<Vec<f64>>,
}

impl Net {
    /// The control points, row by row.
    pub fn point_rows(&self) -> Vec<Vec<[f64; 3]>> {
        self.points.chunks(self.cols).map(<[_]>::to_vec).collect()
    }
    /// Refuse a net that spans no surface ([`super::degenerate`]; after the other
    /// checks of the constructor, so that a bad knot is reported first).
    pub fn check_spans(&self) -> Result<(), GeomError> {
        super::degenerate::check_net_spans(
            self.rows,
            self.cols,
            &self.points,
            self.weights.as_deref(),
        )
    }
    /// The weights, row by row, if rational.
    pub fn weight_rows(&self) -> Option<Vec<Vec<f64>>> {
        let w = self.weights.as_ref()?;
        Some(w.chunks(self.cols).map(<[_]>::to_vec).collect())
    }
}

/// Check a rectangular net of at least `min_rows × min_cols` finite points and its
/// positive weights (errors name `points`, `points[i]`, `points[i][j]`, `weights...`);
/// a net that spans no surface or a subnormal weight is refused
/// ([`super::degenerate`]).
pub(crate) fn validate_net(
    points: &[Vec<[f64; 3]>],
    weights: Option<&[Vec<f64>]>,
    min_rows: usize,
    min_cols: usize,
) -> Result<Net, GeomError> {
    let rows = points.len();
    if rows < min_rows {
        return Err(GeomError::CountMismatch {
            field: "points".into(),
            expected: format!("at least {min_rows} rows"),
            found: format!("{rows}"),
        });
    }
    let cols = points[0].len();
    if cols < min_cols {
        return Err(GeomError::CountMismatch {
            field: "points[0]".into(),
            expected: format!("at least {min_cols} points per row"),
            found: format!("{cols}"),
        });
    }
    let mut flat = Vec::with_capacity(rows * cols);
    for (i, r) in points.iter().enumerate() {
        if r.len() != cols {
            return Err(GeomError::CountMismatch {
                field: format!("points[{i}]"),
                expected: format!("{cols} points (as row 0)"),
                found: format!("{}", r.len()),
            });
        }
        for (j, p) in r.iter().enumerate() {
            require_finite_all(&format!("points[{i}][{j}]"), p)?;
            flat.push(*p);
        }
    }
    let weights = match weights {
        None => None,
        Some(w) => {
            if w.len() != rows {
                return Err(GeomError::CountMismatch {
                    field: "weights".into(),
                    expected: format!("{rows} rows (as points)"),
                    found: format!("{}", w.len()),
                });
            }
            let mut flat_w = Vec::with_capacity(rows * cols);
            for (i, r) in w.iter().enumerate() {
                if r.len() != cols {
                    return Err(GeomError::CountMismatch {
                        field: format!("weights[{i}]"),
                        expected: format!("{cols} weights (as points[{i}])"),
                        found: format!("{}", r.len()),
                    });
                }
                for (j, &x) in r.iter().enumerate() {
                    let field = format!("weights[{i}][{j}]");
                    positive(&field, x).map_err(|e| match e {
                        GeomError::InvalidValue { field, .. } => GeomError::NonPositiveWeight {
                            field,
                            value: format!("{x}"),
                        },
                        other => other,
                    })?;
                    super::degenerate::check_weight(&field, x)?;
                    flat_w.push(x);
                }
            }
            Some(flat_w)
        }
    };
    Ok(Net {
        rows,
        cols,
        points: flat,
        weights,
    })
}

/// `(ku, kv)` derivative orders in jet order `s, s_u, s_v, s_uu, s_uv, s_vv`.
pub(crate) const ORDERS: [(usize, usize); 6] = [(0, 0), (1, 0), (0, 1), (2, 0), (1, 1), (0, 2)];

fn jet_len(order: usize) -> usize {
    match order {
        0 => 1,
        1 => 3,
        _ => 6,
    }
}

/// The homogeneous partial derivatives `H[(ku, kv)]` in jet order, of dimension `D`
/// (3 for polynomial nets, 4 = `(wP, w)` for rational ones).
fn homogeneous<T: Real, const D: usize>(
    bu: &BasisJet<T>,
    first_u: usize,
    bv: &BasisJet<T>,
    first_v: usize,
    order: usize,
    point: impl Fn(usize, usize) -> [T; D],
) -> Vec<[T; D]> {
    let zero = bu.get(0, 0).zero_like();
    let (pu, pv) = (bu.degree, bv.degree);
    let ku_max = order.min(2);
    let zeros = || -> [T; D] { std::array::from_fn(|_| zero.clone()) };
    // rows_sum[i][k] = Σ_j N_j^{(k)}(u) P(first_v + i, first_u + j), k ≤ 2.
    let mut rows_sum: Vec<[[T; D]; 3]> = Vec::with_capacity(pv + 1);
    for i in 0..=pv {
        let mut acc: [[T; D]; 3] = std::array::from_fn(|_| zeros());
        for j in 0..=pu {
            let p = point(first_v + i, first_u + j);
            for (k, a) in acc.iter_mut().enumerate().take(ku_max + 1) {
                let n = bu.get(k, j);
                for c in 0..D {
                    a[c] = a[c].clone() + n.clone() * &p[c];
                }
            }
        }
        rows_sum.push(acc);
    }
    ORDERS[..jet_len(order)]
        .iter()
        .map(|&(ku, kv)| {
            let mut acc = zeros();
            for (i, r) in rows_sum.iter().enumerate() {
                let n = bv.get(kv, i);
                for c in 0..D {
                    acc[c] = acc[c].clone() + n.clone() * &r[ku][c];
                }
            }
            acc
        })
        .collect()
}

/// The jet of the patch on the spans whose first non-zero functions are `first_u`
/// (column) and `first_v` (row), from the basis jets there.
pub(crate) fn tensor_jet<T: Real>(
    net: &Net,
    bu: &BasisJet<T>,
    first_u: usize,
    bv: &BasisJet<T>,
    first_v: usize,
    order: usize,
) -> Vec<[T; 3]> {
    let like = bu.get(0, 0);
    let Some(weights) = &net.weights else {
        return homogeneous(bu, first_u, bv, first_v, order, |i, j| {
            lift(like, &net.points[i * net.cols + j])
        });
    };
    let h = homogeneous(bu, first_u, bv, first_v, order, |i, j| {
        let k = i * net.cols + j;
        let w = weights[k];
        let p = net.points[k];
        // w·P is formed in the number type, so the product is enclosed, not rounded.
        let wt = like.lift(w);
        [
            wt.clone() * like.lift(p[0]),
            wt.clone() * like.lift(p[1]),
            wt.clone() * like.lift(p[2]),
            wt,
        ]
    });
    quotient(&h)
}

/// The quotient rule (module doc) on the homogeneous jet `[A | W]`.
///
/// Written against the arithmetic operations only, so that it serves every [`Real`]
/// and the midpoint–radius enclosures of `super::taylor_fast`
/// ([`MidRad`](crate::num::midrad::MidRad)).
pub(crate) fn quotient<T>(h: &[[T; 4]]) -> Vec<[T; 3]>
where
    T: Clone
        + Add<Output = T>
        + Sub<Output = T>
        + for<'a> Mul<&'a T, Output = T>
        + for<'a> Div<&'a T, Output = T>,
{
    let w = &h[0][3];
    let a = |k: usize| -> [T; 3] { [h[k][0].clone(), h[k][1].clone(), h[k][2].clone()] };
    let wd = |k: usize| &h[k][3];
    let div = |x: [T; 3]| -> [T; 3] { x.map(|c| c / w) };
    let s = div(a(0));
    let mut out = vec![s.clone()];
    if h.len() >= 3 {
        let s_u = div(std::array::from_fn(|c| {
            h[1][c].clone() - wd(1).clone() * &s[c]
        }));
        let s_v = div(std::array::from_fn(|c| {
            h[2][c].clone() - wd(2).clone() * &s[c]
        }));
        if h.len() >= 6 {
            // 2·W_u·s_u as a sum (exactly 2·RN(W_u·s_u) in f64, as (2·W_u)·s_u).
            let twice = |a: &T, b: &T| {
                let t = a.clone() * b;
                t.clone() + t
            };
            let s_uu = div(std::array::from_fn(|c| {
                h[3][c].clone() - twice(wd(1), &s_u[c]) - wd(3).clone() * &s[c]
            }));
            let s_uv = div(std::array::from_fn(|c| {
                h[4][c].clone()
                    - wd(1).clone() * &s_v[c]
                    - wd(2).clone() * &s_u[c]
                    - wd(4).clone() * &s[c]
            }));
            let s_vv = div(std::array::from_fn(|c| {
                h[5][c].clone() - twice(wd(2), &s_v[c]) - wd(5).clone() * &s[c]
            }));
            out.extend([s_u, s_v, s_uu, s_uv, s_vv]);
        } else {
            out.extend([s_u, s_v]);
        }
    }
    out
}
