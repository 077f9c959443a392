//! B-spline knot vectors and basis functions (OPERATIONS.md §1.5, [Y 2.8.13–2.8.14,
//! 2.9.2–2.9.6]): validation with typed errors, span search, the basis by the
//! Cox–de Boor recursion (1.11) and its derivatives by (1.12), and de Boor's
//! recursion for points. Degree `p` = order `m − 1`; 0-based knots `u₀ … u_{n+p}` for
//! `n` control points; domain `[u_p, u_n]`.
//!
//! The generic evaluators take the span and the parameter in any [`Real`]; every
//! denominator is a difference of two knots computed in that number system (never
//! `(u − t) + (t − u)`), so interval evaluation does not lose a denominator to
//! dependency, and on a non-empty span no denominator is zero.

use crate::error::{require_finite_all, GeomError};
use crate::num::Real;

/// A validated knot vector of a degree-`p` B-spline with `n` control points, with
/// its non-empty spans inside the domain.
#[derive(Debug, Clone, PartialEq)]
pub struct KnotVector {
    knots: Vec<f64>,
    degree: usize,
    /// The distinct knot values in `[u_p, u_n]` (the piece boundaries).
    breaks: Vec<f64>,
    /// `spans[i]`: the index `s` with `u_s = breaks[i] < u_{s+1}`.
    spans: Vec<usize>,
}

impl KnotVector {
    /// Errors (fields relative to the curve): `invalid_value` (`degree`) for degree 0;
    /// `count_mismatch` (`points`) for fewer than `p + 1` points, (`knots`) unless there
    /// are `n + p + 1` knots; `non_finite` (`knots[i]`); `invalid_knots` (`knots[i]`) for
    /// a decreasing knot, a multiplicity above `p + 1`, or a multiplicity above `p` inside
    /// the domain (the curve would be discontinuous there); `empty_domain` (`knots`) when
    /// `u_p = u_n`.
    pub fn new(knots: Vec<f64>, degree: usize, n_points: usize) -> Result<KnotVector, GeomError> {
        if degree == 0 {
            return Err(GeomError::InvalidValue {
                field: "degree".into(),
                reason: "the degree must be at least 1".into(),
            });
        }
        if n_points <= degree {
            return Err(GeomError::CountMismatch {
                field: "points".into(),
                expected: format!(
                    "at least degree + 1 = {} control points",
                    degree.saturating_add(1)
                ),
                found: format!("{n_points}"),
            });
        }
        let expected = n_points + degree + 1; // no overflow: degree < n_points
        if knots.len() != expected {
            return Err(GeomError::CountMismatch {
                field: "knots".into(),
                expected: format!("{expected} knots (points + degree + 1)"),
                found: format!("{}", knots.len()),
            });
        }
        require_finite_all("knots", &knots)?;
        let (lo, hi) = (knots[degree], knots[n_points]);
        let mut run = 1;
        for i in 1..knots.len() {
            if knots[i] < knots[i - 1] {
                return Err(GeomError::InvalidKnots {
                    field: format!("knots[{i}]"),
                    reason: format!(
                        "{} is less than the previous knot {}",
                        knots[i],
                        knots[i - 1]
                    ),
                });
            }
            run = if knots[i] == knots[i - 1] { run + 1 } else { 1 };
            let interior = lo < knots[i] && knots[i] < hi;
            let limit = if interior { degree } else { degree + 1 };
            if run > limit {
                return Err(GeomError::InvalidKnots {
                    field: format!("knots[{i}]"),
                    reason: format!(
                        "knot {} has multiplicity {run}, above {limit}{}",
                        knots[i],
                        if interior {
                            " (the degree; the curve would be discontinuous there)"
                        } else {
                            " (degree + 1)"
                        }
                    ),
                });
            }
        }
        if lo >= hi {
            return Err(GeomError::EmptyDomain {
                field: "knots".into(),
                lo: format!("{lo}"),
                hi: format!("{hi}"),
            });
        }
        let mut breaks = Vec::new();
        let mut spans = Vec::new();
        for s in degree..n_points {
            if knots[s] < knots[s + 1] {
                breaks.push(knots[s]);
                spans.push(s);
            }
        }
        breaks.push(hi);
        Ok(KnotVector {
            knots,
            degree,
            breaks,
            spans,
        })
    }

    pub fn knots(&self) -> &[f64] {
        &self.knots
    }
    pub fn degree(&self) -> usize {
        self.degree
    }
    /// `[u_p, u_n]`.
    pub fn domain(&self) -> (f64, f64) {
        (self.breaks[0], self.breaks[self.breaks.len() - 1])
    }
    /// The distinct knots of the domain, `u_p … u_n`.
    pub fn breaks(&self) -> &[f64] {
        &self.breaks
    }
    /// The knot span index of piece `i` (see [`KnotVector::breaks`]).
    pub fn span_of_piece(&self, i: usize) -> usize {
        self.spans[i]
    }
    /// The span `s` with `u_s ≤ t < u_{s+1}` (the last non-empty span at `t = u_n`,
    /// the first or last below or above the domain).
    pub fn find_span(&self, t: f64) -> usize {
        let n = self.breaks.partition_point(|&b| b <= t);
        self.spans[n.saturating_sub(1).min(self.spans.len() - 1)]
    }
    /// The `[u_s, u_{s+1}]` of the piece containing `t` (as [`KnotVector::find_span`]).
    pub fn span_interval(&self, t: f64) -> (f64, f64) {
        let s = self.find_span(t);
        (self.knots[s], self.knots[s + 1])
    }

    /// The derivatives `dᵏ/dtᵏ N_{j,p}(t)`, `k = 0..=order`, of the `p + 1` basis
    /// functions `j = s−p … s` that can be non-zero on span `s`: `out[k][j − (s−p)]`.
    ///
    /// (1.11) on the span, level by level (`N_{j,0} = 1` for `j = s` only), then (1.12)
    /// applied `k` times upward from the degree-`(p−k)` level:
    /// `dᵏN_{j,d} = d·(dᵏ⁻¹N_{j,d−1}/(u_{j+d}−u_j) − dᵏ⁻¹N_{j+1,d−1}/(u_{j+d+1}−u_{j+1}))`.
    /// Terms of functions that vanish on the span are skipped (`0/0 := 0`); the others
    /// have denominators `≥ u_{s+1} − u_s > 0`.
    pub fn basis_derivatives<T: Real>(&self, s: usize, t: &T, order: usize) -> Vec<Vec<T>> {
        let flat = self.basis_derivatives_flat(s, t, order);
        flat.chunks(self.degree + 1).map(<[T]>::to_vec).collect()
    }

    /// [`KnotVector::basis_derivatives`] in one buffer: entry `k(p+1) + j − (s−p)`
    /// (the evaluator's form: one allocation besides two scratch rows).
    pub fn basis_derivatives_flat<T: Real>(&self, s: usize, t: &T, order: usize) -> Vec<T> {
        let p = self.degree;
        let u = |i: usize| t.lift(self.knots[i]);
        // Level d of (1.11), N_{j,d} for j = s−d ..= s, at offset d(d+1)/2 + j − (s−d).
        let offset = |d: usize| d * (d + 1) / 2;
        let mut table: Vec<T> = Vec::with_capacity(offset(p + 1));
        table.push(t.one_like());
        for d in 1..=p {
            let prev = offset(d - 1);
            for j in s - d..=s {
                let mut v = t.zero_like();
                if j + d > s {
                    // N_{j,d−1} lives on the span (j ≥ s−d+1).
                    let n0 = &table[prev + j + d - 1 - s];
                    v = v + (t.clone() - u(j)) / (u(j + d) - u(j)) * n0;
                }
                if j < s {
                    let n1 = &table[prev + j + d - s];
                    v = v + (u(j + d + 1) - t.clone()) / (u(j + d + 1) - u(j + 1)) * n1;
                }
                table.push(v);
            }
        }
        let mut out = Vec::with_capacity((order + 1) * (p + 1));
        let (mut cur, mut next): (Vec<T>, Vec<T>) =
            (Vec::with_capacity(p + 1), Vec::with_capacity(p + 1));
        for k in 0..=order {
            if k > p {
                out.extend(std::iter::repeat_with(|| t.zero_like()).take(p + 1));
                continue;
            }
            // (1.12) k times upward from level p − k.
            cur.clear();
            cur.extend_from_slice(&table[offset(p - k)..offset(p - k + 1)]);
            for d in p - k + 1..=p {
                next.clear();
                let scale = t.lift(d as f64);
                for j in s - d..=s {
                    let mut v = t.zero_like();
                    if j + d > s {
                        v = v + cur[j + d - 1 - s].clone() / (u(j + d) - u(j));
                    }
                    if j < s {
                        v = v - cur[j + d - s].clone() / (u(j + d + 1) - u(j + 1));
                    }
                    next.push(v * &scale);
                }
                std::mem::swap(&mut cur, &mut next);
            }
            out.extend_from_slice(&cur);
        }
        out
    }

    /// de Boor's recursion [Y 2.9.5]–[Y 2.9.6] for the point of span `s`: `rows[j]` are
    /// the (homogeneous) control points `j = s−p … s`, each with any number of
    /// components; the result is the point's components.
    pub fn de_boor<T: Real>(&self, s: usize, t: &T, rows: Vec<Vec<T>>) -> Vec<T> {
        let xs = vec![t.clone(); self.degree];
        blossom(&self.knots, self.degree, s, &xs, rows)
    }
}

/// The blossom (polar form) `f(x₁, …, x_p)` of the degree-`p` polynomial piece on span
/// `s` of `knots`, with `rows[j]` the (homogeneous) control points `j = s−p … s`: de
/// Boor's recursion [Y 2.9.5]–[Y 2.9.6] with the parameter `x_r` at level `r`. All `x_r`
/// equal to `t` give the point at `t`; `f(a^{p−k}, b^k)`, `k = 0..=p`, are the Bézier
/// control points of the piece on `[a, b]` (Ramshaw's blossoming principle). A Bézier
/// curve of degree `p` is the span `s = p` of the knots `0^{p+1} 1^{p+1}` (then the
/// recursion is de Casteljau's).
pub(crate) fn blossom<T: Real>(
    knots: &[f64],
    p: usize,
    s: usize,
    xs: &[T],
    mut rows: Vec<Vec<T>>,
) -> Vec<T> {
    for r in 1..=p {
        let x = &xs[r - 1];
        let u = |i: usize| x.lift(knots[i]);
        for j in (s - p + r..=s).rev() {
            let i = j - (s - p);
            let alpha = (x.clone() - u(j)) / (u(j + p + 1 - r) - u(j));
            let beta = x.one_like() - &alpha;
            let new: Vec<T> = rows[i]
                .iter()
                .zip(&rows[i - 1])
                .map(|(a, b)| alpha.clone() * a + beta.clone() * b)
                .collect();
            rows[i] = new;
        }
    }
    rows.swap_remove(p)
}

/// The basis function `N_{i,m}(t)` of order `m` by the literal recursion (1.11),
/// `0/0 := 0`, with the half-open spans `u_i ≤ t < u_{i+1}`. A reference for tests.
pub fn cox_de_boor(knots: &[f64], i: usize, m: usize, t: f64) -> f64 {
    if m == 1 {
        return if knots[i] <= t && t < knots[i + 1] {
            1.0
        } else {
            0.0
        };
    }
    let ratio = |num: f64, den: f64| if den == 0.0 { 0.0 } else { num / den };
    ratio(t - knots[i], knots[i + m - 1] - knots[i]) * cox_de_boor(knots, i, m - 1, t)
        + ratio(knots[i + m] - t, knots[i + m] - knots[i + 1]) * cox_de_boor(knots, i + 1, m - 1, t)
}

/// `N'_{i,m}(t)` by (1.12): `(m−1)[N_{i,m−1}/(u_{i+m−1}−u_i) − N_{i+1,m−1}/(u_{i+m}−u_{i+1})]`.
pub fn cox_de_boor_derivative(knots: &[f64], i: usize, m: usize, t: f64) -> f64 {
    if m == 1 {
        return 0.0;
    }
    let ratio = |num: f64, den: f64| if den == 0.0 { 0.0 } else { num / den };
    (m - 1) as f64
        * (ratio(cox_de_boor(knots, i, m - 1, t), knots[i + m - 1] - knots[i])
            - ratio(
                cox_de_boor(knots, i + 1, m - 1, t),
                knots[i + m] - knots[i + 1],
            ))
}
