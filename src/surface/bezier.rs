//! Tensor-product (rational) Bézier patch of OPERATIONS.md §1.6 (1.18) with the
//! Bernstein basis, on `[0, 1]²` (CASES `bezier_surface`): net row `i` ↔ `v`, position
//! `j` in the row ↔ `u`.

use super::basis::bernstein_jet;
use super::taylor::{centre, is_point, taylor_tensor_jet};
use super::taylor_fast::{try_centred_jet, BasisSource};
use super::tensor::{tensor_jet, validate_net, Net};
use super::validate::{restrict_domain, Domain};
use super::Surface;
use crate::error::GeomError;
use crate::num::Real;

/// A Bézier patch of degree `cols − 1` in `u` and `rows − 1` in `v`.
#[derive(Debug, Clone, PartialEq)]
pub struct BezierSurface {
    pub(crate) net: Net,
    domain: Domain,
}

impl BezierSurface {
    /// The patch over `points[i][j]` (at least 2 × 2, rectangular) with optional positive
    /// `weights` of the same shape (errors name `points[i]`, `points[i][j]`,
    /// `weights[i][j]`).
    pub fn new(
        points: &[Vec<[f64; 3]>],
        weights: Option<&[Vec<f64>]>,
    ) -> Result<BezierSurface, GeomError> {
        let net = validate_net(points, weights, 2, 2)?;
        net.check_spans()?;
        Ok(BezierSurface {
            net,
            domain: ([0.0, 1.0], [0.0, 1.0]),
        })
    }

    /// The same patch on a sub-rectangle of `[0, 1]²`.
    pub fn with_domain(mut self, domain: Domain) -> Result<BezierSurface, GeomError> {
        self.domain = restrict_domain(self.domain, Some(domain))?;
        Ok(self)
    }

    /// `(degree in u, degree in v)`.
    pub fn degrees(&self) -> (usize, usize) {
        (self.net.cols - 1, self.net.rows - 1)
    }
    /// The control points, row by row.
    pub fn points(&self) -> Vec<Vec<[f64; 3]>> {
        self.net.point_rows()
    }
    /// The weights, row by row, if rational.
    pub fn weights(&self) -> Option<Vec<Vec<f64>>> {
        self.net.weight_rows()
    }
}

impl Surface for BezierSurface {
    fn domain(&self) -> ([f64; 2], [f64; 2]) {
        self.domain
    }
    fn jet<T: Real>(&self, u: &T, v: &T, order: usize) -> Vec<[T; 3]> {
        let (pu, pv) = self.degrees();
        if is_point(u) && is_point(v) {
            let bu = bernstein_jet(pu, u, order);
            let bv = bernstein_jet(pv, v, order);
            return tensor_jet(&self.net, &bu, 0, &bv, 0, order);
        }
        // An interval box: the centred form (super::taylor; f64 intervals take the fast
        // midpoint–radius evaluation of super::taylor_fast).
        let (su, sv) = (
            BasisSource::Bernstein { degree: pu },
            BasisSource::Bernstein { degree: pv },
        );
        if let Some(jet) = try_centred_jet(&self.net, su, u, sv, v, order) {
            return jet;
        }
        let ((cu, du, iu), (cv, dv, iv)) = (centre(u), centre(v));
        let bu = bernstein_jet(pu, &cu, pu);
        let bv = bernstein_jet(pv, &cv, pv);
        taylor_tensor_jet(&self.net, &bu, &du, 0, &bv, &dv, 0, order, iu && iv)
    }
}
