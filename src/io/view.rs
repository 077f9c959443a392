//! The `view` field of `silhouette` cases (docs/FORMAT.md "Views"): a projection of
//! OPERATIONS.md §13.6, as a name (`"isometric"`) or an object
//! (`{"type": "parallel", "direction": [1, 2, 3]}`), read into
//! [`crate::ops::view::View`]; errors name the field.

use crate::error::GeomError;
use crate::ops::view::View;
use serde_json::Value;

fn num(v: &Value, field: &str) -> Result<f64, GeomError> {
    v.as_f64().ok_or_else(|| GeomError::Format {
        field: field.into(),
        message: "expected a number".into(),
    })
}

fn vec3(obj: &serde_json::Map<String, Value>, name: &str) -> Result<[f64; 3], GeomError> {
    let field = format!("view.{name}");
    let arr = obj
        .get(name)
        .and_then(Value::as_array)
        .filter(|a| a.len() == 3)
        .ok_or_else(|| GeomError::Format {
            field: field.clone(),
            message: "expected 3 numbers".into(),
        })?;
    let mut out = [0.0; 3];
    for (i, x) in arr.iter().enumerate() {
        out[i] = num(x, &format!("{field}[{i}]"))?;
    }
    Ok(out)
}

fn named(name: &str) -> Result<View, GeomError> {
    Ok(match name {
        "frontal" => View::frontal(),
        "horizontal" => View::horizontal(),
        "profile" => View::profile(),
        "isometric" => View::isometric(),
        "dimetric" => View::dimetric(),
        "cabinet" => View::cabinet(),
        "cavalier" => View::cavalier(),
        other => {
            return Err(GeomError::Format {
                field: "view".into(),
                message: format!(
                    "unknown view {other:?} (frontal, horizontal, profile, isometric, \
                     dimetric, cabinet, cavalier, or an object: parallel, oblique, central)"
                ),
            })
        }
    })
}

/// The view of a case.
pub fn view(v: &Value) -> Result<View, GeomError> {
    if let Some(name) = v.as_str() {
        return named(name);
    }
    let obj = v.as_object().ok_or_else(|| GeomError::Format {
        field: "view".into(),
        message: "expected a view name or object".into(),
    })?;
    let kind = obj
        .get("type")
        .and_then(Value::as_str)
        .ok_or_else(|| GeomError::Format {
            field: "view.type".into(),
            message: "missing view type".into(),
        })?;
    let allowed: &[&str] = match kind {
        "parallel" => &["type", "direction"],
        "oblique" => &["type", "scale", "angle"],
        "central" => &["type", "eye", "target", "focal"],
        _ => &["type"],
    };
    if let Some(k) = obj.keys().find(|k| !allowed.contains(&k.as_str())) {
        return Err(GeomError::Format {
            field: format!("view.{k}"),
            message: format!("unknown field for a {kind} view"),
        });
    }
    match kind {
        "parallel" => View::parallel(vec3(obj, "direction")?),
        "oblique" => {
            let get = |k: &str| obj.get(k).map(|x| num(x, &format!("view.{k}"))).transpose();
            View::oblique(
                get("scale")?.unwrap_or(0.5),
                get("angle")?.unwrap_or(std::f64::consts::FRAC_PI_4),
            )
        }
        "central" => {
            let focal = obj
                .get("focal")
                .map(|x| num(x, "view.focal"))
                .transpose()?
                .unwrap_or(1.0);
            View::central(vec3(obj, "eye")?, vec3(obj, "target")?, focal)
        }
        other => named(other),
    }
}
