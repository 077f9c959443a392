//! The float correctors that bring a predicted point back onto both surfaces: Newton on
//! (9.6) with one parameter fixed (§9.3), and the plane-constrained system (10.13) —
//! `r − s = 0`, `(r − p*)·t̂ = 0` — shared by the Dragilev integration (§10.5), stepping
//! without an ODE (§10.6, (10.11)), crossing a contact point (§9.5) and the intermediate
//! point (§9.6, the reduced 4 × 4 form of (9.10)).

use super::equations::PairJet;
use super::operand::Pair;
use crate::num::vector::{dot, norm_f64, sub};
use crate::ops::float::{newton, Coordinate, NewtonOutcome};
use crate::surface::Surface;

/// Newton's iteration limit `K_max` (§0.4).
const K_MAX: usize = 32;

/// (9.6): solve (9.1) for the three parameters other than `fixed`, which keeps its value
/// in `x0`. `None` unless Newton converges (§0.4).
pub fn fixed_parameter_newton<R: Surface, S: Surface>(
    pair: &Pair<'_, R, S>,
    x0: [f64; 4],
    fixed: usize,
) -> Option<[f64; 4]> {
    let free: [usize; 3] = match fixed {
        0 => [1, 2, 3],
        1 => [0, 2, 3],
        2 => [0, 1, 3],
        _ => [0, 1, 2],
    };
    let full = |y: &[f64; 3]| {
        let mut x = x0;
        for (k, &i) in free.iter().enumerate() {
            x[i] = y[k];
        }
        x
    };
    let system = |y: &[f64; 3]| {
        let j = PairJet::at(pair.r, pair.s, &full(y), 1);
        let rows = j.jacobian_rows();
        let jac = std::array::from_fn(|i| free.map(|c| rows[i][c]));
        (j.residual(), jac)
    };
    let coords: [Coordinate; 3] = free.map(|i| pair.coords[i]);
    match newton(system, free.map(|i| x0[i]), &coords, K_MAX) {
        NewtonOutcome::Converged(y) => Some(full(&y)),
        _ => None,
    }
}

/// (10.13): solve `r(u, v) − s(a, b) = 0`, `(r(u, v) − p*)·t̂ = 0` from `x0`. `None`
/// unless Newton converges.
pub fn plane_newton<R: Surface, S: Surface>(
    pair: &Pair<'_, R, S>,
    x0: [f64; 4],
    p_star: [f64; 3],
    normal: [f64; 3],
) -> Option<[f64; 4]> {
    let system = |x: &[f64; 4]| {
        let j = PairJet::at(pair.r, pair.s, x, 1);
        let rows = j.jacobian_rows();
        let f = j.residual();
        let plane = dot(&sub(&j.r[0], &p_star), &normal);
        let last = [dot(&normal, &j.r[1]), dot(&normal, &j.r[2]), 0.0, 0.0];
        ([f[0], f[1], f[2], plane], [rows[0], rows[1], rows[2], last])
    };
    match newton(system, x0, &pair.coords, K_MAX) {
        NewtonOutcome::Converged(x) => Some(x),
        _ => None,
    }
}

/// `|r(u, v) − s(a, b)|` at `x`.
pub fn residual_norm<R: Surface, S: Surface>(pair: &Pair<'_, R, S>, x: &[f64; 4]) -> f64 {
    norm_f64(&PairJet::at(pair.r, pair.s, x, 0).residual())
}

/// The space point (1.21) of `x`.
pub fn space_point<R: Surface, S: Surface>(pair: &Pair<'_, R, S>, x: &[f64; 4]) -> [f64; 3] {
    let j = PairJet::at(pair.r, pair.s, x, 0);
    std::array::from_fn(|i| 0.5 * (j.r[0][i] + j.s[0][i]))
}

/// A converged point is accepted (§0.4) when it lies in the domain extended by `δ` and its
/// gap is at most `δ_len`; non-periodic coordinates are clamped into the domain.
pub fn accept<R: Surface, S: Surface>(pair: &Pair<'_, R, S>, x: [f64; 4]) -> Option<[f64; 4]> {
    if !pair.inside(&x, pair.options.precision.delta) {
        return None;
    }
    let y: [f64; 4] = std::array::from_fn(|i| {
        let c = &pair.coords[i];
        if c.periodic {
            c.wrap(x[i])
        } else {
            x[i].clamp(c.lo, c.hi)
        }
    });
    (residual_norm(pair, &y) <= pair.delta_len()).then_some(y)
}
