//! A solution curve as a graph over one coordinate (CERTIFICATION.md "verified", for
//! one-dimensional solution sets such as the intersection curve of OPERATIONS.md §9.1):
//! the parametric Krawczyk operator for `n` equations in `n + 1` unknowns.
//!
//! Split the unknowns into the fixed coordinate `t = x_j` (§9.3 (9.5)) and the other `n`,
//! `z`. For a box `X = Z × T`, the midpoint `m` of `Z`, the interval Jacobian `J_Z(X)`
//! (the columns of `∂F/∂x` without column `j`) and a preconditioner `Y ≈ mid(J_Z)⁻¹`,
//!
//! ```text
//! K(Z, T) = m − Y·F(m, T) + (I − Y·J_Z(X))·(Z − m).
//! ```
//!
//! For each fixed `t ∈ T`, `G_t(z) = F(z, t)` is a square system on `Z` whose Krawczyk
//! operator `m − Y G_t(m) + (I − Y J̃)(Z − m)` is contained in `K(Z, T)`: `G_t(m) ∈ F(m, T)`
//! and, by the mean value theorem on segments from `m` in `Z × {t}`, the rows of `J̃` lie
//! in `J_Z(X)`. If `F` is `C¹` on `X` ([`super::guarded`]) and `K(Z, T) ⊆ int Z`, then by
//! Krawczyk's theorem (with Rump's interior inclusion, as in [`super::krawczyk`]) every
//! `G_t` has exactly one root `z(t)` in `Z`, it lies in `K(Z, T)`, and every matrix of
//! `J_Z(X)` is nonsingular. By the implicit function theorem `t ↦ z(t)` is then `C¹`: the
//! solution set `F⁻¹(0) ∩ X` is exactly the graph of `z` over `T` — one smooth arc that
//! meets the boundary of `X` only in its two end faces `t = inf T` and `t = sup T`
//! (`K ⊆ int Z` keeps it off the other faces).
//!
//! All operations are outward rounded in the interval type, so the computed `K` contains
//! the exact one.

use super::boxes::{self, IBox};
use super::dual::value_and_jacobian;
use super::guarded::{all_smooth, Guarded};
use super::level::CertInterval;
use super::linalg::{identity_minus_product, mat_vec, mid_matrix};
use crate::num::Real;

/// `n` equations in `n + 1` unknowns, `F: ℝⁿ⁺¹ → ℝⁿ`, written once over [`Real`] like
/// [`super::System`]; its solution set is (where `F` is regular) a curve.
pub trait CurveSystem {
    /// The number of equations `n` (the unknowns are `n + 1`).
    fn equations(&self) -> usize;

    /// `F(x)`, `n` values for `n + 1` arguments. It must not branch on the values of its
    /// arguments (an interval argument stands for every point of a box).
    fn eval<T: Real>(&self, x: &[T]) -> Vec<T>;

    /// `F(x)` and the `n × (n + 1)` Jacobian (rows are equations), by default from one
    /// evaluation over dual numbers. An override must enclose the same derivatives for
    /// interval `T`.
    fn eval_with_jacobian<T: Real>(&self, x: &[T]) -> (Vec<T>, Vec<Vec<T>>) {
        value_and_jacobian(x, |d| self.eval(d))
    }
}

/// What one parametric Krawczyk step proves about a box (module doc).
#[derive(Debug, Clone)]
pub enum Graph<I> {
    /// Nothing: `F` is not proven `C¹` on the box, the shapes are wrong, or `mid(J_Z)` is
    /// numerically singular.
    Inconclusive,
    /// `K(Z, T) ⊆ int Z`: over every `t ∈ T` exactly one solution `z(t) ∈ Z`, and it lies
    /// in the given `K` (the free coordinates only, in order, without `j`).
    Unique(IBox<I>),
    /// Every solution of the box lies in `K(Z, T)` (none if `K ∩ Z` is empty); `K` given.
    Image(IBox<I>),
}

/// The free coordinates of `x` (all but `fixed`).
pub fn free<I: Clone>(x: &[I], fixed: usize) -> IBox<I> {
    x.iter()
        .enumerate()
        .filter(|&(i, _)| i != fixed)
        .map(|(_, v)| v.clone())
        .collect()
}

/// `z` with `t` inserted at position `fixed`.
pub fn with_fixed<I: Clone>(z: &[I], t: &I, fixed: usize) -> IBox<I> {
    let mut x = z.to_vec();
    x.insert(fixed, t.clone());
    x
}

/// One parametric Krawczyk step on the box `x` (`n + 1` sides) with coordinate `fixed`
/// as the parameter (module doc).
pub fn graph_krawczyk<S: CurveSystem, I: CertInterval>(sys: &S, x: &[I], fixed: usize) -> Graph<I> {
    let n = sys.equations();
    if x.len() != n + 1 || fixed > n {
        return Graph::Inconclusive;
    }
    let gx: Vec<Guarded<I>> = x.iter().cloned().map(Guarded::new).collect();
    let (_, jac) = sys.eval_with_jacobian(&gx);
    let square = jac.len() == n && jac.iter().all(|r| r.len() == n + 1);
    if !square || !jac.iter().all(|r| all_smooth(r)) {
        return Graph::Inconclusive;
    }
    let jz: Vec<Vec<I>> = jac
        .into_iter()
        .map(|row| free(&row, fixed).into_iter().map(|g| g.value).collect())
        .collect();
    let z = free(x, fixed);
    let m = boxes::midpoint(&z);
    let gm: Vec<Guarded<I>> = with_fixed(&m, &x[fixed], fixed)
        .into_iter()
        .map(Guarded::new)
        .collect();
    let fm = sys.eval(&gm);
    if fm.len() != n || !all_smooth(&fm) {
        return Graph::Inconclusive;
    }
    let Some(y) = I::approx_inverse(&mid_matrix(&jz)) else {
        return Graph::Inconclusive;
    };
    let fm: Vec<I> = fm.into_iter().map(|g| g.value).collect();
    let c = identity_minus_product(&y, &jz);
    let yf = mat_vec(&y, &fm);
    let d: Vec<I> = z.iter().zip(&m).map(|(a, b)| a.clone() - b).collect();
    let cd = mat_vec(&c, &d);
    let k: IBox<I> = (0..n).map(|i| m[i].clone() - &yf[i] + &cd[i]).collect();
    if k.iter().any(|v| v.is_empty()) {
        return Graph::Inconclusive;
    }
    if boxes::is_interior(&k, &z) {
        Graph::Unique(k)
    } else {
        Graph::Image(k)
    }
}

/// A proven graph: over every `t` of the slab `x[fixed]`, exactly one solution in the box
/// `region`, and it lies in `enclosure` (both full `n + 1`-sided boxes; the enclosure's
/// fixed side is the slab).
#[derive(Debug, Clone)]
pub struct GraphBox<I> {
    pub region: IBox<I>,
    pub enclosure: IBox<I>,
    pub fixed: usize,
}

/// Prove a graph over the slab `t` around the free-coordinate box `z` by epsilon-inflation
/// (Rump 1983, as [`super::krawczyk::verify_near`]): after a failed step continue with the
/// hull of `z` and `K` grown by a tenth of its width plus a few units in the last place,
/// clipped to `limit` (the part of space the caller allows, e.g. the domain; a full
/// `n + 1`-sided box). At most `steps` steps.
pub fn prove_graph<S: CurveSystem, I: CertInterval>(
    sys: &S,
    t: &I,
    z: &[I],
    fixed: usize,
    limit: &[I],
    steps: usize,
) -> Option<GraphBox<I>> {
    let bits = t.precision_bits();
    let ulps = (-(f64::from(bits) - 4.0)).exp2();
    let mut z = z.to_vec();
    let lim = free(limit, fixed);
    for _ in 0..steps {
        if !boxes::is_subset(&z, &lim) {
            z = boxes::intersection(&z, &lim)?;
        }
        let x = with_fixed(&z, t, fixed);
        match graph_krawczyk(sys, &x, fixed) {
            Graph::Unique(k) => {
                return Some(GraphBox {
                    enclosure: with_fixed(&k, t, fixed),
                    region: x,
                    fixed,
                })
            }
            Graph::Image(k) => z = boxes::hull(&boxes::inflate_scaled(&k, 0.1, ulps), &z),
            Graph::Inconclusive => return None,
        }
    }
    None
}

/// A tight enclosure of the one solution over the point (or narrow slab) `t ⊆` the slab
/// of a proven [`GraphBox`]: iterate `E ← E ∩ K(E, t)` from the graph's enclosure (each
/// `K` contains the solution, which lies in `E`). The result is a full box with `t` at
/// position `fixed`.
pub fn enclose_at<S: CurveSystem, I: CertInterval>(
    sys: &S,
    graph: &GraphBox<I>,
    t: &I,
    steps: usize,
) -> Option<IBox<I>> {
    let fixed = graph.fixed;
    if !t.is_subset(&graph.region[fixed]) {
        return None;
    }
    let mut e = free(&graph.enclosure, fixed);
    for _ in 0..steps {
        let before = boxes::widths(&e).into_iter().fold(0.0, f64::max);
        let x = with_fixed(&e, t, fixed);
        let k = match graph_krawczyk(sys, &x, fixed) {
            Graph::Unique(k) | Graph::Image(k) => k,
            Graph::Inconclusive => break,
        };
        e = boxes::intersection(&e, &k)?;
        let after = boxes::widths(&e).into_iter().fold(0.0, f64::max);
        if after.is_nan() || after >= 0.5 * before {
            break;
        }
    }
    Some(with_fixed(&e, t, fixed))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::num::Interval;

    /// The unit circle `x² + y² − 1 = 0` in the plane.
    struct Circle;
    impl CurveSystem for Circle {
        fn equations(&self) -> usize {
            1
        }
        fn eval<T: Real>(&self, x: &[T]) -> Vec<T> {
            vec![x[0].sqr() + x[1].sqr() - x[0].lift(1.0)]
        }
    }

    fn iv(lo: f64, hi: f64) -> Interval {
        Interval::from_bounds(lo, hi)
    }

    #[test]
    fn an_arc_of_the_circle_is_a_graph_over_x() {
        // x ∈ [0.1, 0.3]: y = √(1 − x²) ∈ [0.954, 0.995]
        let x = [iv(0.1, 0.3), iv(0.9, 1.05)];
        let Graph::Unique(k) = graph_krawczyk(&Circle, &x, 0) else {
            panic!("expected a proof")
        };
        assert!(k[0].contains((1.0f64 - 0.01).sqrt()) && k[0].contains((1.0f64 - 0.09).sqrt()));
        // the slab over which both branches y = ±√(1 − x²) lie in the box: no proof
        let both = [iv(0.1, 0.3), iv(-1.05, 1.05)];
        assert!(!matches!(
            graph_krawczyk(&Circle, &both, 0),
            Graph::Unique(_)
        ));
        // near x = 1 the circle is no graph over x
        let turn = [iv(0.95, 1.0), iv(-0.2, 0.35)];
        assert!(!matches!(
            graph_krawczyk(&Circle, &turn, 0),
            Graph::Unique(_)
        ));
    }

    #[test]
    fn inflation_and_tight_enclosure_at_a_point() {
        let limit = [iv(-2.0, 2.0), iv(-2.0, 2.0)];
        let g =
            prove_graph(&Circle, &iv(0.5, 0.6), &[iv(0.82, 0.84)], 0, &limit, 8).expect("a graph");
        let e = enclose_at(&Circle, &g, &Interval::point(0.6), 6).expect("inside");
        assert!(e[1].contains(0.8) && e[1].width() < 1e-14, "{e:?}");
    }
}
