//! The 3D drawing of a case and its answer ([`Model`]): polylines with a [`Role`],
//! markers, certified boxes, and the triangles that occlude (module doc of
//! [`crate::render`]).
//!
//! Bounded shapes are sampled first; their extent (with the answer's and the query
//! points) is the *window* — a ball around their bounding box — to which unbounded
//! lines are cut and in which unbounded planes are drawn as a square centred at the foot
//! of the window's centre.

use super::contour::zero_polylines;
use super::RenderOptions;
use crate::certificate::Certified;
use crate::curve::{AnyCurve2, AnyCurve3, Curve};
use crate::error::GeomError;
use crate::ops::answer::{Answer, Bounds, Point, Visibility};
use crate::ops::classify::Side;
use crate::ops::shape::{Linear, LinearObject, Shape};
use crate::ops::view::{ContourFn, View};
use crate::surface::{AnySurface, Surface};

/// What a polyline draws (its colour and width in [`super::draw`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Role {
    /// An input curve, line or segment.
    Curve,
    /// An iso-parameter line of an input surface.
    Net,
    /// The contour (outline) of an input surface in the view (§13.5).
    Contour,
    /// An edge of an input polyhedron.
    Edge,
    /// A curve of the answer (an intersection curve, a section, a silhouette, a line or
    /// segment answer).
    Answer,
    /// The spine of a blend (ball centres, or a chamfer's edge).
    Spine,
    /// A contact curve of a blend on one face.
    Contact,
    /// An iso-parameter line of a blend surface.
    BlendNet,
    /// From the query point of a projection to a foot.
    Guide,
    /// A certified box: its projected edges, or a 4-pixel square round a box smaller
    /// than that.
    Box,
}

/// What a marker marks (its shape and colour in [`super::draw`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum MarkerKind {
    /// A point of the answer (a simple solution).
    Point,
    /// A tangency (multiplicity > 1), an isolated contact point, or a query point on the
    /// boundary of a shell.
    Tangent,
    /// A singular point of an intersection curve.
    Singular,
    /// The query point of `project` or `classify`.
    Query,
    /// A foot of a projection (or the nearest point of `classify`).
    Foot,
    /// A query point proven inside the shell.
    Inside,
    /// A query point proven outside the shell.
    Outside,
}

/// A polyline of the drawing.
#[derive(Debug, Clone, PartialEq)]
pub struct Polyline3 {
    pub role: Role,
    /// The input object it belongs to (its index), if any.
    pub object: Option<usize>,
    pub points: Vec<[f64; 3]>,
}

/// A marked point of the drawing.
#[derive(Debug, Clone, PartialEq)]
pub struct Mark3 {
    pub kind: MarkerKind,
    pub at: [f64; 3],
}

/// The 3D drawing.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Model {
    pub lines: Vec<Polyline3>,
    pub marks: Vec<Mark3>,
    /// The certified boxes of the answer's points (on request).
    pub boxes: Vec<[Bounds; 3]>,
    /// The occluders: every input surface, polyhedron face and blend surface,
    /// tessellated.
    pub triangles: Vec<[[f64; 3]; 3]>,
    /// A plane case: every object is 2D (drawn in its own plane, nothing occludes).
    pub plane: bool,
}

/// What is drawn: the case's shapes, its query point, its answer.
pub struct Input<'a> {
    /// The shapes in input order (`objects`, or `onto` / `shell`).
    pub shapes: &'a [Shape],
    /// The query point of `project` and `classify`.
    pub point: Option<Vec<f64>>,
    /// The certified answer, if the case was solved.
    pub answer: Option<&'a Certified<Answer>>,
    /// The view, for the surfaces' contours.
    pub view: &'a View,
}

/// A ball around the bounded part of the drawing.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Window {
    centre: [f64; 3],
    radius: f64,
}

fn pad(v: &[f64]) -> [f64; 3] {
    [
        v.first().copied().unwrap_or(0.0),
        v.get(1).copied().unwrap_or(0.0),
        v.get(2).copied().unwrap_or(0.0),
    ]
}

fn finite3(p: &[f64; 3]) -> bool {
    p.iter().all(|c| c.is_finite())
}

fn lerp(a: f64, b: f64, s: f64) -> f64 {
    a + (b - a) * s
}

fn add(a: &[f64; 3], b: &[f64; 3], s: f64) -> [f64; 3] {
    [a[0] + s * b[0], a[1] + s * b[1], a[2] + s * b[2]]
}

fn dot(a: &[f64; 3], b: &[f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

impl Model {
    fn line(&mut self, role: Role, object: Option<usize>, points: Vec<[f64; 3]>) {
        let points: Vec<[f64; 3]> = points.into_iter().filter(finite3).collect();
        if points.len() >= 2 {
            self.lines.push(Polyline3 {
                role,
                object,
                points,
            });
        }
    }

    fn mark(&mut self, kind: MarkerKind, at: [f64; 3]) {
        if finite3(&at) {
            self.marks.push(Mark3 { kind, at });
        }
    }

    /// The bounded part's ball (`None` when nothing is bounded).
    fn window(&self) -> Option<Window> {
        let pts = self
            .lines
            .iter()
            .flat_map(|l| l.points.iter())
            .chain(self.marks.iter().map(|m| &m.at));
        let mut lo = [f64::INFINITY; 3];
        let mut hi = [f64::NEG_INFINITY; 3];
        for p in pts {
            for k in 0..3 {
                lo[k] = lo[k].min(p[k]);
                hi[k] = hi[k].max(p[k]);
            }
        }
        if !lo[0].is_finite() {
            return None;
        }
        let centre = [0, 1, 2].map(|k| 0.5 * (lo[k] + hi[k]));
        let half = [0, 1, 2].map(|k| 0.5 * (hi[k] - lo[k]));
        let radius = dot(&half, &half).sqrt();
        // A single point (or points very close together): a window of a sensible size.
        let floor = 1e-3 * centre.iter().fold(0.0f64, |m, c| m.max(c.abs())).max(1.0);
        Some(Window {
            centre,
            radius: radius.max(floor),
        })
    }

    /// Sample a curve over its domain (a closed curve ends where it began).
    fn curve3(&mut self, role: Role, object: Option<usize>, c: &AnyCurve3, samples: usize) {
        let (a, b) = c.domain();
        let pts = (0..=samples)
            .map(|i| c.point(&lerp(a, b, i as f64 / samples as f64)))
            .collect();
        self.line(role, object, pts);
    }

    /// The shared arc of an `arc` answer: the first curve sampled between the ends'
    /// parameters on it (64 steps).
    fn arc(&mut self, c: &Shape, a: &Point, b: &Point) {
        let (Some(&[ta]), Some(&[tb])) = (
            a.params.first().map(Vec::as_slice),
            b.params.first().map(Vec::as_slice),
        ) else {
            return;
        };
        let at = |i: usize| lerp(ta, tb, i as f64 / 64.0);
        let pts = match c {
            Shape::Curve(c) => (0..=64).map(|i| c.point(&at(i))).collect(),
            Shape::Curve2(c) => (0..=64).map(|i| pad(&c.point(&at(i)))).collect(),
            _ => return,
        };
        self.line(Role::Answer, None, pts);
    }

    fn curve2(&mut self, object: usize, c: &AnyCurve2, samples: usize) {
        let (a, b) = c.domain();
        let pts = (0..=samples)
            .map(|i| pad(&c.point(&lerp(a, b, i as f64 / samples as f64))))
            .collect();
        self.line(Role::Curve, Some(object), pts);
    }

    /// A surface over the parameter rectangle `dom`: its net, its contour in the view,
    /// and its triangles.
    fn surface(
        &mut self,
        object: usize,
        s: &AnySurface,
        dom: ([f64; 2], [f64; 2]),
        input: &Input,
        opts: &RenderOptions,
    ) {
        let at = |u: f64, v: f64| s.jet(&u, &v, 0).swap_remove(0);
        let (du, dv) = dom;
        let n = opts.samples.max(8);
        for (dir, lines) in [(0usize, opts.net[0]), (1, opts.net[1])] {
            let closed = s.is_closed()[dir];
            let count = lines.max(2);
            for i in 0..count {
                // A closed direction: `count` lines round the turn, none repeated.
                let f = if closed {
                    i as f64 / count as f64
                } else {
                    i as f64 / (count - 1) as f64
                };
                let pts = (0..=n)
                    .map(|j| {
                        let g = j as f64 / n as f64;
                        if dir == 0 {
                            at(lerp(du[0], du[1], f), lerp(dv[0], dv[1], g))
                        } else {
                            at(lerp(du[0], du[1], g), lerp(dv[0], dv[1], f))
                        }
                    })
                    .collect();
                self.line(Role::Net, Some(object), pts);
            }
        }
        let f = ContourFn {
            surface: s,
            implicit: s.implicit(),
            view: input.view,
        };
        let grid = 2 * n;
        for pl in zero_polylines(grid, grid, |i, j| {
            f.value(
                &lerp(du[0], du[1], i as f64 / grid as f64),
                &lerp(dv[0], dv[1], j as f64 / grid as f64),
            )
        }) {
            let pts = pl
                .iter()
                .map(|&[i, j]| {
                    at(
                        lerp(du[0], du[1], i / grid as f64),
                        lerp(dv[0], dv[1], j / grid as f64),
                    )
                })
                .collect();
            self.line(Role::Contour, Some(object), pts);
        }
        let m = 64;
        let node = |i: usize, j: usize| {
            at(
                lerp(du[0], du[1], i as f64 / m as f64),
                lerp(dv[0], dv[1], j as f64 / m as f64),
            )
        };
        for i in 0..m {
            for j in 0..m {
                let (a, b, c, d) = (
                    node(i, j),
                    node(i + 1, j),
                    node(i + 1, j + 1),
                    node(i, j + 1),
                );
                self.triangle([a, b, c]);
                self.triangle([a, c, d]);
            }
        }
    }

    fn triangle(&mut self, t: [[f64; 3]; 3]) {
        if t.iter().all(finite3) {
            self.triangles.push(t);
        }
    }

    /// A grid of points `rows[i][j]` as a net (both directions) and its triangles.
    fn grid(&mut self, role: Role, rows: &[Vec<[f64; 3]>]) {
        for r in rows {
            self.line(role, None, r.clone());
        }
        let across = rows.iter().map(Vec::len).min().unwrap_or(0);
        for j in 0..across {
            self.line(role, None, rows.iter().map(|r| r[j]).collect());
        }
        for w in rows.windows(2) {
            for j in 0..across.saturating_sub(1) {
                self.triangle([w[0][j], w[1][j], w[1][j + 1]]);
                self.triangle([w[0][j], w[1][j + 1], w[0][j + 1]]);
            }
        }
    }

    fn boxed(&mut self, b: &[Bounds]) {
        if b.len() < 2 || !b.iter().flatten().all(|x| x.is_finite()) {
            return;
        }
        self.boxes
            .push([b[0], b[1], b.get(2).copied().unwrap_or([0.0, 0.0])]);
    }

    fn point(&mut self, kind: MarkerKind, p: &Point, boxes: bool) {
        self.mark(kind, pad(&p.xyz));
        if boxes {
            self.boxed(&p.xyz_box);
        }
    }

    /// A line `o + t·d` cut to the window ([`reach`]).
    fn cut_line(&mut self, role: Role, o: [f64; 3], d: [f64; 3], w: Window) {
        if let Some((a, b)) = reach(&o, &d, w) {
            self.line(role, None, vec![add(&o, &d, a), add(&o, &d, b)]);
        }
    }
}

/// The `t` range of the line `o + t·d` within the window: the chord of the ball of
/// radius `1.25·radius` (a line that misses it: a piece as long as that radius around
/// the point nearest to the centre).
fn reach(o: &[f64; 3], d: &[f64; 3], w: Window) -> Option<(f64, f64)> {
    let dd = dot(d, d);
    if dd == 0.0 || !dd.is_finite() {
        return None;
    }
    let oc = sub(o, &w.centre);
    let t0 = -dot(&oc, d) / dd;
    let c = add(&oc, d, t0);
    let r = 1.25 * w.radius;
    let half = (r * r - dot(&c, &c)).max((0.5 * r).powi(2)).sqrt() / dd.sqrt();
    Some((t0 - half, t0 + half))
}

/// A plane `origin + u·U + v·V` as the parameter square around the foot of the window's
/// centre, of half-size `1.25·radius` along the (normalised) directions.
fn plane_window(o: [f64; 3], u: [f64; 3], v: [f64; 3], w: Window) -> ([f64; 2], [f64; 2]) {
    let c = [w.centre[0] - o[0], w.centre[1] - o[1], w.centre[2] - o[2]];
    // The foot's parameters: the normal equations of the 2×2 least-squares problem.
    let (uu, uv, vv) = (dot(&u, &u), dot(&u, &v), dot(&v, &v));
    let (cu, cv) = (dot(&c, &u), dot(&c, &v));
    let det = uu * vv - uv * uv;
    let (p, q) = if det != 0.0 && det.is_finite() {
        ((cu * vv - cv * uv) / det, (cv * uu - cu * uv) / det)
    } else {
        (0.0, 0.0)
    };
    let r = 1.25 * w.radius;
    let (hu, hv) = (r / uu.sqrt(), r / vv.sqrt());
    ([p - hu, p + hu], [q - hv, q + hv])
}

/// Whether a surface's parameter rectangle is unbounded (only planes are).
fn unbounded(s: &AnySurface) -> bool {
    let (u, v) = s.domain();
    !(u.iter().chain(v.iter()).all(|x| x.is_finite()))
}

/// The 3D drawing of `input` (module doc).
///
/// Errors: none for shapes the front door accepts; a 2D object mixed with 3D ones is
/// drawn in the plane `z = 0`.
pub fn model(input: &Input, opts: &RenderOptions) -> Result<Model, GeomError> {
    let mut m = Model {
        plane: input.shapes.iter().all(Shape::is_2d) && !input.shapes.is_empty(),
        ..Model::default()
    };
    let samples = opts.samples.max(8);
    // Bounded shapes first.
    for (i, s) in input.shapes.iter().enumerate() {
        match s {
            Shape::Curve(c) => m.curve3(Role::Curve, Some(i), c, samples),
            Shape::Curve2(c) => m.curve2(i, c, samples),
            Shape::Surface(s) if !unbounded(s) => {
                let dom = s.domain();
                m.surface(i, s, dom, input, opts);
            }
            Shape::Quadric(q) => {
                if let Some(e) = super::quadric::as_ellipsoid(q) {
                    let s = AnySurface::Ellipsoid(e);
                    m.surface(i, &s, s.domain(), input, opts);
                }
            }
            Shape::Polyhedron(p) => {
                let verts: Vec<[f64; 3]> = p
                    .vertices()
                    .iter()
                    .map(|v| [v[0].to_f64(), v[1].to_f64(), v[2].to_f64()])
                    .collect();
                for f in p.faces() {
                    let ring: Vec<[f64; 3]> = f.indices.iter().map(|&k| verts[k]).collect();
                    let mut closed = ring.clone();
                    closed.push(ring[0]);
                    m.line(Role::Edge, Some(i), closed);
                    for k in 1..ring.len().saturating_sub(1) {
                        m.triangle([ring[0], ring[k], ring[k + 1]]);
                    }
                }
            }
            Shape::Linear(l) => {
                if let Some((o, d, (Some(a), Some(b)))) = line_parts(l) {
                    m.line(Role::Curve, Some(i), vec![add(&o, &d, a), add(&o, &d, b)]);
                }
            }
            _ => {}
        }
    }
    if let Some(p) = &input.point {
        m.mark(MarkerKind::Query, pad(p));
    }
    let answer = input.answer.map(|c| &c.value);
    if let Some(a) = answer {
        bounded_answer(&mut m, a, input, opts.boxes);
    }
    let w = m.window().unwrap_or(Window {
        centre: [0.0; 3],
        radius: 1.0,
    });
    // Unbounded shapes, cut to the window.
    for (i, s) in input.shapes.iter().enumerate() {
        match s {
            Shape::Surface(s) if unbounded(s) => {
                let j = s.jet(&0.0, &0.0, 1);
                let dom = plane_window(j[0], j[1], j[2], w);
                m.surface(i, s, dom, input, opts);
            }
            Shape::Linear(l) => {
                if let LinearObject::Plane(p) = l.rounded() {
                    let (o, u, v) = plane_frame(&p);
                    if let Ok(pl) = crate::surface::plane::Plane::new(o, u, v) {
                        let dom = plane_window(o, u, v, w);
                        m.surface(i, &AnySurface::Plane(pl), dom, input, opts);
                    }
                    continue;
                }
                let Some((o, d, bounds)) = line_parts(l) else {
                    continue;
                };
                let (a, b) = reach(&o, &d, w).unwrap_or((-1.0, 1.0));
                let ends = match bounds {
                    (Some(_), Some(_)) => continue,
                    (Some(lo), None) => (lo, b.max(lo + (b - a) / 2.0)),
                    (None, Some(hi)) => (a.min(hi - (b - a) / 2.0), hi),
                    (None, None) => (a, b),
                };
                m.line(
                    Role::Curve,
                    Some(i),
                    vec![add(&o, &d, ends.0), add(&o, &d, ends.1)],
                );
            }
            Shape::Quadric(q) if super::quadric::as_ellipsoid(q).is_none() => {
                let (net, contour) = super::quadric::sections(
                    q,
                    input.view,
                    w.centre,
                    1.25 * w.radius,
                    opts.net,
                    samples,
                );
                for pl in net {
                    m.line(Role::Net, Some(i), pl);
                }
                for pl in contour {
                    m.line(Role::Contour, Some(i), pl);
                }
            }
            Shape::Conic2(c) => {
                let k = c.coeffs();
                let f = |x: f64, y: f64| {
                    k[0] * x * x + k[1] * x * y + k[2] * y * y + k[3] * x + k[4] * y + k[5]
                };
                let r = 1.25 * w.radius;
                let (x0, y0) = (w.centre[0] - r, w.centre[1] - r);
                let grid = 4 * samples;
                let at = |g: f64| 2.0 * r * g / grid as f64;
                for pl in zero_polylines(grid, grid, |i, j| f(x0 + at(i as f64), y0 + at(j as f64)))
                {
                    let pts = pl
                        .iter()
                        .map(|&[i, j]| [x0 + at(i), y0 + at(j), 0.0])
                        .collect();
                    m.line(Role::Curve, Some(i), pts);
                }
            }
            _ => {}
        }
    }
    if let Some(Answer::Line(l)) = answer {
        m.cut_line(Role::Answer, pad(&l.point), pad(&l.dir), w);
    }
    Ok(m)
}

/// A point and two orthonormal directions of a linear plane (either form).
fn plane_frame(p: &crate::geom::Plane<f64>) -> ([f64; 3], [f64; 3], [f64; 3]) {
    match p {
        crate::geom::Plane::Parametric { origin, u, v } => {
            (pad(origin.as_slice()), pad(u.as_slice()), pad(v.as_slice()))
        }
        crate::geom::Plane::Implicit { normal, d } => {
            let n = pad(normal.as_slice());
            let nn = dot(&n, &n);
            let o = n.map(|c| -d * c / nn);
            let (u, v) = super::quadric::plane_axes(n);
            (o, u, v)
        }
    }
}

/// A line, ray or segment (3D or 2D) as `o + t·d` with its parameter bounds (a segment:
/// `d = b − a` over `[0, 1]`); `None` for planes.
type LineParts = ([f64; 3], [f64; 3], (Option<f64>, Option<f64>));

fn line_parts(l: &Linear) -> Option<LineParts> {
    let v = |x: &[f64]| pad(x);
    match l.rounded() {
        LinearObject::Segment(s) => {
            let (a, b) = (v(s.a().as_slice()), v(s.b().as_slice()));
            Some((a, sub(&b, &a), (Some(0.0), Some(1.0))))
        }
        LinearObject::Segment2(s) => {
            let (a, b) = (v(s.a().as_slice()), v(s.b().as_slice()));
            Some((a, sub(&b, &a), (Some(0.0), Some(1.0))))
        }
        LinearObject::Line(ln) => {
            let (lo, hi) = ln.bounds();
            Some((
                v(ln.origin().as_slice()),
                v(ln.dir().as_slice()),
                (lo.copied(), hi.copied()),
            ))
        }
        LinearObject::Line2(ln) => {
            let (lo, hi) = ln.bounds();
            Some((
                v(ln.origin().as_slice()),
                v(ln.dir().as_slice()),
                (lo.copied(), hi.copied()),
            ))
        }
        LinearObject::Plane(_) => None,
    }
}

fn sub(a: &[f64; 3], b: &[f64; 3]) -> [f64; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

/// The answer's bounded parts: points, curves, singular points, blends, guides.
fn bounded_answer(m: &mut Model, a: &Answer, input: &Input, boxes: bool) {
    let query = input.point.as_ref().map(|p| pad(p));
    let foot = |m: &mut Model, p: &Point| {
        m.point(MarkerKind::Foot, p, boxes);
        if let Some(q) = query {
            m.line(Role::Guide, None, vec![q, pad(&p.xyz)]);
        }
    };
    match a {
        Answer::Points(ps) => {
            for p in ps {
                if query.is_some() {
                    foot(m, p);
                } else {
                    let kind = if p.tangent || p.multiplicity > 1 {
                        MarkerKind::Tangent
                    } else {
                        MarkerKind::Point
                    };
                    m.point(kind, p, boxes);
                }
            }
        }
        Answer::Side(side, nearest) => {
            if let Some(q) = query {
                // The query point again, in the colour of its side.
                m.mark(
                    match side {
                        Side::Inside => MarkerKind::Inside,
                        Side::On => MarkerKind::Tangent,
                        Side::Outside => MarkerKind::Outside,
                    },
                    q,
                );
            }
            if let Some(p) = nearest {
                foot(m, p);
            }
        }
        Answer::Arc(s) => {
            if let Some(c) = input.shapes.first() {
                m.arc(c, &s.a, &s.b);
            }
            m.point(MarkerKind::Point, &s.a, boxes);
            m.point(MarkerKind::Point, &s.b, boxes);
        }
        Answer::Segment(s) => {
            m.line(Role::Answer, None, vec![pad(&s.a.xyz), pad(&s.b.xyz)]);
            m.point(MarkerKind::Point, &s.a, boxes);
            m.point(MarkerKind::Point, &s.b, boxes);
        }
        Answer::Curves(c) => {
            for curve in &c.curves {
                m.line(
                    Role::Answer,
                    None,
                    curve.points.iter().map(|v| pad(&v.xyz)).collect(),
                );
            }
            for s in &c.singular_points {
                m.point(MarkerKind::Singular, &s.point, boxes);
            }
            for p in &c.points {
                m.point(MarkerKind::Tangent, p, boxes);
            }
        }
        Answer::Visibility(v) => {
            let kind = match v.visibility {
                Visibility::Visible => MarkerKind::Inside,
                Visibility::Hidden => MarkerKind::Outside,
                Visibility::OnContour => MarkerKind::Tangent,
            };
            m.point(kind, &v.point, boxes);
        }
        Answer::Blend(b) => {
            for comp in &b.components {
                m.line(
                    Role::Spine,
                    None,
                    comp.spine.points.iter().map(|v| pad(&v.xyz)).collect(),
                );
                for face in &comp.contacts {
                    m.line(
                        Role::Contact,
                        None,
                        face.iter().map(|p| pad(&p.xyz)).collect(),
                    );
                }
                m.grid(Role::BlendNet, &comp.grid.points);
            }
        }
        _ => {}
    }
}
