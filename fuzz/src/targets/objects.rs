//! Objects drawn from the fuzzer's bytes (docs/FORMAT.md "Objects"): planes in their
//! three forms, space and plane curves, surfaces; small most of the time, with the
//! numbers of `num` (so degenerate ones — zero radii, collinear vectors — come up too).

use super::num::{self, double, dvec3, positive, Coord};
use arbitrary::{Result, Unstructured};
use rug::Rational;
use serde_json::{json, Value};

/// A plane in one of its three forms.
#[derive(Debug, Clone)]
pub enum Plane {
    NormalD([Coord; 3], Coord),
    OriginUv([Coord; 3], [Coord; 3], [Coord; 3]),
    Points([[Coord; 3]; 3]),
}

fn cross(a: &[Rational; 3], b: &[Rational; 3]) -> [Rational; 3] {
    let m = |i: usize, j: usize| Rational::from(&a[i] * &b[j]) - Rational::from(&a[j] * &b[i]);
    [m(1, 2), m(2, 0), m(0, 1)]
}

fn diff(a: &[Coord; 3], b: &[Coord; 3]) -> [Coord; 3] {
    std::array::from_fn(|i| Coord::F(a[i].f64() - b[i].f64()))
}

impl Plane {
    pub fn arbitrary(u: &mut Unstructured) -> Result<Plane> {
        Ok(match u.int_in_range(0u8..=5)? {
            0..=3 => Plane::NormalD(num::vec3(u)?, num::coord(u)?),
            4 => Plane::OriginUv(num::vec3(u)?, num::vec3(u)?, num::vec3(u)?),
            _ => Plane::Points([num::vec3(u)?, num::vec3(u)?, num::vec3(u)?]),
        })
    }

    pub fn json(&self) -> Value {
        match self {
            Plane::NormalD(n, d) => {
                json!({"type": "plane", "normal": num::json3(n), "d": d.json()})
            }
            Plane::OriginUv(o, a, b) => json!({"type": "plane", "origin": num::json3(o),
                "u": num::json3(a), "v": num::json3(b)}),
            Plane::Points(p) => json!({"type": "plane",
                "points": [num::json3(&p[0]), num::json3(&p[1]), num::json3(&p[2])]}),
        }
    }

    /// The exact `n·x + d = 0` (OPERATIONS.md §13.1 for three points); `None` when the
    /// input spans no plane (a zero normal: the case must be refused).
    pub fn exact(&self) -> Option<([Rational; 3], Rational)> {
        let q = super::linear::q3;
        let (n, o) = match self {
            Plane::NormalD(n, d) => {
                let n = q(n);
                return n.iter().any(|x| *x != 0).then(|| (n, d.rational()));
            }
            Plane::OriginUv(o, a, b) => (cross(&q(a), &q(b)), q(o)),
            Plane::Points(p) => {
                let (p0, p1, p2) = (q(&p[0]), q(&p[1]), q(&p[2]));
                let a: [Rational; 3] = std::array::from_fn(|i| Rational::from(&p1[i] - &p0[i]));
                let b: [Rational; 3] = std::array::from_fn(|i| Rational::from(&p2[i] - &p0[i]));
                (cross(&a, &b), p0)
            }
        };
        let d = -super::linear::dot(&n, &o);
        n.iter().any(|x| *x != 0).then_some((n, d))
    }

    /// The normal, rounded to doubles.
    pub fn normal_f64(&self) -> [Coord; 3] {
        match self {
            Plane::NormalD(n, _) => *n,
            Plane::OriginUv(_, a, b) => num::cross_f64(a, b),
            Plane::Points(p) => num::cross_f64(&diff(&p[1], &p[0]), &diff(&p[2], &p[0])),
        }
    }

    fn offset(&self) -> Coord {
        match self {
            Plane::NormalD(_, d) => *d,
            _ => Coord::F(0.0),
        }
    }

    /// A plane nearly parallel to this one (or nearly the same).
    pub fn near(&self, u: &mut Unstructured) -> Result<Plane> {
        let n = num::near_copy(u, &self.normal_f64())?;
        let d = if u.arbitrary()? {
            Coord::F(num::ulps(self.offset().f64(), u.int_in_range(-2..=2)?))
        } else {
            num::coord(u)?
        };
        Ok(Plane::NormalD(n, d))
    }

    /// A plane nearly the sum of this one and `other` (three planes nearly through a line).
    pub fn near_sum(&self, u: &mut Unstructured, other: &Plane) -> Result<Plane> {
        let (a, b) = (self.normal_f64(), other.normal_f64());
        let s: [Coord; 3] = std::array::from_fn(|i| Coord::F(finite(a[i].f64() + b[i].f64())));
        let n = num::near_copy(u, &s)?;
        let d = finite(self.offset().f64() + other.offset().f64());
        Ok(Plane::NormalD(
            n,
            Coord::F(num::ulps(d, u.int_in_range(-2..=2)?)),
        ))
    }
}

fn finite(x: f64) -> f64 {
    if x.is_finite() {
        x
    } else {
        0.0
    }
}

/// A relative gap: 0, 10^-k for k in 1..=15, or a few ulps (near-tangencies).
pub fn gap(u: &mut Unstructured) -> Result<f64> {
    Ok(match u.int_in_range(0u8..=3)? {
        0 => 0.0,
        1 => 10f64.powi(-i32::from(u.int_in_range(1u8..=15)?)),
        2 => -(10f64.powi(-i32::from(u.int_in_range(1u8..=15)?))),
        _ => f64::from(u.int_in_range(-3i8..=3)?) * f64::EPSILON,
    })
}

/// A unit coordinate axis, or a small integer direction.
pub fn axis(u: &mut Unstructured) -> Result<[f64; 3]> {
    Ok(match u.int_in_range(0u8..=4)? {
        0 => [0.0, 0.0, 1.0],
        1 => [1.0, 0.0, 0.0],
        2 => [0.0, 1.0, 0.0],
        _ => dvec3(u)?,
    })
}

fn points(u: &mut Unstructured, dim: usize, lo: usize, hi: usize) -> Result<Vec<Vec<f64>>> {
    let n = u.int_in_range(lo..=hi)?;
    (0..n)
        .map(|_| (0..dim).map(|_| double(u)).collect())
        .collect()
}

fn maybe_weights(u: &mut Unstructured, n: usize, obj: &mut Value) -> Result<()> {
    if u.ratio(1u8, 4)? {
        let w: Vec<f64> = (0..n).map(|_| positive(u)).collect::<Result<_>>()?;
        obj["weights"] = json!(w);
    }
    Ok(())
}

/// A space curve.
pub fn curve3(u: &mut Unstructured) -> Result<Value> {
    let (c, a) = (dvec3(u)?, axis(u)?);
    Ok(match u.int_in_range(0u8..=8)? {
        0 => json!({"type": "line", "origin": c, "dir": axis(u)?}),
        1 => json!({"type": "segment", "a": c, "b": dvec3(u)?}),
        2 => json!({"type": "circle", "center": c, "radius": positive(u)?, "axis": a}),
        3 => {
            json!({"type": "ellipse", "center": c, "a": positive(u)?, "b": positive(u)?, "axis": a})
        }
        4 => {
            let t0 = f64::from(u.int_in_range(-8i8..=0)?);
            json!({"type": "helix", "center": c, "radius": positive(u)?, "pitch": double(u)?,
                   "axis": a, "range": [t0, t0 + positive(u)?]})
        }
        5 => {
            json!({"type": "parabola", "vertex": c, "p": positive(u)?, "axis": a, "range": [-2, 2]})
        }
        6 => json!({"type": "hyperbola", "center": c, "a": positive(u)?, "b": positive(u)?,
                    "axis": a, "range": [-1, 1.5]}),
        7 => json!({"type": "polyline", "points": points(u, 3, 2, 5)?}),
        _ => {
            let p = points(u, 3, 2, 5)?;
            let mut obj = json!({"type": "bezier", "points": p});
            maybe_weights(u, p.len(), &mut obj)?;
            obj
        }
    })
}

/// A plane curve.
pub fn curve2(u: &mut Unstructured) -> Result<Value> {
    let c = [double(u)?, double(u)?];
    Ok(match u.int_in_range(0u8..=6)? {
        0 => json!({"type": "line2", "origin": c, "dir": [double(u)?, double(u)?]}),
        1 => json!({"type": "segment2", "a": c, "b": [double(u)?, double(u)?]}),
        2 => json!({"type": "circle2", "center": c, "radius": positive(u)?}),
        3 => json!({"type": "ellipse2", "center": c, "a": positive(u)?, "b": positive(u)?}),
        4 => {
            let coeffs: Vec<f64> = (0..6).map(|_| double(u)).collect::<Result<_>>()?;
            json!({"type": "conic2", "coeffs": coeffs})
        }
        5 => json!({"type": "polyline2", "points": points(u, 2, 2, 5)?}),
        _ => {
            let p = points(u, 2, 2, 5)?;
            let mut obj = json!({"type": "bezier2", "points": p});
            maybe_weights(u, p.len(), &mut obj)?;
            obj
        }
    })
}

/// A surface.
pub fn surface(u: &mut Unstructured) -> Result<Value> {
    let (c, a) = (dvec3(u)?, axis(u)?);
    Ok(match u.int_in_range(0u8..=8)? {
        0 => json!({"type": "plane", "normal": a, "d": double(u)?}),
        1 => json!({"type": "sphere", "center": c, "radius": positive(u)?}),
        2 => json!({"type": "cylinder", "origin": c, "radius": positive(u)?, "axis": a,
                    "height": [-positive(u)?, positive(u)?]}),
        3 => {
            let angle = [0.25, 0.5, 0.785, 1.0, -0.5][u.int_in_range(0usize..=4)?];
            json!({"type": "cone", "origin": c, "radius": positive(u)? - 1.0, "half_angle": angle,
                   "axis": a, "height": [0, positive(u)?]})
        }
        4 => {
            json!({"type": "torus", "center": c, "major": positive(u)?, "minor": positive(u)?, "axis": a})
        }
        5 => {
            json!({"type": "ellipsoid", "center": c, "a": positive(u)?, "b": positive(u)?, "c": positive(u)?})
        }
        6 => json!({"type": "paraboloid", "center": c, "a": positive(u)?, "b": positive(u)?,
                    "axis": a, "range": [0, positive(u)?]}),
        7 => json!({"type": "elliptic_cylinder", "origin": c, "a": positive(u)?, "b": positive(u)?,
                    "axis": a, "height": [0, positive(u)?]}),
        _ => {
            let (m, n) = (u.int_in_range(2usize..=3)?, u.int_in_range(2usize..=3)?);
            let net: Vec<Vec<[f64; 3]>> = (0..n)
                .map(|j| {
                    (0..m)
                        .map(|i| Ok([i as f64, j as f64, double(u)?]))
                        .collect()
                })
                .collect::<Result<_>>()?;
            json!({"type": "bezier_surface", "points": net})
        }
    })
}

/// A point in space, as a list.
pub fn dvec(u: &mut Unstructured) -> Result<Vec<f64>> {
    Ok(dvec3(u)?.to_vec())
}
