//! A verified double root of a slightly perturbed system, in the style of Rump and
//! Graillat ("Verified error bounds for multiple roots of systems of nonlinear
//! equations", Numer. Algorithms 54, 2010): the perturbation `F(x) − e·e_κ` of one
//! equation `κ` by a constant `e` has a double root where
//!
//! ```text
//! F(x) − e·e_κ = 0,      J(x)·y = 0,      y_k = 1,
//! ```
//!
//! a square system of size `2n` in `(x, y without y_k, e)`, regular at a double root
//! where `J` has rank `n − 1`, `κ` is a component where the left null vector of `J` does
//! not vanish and the second derivative along the null vector `y` is not in the range of
//! `J`. Krawczyk on this system (with epsilon-inflation) proves a unique solution
//! `(x*, y*, e*)` in a box: `x*` is a singular root of the system perturbed by `e*` on
//! equation `κ`, and `|e*| ≤ mag(E)`, the reported perturbation. `J(x)y` is the
//! directional derivative, evaluated over one-direction [`Dual`] numbers, so the
//! Krawczyk step differentiates `F` twice (nested duals) from its one formula.

use super::boxes::IBox;
use super::dual::Dual;
use super::krawczyk::verify_near;
use super::level::CertInterval;
use super::newton::newton_point;
use super::system::System;
use crate::num::{IntervalLike, Real};

/// The deflated system of the module documentation.
#[derive(Debug, Clone, Copy)]
pub struct Deflated<'a, S> {
    sys: &'a S,
    /// The normalised component of `y`.
    k: usize,
    /// The perturbed equation.
    kappa: usize,
}

impl<'a, S: System> Deflated<'a, S> {
    /// The deflated system of `sys` with `y_k = 1`, perturbing equation `kappa`.
    pub fn new(sys: &'a S, k: usize, kappa: usize) -> Self {
        Deflated { sys, k, kappa }
    }

    /// The full null vector `y` from the unknowns (inserting `y_k = 1`).
    fn null_vector<T: Real>(&self, w: &[T]) -> Vec<T> {
        let n = self.sys.dim();
        let mut free = w[n..2 * n - 1].iter();
        (0..n)
            .map(|i| {
                if i == self.k {
                    w[0].one_like()
                } else {
                    free.next().cloned().unwrap_or_else(|| w[0].zero_like())
                }
            })
            .collect()
    }
}

impl<S: System> System for Deflated<'_, S> {
    fn dim(&self) -> usize {
        2 * self.sys.dim()
    }
    fn eval<T: Real>(&self, w: &[T]) -> Vec<T> {
        let n = self.sys.dim();
        let y = self.null_vector(w);
        let xd: Vec<Dual<T>> = w[..n]
            .iter()
            .zip(y)
            .map(|(xi, yi)| Dual {
                value: xi.clone(),
                grad: vec![yi],
            })
            .collect();
        let out = self.sys.eval(&xd);
        let e = &w[2 * n - 1];
        let mut res: Vec<T> = out
            .iter()
            .enumerate()
            .map(|(i, d)| {
                if i == self.kappa {
                    d.value.clone() - e
                } else {
                    d.value.clone()
                }
            })
            .collect();
        res.extend(out.iter().map(|d| d.partial(0)));
        res
    }
}

/// A verified double root of a perturbed system.
#[derive(Debug, Clone)]
pub struct DoubleRoot<I> {
    /// An enclosure of the double root `x*`.
    pub x: IBox<I>,
    /// An enclosure of the perturbation `e*` of equation `kappa`.
    pub e: I,
    /// The perturbed equation.
    pub kappa: usize,
}

impl<I: IntervalLike> DoubleRoot<I> {
    /// `max |e|` over the enclosure: the reported perturbation size.
    pub fn perturbation(&self) -> f64 {
        self.e.mag()
    }
}

/// Look for a double root of a perturbation of `sys` near the point `x0`, with
/// approximate right and left null vectors `v`, `u` of `J(x0)`: Newton on the deflated
/// system at the precision of `x0`, then Krawczyk with epsilon-inflation. The boxes of
/// the proof stay narrower than `max_width`.
pub fn double_root<S: System, I: CertInterval>(
    sys: &S,
    x0: &[I],
    v: &[f64],
    u: &[f64],
    max_width: f64,
) -> Option<DoubleRoot<I>> {
    let n = x0.len();
    let argmax = |a: &[f64]| (0..n).max_by(|&i, &j| a[i].abs().total_cmp(&a[j].abs()));
    let (k, kappa) = (argmax(v)?, argmax(u)?);
    if v[k] == 0.0 {
        return None;
    }
    let defl = Deflated::new(sys, k, kappa);
    let f0 = sys.eval(x0);
    let mut w0: Vec<I> = x0.to_vec();
    w0.extend((0..n).filter(|&i| i != k).map(|i| x0[0].lift(v[i] / v[k])));
    w0.push(f0[kappa].mid_interval());
    let (w, _) = newton_point(&defl, &w0, 40)?;
    let bits = w[0].precision_bits();
    let r = (-(f64::from(bits) - 8.0)).exp2();
    let radius: Vec<f64> = w.iter().map(|c| r * c.mag().max(1.0)).collect();
    let proof = verify_near(&defl, &w, &radius, max_width)?;
    let e = &proof.enclosure;
    Some(DoubleRoot {
        x: e[..n].to_vec(),
        e: e[2 * n - 1].clone(),
        kappa,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::num::{Interval, MpfrInterval};

    /// Circles x² + y² = 1 and (x − d)² + y² = 1.
    struct Circles(f64);
    impl System for Circles {
        fn dim(&self) -> usize {
            2
        }
        fn eval<T: Real>(&self, x: &[T]) -> Vec<T> {
            let one = x[0].one_like();
            vec![
                x[0].sqr() + x[1].sqr() - &one,
                (x[0].clone() - &x[0].lift(self.0)).sqr() + x[1].sqr() - &one,
            ]
        }
    }

    #[test]
    fn tangent_circles_have_a_double_root_with_zero_perturbation() {
        let x0 = [Interval::point(1.0 + 1e-9), Interval::point(1e-7)];
        let d = double_root(&Circles(2.0), &x0, &[0.0, 1.0], &[1.0, 0.9], 0.1).unwrap();
        assert!(d.x[0].contains(1.0) && d.x[1].contains(0.0));
        assert!(d.e.contains(0.0) && d.perturbation() < 1e-14);
    }

    #[test]
    fn near_miss_circles_need_the_gap_as_perturbation() {
        // centres 2 + g apart: perturbing one equation by e* = 2g + g²/... closes the gap
        let g = 2f64.powi(-40);
        let x0: Vec<MpfrInterval> =
            vec![MpfrInterval::point(1.0, 128), MpfrInterval::point(0.0, 128)];
        let d = double_root(&Circles(2.0 + g), &x0, &[0.0, 1.0], &[1.0, 0.9], 0.1).unwrap();
        // the double root of the perturbed problem: first circle x² + y² = 1 + e (κ = 0),
        // tangent to the second one at y = 0: 1 + √(1+e) = 2 + g ⇒ e = (1+g)² − 1 = 2g + g²
        let e = 2.0 * g + g * g;
        assert!(d.e.contains(e), "{:?}", d.e);
        assert_eq!(d.kappa, 0);
        assert!(d.x[0].contains(1.0 + g) && d.x[1].contains(0.0));
    }
}
