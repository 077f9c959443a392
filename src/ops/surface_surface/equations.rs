//! The equations of surface ∩ surface, written once over [`Real`] (OPERATIONS.md §9–§10):
//! the system (9.1) `r(u, v) − s(a, b) = 0` with its Jacobian `[r_u r_v −s_a −s_b]`, the
//! curve tangent as the generalised cross product (10.2) of its rows, and the systems
//! the certifier solves — (9.1) as a [`CurveSystem`], the plane-constrained system
//! (10.13), and the height-critical system of the completeness proof.

use crate::certify::graph::CurveSystem;
use crate::certify::system::value_and_rows;
use crate::certify::System;
use crate::num::vector::{add, cross, dot, sub};
use crate::num::Real;
use crate::surface::Surface;

/// The jets of both surfaces at `x = [u, v, a, b]`.
#[derive(Debug, Clone)]
pub struct PairJet<T> {
    /// `[r, r_u, r_v, (r_uu, r_uv, r_vv)]`.
    pub r: Vec<[T; 3]>,
    /// `[s, s_a, s_b, (s_aa, s_ab, s_bb)]`.
    pub s: Vec<[T; 3]>,
}

impl<T: Real> PairJet<T> {
    /// Both jets of order `order` (0, 1 or 2).
    pub fn at<R: Surface, S: Surface>(r: &R, s: &S, x: &[T; 4], order: usize) -> Self {
        PairJet {
            r: r.jet(&x[0], &x[1], order),
            s: s.jet(&x[2], &x[3], order),
        }
    }

    /// (9.1): `r − s`.
    pub fn residual(&self) -> [T; 3] {
        sub(&self.r[0], &self.s[0])
    }

    /// The columns of the Jacobian of (9.1): `r_u, r_v, −s_a, −s_b`.
    pub fn columns(&self) -> [[T; 3]; 4] {
        let neg = |a: &[T; 3]| a.clone().map(|x| -x);
        [
            self.r[1].clone(),
            self.r[2].clone(),
            neg(&self.s[1]),
            neg(&self.s[2]),
        ]
    }

    /// The Jacobian of (9.1) as rows.
    pub fn jacobian_rows(&self) -> [[T; 4]; 3] {
        let c = self.columns();
        std::array::from_fn(|i| std::array::from_fn(|j| c[j][i].clone()))
    }

    /// `N_r = r_u × r_v` (1.6).
    pub fn normal_r(&self) -> [T; 3] {
        cross(&self.r[1], &self.r[2])
    }

    /// `N_s = s_a × s_b`.
    pub fn normal_s(&self) -> [T; 3] {
        cross(&self.s[1], &self.s[2])
    }

    /// (10.2): the parameter velocity `ẋ_j = (−1)^{j+1} M_j` of the curve, `M_j` the
    /// minor of `[r_u r_v −s_a −s_b]` without column `j`:
    /// `(r_v·N_s, −r_u·N_s, −N_r·s_b, N_r·s_a)`. Its space velocity is `N_s × N_r`.
    pub fn param_tangent(&self) -> [T; 4] {
        let (nr, ns) = (self.normal_r(), self.normal_s());
        [
            dot(&self.r[2], &ns),
            -dot(&self.r[1], &ns),
            -dot(&nr, &self.s[2]),
            dot(&nr, &self.s[1]),
        ]
    }
}

/// `N_r,u = r_uu × r_v + r_u × r_uv` and `N_r,v = r_uv × r_v + r_u × r_vv` from a jet of
/// order 2: the derivatives of the (unnormalised) normal.
pub fn normal_derivatives<T: Real>(j: &[[T; 3]]) -> [[T; 3]; 2] {
    [
        add(&cross(&j[3], &j[2]), &cross(&j[1], &j[4])),
        add(&cross(&j[4], &j[2]), &cross(&j[1], &j[5])),
    ]
}

/// `det(a, b, c) = a·(b × c)`.
pub fn det3<T: Real>(a: &[T; 3], b: &[T; 3], c: &[T; 3]) -> T {
    dot(a, &cross(b, c))
}

/// (9.1) as a curve system: 3 equations in `[u, v, a, b]`.
pub struct PairSystem<'a, R, S> {
    pub r: &'a R,
    pub s: &'a S,
}

impl<R: Surface, S: Surface> CurveSystem for PairSystem<'_, R, S> {
    fn equations(&self) -> usize {
        3
    }
    fn eval<T: Real>(&self, x: &[T]) -> Vec<T> {
        let x: [T; 4] = std::array::from_fn(|i| x[i].clone());
        PairJet::at(self.r, self.s, &x, 0).residual().to_vec()
    }
    /// The Jacobian `[r_u r_v −s_a −s_b]` from the surfaces' own first derivatives.
    fn eval_with_jacobian<T: Real>(&self, x: &[T]) -> (Vec<T>, Vec<Vec<T>>) {
        let x: [T; 4] = std::array::from_fn(|i| x[i].clone());
        let j = PairJet::at(self.r, self.s, &x, 1);
        let rows = j.jacobian_rows().into_iter().map(Vec::from).collect();
        (j.residual().to_vec(), rows)
    }
}

/// The height-critical system of the completeness proof: (9.1) and
/// `g = d·(N_r × N_s) = det(d, N_r, N_s) = 0`, four equations in `[u, v, a, b]`. Its roots
/// are the points of the intersection where the height `d·p` is stationary along the
/// curve (the tangent `∥ N_r × N_s` is `⊥ d`), and the points where the curve is not
/// regular (`N_r × N_s = 0`, or a surface's normal vanishes).
pub struct CriticalSystem<'a, R, S> {
    pub r: &'a R,
    pub s: &'a S,
    /// The height direction `d`.
    pub direction: [f64; 3],
}

impl<R: Surface, S: Surface> CriticalSystem<'_, R, S> {
    fn equations<T: Real>(&self, x: &[T], jacobian: bool) -> ([T; 4], Option<[[T; 4]; 4]>) {
        let x: [T; 4] = std::array::from_fn(|i| x[i].clone());
        let order = if jacobian { 2 } else { 1 };
        let j = PairJet::at(self.r, self.s, &x, order);
        let d = self.direction.map(|c| x[0].lift(c));
        let (nr, ns) = (j.normal_r(), j.normal_s());
        let f = j.residual();
        let g = det3(&d, &nr, &ns);
        let values = [f[0].clone(), f[1].clone(), f[2].clone(), g];
        let rows = jacobian.then(|| {
            let fr = j.jacobian_rows();
            let [nru, nrv] = normal_derivatives(&j.r);
            let [nsa, nsb] = normal_derivatives(&j.s);
            let last = [
                det3(&d, &nru, &ns),
                det3(&d, &nrv, &ns),
                det3(&d, &nr, &nsa),
                det3(&d, &nr, &nsb),
            ];
            [fr[0].clone(), fr[1].clone(), fr[2].clone(), last]
        });
        (values, rows)
    }
}

impl<R: Surface, S: Surface> System for CriticalSystem<'_, R, S> {
    fn dim(&self) -> usize {
        4
    }
    fn eval<T: Real>(&self, x: &[T]) -> Vec<T> {
        self.equations(x, false).0.to_vec()
    }
    /// The Jacobian from second-order jets: `∂g/∂u = det(d, N_r,u, N_s)` and so on
    /// (`normal_derivatives`).
    fn eval_with_jacobian<T: Real>(&self, x: &[T]) -> (Vec<T>, Vec<Vec<T>>) {
        let (f, j) = self.equations(x, true);
        value_and_rows(f, j)
    }
}

/// The common-normal system (the regular form of the tangency system (9.7), §9.5
/// "correction"): unknowns `[u, v, a, b, λ]`,
///
/// ```text
/// r(u, v) − s(a, b) − λ N_s(a, b) = 0,    N_s·r_u = 0,    N_s·r_v = 0.
/// ```
///
/// Its roots are the pairs of points with a common normal line; `λ|N_s|` is the signed
/// gap between the surfaces along it, so a root with `λ = 0` is a point where the
/// surfaces touch. Unlike (9.7) it does not vanish along the whole intersection curve
/// (there `N_s·r_u`, `N_s·r_v` are not both 0), and its Jacobian is regular at a
/// nondegenerate contact.
pub struct CommonNormalSystem<'a, R, S> {
    pub r: &'a R,
    pub s: &'a S,
}

impl<R: Surface, S: Surface> CommonNormalSystem<'_, R, S> {
    fn equations<T: Real>(&self, x: &[T], jacobian: bool) -> ([T; 5], Option<[[T; 5]; 5]>) {
        let p: [T; 4] = std::array::from_fn(|i| x[i].clone());
        let lambda = x[4].clone();
        let order = if jacobian { 2 } else { 1 };
        let j = PairJet::at(self.r, self.s, &p, order);
        let ns = j.normal_s();
        let d = j.residual();
        let values = [
            d[0].clone() - lambda.clone() * &ns[0],
            d[1].clone() - lambda.clone() * &ns[1],
            d[2].clone() - lambda.clone() * &ns[2],
            dot(&ns, &j.r[1]),
            dot(&ns, &j.r[2]),
        ];
        let rows = jacobian.then(|| {
            let [nsa, nsb] = normal_derivatives(&j.s);
            let zero = x[0].zero_like();
            let col = |k: usize| -> [T; 5] {
                match k {
                    0 => [
                        j.r[1][0].clone(),
                        j.r[1][1].clone(),
                        j.r[1][2].clone(),
                        dot(&ns, &j.r[3]),
                        dot(&ns, &j.r[4]),
                    ],
                    1 => [
                        j.r[2][0].clone(),
                        j.r[2][1].clone(),
                        j.r[2][2].clone(),
                        dot(&ns, &j.r[4]),
                        dot(&ns, &j.r[5]),
                    ],
                    2 | 3 => {
                        let (sd, nd) = if k == 2 {
                            (&j.s[1], &nsa)
                        } else {
                            (&j.s[2], &nsb)
                        };
                        let e: [T; 3] =
                            std::array::from_fn(|i| -sd[i].clone() - lambda.clone() * &nd[i]);
                        [
                            e[0].clone(),
                            e[1].clone(),
                            e[2].clone(),
                            dot(nd, &j.r[1]),
                            dot(nd, &j.r[2]),
                        ]
                    }
                    _ => [
                        -ns[0].clone(),
                        -ns[1].clone(),
                        -ns[2].clone(),
                        zero.clone(),
                        zero.clone(),
                    ],
                }
            };
            let cols: [[T; 5]; 5] = std::array::from_fn(col);
            std::array::from_fn(|i| std::array::from_fn(|k| cols[k][i].clone()))
        });
        (values, rows)
    }
}

impl<R: Surface, S: Surface> System for CommonNormalSystem<'_, R, S> {
    fn dim(&self) -> usize {
        5
    }
    fn eval<T: Real>(&self, x: &[T]) -> Vec<T> {
        self.equations(x, false).0.to_vec()
    }
    fn eval_with_jacobian<T: Real>(&self, x: &[T]) -> (Vec<T>, Vec<Vec<T>>) {
        let (f, j) = self.equations(x, true);
        value_and_rows(f, j)
    }
}
