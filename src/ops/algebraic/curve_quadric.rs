//! A whole circle or ellipse against a whole sphere or ellipsoid, decided exactly in
//! the curve's plane (OPERATIONS.md §5.2 with §13.2 and §6.4; issue 14 item 5 and
//! defect 8): the quadric restricted to the plane `p + αX̃ + βỸ` of the curve is a
//! conic in `(α, β)` with rational coefficients ([`Implicit::plane_conic`]), the curve
//! is the conic `k₁α² + k₂β² = 1`, and their common points are those of the exact
//! conic ∩ conic solver ([`intersect_conic_conic`]): a curve passing 1e-9 from
//! tangency gives two proven simple crossings, a tangency a proven double point, a
//! miss the empty set — each `complete`. Points are enclosed from the exact
//! `(α, β)` (isolating intervals refined to 2⁻²⁰⁰, then MPFR), and parameters by the
//! interval inverses of the parametrisations. A curve lying on the surface is answered
//! before (by [`super::curve_on_surface`]); a coincident or common-component pair,
//! arcs and other surfaces are left to the numeric certifier (`None`).

use rug::Rational;

use super::conic_conic::{intersect_conic_conic, ConicCut};
use super::on_surface::{conic_frame, Implicit};
use super::pairs::{angle, closed, param, surface_params};
use super::QuadricForm;
use crate::certificate::{Arithmetic, Certified, Status};
use crate::curve::{AnyCurve3, Curve};
use crate::num::{Interval, MpfrInterval};
use crate::ops::answer::{Answer, Point};
use crate::ops::rational::exact::RatInterval;
use crate::surface::AnySurface;

const BITS: u32 = 256;

fn enclose(x: &RatInterval) -> MpfrInterval {
    MpfrInterval::from_rational(&x.lo, BITS).hull(&MpfrInterval::from_rational(&x.hi, BITS))
}

fn norm(v: &[Rational; 3]) -> MpfrInterval {
    let s: Rational = v.iter().map(|x| Rational::from(x * x)).sum();
    MpfrInterval::from_rational(&s, BITS).sqrt()
}

/// The common points of a whole circle or ellipse and a whole sphere or ellipsoid
/// (module doc); `surface_first` orders the parameters as the input.
pub(crate) fn curve_quadric(
    curve: &AnyCurve3,
    surface: &AnySurface,
    surface_first: bool,
) -> Option<Certified<Answer>> {
    let AnyCurve3::Analytic(c) = curve else {
        return None;
    };
    if !c.is_closed() || !matches!(surface, AnySurface::Sphere(_) | AnySurface::Ellipsoid(_)) {
        return None;
    }
    let shape = closed(surface)?;
    let frame = conic_frame(c)?;
    let own = QuadricForm::conic_exact(frame.own_conic()).ok()?;
    let cut = QuadricForm::conic_exact(Implicit::of(surface)?.plane_conic(&frame)?).ok()?;
    let result = intersect_conic_conic(&own, &cut).ok()?;
    let ConicCut::Points(hits) = &result.value else {
        return None;
    };
    let (a, b) = match c.shape() {
        crate::curve::analytic::Shape::Circle { radius } => (radius, radius),
        crate::curve::analytic::Shape::Ellipse { a, b } => (a, b),
        _ => return None,
    };
    let (lx, ly) = (norm(&frame.x), norm(&frame.y));
    let points = hits
        .iter()
        .map(|h| {
            let (mut x, mut y) = (h.x.clone(), h.y.clone());
            let fine = Rational::from(1) >> 200u32;
            x.refine_to_width(&fine);
            y.refine_to_width(&fine);
            let (al, be) = (
                enclose(&RatInterval::from_root(&x)),
                enclose(&RatInterval::from_root(&y)),
            );
            let xyz: [Interval; 3] = std::array::from_fn(|i| {
                MpfrInterval::from_rational(&frame.p[i], BITS)
                    .add(&al.mul(&MpfrInterval::from_rational(&frame.x[i], BITS)))
                    .add(&be.mul(&MpfrInterval::from_rational(&frame.y[i], BITS)))
                    .to_interval()
            });
            // cos t = α|X̃|/a, sin t = β|Ỹ|/b
            let ct = al.mul(&lx).to_interval() / Interval::point(a);
            let st = be.mul(&ly).to_interval() / Interval::point(b);
            let t = param(angle(&st, &ct));
            let uv = surface_params(&shape, &xyz);
            let (first, second) = if surface_first {
                (uv, vec![t])
            } else {
                (vec![t], uv)
            };
            Point {
                xyz: xyz.iter().map(|v| v.midpoint()).collect(),
                xyz_box: xyz.iter().map(|v| [v.lo(), v.hi()]).collect(),
                params: vec![
                    first.iter().map(|p| p.0).collect(),
                    second.iter().map(|p| p.0).collect(),
                ],
                param_box: Some(vec![
                    first.iter().map(|p| p.1).collect(),
                    second.iter().map(|p| p.1).collect(),
                ]),
                multiplicity: h.multiplicity,
                tangent: h.multiplicity >= 2,
                ..Default::default()
            }
        })
        .collect();
    Some(Certified {
        value: Answer::from_points(points),
        status: Status::Verified,
        complete: true,
        arithmetic: Arithmetic::Mpfr,
        bits: BITS,
        reason: None,
        perturbation: None,
    })
}
