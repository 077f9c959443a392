//! Radius and leg laws along the spine (OPERATIONS.md §11.3 variable radius, §11.5
//! (11.11) variable legs): a function `ρ(ℓ)` of the arc length `ℓ` of the edge, given
//! by the caller as stations `(ℓᵢ, ρᵢ)` with strictly increasing `ℓᵢ`:
//!
//! * [`Law::Constant`]: `ρ(ℓ) = ρ` (the constant-radius fillet of §11.2);
//! * [`Law::Linear`]: piecewise linear through the stations (continuous; the surface
//!   is C⁰ across a station where the slope changes, G1 with the faces everywhere);
//! * [`Law::Cubic`]: piecewise cubic Hermite through `(ℓᵢ, ρᵢ)` with the given slopes
//!   `ρ'ᵢ` (C¹).
//!
//! The formula is written once over [`Real`] ([`Law::at`]); a piece is evaluated in
//! Bernstein form over `s = (ℓ − ℓᵢ)/(ℓᵢ₊₁ − ℓᵢ)`, every constant lifted exactly and
//! every step an enclosing operation, so an interval `ℓ` gives an enclosure of the law
//! over it; an interval straddling stations is split into the pieces it touches and
//! the results are joined by hulls ([`piecewise_jet`]). [`Law::prove_positive`]
//! proves `ρ > 0` over a range by that enclosure over a cover of it.
//!
//! It sits beside [`crate::ops::fillet`](mod@crate::ops::fillet) (re-exported there as `fillet::Law`) because
//! the answer of a blend ([`crate::ops::answer::BlendKind`]) carries it.

use crate::curve::domain::piecewise_jet;
use crate::error::GeomError;
use crate::num::{Interval, Real};

/// A law `ρ(ℓ)` (module doc).
#[derive(Debug, Clone, PartialEq)]
pub enum Law {
    Constant(f64),
    /// Stations `[ℓᵢ, ρᵢ]`.
    Linear(Vec<[f64; 2]>),
    /// Stations `[ℓᵢ, ρᵢ, ρ'ᵢ]`.
    Cubic(Vec<[f64; 3]>),
}

fn invalid(field: String, reason: String) -> GeomError {
    GeomError::InvalidValue { field, reason }
}

/// The station abscissae: at least two, finite, strictly increasing; every value
/// finite, the radii positive (`field` names the law: `radius`, `legs[1]`).
fn check_stations<const N: usize>(at: &[[f64; N]], field: &str) -> Result<(), GeomError> {
    if at.len() < 2 {
        return Err(GeomError::CountMismatch {
            field: format!("{field}.at"),
            expected: "at least 2 stations".into(),
            found: at.len().to_string(),
        });
    }
    for (i, row) in at.iter().enumerate() {
        for (j, x) in row.iter().enumerate() {
            if !x.is_finite() {
                return Err(invalid(
                    format!("{field}.at[{i}][{j}]"),
                    format!("must be a finite number, found {x}"),
                ));
            }
        }
        if row[1] <= 0.0 {
            return Err(invalid(
                format!("{field}.at[{i}][1]"),
                format!("the value of the law must be positive, found {}", row[1]),
            ));
        }
        if i > 0 && row[0] <= at[i - 1][0] {
            return Err(invalid(
                format!("{field}.at[{i}][0]"),
                format!(
                    "the stations' arc lengths must increase strictly: {} follows {}",
                    row[0],
                    at[i - 1][0]
                ),
            ));
        }
    }
    Ok(())
}

impl Law {
    /// A constant law; errors: `ρ` not a positive finite number (field `field`).
    pub fn constant(rho: f64, field: &str) -> Result<Law, GeomError> {
        if rho.is_finite() && rho > 0.0 {
            Ok(Law::Constant(rho))
        } else {
            Err(invalid(
                field.into(),
                format!("must be a positive finite number, found {rho}"),
            ))
        }
    }

    /// A piecewise linear law through `at` (errors name `field.at[i][j]`).
    pub fn linear(at: Vec<[f64; 2]>, field: &str) -> Result<Law, GeomError> {
        check_stations(&at, field)?;
        Ok(Law::Linear(at))
    }

    /// A cubic Hermite law through `at` = `[ℓᵢ, ρᵢ, ρ'ᵢ]` (errors name
    /// `field.at[i][j]`); its positivity between the stations is proven by
    /// [`Law::prove_positive`] over the range used.
    pub fn cubic(at: Vec<[f64; 3]>, field: &str) -> Result<Law, GeomError> {
        check_stations(&at, field)?;
        Ok(Law::Cubic(at))
    }

    /// The arc-length span `[ℓ₀, ℓₙ]` of the stations (`None` for a constant).
    pub fn span(&self) -> Option<[f64; 2]> {
        let ends = |first: f64, last: f64| Some([first, last]);
        match self {
            Law::Constant(_) => None,
            Law::Linear(at) => ends(at[0][0], at[at.len() - 1][0]),
            Law::Cubic(at) => ends(at[0][0], at[at.len() - 1][0]),
        }
    }

    /// The constant value, if the law is constant.
    pub fn as_constant(&self) -> Option<f64> {
        match self {
            Law::Constant(r) => Some(*r),
            _ => None,
        }
    }

    /// `ρ(ℓ)` (module doc); outside the span the end pieces continue as polynomials.
    pub fn at<T: Real>(&self, l: &T) -> T {
        match self {
            Law::Constant(r) => l.lift(*r),
            Law::Linear(at) => {
                let breaks: Vec<f64> = at.iter().map(|p| p[0]).collect();
                let [value] = piecewise_jet(l, &breaks, |i, li| {
                    let ([l0, r0], [l1, r1]) = (at[i], at[i + 1]);
                    let s = bernstein_s(li, l0, l1);
                    let y = li.one_like() - &s;
                    vec![[y * li.lift(r0) + s * li.lift(r1)]]
                })
                .remove(0);
                value
            }
            Law::Cubic(at) => {
                let breaks: Vec<f64> = at.iter().map(|p| p[0]).collect();
                let [value] = piecewise_jet(l, &breaks, |i, li| {
                    let ([l0, r0, d0], [l1, r1, d1]) = (at[i], at[i + 1]);
                    let h = li.lift(l1) - li.lift(l0);
                    let three = li.lift(3.0);
                    // Bernstein coefficients of the Hermite cubic
                    let b = [
                        li.lift(r0),
                        li.lift(r0) + h.clone() * li.lift(d0) / &three,
                        li.lift(r1) - h * li.lift(d1) / &three,
                        li.lift(r1),
                    ];
                    let s = bernstein_s(li, l0, l1);
                    let y = li.one_like() - &s;
                    let value = y.powi(3) * &b[0]
                        + three.clone() * &s * &y.sqr() * &b[1]
                        + three * &s.sqr() * &y * &b[2]
                        + s.powi(3) * &b[3];
                    vec![[value]]
                })
                .remove(0);
                value
            }
        }
    }

    /// Prove `ρ(ℓ) > 0` for every `ℓ` of `range` by f64-interval enclosures of
    /// [`Law::at`] over a cover of it (bisected where undecided, down to a width
    /// floor). Errors (field `field`): a box where the law is proven `≤ 0`, or one
    /// where positivity could not be decided (the law touches zero, or nearly).
    /// A constant law needs no range (a positive finite number); a variable law
    /// without a range proves nothing and is refused.
    pub fn prove_positive(&self, range: Option<[f64; 2]>, field: &str) -> Result<(), GeomError> {
        if let Law::Constant(r) = self {
            return Law::constant(*r, field).map(|_| ());
        }
        let Some(range) = range else {
            return Err(invalid(
                field.into(),
                "a variable law needs the spine's range".into(),
            ));
        };
        let floor = (range[1] - range[0]).abs() * 1e-12;
        let mut stack = vec![range];
        let mut budget = 100_000;
        while let Some([a, b]) = stack.pop() {
            let (lo, hi) = self.at(&Interval::from_bounds(a, b)).bounds();
            if lo > 0.0 {
                continue;
            }
            budget -= 1;
            if hi <= 0.0 || b - a <= floor || budget == 0 {
                let mid = 0.5 * (a + b);
                let proven = hi <= 0.0;
                return Err(invalid(
                    field.into(),
                    format!(
                        "the law must be positive over the range; it is {} near ℓ = {mid} \
                         (value ≈ {})",
                        if proven {
                            "≤ 0"
                        } else {
                            "not proven positive"
                        },
                        self.at(&mid)
                    ),
                ));
            }
            let mid = 0.5 * (a + b);
            stack.push([mid, b]);
            stack.push([a, mid]);
        }
        Ok(())
    }
}

/// `s = (ℓ − ℓ₀)/(ℓ₁ − ℓ₀)`, enclosed (the difference `ℓ₁ − ℓ₀` computed in `T`).
fn bernstein_s<T: Real>(l: &T, l0: f64, l1: f64) -> T {
    (l.clone() - l.lift(l0)) / (l.lift(l1) - l.lift(l0))
}
