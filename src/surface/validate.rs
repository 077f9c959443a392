//! Validation of surface input with typed errors naming the field
//! (ARCHITECTURE.md "Errors and bad input"): radii, parameter intervals, domain
//! restrictions and knot vectors.

use crate::error::{require_finite, GeomError};

/// A parameter rectangle `([u_min, u_max], [v_min, v_max])`.
pub type Domain = ([f64; 2], [f64; 2]);

/// `2π` rounded to the nearest double (below the true `2π` by about `2.4e-16`): the
/// upper end of an angular parameter's natural domain.
pub const TAU: f64 = std::f64::consts::TAU;

/// The natural domain `[0, 2π]` of an angular parameter.
pub const FULL_TURN: [f64; 2] = [0.0, TAU];

/// A finite, strictly positive number (a radius, a semi-axis, a weight).
pub fn positive(field: &str, value: f64) -> Result<f64, GeomError> {
    require_finite(field, value)?;
    if value > 0.0 {
        Ok(value)
    } else {
        Err(GeomError::InvalidValue {
            field: field.into(),
            reason: format!("{value} must be positive"),
        })
    }
}

/// A finite, non-negative number.
pub fn non_negative(field: &str, value: f64) -> Result<f64, GeomError> {
    require_finite(field, value)?;
    if value >= 0.0 {
        Ok(value)
    } else {
        Err(GeomError::InvalidValue {
            field: field.into(),
            reason: format!("{value} must not be negative"),
        })
    }
}

/// A finite parameter interval `[lo, hi]` with `lo < hi`.
pub fn interval(field: &str, range: [f64; 2]) -> Result<[f64; 2], GeomError> {
    require_finite(&format!("{field}[0]"), range[0])?;
    require_finite(&format!("{field}[1]"), range[1])?;
    if range[0] < range[1] {
        Ok(range)
    } else {
        Err(GeomError::EmptyDomain {
            field: field.into(),
            lo: format!("{}", range[0]),
            hi: format!("{}", range[1]),
        })
    }
}

/// `requested` (a finite, non-empty interval inside `natural`), or `natural`.
pub fn restrict(
    field: &str,
    natural: [f64; 2],
    requested: Option<[f64; 2]>,
) -> Result<[f64; 2], GeomError> {
    let Some(r) = requested else {
        return Ok(natural);
    };
    let r = interval(field, r)?;
    for (i, &x) in r.iter().enumerate() {
        if x < natural[0] || x > natural[1] {
            return Err(GeomError::ParameterOutsideDomain {
                field: format!("{field}[{i}]"),
                value: format!("{x}"),
                lo: format!("{}", natural[0]),
                hi: format!("{}", natural[1]),
            });
        }
    }
    Ok(r)
}

/// [`restrict`] for both directions, naming `domain[0]` / `domain[1]`.
pub fn restrict_domain(natural: Domain, requested: Option<Domain>) -> Result<Domain, GeomError> {
    Ok((
        restrict("domain[0]", natural.0, requested.map(|d| d.0))?,
        restrict("domain[1]", natural.1, requested.map(|d| d.1))?,
    ))
}

/// A B-spline knot vector for `count` control points of degree `degree ≥ 1`
/// (OPERATIONS.md §1.5, (1.11)): `count ≥ degree + 1`, `count + degree + 1` finite,
/// non-decreasing knots, every multiplicity at most `degree + 1`, and a non-empty domain
/// `[knots[degree], knots[count]]` (0-based). Returns that domain.
pub fn knot_vector(
    field: &str,
    knots: &[f64],
    count: usize,
    degree: usize,
) -> Result<[f64; 2], GeomError> {
    let expected = count + degree + 1;
    if knots.len() != expected {
        return Err(GeomError::CountMismatch {
            field: field.into(),
            expected: format!("{expected} knots (control points + degree + 1)"),
            found: format!("{}", knots.len()),
        });
    }
    for (i, &k) in knots.iter().enumerate() {
        require_finite(&format!("{field}[{i}]"), k)?;
    }
    let mut run = 1;
    for i in 1..knots.len() {
        if knots[i] < knots[i - 1] {
            return Err(GeomError::InvalidKnots {
                field: field.into(),
                reason: format!(
                    "knots must be non-decreasing: [{}] = {} > [{i}] = {}",
                    i - 1,
                    knots[i - 1],
                    knots[i]
                ),
            });
        }
        run = if knots[i] == knots[i - 1] { run + 1 } else { 1 };
        if run > degree + 1 {
            return Err(GeomError::InvalidKnots {
                field: field.into(),
                reason: format!(
                    "knot {} has multiplicity above degree + 1 = {}",
                    knots[i],
                    degree + 1
                ),
            });
        }
    }
    let (lo, hi) = (knots[degree], knots[count]);
    if lo < hi {
        Ok([lo, hi])
    } else {
        Err(GeomError::EmptyDomain {
            field: field.into(),
            lo: format!("{lo}"),
            hi: format!("{hi}"),
        })
    }
}

/// A degree of at least 1.
pub fn degree(field: &str, degree: usize) -> Result<usize, GeomError> {
    if degree >= 1 {
        Ok(degree)
    } else {
        Err(GeomError::InvalidValue {
            field: field.into(),
            reason: "the degree must be at least 1".into(),
        })
    }
}
