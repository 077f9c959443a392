//! The faces a blend runs between (OPERATIONS.md §11): a plane, a sphere or a circular
//! cylinder, with what §11 needs of each, written once over [`Real`]: the unit normal
//! field along the normals (1.6) (constant for a plane, radial for a sphere and a
//! cylinder), the offset along it, the recovery of a contact point's parameters, and
//! the curvature radius that bounds the radius on the concave side (§11.4 degenerate
//! cases).
//!
//! Every formula is evaluated in the caller's number type; over intervals each step is
//! an enclosing operation, so the results enclose the exact values for the exact input
//! doubles (nothing is normalised or rounded before the formula).

use crate::error::GeomError;
use crate::geom::Plane as LinearPlane;
use crate::num::vector::{add_scaled, cross, dot, lift, norm_sq, scale, sub};
use crate::num::Real;
use crate::ops::shape::{LinearObject, Shape};
use crate::surface::quadrics::{Cylinder, Sphere};
use crate::surface::{AnySurface, Surface};

/// A face of a blend. Its unit normal is the one of the surface's own parametrisation
/// (1.6): `u × v` (or the given `normal`) for a plane, outward for a sphere and a
/// cylinder.
#[derive(Debug, Clone, PartialEq)]
pub enum Face {
    /// `origin + s·u + t·v`, normal `u × v`; parameters by (3.7)–(3.8).
    Plane {
        origin: [f64; 3],
        u: [f64; 3],
        v: [f64; 3],
    },
    /// `normal·x + d = 0` (no parameters).
    ImplicitPlane {
        normal: [f64; 3],
        d: f64,
    },
    Sphere(Sphere),
    /// A circular cylinder (`a = b`).
    Cylinder(Cylinder),
}

/// A plane as `m·x = h` with `m` the unit normal, in the number type of `like`.
pub struct PlaneForm<T> {
    pub m: [T; 3],
    pub h: T,
}

impl Face {
    /// The face of a shape; `field` names it in errors (`objects[0]`).
    pub fn of_shape(shape: &Shape, field: &str) -> Result<Face, GeomError> {
        let unsupported = |what: &str| GeomError::Unsupported {
            field: format!("{field}.type"),
            reason: format!(
                "fillets and chamfers run between planes, spheres and circular cylinders, \
                 not {what}"
            ),
        };
        match shape {
            Shape::Linear(l) => match l.doubles().map_err(|e| e.at(field))? {
                LinearObject::Plane(LinearPlane::Parametric { origin, u, v }) => Ok(Face::Plane {
                    origin: arr(&origin),
                    u: arr(&u),
                    v: arr(&v),
                }),
                LinearObject::Plane(LinearPlane::Implicit { normal, d }) => {
                    Ok(Face::ImplicitPlane {
                        normal: arr(&normal),
                        d,
                    })
                }
                other => Err(unsupported(&format!("a {}", other.type_name()))),
            },
            Shape::Surface(AnySurface::Plane(p)) => {
                let (u, v) = p.vectors();
                Ok(Face::Plane {
                    origin: p.origin(),
                    u,
                    v,
                })
            }
            Shape::Surface(AnySurface::Sphere(s)) => Ok(Face::Sphere(s.clone())),
            Shape::Surface(AnySurface::Cylinder(c)) => {
                let [a, b] = c.semi_axes();
                if a != b {
                    return Err(unsupported(
                        "an elliptic cylinder (its offset is no cylinder)",
                    ));
                }
                Ok(Face::Cylinder(c.clone()))
            }
            _ => Err(unsupported("this object")),
        }
    }

    /// `m·x = h` of a plane face (`None` for other faces); `m = n/|n|` enclosed.
    pub fn plane_form<T: Real>(&self, like: &T) -> Option<PlaneForm<T>> {
        let (n, h_times_len) = match self {
            Face::Plane { origin, u, v } => {
                let n = cross(&lift(like, u), &lift(like, v));
                let h = dot(&n, &lift(like, origin));
                (n, h)
            }
            Face::ImplicitPlane { normal, d } => (lift(like, normal), -like.lift(*d)),
            _ => return None,
        };
        let len = norm_sq(&n).sqrt();
        Some(PlaneForm {
            m: n.map(|c| c / &len),
            h: h_times_len / len,
        })
    }

    /// The radius of a sphere or cylinder face (`None` for a plane).
    pub fn radius(&self) -> Option<f64> {
        match self {
            Face::Plane { .. } | Face::ImplicitPlane { .. } => None,
            Face::Sphere(s) => Some(s.radius()),
            Face::Cylinder(c) => Some(c.semi_axes()[0]),
        }
    }

    /// The unit normal at the foot of `x` on the face (1.6), for `x` off the sphere's
    /// centre and the cylinder's axis: the normal is constant along a normal line, so
    /// it is also the normal at the contact point of a ball centred at `x`.
    pub fn normal_at<T: Real>(&self, x: &[T; 3]) -> [T; 3] {
        match self {
            Face::Sphere(s) => {
                let w = sub(x, &lift(&x[0], &s.frame.origin()));
                let len = norm_sq(&w).sqrt();
                w.map(|c| c / &len)
            }
            Face::Cylinder(c) => {
                let (local, axes) = c.frame.to_local(x);
                let radial = add_scaled(&scale(&local[0], &axes[0]), &local[1], &axes[1]);
                let len = (local[0].sqr() + local[1].sqr()).sqrt();
                radial.map(|r| r / &len)
            }
            // A plane's normal is constant (its form always exists).
            _ => self.plane_form(&x[0]).map_or_else(|| x.clone(), |p| p.m),
        }
    }

    /// The parameters of a point `p` of the face: `(u, v)` by (3.7)–(3.8) on a
    /// parametric plane, none on an implicit plane, the angles `(u, v)` of a sphere,
    /// `(u, height)` of a cylinder (`u` in `[0, 2π)` when its sign is decided).
    pub fn params_of<T: Real>(&self, p: &[T; 3]) -> Vec<T> {
        match self {
            Face::ImplicitPlane { .. } => Vec::new(),
            Face::Plane { origin, u, v } => {
                let (a, b) = (lift(&p[0], u), lift(&p[0], v));
                let w = sub(p, &lift(&p[0], origin));
                let (g11, g12, g22) = (dot(&a, &a), dot(&a, &b), dot(&b, &b));
                let (wa, wb) = (dot(&w, &a), dot(&w, &b));
                let g = g11.clone() * &g22 - g12.sqr();
                let u = (g22 * &wa - g12.clone() * &wb) / &g;
                let v = (g11 * &wb - g12 * &wa) / &g;
                vec![u, v]
            }
            Face::Sphere(s) => {
                let (l, _) = s.frame.to_local(p);
                let rho = (l[0].sqr() + l[1].sqr()).sqrt();
                vec![angle(&l[1], &l[0]), l[2].atan2(&rho)]
            }
            Face::Cylinder(c) => {
                let (l, _) = c.frame.to_local(p);
                vec![angle(&l[1], &l[0]), l[2].clone()]
            }
        }
    }

    /// The parameter domain of the face per reported parameter, and whether it is
    /// periodic (no bound to check).
    pub fn domain(&self) -> Vec<([f64; 2], bool)> {
        let of = |s: &dyn Fn() -> ([f64; 2], [f64; 2]), closed: [bool; 2]| {
            let (u, v) = s();
            vec![(u, closed[0]), (v, closed[1])]
        };
        match self {
            Face::ImplicitPlane { .. } => Vec::new(),
            Face::Plane { .. } => vec![([f64::NEG_INFINITY, f64::INFINITY], true); 2],
            Face::Sphere(s) => of(&|| s.domain(), s.is_closed()),
            Face::Cylinder(c) => of(&|| c.domain(), c.is_closed()),
        }
    }
}

/// `atan2(y, x)` moved into `[0, 2π)` when it is proven negative.
fn angle<T: Real>(y: &T, x: &T) -> T {
    let a = y.atan2(x);
    if a.bounds().1 < 0.0 {
        let two_pi = a.pi_like() * a.lift(2.0);
        a + two_pi
    } else {
        a
    }
}

fn arr(v: &nalgebra::Vector3<f64>) -> [f64; 3] {
    [v[0], v[1], v[2]]
}
