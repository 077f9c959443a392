//! The local frame of an analytic surface (spec/CASES.md "Frames"; OPERATIONS.md §1.5:
//! origin `p`, orthonormal `i₁, i₂, i₃`).
//!
//! The input vectors are kept exactly as given; the normalisation happens in the
//! generic formula ([`Frame::axes`]), so that an interval evaluation encloses the
//! exact orthonormal frame of the exact input (ARCHITECTURE.md "Numbers": never
//! normalise an input silently).
//!
//! Rule: `Z = axis/|axis|`. With `ref`, `X = normalise(ref − (ref·Z)Z)`; without it,
//! `e` is the coordinate unit vector least aligned with `Z` (smallest `|axis_i|`, the
//! first on ties) and `X = normalise(e − (e·Z)Z)`. `Y = Z × X`. So axis `+z` gives
//! `X = +x`, `Y = +y`.

use std::any::TypeId;

use rug::Rational;

use crate::error::{require_finite_all, GeomError};
use crate::num::vector::{add, cross, dot, lift, normalize, scale, sub};
use crate::num::Real;

/// An origin and an axis (with an optional reference direction), validated.
#[derive(Debug, Clone, PartialEq)]
pub struct Frame {
    origin: [f64; 3],
    axis: [f64; 3],
    reference: Option<[f64; 3]>,
    /// `[X, Y, Z]` evaluated once in f64 by the same generic formula ([`Frame::axes`]
    /// returns it for `T = f64` instead of recomputing it).
    cached: [[f64; 3]; 3],
}

/// `a × b = 0` decided exactly (rationals; the inputs are exact doubles).
pub fn exactly_parallel(a: &[f64; 3], b: &[f64; 3]) -> bool {
    let r = |x: f64| Rational::from_f64(x).unwrap_or_default();
    let (a, b) = (a.map(r), b.map(r));
    let zero = |i: usize, j: usize| Rational::from(&a[i] * &b[j]) == Rational::from(&a[j] * &b[i]);
    zero(1, 2) && zero(2, 0) && zero(0, 1)
}

impl Frame {
    /// A frame at `origin` with `Z` along `axis` and `X` from `reference` (or the
    /// default rule). Errors name `origin`, `axis` (non-finite or zero) and `ref`
    /// (non-finite, zero or parallel to the axis).
    pub fn new(
        origin: [f64; 3],
        axis: [f64; 3],
        reference: Option<[f64; 3]>,
    ) -> Result<Frame, GeomError> {
        require_finite_all("origin", &origin)?;
        require_finite_all("axis", &axis)?;
        if axis.iter().all(|&a| a == 0.0) {
            return Err(GeomError::ZeroDirection {
                field: "axis".into(),
            });
        }
        if let Some(r) = reference {
            require_finite_all("ref", &r)?;
            if exactly_parallel(&r, &axis) {
                return Err(GeomError::InvalidValue {
                    field: "ref".into(),
                    reason: "the reference direction is zero or parallel to the axis".into(),
                });
            }
        }
        let mut frame = Frame {
            origin,
            axis,
            reference,
            cached: [[0.0; 3]; 3],
        };
        frame.cached = frame.compute_axes(&0.0f64);
        Ok(frame)
    }

    /// The frame at `origin` with the standard axes (`axis = +z`).
    pub fn standard(origin: [f64; 3]) -> Result<Frame, GeomError> {
        Frame::new(origin, [0.0, 0.0, 1.0], None)
    }

    /// The origin as given.
    pub fn origin(&self) -> [f64; 3] {
        self.origin
    }

    /// The axis as given (not normalised).
    pub fn axis(&self) -> [f64; 3] {
        self.axis
    }

    /// The reference direction as given.
    pub fn reference(&self) -> Option<[f64; 3]> {
        self.reference
    }

    /// `[X, Y, Z]` in the number system of `like`. For intervals each entry encloses the
    /// exact frame of the exact input (every step is an enclosing [`Real`] operation);
    /// for f64 it is the f64 evaluation of the same formula, computed once.
    pub fn axes<T: Real>(&self, like: &T) -> [[T; 3]; 3] {
        if TypeId::of::<T>() == TypeId::of::<f64>() {
            return self.cached.map(|a| lift(like, &a));
        }
        self.compute_axes(like)
    }

    fn compute_axes<T: Real>(&self, like: &T) -> [[T; 3]; 3] {
        let z = normalize(&lift(like, &self.axis));
        let e = match self.reference {
            Some(r) => lift(like, &r),
            None => {
                let mut k = 0;
                for i in 1..3 {
                    if self.axis[i].abs() < self.axis[k].abs() {
                        k = i;
                    }
                }
                let mut e = [0.0; 3];
                e[k] = 1.0;
                lift(like, &e)
            }
        };
        let x = normalize(&sub(&e, &scale(&dot(&e, &z), &z)));
        let y = cross(&z, &x);
        [x, y, z]
    }

    /// `x·X + y·Y + z·Z` (a direction: no origin).
    pub fn to_world_vector<T: Real>(axes: &[[T; 3]; 3], local: &[T; 3]) -> [T; 3] {
        std::array::from_fn(|i| {
            local[0].clone() * &axes[0][i]
                + local[1].clone() * &axes[1][i]
                + local[2].clone() * &axes[2][i]
        })
    }

    /// A local jet `[s, s_u, …]` placed in the world: the origin is added to the value,
    /// every entry is rotated by the axes.
    pub fn place_jet<T: Real>(&self, local: Vec<[T; 3]>) -> Vec<[T; 3]> {
        let Some(first) = local.first() else {
            return local;
        };
        let axes = self.axes(&first[0]);
        let origin = lift(&first[0], &self.origin);
        local
            .iter()
            .enumerate()
            .map(|(k, l)| {
                let w = Frame::to_world_vector(&axes, l);
                if k == 0 {
                    add(&w, &origin)
                } else {
                    w
                }
            })
            .collect()
    }

    /// The local coordinates `((x−o)·X, (x−o)·Y, (x−o)·Z)` of a world point, with the
    /// axes used (for the chain rule of implicit forms).
    pub fn to_local<T: Real>(&self, x: &[T; 3]) -> ([T; 3], [[T; 3]; 3]) {
        let axes = self.axes(&x[0]);
        let d = sub(x, &lift(&x[0], &self.origin));
        (std::array::from_fn(|i| dot(&d, &axes[i])), axes)
    }
}
