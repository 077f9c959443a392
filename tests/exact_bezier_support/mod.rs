//! Exact Bézier polygons in rationals, shared by the families that build one curve from
//! another (a piece, a reversal, a knot inserted) and need the truth exactly: de
//! Casteljau splits, pieces and points, and the polygon as the JSON of a case.
#![allow(dead_code)]

use rug::Rational;
use serde_json::{json, Value};

/// A control polygon: points of 2 or 3 rational coordinates.
pub type Poly = Vec<Vec<Rational>>;

/// `(1 − t)·a + t·b`, exactly.
pub fn lerp(a: &[Rational], b: &[Rational], t: &Rational) -> Vec<Rational> {
    a.iter()
        .zip(b)
        .map(|(x, y)| x * (Rational::from(1) - t) + Rational::from(y * t))
        .collect()
}

/// The control polygons of `[0, t]` and `[t, 1]` (de Casteljau, exact).
pub fn split(p: &Poly, t: &Rational) -> (Poly, Poly) {
    let (mut left, mut right) = (vec![p[0].clone()], vec![p[p.len() - 1].clone()]);
    let mut q = p.clone();
    while q.len() > 1 {
        q = q.windows(2).map(|w| lerp(&w[0], &w[1], t)).collect();
        left.push(q[0].clone());
        right.push(q[q.len() - 1].clone());
    }
    right.reverse();
    (left, right)
}

/// The point at `t` (de Casteljau, exact).
pub fn at(p: &Poly, t: &Rational) -> Vec<Rational> {
    split(p, t).1[0].clone()
}

/// The piece over `[a, b]`, reparametrised to `[0, 1]`.
pub fn piece(p: &Poly, a: &Rational, b: &Rational) -> Poly {
    let (_, right) = split(p, a);
    let t = Rational::from(b - a) / (Rational::from(1) - a);
    split(&right, &t).0
}

/// The polygon as doubles, checked exact (the tests' truth is the rational curve).
pub fn doubles(p: &Poly) -> Vec<Vec<f64>> {
    p.iter()
        .map(|v| {
            v.iter()
                .map(|x| {
                    let d = x.to_f64();
                    assert_eq!(Rational::from_f64(d).unwrap(), *x, "not exact in doubles");
                    d
                })
                .collect()
        })
        .collect()
}

/// The polygon as a `bezier` (space) or `bezier2` (plane) object.
pub fn bezier(p: &Poly) -> Value {
    let t = if p[0].len() == 2 { "bezier2" } else { "bezier" };
    json!({"type": t, "points": doubles(p)})
}
