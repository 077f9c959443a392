//! The bilinear patch of OPERATIONS.md (1.17):
//! `s(u, v) = (1−v)[(1−u)p₁ + u p₂] + v[(1−u)p₃ + u p₄]`, `(u, v) ∈ [0, 1]²`.
//!
//! Differences of corners are formed in the number type (exact inputs lifted first), so
//! an interval evaluation encloses the exact jet.

use super::{StepRule, Surface};
use crate::error::{require_finite_all, GeomError};
use crate::num::vector::{add, lift, scale, sub, zero};
use crate::num::Real;

/// A bilinear patch through four corners.
#[derive(Debug, Clone, PartialEq)]
pub struct Bilinear {
    pub(crate) corners: [[f64; 3]; 4],
}

impl Bilinear {
    /// The patch with `s(0,0) = p₁, s(1,0) = p₂, s(0,1) = p₃, s(1,1) = p₄` (errors name
    /// `points[i]`).
    pub fn new(corners: [[f64; 3]; 4]) -> Result<Bilinear, GeomError> {
        for (i, p) in corners.iter().enumerate() {
            require_finite_all(&format!("points[{i}]"), p)?;
        }
        Ok(Bilinear { corners })
    }

    pub fn corners(&self) -> [[f64; 3]; 4] {
        self.corners
    }
}

impl Surface for Bilinear {
    fn domain(&self) -> ([f64; 2], [f64; 2]) {
        ([0.0, 1.0], [0.0, 1.0])
    }
    fn step_rules(&self) -> [StepRule; 2] {
        [StepRule::Curvature, StepRule::WholeRange]
    }
    fn jet<T: Real>(&self, u: &T, v: &T, order: usize) -> Vec<[T; 3]> {
        let [p1, p2, p3, p4] = self.corners.map(|p| lift(u, &p));
        let (d12, d34) = (sub(&p2, &p1), sub(&p4, &p3));
        let bottom = add(&p1, &scale(u, &d12));
        let top = add(&p3, &scale(u, &d34));
        let up = sub(&top, &bottom);
        let mut jet = vec![add(&bottom, &scale(v, &up))];
        if order >= 1 {
            let one_v = u.one_like() - v;
            jet.push(add(&scale(&one_v, &d12), &scale(v, &d34)));
            jet.push(up);
        }
        if order >= 2 {
            jet.push(zero(u));
            jet.push(sub(&d34, &d12));
            jet.push(zero(u));
        }
        jet
    }
}
