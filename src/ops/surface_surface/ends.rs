//! Domain faces of surface ∩ surface decided exactly (OPERATIONS.md §9.4 "Boundary",
//! CERTIFICATION.md "Completeness"; issue 15, the curve at a cylinder's height end).
//!
//! The completeness proof solves, on every bounded face of the domain, the iso-curve of
//! the face against the other surface (module doc of `complete`). Where the intersection
//! curve only *touches* a face, that system has a double root, which interval arithmetic
//! cannot tell from two roots or none. For a circular cylinder and a sphere the face
//! system of a height end is algebraic in the input doubles and is decided here with
//! exact rationals instead.
//!
//! The cylinder is `O + ρ(cos u X + sin u Y) + v Z` with `Z = axis/|axis|` (the frame is
//! exactly orthonormal, `curve::frame`), taken only when `|axis|` is rational (so
//! `Z` is). With `w = c − O` (`c` the sphere's centre, `R` its radius), `w_z = w·Z` and
//! `d² = |w|² − w_z²` (the squared distance of `c` from the axis), the squared distance
//! minus `R²` at the point `(u, v)` of the cylinder is
//!
//! ```text
//! G(u, v) = ρ² + d² + (w_z − v)² − R² − 2ρd cos(u − φ)        (φ: the direction of c)
//! ```
//!
//! On the face `v = h`, `G = A − B cos(u − φ)` with `A = ρ² + d² + (w_z − h)² − R²` and
//! `B = 2ρd`, both known exactly through `A` and `B²`:
//! * `A² > B²` (or `d = 0`, `A ≠ 0`): `G ≠ 0` on the whole circle — the face holds no
//!   point of the intersection ([`FaceTruth::Empty`]);
//! * `A² = B² ≠ 0`: one double root `u₀` (`φ` or `φ + π`), where `G(u, h)` has the sign
//!   `σ = sign A` for every `u ≠ u₀`. Near it the curve `G = 0` is the graph
//!   `v − h ≈ −G(u, h)/G_v` with `G_v = 2(h − w_z)` (implicit function theorem, `G_v ≠
//!   0`), so it lies strictly on the side `−σ·sign(h − w_z)` of the face except at the
//!   touching point. When that side is the domain's ([`FaceTruth::TouchInside`]) the
//!   face holds at most that one point and the curve does not cross there.
//! * otherwise (two transversal roots, or the whole circle on the sphere) nothing is
//!   decided here: the interval solve of the face stands.
//!
//! A trimmed sphere only removes points: both statements stay true.

use crate::surface::quadrics::{Cylinder, Sphere};
use crate::surface::{AnySurface, Surface};
use rug::Rational;
use std::cmp::Ordering;

/// What is known exactly about one face's points of the intersection.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FaceTruth {
    /// None.
    Empty,
    /// At most one, where the curve touches the face from inside the domain.
    TouchInside,
}

/// The face `x_k = bound` (a domain bound, exactly) and what is known about it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DecidedFace {
    pub k: usize,
    pub bound: f64,
    pub truth: FaceTruth,
}

/// The faces of the pair `(r, s)` decided exactly (module doc); empty for other pairs.
pub fn decide(r: Option<&AnySurface>, s: Option<&AnySurface>) -> Vec<DecidedFace> {
    match (r, s) {
        (Some(AnySurface::Cylinder(c)), Some(AnySurface::Sphere(p))) => cylinder_sphere(c, p, 1),
        (Some(AnySurface::Sphere(p)), Some(AnySurface::Cylinder(c))) => cylinder_sphere(c, p, 3),
        _ => Vec::new(),
    }
}

fn q(x: f64) -> Option<Rational> {
    Rational::from_f64(x)
}

fn q3(x: [f64; 3]) -> Option<[Rational; 3]> {
    Some([q(x[0])?, q(x[1])?, q(x[2])?])
}

fn dot(a: &[Rational; 3], b: &[Rational; 3]) -> Rational {
    Rational::from(&a[0] * &b[0]) + Rational::from(&a[1] * &b[1]) + Rational::from(&a[2] * &b[2])
}

/// `√x` when it is rational.
fn rational_sqrt(x: &Rational) -> Option<Rational> {
    if x.cmp0() == Ordering::Less {
        return None;
    }
    let (n, d) = (x.numer(), x.denom());
    (n.is_perfect_square() && d.is_perfect_square())
        .then(|| Rational::from((n.clone().sqrt(), d.clone().sqrt())))
}

fn sign(x: &Rational) -> i32 {
    match x.cmp0() {
        Ordering::Less => -1,
        Ordering::Equal => 0,
        Ordering::Greater => 1,
    }
}

/// The height ends of the cylinder (coordinate `k` of the pair) against the sphere.
fn cylinder_sphere(c: &Cylinder, p: &Sphere, k: usize) -> Vec<DecidedFace> {
    let [a, b] = c.semi_axes();
    if a != b {
        return Vec::new();
    }
    let f = c.frame();
    let (Some(axis), Some(o), Some(centre), Some(rho), Some(big)) = (
        q3(f.axis()),
        q3(f.origin()),
        q3(p.frame().origin()),
        q(a),
        q(p.radius()),
    ) else {
        return Vec::new();
    };
    let Some(len) = rational_sqrt(&dot(&axis, &axis)) else {
        return Vec::new();
    };
    if len.cmp0() != Ordering::Greater {
        return Vec::new();
    }
    let w: [Rational; 3] = std::array::from_fn(|i| Rational::from(&centre[i] - &o[i]));
    let wz = dot(&w, &axis) / &len;
    let d2 = dot(&w, &w) - Rational::from(&wz * &wz);
    let rho2 = Rational::from(&rho * &rho);
    let b2 = Rational::from(4) * &rho2 * &d2;
    let heights = c.domain().1;
    let mut out = Vec::new();
    for (end, h) in heights.into_iter().enumerate() {
        let Some(hq) = q(h) else { continue };
        let dz = Rational::from(&hq - &wz);
        let aa = rho2.clone() + &d2 + Rational::from(&dz * &dz) - Rational::from(&big * &big);
        let a2 = Rational::from(&aa * &aa);
        let truth = if d2.cmp0() == Ordering::Equal {
            (aa.cmp0() != Ordering::Equal).then_some(FaceTruth::Empty)
        } else {
            match a2.cmp(&b2) {
                Ordering::Greater => Some(FaceTruth::Empty),
                Ordering::Equal => {
                    // inside: below the upper end, above the lower one
                    let inside = if end == 1 { -1 } else { 1 };
                    let side = -sign(&aa) * sign(&dz);
                    (side == inside).then_some(FaceTruth::TouchInside)
                }
                Ordering::Less => None,
            }
        };
        if let Some(truth) = truth {
            out.push(DecidedFace { k, bound: h, truth });
        }
    }
    out
}
