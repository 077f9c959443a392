//! A plane Bézier or NURBS curve (polynomial or rational, OPERATIONS.md §1.5, NURBS piece
//! by piece through [`super::exact_spline`]) against a `line2`
//! or `segment2` (§6.3), decided exactly (issue 16; docs/CERTIFICATES.md `exact`).
//!
//! The line `o + s·d` is the zero set of `g(x) = d⊥·(x − o)`, `d⊥ = (−d_y, d_x)`; on
//! the curve `X = N/W` (`W > 0`) it is `G(t)/W(t)` with the polynomial
//! `G = W·g(X)` of rational coefficients (the doubles taken exactly). Its real roots
//! in the curve's domain are isolated exactly with their multiplicities (2: a proven
//! tangency) by the machinery of [`super::bezier_plane`], which also rounds the
//! coordinates and the line's parameter `s = d·(X − o)/|d|²` correctly. A segment's or
//! ranged line's parameter range `[a, b]` is decided exactly: `s(t) − a` has the sign of
//! the polynomial `W·(s − a)` at the root ([`sign_at_root`]). `G ≡ 0`: the curve lies
//! on the line; for a whole line the answer is `coincident` (reason "the curve lies on
//! the line", as for a curve in a plane); for a segment the common set is a piece of the
//! line whose ends need not be unique curve points, left to the numeric certifier
//! (`None`), as is a coordinate that cannot be rounded within the budget.

use rug::Rational;
use std::cmp::Ordering;

use super::bezier_plane::{bezier_points, ratios};
use super::exact_spline::{spline_points, ExactBezier, ExactCurve};
use crate::certificate::{Arithmetic, Certified};
use crate::certify::univariate::RealRoot;
use crate::ops::answer::Answer;
use crate::ops::rational::exact::{dot, sign_at_root};

/// A Bézier or NURBS curve (as exact pieces) against the line `o + s·d` (`d ≠ 0`),
/// restricted to `range` if any.
pub(crate) fn spline_line2(
    curve: &ExactCurve,
    o: &[Rational; 2],
    d: &[Rational; 2],
    range: Option<&[Rational; 2]>,
    curve_first: bool,
    deadline: Option<std::time::Instant>,
) -> Option<Certified<Answer>> {
    let perp = [-d[1].clone(), d[0].clone()];
    let side = |c: &ExactBezier| c.affine(&perp, &-dot(&perp, o));
    let bits = match curve.zero_set(side, range.is_none(), "the curve lies on the line") {
        Ok(bits) => bits,
        Err(r) => return r.map(|r| *r),
    };
    let dd = dot(d, d);
    let unit: [Rational; 2] = std::array::from_fn(|i| Rational::from(&d[i] / &dd));
    let points = spline_points(curve, curve_first, |c, skip_start| {
        let s = c.affine(&unit, &-dot(&unit, o));
        let keep = |t: &mut RealRoot| {
            let Some([a, b]) = range else {
                return true;
            };
            let above = &s - &c.den.scale(a);
            let below = &s - &c.den.scale(b);
            sign_at_root(t, &above) != Ordering::Less
                && sign_at_root(t, &below) != Ordering::Greater
        };
        let g = side(c);
        bezier_points(
            c,
            &g,
            ratios(std::slice::from_ref(&s), &c.den, deadline),
            keep,
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
