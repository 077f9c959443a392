//! The cutting plane of a section, exactly (OPERATIONS.md §13.1): the plane through
//! three points (13.1) and its true-size frame (13.2).
//!
//! Everything is rational: `n = (M₁ − M₀) × (M₂ − M₀)`, `D = −n·M₀`, the foot of the
//! origin `O = −D n/|n|²`, and the frame directions of (13.2) before normalisation,
//! `f₁ = n × k` (`(1, 0, 0)` when `n ∥ k`) and `f₂ = n × f₁`, so `e₁ = f₁/|f₁|`,
//! `e₂ = n̂ × e₁ = f₂/|f₂|`. A point of the plane is `O + s f₁ + t f₂`; its true-size
//! coordinates are `u = s|f₁|`, `v = t|f₂|`. The metric `G = diag(|f₁|², |f₂|²)` is
//! rational, so sections are classified and measured on exact rationals and only
//! the reported lengths and unit vectors need square roots ([`super::surd`]).

use rug::Rational;
use std::cmp::Ordering;

use super::surd::{Surd, Value};
use crate::error::GeomError;
use crate::geom::Plane;
use crate::num::ring::{add3, cross3, dot3, scale3, sub3, V3};

/// The plane `n·x + d = 0` with exact rational coefficients, `n ≠ 0`.
#[derive(Debug, Clone, PartialEq)]
pub struct ExactPlane {
    pub normal: V3<Rational>,
    pub d: Rational,
}

/// The rational frame of a plane: `x = origin + s·f[0] + t·f[1]`, with `g[i] = |f[i]|²`.
#[derive(Debug, Clone, PartialEq)]
pub struct PlaneFrame {
    pub origin: V3<Rational>,
    pub f: [V3<Rational>; 2],
    pub g: [Rational; 2],
}

/// The true-size frame (13.2): `O` exactly, the unit vectors `e₁`, `e₂` correctly
/// rounded (with enclosures and their exact values where rational).
#[derive(Debug, Clone, PartialEq)]
pub struct TrueSizeFrame {
    pub origin: V3<Rational>,
    pub e1: [Value; 3],
    pub e2: [Value; 3],
}

fn is_zero(v: &V3<Rational>) -> bool {
    v.iter().all(|x| x.cmp0() == Ordering::Equal)
}

/// The plane through `M₀, M₁, M₂` (13.1), exactly. Errors name the point that makes
/// the plane undefined: `points[1]` when it coincides with `points[0]`, `points[2]`
/// when the three points are collinear (or it repeats another point).
pub fn plane_through_points_exact(points: &[V3<Rational>; 3]) -> Result<ExactPlane, GeomError> {
    let a = sub3(&points[1], &points[0]);
    if is_zero(&a) {
        return Err(GeomError::InvalidValue {
            field: "points[1]".into(),
            reason: "coincides with points[0]: two equal points span no plane".into(),
        });
    }
    let b = sub3(&points[2], &points[0]);
    let normal = cross3(&a, &b);
    if is_zero(&normal) {
        return Err(GeomError::InvalidValue {
            field: "points[2]".into(),
            reason: "the three points are collinear: they span no plane".into(),
        });
    }
    let d = -dot3(&normal, &points[0]);
    Ok(ExactPlane { normal, d })
}

/// [`plane_through_points_exact`] on doubles taken exactly; non-finite coordinates
/// are errors naming `points[i][j]`.
pub fn plane_through_points(points: [[f64; 3]; 3]) -> Result<ExactPlane, GeomError> {
    let mut exact: [V3<Rational>; 3] = Default::default();
    for (i, p) in points.iter().enumerate() {
        for (j, x) in p.iter().enumerate() {
            exact[i][j] = crate::num::parse::rational_from_f64(&format!("points[{i}][{j}]"), *x)?;
        }
    }
    plane_through_points_exact(&exact)
}

impl ExactPlane {
    /// The implicit form of a plane of the linear kernel (parametric: `n = u × v`).
    pub fn from_plane(p: &Plane<Rational>) -> ExactPlane {
        let v = |x: &nalgebra::Vector3<Rational>| -> V3<Rational> {
            [x[0].clone(), x[1].clone(), x[2].clone()]
        };
        match p {
            Plane::Implicit { normal, d } => ExactPlane {
                normal: v(normal),
                d: d.clone(),
            },
            Plane::Parametric { origin, u, v: w } => {
                let normal = cross3(&v(u), &v(w));
                let d = -dot3(&normal, &v(origin));
                ExactPlane { normal, d }
            }
        }
    }

    /// `n·x + d`, exactly.
    pub fn eval(&self, x: &V3<Rational>) -> Rational {
        dot3(&self.normal, x) + &self.d
    }

    /// The rational frame of (13.2) (module documentation).
    pub fn frame(&self) -> PlaneFrame {
        let n = &self.normal;
        let nn = dot3(n, n);
        let origin = scale3(&(-Rational::from(&self.d / &nn)), n);
        let k = [Rational::new(), Rational::new(), Rational::from(1)];
        let mut f1 = cross3(n, &k);
        if is_zero(&f1) {
            f1 = [Rational::from(1), Rational::new(), Rational::new()];
        }
        let f2 = cross3(n, &f1);
        let g = [dot3(&f1, &f1), dot3(&f2, &f2)];
        PlaneFrame {
            origin,
            f: [f1, f2],
            g,
        }
    }
}

impl PlaneFrame {
    /// The point `origin + s·f₁ + t·f₂`.
    pub fn point(&self, s: &Rational, t: &Rational) -> V3<Rational> {
        add3(
            &self.origin,
            &add3(&scale3(s, &self.f[0]), &scale3(t, &self.f[1])),
        )
    }

    /// The 3D vector `y₁ f₁ + y₂ f₂` of surd coordinates.
    pub fn vector(&self, y: &[Surd; 2]) -> [Surd; 3] {
        std::array::from_fn(|k| y[0].scale(&self.f[0][k]).add(&y[1].scale(&self.f[1][k])))
    }

    /// The squared length `yᵀGy` of the vector of [`PlaneFrame::vector`].
    pub fn norm2(&self, y: &[Surd; 2]) -> Surd {
        y[0].mul(&y[0])
            .scale(&self.g[0])
            .add(&y[1].mul(&y[1]).scale(&self.g[1]))
    }

    /// The unit vector along `y₁ f₁ + y₂ f₂` (`y ≠ 0`), each coordinate correctly rounded.
    pub fn unit(&self, y: &[Surd; 2]) -> [Value; 3] {
        let v = self.vector(y);
        let n = self.norm2(y);
        std::array::from_fn(|k| Value::unit_component(&v[k], &n))
    }

    /// The true-size frame (13.2).
    pub fn true_size(&self) -> TrueSizeFrame {
        let one = || Surd::rational(Rational::from(1));
        let zero = || Surd::rational(Rational::new());
        TrueSizeFrame {
            origin: self.origin.clone(),
            e1: self.unit(&[one(), zero()]),
            e2: self.unit(&[zero(), one()]),
        }
    }

    /// The true-size coordinates `(u, v) = (s|f₁|, t|f₂|)` of `(s, t)`, correctly rounded.
    pub fn true_size_coords(&self, s: &Surd, t: &Surd) -> [Value; 2] {
        let c = |x: &Surd, g: &Rational| Value::signed_sqrt(x.sign(), &x.mul(x).scale(g));
        [c(s, &self.g[0]), c(t, &self.g[1])]
    }
}

/// A point's coordinates of a 3-vector of rationals, as values.
pub fn values(x: &V3<Rational>) -> [Value; 3] {
    std::array::from_fn(|k| Value::rational(&x[k]))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn v(x: [i64; 3]) -> V3<Rational> {
        x.map(Rational::from)
    }

    #[test]
    fn plane_through_three_points_of_16_10() {
        // x + 3y + 16z − 16 = 0 through its axis intercepts.
        let p = plane_through_points([[16.0, 0.0, 0.0], [0.0, 16.0 / 3.0, 0.0], [0.0, 0.0, 1.0]]);
        // 16/3 is not a double: use exact points instead.
        assert!(p.is_ok());
        let p = plane_through_points_exact(&[v([16, 0, 0]), v([1, 5, 0]), v([0, 0, 1])]).unwrap();
        let k = p.d.clone() / Rational::from(-16);
        let n: Vec<Rational> = p.normal.iter().map(|x| Rational::from(x / &k)).collect();
        assert_eq!(
            n,
            vec![Rational::from(1), Rational::from(3), Rational::from(16)]
        );
        let f = p.frame();
        // O = 16 n/266.
        assert_eq!(f.origin[2], Rational::from((16 * 16, 266)));
        let t = f.true_size();
        assert!((t.e1[0].value - 0.9486832981).abs() < 1e-10);
        assert!((t.e2[2].value + 0.1938916836).abs() < 1e-10);
        assert_eq!(t.e1[2].exact, Some(Rational::new()));
    }

    #[test]
    fn degenerate_points_are_typed_errors() {
        let e =
            plane_through_points([[1.0, 2.0, 3.0], [1.0, 2.0, 3.0], [0.0, 0.0, 1.0]]).unwrap_err();
        assert_eq!(e.field(), "points[1]");
        let e = plane_through_points([[0.0; 3], [1.0, 1.0, 1.0], [3.0, 3.0, 3.0]]).unwrap_err();
        assert_eq!(e.field(), "points[2]");
        let e =
            plane_through_points([[0.0; 3], [f64::NAN, 1.0, 1.0], [3.0, 3.0, 3.0]]).unwrap_err();
        assert_eq!(e.field(), "points[1][0]");
    }
}
