//! The certified answer of surface ∩ surface: the float path's curves split at their
//! singular points into arcs, each covered by a proven chain ([`super::chain`]) with
//! proven vertex bounds; singular points certified ([`super::singular`]); and the
//! completeness proof ([`super::complete`]), which traces every component it finds that
//! no chain covers and certifies it in turn.

use super::chain::{distance_bound, Anchor, ChainContext, Piece};
use super::complete::{critical_roots, face_roots, RootBox, RootKind, Roots};
use super::corrector::fixed_parameter_newton;
use super::float::{settle, trace_all, trace_branch};
use super::operand::Pair;
use super::singular::{certify_singular, singular_box, SingularBox};
use super::trace::Tracer;
use super::types::{
    CertifiedCurve, CertifiedSingularPoint, ChainBox, CurveEnd, CurvePoint, IntersectionCurve,
    SurfaceIntersection, VertexBound,
};
use crate::certificate::{Arithmetic, Certified, Status};
use crate::error::GeomError;
use crate::num::Interval;
use crate::surface::Surface;

/// Rounds of "trace what the completeness proof found unmatched".
const MAX_ROUNDS: usize = 6;
/// A singular box grows by critical cluster boxes of at most this size (relative to `L`).
const GROWTH_LIMIT: f64 = 1e-2;

struct State<'p, 'a, R, S> {
    ctx: ChainContext<'p, 'a, R, S>,
    tracer: Tracer<'p, 'a, R, S>,
    boxes: Vec<SingularBox>,
    arcs: Vec<(CertifiedCurve, Vec<Piece>)>,
    /// The roots of the height-critical system over the whole domain.
    critical: Option<Roots>,
    reasons: Vec<String>,
    bits: u32,
}

/// [`super::intersect_surface_surface`].
pub fn intersect<R: Surface, S: Surface>(
    pair: &Pair<'_, R, S>,
) -> Result<Certified<SurfaceIntersection>, GeomError> {
    let float = trace_all(pair);
    let mut state = State::new(pair);
    if pair.options.completeness {
        state.critical = Some(critical_roots(&state.ctx, &pair.options.certify)?);
    }
    state.tracer.singular = float.singular_points;
    state.certify_new_singular();
    for c in float.curves {
        state.add_curve(c);
    }
    let complete = if pair.options.completeness {
        state.prove_complete()?
    } else {
        state.reasons.push("completeness was not requested".into());
        false
    };
    Ok(state.finish(complete))
}

/// [`super::trace_surface_surface`]: the branch through `x` (on the curve).
pub fn trace<R: Surface, S: Surface>(
    pair: &Pair<'_, R, S>,
    x: [f64; 4],
) -> Result<Certified<SurfaceIntersection>, GeomError> {
    let mut state = State::new(pair);
    let curve = trace_branch(&mut state.tracer, x, &mut Vec::new());
    state.certify_new_singular();
    state.add_curve(curve);
    state
        .reasons
        .push("one branch only: nothing is said about other components".into());
    Ok(state.finish(false))
}

impl<'p, 'a, R: Surface, S: Surface> State<'p, 'a, R, S> {
    fn new(pair: &'p Pair<'a, R, S>) -> Self {
        State {
            ctx: ChainContext::new(pair, Vec::new()),
            tracer: Tracer::new(pair),
            boxes: Vec::new(),
            arcs: Vec::new(),
            critical: None,
            reasons: Vec::new(),
            bits: 53,
        }
    }

    /// Certify the tracer's singular points that have no box yet. A box grows to hold
    /// the `verified_singular` boxes of the height-critical system that meet it (the
    /// critical system has a double root at a contact; its cluster box must lie in the
    /// singular box to be accounted for).
    fn certify_new_singular(&mut self) {
        let opts = &self.ctx.pair.options.certify;
        let limit = GROWTH_LIMIT * self.ctx.pair.length;
        while self.boxes.len() < self.tracer.singular.len() {
            let p = self.tracer.singular[self.boxes.len()];
            let mut v = singular_box(&self.ctx, &p);
            let clusters: Vec<[Interval; 4]> = self
                .critical
                .iter()
                .flat_map(|c| &c.roots)
                .filter(|r| r.status == Status::VerifiedSingular)
                .map(|r| r.params)
                .collect();
            for _ in 0..4 {
                let mut grown = false;
                for c in &clusters {
                    let c = self.ctx.shift_near(c, &v);
                    let meets = (0..4).all(|k| !c[k].intersection(&v[k]).is_empty());
                    let inside = (0..4).all(|k| c[k].is_subset(&v[k]));
                    if meets && !inside && c.iter().all(|x| x.width() <= limit) {
                        v = std::array::from_fn(|k| {
                            let h = v[k].hull(&c[k]);
                            let d = 0.05 * h.width();
                            Interval::from_bounds(h.lo() - d, h.hi() + d)
                        });
                        grown = true;
                    }
                }
                if !grown {
                    break;
                }
            }
            let b = certify_singular(&self.ctx, &p, v, opts);
            self.ctx.singular.push(b.params);
            self.boxes.push(b);
        }
    }

    /// Split a float curve at its singular points and certify each arc.
    fn add_curve(&mut self, curve: IntersectionCurve) {
        self.certify_new_singular();
        for (points, start, end) in split(&curve) {
            self.add_arc(points, start, end);
        }
    }

    fn add_arc(&mut self, mut points: Vec<CurvePoint>, start: CurveEnd, end: CurveEnd) {
        let pair = self.ctx.pair;
        let closed = start == CurveEnd::Closed;
        if !closed && points.len() == 2 && points.iter().all(|p| p.singular.is_some()) {
            // no regular point between two singular ones: add the curve point halfway
            let (a, b) = (points[0].params, points[1].params);
            let b: [f64; 4] = std::array::from_fn(|k| pair.unwrap_near(k, a[k], b[k]));
            let x0: [f64; 4] = std::array::from_fn(|k| 0.5 * (a[k] + b[k]));
            let j = (0..4)
                .max_by(|&i, &k| (b[i] - a[i]).abs().total_cmp(&(b[k] - a[k]).abs()))
                .unwrap_or(0);
            if let Some(m) = fixed_parameter_newton(pair, x0, j) {
                let m = pair.wrap(m);
                let xyz = super::corrector::space_point(pair, &m);
                points.insert(
                    1,
                    CurvePoint {
                        params: m,
                        xyz,
                        t: 0.0,
                        singular: None,
                    },
                );
            }
        }
        retime(&mut points);
        let xs = unwrapped(pair, &points);
        let anchors = [
            self.anchor(&points[0], start),
            self.anchor(&points[points.len() - 1], end),
        ];
        let curve = IntersectionCurve {
            closed,
            ends: [start, end],
            points,
        };
        let proof = match anchors {
            [Ok(a), Ok(b)] => self.ctx.arc(&xs, a, b),
            [Err(e), _] | [_, Err(e)] => Err(e),
        };
        let certified = match proof {
            Ok(pieces) => {
                let bounds = self.bounds(&curve, &xs, &pieces);
                let chain = pieces
                    .iter()
                    .map(|p| ChainBox {
                        params: std::array::from_fn(|k| p.graph.region[k]),
                        fixed: p.graph.fixed,
                    })
                    .collect();
                let c = CertifiedCurve {
                    curve,
                    status: Status::Verified,
                    bounds,
                    chain,
                    reason: None,
                };
                (c, pieces)
            }
            Err(reason) => (
                CertifiedCurve {
                    curve,
                    status: Status::Undecided,
                    bounds: Vec::new(),
                    chain: Vec::new(),
                    reason: Some(reason),
                },
                Vec::new(),
            ),
        };
        self.arcs.push(certified);
    }

    /// The anchor of an arc's end point: `None` for a closed arc, a singular box, or a
    /// domain face (the bounded coordinate at its bound).
    fn anchor(&self, p: &CurvePoint, end: CurveEnd) -> Result<Option<Anchor>, String> {
        if let Some(i) = p.singular {
            return Ok(Some(Anchor::Singular(i)));
        }
        match end {
            CurveEnd::Closed => Ok(None),
            CurveEnd::Boundary => {
                let pair = self.ctx.pair;
                (0..4)
                    .find_map(|k| {
                        let c = &pair.coords[k];
                        let [lo, hi] = self.ctx.search[k];
                        if c.periodic {
                            None
                        } else if p.params[k] == c.lo {
                            Some(Anchor::Face(k, lo))
                        } else if p.params[k] == c.hi {
                            Some(Anchor::Face(k, hi))
                        } else {
                            None
                        }
                    })
                    .map(Some)
                    .ok_or_else(|| "a boundary end does not lie on a domain bound".to_string())
            }
            CurveEnd::Singular(i) => Ok(Some(Anchor::Singular(i))),
            CurveEnd::Tangency | CurveEnd::Unfinished => Err(format!(
                "the float trace ended ({end:?}) without reaching the boundary or a singular point"
            )),
        }
    }

    /// The proven bound of every point of a certified arc.
    fn bounds(
        &self,
        curve: &IntersectionCurve,
        xs: &[[f64; 4]],
        pieces: &[Piece],
    ) -> Vec<VertexBound> {
        let pair = self.ctx.pair;
        curve
            .points
            .iter()
            .zip(xs)
            .map(|(p, x)| {
                let found = match p.singular {
                    Some(i) => self.boxes.get(i).map(|b| b.params),
                    None => self.ctx.vertex_box(pieces, x),
                };
                let b = found.unwrap_or_else(|| {
                    // the hull of the pieces holding the point: the curve passes there
                    pieces
                        .iter()
                        .map(|q| std::array::from_fn(|k| q.graph.region[k]))
                        .find(|r: &[Interval; 4]| (0..4).all(|k| r[k].contains(x[k])))
                        .unwrap_or([Interval::ENTIRE; 4])
                });
                let shifted = self.shift_back(&b, x, &p.params);
                let (xyz_box, distance) = distance_bound(pair, &b, &p.xyz);
                VertexBound {
                    param_box: shifted,
                    xyz_box,
                    distance,
                }
            })
            .collect()
    }

    /// A box in unwrapped coordinates (around `x`) moved by the whole periods that take
    /// `x` to its wrapped value `w`.
    fn shift_back(&self, b: &[Interval; 4], x: &[f64; 4], w: &[f64; 4]) -> [Interval; 4] {
        std::array::from_fn(|k| {
            let c = &self.ctx.pair.coords[k];
            if !c.periodic || x[k] == w[k] {
                return b[k];
            }
            let p = self.ctx.period(k);
            let m = ((w[k] - x[k]) / p.midpoint()).round();
            b[k] + p * Interval::point(m)
        })
    }

    /// The completeness proof (module doc of `complete`): solve, match, trace what is
    /// unmatched, repeat.
    fn prove_complete(&mut self) -> Result<bool, GeomError> {
        let opts = self.ctx.pair.options.certify.clone();
        let mut holes: Vec<[Interval; 4]> = self.boxes.iter().map(|b| b.params).collect();
        let mut solved = self.solve(&holes, &opts)?;
        for _ in 0..MAX_ROUNDS {
            let unmatched: Vec<RootBox> = solved
                .roots
                .iter()
                .filter(|r| !self.matched(r))
                .cloned()
                .collect();
            if unmatched.is_empty() {
                break;
            }
            let before = (self.arcs.len(), self.boxes.len());
            for r in &unmatched {
                if self
                    .arcs
                    .iter()
                    .any(|(_, pieces)| self.in_pieces(&r.params, pieces, false))
                {
                    continue;
                }
                if r.status == Status::VerifiedSingular {
                    continue;
                }
                let Ok(x) = settle(self.ctx.pair, self.ctx.pair.wrap(r.estimate)) else {
                    continue;
                };
                let curve = trace_branch(&mut self.tracer, x, &mut Vec::new());
                self.add_curve(curve);
            }
            if (self.arcs.len(), self.boxes.len()) == before {
                break;
            }
            if self.boxes.len() > holes.len() {
                holes = self.boxes.iter().map(|b| b.params).collect();
                solved = self.solve(&holes, &opts)?;
            }
        }
        let unmatched: Vec<&RootBox> = solved.roots.iter().filter(|r| !self.matched(r)).collect();
        if let Some(r) = unmatched.first() {
            self.reasons.push(format!(
                "{} root(s) of the completeness systems lie on no certified chain (first: {:?} \
                 {:?} near {:?})",
                unmatched.len(),
                r.kind,
                r.status,
                r.estimate
            ));
        }
        let unmatched = unmatched.len();
        self.reasons.extend(solved.reasons.iter().cloned());
        self.bits = self.bits.max(solved.bits);
        let arcs_ok = self.arcs.iter().all(|(c, _)| c.status == Status::Verified);
        Ok(solved.complete && unmatched == 0 && arcs_ok)
    }

    /// The face roots (domain faces and the faces of `holes`) with the critical roots.
    fn solve(
        &self,
        holes: &[[Interval; 4]],
        opts: &crate::certify::Options,
    ) -> Result<Roots, GeomError> {
        let mut faces = face_roots(&self.ctx, holes, opts)?;
        if let Some(critical) = &self.critical {
            faces.complete &= critical.complete;
            faces.bits = faces.bits.max(critical.bits);
            faces.reasons.extend(critical.reasons.iter().cloned());
            faces.roots.extend(critical.roots.iter().cloned());
        }
        Ok(faces)
    }

    /// A completeness root lies on a certified chain (or, off a singular box's face, in a
    /// singular box).
    fn matched(&self, r: &RootBox) -> bool {
        let in_chain = self
            .arcs
            .iter()
            .filter(|(c, _)| c.status == Status::Verified)
            .any(|(_, pieces)| self.in_pieces(&r.params, pieces, false));
        let in_hole = r.kind != RootKind::SingularFace
            && self
                .boxes
                .iter()
                .any(|b| self.ctx.shifted_inside(&r.params, &b.params, false));
        in_chain || in_hole
    }

    fn in_pieces(&self, x: &[Interval; 4], pieces: &[Piece], interior: bool) -> bool {
        pieces.iter().any(|p| {
            let region: [Interval; 4] = std::array::from_fn(|k| p.graph.region[k]);
            self.ctx.shifted_inside(x, &region, interior)
        })
    }

    fn finish(self, complete: bool) -> Certified<SurfaceIntersection> {
        let mut reasons = self.reasons;
        let curves: Vec<CertifiedCurve> = self.arcs.into_iter().map(|(c, _)| c).collect();
        for c in &curves {
            if let Some(r) = &c.reason {
                reasons.push(format!("curve: {r}"));
            }
        }
        let ends = |i: usize| {
            curves
                .iter()
                .filter(|c| c.status == Status::Verified)
                .flat_map(|c| [c.curve.points.first(), c.curve.points.last()])
                .flatten()
                .filter(|p| p.singular == Some(i))
                .count()
        };
        let singular_points: Vec<CertifiedSingularPoint> = self
            .boxes
            .iter()
            .zip(&self.tracer.singular)
            .enumerate()
            .map(|(i, (b, p))| {
                if let Some(r) = &b.reason {
                    reasons.push(format!("singular point {i}: {r}"));
                }
                let mut point = *p;
                if ends(i) > 0 {
                    point.kind = super::types::SingularKind::Crossing;
                }
                CertifiedSingularPoint {
                    point,
                    param_box: b.params,
                    xyz_box: b.xyz,
                    status: b.status,
                    perturbation: b.perturbation,
                    branch_ends: ends(i),
                    reason: b.reason.clone(),
                }
            })
            .collect();
        let status = curves
            .iter()
            .map(|c| c.status)
            .chain(singular_points.iter().map(|p| p.status))
            .fold(Status::Verified, Status::weakest);
        let perturbation = singular_points
            .iter()
            .filter_map(|p| p.perturbation)
            .reduce(f64::max);
        let nothing = curves.is_empty() && singular_points.is_empty();
        let status = if nothing && !complete {
            Status::Undecided
        } else {
            status
        };
        Certified {
            value: SurfaceIntersection {
                curves,
                singular_points,
            },
            status,
            complete,
            arithmetic: if self.bits > 53 {
                Arithmetic::Mpfr
            } else {
                Arithmetic::Interval
            },
            bits: self.bits,
            reason: (!reasons.is_empty()).then(|| reasons.join("; ")),
            perturbation,
        }
    }
}

/// The arcs of a float curve between its singular points, with their end kinds
/// (`Closed` twice for a closed curve without singular points).
fn split(curve: &IntersectionCurve) -> Vec<(Vec<CurvePoint>, CurveEnd, CurveEnd)> {
    let mut pts = curve.points.clone();
    if pts.is_empty() {
        return Vec::new();
    }
    let cuts: Vec<usize> = (0..pts.len())
        .filter(|&i| pts[i].singular.is_some())
        .collect();
    if curve.closed {
        if cuts.is_empty() {
            return vec![(pts, CurveEnd::Closed, CurveEnd::Closed)];
        }
        pts.pop();
        pts.rotate_left(cuts[0]);
        let first = pts[0];
        pts.push(first);
        let cuts: Vec<usize> = (0..pts.len())
            .filter(|&i| pts[i].singular.is_some())
            .collect();
        return cuts
            .windows(2)
            .map(|w| {
                let (a, b) = (w[0], w[1]);
                let (ea, eb) = (
                    CurveEnd::Singular(pts[a].singular.unwrap_or(0)),
                    CurveEnd::Singular(pts[b].singular.unwrap_or(0)),
                );
                (pts[a..=b].to_vec(), ea, eb)
            })
            .collect();
    }
    let mut bounds = vec![0];
    bounds.extend(
        cuts.iter()
            .copied()
            .filter(|&i| i != 0 && i != pts.len() - 1),
    );
    bounds.push(pts.len() - 1);
    bounds
        .windows(2)
        .map(|w| {
            let (a, b) = (w[0], w[1]);
            let end_at = |i: usize, fallback: CurveEnd| match pts[i].singular {
                Some(s) => CurveEnd::Singular(s),
                None => fallback,
            };
            (
                pts[a..=b].to_vec(),
                end_at(a, curve.ends[0]),
                end_at(b, curve.ends[1]),
            )
        })
        .filter(|(p, _, _)| p.len() >= 2)
        .collect()
}

/// Cumulative chord lengths from the arc's first point (§1.9).
fn retime(points: &mut [CurvePoint]) {
    let mut t = 0.0;
    for i in 0..points.len() {
        if i > 0 {
            let d: f64 = (0..3)
                .map(|k| (points[i].xyz[k] - points[i - 1].xyz[k]).powi(2))
                .sum::<f64>()
                .sqrt();
            t += d;
        }
        points[i].t = t;
    }
}

/// The points' parameters made continuous across periodic seams.
fn unwrapped<R, S>(pair: &Pair<'_, R, S>, points: &[CurvePoint]) -> Vec<[f64; 4]> {
    let mut out: Vec<[f64; 4]> = Vec::with_capacity(points.len());
    for p in points {
        let x = match out.last() {
            Some(prev) => std::array::from_fn(|k| pair.unwrap_near(k, prev[k], p.params[k])),
            None => p.params,
        };
        out.push(x);
    }
    out
}
