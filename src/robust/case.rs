//! The cases of the robustness generators: plain doubles, as a docs/FORMAT.md case would
//! give them, with the conversions every consumer needs — geocert's objects (doubles,
//! or the same values as exact rationals), the CGAL oracle's inputs (feature `cgal`)
//! and one JSON line of docs/FORMAT.md that `geocert solve -` replays.

use nalgebra::{Vector2, Vector3};
use rug::Rational;
use serde_json::{json, Value};

use crate::geom::{Coord, Line, Line2, Linear, Linear2, Plane, Segment, Segment2};
use crate::GeomError;

pub type P3 = [f64; 3];
pub type P2 = [f64; 2];

/// A plane: `origin + s·u + t·v`, or `normal·x + d = 0` (docs/FORMAT.md `plane`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum PlaneIn {
    Parametric { origin: P3, u: P3, v: P3 },
    Implicit { normal: P3, d: f64 },
}

/// A 3D line `origin + t·dir` or a segment `(1 − t)·a + t·b`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum LinearIn {
    Line { origin: P3, dir: P3 },
    Segment { a: P3, b: P3 },
}

/// A 2D line or segment.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Linear2In {
    Line { origin: P2, dir: P2 },
    Segment { a: P2, b: P2 },
}

/// One case of one construction.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Case {
    ThreePlanes([PlaneIn; 3]),
    LinePlane(LinearIn, PlaneIn),
    PlanePlane(PlaneIn, PlaneIn),
    /// A point projected onto an unbounded line.
    ProjectLine(P3, P3, P3),
    ProjectPlane(P3, PlaneIn),
    /// Two unbounded 2D lines (`Linear2In::Line`) or two 2D segments.
    Linear2(Linear2In, Linear2In),
}

/// A line or segment owned, for [`Linear`]'s borrow.
#[derive(Debug, Clone)]
pub enum LinearObj<T: Coord> {
    Line(Line<T>),
    Segment(Segment<T>),
}

impl<T: Coord> LinearObj<T> {
    pub fn linear(&self) -> Linear<'_, T> {
        match self {
            LinearObj::Line(l) => Linear::Line(l),
            LinearObj::Segment(s) => Linear::Segment(s),
        }
    }
}

/// A 2D line or segment owned, for [`Linear2`]'s borrow.
#[derive(Debug, Clone)]
pub enum Linear2Obj<T: Coord> {
    Line(Line2<T>),
    Segment(Segment2<T>),
}

impl<T: Coord> Linear2Obj<T> {
    pub fn linear(&self) -> Linear2<'_, T> {
        match self {
            Linear2Obj::Line(l) => Linear2::Line(l),
            Linear2Obj::Segment(s) => Linear2::Segment(s),
        }
    }
}

/// The exact rational value of a double (inputs are finite by construction).
pub fn q(x: f64) -> Rational {
    Rational::from_f64(x).unwrap_or_default()
}

fn v3<T: Coord>(v: P3, f: impl Fn(f64) -> T) -> Vector3<T> {
    Vector3::new(f(v[0]), f(v[1]), f(v[2]))
}

fn v2<T: Coord>(v: P2, f: impl Fn(f64) -> T) -> Vector2<T> {
    Vector2::new(f(v[0]), f(v[1]))
}

impl PlaneIn {
    /// geocert's plane over `T` (`f64`, or the same values as rationals).
    pub fn object<T: Coord>(&self, f: impl Fn(f64) -> T + Copy) -> Result<Plane<T>, GeomError> {
        match *self {
            PlaneIn::Parametric { origin, u, v } => {
                Plane::parametric(v3(origin, f), v3(u, f), v3(v, f))
            }
            PlaneIn::Implicit { normal, d } => Plane::implicit(v3(normal, f), f(d)),
        }
    }
    pub fn json(&self) -> Value {
        match self {
            PlaneIn::Parametric { origin, u, v } => {
                json!({"type": "plane", "origin": origin, "u": u, "v": v})
            }
            PlaneIn::Implicit { normal, d } => json!({"type": "plane", "normal": normal, "d": d}),
        }
    }
}

impl LinearIn {
    pub fn object<T: Coord>(&self, f: impl Fn(f64) -> T + Copy) -> Result<LinearObj<T>, GeomError> {
        Ok(match *self {
            LinearIn::Line { origin, dir } => {
                LinearObj::Line(Line::new(v3(origin, f), v3(dir, f))?)
            }
            LinearIn::Segment { a, b } => LinearObj::Segment(Segment::new(v3(a, f), v3(b, f))?),
        })
    }
    pub fn json(&self) -> Value {
        match self {
            LinearIn::Line { origin, dir } => json!({"type": "line", "origin": origin, "dir": dir}),
            LinearIn::Segment { a, b } => json!({"type": "segment", "a": a, "b": b}),
        }
    }
}

impl Linear2In {
    pub fn object<T: Coord>(
        &self,
        f: impl Fn(f64) -> T + Copy,
    ) -> Result<Linear2Obj<T>, GeomError> {
        Ok(match *self {
            Linear2In::Line { origin, dir } => {
                Linear2Obj::Line(Line2::new(v2(origin, f), v2(dir, f))?)
            }
            Linear2In::Segment { a, b } => Linear2Obj::Segment(Segment2::new(v2(a, f), v2(b, f))?),
        })
    }
    pub fn json(&self) -> Value {
        match self {
            Linear2In::Line { origin, dir } => {
                json!({"type": "line2", "origin": origin, "dir": dir})
            }
            Linear2In::Segment { a, b } => json!({"type": "segment2", "a": a, "b": b}),
        }
    }
}

/// The identity conversion, for [`PlaneIn::object`] and friends.
pub fn same(x: f64) -> f64 {
    x
}

impl Case {
    /// Whether geocert accepts every object (no zero direction, collinear plane
    /// vectors, zero normal or degenerate segment): the generators keep only these.
    pub fn is_valid(&self) -> bool {
        let f = same;
        match self {
            Case::ThreePlanes(p) => p.iter().all(|p| p.object(f).is_ok()),
            Case::LinePlane(l, p) => l.object(f).is_ok() && p.object(f).is_ok(),
            Case::PlanePlane(a, b) => a.object(f).is_ok() && b.object(f).is_ok(),
            Case::ProjectLine(_, o, d) => Line::new(v3(*o, f), v3(*d, f)).is_ok(),
            Case::ProjectPlane(_, p) => p.object(f).is_ok(),
            Case::Linear2(a, b) => a.object(f).is_ok() && b.object(f).is_ok(),
        }
    }

    /// The case as one JSON line of docs/FORMAT.md (numbers in shortest round-trip
    /// form, so they read back to the same doubles).
    pub fn json_line(&self, id: &str) -> String {
        let intersect =
            |objects: Vec<Value>| json!({"id": id, "op": "intersect", "objects": objects});
        let project = |point: &[f64], onto: Value| json!({"id": id, "op": "project", "point": point, "onto": onto});
        let value = match self {
            Case::ThreePlanes(p) => intersect(p.iter().map(PlaneIn::json).collect()),
            Case::LinePlane(l, p) => intersect(vec![l.json(), p.json()]),
            Case::PlanePlane(a, b) => intersect(vec![a.json(), b.json()]),
            Case::ProjectLine(p, o, d) => project(
                p,
                LinearIn::Line {
                    origin: *o,
                    dir: *d,
                }
                .json(),
            ),
            Case::ProjectPlane(p, pl) => project(p, pl.json()),
            Case::Linear2(a, b) => intersect(vec![a.json(), b.json()]),
        };
        value.to_string()
    }
}

#[cfg(feature = "cgal")]
mod to_oracle {
    use super::*;
    use crate::oracle::{Line2Input, LineInput, PlaneInput, Segment2Input, SegmentInput};

    impl PlaneIn {
        pub fn oracle(&self) -> PlaneInput {
            match *self {
                PlaneIn::Parametric { origin, u, v } => PlaneInput::Parametric { origin, u, v },
                PlaneIn::Implicit { normal, d } => PlaneInput::Implicit {
                    a: normal[0],
                    b: normal[1],
                    c: normal[2],
                    d,
                },
            }
        }
    }

    /// A line as the oracle takes it.
    pub fn line(origin: P3, dir: P3) -> LineInput {
        LineInput {
            point: origin,
            direction: dir,
        }
    }

    /// A segment as the oracle takes it.
    pub fn segment(a: P3, b: P3) -> SegmentInput {
        SegmentInput {
            source: a,
            target: b,
        }
    }

    /// A 2D line as the oracle takes it.
    pub fn line2(origin: P2, dir: P2) -> Line2Input {
        Line2Input {
            point: origin,
            direction: dir,
        }
    }

    /// A 2D segment as the oracle takes it.
    pub fn segment2(a: P2, b: P2) -> Segment2Input {
        Segment2Input {
            source: a,
            target: b,
        }
    }
}

#[cfg(feature = "cgal")]
pub use to_oracle::{line, line2, segment, segment2};
