//! The answer of `fillet` and `chamfer` → the record field `blend` (docs/FORMAT.md
//! "Blends"): a field-for-field translation of [`BlendAnswer`]; the spines go to the
//! record's `curves`.

use serde::Serialize;

use super::answer_out::point;
use super::number::doubles;
use super::result::{Bounds, PointOut};
use crate::ops::{BlendAnswer, BlendComponent, BlendKind};

/// The sampled blend surface of one component.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct GridOut {
    #[serde(serialize_with = "doubles")]
    pub t: Vec<f64>,
    #[serde(serialize_with = "doubles")]
    pub z: Vec<f64>,
    /// `points[i][j] = f(t[i], z[j])`.
    #[serde(serialize_with = "doubles")]
    pub points: Vec<Vec<[f64; 3]>>,
    #[serde(rename = "box", serialize_with = "doubles")]
    pub boxes: Vec<Vec<[Bounds; 3]>>,
}

/// One component: the contacts on each face at the stations of `curves[i]`, and the grid.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ComponentOut {
    pub contacts: [Vec<PointOut>; 2],
    pub grid: GridOut,
    pub status: &'static str,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub reason: Option<String>,
}

/// `blend` of a record of kind `surface`.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct BlendOut {
    #[serde(rename = "type")]
    pub kind: &'static str,
    #[serde(skip_serializing_if = "Option::is_none", serialize_with = "doubles")]
    pub radius: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none", serialize_with = "doubles")]
    pub legs: Option<[f64; 2]>,
    pub sector: u8,
    pub components: Vec<ComponentOut>,
}

fn component(c: &BlendComponent) -> ComponentOut {
    ComponentOut {
        contacts: [0, 1].map(|k| c.contacts[k].iter().map(point).collect()),
        grid: GridOut {
            t: c.grid.t.clone(),
            z: c.grid.z.clone(),
            points: c.grid.points.clone(),
            boxes: c.grid.boxes.clone(),
        },
        status: c.spine.status.as_str(),
        reason: c.spine.reason.clone(),
    }
}

/// The record field of a blend.
pub fn blend(b: &BlendAnswer) -> BlendOut {
    let (kind, radius, legs) = match b.kind {
        BlendKind::Fillet { radius } => ("fillet", Some(radius), None),
        BlendKind::Chamfer { legs } => ("chamfer", None, Some(legs)),
    };
    BlendOut {
        kind,
        radius,
        legs,
        sector: b.sector,
        components: b.components.iter().map(component).collect(),
    }
}
