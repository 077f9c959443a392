//! Krawczyk over a box cut into parts (issue 21: a root exactly on a knot of a NURBS).
//!
//! A NURBS curve or patch is one rational map per knot span, so a system built from it
//! is a different smooth map on each closed part of a box that straddles a knot, and
//! the guards of [`super::guarded`] never prove the whole box smooth: a root lying on
//! the knot could only be placed by an exact candidate, which does not exist when the
//! other unknowns are irrational there (a NURBS circle through a sphere at a knot).
//!
//! **The theorem used.** Let `X` be a box, the union of closed boxes `P₁ … P_k`, and
//! `F: X → ℝⁿ` continuous, with `F = F_i` on `P_i` for maps `F_i` that are `C¹` on
//! `P_i` (proven by the guards, each `F_i` evaluated on its own `P_i` only). Let `J` be
//! the interval hull of the enclosures `F_i′(P_i)`. For `m, z ∈ X` the segment
//! `γ(s) = m + s(z − m)` meets each convex `P_i` in a closed interval of `s`, finitely
//! many intervals cover `[0, 1]`, and `F∘γ` is continuous and `C¹` on each: so it is
//! absolutely continuous and
//! `F(z) − F(m) = ∫₀¹ F′(γ(s)) (z − m) ds = J̃ (z − m)` with `J̃ = ∫₀¹ F′(γ(s)) ds`,
//! whose entries lie in those of `J` (an interval is convex). `J` is thus a slope
//! matrix of `F` over `X`, which is all the Krawczyk theorem needs
//! ([`super::krawczyk`]; Neumaier, *Interval Methods for Systems of Equations*, 1990,
//! §5.1, states it for slopes; Rump 1983 for the interior inclusion): if
//! `K(X) ⊆ int X`, `F` has exactly one zero in `X`, and it lies in `K(X)`.
//!
//! Continuity is the caller's proof obligation (the curve's point, not its derivative,
//! enters the system, and a NURBS is continuous at every interior knot:
//! [`crate::curve::bspline::KnotVector::new`] refuses a multiplicity above the
//! degree). A foot equation `(p − c)·c′` is not continuous at a knot where `c′`
//! jumps, and must not be given here.

use super::boxes::{self, IBox};
use super::krawczyk::{krawczyk_with, smooth_jacobian, value_at, Krawczyk};
use super::level::CertInterval;
use super::system::System;

/// The parts of a box: each with the system valid on it.
pub type Parts<S, I> = Vec<(S, IBox<I>)>;

/// One Krawczyk step over `x` for a map that equals `parts[i].0` on the closed box
/// `parts[i].1` (module doc), about the midpoint of `x`. The parts must cover `x` and
/// the map must be continuous on `x`; `Inconclusive` when a part is not proven `C¹`,
/// when no part holds the midpoint, or when a shape is wrong.
pub fn krawczyk_parts<S: System, I: CertInterval>(parts: &[(S, IBox<I>)], x: &[I]) -> Krawczyk<I> {
    let m = boxes::midpoint(x);
    let Some((sys, _)) = parts.iter().find(|(_, p)| boxes::is_subset(&m, p)) else {
        return Krawczyk::Inconclusive;
    };
    let Some(fm) = value_at(sys, &m) else {
        return Krawczyk::Inconclusive;
    };
    let mut j: Option<Vec<Vec<I>>> = None;
    for (sys, p) in parts {
        let Some((_, jp)) = smooth_jacobian(sys, p) else {
            return Krawczyk::Inconclusive;
        };
        j = Some(match j {
            None => jp,
            Some(j) => j
                .iter()
                .zip(&jp)
                .map(|(a, b)| a.iter().zip(b).map(|(u, v)| u.hull(v)).collect())
                .collect(),
        });
    }
    match j {
        Some(j) => krawczyk_with(x, &m, &j, &fm),
        None => Krawczyk::Inconclusive,
    }
}

/// A root proven unique in a box cut into parts: `parts_of(X)` gives the parts of any
/// box `X` (each a closed box with the map valid on it, together covering `X`).
/// Epsilon-inflation from `start` (Rump 1983), a few steps: `X ← hull(X, K(X))` grown
/// by half its width on each side (and a few ulps); once `K(X) ⊆ int X`, the enclosure is narrowed by
/// `E ← E ∩ K(E)` while that shrinks it by a tenth or more. Returns `(X, E)`: exactly one zero in `X`, and
/// it lies in `E ⊆ X`.
pub fn verify_in_parts<S: System, I: CertInterval>(
    parts_of: &dyn Fn(&[I]) -> Parts<S, I>,
    start: &[I],
    steps: usize,
) -> Option<(IBox<I>, IBox<I>)> {
    let mut x: IBox<I> = start.to_vec();
    for _ in 0..steps {
        match krawczyk_parts(&parts_of(&x), &x) {
            Krawczyk::Unique(k) => {
                let region = x.clone();
                let mut e = boxes::intersection(&x, &k)?;
                for _ in 0..64 {
                    let before = boxes::widths(&e).into_iter().fold(0.0, f64::max);
                    let k = match krawczyk_parts(&parts_of(&e), &e) {
                        Krawczyk::Unique(k) | Krawczyk::Image(k) => k,
                        Krawczyk::Inconclusive => break,
                    };
                    let Some(next) = boxes::intersection(&e, &k) else {
                        break;
                    };
                    e = next;
                    let after = boxes::widths(&e).into_iter().fold(0.0, f64::max);
                    // linear contraction (the hull's slopes differ across the cut)
                    if after.is_nan() || after >= 0.9 * before {
                        break;
                    }
                }
                return Some((region, e));
            }
            Krawczyk::Image(k) => {
                // Room for the rounding of F(m): double the hull of X and K(X).
                let grown = boxes::hull(&x, &k);
                x = boxes::inflate_scaled(&grown, 0.5, 4e-15);
            }
            Krawczyk::Inconclusive => return None,
        }
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::certify::boxes::test_box as b;
    use crate::num::{Interval, IntervalLike, Real};

    /// One linear piece `F(x, y) = (a·x + y − c, x − 2y)` of a map whose first
    /// equation changes slope at `x = 0` (`a` is 1 on the left, 3 on the right): with
    /// `c = 0` the root is `(0, 0)`, exactly on the cut.
    #[derive(Clone, Copy)]
    struct Piece {
        a: f64,
        c: f64,
    }

    impl System for Piece {
        fn dim(&self) -> usize {
            2
        }
        fn eval<T: Real>(&self, x: &[T]) -> Vec<T> {
            vec![
                x[0].clone() * &x[0].lift(self.a) + &x[1] - x[0].lift(self.c),
                x[0].clone() - &(x[1].clone() * &x[1].lift(2.0)),
            ]
        }
    }

    /// The parts of `x` on each side of `x₀ = 0` (the map is continuous there when
    /// both pieces share `c`).
    fn halves(left: Piece, right: Piece, x: &[Interval]) -> Vec<(Piece, Vec<Interval>)> {
        let mut out = Vec::new();
        for (p, (lo, hi)) in [
            (left, (f64::NEG_INFINITY, 0.0)),
            (right, (0.0, f64::INFINITY)),
        ] {
            let xi = x[0].intersection(&Interval::from_bounds(lo, hi));
            if !xi.is_empty() {
                out.push((p, vec![xi, x[1]]));
            }
        }
        out
    }

    #[test]
    fn a_root_on_the_cut_is_proven_across_it() {
        let (l, r) = (Piece { a: 1.0, c: 0.0 }, Piece { a: 3.0, c: 0.0 });
        let parts_of = |x: &[Interval]| halves(l, r, x);
        let start = b(&[(-0.01, 0.02), (-0.01, 0.01)]);
        let (region, e) = verify_in_parts(&parts_of, &start, 6).expect("proven");
        assert!(boxes::is_subset(&e, &region));
        assert!(e[0].contains(0.0) && e[1].contains(0.0));
        assert!(e.iter().all(|v| v.wid() < 1e-12), "{e:?}");
    }

    #[test]
    fn a_root_off_the_cut_is_found_on_its_side() {
        // c = 0.3: left root where x + y = 0.3, x = 2y → x = 0.2 > 0: not a root of the
        // left piece's side; the right piece's root 3x + y = 0.3, x = 2y → x = 3/35.
        let (l, r) = (Piece { a: 1.0, c: 0.3 }, Piece { a: 3.0, c: 0.3 });
        let parts_of = |x: &[Interval]| halves(l, r, x);
        let start = b(&[(-0.05, 0.2), (-0.05, 0.1)]);
        let (_, e) = verify_in_parts(&parts_of, &start, 8).expect("proven");
        assert!(e[0].contains(0.3 / 3.5) && e[0].wid() < 1e-12, "{e:?}");
    }

    #[test]
    fn parts_that_do_not_cover_prove_nothing() {
        let none = |_: &[Interval]| Vec::<(Piece, Vec<Interval>)>::new();
        let start = b(&[(-0.01, 0.02), (-0.01, 0.01)]);
        assert!(verify_in_parts(&none, &start, 6).is_none());
    }
}
