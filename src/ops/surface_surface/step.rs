//! One step along an intersection curve, float, by the three methods of the spec:
//!
//! * marching (§9.3): the contravariant predictor (9.4), the fixed parameter (9.5) kept,
//!   Newton on (9.6);
//! * Dragilev (§10.5): one classical RK4 step of length `h` on the pair's form — (10.4)
//!   for two implicit surfaces (in space), (10.9) for a parametric and an implicit one (in
//!   the parametric surface's parameters), (10.5)–(10.6) for two parametric ones (in all
//!   four parameters) — then the drift control (10.13) on the plane through the RK4 point
//!   normal to the step's tangent;
//! * stepping without an ODE (§10.6): `p* = p_k + h τ_k` and the next point on the plane
//!   `Π_k` by (10.11).
//!
//! Every method returns the converged point; acceptance (§9.3) is the tracer's.

use super::corrector::{fixed_parameter_newton, plane_newton};
use super::frame::{contravariant, LocalFrame};
use super::operand::Pair;
use super::options::{DragilevForm, Method};
use crate::num::vector::{cross, dot, norm_f64};
use crate::surface::{AnyImplicit, Implicit, Surface};

/// One step of length `h` from `frame` by `method`.
pub fn step<R: Surface, S: Surface>(
    pair: &Pair<'_, R, S>,
    frame: &LocalFrame,
    h: f64,
) -> Option<[f64; 4]> {
    match pair.options.method {
        Method::Marching => {
            let x0 = frame.predict(h);
            fixed_parameter_newton(pair, x0, frame.fixed_parameter())
        }
        Method::PlaneStep => {
            let p = frame.point();
            let p_star = std::array::from_fn(|i| p[i] + h * frame.tangent[i]);
            plane_newton(pair, frame.predict(h), p_star, frame.tangent)
        }
        Method::Dragilev => {
            let p_star = dragilev_point(pair, frame, h)?;
            plane_newton(pair, frame.predict(h), p_star, frame.tangent)
        }
    }
}

/// The Dragilev form actually used (`Auto`: the implicit forms the operands have).
pub fn form<R, S>(pair: &Pair<'_, R, S>) -> DragilevForm {
    let have = [pair.implicit[0].is_some(), pair.implicit[1].is_some()];
    match pair.options.form {
        DragilevForm::Auto => match have {
            [true, true] => DragilevForm::Implicit,
            [false, false] => DragilevForm::Parametric,
            _ => DragilevForm::ParametricImplicit,
        },
        DragilevForm::Implicit if have != [true, true] => DragilevForm::Parametric,
        DragilevForm::ParametricImplicit if have == [false, false] => DragilevForm::Parametric,
        f => f,
    }
}

/// The space point reached by one RK4 step of length `h` on the Dragilev form.
fn dragilev_point<R: Surface, S: Surface>(
    pair: &Pair<'_, R, S>,
    frame: &LocalFrame,
    h: f64,
) -> Option<[f64; 3]> {
    let reference = frame.tangent;
    match form(pair) {
        DragilevForm::Implicit => {
            let (f, g) = (pair.implicit[0].as_ref()?, pair.implicit[1].as_ref()?);
            let field = |p: &[f64]| -> Option<Vec<f64>> {
                let p = [p[0], p[1], p[2]];
                implicit_tangent(f, g, &p, &reference).map(Vec::from)
            };
            let end = rk4(&frame.point(), h, field)?;
            Some([end[0], end[1], end[2]])
        }
        DragilevForm::ParametricImplicit => {
            if let Some(g) = &pair.implicit[1] {
                let y = rk4(&[frame.x[0], frame.x[1]], h, |y| {
                    parametric_implicit_velocity(pair.r, g, [y[0], y[1]], &reference)
                })?;
                Some(pair.r.jet(&y[0], &y[1], 0)[0])
            } else {
                let g = pair.implicit[0].as_ref()?;
                let y = rk4(&[frame.x[2], frame.x[3]], h, |y| {
                    parametric_implicit_velocity(pair.s, g, [y[0], y[1]], &reference)
                })?;
                Some(pair.s.jet(&y[0], &y[1], 0)[0])
            }
        }
        DragilevForm::Parametric => {
            let y = rk4(&frame.x, h, |y| {
                parametric_velocity(pair, [y[0], y[1], y[2], y[3]], &reference).map(Vec::from)
            })?;
            let x = [y[0], y[1], y[2], y[3]];
            Some(super::corrector::space_point(pair, &x))
        }
        DragilevForm::Auto => None,
    }
}

/// Classical RK4 for `y' = f(y)` over one step `h`.
fn rk4(y: &[f64], h: f64, f: impl Fn(&[f64]) -> Option<Vec<f64>>) -> Option<Vec<f64>> {
    let at = |k: &[f64], c: f64| -> Vec<f64> { y.iter().zip(k).map(|(a, b)| a + c * b).collect() };
    let k1 = f(y)?;
    let k2 = f(&at(&k1, 0.5 * h))?;
    let k3 = f(&at(&k2, 0.5 * h))?;
    let k4 = f(&at(&k3, h))?;
    let out: Vec<f64> = (0..y.len())
        .map(|i| y[i] + h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]))
        .collect();
    out.iter().all(|v| v.is_finite()).then_some(out)
}

/// `v` or `−v`, whichever agrees with `reference` (continuity of the sign, §10.5).
fn oriented(v: [f64; 3], reference: &[f64; 3]) -> [f64; 3] {
    if dot(&v, reference) < 0.0 {
        v.map(|c| -c)
    } else {
        v
    }
}

/// (10.4): `τ = ∇F × ∇Φ / |∇F × ∇Φ|`.
pub fn implicit_tangent(
    f: &AnyImplicit,
    g: &AnyImplicit,
    p: &[f64; 3],
    reference: &[f64; 3],
) -> Option<[f64; 3]> {
    let gf = f.implicit_jet(p, 1).gradient?;
    let gg = g.implicit_jet(p, 1).gradient?;
    let c = cross(&gf, &gg);
    let n = norm_f64(&c);
    (n > 0.0 && n.is_finite()).then(|| oriented(c.map(|x| x / n), reference))
}

/// (10.9): `(u', v') = ±(B, −A)/√(g₁₁B² − 2g₁₂AB + g₂₂A²)`, `A = ∇Φ·q_u`, `B = ∇Φ·q_v`,
/// the sign making the space tangent `q_u u' + q_v v'` agree with `reference`.
pub fn parametric_implicit_velocity<Q: Surface>(
    q: &Q,
    g: &AnyImplicit,
    y: [f64; 2],
    reference: &[f64; 3],
) -> Option<Vec<f64>> {
    let j = q.jet(&y[0], &y[1], 1);
    let grad = g.implicit_jet(&j[0], 1).gradient?;
    let (a, b) = (dot(&grad, &j[1]), dot(&grad, &j[2]));
    let (g11, g12, g22) = (dot(&j[1], &j[1]), dot(&j[1], &j[2]), dot(&j[2], &j[2]));
    let root = (g11 * b * b - 2.0 * g12 * a * b + g22 * a * a).sqrt();
    if !(root > 0.0 && root.is_finite()) {
        return None;
    }
    let (du, dv) = (b / root, -a / root);
    let space: [f64; 3] = std::array::from_fn(|i| j[1][i] * du + j[2][i] * dv);
    let sign = if dot(&space, reference) < 0.0 {
        -1.0
    } else {
        1.0
    };
    Some(vec![sign * du, sign * dv])
}

/// (10.5)–(10.6): `τ = N_r × N_s/|N_r × N_s|` oriented by `reference`, and the parameter
/// velocities of both surfaces for it.
pub fn parametric_velocity<R: Surface, S: Surface>(
    pair: &Pair<'_, R, S>,
    x: [f64; 4],
    reference: &[f64; 3],
) -> Option<[f64; 4]> {
    let jr = pair.r.jet(&x[0], &x[1], 1);
    let js = pair.s.jet(&x[2], &x[3], 1);
    let c = cross(&cross(&jr[1], &jr[2]), &cross(&js[1], &js[2]));
    let n = norm_f64(&c);
    if !(n > 0.0 && n.is_finite()) {
        return None;
    }
    let tau = oriented(c.map(|v| v / n), reference);
    let [du, dv] = contravariant(&jr, &tau);
    let [da, db] = contravariant(&js, &tau);
    Some([du, dv, da, db])
}
