//! Parsing one case's JSON text strictly (spec/CASES.md "Cases": a typo must not
//! silently change a query): a key written twice in one object is an error naming
//! the key's path, where serde_json's own `Value` would keep the last one. The raw
//! text of the top-level `id` is kept too, so a numeric id is echoed exactly as
//! written (`18446744073709551616`, `1.50`) although serde_json reads it as a double.

use serde::de::{self, DeserializeSeed, MapAccess, SeqAccess, Visitor};
use serde_json::map::Entry;
use serde_json::value::RawValue;
use serde_json::{Map, Value};
use std::cell::RefCell;
use std::fmt;

/// Why a case's text did not parse.
#[derive(Debug)]
pub enum StrictError {
    /// A key written twice: the path of the second one and the message.
    Duplicate { field: String, message: String },
    /// Not JSON (serde_json's error, with its line and column in the text).
    Syntax(serde_json::Error),
}

/// A parsed case: its JSON value and the raw text of its top-level `id`, if any.
#[derive(Debug)]
pub struct Parsed {
    pub value: Value,
    pub raw_id: Option<Box<RawValue>>,
}

/// Parse `text` as one JSON value, refusing duplicate keys (see the module docs).
pub fn parse_strict(text: &str) -> Result<Parsed, StrictError> {
    let duplicate = RefCell::new(None);
    let raw_id = RefCell::new(None);
    let mut de = serde_json::Deserializer::from_str(text);
    let seed = Seed {
        path: None,
        duplicate: &duplicate,
        raw_id: Some(&raw_id),
    };
    let value = seed.deserialize(&mut de).and_then(|v| de.end().map(|()| v));
    match (value, duplicate.into_inner()) {
        (_, Some((field, message))) => Err(StrictError::Duplicate { field, message }),
        (Ok(value), None) => Ok(Parsed {
            value,
            raw_id: raw_id.into_inner(),
        }),
        (Err(e), None) => Err(StrictError::Syntax(e)),
    }
}

/// One step of the path from the case down to a value (kept on the stack).
enum Step<'a> {
    Key(&'a str),
    Index(usize),
}

struct PathNode<'a> {
    parent: Option<&'a PathNode<'a>>,
    step: Step<'a>,
}

impl PathNode<'_> {
    fn text(&self) -> String {
        let mut s = self.parent.map_or_else(String::new, PathNode::text);
        match self.step {
            Step::Key(k) if s.is_empty() => s.push_str(k),
            Step::Key(k) => {
                s.push('.');
                s.push_str(k);
            }
            Step::Index(i) => s.push_str(&format!("[{i}]")),
        }
        s
    }
}

type Duplicate = RefCell<Option<(String, String)>>;

#[derive(Clone, Copy)]
struct Seed<'p, 'c> {
    path: Option<&'p PathNode<'p>>,
    duplicate: &'c Duplicate,
    /// Set only at the top level: where the raw text of `id` goes.
    raw_id: Option<&'c RefCell<Option<Box<RawValue>>>>,
}

impl<'de> DeserializeSeed<'de> for Seed<'_, '_> {
    type Value = Value;
    fn deserialize<D: de::Deserializer<'de>>(self, d: D) -> Result<Value, D::Error> {
        d.deserialize_any(self)
    }
}

impl<'de> Visitor<'de> for Seed<'_, '_> {
    type Value = Value;

    fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
        f.write_str("a JSON value")
    }
    fn visit_bool<E>(self, v: bool) -> Result<Value, E> {
        Ok(Value::Bool(v))
    }
    fn visit_i64<E>(self, v: i64) -> Result<Value, E> {
        Ok(Value::from(v))
    }
    fn visit_u64<E>(self, v: u64) -> Result<Value, E> {
        Ok(Value::from(v))
    }
    fn visit_f64<E>(self, v: f64) -> Result<Value, E> {
        // serde_json never hands a non-finite double to a visitor (it refuses 1e309).
        Ok(serde_json::Number::from_f64(v).map_or(Value::Null, Value::Number))
    }
    fn visit_str<E>(self, v: &str) -> Result<Value, E> {
        Ok(Value::String(v.to_owned()))
    }
    fn visit_string<E>(self, v: String) -> Result<Value, E> {
        Ok(Value::String(v))
    }
    fn visit_unit<E>(self) -> Result<Value, E> {
        Ok(Value::Null)
    }

    fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<Value, A::Error> {
        let mut out = Vec::new();
        loop {
            let node = PathNode {
                parent: self.path,
                step: Step::Index(out.len()),
            };
            let seed = Seed {
                path: Some(&node),
                raw_id: None,
                ..self
            };
            match seq.next_element_seed(seed)? {
                Some(v) => out.push(v),
                None => return Ok(Value::Array(out)),
            }
        }
    }

    fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<Value, A::Error> {
        let mut out = Map::new();
        while let Some(key) = map.next_key::<String>()? {
            // One look-up per key: the entry says whether the key came before.
            let slot = match out.entry(key) {
                Entry::Vacant(slot) => slot,
                Entry::Occupied(old) => {
                    let node = PathNode {
                        parent: self.path,
                        step: Step::Key(old.key()),
                    };
                    let message = format!("duplicate key `{}`", old.key());
                    *self.duplicate.borrow_mut() = Some((node.text(), message.clone()));
                    return Err(de::Error::custom(message));
                }
            };
            let value = match self.raw_id {
                Some(raw_slot) if slot.key() == "id" => {
                    let raw: Box<RawValue> = map.next_value()?;
                    let value = serde_json::from_str(raw.get()).map_err(de::Error::custom)?;
                    *raw_slot.borrow_mut() = Some(raw);
                    value
                }
                _ => {
                    let node = PathNode {
                        parent: self.path,
                        step: Step::Key(slot.key()),
                    };
                    map.next_value_seed(Seed {
                        path: Some(&node),
                        raw_id: None,
                        ..self
                    })?
                }
            };
            slot.insert(value);
        }
        Ok(Value::Object(out))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn duplicate_keys_are_named_by_path() {
        let dup = |t: &str| match parse_strict(t) {
            Err(StrictError::Duplicate { field, message }) => (field, message),
            other => panic!("{t}: {other:?}"),
        };
        assert_eq!(dup(r#"{"op": "a", "op": "b"}"#).0, "op");
        assert_eq!(
            dup(r#"{"objects": [{}, {"type": "plane", "d": 1, "d": 2}]}"#),
            ("objects[1].d".into(), "duplicate key `d`".into())
        );
        assert_eq!(dup(r#"{"id": 1, "id": 2}"#).0, "id");
        assert_eq!(
            dup(r#"{"options": {"x": {"y": 1, "y": 1}}}"#).0,
            "options.x.y"
        );
    }

    #[test]
    fn values_and_raw_ids_as_written() {
        let text = r#"{"id": 18446744073709551616, "a": [1, -2, 0.5, "s", null, true, {"b": []}]}"#;
        let p = parse_strict(text).unwrap();
        assert_eq!(p.raw_id.unwrap().get(), "18446744073709551616");
        assert_eq!(
            p.value["a"],
            serde_json::json!([1, -2, 0.5, "s", null, true, {"b": []}])
        );
        assert_eq!(
            p.value,
            serde_json::from_str::<Value>(text).unwrap(),
            "the same value serde_json builds"
        );
        assert!(matches!(parse_strict("{} x"), Err(StrictError::Syntax(_))));
        assert!(matches!(
            parse_strict("[1, NaN]"),
            Err(StrictError::Syntax(_))
        ));
    }
}
