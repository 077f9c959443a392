//! Polylines (OPERATIONS.md §1.5 [Y 2.4.1]): `c(t) = (1−w)P_i + w P_{i+1}`,
//! `w = (t − t_i)/(t_{i+1} − t_i)`, on `[t₀, t_n]`; uniform `t_i = i` by default.
//! An interval parameter is split at the vertices it straddles ([`piecewise_jet`]), so
//! the derivative enclosure covers the one-sided derivatives of every segment touched.

use super::domain::{periodic_jet, piecewise_jet};
use super::{Curve, StepHint};
use crate::error::{require_finite_all, GeomError};
use crate::num::vector::{add_scaled, lift, scale, sub, zero};
use crate::num::Real;

/// A polyline through `points` at parameters `params`.
#[derive(Debug, Clone, PartialEq)]
pub struct Polyline<const D: usize> {
    points: Vec<[f64; D]>,
    params: Vec<f64>,
}

impl<const D: usize> Polyline<D> {
    /// Errors: `count_mismatch` (`points`, fewer than 2; `params`, not one per point),
    /// `non_finite` (`points[i][j]`, `params[i]`), `invalid_value` (`params[i]`) unless
    /// the parameters increase strictly.
    pub fn new(points: Vec<[f64; D]>, params: Option<Vec<f64>>) -> Result<Self, GeomError> {
        if points.len() < 2 {
            return Err(GeomError::CountMismatch {
                field: "points".into(),
                expected: "at least 2 points".into(),
                found: format!("{}", points.len()),
            });
        }
        for (i, p) in points.iter().enumerate() {
            require_finite_all(&format!("points[{i}]"), p)?;
        }
        let params = match params {
            None => (0..points.len()).map(|i| i as f64).collect(),
            Some(t) => {
                if t.len() != points.len() {
                    return Err(GeomError::CountMismatch {
                        field: "params".into(),
                        expected: format!("{} parameters (one per point)", points.len()),
                        found: format!("{}", t.len()),
                    });
                }
                require_finite_all("params", &t)?;
                if let Some(i) = (1..t.len()).find(|&i| t[i] <= t[i - 1]) {
                    return Err(GeomError::InvalidValue {
                        field: format!("params[{i}]"),
                        reason: format!(
                            "{} does not exceed the previous parameter {}",
                            t[i],
                            t[i - 1]
                        ),
                    });
                }
                t
            }
        };
        Ok(Polyline { points, params })
    }
    pub fn points(&self) -> &[[f64; D]] {
        &self.points
    }
    pub fn params(&self) -> &[f64] {
        &self.params
    }
    /// The jet on the open chain of segments (the last segment's continuation beyond
    /// the end).
    fn open_jet<T: Real>(&self, t: &T, order: usize) -> Vec<[T; D]> {
        piecewise_jet(t, &self.params, |i, ti| {
            let (a, b) = (lift(ti, &self.points[i]), lift(ti, &self.points[i + 1]));
            let (ta, tb) = (ti.lift(self.params[i]), ti.lift(self.params[i + 1]));
            let d = scale(&(ti.one_like() / (tb - &ta)), &sub(&b, &a));
            let mut jet = vec![add_scaled(&a, &(ti.clone() - ta), &d), d];
            jet.resize(order + 1, zero(ti));
            jet
        })
    }

    fn piece_of(&self, t: f64) -> usize {
        let n = self.params.partition_point(|&b| b <= t);
        n.saturating_sub(1).min(self.params.len() - 2)
    }
}

impl<const D: usize> Curve<D> for Polyline<D> {
    fn domain(&self) -> (f64, f64) {
        (self.params[0], self.params[self.params.len() - 1])
    }
    fn is_closed(&self) -> bool {
        self.points[0] == self.points[self.points.len() - 1]
    }
    fn jet<T: Real>(&self, t: &T, order: usize) -> Vec<[T; D]> {
        // A closed polyline wraps its parameter (see `NurbsCurve::jet`).
        if self.is_closed() {
            return periodic_jet(t, self.domain(), |tw| self.open_jet(tw, order));
        }
        self.open_jet(t, order)
    }
    /// The inner vertices.
    fn tangent_breaks(&self) -> Vec<(f64, f64)> {
        let n = self.params.len();
        self.params[1..n - 1].iter().map(|&t| (t, t)).collect()
    }
    /// (2.1) clamped to ½ of the current segment's parameter length (as knot spans).
    fn step_hint(&self, t: f64) -> StepHint {
        let i = self.piece_of(t);
        StepHint::Adaptive {
            max_step: Some(0.5 * (self.params[i + 1] - self.params[i])),
        }
    }
}
