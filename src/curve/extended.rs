//! The extended curve of OPERATIONS.md §1.5 "Derived curves" (reconstructed
//! [Y 2.10.6]): beyond an open end the curve continues along its end tangent,
//! `c(t_max) + (t − t_max) c'(t_max)` (and `c(t_min) + (t − t_min) c'(t_min)` before
//! the start), over a domain widened by given parameter lengths (the widened ends are
//! the doubles `t_min − before`, `t_max + after` as computed in f64).
//!
//! The three parts are joined by [`piecewise_jet`] at `t_min` and `t_max`, so an
//! interval parameter straddling an end is split and hulled; the end point and tangent
//! are evaluated in the number system of `t` at the exact double `t_min` / `t_max`, so
//! intervals enclose them. The curve is C¹ at the ends (its `c''` jumps there), which
//! are its [`Curve::piece_breaks`].

use super::domain::piecewise_jet;
use super::{Curve, StepHint};
use crate::error::{require_finite, GeomError};
use crate::num::Real;

/// A bounded open curve continued along its end tangents.
#[derive(Debug, Clone, PartialEq)]
pub struct Extended<C> {
    base: C,
    /// `[t_min − before, t_min, t_max, t_max + after]`.
    breaks: [f64; 4],
    /// `Some(0 | 1 | 2)`: one part alone (before, base, after), for [`Curve::pinned_at`].
    pin: Option<usize>,
}

impl<C> Extended<C> {
    /// Widen the domain by `before` (below `t_min`) and `after` (above `t_max`),
    /// parameter lengths `≥ 0`. Errors: `non_finite` / `invalid_value` (`extend[0]`,
    /// `extend[1]`) for a non-finite or negative length; `unsupported` (`base`) for a
    /// closed or unbounded base (a closed curve wraps its parameter instead).
    pub fn new<const D: usize>(base: C, before: f64, after: f64) -> Result<Self, GeomError>
    where
        C: Curve<D>,
    {
        for (i, v) in [before, after].into_iter().enumerate() {
            let field = format!("extend[{i}]");
            require_finite(&field, v)?;
            if v < 0.0 {
                return Err(GeomError::InvalidValue {
                    field,
                    reason: format!("{v} must not be negative"),
                });
            }
        }
        let (lo, hi) = base.domain();
        let unsupported = |reason: &str| GeomError::Unsupported {
            field: "base".into(),
            reason: reason.into(),
        };
        if !(lo.is_finite() && hi.is_finite()) {
            return Err(unsupported("an unbounded curve has no end to extend"));
        }
        if base.is_closed() {
            return Err(unsupported(
                "a closed curve has no open end (it wraps its parameter)",
            ));
        }
        let breaks = [lo - before, lo, hi, hi + after];
        for (i, b) in [breaks[0], breaks[3]].into_iter().enumerate() {
            require_finite(&format!("extend[{i}]"), b)?;
        }
        Ok(Extended {
            base,
            breaks,
            pin: None,
        })
    }

    /// The curve that is extended.
    pub fn base(&self) -> &C {
        &self.base
    }

    /// The part (0 before, 1 the base, 2 after) holding `t` (the base at its ends).
    fn part_of(&self, t: f64) -> usize {
        if t < self.breaks[1] {
            0
        } else if t > self.breaks[2] {
            2
        } else {
            1
        }
    }

    /// The jet of part `i` at `t`: the base (kept inside its domain unless pinned), or
    /// the tangent line at its end, `[c(e) + (t − e) c'(e), c'(e), 0, …]`.
    fn part_jet<T: Real, const D: usize>(&self, i: usize, t: &T, order: usize) -> Vec<[T; D]>
    where
        C: Curve<D>,
    {
        if i == 1 {
            let t = if self.pin.is_some() {
                t.clone()
            } else {
                t.restrict_to(self.breaks[1], self.breaks[2])
            };
            return self.base.jet(&t, order);
        }
        let e = t.lift(if i == 0 {
            self.breaks[1]
        } else {
            self.breaks[2]
        });
        let end = self.base.jet(&e, 1);
        let dt = t.clone() - &e;
        (0..=order)
            .map(|m| match m {
                0 => std::array::from_fn(|k| end[0][k].clone() + dt.clone() * &end[1][k]),
                1 => end[1].clone(),
                _ => std::array::from_fn(|_| t.zero_like()),
            })
            .collect()
    }
}

impl<const D: usize, C: Curve<D> + Clone> Curve<D> for Extended<C> {
    fn domain(&self) -> (f64, f64) {
        (self.breaks[0], self.breaks[3])
    }
    fn jet<T: Real>(&self, t: &T, order: usize) -> Vec<[T; D]> {
        if let Some(i) = self.pin {
            return self.part_jet(i, t, order);
        }
        let (a, b) = t.bounds();
        if self.breaks[1] <= a && b <= self.breaks[2] {
            return self.part_jet(1, t, order); // the closed base (its ends included)
        }
        piecewise_jet(t, &self.breaks, |i, ti| self.part_jet(i, ti, order))
    }
    /// The base's breaks (the tangent is continuous at the joins).
    fn tangent_breaks(&self) -> Vec<(f64, f64)> {
        self.base.tangent_breaks()
    }
    /// The widened ends (where `c''` jumps) and the base's own breaks.
    fn piece_breaks(&self) -> Vec<f64> {
        if self.pin.is_some() {
            return Vec::new();
        }
        let mut out = Vec::new();
        if self.breaks[0] < self.breaks[1] {
            out.push(self.breaks[1]);
        }
        out.extend(self.base.piece_breaks());
        if self.breaks[2] < self.breaks[3] {
            out.push(self.breaks[2]);
        }
        out
    }
    fn pinned_at(&self, t: f64) -> Option<Self> {
        let part = self.part_of(t);
        let mut out = self.clone();
        if part == 1 {
            if let Some(inner) = self.base.pinned_at(t) {
                out.base = inner;
            }
        }
        out.pin = Some(part);
        Some(out)
    }
    /// The base's rule on the base (one step per base when it is straight); the
    /// straight parts are one step each.
    fn step_hint(&self, t: f64) -> StepHint {
        let part = self.part_of(t);
        if part != 1 {
            let len = self.breaks[part + 1] - self.breaks[part];
            return StepHint::Adaptive {
                max_step: Some(len.max(f64::MIN_POSITIVE)),
            };
        }
        match self.base.step_hint(t) {
            StepHint::Whole => StepHint::Adaptive {
                max_step: Some(self.breaks[2] - self.breaks[1]),
            },
            hint => hint,
        }
    }
}
