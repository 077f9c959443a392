//! The nearest point of a curve or surface to a point (OPERATIONS.md §3.2–§3.4,
//! "nearest"), proven from the certified feet.
//!
//! The squared distance `f = |p − s(x)|²` is smooth in the parameters, so at a minimum
//! in the interior of the parameter domain its gradient vanishes: the minimum is a
//! root of the foot equations (3.2) / (3.9) — even where the parametrisation is
//! singular (a pole, an apex), since the gradient is `−2 (p − s)·s_x`. Periodic
//! directions have no boundary. So the nearest point is either one of the feet or lies
//! on the boundary of an open direction: the ends of an open curve, the edge curves of
//! a surface. When the feet are `complete` (no other root exists), the candidate whose
//! distance enclosure lies strictly below every other candidate's and below a proven
//! lower bound of the boundary's distance is the nearest point, with a proof.
//!
//! Distances are enclosed in f64 interval arithmetic (outward rounding, `num::interval`)
//! from the certified point boxes; the boundary's lower bound comes from interval
//! evaluations of the shape over pieces of the boundary (each encloses every point of
//! its piece), bisected where they cannot yet be told apart from the best foot.

use crate::certificate::{Certified, Status};
use crate::curve::Curve;
use crate::num::round::{next_down, next_up};
use crate::num::Interval;
use crate::ops::certified::{surface_unknowns, CertifiedPoint};
use crate::surface::Surface;

/// Which candidate is the nearest.
#[derive(Debug, Clone, PartialEq)]
pub enum NearestChoice<const D: usize> {
    /// The foot with this index in the certified feet.
    Foot(usize),
    /// An end of an open curve: its parameter, the point there and an enclosure of it
    /// (the end parameter may be a rounding of an irrational bound).
    End {
        t: f64,
        /// An enclosure of the exact end parameter.
        t_box: Interval,
        point: [f64; D],
        point_box: [Interval; D],
    },
}

/// The nearest point and whether it is proven.
#[derive(Debug, Clone, PartialEq)]
pub struct Nearest<const D: usize> {
    pub choice: NearestChoice<D>,
    /// An enclosure of the distance to the chosen candidate.
    pub distance: Interval,
    /// `Verified` when proven nearest (module doc), otherwise `Undecided` with `reason`.
    pub status: Status,
    pub reason: Option<String>,
}

/// An enclosure of the distances from `q` to the points of `b` (outward rounded).
pub fn distance_enclosure<const D: usize>(q: &[f64; D], b: &[Interval; D]) -> Interval {
    let mut s = Interval::point(0.0);
    for i in 0..D {
        s = s.add(&b[i].sub(&Interval::point(q[i])).sqr());
    }
    s.sqrt()
}

/// The parameter interval of a domain bound: the bound itself, or, when it is the
/// rounding of an irrational number, both neighbours around it (the exact bound lies
/// within one ulp).
fn bound_interval(b: f64, rounded: bool) -> Interval {
    if rounded {
        Interval::from_bounds(next_down(b), next_up(b))
    } else {
        Interval::point(b)
    }
}

/// The nearest point of an open or closed curve (module doc): among the certified
/// `feet` and the ends of the domain.
pub fn nearest_point_curve<C: Curve<D>, const D: usize>(
    curve: &C,
    q: &[f64; D],
    feet: &Certified<Vec<CertifiedPoint<D>>>,
) -> Option<Nearest<D>> {
    let mut candidates = foot_candidates(q, feet);
    if !curve.is_closed() {
        let (lo, hi) = curve.domain();
        let rounded = curve.domain_rounded();
        for t in [lo, hi] {
            let point = curve.jet(&t, 0)[0];
            let t_box = bound_interval(t, rounded);
            let point_box = curve.jet(&t_box, 0).swap_remove(0);
            let d = distance_enclosure(q, &point_box);
            let choice = NearestChoice::End {
                t,
                t_box,
                point,
                point_box,
            };
            candidates.push((choice, d, estimate(q, &point)));
        }
    }
    decide(candidates, feet, |_| true)
}

/// The nearest point of a surface (module doc): among the certified `feet`, against a
/// proven lower bound of the distance to the edges of its open directions. A nearest
/// point on an edge is reported undecided (the edges are bounded, not searched).
pub fn nearest_point_surface<S: Surface>(
    surface: &S,
    q: &[f64; 3],
    feet: &Certified<Vec<CertifiedPoint<3>>>,
) -> Option<Nearest<3>> {
    let candidates = foot_candidates(q, feet);
    decide(candidates, feet, |threshold| {
        edges_farther(surface, q, threshold)
    })
}

/// Each foot with its distance enclosure and float estimate.
fn foot_candidates<const D: usize>(
    q: &[f64; D],
    feet: &Certified<Vec<CertifiedPoint<D>>>,
) -> Vec<Candidate<D>> {
    feet.value
        .iter()
        .enumerate()
        .map(|(i, f)| {
            let d = distance_enclosure(q, &f.point_box);
            (NearestChoice::Foot(i), d, estimate(q, &f.point))
        })
        .collect()
}

/// A candidate, its distance enclosure and its float distance.
type Candidate<const D: usize> = (NearestChoice<D>, Interval, f64);

fn estimate<const D: usize>(q: &[f64; D], p: &[f64; D]) -> f64 {
    (0..D)
        .map(|i| (p[i] - q[i]) * (p[i] - q[i]))
        .sum::<f64>()
        .sqrt()
}

/// Pick the candidate of smallest distance; prove it nearest when the feet are
/// complete, its distance lies strictly below every other candidate's, and
/// `boundary_farther(upper bound of its distance)` holds.
fn decide<const D: usize>(
    mut candidates: Vec<Candidate<D>>,
    feet: &Certified<Vec<CertifiedPoint<D>>>,
    boundary_farther: impl Fn(f64) -> bool,
) -> Option<Nearest<D>> {
    candidates.sort_by(|a, b| a.2.total_cmp(&b.2));
    let mut it = candidates.into_iter();
    let (choice, distance, _) = it.next()?;
    let rest: Vec<Interval> = it.map(|c| c.1).collect();
    let reason = if !feet.complete {
        Some("the feet are not complete, so a nearer one may exist".to_string())
    } else if rest
        .iter()
        .any(|d| distance.hi() >= d.lo() || distance.hi().is_nan())
    {
        Some("two candidates are not separated by their distance enclosures".to_string())
    } else if !boundary_farther(distance.hi()) {
        Some("the domain boundary is not proven farther than the nearest foot".to_string())
    } else if matches!(choice, NearestChoice::Foot(i) if feet.value[i].root.status == Status::Undecided)
    {
        Some("the nearest foot is not certified".to_string())
    } else {
        None
    };
    Some(Nearest {
        choice,
        distance,
        status: if reason.is_none() {
            Status::Verified
        } else {
            Status::Undecided
        },
        reason,
    })
}

/// Every point of the surface's edges (the boundary curves of its open directions)
/// lies farther than `threshold` from `q`: proven by interval evaluation over pieces
/// of each edge, bisected up to a budget where a piece's box comes closer.
fn edges_farther<S: Surface>(surface: &S, q: &[f64; 3], threshold: f64) -> bool {
    let unknowns = surface_unknowns(surface);
    let search = unknowns.search_box();
    let mut budget = 4096usize;
    for direction in 0..2 {
        if unknowns.periodic[direction] {
            continue;
        }
        let [lo, hi] = unknowns.domain[direction];
        let other = 1 - direction;
        let free = Interval::from_bounds(search[other][0], search[other][1]);
        for end in [lo, hi] {
            let fixed = bound_interval(end, unknowns.rounded[direction]);
            let mut stack = vec![free];
            while let Some(piece) = stack.pop() {
                let b = if direction == 0 {
                    surface.jet(&fixed, &piece, 0).swap_remove(0)
                } else {
                    surface.jet(&piece, &fixed, 0).swap_remove(0)
                };
                if distance_enclosure(q, &b).lo() > threshold {
                    continue;
                }
                if budget == 0 || piece.width() == 0.0 {
                    return false;
                }
                budget -= 1;
                let (a, c) = piece.bisect();
                stack.push(a);
                stack.push(c);
            }
        }
    }
    true
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn distance_enclosure_holds_the_box_extremes() {
        let b = [
            Interval::from_bounds(3.0, 4.0),
            Interval::from_bounds(-1.0, 1.0),
        ];
        let d = distance_enclosure(&[0.0, 0.0], &b);
        // Nearest point (3, 0), farthest (4, ±1).
        assert!(d.lo() <= 3.0 && d.lo() > 2.999);
        assert!(d.hi() >= 17f64.sqrt() && d.hi() < 4.2);
    }

    #[test]
    fn a_rounded_bound_covers_its_neighbours() {
        let b = bound_interval(std::f64::consts::FRAC_PI_2, true);
        assert!(b.lo() < std::f64::consts::FRAC_PI_2 && b.hi() > std::f64::consts::FRAC_PI_2);
        assert!(bound_interval(1.0, false).is_point());
    }
}
