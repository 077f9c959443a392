//! Numbers in the case format (docs/FORMAT.md "Numbers").
//!
//! A JSON number is parsed correctly rounded (serde_json's `float_roundtrip`) and is
//! then an exact double. Linear objects also accept a string: `"p/q"` or a decimal
//! string, which is exact and not rounded. Non-finite values cannot be written in
//! JSON; a number too large for a double is a parse error naming the field.

use serde::de::{self, Deserializer, Visitor};
use serde::Deserialize;
use std::fmt;

/// One number of a case, as written: a double, or an exact string.
#[derive(Debug, Clone, PartialEq)]
pub enum Num {
    /// A JSON number, correctly rounded to a double (exact from then on).
    Double(f64),
    /// A string holding an exact number, `"p/q"` or a decimal; parsed by the consumer.
    Text(String),
}

impl Num {
    /// The double, if this number was written as a JSON number.
    pub fn as_double(&self) -> Option<f64> {
        match self {
            Num::Double(v) => Some(*v),
            Num::Text(_) => None,
        }
    }
}

impl<'de> Deserialize<'de> for Num {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        struct NumVisitor;
        impl Visitor<'_> for NumVisitor {
            type Value = Num;
            fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
                f.write_str("a number, or a string holding \"p/q\" or a decimal")
            }
            fn visit_f64<E: de::Error>(self, v: f64) -> Result<Num, E> {
                if v.is_finite() {
                    Ok(Num::Double(v))
                } else {
                    Err(E::custom(format!("{v} is not a finite number")))
                }
            }
            fn visit_u64<E: de::Error>(self, v: u64) -> Result<Num, E> {
                if v < (1u64 << 53) {
                    Ok(Num::Double(v as f64))
                } else {
                    // An integer literal with more than 53 significant bits is exact text.
                    Ok(Num::Text(v.to_string()))
                }
            }
            fn visit_i64<E: de::Error>(self, v: i64) -> Result<Num, E> {
                if v.unsigned_abs() < (1u64 << 53) {
                    Ok(Num::Double(v as f64))
                } else {
                    Ok(Num::Text(v.to_string()))
                }
            }
            fn visit_str<E: de::Error>(self, v: &str) -> Result<Num, E> {
                Ok(Num::Text(v.to_string()))
            }
        }
        deserializer.deserialize_any(NumVisitor)
    }
}

/// A number that must be a double (curved objects, tolerances): strings are refused.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Double(pub f64);

impl<'de> Deserialize<'de> for Double {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        match Num::deserialize(deserializer)? {
            Num::Double(v) => Ok(Double(v)),
            Num::Text(t) => match t.parse::<f64>() {
                // An integer written with more than 53 bits: round it like a JSON number.
                Ok(v) if v.is_finite() && t.bytes().all(|b| b.is_ascii_digit() || b == b'-') => {
                    Ok(Double(v))
                }
                _ => Err(de::Error::custom(format!(
                    "{t:?}: exact strings are accepted only by linear objects; write a number"
                ))),
            },
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_parse_correctly_rounded() {
        let v: Vec<Num> = serde_json::from_str(r#"[0.1, 1, -3, "1/3", 9007199254740993]"#).unwrap();
        assert_eq!(v[0], Num::Double(0.1));
        assert_eq!(v[1], Num::Double(1.0));
        assert_eq!(v[2], Num::Double(-3.0));
        assert_eq!(v[3], Num::Text("1/3".into()));
        // 2^53 + 1 is not a double: kept exact as text.
        assert_eq!(v[4], Num::Text("9007199254740993".into()));
        // The shortest round-trip form of a double reads back to the same bits.
        let x = 0.1f64 + 0.2;
        let back: Num = serde_json::from_str(&serde_json::to_string(&x).unwrap()).unwrap();
        assert_eq!(back.as_double().map(f64::to_bits), Some(x.to_bits()));
    }

    #[test]
    fn out_of_range_numbers_are_errors() {
        assert!(serde_json::from_str::<Num>("1e400").is_err());
        assert!(serde_json::from_str::<Double>("\"1/3\"").is_err());
        assert_eq!(serde_json::from_str::<Double>("2.5").unwrap(), Double(2.5));
    }
}
