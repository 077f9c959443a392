//! Tight interval enclosures of a tensor-product patch over a parameter box: the
//! centred (Taylor) form of the polynomial pieces.
//!
//! On one pair of spans the homogeneous patch `H(u, v) = Σ N_j(u) N_i(v) Q_ij` is a
//! polynomial of degree `(p, q)`, so it equals its Taylor expansion at the box centre
//! `(m_u, m_v)` exactly:
//!
//! `H(m_u + δ_u, m_v + δ_v) = Σ_{k ≤ p, l ≤ q} C_kl δ_u^k δ_v^l`,
//! `C_kl = Σ_ij (N_j^{(k)}(m_u)/k!) (N_i^{(l)}(m_v)/l!) Q_ij`,
//!
//! and `∂_u^a ∂_v^b H = Σ C_kl k!/(k−a)! l!/(l−b)! δ_u^{k−a} δ_v^{l−b}`. The coefficients
//! come from point evaluations at the centre (narrow intervals), and only the powers of
//! `δ ∈ [lo − m, hi − m]` are wide, so the enclosure converges to the true range as the
//! box shrinks — unlike the direct sum `Σ N_j(u) P_j` over an interval `u`, which loses
//! the cancellation `Σ N_j' = 0` and overestimates by a constant factor.
//!
//! Before the powers are summed the patch is translated by `P_ref ≈ s(m)` (an f64 point):
//! `C'^A = C^A − P_ref C^W`, so the quotient rule works on `s − P_ref`, which is small on
//! the box, and its cancellations stay small. Every step is an identity evaluated by
//! enclosing operations, so the result encloses the jet over the box.

use super::basis::BasisJet;
use super::sets::meet;
use super::tensor::{quotient, Net, ORDERS};
use crate::num::vector::lift;
use crate::num::Real;

/// `true` for a point parameter (f64, or a point interval): evaluated directly.
pub(crate) fn is_point<T: Real>(t: &T) -> bool {
    let (lo, hi) = t.bounds();
    lo == hi
}

/// The centre `m` of a parameter interval as an exact point of the number type,
/// `δ = t − m` (an enclosure of the offsets; exact for f64), and whether `m` is proven
/// to lie in `t`: strictly between the outward f64 bounds (a double strictly above
/// `round_down(lo)` is at least `lo`), or `t` is that double. (A very narrow MPFR
/// interval can lie between two doubles, so its rounded midpoint can lie outside it;
/// the Taylor form does not mind, the mean value form does.)
pub(crate) fn centre<T: Real>(t: &T) -> (T, T, bool) {
    let x = t.mid();
    let (lo, hi) = t.bounds();
    let inside = (lo < x && x < hi) || (lo == hi && x == lo);
    let m = t.lift(x);
    let delta = t.clone() - &m;
    (m, delta, inside)
}

/// `k!` as a double (exact for the degrees used here).
fn factorial(k: usize) -> f64 {
    (1..=k).map(|i| i as f64).product()
}

/// `k!/(k−a)!`.
fn falling(k: usize, a: usize) -> f64 {
    ((k - a + 1)..=k).map(|i| i as f64).product()
}

/// `δ^e` for `e = 0..=n` (`powi`: tight for intervals that contain 0).
fn powers<T: Real>(delta: &T, n: usize) -> Vec<T> {
    (0..=n).map(|e| delta.powi(e as i32)).collect()
}

/// The homogeneous jet `∂_u^a ∂_v^b H` over the box `m + δ` (jet order), of dimension `D`,
/// with `H` translated so that `C_00 ≈ 0` in its first three components; also the same
/// derivatives at the centre, and the translation `P_ref`.
#[allow(clippy::too_many_arguments)]
fn centred_homogeneous<T: Real, const D: usize>(
    bu: &BasisJet<T>,
    delta_u: &T,
    first_u: usize,
    bv: &BasisJet<T>,
    delta_v: &T,
    first_v: usize,
    order: usize,
    point: impl Fn(usize, usize) -> [T; D],
) -> ([f64; 3], Vec<[T; D]>, Vec<[T; D]>) {
    let like = delta_u;
    let (a, b) = (basis_taylor(bu, like), basis_taylor(bv, like));
    let shape = Shape {
        p: bu.degree,
        q: bv.degree,
    };
    let point = |i, j| point(first_v + i, first_u + j);
    let mut coef = patch_coefficients(&a, &b, shape, point, like);
    let reference = translate(&mut coef, like);
    let len = match order {
        0 => 1,
        1 => 3,
        _ => 6,
    };
    let at_centre = at_centre(&coef, shape, len, like);
    let over_box = over_box(&coef, shape, delta_u, delta_v, order, len);
    (reference, over_box, at_centre)
}

/// The degrees `(p, q)` of a span pair: its coefficients `C_kl` are stored at
/// `k·(q+1) + l`.
#[derive(Clone, Copy)]
struct Shape {
    p: usize,
    q: usize,
}

/// `D` zeros in the number system of `like`.
fn zeros<T: Real, const D: usize>(like: &T) -> [T; D] {
    std::array::from_fn(|_| like.zero_like())
}

/// Taylor coefficients of the basis at the centre: `a[k·(n+1) + j] = N_j^{(k)}(m)/k!`.
fn basis_taylor<T: Real>(b: &BasisJet<T>, like: &T) -> Vec<T> {
    let n = b.degree;
    let mut out = Vec::with_capacity((n + 1) * (n + 1));
    for k in 0..=n {
        let f = like.lift(factorial(k));
        out.extend((0..=n).map(|j| b.get(k, j).clone() / &f));
    }
    out
}

/// The patch's Taylor coefficients at the centre, `C_kl = Σ_i b_li Σ_j a_kj Q_ij`, from
/// the basis coefficients and the control points `point(i, j)` of the span pair.
fn patch_coefficients<T: Real, const D: usize>(
    a: &[T],
    b: &[T],
    Shape { p, q }: Shape,
    point: impl Fn(usize, usize) -> [T; D],
    like: &T,
) -> Vec<[T; D]> {
    // rows[i·(p+1) + k] = Σ_j a_kj Q_ij
    let mut rows: Vec<[T; D]> = vec![zeros(like); (q + 1) * (p + 1)];
    for i in 0..=q {
        for j in 0..=p {
            let pt = point(i, j);
            for k in 0..=p {
                let (akj, r) = (&a[k * (p + 1) + j], &mut rows[i * (p + 1) + k]);
                for c in 0..D {
                    r[c] = r[c].clone() + akj.clone() * &pt[c];
                }
            }
        }
    }
    // coef[k·(q+1) + l] = Σ_i b_li rows[i][k]
    let mut coef: Vec<[T; D]> = vec![zeros(like); (p + 1) * (q + 1)];
    for k in 0..=p {
        for l in 0..=q {
            let acc = &mut coef[k * (q + 1) + l];
            for i in 0..=q {
                let (bli, r) = (&b[l * (q + 1) + i], &rows[i * (p + 1) + k]);
                for c in 0..D {
                    acc[c] = acc[c].clone() + bli.clone() * &r[c];
                }
            }
        }
    }
    coef
}

/// Translate by `P_ref ≈ s(m)`: `A' = A − P_ref·W` (`W ≡ 1` for polynomial patches,
/// `D = 3`). Returns `P_ref`.
fn translate<T: Real, const D: usize>(coef: &mut [[T; D]], like: &T) -> [f64; 3] {
    let c00 = &coef[0];
    let reference: [f64; 3] = std::array::from_fn(|c| {
        let x = if D == 4 {
            (c00[c].clone() / &c00[3]).mid()
        } else {
            c00[c].mid()
        };
        if x.is_finite() {
            x
        } else {
            0.0
        }
    });
    let r = lift(like, &reference);
    if D == 4 {
        for cl in coef.iter_mut() {
            for c in 0..3 {
                cl[c] = cl[c].clone() - r[c].clone() * &cl[3];
            }
        }
    } else {
        for c in 0..3 {
            coef[0][c] = coef[0][c].clone() - &r[c];
        }
    }
    reference
}

/// The derivatives at the centre (`δ = 0`), the first `len` in jet order:
/// `∂_u^a ∂_v^b H(m) = a! b! C_ab`.
fn at_centre<T: Real, const D: usize>(
    coef: &[[T; D]],
    Shape { p, q }: Shape,
    len: usize,
    like: &T,
) -> Vec<[T; D]> {
    ORDERS[..len]
        .iter()
        .map(|&(da, db)| {
            let f = like.lift(factorial(da) * factorial(db));
            let c = if da <= p && db <= q {
                coef[da * (q + 1) + db].clone()
            } else {
                zeros(like)
            };
            std::array::from_fn(|i| f.clone() * &c[i])
        })
        .collect()
}

/// Powers of `δ` with the derivative factors: `f[a][k] = k!/(k−a)! δ^{k−a}` (`a ≤ 2`,
/// `k ≤ n`; 0 for `k < a`), constants in the number system of `like`.
fn derivative_powers<T: Real>(delta: &T, n: usize, like: &T) -> [Vec<T>; 3] {
    let pw = powers(delta, n);
    std::array::from_fn(|a| {
        (0..=n)
            .map(|k| {
                if k < a {
                    like.zero_like()
                } else {
                    like.lift(falling(k, a)) * &pw[k - a]
                }
            })
            .collect()
    })
}

/// The derivatives over the box, the first `len` in jet order: with
/// `g[b][k] = Σ_l fv[b][l] C_kl`, `H_ab = Σ_k fu[a][k] g[b][k]`.
fn over_box<T: Real, const D: usize>(
    coef: &[[T; D]],
    Shape { p, q }: Shape,
    delta_u: &T,
    delta_v: &T,
    order: usize,
    len: usize,
) -> Vec<[T; D]> {
    let like = delta_u;
    let (fu, fv) = (
        derivative_powers(delta_u, p, like),
        derivative_powers(delta_v, q, like),
    );
    let b_max = order.min(2);
    let g: Vec<Vec<[T; D]>> = (0..=b_max)
        .map(|bb| {
            (0..=p)
                .map(|k| {
                    let mut acc = zeros(like);
                    for l in bb..=q {
                        let f = &fv[bb][l];
                        let cl = &coef[k * (q + 1) + l];
                        for c in 0..D {
                            acc[c] = acc[c].clone() + f.clone() * &cl[c];
                        }
                    }
                    acc
                })
                .collect()
        })
        .collect();
    ORDERS[..len]
        .iter()
        .map(|&(da, db)| {
            let mut acc = zeros(like);
            for k in da..=p {
                let f = &fu[da][k];
                for c in 0..D {
                    acc[c] = acc[c].clone() + f.clone() * &g[db][k][c];
                }
            }
            acc
        })
        .collect()
}

/// The jet of the patch on one pair of spans over the box `m + δ`, from the basis
/// derivatives at the centre up to the degrees (`bu.order() == bu.degree`).
///
/// For rational patches the quotient rule over the box overestimates the first
/// derivatives to first order in the box width (`W_u·s` and `A_u` vary together), so
/// `s`, `s_u`, `s_v` are also enclosed by the mean value form
/// `E(m) + E_u(box)·δ_u + E_v(box)·δ_v` (valid on one polynomial piece: `E` is smooth
/// there; and only when the centre lies in the box, `centre_inside`, so that the segment
/// from `m` to any point stays in it) and the two enclosures are intersected
/// ([`super::sets::meet`]).
///
/// Callers try the midpoint–radius evaluation of [`super::taylor_fast`] first (f64
/// intervals: the same identities at about a sixth of the cost); this generic code
/// serves the other number types and the boxes it declines.
#[allow(clippy::too_many_arguments)]
pub(crate) fn taylor_tensor_jet<T: Real>(
    net: &Net,
    bu: &BasisJet<T>,
    delta_u: &T,
    first_u: usize,
    bv: &BasisJet<T>,
    delta_v: &T,
    first_v: usize,
    order: usize,
    centre_inside: bool,
) -> Vec<[T; 3]> {
    let like = delta_u;
    let (reference, mut jet) = match &net.weights {
        None => {
            let (reference, h, _) =
                centred_homogeneous(bu, delta_u, first_u, bv, delta_v, first_v, order, |i, j| {
                    lift(like, &net.points[i * net.cols + j])
                });
            (reference, h)
        }
        Some(w) => {
            // The mean value form of the first derivatives needs the second ones.
            let inner = if order >= 1 { 2 } else { 0 };
            let (reference, h, at_centre) =
                centred_homogeneous(bu, delta_u, first_u, bv, delta_v, first_v, inner, |i, j| {
                    let k = i * net.cols + j;
                    let wt = like.lift(w[k]);
                    let p = &net.points[k];
                    [
                        wt.clone() * like.lift(p[0]),
                        wt.clone() * like.lift(p[1]),
                        wt.clone() * like.lift(p[2]),
                        wt,
                    ]
                });
            let mut jet = quotient(&h);
            if order >= 1 && centre_inside {
                let centre = quotient(&at_centre);
                let mvf = |e: usize, eu: usize, ev: usize, jet: &[[T; 3]]| -> [T; 3] {
                    std::array::from_fn(|c| {
                        let form = centre[e][c].clone()
                            + jet[eu][c].clone() * delta_u
                            + jet[ev][c].clone() * delta_v;
                        meet(&jet[e][c], &form)
                    })
                };
                jet[1] = mvf(1, 3, 4, &jet);
                jet[2] = mvf(2, 4, 5, &jet);
                jet[0] = mvf(0, 1, 2, &jet);
            }
            jet.truncate(match order {
                0 => 1,
                1 => 3,
                _ => 6,
            });
            (reference, jet)
        }
    };
    let r = lift(like, &reference);
    jet[0] = std::array::from_fn(|c| jet[0][c].clone() + &r[c]);
    jet
}
