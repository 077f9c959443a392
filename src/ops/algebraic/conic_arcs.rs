//! A plane Bézier or NURBS curve against a plane spline whose pieces are conic arcs
//! (rational quadratic Bézier pieces: a quadratic Bézier, a NURBS circle or a rounded
//! corner, OPERATIONS.md §1.5), decided exactly (issues 14 and 16;
//! docs/CERTIFICATES.md `exact`).
//!
//! A rational quadratic piece with control points `P₀, P₁, P₂` (not collinear) and
//! weights `w₀, w₁, w₂ > 0` is an arc of the conic
//!
//! `w₀w₂·λ₁(x)² − 4w₁²·λ₀(x)·λ₂(x) = 0`,
//!
//! where `λᵢ(x)/Δ` are the barycentric coordinates of `x` in the control triangle
//! (`λ₀ = det(P₁ − x, P₂ − x)`, cyclically; `Δ = λ₀ + λ₁ + λ₂ = det(P₁ − P₀, P₂ − P₀)`):
//! on the piece `λᵢ/Δ = wᵢBᵢ²(u)/Σⱼ wⱼBⱼ²(u)`, so `λ₁²/(λ₀λ₂) = 4w₁²/(w₀w₂)`. A point of
//! that conic lies on the arc (`u ∈ [0, 1]`) exactly when all three `λᵢ/Δ ≥ 0`: for
//! `u ∉ [0, 1]` either `λ₁/Δ < 0`, or the denominator is negative and then `λ₀/Δ < 0`
//! (the other branch of a hyperbola). On the arc the parameter is
//! `u = (w₀λ₁ + 2w₁λ₂)/(w₀λ₁ + 2w₁λ₂ + 2w₁λ₀ + w₂λ₁)` — the mediant of the two equal
//! ratios `u/(1 − u) = w₀λ₁/(2w₁λ₀) = 2w₁λ₂/(w₂λ₁)`, defined at both ends.
//!
//! The other curve `X = N/W` meets the piece where `W²F(N/W) = 0`
//! ([`super::bezier_conic2`]); on that curve each `W·λᵢ(N/W)` is a polynomial, so the
//! arc test is the exact sign of three polynomials at a root, and the piece's parameter
//! (mapped to its knot span) is a ratio of polynomials, rounded correctly like the
//! coordinates ([`super::bezier_plane::ratios`]). Each piece keeps its arc half-open
//! (`u = 1` belongs to the next piece, or to the first one on a closed curve), so a
//! point at a knot is reported once. At a knot where the two pieces lie on different
//! conics, a root of higher multiplicity on one side than on the other leaves the pair
//! to the numeric certifier (`None`), as does a degenerate piece (collinear control
//! points), a curve lying on one of the conics, or a number not rounded within the
//! budget or before the deadline.

use rug::Rational;
use std::cell::Cell;
use std::cmp::Ordering;

use super::bezier_plane::{bezier_points, ratios};
use super::exact_spline::{spline_points, ExactBezier, ExactCurve};
use crate::certificate::{Arithmetic, Certified};
use crate::certify::univariate::{Polynomial, RealRoot};
use crate::ops::answer::{Answer, Point};
use crate::ops::rational::exact::sign_at_root;
use crate::ops::rational::QuadricForm;

/// An affine function `a·x + c` of the plane point.
#[derive(Clone)]
struct Affine {
    a: [Rational; 2],
    c: Rational,
}

/// `det(A − x, B − x) = det(A, B) + det(B, x) − det(A, x)`, with
/// `det(P, x) = −P_y·x + P_x·y`.
fn det_form(a: &[Rational; 2], b: &[Rational; 2]) -> Affine {
    Affine {
        a: [Rational::from(&a[1] - &b[1]), Rational::from(&b[0] - &a[0])],
        c: Rational::from(&a[0] * &b[1]) - Rational::from(&a[1] * &b[0]),
    }
}

/// The quadric form of `k·f·g` for affine `f`, `g`: `xᵀ k(f_a g_aᵀ + g_a f_aᵀ)/2 x +
/// 2·k(f_a g_c + g_a f_c)/2·x + k f_c g_c`.
fn product(f: &Affine, g: &Affine, k: &Rational) -> QuadricForm<2> {
    let half = Rational::from((1, 2));
    let a = std::array::from_fn(|i| {
        std::array::from_fn(|j| {
            let s = Rational::from(&f.a[i] * &g.a[j]) + Rational::from(&g.a[i] * &f.a[j]);
            s * &half * k
        })
    });
    let b = std::array::from_fn(|i| {
        (Rational::from(&f.a[i] * &g.c) + Rational::from(&g.a[i] * &f.c)) * &half * k
    });
    QuadricForm {
        a,
        b,
        c: Rational::from(&f.c * &g.c) * k,
    }
}

fn sum(p: QuadricForm<2>, q: QuadricForm<2>) -> QuadricForm<2> {
    QuadricForm {
        a: std::array::from_fn(|i| {
            std::array::from_fn(|j| Rational::from(&p.a[i][j] + &q.a[i][j]))
        }),
        b: std::array::from_fn(|i| Rational::from(&p.b[i] + &q.b[i])),
        c: p.c + q.c,
    }
}

/// One conic arc of the spline: its conic, the barycentric forms `λᵢ`, the weights,
/// the sign of `Δ`, and its knot span.
struct Arc {
    form: QuadricForm<2>,
    lambda: [Affine; 3],
    w: [Rational; 3],
    orientation: Ordering,
    span: (Rational, Rational),
}

impl Arc {
    /// The piece's Bernstein data on its span (`p(a)`, `p(a) + (b − a)p′(a)/2`, `p(b)`
    /// for each quadratic `p`), or `None` for a piece of another degree, a weight ≤ 0
    /// or collinear control points.
    fn of(piece: &ExactBezier) -> Option<Arc> {
        if piece.nums.len() != 2
            || piece.den.degree().unwrap_or(0) > 2
            || piece.nums.iter().any(|n| n.degree().unwrap_or(0) > 2)
        {
            return None;
        }
        let (a, b) = piece.domain.clone();
        let half_len = Rational::from(&b - &a) / 2u32;
        let bern = |p: &Polynomial| {
            let pa = p.eval(&a);
            let mid = Rational::from(&pa + &(p.derivative().eval(&a) * &half_len));
            [pa, mid, p.eval(&b)]
        };
        let w = bern(&piece.den);
        if w.iter().any(|wi| wi.cmp0() != Ordering::Greater) {
            return None;
        }
        let (nx, ny) = (bern(&piece.nums[0]), bern(&piece.nums[1]));
        let pts: [[Rational; 2]; 3] = std::array::from_fn(|i| {
            [
                Rational::from(&nx[i] / &w[i]),
                Rational::from(&ny[i] / &w[i]),
            ]
        });
        let lambda = [
            det_form(&pts[1], &pts[2]),
            det_form(&pts[2], &pts[0]),
            det_form(&pts[0], &pts[1]),
        ];
        let delta = Rational::from(&lambda[0].c + &lambda[1].c) + &lambda[2].c;
        let orientation = delta.cmp0();
        if orientation == Ordering::Equal {
            return None;
        }
        let k1 = Rational::from(&w[0] * &w[2]);
        let k2 = -(Rational::from(&w[1] * &w[1]) * 4u32);
        let form = sum(
            product(&lambda[1], &lambda[1], &k1),
            product(&lambda[0], &lambda[2], &k2),
        );
        Some(Arc {
            form,
            lambda,
            w,
            orientation,
            span: (a, b),
        })
    }

    /// `W·λᵢ(N/W)` on the curve `c`.
    fn lambdas(&self, c: &ExactBezier) -> [Polynomial; 3] {
        std::array::from_fn(|i| c.affine(&self.lambda[i].a, &self.lambda[i].c))
    }

    /// The knot parameter `a + (b − a)u` as `num/den` on the curve `c` (module doc).
    fn parameter(&self, l: &[Polynomial; 3]) -> (Polynomial, Polynomial) {
        let [w0, w1, w2] = &self.w;
        let two_w1 = Rational::from(w1 * 2u32);
        let u_num = &l[1].scale(w0) + &l[2].scale(&two_w1);
        let den = &(&u_num + &l[0].scale(&two_w1)) + &l[1].scale(w2);
        let (a, b) = &self.span;
        let num = &den.scale(a) + &u_num.scale(&Rational::from(b - a));
        (num, den)
    }
}

/// The multiplicity of the root `t` as a root of `g` (0: not a root).
fn multiplicity_in(t: &RealRoot, g: &Polynomial) -> u32 {
    let mut g = g.clone();
    let mut m = 0;
    while !g.is_zero() && t.is_root_of(&g) {
        m += 1;
        g = g.derivative();
    }
    m
}

/// The conic arcs of a spline whose every piece is a non-degenerate rational quadratic.
fn arcs(curve: &ExactCurve) -> Option<Vec<Arc>> {
    curve.pieces.iter().map(Arc::of).collect()
}

/// `searched` against the conic-arc spline `arcs_of` (module doc); `searched_first`
/// orders the parameters. `None` when a piece of `arcs_of` is not a conic arc, or when
/// the pair is left to the numeric certifier.
pub(super) fn spline_conic_arcs(
    searched: &ExactCurve,
    arcs_of: &ExactCurve,
    searched_first: bool,
    deadline: Option<std::time::Instant>,
) -> Option<Certified<Answer>> {
    let arcs = arcs(arcs_of)?;
    let mut bits = 0;
    let mut points: Vec<Point> = Vec::new();
    for (j, arc) in arcs.iter().enumerate() {
        let on = |c: &ExactBezier| c.quadric(&arc.form);
        bits = bits.max(searched.zero_set(on, false, "").ok()?);
        let last = j + 1 == arcs.len();
        let previous = match j {
            0 if arcs_of.closed => arcs.last(),
            0 => None,
            _ => arcs.get(j - 1),
        };
        let mismatch = Cell::new(false);
        let found = spline_points(searched, searched_first, |c, skip_start| {
            let l = arc.lambdas(c);
            let (num, den) = arc.parameter(&l);
            let nums = [num];
            let g = on(c);
            let keep = |t: &mut RealRoot| {
                let s: Vec<Ordering> = l.iter().map(|li| sign_at_root(t, li)).collect();
                let against = arc.orientation.reverse();
                if s.contains(&against) {
                    return false;
                }
                let at_end = s[0] == Ordering::Equal && s[1] == Ordering::Equal;
                // The arc's end `u = 1` belongs to the next piece (the first one on a
                // closed curve); only the last arc of an open curve keeps it.
                let end_is_next = !last || arcs_of.closed;
                if at_end && end_is_next {
                    return false;
                }
                let at_start = s[1] == Ordering::Equal && s[2] == Ordering::Equal;
                if let (true, Some(prev)) = (at_start && t.multiplicity() > 1, previous) {
                    let other = multiplicity_in(t, &c.quadric(&prev.form));
                    mismatch.set(mismatch.get() || other != t.multiplicity());
                }
                true
            };
            bezier_points(
                c,
                &g,
                ratios(&nums, &den, deadline),
                keep,
                skip_start,
                searched_first,
                deadline,
            )
        })?;
        if mismatch.get() {
            return None;
        }
        points.extend(found);
    }
    let side = usize::from(!searched_first);
    points.sort_by(|p, q| p.params[side][0].total_cmp(&q.params[side][0]));
    Some(Certified::exact(
        Answer::from_points(points),
        Arithmetic::Rational,
        bits,
    ))
}
