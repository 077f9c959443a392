//! Tracing one branch from a point, float (OPERATIONS.md §9.3–§9.5, §10.5): steps by the
//! chosen method ([`super::step`]) with the acceptance rules of §9.3, and the bookkeeping
//! of §9.4 — boundary ends, closure, covered start points — and §9.5 at contact points
//! (a crossing is located and passed straight through).

use super::contact::locate_contact;
use super::corrector::{fixed_parameter_newton, space_point};
use super::frame::{allowed_steps, chord_tolerance, step_length, LocalFrame};
use super::operand::Pair;
use super::step::step;
use super::types::{CurveEnd, SingularKind, SingularPoint};
use crate::num::vector::{dot, norm_f64, sub};
use crate::surface::Surface;

/// A start point of stage 1 (§9.2) still to be traced.
#[derive(Debug, Clone, Copy)]
pub struct Start {
    pub x: [f64; 4],
    pub p: [f64; 3],
    /// The unit tangent there (unoriented).
    pub tangent: [f64; 3],
}

/// One direction of a march: the points after the start and how it ended.
#[derive(Debug, Clone)]
pub struct Direction {
    /// `(parameters, singular point index)`; the first is the start.
    pub points: Vec<([f64; 4], Option<usize>)>,
    pub end: CurveEnd,
}

/// The tracer: the pair, and the singular points met so far (shared by all branches).
pub struct Tracer<'p, 'a, R, S> {
    pub pair: &'p Pair<'a, R, S>,
    pub singular: Vec<SingularPoint>,
}

/// Points this close in space (relative to `L`) are one singular point.
const SAME_SINGULAR: f64 = 1e-7;

impl<'p, 'a, R: Surface, S: Surface> Tracer<'p, 'a, R, S> {
    pub fn new(pair: &'p Pair<'a, R, S>) -> Self {
        Tracer {
            pair,
            singular: Vec::new(),
        }
    }

    /// The index of the singular point `p`, added if new.
    pub fn add_singular(&mut self, p: SingularPoint) -> usize {
        let tol = SAME_SINGULAR * self.pair.length;
        if let Some(i) = self
            .singular
            .iter()
            .position(|q| norm_f64(&sub(&q.xyz, &p.xyz)) <= tol)
        {
            if p.kind == SingularKind::Crossing {
                self.singular[i].kind = SingularKind::Crossing;
            }
            return i;
        }
        self.singular.push(p);
        self.singular.len() - 1
    }

    /// March from `start` in the direction `σ n̂_r × n̂_s` (§9.3), removing covered start
    /// points (§9.4). With `close_at_start`, a return to the start closes the curve.
    pub fn march(&mut self, start: [f64; 4], sigma: f64, starts: &mut Vec<Start>) -> Direction {
        let pair = self.pair;
        let sin_sw = pair.options.precision.sin_switch();
        let r_min = pair.options.min_step * pair.length;
        let p0 = space_point(pair, &start);
        let mut points = vec![(start, None)];
        let mut frame = LocalFrame::at(pair, start, sigma, None);
        let t0 = frame.tangent;
        if frame.sin.partial_cmp(&sin_sw).is_none_or(|o| o.is_lt()) {
            return Direction {
                points,
                end: CurveEnd::Tangency,
            };
        }
        loop {
            // The deadline and the float stage's work budget too end a march unfinished
            // (issue 20): one unit per point ([`Pair::spend`]).
            if points.len() >= pair.options.max_points || pair.spend(1) {
                return Direction {
                    points,
                    end: CurveEnd::Unfinished,
                };
            }
            let mut h = step_length(pair, &frame);
            if points.len() >= 3 && closes(pair, &frame, &p0, &start, h) {
                close_at_start(pair, &mut points, &p0, start);
                return Direction {
                    points,
                    end: CurveEnd::Closed,
                };
            }
            let mut accepted = None;
            while h >= r_min {
                match self.try_step(&frame, h) {
                    Attempt::Next(y, f1) => {
                        accepted = Some((y, f1));
                        break;
                    }
                    Attempt::Boundary(y) => {
                        points.push((y, None));
                        return Direction {
                            points,
                            end: CurveEnd::Boundary,
                        };
                    }
                    Attempt::Retry => h *= 0.5,
                }
            }
            let Some((y, next)) = accepted else {
                // §9.3: r₀ < r_min. Near a contact (§9.5) try to pass it.
                match self.pass_contact(&frame, &mut points) {
                    Some(f) => {
                        frame = f;
                        continue;
                    }
                    None => {
                        let end = self.stuck_end(&frame, &mut points);
                        return Direction { points, end };
                    }
                }
            };
            if dot(&frame.cross, &next.cross) < 0.0 {
                // n̂_r × n̂_s changed its sign along the step: a contact was passed (§9.5).
                if let Some(i) = self.contact_between(&frame, &next) {
                    points.push((self.singular[i].params, Some(i)));
                }
            }
            remove_covered(pair, starts, &frame, &next);
            if points.len() >= 3 && passes_start(pair, &frame, &next, (&p0, &t0), &start) {
                // §9.4 "Closure" when the step jumped over the start: it ends there
                close_at_start(pair, &mut points, &p0, start);
                return Direction {
                    points,
                    end: CurveEnd::Closed,
                };
            }
            points.push((y, None));
            frame = next;
        }
    }

    /// One attempt at a step of length `h`: the next point with its frame, a boundary end
    /// point, or a retry with a shorter step.
    fn try_step(&self, frame: &LocalFrame, h: f64) -> Attempt {
        let pair = self.pair;
        let predicted = frame.predict(h);
        if !pair.inside(&predicted, 0.0) {
            if let Some(b) = boundary_point(pair, &frame.x, &predicted) {
                return Attempt::Boundary(b);
            }
        }
        let Some(y) = step(pair, frame, h) else {
            return Attempt::Retry;
        };
        if !pair.inside(&y, 0.0) {
            return match boundary_point(pair, &frame.x, &y) {
                Some(b) => Attempt::Boundary(b),
                None => Attempt::Retry,
            };
        }
        let y = pair.wrap(y);
        let next = LocalFrame::at(pair, y, 1.0, Some(frame.tangent));
        if acceptable(pair, frame, &next, h) {
            Attempt::Next(y, next)
        } else {
            Attempt::Retry
        }
    }

    /// §9.5 "Crossing a contact point": locate the contact near the current point, then
    /// solve (10.13) on the plane at `r₀` beyond it along the last tangent. On success the
    /// contact and the point beyond are appended and the frame there returned.
    fn pass_contact(
        &mut self,
        frame: &LocalFrame,
        points: &mut Vec<([f64; 4], Option<usize>)>,
    ) -> Option<LocalFrame> {
        let pair = self.pair;
        let reach = allowed_steps(pair, &frame.x)
            .into_iter()
            .fold(0.0, f64::max);
        let c = locate_contact(pair, frame.x, reach, SingularKind::Crossing)?;
        let i = self.add_singular(c);
        if points.iter().any(|(_, s)| *s == Some(i)) {
            return None;
        }
        let beyond = self.beyond(frame, &c)?;
        points.push((c.params, Some(i)));
        points.push((beyond.x, None));
        Some(beyond)
    }

    /// The point at chord `h` beyond the contact `c` along the tangent of `frame`, by the
    /// plane corrector (10.13) from the parameters extrapolated through `c`.
    fn beyond(&self, frame: &LocalFrame, c: &SingularPoint) -> Option<LocalFrame> {
        let pair = self.pair;
        let sin_sw = pair.options.precision.sin_switch();
        let d = norm_f64(&sub(&c.xyz, &frame.point())).max(pair.options.min_step * pair.length);
        for scale in [1.0, 4.0, 16.0] {
            let h = (d * scale)
                .max(1e-6 * pair.length)
                .min(step_length(pair, frame));
            let p_star: [f64; 3] = std::array::from_fn(|k| c.xyz[k] + h * frame.tangent[k]);
            let x0: [f64; 4] = std::array::from_fn(|k| {
                let xc = pair.unwrap_near(k, frame.x[k], c.params[k]);
                xc + h * frame.velocity[k]
            });
            let y = super::corrector::plane_newton(pair, x0, p_star, frame.tangent)?;
            if !pair.inside(&y, 0.0) {
                continue;
            }
            let f = LocalFrame::at(pair, pair.wrap(y), 1.0, Some(frame.tangent));
            let ahead = dot(&sub(&f.point(), &c.xyz), &frame.tangent) > 0.0;
            if f.sin >= sin_sw && ahead {
                return Some(f);
            }
        }
        None
    }

    /// A contact between two consecutive frames whose `n̂_r × n̂_s` point opposite ways.
    fn contact_between(&mut self, a: &LocalFrame, b: &LocalFrame) -> Option<usize> {
        let pair = self.pair;
        let dw = sub(&b.cross, &a.cross);
        let lambda = (-dot(&a.cross, &dw) / dot(&dw, &dw)).clamp(0.0, 1.0);
        let guess: [f64; 4] = std::array::from_fn(|k| {
            let bk = pair.unwrap_near(k, a.x[k], b.x[k]);
            a.x[k] + lambda * (bk - a.x[k])
        });
        let reach = (0..4)
            .map(|k| pair.param_distance(k, a.x[k], b.x[k]))
            .fold(0.0, f64::max);
        let c = locate_contact(pair, guess, 2.0 * reach, SingularKind::Crossing)?;
        // The contact must lie on the chord's side range (between the two points).
        let along = dot(&sub(&c.xyz, &a.point()), &a.tangent);
        let chord = norm_f64(&sub(&b.point(), &a.point()));
        (along >= -1e-9 * pair.length && along <= chord * 1.5).then(|| self.add_singular(c))
    }

    /// How a march that cannot step ends: at a located contact (its singular point), or
    /// `Tangency` where the normals are nearly collinear, else `Unfinished`.
    fn stuck_end(
        &mut self,
        frame: &LocalFrame,
        points: &mut Vec<([f64; 4], Option<usize>)>,
    ) -> CurveEnd {
        let pair = self.pair;
        let reach = allowed_steps(pair, &frame.x)
            .into_iter()
            .fold(0.0, f64::max);
        if let Some(c) = locate_contact(pair, frame.x, reach, SingularKind::Crossing) {
            let i = self.add_singular(c);
            if points.last().is_some_and(|(_, s)| *s != Some(i)) {
                points.push((c.params, Some(i)));
            }
            return CurveEnd::Singular(i);
        }
        if frame.sin < pair.options.precision.delta_tan() {
            CurveEnd::Tangency
        } else {
            CurveEnd::Unfinished
        }
    }
}

#[allow(clippy::large_enum_variant)] // short-lived, one per step; boxing buys nothing
enum Attempt {
    Next([f64; 4], LocalFrame),
    Boundary([f64; 4]),
    Retry,
}

/// §9.3 step acceptance: each parameter change within its allowed step, the chord at most
/// `2h`, moving forward, and the chord within the chord tolerance of the curve (the
/// sagitta `|Δp|·θ/8` of an arc turning by `θ` between the two tangents).
fn acceptable<R: Surface, S: Surface>(
    pair: &Pair<'_, R, S>,
    a: &LocalFrame,
    b: &LocalFrame,
    h: f64,
) -> bool {
    let allowed = allowed_steps(pair, &a.x);
    let within = (0..4).all(|k| pair.param_distance(k, a.x[k], b.x[k]) <= allowed[k] * 1.0001);
    let chord = sub(&b.point(), &a.point());
    let length = norm_f64(&chord);
    let forward = dot(&chord, &a.tangent) > 0.0;
    let turn = dot(&a.tangent, &b.tangent).clamp(-1.0, 1.0).acos();
    let sagitta = length * turn / 8.0;
    within && forward && length <= 2.0 * h && sagitta <= 1.5 * chord_tolerance(pair)
}

/// §9.4 "Closure": after at least two steps, the start lies within the next step ahead
/// (`|p₀ − p_k| ≤ h`, `(p₀ − p_k)·t > 0`, nearly along `t`) or within a sliver of `h`
/// in any direction, and its parameters are near.
fn closes<R: Surface, S: Surface>(
    pair: &Pair<'_, R, S>,
    frame: &LocalFrame,
    p0: &[f64; 3],
    x0: &[f64; 4],
    h: f64,
) -> bool {
    let d = sub(p0, &frame.point());
    let dist = norm_f64(&d);
    // a point within a sliver of the start closes whatever the direction (rounding may
    // put it just behind the start; marching on would go round the loop again)
    let behind = dot(&d, &frame.tangent) < 0.9 * dist;
    if dist > h || (behind && dist > CLOSING_SLIVER * h) {
        return false;
    }
    let allowed = allowed_steps(pair, &frame.x);
    (0..4).all(|k| pair.param_distance(k, frame.x[k], x0[k]) <= 2.0 * allowed[k])
}

/// The step `a → b` passed the start `p0` (impl, §9.4 "Closure"): `p0` projects into
/// the chord, lies within a few chord tolerances of it, the chord runs along the start's
/// tangent `t0` (not a branch crossing there), and its parameters are near. The
/// check before each step ([`closes`]) misses this when a step accepted up to `2h`
/// (§9.3) carries the march past the start, which then lies behind the new point; the
/// march would go round the loop again until its point budget is spent.
fn passes_start<R: Surface, S: Surface>(
    pair: &Pair<'_, R, S>,
    a: &LocalFrame,
    b: &LocalFrame,
    (p0, t0): (&[f64; 3], &[f64; 3]),
    x0: &[f64; 4],
) -> bool {
    let (pa, pb) = (a.point(), b.point());
    let chord = sub(&pb, &pa);
    let len2 = dot(&chord, &chord);
    if len2 <= 0.0 {
        return false;
    }
    let lambda = dot(&sub(p0, &pa), &chord) / len2;
    if !(0.0..=1.0).contains(&lambda) {
        return false;
    }
    let foot: [f64; 3] = std::array::from_fn(|i| pa[i] + lambda * chord[i]);
    let tol = 4.0 * chord_tolerance(pair) + pair.delta_len();
    let aligned = dot(t0, &chord).abs() >= 0.85 * len2.sqrt();
    if norm_f64(&sub(p0, &foot)) > tol || !aligned {
        return false;
    }
    let allowed = allowed_steps(pair, &a.x);
    (0..4).all(|k| pair.param_distance(k, a.x[k], x0[k]) <= 2.0 * allowed[k])
}

/// End a closed march at its start. A last point much nearer the start than its
/// predecessor is dropped first: the closing chord would be tiny next to the others, and
/// the certified chain (module doc of `chain`) cannot join a box over a sliver to boxes
/// many times longer — the loop would stay undecided although it closes.
fn close_at_start<R, S>(
    pair: &Pair<'_, R, S>,
    points: &mut Vec<([f64; 4], Option<usize>)>,
    p0: &[f64; 3],
    start: [f64; 4],
) where
    R: Surface,
    S: Surface,
{
    let n = points.len();
    if n >= 4 && points[n - 1].1.is_none() {
        let last = space_point(pair, &points[n - 1].0);
        let before = space_point(pair, &points[n - 2].0);
        let gap = norm_f64(&sub(p0, &last));
        if gap < CLOSING_SLIVER * norm_f64(&sub(&last, &before)) {
            points.pop();
        }
    }
    points.push((start, None));
}

/// A closing chord shorter than this share of the chord before it is merged into it.
const CLOSING_SLIVER: f64 = 0.25;

/// §9.4 "Boundary": the first non-periodic parameter that leaves its range between `x`
/// (inside) and `y` is set to its bound and made the fixed parameter; (9.1) is solved for
/// the other three from the interpolated point. `None` if that fails.
fn boundary_point<R: Surface, S: Surface>(
    pair: &Pair<'_, R, S>,
    x: &[f64; 4],
    y: &[f64; 4],
) -> Option<[f64; 4]> {
    let y: [f64; 4] = std::array::from_fn(|k| pair.unwrap_near(k, x[k], y[k]));
    let mut best: Option<(f64, usize, f64)> = None;
    for (k, c) in pair.coords.iter().enumerate() {
        if c.periodic || (c.lo..=c.hi).contains(&y[k]) {
            continue;
        }
        let bound = if y[k] < c.lo { c.lo } else { c.hi };
        let lambda = ((bound - x[k]) / (y[k] - x[k])).clamp(0.0, 1.0);
        if best.is_none_or(|(l, _, _)| lambda < l) {
            best = Some((lambda, k, bound));
        }
    }
    let (lambda, k, bound) = best?;
    let mut z0: [f64; 4] = std::array::from_fn(|i| x[i] + lambda * (y[i] - x[i]));
    z0[k] = bound;
    let z = fixed_parameter_newton(pair, z0, k)?;
    let mut z = pair.wrap(z);
    z[k] = bound;
    pair.inside(&z, 0.0).then_some(z)
}

/// §9.4 "Covered start points": drop every start point within `|Δp|` of the chord
/// `[p_k, p_{k+1}]` whose tangent is nearly parallel to it and whose parameters lie within
/// the step's windows (so that a start on a crossing branch stays).
fn remove_covered<R: Surface, S: Surface>(
    pair: &Pair<'_, R, S>,
    starts: &mut Vec<Start>,
    a: &LocalFrame,
    b: &LocalFrame,
) {
    let (pa, pb) = (a.point(), b.point());
    let chord = sub(&pb, &pa);
    let len2 = dot(&chord, &chord);
    let radius = len2.sqrt().max(pair.delta_len());
    let allowed = allowed_steps(pair, &a.x);
    starts.retain(|s| {
        let lambda = if len2 > 0.0 {
            (dot(&sub(&s.p, &pa), &chord) / len2).clamp(0.0, 1.0)
        } else {
            0.0
        };
        let foot: [f64; 3] = std::array::from_fn(|i| pa[i] + lambda * chord[i]);
        let near = norm_f64(&sub(&s.p, &foot)) <= radius;
        let aligned = dot(&s.tangent, &a.tangent).abs() >= 0.85;
        let params = (0..4).all(|k| {
            pair.param_distance(k, s.x[k], a.x[k]) <= 2.0 * allowed[k]
                || pair.param_distance(k, s.x[k], b.x[k]) <= 2.0 * allowed[k]
        });
        !(near && aligned && params)
    });
}
