//! The implicit `quadric` of the case format (CASES.md table of surfaces; OPERATIONS.md
//! §1.4): `F(x) = [x 1]ᵀ Q [x 1] = xᵀAx + 2bᵀx + c₀` of a symmetric 4×4 matrix
//! `Q = [[A, b], [bᵀ, c₀]]`, its doubles taken as exact rationals ([`QuadricForm`]).
//!
//! - A line or segment against it, exactly (§5.2, eq. (6.3)): `F(o + t·d)` is a
//!   quadratic in `t` with exact rational coefficients, its roots isolated and rounded
//!   correctly by [`super::intersect_line_quadric_exact`]; a tangency is an exact double
//!   root (`multiplicity: 2`), a line on the quadric (`F ≡ 0` along it) is `coincident`
//!   (or the segment itself). The quadric has no parametrisation: its points carry no
//!   parameters.
//! - A point against it (§4): the sign of `F` at the exact point, so `inside` (`F < 0`),
//!   `on` (`F = 0`) or `outside` (`F > 0`), the side convention of §1.4.

use rug::Rational;

use super::pairs::{line3, line_cut_answer};
use super::{intersect_line_quadric_exact, QuadricForm};
use crate::certificate::{Arithmetic, Certified};
use crate::ops::answer::Answer;
use crate::ops::classify::Side;
use crate::ops::shape::Linear;
use crate::surface::implicit::ImplicitQuadric;

/// The exact form of the quadric; `None` only for a zero matrix, which
/// [`ImplicitQuadric::new`] already refuses.
pub(crate) fn form(q: &ImplicitQuadric) -> Option<QuadricForm<3>> {
    QuadricForm::of_implicit(q)
}

/// A line or segment against the quadric, exactly (module doc); `None` when `line` is
/// not a 3D line or segment.
pub(crate) fn line_quadric(
    line: &Linear,
    q: &ImplicitQuadric,
    line_first: bool,
) -> Option<Certified<Answer>> {
    let line = line3(line)?;
    let form = form(q)?;
    let cut = intersect_line_quadric_exact(&line.o, &line.d, &form);
    Some(line_cut_answer(
        &line,
        cut,
        |_, _| (Vec::new(), true),
        line_first,
    ))
}

/// The side of the exact point `p` (module doc): `status: exact`.
pub(crate) fn classify_point_quadric(
    p: &[Rational; 3],
    q: &ImplicitQuadric,
) -> Option<Certified<Answer>> {
    let f = form(q)?.eval(p);
    let side = match f.cmp0() {
        std::cmp::Ordering::Less => Side::Inside,
        std::cmp::Ordering::Equal => Side::On,
        std::cmp::Ordering::Greater => Side::Outside,
    };
    let bits = f
        .numer()
        .significant_bits()
        .max(f.denom().significant_bits());
    Some(Certified::exact(
        Answer::Side(side, None),
        Arithmetic::Rational,
        bits,
    ))
}
