//! Numbers drawn from the fuzzer's bytes: mostly small and exact (integers, dyadic
//! fractions), often adversarial (±1–3 ulp off an integer, magnitudes 2^±160, raw
//! bits), sometimes exact strings `"p/q"` where the format allows them.

use arbitrary::{Result, Unstructured};
use rug::Rational;
use serde_json::{json, Value};

/// One input number: a double taken exactly, or an exact fraction (a `"p/q"` string).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Coord {
    F(f64),
    Q(i64, i64),
}

impl Coord {
    pub fn json(self) -> Value {
        match self {
            Coord::F(x) => json!(x),
            Coord::Q(p, q) => json!(format!("{p}/{q}")),
        }
    }
    pub fn rational(self) -> Rational {
        match self {
            Coord::F(x) => Rational::from_f64(x).expect("finite"),
            Coord::Q(p, q) => Rational::from((p, q)),
        }
    }
    pub fn f64(self) -> f64 {
        match self {
            Coord::F(x) => x,
            Coord::Q(p, q) => p as f64 / q as f64,
        }
    }
}

/// `x` moved by `k` ulps (k may be negative).
pub fn ulps(x: f64, k: i32) -> f64 {
    let mut y = x;
    for _ in 0..k.unsigned_abs() {
        y = if k > 0 { y.next_up() } else { y.next_down() };
    }
    if y.is_finite() {
        y
    } else {
        x
    }
}

/// A double: small integers and dyadic fractions most of the time, an ulp off an
/// integer, a huge or tiny power of two times an integer, or raw bits.
pub fn double(u: &mut Unstructured) -> Result<f64> {
    let n = f64::from(u.int_in_range(-8i8..=8)?);
    Ok(match u.int_in_range(0u8..=9)? {
        0..=3 => n,
        4 => n / f64::from(1u32 << u.int_in_range(1u8..=20)?),
        5 => ulps(n, u.int_in_range(-3..=3)?),
        6 => n * 2f64.powi(u.int_in_range(-160..=160)?),
        7 => {
            let x = f64::from_bits(u.arbitrary()?);
            if x.is_finite() {
                x
            } else {
                n
            }
        }
        8 => n + f64::from(u.int_in_range(-99i8..=99)?) / 100.0,
        _ => ulps(
            n * 2f64.powi(u.int_in_range(-60..=60)?),
            u.int_in_range(-2..=2)?,
        ),
    })
}

/// A positive double (radii, semi-axes): a small integer or fraction, or one of
/// `double` made positive, never zero.
pub fn positive(u: &mut Unstructured) -> Result<f64> {
    let x = double(u)?.abs();
    Ok(if x > 0.0 && x.is_finite() { x } else { 1.0 })
}

/// A number for a linear object: a double, or now and then an exact fraction.
pub fn coord(u: &mut Unstructured) -> Result<Coord> {
    if u.ratio(1u8, 8)? {
        let p = i64::from(u.int_in_range(-1000i16..=1000)?);
        let q = i64::from(u.int_in_range(1i16..=1000)?);
        Ok(Coord::Q(p, q))
    } else {
        Ok(Coord::F(double(u)?))
    }
}

pub fn vec3(u: &mut Unstructured) -> Result<[Coord; 3]> {
    Ok([coord(u)?, coord(u)?, coord(u)?])
}

pub fn dvec3(u: &mut Unstructured) -> Result<[f64; 3]> {
    Ok([double(u)?, double(u)?, double(u)?])
}

pub fn json3(v: &[Coord; 3]) -> Value {
    json!([v[0].json(), v[1].json(), v[2].json()])
}

/// A near copy of `v`: `v` times a small integer or power of two, then one coordinate
/// moved by a few ulps (or not at all): near-parallel directions and normals.
pub fn near_copy(u: &mut Unstructured, v: &[Coord; 3]) -> Result<[Coord; 3]> {
    let k = match u.int_in_range(0u8..=3)? {
        0 => 1.0,
        1 => -1.0,
        2 => f64::from(u.int_in_range(-4i8..=4)?),
        _ => 2f64.powi(u.int_in_range(-40..=40)?),
    };
    let mut w = v.map(|c| {
        let x = c.f64() * k;
        Coord::F(if x.is_finite() { x } else { c.f64() })
    });
    let i = u.int_in_range(0usize..=2)?;
    w[i] = Coord::F(ulps(w[i].f64(), u.int_in_range(-3..=3)?));
    Ok(w)
}

/// `a × b` rounded to doubles (a direction nearly in a plane, nearly perpendicular).
pub fn cross_f64(a: &[Coord; 3], b: &[Coord; 3]) -> [Coord; 3] {
    let (a, b) = (a.map(Coord::f64), b.map(Coord::f64));
    let c = [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ];
    c.map(|x| Coord::F(if x.is_finite() { x } else { 1.0 }))
}
