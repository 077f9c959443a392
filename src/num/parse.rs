//! Exact numbers from text and from doubles (docs/FORMAT.md "Numbers": a string `"p/q"` or a
//! decimal string is accepted wherever a linear object takes a number, and is exact).
//!
//! Accepted forms: an integer fraction `[+-]digits/digits` (non-zero denominator), or a
//! decimal `[+-]digits[.digits][(e|E)[+-]digits]` (also `.5` and `5.`). The decimal
//! exponent is limited to ±100000 so that a short string cannot ask for gigabytes; such
//! a string is rejected as `invalid_number`.
//!
//! Size caps (issue 20, docs/FORMAT.md "Numbers"): a string holds at most
//! [`MAX_EXACT_DIGITS`] digits, and the numerator and denominator of its value at most
//! [`MAX_EXACT_BITS`] bits each (so `1e-5000`, short as it is, is refused): the exact
//! curved paths cost a power of the bit length (a line of 100 000-digit coordinates
//! against a sphere or torus took seconds to minutes). Beyond them the number is an
//! `invalid_value` error naming the field, whose message gives the size, not the digits.

use rug::{Integer, Rational};

use crate::error::GeomError;

/// The largest decimal exponent accepted in a number string.
pub const MAX_DECIMAL_EXPONENT: i64 = 100_000;

/// The most digits a number string may hold (all digits, with those of a fraction's
/// denominator and of the exponent).
pub const MAX_EXACT_DIGITS: usize = 4000;

/// The most bits of the numerator and of the denominator of an exact number from text.
pub const MAX_EXACT_BITS: u32 = 16_384;

/// Parse an exact number string into a rational; the error names `field`: a malformed
/// string is `invalid_number`, one beyond the size caps (module doc) `invalid_value`.
pub fn parse_rational(field: &str, text: &str) -> Result<Rational, GeomError> {
    let too_big = |what: String| {
        GeomError::InvalidValue {
        field: field.to_string(),
        reason: format!("an exact number of {what} is beyond the maximum of {MAX_EXACT_DIGITS} digits and {MAX_EXACT_BITS} bits (numerator and denominator each)"),
    }
    };
    let digits = text.bytes().filter(u8::is_ascii_digit).count();
    if digits > MAX_EXACT_DIGITS {
        return Err(too_big(format!("{digits} digits")));
    }
    let q = parse_inner(text).ok_or_else(|| GeomError::InvalidNumber {
        field: field.to_string(),
        text: text.to_string(),
    })?;
    let bits = q
        .numer()
        .significant_bits()
        .max(q.denom().significant_bits());
    if bits > MAX_EXACT_BITS {
        return Err(too_big(format!("{bits} bits")));
    }
    Ok(q)
}

/// The exact value of a finite double; NaN and infinities are rejected naming `field`.
pub fn rational_from_f64(field: &str, x: f64) -> Result<Rational, GeomError> {
    Rational::from_f64(x).ok_or_else(|| GeomError::NonFinite {
        field: field.to_string(),
        value: format!("{x}"),
    })
}

fn digits(s: &str) -> bool {
    !s.is_empty() && s.bytes().all(|b| b.is_ascii_digit())
}

fn parse_inner(text: &str) -> Option<Rational> {
    let (negative, body) = match text.as_bytes().first()? {
        b'-' => (true, &text[1..]),
        b'+' => (false, &text[1..]),
        _ => (false, text),
    };
    let value = if let Some((p, q)) = body.split_once('/') {
        if !digits(p) || !digits(q) {
            return None;
        }
        let p: Integer = p.parse().ok()?;
        let q: Integer = q.parse().ok()?;
        if q == 0 {
            return None;
        }
        Rational::from((p, q))
    } else {
        decimal(body)?
    };
    Some(if negative { -value } else { value })
}

fn decimal(body: &str) -> Option<Rational> {
    let (mantissa, exponent) = match body.find(['e', 'E']) {
        Some(i) => (&body[..i], Some(&body[i + 1..])),
        None => (body, None),
    };
    let (int_part, frac_part) = match mantissa.split_once('.') {
        Some((a, b)) => (a, b),
        None => (mantissa, ""),
    };
    if (int_part.is_empty() && frac_part.is_empty())
        || !(int_part.is_empty() || digits(int_part))
        || !(frac_part.is_empty() || digits(frac_part))
    {
        return None;
    }
    let mut exp10: i64 = match exponent {
        None => 0,
        Some(e) => {
            let d = e.strip_prefix(['+', '-']).unwrap_or(e);
            if !digits(d) || d.len() > 7 {
                return None;
            }
            e.parse().ok()?
        }
    };
    if exp10.abs() > MAX_DECIMAL_EXPONENT {
        return None;
    }
    exp10 -= frac_part.len() as i64;
    let all = format!("{int_part}{frac_part}");
    let n: Integer = all.parse().ok()?;
    let scale = Integer::from(Integer::u_pow_u(10, exp10.unsigned_abs() as u32));
    Some(if exp10 >= 0 {
        Rational::from(n * scale)
    } else {
        Rational::from((n, scale))
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parses_fractions_and_decimals_exactly() {
        assert_eq!(parse_rational("x", "1/3").unwrap(), Rational::from((1, 3)));
        assert_eq!(
            parse_rational("x", "-6/4").unwrap(),
            Rational::from((-3, 2))
        );
        assert_eq!(parse_rational("x", "0.1").unwrap(), Rational::from((1, 10)));
        assert_eq!(
            parse_rational("x", "-1.5e-3").unwrap(),
            Rational::from((-3, 2000))
        );
        assert_eq!(parse_rational("x", "+2E2").unwrap(), Rational::from(200));
        assert_eq!(parse_rational("x", ".5").unwrap(), Rational::from((1, 2)));
        assert_eq!(parse_rational("x", "5.").unwrap(), Rational::from(5));
        let tiny = parse_rational("x", "1e-400").unwrap();
        assert_eq!(tiny * Rational::from(Integer::u_pow_u(10, 400)), 1);
    }

    #[test]
    fn numbers_beyond_the_size_caps_name_the_field() {
        let long = format!("0.{}", "7".repeat(MAX_EXACT_DIGITS - 1));
        assert!(parse_rational("x", &long).is_ok());
        for bad in [
            format!("0.{}", "7".repeat(MAX_EXACT_DIGITS)),
            format!("1/{}", "3".repeat(MAX_EXACT_DIGITS)),
            "1e-5000".to_string(),
            "1e99999".to_string(),
        ] {
            let e = parse_rational("objects[0].origin[1]", &bad).unwrap_err();
            assert_eq!(e.kind(), "invalid_value", "{bad}");
            assert_eq!(e.field(), "objects[0].origin[1]");
            assert!(e.to_string().len() < 300);
        }
    }

    #[test]
    fn rejects_malformed_text_naming_the_field() {
        for bad in [
            "",
            "-",
            "1/0",
            "1/-2",
            "1.2.3",
            "e5",
            "1e",
            "0x10",
            "1/2/3",
            " 1",
            "nan",
            "1e999999999",
        ] {
            let e = parse_rational("objects[0].origin[1]", bad).unwrap_err();
            assert_eq!(e.kind(), "invalid_number", "{bad}");
            assert_eq!(e.field(), "objects[0].origin[1]");
        }
        assert_eq!(
            rational_from_f64("d", f64::NAN).unwrap_err().kind(),
            "non_finite"
        );
        assert_eq!(
            rational_from_f64("d", 0.1).unwrap(),
            Rational::from_f64(0.1).unwrap()
        );
    }
}
