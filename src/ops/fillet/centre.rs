//! The ball-centre curve of a constant-radius fillet (OPERATIONS.md §11.2): the
//! intersection of the offset surfaces `r̃ = r + d₁m`, `s̃ = s + d₂n` (11.1), in closed
//! form for the faces of [`Face`], whose offsets are again planes, spheres and
//! cylinders exactly (radius `R + d`):
//!
//! * plane / plane: the line `m₁·x = h₁`, `m₂·x = h₂`, `x(t) = x₀ + t·ê` with
//!   `ê = (m₁ × m₂)/|m₁ × m₂|` and `x₀` its point nearest to the world origin
//!   (`t` is arc length; the caller gives the range);
//! * sphere / plane: the circle of the offset sphere in the offset plane,
//!   `x(t) = q + ρ_c (cos t E₁ + sin t E₂)`, `t ∈ [0, 2π]`;
//! * plane / cylinder (plane not parallel to the axis): `t` is the cylinder's angle
//!   `u` and `v(u)` solves the plane's linear equation;
//! * cylinder / cylinder (axes not parallel): `t` is the angle `u` of one cylinder
//!   and its height solves the other's quadratic `α v² + β v + γ = 0` on one branch
//!   `v = (−β ± √(β² − 4αγ))/(2α)`, where the discriminant stays positive.
//!
//! Each formula is written once over [`Real`] ([`CentreCurve::point`]), so over
//! intervals it encloses the exact centre of the exact input, and the conditions
//! under which the closed form is the centre curve ([`CentreCurve::conditions`]) can
//! be proven over parameter boxes (`prove`).

use super::face::Face;
use crate::error::GeomError;
use crate::num::vector::{add, add_scaled, cross, dot, lift, norm_sq, scale, sub};
use crate::num::Real;

/// Which closed form the curve uses.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum CentreForm {
    PlanePlane,
    /// `sphere` is the index (0 or 1) of the sphere face.
    SpherePlane {
        sphere: usize,
    },
    /// `cylinder` is the index of the cylinder face.
    PlaneCylinder {
        cylinder: usize,
    },
    /// `t` is the angle of face `param`; `branch` is the sign of the root (±1).
    CylinderCylinder {
        param: usize,
        branch: f64,
    },
}

/// One ball-centre curve: the two faces, the signed offsets `d₁ = σ₁ρ`, `d₂ = σ₂ρ`
/// (11.1), the closed form and its parameter range.
#[derive(Debug, Clone, PartialEq)]
pub struct CentreCurve {
    pub faces: [Face; 2],
    pub offsets: [f64; 2],
    pub form: CentreForm,
    pub range: [f64; 2],
    pub closed: bool,
}

/// A station of the curve (§11.4): the centre `c`, the contact points `p₁ = c − d₁m`,
/// `p₂ = c − d₂n`, the unit normals there and `cos φ = sign(d₁d₂)(m·n)` (11.5).
#[derive(Debug, Clone, PartialEq)]
pub struct Station<T> {
    pub centre: [T; 3],
    pub contact: [[T; 3]; 2],
    pub normal: [[T; 3]; 2],
    pub cos_phi: T,
}

/// What a condition of [`CentreCurve::conditions`] guarantees when it is positive.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Condition {
    /// The closed form is real there (a positive discriminant, a plane not parallel
    /// to the axis, a circle of positive radius).
    Real,
    /// `|m × n|² > 0`: the faces are transversal at the contacts (`1 + cos φ > 0`
    /// and a cross-section arc of positive angle).
    Transversal,
    /// A contact parameter of face `k` lies inside its domain (two conditions per
    /// bounded parameter: above the lower and below the upper bound).
    Domain(usize),
}

fn unsupported(reason: &str) -> GeomError {
    GeomError::Unsupported {
        field: "objects".into(),
        reason: reason.into(),
    }
}

impl CentreCurve {
    /// The curve's closed form for two faces; `range` is required for two planes
    /// (field `range`). Errors: other pairs of faces (`unsupported`).
    pub fn new(
        faces: [Face; 2],
        offsets: [f64; 2],
        range: Option<[f64; 2]>,
    ) -> Result<Vec<CentreCurve>, GeomError> {
        let is_plane = |f: &Face| matches!(f, Face::Plane { .. } | Face::ImplicitPlane { .. });
        let turn = [0.0, 2.0 * std::f64::consts::PI];
        let curve = |form, range, closed| CentreCurve {
            faces: faces.clone(),
            offsets,
            form,
            range,
            closed,
        };
        let form = match (&faces[0], &faces[1]) {
            (a, b) if is_plane(a) && is_plane(b) => {
                let range = range.ok_or_else(|| GeomError::Format {
                    field: "range".into(),
                    message: "a blend of two unbounded planes needs `range`, the arc-length \
                              interval of the centre line"
                        .into(),
                })?;
                return Ok(vec![curve(CentreForm::PlanePlane, range, false)]);
            }
            (Face::Sphere(_), b) if is_plane(b) => CentreForm::SpherePlane { sphere: 0 },
            (a, Face::Sphere(_)) if is_plane(a) => CentreForm::SpherePlane { sphere: 1 },
            (Face::Cylinder(_), b) if is_plane(b) => plane_cylinder(&faces, 0)?,
            (a, Face::Cylinder(_)) if is_plane(a) => plane_cylinder(&faces, 1)?,
            (Face::Cylinder(_), Face::Cylinder(_)) => {
                let probe = curve(CentreForm::PlanePlane, turn, true);
                return Ok(cylinder_branches(&probe)?
                    .into_iter()
                    .map(|form| curve(form, turn, true))
                    .collect());
            }
            _ => {
                return Err(unsupported(
                    "closed-form centre curves exist here for plane/plane, sphere/plane, \
                     plane/cylinder and cylinder/cylinder",
                ))
            }
        };
        Ok(vec![curve(form, turn, true)])
    }

    /// The offset radius `R + d` of a sphere or cylinder face `k`.
    fn offset_radius<T: Real>(&self, k: usize, like: &T) -> T {
        like.lift(self.faces[k].radius().unwrap_or(0.0)) + like.lift(self.offsets[k])
    }

    /// The offset plane `m·x = h + d` of plane face `k`.
    fn offset_plane<T: Real>(&self, k: usize, like: &T) -> ([T; 3], T) {
        match self.faces[k].plane_form(like) {
            Some(p) => (p.m, p.h + like.lift(self.offsets[k])),
            None => (lift(like, &[f64::NAN; 3]), like.lift(f64::NAN)),
        }
    }

    /// The centre `x(t)` (module doc).
    pub fn point<T: Real>(&self, t: &T) -> [T; 3] {
        match self.form {
            CentreForm::PlanePlane => {
                let ((m1, h1), (m2, h2)) = (self.offset_plane(0, t), self.offset_plane(1, t));
                let e = cross(&m1, &m2);
                let ee = norm_sq(&e);
                let x0 = add(&scale(&h1, &cross(&m2, &e)), &scale(&h2, &cross(&e, &m1)))
                    .map(|c| c / &ee);
                add_scaled(&x0, &(t.clone() / ee.sqrt()), &e)
            }
            CentreForm::SpherePlane { sphere } => self.sphere_plane_point(sphere, t),
            CentreForm::PlaneCylinder { cylinder } => {
                let (m, h) = self.offset_plane(1 - cylinder, t);
                let (base, z) = self.cylinder_base(cylinder, t);
                // m·(base + v Z) = h
                let v = (h - dot(&m, &base)) / dot(&m, &z);
                add_scaled(&base, &v, &z)
            }
            CentreForm::CylinderCylinder { param, branch } => {
                let (base, z, [alpha, beta, gamma]) = self.cylinder_quadratic(param, t);
                let disc = beta.sqr() - t.lift(4.0) * alpha.clone() * &gamma;
                let v = (-beta + t.lift(branch) * disc.sqrt()) / (t.lift(2.0) * alpha);
                add_scaled(&base, &v, &z)
            }
        }
    }

    fn sphere_plane_point<T: Real>(&self, sphere: usize, t: &T) -> [T; 3] {
        let (m, h) = self.offset_plane(1 - sphere, t);
        let Face::Sphere(s) = &self.faces[sphere] else {
            return lift(t, &[f64::NAN; 3]);
        };
        let c = lift(t, &s.frame.origin());
        let e = dot(&m, &c) - h;
        let q = add_scaled(&c, &-e.clone(), &m);
        let rc = (self.offset_radius(sphere, t).sqr() - e.sqr()).sqrt();
        let (e1, e2) = in_plane_basis(&m);
        add(
            &q,
            &add(
                &scale(&(rc.clone() * t.cos()), &e1),
                &scale(&(rc * t.sin()), &e2),
            ),
        )
    }

    /// `o + R'(cos t X + sin t Y)` and `Z` of cylinder face `k` offset by its `d`.
    fn cylinder_base<T: Real>(&self, k: usize, t: &T) -> ([T; 3], [T; 3]) {
        let Face::Cylinder(c) = &self.faces[k] else {
            return (lift(t, &[f64::NAN; 3]), lift(t, &[f64::NAN; 3]));
        };
        let [x, y, z] = c.frame.axes(t);
        let r = self.offset_radius(k, t);
        let radial = add(&scale(&t.cos(), &x), &scale(&t.sin(), &y));
        (add(&lift(t, &c.frame.origin()), &scale(&r, &radial)), z)
    }

    /// The base point and axis of cylinder `param` at angle `t`, and the coefficients
    /// `(α, β, γ)` of the other offset cylinder's equation in the height `v`:
    /// `|g(w₀) + v g(Z)|² = R₂'²`, `g(y) = y − (y·Z₂)Z₂`, `w₀ = base − o₂`.
    fn cylinder_quadratic<T: Real>(&self, param: usize, t: &T) -> ([T; 3], [T; 3], [T; 3]) {
        let (base, z) = self.cylinder_base(param, t);
        let other = 1 - param;
        let Face::Cylinder(c2) = &self.faces[other] else {
            let nan = t.lift(f64::NAN);
            return (base, z, [nan.clone(), nan.clone(), nan]);
        };
        let z2 = c2.frame.axes(t)[2].clone();
        let g = |y: &[T; 3]| add_scaled(y, &-dot(y, &z2), &z2);
        let (gw, gz) = (g(&sub(&base, &lift(t, &c2.frame.origin()))), g(&z));
        let r2 = self.offset_radius(other, t);
        let coefficients = [
            norm_sq(&gz),
            t.lift(2.0) * dot(&gw, &gz),
            norm_sq(&gw) - r2.sqr(),
        ];
        (base, z, coefficients)
    }

    /// The station at `t` (§11.4).
    pub fn station<T: Real>(&self, t: &T) -> Station<T> {
        let centre = self.point(t);
        let normal = [0, 1].map(|k| self.faces[k].normal_at(&centre));
        let contact = [0, 1].map(|k| add_scaled(&centre, &-t.lift(self.offsets[k]), &normal[k]));
        let sign = (self.offsets[0] * self.offsets[1]).signum();
        let cos_phi = t.lift(sign) * dot(&normal[0], &normal[1]);
        Station {
            centre,
            contact,
            normal,
            cos_phi,
        }
    }

    /// The quantities that must be positive at `t` for `x(t)` to be a centre of the
    /// fillet with contacts inside both faces ([`Condition`]).
    pub fn conditions<T: Real>(&self, t: &T) -> Vec<(T, Condition)> {
        let mut out = Vec::new();
        match self.form {
            CentreForm::PlanePlane => {}
            CentreForm::SpherePlane { sphere } => {
                let (m, h) = self.offset_plane(1 - sphere, t);
                if let Face::Sphere(s) = &self.faces[sphere] {
                    let e = dot(&m, &lift(t, &s.frame.origin())) - h;
                    out.push((
                        self.offset_radius(sphere, t).sqr() - e.sqr(),
                        Condition::Real,
                    ));
                }
            }
            CentreForm::PlaneCylinder { cylinder } => {
                let (m, _) = self.offset_plane(1 - cylinder, t);
                let (_, z) = self.cylinder_base(cylinder, t);
                out.push((dot(&m, &z).sqr(), Condition::Real));
            }
            CentreForm::CylinderCylinder { param, .. } => {
                let (_, _, [alpha, beta, gamma]) = self.cylinder_quadratic(param, t);
                out.push((alpha.clone(), Condition::Real));
                out.push((beta.sqr() - t.lift(4.0) * alpha * &gamma, Condition::Real));
            }
        }
        let st = self.station(t);
        out.push((
            norm_sq(&cross(&st.normal[0], &st.normal[1])),
            Condition::Transversal,
        ));
        for k in 0..2 {
            let params = self.faces[k].params_of(&st.contact[k]);
            for (p, ([lo, hi], periodic)) in params.iter().zip(self.faces[k].domain()) {
                if !periodic {
                    out.push((p.clone() - t.lift(lo), Condition::Domain(k)));
                    out.push((t.lift(hi) - p.clone(), Condition::Domain(k)));
                }
            }
        }
        out
    }
}

/// Plane / cylinder with the cylinder at index `cylinder`. Errors: a plane parallel to
/// the axis in f64 (the centre curves are lines, `unsupported`).
fn plane_cylinder(faces: &[Face; 2], cylinder: usize) -> Result<CentreForm, GeomError> {
    let Face::Cylinder(c) = &faces[cylinder] else {
        return Err(unsupported("expected a cylinder"));
    };
    let m = faces[1 - cylinder]
        .plane_form(&0.0)
        .map_or([0.0; 3], |p| p.m);
    if dot(&m, &c.frame.axes(&0.0)[2]).abs() <= 1e-12 {
        return Err(unsupported(
            "the plane is parallel to the cylinder's axis: the centre curves are lines, \
             not in this build",
        ));
    }
    Ok(CentreForm::PlaneCylinder { cylinder })
}

/// Two orthonormal vectors `E₁ = normalize(m × e_k)`, `E₂ = m × E₁` perpendicular to
/// the unit `m`, `e_k` the coordinate vector least aligned with `m` (chosen from the
/// midpoint, so one choice serves a whole evaluation).
fn in_plane_basis<T: Real>(m: &[T; 3]) -> ([T; 3], [T; 3]) {
    let mags = [0, 1, 2].map(|i| m[i].mid().abs());
    let k = (0..3)
        .min_by(|&i, &j| mags[i].total_cmp(&mags[j]))
        .unwrap_or(0);
    let mut e = [0.0; 3];
    e[k] = 1.0;
    let a = cross(m, &lift(&m[0], &e));
    let len = norm_sq(&a).sqrt();
    let e1 = a.map(|c| c / &len);
    let e2 = cross(m, &e1);
    (e1, e2)
}

/// The branches of two cylinders: parametrised by the angle of the first cylinder
/// whose discriminant is positive at every sample of a float scan (the curve does not
/// turn back in that angle), both roots. Errors: parallel axes, or both angles turn
/// back (`unsupported`). No branch: the offsets do not meet (sampled).
fn cylinder_branches(probe: &CentreCurve) -> Result<Vec<CentreForm>, GeomError> {
    let samples = 720;
    for param in 0..2 {
        let mut c = probe.clone();
        c.form = CentreForm::CylinderCylinder { param, branch: 1.0 };
        let mut min = f64::INFINITY;
        let mut max = f64::NEG_INFINITY;
        let mut alpha = f64::INFINITY;
        for i in 0..samples {
            let t = 2.0 * std::f64::consts::PI * i as f64 / samples as f64;
            let (_, _, [a, b, g]) = c.cylinder_quadratic(param, &t);
            let disc = b * b - 4.0 * a * g;
            min = min.min(disc);
            max = max.max(disc);
            alpha = alpha.min(a);
        }
        if alpha.is_nan() || alpha <= 1e-12 {
            return Err(unsupported(
                "the cylinders' axes are parallel: the centre curves are lines, \
                 not in this build",
            ));
        }
        // Negative everywhere (no branch): both roots of this angle, which the proof
        // then finds absent over the whole range.
        if min > 0.0 || max < 0.0 {
            return Ok([1.0, -1.0]
                .map(|branch| CentreForm::CylinderCylinder { param, branch })
                .to_vec());
        }
    }
    Err(unsupported(
        "the centre curve of these cylinders turns back in both angles (it is not a \
         graph over either cylinder's angle): not in this build",
    ))
}
