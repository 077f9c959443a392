//! Derived curves of OPERATIONS.md §1.5 [Y 2.10]: trimmed `c(t₁ + σ(τ − τ₀))`,
//! reversed, and reparametrised `c(t_min + (τ − τ_min)(t_max − t_min)/(τ_max − τ_min))`.
//! All three are one affine change of parameter `t = t₁ + (τ − τ₀)·s`,
//! `s = (n₁ − n₀)/(d₁ − d₀)`, with `dᵏc/dτᵏ = sᵏ c⁽ᵏ⁾(t)`.
//!
//! The scale `s` is computed in the number system of the evaluation from the double
//! inputs, so an interval evaluation encloses the exact reparametrised curve. A trim of
//! a closed curve may run across its seam: the base curve wraps the parameter (§1.5
//! "closed-curve parameter distance taken modulo the period").

use super::domain::Domain;
use super::{Curve, StepHint};
use crate::error::{require_finite, GeomError};
use crate::num::Real;
use rug::float::Round;
use rug::{Float, Rational};

/// A curve under the affine change of parameter `t = t₁ + (τ − τ₀)(n₁ − n₀)/(d₁ − d₀)`.
#[derive(Debug, Clone, PartialEq)]
pub struct Reparametrised<C> {
    base: C,
    t1: f64,
    tau0: f64,
    num: (f64, f64),
    den: (f64, f64),
    domain: Domain,
    closed: bool,
}

/// The exact rational value of a double (finite by the callers' checks).
pub(super) fn q(x: f64) -> Rational {
    Rational::from_f64(x).unwrap_or_default()
}

/// The greatest double `≤ x`.
pub(super) fn round_down(x: &Rational) -> f64 {
    Float::with_val_round(53, x, Round::Down).0.to_f64()
}

/// The least double `≥ x`.
pub(super) fn round_up(x: &Rational) -> f64 {
    Float::with_val_round(53, x, Round::Up).0.to_f64()
}

impl<C> Reparametrised<C> {
    /// The curve that is reparametrised.
    pub fn base(&self) -> &C {
        &self.base
    }

    /// The exact base parameter of `τ` (for validation).
    fn exact_base_parameter(&self, tau: f64) -> Rational {
        let s = (q(self.num.1) - q(self.num.0)) / (q(self.den.1) - q(self.den.0));
        q(self.t1) + (q(tau) - q(self.tau0)) * s
    }

    /// Validate the base range `t(τ)` for `τ` in the domain, and set `closed`: a
    /// non-periodic base must contain the whole mapped range (errors:
    /// `parameter_outside_domain`, `domain[i]`); the result is closed when the base is
    /// closed and the mapped range is its whole domain (up to the period).
    fn finish<const D: usize>(mut self) -> Result<Self, GeomError>
    where
        C: Curve<D>,
    {
        let (lo, hi) = self.base.domain();
        let ends = [self.domain.lo, self.domain.hi].map(|tau| self.exact_base_parameter(tau));
        let width = (ends[1].clone() - &ends[0]).abs();
        if self.base.is_periodic() {
            self.closed = self.base.is_closed() && width == q(hi) - q(lo);
            return Ok(self);
        }
        for (i, e) in ends.iter().enumerate() {
            if lo.is_finite() && *e < q(lo) || hi.is_finite() && *e > q(hi) {
                return Err(GeomError::ParameterOutsideDomain {
                    field: format!("domain[{i}]"),
                    value: format!("{}", e.to_f64()),
                    lo: format!("{lo}"),
                    hi: format!("{hi}"),
                });
            }
        }
        self.closed = self.base.is_closed() && width == q(hi) - q(lo);
        Ok(self)
    }

    /// The trimmed curve `c(t₁ + σ(τ − τ₀))`, `τ ∈ [τ₀, τ_end]`, `σ = ±1` (§1.5).
    /// Errors: `non_finite` (`t1`, `tau0`, `domain[1]`), `invalid_value` (`sigma`),
    /// `empty_domain` (`domain`), `parameter_outside_domain` (`domain[i]`) for a
    /// non-periodic base.
    pub fn trimmed<const D: usize>(
        base: C,
        t1: f64,
        sigma: f64,
        tau0: f64,
        tau_end: f64,
    ) -> Result<Self, GeomError>
    where
        C: Curve<D>,
    {
        require_finite("t1", t1)?;
        require_finite("tau0", tau0)?;
        if sigma != 1.0 && sigma != -1.0 {
            return Err(GeomError::InvalidValue {
                field: "sigma".into(),
                reason: format!("{sigma} must be +1 or -1"),
            });
        }
        let domain = Domain::new("domain", tau0, tau_end)?;
        Reparametrised {
            base,
            t1,
            tau0,
            num: (0.0, sigma),
            den: (0.0, 1.0),
            domain,
            closed: false,
        }
        .finish()
    }

    /// The base curve on `[t_a, t_b]` with its own parameter (`σ = +1`, `τ₀ = t₁ = t_a`).
    pub fn restricted<const D: usize>(base: C, t_a: f64, t_b: f64) -> Result<Self, GeomError>
    where
        C: Curve<D>,
    {
        Self::trimmed(base, t_a, 1.0, t_a, t_b)
    }

    /// The reversed curve `c(t_min + t_max − τ)`, `τ ∈ [t_min, t_max]`.
    /// Errors: `unsupported` (`domain`) for an unbounded domain.
    pub fn reversed<const D: usize>(base: C) -> Result<Self, GeomError>
    where
        C: Curve<D>,
    {
        let (lo, hi) = base.domain();
        if !(lo.is_finite() && hi.is_finite()) {
            return Err(GeomError::Unsupported {
                field: "domain".into(),
                reason: "a curve with an unbounded domain cannot be reversed".into(),
            });
        }
        Self::trimmed(base, hi, -1.0, lo, hi)
    }

    /// The reparametrised curve `c(t_min + (τ − τ_min)(t_max − t_min)/(τ_max − τ_min))`,
    /// `τ ∈ [τ_min, τ_max]` (§1.5). Errors: `non_finite`, `empty_domain` (`domain`),
    /// `unsupported` (`domain`) for an unbounded base domain.
    #[allow(clippy::self_named_constructors)] // the §1.5 name of the derived curve
    pub fn reparametrised<const D: usize>(
        base: C,
        tau_min: f64,
        tau_max: f64,
    ) -> Result<Self, GeomError>
    where
        C: Curve<D>,
    {
        let domain = Domain::new("domain", tau_min, tau_max)?;
        let (lo, hi) = base.domain();
        if !(lo.is_finite() && hi.is_finite()) {
            return Err(GeomError::Unsupported {
                field: "domain".into(),
                reason: "a curve with an unbounded domain cannot be reparametrised".into(),
            });
        }
        Reparametrised {
            base,
            t1: lo,
            tau0: tau_min,
            num: (lo, hi),
            den: (tau_min, tau_max),
            domain,
            closed: false,
        }
        .finish()
    }

    /// The scale `s = dt/dτ` in the number system of `like` (an enclosure for intervals).
    fn scale<T: Real>(&self, like: &T) -> T {
        (like.lift(self.num.1) - like.lift(self.num.0))
            / (like.lift(self.den.1) - like.lift(self.den.0))
    }

    /// The base parameter `t(τ)` in f64 (for step hints and samples).
    pub fn base_parameter(&self, tau: f64) -> f64 {
        self.t1 + (tau - self.tau0) * ((self.num.1 - self.num.0) / (self.den.1 - self.den.0))
    }
}

impl<const D: usize, C: Curve<D>> Curve<D> for Reparametrised<C> {
    fn domain(&self) -> (f64, f64) {
        self.domain.pair()
    }
    fn is_closed(&self) -> bool {
        self.closed
    }
    fn is_periodic(&self) -> bool {
        self.closed && self.base.is_periodic()
    }
    /// A closed reparametrisation wraps its base, whose period may be rounded.
    fn domain_rounded(&self) -> bool {
        self.closed && self.base.domain_rounded()
    }
    fn jet<T: Real>(&self, tau: &T, order: usize) -> Vec<[T; D]> {
        let s = self.scale(tau);
        let t = tau.lift(self.t1) + (tau.clone() - tau.lift(self.tau0)) * &s;
        let mut jet = self.base.jet(&t, order);
        let mut factor = s.clone();
        for entry in jet.iter_mut().skip(1) {
            for x in entry.iter_mut() {
                *x = x.clone() * &factor;
            }
            factor = factor * &s;
        }
        jet
    }
    /// The base curve's breaks mapped exactly (in rationals) through `τ = τ₀ + (t − t₁)/s`
    /// and rounded outward to doubles; for a periodic base every period that meets the
    /// domain contributes.
    fn tangent_breaks(&self) -> Vec<(f64, f64)> {
        let base = self.base.tangent_breaks();
        if base.is_empty() {
            return base;
        }
        let s = (q(self.num.1) - q(self.num.0)) / (q(self.den.1) - q(self.den.0));
        let to_tau = |t: &Rational| q(self.tau0) + (t.clone() - q(self.t1)) / &s;
        let (lo, hi) = self.domain.pair();
        let (qlo, qhi) = (q(lo), q(hi));
        let (blo, bhi) = self.base.domain();
        let shifts: Vec<Rational> = if self.base.is_periodic() {
            // Base parameters reached: t(lo) … t(hi); the periods k that bring a break there.
            let period = q(bhi) - q(blo);
            let ends = [self.base_parameter(lo), self.base_parameter(hi)];
            let (a, b) = (ends[0].min(ends[1]), ends[0].max(ends[1]));
            let p = bhi - blo;
            let (k0, k1) = (((a - bhi) / p).floor() - 1.0, ((b - blo) / p).ceil() + 1.0);
            let mut k = k0;
            let mut v = Vec::new();
            while k <= k1 && v.len() < 10_000 {
                v.push(period.clone() * Rational::from_f64(k).unwrap_or_default());
                k += 1.0;
            }
            v
        } else {
            vec![Rational::new()]
        };
        let mut out = Vec::new();
        for (b_lo, b_hi) in base {
            for shift in &shifts {
                let ends = [b_lo, b_hi].map(|b| to_tau(&(q(b) + shift)));
                let (e0, e1) = if ends[0] <= ends[1] {
                    (ends[0].clone(), ends[1].clone())
                } else {
                    (ends[1].clone(), ends[0].clone())
                };
                let inside = if self.is_periodic() {
                    qlo <= e1 && e0 < qhi
                } else {
                    qlo < e1 && e0 < qhi
                };
                if inside {
                    out.push((round_down(&e0), round_up(&e1)));
                }
            }
        }
        out.sort_by(|a, b| a.0.total_cmp(&b.0));
        out
    }
    fn step_hint(&self, tau: f64) -> StepHint {
        let s = ((self.num.1 - self.num.0) / (self.den.1 - self.den.0)).abs();
        match self.base.step_hint(self.base_parameter(tau)) {
            StepHint::Whole => StepHint::Whole,
            StepHint::Angular { rate } => StepHint::Angular { rate: rate * s },
            StepHint::Adaptive { max_step } => StepHint::Adaptive {
                max_step: max_step.map(|m| m / s),
            },
        }
    }
}
