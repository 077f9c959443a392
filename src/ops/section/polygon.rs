//! Plane sections of closed polyhedra (OPERATIONS.md §13.3, any closed shell of the
//! case format): the ordered section polygon(s), with exact rational vertices.
//!
//! Each face is cut along the line `L` it shares with the plane `n·x + d = 0`; a
//! vertex's side is the exact sign of `s(v) = n·v + d`. Vertices on the plane are
//! decided by symbolic perturbation: the plane is moved by `∓ε` (`s(v) + ε`, so a
//! vertex on the plane counts on the `+` side; or `s(v) − ε`), which makes every
//! crossing transversal, and the polygon of the moved plane is taken in the limit
//! `ε → 0`: a crossing on the edge `uv` (`s(u) < 0 ≤ s(v)`) is the exact point
//! `u + (v − u)·s(u)/(s(u) − s(v))` (a vertex on the plane is its own crossing). The
//! crossings of one face are sorted along `D = n × N_f` (`N_f` the outward face
//! normal), ties broken by their motion with `ε` (exact too), and paired; the segment
//! runs along `D`, which is the direction of the cap of `{s ≤ 0}` (outward normal `n`)
//! traversing its edge with that face, so every loop is counter-clockwise seen from
//! `+n` around the material and clockwise around a hole. Segments chain through their
//! edges (each edge joins two faces), so coinciding limit points never confuse the
//! order. The `+ε` side is used first; when it cuts nothing (a plane touching the
//! shell from below) the `−ε` side is used. In the limit, repeated consecutive points
//! are merged: a plane through a vertex or along an edge of a convex shell from
//! outside gives a single point or a two-point (degenerate) loop, and a plane
//! containing a face gives that face's polygon.

use rug::Rational;
use std::cmp::Ordering;
use std::collections::HashMap;

use super::plane::ExactPlane;
use crate::num::ring::{cross3, dot3, sub3, V3};
use crate::ops::polyhedron::Polyhedron;

/// One section loop: its exact vertices in order (not repeating the first).
#[derive(Debug, Clone, PartialEq)]
pub struct SectionLoop {
    pub vertices: Vec<V3<Rational>>,
}

impl SectionLoop {
    /// Twice the signed area times `|n|`: `n·Σ pᵢ × pᵢ₊₁` (positive for material
    /// loops, negative for holes).
    pub fn area_times(&self, n: &V3<Rational>) -> Rational {
        let k = self.vertices.len();
        let mut s = Rational::new();
        for i in 0..k {
            s += dot3(n, &cross3(&self.vertices[i], &self.vertices[(i + 1) % k]));
        }
        s
    }
}

type Edge = (usize, usize);

fn edge(a: usize, b: usize) -> Edge {
    (a.min(b), a.max(b))
}

/// The section of a closed polyhedron by a plane: its loops (module documentation).
pub fn section_plane_polyhedron(plane: &ExactPlane, shell: &Polyhedron) -> Vec<SectionLoop> {
    let s: Vec<Rational> = shell.vertices().iter().map(|v| plane.eval(v)).collect();
    for up in [true, false] {
        let side: Vec<bool> = s
            .iter()
            .map(|x| match x.cmp0() {
                Ordering::Equal => up,
                o => o == Ordering::Greater,
            })
            .collect();
        let loops = cut(plane, shell, &s, &side);
        if !loops.is_empty() {
            return loops;
        }
    }
    vec![]
}

/// A crossing: its edge (`below` vertex, `above` vertex) and exact point.
struct Crossing {
    edge: Edge,
    point: V3<Rational>,
    key: (Rational, Rational),
}

fn cut(plane: &ExactPlane, shell: &Polyhedron, s: &[Rational], side: &[bool]) -> Vec<SectionLoop> {
    let vs = shell.vertices();
    let mut next: HashMap<Edge, Edge> = HashMap::new();
    let mut points: HashMap<Edge, V3<Rational>> = HashMap::new();
    for f in shell.faces() {
        let dir = cross3(&plane.normal, &f.normal);
        let k = f.indices.len();
        let mut crossings: Vec<Crossing> = vec![];
        for i in 0..k {
            let (a, b) = (f.indices[i], f.indices[(i + 1) % k]);
            if side[a] == side[b] {
                continue;
            }
            let (lo, hi) = if side[a] { (b, a) } else { (a, b) };
            let point = crossing(&vs[lo], &vs[hi], &s[lo], &s[hi]);
            // Motion with ε: d/dε of D·p is −D·(hi − lo)/(s(hi) − s(lo)).
            let den = Rational::from(&s[hi] - &s[lo]);
            let motion = -dot3(&dir, &sub3(&vs[hi], &vs[lo])) / den;
            let key = (dot3(&dir, &point), motion);
            crossings.push(Crossing {
                edge: edge(lo, hi),
                point,
                key,
            });
        }
        crossings.sort_by(|x, y| x.key.cmp(&y.key));
        for pair in crossings.chunks(2) {
            if let [from, to] = pair {
                next.insert(from.edge, to.edge);
                points.insert(from.edge, from.point.clone());
                points.insert(to.edge, to.point.clone());
            }
        }
    }
    chain(next, &points)
}

fn crossing(
    lo: &V3<Rational>,
    hi: &V3<Rational>,
    s_lo: &Rational,
    s_hi: &Rational,
) -> V3<Rational> {
    if s_lo.cmp0() == Ordering::Equal {
        return lo.clone();
    }
    if s_hi.cmp0() == Ordering::Equal {
        return hi.clone();
    }
    let t = s_lo / Rational::from(s_lo - s_hi);
    std::array::from_fn(|i| Rational::from(&hi[i] - &lo[i]) * &t + &lo[i])
}

/// Follow the segments into loops, merging repeated consecutive points.
fn chain(mut next: HashMap<Edge, Edge>, points: &HashMap<Edge, V3<Rational>>) -> Vec<SectionLoop> {
    let mut starts: Vec<Edge> = next.keys().copied().collect();
    starts.sort();
    let mut loops = vec![];
    for start in starts {
        let Some(mut at) = next.remove(&start) else {
            continue;
        };
        let mut vertices = vec![points[&start].clone()];
        while at != start {
            vertices.push(points[&at].clone());
            match next.remove(&at) {
                Some(n) => at = n,
                None => break, // an open chain cannot occur on a closed shell
            }
        }
        vertices.dedup();
        while vertices.len() > 1 && vertices.first() == vertices.last() {
            vertices.pop();
        }
        loops.push(SectionLoop { vertices });
    }
    loops
}
