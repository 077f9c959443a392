//! The picture plane ([`Scene`]): the [`Model`] projected by a view of OPERATIONS.md
//! §13.6, in pixels, each polyline split into visible and hidden runs by a depth buffer
//! of the model's triangles ([`super::depth`]).

use super::depth::DepthBuffer;
use super::model::{MarkerKind, Model, Role};
use crate::num::vector::cross;
use crate::ops::answer::Bounds;
use crate::ops::view::View;

/// A polyline of the picture, in pixels (`y` downwards).
#[derive(Debug, Clone, PartialEq)]
pub struct Stroke {
    pub role: Role,
    pub object: Option<usize>,
    pub points: Vec<[f64; 2]>,
    /// The model's point of each vertex (a vertex where the stroke was split: the point
    /// on the model's segment).
    pub source: Vec<[f64; 3]>,
    /// Hidden by a surface in front of it (drawn dashed).
    pub hidden: bool,
}

/// A marker of the picture, in pixels.
#[derive(Debug, Clone, PartialEq)]
pub struct Marker {
    pub kind: MarkerKind,
    pub at: [f64; 2],
    pub hidden: bool,
}

/// The picture: strokes and markers in pixels of a `size[0] × size[1]` image, and the
/// map from picture coordinates `(X, Y)` of §13.6 to pixels.
#[derive(Debug, Clone, PartialEq)]
pub struct Scene {
    pub size: [u32; 2],
    pub strokes: Vec<Stroke>,
    pub markers: Vec<Marker>,
    pub title: String,
    /// Pixels per picture unit.
    pub scale: f64,
    /// The picture point drawn at the image's centre.
    pub centre: [f64; 2],
}

/// Margin around the drawing, and room for the title, in pixels.
const MARGIN: f64 = 24.0;
const TITLE: f64 = 28.0;

impl Scene {
    /// The pixel of the picture point `(X, Y)`.
    pub fn pixel(&self, p: [f64; 2]) -> [f64; 2] {
        pixel(self.size, self.scale, self.centre, p)
    }
}

fn pixel(size: [u32; 2], scale: f64, centre: [f64; 2], p: [f64; 2]) -> [f64; 2] {
    let (w, h) = (f64::from(size[0]), f64::from(size[1]));
    [
        0.5 * w + (p[0] - centre[0]) * scale,
        0.5 * (h + TITLE) - (p[1] - centre[1]) * scale,
    ]
}

/// The picture of `model` in `view` (module doc). A plane model is drawn with `X = x`,
/// `Y = y` whatever the view.
pub fn scene(model: &Model, view: &View, size: [u32; 2], title: String) -> Scene {
    let view = if model.plane {
        View::horizontal()
    } else {
        view.clone()
    };
    let toward = {
        let d = cross(&view.e_x, &view.e_y);
        let l = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
        d.map(|c| c / l)
    };
    let depth_of = |x: &[f64; 3]| toward[0] * x[0] + toward[1] * x[1] + toward[2] * x[2];
    let project = |x: &[f64; 3]| view.project(x);
    // The picture's extent: every projected vertex and marker.
    let mut lo = [f64::INFINITY; 2];
    let mut hi = [f64::NEG_INFINITY; 2];
    let all = model
        .lines
        .iter()
        .flat_map(|l| l.points.iter())
        .chain(model.marks.iter().map(|m| &m.at));
    for x in all {
        let p = project(x);
        if p.iter().all(|c| c.is_finite()) {
            for k in 0..2 {
                lo[k] = lo[k].min(p[k]);
                hi[k] = hi[k].max(p[k]);
            }
        }
    }
    if !lo[0].is_finite() {
        lo = [-1.0, -1.0];
        hi = [1.0, 1.0];
    }
    let (w, h) = (f64::from(size[0]), f64::from(size[1]));
    let span = [(hi[0] - lo[0]).max(1e-300), (hi[1] - lo[1]).max(1e-300)];
    let scale = ((w - 2.0 * MARGIN) / span[0]).min((h - 2.0 * MARGIN - TITLE) / span[1]);
    let centre = [0.5 * (lo[0] + hi[0]), 0.5 * (lo[1] + hi[1])];
    let mut out = Scene {
        size,
        strokes: Vec::new(),
        markers: Vec::new(),
        title,
        scale,
        centre,
    };
    let to_pixel = |x: &[f64; 3]| {
        let p = pixel(size, scale, centre, project(x));
        [p[0], p[1], depth_of(x)]
    };
    // The occluders.
    let (mut zlo, mut zhi) = (f64::INFINITY, f64::NEG_INFINITY);
    for t in &model.triangles {
        for x in t {
            let z = depth_of(x);
            zlo = zlo.min(z);
            zhi = zhi.max(z);
        }
    }
    let tolerance = if zhi > zlo { 0.01 * (zhi - zlo) } else { 0.0 };
    let mut buffer = DepthBuffer::new(size[0] as usize, size[1] as usize, tolerance);
    if !model.plane {
        for t in &model.triangles {
            buffer.triangle(t.map(|x| to_pixel(&x)));
        }
    }
    for line in &model.lines {
        let run: Vec<([f64; 3], [f64; 3])> =
            line.points.iter().map(|x| (to_pixel(x), *x)).collect();
        for (vertices, hidden) in split(&run, &buffer) {
            out.strokes.push(Stroke {
                role: line.role,
                object: line.object,
                points: vertices.iter().map(|(p, _)| [p[0], p[1]]).collect(),
                source: vertices.iter().map(|(_, x)| *x).collect(),
                hidden,
            });
        }
    }
    for b in &model.boxes {
        out.strokes.extend(box_strokes(b, &to_pixel));
    }
    for m in &model.marks {
        let p = to_pixel(&m.at);
        out.markers.push(Marker {
            kind: m.kind,
            at: [p[0], p[1]],
            hidden: buffer.hides(p[0], p[1], p[2]),
        });
    }
    out
}

/// The strokes of a certified box: its 12 edges projected, or — when its image is less
/// than 4 pixels wide or high — the square of 4 pixels round the image's centre (so a
/// box of 10⁻¹⁶ still shows where it is). Never hidden.
fn box_strokes(b: &[Bounds; 3], to_pixel: &dyn Fn(&[f64; 3]) -> [f64; 3]) -> Vec<Stroke> {
    let corner = |k: usize| [b[0][k & 1], b[1][(k >> 1) & 1], b[2][(k >> 2) & 1]];
    let px: Vec<[f64; 3]> = (0..8).map(|k| to_pixel(&corner(k))).collect();
    let stroke = |points: Vec<[f64; 2]>, source: Vec<[f64; 3]>| Stroke {
        role: Role::Box,
        object: None,
        points,
        source,
        hidden: false,
    };
    let (lo, hi) = px.iter().fold(
        ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]),
        |(lo, hi), p| {
            (
                [lo[0].min(p[0]), lo[1].min(p[1])],
                [hi[0].max(p[0]), hi[1].max(p[1])],
            )
        },
    );
    if hi[0] - lo[0] < 4.0 || hi[1] - lo[1] < 4.0 {
        let c = [0.5 * (lo[0] + hi[0]), 0.5 * (lo[1] + hi[1])];
        let sq: Vec<[f64; 2]> = [
            (-2.0, -2.0),
            (2.0, -2.0),
            (2.0, 2.0),
            (-2.0, 2.0),
            (-2.0, -2.0),
        ]
        .iter()
        .map(|(dx, dy)| [c[0] + dx, c[1] + dy])
        .collect();
        let mid = [0, 1, 2].map(|k| 0.5 * (b[k][0] + b[k][1]));
        return vec![stroke(sq, vec![mid; 5])];
    }
    let mut out = Vec::new();
    for k in 0..8usize {
        for bit in [1usize, 2, 4] {
            if k & bit == 0 {
                let (a, e) = (px[k], px[k | bit]);
                out.push(stroke(
                    vec![[a[0], a[1]], [e[0], e[1]]],
                    vec![corner(k), corner(k | bit)],
                ));
            }
        }
    }
    out
}

/// A vertex: its pixel and depth, and its model point.
type Vertex = ([f64; 3], [f64; 3]);

/// Split a polyline into runs that are all visible or all hidden: each segment is
/// tested every 2 pixels, and a run ends at the first sample of the other kind (that
/// sample starts the next run).
fn split(line: &[Vertex], buffer: &DepthBuffer) -> Vec<(Vec<Vertex>, bool)> {
    let finite: Vec<Vertex> = line
        .iter()
        .copied()
        .filter(|(p, _)| p.iter().all(|c| c.is_finite()))
        .collect();
    let Some(first) = finite.first() else {
        return Vec::new();
    };
    let hides = |p: &[f64; 3]| buffer.hides(p[0], p[1], p[2]);
    let mix = |a: &[f64; 3], b: &[f64; 3], s: f64| [0, 1, 2].map(|c| a[c] + s * (b[c] - a[c]));
    let mut runs = Vec::new();
    let mut state = hides(&first.0);
    let mut run = vec![*first];
    for w in finite.windows(2) {
        let (a, b) = (w[0], w[1]);
        let len = ((b.0[0] - a.0[0]).powi(2) + (b.0[1] - a.0[1]).powi(2)).sqrt();
        let steps = ((len / 2.0).ceil() as usize).clamp(1, 4096);
        for k in 1..=steps {
            let s = k as f64 / steps as f64;
            let v = (mix(&a.0, &b.0, s), mix(&a.1, &b.1, s));
            let h = hides(&v.0);
            if h != state {
                run.push(v);
                runs.push((std::mem::take(&mut run), state));
                run.push(v);
                state = h;
            }
        }
        if run.last().map(|v| v.0) != Some(b.0) {
            run.push(b);
        }
    }
    runs.push((run, state));
    runs.retain(|(r, _)| r.len() >= 2);
    runs
}
