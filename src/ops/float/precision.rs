//! Tolerances of the float path (OPERATIONS.md §12): the operation tolerance ε and
//! the equality tolerance δ, relative to a length scale.

/// `OperationPrecision { eps, delta }` of §12, with the derived defaults.
///
/// Both are relative: lengths use `eps·L` and `delta·L` for the problem's length scale
/// `L`; parameters use `eps·range`. They steer the float path only — a certificate
/// decides the exact input and never depends on them (docs/CERTIFICATES.md).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Precision {
    /// ε: Newton stops when every increment is below `eps` times the coordinate's scale.
    pub eps: f64,
    /// δ: two quantities are equal (same solution, point on object) within `delta`
    /// times their scale; (12.1) asks `δ ≥ 10²·ε`.
    pub delta: f64,
}

impl Default for Precision {
    /// §12 defaults: `n = 12` digits, `ε = 1e-12`, `δ = 1e-10`.
    fn default() -> Self {
        Precision {
            eps: 1e-12,
            delta: 1e-10,
        }
    }
}

impl Precision {
    /// The tangency classification tolerance `δ_tan = √δ` (§12: a tangency is located
    /// only to `O(√ε)`).
    pub fn delta_tan(&self) -> f64 {
        self.delta.sqrt()
    }

    /// The Newton-switch angle `θ_sw = 10⁻³` (§5.2, §6.4): below `sin θ_sw` between a
    /// tangent and a tangent plane (or two tangents) the fallback system is used.
    pub fn sin_switch(&self) -> f64 {
        1e-3
    }

    /// `ε_i` for a parameter of range `range` at value `x`: (12.2)
    /// `ε_i = ε·max(|x|, range)`.
    pub fn eps_param(&self, x: f64, range: f64) -> f64 {
        self.eps * x.abs().max(range)
    }

    /// `δ_i` for a parameter of range `range` at value `x` (12.2).
    pub fn delta_param(&self, x: f64, range: f64) -> f64 {
        self.delta * x.abs().max(range)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn defaults_satisfy_12_1() {
        let p = Precision::default();
        assert!(p.delta >= 100.0 * p.eps);
        assert_eq!(p.delta_tan(), 1e-5);
        assert_eq!(p.eps_param(-4.0, 2.0), 4e-12);
        assert_eq!(p.delta_param(0.5, 2.0), 2e-10);
    }
}
