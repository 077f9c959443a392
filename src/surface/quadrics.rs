//! Quadrics of OPERATIONS.md §1.6 with the parametrisations and default domains of
//! docs/FORMAT.md: sphere, ellipsoid, hyperboloids of one and two sheets, the elliptic
//! paraboloid (polar form), elliptic cylinder and circular cone. All share the formula of
//! `surface::rotational`; the rectangular paraboloids ([Y 3.2.12], [Y 3.2.13]) are
//! [`super::plane::ParaboloidRect`].
//!
//! Every constructor validates its input (typed errors naming `center`/`origin`,
//! `axis`, `ref`, the radii, `range`/`height` and `domain`); the frame rule is that of
//! [`Frame`].

use super::frame::Frame;
use super::rotational::{rotational_jet, Profile};
use super::validate::{interval, positive, restrict_domain, Domain, FULL_TURN};
use super::{StepRule, Surface};
use crate::error::{require_finite, require_finite_all, GeomError};
use crate::num::Real;

const HALF_PI: f64 = std::f64::consts::FRAC_PI_2;
const Z_AXIS: [f64; 3] = [0.0, 0.0, 1.0];

/// `(cos v, sin v)` and derivatives: the sphere/ellipsoid profile.
fn trig_profile<T: Real>(v: &T) -> Profile<T> {
    let (c, s) = (v.cos(), v.sin());
    Profile {
        f: [c.clone(), -s.clone(), -c.clone()],
        g: [s.clone(), c, -s],
    }
}

/// The domain restriction and closedness common to the surfaces whose `u` is an angle.
fn angular_closed(domain: &Domain) -> [bool; 2] {
    [domain.0 == FULL_TURN, false]
}

macro_rules! domain_accessors {
    ($t:ty) => {
        impl $t {
            /// The same surface on a sub-rectangle of its domain (errors name
            /// `domain[0]`, `domain[1]`).
            pub fn with_domain(mut self, domain: Domain) -> Result<Self, GeomError> {
                self.domain = restrict_domain(self.domain, Some(domain))?;
                Ok(self)
            }
            /// The local frame.
            pub fn frame(&self) -> &Frame {
                &self.frame
            }
        }
    };
}

/// Sphere `center + r cos v (cos u X + sin u Y) + r sin v Z`, `u ∈ [0, 2π]` (closed),
/// `v ∈ [−π/2, π/2]`.
#[derive(Debug, Clone, PartialEq)]
pub struct Sphere {
    pub(crate) frame: Frame,
    pub(crate) radius: f64,
    domain: Domain,
}

impl Sphere {
    /// A sphere; `axis` defaults to `+z`.
    pub fn new(
        center: [f64; 3],
        radius: f64,
        axis: Option<[f64; 3]>,
        reference: Option<[f64; 3]>,
    ) -> Result<Sphere, GeomError> {
        require_finite_all("center", &center)?;
        let frame = Frame::new(center, axis.unwrap_or(Z_AXIS), reference)?;
        Ok(Sphere {
            frame,
            radius: positive("radius", radius)?,
            domain: (FULL_TURN, [-HALF_PI, HALF_PI]),
        })
    }
    pub fn radius(&self) -> f64 {
        self.radius
    }
}
domain_accessors!(Sphere);

impl Surface for Sphere {
    super::implicit_value_by_form!();
    fn domain(&self) -> ([f64; 2], [f64; 2]) {
        self.domain
    }
    fn v_poles(&self) -> [bool; 2] {
        let [lo, hi] = self.domain.1;
        [lo == -HALF_PI, hi == HALF_PI]
    }
    fn is_closed(&self) -> [bool; 2] {
        angular_closed(&self.domain)
    }
    fn step_rules(&self) -> [StepRule; 2] {
        [StepRule::Angle, StepRule::Angle]
    }
    fn jet<T: Real>(&self, u: &T, v: &T, order: usize) -> Vec<[T; 3]> {
        let r = self.radius;
        rotational_jet(&self.frame, [r, r, r], u, &trig_profile(v), order)
    }
}

/// Ellipsoid `center + a cos v cos u X + b cos v sin u Y + c sin v Z`, domain as the
/// sphere's.
#[derive(Debug, Clone, PartialEq)]
pub struct Ellipsoid {
    pub(crate) frame: Frame,
    pub(crate) abc: [f64; 3],
    domain: Domain,
}

impl Ellipsoid {
    /// An ellipsoid with semi-axes `a, b, c > 0`; `axis` defaults to `+z`.
    pub fn new(
        center: [f64; 3],
        [a, b, c]: [f64; 3],
        axis: Option<[f64; 3]>,
        reference: Option<[f64; 3]>,
    ) -> Result<Ellipsoid, GeomError> {
        require_finite_all("center", &center)?;
        let frame = Frame::new(center, axis.unwrap_or(Z_AXIS), reference)?;
        Ok(Ellipsoid {
            frame,
            abc: [positive("a", a)?, positive("b", b)?, positive("c", c)?],
            domain: (FULL_TURN, [-HALF_PI, HALF_PI]),
        })
    }
    pub fn semi_axes(&self) -> [f64; 3] {
        self.abc
    }
}
domain_accessors!(Ellipsoid);

impl Surface for Ellipsoid {
    super::implicit_value_by_form!();
    fn domain(&self) -> ([f64; 2], [f64; 2]) {
        self.domain
    }
    fn v_poles(&self) -> [bool; 2] {
        let [lo, hi] = self.domain.1;
        [lo == -HALF_PI, hi == HALF_PI]
    }
    fn is_closed(&self) -> [bool; 2] {
        angular_closed(&self.domain)
    }
    fn step_rules(&self) -> [StepRule; 2] {
        [StepRule::Angle, StepRule::Angle]
    }
    fn jet<T: Real>(&self, u: &T, v: &T, order: usize) -> Vec<[T; 3]> {
        rotational_jet(&self.frame, self.abc, u, &trig_profile(v), order)
    }
}

/// Which hyperboloid: one sheet `(a cosh v cos u, b cosh v sin u, c sinh v)` or two
/// sheets `(a sinh v cos u, b sinh v sin u, c cosh v)` (the sheet on `+Z`; reverse the
/// axis for the other one).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Sheets {
    One,
    Two,
}

/// Hyperboloid of one or two sheets, `u ∈ [0, 2π]` (closed), `v ∈ range`.
#[derive(Debug, Clone, PartialEq)]
pub struct Hyperboloid {
    pub(crate) frame: Frame,
    pub(crate) abc: [f64; 3],
    pub(crate) sheets: Sheets,
    domain: Domain,
}

impl Hyperboloid {
    /// A hyperboloid with `a, b, c > 0` over `v ∈ range` (required: the surface is
    /// unbounded).
    pub fn new(
        sheets: Sheets,
        center: [f64; 3],
        [a, b, c]: [f64; 3],
        axis: [f64; 3],
        reference: Option<[f64; 3]>,
        range: [f64; 2],
    ) -> Result<Hyperboloid, GeomError> {
        require_finite_all("center", &center)?;
        let frame = Frame::new(center, axis, reference)?;
        Ok(Hyperboloid {
            frame,
            abc: [positive("a", a)?, positive("b", b)?, positive("c", c)?],
            sheets,
            domain: (FULL_TURN, interval("range", range)?),
        })
    }
    pub fn sheets(&self) -> Sheets {
        self.sheets
    }
    pub fn semi_axes(&self) -> [f64; 3] {
        self.abc
    }
}
domain_accessors!(Hyperboloid);

impl Surface for Hyperboloid {
    super::implicit_value_by_form!();
    fn domain(&self) -> ([f64; 2], [f64; 2]) {
        self.domain
    }
    fn is_closed(&self) -> [bool; 2] {
        angular_closed(&self.domain)
    }
    /// `u` is an angle as on the sphere (impl: §2.2 lists the sphere-like surfaces; on a
    /// circular section the normal turns by at most `Δu`, and the pole row of a
    /// paraboloid would otherwise take `Δ_min` steps).
    fn step_rules(&self) -> [StepRule; 2] {
        [StepRule::Angle, StepRule::Curvature]
    }
    fn jet<T: Real>(&self, u: &T, v: &T, order: usize) -> Vec<[T; 3]> {
        let (ch, sh) = (v.cosh(), v.sinh());
        let (cosh, sinh) = ([ch.clone(), sh.clone(), ch], [sh.clone(), v.cosh(), sh]);
        let profile = match self.sheets {
            Sheets::One => Profile { f: cosh, g: sinh },
            Sheets::Two => Profile { f: sinh, g: cosh },
        };
        rotational_jet(&self.frame, self.abc, u, &profile, order)
    }
}

/// Elliptic paraboloid (polar form, CASES `paraboloid`):
/// `center + a v cos u X + b v sin u Y + v² Z`, `u ∈ [0, 2π]` (closed), `v ∈ range`.
#[derive(Debug, Clone, PartialEq)]
pub struct Paraboloid {
    pub(crate) frame: Frame,
    pub(crate) ab: [f64; 2],
    domain: Domain,
}

impl Paraboloid {
    pub fn new(
        center: [f64; 3],
        [a, b]: [f64; 2],
        axis: [f64; 3],
        reference: Option<[f64; 3]>,
        range: [f64; 2],
    ) -> Result<Paraboloid, GeomError> {
        require_finite_all("center", &center)?;
        let frame = Frame::new(center, axis, reference)?;
        Ok(Paraboloid {
            frame,
            ab: [positive("a", a)?, positive("b", b)?],
            domain: (FULL_TURN, interval("range", range)?),
        })
    }
    pub fn semi_axes(&self) -> [f64; 2] {
        self.ab
    }
}
domain_accessors!(Paraboloid);

impl Surface for Paraboloid {
    super::implicit_value_by_form!();
    fn domain(&self) -> ([f64; 2], [f64; 2]) {
        self.domain
    }
    fn is_closed(&self) -> [bool; 2] {
        angular_closed(&self.domain)
    }
    /// `u` is an angle as on the sphere (impl: §2.2 lists the sphere-like surfaces; on a
    /// circular section the normal turns by at most `Δu`, and the pole row of a
    /// paraboloid would otherwise take `Δ_min` steps).
    fn step_rules(&self) -> [StepRule; 2] {
        [StepRule::Angle, StepRule::Curvature]
    }
    fn jet<T: Real>(&self, u: &T, v: &T, order: usize) -> Vec<[T; 3]> {
        let (zero, one, two) = (v.zero_like(), v.one_like(), v.lift(2.0));
        let profile = Profile {
            f: [v.clone(), one, zero],
            g: [v.sqr(), two.clone() * v, two],
        };
        let [a, b] = self.ab;
        rotational_jet(&self.frame, [a, b, 1.0], u, &profile, order)
    }
}

/// Elliptic cylinder `origin + a cos u X + b sin u Y + v Z` (CASES `cylinder`:
/// `a = b = radius`), `u ∈ [0, 2π]` (closed), `v ∈ height`.
#[derive(Debug, Clone, PartialEq)]
pub struct Cylinder {
    pub(crate) frame: Frame,
    pub(crate) ab: [f64; 2],
    domain: Domain,
}

impl Cylinder {
    pub fn new(
        origin: [f64; 3],
        [a, b]: [f64; 2],
        axis: [f64; 3],
        reference: Option<[f64; 3]>,
        height: [f64; 2],
    ) -> Result<Cylinder, GeomError> {
        let frame = Frame::new(origin, axis, reference)?;
        Ok(Cylinder {
            frame,
            ab: [positive("a", a)?, positive("b", b)?],
            domain: (FULL_TURN, interval("height", height)?),
        })
    }
    pub fn semi_axes(&self) -> [f64; 2] {
        self.ab
    }
}
domain_accessors!(Cylinder);

impl Surface for Cylinder {
    super::implicit_value_by_form!();
    fn domain(&self) -> ([f64; 2], [f64; 2]) {
        self.domain
    }
    fn is_closed(&self) -> [bool; 2] {
        angular_closed(&self.domain)
    }
    fn step_rules(&self) -> [StepRule; 2] {
        [StepRule::Angle, StepRule::WholeRange]
    }
    fn jet<T: Real>(&self, u: &T, v: &T, order: usize) -> Vec<[T; 3]> {
        let (zero, one) = (v.zero_like(), v.one_like());
        let profile = Profile {
            f: [one.clone(), zero.clone(), zero.clone()],
            g: [v.clone(), one, zero],
        };
        let [a, b] = self.ab;
        rotational_jet(&self.frame, [a, b, 1.0], u, &profile, order)
    }
}

/// Circular cone `origin + (r + v tan α)(cos u X + sin u Y) + v Z` (CASES `cone`; `r`
/// is the radius at `v = 0`, `r = 0` puts the apex at the origin), `u ∈ [0, 2π]`
/// (closed), `v ∈ height`. `tan α` is evaluated in the number type, so intervals
/// enclose the exact cone of the exact double `α`.
#[derive(Debug, Clone, PartialEq)]
pub struct Cone {
    pub(crate) frame: Frame,
    pub(crate) radius: f64,
    pub(crate) half_angle: f64,
    domain: Domain,
}

impl Cone {
    /// A cone with `radius ≥ 0` and `half_angle ∈ (−π/2, π/2)`, not 0 (that is a
    /// cylinder; a negative angle narrows with `v`).
    pub fn new(
        origin: [f64; 3],
        radius: f64,
        half_angle: f64,
        axis: [f64; 3],
        reference: Option<[f64; 3]>,
        height: [f64; 2],
    ) -> Result<Cone, GeomError> {
        let frame = Frame::new(origin, axis, reference)?;
        super::validate::non_negative("radius", radius)?;
        require_finite("half_angle", half_angle)?;
        if half_angle == 0.0 || half_angle.abs() >= HALF_PI {
            return Err(GeomError::InvalidValue {
                field: "half_angle".into(),
                reason: format!("{half_angle} must lie in (−π/2, π/2) and not be 0"),
            });
        }
        Ok(Cone {
            frame,
            radius,
            half_angle,
            domain: (FULL_TURN, interval("height", height)?),
        })
    }
    pub fn radius(&self) -> f64 {
        self.radius
    }
    pub fn half_angle(&self) -> f64 {
        self.half_angle
    }
}
domain_accessors!(Cone);

impl Surface for Cone {
    super::implicit_value_by_form!();
    fn domain(&self) -> ([f64; 2], [f64; 2]) {
        self.domain
    }
    fn is_closed(&self) -> [bool; 2] {
        angular_closed(&self.domain)
    }
    fn step_rules(&self) -> [StepRule; 2] {
        [StepRule::Angle, StepRule::WholeRange]
    }
    fn jet<T: Real>(&self, u: &T, v: &T, order: usize) -> Vec<[T; 3]> {
        let (zero, one) = (v.zero_like(), v.one_like());
        let t = v.lift(self.half_angle).tan();
        let profile = Profile {
            f: [v.lift(self.radius) + t.clone() * v, t, zero.clone()],
            g: [v.clone(), one, zero],
        };
        rotational_jet(&self.frame, [1.0, 1.0, 1.0], u, &profile, order)
    }
}
