//! Seeded families of line ∩ line cases in space: lines, rays, ranged lines and
//! segments in every pairing, generic or built to be exactly degenerate (crossing,
//! parallel, collinear overlapping / touching / disjoint), moved one ulp off, and at
//! magnitudes from about 1e-150 to 1e150. Every case is a function of its family and
//! seed ([`case`]), like the generators of [`super::gen`].
//!
//! Exact configurations are built from "grain" data, multiples of 2⁻²⁰ below 16 in
//! magnitude (24-bit significands), combined with small integer or dyadic coefficients:
//! every sum and product used stays below 2⁻²³·2³¹, so it is exact in doubles and the
//! configuration holds for the doubles themselves; the magnitude family scales such a
//! configuration by `2^k`, `|k| ≤ 498`, which keeps every incidence and parameter.

use serde_json::{json, Value};

use super::case::{LinearObj, P3};
use super::rng::Rng;
use crate::geom::{Coord, Line, ParamRange, Segment};
use crate::num::round::{next_down, next_up};
use crate::GeomError;

/// A family of cases.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Family {
    /// Uniform doubles in `[−10, 10)` with full significands (skew, almost surely).
    Generic,
    /// Coplanar objects whose carriers cross exactly, at a double or not, inside or
    /// outside the domains, at a domain end or not.
    Crossing,
    /// Parallel distinct carriers.
    Parallel,
    /// Collinear objects: overlapping, touching at an end or disjoint.
    Collinear,
    /// A crossing, parallel or collinear case with one number moved by one ulp
    /// (skew or not, parallel or not, touching or not by one ulp).
    OneUlp,
    /// Coordinates `±m·2^e`, `e ∈ [−498, 498]` mixed, or an exact configuration scaled
    /// by `2^k`, `|k| ≤ 498`.
    Magnitudes,
}

impl Family {
    pub const ALL: [Family; 6] = [
        Family::Generic,
        Family::Crossing,
        Family::Parallel,
        Family::Collinear,
        Family::OneUlp,
        Family::Magnitudes,
    ];
    pub fn name(self) -> &'static str {
        match self {
            Family::Generic => "generic",
            Family::Crossing => "crossing",
            Family::Parallel => "parallel",
            Family::Collinear => "collinear",
            Family::OneUlp => "one-ulp",
            Family::Magnitudes => "magnitudes 1e±150",
        }
    }
}

/// A line `origin + t·dir` with `t ∈ [range[0], range[1]]` (`None`: an open end; one
/// open end is a ray, two an unbounded line), or a segment `(1 − t)·a + t·b`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Shape {
    Line {
        origin: P3,
        dir: P3,
        range: [Option<f64>; 2],
    },
    Segment {
        a: P3,
        b: P3,
    },
}

/// One case: two objects.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LineLineCase {
    pub a: Shape,
    pub b: Shape,
}

fn v3<T: Coord>(v: P3, f: impl Fn(f64) -> T) -> nalgebra::Vector3<T> {
    nalgebra::Vector3::new(f(v[0]), f(v[1]), f(v[2]))
}

impl Shape {
    /// geocert's object over `T` (`f64`, or the same values as rationals).
    pub fn object<T: Coord>(&self, f: impl Fn(f64) -> T + Copy) -> Result<LinearObj<T>, GeomError> {
        Ok(match *self {
            Shape::Line { origin, dir, range } => {
                let range = match range {
                    [None, None] => None,
                    [Some(lo), None] => Some(ParamRange::AtLeast(f(lo))),
                    [None, Some(hi)] => Some(ParamRange::AtMost(f(hi))),
                    [Some(lo), Some(hi)] => Some(ParamRange::Closed([f(lo), f(hi)])),
                };
                LinearObj::Line(Line::with_param_range(v3(origin, f), v3(dir, f), range)?)
            }
            Shape::Segment { a, b } => LinearObj::Segment(Segment::new(v3(a, f), v3(b, f))?),
        })
    }
    /// The object in the CASES.md form, an open end of `range` written `null` (the
    /// proposed extension for rays).
    pub fn json(&self) -> Value {
        match self {
            Shape::Line {
                origin,
                dir,
                range: [None, None],
            } => json!({"type": "line", "origin": origin, "dir": dir}),
            Shape::Line { origin, dir, range } => {
                json!({"type": "line", "origin": origin, "dir": dir, "range": range})
            }
            Shape::Segment { a, b } => json!({"type": "segment", "a": a, "b": b}),
        }
    }
    /// Every number of the shape, for perturbation and scaling: `(value, position-like)`
    /// (range ends are parameters: not scaled with the configuration).
    fn numbers(&mut self) -> Vec<(&mut f64, bool)> {
        match self {
            Shape::Line { origin, dir, range } => origin
                .iter_mut()
                .chain(dir.iter_mut())
                .map(|x| (x, true))
                .chain(range.iter_mut().flatten().map(|x| (x, false)))
                .collect(),
            Shape::Segment { a, b } => a
                .iter_mut()
                .chain(b.iter_mut())
                .map(|x| (x, true))
                .collect(),
        }
    }
}

impl LineLineCase {
    /// Whether geocert accepts both objects (the generators keep only these) and a
    /// closed range is not a single point (so that CGAL gets a proper segment).
    pub fn is_valid(&self) -> bool {
        let proper = |s: &Shape| match s {
            Shape::Line {
                range: [Some(lo), Some(hi)],
                ..
            } => lo < hi,
            _ => true,
        };
        [self.a, self.b]
            .iter()
            .all(|s| proper(s) && s.object(|x| x).is_ok())
    }
    /// The case as one JSON line of CASES.md (with the proposed `null` range ends).
    pub fn json_line(&self, id: &str) -> String {
        json!({"id": id, "op": "intersect", "objects": [self.a.json(), self.b.json()]}).to_string()
    }
}

/// The case of `family` determined by `seed` (invalid draws are redrawn from the same
/// stream).
pub fn case(family: Family, seed: u64) -> LineLineCase {
    let mut rng = Rng::new(seed);
    loop {
        let c = draw(family, &mut rng);
        if c.is_valid() {
            return c;
        }
    }
}

fn draw(family: Family, rng: &mut Rng) -> LineLineCase {
    match family {
        Family::Generic => random(Rng::generic, rng),
        Family::Crossing => crossing(rng),
        Family::Parallel => parallel(rng),
        Family::Collinear => collinear(rng),
        Family::OneUlp => {
            let mut c = match rng.below(3) {
                0 => crossing(rng),
                1 => parallel(rng),
                _ => collinear(rng),
            };
            perturb(&mut c, rng);
            c
        }
        Family::Magnitudes => {
            if rng.coin() {
                return random(Rng::mixed, rng);
            }
            let mut c = match rng.below(3) {
                0 => crossing(rng),
                1 => parallel(rng),
                _ => collinear(rng),
            };
            let s = 2f64.powi(rng.int(-498, 498) as i32);
            for shape in [&mut c.a, &mut c.b] {
                for (x, position) in shape.numbers() {
                    if position {
                        *x *= s;
                    }
                }
            }
            c
        }
    }
}

// ---- data ---------------------------------------------------------------------

/// A multiple of 2⁻²⁰ in `(−16, 16)`.
fn grain(rng: &mut Rng) -> f64 {
    rng.int(-(1 << 24) + 1, (1 << 24) - 1) as f64 / (1u64 << 20) as f64
}
fn p3(src: fn(&mut Rng) -> f64, rng: &mut Rng) -> P3 {
    [src(rng), src(rng), src(rng)]
}
/// `o + t·d` (exact on grain data with dyadic `t`).
fn at(o: P3, t: f64, d: P3) -> P3 {
    [o[0] + t * d[0], o[1] + t * d[1], o[2] + t * d[2]]
}
fn scaled(k: f64, d: P3) -> P3 {
    [k * d[0], k * d[1], k * d[2]]
}
/// A non-zero integer in `[−4, 4]`.
fn nonzero(rng: &mut Rng) -> f64 {
    let k = rng.int(1, 4) as f64;
    if rng.coin() {
        -k
    } else {
        k
    }
}

/// The object on the carrier `o + t·d` with the domain ends `lo < hi` (parameters on
/// this carrier): an unbounded line, a ray either way, a ranged line or the segment
/// between the ends.
fn shape(o: P3, d: P3, [lo, hi]: [f64; 2], rng: &mut Rng) -> Shape {
    let line = |range| Shape::Line {
        origin: o,
        dir: d,
        range,
    };
    match rng.below(5) {
        0 => line([None, None]),
        1 => line([Some(lo), None]),
        2 => line([None, Some(hi)]),
        3 => line([Some(lo), Some(hi)]),
        _ => {
            // either orientation
            let (a, b) = (at(o, lo, d), at(o, hi, d));
            if rng.coin() {
                Shape::Segment { a, b }
            } else {
                Shape::Segment { a: b, b: a }
            }
        }
    }
}

/// Two domain ends `lo < hi` near `t` (a dyadic parameter, or `None`): one of them is
/// `t` itself a third of the time, otherwise both are dyadic steps around it, so
/// that `t` falls inside, outside or on the boundary.
fn ends(t: f64, rng: &mut Rng) -> [f64; 2] {
    let step = |rng: &mut Rng| rng.int(-8, 8) as f64 / 4.0;
    let (mut lo, mut hi) = (t + step(rng), t + step(rng));
    match rng.below(6) {
        0 => lo = t,
        1 => hi = t,
        _ => {}
    }
    if lo > hi {
        std::mem::swap(&mut lo, &mut hi);
    }
    if lo == hi {
        hi = lo + 0.5;
    }
    [lo, hi]
}

fn random(src: fn(&mut Rng) -> f64, rng: &mut Rng) -> LineLineCase {
    let one = |rng: &mut Rng| {
        let (o, d) = (p3(src, rng), p3(src, rng));
        let mut e = [src(rng), src(rng)];
        e.sort_by(f64::total_cmp);
        shape(o, d, e, rng)
    };
    LineLineCase {
        a: one(rng),
        b: one(rng),
    }
}

/// Two carriers crossing at an exact point: at the dyadic point `x` (ends may touch
/// it), or — half of the time — at `o₂ + t₂d₂` with `t₂ = −β/δ`, `δ ∈ {±3, ±5, ±7}`
/// (a point that is not a double, in general): `o₂ = o₁ + α d₁ + β e`,
/// `d₂ = γ d₁ + δ e`, all in the plane of `d₁` and `e` through `o₁`.
fn crossing(rng: &mut Rng) -> LineLineCase {
    let (d1, e) = (p3(grain, rng), p3(grain, rng));
    if rng.coin() {
        let x = p3(grain, rng);
        let d2 = [
            e[0] + nonzero(rng) * d1[0],
            e[1] + nonzero(rng) * d1[1],
            e[2] + nonzero(rng) * d1[2],
        ];
        let (s1, s2) = (rng.int(-16, 16) as f64 / 8.0, rng.int(-16, 16) as f64 / 8.0);
        let (o1, o2) = (at(x, -s1, d1), at(x, -s2, d2));
        return LineLineCase {
            a: shape(o1, d1, ends(s1, rng), rng),
            b: shape(o2, d2, ends(s2, rng), rng),
        };
    }
    let o1 = p3(grain, rng);
    let (alpha, beta, gamma) = (rng.small_int(), nonzero(rng), rng.small_int());
    let delta = [3.0, 5.0, 7.0][rng.below(3)] * if rng.coin() { 1.0 } else { -1.0 };
    let o2 = at(at(o1, alpha, d1), beta, e);
    let d2 = at(scaled(gamma, d1), delta, e);
    let t2 = -beta / delta;
    let t1 = alpha + gamma * t2;
    let near = |t: f64| (4.0 * t).round() / 4.0;
    LineLineCase {
        a: shape(o1, d1, ends(near(t1), rng), rng),
        b: shape(o2, d2, ends(near(t2), rng), rng),
    }
}

/// Parallel distinct carriers: `d₂ = c·d₁` (`c` a small power of two or integer, either
/// sign), `o₂ = o₁ + α d₁ + β e`, `β ≠ 0` (off the first line unless `e ∥ d₁`).
fn parallel(rng: &mut Rng) -> LineLineCase {
    let (o1, d1, e) = (p3(grain, rng), p3(grain, rng), p3(grain, rng));
    let c = nonzero(rng) * [1.0, 0.5, 0.25][rng.below(3)];
    let o2 = at(at(o1, rng.small_int(), d1), nonzero(rng) / 4.0, e);
    LineLineCase {
        a: shape(o1, d1, ends(0.0, rng), rng),
        b: shape(o2, scaled(c, d1), ends(0.0, rng), rng),
    }
}

/// Collinear objects: `d₂ = c·d₁` with `c = ±2^j`, `|j| ≤ 2`, `o₂ = o₁ + α d₁`; the
/// second object's ends are chosen on the first's parameter grid (multiples of 1/4 in
/// `t₁`, mapped exactly by `t₂ = (t₁ − α)/c`), so they coincide with the first's ends
/// often: overlaps, touching ends and disjoint pieces.
fn collinear(rng: &mut Rng) -> LineLineCase {
    let (o1, d1) = (p3(grain, rng), p3(grain, rng));
    let c = [1.0, 2.0, 4.0, 0.5, 0.25][rng.below(5)] * if rng.coin() { 1.0 } else { -1.0 };
    let alpha = rng.int(-8, 8) as f64 / 4.0;
    let o2 = at(o1, alpha, d1);
    let e1 = ends(0.0, rng);
    let mut e2 = ends(e1[rng.below(2)], rng).map(|t1| (t1 - alpha) / c);
    e2.sort_by(f64::total_cmp);
    LineLineCase {
        a: shape(o1, d1, e1, rng),
        b: shape(o2, scaled(c, d1), e2, rng),
    }
}

/// Move one number (a coordinate or a range end) one ulp up or down.
fn perturb(c: &mut LineLineCase, rng: &mut Rng) {
    let n = c.a.numbers().len() + c.b.numbers().len();
    let (mut k, up) = (rng.below(n), rng.coin());
    for shape in [&mut c.a, &mut c.b] {
        let mut xs = shape.numbers();
        if k < xs.len() {
            let x = &mut *xs[k].0;
            *x = if up { next_up(*x) } else { next_down(*x) };
            return;
        }
        k -= xs.len();
    }
}

#[cfg(feature = "cgal")]
mod to_oracle {
    use super::Shape;
    use crate::oracle::{Linear3Input, SegmentInput};

    impl Shape {
        /// The object as the oracle takes it (open ends infinite).
        pub fn oracle(&self) -> Linear3Input {
            match *self {
                Shape::Line { origin, dir, range } => Linear3Input::Line {
                    point: origin,
                    direction: dir,
                    lo: range[0].unwrap_or(f64::NEG_INFINITY),
                    hi: range[1].unwrap_or(f64::INFINITY),
                },
                Shape::Segment { a, b } => Linear3Input::Segment(SegmentInput {
                    source: a,
                    target: b,
                }),
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The exact families are what they claim, decided in rationals here (not by
    /// geocert): crossing carriers are coplanar and not parallel, parallel ones are
    /// parallel and distinct, collinear ones collinear; scaling keeps them so.
    #[test]
    fn families_hold_exactly() {
        use crate::robust::case::q;
        use rug::Rational;
        let carrier = |s: &Shape| -> [[Rational; 3]; 2] {
            let v = |p: P3| p.map(q);
            match *s {
                Shape::Line { origin, dir, .. } => [v(origin), v(dir)],
                Shape::Segment { a, b } => {
                    let (a, b) = (v(a), v(b));
                    let d = [0, 1, 2].map(|i| Rational::from(&b[i] - &a[i]));
                    [a, d]
                }
            }
        };
        let cross = |a: &[Rational; 3], b: &[Rational; 3]| {
            [(1, 2), (2, 0), (0, 1)]
                .map(|(i, j)| Rational::from(&a[i] * &b[j]) - Rational::from(&a[j] * &b[i]))
        };
        let zero = |v: &[Rational; 3]| v.iter().all(|x| x.cmp0().is_eq());
        for seed in 0..2000 {
            for family in [Family::Crossing, Family::Parallel, Family::Collinear] {
                let c = case(family, seed);
                let ([o1, d1], [o2, d2]) = (carrier(&c.a), carrier(&c.b));
                let n = cross(&d1, &d2);
                let w = [0, 1, 2].map(|i| Rational::from(&o2[i] - &o1[i]));
                let wn: Rational = (0..3).map(|i| Rational::from(&w[i] * &n[i])).sum();
                let off = !zero(&cross(&w, &d1));
                match family {
                    Family::Crossing => assert!(wn.cmp0().is_eq(), "{seed}: {c:?}"),
                    Family::Parallel => assert!(zero(&n), "{seed}: {c:?}"),
                    _ => assert!(zero(&n) && !off, "{seed}: {c:?}"),
                }
            }
        }
    }
}
