//! Projection of a point onto a surface along a direction (OPERATIONS.md §3.5, §5.3):
//! the intersections of the line `l(t) = p + t·ĉ` with the surface, `t` the signed
//! travel; the nearest is the one with the smallest `|t|`.

use crate::curve::Curve;
use crate::num::vector::{norm_f64, sub};
use crate::num::Real;
use crate::ops::float::Precision;
use crate::ops::intersect::{intersect_curve_surface_f64, CurveSurfacePoint};
use crate::surface::Surface;

/// The line `origin + t·dir` on `t ∈ [lo, hi]`, as a curve (§1.5 line).
#[derive(Debug, Clone, PartialEq)]
pub struct Ray {
    pub origin: [f64; 3],
    pub dir: [f64; 3],
    pub range: [f64; 2],
}

impl Curve<3> for Ray {
    fn domain(&self) -> (f64, f64) {
        (self.range[0], self.range[1])
    }

    fn jet<T: Real>(&self, t: &T, order: usize) -> Vec<[T; 3]> {
        let point = std::array::from_fn(|i| t.lift(self.origin[i]) + t.lift(self.dir[i]) * t);
        let mut out = vec![point];
        if order >= 1 {
            out.push(std::array::from_fn(|i| t.lift(self.dir[i])));
        }
        for _ in 2..=order {
            out.push(std::array::from_fn(|_| t.zero_like()));
        }
        out
    }
}

/// The line through `p` along `dir` restricted to the travel that can reach the
/// surface: `|t|·|dir| ≤ |p − m| + ρ`, with `m` and `ρ` a centre and radius enclosing
/// the walk nodes and their windows.
pub fn ray_through<S: Surface>(
    surface: &S,
    p: &[f64; 3],
    dir: &[f64; 3],
    nodes: &[[f64; 4]],
) -> Ray {
    let points: Vec<([f64; 3], f64)> = nodes
        .iter()
        .map(|&[u, v, du, dv]| {
            let j = surface.jet(&u, &v, 1);
            (j[0], norm_f64(&j[1]) * du + norm_f64(&j[2]) * dv)
        })
        .collect();
    let n = points.len().max(1) as f64;
    let m: [f64; 3] = std::array::from_fn(|i| points.iter().map(|(q, _)| q[i]).sum::<f64>() / n);
    let rho = points
        .iter()
        .map(|(q, r)| norm_f64(&sub(q, &m)) + r)
        .fold(0.0f64, f64::max);
    let reach = (norm_f64(&sub(p, &m)) + rho) / norm_f64(dir) * 1.01 + f64::MIN_POSITIVE;
    Ray {
        origin: *p,
        dir: *dir,
        range: [-reach, reach],
    }
}

/// All projections of `p` onto `surface` along `dir` (§3.5), float only, ordered by
/// travel `t`; with `nearest`, only the one of smallest `|t|`.
pub fn project_point_surface_along_f64<S: Surface>(
    surface: &S,
    p: &[f64; 3],
    dir: &[f64; 3],
    nodes: &[[f64; 4]],
    turn: f64,
    precision: &Precision,
    nearest: bool,
) -> Vec<CurveSurfacePoint> {
    let ray = ray_through(surface, p, dir, nodes);
    // §5.3: for a line, (2.1) gives one step over the whole range.
    let (lo, hi) = ray.domain();
    let samples = [(lo, hi - lo), (hi, hi - lo)];
    let mut points = intersect_curve_surface_f64(surface, &ray, &samples, nodes, turn, precision);
    if nearest {
        points.sort_by(|a, b| a.t.abs().total_cmp(&b.t.abs()));
        points.truncate(1);
    }
    points
}
