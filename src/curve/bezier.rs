//! Bézier and rational Bézier curves (OPERATIONS.md §1.5 (Bézier), [Y 2.5], [Y 2.7.2])
//! and the conic arc [Y 2.6.1].
//!
//! Evaluation by de Casteljau's algorithm on the homogeneous points `(w P, w)` (the
//! homogeneous form [Y 2.7.4]); derivatives from the last de Casteljau levels,
//! `c⁽ᵏ⁾ = n!/(n−k)! Δᵏ P⁽ⁿ⁻ᵏ⁾` (the hodograph rule `c' = nΣ(P_{i+1}−P_i)B_{i,n−1}`
//! applied k times), and for rational curves the quotient rule of §1.5. Every step is
//! a sum of products, so interval parameters give enclosures.

use super::domain::Domain;
use super::rational::quotient_jet;
use super::span_hull;
use super::Curve;
use crate::error::{require_finite_all, GeomError};
use crate::num::{Interval, Real};

/// A (rational) Bézier curve `Σ B_{i,n}(t) w_i P_i / Σ B_{i,n}(t) w_i`, `t ∈ [0, 1]`
/// (or a sub-range).
#[derive(Debug, Clone, PartialEq)]
pub struct Bezier<const D: usize> {
    points: Vec<[f64; D]>,
    weights: Option<Vec<f64>>,
    domain: Domain,
}

/// Validate control points and optional weights (shared with NURBS curves):
/// `non_finite` (`points[i][j]`, `weights[i]`), `count_mismatch` (`weights`),
/// `non_positive_weight` / `degenerate_weight` (subnormal, `weights[i]`).
pub(crate) fn check_net<const D: usize>(
    points: &[[f64; D]],
    weights: Option<&[f64]>,
) -> Result<(), GeomError> {
    for (i, p) in points.iter().enumerate() {
        require_finite_all(&format!("points[{i}]"), p)?;
    }
    if let Some(w) = weights {
        if w.len() != points.len() {
            return Err(GeomError::CountMismatch {
                field: "weights".into(),
                expected: format!("{} weights (one per point)", points.len()),
                found: format!("{}", w.len()),
            });
        }
        require_finite_all("weights", w)?;
        if let Some(i) = w.iter().position(|&x| x <= 0.0) {
            return Err(GeomError::NonPositiveWeight {
                field: format!("weights[{i}]"),
                value: format!("{}", w[i]),
            });
        }
        for (i, &x) in w.iter().enumerate() {
            super::weight::check_weight(&format!("weights[{i}]"), x)?;
        }
    }
    Ok(())
}

impl<const D: usize> Bezier<D> {
    /// Errors: `count_mismatch` (`points`, fewer than 2), those of the control net
    /// (`non_finite`, `count_mismatch` / `non_positive_weight` for `weights`), and
    /// `empty_domain` / `parameter_outside_domain` (`domain`, inside `[0, 1]`).
    pub fn new(
        points: Vec<[f64; D]>,
        weights: Option<Vec<f64>>,
        domain: Option<(f64, f64)>,
    ) -> Result<Self, GeomError> {
        if points.len() < 2 {
            return Err(GeomError::CountMismatch {
                field: "points".into(),
                expected: "at least 2 control points (degree ≥ 1)".into(),
                found: format!("{}", points.len()),
            });
        }
        check_net(&points, weights.as_deref())?;
        let domain = match domain {
            None => Domain { lo: 0.0, hi: 1.0 },
            Some((a, b)) => {
                let d = Domain::new("domain", a, b)?;
                d.check_inside("domain", (0.0, 1.0))?;
                d
            }
        };
        Ok(Bezier {
            points,
            weights,
            domain,
        })
    }
    pub fn points(&self) -> &[[f64; D]] {
        &self.points
    }
    pub fn weights(&self) -> Option<&[f64]> {
        self.weights.as_deref()
    }
    /// The degree `n` (number of points − 1).
    pub fn degree(&self) -> usize {
        self.points.len() - 1
    }
}

/// The conic arc of [Y 2.6.1]: `[(1−t)²P₀ + 2t(1−t)wP₁ + t²P₂] / [(1−t)² + 2t(1−t)w + t²]`
/// (`w < 1` ellipse, `w = 1` parabola, `w > 1` hyperbola; a circular arc of angle `φ`
/// has `w = cos(φ/2)` and `P₁` at the intersection of the end tangents).
/// Errors as [`Bezier::new`] (`weights[1]` for `w ≤ 0`).
pub fn conic_arc<const D: usize>(
    p0: [f64; D],
    p1: [f64; D],
    p2: [f64; D],
    w: f64,
) -> Result<Bezier<D>, GeomError> {
    Bezier::new(vec![p0, p1, p2], Some(vec![1.0, w, 1.0]), None)
}

/// De Casteljau on rows of components: `rows[i]` is control point `i` (any number of
/// components). Returns `d⁽ᵏ⁾/dtᵏ` of every component for `k = 0..=order`.
pub(crate) fn de_casteljau_jet<T: Real>(rows: Vec<Vec<T>>, t: &T, order: usize) -> Vec<Vec<T>> {
    let n = rows.len() - 1;
    let m = rows[0].len();
    let s = t.one_like() - t;
    // levels[r] holds the n+1−r points of de Casteljau level r; keep the last order+1.
    let mut level = rows;
    let mut kept: Vec<Vec<Vec<T>>> = Vec::new();
    for r in 0..=n {
        if r + order >= n {
            kept.push(level.clone());
        }
        if r == n {
            break;
        }
        level = (0..n - r)
            .map(|i| {
                (0..m)
                    .map(|j| s.clone() * &level[i][j] + t.clone() * &level[i + 1][j])
                    .collect()
            })
            .collect();
    }
    // kept.last() is level n (one point); level n−k is kept[len−1−k].
    let mut out = Vec::with_capacity(order + 1);
    let mut falling = 1.0f64; // n!/(n−k)!
    for k in 0..=order {
        if k > n {
            out.push(vec![t.zero_like(); m]);
            continue;
        }
        if k > 0 {
            falling *= (n + 1 - k) as f64;
        }
        let mut pts = kept[kept.len() - 1 - k].clone();
        for _ in 0..k {
            pts = (0..pts.len() - 1)
                .map(|i| (0..m).map(|j| pts[i + 1][j].clone() - &pts[i][j]).collect())
                .collect();
        }
        let f = t.lift(falling);
        out.push(pts[0].iter().map(|x| x.clone() * &f).collect());
    }
    out
}

/// Split homogeneous component jets (`D` numerator components, then the weight when
/// `rational`) into the curve jet, applying the quotient rule of §1.5 if rational.
pub(crate) fn finish_jet<T: Real, const D: usize>(jet: Vec<Vec<T>>, rational: bool) -> Vec<[T; D]> {
    let numerator: Vec<[T; D]> = jet
        .iter()
        .map(|row| std::array::from_fn(|i| row[i].clone()))
        .collect();
    if !rational {
        return numerator;
    }
    let weight: Vec<T> = jet.into_iter().map(|row| row[D].clone()).collect();
    quotient_jet(&numerator, &weight)
}

impl<const D: usize> Curve<D> for Bezier<D> {
    fn domain(&self) -> (f64, f64) {
        self.domain.pair()
    }
    fn jet<T: Real>(&self, t: &T, order: usize) -> Vec<[T; D]> {
        let rows = homogeneous_rows(&self.points, self.weights.as_deref(), t);
        let rational = self.weights.is_some();
        let n = self.points.len() - 1;
        let jet = finish_jet(de_casteljau_jet(rows, t, order), rational);
        // Over a wide f64 interval de Casteljau's levels are loose: narrow them by the
        // hull of the Bézier form on the interval (`span_hull`), the curve being span `n`
        // of the knots `0^{n+1} 1^{n+1}`.
        span_hull::meet(jet, t, |ab| {
            let mut knots = vec![0.0; n + 1];
            knots.resize(2 * n + 2, 1.0);
            let rows =
                homogeneous_rows(&self.points, self.weights.as_deref(), &Interval::point(0.0));
            span_hull::hull_jet(&knots, n, n, &rows, rational, ab, order)
        })
    }
}

/// The control points as rows `(w P, w)` (rational) or `P`, in the number system of
/// `like` (shared with NURBS curves).
pub(crate) fn homogeneous_rows<T: Real, const D: usize>(
    points: &[[f64; D]],
    weights: Option<&[f64]>,
    like: &T,
) -> Vec<Vec<T>> {
    match weights {
        None => points
            .iter()
            .map(|p| p.iter().map(|&x| like.lift(x)).collect())
            .collect(),
        Some(w) => points
            .iter()
            .zip(w)
            .map(|(p, &w)| {
                let wt = like.lift(w);
                let mut row: Vec<T> = p.iter().map(|&x| like.lift(x) * &wt).collect();
                row.push(wt);
                row
            })
            .collect(),
    }
}
