//! B-spline and NURBS curves (OPERATIONS.md §1.5 "NURBS" [Y 2.9.1]):
//! `c(t) = Σ N_{i,p}(t) w_i P_i / Σ N_{i,p}(t) w_i` on `[u_p, u_n]`; all weights 1
//! (or none) is a B-spline curve.
//!
//! Evaluation: the homogeneous numerator `A = Σ N w P` and weight `W = Σ N w` and their
//! derivatives from the basis derivatives (1.11)–(1.12) of [`KnotVector`], then the
//! quotient rule of §1.5. An interval parameter that straddles knots is split into the
//! spans it touches ([`piecewise_jet`]) and the span results joined by hulls. A
//! periodic curve (last `p` control points and weights equal to the first `p`, knot
//! intervals repeating across the seam — what [`NurbsCurve::periodic`] builds, the
//! (impl) closed curve of §1.5) wraps its parameter ([`periodic_jet`]).

use super::bezier::{check_net, finish_jet, homogeneous_rows};
use super::bspline::KnotVector;
use super::domain::{periodic_jet, piecewise_jet, Domain};
use super::rational::quotient_jet;
use super::span_hull;
use super::{Curve, StepHint};
use crate::error::GeomError;
use crate::num::{Interval, Real};
use rug::Rational;

/// A NURBS (or B-spline) curve of degree `p` with `n` control points and `n + p + 1`
/// knots.
#[derive(Debug, Clone, PartialEq)]
pub struct NurbsCurve<const D: usize> {
    knots: KnotVector,
    points: Vec<[f64; D]>,
    weights: Option<Vec<f64>>,
    domain: Domain,
    closed: bool,
    periodic: bool,
    /// [`Curve::pinned_at`]: the piece (of [`KnotVector::breaks`]) whose formula
    /// [`Curve::jet`] evaluates everywhere.
    pin: Option<usize>,
}

impl<const D: usize> NurbsCurve<D> {
    /// Errors: those of [`KnotVector::new`] and of the control net (`points[i][j]`,
    /// `weights`, `weights[i]`), and `empty_domain` / `parameter_outside_domain`
    /// (`domain`) for a sub-domain outside `[u_p, u_n]`.
    pub fn new(
        degree: usize,
        knots: Vec<f64>,
        points: Vec<[f64; D]>,
        weights: Option<Vec<f64>>,
        domain: Option<(f64, f64)>,
    ) -> Result<Self, GeomError> {
        check_net(&points, weights.as_deref())?;
        let knots = KnotVector::new(knots, degree, points.len())?;
        let natural = knots.domain();
        let sub = match domain {
            None => Domain {
                lo: natural.0,
                hi: natural.1,
            },
            Some((a, b)) => {
                let d = Domain::new("domain", a, b)?;
                d.check_inside("domain", natural)?;
                d
            }
        };
        let whole = sub.pair() == natural;
        let periodic = whole && is_periodic_net(&knots, &points, weights.as_deref());
        let closed = whole && (periodic || is_clamped_closed(&knots, &points, weights.as_deref()));
        Ok(NurbsCurve {
            knots,
            points,
            weights,
            domain: sub,
            closed,
            periodic,
            pin: None,
        })
    }

    /// The closed (periodic) curve of §1.5 (impl): the `n` distinct `points` (and
    /// weights), the first `p` of them repeated at the end, uniform knots `0, 1, …,
    /// n + 2p`; domain `[p, n + p]`, closed and periodic. Errors as [`NurbsCurve::new`]
    /// (`points` when `n < p + 1`).
    pub fn periodic(
        degree: usize,
        points: Vec<[f64; D]>,
        weights: Option<Vec<f64>>,
    ) -> Result<Self, GeomError> {
        check_net(&points, weights.as_deref())?;
        if degree == 0 || points.len() <= degree {
            // Let the knot validation name the problem.
            KnotVector::new(vec![], degree, points.len())?;
        }
        let n = points.len();
        let mut wrapped = points.clone();
        wrapped.extend_from_slice(&points[..degree]);
        let weights = weights.map(|w| {
            let mut ww = w.clone();
            ww.extend_from_slice(&w[..degree]);
            ww
        });
        let knots = (0..=(n + 2 * degree)).map(|i| i as f64).collect();
        NurbsCurve::new(degree, knots, wrapped, weights, None)
    }

    pub fn degree(&self) -> usize {
        self.knots.degree()
    }
    pub fn knots(&self) -> &[f64] {
        self.knots.knots()
    }
    pub fn knot_vector(&self) -> &KnotVector {
        &self.knots
    }
    pub fn points(&self) -> &[[f64; D]] {
        &self.points
    }
    pub fn weights(&self) -> Option<&[f64]> {
        self.weights.as_deref()
    }
    /// The sub-domain given at construction, if any.
    pub fn sub_domain(&self) -> Option<(f64, f64)> {
        (self.domain.pair() != self.knots.domain()).then(|| self.domain.pair())
    }

    /// Homogeneous rows `(w P, w)` (or `P`) of the control points `s−p … s`.
    fn rows<T: Real>(&self, s: usize, like: &T) -> Vec<Vec<T>> {
        let p = self.degree();
        let w = self.weights.as_deref().map(|w| &w[s - p..=s]);
        homogeneous_rows(&self.points[s - p..=s], w, like)
    }

    /// The jet on span `s` from the basis derivatives (1.11)–(1.12): the homogeneous
    /// sums `A⁽ᵏ⁾ = Σ N⁽ᵏ⁾ w P`, `W⁽ᵏ⁾ = Σ N⁽ᵏ⁾ w`, then the quotient rule; for an f64
    /// interval parameter, intersected with the hull of the span's Bézier form
    /// ([`span_hull`]).
    fn span_jet<T: Real>(&self, s: usize, t: &T, order: usize) -> Vec<[T; D]> {
        let p = self.degree();
        let basis = self.knots.basis_derivatives_flat(s, t, order);
        let mut numerator: Vec<[T; D]> = vec![std::array::from_fn(|_| t.zero_like()); order + 1];
        let mut weight: Vec<T> = vec![t.zero_like(); order + 1];
        for (j, i) in (s - p..=s).enumerate() {
            let point: [T; D] = std::array::from_fn(|c| t.lift(self.points[i][c]));
            let w = self.weights.as_ref().map(|w| t.lift(w[i]));
            for k in 0..=order {
                let n = &basis[k * (p + 1) + j];
                let nw = match &w {
                    Some(w) => {
                        let nw = n.clone() * w;
                        weight[k] = weight[k].clone() + &nw;
                        nw
                    }
                    None => n.clone(),
                };
                for (acc, x) in numerator[k].iter_mut().zip(&point) {
                    *acc = acc.clone() + nw.clone() * x;
                }
            }
        }
        let jet = if self.weights.is_some() {
            quotient_jet(&numerator, &weight)
        } else {
            numerator
        };
        // Over a wide f64 interval the basis sums are loose: narrow them by the hull of
        // the span's Bézier form (`span_hull`).
        span_hull::meet(jet, t, |ab| {
            let rows = self.rows(s, &Interval::point(0.0));
            span_hull::hull_jet(
                self.knots.knots(),
                p,
                s,
                &rows,
                self.weights.is_some(),
                ab,
                order,
            )
        })
    }

    /// The point by de Boor's recursion [Y 2.9.5]–[Y 2.9.6] (an alternative to the
    /// basis evaluation of [`Curve::jet`], for point evaluation and cross-checks).
    pub fn point_de_boor<T: Real>(&self, t: &T) -> [T; D] {
        let eval = |ti: &T| {
            piecewise_jet(ti, self.knots.breaks(), |i, tp| {
                let s = self.knots.span_of_piece(i);
                let row = self.knots.de_boor(s, tp, self.rows(s, tp));
                finish_jet::<T, D>(vec![row], self.weights.is_some())
            })
        };
        let mut jet = if self.periodic {
            periodic_jet(t, self.domain.pair(), eval)
        } else {
            eval(t)
        };
        jet.swap_remove(0)
    }
}

/// Clamped at both ends (multiplicity `p + 1` at `u_p` and `u_n`) with `P₀ = P_{n−1}`
/// and equal end weights: then `c(t_min) = P₀ = c(t_max)` exactly.
fn is_clamped_closed<const D: usize>(
    knots: &KnotVector,
    points: &[[f64; D]],
    weights: Option<&[f64]>,
) -> bool {
    let (u, p, n) = (knots.knots(), knots.degree(), points.len());
    let clamped = u[..=p].iter().all(|&x| x == u[p]) && u[n..].iter().all(|&x| x == u[n]);
    clamped && points[0] == points[n - 1] && weights.is_none_or(|w| w[0] == w[n - 1])
}

/// The last `p` control points and weights repeat the first `p`, and the knot
/// intervals repeat with period `n − p` (compared exactly): the curve is `C^{p−1}`
/// periodic with period `u_n − u_p`.
fn is_periodic_net<const D: usize>(
    knots: &KnotVector,
    points: &[[f64; D]],
    weights: Option<&[f64]>,
) -> bool {
    let (u, p, n) = (knots.knots(), knots.degree(), points.len());
    let shift = n - p;
    let same_points = (0..p).all(|i| points[i] == points[i + shift]);
    let same_weights = weights.is_none_or(|w| (0..p).all(|i| w[i] == w[i + shift]));
    let q = |x: f64| Rational::from_f64(x).unwrap_or_default();
    let gap = |i: usize| q(u[i + 1]) - q(u[i]);
    let same_gaps = (0..2 * p).all(|i| gap(i) == gap(i + shift));
    shift > 0 && same_points && same_weights && same_gaps
}

impl<const D: usize> Curve<D> for NurbsCurve<D> {
    fn domain(&self) -> (f64, f64) {
        self.domain.pair()
    }
    fn is_closed(&self) -> bool {
        self.closed
    }
    fn is_periodic(&self) -> bool {
        self.periodic
    }
    fn jet<T: Real>(&self, t: &T, order: usize) -> Vec<[T; D]> {
        let order = order.min(3);
        if let Some(i) = self.pin {
            // One span's rational map, valid for every real t (its continuation).
            return self.span_jet(self.knots.span_of_piece(i), t, order);
        }
        let eval = |ti: &T| {
            piecewise_jet(ti, self.knots.breaks(), |i, tp| {
                self.span_jet(self.knots.span_of_piece(i), tp, order)
            })
        };
        // A closed curve wraps its parameter, periodic or only clamped closed (C⁰ at
        // the seam): the certifier treats the parameter of every closed curve as an
        // angle (`ops::certified::curve_unknowns`), which is sound only if the jet
        // beyond the domain is the curve's own, not the end spans' continuation.
        if self.periodic || self.closed {
            periodic_jet(t, self.domain.pair(), eval)
        } else {
            eval(t)
        }
    }
    /// The knots of multiplicity ≥ p inside the domain (C⁰ there); for a periodic
    /// curve those of the closed domain, seam included.
    fn tangent_breaks(&self) -> Vec<(f64, f64)> {
        let (u, p) = (self.knots.knots(), self.degree());
        let (lo, hi) = self.domain.pair();
        let mut out = Vec::new();
        let mut i = 0;
        while i < u.len() {
            let mut j = i;
            while j < u.len() && u[j] == u[i] {
                j += 1;
            }
            let inside = if self.periodic {
                lo <= u[i] && u[i] < hi
            } else {
                lo < u[i] && u[i] < hi
            };
            if inside && j - i >= p {
                out.push((u[i], u[i]));
            }
            i = j;
        }
        out
    }
    /// The distinct knots strictly inside the domain (a pinned curve has none).
    fn piece_breaks(&self) -> Vec<f64> {
        let (lo, hi) = self.domain.pair();
        if self.pin.is_some() {
            return Vec::new();
        }
        let b = self.knots.breaks();
        b.iter().copied().filter(|&k| lo < k && k < hi).collect()
    }
    /// The same curve with `pin` set to the piece holding `t` ([`KnotVector::breaks`]:
    /// piece `i` is `[b_i, b_{i+1}]`), not closed nor periodic any more (the
    /// continuation of one piece does not wrap).
    fn pinned_at(&self, t: f64) -> Option<Self> {
        let b = self.knots.breaks();
        let pieces = b.len().saturating_sub(1).max(1);
        let i = b
            .partition_point(|&k| k <= t)
            .saturating_sub(1)
            .min(pieces - 1);
        Some(NurbsCurve {
            pin: Some(i),
            closed: false,
            periodic: false,
            ..self.clone()
        })
    }
    /// (2.1) with the B-spline clamp of §2.1: at most ½ of the current knot span.
    fn step_hint(&self, t: f64) -> StepHint {
        let (a, b) = self.knots.span_interval(t);
        StepHint::Adaptive {
            max_step: Some(0.5 * (b - a)),
        }
    }
}
