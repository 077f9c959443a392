//! Surfaces polynomial in `(u, v)` on a rectangle (OPERATIONS.md §1.6): the plane
//! `p + u a + v b` [Y 3.2.1] and the rectangular paraboloids
//! `(a u, b v, u² ± v²)` [Y 3.2.12], [Y 3.2.13].

use super::frame::{exactly_parallel, Frame};
use super::validate::{interval, positive, restrict_domain, Domain};
use super::{StepRule, Surface};
use crate::error::{require_finite_all, GeomError};
use crate::num::vector::{add, lift, scale, zero};
use crate::num::Real;

const ALL: [f64; 2] = [f64::NEG_INFINITY, f64::INFINITY];

/// The plane `origin + u·a + v·b` (CASES `plane` with `origin`, `u`, `v`; `a`, `b` need
/// not be orthogonal or unit), on `ℝ²` or a rectangle.
///
/// The origin may be a box instead of a point ([`Plane::through_box`]): an implicit
/// plane `n·x + d = 0` rarely has a point with double coordinates (`x = 1/3`), so the
/// front door gives it the box of one ulp around `−d/n_k` that holds one, and exact
/// spanning vectors. Every enclosure (interval or MPFR) then evaluates the origin as that
/// box, so it encloses the point of *every* plane through the box with these vectors —
/// and a certificate proven from enclosures (Krawczyk, exclusion, an arc in a box)
/// holds for each of them, the user's exact plane among them. The float path uses the
/// double `origin` (the rounded point).
#[derive(Debug, Clone, PartialEq)]
pub struct Plane {
    pub(crate) origin: [f64; 3],
    /// `Some((lo, hi))`: the origin is the box `[lo, hi]` (holding `origin`).
    pub(crate) origin_box: Option<([f64; 3], [f64; 3])>,
    pub(crate) a: [f64; 3],
    pub(crate) b: [f64; 3],
    domain: Domain,
}

impl Plane {
    /// A plane; errors name `origin`, `u`, `v` (non-finite) and `v` for vectors that are
    /// exactly collinear (including a zero vector).
    pub fn new(origin: [f64; 3], a: [f64; 3], b: [f64; 3]) -> Result<Plane, GeomError> {
        require_finite_all("origin", &origin)?;
        require_finite_all("u", &a)?;
        require_finite_all("v", &b)?;
        if exactly_parallel(&a, &b) {
            return Err(GeomError::CollinearPlaneVectors { field: "v".into() });
        }
        Ok(Plane {
            origin,
            origin_box: None,
            a,
            b,
            domain: (ALL, ALL),
        })
    }

    /// The planes spanned by `a`, `b` through the points of the box `[lo, hi]`, with the
    /// rounded point `origin` inside it for the float path (struct doc). Errors as
    /// [`Plane::new`], and `origin` (`invalid_value`) when the box is empty or does not
    /// hold `origin`.
    pub fn through_box(
        origin: [f64; 3],
        [lo, hi]: [[f64; 3]; 2],
        a: [f64; 3],
        b: [f64; 3],
    ) -> Result<Plane, GeomError> {
        require_finite_all("origin", &lo)?;
        require_finite_all("origin", &hi)?;
        if (0..3).any(|k| !(lo[k] <= origin[k] && origin[k] <= hi[k])) {
            return Err(GeomError::InvalidValue {
                field: "origin".into(),
                reason: "the origin box does not hold the origin".into(),
            });
        }
        let mut p = Plane::new(origin, a, b)?;
        p.origin_box = (lo != hi).then_some((lo, hi));
        Ok(p)
    }

    /// The origin in the number system of `like`: the box for enclosures, the rounded
    /// point for f64 (struct doc).
    pub(crate) fn origin_in<T: Real>(&self, like: &T) -> [T; 3] {
        match &self.origin_box {
            Some((lo, hi)) if !T::IS_F64 => {
                std::array::from_fn(|k| like.lift(lo[k]).hull_with(&like.lift(hi[k])))
            }
            _ => lift(like, &self.origin),
        }
    }

    /// The same plane on a rectangle (finite, non-empty).
    pub fn with_domain(mut self, domain: Domain) -> Result<Plane, GeomError> {
        self.domain = restrict_domain(self.domain, Some(domain))?;
        Ok(self)
    }

    pub fn origin(&self) -> [f64; 3] {
        self.origin
    }
    /// The spanning vectors `(a, b)` as given.
    pub fn vectors(&self) -> ([f64; 3], [f64; 3]) {
        (self.a, self.b)
    }
}

impl Surface for Plane {
    super::implicit_value_by_form!();
    fn domain(&self) -> ([f64; 2], [f64; 2]) {
        self.domain
    }
    fn step_rules(&self) -> [StepRule; 2] {
        [StepRule::WholeRange, StepRule::WholeRange]
    }
    fn jet<T: Real>(&self, u: &T, v: &T, order: usize) -> Vec<[T; 3]> {
        let (a, b) = (lift(u, &self.a), lift(u, &self.b));
        let p = add(&self.origin_in(u), &add(&scale(u, &a), &scale(v, &b)));
        let mut jet = vec![p];
        if order >= 1 {
            jet.push(a);
            jet.push(b);
        }
        if order >= 2 {
            jet.extend([zero(u), zero(u), zero(u)]);
        }
        jet
    }
}

/// Rectangular paraboloid `center + a u X + b v Y + (u² + σ v²) Z`: elliptic for
/// `σ = +1` [Y 3.2.12], hyperbolic for `σ = −1` [Y 3.2.13]; open, on a required
/// rectangle.
#[derive(Debug, Clone, PartialEq)]
pub struct ParaboloidRect {
    pub(crate) frame: Frame,
    pub(crate) ab: [f64; 2],
    /// `σ = ±1`.
    pub(crate) sign: f64,
    domain: Domain,
}

impl ParaboloidRect {
    /// `z = u² + v²`, `x = a u`, `y = b v`.
    pub fn elliptic(
        frame: Frame,
        ab: [f64; 2],
        domain: Domain,
    ) -> Result<ParaboloidRect, GeomError> {
        ParaboloidRect::new(frame, ab, 1.0, domain)
    }

    /// `z = u² − v²`, `x = a u`, `y = b v` (implicit `x²/a² − y²/b² = z`).
    pub fn hyperbolic(
        frame: Frame,
        ab: [f64; 2],
        domain: Domain,
    ) -> Result<ParaboloidRect, GeomError> {
        ParaboloidRect::new(frame, ab, -1.0, domain)
    }

    fn new(
        frame: Frame,
        [a, b]: [f64; 2],
        sign: f64,
        domain: Domain,
    ) -> Result<ParaboloidRect, GeomError> {
        Ok(ParaboloidRect {
            frame,
            ab: [positive("a", a)?, positive("b", b)?],
            sign,
            domain: (
                interval("domain[0]", domain.0)?,
                interval("domain[1]", domain.1)?,
            ),
        })
    }

    pub fn frame(&self) -> &Frame {
        &self.frame
    }
    pub fn semi_axes(&self) -> [f64; 2] {
        self.ab
    }
    /// `true` for the hyperbolic paraboloid.
    pub fn is_hyperbolic(&self) -> bool {
        self.sign < 0.0
    }
}

impl Surface for ParaboloidRect {
    super::implicit_value_by_form!();
    fn domain(&self) -> ([f64; 2], [f64; 2]) {
        self.domain
    }
    fn jet<T: Real>(&self, u: &T, v: &T, order: usize) -> Vec<[T; 3]> {
        let (a, b, sign) = (u.lift(self.ab[0]), u.lift(self.ab[1]), u.lift(self.sign));
        let (zero, two) = (u.zero_like(), u.lift(2.0));
        let mut local = vec![[
            a.clone() * u,
            b.clone() * v,
            u.sqr() + sign.clone() * v.sqr(),
        ]];
        if order >= 1 {
            local.push([a, zero.clone(), two.clone() * u]);
            local.push([zero.clone(), b, two.clone() * &sign * v]);
        }
        if order >= 2 {
            local.push([zero.clone(), zero.clone(), two.clone()]);
            local.push([zero.clone(), zero.clone(), zero.clone()]);
            local.push([zero.clone(), zero, two * &sign]);
        }
        self.frame.place_jet(&local)
    }
}
