//! Stage 1 of surface ∩ surface (OPERATIONS.md §9.2): starting points on every curve that
//! crosses an iso-line, from the iso-curves of each surface intersected with the other
//! (§5.2, [`intersect_curve_surface_f64`]); points where the surfaces touch are kept apart
//! as contact candidates. In addition (impl), node pairs of the two walks whose points
//! are close and whose normals are nearly parallel seed the contact locator, so that
//! isolated contacts (which no iso-line need meet) are candidates too.

use super::frame::LocalFrame;
use super::operand::Pair;
use super::trace::Start;
use crate::curve::Curve;
use crate::num::vector::{cross, dot, norm_f64, sub};
use crate::ops::intersect::curve_surface::{
    intersect_curve_surface_until, CurveSurfacePoint, Seeds,
};
use crate::ops::project::IsoCurve;
use crate::surface::Surface;
use crate::walk::surface::{SurfaceWalk, SurfaceWalkOptions};
use crate::walk::{CurveWalk, WalkOptions};

/// `Δα_scan` of §2.1.
const SCAN: f64 = std::f64::consts::PI / 10.0;

/// The walk nodes `[u, v, Δu, Δv]` of a surface (§2.3, `Δα_scan`).
pub fn nodes<S: Surface>(s: &S) -> Vec<[f64; 4]> {
    SurfaceWalk::new(s, SurfaceWalkOptions::new(SCAN))
        .map(|w| w.map(|n| [n.u, n.v, n.du, n.dv]).collect())
        .unwrap_or_default()
}

/// The iso-values of §9.2: the row values `v_j` and the `u_i` of the longest row.
fn iso_values(nodes: &[[f64; 4]]) -> (Vec<f64>, Vec<f64>) {
    let mut rows: Vec<f64> = Vec::new();
    let mut row_u: Vec<Vec<f64>> = Vec::new();
    for n in nodes {
        if rows.last() != Some(&n[1]) {
            rows.push(n[1]);
            row_u.push(Vec::new());
        }
        if let Some(r) = row_u.last_mut() {
            r.push(n[0]);
        }
    }
    let us = row_u.into_iter().max_by_key(Vec::len).unwrap_or_default();
    (rows, us)
}

/// Stage 1: the start points and the contact candidates (`[u, v, a, b]`). Once the
/// certifier's deadline (`options.certify.deadline`) has passed or the float stage's
/// share of `max_boxes` is spent ([`Pair::spend`]: one unit per iso-curve, curve sample,
/// guess and contact node), the iso-curves left are not intersected (issue 20): the
/// start points found by then only seed the tracer, and the completeness proof, run
/// under the same limits and independent of this stage, fails rather than claim a
/// point missed here absent.
pub fn starting_points<R: Surface, S: Surface>(
    pair: &Pair<'_, R, S>,
) -> (Vec<Start>, Vec<[f64; 4]>) {
    let (nr, ns) = (nodes(pair.r), nodes(pair.s));
    let stop = || pair.spend(1);
    let mut found: Vec<([f64; 4], bool)> = Vec::new();
    // 1. iso-curves of r against s: points (u, v) = iso, (a, b) on s
    for (fixed, value, cp) in
        iso_intersections(pair.r, pair.s, &nr, &ns, &pair.options.precision, &stop)
    {
        let t = cp.t;
        let (u, v) = if fixed == 1 { (t, value) } else { (value, t) };
        let [a, b] = cp.surface_params;
        found.push(([u, v, a, b], cp.tangent));
    }
    // 2. iso-curves of s against r
    for (fixed, value, cp) in
        iso_intersections(pair.s, pair.r, &ns, &nr, &pair.options.precision, &stop)
    {
        let t = cp.t;
        let (a, b) = if fixed == 1 { (t, value) } else { (value, t) };
        let [u, v] = cp.surface_params;
        found.push(([u, v, a, b], cp.tangent));
    }
    let sin_tan = pair.options.precision.delta_tan();
    let mut starts = Vec::new();
    let mut contacts = Vec::new();
    for (x, tangent) in found {
        let f = LocalFrame::at(pair, x, 1.0, None);
        if tangent || f.sin.partial_cmp(&sin_tan).is_none_or(|o| o.is_lt()) {
            contacts.push(x);
        } else if !starts.iter().any(|s: &Start| same(pair, &s.x, &x)) {
            starts.push(Start {
                x,
                p: f.point(),
                tangent: f.tangent,
            });
        }
    }
    if !pair.spend(0) {
        contacts.extend(contact_seeds(pair, &nr, &ns));
    }
    (starts, contacts)
}

/// Two start points are one (§0.4 with δ on all four parameters).
fn same<R, S>(pair: &Pair<'_, R, S>, x: &[f64; 4], y: &[f64; 4]) -> bool {
    (0..4).all(|k| {
        let c = &pair.coords[k];
        pair.param_distance(k, x[k], y[k]) <= pair.options.precision.delta * (c.hi - c.lo).max(1.0)
    })
}

/// Every iso-curve of `q` (rows `v = v_j`, columns `u = u_i`) intersected with `other`:
/// `(fixed direction of q, fixed value, point)` with `t` the free parameter of q; the
/// iso-curves left once `stop` says so are skipped (asked per iso-curve, and per
/// curve sample and guess inside [`intersect_curve_surface_until`]).
fn iso_intersections<Q: Surface, O: Surface>(
    q: &Q,
    other: &O,
    q_nodes: &[[f64; 4]],
    other_nodes: &[[f64; 4]],
    precision: &crate::ops::float::Precision,
    stop: &dyn Fn() -> bool,
) -> Vec<(usize, f64, CurveSurfacePoint)> {
    let (rows, columns) = iso_values(q_nodes);
    let mut out = Vec::new();
    let lines = rows
        .iter()
        .map(|&v| (1usize, v))
        .chain(columns.iter().map(|&u| (0usize, u)));
    for (fixed, value) in lines {
        if stop() {
            break;
        }
        // IsoCurve's `direction` is the running parameter.
        let iso = IsoCurve {
            surface: q,
            direction: 1 - fixed,
            fixed: value,
        };
        let samples: Vec<(f64, f64)> = match CurveWalk::new(&iso, WalkOptions::default()) {
            Ok(w) => w.map(|s| (s.t, s.step)).collect(),
            Err(_) => continue,
        };
        if samples.is_empty() || iso.domain().0 >= iso.domain().1 {
            continue;
        }
        let seeds = Seeds {
            curve_samples: &samples,
            surface_nodes: other_nodes,
            turn: SCAN,
        };
        for p in intersect_curve_surface_until(other, &iso, &seeds, precision, stop) {
            out.push((fixed, value, p));
        }
    }
    out
}

/// Node pairs whose points lie within the sum of their windows' radii and whose normals
/// are within `2Δα_scan` of parallel: seeds of the contact locator (impl).
fn contact_seeds<R: Surface, S: Surface>(
    pair: &Pair<'_, R, S>,
    nr: &[[f64; 4]],
    ns: &[[f64; 4]],
) -> Vec<[f64; 4]> {
    struct Node {
        uv: [f64; 2],
        p: [f64; 3],
        n: [f64; 3],
        radius: f64,
    }
    let prepare = |q: &dyn Fn(f64, f64) -> Vec<[f64; 3]>, nodes: &[[f64; 4]]| -> Vec<Node> {
        nodes
            .iter()
            .filter_map(|&[u, v, du, dv]| {
                let j = q(u, v);
                let n = cross(&j[1], &j[2]);
                let len = norm_f64(&n);
                (len > 0.0).then(|| Node {
                    uv: [u, v],
                    p: j[0],
                    n: n.map(|c| c / len),
                    radius: norm_f64(&j[1]) * du + norm_f64(&j[2]) * dv,
                })
            })
            .collect()
    };
    let a = prepare(&|u, v| pair.r.jet(&u, &v, 1), nr);
    let b = prepare(&|u, v| pair.s.jet(&u, &v, 1), ns);
    let limit = (2.0 * SCAN).sin();
    let mut seeds = Vec::new();
    for x in &a {
        if pair.spend(1) {
            break;
        }
        for y in &b {
            let close = norm_f64(&sub(&x.p, &y.p)) <= x.radius + y.radius;
            if close && norm_f64(&cross(&x.n, &y.n)) <= limit && dot(&x.n, &y.n).abs() > 0.0 {
                seeds.push([x.uv[0], x.uv[1], y.uv[0], y.uv[1]]);
            }
        }
    }
    seeds
}
