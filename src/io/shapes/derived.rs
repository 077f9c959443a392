//! The derived curves of the case format (extension; OPERATIONS.md §1.2, §1.5):
//! `offset_curve` (`base`, `offset` `[dx, dy, dz]`: `c + t̂ × d`), `offset_curve2`
//! (`base`, `distance`: `c + a·n`), `composite_curve` / `composite_curve2` (`pieces`,
//! joined end to end) and `extended_curve` / `extended_curve2` (`base`, `extend`
//! `[before, after]`: continued along the end tangents). `base` and `pieces[k]` are
//! curve objects of the same dimension, read by the same reader (so derived curves
//! nest); errors name the path below them (`objects[0].pieces[1].points[2]`).

use super::curve_fields::{missing, P3};
use super::parse_fields;
use crate::error::GeomError;
use serde::Deserialize;
use serde_json::{json, Value};

/// `offset_curve`: the space offset `c + t̂ × d`.
#[derive(Debug, Clone, PartialEq)]
pub struct Offset3Spec<S> {
    pub base: Box<S>,
    pub offset: P3,
}

/// `offset_curve2`: the plane offset `c + a·n` at signed distance `a`.
#[derive(Debug, Clone, PartialEq)]
pub struct Offset2Spec<S> {
    pub base: Box<S>,
    pub distance: f64,
}

/// `composite_curve` / `composite_curve2`: pieces joined end to end.
#[derive(Debug, Clone, PartialEq)]
pub struct CompositeSpec<S> {
    pub pieces: Vec<S>,
}

/// `extended_curve` / `extended_curve2`: widened by `extend = [before, after]`.
#[derive(Debug, Clone, PartialEq)]
pub struct ExtendedSpec<S> {
    pub base: Box<S>,
    pub extend: [f64; 2],
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct Offset3Fields {
    base: Option<Value>,
    offset: Option<P3>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct Offset2Fields {
    base: Option<Value>,
    distance: Option<f64>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct CompositeFields {
    pieces: Option<Vec<Value>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct ExtendedFields {
    base: Option<Value>,
    extend: Option<[f64; 2]>,
}

/// `field.name` (or `name` at the top).
fn below(field: &str, name: &str) -> String {
    if field.is_empty() {
        name.to_string()
    } else {
        format!("{field}.{name}")
    }
}

/// A required field, or `format` "missing field" naming it.
fn need<V>(v: Option<V>, field: &str, name: &str) -> Result<V, GeomError> {
    v.ok_or_else(|| missing(&below(field, name)))
}

/// The curve reader of one dimension, as the derived curves call it for their parts.
pub(super) type Reader<'a, S> = &'a dyn Fn(Value, &str) -> Result<S, GeomError>;

/// The `base` curve read below `field.base`.
fn base<S>(v: Option<Value>, field: &str, read: Reader<S>) -> Result<Box<S>, GeomError> {
    let v = need(v, field, "base")?;
    read(v, &below(field, "base")).map(Box::new)
}

/// `offset_curve`'s fields (its `type` removed).
pub(super) fn offset3<S>(
    v: Value,
    field: &str,
    read: Reader<S>,
) -> Result<Offset3Spec<S>, GeomError> {
    let f: Offset3Fields = parse_fields(v, field)?;
    let offset = need(f.offset, field, "offset")?;
    Ok(Offset3Spec {
        base: base(f.base, field, read)?,
        offset,
    })
}

/// `offset_curve2`'s fields.
pub(super) fn offset2<S>(
    v: Value,
    field: &str,
    read: Reader<S>,
) -> Result<Offset2Spec<S>, GeomError> {
    let f: Offset2Fields = parse_fields(v, field)?;
    let distance = need(f.distance, field, "distance")?;
    Ok(Offset2Spec {
        base: base(f.base, field, read)?,
        distance,
    })
}

/// `composite_curve(2)`'s fields: at least one piece (`invalid_value`, `pieces`).
pub(super) fn composite<S>(
    v: Value,
    field: &str,
    read: Reader<S>,
) -> Result<CompositeSpec<S>, GeomError> {
    let f: CompositeFields = parse_fields(v, field)?;
    let pieces = need(f.pieces, field, "pieces")?;
    if pieces.is_empty() {
        return Err(GeomError::InvalidValue {
            field: below(field, "pieces"),
            reason: "a composite curve needs at least one piece".into(),
        });
    }
    let pieces = pieces
        .into_iter()
        .enumerate()
        .map(|(k, p)| read(p, &below(field, &format!("pieces[{k}]"))))
        .collect::<Result<_, _>>()?;
    Ok(CompositeSpec { pieces })
}

/// `extended_curve(2)`'s fields.
pub(super) fn extended<S>(
    v: Value,
    field: &str,
    read: Reader<S>,
) -> Result<ExtendedSpec<S>, GeomError> {
    let f: ExtendedFields = parse_fields(v, field)?;
    let extend = need(f.extend, field, "extend")?;
    Ok(ExtendedSpec {
        base: base(f.base, field, read)?,
        extend,
    })
}

/// The built parts with their errors named below the part (`base.radius`,
/// `pieces[1].points`).
pub(super) fn build_parts<S, C>(
    parts: &[(&S, String)],
    build: impl Fn(&S) -> Result<C, GeomError>,
) -> Result<Vec<C>, GeomError> {
    parts
        .iter()
        .map(|(s, name)| build(s).map_err(|e| e.at(name)))
        .collect()
}

impl<S> CompositeSpec<S> {
    /// The pieces with their field names.
    pub(super) fn named(&self) -> Vec<(&S, String)> {
        let named = |(k, p)| (p, format!("pieces[{k}]"));
        self.pieces.iter().enumerate().map(named).collect()
    }

    pub(super) fn to_json(&self, type_name: &str, write: impl Fn(&S) -> Value) -> Value {
        let pieces: Vec<Value> = self.pieces.iter().map(write).collect();
        json!({"type": type_name, "pieces": pieces})
    }
}
