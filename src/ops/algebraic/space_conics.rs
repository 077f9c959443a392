//! Two framed conics of space (circle, ellipse, hyperbola, parabola, OPERATIONS.md §1.5)
//! against each other, decided exactly where their planes differ (issue 16, §6.5;
//! docs/CERTIFICATES.md `exact`).
//!
//! Each conic lies in its plane `Z̃ᵢ·(x − pᵢ) = 0` with a rational normal `Z̃ᵢ` (its
//! axis taken exactly, [`super::conic_plane`]):
//!
//! - `Z̃₁ × Z̃₂ = 0`, `Z̃₁·(p₂ − p₁) ≠ 0`: parallel distinct planes, `empty` (reason
//!   `parallel`), exact;
//! - `Z̃₁ × Z̃₂ = 0` and the planes equal: one plane, the exact conic ∩ conic of §6.3
//!   in a rational chart of it ([`super::coplanar`]);
//! - otherwise every common point lies on the rational line `L = o + s·m`,
//!   `m = Z̃₁ × Z̃₂`, of both planes, and is a point of `L` on both conics: each conic
//!   restricted to `L` is the rational polynomial `Pᵢ(s)` of the conic ∩ plane route
//!   ([`super::conic_plane::restricted`], degree ≤ 4, with the branch rules of
//!   [`super::conic_plane::hits`]). The common points are the roots `s` of `P₁` on the
//!   right branch of the first conic that are roots of `P₂` (decided exactly:
//!   [`crate::certify::univariate::RealRoot::is_root_of`]) on the right branch of the
//!   second. No tolerance enters: two points are the same exactly when they are the same
//!   algebraic `s`.
//!
//! Multiplicity: the tangent of conic `i` at a common point lies in plane `i`; it lies
//! in the other plane only when it is along `L`, i.e. when `L` touches conic `i` there
//! (`s` a multiple root of `Pᵢ`). So the curves cross (multiplicity 1) unless `L`
//! touches both, where they share the tangent `m`: a proven tangency, reported with the
//! multiplicity 2 (`tangent: true`).
//!
//! Coordinates `o + s·m` are correctly rounded from the exact `s`, and each curve's
//! parameter by Ziv's loop ([`super::conic_plane::curve_params`], which also keeps the
//! parameters inside each curve's domain: an arc may pass a point more than once or
//! not at all). Where Ziv's loop reaches its cap the pair is left to the numeric
//! certifier (`None`), as for conic ∩ plane.

use rug::Rational;
use std::cmp::Ordering;

use super::conic_plane::{
    cross, curve_params, exact_frame, hits, is_zero, on_branch, point, restricted, Hit, Local,
};
use crate::certificate::{Arithmetic, Certified};
use crate::certify::univariate::{Polynomial, RealRoot};
use crate::curve::analytic::{Analytic, Shape as CurveShape};
use crate::ops::answer::Answer;
use crate::ops::rational::exact::{dot, sign_at_root};

type V3 = [Rational; 3];

/// The multiplicity of the root `s` in `p` (`p ≢ 0`, `s` a root): the first derivative
/// that does not vanish at `s`, decided exactly.
fn multiplicity(s: &RealRoot, p: &Polynomial) -> u32 {
    let mut k = 0;
    let mut d = p.clone();
    while !d.is_zero() && s.is_root_of(&d) {
        k += 1;
        d = d.derivative();
    }
    k
}

/// Two conics of space, exactly (module doc), the first one's parameter first; `None`
/// for a helix, when a parameter cannot be correctly rounded within the cap, or for the
/// coplanar pairs [`super::coplanar`] leaves to the numeric certifier.
pub(crate) fn conic_conic3(
    a: &Analytic,
    b: &Analytic,
    deadline: Option<std::time::Instant>,
) -> Option<Certified<Answer>> {
    let (sa, sb) = (a.shape(), b.shape());
    if matches!(sa, CurveShape::Helix { .. }) || matches!(sb, CurveShape::Helix { .. }) {
        return None;
    }
    let (fa, fb) = (exact_frame(a), exact_frame(b));
    let m = cross(&fa.z, &fb.z);
    if is_zero(&m) {
        let w: V3 = std::array::from_fn(|i| Rational::from(&fb.p[i] - &fa.p[i]));
        if dot(&fa.z, &w).cmp0() == Ordering::Equal {
            return super::coplanar::coplanar_conics(a, b, deadline);
        }
        let mut r = Certified::exact(Answer::Empty, Arithmetic::Rational, 53);
        r.reason = Some("parallel".into());
        return Some(r);
    }
    // o = (h₁(n₂ × m) + h₂(m × n₁))/|m|²: on both planes (as in conic ∩ plane).
    let (h1, h2) = (dot(&fa.z, &fa.p), dot(&fb.z, &fb.p));
    let (u, v) = (cross(&fb.z, &m), cross(&m, &fa.z));
    let mm = dot(&m, &m);
    let o: V3 =
        std::array::from_fn(|i| (Rational::from(&h1 * &u[i]) + Rational::from(&h2 * &v[i])) / &mm);
    let (pa, xa, ya) = restricted(sa, &fa, &o, &m)?;
    let (pb, xb, yb) = restricted(sb, &fb, &o, &m)?;
    let la = Local {
        frame: &fa,
        o: &o,
        m: &m,
        shape: sa,
    };
    let lb = Local {
        frame: &fb,
        o: &o,
        m: &m,
        shape: sb,
    };
    let mut points = Vec::new();
    for hit in hits(sa, &pa, &xa, &ya) {
        if !hit.s.is_root_of(&pb) {
            continue;
        }
        let mut s = hit.s.clone();
        let (sx, sy) = (sign_at_root(&mut s, &xb), sign_at_root(&mut s, &yb));
        if !on_branch(sb, sx) {
            continue;
        }
        let mut mb = multiplicity(&hit.s, &pb);
        if matches!(sb, CurveShape::Parabola { .. }) && sx == Ordering::Equal {
            mb /= 2;
        }
        let tangent = hit.multiplicity >= 2 && mb >= 2;
        let hit_b = Hit {
            s: hit.s.clone(),
            multiplicity: mb,
            sx,
            sy,
        };
        let ta = curve_params(a, &la, &hit, &ya)?;
        let tb = curve_params(b, &lb, &hit_b, &yb)?;
        let shared = Hit {
            s: hit.s.clone(),
            multiplicity: if tangent { 2 } else { 1 },
            sx: hit.sx,
            sy: hit.sy,
        };
        for t in &ta {
            for t2 in &tb {
                let mut p = point(&shared, &o, &m, *t, None, true);
                p.params[1] = vec![t2.nearest];
                if let Some(bx) = &mut p.param_box {
                    bx[1] = vec![[t2.lo, t2.hi]];
                }
                if let Some(e) = &mut p.exact {
                    e.params[1] = if t2.lo == t2.hi {
                        vec![Rational::from_f64(t2.nearest).unwrap_or_default()]
                    } else {
                        vec![]
                    };
                }
                points.push(p);
            }
        }
    }
    Some(Certified::exact(
        Answer::from_points(points),
        Arithmetic::Rational,
        pa.max_bits().max(pb.max_bits()),
    ))
}
