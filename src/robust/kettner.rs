//! The near-collinear orientation grid of Kettner, Mehlhorn, Pion, Schirra and Yap,
//! "Classroom examples of robustness problems in geometric computations" (CGTA 40,
//! 2008), §4: `p = (0.5 + i·2⁻⁵³, 0.5 + j·2⁻⁵³)`, `i, j ∈ [0, 256)`, `q = (12, 12)`,
//! `r = (24, 24)`; the orientation of `(p, q, r)` decided by each method against the
//! exact sign. (The doubles in [0.5, 1) are 2⁻⁵³ apart, so `0.5 + i·2⁻⁵³` is exact.)

use std::cmp::Ordering;

use super::case::q;
use crate::certificate::Arithmetic;
use crate::geom::lines2::{intersect_line2_line2, Empty2, Intersection2};
use crate::geom::{Line2, Linear2, Segment2};

/// The grid's side.
pub const SIDE: usize = 256;
pub const Q: [f64; 2] = [12.0, 12.0];
pub const R: [f64; 2] = [24.0, 24.0];

/// Point `(i, j)` of the grid.
pub fn point(i: usize, j: usize) -> [f64; 2] {
    let h = 2f64.powi(-53);
    [0.5 + i as f64 * h, 0.5 + j as f64 * h]
}

/// The exact orientation of `(p, q, r)`: the sign of `(q − p) × (r − p)`.
pub fn exact(p: [f64; 2], q_: [f64; 2], r: [f64; 2]) -> Ordering {
    let (px, py) = (q(p[0]), q(p[1]));
    let a = (q(q_[0]) - &px) * (q(r[1]) - &py);
    let b = (q(q_[1]) - py) * (q(r[0]) - px);
    (a - b).cmp0()
}

/// The classroom orientation in plain doubles: `(q_x − p_x)(r_y − p_y) − (q_y − p_y)(r_x − p_x)`.
pub fn plain(p: [f64; 2], q: [f64; 2], r: [f64; 2]) -> Ordering {
    let d = (q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0]);
    d.partial_cmp(&0.0).unwrap_or(Ordering::Equal)
}

/// The orientation decided by geocert's certified 2D intersection: the segment `qr`
/// against the line through `p` along an axis `e` not parallel to `qr`. geocert's
/// exact verdict and correctly rounded `t₂` (its sign is exact) give
/// `t₂ = ((p − q) × (r − q))/Δ` with `Δ = (r − q) × e` (OPERATIONS.md §6.1 eq. (6.1)),
/// and `orient(p, q, r) = −(p − q) × (r − q)`, so the orientation is `−sign(t₂)·sign(Δ)`.
/// With `e = (1, 0)`, `Δ = q_y − r_y`; with `e = (0, 1)` (when `q_y = r_y`),
/// `Δ = r_x − q_x`; both signs are comparisons of doubles. Also returns the arithmetic
/// that decided it. `None` when `q = r`.
pub fn certified(p: [f64; 2], q: [f64; 2], r: [f64; 2]) -> Option<(Ordering, Arithmetic)> {
    let (e, delta) = if q[1] != r[1] {
        ([1.0, 0.0], q[1].partial_cmp(&r[1])?)
    } else {
        ([0.0, 1.0], r[0].partial_cmp(&q[0])?)
    };
    let s = Segment2::new(q.into(), r.into()).ok()?;
    let l = Line2::new(p.into(), e.into()).ok()?;
    let c = intersect_line2_line2(Linear2::Segment(&s), Linear2::Line(&l));
    let t2 = match c.value {
        Intersection2::Point { t2, .. } => t2,
        Intersection2::Empty(Empty2::OutsideDomain { t2, .. }) => t2,
        // Δ ≠ 0: the carriers cross.
        _ => return None,
    };
    let sign = match (t2.sign(), delta) {
        (Ordering::Equal, _) => Ordering::Equal,
        (s, Ordering::Greater) => s.reverse(),
        (s, _) => s,
    };
    Some((sign, c.arithmetic))
}

/// The signs at every point of the grid, point `(i, j)` at index `i·SIDE + j`.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct SignMap {
    /// The exact orientation.
    pub truth: Vec<Ordering>,
    /// Plain f64 ([`plain`]).
    pub plain: Vec<Ordering>,
    /// geocert certified ([`certified`]; `None`: no answer) and whether its double-double
    /// filter decided it.
    pub certified: Vec<Option<Ordering>>,
    pub filter_decided: Vec<bool>,
}

/// The signs of every method on the 256×256 grid.
pub fn sign_map() -> SignMap {
    let n = SIDE * SIDE;
    let mut m = SignMap {
        truth: Vec::with_capacity(n),
        plain: Vec::with_capacity(n),
        certified: Vec::with_capacity(n),
        filter_decided: Vec::with_capacity(n),
    };
    for i in 0..SIDE {
        for j in 0..SIDE {
            let p = point(i, j);
            m.truth.push(exact(p, Q, R));
            m.plain.push(plain(p, Q, R));
            let c = certified(p, Q, R);
            m.certified.push(c.map(|(s, _)| s));
            m.filter_decided
                .push(c.is_some_and(|(_, a)| a == Arithmetic::Filter));
        }
    }
    m
}

/// How many of `signs` are negative, zero and positive.
pub fn histogram<'a>(signs: impl IntoIterator<Item = &'a Ordering>) -> [usize; 3] {
    let mut h = [0; 3];
    for s in signs {
        h[(*s as i8 + 1) as usize] += 1;
    }
    h
}

/// The counts over the grid.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct KettnerCounts {
    pub points: usize,
    /// Exactly collinear `(p, q, r)`.
    pub collinear: usize,
    /// Plain f64 gave a wrong sign.
    pub plain_wrong: usize,
    /// Epick's collinearity verdict (see [`epick_collinear`]) was wrong; `None`
    /// without the `cgal` feature.
    pub epick_wrong: Option<usize>,
    /// geocert's double-double filter could not decide (the exact tiers did).
    pub filter_undecided: usize,
    /// geocert certified gave a wrong sign (or no answer).
    pub certified_wrong: usize,
    /// The exact signs: how many points are negative, zero, positive (the pixels of
    /// each colour on the certified sign map, [`super::plot`]).
    pub truth_signs: [usize; 3],
    /// Plain f64's signs: negative, zero, positive (the plain sign map's pixels).
    pub plain_signs: [usize; 3],
}

/// CGAL Epick on the grid: the oracle exposes no orientation predicate, so this asks
/// Epick whether the line through `p` parallel to `qr` equals the line through `q`
/// along `r − q` (both `Line_2(point, vector)`; `r − q` is exact here). Epick answers
/// `Line` (equal: collinear) or `Empty` (parallel: not collinear); it builds each
/// line's coefficients `a x + b y + c = 0` in doubles, so `c` is rounded. This decides
/// collinearity only, not the sign.
#[cfg(feature = "cgal")]
pub fn epick_collinear(p: [f64; 2], q: [f64; 2], r: [f64; 2]) -> Option<bool> {
    use crate::oracle::{epick, Intersection, Line2Input};
    let d = [r[0] - q[0], r[1] - q[1]];
    let a = Line2Input {
        point: p,
        direction: d,
    };
    let b = Line2Input {
        point: q,
        direction: d,
    };
    match epick::intersect_line2_line2(&a, &b).ok()? {
        Intersection::Line { .. } => Some(true),
        Intersection::Empty => Some(false),
        _ => None,
    }
}

/// Run every method on the 256×256 grid.
pub fn grid() -> KettnerCounts {
    let m = sign_map();
    let wrong = |v: &[Ordering]| v.iter().zip(&m.truth).filter(|(a, b)| a != b).count();
    let certified_wrong = m
        .certified
        .iter()
        .zip(&m.truth)
        .filter(|(c, t)| **c != Some(**t))
        .count();
    #[allow(unused_mut)]
    let mut c = KettnerCounts {
        points: SIDE * SIDE,
        collinear: m.truth.iter().filter(|s| s.is_eq()).count(),
        plain_wrong: wrong(&m.plain),
        epick_wrong: None,
        filter_undecided: m.filter_decided.iter().filter(|d| !**d).count(),
        certified_wrong,
        truth_signs: histogram(&m.truth),
        plain_signs: histogram(&m.plain),
    };
    #[cfg(feature = "cgal")]
    {
        let mut w = 0;
        for i in 0..SIDE {
            for j in 0..SIDE {
                let p = point(i, j);
                let truth = m.truth[i * SIDE + j];
                w += (epick_collinear(p, Q, R) != Some(truth == Ordering::Equal)) as usize;
            }
        }
        c.epick_wrong = Some(w);
    }
    c
}
