//! Reading JSON values into typed specs with errors that name the field path
//! (`objects[1].dir[2]`): the one place that turns serde's paths into
//! [`GeomError::Format`] fields, and reads an object's `type`.

use crate::error::GeomError;
use serde_json::Value;

/// Deserialize a JSON value, reporting errors with the field path below `prefix`.
pub fn deserialize_at<T: serde::de::DeserializeOwned>(
    value: serde_json::Value,
    prefix: &str,
) -> Result<T, GeomError> {
    serde_path_to_error::deserialize::<_, T>(value).map_err(|e| {
        let path = e.path().to_string();
        let field = match (prefix.is_empty(), path == ".") {
            (_, true) => prefix.to_string(),
            (true, false) => path,
            (false, false) if path.starts_with('[') => format!("{prefix}{path}"),
            (false, false) => format!("{prefix}.{path}"),
        };
        GeomError::Format {
            field,
            message: e.into_inner().to_string(),
        }
    })
}

/// Remove and return the `type` of an object value, naming errors `field.type`.
pub fn take_type(value: &mut Value, field: &str) -> Result<String, GeomError> {
    let type_field = if field.is_empty() {
        "type".to_string()
    } else {
        format!("{field}.type")
    };
    let Some(map) = value.as_object_mut() else {
        return Err(GeomError::Format {
            field: field.to_string(),
            message: "expected an object with a \"type\" field".into(),
        });
    };
    match map.remove("type") {
        Some(Value::String(s)) => Ok(s),
        Some(_) => Err(GeomError::Format {
            field: type_field,
            message: "expected a string".into(),
        }),
        None => Err(GeomError::Format {
            field: type_field,
            message: "missing field `type`".into(),
        }),
    }
}
