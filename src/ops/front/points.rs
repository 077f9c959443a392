//! Certified roots of the curved operations → [`Answer`] points: each root's
//! parameters split by input shape, its point and enclosure, tangency, distances.

use crate::certificate::{Certified, Status};
use crate::num::Interval;
use crate::ops::answer::{Answer, Point};
use crate::ops::certified::CertifiedPoint;

pub(crate) fn bounds<const D: usize>(b: &[Interval; D]) -> Vec<[f64; 2]> {
    b.iter().map(|x| [x.lo(), x.hi()]).collect()
}

/// The Euclidean distance of two points (rounded; a reported estimate).
pub(crate) fn distance(a: &[f64], b: &[f64]) -> f64 {
    a.iter()
        .zip(b)
        .map(|(x, y)| (x - y) * (x - y))
        .sum::<f64>()
        .sqrt()
}

/// One certified root as a point; `sizes` splits its parameters by shape, in input
/// order; `distance_to` adds the distance from a query point.
pub(crate) fn point<const D: usize>(
    p: &CertifiedPoint<D>,
    sizes: &[usize],
    distance_to: Option<&[f64; D]>,
) -> Point {
    let mut params = Vec::new();
    let mut param_box = Vec::new();
    let mut k = 0;
    for &n in sizes {
        params.push(p.root.params[k..k + n].to_vec());
        param_box.push(
            p.root.enclosure[k..k + n]
                .iter()
                .map(|x| [x.lo(), x.hi()])
                .collect(),
        );
        k += n;
    }
    let singular = p.root.status == Status::VerifiedSingular;
    Point {
        xyz: p.point.to_vec(),
        xyz_box: bounds(&p.point_box),
        params,
        param_box: Some(param_box),
        multiplicity: if singular { 2 } else { 1 },
        tangent: singular,
        distance: distance_to.map(|q| distance(&p.point, q)),
        ..Default::default()
    }
}

/// Every certified root as a point ([`point`]).
pub(crate) fn points<const D: usize>(
    c: Certified<Vec<CertifiedPoint<D>>>,
    sizes: &[usize],
    distance_to: Option<&[f64; D]>,
) -> Certified<Answer> {
    let pts = c
        .value
        .iter()
        .map(|p| point(p, sizes, distance_to))
        .collect();
    c.clone_with(Answer::from_points(pts))
}

/// `nearest` along a direction: the hit of smallest distance; proven only when the
/// hits are complete and its enclosure of `|t|` along the ray lies below every
/// other's (the ray's parameter is the shape's last parameter, `ray_param`).
pub(crate) fn keep_nearest_hit(r: &mut Certified<Answer>, ray_param: usize) {
    let Answer::Points(points) = &mut r.value else {
        return;
    };
    points.sort_by(|a, b| {
        a.distance
            .unwrap_or(f64::INFINITY)
            .total_cmp(&b.distance.unwrap_or(f64::INFINITY))
    });
    let t_abs = |q: &Point| {
        q.param_box
            .as_ref()
            .and_then(|b| b.get(ray_param))
            .and_then(|t| t.first())
            .map(|&[lo, hi]| Interval::from_bounds(lo, hi).abs())
    };
    let separated = match t_abs(&points[0]) {
        Some(t0) => points[1..]
            .iter()
            .all(|q| t_abs(q).is_some_and(|t| t0.hi() < t.lo())),
        None => false,
    };
    points.truncate(1);
    points[0].nearest = Some(true);
    if !(separated && r.complete) {
        r.status = Status::Undecided;
        r.reason = Some(
            "the nearest hit is not proven: the search is incomplete or two hits are not separated"
                .into(),
        );
    }
}
