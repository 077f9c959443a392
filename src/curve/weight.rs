//! Weights of rational curves and surfaces: a subnormal positive weight is refused
//! (`degenerate_weight`, issue 20), here below `surface`, which uses it too.

use crate::error::GeomError;

/// The smallest normal double, `2⁻¹⁰²²`: positive weights below it are refused.
pub const MIN_WEIGHT: f64 = f64::MIN_POSITIVE;

/// A subnormal positive weight is refused naming `field` (`degenerate_weight`).
pub(crate) fn check_weight(field: &str, w: f64) -> Result<(), GeomError> {
    if w > 0.0 && w < MIN_WEIGHT {
        return Err(GeomError::DegenerateWeight {
            field: field.into(),
            value: format!("{w:e}"),
        });
    }
    Ok(())
}
