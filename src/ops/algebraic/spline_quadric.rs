//! A space Bézier or NURBS curve (polynomial or rational, OPERATIONS.md §1.5, NURBS piece
//! by piece through [`super::exact_spline`]) against a whole sphere or ellipsoid (§5.2
//! with §6.4), decided exactly (issue 14: poles and seams; issue 16).
//!
//! On the curve `X = N/W` (`W > 0`) the quadric's equation `F(x) = xᵀAx + 2bᵀx + c₀`
//! (rational: the doubles of the input taken exactly) is `G(t)/W(t)²` with the polynomial
//! `G = NᵀAN + 2W·bᵀN + c₀W²` ([`ExactBezier::quadric`]). Its real roots in the curve's
//! domain are isolated exactly with their multiplicities (2: a proven tangency) by the
//! machinery of [`super::bezier_plane`], which also rounds `t` and the coordinates
//! correctly. Nothing here depends on the surface's parametrisation, so a root on a
//! pole or on the seam meridian is as decided as any other, and a curve passing `10⁻¹⁵`
//! from tangency gives two proven simple crossings or a proven miss.
//!
//! The surface's angles `(u, v)` are not rational at a root: they are enclosed by the
//! interval inverse of the parametrisation ([`super::pairs::surface_params`]) over the
//! correctly rounded coordinates' one-ulp boxes, so the answer is `verified` (the count,
//! the multiplicities and the coordinates are exact; the angles' boxes hold the exact
//! values, and at a pole the longitude's box is the whole circle). `G ≡ 0` on every
//! piece: the curve lies on the surface (kind `coincident`); on some pieces only, or
//! when a number cannot be rounded within the budget or before the deadline, the pair
//! is left to the numeric certifier (`None`).

use super::bezier_plane::{bezier_points, round_at, OtherParams};
use super::exact_spline::{spline_points, ExactBezier, ExactCurve};
use super::pairs::{closed, surface_params, Closed};
use crate::certificate::{Arithmetic, Certified, Status};
use crate::curve::AnyCurve3;
use crate::num::round::Rounded;
use crate::num::Interval;
use crate::ops::answer::Answer;
use crate::surface::AnySurface;

/// The common points of a Bézier or NURBS space curve and a whole sphere or ellipsoid
/// (module doc); `surface_first` orders the parameters as in the input. `None` for
/// other pairs, or when left to the numeric certifier.
pub(crate) fn spline_quadric(
    curve: &AnyCurve3,
    surface: &AnySurface,
    surface_first: bool,
    deadline: Option<std::time::Instant>,
) -> Option<Certified<Answer>> {
    let exact = match curve {
        AnyCurve3::Bezier(b) => ExactCurve::bezier(b),
        AnyCurve3::Nurbs(n) => ExactCurve::nurbs(n),
        _ => return None,
    };
    let shape = closed(surface)?;
    let Closed::Quadric(form, ..) = &shape else {
        return None;
    };
    let on = |c: &ExactBezier| c.quadric(form);
    let bits = match exact.zero_set(on, true, "the curve lies on the surface") {
        Ok(bits) => bits,
        Err(r) => return r.map(|r| *r),
    };
    let curve_first = !surface_first;
    let points = spline_points(&exact, curve_first, |c, skip_start| {
        bezier_points(
            c,
            &on(c),
            angles(&shape, c, deadline),
            |_| true,
            skip_start,
            curve_first,
            deadline,
        )
    })?;
    let mut r = Certified::exact(Answer::from_points(points), Arithmetic::Rational, bits);
    if !r.value.points().is_empty() {
        r.status = Status::Verified;
        r.reason = Some(
            "the common points are decided exactly (count, multiplicities, coordinates \
             correctly rounded); the surface's angles are enclosed, not correctly rounded"
                .into(),
        );
    }
    Some(r)
}

/// The surface's `(u, v)` at a root of the piece: the interval inverse of the
/// parametrisation over the coordinates' correctly rounded enclosures (module doc).
fn angles<'a>(
    shape: &'a Closed,
    c: &'a ExactBezier,
    deadline: Option<std::time::Instant>,
) -> OtherParams<'a> {
    Box::new(move |t| {
        let xyz: Vec<Interval> = c
            .nums
            .iter()
            .map(|num| {
                round_at(t, num, &c.den, deadline).map(|(r, _)| Interval::from_bounds(r.lo, r.hi))
            })
            .collect::<Option<_>>()?;
        let xyz: [Interval; 3] = xyz.try_into().ok()?;
        let uv = surface_params(shape, &xyz);
        Some(
            uv.into_iter()
                .map(|(nearest, [lo, hi])| (Rounded { nearest, lo, hi }, None))
                .collect(),
        )
    })
}
