//! The local frame of analytic curves and surfaces (OPERATIONS.md §1.5 "origin `p`,
//! orthonormal `i₁, i₂, i₃`"; spec/CASES.md "Frames"): `Z` is `axis` normalised; `X` is
//! `ref` made orthogonal to `Z` and normalised; without `ref`, `e` is the coordinate
//! unit vector least aligned with `Z` (the smallest `|axis_i|`, first in x, y, z order
//! on ties), so that axis +z gives `X = +x`; `Y = Z × X`.
//!
//! The inputs are kept exactly as given (ARCHITECTURE.md "Numbers": never normalise an
//! input silently). The normalisation happens in the formula, in the number system of
//! the evaluation: with `a = axis`, `r = ref` (or `e`),
//! `w = r|a|² − (r·a)a` (the exact projection of `r` scaled by `|a|²`),
//! `Z = a/|a|`, `X = w/|w|`, `Y = (a × w)/(|a||w|)`,
//! so an interval evaluation encloses the exact orthonormal frame of the double inputs.

use crate::error::{require_finite_all, GeomError};
use crate::geom::objects::Coord;
use crate::num::vector::{add_scaled, cross, dot, lift, norm_sq, scale};
use crate::num::Real;
use nalgebra::Vector3;

/// An origin with an orthonormal frame given by `axis` (Z) and an optional `ref` (X).
#[derive(Debug, Clone, PartialEq)]
pub struct Frame {
    origin: [f64; 3],
    axis: [f64; 3],
    reference: Option<[f64; 3]>,
}

impl Frame {
    /// Errors: `non_finite` (`origin[i]`, `axis[i]`, `ref[i]`), `zero_direction`
    /// (`axis`, `ref`), `invalid_value` (`ref`) when `ref × axis = 0` exactly (no X
    /// orthogonal to Z can be made from it).
    pub fn new(
        origin: [f64; 3],
        axis: [f64; 3],
        reference: Option<[f64; 3]>,
    ) -> Result<Frame, GeomError> {
        require_finite_all("origin", &origin)?;
        require_finite_all("axis", &axis)?;
        if axis.iter().all(|&x| x == 0.0) {
            return Err(GeomError::ZeroDirection {
                field: "axis".into(),
            });
        }
        if let Some(r) = reference {
            require_finite_all("ref", &r)?;
            if r.iter().all(|&x| x == 0.0) {
                return Err(GeomError::ZeroDirection {
                    field: "ref".into(),
                });
            }
            if <f64 as Coord>::cross_is_zero(&Vector3::from(r), &Vector3::from(axis)) {
                return Err(GeomError::InvalidValue {
                    field: "ref".into(),
                    reason: "ref is parallel to axis, so it gives no X direction".into(),
                });
            }
        }
        Ok(Frame {
            origin,
            axis,
            reference,
        })
    }

    /// The frame at `origin` with axis +z and no `ref`: `X = +x`, `Y = +y`, `Z = +z`.
    pub fn standard(origin: [f64; 3]) -> Result<Frame, GeomError> {
        Frame::new(origin, [0.0, 0.0, 1.0], None)
    }

    /// The origin `p`.
    pub fn origin(&self) -> [f64; 3] {
        self.origin
    }
    /// `axis` as given.
    pub fn axis(&self) -> [f64; 3] {
        self.axis
    }
    /// `ref` as given.
    pub fn reference(&self) -> Option<[f64; 3]> {
        self.reference
    }

    /// The vector `r` that X is made from: `ref`, or the coordinate unit vector least
    /// aligned with the axis (first on ties).
    fn reference_or_default(&self) -> [f64; 3] {
        if let Some(r) = self.reference {
            return r;
        }
        let mags = self.axis.map(f64::abs);
        let mut i = 0;
        for j in 1..3 {
            if mags[j] < mags[i] {
                i = j;
            }
        }
        let mut e = [0.0; 3];
        e[i] = 1.0;
        e
    }

    /// `[X, Y, Z]` in the number system of `like` (see the module documentation).
    pub fn axes<T: Real>(&self, like: &T) -> [[T; 3]; 3] {
        let a = lift(like, &self.axis);
        let r = lift(like, &self.reference_or_default());
        let a_sq = norm_sq(&a);
        let a_len = a_sq.clone().sqrt();
        // w = r|a|² − (r·a)a, orthogonal to a.
        let w = add_scaled(&scale(&a_sq, &r), &-dot(&r, &a), &a);
        let w_len = norm_sq(&w).sqrt();
        // Divisions rather than reciprocals: exact whenever the quotient is a double.
        let x = w.clone().map(|c| c / &w_len);
        let y = cross(&a, &w).map(|c| c / (a_len.clone() * &w_len));
        let z = a.map(|c| c / &a_len);
        [x, y, z]
    }

    /// Map a jet in local coordinates (`[x, y, z]` per derivative order) to space:
    /// `c = p + x X + y Y + z Z`, derivatives without `p`.
    pub fn map_jet<T: Real>(&self, local: &[[T; 3]]) -> Vec<[T; 3]> {
        let Some(first) = local.first() else {
            return Vec::new();
        };
        let [x, y, z] = self.axes(&first[0]);
        local
            .iter()
            .enumerate()
            .map(|(k, l)| {
                std::array::from_fn(|i| {
                    let v = l[0].clone() * &x[i] + l[1].clone() * &y[i] + l[2].clone() * &z[i];
                    if k == 0 {
                        v + l[0].lift(self.origin[i])
                    } else {
                        v
                    }
                })
            })
            .collect()
    }
}
