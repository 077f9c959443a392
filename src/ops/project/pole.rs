//! Roots of the foot equations (3.9) at a pole of the parametrisation (OPERATIONS.md
//! §14.1; issue 14 item 4): along a pole edge `v = v_p` ([`Surface::v_poles`]) the
//! surface is one point `P` and `s_u ≡ 0`, so `F₁ = (p − s)·s_u` vanishes for every
//! `u`, and `(u', v_p)` is a root of (3.9) wherever `F₂(u', v_p) = (p − P)·s_v(u', v_p)`
//! does. Such a root is a foot only if `p − P` is normal to the surface at `P`.
//!
//! A `verified` root in a box `B` straddling the pole edge is proven no foot when, at
//! the exact `v_p` (an MPFR enclosure of 256 bits; `v_p ∈ B_v` checked), `F₂` takes
//! opposite non-zero signs at the two ends of `B_u`: by the intermediate value theorem
//! a root `(u', v_p)` lies in `B`, so it is the box's unique root; and `F₂ ≠ 0` at an
//! end says that `p − P` has a non-zero component along the tangent vector
//! `s_v(u, v_p)` of the surface at `P`, so `P` is not a foot.

use std::f64::consts::FRAC_PI_2;

use rug::float::{Constant, Round};
use rug::Float;

use super::equations::surface_foot_equations;
use crate::certificate::Status;
use crate::certify::Root;
use crate::num::real::Arith;
use crate::num::vector::lift;
use crate::num::MpfrInterval;
use crate::surface::Surface;

const BITS: u32 = 256;

/// The root `r` of (3.9) for the point `p` lies on a pole edge of `surface` whose
/// point is not a foot (module doc): a root of the system, but no answer.
pub fn spurious_pole_root<S: Surface>(surface: &S, p: &[f64; 3], r: &Root) -> bool {
    if r.status != Status::Verified || r.enclosure.len() != 2 {
        return false;
    }
    let (_, [v0, v1]) = surface.domain();
    let rounded = surface.domain_rounded()[1];
    let poles = surface.v_poles();
    let bu = &r.enclosure[0];
    let bv = MpfrInterval::from_interval(&r.enclosure[1], BITS);
    [(v0, poles[0]), (v1, poles[1])]
        .into_iter()
        .filter(|&(_, pole)| pole)
        .any(|(end, _)| {
            let v = exact_end(end, rounded);
            v.is_subset(&bv) && opposite_signs(surface, p, [bu.lo(), bu.hi()], &v)
        })
}

/// The exact pole value: the double `end` itself, or the multiple of `π/2` it is the
/// nearest double to ([`Surface::domain_rounded`]), enclosed by directed rounding.
fn exact_end(end: f64, rounded: bool) -> MpfrInterval {
    if !rounded {
        return MpfrInterval::point(end, BITS);
    }
    let k = (end / FRAC_PI_2).round();
    let pi = MpfrInterval::from_float_bounds(
        &Float::with_val_round(BITS, Constant::Pi, Round::Down).0,
        &Float::with_val_round(BITS, Constant::Pi, Round::Up).0,
        BITS,
    );
    // k/2 is exact in binary; the product is outward rounded
    pi.clone() * &pi.lift(k / 2.0)
}

/// `F₂(u, v)` has opposite non-zero signs at `u = ends[0]` and `u = ends[1]`.
fn opposite_signs<S: Surface>(surface: &S, p: &[f64; 3], ends: [f64; 2], v: &MpfrInterval) -> bool {
    let sign = |u: f64| {
        let u = MpfrInterval::point(u, BITS);
        let f2 = surface_foot_equations(surface, &lift(v, p), &u, v, false).0[1].clone();
        if *f2.lo() > 0 {
            1
        } else if *f2.hi() < 0 {
            -1
        } else {
            0
        }
    };
    let (a, b) = (sign(ends[0]), sign(ends[1]));
    a != 0 && a == -b
}
