//! Point → plane conic projection decided exactly (OPERATIONS.md §3.2 for a curve in
//! the plane, with the implicit conic of §1.7 eq. (1.19); docs/CERTIFICATES.md `exact`).
//!
//! A foot `q` of the perpendicular from `p` onto the conic `F(x, y) = 0` is a point of
//! the conic where `p − q` is parallel to the normal `∇F(q)`:
//!
//! `G(q) = (p_x − x)·F_y(q) − (p_y − y)·F_x(q) = 0`,
//!
//! which for `F = a x² + b xy + c y² + d x + e y + f` is again a conic (the Apollonius
//! conic of `p`) with rational coefficients
//! `[−b, 2(a − c), b, b p_x − e − 2a p_y, 2c p_x + d − b p_y, e p_x − d p_y]`.
//! The feet are therefore exactly the points of `F ∩ G`, found by the exact conic ∩
//! conic solver, and the intersection multiplicity of a foot is its multiplicity as a
//! critical point of the squared distance: 1 for a simple foot, 2 for a point `p` on the
//! evolute, 3 at a cusp of the evolute (the centre of curvature of a vertex).
//!
//! Only the pair's continuum is left to the numeric path: `G ≡ 0` (`p` the centre of a
//! circle, where every point of the circle is a foot). Distances are correctly rounded
//! (exactly from rationals, or by Ziv's strategy); with `nearest` the nearest foot is
//! chosen by enclosures of the squared distances refined until it is strictly nearest,
//! and an unresolved tie is also left to the numeric path.

use rug::Rational;
use std::cmp::Ordering;

use super::conic_conic::intersect_conic_conic_until;
use super::pairs::{not_correctly_rounded, plane_conic, PlaneConic};
use super::{ConicCut, ConicHit, QuadricForm};
use crate::certificate::Certified;
use crate::certify::univariate::RealRoot;
use crate::num::round::{sqrt_rational, Rounded};
use crate::num::{Interval, MpfrInterval};
use crate::ops::answer::{Answer, Point};
use crate::ops::rational::rounding::{correctly_rounded, enclose_root, PRECISION_CAP};
use crate::ops::shape::Shape;

/// The coefficients of the Apollonius conic `G` of `p` for the conic `f` (module
/// documentation).
fn apollonius(f: &[Rational; 6], p: &[Rational; 2]) -> [Rational; 6] {
    let [a, b, c, d, e, _] = f;
    let [px, py] = p;
    [
        Rational::from(-b),
        Rational::from(a - c) * 2u32,
        b.clone(),
        Rational::from(b * px) - e - Rational::from(a * py) * 2u32,
        Rational::from(c * px) * 2u32 + d - Rational::from(b * py),
        Rational::from(e * px) - Rational::from(d * py),
    ]
}

/// A foot's algebraic coordinates, refined on demand.
#[derive(Clone)]
struct Foot {
    x: RealRoot,
    y: RealRoot,
}

impl Foot {
    fn of(h: &ConicHit) -> Foot {
        Foot {
            x: h.x.clone(),
            y: h.y.clone(),
        }
    }

    /// The squared distance to `p`, enclosed at `bits` (the coordinates refined to
    /// that width, then enclosing MPFR interval arithmetic).
    fn distance2(&mut self, p: &[Rational; 2], bits: u32) -> MpfrInterval {
        let dx = MpfrInterval::from_rational(&p[0], bits) - enclose_root(&mut self.x, bits);
        let dy = MpfrInterval::from_rational(&p[1], bits) - enclose_root(&mut self.y, bits);
        dx.sqr() + dy.sqr()
    }
}

/// The distance from `p` to the foot, correctly rounded (`None`: Ziv's cap).
fn distance(h: &ConicHit, p: &[Rational; 2]) -> Option<Rounded> {
    if let (Some(x), Some(y)) = (h.x.exact(), h.y.exact()) {
        let d2 = Rational::from(&p[0] - x).square() + Rational::from(&p[1] - y).square();
        return Some(sqrt_rational(&d2));
    }
    let mut foot = Foot::of(h);
    correctly_rounded(|bits| foot.distance2(p, bits).sqrt())
}

/// The index of the foot strictly nearest to `p`, proven by enclosures of the squared
/// distances; `None` while two of them cannot be separated within the precision cap.
fn nearest_index(hits: &[ConicHit], p: &[Rational; 2]) -> Option<usize> {
    let mut feet: Vec<Foot> = hits.iter().map(Foot::of).collect();
    let mut bits = 64;
    while bits <= PRECISION_CAP {
        let d: Vec<MpfrInterval> = feet.iter_mut().map(|f| f.distance2(p, bits)).collect();
        let best = (0..d.len())
            .min_by(|&i, &j| d[i].hi().partial_cmp(d[j].hi()).unwrap_or(Ordering::Equal))?;
        if (0..d.len()).all(|j| j == best || d[best].hi() < d[j].lo()) {
            return Some(best);
        }
        bits *= 2;
    }
    None
}

/// Every foot of the perpendicular from `p` onto a whole `circle2` or `ellipse2` or a
/// `conic2`, exactly (or with `nearest` the nearest foot); `None` where the pair is not
/// one of these or is left to the numeric path (module documentation). Past `deadline`
/// the feet are `undecided` ("time limit reached", [`intersect_conic_conic_until`]).
pub(crate) fn project_point_conic2(
    p: [f64; 2],
    onto: &Shape,
    nearest: bool,
    deadline: Option<std::time::Instant>,
) -> Option<Certified<Answer>> {
    let conic: PlaneConic = plane_conic(onto)?;
    let pr = [Rational::from_f64(p[0])?, Rational::from_f64(p[1])?];
    let g = apollonius(&conic.form.coefficients(), &pr);
    if g.iter().all(|x| *x == 0) {
        return None;
    }
    let cut =
        intersect_conic_conic_until(&conic.form, &QuadricForm::conic_exact(g).ok()?, deadline)
            .ok()?;
    let ConicCut::Points(hits) = &cut.value else {
        // The conic has no component in common with its own Apollonius conic unless it
        // is degenerate (a line pair): left to the numeric path.
        return None;
    };
    let chosen: Vec<usize> = if nearest && !hits.is_empty() {
        vec![nearest_index(hits, &pr)?]
    } else {
        (0..hits.len()).collect()
    };
    let mut all_rounded = true;
    let points: Vec<Point> = chosen
        .into_iter()
        .map(|i| {
            let h = &hits[i];
            let b: [Interval; 2] =
                std::array::from_fn(|k| Interval::from_bounds(h.point[k].lo, h.point[k].hi));
            let (t, rounded) = conic.point(h, &b);
            let d = distance(h, &pr);
            all_rounded &= rounded && d.is_some();
            Point {
                xyz: h.nearest().to_vec(),
                xyz_box: b.iter().map(|x| [x.lo(), x.hi()]).collect(),
                params: vec![t.iter().map(|x| x.0).collect()],
                param_box: Some(vec![t.iter().map(|x| x.1).collect()]),
                multiplicity: h.multiplicity,
                distance: Some(d.map_or_else(|| fallback_distance(h, &pr), |d| d.nearest)),
                nearest: nearest.then_some(true),
                ..Default::default()
            }
        })
        .collect();
    // In the order of the curve's parameter, as the numeric path reports feet.
    let mut points = points;
    points.sort_by(|a, b| {
        a.params[0]
            .partial_cmp(&b.params[0])
            .unwrap_or(Ordering::Equal)
    });
    let mut r = cut.clone_with(Answer::from_points(points));
    if !all_rounded {
        not_correctly_rounded(&mut r);
    }
    Some(r)
}

/// The distance at 64 bits when Ziv's loop could not round it (the answer's status is
/// lowered by [`not_correctly_rounded`]).
fn fallback_distance(h: &ConicHit, p: &[Rational; 2]) -> f64 {
    Foot::of(h).distance2(p, 64).sqrt().midpoint().to_f64()
}
