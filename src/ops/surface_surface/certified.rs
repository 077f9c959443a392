//! The certified answer of surface ∩ surface: the float path's curves split at their
//! singular points into arcs, each covered by a proven chain ([`super::chain`]) with
//! proven vertex bounds; singular points certified ([`super::singular`]); and the
//! completeness proof ([`super::complete`]), which traces every component it finds that
//! no chain covers and certifies it in turn.

use super::chain::{distance_bound, Anchor, ChainContext, Piece};
use super::complete::{
    critical_roots, domain_face_roots, hole_face_roots, RootBox, RootKind, Solved, DIRECTIONS,
};
use super::contact::locate_contact;
use super::corrector::fixed_parameter_newton;
use super::float::{settle, trace_all, trace_branch};
use super::operand::Pair;
use super::singular::{certify_singular, singular_region, SingularBox, REGION_SIZE};
use super::trace::Tracer;
use super::types::{
    CertifiedCurve, CertifiedSingularPoint, ChainBox, CurveEnd, CurvePoint, IntersectionCurve,
    SingularKind, SurfaceIntersection, VertexBound,
};
use crate::certificate::{Arithmetic, Certified, Status};
use crate::error::GeomError;
use crate::num::Interval;
use crate::surface::Surface;

/// Rounds of "trace what the completeness proof found unmatched".
const MAX_ROUNDS: usize = 6;
/// A singular region grows by critical cluster boxes of at most this size (relative to `L`).
const GROWTH_LIMIT: f64 = 1e-2;
/// The largest singular region (relative to `L`).
const MAX_REGION: f64 = 0.07;

struct State<'p, 'a, R, S> {
    ctx: ChainContext<'p, 'a, R, S>,
    tracer: Tracer<'p, 'a, R, S>,
    boxes: Vec<SingularBox>,
    arcs: Vec<(CertifiedCurve, Vec<Piece>)>,
    /// The roots of the height-critical system over the whole domain.
    critical: Option<Solved>,
    reasons: Vec<String>,
    bits: u32,
}

/// [`super::intersect_surface_surface`].
pub fn intersect<R: Surface, S: Surface>(
    pair: &Pair<'_, R, S>,
) -> Result<Certified<SurfaceIntersection>, GeomError> {
    let float = trace_all(pair);
    // The float stage stopped on its share of `max_boxes` (issue 20), not the deadline.
    let budget_spent = pair.spend(0) && !pair.options.certify.late();
    let mut state = State::new(pair);
    state.tracer.singular = float.singular_points;
    if pair.options.completeness {
        state.solve_critical()?;
    } else {
        state.certify_new_singular();
    }
    for c in float.curves {
        state.add_curve(c);
    }
    let complete = if pair.options.completeness {
        state.prove_complete()?
    } else {
        state.check_reaching(None);
        state.reasons.push("completeness was not requested".into());
        false
    };
    if budget_spent && !complete {
        state.reasons.insert(
            0,
            format!(
                "box budget spent: the float stage stopped after {} units of work ({} per box)",
                pair.work(),
                super::operand::FLOAT_WORK
            ),
        );
    }
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
    state.check_reaching(None);
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

    /// The height-critical system over the whole domain, with the first direction whose
    /// undecided boxes all lie in singular regions (the regions are certified here, grown
    /// by the critical system's clusters first).
    fn solve_critical(&mut self) -> Result<(), GeomError> {
        let opts = self.ctx.pair.options.certify.clone();
        for (i, d) in DIRECTIONS.into_iter().enumerate() {
            let solved = critical_roots(&self.ctx, d, &opts)?;
            self.critical = Some(solved);
            if i == 0 {
                self.contacts_at_clusters();
                self.certify_new_singular();
            } else {
                self.regrow_all();
            }
            if self.critical_excused() {
                return Ok(());
            }
        }
        Ok(())
    }

    /// Every undecided box of the critical solve lies in a singular region.
    fn critical_excused(&self) -> bool {
        self.critical
            .as_ref()
            .is_none_or(|c| c.undecided.iter().all(|(b, _)| self.in_region(b)))
    }

    fn in_region(&self, b: &[Interval; 4]) -> bool {
        self.boxes
            .iter()
            .any(|s| self.ctx.shifted_inside(b, &s.region, false))
    }

    /// The critical system's `verified_singular` clusters and undecided boxes (small
    /// ones): a singular region grows to hold those that meet it.
    fn clusters(&self) -> Vec<[Interval; 4]> {
        let limit = GROWTH_LIMIT * self.ctx.pair.length;
        let Some(c) = &self.critical else {
            return Vec::new();
        };
        c.roots
            .iter()
            .filter(|r| r.status == Status::VerifiedSingular)
            .map(|r| r.params)
            .chain(c.undecided.iter().map(|(b, _)| *b))
            .filter(|b| b.iter().all(|x| x.width() <= limit))
            .collect()
    }

    /// A contact located from each cluster of the critical system outside every
    /// region: near a tangency the float search can miss (a plane touching a torus off
    /// its seam, or an implicit plane whose enclosure holds tangent and cutting planes
    /// alike, `Plane::through_box`), and such a cluster is then left undecided, though
    /// a singular region would hold it.
    fn contacts_at_clusters(&mut self) {
        for c in self.clusters() {
            if self.in_region(&c) {
                continue;
            }
            let x = self.ctx.pair.wrap(std::array::from_fn(|k| c[k].midpoint()));
            if let Some(p) = locate_contact(self.ctx.pair, x, 0.5, SingularKind::Contact) {
                self.tracer.add_singular(p);
            }
        }
    }

    /// `v` grown to hold every cluster box that meets it.
    fn grown(&self, mut v: [Interval; 4]) -> [Interval; 4] {
        let clusters = self.clusters();
        for _ in 0..4 {
            let mut grown = false;
            for c in &clusters {
                let c = self.ctx.shift_near(c, &v);
                let meets = (0..4).all(|k| !c[k].intersection(&v[k]).is_empty());
                let inside = (0..4).all(|k| c[k].is_subset(&v[k]));
                if meets && !inside {
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
        v
    }

    /// Certify the tracer's singular points that have no region yet.
    fn certify_new_singular(&mut self) {
        let opts = self.ctx.pair.options.certify.clone();
        while self.boxes.len() < self.tracer.singular.len() {
            let p = self.tracer.singular[self.boxes.len()];
            let v = self.grown(singular_region(&self.ctx, &p, REGION_SIZE));
            let b = certify_singular(&self.ctx, &p, v, REGION_SIZE, &opts);
            self.ctx.singular.push(b.region);
            self.boxes.push(b);
        }
    }

    /// Regrow every region with the current clusters.
    fn regrow_all(&mut self) {
        for i in 0..self.boxes.len() {
            let v = self.grown(self.boxes[i].region);
            self.set_region(i, v);
        }
    }

    /// Replace region `i` (it only ever grows: chains ending in the old one end in it).
    fn set_region(&mut self, i: usize, v: [Interval; 4]) {
        let pair = self.ctx.pair;
        let b = &mut self.boxes[i];
        b.region = v;
        b.region_xyz = distance_bound(pair, &v, &self.tracer.singular[i].xyz).0;
        self.ctx.singular[i] = v;
    }

    /// Region `i` at the next size (four times larger), holding the old one.
    fn enlarge(&mut self, i: usize) -> bool {
        let size = 4.0 * self.boxes[i].size;
        if size > MAX_REGION {
            return false;
        }
        let p = self.tracer.singular[i];
        let old = self.boxes[i].region;
        let v = singular_region(&self.ctx, &p, size);
        let v = self.grown(std::array::from_fn(|k| v[k].hull(&old[k])));
        self.boxes[i].size = size;
        self.set_region(i, v);
        true
    }

    /// Split a float curve at its singular points and certify each arc.
    fn add_curve(&mut self, mut curve: IntersectionCurve) {
        self.certify_new_singular();
        if super::float::collapsed(self.ctx.pair, &curve) {
            return;
        }
        self.close_at_touch(&mut curve);
        for (points, start, end) in split(&curve) {
            self.add_arc(points, start, end);
        }
    }

    /// A float curve whose two ends lie on the same face decided exactly to hold no
    /// point of the intersection, or one the curve touches from inside
    /// ([`super::ends::FaceTruth`]), stepped out of the domain by rounding where the loop
    /// touches or nears the face (no arc ends on such a face twice): it is taken as the
    /// loop it is — its two end points (clipped to the face, off the curve) dropped and
    /// the rest closed — and proven as any closed chain (the proof does not rely on this
    /// guess).
    fn close_at_touch(&self, curve: &mut IntersectionCurve) {
        let pair = self.ctx.pair;
        let face = |p: &CurvePoint| {
            (0..4).find_map(|k| {
                let c = &pair.coords[k];
                let bound = if p.params[k] == c.lo {
                    c.lo
                } else if p.params[k] == c.hi {
                    c.hi
                } else {
                    return None;
                };
                (!c.periodic).then_some((k, bound))
            })
        };
        let (Some(first), Some(last)) = (curve.points.first(), curve.points.last()) else {
            return;
        };
        let ends = curve.ends == [CurveEnd::Boundary; 2];
        let touched = match (face(first), face(last)) {
            (Some(a), Some(b)) if a == b => pair.decided.iter().any(|d| (d.k, d.bound) == a),
            _ => false,
        };
        let singular = curve.points.iter().any(|p| p.singular.is_some());
        if ends && touched && !singular && curve.points.len() >= 5 {
            curve.points.pop();
            curve.points.remove(0);
            let first = curve.points[0];
            curve.points.push(first);
            curve.closed = true;
            curve.ends = [CurveEnd::Closed; 2];
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
                    Some(i) => self.boxes.get(i).map(|b| b.region),
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

    /// The completeness proof (module doc of `complete`): the face systems of the domain
    /// and of the singular regions (a region whose faces cannot be decided grows), then
    /// match every root with a chain; trace from the unmatched ones, certify, repeat.
    fn prove_complete(&mut self) -> Result<bool, GeomError> {
        let mut faces = self.faces()?;
        for _ in 0..MAX_ROUNDS {
            let unmatched: Vec<RootBox> = self
                .all_roots(&faces)
                .filter(|r| !self.matched(r))
                .collect();
            if unmatched.is_empty() {
                break;
            }
            let before = (self.arcs.len(), self.boxes.len());
            for r in &unmatched {
                let traced = self
                    .arcs
                    .iter()
                    .any(|(_, pieces)| self.in_pieces(&r.params, pieces, false))
                    || self.near_traced(&r.estimate);
                if traced {
                    continue;
                }
                if r.status == Status::VerifiedSingular {
                    // A tangential root no trace explains: a contact the float search
                    // missed (a plane touching a torus off its seam). Located from the
                    // root, it gets a singular region like every other contact.
                    let x = self.ctx.pair.wrap(r.estimate);
                    if let Some(c) = locate_contact(self.ctx.pair, x, 0.5, SingularKind::Contact) {
                        self.tracer.add_singular(c);
                        self.certify_new_singular();
                    }
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
            if self.boxes.len() > before.1 {
                faces = self.faces()?;
            }
        }
        self.check_reaching(Some(&faces));
        let unmatched: Vec<RootBox> = self
            .all_roots(&faces)
            .filter(|r| !self.matched(r))
            .collect();
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
        let critical_ok = self.critical_excused();
        let faces_ok = faces
            .undecided
            .iter()
            .all(|(b, kind)| *kind == RootKind::DomainFace && self.in_region(b));
        for (ok, solved) in [
            (critical_ok, self.critical.as_ref()),
            (faces_ok, Some(&faces)),
        ] {
            if !ok {
                if let Some(s) = solved {
                    self.reasons.extend(s.reasons.iter().cloned());
                }
            }
        }
        self.bits = self
            .bits
            .max(faces.bits)
            .max(self.critical.as_ref().map_or(53, |c| c.bits));
        let arcs_ok = self.arcs.iter().all(|(c, _)| c.status == Status::Verified);
        Ok(critical_ok && faces_ok && unmatched.is_empty() && arcs_ok)
    }

    /// The face roots: the domain's faces outside the regions, and each region's faces,
    /// a region growing (up to [`MAX_REGION`]) while its faces leave undecided boxes or
    /// roots that are not proven simple.
    fn faces(&mut self) -> Result<Solved, GeomError> {
        let opts = self.ctx.pair.options.certify.clone();
        let mut out = Solved::default();
        for i in 0..self.boxes.len() {
            loop {
                let f = hole_face_roots(&self.ctx, &self.boxes[i].region, &opts)?;
                let bad =
                    !f.undecided.is_empty() || f.roots.iter().any(|r| r.status != Status::Verified);
                if !bad || !self.enlarge(i) {
                    out.extend(f);
                    break;
                }
            }
        }
        let holes: Vec<[Interval; 4]> = self.boxes.iter().map(|b| b.region).collect();
        out.extend(domain_face_roots(&self.ctx, &holes, &opts)?);
        Ok(out)
    }

    /// A closed chain reaching past a domain face (module doc of `chain`) proves a loop
    /// of the continued surfaces. It is a loop of the domain when it has a vertex strictly
    /// inside the domain and crosses no face: a crossing is a point of a face on the
    /// loop, so in a piece reaching past that face, and every such point lies in a root
    /// box or an undecided box of the face solves (faces decided exactly have none: no
    /// point, or one touched from inside), or in a singular region (whose parts of the
    /// faces are not solved). Otherwise the chain is demoted to undecided.
    ///
    /// Without the face solves (`None`: one branch traced, or no completeness asked for)
    /// a reaching chain is demoted.
    fn check_reaching(&mut self, faces: Option<&Solved>) {
        let known = faces.is_some();
        let faces = faces.cloned().unwrap_or_default();
        let on_faces: Vec<[Interval; 4]> = faces
            .roots
            .iter()
            .filter(|r| r.kind == RootKind::DomainFace)
            .map(|r| r.params)
            .chain(
                faces
                    .undecided
                    .iter()
                    .filter(|(_, k)| *k == RootKind::DomainFace)
                    .map(|(b, _)| *b),
            )
            // the face solves leave out the singular regions' parts of the faces
            .chain(self.boxes.iter().map(|b| b.region))
            .collect();
        let search = self.ctx.search;
        let pair = self.ctx.pair;
        let strictly_inside = |b: &[Interval; 4]| {
            (0..4).all(|k| {
                pair.coords[k].periodic || (search[k][0] < b[k].lo() && b[k].hi() < search[k][1])
            })
        };
        for (c, pieces) in self.arcs.iter_mut() {
            if c.status != Status::Verified || !c.curve.closed {
                continue;
            }
            let reach: Vec<&Piece> = pieces.iter().filter(|p| self.ctx.reaching(p)).collect();
            if reach.is_empty() {
                continue;
            }
            let crossed = !known
                || reach.iter().any(|p| {
                    let region: [Interval; 4] = std::array::from_fn(|k| p.graph.region[k]);
                    on_faces.iter().any(|b| {
                        let b = self.ctx.shift_near(b, &region);
                        (0..4).all(|k| !b[k].intersection(&region[k]).is_empty())
                    })
                });
            let inside = c.bounds.iter().any(|v| strictly_inside(&v.param_box));
            if crossed || !inside {
                c.status = Status::Undecided;
                c.bounds.clear();
                c.chain.clear();
                c.reason = Some(if crossed {
                    "the loop's chain reaches past a domain face where the face system has a \
                     root or an undecided box: whether it leaves the domain is not proven"
                        .into()
                } else {
                    "no vertex of the loop is proven strictly inside the domain".into()
                });
                pieces.clear();
            }
        }
    }

    fn all_roots<'s>(&'s self, faces: &'s Solved) -> impl Iterator<Item = RootBox> + 's {
        faces
            .roots
            .iter()
            .chain(self.critical.iter().flat_map(|c| &c.roots))
            .cloned()
    }

    /// A completeness root lies on a certified chain (or, off a singular box's face, in a
    /// singular box).
    ///
    /// A root on a domain face is matched only by a piece inside the search box: one
    /// reaching past the face holds a crossing its chain does not account for.
    fn matched(&self, r: &RootBox) -> bool {
        let face = r.kind == RootKind::DomainFace;
        let in_chain = self
            .arcs
            .iter()
            .filter(|(c, _)| c.status == Status::Verified)
            .any(|(_, pieces)| {
                pieces.iter().any(|p| {
                    let region: [Interval; 4] = std::array::from_fn(|k| p.graph.region[k]);
                    !(face && self.ctx.reaching(p))
                        && self.ctx.shifted_inside(&r.params, &region, false)
                })
            });
        let in_hole = r.kind != RootKind::SingularFace && self.in_region(&r.params);
        in_chain || in_hole
    }

    /// The point `x` lies on a traced curve (certified or not) within a few chord
    /// tolerances: tracing from it would repeat that curve.
    fn near_traced(&self, x: &[f64; 4]) -> bool {
        let pair = self.ctx.pair;
        let p = super::corrector::space_point(pair, &pair.wrap(*x));
        let tol = 8.0 * super::frame::chord_tolerance(pair) + pair.delta_len();
        self.arcs.iter().any(|(c, _)| {
            c.curve.points.windows(2).any(|w| {
                let (a, b) = (w[0].xyz, w[1].xyz);
                let ab = crate::num::vector::sub(&b, &a);
                let len2 = crate::num::vector::dot(&ab, &ab);
                let lambda = if len2 > 0.0 {
                    (crate::num::vector::dot(&crate::num::vector::sub(&p, &a), &ab) / len2)
                        .clamp(0.0, 1.0)
                } else {
                    0.0
                };
                let foot: [f64; 3] = std::array::from_fn(|i| a[i] + lambda * ab[i]);
                crate::num::vector::norm_f64(&crate::num::vector::sub(&p, &foot)) <= tol
            })
        })
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
                    region: b.region,
                    region_xyz: b.region_xyz,
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
