//! A proof that a system has at most two roots (counted with multiplicity) in a region
//! around a nearly singular root, by a Lyapunov–Schmidt reduction to one variable and
//! Rolle's theorem; and, on the same reduction, a proof that it has none.
//!
//! Local coordinates: a point `m`, a pivot coordinate `k` and an approximate null
//! direction `q` of `J(m)` with `q_k = 1`. With `w = (z, t)`, `z ∈ ℝⁿ⁻¹` indexing the
//! coordinates `j ≠ k`,
//!
//! ```text
//! x_k = m_k + t,      x_j = m_j + z_j + t·q_j   (j ≠ k),
//! ```
//!
//! a shear, exactly invertible (`t = x_k − m_k`, `z_j = x_j − m_j − t q_j`). The system is
//! preconditioned, `G(w) = Y·F(x(w))`, with `Y` the inverse of `J(m)·[e_j, q]` whose last
//! column is replaced by the left null vector `u`, so that `∂G/∂w ≈ diag(I, 0)`. Write
//! `G = (G', g)`, `A = ∂G'/∂z`. Every root of `F` is a root of `G`.
//!
//! 1. *Parametric Krawczyk* on `G'(·, t)` over `Z` with `t ∈ T` as an interval: if
//!    `K(Z, T) ⊆ int Z`, then for every `t ∈ T` there is exactly one `z(t) ∈ Z` with
//!    `G'(z(t), t) = 0`, and `A` is nonsingular on the region, so `z` is `C²` on `T`
//!    (implicit function theorem) and the roots of `G` in `Z × T` are the points
//!    `(z(t), t)` with `φ(t) = g(z(t), t) = 0`.
//! 2. *Second derivative*: differentiating `G'(z(t), t) = 0` twice gives
//!    `A z' = −G'_t` and `A z'' = −(G'_tt + 2 G'_tz z' + z'ᵀ G'_zz z')`, and
//!    `φ'' = g_tt + 2 g_tz z' + z'ᵀ g_zz z' + g_z z''`. Enclosing every term over the
//!    region (second derivatives by nested [`super::dual::Dual`] numbers, the linear
//!    solves by [`solve_enclosure`]) and finding `0 ∉ φ''` proves `φ'` strictly monotone:
//!    `φ'` has at most one zero, so `φ` has at most two zeros counted with multiplicity
//!    (Rolle), and a root where `φ' = 0` — a singular root of `F` — is the only one.
//! 3. *No root*: if `φ'' > 0` on `T` (convex), then `φ(t) ≥ φ(t₀) + φ'(t₀)(t − t₀)` for
//!    all `t ∈ T`; a positive lower bound of the right side over `T` proves `φ > 0`, so no
//!    root (symmetrically for `φ'' < 0`). `φ(t₀)`, `φ'(t₀)` are enclosed through a tight
//!    enclosure of `z(t₀)`.
//!
//! All the region's points are covered: the caller's box is mapped into local
//! coordinates with interval arithmetic (outward), and `Z × T` contains that image.

use super::boxes::{self, IBox};
use super::dual::{jet2, Dual};
use super::guarded::{all_smooth, Guarded};
use super::krawczyk::smooth_jacobian;
use super::level::CertInterval;
use super::linalg::{identity_minus_product, inverse_f64, mat_vec, mid_matrix, norm_inf_upper};
use super::system::System;
use crate::num::interval::directed::{add_down, div_up};
use crate::num::{IntervalLike, Real};

/// The local coordinates and preconditioner of the module documentation.
#[derive(Debug, Clone)]
pub struct Local<'a, S> {
    sys: &'a S,
    m: Vec<f64>,
    k: usize,
    q: Vec<f64>,
    y: Vec<Vec<f64>>,
}

impl<'a, S: System> Local<'a, S> {
    /// Local coordinates at `m` along `q` (normalised here to `q_k = 1`, `k` its largest
    /// component), preconditioned with the left null vector `u`; `None` if degenerate.
    pub fn new(sys: &'a S, m: &[f64], q: &[f64], u: &[f64]) -> Option<Self> {
        let n = m.len();
        let k = (0..n).max_by(|&i, &j| q[i].abs().total_cmp(&q[j].abs()))?;
        if q[k] == 0.0 {
            return None;
        }
        let q: Vec<f64> = q.iter().map(|v| v / q[k]).collect();
        let jm = sys.jacobian(m);
        // columns e_j (j ≠ k) of J(m), then u in place of J(m) q
        let mut cols: Vec<Vec<f64>> = (0..n)
            .filter(|&j| j != k)
            .map(|j| (0..n).map(|i| jm[i][j]).collect())
            .collect();
        cols.push(u.to_vec());
        let mt: Vec<Vec<f64>> = (0..n)
            .map(|i| (0..n).map(|c| cols[c][i]).collect())
            .collect();
        let y = inverse_f64(&mt)?;
        Some(Local {
            sys,
            m: m.to_vec(),
            k,
            q,
            y,
        })
    }

    /// The pivot coordinate `k`.
    pub fn pivot(&self) -> usize {
        self.k
    }

    /// The null direction (with `q_k = 1`).
    pub fn direction(&self) -> &[f64] {
        &self.q
    }

    /// The centre `m`.
    pub fn centre(&self) -> &[f64] {
        &self.m
    }

    /// `x(w)` (module doc), in any number type.
    pub fn to_global<T: Real>(&self, w: &[T]) -> Vec<T> {
        let n = self.m.len();
        let t = &w[n - 1];
        let mut z = w[..n - 1].iter();
        (0..n)
            .map(|j| {
                let mj = t.lift(self.m[j]);
                if j == self.k {
                    mj + t
                } else {
                    let zj = z.next().cloned().unwrap_or_else(|| t.zero_like());
                    mj + &zj + &(t.clone() * &t.lift(self.q[j]))
                }
            })
            .collect()
    }

    /// An enclosure of `w(x)` for every `x` in the box (interval arithmetic on the
    /// inverse shear).
    pub fn to_local<I: IntervalLike>(&self, x: &[I]) -> IBox<I> {
        let n = self.m.len();
        let t = x[self.k].clone() - &x[self.k].lift(self.m[self.k]);
        let mut w: IBox<I> = (0..n)
            .filter(|&j| j != self.k)
            .map(|j| x[j].clone() - &x[j].lift(self.m[j]) - &(t.clone() * &t.lift(self.q[j])))
            .collect();
        w.push(t);
        w
    }
}

impl<S: System> System for Local<'_, S> {
    fn dim(&self) -> usize {
        self.m.len()
    }
    fn eval<T: Real>(&self, w: &[T]) -> Vec<T> {
        let f = self.sys.eval(&self.to_global(w));
        self.y
            .iter()
            .map(|row| {
                let mut acc = w[0].zero_like();
                for (yij, fj) in row.iter().zip(&f) {
                    acc = acc + fj.clone() * &fj.lift(*yij);
                }
                acc
            })
            .collect()
    }
}

/// An enclosure of `{A⁻¹ b : A ∈ a, b ∈ b}` for an interval matrix `a` close to a matrix
/// with approximate inverse `y`: with `C = I − y a` and `‖C‖∞ ≤ c < 1`, every solution
/// satisfies `x = y b + C x` and `‖x‖∞ ≤ ‖y b‖∞ / (1 − c) =: ρ`, hence
/// `x ∈ y b + C·[−ρ, ρ]ⁿ`. `None` if `c ≥ 1` (or the data are not finite).
pub fn solve_enclosure<I: IntervalLike>(y: &[Vec<I>], c: &[Vec<I>], b: &[I]) -> Option<Vec<I>> {
    if b.is_empty() {
        return Some(Vec::new());
    }
    let cn = norm_inf_upper(c);
    if cn.is_nan() || cn >= 1.0 {
        return None;
    }
    let yb = mat_vec(y, b);
    let ybn = yb.iter().fold(0.0, |s: f64, v| s.max(v.mag()));
    let rho = div_up(ybn, add_down(1.0, -cn));
    if !rho.is_finite() {
        return None;
    }
    let ball: Vec<I> = b.iter().map(|v| v.with_bounds(-rho, rho)).collect();
    let cb = mat_vec(c, &ball);
    Some(yb.into_iter().zip(cb).map(|(a, d)| a + d).collect())
}

/// A proven region of at most two roots (module doc, steps 1–2).
#[derive(Debug, Clone)]
pub struct CountRegion<'a, S, I> {
    /// The local coordinates.
    pub local: Local<'a, S>,
    /// `Z × T` (the last side is `T`).
    pub region: IBox<I>,
    /// The sign of `φ''` on the region (+1 or −1).
    pub curvature_sign: f64,
}

impl<S: System, I: CertInterval> CountRegion<'_, S, I> {
    /// True if every point of the box `x` lies in the region.
    pub fn covers(&self, x: &[I]) -> bool {
        boxes::is_subset(&self.local.to_local(x), &self.region)
    }
}

/// Split a [`Jet2`](super::dual::Jet2)-like Jacobian of `G` over the region into `A`
/// (`∂G'/∂z`) and `G'_t`.
fn blocks<I: Clone>(jac: &[Vec<I>]) -> (Vec<Vec<I>>, Vec<I>) {
    let n = jac.len();
    let a = jac[..n - 1].iter().map(|r| r[..n - 1].to_vec()).collect();
    let gt = jac[..n - 1].iter().map(|r| r[n - 1].clone()).collect();
    (a, gt)
}

fn unguard<I>(v: Vec<Guarded<I>>) -> Vec<I> {
    v.into_iter().map(|g| g.value).collect()
}

/// Step 1: the parametric Krawczyk test with epsilon-inflation of `Z`; returns the
/// region `Z × T` on success.
fn parametric_krawczyk<S: System, I: CertInterval>(
    local: &Local<'_, S>,
    mut w: IBox<I>,
) -> Option<IBox<I>> {
    let n = w.len();
    if n == 1 {
        return Some(w);
    }
    let bits = w[0].precision_bits();
    let ulps = (-(f64::from(bits) - 4.0)).exp2();
    for _ in 0..6 {
        let (_, jac) = smooth_jacobian(local, &w)?;
        let (a, _) = blocks(&jac);
        let mut c_pt = boxes::midpoint(&w[..n - 1]);
        c_pt.push(w[n - 1].clone());
        let gc: Vec<Guarded<I>> = c_pt.iter().cloned().map(Guarded::new).collect();
        let fc = local.eval(&gc);
        if !all_smooth(&fc) {
            return None;
        }
        let fc = unguard(fc);
        let ya = I::approx_inverse(&mid_matrix(&a))?;
        let cm = identity_minus_product(&ya, &a);
        let yf = mat_vec(&ya, &fc[..n - 1]);
        let d: Vec<I> = (0..n - 1).map(|i| w[i].clone() - &c_pt[i]).collect();
        let cd = mat_vec(&cm, &d);
        let k: Vec<I> = (0..n - 1)
            .map(|i| c_pt[i].clone() - &yf[i] + &cd[i])
            .collect();
        if boxes::is_interior(&k, &w[..n - 1]) {
            return Some(w);
        }
        let grown = boxes::inflate_scaled(&boxes::hull(&k, &w[..n - 1]), 0.1, ulps);
        w[..n - 1].clone_from_slice(&grown);
    }
    None
}

/// Steps 1–2 for the box `target`: a region containing it in which the system has at
/// most two roots counted with multiplicity, or `None` if that is not proven.
pub fn at_most_two_roots<'a, S: System, I: CertInterval>(
    local: Local<'a, S>,
    target: &[I],
) -> Option<CountRegion<'a, S, I>> {
    let n = target.len();
    let mut w = local.to_local(target);
    let bits = target[0].precision_bits();
    let ulps = (-(f64::from(bits) - 4.0)).exp2();
    let t_side = w[n - 1].clone();
    w = boxes::inflate_scaled(&w, 0.25, ulps);
    w[n - 1] = t_side;
    let w = parametric_krawczyk(&local, w)?;
    let gw: Vec<Guarded<I>> = w.iter().cloned().map(Guarded::new).collect();
    let jet = jet2(&gw, |d: &[Dual<Dual<Guarded<I>>>]| local.eval(d));
    let smooth = all_smooth(&jet.value)
        && jet.jacobian.iter().all(|r| all_smooth(r))
        && jet.hessian.iter().flatten().all(|r| all_smooth(r));
    if !smooth {
        return None;
    }
    let jac: Vec<Vec<I>> = jet.jacobian.into_iter().map(unguard).collect();
    let hess: Vec<Vec<Vec<I>>> = jet
        .hessian
        .into_iter()
        .map(|h| h.into_iter().map(unguard).collect())
        .collect();
    let phi2 = second_derivative(&jac, &hess)?;
    let sign = if phi2.inf() > 0.0 {
        1.0
    } else if phi2.sup() < 0.0 {
        -1.0
    } else {
        return None;
    };
    Some(CountRegion {
        local,
        region: w,
        curvature_sign: sign,
    })
}

/// Step 2's enclosure of `φ''` over the region from the Jacobian and Hessians of `G`.
fn second_derivative<I: CertInterval>(jac: &[Vec<I>], hess: &[Vec<Vec<I>>]) -> Option<I> {
    let n = jac.len();
    let t = n - 1;
    let zero = jac[0][0].zero_like();
    let two = zero.lift(2.0);
    let (a, gt) = blocks(jac);
    let (ya, cm) = if n > 1 {
        let ya = I::approx_inverse(&mid_matrix(&a))?;
        let cm = identity_minus_product(&ya, &a);
        (ya, cm)
    } else {
        (Vec::new(), Vec::new())
    };
    let neg: Vec<I> = gt.iter().map(|v| -v.clone()).collect();
    let zt = solve_enclosure(&ya, &cm, &neg)?;
    // the second-order term of component i: h_tt + 2 h_tz z' + z'ᵀ h_zz z'
    let second = |h: &Vec<Vec<I>>| {
        let mut s = h[t][t].clone();
        for a in 0..t {
            s = s + two.clone() * &h[t][a] * &zt[a];
            for b in 0..t {
                s = s + h[a][b].clone() * &zt[a] * &zt[b];
            }
        }
        s
    };
    let rhs: Vec<I> = (0..t).map(|i| -second(&hess[i])).collect();
    let ztt = solve_enclosure(&ya, &cm, &rhs)?;
    let mut phi2 = second(&hess[t]);
    for a in 0..t {
        phi2 = phi2 + jac[t][a].clone() * &ztt[a];
    }
    (!phi2.is_empty()).then_some(phi2)
}

/// Step 3: true if `φ` has no zero on `T` (so the region holds no root), using the
/// point `t0 ∈ T` (a good choice is where `φ'` nearly vanishes).
pub fn no_root<S: System, I: CertInterval>(count: &CountRegion<'_, S, I>, t0: f64) -> bool {
    let w = &count.region;
    let n = w.len();
    let tside = &w[n - 1];
    let t0 = t0.clamp(tside.inf(), tside.sup());
    let tp = tside.lift(t0);
    if !tp.is_subset(tside) {
        return false;
    }
    // a tight enclosure of z(t0): iterate the Krawczyk step of G'(·, t0) from Z
    let mut z: IBox<I> = w[..n - 1].to_vec();
    let local = &count.local;
    let full = |z: &[I]| {
        let mut v = z.to_vec();
        v.push(tp.clone());
        v
    };
    let guard = |v: Vec<I>| v.into_iter().map(Guarded::new).collect::<Vec<_>>();
    for _ in 0..8 {
        if n == 1 {
            break;
        }
        let Some((_, jac)) = smooth_jacobian(local, &full(&z)) else {
            return false;
        };
        let (a, _) = blocks(&jac);
        let Some(ya) = I::approx_inverse(&mid_matrix(&a)) else {
            return false;
        };
        let c = boxes::midpoint(&z);
        let fc = unguard(local.eval(&guard(full(&c))));
        let cm = identity_minus_product(&ya, &a);
        let yf = mat_vec(&ya, &fc[..n - 1]);
        let d: Vec<I> = (0..n - 1).map(|i| z[i].clone() - &c[i]).collect();
        let cd = mat_vec(&cm, &d);
        let k: Vec<I> = (0..n - 1).map(|i| c[i].clone() - &yf[i] + &cd[i]).collect();
        match boxes::intersection(&z, &k) {
            Some(next) => z = next,
            None => return false,
        }
    }
    let Some((g, jac)) = smooth_jacobian(local, &full(&z)) else {
        return false;
    };
    let (a, gt) = blocks(&jac);
    let mut phi1 = jac[n - 1][n - 1].clone();
    if n > 1 {
        let Some(ya) = I::approx_inverse(&mid_matrix(&a)) else {
            return false;
        };
        let cm = identity_minus_product(&ya, &a);
        let neg: Vec<I> = gt.iter().map(|v| -v.clone()).collect();
        let Some(zt) = solve_enclosure(&ya, &cm, &neg) else {
            return false;
        };
        for i in 0..n - 1 {
            phi1 = phi1 + jac[n - 1][i].clone() * &zt[i];
        }
    }
    let bound = g[n - 1].clone() + phi1 * (tside.clone() - &tp);
    if bound.is_empty() {
        return false;
    }
    if count.curvature_sign > 0.0 {
        bound.inf() > 0.0
    } else {
        bound.sup() < 0.0
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::num::Interval;

    /// `x² + c` (one variable): two roots `±√−c`, a double root, or none.
    struct Parabola(f64);
    impl System for Parabola {
        fn dim(&self) -> usize {
            1
        }
        fn eval<T: Real>(&self, x: &[T]) -> Vec<T> {
            vec![x[0].sqr() + x[0].lift(self.0)]
        }
    }

    /// `x³`: a triple root, more than the count can bound.
    struct Cubic;
    impl System for Cubic {
        fn dim(&self) -> usize {
            1
        }
        fn eval<T: Real>(&self, x: &[T]) -> Vec<T> {
            vec![x[0].powi(3)]
        }
    }

    fn around_zero(r: f64) -> Vec<Interval> {
        vec![Interval::from_bounds(-r, r)]
    }

    #[test]
    fn count_and_exclusion_in_one_variable() {
        for (c, roots) in [(-1e-20, true), (0.0, true), (1e-20, false)] {
            let sys = Parabola(c);
            let local = Local::new(&sys, &[0.0], &[1.0], &[1.0]).unwrap();
            let count = at_most_two_roots(local, &around_zero(1e-3)).unwrap();
            assert_eq!(count.curvature_sign, 1.0);
            assert!(count.covers(&around_zero(1e-3)));
            assert_eq!(no_root(&count, 0.0), !roots, "c = {c}");
        }
        let local = Local::new(&Cubic, &[0.0], &[1.0], &[1.0]).unwrap();
        assert!(at_most_two_roots(local, &around_zero(1e-3)).is_none());
    }

    #[test]
    fn local_coordinates_round_trip() {
        let sys = Parabola(0.0);
        let mut local = Local::new(&sys, &[0.0], &[1.0], &[1.0]).unwrap();
        // a 3-variable shear by hand: m = (1, 2, 3), k = 1, q = (0.5, 1, −2)
        local.m = vec![1.0, 2.0, 3.0];
        local.k = 1;
        local.q = vec![0.5, 1.0, -2.0];
        let w = [
            Interval::point(0.25),
            Interval::point(-0.5),
            Interval::point(0.125),
        ];
        let x = local.to_global(&w);
        assert_eq!(
            x,
            vec![
                Interval::point(1.3125),
                Interval::point(2.125),
                Interval::point(2.25)
            ]
        );
        assert_eq!(local.to_local(&x), w.to_vec());
    }

    #[test]
    fn linear_solve_enclosure_contains_the_solutions() {
        let iv = |m: f64| Interval::from_bounds(m - 0.01, m + 0.01);
        let a = vec![vec![iv(2.0), iv(1.0)], vec![iv(1.0), iv(3.0)]];
        let y = crate::certify::level::CertInterval::approx_inverse(&mid_matrix(&a)).unwrap();
        let c = identity_minus_product(&y, &a);
        let x = solve_enclosure(&y, &c, &[Interval::point(1.0), Interval::point(2.0)]).unwrap();
        // the solution for the midpoint matrix, (1/5, 3/5), and for two corner matrices
        assert!(x[0].contains(0.2) && x[1].contains(0.6));
        for (a00, a11) in [(2.01, 2.99), (1.99, 3.01)] {
            let det = a00 * a11 - 1.0;
            let (s0, s1) = ((a11 - 2.0) / det, (2.0 * a00 - 1.0) / det);
            assert!(x[0].contains(s0) && x[1].contains(s1));
        }
    }
}
