//! A line, ray, ranged line or segment of space against a framed conic (circle, ellipse,
//! hyperbola, parabola, OPERATIONS.md §1.5), decided exactly (issue 16;
//! docs/CERTIFICATES.md `exact`).
//!
//! With the conic's exact frame of [`super::conic_plane`] (origin `p`, unnormalised
//! `X̃`, `Ỹ`, axis `Z̃`), the line `o + t·d` has the affine local coordinates
//! `X(t) = (o − p)·X̃ + t d·X̃`, `Y(t)` likewise, and the conic's equation in them is the
//! rational polynomial `P(t)` of the curve ∩ plane route (the equation of the cylinder
//! over the conic, restricted to the line). The line meets the conic's plane where
//! `Z̃·(o + t·d − p) = 0`:
//!
//! - `Z̃·d ≠ 0`: at the one rational `t* = Z̃·(p − o)/(Z̃·d)`; the point is on the conic
//!   exactly when `P(t*) = 0` and it is on the right branch ([`on_branch`]), decided in
//!   rationals. A line crossing the plane is never tangent to a plane curve (its
//!   tangents lie in the plane): multiplicity 1;
//! - `Z̃·d = 0`, `Z̃·(o − p) ≠ 0`: parallel to the plane, `empty` (reason `parallel`);
//! - the line lies in the plane: every real root of `P` (never `≡ 0`: the conics hold no
//!   line) is a common point, its multiplicity the intersection multiplicity in the
//!   plane (2: a proven tangency), exactly as a plane ∩ conic line ([`hits`]).
//!
//! Each root is then kept when inside the line's range (one-sided for a ray, compared
//! exactly, refining an irrational root) and when its curve parameter, correctly
//! rounded by Ziv's loop ([`curve_params`]), is in the conic's domain. Coordinates and
//! the line parameter are correctly rounded from the exact root ([`point`]). Where Ziv's
//! loop reaches its cap the pair is left to the numeric certifier (`None`).

use rug::Rational;
use std::cmp::Ordering;

use super::conic_plane::{
    curve_params, exact_frame, hits, on_branch, point, restricted, Hit, Local,
};
use crate::certificate::{Arithmetic, Certified};
use crate::certify::univariate::{real_roots, Polynomial, RealRoot};
use crate::curve::analytic::{Analytic, Shape as CurveShape};
use crate::ops::answer::Answer;
use crate::ops::rational::exact::{compare_root as compare, dot, sign_at_root};
use crate::ops::shape::{Linear, LinearObject};

type V3 = [Rational; 3];

/// A line of space exactly, with the ends of its parameter range (`None`: infinite).
pub(super) struct SpaceLine {
    pub(super) o: V3,
    pub(super) d: V3,
    pub(super) lo: Option<Rational>,
    pub(super) hi: Option<Rational>,
}

/// A 3D line (ray, ranged line) or segment exactly; `None` for other objects.
pub(super) fn space_line(l: &Linear) -> Option<SpaceLine> {
    let v = |x: &nalgebra::Vector3<Rational>| -> V3 { std::array::from_fn(|i| x[i].clone()) };
    match l.exact() {
        LinearObject::Line(l) => {
            let (lo, hi) = l.bounds();
            Some(SpaceLine {
                o: v(l.origin()),
                d: v(l.dir()),
                lo: lo.cloned(),
                hi: hi.cloned(),
            })
        }
        LinearObject::Segment(s) => Some(SpaceLine {
            o: v(s.a()),
            d: std::array::from_fn(|i| Rational::from(&s.b()[i] - &s.a()[i])),
            lo: Some(Rational::new()),
            hi: Some(Rational::from(1)),
        }),
        _ => None,
    }
}

impl SpaceLine {
    /// Whether the root `t` lies in the range, exactly.
    pub(super) fn contains(&self, t: &RealRoot) -> bool {
        let mut t = t.clone();
        self.lo
            .as_ref()
            .is_none_or(|lo| compare(&mut t, lo) != Ordering::Less)
            && self
                .hi
                .as_ref()
                .is_none_or(|hi| compare(&mut t, hi) != Ordering::Greater)
    }
}

/// The exact root `t = x` (multiplicity 1).
fn rational_root(x: Rational) -> RealRoot {
    let p = Polynomial::from_coeffs(vec![-x, Rational::from(1)]);
    real_roots(&p)
        .ok()
        .and_then(|mut r| r.pop())
        .expect("a linear polynomial has its root")
}

/// The line against a framed conic, exactly (module doc), the curve's parameter first
/// or second as in the input; `None` for the helix, for objects that are not a line or
/// segment, or when a parameter cannot be correctly rounded within the cap.
pub(crate) fn line_conic(
    line: &Linear,
    curve: &Analytic,
    curve_first: bool,
) -> Option<Certified<Answer>> {
    let shape = curve.shape();
    if matches!(shape, CurveShape::Helix { .. }) {
        return None;
    }
    let line = space_line(line)?;
    let f = exact_frame(curve);
    let (p, fx, fy) = restricted(shape, &f, &line.o, &line.d)?;
    let zd = dot(&f.z, &line.d);
    let w: V3 = std::array::from_fn(|i| Rational::from(&f.p[i] - &line.o[i]));
    let zw = dot(&f.z, &w);
    let mut found = if zd.cmp0() != Ordering::Equal {
        let t = zw / &zd;
        let mut s = rational_root(t.clone());
        let on = p.eval(&t).cmp0() == Ordering::Equal;
        let sx = sign_at_root(&mut s, &fx);
        let sy = sign_at_root(&mut s, &fy);
        if on && on_branch(shape, sx) {
            vec![Hit {
                s,
                multiplicity: 1,
                sx,
                sy,
            }]
        } else {
            vec![]
        }
    } else if zw.cmp0() != Ordering::Equal {
        let mut r = Certified::exact(Answer::Empty, Arithmetic::Rational, p.max_bits());
        r.reason = Some("parallel".into());
        return Some(r);
    } else {
        hits(shape, &p, &fx, &fy)
    };
    found.retain(|h| line.contains(&h.s));
    let local = Local {
        frame: &f,
        o: &line.o,
        m: &line.d,
        shape,
    };
    let own = [[Rational::new(), Rational::from(1)]];
    let mut points = Vec::new();
    for hit in &found {
        for t in curve_params(curve, &local, hit, &fy)? {
            points.push(point(hit, &line.o, &line.d, t, Some(&own[..]), curve_first));
        }
    }
    Some(Certified::exact(
        Answer::from_points(points),
        Arithmetic::Rational,
        p.max_bits(),
    ))
}
