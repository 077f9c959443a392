//! The exact conic of a section → its result record field `conic` (docs/FORMAT.md
//! "Sections"): a field-for-field translation of [`Section`]; every number is the
//! correctly rounded double (with its enclosure `*_box`, and its exact rational as a
//! `"p/q"` string where it is rational).

use serde::Serialize;

use super::number::doubles;
use crate::ops::section::{Section, Value};

/// One reported number: its double, enclosure and exact rational (when rational).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ValuesOut {
    #[serde(serialize_with = "doubles")]
    pub value: Vec<f64>,
    #[serde(rename = "box", serialize_with = "doubles")]
    pub bounds: Vec<[f64; 2]>,
    /// The exact rationals, when every coordinate is rational.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub exact: Option<Vec<String>>,
}

/// An axis of `conic.axes`.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct AxisOut {
    pub dir: ValuesOut,
    pub length: ValuesOut,
}

/// A line of `conic.lines`.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ConicLineOut {
    pub point: ValuesOut,
    pub dir: ValuesOut,
}

/// The true-size plane frame (13.2).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct FrameOut {
    pub origin: ValuesOut,
    pub e1: ValuesOut,
    pub e2: ValuesOut,
}

/// `conic` of a result: the exact plane section of a quadric.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ConicOut {
    #[serde(rename = "type")]
    pub kind: &'static str,
    pub frame: FrameOut,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub center: Option<ValuesOut>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub center_uv: Option<ValuesOut>,
    pub axes: Vec<AxisOut>,
    pub lines: Vec<ConicLineOut>,
}

fn values(v: &[Value]) -> ValuesOut {
    let exact: Option<Vec<String>> = v
        .iter()
        .map(|x| x.exact.as_ref().map(|q| q.to_string()))
        .collect();
    ValuesOut {
        value: v.iter().map(|x| x.value).collect(),
        bounds: v.iter().map(|x| x.bounds).collect(),
        exact,
    }
}

fn rationals(v: &[rug::Rational]) -> ValuesOut {
    let v: Vec<Value> = v.iter().map(Value::rational).collect();
    values(&v)
}

/// The record field of a section.
pub fn conic(s: &Section) -> ConicOut {
    let t = s.frame.true_size();
    ConicOut {
        kind: s.kind.as_str(),
        frame: FrameOut {
            origin: rationals(&t.origin),
            e1: values(&t.e1),
            e2: values(&t.e2),
        },
        center: s.center.as_ref().map(|c| rationals(c)),
        center_uv: s.center_uv.as_ref().map(|c| values(c)),
        axes: s
            .axes
            .iter()
            .map(|a| AxisOut {
                dir: values(&a.dir),
                length: values(std::slice::from_ref(&a.length)),
            })
            .collect(),
        lines: s
            .lines
            .iter()
            .map(|l| ConicLineOut {
                point: values(&l.point),
                dir: values(&l.dir),
            })
            .collect(),
    }
}
