//! Offset curves (OPERATIONS.md §1.2 and §1.5 "Derived curves"): the plane offset
//! `c(t) + a·n(t)` at signed distance `a`, `n = (−y', x')/|c'|` of (1.4)
//! ([`Offset2`]), and the space offset `c(t) + t̂(t) × d` for a fixed vector `d`
//! ([`Offset3`]; for a planar `c` and `d` normal to its plane, the planar offset of
//! length `|d|`).
//!
//! Both are `c + D(t̂)` for a linear map `D`, so the jet of order `k` is
//! `c⁽ᵐ⁾ + D(t̂⁽ᵐ⁾)`, `m ≤ k`, with `t̂⁽ᵐ⁾` from the base jet of order `k + 1` by
//! [`unit_tangent_jet`]. The base curves cap their jets at order 3, so an offset's jet
//! is known up to order 2; entries of higher order are "unknown": NaN for f64, the
//! whole line for intervals (an enclosure of anything).
//!
//! Interval soundness: every operation is an enclosing [`Real`] operation, so an
//! interval jet encloses the exact offset over the parameter interval. Where the base
//! tangent's enclosure holds 0 (a cusp, a stationary point) the offset is undefined and
//! the enclosure is unbounded (f64: NaN or ∞), never a wrong finite value.
//!
//! Where the base tangent may jump (a polyline vertex, a knot of multiplicity ≥ p) the
//! offset is discontinuous; such bases are refused (`unsupported`, field `base`).

use super::diffgeo::unit_tangent_jet;
use super::{Curve, StepHint};
use crate::error::{require_finite, require_finite_all, GeomError};
use crate::num::vector::cross;
use crate::num::Real;

/// The plane offset `c(t) + a·n(t)` of §1.2 (signed distance `a`, `n` to the left of
/// the direction of travel).
#[derive(Debug, Clone, PartialEq)]
pub struct Offset2<C> {
    base: C,
    distance: f64,
}

/// The space offset `c(t) + t̂(t) × d` of §1.5.
#[derive(Debug, Clone, PartialEq)]
pub struct Offset3<C> {
    base: C,
    offset: [f64; 3],
}

/// Refuse a base whose tangent may jump strictly inside its domain.
fn check_base<const D: usize, C: Curve<D>>(base: &C) -> Result<(), GeomError> {
    let (lo, hi) = base.domain();
    if let Some((a, _)) = base
        .tangent_breaks()
        .into_iter()
        .find(|&(a, b)| lo < b && a < hi)
    {
        return Err(GeomError::Unsupported {
            field: "base".into(),
            reason: format!(
                "the base curve's tangent may jump at t = {a}, where its offset is \
                 discontinuous; offset each smooth piece instead"
            ),
        });
    }
    Ok(())
}

impl<C> Offset2<C> {
    /// Errors: `non_finite` (`distance`); `unsupported` (`base`) for a base whose
    /// tangent may jump inside its domain. A zero distance gives the base curve.
    pub fn new(base: C, distance: f64) -> Result<Self, GeomError>
    where
        C: Curve<2>,
    {
        require_finite("distance", distance)?;
        check_base(&base)?;
        Ok(Offset2 { base, distance })
    }

    /// The curve that is offset.
    pub fn base(&self) -> &C {
        &self.base
    }

    /// The signed distance `a`.
    pub fn distance(&self) -> f64 {
        self.distance
    }
}

impl<C> Offset3<C> {
    /// Errors: `non_finite` (`offset[i]`); `unsupported` (`base`) as [`Offset2::new`].
    pub fn new(base: C, offset: [f64; 3]) -> Result<Self, GeomError>
    where
        C: Curve<3>,
    {
        require_finite_all("offset", &offset)?;
        check_base(&base)?;
        Ok(Offset3 { base, offset })
    }

    /// The curve that is offset.
    pub fn base(&self) -> &C {
        &self.base
    }

    /// The vector `d`.
    pub fn offset(&self) -> [f64; 3] {
        self.offset
    }
}

/// An unknown value: NaN for f64, the whole line for intervals (`1/[−1, 1]`).
fn unknown<T: Real>(like: &T) -> T {
    if T::IS_F64 {
        like.lift(f64::NAN)
    } else {
        like.one_like() / like.lift(-1.0).hull_with(&like.one_like())
    }
}

/// The jet of `c + D(t̂)` of order `order` from the base jet of order `order + 1`
/// (see the module doc for the cap and the enclosure).
fn offset_jet<T: Real, const D: usize, C: Curve<D>>(
    base: &C,
    t: &T,
    order: usize,
    displace: impl Fn(&[T; D]) -> [T; D],
) -> Vec<[T; D]> {
    let jet = base.jet(t, order + 1);
    let tangent = unit_tangent_jet(&jet[1..]);
    (0..=order)
        .map(|m| match (jet.get(m), tangent.get(m)) {
            (Some(c), Some(u)) if m + 1 < jet.len() => {
                let d = displace(u);
                std::array::from_fn(|i| c[i].clone() + &d[i])
            }
            _ => std::array::from_fn(|_| unknown(t)),
        })
        .collect()
}

/// The `Curve` methods that an offset takes from its base unchanged: the domain, the
/// pieces (on each the offset of one formula), the breaks and the step rule (the
/// offset's tangent is parallel to the base's wherever it is defined).
macro_rules! from_base {
    () => {
        fn domain(&self) -> (f64, f64) {
            self.base.domain()
        }
        /// Closed when the base is periodic: point and tangent then match at the seam.
        fn is_closed(&self) -> bool {
            self.base.is_periodic()
        }
        fn is_periodic(&self) -> bool {
            self.base.is_periodic()
        }
        fn domain_rounded(&self) -> bool {
            self.base.domain_rounded()
        }
        fn tangent_breaks(&self) -> Vec<(f64, f64)> {
            self.base.tangent_breaks()
        }
        fn piece_breaks(&self) -> Vec<f64> {
            self.base.piece_breaks()
        }
        fn pinned_at(&self, t: f64) -> Option<Self> {
            let base = self.base.pinned_at(t)?;
            Some(Self {
                base,
                ..self.clone()
            })
        }
        fn step_hint(&self, t: f64) -> StepHint {
            self.base.step_hint(t)
        }
    };
}

impl<C: Curve<2> + Clone> Curve<2> for Offset2<C> {
    from_base!();
    fn jet<T: Real>(&self, t: &T, order: usize) -> Vec<[T; 2]> {
        let a = t.lift(self.distance);
        offset_jet(&self.base, t, order, |u: &[T; 2]| {
            [-(a.clone() * &u[1]), a.clone() * &u[0]]
        })
    }
}

impl<C: Curve<3> + Clone> Curve<3> for Offset3<C> {
    from_base!();
    fn jet<T: Real>(&self, t: &T, order: usize) -> Vec<[T; 3]> {
        let d = self.offset.map(|x| t.lift(x));
        offset_jet(&self.base, t, order, |u: &[T; 3]| cross(u, &d))
    }
}
