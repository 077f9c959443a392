//! The Newton driver of OPERATIONS.md §0.4, for square systems of size `K ≤ 6`.
//!
//! ```text
//! for it in 1..=K_max: solve J(x) Δ = −F(x); singular J → Singular(x);
//!     x ← x + Δ, wrap periodic coordinates; a non-periodic coordinate beyond
//!     [min − Δ_scan, max + Δ_scan] → Diverged; |Δ_i| < ε_i for all i → Converged(x)
//! ```
//! The linear solve is Gaussian elimination with partial pivoting; "singular" is the
//! §0.4 test `|det J| ≤ κ_sing·Π|column norms|` with `κ_sing = 1e-12`.

/// One unknown of a Newton system: its domain, period and stopping tolerance.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Coordinate {
    /// `[min, max]` of the parameter.
    pub lo: f64,
    pub hi: f64,
    /// The parameter is periodic with period `hi − lo` (iterates are wrapped into it).
    pub periodic: bool,
    /// ε_i: the iteration stops when every `|Δ_i| < eps`.
    pub eps: f64,
    /// Δ_scan: how far beyond the domain an iterate may wander before it is `Diverged`.
    pub margin: f64,
}

impl Coordinate {
    /// The unknown `[lo, hi]` with the §12 stopping tolerance `ε·max(range, 1)` (12.2)
    /// and a scan margin of one range.
    pub fn new(lo: f64, hi: f64, periodic: bool, precision: &super::Precision) -> Coordinate {
        let range = hi - lo;
        Coordinate {
            lo,
            hi,
            periodic,
            eps: precision.eps * range.max(1.0),
            margin: range,
        }
    }

    /// The parameter of a curve.
    pub fn of_curve<const D: usize>(
        c: &impl crate::curve::Curve<D>,
        precision: &super::Precision,
    ) -> Coordinate {
        let (lo, hi) = c.domain();
        Coordinate::new(lo, hi, c.is_closed(), precision)
    }

    /// The two parameters of a surface.
    pub fn of_surface(
        s: &impl crate::surface::Surface,
        precision: &super::Precision,
    ) -> [Coordinate; 2] {
        let (u, v) = s.domain();
        let closed = s.is_closed();
        [
            Coordinate::new(u[0], u[1], closed[0], precision),
            Coordinate::new(v[0], v[1], closed[1], precision),
        ]
    }

    /// Wrap a periodic value into `[lo, hi)`; other values are returned unchanged.
    pub fn wrap(&self, x: f64) -> f64 {
        if !self.periodic {
            return x;
        }
        let period = self.hi - self.lo;
        let y = self.lo + (x - self.lo).rem_euclid(period);
        if y >= self.hi {
            self.lo
        } else {
            y
        }
    }

    fn escaped(&self, x: f64) -> bool {
        !self.periodic && (x < self.lo - self.margin || x > self.hi + self.margin)
    }
}

/// How a Newton run ended (§0.4).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum NewtonOutcome<const K: usize> {
    /// Every increment fell below its ε; the last iterate (after the last step).
    Converged([f64; K]),
    /// The Jacobian was singular at this iterate (fall back to the tangency system).
    Singular([f64; K]),
    /// A non-periodic coordinate left its domain by more than its margin.
    Diverged([f64; K]),
    /// `max_iter` steps without convergence, or a non-finite value.
    NotConverged([f64; K]),
}

/// `κ_sing` of §0.4.
const KAPPA_SING: f64 = 1e-12;

/// Run Newton's method on `system(x) = (F(x), J(x))` (`J[i][j] = ∂F_i/∂x_j`) from
/// `x0` over the coordinates `coords`, at most `max_iter` steps (`K_max`: 32, 200
/// for the linearly convergent tangency systems).
pub fn newton<const K: usize>(
    system: impl FnMut(&[f64; K]) -> ([f64; K], [[f64; K]; K]),
    x0: [f64; K],
    coords: &[Coordinate; K],
    max_iter: usize,
) -> NewtonOutcome<K> {
    newton_with(system, x0, coords, max_iter, KAPPA_SING)
}

/// [`newton`] with the singularity threshold `kappa` in place of `κ_sing`. The
/// tangency fallback systems ((5.5), (6.8)) are singular at their root by construction
/// and converge only linearly towards it, so they run with `kappa = 0` (only an
/// exactly singular pivot stops them).
pub fn newton_with<const K: usize>(
    mut system: impl FnMut(&[f64; K]) -> ([f64; K], [[f64; K]; K]),
    x0: [f64; K],
    coords: &[Coordinate; K],
    max_iter: usize,
    kappa: f64,
) -> NewtonOutcome<K> {
    let mut x = x0;
    for _ in 0..max_iter {
        let (f, j) = system(&x);
        if f.iter().chain(j.iter().flatten()).any(|v| !v.is_finite()) {
            return NewtonOutcome::NotConverged(x);
        }
        let Some(step) = solve_linear_with(j, f.map(|v| -v), kappa) else {
            return NewtonOutcome::Singular(x);
        };
        let mut done = true;
        for i in 0..K {
            x[i] = coords[i].wrap(x[i] + step[i]);
            if coords[i].escaped(x[i]) {
                return NewtonOutcome::Diverged(x);
            }
            done &= step[i].abs() < coords[i].eps;
        }
        if done {
            return NewtonOutcome::Converged(x);
        }
    }
    NewtonOutcome::NotConverged(x)
}

/// Solve `a·x = b` by Gaussian elimination with partial pivoting; `None` when `a` is
/// singular by the §0.4 test `|det a| ≤ κ_sing·Π|column norms|` (or not finite).
pub fn solve_linear<const K: usize>(a: [[f64; K]; K], b: [f64; K]) -> Option<[f64; K]> {
    solve_linear_with(a, b, KAPPA_SING)
}

/// [`solve_linear`] with the threshold `kappa` in place of `κ_sing`.
pub fn solve_linear_with<const K: usize>(
    mut a: [[f64; K]; K],
    mut b: [f64; K],
    kappa: f64,
) -> Option<[f64; K]> {
    let scale: f64 = (0..K)
        .map(|j| (0..K).map(|i| a[i][j] * a[i][j]).sum::<f64>().sqrt())
        .product();
    let mut det = 1.0;
    for col in 0..K {
        let pivot = (col..K).max_by(|&p, &q| a[p][col].abs().total_cmp(&a[q][col].abs()))?;
        if a[pivot][col] == 0.0 {
            return None;
        }
        if pivot != col {
            a.swap(pivot, col);
            b.swap(pivot, col);
            det = -det;
        }
        det *= a[col][col];
        for row in col + 1..K {
            let factor = a[row][col] / a[col][col];
            let pivot_row = a[col];
            for (x, p) in a[row][col..].iter_mut().zip(&pivot_row[col..]) {
                *x -= factor * p;
            }
            b[row] -= factor * b[col];
        }
    }
    // NaN compares as not greater: a non-finite determinant is singular too.
    if det.abs().partial_cmp(&(kappa * scale)) != Some(std::cmp::Ordering::Greater) {
        return None;
    }
    let mut x = [0.0; K];
    for row in (0..K).rev() {
        let tail: f64 = (row + 1..K).map(|k| a[row][k] * x[k]).sum();
        x[row] = (b[row] - tail) / a[row][row];
    }
    x.iter().all(|v| v.is_finite()).then_some(x)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn open(lo: f64, hi: f64) -> Coordinate {
        Coordinate {
            lo,
            hi,
            periodic: false,
            eps: 1e-14,
            margin: 1.0,
        }
    }

    #[test]
    fn converges_to_the_root_of_a_square_system() {
        // x² + y² = 4, x = y: the root (√2, √2).
        let sys = |p: &[f64; 2]| {
            (
                [p[0] * p[0] + p[1] * p[1] - 4.0, p[0] - p[1]],
                [[2.0 * p[0], 2.0 * p[1]], [1.0, -1.0]],
            )
        };
        let NewtonOutcome::Converged(x) = newton(sys, [1.0, 1.2], &[open(0.0, 3.0); 2], 32) else {
            panic!("no convergence")
        };
        assert!((x[0] - 2f64.sqrt()).abs() < 1e-15 && (x[1] - 2f64.sqrt()).abs() < 1e-15);
    }

    #[test]
    fn a_zero_jacobian_is_singular_and_an_escape_diverges() {
        let flat = |_: &[f64; 1]| ([1.0], [[0.0]]);
        assert_eq!(
            newton(flat, [0.5], &[open(0.0, 1.0)], 32),
            NewtonOutcome::Singular([0.5])
        );
        // x − 10 = 0 from 0 jumps to 10, beyond [0, 1] + margin 1.
        let far = |p: &[f64; 1]| ([p[0] - 10.0], [[1.0]]);
        assert_eq!(
            newton(far, [0.0], &[open(0.0, 1.0)], 32),
            NewtonOutcome::Diverged([10.0])
        );
    }

    #[test]
    fn periodic_coordinates_wrap_into_their_period() {
        let c = Coordinate {
            lo: 0.0,
            hi: 2.0 * std::f64::consts::PI,
            periodic: true,
            eps: 1e-14,
            margin: 0.0,
        };
        assert_eq!(c.wrap(-1.0), 2.0 * std::f64::consts::PI - 1.0);
        assert_eq!(c.wrap(1.0), 1.0);
        // sin t = 0 from t = 6.2 converges to 2π, wrapped to 0.
        let sys = |p: &[f64; 1]| ([p[0].sin()], [[p[0].cos()]]);
        let NewtonOutcome::Converged(x) = newton(sys, [6.2], &[c], 32) else {
            panic!("no convergence")
        };
        assert!(x[0] < 1e-12 || (2.0 * std::f64::consts::PI - x[0]) < 1e-12);
    }

    #[test]
    fn solves_a_permuted_system_and_rejects_a_rank_deficient_one() {
        let x = solve_linear(
            [[0.0, 2.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 4.0]],
            [2.0, 3.0, 8.0],
        );
        assert_eq!(x, Some([3.0, 1.0, 2.0]));
        let rank2 = [[1.0, 2.0, 3.0], [2.0, 4.0, 6.0], [0.0, 1.0, 1.0]];
        assert_eq!(solve_linear(rank2, [1.0, 2.0, 3.0]), None);
    }
}
