//! Lines and segments of OPERATIONS.md §1.5 ([Y 2.2.1–2.2.2]; docs/FORMAT.md `line`,
//! `segment`, `line2`, `segment2`) in any dimension. Affine in `t`, so an interval
//! parameter gives the exact range of values up to outward rounding.

use super::domain::Domain;
use super::{Curve, StepHint};
use crate::error::{require_finite_all, GeomError};
use crate::num::vector::{add_scaled, lift, sub, zero};
use crate::num::Real;

/// A line `c(t) = origin + t·dir` (§1.5, [Y 2.2.1]); `t ∈ ℝ` unless a range is given.
#[derive(Debug, Clone, PartialEq)]
pub struct Line<const D: usize> {
    pub(crate) origin: [f64; D],
    pub(crate) dir: [f64; D],
    pub(crate) range: Option<Domain>,
}

impl<const D: usize> Line<D> {
    /// Errors: `non_finite` (`origin[i]`, `dir[i]`, `range[i]`), `zero_direction`
    /// (`dir`), `empty_domain` (`range`).
    pub fn new(
        origin: [f64; D],
        dir: [f64; D],
        range: Option<(f64, f64)>,
    ) -> Result<Self, GeomError> {
        require_finite_all("origin", &origin)?;
        require_finite_all("dir", &dir)?;
        if dir.iter().all(|&x| x == 0.0) {
            return Err(GeomError::ZeroDirection {
                field: "dir".into(),
            });
        }
        let range = range.map(|(a, b)| Domain::new("range", a, b)).transpose()?;
        Ok(Line { origin, dir, range })
    }
    pub fn origin(&self) -> [f64; D] {
        self.origin
    }
    pub fn dir(&self) -> [f64; D] {
        self.dir
    }
    pub fn range(&self) -> Option<(f64, f64)> {
        self.range.map(|d| d.pair())
    }
}

impl<const D: usize> Curve<D> for Line<D> {
    fn domain(&self) -> (f64, f64) {
        self.range
            .map_or((f64::NEG_INFINITY, f64::INFINITY), |d| d.pair())
    }
    fn jet<T: Real>(&self, t: &T, order: usize) -> Vec<[T; D]> {
        let d = lift(t, &self.dir);
        let mut jet = vec![add_scaled(&lift(t, &self.origin), t, &d), d];
        jet.resize(order + 1, zero(t));
        jet.truncate(order + 1);
        jet
    }
    fn step_hint(&self, _t: f64) -> StepHint {
        StepHint::Whole
    }
}

/// A segment `c(t) = (1−t)·a + t·b` (§1.5, [Y 2.2.2]), `t ∈ [0, 1]` or a sub-range.
#[derive(Debug, Clone, PartialEq)]
pub struct Segment<const D: usize> {
    pub(crate) a: [f64; D],
    pub(crate) b: [f64; D],
    pub(crate) domain: Domain,
}

impl<const D: usize> Segment<D> {
    /// Errors: `non_finite` (`a[i]`, `b[i]`, `domain[i]`), `invalid_value` (`b`) when
    /// `a = b`, `empty_domain` / `parameter_outside_domain` (`domain`, inside `[0, 1]`).
    pub fn new(a: [f64; D], b: [f64; D], domain: Option<(f64, f64)>) -> Result<Self, GeomError> {
        require_finite_all("a", &a)?;
        require_finite_all("b", &b)?;
        if a == b {
            return Err(GeomError::InvalidValue {
                field: "b".into(),
                reason: "the segment's end points coincide".into(),
            });
        }
        let domain = sub_domain(domain, (0.0, 1.0))?;
        Ok(Segment { a, b, domain })
    }
    pub fn a(&self) -> [f64; D] {
        self.a
    }
    pub fn b(&self) -> [f64; D] {
        self.b
    }
}

impl<const D: usize> Curve<D> for Segment<D> {
    fn domain(&self) -> (f64, f64) {
        self.domain.pair()
    }
    fn jet<T: Real>(&self, t: &T, order: usize) -> Vec<[T; D]> {
        let a = lift(t, &self.a);
        let b = lift(t, &self.b);
        let s = t.one_like() - t;
        let p = std::array::from_fn(|i| s.clone() * &a[i] + t.clone() * &b[i]);
        let mut jet = vec![p, sub(&b, &a)];
        jet.resize(order + 1, zero(t));
        jet.truncate(order + 1);
        jet
    }
    fn step_hint(&self, _t: f64) -> StepHint {
        StepHint::Whole
    }
}

/// Check an optional domain against a natural range, or take the natural range.
pub(crate) fn sub_domain(
    domain: Option<(f64, f64)>,
    natural: (f64, f64),
) -> Result<Domain, GeomError> {
    match domain {
        None => Domain::new("domain", natural.0, natural.1),
        Some((a, b)) => {
            let d = Domain::new("domain", a, b)?;
            d.check_inside("domain", natural)?;
            Ok(d)
        }
    }
}
