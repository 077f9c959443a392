//! Control nets that span no surface (issue 20 "degenerate objects"): a tensor-product
//! patch (OPERATIONS.md §1.6, (1.18)) whose normal `s_u × s_v` vanishes everywhere.
//! Walking such a patch (§2.2) takes the smallest step `range·10⁻⁴` in both directions
//! (10⁸ nodes) and the certifier finds a continuum of roots, so the net is refused
//! with a `degenerate_surface` error naming `points`, and a subnormal weight with a
//! `degenerate_weight` error naming it.
//!
//! The tests are exact (rational arithmetic on the exact doubles), so that no genuine
//! surface is refused:
//! * every control point on one line (all equal included): the patch lies in a line;
//! * every column of the net constant (and, with weights, the rows of weights
//!   proportional): `s(u, v)` does not depend on `v`, since the `v` basis functions sum
//!   to one (resp. the common factor `Σ N_i(v) c_i` cancels in `A/W`); the same for rows
//!   and `u`.
//!
//! A net degenerate only along one edge (a pole, as in a triangular patch) is a genuine
//! surface and is accepted.

use rug::Rational;

use crate::error::GeomError;

pub(crate) use crate::curve::weight::check_weight;
pub use crate::curve::weight::MIN_WEIGHT;

fn exact(p: &[f64; 3]) -> [Rational; 3] {
    p.map(|x| Rational::from_f64(x).unwrap_or_default())
}

/// Every point on one line through `points[0]` (exactly).
fn collinear(points: &[[f64; 3]]) -> bool {
    let p0 = exact(&points[0]);
    let diff = |p: &[f64; 3]| -> [Rational; 3] {
        let q = exact(p);
        std::array::from_fn(|i| Rational::from(&q[i] - &p0[i]))
    };
    let Some(d) = points.iter().find(|p| **p != points[0]).map(diff) else {
        return true;
    };
    points.iter().all(|p| {
        let e = diff(p);
        (0..3).all(|i| {
            let (j, k) = ((i + 1) % 3, (i + 2) % 3);
            Rational::from(&d[j] * &e[k]) == Rational::from(&d[k] * &e[j])
        })
    })
}

/// The net (`rows × cols`, row by row) independent of the row index: every column
/// constant and, with weights, each row of weights a multiple of row 0.
fn rows_alike(rows: usize, cols: usize, points: &[[f64; 3]], weights: Option<&[f64]>) -> bool {
    let same_points = (1..rows).all(|r| (0..cols).all(|c| points[r * cols + c] == points[c]));
    same_points
        && weights.is_none_or(|w| {
            let q = |k: usize| Rational::from_f64(w[k]).unwrap_or_default();
            (1..rows).all(|r| (1..cols).all(|c| q(r * cols + c) * q(0) == q(c) * q(r * cols)))
        })
}

/// The net transposed (columns become rows).
fn transposed<T: Copy>(rows: usize, cols: usize, v: &[T]) -> Vec<T> {
    (0..cols)
        .flat_map(|c| (0..rows).map(move |r| v[r * cols + c]))
        .collect()
}

/// Refuse a net that spans no surface (module doc); the error names `points`.
pub(crate) fn check_net_spans(
    rows: usize,
    cols: usize,
    points: &[[f64; 3]],
    weights: Option<&[f64]>,
) -> Result<(), GeomError> {
    let refuse = |reason: &str| {
        Err(GeomError::DegenerateSurface {
            field: "points".into(),
            reason: reason.into(),
        })
    };
    if points.iter().all(|p| *p == points[0]) {
        return refuse("every control point is the same: the patch collapses to a point");
    }
    if collinear(points) {
        return refuse("the control points lie on one line: the patch has no normal");
    }
    if rows_alike(rows, cols, points, weights) {
        return refuse("every row of the net is the same: the patch does not depend on v");
    }
    let tw = weights.map(|w| transposed(rows, cols, w));
    if rows_alike(cols, rows, &transposed(rows, cols, points), tw.as_deref()) {
        return refuse("every column of the net is the same: the patch does not depend on u");
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_pole_is_not_degenerate_but_equal_rows_are() {
        // a triangle-like patch: row 0 collapsed to a pole
        let pole = [[0.0, 0.0, 1.0]; 3];
        let row = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [1.0, 1.0, 0.0]];
        let net: Vec<[f64; 3]> = pole.iter().chain(row.iter()).copied().collect();
        assert!(check_net_spans(2, 3, &net, None).is_ok());
        let flat: Vec<[f64; 3]> = row.iter().chain(row.iter()).copied().collect();
        let e = check_net_spans(2, 3, &flat, None).unwrap_err();
        assert_eq!((e.kind(), e.field()), ("degenerate_surface", "points"));
        // proportional weights keep it independent of v; others make a surface
        assert!(check_net_spans(2, 3, &flat, Some(&[1.0, 2.0, 3.0, 2.0, 4.0, 6.0])).is_err());
        assert!(check_net_spans(2, 3, &flat, Some(&[1.0, 2.0, 3.0, 2.0, 4.0, 5.0])).is_ok());
    }

    #[test]
    fn subnormal_weights_are_refused() {
        assert!(check_weight("w", 1e-310).is_err());
        assert!(check_weight("w", f64::MIN_POSITIVE).is_ok());
        assert!(check_weight("w", 1.0).is_ok());
    }
}
