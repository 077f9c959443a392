//! The promise on every reported number (docs/FORMAT.md "Results", "Numbers beyond the
//! double range"; CERTIFICATION.md), enforced once where the front door hands an answer
//! out ([`keep`]), after each operation has formed its numbers:
//!
//! 1. no number is `NaN`: an estimate is a double, or `±∞` only inside a box that
//!    reaches `±∞` (a value beyond the double range);
//! 2. every estimate lies in its own enclosure: one outside is moved to the nearest
//!    point of the box (a missing one is the box midpoint);
//! 3. every `param_box` meets its object's parameter domain: a periodic coordinate
//!    whose box lies outside the domain is shifted by whole periods (an enclosure of
//!    the exact period, so the shifted box still holds the parameter modulo the
//!    period) until its midpoint lies in the domain; a box that straddles the seam is
//!    an arc across it and keeps its tightness (`[−ε, ε]` means `[2π − ε, 2π] ∪
//!    [0, ε]`), the estimate shifted by a period into the box if it lies a period
//!    away. A non-periodic coordinate is clipped to the domain: an answer is a point
//!    of the object, so its parameter lies in the domain.
//!
//! A point whose numbers cannot be formed (a `NaN` with no box to take one from) is
//! left out of an `undecided` answer; in a certified answer it is kept and the answer
//! is downgraded to `undecided` with the reason — never left out, never hidden.

use crate::certificate::{Certified, Status};
use crate::curve::Curve;
use crate::num::round::{next_down, next_up};
use crate::num::Interval;
use crate::ops::answer::{Answer, Bounds, CurvesAnswer, Point};
use crate::ops::shape::Shape;
use crate::surface::Surface;

/// One parameter's domain `[lo, hi]`; `rounded`: the ends are roundings of irrational
/// values (`2π`), covered outward by one ulp.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ParamDomain {
    pub bounds: [f64; 2],
    pub periodic: bool,
    pub rounded: bool,
}

impl ParamDomain {
    /// The domain, outward by one ulp where its ends are rounded: it holds the exact one.
    fn outer(&self) -> [f64; 2] {
        let [lo, hi] = self.bounds;
        if self.rounded {
            [next_down(lo), next_up(hi)]
        } else {
            [lo, hi]
        }
    }

    /// An enclosure of the exact period (the exact domain's length).
    fn period(&self) -> Interval {
        let [lo, hi] = self.bounds;
        let p = Interval::point(hi) - Interval::point(lo);
        let [a, b] = self.outer();
        p.hull(&(Interval::point(b) - Interval::point(a)))
    }
}

/// The parameter domains of a shape, in the order of its `params`; `None` where the
/// shape's parameters are not checked (lines, planes, conics, shells).
pub fn domains(shape: &Shape) -> Option<Vec<ParamDomain>> {
    match shape {
        Shape::Curve(c) => Some(vec![curve_domain(c)]),
        Shape::Curve2(c) => Some(vec![curve_domain(c)]),
        Shape::Surface(s) => {
            let (u, v) = s.domain();
            let closed = s.is_closed();
            let rounded = s.domain_rounded();
            Some(
                (0..2)
                    .map(|i| ParamDomain {
                        bounds: [u, v][i],
                        periodic: closed[i],
                        rounded: rounded[i],
                    })
                    .collect(),
            )
        }
        _ => None,
    }
}

fn curve_domain<const D: usize>(c: &impl Curve<D>) -> ParamDomain {
    let (lo, hi) = c.domain();
    ParamDomain {
        bounds: [lo, hi],
        periodic: c.is_closed(),
        rounded: c.domain_rounded(),
    }
}

/// A representative of the box `[lo, hi]`: its midpoint, the finite end of a half-open
/// box, 0 for the whole line.
fn midpoint([lo, hi]: Bounds) -> f64 {
    match (lo.is_finite(), hi.is_finite()) {
        (true, true) => (lo / 2.0 + hi / 2.0).clamp(lo, hi),
        (true, false) => lo,
        (false, true) => hi,
        _ => 0.0f64.clamp(lo, hi),
    }
}

/// Rule 1 and 2 for one estimate and its box; `false` when the box is empty, or when
/// the estimate is `NaN` and its box the whole line (no number to report).
fn settle(x: &mut f64, b: &mut Bounds) -> bool {
    if b[0].is_nan() {
        b[0] = f64::NEG_INFINITY;
    }
    if b[1].is_nan() {
        b[1] = f64::INFINITY;
    }
    if b[0] > b[1] {
        return false;
    }
    let whole = b[0] == f64::NEG_INFINITY && b[1] == f64::INFINITY;
    let formed = !(x.is_nan() && whole);
    if x.is_nan() {
        *x = midpoint(*b);
    }
    *x = x.clamp(b[0], b[1]);
    formed
}

/// Rule 3 for one parameter box (module doc), before [`settle`].
fn into_domain(x: &mut f64, b: &mut Bounds, d: &ParamDomain) {
    let [lo, hi] = d.outer();
    if b[0].is_nan() || b[1].is_nan() || b[0] > b[1] {
        return;
    }
    if !d.periodic {
        if b[0] <= hi && b[1] >= lo {
            *b = [b[0].max(lo), b[1].min(hi)];
        }
        return;
    }
    let p = d.period();
    let mid = midpoint(*b);
    if lo <= mid && mid <= hi {
        // In the domain, or an arc across the seam: kept; the estimate into the box.
        if x.is_finite() && (*x < b[0] || *x > b[1]) {
            for k in [-1.0, 1.0] {
                let y = *x + k * p.midpoint();
                if b[0] <= y && y <= b[1] {
                    *x = y;
                }
            }
        }
        return;
    }
    let whole = [d.bounds[0], hi];
    let k = ((mid - d.bounds[0]) / p.midpoint()).floor();
    if !k.is_finite() || b[1] - b[0] >= p.lo() {
        *b = whole;
        return;
    }
    let shifted = Interval::from_bounds(b[0], b[1]) - Interval::point(k) * p;
    *b = [shifted.lo(), shifted.hi()];
    if x.is_finite() {
        *x -= k * p.midpoint();
    }
}

/// Rules 1–3 on one point; `false` when a number of it cannot be formed.
fn point(p: &mut Point, domains: &[Option<Vec<ParamDomain>>]) -> bool {
    let mut sound = true;
    if p.xyz_box.len() == p.xyz.len() {
        for (x, b) in p.xyz.iter_mut().zip(&mut p.xyz_box) {
            sound &= settle(x, b);
        }
    } else {
        sound &= p.xyz.iter().all(|x| !x.is_nan());
    }
    let shaped = domains.len() == p.params.len();
    for (i, params) in p.params.iter_mut().enumerate() {
        let boxes = p.param_box.as_mut().and_then(|b| b.get_mut(i));
        let dom = domains.get(i).filter(|_| shaped).and_then(|d| d.as_ref());
        match boxes {
            Some(boxes) if boxes.len() == params.len() => {
                for (j, (x, b)) in params.iter_mut().zip(boxes.iter_mut()).enumerate() {
                    if let Some(d) = dom.and_then(|d| d.get(j)) {
                        into_domain(x, b, d);
                    }
                    sound &= settle(x, b);
                }
            }
            _ => sound &= params.iter().all(|x| !x.is_nan()),
        }
    }
    for d in [&mut p.distance, &mut p.signed_distance] {
        if d.is_some_and(f64::is_nan) {
            *d = None;
            sound = false;
        }
    }
    sound
}

/// Rules 1–3 on every point of a list; unsound points are left out when `drop`.
fn points(ps: &mut Vec<Point>, domains: &[Option<Vec<ParamDomain>>], drop: bool) -> bool {
    let mut sound = true;
    ps.retain_mut(|p| {
        let ok = point(p, domains);
        sound &= ok;
        ok || !drop
    });
    sound
}

fn curves(c: &mut CurvesAnswer, domains: &[Option<Vec<ParamDomain>>], undecided: bool) -> bool {
    let mut sound = points(&mut c.points, domains, undecided);
    // Singular points stay (curve ends refer to them by index); an unsound one only
    // counts against a certified one.
    for s in &mut c.singular_points {
        sound &= point(&mut s.point, domains) || s.status == Status::Undecided;
    }
    for curve in &mut c.curves {
        let finite = |v: &crate::ops::answer::CurveVertex| {
            !v.xyz
                .iter()
                .chain(v.params.iter().flatten())
                .any(|x| x.is_nan())
        };
        if curve.status == Status::Undecided {
            curve.points.retain(finite);
        } else {
            sound &= curve.points.iter().all(finite);
        }
    }
    sound
}

/// Enforce the module's rules on an answer, with the parameter domains of its shapes
/// in input order ([`domains`]).
pub fn keep(c: &mut Certified<Answer>, domains: &[Option<Vec<ParamDomain>>]) {
    let undecided = c.status == Status::Undecided;
    let sound = match &mut c.value {
        Answer::Points(ps) => {
            let sound = points(ps, domains, undecided);
            if ps.is_empty() {
                c.value = Answer::Empty;
            }
            sound
        }
        Answer::Segment(s) | Answer::Arc(s) => point(&mut s.a, domains) & point(&mut s.b, domains),
        Answer::Ray(r) => point(&mut r.start, domains),
        Answer::Side(_, p) => {
            let formed = p.as_mut().is_none_or(|q| point(q, domains));
            if !formed {
                // The nearest point is an addition to a decided side: left out, said why.
                *p = None;
                c.reason = Some("the nearest point could not be formed".into());
            }
            true
        }
        Answer::Curves(cs) => curves(cs, domains, undecided),
        _ => true,
    };
    if !sound && !undecided {
        c.status = Status::Undecided;
        c.complete = false;
        c.reason = Some("a reported number could not be formed (not a number)".into());
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::{PI, TAU};

    fn turn() -> ParamDomain {
        ParamDomain {
            bounds: [0.0, TAU],
            periodic: true,
            rounded: true,
        }
    }

    #[test]
    fn a_box_below_the_seam_is_shifted_into_the_domain() {
        let (mut x, mut b) = (7.0 * PI / 4.0, [-PI / 2.0, 0.0]);
        into_domain(&mut x, &mut b, &turn());
        assert!(settle(&mut x, &mut b));
        // The shifted box may reach an ulp or two past 2π (the period is enclosed): an
        // arc across the seam, still holding 7π/4 and no wider than the input.
        assert!(b[0] >= 0.0 && b[1] <= next_up(next_up(TAU)), "{b:?}");
        assert!(b[0] <= 1.5 * PI && b[1] >= TAU - 1e-12, "{b:?}");
        assert!(b[0] <= x && x <= b[1]);
    }

    #[test]
    fn a_box_across_the_seam_stays_a_tight_arc() {
        let (mut x, mut b) = (TAU - 0.05, [-0.1, 0.1]);
        into_domain(&mut x, &mut b, &turn());
        assert_eq!(b, [-0.1, 0.1]);
        assert!(settle(&mut x, &mut b) && (x + 0.05).abs() < 1e-12, "{x}");
        let (mut x, mut b) = (1.0, [-TAU - 0.1, -TAU + 0.1]);
        into_domain(&mut x, &mut b, &turn());
        assert!(b[0] <= 0.0 && 0.0 <= b[1] && b[1] < 0.11, "{b:?}");
    }

    #[test]
    fn nan_estimates_take_the_box_midpoint() {
        let (mut x, mut b) = (f64::NAN, [f64::NEG_INFINITY, f64::INFINITY]);
        assert!(!settle(&mut x, &mut b) && x == 0.0, "no number to report");
        let (mut x, mut b) = (f64::NAN, [f64::NAN, 4.0]);
        assert!(settle(&mut x, &mut b) && x == 4.0 && b[0] == f64::NEG_INFINITY);
        let (mut x, mut b) = (1.1e15, [2.99, 2.99]);
        assert!(settle(&mut x, &mut b) && x == 2.99);
    }
}
