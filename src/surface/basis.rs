//! Bernstein and B-spline basis functions with their derivatives, generic over
//! [`Arith`] (every [`crate::num::Real`], and the midpoint–radius enclosures of the fast
//! surface path) (OPERATIONS.md §1.5 (2.5), (1.11)–(1.12); §1.6 (1.18)).
//!
//! Interval soundness: on one knot span every basis function is a polynomial, and the
//! recursions below evaluate it (and its derivatives) by enclosing operations, with every
//! knot difference formed from the exact knots in the number type. An interval parameter
//! that straddles knots is evaluated on every span it touches and the results are joined
//! with [`super::sets::hull`] (see [`spans_touching`]). Outside the domain the first / last
//! polynomial piece is continued.

use crate::num::real::Arith;

/// The values and derivatives of the `degree + 1` basis functions that are non-zero on
/// one span: `get(k, j)` is the `k`-th derivative of the `j`-th of them (for B-splines,
/// of `N_{span−degree+j, degree}`; for Bernstein, of `B_{j, degree}`).
#[derive(Debug, Clone)]
pub struct BasisJet<T> {
    pub degree: usize,
    values: Vec<T>,
}

impl<T> BasisJet<T> {
    /// The `k`-th derivative of the `j`-th non-zero function.
    #[inline]
    pub fn get(&self, k: usize, j: usize) -> &T {
        &self.values[k * (self.degree + 1) + j]
    }
    /// The highest derivative held.
    pub fn order(&self) -> usize {
        self.values.len() / (self.degree + 1) - 1
    }
}

/// Index of the first entry of triangle row `d` (rows of length `d + 1`).
#[inline]
fn row(d: usize) -> usize {
    d * (d + 1) / 2
}

/// The derivatives of the degree-`degree` functions from the triangle of all lower
/// degrees: the `k`-th derivative comes from row `degree − k` by applying `k` times the
/// derivative rule (1.12) `D N_{i,m} = β_{i,m} N_{i,m−1} − β_{i+1,m} N_{i+1,m−1}`, with
/// `beta(m, j)` the coefficient of the `j`-th function of row `m − 1`
/// (`β_{i,m} = m/(t_{i+m} − t_i)`, `m` for Bernstein). The rule is applied in place,
/// from the right, so one buffer serves every step.
fn derivatives<T: Arith>(
    mut buf: Vec<T>,
    degree: usize,
    order: usize,
    beta: impl Fn(usize, usize) -> T,
) -> Vec<T> {
    let p = degree;
    let tri_len = row(p + 1);
    debug_assert_eq!(buf.len(), tri_len);
    buf.extend_from_within(row(p)..row(p) + p + 1);
    for k in 1..=order.min(p) {
        let start = p - k;
        let tail = buf.len();
        buf.extend_from_within(row(start)..row(start) + start + 1);
        for m in start + 1..=p {
            // c = buf[tail..] holds m functions of degree m − 1; make it the m + 1 of
            // degree m: c[j] ← β(m, j−1)·c[j−1] − β(m, j)·c[j], from j = m down to 0 (each
            // step reads only entries not yet overwritten; β(m, j) is reused from the
            // step before).
            buf.push(buf[tail].lift(0.0));
            let c = &mut buf[tail..];
            let mut beta_j: Option<T> = None;
            for j in (0..=m).rev() {
                let right = beta_j.take().map(|b| b * &c[j]);
                let left = (j >= 1).then(|| {
                    let b = beta(m, j - 1);
                    let term = b.clone() * &c[j - 1];
                    beta_j = Some(b);
                    term
                });
                c[j] = match (left, right) {
                    (Some(l), Some(r)) => l - r,
                    (Some(l), None) => l,
                    (None, Some(r)) => -r,
                    (None, None) => unreachable!("m ≥ 1"),
                };
            }
        }
    }
    let zero = buf[0].lift(0.0);
    buf.resize(tri_len + (order + 1) * (p + 1), zero);
    buf.drain(..tri_len);
    buf
}

/// The Bernstein polynomials `B_{j,n}(t)` (2.5) and their derivatives up to `order`.
pub fn bernstein_jet<T: Arith>(n: usize, t: &T, order: usize) -> BasisJet<T> {
    let one = t.lift(1.0);
    let s = one.clone() - t;
    let mut tri = Vec::with_capacity(row(n + 1) + (order + 2) * (n + 1));
    tri.push(one);
    for d in 1..=n {
        let prev = row(d - 1);
        for j in 0..=d {
            // B_{j,d} = (1−t) B_{j,d−1} + t B_{j−1,d−1}
            let a = (j < d).then(|| s.clone() * &tri[prev + j]);
            let b = (j >= 1).then(|| t.clone() * &tri[prev + j - 1]);
            let v = match (a, b) {
                (Some(a), Some(b)) => a + b,
                (Some(a), None) => a,
                (None, Some(b)) => b,
                (None, None) => unreachable!("d ≥ 1"),
            };
            tri.push(v);
        }
    }
    let values = derivatives(tri, n, order, |m, _| t.lift(m as f64));
    BasisJet { degree: n, values }
}

/// The B-spline basis (1.11) of degree `p` on the non-empty span `span`
/// (`knots[span] < knots[span + 1]`, `p ≤ span`, `span + p + 1 < knots.len()`), and its
/// derivatives (1.12) up to `order`: the functions `N_{span−p+j, p}`, `j = 0..=p`.
///
/// Every denominator is a difference of two knots around the span, never zero there.
pub fn bspline_jet<T: Arith>(
    knots: &[f64],
    p: usize,
    span: usize,
    t: &T,
    order: usize,
) -> BasisJet<T> {
    let knot = |i: usize| t.lift(knots[i]);
    // α_{i,d} = (t − t_i)/(t_{i+d} − t_i) for i = span−d+1 ..= span.
    let alpha = |i: usize, d: usize| (t.clone() - knot(i)) / (knot(i + d) - knot(i));
    let mut tri = Vec::with_capacity(row(p + 1) + (order + 2) * (p + 1));
    tri.push(t.lift(1.0));
    for d in 1..=p {
        let prev = row(d - 1);
        let first = span + 1 - d; // the i of α for j = 1
                                  // The α of step j is the α_{i+1} of step j − 1.
        let mut alpha_i: Option<T> = None;
        for j in 0..=d {
            // N_{i,d} = α_{i,d} N_{i,d−1} + (1 − α_{i+1,d}) N_{i+1,d−1}, i = span−d+j.
            let a = alpha_i.take().map(|al| al * &tri[prev + j - 1]);
            let b = (j < d).then(|| {
                let al = alpha(first + j, d);
                let term = (t.lift(1.0) - &al) * &tri[prev + j];
                alpha_i = Some(al);
                term
            });
            let v = match (a, b) {
                (Some(a), Some(b)) => a + b,
                (Some(a), None) => a,
                (None, Some(b)) => b,
                (None, None) => unreachable!("d ≥ 1"),
            };
            tri.push(v);
        }
    }
    // β_{i,m} = m/(t_{i+m} − t_i) for the j-th function of row m − 1, i = span−m+1+j.
    let beta = |m: usize, j: usize| {
        let i = span + 1 + j - m;
        t.lift(m as f64) / (knot(i + m) - knot(i))
    };
    let values = derivatives(tri, p, order, beta);
    BasisJet { degree: p, values }
}

/// The span `s ∈ [p, n−1]` with `knots[s] ≤ t < knots[s+1]` for `n` control points;
/// `t` below the domain gives the first span and `t ≥ knots[n]` the last non-empty one
/// (§1.5: "at `t = t_max` use the last non-empty span").
pub fn find_span(knots: &[f64], p: usize, n: usize, t: f64) -> usize {
    let mut last = n - 1;
    while last > p && knots[last] == knots[last + 1] {
        last -= 1;
    }
    if t >= knots[last + 1] {
        return last;
    }
    if t.is_nan() || t < knots[p] {
        let mut s = p;
        while knots[s] == knots[s + 1] {
            s += 1;
        }
        return s;
    }
    // knots[lo] ≤ t < knots[hi]
    let (mut lo, mut hi) = (p, last + 1);
    while hi - lo > 1 {
        let mid = (lo + hi) / 2;
        if t < knots[mid] {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    lo
}

/// The first and last spans whose polynomial pieces define the function at some point
/// of `[lo, hi]` under the right-continuous convention of [`find_span`] (the empty spans
/// between them are to be skipped).
pub fn spans_touching(knots: &[f64], p: usize, n: usize, (lo, hi): (f64, f64)) -> (usize, usize) {
    let a = find_span(knots, p, n, lo);
    if lo == hi {
        return (a, a);
    }
    (a, find_span(knots, p, n, hi))
}
