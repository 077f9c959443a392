//! Three surfaces (OPERATIONS.md §7.2), float path, with initial guesses found by a
//! search rather than supplied by the caller.
//!
//! Search (impl; §7.2 gives none beyond "a known approximate point"): every walk node
//! of a surface covers a patch of radius `|s_u|Δu + |s_v|Δv` around its point; node
//! triples whose patches overlap pairwise (found through a uniform grid over the
//! nodes of two surfaces) are linearised — the three tangent planes are intersected by
//! (7.2) and the increments recovered on each tangent plane by (3.7)–(3.8) — and a
//! guess is emitted when every increment lies inside its node's window. Newton runs on
//! (7.3) with the Jacobian (7.4); solutions are verified (`|r − q|, |s − q| ≤ δ_len`)
//! and merged (§0.4).

use crate::certify::system::value_and_rows;
use crate::certify::System;
use crate::num::vector::{cross, dot, norm_f64, sub};
use crate::num::Real;
use crate::ops::float::merge::{merge_duplicates, ParamTolerance};
use crate::ops::float::{newton, Coordinate, NewtonOutcome, Precision};
use crate::surface::Surface;
use std::collections::HashMap;

/// One common point of three surfaces.
#[derive(Debug, Clone, PartialEq)]
pub struct ThreeSurfacePoint {
    /// The parameters on each surface, in input order.
    pub params: [[f64; 2]; 3],
    /// The point (on the third surface).
    pub point: [f64; 3],
}

/// (7.3) `[r(u,v) − q(x,y); s(a,b) − q(x,y)]` with, on request, the Jacobian (7.4),
/// written once for every number type (`x = [u, v, a, b, x, y]`).
pub fn three_surface_equations<T: Real, R: Surface, S: Surface, Q: Surface>(
    r: &R,
    s: &S,
    q: &Q,
    x: &[T; 6],
    jacobian: bool,
) -> ([T; 6], Option<[[T; 6]; 6]>) {
    let order = usize::from(jacobian);
    let (jr, js, jq) = (
        r.jet(&x[0], &x[1], order),
        s.jet(&x[2], &x[3], order),
        q.jet(&x[4], &x[5], order),
    );
    let (fr, fs) = (sub(&jr[0], &jq[0]), sub(&js[0], &jq[0]));
    let f = std::array::from_fn(|i| {
        if i < 3 {
            fr[i].clone()
        } else {
            fs[i - 3].clone()
        }
    });
    let j = jacobian.then(|| {
        let zero = x[0].zero_like();
        std::array::from_fn(|row| {
            let (k, first) = (row % 3, row < 3);
            let a = if first { &jr } else { &js };
            let mut line: [T; 6] = std::array::from_fn(|_| zero.clone());
            let offset = if first { 0 } else { 2 };
            line[offset] = a[1][k].clone();
            line[offset + 1] = a[2][k].clone();
            line[4] = -jq[1][k].clone();
            line[5] = -jq[2][k].clone();
            line
        })
    });
    (f, j)
}

/// A walk node with its point, tangent plane and covering radius.
struct Node {
    params: [f64; 2],
    window: [f64; 2],
    point: [f64; 3],
    su: [f64; 3],
    sv: [f64; 3],
    radius: f64,
}

fn nodes_of<S: Surface>(surface: &S, nodes: &[[f64; 4]]) -> Vec<Node> {
    nodes
        .iter()
        .map(|&[u, v, du, dv]| {
            let j = surface.jet(&u, &v, 1);
            Node {
                params: [u, v],
                window: [du, dv],
                point: j[0],
                su: j[1],
                sv: j[2],
                radius: norm_f64(&j[1]) * du + norm_f64(&j[2]) * dv,
            }
        })
        .collect()
}

/// All common points of `r`, `s`, `q` (§7.2), float only, from their walk nodes
/// `[(u, v, Δu, Δv)]` (§2.3).
pub fn intersect_three_surfaces_f64<R: Surface, S: Surface, Q: Surface>(
    surfaces: (&R, &S, &Q),
    nodes: [&[[f64; 4]]; 3],
    precision: &Precision,
) -> Vec<ThreeSurfacePoint> {
    let (r, s, q) = surfaces;
    let (nr, ns, nq) = (
        nodes_of(r, nodes[0]),
        nodes_of(s, nodes[1]),
        nodes_of(q, nodes[2]),
    );
    let cell = nr
        .iter()
        .chain(&ns)
        .chain(&nq)
        .map(|n| n.radius)
        .fold(0.0f64, f64::max)
        .max(f64::MIN_POSITIVE);
    let key = |p: &[f64; 3]| p.map(|x| (x / (2.0 * cell)).floor() as i64);
    let grid = |ns: &[Node]| {
        let mut g: HashMap<[i64; 3], Vec<usize>> = HashMap::new();
        for (i, n) in ns.iter().enumerate() {
            g.entry(key(&n.point)).or_default().push(i);
        }
        g
    };
    let (gr, gs) = (grid(&nr), grid(&ns));
    let near = |g: &HashMap<[i64; 3], Vec<usize>>, p: &[f64; 3]| {
        let k = key(p);
        let mut out = Vec::new();
        for dx in -1..=1 {
            for dy in -1..=1 {
                for dz in -1..=1 {
                    if let Some(v) = g.get(&[k[0] + dx, k[1] + dy, k[2] + dz]) {
                        out.extend_from_slice(v);
                    }
                }
            }
        }
        out
    };
    let overlap = |a: &Node, b: &Node| norm_f64(&sub(&a.point, &b.point)) <= a.radius + b.radius;
    let mut guesses = Vec::new();
    for c in &nq {
        // guesses only seed the search (issue 20: three surfaces through one curve
        // would give one at nearly every triple of nodes)
        if guesses.len() >= super::curve_surface::MAX_GUESSES {
            break;
        }
        let near_s = near(&gs, &c.point);
        for i in near(&gr, &c.point) {
            let a = &nr[i];
            if !overlap(a, c) {
                continue;
            }
            for &k in &near_s {
                let b = &ns[k];
                if overlap(b, c) && overlap(a, b) {
                    if let Some(g) = linearised_guess([a, b, c]) {
                        guesses.push(g);
                    }
                }
            }
        }
    }
    let coords = coordinates(
        [r.domain(), s.domain(), q.domain()],
        [r.is_closed(), s.is_closed(), q.is_closed()],
        precision,
    );
    let length = nq.iter().map(|n| norm_f64(&n.point)).fold(1.0f64, f64::max);
    let delta_len = precision.delta * length;
    let mut found = Vec::new();
    for x0 in guesses {
        let system = |x: &[f64; 6]| {
            let (f, j) = three_surface_equations(r, s, q, x, true);
            (f, j.unwrap_or([[f64::NAN; 6]; 6]))
        };
        let NewtonOutcome::Converged(x) = newton(system, x0, &coords, 32) else {
            continue;
        };
        let Some(y) = inside(x, &coords, precision) else {
            continue;
        };
        let (f, _) = three_surface_equations(r, s, q, &y, false);
        let gap = norm_f64(&[f[0], f[1], f[2]]).max(norm_f64(&[f[3], f[4], f[5]]));
        if gap <= delta_len {
            let point = q.jet(&y[4], &y[5], 0)[0];
            found.push((
                ThreeSurfacePoint {
                    params: [[y[0], y[1]], [y[2], y[3]], [y[4], y[5]]],
                    point,
                },
                gap,
            ));
        }
    }
    let tolerances = coords.map(|c| ParamTolerance {
        delta: precision.delta * (c.hi - c.lo).max(1.0),
        period: c.periodic.then_some(c.hi - c.lo),
    });
    let flat = |(p, _): &(ThreeSurfacePoint, f64)| p.params.concat();
    let merged = merge_duplicates(found, &tolerances, flat, |(_, g)| *g);
    let length_tol = [ParamTolerance {
        delta: delta_len,
        period: None,
    }; 3];
    let merged = merge_duplicates(merged, &length_tol, |(p, _)| p.point.to_vec(), |(_, g)| *g);
    let mut points: Vec<ThreeSurfacePoint> = merged.into_iter().map(|(p, _)| p).collect();
    points.sort_by(|a, b| {
        a.point
            .partial_cmp(&b.point)
            .unwrap_or(std::cmp::Ordering::Equal)
    });
    points
}

/// Intersect the three tangent planes (7.2) and recover the increments on each by
/// (3.7)–(3.8); `Some(guess)` when every increment is inside its node's window.
fn linearised_guess(nodes: [&Node; 3]) -> Option<[f64; 6]> {
    let n = nodes.map(|m| cross(&m.su, &m.sv));
    let triple = dot(&n[0], &cross(&n[1], &n[2]));
    let scale = norm_f64(&n[0]) * norm_f64(&n[1]) * norm_f64(&n[2]);
    // Nearly parallel tangent planes (or NaN): no linearised point.
    if triple.abs().partial_cmp(&(1e-12 * scale)) != Some(std::cmp::Ordering::Greater) {
        return None;
    }
    let h = [0, 1, 2].map(|i| dot(&n[i], &nodes[i].point));
    let (c12, c20, c01) = (
        cross(&n[1], &n[2]),
        cross(&n[2], &n[0]),
        cross(&n[0], &n[1]),
    );
    let p: [f64; 3] =
        std::array::from_fn(|k| (h[0] * c12[k] + h[1] * c20[k] + h[2] * c01[k]) / triple);
    let mut guess = [0.0; 6];
    for (i, m) in nodes.iter().enumerate() {
        let w = sub(&p, &m.point);
        let (g11, g12, g22) = (dot(&m.su, &m.su), dot(&m.su, &m.sv), dot(&m.sv, &m.sv));
        let det = g11 * g22 - g12 * g12;
        let (a, b) = (dot(&m.su, &w), dot(&m.sv, &w));
        let (du, dv) = ((g22 * a - g12 * b) / det, (g11 * b - g12 * a) / det);
        let within = du.abs() <= m.window[0] && dv.abs() <= m.window[1];
        if !within {
            return None;
        }
        guess[2 * i] = m.params[0] + du;
        guess[2 * i + 1] = m.params[1] + dv;
    }
    Some(guess)
}

type Domain = ([f64; 2], [f64; 2]);

fn coordinates(
    domains: [Domain; 3],
    closed: [[bool; 2]; 3],
    precision: &Precision,
) -> [Coordinate; 6] {
    std::array::from_fn(|i| {
        let d = domains[i / 2];
        let [lo, hi] = if i % 2 == 0 { d.0 } else { d.1 };
        Coordinate::new(lo, hi, closed[i / 2][i % 2], precision)
    })
}

/// `x` clamped into the domains when within δ of them (§0.4), else `None`.
fn inside(x: [f64; 6], coords: &[Coordinate; 6], precision: &Precision) -> Option<[f64; 6]> {
    let mut y = x;
    for (value, c) in y.iter_mut().zip(coords) {
        let slack = precision.delta * (c.hi - c.lo);
        if !c.periodic && !(c.lo - slack..=c.hi + slack).contains(value) {
            return None;
        }
        *value = value.clamp(c.lo, c.hi);
    }
    Some(y)
}

/// (7.3): `r(u,v) − q(x,y) = s(a,b) − q(x,y) = 0`, six unknowns.
pub struct ThreeSurfaceSystem<'a, R, S, Q> {
    pub r: &'a R,
    pub s: &'a S,
    pub q: &'a Q,
}

impl<R: Surface, S: Surface, Q: Surface> System for ThreeSurfaceSystem<'_, R, S, Q> {
    fn dim(&self) -> usize {
        6
    }
    fn eval<T: Real>(&self, x: &[T]) -> Vec<T> {
        let x: [T; 6] = std::array::from_fn(|i| x[i].clone());
        three_surface_equations(self.r, self.s, self.q, &x, false)
            .0
            .to_vec()
    }
    /// The Jacobian (7.4) from the surfaces' own first derivatives (one jet of order 1
    /// each instead of jets over dual numbers; interval boxes of patches take the fast
    /// centred form).
    fn eval_with_jacobian<T: Real>(&self, x: &[T]) -> (Vec<T>, Vec<Vec<T>>) {
        let x: [T; 6] = std::array::from_fn(|i| x[i].clone());
        let (f, j) = three_surface_equations(self.r, self.s, self.q, &x, true);
        value_and_rows(f, j)
    }
}

/// All common points of three surfaces (§7.2), certified: roots of (7.3) in verified
/// boxes, `complete` when the subdivision of the six-dimensional domain finished.
pub fn intersect_three_surfaces<R: Surface, S: Surface, Q: Surface>(
    surfaces: (&R, &S, &Q),
    nodes: [&[[f64; 4]]; 3],
    precision: &Precision,
    opts: &crate::ops::certified::Options,
) -> Result<crate::Certified<Vec<crate::ops::certified::CertifiedPoint<3>>>, crate::GeomError> {
    use crate::ops::certified::{
        certify_roots, surface_point, surface_unknowns, CertifiedPoint, Unknowns,
    };
    let (r, s, q) = surfaces;
    let guesses: Vec<Vec<f64>> = intersect_three_surfaces_f64(surfaces, nodes, precision)
        .iter()
        .map(|p| p.params.concat())
        .collect();
    let unknowns = Unknowns::concat(&[
        surface_unknowns(r),
        surface_unknowns(s),
        surface_unknowns(q),
    ]);
    let roots = certify_roots(&ThreeSurfaceSystem { r, s, q }, &unknowns, &guesses, opts)?;
    Ok(roots.map(|rs| {
        rs.into_iter()
            .map(|root| {
                let uv = [root.params[4], root.params[5]];
                let (point, point_box) =
                    surface_point(q, uv, &root.enclosure[4], &root.enclosure[5]);
                CertifiedPoint {
                    root,
                    point,
                    point_box,
                }
            })
            .collect()
    }))
}
