//! A plane Bézier or NURBS curve (polynomial or rational, OPERATIONS.md §1.5, NURBS piece
//! by piece through [`super::exact_spline`]) against a whole `circle2`, `ellipse2` or
//! implicit `conic2` (§1.6, §6.4), decided exactly (issues 14 and 16;
//! docs/CERTIFICATES.md `exact`).
//!
//! On the curve `X = N/W` (`W > 0`) the conic's equation `F(x) = xᵀAx + 2bᵀx + c₀`
//! is `G(t)/W(t)²` with the polynomial `G = NᵀAN + 2W·bᵀN + c₀W²` of rational
//! coefficients (the doubles taken exactly, [`super::exact_spline::ExactBezier::quadric`]).
//! Its real roots in the curve's domain are isolated exactly with their multiplicities —
//! the intersection multiplicities where the curve is regular: 2 a proven tangency, 4
//! the contact of a curve with its osculating circle at a vertex — by the machinery of
//! [`super::bezier_plane`], which also rounds the coordinates correctly. The conic's
//! own parameter (the angle of a circle or an ellipse, §1.6) is rounded correctly by
//! Ziv's loop from the exact signs of `X − c` at the root
//! ([`super::params::Ellipse2::curve_point`]); a conic given implicitly has none.
//! `G ≡ 0`: the curve lies on the conic (kind `coincident`, reason "the curve lies on
//! the conic", as for a curve on a line); on some pieces only, or when a number cannot
//! be rounded within the budget or before the deadline, the pair is left to the
//! numeric certifier (`None`).

use super::bezier_plane::{bezier_points, Exactly, OtherParams};
use super::exact_spline::{spline_points, ExactBezier, ExactCurve};
use super::params::Ellipse2;
use crate::certificate::{Arithmetic, Certified};
use crate::num::round::Rounded;
use crate::ops::answer::Answer;
use crate::ops::rational::QuadricForm;

/// A Bézier or NURBS curve (as exact pieces) against a whole plane conic `form = 0`,
/// whose angle is reported when `param` gives its centre and semi-axes.
pub(super) fn spline_conic2(
    curve: &ExactCurve,
    form: &QuadricForm<2>,
    param: Option<Ellipse2>,
    curve_first: bool,
    deadline: Option<std::time::Instant>,
) -> Option<Certified<Answer>> {
    let on = |c: &ExactBezier| c.quadric(form);
    let bits = match curve.zero_set(on, true, "the curve lies on the conic") {
        Ok(bits) => bits,
        Err(r) => return r.map(|r| *r),
    };
    let points = spline_points(curve, curve_first, |c, skip_start| {
        bezier_points(
            c,
            &on(c),
            angle(param, c),
            |_| true,
            skip_start,
            curve_first,
            deadline,
        )
    })?;
    Some(Certified::exact(
        Answer::from_points(points),
        Arithmetic::Rational,
        bits,
    ))
}

/// The conic's angle at a root of the piece, correctly rounded (none for an implicit
/// conic).
fn angle(param: Option<Ellipse2>, c: &ExactBezier) -> OtherParams<'_> {
    Box::new(move |t| {
        let Some(e) = param else {
            return Some(Vec::new());
        };
        let nums = [c.nums[0].clone(), c.nums[1].clone()];
        let (nearest, [lo, hi]) = e.curve_point(&nums, &c.den, t)?;
        let r: Exactly = (Rounded { nearest, lo, hi }, None);
        Some(vec![r])
    })
}
