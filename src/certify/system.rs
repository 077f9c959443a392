//! The square systems `F: ℝⁿ → ℝⁿ` the certifier solves (OPERATIONS.md §0.4: every
//! iterative operation is Newton on such a system), and the checks of user input.

use super::dual::{value_and_jacobian, Dual};
use crate::error::GeomError;
use crate::num::Real;

/// The largest system [`super::solve`] and [`super::certify_root`] accept (issue: sizes
/// 1 to 6; the three-surface system of OPERATIONS.md §7.2 is the largest).
pub const MAX_DIM: usize = 6;

/// A square system of equations `F(x) = 0`, written once over [`Real`] so that the same
/// formula runs in f64 (Newton), in f64 intervals and in MPFR intervals (certification),
/// and, over [`Dual`] numbers, gives its own Jacobian.
///
/// The system may be defined on part of space only (a `sqrt`, a division): the
/// certifier then proves nothing where it is not smooth (see [`super::guarded`]).
/// `eval` must return exactly `dim()` values and must not branch on the values of its
/// arguments (an interval argument stands for every point of a box).
pub trait System {
    /// The number of unknowns and of equations.
    fn dim(&self) -> usize;

    /// `F(x)`, `dim()` values.
    fn eval<T: Real>(&self, x: &[T]) -> Vec<T>;

    /// `F(x)` and the Jacobian `∂Fᵢ/∂xⱼ` (rows are equations), by default from one
    /// evaluation over [`Dual`] numbers. An override must enclose the same derivatives
    /// for interval `T`.
    fn eval_with_jacobian<T: Real>(&self, x: &[T]) -> (Vec<T>, Vec<Vec<T>>) {
        value_and_jacobian(x, |d: &[Dual<T>]| self.eval(d))
    }

    /// The Jacobian `∂Fᵢ/∂xⱼ`.
    fn jacobian<T: Real>(&self, x: &[T]) -> Vec<Vec<T>> {
        self.eval_with_jacobian(x).1
    }

    /// Values that vanish at every root of the system (consequences of `F = 0`, such
    /// as the implicit form of a surface at the curve's point, which holds wherever
    /// the curve meets the surface): a box over which one of them is proven nonzero
    /// holds no root, and is excluded at once even where `F`'s own image, wide in the
    /// other unknowns, still holds 0. For interval `T` each value must enclose the
    /// exact one over the box. Default: none (only `F` itself).
    fn implied<T: Real>(&self, x: &[T]) -> Vec<T> {
        let _ = x;
        Vec::new()
    }
}

/// `(F, J)` from fixed-size arrays, for `eval_with_jacobian` overrides that evaluate an
/// explicit Jacobian formula; a missing Jacobian gives no rows (the certifier's shape
/// check then makes the box inconclusive).
pub fn value_and_rows<T, const N: usize>(
    f: [T; N],
    j: Option<[[T; N]; N]>,
) -> (Vec<T>, Vec<Vec<T>>) {
    let rows = j.map_or_else(Vec::new, |j| j.into_iter().map(Vec::from).collect());
    (Vec::from(f), rows)
}

/// Check a system's size and that it returns `dim()` values and a `dim()`×`dim()`
/// Jacobian at the point `at` (typed errors naming `system`).
pub fn check_system<S: System>(sys: &S, at: &[f64]) -> Result<usize, GeomError> {
    let n = sys.dim();
    if n == 0 || n > MAX_DIM {
        return Err(GeomError::Unsupported {
            field: "system.dim".into(),
            reason: format!("systems of size 1 to {MAX_DIM} are supported, not {n}"),
        });
    }
    let (values, jacobian) = sys.eval_with_jacobian(at);
    let rows_ok = jacobian.len() == n && jacobian.iter().all(|r| r.len() == n);
    if values.len() != n || !rows_ok {
        return Err(GeomError::CountMismatch {
            field: "system.eval".into(),
            expected: format!("{n} values and a {n}×{n} Jacobian"),
            found: format!("{} values, {} Jacobian rows", values.len(), jacobian.len()),
        });
    }
    Ok(n)
}

/// Check a point given by the user: `n` finite coordinates (errors name `field[i]`).
pub fn check_point(field: &str, x: &[f64], n: usize) -> Result<(), GeomError> {
    if x.len() != n {
        return Err(GeomError::CountMismatch {
            field: field.into(),
            expected: format!("{n} coordinates"),
            found: format!("{}", x.len()),
        });
    }
    for (i, &v) in x.iter().enumerate() {
        crate::error::require_finite(&format!("{field}[{i}]"), v)?;
    }
    Ok(())
}

/// Check a parameter box: `n` finite intervals `[lo, hi]` with `lo ≤ hi`.
pub fn check_domain(domain: &[[f64; 2]], n: usize) -> Result<(), GeomError> {
    if domain.len() != n {
        return Err(GeomError::CountMismatch {
            field: "domain".into(),
            expected: format!("{n} intervals"),
            found: format!("{}", domain.len()),
        });
    }
    for (i, &[lo, hi]) in domain.iter().enumerate() {
        let field = format!("domain[{i}]");
        crate::error::require_finite(&field, lo)?;
        crate::error::require_finite(&field, hi)?;
        if lo > hi {
            return Err(GeomError::EmptyDomain {
                field,
                lo: format!("{lo}"),
                hi: format!("{hi}"),
            });
        }
    }
    Ok(())
}
