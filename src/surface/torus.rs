//! Torus of OPERATIONS.md §1.6 and docs/FORMAT.md:
//! `center + (R + r cos v)(cos u X + sin u Y) + r sin v Z`.
//!
//! Domain: for `r < R` (ring torus) the CASES default `[0, 2π]²`, closed in both
//! directions. For `r ≥ R` (horn and spindle tori, `R = 0` a sphere) §1.6 restricts `v`
//! to `[−π + γ, π − γ]`, `γ = arccos(R/r)` — the outer part, whose ends are the points on
//! the axis where `R + r cos v = 0`; the endpoints are `γ` rounded in f64, and the surface
//! is closed in `u` only.

use super::frame::Frame;
use super::rotational::{rotational_jet, Profile};
use super::validate::{non_negative, positive, restrict_domain, Domain, FULL_TURN};
use super::{StepRule, Surface};
use crate::error::{require_finite_all, GeomError};
use crate::num::Real;

/// A torus with major radius `R ≥ 0` and minor radius `r > 0`.
#[derive(Debug, Clone, PartialEq)]
pub struct Torus {
    pub(crate) frame: Frame,
    pub(crate) major: f64,
    pub(crate) minor: f64,
    domain: Domain,
}

impl Torus {
    /// A torus about `axis` (errors name `center`, `axis`, `ref`, `major`, `minor`).
    pub fn new(
        center: [f64; 3],
        major: f64,
        minor: f64,
        axis: [f64; 3],
        reference: Option<[f64; 3]>,
    ) -> Result<Torus, GeomError> {
        require_finite_all("center", &center)?;
        let frame = Frame::new(center, axis, reference)?;
        let major = non_negative("major", major)?;
        let minor = positive("minor", minor)?;
        let v_range = if minor < major {
            FULL_TURN
        } else {
            let gamma = (major / minor).acos();
            let pi = std::f64::consts::PI;
            [-pi + gamma, pi - gamma]
        };
        Ok(Torus {
            frame,
            major,
            minor,
            domain: (FULL_TURN, v_range),
        })
    }

    /// The same torus on a sub-rectangle of its domain.
    pub fn with_domain(mut self, domain: Domain) -> Result<Torus, GeomError> {
        self.domain = restrict_domain(self.domain, Some(domain))?;
        Ok(self)
    }

    pub fn frame(&self) -> &Frame {
        &self.frame
    }
    pub fn major(&self) -> f64 {
        self.major
    }
    pub fn minor(&self) -> f64 {
        self.minor
    }
}

impl Surface for Torus {
    super::implicit_value_by_form!();
    fn domain(&self) -> ([f64; 2], [f64; 2]) {
        self.domain
    }
    /// Both ends are angles: `2π`, and for `r ≥ R` the computed `±(π − arccos(R/r))`.
    fn domain_rounded(&self) -> [bool; 2] {
        [true, true]
    }
    fn is_closed(&self) -> [bool; 2] {
        let ring = self.minor < self.major;
        [
            self.domain.0 == FULL_TURN,
            ring && self.domain.1 == FULL_TURN,
        ]
    }
    fn step_rules(&self) -> [StepRule; 2] {
        [StepRule::Angle, StepRule::Angle]
    }
    fn jet<T: Real>(&self, u: &T, v: &T, order: usize) -> Vec<[T; 3]> {
        let (big, r) = (v.lift(self.major), v.lift(self.minor));
        let (rc, rs) = (r.clone() * v.cos(), r * v.sin());
        let profile = Profile {
            f: [big + &rc, -rs.clone(), -rc.clone()],
            g: [rs.clone(), rc, -rs],
        };
        rotational_jet(&self.frame, [1.0, 1.0, 1.0], u, &profile, order)
    }
}
