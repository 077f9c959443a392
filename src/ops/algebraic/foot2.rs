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
//! The pair's continuum, `G ≡ 0` (`p` the centre of a circle, where every point of the
//! circle is a foot at the distance `r`), is answered exactly as kind `coincident` with
//! the distance in `reason`. Distances are correctly rounded (exactly from rationals, or
//! by Ziv's strategy); with `nearest` the nearest foot is chosen by enclosures of the
//! squared distances refined until it is strictly nearest, and an unresolved tie is left
//! to the numeric path.
//!
//! The same construction serves conics of space ([`super::foot3`]) through a [`Chart`]:
//! rational chart coordinates whose metric is diagonal with rational weights, under which
//! the Apollonius conic keeps rational coefficients.

use rug::Rational;
use std::cmp::Ordering;

use super::conic_conic::intersect_conic_conic_until;
use super::pairs::{not_correctly_rounded, plane_conic, PlaneConic};
use super::{ConicCut, ConicHit, QuadricForm};
use crate::certificate::{Arithmetic, Certified};
use crate::certify::univariate::RealRoot;
use crate::num::round::{sqrt_rational, Rounded};
use crate::num::{Interval, MpfrInterval};
use crate::ops::answer::{Answer, Point};
use crate::ops::rational::rounding::{correctly_rounded, enclose_root, PRECISION_CAP};
use crate::ops::shape::Shape;

/// A point and the Euclidean metric of a conic's chart (§3.2): the squared distance
/// from `p` to a chart point `(x, y)` is `g₀(x − p₀)² + g₁(y − p₁)² + h2`. A plane conic
/// has `g = (1, 1)`, `h2 = 0`; a conic of space is charted by its unnormalised frame
/// (`g = (1/|X̃|², 1/|Ỹ|²)`, `h2` the squared height of `p` over its plane), so every
/// number stays rational.
pub(super) struct Chart {
    pub(super) p: [Rational; 2],
    pub(super) g: [Rational; 2],
    pub(super) h2: Rational,
}

impl Chart {
    /// The chart of a plane conic.
    fn plane(p: [Rational; 2]) -> Chart {
        Chart {
            p,
            g: [Rational::from(1), Rational::from(1)],
            h2: Rational::new(),
        }
    }

    /// The coefficients of the Apollonius conic `G` of `p` for the conic `f` (module
    /// documentation), in the chart's metric: the tangent `(F_y, −F_x)` is orthogonal to
    /// `p − q` when `g₀(p₀ − x)F_y − g₁(p₁ − y)F_x = 0`.
    pub(super) fn apollonius(&self, f: &[Rational; 6]) -> [Rational; 6] {
        let [a, b, c, d, e, _] = f;
        let [px, py] = &self.p;
        let [gx, gy] = &self.g;
        let m = |x: &Rational, y: &Rational| Rational::from(x * y);
        [
            -m(gx, b),
            (m(gy, a) - m(gx, c)) * 2u32,
            m(gy, b),
            m(gx, &(m(b, px) - e)) - m(gy, a) * py * 2u32,
            m(gx, c) * px * 2u32 + m(gy, &(d - m(b, py))),
            m(gx, e) * px - m(gy, d) * py,
        ]
    }

    /// The exact squared distance to the chart point `(x, y)`.
    fn distance2_exact(&self, x: &Rational, y: &Rational) -> Rational {
        let dx = Rational::from(&self.p[0] - x).square() * &self.g[0];
        let dy = Rational::from(&self.p[1] - y).square() * &self.g[1];
        dx + dy + &self.h2
    }
}

/// A foot's algebraic chart coordinates, refined on demand.
#[derive(Clone)]
pub(super) struct Foot {
    x: RealRoot,
    y: RealRoot,
}

impl Foot {
    pub(super) fn of(h: &ConicHit) -> Foot {
        Foot {
            x: h.x.clone(),
            y: h.y.clone(),
        }
    }

    /// The squared distance to the chart's point, enclosed at `bits` (the coordinates
    /// refined to that width, then enclosing MPFR interval arithmetic).
    fn distance2(&mut self, chart: &Chart, bits: u32) -> MpfrInterval {
        let q = |v: &Rational| MpfrInterval::from_rational(v, bits);
        let dx = q(&chart.p[0]) - enclose_root(&mut self.x, bits);
        let dy = q(&chart.p[1]) - enclose_root(&mut self.y, bits);
        dx.sqr() * q(&chart.g[0]) + dy.sqr() * q(&chart.g[1]) + q(&chart.h2)
    }
}

/// The distance from the chart's point to the foot, correctly rounded (`None`: Ziv's
/// cap).
pub(super) fn distance(h: &ConicHit, chart: &Chart) -> Option<Rounded> {
    if let (Some(x), Some(y)) = (h.x.exact(), h.y.exact()) {
        return Some(sqrt_rational(&chart.distance2_exact(x, y)));
    }
    let mut foot = Foot::of(h);
    correctly_rounded(|bits| foot.distance2(chart, bits).sqrt())
}

/// The distance at 64 bits when Ziv's loop could not round it (the answer's status is
/// lowered by [`not_correctly_rounded`]).
pub(super) fn fallback_distance(h: &ConicHit, chart: &Chart) -> f64 {
    Foot::of(h).distance2(chart, 64).sqrt().midpoint().to_f64()
}

/// The index of the foot strictly nearest to the chart's point, proven by enclosures of
/// the squared distances; `None` while two of them cannot be separated within the
/// precision cap.
fn nearest_index(hits: &[ConicHit], chart: &Chart) -> Option<usize> {
    let mut feet: Vec<Foot> = hits.iter().map(Foot::of).collect();
    let mut bits = 64;
    while bits <= PRECISION_CAP {
        let d: Vec<MpfrInterval> = feet.iter_mut().map(|f| f.distance2(chart, bits)).collect();
        let best = (0..d.len())
            .min_by(|&i, &j| d[i].hi().partial_cmp(d[j].hi()).unwrap_or(Ordering::Equal))?;
        if (0..d.len()).all(|j| j == best || d[best].hi() < d[j].lo()) {
            return Some(best);
        }
        bits *= 2;
    }
    None
}

/// The feet of the chart's point on the conic `form`: `Some(Err(()))` when every point
/// of the conic is a foot (`G ≡ 0`: the centre of a circle, or a point on a circle's
/// axis), `None` when the pair is left to the numeric path (a line pair, or the exact
/// solver's own refusal); past `deadline` the answer is `undecided`.
pub(super) fn feet(
    form: &QuadricForm<2>,
    chart: &Chart,
    deadline: Option<std::time::Instant>,
) -> Option<Result<Certified<ConicCut>, ()>> {
    let g = chart.apollonius(&form.coefficients());
    if g.iter().all(|x| *x == 0) {
        return Some(Err(()));
    }
    let cut =
        intersect_conic_conic_until(form, &QuadricForm::conic_exact(g).ok()?, deadline).ok()?;
    // The conic has no component in common with its own Apollonius conic unless it is
    // degenerate (a line pair): left to the numeric path.
    matches!(cut.value, ConicCut::Points(_)).then_some(Ok(cut))
}

/// The exact answer for a continuum of feet: every point of the curve is at the same
/// distance `d²` (`√` correctly rounded), so every point is a foot and every point is
/// nearest (docs/FORMAT.md "Projections": kind `coincident`).
pub(crate) fn every_point_a_foot(what: &str, d2: &Rational) -> Certified<Answer> {
    let d = sqrt_rational(d2);
    let mut r = Certified::exact(Answer::Coincident, Arithmetic::Rational, 53);
    r.reason = Some(format!(
        "every point of the {what} is a foot, at the same distance {:?}{}",
        d.nearest,
        if d.lo == d.hi { "" } else { " (rounded)" }
    ));
    r
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
    let chart = Chart::plane([Rational::from_f64(p[0])?, Rational::from_f64(p[1])?]);
    let cut = match feet(&conic.form, &chart, deadline)? {
        Ok(cut) => cut,
        Err(()) => return circle_from_centre(&conic.form, &chart),
    };
    let ConicCut::Points(hits) = &cut.value else {
        return None;
    };
    let chosen = chosen(hits, &chart, nearest)?;
    let mut all_rounded = true;
    let points: Vec<Point> = chosen
        .into_iter()
        .map(|i| {
            let h = &hits[i];
            let b: [Interval; 2] =
                std::array::from_fn(|k| Interval::from_bounds(h.point[k].lo, h.point[k].hi));
            let (t, rounded) = conic.point(h, &b);
            let d = distance(h, &chart);
            all_rounded &= rounded && d.is_some();
            Point {
                xyz: h.nearest().to_vec(),
                xyz_box: b.iter().map(|x| [x.lo(), x.hi()]).collect(),
                params: vec![t.iter().map(|x| x.0).collect()],
                param_box: Some(vec![t.iter().map(|x| x.1).collect()]),
                multiplicity: h.multiplicity,
                distance: Some(d.map_or_else(|| fallback_distance(h, &chart), |d| d.nearest)),
                nearest: nearest.then_some(true),
                ..Default::default()
            }
        })
        .collect();
    Some(feet_answer(&cut, points, all_rounded))
}

/// The indices of the feet to report: all, or with `nearest` the proven nearest one
/// (`None` while a tie is unresolved).
pub(super) fn chosen(hits: &[ConicHit], chart: &Chart, nearest: bool) -> Option<Vec<usize>> {
    Some(if nearest && !hits.is_empty() {
        vec![nearest_index(hits, chart)?]
    } else {
        (0..hits.len()).collect()
    })
}

/// The answer of the feet `points` under the certificate of the conic ∩ conic cut, in
/// the order of the curve's parameter (as the numeric path reports feet), lowered to
/// `verified` when a number could not be correctly rounded.
pub(super) fn feet_answer(
    cut: &Certified<ConicCut>,
    mut points: Vec<Point>,
    all_rounded: bool,
) -> Certified<Answer> {
    points.sort_by(|a, b| {
        a.params[0]
            .partial_cmp(&b.params[0])
            .unwrap_or(Ordering::Equal)
    });
    let mut r = cut.clone_with(Answer::from_points(points));
    if !all_rounded {
        not_correctly_rounded(&mut r);
    }
    r
}

/// Every point of a circle is a foot of its centre (`G ≡ 0`): the squared distance is
/// the radius's square, `−f/a` of the circle `a(x² + y²) + dx + ey + f` written about
/// its centre (`F(p) = a·|p − c|² − a r² = −a r²` at the centre).
fn circle_from_centre(form: &QuadricForm<2>, chart: &Chart) -> Option<Certified<Answer>> {
    let f = form.coefficients();
    let at_p = f[0].clone() * chart.p[0].clone().square()
        + Rational::from(&f[1] * &chart.p[0]) * &chart.p[1]
        + f[2].clone() * chart.p[1].clone().square()
        + Rational::from(&f[3] * &chart.p[0])
        + Rational::from(&f[4] * &chart.p[1])
        + &f[5];
    let r2 = -(at_p / &f[0]);
    match r2.cmp0() {
        Ordering::Greater => Some(every_point_a_foot("circle", &r2)),
        Ordering::Less => {
            let mut r = Certified::exact(Answer::Empty, Arithmetic::Rational, 53);
            r.reason = Some("the conic has no real point".into());
            Some(r)
        }
        // A one-point conic: its point is `p`, left to the numeric path.
        Ordering::Equal => None,
    }
}
