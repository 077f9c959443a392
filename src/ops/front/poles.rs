//! A space curve against a whole sphere or ellipsoid near one of its poles, solved on
//! one chart with new poles (OPERATIONS.md §14.1–§14.2 with the corrected (14.5);
//! issue 14 item 4).
//!
//! On the surface's own `(u, v)` the whole pole edge `v = ±π/2` maps to one point, so
//! the curve–surface system is singular along it and a root at (or very near) a pole
//! cannot be isolated: the answer was `complete: false` with the root missing. Here,
//! when the curve is not proven to stay [`NEAR`] away from both poles, the system is
//! solved on the re-parametrised surface [`Repole`] instead, whose two new poles are
//! proven off the curve:
//!
//! 1. candidate pole directions (the 26 directions of `{−1, 0, 1}³`, in the unit-sphere
//!    coordinates `q = diag(k)⁻¹ · local(x)` of the surface, where the surface is the
//!    unit sphere) are ranked by their distance from the curve's walk samples; pairs at
//!    an angle of 60° or more, and not near antipodal (`cos ≥ −0.9`, so the net of §14.2
//!    is well conditioned), are tried best first;
//! 2. a pair is taken when both new pole points are proven off the curve: the curve's
//!    enclosure `q([t₀, t₁])`, by interval evaluation over pieces of its domain
//!    (bisected until proven, [`PROOF_BOXES`] pieces at most), lies at a positive
//!    distance from the enclosure of the exact unit pole `P/|P|` ([`proven_away`]);
//! 3. no root of the curve can then lie at a new pole, and the chart covers the whole
//!    surface, so the chart's roots are all the roots: `complete` carries over. A curve
//!    for which no pair is proven keeps the surface's own parameters (as before).
//!
//! Every root is mapped back to the surface's own `(u, v)` by (14.7)
//! ([`Repole::original_params`]): its unit-sphere point is enclosed twice — by the
//! net's jet over the root's chart box, and by `q` of the curve's point box (both hold
//! the exact point `X(α, λ) = q(c(t))` of the exact root) — and `u = atan2(Y, X)`,
//! `v = atan2(Z, √(X² + Y²))` are evaluated in interval arithmetic over the meet of the
//! two, so the reported boxes hold the exact parameters. The seam is a regular curve of
//! the chart, so a root on it is found once; its `u` box is the arc across the seam
//! (`[−ε, ε]`, docs/FORMAT.md). At a pole `u` is not determined (every angle is one): a
//! root whose box holds the pole reports `u = 0` with the whole turn `[0, 2π]` as its
//! box, like the exact paths.

use std::f64::consts::FRAC_PI_2;

use super::seeds::{curve_samples, surface_nodes, TURN};
use crate::certificate::Certified;
use crate::curve::{AnyCurve3, Curve};
use crate::error::GeomError;
use crate::num::vector::{lift, norm_f64, normalize, sub};
use crate::num::{Interval, Real};
use crate::ops::algebraic::exact_line::{angle, param};
use crate::ops::certified::CertifiedPoint;
use crate::ops::intersect::intersect_curve_surface;
use crate::ops::options::Options;
use crate::surface::pencil::Pole;
use crate::surface::repole::{Repole, SphereMapped};
use crate::surface::validate::FULL_TURN;
use crate::surface::AnySurface;

/// A curve proven at least this far (in the unit-sphere coordinates `q`) from both
/// poles keeps the surface's own parameters: the answer is unchanged there. (The
/// re-poled chart's root boxes come out a few times wider, so it is used only where it
/// is needed: the corpus' curves passing 0.11 and 0.22 from a pole keep their answers.)
pub(crate) const NEAR: f64 = 0.05;

/// The most pieces of the curve's domain evaluated by one proof of [`proven_away`].
const PROOF_BOXES: usize = 4096;

/// The most pole pairs tried.
const TRIES: usize = 4;

type Roots = Certified<Vec<CertifiedPoint<3>>>;

/// The roots of `curve` on a whole sphere or ellipsoid `s`, in the surface's own
/// parameters `(u, v, t)`, solved on a chart with new poles (module doc). `None`: not a
/// whole sphere or ellipsoid, the curve is proven away from its poles, or no new poles
/// are proven off the curve — the caller solves on the surface's own parameters.
pub(crate) fn curve_near_poles(
    s: &AnySurface,
    curve: &AnyCurve3,
    opts: &Options,
) -> Option<Result<Roots, GeomError>> {
    match s {
        AnySurface::Sphere(x) => on_new_poles(x, curve, opts),
        AnySurface::Ellipsoid(x) => on_new_poles(x, curve, opts),
        _ => None,
    }
}

fn on_new_poles<S: SphereMapped>(
    s: &S,
    curve: &AnyCurve3,
    opts: &Options,
) -> Option<Result<Roots, GeomError>> {
    if s.domain() != (FULL_TURN, [-FRAC_PI_2, FRAC_PI_2]) {
        return None;
    }
    let old = [[0.0, 0.0, 1.0], [0.0, 0.0, -1.0]];
    if old.iter().all(|p| proven_away(s, curve, p, NEAR)) {
        return None;
    }
    let samples = match curve_samples(curve, opts) {
        Ok(x) => x,
        Err(e) => return Some(Err(e)),
    };
    let qs: Vec<[f64; 3]> = samples
        .iter()
        .map(|&(t, _)| unit_coords(s, &curve.jet(&t, 0)[0]))
        .collect();
    for [p1, p2] in pole_pairs(&qs).into_iter().take(TRIES) {
        if proven_away(s, curve, &p1, 0.0) && proven_away(s, curve, &p2, 0.0) {
            let chart = Repole::new(s.clone(), Pole::Direction(p1), Pole::Direction(p2)).ok()?;
            return Some(solve(&chart, curve, &samples, opts));
        }
    }
    None
}

/// The unit-sphere coordinates `q = diag(k)⁻¹ · local(x)` of a world point (the
/// surface is `|q| = 1`, its pole `v = π/2` is `q = (0, 0, 1)`); an enclosure for
/// interval types (the frame's [`to_local`](crate::surface::frame::Frame::to_local)
/// encloses the exact local coordinates, the division is outward rounded).
fn unit_coords<S: SphereMapped, T: Real>(s: &S, x: &[T; 3]) -> [T; 3] {
    let (local, _) = s.sphere_frame().to_local(x);
    let k = s.sphere_scales();
    std::array::from_fn(|i| local[i].clone() / x[0].lift(k[i]))
}

/// Whether the curve is proven farther than `margin` from the unit pole `P/|P|` (in
/// `q`): `|q(c(t)) − P/|P||² > margin²` for every `t` of the domain, shown on pieces of
/// the domain bisected until each is proven (the pieces share their ends, so they
/// cover the domain whatever the rounding). `false` when [`PROOF_BOXES`] pieces do
/// not suffice.
fn proven_away<S: SphereMapped>(s: &S, curve: &AnyCurve3, p: &[f64; 3], margin: f64) -> bool {
    let like = Interval::point(0.0);
    let pole = normalize(&lift(&like, p));
    let bound = Interval::point(margin).sqr();
    let (lo, hi) = curve.domain();
    let mut todo = vec![(lo, hi)];
    let mut spent = 0;
    while let Some((a, b)) = todo.pop() {
        spent += 1;
        if spent > PROOF_BOXES {
            return false;
        }
        let x = &curve.jet(&Interval::from_bounds(a, b), 0)[0];
        let d = sub(&unit_coords(s, x), &pole);
        let dist = d[0].sqr() + d[1].sqr() + d[2].sqr();
        if dist.lo() > bound.hi() {
            continue;
        }
        let m = a + (b - a) / 2.0;
        if !(a < m && m < b) {
            return false;
        }
        todo.extend([(a, m), (m, b)]);
    }
    true
}

/// The candidate pairs of new poles, best first (module doc, step 1): each direction's
/// score is its least distance from the sampled curve points `qs`.
fn pole_pairs(qs: &[[f64; 3]]) -> Vec<[[f64; 3]; 2]> {
    let dirs: Vec<[f64; 3]> = (0..27)
        .map(|i| {
            [
                (i % 3) as f64 - 1.0,
                ((i / 3) % 3) as f64 - 1.0,
                (i / 9) as f64 - 1.0,
            ]
        })
        .filter(|d| d.iter().any(|&x| x != 0.0))
        .collect();
    let unit = |d: &[f64; 3]| d.map(|x| x / norm_f64(d));
    let score = |d: &[f64; 3]| {
        let e = unit(d);
        qs.iter()
            .map(|q| norm_f64(&std::array::from_fn::<f64, 3, _>(|i| q[i] - e[i])))
            .fold(f64::INFINITY, f64::min)
    };
    let scores: Vec<f64> = dirs.iter().map(score).collect();
    let mut pairs = Vec::new();
    for i in 0..dirs.len() {
        for j in i + 1..dirs.len() {
            let (a, b) = (unit(&dirs[i]), unit(&dirs[j]));
            let cos: f64 = (0..3).map(|k| a[k] * b[k]).sum();
            if (-0.9..=0.5).contains(&cos) {
                pairs.push((scores[i].min(scores[j]), [dirs[i], dirs[j]]));
            }
        }
    }
    pairs.sort_by(|a, b| b.0.total_cmp(&a.0));
    pairs.into_iter().map(|(_, p)| p).collect()
}

/// The roots on the chart, mapped back to the surface's own parameters.
fn solve<S: SphereMapped>(
    chart: &Repole<S>,
    curve: &AnyCurve3,
    samples: &[(f64, f64)],
    opts: &Options,
) -> Result<Roots, GeomError> {
    let roots = intersect_curve_surface(
        chart,
        curve,
        samples,
        &surface_nodes(chart, opts)?,
        TURN,
        &opts.precision,
        &opts.certify(),
    )?;
    Ok(roots.map(|ps| ps.into_iter().map(|p| back(chart, p)).collect()))
}

/// One root `(α, λ, t)` of the chart as `(u, v, t)` of the surface (module doc).
fn back<S: SphereMapped>(chart: &Repole<S>, mut p: CertifiedPoint<3>) -> CertifiedPoint<3> {
    let e = &p.root.enclosure;
    let by_chart = chart.net().jet(&e[0], &e[1], 0).swap_remove(0);
    let by_curve = unit_coords(chart.surface(), &p.point_box);
    let x: [Interval; 3] = std::array::from_fn(|i| {
        let both = by_chart[i].intersection(&by_curve[i]);
        if both.is_empty() {
            by_chart[i]
        } else {
            both
        }
    });
    let (u0, v0) = chart.original_params(&p.root.params[0], &p.root.params[1]);
    let (u, u_box) = if x[0].contains_zero() && x[1].contains_zero() {
        // The box holds the pole: every angle is its u.
        let turn = x[0].pi_like() * Interval::point(2.0);
        (0.0, Interval::from_bounds(0.0, turn.hi()))
    } else {
        let (mid, [lo, hi]) = param(angle(&x[1], &x[0]));
        let u = if (lo..=hi).contains(&u0) { u0 } else { mid };
        (u, Interval::from_bounds(lo, hi))
    };
    let rho = (x[0].sqr() + x[1].sqr()).sqrt();
    let v_box = x[2].atan2(&rho);
    let v = v0.clamp(v_box.lo(), v_box.hi());
    p.root.params[0] = u;
    p.root.params[1] = v;
    p.root.enclosure[0] = u_box;
    p.root.enclosure[1] = v_box;
    p
}
