//! The local frame of analytic curves and surfaces (OPERATIONS.md §1.5 "origin `p`,
//! orthonormal `i₁, i₂, i₃`"; docs/FORMAT.md "Frames"): `Z` is `axis` normalised; `X` is
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
use crate::num::vector::{add, add_scaled, cross, dot, lift, norm_sq, scale, sub};
use crate::num::Real;
use nalgebra::Vector3;

/// An origin with an orthonormal frame given by `axis` (Z) and an optional `ref` (X).
/// One frame serves curves and surfaces (`crate::surface::frame` re-exports it).
#[derive(Debug, Clone, PartialEq)]
pub struct Frame {
    origin: [f64; 3],
    axis: [f64; 3],
    reference: Option<[f64; 3]>,
    /// `[X, Y, Z]` evaluated once in f64 by the same generic formula ([`Frame::axes`]
    /// returns it for `T = f64` instead of recomputing it).
    cached: [[f64; 3]; 3],
}

/// `v` scaled by a power of two so that its largest component lies in `[1, 2)`, when
/// that scaling is exact in every component (else `v` as given). The frame is
/// invariant under positive scalings of `axis` and of `ref` (`Z = a/|a|`, `X = w/|w|`
/// with `w` homogeneous in `a` and in `r`), so the scaled inputs give the exact same
/// frame; without it `|a|²` overflows for components beyond ~1e154 (issue 14 item 4:
/// an axis component −4.6e294 made every coordinate of a parabola `NaN`) and
/// underflows to 0 below ~1e-162.
fn balanced(v: [f64; 3]) -> [f64; 3] {
    let m = v.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    if m == 0.0 || !m.is_finite() || (1.0..2.0).contains(&m) {
        return v;
    }
    // m = f·2^e with f in [1, 2): e from the bits (subnormals through a first scaling).
    let exponent = |x: f64| ((x.to_bits() >> 52) & 0x7ff) as i32 - 1023;
    let e = if m < f64::MIN_POSITIVE {
        exponent(m * 2f64.powi(64)) - 64
    } else {
        exponent(m)
    };
    // 2^−e in two factors, each a normal double.
    let (s1, s2) = (2f64.powi(-e / 2), 2f64.powi(-e - (-e / 2)));
    let scaled = v.map(|x| x * s1 * s2);
    let exact = scaled.iter().zip(&v).all(|(y, x)| y / s2 / s1 == *x);
    if exact {
        scaled
    } else {
        v
    }
}

/// `a × b = 0` decided exactly (the inputs are exact doubles): `a` and `b` are
/// parallel, or one of them is zero.
pub fn exactly_parallel(a: &[f64; 3], b: &[f64; 3]) -> bool {
    <f64 as Coord>::cross_is_zero(&Vector3::from(*a), &Vector3::from(*b))
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
            if exactly_parallel(&r, &axis) {
                return Err(GeomError::InvalidValue {
                    field: "ref".into(),
                    reason: "ref is parallel to axis, so it gives no X direction".into(),
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

    /// `[X, Y, Z]` in the number system of `like` (see the module documentation). For
    /// intervals each entry encloses the exact frame of the exact input (every step is
    /// an enclosing [`Real`] operation); for f64 it is the f64 evaluation of the same
    /// formula, computed once.
    pub fn axes<T: Real>(&self, like: &T) -> [[T; 3]; 3] {
        if T::IS_F64 {
            return self.cached.map(|a| lift(like, &a));
        }
        self.compute_axes(like)
    }

    fn compute_axes<T: Real>(&self, like: &T) -> [[T; 3]; 3] {
        let a = lift(like, &balanced(self.axis));
        let r = lift(like, &balanced(self.reference_or_default()));
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

    /// `x·X + y·Y + z·Z` (a direction: no origin).
    pub fn to_world_vector<T: Real>(axes: &[[T; 3]; 3], local: &[T; 3]) -> [T; 3] {
        std::array::from_fn(|i| {
            local[0].clone() * &axes[0][i]
                + local[1].clone() * &axes[1][i]
                + local[2].clone() * &axes[2][i]
        })
    }

    /// A jet in local coordinates (`[x, y, z]` per derivative order) placed in space:
    /// `c = p + x X + y Y + z Z`, derivatives rotated only.
    pub fn place_jet<T: Real>(&self, local: &[[T; 3]]) -> Vec<[T; 3]> {
        let Some(first) = local.first() else {
            return Vec::new();
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
