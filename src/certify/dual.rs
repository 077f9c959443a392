//! Forward-mode dual numbers generic over [`Real`], so that a system's Jacobian (and,
//! nested, its Hessians) is computed from its one `eval` formula (ARCHITECTURE.md
//! "one formula, written once").
//!
//! A [`Dual`] is `value + Σ grad[i]·εᵢ` with `εᵢεⱼ = 0`. Every operation applies the
//! chain rule with the operations of `T`, so over an interval type each derivative entry
//! encloses the true partial derivative over the operand box (the chain rule is an
//! identity between real functions; each factor is an enclosure, and interval
//! arithmetic is inclusion isotone). An empty `grad` stands for the zero vector (a
//! constant), so constants cost no allocation.

use std::ops::{Add, Div, Mul, Neg, Sub};

use crate::num::{Arith, Real};

/// A number with its gradient with respect to the seeded variables.
#[derive(Clone, Debug, PartialEq)]
pub struct Dual<T> {
    /// The value.
    pub value: T,
    /// The partial derivatives; empty means all zero.
    pub grad: Vec<T>,
}

impl<T: Real> Dual<T> {
    /// A constant (zero gradient).
    pub fn constant(value: T) -> Self {
        Dual {
            value,
            grad: Vec::new(),
        }
    }

    /// The variable number `index` of `count`, at `value` (gradient `e_index`).
    pub fn variable(value: T, index: usize, count: usize) -> Self {
        let (zero, one) = (value.zero_like(), value.one_like());
        let grad = (0..count)
            .map(|i| {
                if i == index {
                    one.clone()
                } else {
                    zero.clone()
                }
            })
            .collect();
        Dual { value, grad }
    }

    /// The partial derivative `i` (zero for a constant).
    pub fn partial(&self, i: usize) -> T {
        self.grad
            .get(i)
            .cloned()
            .unwrap_or_else(|| self.value.zero_like())
    }

    /// `f(self)` given `f(value)` and `f'(value)`: the chain rule.
    fn chain(&self, value: T, derivative: T) -> Self {
        let grad = self.grad.iter().map(|g| g.clone() * &derivative).collect();
        Dual { value, grad }
    }

    /// `a·self.grad + b·other.grad`, entry by entry (either may be a constant).
    fn combine(&self, a: &T, other: &Self, b: &T) -> Vec<T> {
        match (self.grad.is_empty(), other.grad.is_empty()) {
            (true, true) => Vec::new(),
            (false, true) => self.grad.iter().map(|g| g.clone() * a).collect(),
            (true, false) => other.grad.iter().map(|g| g.clone() * b).collect(),
            (false, false) => self
                .grad
                .iter()
                .zip(&other.grad)
                .map(|(g, h)| g.clone() * a + h.clone() * b)
                .collect(),
        }
    }
}

impl<T: Real> Add<&Dual<T>> for Dual<T> {
    type Output = Dual<T>;
    fn add(mut self, rhs: &Dual<T>) -> Dual<T> {
        self.value = self.value + &rhs.value;
        if self.grad.is_empty() {
            self.grad.clone_from(&rhs.grad);
        } else if !rhs.grad.is_empty() {
            for (g, h) in self.grad.iter_mut().zip(&rhs.grad) {
                *g = g.clone() + h;
            }
        }
        self
    }
}

impl<T: Real> Sub<&Dual<T>> for Dual<T> {
    type Output = Dual<T>;
    fn sub(mut self, rhs: &Dual<T>) -> Dual<T> {
        self.value = self.value - &rhs.value;
        if self.grad.is_empty() {
            self.grad = rhs.grad.iter().map(|h| -h.clone()).collect();
        } else if !rhs.grad.is_empty() {
            for (g, h) in self.grad.iter_mut().zip(&rhs.grad) {
                *g = g.clone() - h;
            }
        }
        self
    }
}

impl<T: Real> Mul<&Dual<T>> for Dual<T> {
    type Output = Dual<T>;
    fn mul(self, rhs: &Dual<T>) -> Dual<T> {
        // (uv)' = u'v + uv'
        let grad = self.combine(&rhs.value, rhs, &self.value);
        Dual {
            value: self.value * &rhs.value,
            grad,
        }
    }
}

impl<T: Real> Div<&Dual<T>> for Dual<T> {
    type Output = Dual<T>;
    fn div(self, rhs: &Dual<T>) -> Dual<T> {
        // (u/v)' = (u' − (u/v)·v')/v: q encloses u/v, so this encloses the derivative.
        let q = self.value.clone() / &rhs.value;
        let grad = match (self.grad.is_empty(), rhs.grad.is_empty()) {
            (true, true) => Vec::new(),
            (false, true) => self.grad.iter().map(|g| g.clone() / &rhs.value).collect(),
            _ => {
                let minus_q = -q.clone();
                let one = q.one_like();
                self.combine(&one, rhs, &minus_q)
                    .into_iter()
                    .map(|g| g / &rhs.value)
                    .collect()
            }
        };
        Dual { value: q, grad }
    }
}

macro_rules! by_value {
    ($($Tr:ident $m:ident),*) => {$(
        impl<T: Real> $Tr<Dual<T>> for Dual<T> {
            type Output = Dual<T>;
            fn $m(self, rhs: Dual<T>) -> Dual<T> {
                $Tr::$m(self, &rhs)
            }
        }
    )*};
}
by_value!(Add add, Sub sub, Mul mul, Div div);

impl<T: Real> Neg for Dual<T> {
    type Output = Dual<T>;
    fn neg(self) -> Dual<T> {
        Dual {
            value: -self.value,
            grad: self.grad.into_iter().map(|g| -g).collect(),
        }
    }
}

impl<T: Real> Arith for Dual<T> {
    fn lift(&self, v: f64) -> Self {
        Dual::constant(self.value.lift(v))
    }
}

impl<T: Real> Real for Dual<T> {
    fn pi_like(&self) -> Self {
        Dual::constant(self.value.pi_like())
    }
    fn sqr(&self) -> Self {
        let two_x = self.value.lift(2.0) * &self.value;
        self.chain(self.value.sqr(), two_x)
    }
    fn sqrt(&self) -> Self {
        let s = self.value.sqrt();
        let d = self.value.one_like() / (self.value.lift(2.0) * &s);
        self.chain(s, d)
    }
    fn powi(&self, n: i32) -> Self {
        if n == 0 {
            return Dual::constant(self.value.one_like());
        }
        let d = self.value.lift(f64::from(n)) * self.value.powi(n - 1);
        self.chain(self.value.powi(n), d)
    }
    fn sin(&self) -> Self {
        self.chain(self.value.sin(), self.value.cos())
    }
    fn cos(&self) -> Self {
        self.chain(self.value.cos(), -self.value.sin())
    }
    fn tan(&self) -> Self {
        let t = self.value.tan();
        let d = self.value.one_like() + t.sqr();
        self.chain(t, d)
    }
    fn exp(&self) -> Self {
        let e = self.value.exp();
        self.chain(e.clone(), e)
    }
    fn ln(&self) -> Self {
        let d = self.value.one_like() / &self.value;
        self.chain(self.value.ln(), d)
    }
    fn sinh(&self) -> Self {
        self.chain(self.value.sinh(), self.value.cosh())
    }
    fn cosh(&self) -> Self {
        self.chain(self.value.cosh(), self.value.sinh())
    }
    fn atan2(&self, x: &Self) -> Self {
        // d atan2(y, x) = (x dy − y dx)/(x² + y²)
        let (y0, x0) = (&self.value, &x.value);
        let r2 = x0.sqr() + y0.sqr();
        let minus_y = -y0.clone();
        let grad = self
            .combine(x0, x, &minus_y)
            .into_iter()
            .map(|g| g / &r2)
            .collect();
        Dual {
            value: y0.atan2(x0),
            grad,
        }
    }
    fn mid(&self) -> f64 {
        self.value.mid()
    }
    fn bounds(&self) -> (f64, f64) {
        self.value.bounds()
    }
    /// Joins two pieces of a piecewise formula: value and every partial derivative
    /// hulled, so the result encloses the derivative of whichever piece applies.
    fn hull_with(&self, other: &Self) -> Self {
        let n = self.grad.len().max(other.grad.len());
        let zero = self.value.zero_like();
        let grad = (0..n)
            .map(|i| {
                let a = self.grad.get(i).unwrap_or(&zero);
                let b = other.grad.get(i).unwrap_or(&zero);
                a.hull_with(b)
            })
            .collect();
        Dual {
            value: self.value.hull_with(&other.value),
            grad,
        }
    }
    /// Restricts the value to one piece's parameter range; the derivative with respect
    /// to the variables is unchanged (the restriction selects a piece, it does not
    /// change the parameter).
    fn restrict_to(&self, lo: f64, hi: f64) -> Self {
        Dual {
            value: self.value.restrict_to(lo, hi),
            grad: self.grad.clone(),
        }
    }
}

/// Seed `x` as the variables of a gradient computation.
pub fn seed<T: Real>(x: &[T]) -> Vec<Dual<T>> {
    let n = x.len();
    x.iter()
        .enumerate()
        .map(|(i, xi)| Dual::variable(xi.clone(), i, n))
        .collect()
}

/// Values and the Jacobian `∂fᵢ/∂xⱼ` of `f` at `x`, by one evaluation over [`Dual`].
pub fn value_and_jacobian<T: Real>(
    x: &[T],
    f: impl FnOnce(&[Dual<T>]) -> Vec<Dual<T>>,
) -> (Vec<T>, Vec<Vec<T>>) {
    let n = x.len();
    let out = f(&seed(x));
    let jacobian = out
        .iter()
        .map(|d| (0..n).map(|j| d.partial(j)).collect())
        .collect();
    (out.into_iter().map(|d| d.value).collect(), jacobian)
}

/// Value, gradient and Hessian of each component of `f` at `x` (nested duals).
#[derive(Clone, Debug)]
pub struct Jet2<T> {
    /// `fᵢ(x)`.
    pub value: Vec<T>,
    /// `∂fᵢ/∂xⱼ`.
    pub jacobian: Vec<Vec<T>>,
    /// `∂²fᵢ/∂xⱼ∂xₖ`, indexed `[i][j][k]`.
    pub hessian: Vec<Vec<Vec<T>>>,
}

/// [`Jet2`] of `f` at `x`, by one evaluation over `Dual<Dual<T>>`.
pub fn jet2<T: Real>(x: &[T], f: impl FnOnce(&[Dual<Dual<T>>]) -> Vec<Dual<Dual<T>>>) -> Jet2<T> {
    let n = x.len();
    let inner = seed(x);
    let outer = seed(&inner);
    let out = f(&outer);
    let mut jet = Jet2 {
        value: Vec::with_capacity(out.len()),
        jacobian: Vec::with_capacity(out.len()),
        hessian: Vec::with_capacity(out.len()),
    };
    for d in out {
        jet.jacobian
            .push((0..n).map(|j| d.value.partial(j)).collect());
        jet.hessian.push(
            (0..n)
                .map(|j| (0..n).map(|k| d.partial(j).partial(k)).collect())
                .collect(),
        );
        jet.value.push(d.value.value);
    }
    jet
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::num::{Interval, IntervalLike};

    fn f<T: Real>(x: &[T]) -> Vec<T> {
        // f0 = x² y + sin(x)/y, f1 = exp(x y) − sqrt(y) + atan2(y, x)
        let (x0, y0) = (&x[0], &x[1]);
        vec![
            x0.sqr() * y0 + &(x0.sin() / y0),
            (x0.clone() * y0).exp() - y0.sqrt() + &y0.atan2(x0),
        ]
    }

    #[test]
    fn jacobian_matches_hand_derivatives() {
        let (x, y) = (0.7_f64, 1.3_f64);
        let (v, j) = value_and_jacobian(&[x, y], f);
        assert_eq!(v, f(&[x, y]));
        let r2 = x * x + y * y;
        let expect = [
            [2.0 * x * y + x.cos() / y, x * x - x.sin() / (y * y)],
            [
                y * (x * y).exp() - y / r2,
                x * (x * y).exp() - 0.5 / y.sqrt() + x / r2,
            ],
        ];
        for i in 0..2 {
            for k in 0..2 {
                assert!((j[i][k] - expect[i][k]).abs() < 1e-14, "{i}{k}");
            }
        }
    }

    #[test]
    fn hessian_matches_hand_derivatives() {
        // g = x³ y² : g_xx = 6 x y², g_xy = 6 x² y, g_yy = 2 x³
        let (x, y) = (1.5_f64, -0.5_f64);
        let jet = jet2(&[x, y], |d| vec![d[0].powi(3) * d[1].sqr()]);
        assert_eq!(jet.value[0], 1.5f64.powi(3) * 0.25);
        assert_eq!(
            jet.jacobian[0],
            vec![3.0 * x * x * y * y, 2.0 * x.powi(3) * y]
        );
        assert_eq!(jet.hessian[0][0][0], 6.0 * x * y * y);
        assert_eq!(jet.hessian[0][0][1], 6.0 * x * x * y);
        assert_eq!(jet.hessian[0][1][0], 6.0 * x * x * y);
        assert_eq!(jet.hessian[0][1][1], 2.0 * x.powi(3));
    }

    #[test]
    fn interval_jacobian_encloses_point_jacobians() {
        let bx = [
            Interval::from_bounds(0.6, 0.8),
            Interval::from_bounds(1.2, 1.4),
        ];
        let (_, jb) = value_and_jacobian(&bx, f);
        // Interior points: a rounded f64 derivative there is far from the box's bounds.
        for &x in &[0.65, 0.7, 0.75] {
            for &y in &[1.25, 1.31, 1.35] {
                let (_, jp) = value_and_jacobian(&[x, y], f);
                for i in 0..2 {
                    for k in 0..2 {
                        assert!(jb[i][k].contains_value(jp[i][k]), "{x} {y} {i}{k}");
                    }
                }
            }
        }
    }
}
