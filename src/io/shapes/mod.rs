//! Curved objects of the case format (docs/FORMAT.md "Objects"): specs as written,
//! parsed from JSON values with typed errors naming the field path, validated by
//! building the geometric object, and written back to JSON so that a spec survives a
//! round trip bit for bit (doubles print in shortest round-trip form).
//!
//! Curved objects take doubles only: a number written as a string (`"p/q"`) is
//! refused with an `unsupported` error naming the field.
//!
//! * [`curve`] — every curve type: [`parse_curve3`], [`parse_curve2`]; the derived
//!   curves (offset, composite, extended) in [`derived`];
//! * [`surface`] — every surface type: [`surface::parse_surface`].

pub mod curve;
mod curve_fields;
pub mod derived;
pub mod motion;
pub mod surface;

pub use curve::{curve3_from_json, parse_curve2, parse_curve3, Curve2Spec, Curve3Spec, PlaneShape};

use super::de::deserialize_at;
pub use super::de::take_type;
use crate::error::GeomError;
use serde::de::DeserializeOwned;
use serde::Serialize;
use serde_json::Value;

/// Refuse numbers written as strings anywhere in `value` (curved objects take
/// doubles): `unsupported`, naming the path of the first one.
pub fn refuse_exact_strings(value: &Value, field: &str) -> Result<(), GeomError> {
    match value {
        Value::String(s) => Err(GeomError::Unsupported {
            field: field.to_string(),
            reason: format!("{s:?}: curved objects take doubles; exact strings are accepted only by linear objects"),
        }),
        Value::Array(items) => items
            .iter()
            .enumerate()
            .try_for_each(|(i, v)| refuse_exact_strings(v, &format!("{field}[{i}]"))),
        Value::Object(map) => map.iter().try_for_each(|(k, v)| {
            let path = if field.is_empty() {
                k.clone()
            } else {
                format!("{field}.{k}")
            };
            refuse_exact_strings(v, &path)
        }),
        _ => Ok(()),
    }
}

/// Deserialize the fields of one object (its `type` already removed), refusing
/// unknown fields, naming errors below `field`; a number written as a string where the
/// parser stopped is `unsupported` (curved objects take doubles), not a format error.
pub fn parse_fields<T: DeserializeOwned>(value: Value, field: &str) -> Result<T, GeomError> {
    let has_strings = refuse_exact_strings(&value, field).is_err();
    let copy = has_strings.then(|| value.clone());
    deserialize_at(value, field).map_err(|e| {
        match copy.as_ref().map(|v| refuse_exact_strings(v, field)) {
            Some(Err(unsupported)) if unsupported.field() == e.field() && !is_unknown_field(&e) => {
                unsupported
            }
            _ => e,
        }
    })
}

fn is_unknown_field(e: &GeomError) -> bool {
    matches!(e, GeomError::Format { message, .. } if message.starts_with("unknown field"))
}

/// A spec as a JSON object with its `type`.
pub fn to_json_with_type<T: Serialize>(type_name: &str, spec: &T) -> Value {
    let mut map = serde_json::Map::new();
    map.insert("type".into(), Value::String(type_name.into()));
    if let Ok(Value::Object(fields)) = serde_json::to_value(spec) {
        map.extend(fields);
    }
    Value::Object(map)
}
