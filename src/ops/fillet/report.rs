//! The sampled answer of a blend component ([`BlendComponent`]): stations along the
//! spine, each reported as float estimates (f64 evaluation of the formula) with
//! certified enclosures (the same formula in f64 intervals at the exact double
//! parameter, outward rounded), the contact points on both faces with their
//! parameters, and the surface grid.

use super::blend::{BlendFormula, ChamferSurface, FilletSurface};
use super::face::Face;
use crate::certificate::Status;
use crate::num::{Interval, Real};
use crate::ops::answer::{
    BlendComponent, BlendGrid, Bounds, CurveAnswer, CurveEnd, CurveVertex, Point,
};

/// What a component reports at a station `t`: the spine point and the two contacts.
pub trait Stations: BlendFormula {
    fn faces(&self) -> [&Face; 2];
    fn closed(&self) -> bool;
    /// `(spine point, [contact on face 0, contact on face 1])` at `t`.
    fn at<T: Real>(&self, t: &T) -> ([T; 3], [[T; 3]; 2]);
}

impl Stations for FilletSurface {
    fn faces(&self) -> [&Face; 2] {
        [&self.centre.faces[0], &self.centre.faces[1]]
    }
    fn closed(&self) -> bool {
        self.centre.closed
    }
    fn at<T: Real>(&self, t: &T) -> ([T; 3], [[T; 3]; 2]) {
        let st = self.centre.station(t);
        (st.centre, st.contact)
    }
}

impl Stations for ChamferSurface {
    fn faces(&self) -> [&Face; 2] {
        [&self.edge.faces[0], &self.edge.faces[1]]
    }
    fn closed(&self) -> bool {
        false
    }
    fn at<T: Real>(&self, t: &T) -> ([T; 3], [[T; 3]; 2]) {
        (self.edge.point(t), self.contacts(t))
    }
}

fn bounds<const D: usize>(x: &[Interval; D]) -> [Bounds; D] {
    x.map(|c| [c.lo(), c.hi()])
}

fn bounds_vec(x: &[Interval]) -> Vec<Bounds> {
    x.iter().map(|c| [c.lo(), c.hi()]).collect()
}

/// An upper bound of the distance from `x` to every point of the box `b` (rounded up).
fn distance_to_box(x: &[f64; 3], b: &[Bounds; 3]) -> f64 {
    let sq: f64 = (0..3)
        .map(|k| {
            let d = (x[k] - b[k][0]).abs().max((b[k][1] - x[k]).abs());
            let d = d.next_up();
            (d * d).next_up()
        })
        .sum();
    sq.next_up().next_up().sqrt().next_up()
}

/// The station parameters: `n` values over the range; a closed spine repeats its
/// first station last.
fn stations(range: [f64; 2], n: usize, closed: bool) -> Vec<f64> {
    let [t0, t1] = range;
    let steps = if closed { n } else { n - 1 };
    let mut t: Vec<f64> = (0..steps)
        .map(|i| t0 + (t1 - t0) * i as f64 / steps as f64)
        .collect();
    t.push(if closed { t0 } else { t1 });
    t
}

/// The component sampled on `grid = [stations, points across]` (each ≥ 2), with the
/// status and reason of its proof.
pub fn component<S: Stations>(
    s: &S,
    grid: [usize; 2],
    status: Status,
    reason: Option<String>,
) -> BlendComponent {
    let proven = status != Status::Undecided;
    let faces = s.faces();
    let ts = stations(s.range(), grid[0], s.closed());
    let zs: Vec<f64> = (0..grid[1])
        .map(|j| j as f64 / (grid[1] - 1) as f64)
        .collect();
    let mut vertices = Vec::new();
    let mut contacts: [Vec<Point>; 2] = [Vec::new(), Vec::new()];
    let mut out = BlendGrid {
        t: ts.clone(),
        z: zs.clone(),
        ..BlendGrid::default()
    };
    let mut largest: f64 = 0.0;
    for &t in &ts {
        let (spine, touch) = s.at(&t);
        let ti = Interval::point(t);
        let (spine_box, touch_box) = s.at(&ti);
        let sb = bounds(&spine_box);
        let bound = distance_to_box(&spine, &sb);
        largest = largest.max(bound);
        vertices.push(CurveVertex {
            xyz: spine.to_vec(),
            params: [0, 1].map(|k| faces[k].params_of(&touch[k])).to_vec(),
            bound: proven.then_some(bound),
            exact: None,
        });
        for k in 0..2 {
            contacts[k].push(Point {
                xyz: touch[k].to_vec(),
                xyz_box: bounds(&touch_box[k]).to_vec(),
                params: vec![faces[k].params_of(&touch[k])],
                param_box: Some(vec![bounds_vec(&faces[k].params_of(&touch_box[k]))]),
                multiplicity: 1,
                tangent: true,
                ..Point::default()
            });
        }
        out.points.push(zs.iter().map(|z| s.point(&t, z)).collect());
        out.boxes.push(
            zs.iter()
                .map(|&z| bounds(&s.point(&ti, &Interval::point(z))))
                .collect(),
        );
    }
    let closed = s.closed();
    BlendComponent {
        spine: CurveAnswer {
            points: vertices,
            closed,
            ends: if closed {
                [CurveEnd::Closed; 2]
            } else {
                [CurveEnd::Boundary; 2]
            },
            distance_bound: proven.then_some(largest),
            status,
            reason,
        },
        contacts,
        grid: out,
    }
}
