//! Typed errors for bad input (ARCHITECTURE.md "Errors and bad input").
//!
//! Every kind names the offending field, as a path such as `objects[1].dir`.
//! Constructors name their own fields (`dir`); callers that know more context
//! prefix it with [`GeomError::at`]. Huge or tiny magnitudes are never an error.

use thiserror::Error;

/// Why an input was rejected. `kind()` is the stable name used in JSON.
#[derive(Debug, Clone, PartialEq, Eq, Error)]
pub enum GeomError {
    /// The text of the case is not valid JSON, or does not fit the case format
    /// (unknown field, missing field, wrong type). `message` comes from the parser
    /// and names the field.
    #[error("{field}: {message}")]
    Format { field: String, message: String },
    /// NaN, an infinity, or a number that is out of the f64 range.
    #[error("{field}: {value} is not a finite number")]
    NonFinite { field: String, value: String },
    /// A string that should hold an exact number (`"p/q"` or a decimal) does not.
    #[error("{field}: {text:?} is not a number (expected a double, \"p/q\" or a decimal string)")]
    InvalidNumber { field: String, text: String },
    /// A direction vector that is exactly zero.
    #[error("{field}: the direction is the zero vector")]
    ZeroDirection { field: String },
    /// The two spanning vectors of a parametric plane are exactly collinear.
    #[error("{field}: the plane's vectors u and v are collinear (u × v = 0)")]
    CollinearPlaneVectors { field: String },
    /// The normal of an implicit plane is exactly zero.
    #[error("{field}: the normal is the zero vector")]
    ZeroNormal { field: String },
    /// A knot vector that is too short/long or not non-decreasing, or a knot
    /// multiplicity above degree + 1.
    #[error("{field}: invalid knot vector: {reason}")]
    InvalidKnots { field: String, reason: String },
    /// A rational weight that is zero or negative.
    #[error("{field}: weight {value} is not positive")]
    NonPositiveWeight { field: String, value: String },
    /// Counts that must agree do not (control points vs degree, weights vs points).
    #[error("{field}: expected {expected}, found {found}")]
    CountMismatch {
        field: String,
        expected: String,
        found: String,
    },
    /// A parameter interval `[lo, hi]` that is empty or inverted.
    #[error("{field}: the interval [{lo}, {hi}] is empty or inverted")]
    EmptyDomain {
        field: String,
        lo: String,
        hi: String,
    },
    /// A parameter value outside the object's domain.
    #[error("{field}: parameter {value} is outside the domain [{lo}, {hi}]")]
    ParameterOutsideDomain {
        field: String,
        value: String,
        lo: String,
        hi: String,
    },
    /// A value that is finite but not allowed (a zero radius, a negative degree, ...).
    #[error("{field}: {reason}")]
    InvalidValue { field: String, reason: String },
    /// The operation is not defined for these objects (yet).
    #[error("{field}: {reason}")]
    Unsupported { field: String, reason: String },
    /// A blend that does not exist as asked (OPERATIONS.md §11.4 degenerate cases):
    /// the faces are tangent across the edge, or the radius exceeds a face's radius of
    /// curvature on the side of the blend.
    #[error("{field}: {reason}")]
    DegenerateBlend { field: String, reason: String },
    /// A patch whose control net does not span a surface: every control point equal
    /// (collapsed), all on one line, or the patch independent of one parameter (every
    /// row or every column of the net the same): its normal vanishes everywhere.
    #[error("{field}: {reason}")]
    DegenerateSurface { field: String, reason: String },
    /// A positive weight that is subnormal (below 2⁻¹⁰²² ≈ 2.2·10⁻³⁰⁸): the rational
    /// form divides by it and its reciprocal overflows.
    #[error("{field}: weight {value} is subnormal (below 2.2e-308)")]
    DegenerateWeight { field: String, value: String },
}

impl GeomError {
    /// The stable, snake_case name of the error kind, as written in JSON results.
    pub fn kind(&self) -> &'static str {
        match self {
            GeomError::Format { .. } => "format",
            GeomError::NonFinite { .. } => "non_finite",
            GeomError::InvalidNumber { .. } => "invalid_number",
            GeomError::ZeroDirection { .. } => "zero_direction",
            GeomError::CollinearPlaneVectors { .. } => "collinear_plane_vectors",
            GeomError::ZeroNormal { .. } => "zero_normal",
            GeomError::InvalidKnots { .. } => "invalid_knots",
            GeomError::NonPositiveWeight { .. } => "non_positive_weight",
            GeomError::CountMismatch { .. } => "count_mismatch",
            GeomError::EmptyDomain { .. } => "empty_domain",
            GeomError::ParameterOutsideDomain { .. } => "parameter_outside_domain",
            GeomError::InvalidValue { .. } => "invalid_value",
            GeomError::Unsupported { .. } => "unsupported",
            GeomError::DegenerateBlend { .. } => "degenerate_blend",
            GeomError::DegenerateSurface { .. } => "degenerate_surface",
            GeomError::DegenerateWeight { .. } => "degenerate_weight",
        }
    }

    /// The path of the offending field.
    pub fn field(&self) -> &str {
        match self {
            GeomError::Format { field, .. }
            | GeomError::NonFinite { field, .. }
            | GeomError::InvalidNumber { field, .. }
            | GeomError::ZeroDirection { field }
            | GeomError::CollinearPlaneVectors { field }
            | GeomError::ZeroNormal { field }
            | GeomError::InvalidKnots { field, .. }
            | GeomError::NonPositiveWeight { field, .. }
            | GeomError::CountMismatch { field, .. }
            | GeomError::EmptyDomain { field, .. }
            | GeomError::ParameterOutsideDomain { field, .. }
            | GeomError::InvalidValue { field, .. }
            | GeomError::Unsupported { field, .. }
            | GeomError::DegenerateBlend { field, .. }
            | GeomError::DegenerateSurface { field, .. }
            | GeomError::DegenerateWeight { field, .. } => field,
        }
    }

    fn field_mut(&mut self) -> &mut String {
        match self {
            GeomError::Format { field, .. }
            | GeomError::NonFinite { field, .. }
            | GeomError::InvalidNumber { field, .. }
            | GeomError::ZeroDirection { field }
            | GeomError::CollinearPlaneVectors { field }
            | GeomError::ZeroNormal { field }
            | GeomError::InvalidKnots { field, .. }
            | GeomError::NonPositiveWeight { field, .. }
            | GeomError::CountMismatch { field, .. }
            | GeomError::EmptyDomain { field, .. }
            | GeomError::ParameterOutsideDomain { field, .. }
            | GeomError::InvalidValue { field, .. }
            | GeomError::Unsupported { field, .. }
            | GeomError::DegenerateBlend { field, .. }
            | GeomError::DegenerateSurface { field, .. }
            | GeomError::DegenerateWeight { field, .. } => field,
        }
    }

    /// Replace the leading path `from` of the field by `to` (an operation built on
    /// another one names the caller's fields: `objects[1].range` → `direction.range`);
    /// other fields are kept.
    pub fn renamed(mut self, from: &str, to: &str) -> Self {
        let field = self.field_mut();
        if let Some(rest) = field.strip_prefix(from) {
            *field = format!("{to}{rest}");
        }
        self
    }

    /// Prefix the field path with the context the caller knows:
    /// `GeomError::ZeroDirection{field:"dir"}.at("objects[1]")` names `objects[1].dir`.
    pub fn at(mut self, prefix: &str) -> Self {
        let field = self.field_mut();
        *field = if field.is_empty() {
            prefix.to_string()
        } else if field.starts_with('[') {
            format!("{prefix}{field}")
        } else {
            format!("{prefix}.{field}")
        };
        self
    }
}

/// Reject NaN and infinities, naming the field. Used by every constructor.
pub fn require_finite(field: &str, value: f64) -> Result<f64, GeomError> {
    if value.is_finite() {
        Ok(value)
    } else {
        Err(GeomError::NonFinite {
            field: field.to_string(),
            value: format!("{value}"),
        })
    }
}

/// [`require_finite`] for every component of a vector, naming `field[i]`.
pub fn require_finite_all(field: &str, values: &[f64]) -> Result<(), GeomError> {
    // The common case builds no field names (this runs on every constructor call).
    if values.iter().all(|v| v.is_finite()) {
        return Ok(());
    }
    for (i, &v) in values.iter().enumerate() {
        require_finite(&format!("{field}[{i}]"), v)?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn at_builds_field_paths() {
        let e = GeomError::ZeroDirection {
            field: "dir".into(),
        }
        .at("objects[1]");
        assert_eq!(e.field(), "objects[1].dir");
        let e = GeomError::ZeroDirection {
            field: "[2]".into(),
        }
        .at("points");
        assert_eq!(e.field(), "points[2]");
        assert_eq!(e.kind(), "zero_direction");
    }

    #[test]
    fn non_finite_names_the_component() {
        let e = require_finite_all("origin", &[0.0, f64::NAN, 1.0]).unwrap_err();
        assert_eq!(e.field(), "origin[1]");
        assert_eq!(e.kind(), "non_finite");
        assert!(require_finite("x", f64::INFINITY).is_err());
        assert_eq!(require_finite("x", -0.0), Ok(-0.0));
    }
}
