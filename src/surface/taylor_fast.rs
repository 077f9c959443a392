//! The centred form of [`super::taylor`] for f64 intervals, evaluated in midpoint–radius
//! form: the Taylor coefficients `C_kl` of the homogeneous patch at the box centre are
//! computed by plain f64 dot products (no interval operation in the `O(p²q²)` part),
//! and a rigorous bound on their error comes from a-priori rounding-error analysis
//! (Higham, *Accuracy and Stability of Numerical Algorithms*, §3.1: a recursive dot
//! product of length `n` has error at most `γ_n Σ|x_i y_i|`, `γ_n = nu/(1 − nu) ≤
//! (n+1)u`, plus `n·η` for underflow, `η = 2⁻¹⁰⁷⁴`). Issue 5's enclosure goal needs
//! this: the generic interval evaluation branches on signs and rounds each product by
//! error-free transformations, about 60× one f64 jet; this path is 8–10× (BENCHMARKS.md).
//!
//! It encloses the same identity as the generic code (the formula in `super::taylor`),
//! not an approximation of it; the two are compared in the tests below and every
//! enclosure is checked against MPFR evaluations in `tests/surface_enclosure.rs`.
//!
//! Every bound is rounded upward with [`up`] and [`inflate`] of [`crate::num::midrad`]
//! (round-to-nearest plus a proven margin; the proofs are there). The quotient rule and
//! the mean value form then run on [`MidRad`] enclosures through the same generic
//! [`quotient`] as every other number type. Any non-finite value (overflow, a weight
//! sum not bounded away from 0) makes [`try_taylor_tensor_jet`] return `None`, and the
//! caller uses the generic interval code.

use super::basis::{bernstein_jet, bspline_jet, BasisJet};
use super::tensor::{quotient, Net, ORDERS};
use crate::num::midrad::{inflate, up, MidRad, EPS, ETA, U};
use crate::num::{Interval, Real};

/// Degrees up to 7 per direction: `(p+1)(q+1) ≤ 64` terms per sum, as [`inflate`] needs.
const MAX_N: usize = 8;
/// One direction's Taylor coefficients of the basis at the centre, `a[k][j] =
/// N_j^{(k)}(m)/k!`, in midpoint–radius form, with the row sums the bounds need.
struct Basis {
    n: usize,
    /// Midpoints `ã_kj`.
    mid: [[f64; MAX_N]; MAX_N],
    /// `≥ Σ_j |ã_kj|`.
    abs: [f64; MAX_N],
    /// `≥ Σ_j α_kj`, the radii (so `|a_kj − ã_kj| ≤ α_kj`).
    rad: [f64; MAX_N],
    /// `≥ Σ_j |a_kj|` over the true values.
    hat: [f64; MAX_N],
    /// `≥ γ_n · abs[k]` (the dot-product rounding factor times the row sum).
    gamma_abs: [f64; MAX_N],
}

fn basis(b: &BasisJet<MidRad>) -> Option<Basis> {
    let n = b.degree + 1;
    if n > MAX_N || b.order() < b.degree {
        return None;
    }
    // γ_n ≤ (n+1)·u, exact in f64.
    let gamma = (n + 1) as f64 * U;
    let mut out = Basis {
        n,
        mid: [[0.0; MAX_N]; MAX_N],
        abs: [0.0; MAX_N],
        rad: [0.0; MAX_N],
        hat: [0.0; MAX_N],
        gamma_abs: [0.0; MAX_N],
    };
    let mut factorial = 1.0;
    for k in 0..n {
        if k >= 2 {
            factorial *= k as f64;
        }
        let (mut abs, mut rad) = (0.0, 0.0);
        for j in 0..n {
            // N^{(k)}/k! (an enclosing division by the exact k! > 1).
            let x = if k < 2 {
                *b.get(k, j)
            } else {
                *b.get(k, j) / MidRad::new(factorial, 0.0)
            };
            if !x.is_finite() {
                return None;
            }
            out.mid[k][j] = x.mid;
            abs += x.mid.abs();
            rad += x.rad;
        }
        out.abs[k] = inflate(abs);
        out.rad[k] = inflate(rad);
        out.hat[k] = up(out.abs[k] + out.rad[k]);
        out.gamma_abs[k] = up(gamma * out.abs[k]);
    }
    Some(out)
}

/// `k!/(k−a)!` (exact for the degrees allowed here).
fn falling(k: usize, a: usize) -> f64 {
    ((k - a + 1)..=k).map(|i| i as f64).product()
}

/// Upper bounds of `k!/(k−a)!·r^{k−a}` for `a ≤ 2`, `k < n` (0 for `k < a`): the factors
/// of `C_kl` in the derivative `∂^a` over `|δ| ≤ r`.
fn derivative_factors(r: f64, n: usize) -> [[f64; MAX_N]; 3] {
    let mut pw = [1.0; MAX_N];
    for e in 1..n {
        pw[e] = up(pw[e - 1] * r);
    }
    let mut f = [[0.0; MAX_N]; 3];
    for (a, row) in f.iter_mut().enumerate() {
        for k in a..n {
            row[k] = up(falling(k, a) * pw[k - a]);
        }
    }
    f
}

/// Where one direction's basis functions come from.
#[derive(Clone, Copy)]
pub(crate) enum BasisSource<'a> {
    /// The B-spline basis of `degree` on the non-empty span `span` of `knots`.
    BSpline {
        knots: &'a [f64],
        degree: usize,
        span: usize,
    },
    /// The Bernstein polynomials of `degree`.
    Bernstein { degree: usize },
}

impl BasisSource<'_> {
    /// The basis jet up to the degree at the exact point `m`, enclosed in [`MidRad`].
    fn at(&self, m: f64) -> BasisJet<MidRad> {
        let t = MidRad::new(m, 0.0);
        match *self {
            BasisSource::BSpline {
                knots,
                degree,
                span,
            } => bspline_jet(knots, degree, span, &t, degree),
            BasisSource::Bernstein { degree } => bernstein_jet(degree, &t, degree),
        }
    }
    /// The index of the first control point the basis weighs.
    fn first(&self) -> usize {
        match *self {
            BasisSource::BSpline { degree, span, .. } => span - degree,
            BasisSource::Bernstein { .. } => 0,
        }
    }
}

/// The centre `m` of a bounded parameter interval, a radius `r ≥ |t − m|` over it, and
/// whether `m` lies in it (as `super::taylor::centre`).
fn centre(t: &Interval) -> Option<(f64, f64, bool)> {
    if t.is_empty() || !t.is_bounded() {
        return None;
    }
    let m = t.midpoint();
    let r = (*t - Interval::point(m)).mag();
    let (lo, hi) = (t.lo(), t.hi());
    Some((m, r, (lo < m && m < hi) || (lo == hi && m == lo)))
}

/// The centred form of [`super::taylor::taylor_tensor_jet`] over the box `u × v` on one
/// pair of spans, for the number types that are f64 intervals ([`Real::as_f64_interval`]:
/// `Interval`, and the certifier's `Guarded<Interval>`), in midpoint–radius form; `None`
/// for any other number type, or when the fast path declines (module doc).
///
/// The result goes back through [`Real::from_f64_interval`] with `u, v` as arguments:
/// on one pair of spans the patch is a polynomial, or a quotient whose denominator the
/// fast path has proven positive over the box, so it is `C^∞` there (a `Guarded` jet is
/// smooth exactly when both parameters are; the hull over several spans is marked
/// non-smooth by the caller's join).
pub(crate) fn try_centred_jet<T: Real>(
    net: &Net,
    source_u: BasisSource,
    u: &T,
    source_v: BasisSource,
    v: &T,
    order: usize,
) -> Option<Vec<[T; 3]>> {
    let jet = interval_jet(net, source_u, &view(u)?, source_v, &view(v)?, order)?;
    let back = |x: &Interval| T::from_f64_interval([x.lo(), x.hi()], &[u, v]);
    jet.iter()
        .map(|[x, y, z]| Some([back(x)?, back(y)?, back(z)?]))
        .collect()
}

/// The f64 interval a parameter is, if it is one and not empty (an empty parameter
/// takes the generic path, as [`centre`] would decline it).
fn view<T: Real>(t: &T) -> Option<Interval> {
    let [lo, hi] = t.as_f64_interval()?;
    (lo <= hi).then(|| Interval::from_bounds(lo, hi))
}

fn interval_jet(
    net: &Net,
    source_u: BasisSource,
    u: &Interval,
    source_v: BasisSource,
    v: &Interval,
    order: usize,
) -> Option<Vec<[Interval; 3]>> {
    let ((mu, r_u, inside_u), (mv, r_v, inside_v)) = (centre(u)?, centre(v)?);
    let spans = Spans {
        a: basis(&source_u.at(mu))?,
        first_u: source_u.first(),
        r_u,
        b: basis(&source_v.at(mv))?,
        first_v: source_v.first(),
        r_v,
    };
    match net.weights {
        None => polynomial_jet(net, &spans, order),
        Some(_) => rational_jet(net, &spans, order, inside_u && inside_v),
    }
}

/// The basis Taylor coefficients at the centres, the first control point of each
/// span, and the radii `r ≥ |δ|` of the box around the centre.
struct Spans {
    a: Basis,
    first_u: usize,
    r_u: f64,
    b: Basis,
    first_v: usize,
    r_v: f64,
}

fn jet_len(order: usize) -> usize {
    match order {
        0 => 1,
        1 => 3,
        _ => 6,
    }
}

/// A polynomial patch: the centred form is the jet (translated back by `P_ref`).
fn polynomial_jet(net: &Net, spans: &Spans, order: usize) -> Option<Vec<[Interval; 3]>> {
    let (reference, over_box, _) = centred_f64::<3>(net, spans, order)?;
    let mut jet = Vec::with_capacity(over_box.len());
    for e in &over_box {
        jet.push(intervals(e)?);
    }
    untranslate(&mut jet, &reference);
    Some(jet)
}

/// A rational patch: the quotient rule over the box and, when the centre lies in the
/// box, the mean value form of `s, s_u, s_v` intersected with it (as the generic code
/// does, `super::taylor::taylor_tensor_jet`), all on [`MidRad`] enclosures.
fn rational_jet(
    net: &Net,
    spans: &Spans,
    order: usize,
    centre_inside: bool,
) -> Option<Vec<[Interval; 3]>> {
    let inner = if order >= 1 { 2 } else { 0 };
    let (reference, over_box, at_centre) = centred_f64::<4>(net, spans, inner)?;
    let mut jet_mr = quotient(&over_box);
    let mut jet = Vec::with_capacity(jet_mr.len());
    for e in &jet_mr {
        jet.push(intervals(e)?);
    }
    if order >= 1 && centre_inside {
        let centre = quotient(&at_centre[..3]);
        let (du, dv) = (MidRad::new(0.0, spans.r_u), MidRad::new(0.0, spans.r_v));
        for (e, eu, ev) in [(1, 3, 4), (2, 4, 5), (0, 1, 2)] {
            for c in 0..3 {
                let form = centre[e][c] + jet_mr[eu][c] * du + jet_mr[ev][c] * dv;
                let met = jet[e][c].intersection(&form.to_interval()?);
                jet[e][c] = met;
                jet_mr[e][c] = MidRad::from_interval(&met);
            }
        }
    }
    jet.truncate(jet_len(order));
    untranslate(&mut jet, &reference);
    Some(jet)
}

fn intervals<const D: usize>(e: &[MidRad; D]) -> Option<[Interval; 3]> {
    Some([
        e[0].to_interval()?,
        e[1].to_interval()?,
        e[2].to_interval()?,
    ])
}

/// `s = (s − P_ref) + P_ref`.
fn untranslate(jet: &mut [[Interval; 3]], reference: &[f64; 3]) {
    for c in 0..3 {
        jet[0][c] += Interval::point(reference[c]);
    }
}

/// Per span pair: one `D`-vector per basis pair `(k, l)` (or control point `(i, j)`).
type Grid<const D: usize> = [[[f64; D]; MAX_N]; MAX_N];

/// The centred Taylor coefficients of the homogeneous patch at the box centre, with
/// rigorous error bounds, translated by `P_ref ≈ s(m)`; then the jet (in [`ORDERS`]
/// order) over the box and at the centre, as midpoint–radius enclosures: `(P_ref,
/// over_box, at_centre)`. `None` when a bound is not finite.
#[allow(clippy::type_complexity)]
fn centred_f64<const D: usize>(
    net: &Net,
    spans: &Spans,
    order: usize,
) -> Option<([f64; 3], Vec<[MidRad; D]>, Vec<[MidRad; D]>)> {
    let (q, qmax) = control_data::<D>(net, spans);
    let mut coef = coefficients(&spans.a, &spans.b, &q);
    let mut err = error_bounds(&spans.a, &spans.b, &qmax);
    let reference = translate(&mut coef, &mut err, spans.a.n, spans.b.n);
    let (over_box, at_centre) = jets(&coef, &err, spans, order)?;
    Some((reference, over_box, at_centre))
}

/// The control data `Q̃_ij = (RN(w·P), w)` or `P` of the span pair, and per component
/// the largest `|Q̃|`: `|Q − Q̃| ≤ ulp(Q̃)/2 ≤ κ_c` and `|Q| ≤ Q̂_c` (see [`error_bounds`]).
#[allow(clippy::needless_range_loop)]
#[inline(always)]
fn control_data<const D: usize>(net: &Net, spans: &Spans) -> (Grid<D>, [f64; D]) {
    let mut q = [[[0.0; D]; MAX_N]; MAX_N];
    let mut qmax = [0.0f64; D];
    for (i, row) in q.iter_mut().enumerate().take(spans.b.n) {
        for (j, x) in row.iter_mut().enumerate().take(spans.a.n) {
            let k = (spans.first_v + i) * net.cols + spans.first_u + j;
            let p = net.points[k];
            for c in 0..D {
                x[c] = match &net.weights {
                    Some(w) if c == 3 => w[k],
                    Some(w) => w[k] * p[c],
                    None => p[c],
                };
                qmax[c] = qmax[c].max(x[c].abs());
            }
        }
    }
    (q, qmax)
}

/// Rows `R̃_ik = Σ_j ã_kj Q̃_ij`, then `C̃_kl = Σ_i b̃_li R̃_ik` (RN dot products).
#[allow(clippy::needless_range_loop)]
#[inline(always)]
fn coefficients<const D: usize>(a: &Basis, b: &Basis, q: &Grid<D>) -> Grid<D> {
    let (nu, nv) = (a.n, b.n);
    let mut rows = [[[0.0; D]; MAX_N]; MAX_N];
    for i in 0..nv {
        for k in 0..nu {
            let acc = &mut rows[i][k];
            for j in 0..nu {
                let (x, qij) = (a.mid[k][j], &q[i][j]);
                for c in 0..D {
                    acc[c] += x * qij[c];
                }
            }
        }
    }
    let mut coef = [[[0.0; D]; MAX_N]; MAX_N];
    for k in 0..nu {
        for l in 0..nv {
            let acc = &mut coef[k][l];
            for i in 0..nv {
                let (y, r) = (b.mid[l][i], &rows[i][k]);
                for c in 0..D {
                    acc[c] += y * r[c];
                }
            }
        }
    }
    coef
}

/// Error bounds `E_kl ≥ |C_kl − C̃_kl|` of [`coefficients`]. With `R_ik` the exact row sums:
///   `|R_ik − R̃_ik| ≤ Σ_j α_kj|Q_ij| + Σ_j |ã_kj| κ + γ_n Σ_j |ã_kj||Q̃_ij| + n·η =: ρ_k`,
///   `|R_ik| ≤ Â_k Q̂ =: R_k`, `|R̃_ik| ≤ R_k + ρ_k =: R̃_k`,
///   `|C_kl − C̃_kl| ≤ Σ_i β_li |R_ik| + Σ_i |b̃_li| ρ_k + γ_n Σ_i |b̃_li||R̃_ik| + n·η`.
#[inline(always)]
// `k` indexes the basis arrays and the grid together.
#[allow(clippy::needless_range_loop)]
fn error_bounds<const D: usize>(a: &Basis, b: &Basis, qmax: &[f64; D]) -> Grid<D> {
    let (nu, nv) = (a.n, b.n);
    let q_hat: [f64; D] = std::array::from_fn(|c| up(qmax[c]));
    let kappa: [f64; D] = std::array::from_fn(|c| up(qmax[c] * EPS));
    let mut err = [[[0.0; D]; MAX_N]; MAX_N];
    for k in 0..nu {
        for c in 0..D {
            let rho = inflate(
                a.rad[k] * q_hat[c]
                    + a.abs[k] * kappa[c]
                    + a.gamma_abs[k] * qmax[c]
                    + nu as f64 * ETA,
            );
            let r_max = up(a.hat[k] * q_hat[c]);
            let r_tilde = up(r_max + rho);
            for (l, e) in err[k].iter_mut().enumerate().take(nv) {
                e[c] = inflate(
                    b.rad[l] * r_max + b.abs[l] * rho + b.gamma_abs[l] * r_tilde + nv as f64 * ETA,
                );
            }
        }
    }
    err
}

/// Translate by `P_ref ≈ s(m)`, as the generic code does: `C' = C^A − P_ref·C^W`
/// (rational) or `C'_00 = C_00 − P_ref` (polynomial). Error of each new coefficient:
/// the old ones, `|P|·E^W`, and the two roundings (each `≤ 2⁻⁵²|result| + η`).
/// Returns `P_ref`.
#[inline(always)]
fn translate<const D: usize>(
    coef: &mut Grid<D>,
    err: &mut Grid<D>,
    nu: usize,
    nv: usize,
) -> [f64; 3] {
    let reference: [f64; 3] = std::array::from_fn(|c| {
        let x = if D == 4 {
            coef[0][0][c] / coef[0][0][3]
        } else {
            coef[0][0][c]
        };
        if x.is_finite() {
            x
        } else {
            0.0
        }
    });
    if D == 4 {
        for k in 0..nu {
            for l in 0..nv {
                let (cw, ew) = (coef[k][l][3], err[k][l][3]);
                for c in 0..3 {
                    let x = reference[c] * cw;
                    let t = coef[k][l][c] - x;
                    err[k][l][c] = inflate(
                        err[k][l][c]
                            + reference[c].abs() * ew
                            + EPS * x.abs()
                            + EPS * t.abs()
                            + 2.0 * ETA,
                    );
                    coef[k][l][c] = t;
                }
            }
        }
    } else {
        for c in 0..3 {
            let t = coef[0][0][c] - reference[c];
            err[0][0][c] = inflate(err[0][0][c] + EPS * t.abs() + ETA);
            coef[0][0][c] = t;
        }
    }
    reference
}

/// The jet entries up to `order` over the box and at the centre, from the coefficients
/// `C̃` and their errors `E`: `∂_u^a ∂_v^b H(m + δ) = Σ_{k≥a, l≥b} k!/(k−a)! l!/(l−b)!
/// C_kl δ_u^{k−a} δ_v^{l−b}`, midpoint `a!b!·C̃_ab` (exact: `a!b! ∈ {1, 2}`), radius
/// `a!b!·E_ab` plus the other terms bounded by their magnitudes `|C_kl| ≤ T_kl` over
/// `|δ_u| ≤ r_u`, `|δ_v| ≤ r_v`. `None` when a bound is not finite.
#[allow(clippy::type_complexity, clippy::needless_range_loop)]
#[inline(always)]
fn jets<const D: usize>(
    coef: &Grid<D>,
    err: &Grid<D>,
    spans: &Spans,
    order: usize,
) -> Option<(Vec<[MidRad; D]>, Vec<[MidRad; D]>)> {
    let (nu, nv) = (spans.a.n, spans.b.n);
    let mut mag = [[[0.0; D]; MAX_N]; MAX_N];
    for k in 0..nu {
        for l in 0..nv {
            for c in 0..D {
                mag[k][l][c] = up(coef[k][l][c].abs() + err[k][l][c]);
            }
        }
    }
    let fu = derivative_factors(spans.r_u, nu);
    let fv = derivative_factors(spans.r_v, nv);
    let len = jet_len(order);
    let mut over_box = Vec::with_capacity(len);
    let mut at_centre = Vec::with_capacity(len);
    let zero = [MidRad::new(0.0, 0.0); D];
    for &(da, db) in &ORDERS[..len] {
        if da >= nu || db >= nv {
            over_box.push(zero);
            at_centre.push(zero);
            continue;
        }
        let scale = falling(da, da) * falling(db, db);
        let mut rad = [0.0; D];
        for k in da..nu {
            for l in db..nv {
                let g = up(fu[da][k] * fv[db][l]);
                let centre_term = k == da && l == db;
                for c in 0..D {
                    rad[c] += g * if centre_term {
                        err[k][l][c]
                    } else {
                        mag[k][l][c]
                    };
                }
            }
        }
        let mut boxed = zero;
        let mut centre = zero;
        for c in 0..D {
            let m = scale * coef[da][db][c];
            let (r_box, r_centre) = (inflate(rad[c]), up(scale * err[da][db][c]));
            if !(m.is_finite() && r_box.is_finite() && r_centre.is_finite()) {
                return None;
            }
            boxed[c] = MidRad::new(m, r_box);
            centre[c] = MidRad::new(m, r_centre);
        }
        over_box.push(boxed);
        at_centre.push(centre);
    }
    Some((over_box, at_centre))
}

#[cfg(test)]
pub(super) mod tests {
    use super::*;
    use crate::num::{IntervalLike, MpfrInterval};
    use crate::surface::taylor::{centre as generic_centre, taylor_tensor_jet};

    /// Bézier knots of degree 3: one span pair `[0, 1]²`.
    pub(in crate::surface) const KNOTS: [f64; 8] = [0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0];

    /// The control points (rows ↔ `v`) and weights of a rational bicubic patch on
    /// [`KNOTS`], net scaled by `scale`, with varied weights.
    #[allow(clippy::type_complexity)]
    pub(in crate::surface) fn patch_points(scale: f64) -> (Vec<Vec<[f64; 3]>>, Vec<Vec<f64>>) {
        let points: Vec<Vec<[f64; 3]>> = (0..4)
            .map(|i| {
                (0..4)
                    .map(|j| {
                        let z = ((i * 7 + j * 3) % 5) as f64 - 2.0;
                        [
                            scale * j as f64,
                            scale * (i as f64 + 0.1 * j as f64),
                            scale * z,
                        ]
                    })
                    .collect()
            })
            .collect();
        let weights: Vec<Vec<f64>> = (0..4)
            .map(|i| {
                (0..4)
                    .map(|j| 0.5 + ((i + 2 * j) % 4) as f64 * 0.4)
                    .collect()
            })
            .collect();
        (points, weights)
    }

    /// The net of [`patch_points`], rows flattened in order.
    fn patch(scale: f64) -> Net {
        let (points, weights) = patch_points(scale);
        Net {
            rows: 4,
            cols: 4,
            points: points.concat(),
            weights: Some(weights.concat()),
        }
    }

    fn source() -> BasisSource<'static> {
        BasisSource::BSpline {
            knots: &KNOTS,
            degree: 3,
            span: 3,
        }
    }

    fn fast(net: &Net, u: &Interval, v: &Interval) -> Vec<[Interval; 3]> {
        try_centred_jet(net, source(), u, source(), v, 2).expect("fast path")
    }

    /// The generic centred form (what `NurbsSurface::jet` computes for every other type).
    fn generic<T: Real>(net: &Net, u: &T, v: &T) -> Vec<[T; 3]> {
        let ((cu, du, iu), (cv, dv, iv)) = (generic_centre(u), generic_centre(v));
        let bu = bspline_jet(&KNOTS, 3, 3, &cu, 3);
        let bv = bspline_jet(&KNOTS, 3, 3, &cv, 3);
        taylor_tensor_jet(net, &bu, &du, 0, &bv, &dv, 0, 2, iu && iv)
    }

    #[test]
    fn fast_enclosures_are_as_tight_as_the_generic_interval_ones() {
        // Both enclose the jet (they intersect), and the midpoint–radius bounds are at
        // most 1.5× wider plus a rounding-level margin of 1e-11 relative (its a-priori
        // error bounds, 1e-13–2e-12 relative, are up to ~20× the generic interval
        // widths on boxes one ulp wide),
        // on boxes from 1e-3 wide down to one ulp. (On wide boxes, 0.2, the symmetric
        // radii lose the signs of even powers: up to ~3× the generic widths.)
        let s = patch(1.0);
        for width in [1e-3, 1e-8, 0.0] {
            for (u, v) in [(0.1, 0.2), (0.45, 0.7), (0.8, 0.05)] {
                let hi = |x: f64| if width == 0.0 { x.next_up() } else { x + width };
                let (bu, bv) = (
                    Interval::from_bounds(u, hi(u)),
                    Interval::from_bounds(v, hi(v)),
                );
                let (f, g) = (fast(&s, &bu, &bv), generic(&s, &bu, &bv));
                for (e, (fe, ge)) in f.iter().zip(&g).enumerate() {
                    for c in 0..3 {
                        let (x, y) = (fe[c], ge[c]);
                        assert!(!x.intersection(&y).is_empty(), "{width} {e}.{c}");
                        let margin = 1e-11 * (1.0 + y.mag());
                        assert!(
                            x.wid() <= 1.5 * y.wid() + margin,
                            "width {width}, entry {e}.{c}: fast {x:?} vs generic {y:?}"
                        );
                    }
                }
            }
        }
    }

    #[test]
    fn other_number_types_take_the_generic_path() {
        let s = patch(1.0);
        let m = MpfrInterval::from_bounds(0.25, 0.5, 100);
        assert!(try_centred_jet(&s, source(), &m, source(), &m, 2).is_none());
        assert!(try_centred_jet(&s, source(), &0.3, source(), &0.3, 2).is_none());
        let unbounded = Interval::ENTIRE;
        let iv = Interval::from_bounds(0.25, 0.5);
        assert!(try_centred_jet::<Interval>(&s, source(), &unbounded, source(), &iv, 2).is_none());
    }

    #[test]
    fn huge_and_tiny_nets_are_enclosed() {
        // The fast path answers at 1e±250 and its enclosure contains the 200-bit MPFR
        // enclosure of the same box (which contains the jet; `NurbsSurface::jet` takes
        // this path: nurbs's tests).
        for scale in [1e-250, 1e-12, 1e250] {
            let s = patch(scale);
            let (bu, bv) = (
                Interval::from_bounds(0.3, 0.3 + 1e-4),
                Interval::from_bounds(0.6, 0.6 + 1e-4),
            );
            let (mu, mv) = (
                MpfrInterval::from_bounds(0.3, 0.3 + 1e-4, 200),
                MpfrInterval::from_bounds(0.6, 0.6 + 1e-4, 200),
            );
            let f = fast(&s, &bu, &bv);
            let m = generic(&s, &mu, &mv);
            for (e, (fe, me)) in f.iter().zip(&m).enumerate() {
                for c in 0..3 {
                    assert!(
                        me[c].to_interval().is_subset(&fe[c]),
                        "scale {scale:e}, entry {e}.{c}: {:?} ⊄ {:?}",
                        me[c],
                        fe[c]
                    );
                }
            }
        }
    }
}
