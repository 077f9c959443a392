//! Composite curves (OPERATIONS.md §1.5 "Derived curves", [Y 2.11.2–2.11.3]): pieces
//! `k = 0..n−1` joined end to end under one global parameter `t ∈ [0, Σ Δ_k]`,
//! `Δ_k = t_max,k − t_min,k`; piece `k` covers `[B_k, B_{k+1}]`, `B_k = Σ_{j<k} Δ_j`,
//! with the local parameter `t_min,k + (t − B_k)`.
//!
//! Exactness: the constructor checks in rationals that every `Δ_k` and every `B_k` is
//! a double, so the joints are exact and the local parameter, evaluated in the number
//! system of `t`, encloses the exact one. An interval parameter that straddles a joint
//! is split there and the pieces' jets are hulled ([`piecewise_jet`]), so the jet
//! encloses the values (and the one-sided derivatives) over the whole interval. At a
//! joint a point parameter (f64) evaluates the later piece (§1.5 takes the earlier
//! one; the points agree, checked at construction, only derivatives may differ).
//!
//! The joints are [`Curve::piece_breaks`] and [`Curve::tangent_breaks`], so the
//! certifier solves piece by piece as it does across NURBS knots.

use super::derived::{q, round_down, round_up};
use super::domain::{periodic_jet, piecewise_jet};
use super::{is_angle_bound, Curve, StepHint};
use crate::error::GeomError;
use crate::num::Real;
use rug::Rational;

/// Pieces joined end to end under the global parameter of §1.5.
#[derive(Debug, Clone, PartialEq)]
pub struct Composite<C> {
    pieces: Vec<C>,
    /// `B_0 = 0, B_1, …, B_n`: the global start of each piece and the total length.
    breaks: Vec<f64>,
    closed: bool,
    /// `Some(k)`: the continuation of piece `k` alone ([`Curve::pinned_at`]).
    pin: Option<usize>,
}

/// `(x₀, …)` for error messages.
fn show<const D: usize>(p: &[f64; D]) -> String {
    let parts: Vec<String> = p.iter().map(|x| format!("{x}")).collect();
    format!("({})", parts.join(", "))
}

/// The double equal to `x`, if there is one.
fn exact_double(x: &Rational) -> Option<f64> {
    let d = x.to_f64();
    (d.is_finite() && q(d) == *x).then_some(d)
}

impl<C> Composite<C> {
    /// Join `pieces` end to end. Errors: `invalid_value` (`pieces`) when empty;
    /// `unsupported` (`pieces[k]`) for an unbounded piece, (`pieces[k].domain`) when a
    /// parameter length `Δ_k` or a joint `B_k` (or a piece's own knot, moved to the
    /// global parameter) is not a double; `invalid_value` (`pieces[k]`) when the end of
    /// piece `k` is not exactly (in f64) the start of piece `k + 1`.
    pub fn new<const D: usize>(pieces: Vec<C>) -> Result<Self, GeomError>
    where
        C: Curve<D>,
    {
        if pieces.is_empty() {
            return Err(GeomError::InvalidValue {
                field: "pieces".into(),
                reason: "a composite curve needs at least one piece".into(),
            });
        }
        let mut breaks = vec![0.0];
        let mut sum = Rational::new();
        for (k, piece) in pieces.iter().enumerate() {
            let (lo, hi) = piece.domain();
            if !(lo.is_finite() && hi.is_finite()) {
                return Err(GeomError::Unsupported {
                    field: format!("pieces[{k}]"),
                    reason: "a piece of a composite curve must be bounded".into(),
                });
            }
            let not_double = |what: String| GeomError::Unsupported {
                field: format!("pieces[{k}].domain"),
                reason: format!("{what} is not a double; reparametrise the piece"),
            };
            for b in piece.piece_breaks() {
                let g = sum.clone() + q(b) - q(lo);
                exact_double(&g).ok_or_else(|| not_double(format!("the joint at t = {b}")))?;
            }
            sum += q(hi) - q(lo);
            let end = exact_double(&sum)
                .ok_or_else(|| not_double(format!("the global parameter {}", sum.to_f64())))?;
            exact_double(&(q(hi) - q(lo)))
                .ok_or_else(|| not_double(format!("the length {hi} − {lo}")))?;
            breaks.push(end);
        }
        for k in 0..pieces.len() - 1 {
            let end = pieces[k].point(&pieces[k].domain().1);
            let start = pieces[k + 1].point(&pieces[k + 1].domain().0);
            if end != start {
                return Err(GeomError::InvalidValue {
                    field: format!("pieces[{k}]"),
                    reason: format!(
                        "ends at {} but pieces[{}] starts at {}: the pieces must meet exactly",
                        show(&end),
                        k + 1,
                        show(&start)
                    ),
                });
            }
        }
        let (first, last) = (&pieces[0], &pieces[pieces.len() - 1]);
        let closed = last.point(&last.domain().1) == first.point(&first.domain().0);
        Ok(Composite {
            pieces,
            breaks,
            closed,
            pin: None,
        })
    }

    /// The pieces, in order.
    pub fn pieces(&self) -> &[C] {
        &self.pieces
    }

    /// The piece containing the global parameter `t` (the later one at a joint).
    fn piece_of(&self, t: f64) -> usize {
        let n = self.breaks.partition_point(|&b| b <= t);
        n.saturating_sub(1).min(self.pieces.len() - 1)
    }
}

impl<C> Composite<C> {
    /// The local parameter `t_min,k + (t − B_k)` of piece `k`, in f64.
    fn local_of<const D: usize>(&self, k: usize, t: f64) -> f64
    where
        C: Curve<D>,
    {
        self.pieces[k].domain().0 + (t - self.breaks[k])
    }

    /// The jet of piece `k` at the global `t`; `restrict` keeps the local parameter
    /// inside the piece at its inner joints (every real `t` of the piece maps there).
    fn piece_jet<T: Real, const D: usize>(
        &self,
        k: usize,
        t: &T,
        order: usize,
        restrict: bool,
    ) -> Vec<[T; D]>
    where
        C: Curve<D>,
    {
        let (lo, hi) = self.pieces[k].domain();
        let mut local = t.lift(lo) + (t.clone() - t.lift(self.breaks[k]));
        if restrict {
            let below = if k == 0 { f64::NEG_INFINITY } else { lo };
            let above = if k + 1 == self.pieces.len() {
                f64::INFINITY
            } else {
                hi
            };
            local = local.restrict_to(below, above);
        }
        self.pieces[k].jet(&local, order)
    }
}

impl<const D: usize, C: Curve<D> + Clone> Curve<D> for Composite<C> {
    fn domain(&self) -> (f64, f64) {
        (0.0, self.breaks[self.breaks.len() - 1])
    }
    fn is_closed(&self) -> bool {
        self.closed
    }
    /// The first or last piece's domain stands for an irrational end (or the total does).
    fn domain_rounded(&self) -> bool {
        let (first, last) = (&self.pieces[0], &self.pieces[self.pieces.len() - 1]);
        first.domain_rounded() || last.domain_rounded() || is_angle_bound(self.domain().1)
    }
    fn jet<T: Real>(&self, t: &T, order: usize) -> Vec<[T; D]> {
        if let Some(k) = self.pin {
            return self.piece_jet(k, t, order, false);
        }
        let eval =
            |tw: &T| piecewise_jet(tw, &self.breaks, |k, tk| self.piece_jet(k, tk, order, true));
        // A closed curve wraps its parameter (see `NurbsCurve::jet`).
        if self.closed {
            periodic_jet(t, self.domain(), eval)
        } else {
            eval(t)
        }
    }
    /// The inner joints, and the pieces' own breaks moved to the global parameter
    /// (exactly in rationals, rounded outward).
    fn tangent_breaks(&self) -> Vec<(f64, f64)> {
        let n = self.pieces.len();
        let mut out: Vec<(f64, f64)> = self.breaks[1..n].iter().map(|&b| (b, b)).collect();
        for (k, piece) in self.pieces.iter().enumerate() {
            let lo = piece.domain().0;
            for (a, b) in piece.tangent_breaks() {
                let [ga, gb] = [a, b].map(|x| q(self.breaks[k]) + q(x) - q(lo));
                let (ga, gb) = (round_down(&ga), round_up(&gb));
                if self.breaks[k] <= gb && ga <= self.breaks[k + 1] {
                    out.push((ga.max(self.breaks[k]), gb.min(self.breaks[k + 1])));
                }
            }
        }
        out.retain(|&(a, b)| 0.0 < b && a < self.breaks[n]);
        out.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.total_cmp(&b.1)));
        out.dedup();
        out
    }
    /// The inner joints and the pieces' own breaks (exact doubles, checked by
    /// [`Composite::new`]).
    fn piece_breaks(&self) -> Vec<f64> {
        if self.pin.is_some() {
            return Vec::new();
        }
        let n = self.pieces.len();
        let mut out: Vec<f64> = self.breaks[1..n].to_vec();
        for (k, piece) in self.pieces.iter().enumerate() {
            let lo = piece.domain().0;
            for b in piece.piece_breaks() {
                let g = q(self.breaks[k]) + q(b) - q(lo);
                out.push(g.to_f64());
            }
        }
        out.sort_by(f64::total_cmp);
        out.dedup();
        out
    }
    /// Piece `k` containing `t` alone (itself pinned when it has pieces), continued
    /// beyond its joints by its own formula.
    fn pinned_at(&self, t: f64) -> Option<Self> {
        let k = self.piece_of(t);
        let mut out = self.clone();
        if let Some(inner) = self.pieces[k].pinned_at(self.local_of(k, t)) {
            out.pieces[k] = inner;
        }
        out.pin = Some(k);
        Some(out)
    }
    /// The piece's rule at its local parameter; "one step covers the whole domain"
    /// becomes one step per piece.
    fn step_hint(&self, t: f64) -> StepHint {
        let k = self.piece_of(t);
        match self.pieces[k].step_hint(self.local_of(k, t)) {
            StepHint::Whole => StepHint::Adaptive {
                max_step: Some(self.breaks[k + 1] - self.breaks[k]),
            },
            hint => hint,
        }
    }
}
