//! The float path of surface ∩ surface (OPERATIONS.md §9.1–§9.6): stage 1 start points,
//! stage 2 marches in both directions from each start point not yet covered (§9.4
//! "Assembly"), contact candidates verified into isolated contact points, and the
//! intermediate point of a traced curve (§9.6).

use super::contact::locate_contact;
use super::corrector::{plane_newton, space_point};
use super::operand::Pair;
use super::start::starting_points;
use super::trace::{Direction, Start, Tracer};
use super::types::{CurveEnd, CurvePoint, IntersectionCurve, SingularKind, SurfaceIntersectionF64};
use crate::error::GeomError;
use crate::num::vector::{dot, norm_f64, sub};
use crate::surface::Surface;

/// The most contact candidates handed to the locator (nearest first).
const MAX_CONTACT_SEEDS: usize = 64;

/// Every curve and singular point the float path finds (§9.2–§9.5). Once the
/// certifier's deadline has passed or the float stage's share of `max_boxes` is spent
/// ([`Pair::spend`]), no new branch is traced and no contact located (issue 20): what
/// was found seeds the certified stage, whose completeness proof does not rely on it.
pub fn trace_all<R: Surface, S: Surface>(pair: &Pair<'_, R, S>) -> SurfaceIntersectionF64 {
    let late = || pair.spend(1);
    let (mut starts, contacts) = starting_points(pair);
    let mut tracer = Tracer::new(pair);
    let mut curves: Vec<IntersectionCurve> = Vec::new();
    while let Some(s) = starts.pop() {
        if late() {
            break;
        }
        if curves.iter().any(|c| on_curve(pair, c, &s)) {
            continue;
        }
        let c = trace_branch(&mut tracer, s.x, &mut starts);
        if !collapsed(pair, &c) {
            curves.push(c);
        }
    }
    let reach = 0.5;
    for x in contacts.into_iter().take(MAX_CONTACT_SEEDS) {
        if late() {
            break;
        }
        if let Some(c) = locate_contact(pair, x, reach, SingularKind::Contact) {
            tracer.add_singular(c);
        }
    }
    SurfaceIntersectionF64 {
        curves,
        singular_points: tracer.singular,
    }
}

/// A "curve" that is one singular point: both ends at the same singular point and no
/// longer than `δ_len` (a start point on an iso-line that passes through a cone's apex
/// marches into the apex at once).
pub fn collapsed<R, S>(pair: &Pair<'_, R, S>, c: &IntersectionCurve) -> bool {
    matches!(c.ends, [CurveEnd::Singular(i), CurveEnd::Singular(k)] if i == k)
        && c.polyline_length() <= pair.delta_len()
}

/// The branch through `x`: a march with `σ = +1`, and unless it closes, one with `σ = −1`;
/// the result is `reverse(second) + first` (§9.4 "Assembly").
pub fn trace_branch<R: Surface, S: Surface>(
    tracer: &mut Tracer<'_, '_, R, S>,
    x: [f64; 4],
    starts: &mut Vec<Start>,
) -> IntersectionCurve {
    let forward = tracer.march(x, 1.0, starts);
    if forward.end == CurveEnd::Closed {
        return assemble(tracer.pair, None, &forward);
    }
    let backward = tracer.march(x, -1.0, starts);
    assemble(tracer.pair, Some(&backward), &forward)
}

fn assemble<R: Surface, S: Surface>(
    pair: &Pair<'_, R, S>,
    backward: Option<&Direction>,
    forward: &Direction,
) -> IntersectionCurve {
    let mut raw: Vec<([f64; 4], Option<usize>)> = backward
        .map(|b| b.points.iter().skip(1).rev().copied().collect())
        .unwrap_or_default();
    raw.extend(forward.points.iter().copied());
    let mut points: Vec<CurvePoint> = Vec::with_capacity(raw.len());
    for (x, singular) in raw {
        let xyz = space_point(pair, &x);
        let t = points
            .last()
            .map_or(0.0, |p| p.t + norm_f64(&sub(&xyz, &p.xyz)));
        points.push(CurvePoint {
            params: x,
            xyz,
            t,
            singular,
        });
    }
    let (closed, ends) = match backward {
        None => (true, [CurveEnd::Closed; 2]),
        Some(b) => (false, [b.end, forward.end]),
    };
    IntersectionCurve {
        points,
        closed,
        ends,
    }
}

/// The start `s` lies on the traced curve `c` (within the chord tolerance of a chord,
/// with a parallel tangent).
fn on_curve<R: Surface, S: Surface>(
    pair: &Pair<'_, R, S>,
    c: &IntersectionCurve,
    s: &Start,
) -> bool {
    let tol = 4.0 * super::frame::chord_tolerance(pair) + pair.delta_len();
    c.points.windows(2).any(|w| {
        let (a, b) = (w[0].xyz, w[1].xyz);
        let ab = sub(&b, &a);
        let len2 = dot(&ab, &ab);
        let lambda = if len2 > 0.0 {
            (dot(&sub(&s.p, &a), &ab) / len2).clamp(0.0, 1.0)
        } else {
            0.0
        };
        let foot: [f64; 3] = std::array::from_fn(|i| a[i] + lambda * ab[i]);
        let aligned = len2 > 0.0 && dot(&s.tangent, &ab).abs() >= 0.85 * len2.sqrt();
        norm_f64(&sub(&s.p, &foot)) <= tol && aligned
    })
}

/// §9.6: the point of `curve` at curve parameter `t` (`t_min ≤ t ≤ t_max`): on the plane
/// through `(1 − λ)p₁ + λp₂` normal to the chord `p₂ − p₁` of the enclosing stored points,
/// by the reduced 4 × 4 form of (9.10), from the interpolated parameters.
pub fn point_at<R: Surface, S: Surface>(
    pair: &Pair<'_, R, S>,
    curve: &IntersectionCurve,
    t: f64,
) -> Result<CurvePoint, GeomError> {
    let pts = &curve.points;
    let (lo, hi) = (
        pts.first().map_or(0.0, |p| p.t),
        pts.last().map_or(0.0, |p| p.t),
    );
    crate::error::require_finite("t", t)?;
    if pts.len() < 2 || !(lo..=hi).contains(&t) {
        return Err(GeomError::ParameterOutsideDomain {
            field: "t".into(),
            value: format!("{t}"),
            lo: format!("{lo}"),
            hi: format!("{hi}"),
        });
    }
    let i = pts.partition_point(|p| p.t <= t).clamp(1, pts.len() - 1);
    let (p1, p2) = (&pts[i - 1], &pts[i]);
    let span = p2.t - p1.t;
    let lambda = if span > 0.0 { (t - p1.t) / span } else { 0.0 };
    let p: [f64; 3] = std::array::from_fn(|k| (1.0 - lambda) * p1.xyz[k] + lambda * p2.xyz[k]);
    let chord = sub(&p2.xyz, &p1.xyz);
    let len = norm_f64(&chord);
    let x0: [f64; 4] = std::array::from_fn(|k| {
        let b = pair.unwrap_near(k, p1.params[k], p2.params[k]);
        (1.0 - lambda) * p1.params[k] + lambda * b
    });
    let solved = if len > 0.0 {
        plane_newton(pair, x0, p, chord.map(|c| c / len))
    } else {
        Some(p1.params)
    };
    let x = solved
        .map(|x| pair.wrap(x))
        .ok_or_else(|| GeomError::Unsupported {
            field: "t".into(),
            reason: "Newton on (9.10) did not converge between the stored points".into(),
        })?;
    Ok(CurvePoint {
        params: x,
        xyz: space_point(pair, &x),
        t,
        singular: None,
    })
}

/// Move a user's start point `[u, v, a, b]` onto the curve: (10.13) on the plane through
/// the mean of its two surface points, normal to the local tangent (§10.5 "Starting
/// point"). Errors name `start`.
pub fn settle<R: Surface, S: Surface>(
    pair: &Pair<'_, R, S>,
    start: [f64; 4],
) -> Result<[f64; 4], GeomError> {
    for (i, &v) in start.iter().enumerate() {
        crate::error::require_finite(&format!("start[{i}]"), v)?;
    }
    let bad = |reason: &str| GeomError::InvalidValue {
        field: "start".into(),
        reason: reason.into(),
    };
    let frame = super::frame::LocalFrame::at(pair, start, 1.0, None);
    if !(frame.sin > 0.0 && frame.sin.is_finite()) {
        return Err(bad(
            "the surfaces are tangent (or a normal vanishes) at the start",
        ));
    }
    let x = plane_newton(pair, start, frame.point(), frame.tangent)
        .ok_or_else(|| bad("no intersection point was found near the start"))?;
    super::corrector::accept(pair, x).ok_or_else(|| bad("the point found lies outside the domains"))
}
