//! Point against a closed polyhedral shell (OPERATIONS.md §4), decided exactly.
//!
//! The float method of §4 (the normal at the nearest point, with the tolerance δ and a
//! fallback for non-convex edges) is replaced by exact decisions on the exact input
//! (docs/CERTIFICATES.md: a point one ulp off a face is `outside` or `inside`, not `on`):
//!
//! * `on`: the point lies on a face — exactly on its plane and inside or on the
//!   boundary of its polygon;
//! * otherwise the parity of the crossings of a ray from the point: the ray is
//!   accepted only if it meets no edge or vertex and lies in no face plane (decided
//!   exactly), so every counted crossing is transversal through a face interior; a
//!   degenerate ray is replaced by the next of a fixed list of directions.
//!
//! The nearest shell point (step 1 of §4) is the exact minimiser of the squared
//! distance over face interiors (the foot on the plane, when inside the polygon) and
//! the edges (the clamped foot on the segment), so vertices are included.

use rug::Rational;
use std::cmp::Ordering;

use super::polyhedron::{scale_add, Face, Polyhedron};
use crate::certificate::{Arithmetic, Certified};
use crate::num::ring::{dot3, sub3, Field, Ring, V3};

/// Where a point lies relative to a closed shell.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Side {
    Inside,
    On,
    Outside,
}

impl Side {
    /// The `kind` of a result (docs/FORMAT.md).
    pub fn as_str(self) -> &'static str {
        match self {
            Side::Inside => "inside",
            Side::On => "on",
            Side::Outside => "outside",
        }
    }
}

/// The answer of §4: the side and the nearest shell point, exactly.
#[derive(Debug, Clone, PartialEq)]
pub struct ShellPoint {
    pub side: Side,
    pub nearest: V3<Rational>,
    pub distance_squared: Rational,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum InPolygon {
    Inside,
    Boundary,
    Outside,
}

/// The 2D coordinates of `x` in the face's projection (dropping `axis`).
fn project(x: &V3<Rational>, axis: usize) -> [&Rational; 2] {
    match axis {
        0 => [&x[1], &x[2]],
        1 => [&x[2], &x[0]],
        _ => [&x[0], &x[1]],
    }
}

/// Exact point-in-polygon (crossing number with the half-open rule) with boundary
/// detection, for a point `x` known to lie on the face's plane. The projection drops a
/// coordinate in which the normal is non-zero, so it is one-to-one on the plane.
fn in_face(x: &V3<Rational>, shell: &Polyhedron, f: &Face) -> InPolygon {
    let q = project(x, f.axis);
    let vs: Vec<[&Rational; 2]> = shell.face_vertices(f).map(|v| project(v, f.axis)).collect();
    let mut inside = false;
    for i in 0..vs.len() {
        let (a, b) = (vs[i], vs[(i + 1) % vs.len()]);
        // orient(a, b, q) = (b − a) × (q − a)
        let o = (b[0].minus(a[0]))
            .times(&q[1].minus(a[1]))
            .minus(&(b[1].minus(a[1])).times(&q[0].minus(a[0])));
        let o = o.sign();
        let between = |k: usize| {
            let (lo, hi) = if a[k] <= b[k] {
                (a[k], b[k])
            } else {
                (b[k], a[k])
            };
            lo <= q[k] && q[k] <= hi
        };
        if o == Ordering::Equal && between(0) && between(1) {
            return InPolygon::Boundary;
        }
        if (a[1] > q[1]) != (b[1] > q[1]) && ((b[1] > a[1]) == (o == Ordering::Greater)) {
            inside = !inside;
        }
    }
    if inside {
        InPolygon::Inside
    } else {
        InPolygon::Outside
    }
}

/// The ray directions tried in turn: fixed, "generic" integer vectors (no two parallel,
/// none along an axis or a diagonal), so the answer is reproducible.
fn ray_directions() -> impl Iterator<Item = V3<Rational>> {
    let mut state: u64 = 0x9E37_79B9_7F4A_7C15;
    (0..64).map(move |_| {
        let mut c = || {
            state = state
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1_442_695_040_888_963_407);
            Rational::from(((state >> 40) as i64) - (1 << 23))
        };
        [c(), c(), c()]
    })
}

/// Crossings of the ray `p + s·r`, `s > 0`, with the faces; `None` when the ray touches
/// an edge or a vertex or lies in a face plane (a degenerate ray).
fn crossings(p: &V3<Rational>, r: &V3<Rational>, shell: &Polyhedron) -> Option<usize> {
    let mut count = 0;
    for f in shell.faces() {
        let den = dot3(&f.normal, r);
        let num = f.offset.minus(&dot3(&f.normal, p));
        if den.is_zero() {
            if num.is_zero() {
                return None; // the ray lies in this face's plane
            }
            continue;
        }
        let s = num.divide(&den);
        if s.sign() != Ordering::Greater {
            continue;
        }
        match in_face(&scale_add(p, &s, r), shell, f) {
            InPolygon::Inside => count += 1,
            InPolygon::Boundary => return None,
            InPolygon::Outside => {}
        }
    }
    Some(count)
}

/// The nearest point of the shell and its squared distance (exact).
fn nearest(p: &V3<Rational>, shell: &Polyhedron) -> (V3<Rational>, Rational) {
    let mut best: Option<(V3<Rational>, Rational)> = None;
    let mut offer = |x: V3<Rational>| {
        let w = sub3(p, &x);
        let d2 = dot3(&w, &w);
        if best.as_ref().is_none_or(|(_, b)| d2 < *b) {
            best = Some((x, d2));
        }
    };
    for f in shell.faces() {
        let nn = dot3(&f.normal, &f.normal);
        let t = f.offset.minus(&dot3(&f.normal, p)).divide(&nn);
        let foot = scale_add(p, &t, &f.normal);
        if in_face(&foot, shell, f) != InPolygon::Outside {
            offer(foot);
        }
        let vs: Vec<&V3<Rational>> = shell.face_vertices(f).collect();
        for i in 0..vs.len() {
            let (a, b) = (vs[i], vs[(i + 1) % vs.len()]);
            // Each undirected edge once: the other face holds it reversed.
            if f.indices[i] > f.indices[(i + 1) % vs.len()] {
                continue;
            }
            let d = sub3(b, a);
            let t = dot3(&sub3(p, a), &d).divide(&dot3(&d, &d));
            let t = t.clamp(&Rational::new(), &Rational::from(1));
            offer(scale_add(a, &t, &d));
        }
    }
    // A validated shell has faces, so `best` is set; fall back to the first vertex.
    best.unwrap_or_else(|| {
        let v = shell.vertices()[0].clone();
        let w = sub3(p, &v);
        let d2 = dot3(&w, &w);
        (v, d2)
    })
}

/// Classify `p` against the shell (OPERATIONS.md §4), exactly. `undecided` only if
/// every one of the fixed ray directions is degenerate (never observed; the reason says
/// so).
pub fn classify_point_polyhedron(p: &V3<Rational>, shell: &Polyhedron) -> Certified<ShellPoint> {
    let bits = |q: &Rational| {
        q.numer()
            .significant_bits()
            .max(q.denom().significant_bits())
    };
    let on = shell
        .faces()
        .iter()
        .any(|f| dot3(&f.normal, p) == f.offset && in_face(p, shell, f) != InPolygon::Outside);
    if on {
        let value = ShellPoint {
            side: Side::On,
            nearest: p.clone(),
            distance_squared: Rational::new(),
        };
        let b = p.iter().map(bits).max().unwrap_or(53).max(53);
        return Certified::exact(value, Arithmetic::Rational, b);
    }
    let (point, d2) = nearest(p, shell);
    let b = point
        .iter()
        .chain([&d2])
        .map(bits)
        .max()
        .unwrap_or(53)
        .max(53);
    for r in ray_directions() {
        if let Some(n) = crossings(p, &r, shell) {
            let side = if n % 2 == 1 {
                Side::Inside
            } else {
                Side::Outside
            };
            let value = ShellPoint {
                side,
                nearest: point,
                distance_squared: d2,
            };
            return Certified::exact(value, Arithmetic::Rational, b);
        }
    }
    let value = ShellPoint {
        side: Side::Outside,
        nearest: point,
        distance_squared: d2,
    };
    Certified::undecided(
        value,
        Arithmetic::Rational,
        b,
        "every ray direction tried touches an edge or a vertex",
    )
}
