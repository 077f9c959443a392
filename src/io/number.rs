//! Numbers in the case format (docs/FORMAT.md "Numbers").
//!
//! A JSON number is parsed correctly rounded (serde_json's `float_roundtrip`) and is
//! then an exact double. Linear objects also accept a string: `"p/q"` or a decimal
//! string, which is exact and not rounded. Non-finite values cannot be written in
//! JSON; a number too large for a double is a parse error naming the field.

use serde::de::{self, Deserializer, Visitor};
use serde::ser::{Serialize, Serializer};
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

/// A double in the shortest form that reads back to the same bits, with an exponent
/// when that is shorter (`1e300`, not the 301 digits of Rust's `{}`), as in results.
pub fn shortest(x: f64) -> String {
    serde_json::Number::from_f64(x).map_or_else(|| format!("{x}"), |n| n.to_string())
}

/// The doubles of results (docs/FORMAT.md "Numbers beyond the double range"): a
/// finite double is a JSON number in shortest round-trip form; JSON has no infinity, so
/// `±∞` — the correctly rounded value of a number beyond the double range, or an
/// enclosure end with no finite double — is the string `"inf"` or `"-inf"` (never
/// `null`). NaN, which no result holds, would be `"nan"`.
pub trait Doubles {
    fn write<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error>;
}

impl Doubles for f64 {
    fn write<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        if self.is_finite() {
            s.serialize_f64(*self)
        } else if self.is_nan() {
            s.serialize_str("nan")
        } else if *self > 0.0 {
            s.serialize_str("inf")
        } else {
            s.serialize_str("-inf")
        }
    }
}

/// A borrowed value serialised through [`Doubles`].
struct AsDoubles<'a, T>(&'a T);

impl<T: Doubles> Serialize for AsDoubles<'_, T> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        self.0.write(s)
    }
}

impl<T: Doubles> Doubles for Vec<T> {
    fn write<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.collect_seq(self.iter().map(AsDoubles))
    }
}

impl<T: Doubles, const N: usize> Doubles for [T; N] {
    fn write<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.collect_seq(self.iter().map(AsDoubles))
    }
}

impl<T: Doubles> Doubles for Option<T> {
    fn write<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        match self {
            Some(v) => s.serialize_some(&AsDoubles(v)),
            None => s.serialize_none(),
        }
    }
}

/// `#[serde(serialize_with = "doubles")]` for result fields holding doubles.
pub fn doubles<T: Doubles, S: Serializer>(v: &T, s: S) -> Result<S::Ok, S::Error> {
    v.write(s)
}

/// Digits beyond which a plain decimal in a message is rewritten by [`tidy_numbers`].
const LONG_DECIMAL: usize = 24;

/// Rewrite the long plain decimals of a message (`{}` of 1e300 has 301 digits) in
/// shortest form ([`shortest`]). Rust prints a double's shortest round-trip digits
/// padded with zeros, so parsing them back gives the same double: nothing is lost.
/// Text inside double quotes is the user's own and is left alone.
pub fn tidy_numbers(message: &str) -> std::borrow::Cow<'_, str> {
    let b = message.as_bytes();
    let long = |i: usize| {
        b[i..]
            .iter()
            .take_while(|c| c.is_ascii_digit() || **c == b'.')
            .count()
            > LONG_DECIMAL
    };
    if !(0..b.len()).any(|i| b[i].is_ascii_digit() && long(i)) {
        return message.into();
    }
    let mut out = String::with_capacity(message.len());
    let (mut i, mut quoted, mut done) = (0, false, 0);
    while i < b.len() {
        let starts_number = !quoted
            && b[i].is_ascii_digit()
            && (i == 0 || !(b[i - 1].is_ascii_alphanumeric() || b[i - 1] == b'.'));
        if starts_number && long(i) {
            let negative = i > 0 && b[i - 1] == b'-';
            let start = if negative { i - 1 } else { i };
            let len = b[i..]
                .iter()
                .take_while(|c| c.is_ascii_digit() || **c == b'.')
                .count();
            let token = &message[start..i + len];
            if let Ok(v) = token.trim_end_matches('.').parse::<f64>() {
                out.push_str(&message[done..start]);
                out.push_str(&shortest(v));
                done = i + len;
            }
            i += len;
            continue;
        }
        if b[i] == b'"' && (i == 0 || b[i - 1] != b'\\') {
            quoted = !quoted;
        }
        i += 1;
    }
    out.push_str(&message[done..]);
    out.into()
}

/// A number as the user wrote it, cut short when it is very long (for messages).
pub fn abbreviate(text: &str) -> String {
    let n = text.chars().count();
    if n <= 40 {
        return text.to_string();
    }
    let head: String = text.chars().take(20).collect();
    format!("{head}… ({n} characters)")
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
    fn long_decimals_in_messages_are_shortened() {
        let huge = format!("{}", 1e300);
        let tiny = format!("{}", -1.5e-300);
        assert!(huge.len() > 300 && tiny.len() > 300);
        let m = format!("objects[0].range: the interval [{huge}, {tiny}] is empty");
        // The form of the results (serde_json's: `1e+300`).
        let (h, t) = (shortest(1e300), shortest(-1.5e-300));
        assert!(h.len() <= 6 && t.len() <= 9, "{h} {t}");
        assert_eq!(
            tidy_numbers(&m),
            format!("objects[0].range: the interval [{h}, {t}] is empty")
        );
        let m = format!("invalid type: floating point `{huge}.0`, expected u32");
        assert_eq!(
            tidy_numbers(&m),
            format!("invalid type: floating point `{h}`, expected u32")
        );
        // Short numbers, field indices and quoted user text stay as they are.
        let kept = format!("objects[12].d: \"{huge}/0\" is not a number, 0.5 and 123");
        assert_eq!(tidy_numbers(&kept), kept);
        for x in [
            1e300,
            -2.5e-300,
            0.1 + 0.2,
            123456789.0,
            f64::MAX,
            f64::MIN_POSITIVE,
        ] {
            assert_eq!(shortest(x).parse::<f64>().unwrap(), x);
            assert_eq!(tidy_numbers(&format!("{x}")).parse::<f64>().unwrap(), x);
            assert!(tidy_numbers(&format!("{x}")).len() <= 24);
        }
        assert_eq!(abbreviate("1e309"), "1e309");
        assert!(abbreviate(&"9".repeat(400)).len() < 50);
    }

    #[test]
    fn doubles_beyond_the_range_are_strings() {
        #[derive(serde::Serialize)]
        struct R {
            #[serde(serialize_with = "doubles")]
            v: Vec<[f64; 2]>,
            #[serde(serialize_with = "doubles")]
            o: Option<f64>,
        }
        let r = R {
            v: vec![[f64::MAX, f64::INFINITY], [f64::NEG_INFINITY, 0.5]],
            o: Some(f64::NEG_INFINITY),
        };
        // The finite double is written by serde_json's own float formatter (whose
        // exponent style, `e308` or `e+308`, depends on its version).
        let max = serde_json::to_string(&f64::MAX).unwrap();
        assert_eq!(
            serde_json::to_string(&r).unwrap(),
            format!(r#"{{"v":[[{max},"inf"],["-inf",0.5]],"o":"-inf"}}"#)
        );
    }

    #[test]
    fn out_of_range_numbers_are_errors() {
        assert!(serde_json::from_str::<Num>("1e400").is_err());
        assert!(serde_json::from_str::<Double>("\"1/3\"").is_err());
        assert_eq!(serde_json::from_str::<Double>("2.5").unwrap(), Double(2.5));
    }
}
