//! Locating singular points of the intersection, float (OPERATIONS.md §9.5): points where
//! the surfaces touch (`n̂_r × n̂_s = 0`), found by Newton on the common-normal system
//! ([`CommonNormalSystem`], the regular form of (9.7): (9.8) is singular all along the
//! curve, §9.5 "Solver note"), and points where the intersection passes through a
//! singular point of one surface (a cone's apex: its normal vanishes), found as critical
//! points of `φ = G(r(u, v))` when the other surface has an implicit form `G`.
//!
//! Verification as in §9.5: a converged point is a contact when the gap along the common
//! normal is at most `δ_len` (for `φ`: the distance estimate `|φ|/|∇G|`, or
//! `√(2|φ|/‖∇²G‖)` where `∇G` vanishes).

use super::equations::CommonNormalSystem;
use super::operand::Pair;
use super::types::{SingularKind, SingularPoint};
use crate::certify::System;
use crate::num::vector::{cross, dot, norm_f64, sub};
use crate::ops::float::{newton, newton_with, Coordinate, NewtonOutcome};
use crate::surface::{AnyImplicit, Implicit, Surface};

/// The Newton limit of the tangency systems (§0.4: 200).
const K_TANGENCY: usize = 200;

/// A contact near the guess `x` (within `reach` in every parameter, periodic distance), or
/// `None`.
pub fn locate_contact<R: Surface, S: Surface>(
    pair: &Pair<'_, R, S>,
    x: [f64; 4],
    reach: f64,
    kind: SingularKind,
) -> Option<SingularPoint> {
    let near = |y: &[f64; 4]| (0..4).all(|i| pair.param_distance(i, x[i], y[i]) <= reach);
    if let Some(p) = common_normal(pair, x) {
        if near(&p.params) && p.gap <= pair.delta_len() {
            return Some(SingularPoint { kind, ..p });
        }
    }
    let p = implicit_critical(pair, x)?;
    (near(&p.params) && p.gap <= pair.delta_len()).then_some(SingularPoint { kind, ..p })
}

/// Newton on the common-normal system from `x` (and `λ` from the residual): the point
/// with its gap `|λ|·|N_s|`, if Newton converges inside the domain.
pub fn common_normal<R: Surface, S: Surface>(
    pair: &Pair<'_, R, S>,
    x: [f64; 4],
) -> Option<SingularPoint> {
    let sys = CommonNormalSystem {
        r: pair.r,
        s: pair.s,
    };
    let jr = pair.r.jet(&x[0], &x[1], 0);
    let js = pair.s.jet(&x[2], &x[3], 1);
    let ns = cross(&js[1], &js[2]);
    let lambda = dot(&sub(&jr[0], &js[0]), &ns) / dot(&ns, &ns);
    let lambda = if lambda.is_finite() { lambda } else { 0.0 };
    let system = |y: &[f64; 5]| {
        let (f, j) = sys.eval_with_jacobian(y);
        let f: [f64; 5] = std::array::from_fn(|i| f[i]);
        let j: [[f64; 5]; 5] = std::array::from_fn(|i| std::array::from_fn(|k| j[i][k]));
        (f, j)
    };
    let free = Coordinate {
        lo: f64::NEG_INFINITY,
        hi: f64::INFINITY,
        periodic: false,
        eps: pair.options.precision.eps * pair.length,
        margin: f64::INFINITY,
    };
    let coords = [
        pair.coords[0],
        pair.coords[1],
        pair.coords[2],
        pair.coords[3],
        free,
    ];
    let y = match newton(
        system,
        [x[0], x[1], x[2], x[3], lambda],
        &coords,
        K_TANGENCY,
    ) {
        NewtonOutcome::Converged(y) => y,
        _ => return None,
    };
    let params = [y[0], y[1], y[2], y[3]];
    if !pair.inside(&params, pair.options.precision.delta) {
        return None;
    }
    let params = pair.wrap(params);
    let js = pair.s.jet(&y[2], &y[3], 1);
    let gap = y[4].abs() * norm_f64(&cross(&js[1], &js[2]));
    Some(SingularPoint {
        params,
        xyz: super::corrector::space_point(pair, &params),
        kind: SingularKind::Contact,
        gap,
    })
}

/// A critical point of `φ = G(r(u, v))` (or of `G_r(s(a, b))`) near `x`, for a pair with
/// an implicit form; the other surface's parameters by a damped projection.
pub fn implicit_critical<R: Surface, S: Surface>(
    pair: &Pair<'_, R, S>,
    x: [f64; 4],
) -> Option<SingularPoint> {
    if let Some(g) = &pair.implicit[1] {
        let (uv, gap) = critical_on(pair.r, g, [x[0], x[1]], [pair.coords[0], pair.coords[1]])?;
        let p = pair.r.jet(&uv[0], &uv[1], 0)[0];
        let ab = project(pair.s, &p, [x[2], x[3]])?;
        let params = [uv[0], uv[1], ab[0], ab[1]];
        return finish(pair, params, gap);
    }
    let g = pair.implicit[0].as_ref()?;
    let (ab, gap) = critical_on(pair.s, g, [x[2], x[3]], [pair.coords[2], pair.coords[3]])?;
    let p = pair.s.jet(&ab[0], &ab[1], 0)[0];
    let uv = project(pair.r, &p, [x[0], x[1]])?;
    finish(pair, [uv[0], uv[1], ab[0], ab[1]], gap)
}

fn finish<R: Surface, S: Surface>(
    pair: &Pair<'_, R, S>,
    params: [f64; 4],
    gap: f64,
) -> Option<SingularPoint> {
    if !pair.inside(&params, pair.options.precision.delta) {
        return None;
    }
    let params = pair.wrap(params);
    let d = super::corrector::residual_norm(pair, &params);
    Some(SingularPoint {
        params,
        xyz: super::corrector::space_point(pair, &params),
        kind: SingularKind::Crossing,
        gap: gap.max(d),
    })
}

/// Newton on `∇φ = 0`, `φ(u, v) = G(q(u, v))`: `φ_u = ∇G·q_u`,
/// `φ_uv = q_uᵀ ∇²G q_v + ∇G·q_uv`. Returns the point and its distance estimate.
fn critical_on<Q: Surface>(
    q: &Q,
    g: &AnyImplicit,
    at: [f64; 2],
    coords: [Coordinate; 2],
) -> Option<([f64; 2], f64)> {
    let hess = |h: &[[f64; 3]; 3], a: &[f64; 3], b: &[f64; 3]| {
        (0..3)
            .map(|i| (0..3).map(|k| a[i] * h[i][k] * b[k]).sum::<f64>())
            .sum::<f64>()
    };
    let system = |y: &[f64; 2]| {
        let j = q.jet(&y[0], &y[1], 2);
        let gj = g.implicit_jet(&j[0], 2);
        let (Some(grad), Some(h)) = (gj.gradient, gj.hessian) else {
            return ([f64::NAN; 2], [[f64::NAN; 2]; 2]);
        };
        let f = [dot(&grad, &j[1]), dot(&grad, &j[2])];
        let uv = hess(&h, &j[1], &j[2]) + dot(&grad, &j[4]);
        let jac = [
            [hess(&h, &j[1], &j[1]) + dot(&grad, &j[3]), uv],
            [uv, hess(&h, &j[2], &j[2]) + dot(&grad, &j[5])],
        ];
        (f, jac)
    };
    let y = match newton_with(system, at, &coords, K_TANGENCY, 0.0) {
        NewtonOutcome::Converged(y) => y,
        _ => return None,
    };
    let p = q.jet(&y[0], &y[1], 0)[0];
    let gj = g.implicit_jet(&p, 2);
    let grad = norm_f64(&gj.gradient?);
    let h = gj.hessian?;
    let hnorm = h.iter().flatten().map(|v| v * v).sum::<f64>().sqrt();
    let phi = gj.value.abs();
    let by_gradient = if grad > 0.0 {
        phi / grad
    } else {
        f64::INFINITY
    };
    let by_curvature = if hnorm > 0.0 {
        (2.0 * phi / hnorm).sqrt()
    } else {
        f64::INFINITY
    };
    Some((y, by_gradient.min(by_curvature)))
}

/// The parameters of the point of `q` nearest to `p` near `at`: Gauss–Newton with a small
/// Levenberg–Marquardt damping (so that a parameter with a vanishing derivative, the
/// angle at a cone's apex, stays where it is).
fn project<Q: Surface>(q: &Q, p: &[f64; 3], at: [f64; 2]) -> Option<[f64; 2]> {
    let mut y = at;
    for _ in 0..50 {
        let j = q.jet(&y[0], &y[1], 1);
        let d = sub(p, &j[0]);
        let (g11, g12, g22) = (dot(&j[1], &j[1]), dot(&j[1], &j[2]), dot(&j[2], &j[2]));
        let damp = 1e-12 * (g11 + g22).max(f64::MIN_POSITIVE);
        let (a, b) = (dot(&d, &j[1]), dot(&d, &j[2]));
        let (m11, m22) = (g11 + damp, g22 + damp);
        let det = m11 * m22 - g12 * g12;
        if !(det.is_finite() && det > 0.0) {
            return None;
        }
        let step = [(m22 * a - g12 * b) / det, (m11 * b - g12 * a) / det];
        y = [y[0] + step[0], y[1] + step[1]];
        if step[0].abs() + step[1].abs() <= 1e-15 * (1.0 + y[0].abs() + y[1].abs()) {
            break;
        }
    }
    y.iter().all(|v| v.is_finite()).then_some(y)
}
