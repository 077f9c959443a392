//! Point → circle and point → ellipse of space, decided exactly (OPERATIONS.md §3.2 for
//! a space curve, with the framed conics of §1.5; issue 14 item 9; docs/CERTIFICATES.md
//! `exact`).
//!
//! A foot `q` on a plane curve is a foot of `p`'s orthogonal projection `p′` onto the
//! curve's plane: `|p − q|² = |p′ − q|² + h²`, `h` the height of `p` over the plane.
//! With the conic's exact frame ([`super::conic_plane`]: origin `P`, unnormalised
//! orthogonal `X̃`, `Ỹ`, axis `Z̃`, all rational) take the chart coordinates
//! `ξ = (x − P)·X̃`, `η = (x − P)·Ỹ`. The plane's metric in them is diagonal,
//! `|Δ|² = Δξ²/|X̃|² + Δη²/|Ỹ|²`, with rational weights, the conic is
//! `ξ²/(|X̃|²a²) + η²/(|Ỹ|²b²) = 1` (`a = b = r` for a circle), and `h² = ((p − P)·Z̃)²/|Z̃|²`:
//! every number is rational, and the feet are the points of the conic and its Apollonius
//! conic in that metric ([`super::foot2::Chart`]), solved exactly with their
//! multiplicities (2 on the evolute, 3 at its cusps).
//!
//! A foot's point is `P + ξ X̃/|X̃|² + η Ỹ/|Ỹ|²`, each coordinate correctly rounded
//! (exactly where the coefficients of the irrational chart coordinates vanish, else by
//! Ziv's loop); its parameter `t = atan2(η/(|Ỹ| b), ξ/(|X̃| a))` by Ziv's loop (exactly
//! `0` or `π` where `η = 0`). A number Ziv's loop cannot round within its cap lowers the
//! answer to `verified`. A point on a circle's axis has every point of the circle as a
//! foot (the Apollonius conic vanishes): `coincident`, the distance `√(r² + h²)` in
//! `reason` (an arc too: each of its points is a foot). Otherwise only whole circles
//! and ellipses are taken; arcs and the other conics are left to the numeric certifier
//! (`None`).

use rug::Rational;
use std::cmp::Ordering;

use super::conic_plane::{exact_frame, ExactFrame};
use super::foot2::{
    chosen, distance, every_point_a_foot, fallback_distance, feet, feet_answer, Chart,
};
use super::{ConicCut, ConicHit, QuadricForm};
use crate::certificate::Certified;
use crate::certify::univariate::RealRoot;
use crate::curve::analytic::{Analytic, Shape as CurveShape};
use crate::curve::Curve;
use crate::num::round::{round_rational, Rounded};
use crate::num::{MpfrInterval, Real};
use crate::ops::answer::{Answer, Point};
use crate::ops::rational::exact::dot;
use crate::ops::rational::rounding::{
    correctly_rounded, enclose_root, wrapped_angle, PRECISION_CAP,
};
use rug::float::Round;

type V3 = [Rational; 3];

/// The chart of the module documentation.
struct SpaceChart {
    frame: ExactFrame,
    chart: Chart,
    /// The semi-axes `(a, b)` (both `r` for a circle).
    axes: [f64; 2],
}

impl SpaceChart {
    /// The chart of the whole circle or ellipse `c` and the point `p`, with the conic's
    /// equation; `None` for other curves.
    fn of(c: &Analytic, p: &[f64; 3]) -> Option<(SpaceChart, QuadricForm<2>)> {
        let axes = match c.shape() {
            CurveShape::Circle { radius } => [radius, radius],
            CurveShape::Ellipse { a, b } => [a, b],
            _ => return None,
        };
        let frame = exact_frame(c);
        let w: V3 = std::array::from_fn(|i| {
            Rational::from_f64(p[i])
                .map(|x| x - &frame.p[i])
                .unwrap_or_default()
        });
        let g = [
            Rational::from(1) / dot(&frame.x, &frame.x),
            Rational::from(1) / dot(&frame.y, &frame.y),
        ];
        let h2 = dot(&w, &frame.z).square() / dot(&frame.z, &frame.z);
        let [a2, b2] =
            [Rational::from_f64(axes[0])?, Rational::from_f64(axes[1])?].map(|x| x.square());
        let form = QuadricForm::conic_exact([
            Rational::from(&g[0] / &a2),
            Rational::new(),
            Rational::from(&g[1] / &b2),
            Rational::new(),
            Rational::new(),
            Rational::from(-1),
        ])
        .ok()?;
        let chart = Chart {
            p: [dot(&w, &frame.x), dot(&w, &frame.y)],
            g,
            h2,
        };
        Some((SpaceChart { frame, chart, axes }, form))
    }

    /// Coordinate `i` of the foot, correctly rounded; `Err` with an outward enclosure
    /// where Ziv's loop reaches its cap.
    fn coordinate(&self, h: &ConicHit, i: usize) -> Result<Rounded, Rounded> {
        let (f, g) = (&self.frame, &self.chart.g);
        let cx = Rational::from(&f.x[i] * &g[0]);
        let cy = Rational::from(&f.y[i] * &g[1]);
        // A chart coordinate with a zero coefficient does not enter.
        let term = |c: &Rational, r: &RealRoot| -> Option<Rational> {
            if c.cmp0() == Ordering::Equal {
                Some(Rational::new())
            } else {
                r.exact().map(|x| Rational::from(c * x))
            }
        };
        if let (Some(a), Some(b)) = (term(&cx, &h.x), term(&cy, &h.y)) {
            return Ok(round_rational(&(a + b + &f.p[i])));
        }
        let (mut x, mut y) = (h.x.clone(), h.y.clone());
        rounded_or_enclosed(|bits| {
            let q = |v: &Rational| MpfrInterval::from_rational(v, bits);
            q(&f.p[i]) + enclose_root(&mut x, bits) * q(&cx) + enclose_root(&mut y, bits) * q(&cy)
        })
    }

    /// The curve parameter of the foot, correctly rounded; `Err` with an outward
    /// enclosure where Ziv's loop reaches its cap.
    fn parameter(&self, h: &ConicHit) -> Result<Rounded, Rounded> {
        if h.y.exact().is_some_and(|y| y.cmp0() == Ordering::Equal) {
            // On the X axis: ξ ≠ 0 (the centre is not on the conic), its sign decides.
            let left = h.x.compare(&Rational::new()) == Ordering::Less;
            let pi = |bits| MpfrInterval::point(0.0, bits).pi_like();
            return if left {
                rounded_or_enclosed(pi)
            } else {
                Ok(Rounded::exact(0.0))
            };
        }
        let (mut x, mut y) = (h.x.clone(), h.y.clone());
        let f = &self.frame;
        rounded_or_enclosed(|bits| {
            let q = |v: &Rational| MpfrInterval::from_rational(v, bits);
            let local = |r: &mut RealRoot, e: &V3, axis: f64| {
                enclose_root(r, bits) / q(&dot(e, e)).sqrt() / MpfrInterval::point(axis, bits)
            };
            let xl = local(&mut x, &f.x, self.axes[0]);
            let yl = local(&mut y, &f.y, self.axes[1]);
            wrapped_angle(&yl, &xl)
        })
    }
}

/// The number `enclose` encloses, correctly rounded by Ziv's loop; at its cap `Err` with
/// the enclosure at the cap rounded outward to doubles (its midpoint as the value).
fn rounded_or_enclosed(mut enclose: impl FnMut(u32) -> MpfrInterval) -> Result<Rounded, Rounded> {
    if let Some(r) = correctly_rounded(&mut enclose) {
        return Ok(r);
    }
    let x = enclose(PRECISION_CAP);
    Err(Rounded {
        nearest: x.midpoint().to_f64(),
        lo: x.lo().to_f64_round(Round::Down),
        hi: x.hi().to_f64_round(Round::Up),
    })
}

/// Every foot of the perpendicular from `p` onto a whole circle or ellipse of space,
/// exactly (or with `nearest` the nearest foot); `None` where the curve is another one
/// or the pair is left to the numeric path (module documentation). Past `deadline` the
/// feet are `undecided` ("time limit reached").
pub(crate) fn project_point_conic3(
    p: [f64; 3],
    c: &Analytic,
    nearest: bool,
    deadline: Option<std::time::Instant>,
) -> Option<Certified<Answer>> {
    let (sc, form) = SpaceChart::of(c, &p)?;
    let cut = match feet(&form, &sc.chart, deadline)? {
        // An arc of a conic: its ends and domain are left to the numeric path.
        Ok(_) if !c.is_closed() => return None,
        Ok(cut) => cut,
        Err(()) => {
            // A circle (or an arc of it) seen from its axis: |p − q|² = r² + h² for
            // every q.
            let r2 = Rational::from_f64(sc.axes[0])?.square();
            return Some(every_point_a_foot("circle", &(r2 + &sc.chart.h2)));
        }
    };
    let ConicCut::Points(hits) = &cut.value else {
        return None;
    };
    let chosen = chosen(hits, &sc.chart, nearest)?;
    let mut all_rounded = true;
    let points: Vec<Point> = chosen
        .into_iter()
        .map(|i| {
            let h = &hits[i];
            let xyz: Vec<Result<Rounded, Rounded>> = (0..3).map(|k| sc.coordinate(h, k)).collect();
            let t = sc.parameter(h);
            let d = distance(h, &sc.chart);
            all_rounded &= xyz.iter().all(Result::is_ok) && t.is_ok() && d.is_some();
            let xyz: Vec<Rounded> = xyz.into_iter().map(|r| r.unwrap_or_else(|e| e)).collect();
            let t = t.unwrap_or_else(|e| e);
            Point {
                xyz: xyz.iter().map(|r| r.nearest).collect(),
                xyz_box: xyz.iter().map(|r| [r.lo, r.hi]).collect(),
                params: vec![vec![t.nearest]],
                param_box: Some(vec![vec![[t.lo, t.hi]]]),
                multiplicity: h.multiplicity,
                distance: Some(d.map_or_else(|| fallback_distance(h, &sc.chart), |d| d.nearest)),
                nearest: nearest.then_some(true),
                ..Default::default()
            }
        })
        .collect();
    Some(feet_answer(&cut, points, all_rounded))
}
