//! The exact line of the algebraic pairs and the enclosed angle parameters of their
//! closed surfaces (OPERATIONS.md §1.6, §5.2): below `pairs` and `apex_line`, which both
//! use them.

use rug::Rational;

use crate::num::{Interval, Real};

/// An exact line `o + t·d` with the parameter range it is restricted to.
pub(super) struct ExactLine<const D: usize> {
    pub(super) o: [Rational; D],
    pub(super) d: [Rational; D],
    pub(super) range: Option<[Rational; 2]>,
}

/// The angle of `(x, y)` in `[0, 2π)`, enclosed: `atan2` or, near its branch cut on the
/// negative x-axis, `π + atan2(−y, −x)`, whichever is narrower; `[−π, 0]` shifted by
/// 2π. A box straddling the seam `t = 0` keeps its straddling enclosure ([`param`]
/// reports it in the domain).
pub(crate) fn angle(y: &Interval, x: &Interval) -> Interval {
    let pi = x.pi_like();
    let direct = y.atan2(x);
    let across = y.neg().atan2(&x.neg()) + pi;
    if across.width() < direct.width() {
        across
    } else if below_zero(&direct) {
        direct + pi + pi
    } else {
        direct
    }
}

/// The angle box lies in `[−π, 0]` and is not the exact angle 0 (`[0, 0]` stays 0).
fn below_zero(b: &Interval) -> bool {
    b.hi() < 0.0 || (b.hi() == 0.0 && b.lo() < 0.0)
}

/// Estimate and enclosure of an angle parameter in the domain `[0, 2π]` (issue 14
/// item 2: a box in `(−π, 0]` with its estimate in `[0, 2π)` put the estimate outside
/// its box, and the box outside the domain; such a box is shifted by 2π); an empty
/// enclosure (the angle of the origin) stands for the whole circle. A box that
/// straddles the seam `0` is an arc across it and stays as tight as it is (its lower
/// end below 0 means `2π + lo`), with the estimate inside it and not below 0.
pub(crate) fn param(b: Interval) -> (f64, [f64; 2]) {
    // 2π, enclosed (outward: `pi_like` encloses π).
    let two_pi = Interval::point(0.0).pi_like() * Interval::point(2.0);
    if b.is_empty() {
        // A point on the axis (a pole): every angle is its parameter.
        return (0.0, [0.0, two_pi.hi()]);
    }
    let b = if below_zero(&b) { b + two_pi } else { b };
    let m = b.midpoint().max(0.0).clamp(b.lo(), b.hi());
    (m, [b.lo(), b.hi()])
}
