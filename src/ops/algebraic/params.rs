//! The parameters of exact hits, correctly rounded ([`super::rounding`]): the angles
//! `(u, v)` of a point on a whole sphere, ellipsoid or ring torus hit by a line, and the
//! angle `t` of a point on a whole `circle2` / `ellipse2`. The signs that decide the
//! special values (a zero angle, π, a pole) are exact: the local coordinates of a point
//! `o + t·d` are affine in the exact parameter `t` up to a positive factor (the length
//! of the frame's unnormalised axis), so their signs are signs of polynomials at an
//! algebraic number ([`crate::ops::rational::exact::sign_at_root`]).

use rug::Rational;
use std::cmp::Ordering;

use super::line::affine;
use crate::certify::univariate::{Polynomial, RealRoot};
use crate::num::round::Rounded;
use crate::num::{MpfrInterval, Real};
use crate::ops::closed_surface::frame_x_unnormalised;
use crate::ops::rational::exact::{dot, sign_at_root};
use crate::ops::rational::rounding::{
    correctly_rounded, enclose_root, special_angle, wrapped_angle,
};
use crate::surface::frame::Frame;

/// A parameter as reported: the correctly rounded value and its enclosure.
pub(crate) type Param = (f64, [f64; 2]);

fn param(r: Rounded) -> Param {
    (r.nearest, [r.lo, r.hi])
}

/// The whole circle: the parameter of a pole (every angle is one; 0 is reported).
fn any_angle() -> Param {
    let two_pi = MpfrInterval::point(0.0, 64).pi_like() * MpfrInterval::point(2.0, 64);
    (0.0, [0.0, two_pi.hi_f64()])
}

/// `atan2(y, x)` wrapped into `[0, 2π)` and correctly rounded, given the exact signs of
/// `y` and `x` and enclosures of both at any precision.
pub(crate) fn angle(
    sy: Ordering,
    sx: Ordering,
    mut enclose: impl FnMut(u32) -> (MpfrInterval, MpfrInterval),
) -> Option<Param> {
    match (sy, sx) {
        (Ordering::Equal, Ordering::Equal) => Some(any_angle()),
        (Ordering::Equal, Ordering::Greater) => special_angle(false).map(param),
        (Ordering::Equal, Ordering::Less) => special_angle(true).map(param),
        _ => correctly_rounded(|bits| {
            let (y, x) = enclose(bits);
            wrapped_angle(&y, &x)
        })
        .map(param),
    }
}

/// `atan2(z, ρ)` (a latitude in `[−π/2, π/2]`, `ρ ≥ 0`), correctly rounded, given the
/// exact sign of `z`.
fn latitude(
    sz: Ordering,
    mut enclose: impl FnMut(u32) -> (MpfrInterval, MpfrInterval),
) -> Option<Param> {
    if sz == Ordering::Equal {
        return special_angle(false).map(param);
    }
    correctly_rounded(|bits| {
        let (z, rho) = enclose(bits);
        z.atan2(&rho)
    })
    .map(param)
}

/// The closed surface's frame and shape, for the parameters of its points.
pub(crate) struct ClosedFrame<'a> {
    pub frame: &'a Frame,
    /// The semi-axes along X, Y, Z (sphere: the radius three times); torus: `[1; 3]`.
    pub scale: [f64; 3],
    /// The torus's major radius (`None` for a sphere or an ellipsoid).
    pub major: Option<f64>,
}

/// `(u, v)` of the hit `o + t·d` of a line on the closed surface, correctly rounded;
/// `None` when Ziv's loop reaches its cap.
pub(crate) fn line_hit_params(
    shape: &ClosedFrame<'_>,
    o: &[Rational; 3],
    d: &[Rational; 3],
    t: &RealRoot,
) -> Option<Vec<Param>> {
    let f = shape.frame;
    let center = f
        .origin()
        .map(|x| Rational::from_f64(x).unwrap_or_default());
    let z = f.axis().map(|x| Rational::from_f64(x).unwrap_or_default());
    let x = frame_x_unnormalised(&f.axis(), f.reference().as_ref());
    let y: [Rational; 3] = std::array::from_fn(|i| {
        let (j, k) = ((i + 1) % 3, (i + 2) % 3);
        Rational::from(&z[j] * &x[k]) - Rational::from(&z[k] * &x[j])
    });
    let w: [Rational; 3] = std::array::from_fn(|i| Rational::from(&o[i] - &center[i]));
    // Local coordinate along e (up to the factor 1/|e|): (o − c)·e + t·(d·e).
    let form = |e: &[Rational; 3]| affine(&dot(&w, e), &dot(d, e));
    let (fx, fy, fz) = (form(&x), form(&y), form(&z));
    let mut root = t.clone();
    let mut sign = |p: &Polynomial| sign_at_root(&mut root, p);
    let (sx, sy, sz) = (sign(&fx), sign(&fy), sign(&fz));
    let major = shape.major;
    // ρ − R at z = 0 (torus): the sign of ρ² − R² = x̃²/|X̃|² + ỹ²/|Ỹ|² − R².
    let s_tube = match major {
        Some(r) if sz == Ordering::Equal => {
            let r = Rational::from_f64(r).unwrap_or_default();
            let inv = |e: &[Rational; 3]| Rational::from(1) / dot(e, e);
            let rho2 = &(&fx * &fx).scale(&inv(&x)) + &(&fy * &fy).scale(&inv(&y));
            let q = &rho2 - &Polynomial::constant(r.clone() * r);
            sign(&q)
        }
        _ => Ordering::Greater,
    };
    let mut t_enc = t.clone();
    let mut local = |bits: u32| -> [MpfrInterval; 3] {
        let tt = enclose_root(&mut t_enc, bits);
        let p: [MpfrInterval; 3] = std::array::from_fn(|i| {
            MpfrInterval::from_rational(&o[i], bits)
                + tt.clone() * MpfrInterval::from_rational(&d[i], bits)
        });
        let (q, _) = f.to_local(&p);
        std::array::from_fn(|i| q[i].clone() / MpfrInterval::point(shape.scale[i], bits))
    };
    let u = angle(sy, sx, |bits| {
        let q = local(bits);
        (q[1].clone(), q[0].clone())
    })?;
    let v = match major {
        Some(r) => angle(sz, s_tube, |bits| {
            let q = local(bits);
            let rho = (q[0].sqr() + q[1].sqr()).sqrt();
            (q[2].clone(), rho - MpfrInterval::point(r, bits))
        })?,
        None => latitude(sz, |bits| {
            let q = local(bits);
            (q[2].clone(), (q[0].sqr() + q[1].sqr()).sqrt())
        })?,
    };
    Some(vec![u, v])
}

/// Centre and semi-axes of a whole `circle2` / `ellipse2`: `t = atan2((y − c_y)/b,
/// (x − c_x)/a)`.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Ellipse2 {
    pub center: [f64; 2],
    pub axes: [f64; 2],
}

impl Ellipse2 {
    fn local(&self, p: [MpfrInterval; 2], bits: u32) -> (MpfrInterval, MpfrInterval) {
        let c = |i: usize| {
            (p[i].clone() - MpfrInterval::point(self.center[i], bits))
                / MpfrInterval::point(self.axes[i], bits)
        };
        (c(1), c(0))
    }

    /// `t` of the hit `o + s·d` of a 2D line, correctly rounded.
    pub(crate) fn line_hit(
        &self,
        o: &[Rational; 2],
        d: &[Rational; 2],
        s: &RealRoot,
    ) -> Option<Param> {
        let nums = [0, 1].map(|i| affine(&o[i], &d[i]));
        self.curve_point(&nums, &Polynomial::constant(Rational::from(1)), s)
    }

    /// `t` of the point `nums(s)/den(s)` of a rational curve at the root `s`, where
    /// `den(s) > 0` (a line: `den = 1`; a Bézier or NURBS piece, §1.5), correctly
    /// rounded. The signs of `x − c_x`, `y − c_y` are those of `numᵢ − cᵢ·den` at `s`,
    /// decided exactly; the coordinates are enclosed by evaluating the polynomials over
    /// an MPFR enclosure of `s` ([`Polynomial::enclose`]).
    pub(crate) fn curve_point(
        &self,
        nums: &[Polynomial; 2],
        den: &Polynomial,
        s: &RealRoot,
    ) -> Option<Param> {
        let c = self
            .center
            .map(|x| Rational::from_f64(x).unwrap_or_default());
        let mut root = s.clone();
        let mut sign = |i: usize| sign_at_root(&mut root, &(&nums[i] - &den.scale(&c[i])));
        let (sx, sy) = (sign(0), sign(1));
        let mut s_enc = s.clone();
        angle(sy, sx, |bits| {
            let ss = enclose_root(&mut s_enc, bits);
            let w = den.enclose(&ss, bits);
            let p = std::array::from_fn(|i| nums[i].enclose(&ss, bits) / w.clone());
            self.local(p, bits)
        })
    }

    /// `t` of the point `(x, y)` (algebraic coordinates), correctly rounded.
    pub(crate) fn point(&self, x: &RealRoot, y: &RealRoot) -> Option<Param> {
        let c = self
            .center
            .map(|v| Rational::from_f64(v).unwrap_or_default());
        let (sx, sy) = (x.compare(&c[0]), y.compare(&c[1]));
        let (mut xe, mut ye) = (x.clone(), y.clone());
        angle(sy, sx, |bits| {
            let p = [enclose_root(&mut xe, bits), enclose_root(&mut ye, bits)];
            self.local(p, bits)
        })
    }
}
