//! The `radius` of `fillet` and each of the `legs` of `chamfer` cases (docs/FORMAT.md
//! "Blends"): a number (constant), or a law of the spine's arc length
//! `{"law": "linear", "at": [[ℓ, ρ], ...]}` / `{"law": "cubic", "at": [[ℓ, ρ, ρ'], ...]}`,
//! read into [`Law`] (which checks the stations); and the law written back in results.

use super::de::deserialize_at;
use super::number::Double;
use crate::error::GeomError;
use crate::ops::fillet::Law;
use serde::Deserialize;
use serde_json::{json, Value};

#[derive(Debug, Deserialize)]
#[serde(rename_all = "snake_case")]
enum Kind {
    Linear,
    Cubic,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct RawLaw {
    law: Kind,
    at: Vec<Vec<Double>>,
}

/// The law written at `field` (`radius`, `legs[1]`); errors name the field path.
pub fn law(value: &Value, field: &str) -> Result<Law, GeomError> {
    if !value.is_object() {
        let Double(r) = deserialize_at(value.clone(), field)?;
        return Law::constant(r, field);
    }
    let raw: RawLaw = deserialize_at(value.clone(), field)?;
    let width = match raw.law {
        Kind::Linear => 2,
        Kind::Cubic => 3,
    };
    let mut rows = Vec::with_capacity(raw.at.len());
    for (i, row) in raw.at.iter().enumerate() {
        if row.len() != width {
            return Err(GeomError::CountMismatch {
                field: format!("{field}.at[{i}]"),
                expected: format!(
                    "{width} numbers ({})",
                    if width == 2 {
                        "ℓ, value"
                    } else {
                        "ℓ, value, slope"
                    }
                ),
                found: row.len().to_string(),
            });
        }
        rows.push(row.iter().map(|d| d.0).collect::<Vec<f64>>());
    }
    match raw.law {
        Kind::Linear => Law::linear(rows.iter().map(|r| [r[0], r[1]]).collect(), field),
        Kind::Cubic => Law::cubic(rows.iter().map(|r| [r[0], r[1], r[2]]).collect(), field),
    }
}

/// The law as results write it: a number for a constant, else the object it was read
/// from.
pub fn law_json(law: &Law) -> Value {
    match law {
        Law::Constant(r) => json!(r),
        Law::Linear(at) => json!({"law": "linear", "at": at}),
        Law::Cubic(at) => json!({"law": "cubic", "at": at}),
    }
}
