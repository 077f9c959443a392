//! A line against an exact quadric or conic (OPERATIONS.md §5.2, §6.3 eq. (6.3)) and
//! against a torus (§1.6), through the restricted polynomial of degree 2 or 4.
//!
//! Quadric `F(x) = xᵀAx + 2bᵀx + c₀` on `o + t·d`: `F = αt² + 2βt + γ` with
//! `α = dᵀAd`, `β = dᵀ(Ao + b)`, `γ = F(o)` (eq. (6.3)); its half-gradient on the line
//! is `(Ao + b) + t·Ad`.
//!
//! Torus with centre `c`, axis `a` (any non-zero length), radii `R ≥ 0`, `r > 0`:
//! with `q = x − c`, `ρ² = |q|² − (q·a)²/|a|²` the squared distance from the axis,
//! `(|q|² + R² − r²)² = 4R²ρ²` (§1.6) multiplied by `|a|²` is the exact polynomial
//! `T(x) = |a|²(|q|² + K)² − 4R²(|a|²|q|² − (q·a)²)`, `K = R² − r²`, no square root of
//! `|a|²` needed. On the line `q = w + t·d` (`w = o − c`) it is a quartic in `t`;
//! `∇T/4 = |a|²(|q|² + K − 2R²)q + 2R²(q·a)a`.

use rug::Rational;

use super::line::{affine, line_cut, LineCut};
use crate::certificate::Certified;
use crate::certify::univariate::Polynomial;
use crate::error::GeomError;
use crate::num::parse::rational_from_f64;
use crate::ops::rational::exact::{dot, exact_line, exact_vec, positive, sign_at_root};
use crate::ops::rational::QuadricForm;

/// Line `origin + t·direction` against the exact quadric (`D = 3`) or conic (`D = 2`):
/// every real intersection with its exact multiplicity, `status: exact`,
/// `complete: true`. Errors: non-finite data, zero direction.
pub fn intersect_line_quadric<const D: usize>(
    origin: [f64; D],
    direction: [f64; D],
    quadric: &QuadricForm<D>,
) -> Result<Certified<LineCut<D>>, GeomError> {
    let (o, d) = exact_line(&origin, &direction)?;
    Ok(intersect_line_quadric_exact(&o, &d, quadric))
}

/// [`intersect_line_quadric`] on exact data (`o + t·d`; `d` need not be a double, as
/// for a segment's `b − a`).
pub fn intersect_line_quadric_exact<const D: usize>(
    o: &[Rational; D],
    d: &[Rational; D],
    quadric: &QuadricForm<D>,
) -> Certified<LineCut<D>> {
    let ad = quadric.mul_a(d);
    let g0 = quadric.half_gradient(o);
    let alpha = dot(d, &ad);
    let beta = dot(d, &g0);
    let gamma = quadric.eval(o);
    let p = Polynomial::from_coeffs(vec![gamma, beta * 2u32, alpha]);
    let gradient: Vec<Polynomial> = (0..D).map(|i| affine(&g0[i], &ad[i])).collect();
    line_cut(o, d, &p, &gradient)
}

/// Line against a plane conic (§6.3): [`intersect_line_quadric`] in 2D.
pub fn intersect_line_conic(
    origin: [f64; 2],
    direction: [f64; 2],
    conic: &QuadricForm<2>,
) -> Result<Certified<LineCut<2>>, GeomError> {
    intersect_line_quadric(origin, direction, conic)
}

/// A torus with exact data (§1.6): centre, axis (any non-zero length), major radius
/// `R ≥ 0`, minor radius `r > 0`.
#[derive(Debug, Clone, PartialEq)]
pub struct TorusData {
    center: [Rational; 3],
    axis: [Rational; 3],
    major: Rational,
    minor: Rational,
}

impl TorusData {
    /// The exact data of a torus of the model.
    pub fn of_torus(t: &crate::surface::torus::Torus) -> Result<TorusData, GeomError> {
        let f = t.frame();
        TorusData::new(f.origin(), f.axis(), t.major(), t.minor())
    }

    /// Validate and take the doubles exactly.
    pub fn new(
        center: [f64; 3],
        axis: [f64; 3],
        major: f64,
        minor: f64,
    ) -> Result<TorusData, GeomError> {
        let center = exact_vec("center", &center)?;
        let axis = exact_vec("axis", &axis)?;
        if axis.iter().all(|x| x.cmp0() == std::cmp::Ordering::Equal) {
            return Err(GeomError::ZeroDirection {
                field: "axis".into(),
            });
        }
        let major = rational_from_f64("major_radius", major)?;
        if major.cmp0() == std::cmp::Ordering::Less {
            return Err(GeomError::InvalidValue {
                field: "major_radius".into(),
                reason: "must not be negative".into(),
            });
        }
        let minor = positive("minor_radius", minor)?;
        Ok(TorusData {
            center,
            axis,
            major,
            minor,
        })
    }
}

/// Line `origin + t·direction` against a torus: the quartic of the module
/// documentation, its real roots with exact multiplicities (0, 2 with one double, 3, 4
/// hits, …), `status: exact`, `complete: true`.
///
/// Two degenerate tori of §1.6: with `R = 0` the quartic is the square of the sphere
/// `|q|² = r²` (every point would be double and singular), so the sphere is solved
/// instead. With `r > R` (spindle) the quartic's zero set is the outer "apple"
/// (`|q|² + R² − r² = 2Rρ ≥ 0`) together with the inner "lemon" (`= −2Rρ ≤ 0`), which
/// the §1.6 domain `v ∈ [−π+γ, π−γ]` excludes: points with `|q|² + R² − r² < 0` are
/// dropped (decided exactly; the two axis points, where both sheets meet, are kept),
/// and `reason` says so.
pub fn intersect_line_torus(
    origin: [f64; 3],
    direction: [f64; 3],
    torus: &TorusData,
) -> Result<Certified<LineCut<3>>, GeomError> {
    let (o, d) = exact_line(&origin, &direction)?;
    Ok(intersect_line_torus_exact(&o, &d, torus))
}

/// [`intersect_line_torus`] on exact data (`d ≠ 0`).
pub fn intersect_line_torus_exact(
    o: &[Rational; 3],
    d: &[Rational; 3],
    torus: &TorusData,
) -> Certified<LineCut<3>> {
    if torus.major.cmp0() == std::cmp::Ordering::Equal {
        let sphere = QuadricForm::sphere_exact(&torus.center, &torus.minor);
        return intersect_line_quadric_exact(o, d, &sphere);
    }
    let a = &torus.axis;
    let w: [Rational; 3] = std::array::from_fn(|i| Rational::from(&o[i] - &torus.center[i]));
    let aa = dot(a, a);
    let r2 = Rational::from(&torus.major * &torus.major);
    let k = r2.clone() - Rational::from(&torus.minor * &torus.minor);
    // |q|², q·a and the coordinates of q as polynomials in t.
    let qq = Polynomial::from_coeffs(vec![dot(&w, &w), dot(&w, d) * 2u32, dot(d, d)]);
    let qa = affine(&dot(&w, a), &dot(d, a));
    let constant = |x: Rational| Polynomial::constant(x);
    let s = &qq + &constant(k);
    let squared = (&s * &s).scale(&aa);
    let radial_part = (&qq.scale(&aa) - &(&qa * &qa)).scale(&(r2.clone() * 4u32));
    let quartic = &squared - &radial_part;
    // ∇T/4 on the line.
    let radial = (&s - &constant(r2.clone() * 2u32)).scale(&aa);
    let axial = qa.scale(&(r2 * 2u32));
    let gradient: Vec<Polynomial> = (0..3)
        .map(|i| &(&radial * &affine(&w[i], &d[i])) + &axial.scale(&a[i]))
        .collect();
    let mut cut = line_cut(o, d, &quartic, &gradient);
    if torus.minor > torus.major {
        if let LineCut::Points(hits) = &mut cut.value {
            hits.retain_mut(|h| sign_at_root(&mut h.t, &s) != std::cmp::Ordering::Less);
        }
        cut.reason = Some(
            "spindle torus: points of the quartic's inner sheet, outside the surface, are omitted"
                .into(),
        );
    }
    cut
}
