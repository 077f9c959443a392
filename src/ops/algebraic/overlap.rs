//! Two Bézier or NURBS curves (plane or space, polynomial or rational) that share an
//! arc, decided exactly (issue 20): a copy reversed, re-knotted, or one half of a
//! de Casteljau split of the other. Two curves sharing an arc have common points in
//! every box along it, so the numeric certifier could only subdivide until its budget.
//!
//! The proof, in rationals (the doubles taken exactly, [`ExactCurve`]): an end of the
//! common arc is an end of one of the curves, so every candidate pair of parameters
//! `(t, s)` with `A(t) = B(s)` where `t` or `s` is a domain end is located exactly —
//! the end point `P` is rational, the parameters on the other curve are the rational
//! roots of `W(t)·X(t) − W(t)·P` ([`real_roots_in`]; a root that is not rational is
//! tried as its nearest double and kept only if exact). For two such pairs the affine
//! map `t = φ(s) = αs + β` through them is tested on every stretch between the pieces'
//! breakpoints by the polynomial identities `N_A,k(φ(s))·W_B(s) = N_B,k(s)·W_A(φ(s))`
//! (equality of the two rational points for all `s`, the denominators positive):
//! the arcs `A([t₀, t₁])` and `B([s₀, s₁])` are then the same point set. Nothing
//! else is claimed: a pair that no affine map relates (a rational curve under a
//! Möbius change of parameter) is left to the numeric route, whose overlap guard
//! answers `undecided` (`crate::ops::front`).
//!
//! The answer: kind `coincident` when the arc is all of both curves; kind `arc`
//! (its ends `a`, `b` with their parameters on both curves) when it is all of one of
//! them (the intersection is then that arc, `complete`); kind `arc` with
//! `complete: false` when each curve goes on beyond it (other common points are not
//! searched). The exact values of the ends are given (`exact`).

use rug::Rational;

use super::exact_spline::{ExactBezier, ExactCurve};
use crate::certificate::{Arithmetic, Certified};
use crate::certify::univariate::{real_roots_in, Polynomial};
use crate::curve::{AnyCurve2, AnyCurve3};
use crate::num::round::round_rational;
use crate::ops::answer::{Answer, ExactPoint, Point, SegmentAnswer};
use crate::ops::shape::Shape;

/// The shared arc of `a` and `b` when both are Bézier or NURBS curves of the same
/// dimension and the exact test proves one (module doc); `None` otherwise (including
/// past `deadline`, checked per candidate map).
pub(crate) fn curve_overlap(
    a: &Shape,
    b: &Shape,
    deadline: Option<std::time::Instant>,
) -> Option<Certified<Answer>> {
    let (ea, eb) = (exact(a)?, exact(b)?);
    let dim = |c: &ExactCurve| c.pieces.first().map(|p| p.nums.len());
    if dim(&ea) != dim(&eb) {
        return None; // a plane curve against a space curve: refused by the front door
    }
    let (da, db) = (ends(&ea)?, ends(&eb)?);
    let mut pairs: Vec<(Rational, Rational)> = Vec::new();
    let mut add = |t: Rational, s: Rational| {
        if !pairs.iter().any(|(x, y)| *x == t && *y == s) {
            pairs.push((t, s));
        }
    };
    for s in [&db.0, &db.1] {
        for t in locate(&ea, &eval(&eb, s)?)? {
            add(t, s.clone());
        }
    }
    for t in [&da.0, &da.1] {
        for s in locate(&eb, &eval(&ea, t)?)? {
            add(t.clone(), s);
        }
    }
    let mut best: Option<[(Rational, Rational); 2]> = None;
    for i in 0..pairs.len() {
        for j in i + 1..pairs.len() {
            if crate::certify::past(deadline) {
                return None;
            }
            let (p, q) = (&pairs[i], &pairs[j]);
            if p.0 == q.0 || p.1 == q.1 {
                continue;
            }
            let (p, q) = if p.1 < q.1 { (p, q) } else { (q, p) };
            let wider = best
                .as_ref()
                .is_none_or(|[bp, bq]| Rational::from(&q.1 - &p.1) > Rational::from(&bq.1 - &bp.1));
            if wider && same_arc(&ea, &eb, p, q) {
                best = Some([p.clone(), q.clone()]);
            }
        }
    }
    let [p, q] = best?;
    let all = |x: &Rational, y: &Rational, d: &(Rational, Rational)| {
        let (lo, hi) = if x < y { (x, y) } else { (y, x) };
        *lo == d.0 && *hi == d.1
    };
    let (all_a, all_b) = (all(&p.0, &q.0, &da), all(&p.1, &q.1, &db));
    let bits = ea
        .max_bits(|c| c.den.clone())
        .max(eb.max_bits(|c| c.den.clone()));
    if all_a && all_b {
        let mut r = Certified::exact(Answer::Coincident, Arithmetic::Rational, bits.max(53));
        r.reason = Some(
            "the two curves are the same point set, one a reparametrisation of the other".into(),
        );
        return Some(r);
    }
    let arc = Answer::Arc(SegmentAnswer {
        a: end_point(&ea, &p)?,
        b: end_point(&ea, &q)?,
    });
    let mut r = Certified::exact(arc, Arithmetic::Rational, bits.max(53));
    if all_a || all_b {
        r.reason = Some("the curves share the arc from a to b, all of one of them".into());
    } else {
        r.complete = false;
        r.reason = Some(
            "the curves share the arc from a to b; other common points were not searched".into(),
        );
    }
    Some(r)
}

/// The exact pieces of a Bézier or NURBS curve (2D or 3D).
fn exact(s: &Shape) -> Option<ExactCurve> {
    match s {
        Shape::Curve2(AnyCurve2::Bezier(c)) => Some(ExactCurve::bezier(c)),
        Shape::Curve2(AnyCurve2::Nurbs(c)) => Some(ExactCurve::nurbs(c)),
        Shape::Curve(AnyCurve3::Bezier(c)) => Some(ExactCurve::bezier(c)),
        Shape::Curve(AnyCurve3::Nurbs(c)) => Some(ExactCurve::nurbs(c)),
        _ => None,
    }
}

/// The curve's domain `[lo, hi]` (the first piece's start, the last piece's end).
fn ends(c: &ExactCurve) -> Option<(Rational, Rational)> {
    Some((
        c.pieces.first()?.domain.0.clone(),
        c.pieces.last()?.domain.1.clone(),
    ))
}

/// The piece holding `t` (the first whose closed domain does).
fn piece<'c>(c: &'c ExactCurve, t: &Rational) -> Option<&'c ExactBezier> {
    c.pieces
        .iter()
        .find(|p| p.domain.0 <= *t && *t <= p.domain.1)
}

/// `X(t)`, exactly (`None`: outside the domain or a zero denominator).
fn eval(c: &ExactCurve, t: &Rational) -> Option<Vec<Rational>> {
    let p = piece(c, t)?;
    let w = p.den.eval(t);
    if w == 0 {
        return None;
    }
    Some(p.nums.iter().map(|n| n.eval(t) / &w).collect())
}

/// Every rational parameter of `c` at which it passes through `x` (`None`: a piece
/// that is the point `x` itself, a degenerate curve left to the numeric route).
fn locate(c: &ExactCurve, x: &[Rational]) -> Option<Vec<Rational>> {
    let mut out: Vec<Rational> = Vec::new();
    for p in &c.pieces {
        let f: Vec<Polynomial> = p
            .nums
            .iter()
            .zip(x)
            .map(|(n, xk)| n - &p.den.scale(xk))
            .collect();
        let first = f.iter().find(|g| !g.is_zero())?;
        let roots = real_roots_in(first, &p.domain.0, &p.domain.1).ok()?;
        for r in roots {
            let candidates = match r.exact() {
                Some(t) => vec![t.clone()],
                None => convergents(r.nearest()),
            };
            for t in candidates {
                if f.iter().all(|g| g.eval(&t) == 0) && !out.contains(&t) {
                    out.push(t);
                }
            }
        }
    }
    Some(out)
}

/// The continued-fraction convergents of the double `x` with denominators up to
/// `2³²` (the rational parameters an isolated root may be, tried exactly by the caller;
/// `1/3`, the end of a piece split at a third, is one of them).
fn convergents(x: f64) -> Vec<Rational> {
    let Some(mut rest) = Rational::from_f64(x) else {
        return Vec::new();
    };
    let (mut p0, mut q0) = (rug::Integer::from(0), rug::Integer::from(1));
    let (mut p1, mut q1) = (rug::Integer::from(1), rug::Integer::from(0));
    let mut out = Vec::new();
    while q1.significant_bits() <= 32 && out.len() < 64 {
        let a = rest.clone().floor().into_numer_denom().0;
        let p2 = rug::Integer::from(&a * &p1) + &p0;
        let q2 = rug::Integer::from(&a * &q1) + &q0;
        if q2.significant_bits() > 32 {
            break;
        }
        out.push(Rational::from((p2.clone(), q2.clone())));
        (p0, q0, p1, q1) = (p1, q1, p2, q2);
        let frac = Rational::from(&rest - &Rational::from(&a));
        if frac == 0 {
            break;
        }
        rest = frac.recip();
    }
    out
}

/// Whether `A(φ(s)) = B(s)` for every `s` between `p.1 < q.1`, with `φ` the affine map
/// taking `p.1 ↦ p.0` and `q.1 ↦ q.0`: the polynomial identities of the module doc on
/// each stretch between the breakpoints of both curves.
fn same_arc(
    a: &ExactCurve,
    b: &ExactCurve,
    p: &(Rational, Rational),
    q: &(Rational, Rational),
) -> bool {
    let alpha = Rational::from(&q.0 - &p.0) / Rational::from(&q.1 - &p.1);
    let beta = Rational::from(&p.0 - &(Rational::from(&alpha * &p.1)));
    let phi = |s: &Rational| Rational::from(&alpha * s) + &beta;
    let (s0, s1) = (&p.1, &q.1);
    let mut cuts: Vec<Rational> = vec![s0.clone(), s1.clone()];
    for piece in &b.pieces {
        cuts.extend([piece.domain.0.clone(), piece.domain.1.clone()]);
    }
    for piece in &a.pieces {
        for t in [&piece.domain.0, &piece.domain.1] {
            cuts.push(Rational::from(t - &beta) / &alpha);
        }
    }
    cuts.retain(|c| s0 <= c && c <= s1);
    cuts.sort();
    cuts.dedup();
    cuts.windows(2).all(|w| {
        let mid = Rational::from(&w[0] + &w[1]) / 2u32;
        let (Some(pa), Some(pb)) = (piece(a, &phi(&mid)), piece(b, &mid)) else {
            return false;
        };
        // `compose_affine(c₀, c₁)` is `P(c₀ + c₁·s)`.
        let den_a = pa.den.compose_affine(&beta, &alpha);
        pa.nums.iter().zip(&pb.nums).all(|(na, nb)| {
            let left = &na.compose_affine(&beta, &alpha) * &pb.den;
            let right = nb * &den_a;
            (&left - &right).is_zero()
        })
    })
}

/// An end of the shared arc at the parameters `(t, s)`: the point `A(t)` and both
/// parameters, correctly rounded, with their exact values.
fn end_point(a: &ExactCurve, (t, s): &(Rational, Rational)) -> Option<Point> {
    let xyz = eval(a, t)?;
    let r: Vec<_> = xyz.iter().map(round_rational).collect();
    let (rt, rs) = (round_rational(t), round_rational(s));
    Some(Point {
        xyz: r.iter().map(|x| x.nearest).collect(),
        xyz_box: r.iter().map(|x| [x.lo, x.hi]).collect(),
        params: vec![vec![rt.nearest], vec![rs.nearest]],
        param_box: Some(vec![vec![[rt.lo, rt.hi]], vec![[rs.lo, rs.hi]]]),
        multiplicity: 1,
        exact: Some(ExactPoint {
            xyz,
            params: vec![vec![t.clone()], vec![s.clone()]],
            distance_squared: None,
        }),
        ..Default::default()
    })
}

/// Whether the claimed arc from `(t₀, s₀)` to `(t₁, s₁)` (parameters on `a` and on `b`)
/// is shared by the two Bézier or NURBS curves: the same exact test as the solver's
/// (module doc), the affine map `φ` through the two pairs and the polynomial identities
/// on every stretch between breakpoints, so `Some(true)` proves that `A([t₀, t₁])` and
/// `B([s₀, s₁])` are one point set. `Some(false)`: no affine map relates them there (a
/// parameter outside a domain, or the identities fail; the arcs may still be related by
/// another change of parameter). `None`: a shape is not such a curve, the dimensions
/// differ, or the arc is one point (`t₀ = t₁` or `s₀ = s₁`).
pub(crate) fn shares_arc(
    a: &Shape,
    b: &Shape,
    p: &(Rational, Rational),
    q: &(Rational, Rational),
) -> Option<bool> {
    let (ea, eb) = (exact(a)?, exact(b)?);
    let dim = |c: &ExactCurve| c.pieces.first().map(|p| p.nums.len());
    if dim(&ea) != dim(&eb) || p.0 == q.0 || p.1 == q.1 {
        return None;
    }
    let within = |c: &ExactCurve, x: &Rational| piece(c, x).is_some();
    if !(within(&ea, &p.0) && within(&ea, &q.0) && within(&eb, &p.1) && within(&eb, &q.1)) {
        return Some(false);
    }
    let (p, q) = if p.1 < q.1 { (p, q) } else { (q, p) };
    Some(same_arc(&ea, &eb, p, q))
}

/// The exact point `X(t)` of a Bézier or NURBS curve (`None`: another shape, or `t`
/// outside its domain).
pub(crate) fn exact_point(c: &Shape, t: &Rational) -> Option<Vec<Rational>> {
    eval(&exact(c)?, t)
}
