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
//!   `v = (−β ± √(β² − 4αγ))/(2α)`, where the discriminant stays positive;
//! * sphere / cylinder: the same with the offset sphere's quadratic `|w₀ + vZ|² = R'²`
//!   (`α = 1`), when its discriminant is positive for every angle (two closed
//!   branches; a centre curve that turns back in the angle is not built);
//! * sphere / sphere (distinct centres): the circle of the two offset spheres,
//!   `x(t) = q + ρ_c (cos t E₁ + sin t E₂)` in the plane normal to the line of centres,
//!   `q = c₁ + ξw`, `w = c₂ − c₁`, `ξ = (|w|² + R₁'² − R₂'²)/(2|w|²)`,
//!   `ρ_c² = R₁'² − ξ²|w|²`.
//!
//! Each formula is written once over [`Real`] ([`CentreCurve::point`]), so over
//! intervals it encloses the exact centre of the exact input, and the conditions
//! under which the closed form is the centre curve ([`CentreCurve::conditions`]) can
//! be proven over parameter boxes (`prove`).

use super::face::Face;
use crate::error::GeomError;
use crate::num::vector::{add, add_scaled, cross, dot, lift, norm_sq, scale, sub};
use crate::num::Real;
use crate::ops::blend_law::Law;

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
    /// `t` is the angle of the cylinder face `cylinder` (the other is a sphere);
    /// `branch` is the sign of the root (±1).
    CylinderSphere {
        cylinder: usize,
        branch: f64,
    },
    SphereSphere,
}

/// One ball-centre curve: the two faces, the signs `σ₁`, `σ₂` of the sector and the
/// radius law `ρ` (the signed offsets are `d₁ = σ₁ρ`, `d₂ = σ₂ρ`, (11.1); a law
/// `ρ(ℓ)` of the spine's arc length for two planes, §11.3), the closed form and its
/// parameter range.
#[derive(Debug, Clone, PartialEq)]
pub struct CentreCurve {
    pub faces: [Face; 2],
    /// `σ₁`, `σ₂` as ±1.
    pub signs: [f64; 2],
    pub radius: Law,
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
    /// (field `range`; a radius law's span by default). Errors: other pairs of faces
    /// (`unsupported`); a non-constant law for faces other than two planes
    /// (`unsupported`, field `radius`).
    pub fn new(
        faces: [Face; 2],
        signs: [f64; 2],
        radius: Law,
        range: Option<[f64; 2]>,
    ) -> Result<Vec<CentreCurve>, GeomError> {
        let is_plane = |f: &Face| matches!(f, Face::Plane { .. } | Face::ImplicitPlane { .. });
        let turn = [0.0, 2.0 * std::f64::consts::PI];
        if radius.as_constant().is_none() && !(is_plane(&faces[0]) && is_plane(&faces[1])) {
            return Err(GeomError::Unsupported {
                field: "radius".into(),
                reason: "a variable radius is built between two planes in this build".into(),
            });
        }
        let curve = |form, range, closed| CentreCurve {
            faces: faces.clone(),
            signs,
            radius: radius.clone(),
            form,
            range,
            closed,
        };
        let form = match (&faces[0], &faces[1]) {
            (a, b) if is_plane(a) && is_plane(b) => {
                let range = range.or(radius.span()).ok_or_else(|| GeomError::Format {
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
                return Ok(cylinder_branches(&probe, &[0, 1])?
                    .into_iter()
                    .map(|form| curve(form, turn, true))
                    .collect());
            }
            (Face::Cylinder(_), Face::Sphere(_)) | (Face::Sphere(_), Face::Cylinder(_)) => {
                let probe = curve(CentreForm::PlanePlane, turn, true);
                let cylinder = usize::from(matches!(faces[1], Face::Cylinder(_)));
                return Ok(cylinder_branches(&probe, &[cylinder])?
                    .into_iter()
                    .map(|form| curve(form, turn, true))
                    .collect());
            }
            (Face::Sphere(a), Face::Sphere(b)) => {
                if a.frame.origin() == b.frame.origin() {
                    return Err(unsupported(
                        "concentric spheres have no edge (their offsets are concentric \
                         spheres): no fillet",
                    ));
                }
                CentreForm::SphereSphere
            }
            _ => {
                return Err(unsupported(
                    "closed-form centre curves exist here for plane/plane, sphere/plane, \
                     plane/cylinder, cylinder/cylinder, sphere/cylinder and sphere/sphere",
                ))
            }
        };
        Ok(vec![curve(form, turn, true)])
    }

    /// The signed offsets `d_k(t) = σ_k ρ(t)` (exact for a constant radius).
    pub fn offsets<T: Real>(&self, t: &T) -> [T; 2] {
        let rho = self.radius.at(t);
        self.signs.map(|s| t.lift(s) * &rho)
    }

    /// The offset radius `R + d` of a sphere or cylinder face `k` (constant radius).
    fn offset_radius<T: Real>(&self, k: usize, t: &T) -> T {
        t.lift(self.faces[k].radius().unwrap_or(0.0)) + &self.offsets(t)[k]
    }

    /// The offset plane `m·x = h + d(t)` of plane face `k`.
    fn offset_plane<T: Real>(&self, k: usize, t: &T) -> ([T; 3], T) {
        let d = self.offsets(t)[k].clone();
        match self.faces[k].plane_form(t) {
            Some(p) => (p.m, p.h + d),
            None => (lift(t, &[f64::NAN; 3]), t.lift(f64::NAN)),
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
            CentreForm::SphereSphere => {
                let (q, rc2, axis) = self.sphere_sphere_circle(t);
                circle_point(&q, &rc2.sqrt(), &axis, t)
            }
            CentreForm::CylinderCylinder {
                param: cylinder,
                branch,
            }
            | CentreForm::CylinderSphere { cylinder, branch } => {
                let (base, z, [alpha, beta, gamma]) = self.cylinder_quadratic(cylinder, t);
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
        circle_point(&q, &rc, &m, t)
    }

    /// The circle of the two offset spheres: its centre `q`, `ρ_c²` and the unit
    /// normal of its plane (module doc).
    fn sphere_sphere_circle<T: Real>(&self, t: &T) -> ([T; 3], T, [T; 3]) {
        let (Face::Sphere(a), Face::Sphere(b)) = (&self.faces[0], &self.faces[1]) else {
            let nan = lift(t, &[f64::NAN; 3]);
            return (nan.clone(), t.lift(f64::NAN), nan);
        };
        let c1 = lift(t, &a.frame.origin());
        let w = sub(&lift(t, &b.frame.origin()), &c1);
        let ww = norm_sq(&w);
        let (r1, r2) = (
            self.offset_radius(0, t).sqr(),
            self.offset_radius(1, t).sqr(),
        );
        let xi = (ww.clone() + &r1 - r2) / (t.lift(2.0) * &ww);
        let q = add_scaled(&c1, &xi, &w);
        let rc2 = r1 - xi.sqr() * &ww;
        let len = ww.sqrt();
        (q, rc2, w.map(|c| c / &len))
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
    /// `(α, β, γ)` of the other offset surface's equation in the height `v`:
    /// `|g(w₀) + v g(Z)|² = R₂'²`, `w₀ = base − o₂`, with `g(y) = y − (y·Z₂)Z₂` for a
    /// cylinder (axis `Z₂`) and `g(y) = y` for a sphere (centre `o₂`).
    fn cylinder_quadratic<T: Real>(&self, param: usize, t: &T) -> ([T; 3], [T; 3], [T; 3]) {
        let (base, z) = self.cylinder_base(param, t);
        let other = 1 - param;
        let (origin, z2) = match &self.faces[other] {
            Face::Cylinder(c2) => (c2.frame.origin(), Some(c2.frame.axes(t)[2].clone())),
            Face::Sphere(s2) => (s2.frame.origin(), None),
            _ => {
                let nan = t.lift(f64::NAN);
                return (base, z, [nan.clone(), nan.clone(), nan]);
            }
        };
        let g = |y: &[T; 3]| match &z2 {
            Some(z2) => add_scaled(y, &-dot(y, z2), z2),
            None => y.clone(),
        };
        let (gw, gz) = (g(&sub(&base, &lift(t, &origin))), g(&z));
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
        let d = self.offsets(t);
        let contact = [0, 1].map(|k| add_scaled(&centre, &-d[k].clone(), &normal[k]));
        let sign = self.signs[0] * self.signs[1];
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
            CentreForm::SphereSphere => {
                out.push((self.sphere_sphere_circle(t).1, Condition::Real));
            }
            CentreForm::CylinderCylinder { param, .. }
            | CentreForm::CylinderSphere {
                cylinder: param, ..
            } => {
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

/// `q + r(cos t E₁ + sin t E₂)` with `(E₁, E₂)` = [`in_plane_basis`] of the unit `m`.
fn circle_point<T: Real>(q: &[T; 3], r: &T, m: &[T; 3], t: &T) -> [T; 3] {
    let (e1, e2) = in_plane_basis(m);
    add(
        q,
        &add(
            &scale(&(r.clone() * t.cos()), &e1),
            &scale(&(r.clone() * t.sin()), &e2),
        ),
    )
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

/// The branches of a cylinder pair or a sphere/cylinder pair: parametrised by the
/// angle of the first cylinder of `params` whose discriminant is positive at every
/// sample of a float scan (the curve does not turn back in that angle), both roots.
/// Errors: parallel axes, or the curve turns back in every angle tried
/// (`unsupported`). No branch (the discriminant ≤ 0 at every sample): both roots,
/// which the proof then finds absent, or touching (tangent faces).
fn cylinder_branches(probe: &CentreCurve, params: &[usize]) -> Result<Vec<CentreForm>, GeomError> {
    let samples = 720;
    let sphere = params.len() == 1;
    for &param in params {
        let form = |branch| {
            if sphere {
                CentreForm::CylinderSphere {
                    cylinder: param,
                    branch,
                }
            } else {
                CentreForm::CylinderCylinder { param, branch }
            }
        };
        let mut min = f64::INFINITY;
        let mut max = f64::NEG_INFINITY;
        let mut alpha = f64::INFINITY;
        for i in 0..samples {
            let t = 2.0 * std::f64::consts::PI * i as f64 / samples as f64;
            let (_, _, [a, b, g]) = probe.cylinder_quadratic(param, &t);
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
        if min > 0.0 || max <= 0.0 {
            return Ok([1.0, -1.0].map(form).to_vec());
        }
    }
    Err(unsupported(if sphere {
        "the centre curve of this sphere and cylinder turns back in the cylinder's angle \
         (the offset sphere does not enclose the whole offset cylinder's cross-section \
         circle): not in this build"
    } else {
        "the centre curve of these cylinders turns back in both angles (it is not a \
         graph over either cylinder's angle): not in this build"
    }))
}
