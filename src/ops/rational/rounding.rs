//! Correct rounding of the transcendental parameters of exact answers (CERTIFICATION.md
//! `exact`: every reported number is the exact value correctly rounded).
//!
//! The angle parameters of a point found exactly — `u = atan2(y, x)` of its local
//! coordinates on a sphere, ellipsoid, torus or plane ellipse — are transcendental
//! functions of algebraic numbers. They are rounded by Ziv's strategy: the point is
//! enclosed in MPFR intervals at 64, 128, … bits (its exact parameter refined to that
//! width), the angle computed with MPFR's proven interval `atan2`, and the precision
//! doubled until the enclosure lies strictly between two consecutive midpoints of
//! doubles, so that every value in it — the exact one included — rounds to the same
//! double. Angles that are exactly a double (zero) are decided beforehand from exact
//! signs, since no enclosure of them ever shrinks off a double. Beyond
//! [`PRECISION_CAP`] bits the number is reported as not correctly rounded.

use rug::float::Round;
use rug::Rational;
use std::cmp::Ordering;

use crate::certify::univariate::RealRoot;
use crate::num::round::Rounded;
use crate::num::{MpfrInterval, Real};

/// The most bits Ziv's loop uses before giving up.
pub(crate) const PRECISION_CAP: u32 = 4096;

/// The correctly rounded double of the real number that `enclose(bits)` encloses at
/// each precision, with the tight enclosure of [`Rounded`]; `None` when
/// [`PRECISION_CAP`] is reached first (the number may be exactly a double, or too close
/// to a rounding boundary).
pub(crate) fn correctly_rounded(mut enclose: impl FnMut(u32) -> MpfrInterval) -> Option<Rounded> {
    let mut bits = 64;
    while bits <= PRECISION_CAP {
        let x = enclose(bits);
        if !x.is_empty() && x.is_bounded() {
            let lo = x.lo().to_f64_round(Round::Nearest);
            let hi = x.hi().to_f64_round(Round::Nearest);
            // Rounding to nearest is monotonic: both ends rounding to `lo` means every
            // number between them does; strictly off `lo` gives the side.
            if lo == hi && lo.is_finite() {
                if *x.lo() > lo {
                    return Some(Rounded::inexact(lo, Ordering::Greater));
                }
                if *x.hi() < lo {
                    return Some(Rounded::inexact(lo, Ordering::Less));
                }
            }
        }
        bits *= 2;
    }
    None
}

/// An enclosure of the algebraic number `t` at `bits` bits of relative width.
pub(crate) fn enclose_root(t: &mut RealRoot, bits: u32) -> MpfrInterval {
    let (lo, hi) = t.interval();
    let scale = lo
        .clone()
        .abs()
        .max(hi.clone().abs())
        .max(Rational::from(1));
    let width = scale >> (bits + 8);
    t.refine_to_width(&width);
    let (lo, hi) = t.interval();
    let (a, b) = (
        MpfrInterval::from_rational(&lo, bits),
        MpfrInterval::from_rational(&hi, bits),
    );
    a.hull(&b)
}

/// The parameter angle in `[0, 2π)` of local coordinates `(x, y)`:
/// `atan2(y, x)`, plus `2π` when `y < 0`; the whole line while the sign of `y` is not
/// yet resolved (so that Ziv's loop asks for more bits).
pub(crate) fn wrapped_angle(y: &MpfrInterval, x: &MpfrInterval) -> MpfrInterval {
    let a = y.atan2(x);
    if *y.lo() > 0 {
        a
    } else if *y.hi() < 0 {
        let two_pi = a.pi_like() + a.pi_like();
        a + two_pi
    } else {
        MpfrInterval::entire(y.prec())
    }
}

/// A correctly rounded angle whose exact value is known to be one of the special
/// values 0, π (as `Rounded`), decided from exact signs.
pub(crate) fn special_angle(is_pi: bool) -> Option<Rounded> {
    if is_pi {
        correctly_rounded(|bits| MpfrInterval::point(0.0, bits).pi_like())
    } else {
        Some(Rounded::exact(0.0))
    }
}
