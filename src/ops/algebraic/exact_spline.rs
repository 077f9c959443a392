//! Bézier and NURBS curves as exact rational pieces (OPERATIONS.md §1.5), the input of
//! the exact curve ∩ plane and curve ∩ line routes ([`super::bezier_plane`],
//! [`super::bezier_line2`]; issue 16).
//!
//! On a knot span `[u_s, u_{s+1})` of a NURBS curve of degree `p` the basis functions
//! `N_{s−p,p} … N_{s,p}` are polynomials; they are built exactly by the triangular
//! Cox–de Boor recursion of [Y 2.9] (The NURBS Book A2.2) over [`Polynomial`]s, in which
//! every division is by a knot difference `u_{s+r+1} − u_{s+1−j+r} > 0` (a constant:
//! the `t` of the left and right factors cancels). The curve on the span is then
//! `X(t) = Σ wᵢPᵢNᵢ(t) / Σ wᵢNᵢ(t)` in the power basis of the global parameter `t`, the
//! doubles taken exactly — an [`ExactBezier`] piece whose domain is the span clipped to
//! the curve's domain. A Bézier curve is one piece.
//!
//! A root shared by two pieces (a common point at a knot) is reported once, by the
//! piece on its left, with the smaller of the two one-sided multiplicities: at a knot
//! where the curve is only `C⁰` a one-sided tangency does not make a touching point. On
//! a closed curve (`X(lo) = X(hi)`) a root at both domain ends is one point, reported at
//! `lo` (issue 14, seams).

use rug::Rational;

use crate::certificate::{Arithmetic, Certified};
use crate::certify::univariate::Polynomial;
use crate::curve::bezier::Bezier;
use crate::curve::nurbs::NurbsCurve;
use crate::curve::Curve;
use crate::ops::answer::{Answer, Point};
use crate::ops::rational::QuadricForm;

/// `Σ cᵢ Bᵢⁿ(t)` in the power basis, exactly.
fn bernstein(c: &[Rational]) -> Polynomial {
    let n = c.len() - 1;
    let t = Polynomial::x();
    let one_minus_t = Polynomial::from_coeffs(vec![Rational::from(1), Rational::from(-1)]);
    let mut sum = Polynomial::zero();
    let mut binom = rug::Integer::from(1);
    for (i, ci) in c.iter().enumerate() {
        let b = &t.pow(i as u32) * &one_minus_t.pow((n - i) as u32);
        sum = &sum + &b.scale(&(Rational::from(&binom) * ci));
        binom = binom * (n - i) as u32 / (i as u32 + 1);
    }
    sum
}

/// A Bézier curve with its exact data: `X(t) = nums(t)/den(t)` in the power basis,
/// `den = Σ wᵢBᵢⁿ > 0` (OPERATIONS.md §1.5), the domain's double ends as rationals.
pub(super) struct ExactBezier {
    pub(super) den: Polynomial,
    pub(super) nums: Vec<Polynomial>,
    pub(super) domain: (Rational, Rational),
}

impl ExactBezier {
    pub(super) fn new<const D: usize>(curve: &Bezier<D>) -> ExactBezier {
        let q = |v: f64| Rational::from_f64(v).unwrap_or_default();
        let pts: Vec<[Rational; D]> = curve.points().iter().map(|p| p.map(q)).collect();
        let w: Vec<Rational> = match curve.weights() {
            Some(w) => w.iter().map(|&x| q(x)).collect(),
            None => vec![Rational::from(1); pts.len()],
        };
        let nums = (0..D)
            .map(|k| {
                let c: Vec<Rational> = pts
                    .iter()
                    .zip(&w)
                    .map(|(p, wi)| Rational::from(&p[k] * wi))
                    .collect();
                bernstein(&c)
            })
            .collect();
        let (lo, hi) = curve.domain();
        ExactBezier {
            den: bernstein(&w),
            nums,
            domain: (q(lo), q(hi)),
        }
    }

    /// `W(t)·(a·X(t) + c)`: an affine function of the point, times the denominator.
    pub(super) fn affine(&self, a: &[Rational], c: &Rational) -> Polynomial {
        let mut p = self.den.scale(c);
        for (num, ak) in self.nums.iter().zip(a) {
            p = &p + &num.scale(ak);
        }
        p
    }

    /// `W(t)²·F(X(t))` for the quadric form `F(x) = xᵀAx + 2bᵀx + c₀`
    /// (OPERATIONS.md §1.6): `Σ aᵢⱼNᵢNⱼ + 2W·Σ bᵢNᵢ + c₀W²`, whose real roots in the
    /// domain are the curve's points on the quadric (`W > 0`).
    pub(super) fn quadric<const D: usize>(&self, f: &QuadricForm<D>) -> Polynomial {
        let mut p = (&self.den * &self.den).scale(f.constant());
        let two = Rational::from(2);
        for (i, ni) in self.nums.iter().enumerate().take(D) {
            let b2 = Rational::from(&f.linear()[i] * &two);
            p = &p + &(&self.den * ni).scale(&b2);
            for (j, nj) in self.nums.iter().enumerate().take(D) {
                p = &p + &(ni * nj).scale(&f.matrix()[i][j]);
            }
        }
        p
    }
}

/// A curve as exact rational pieces, left to right, covering its domain.
pub(super) struct ExactCurve {
    pub(super) pieces: Vec<ExactBezier>,
    /// `X(lo) = X(hi)` (a closed Bézier or NURBS curve over its whole domain).
    pub(super) closed: bool,
}

fn q(v: f64) -> Rational {
    Rational::from_f64(v).unwrap_or_default()
}

impl ExactCurve {
    pub(super) fn bezier<const D: usize>(c: &Bezier<D>) -> ExactCurve {
        ExactCurve {
            pieces: vec![ExactBezier::new(c)],
            closed: c.is_closed(),
        }
    }

    pub(super) fn nurbs<const D: usize>(c: &NurbsCurve<D>) -> ExactCurve {
        let (u, p) = (c.knots(), c.degree());
        let n = c.points().len();
        let (lo, hi) = c.domain();
        let mut pieces = Vec::new();
        for s in p..n {
            let (a, b) = (u[s].max(lo), u[s + 1].min(hi));
            if u[s] >= u[s + 1] || a > b || (a == b && !pieces.is_empty()) {
                continue; // empty span, or outside the (sub-)domain
            }
            if a == b && b < hi {
                continue; // touches the domain only at its lower end: the next span has it
            }
            pieces.push(span_piece(c, s, (q(a), q(b))));
        }
        ExactCurve {
            pieces,
            closed: c.is_closed(),
        }
    }

    /// The curve against the zero set of `f` (a plane, a line, a conic, as the
    /// polynomial of each piece): `Ok(bits)`, the largest coefficient size, when `f` is
    /// not identically zero on any piece; when it is on every piece and `whole`, the
    /// exact answer `coincident` with `reason` ("the curve lies …"); otherwise (on
    /// some pieces only, or a bounded other object) `Err(None)`: left to the numeric
    /// certifier.
    pub(super) fn zero_set(
        &self,
        f: impl Fn(&ExactBezier) -> Polynomial,
        whole: bool,
        reason: &str,
    ) -> Result<u32, Option<Box<Certified<Answer>>>> {
        let bits = self.max_bits(&f);
        let lying = self.pieces.iter().filter(|c| f(c).is_zero()).count();
        if lying == self.pieces.len() && whole {
            let mut r = Certified::exact(Answer::Coincident, Arithmetic::Rational, bits);
            r.reason = Some(reason.into());
            return Err(Some(Box::new(r)));
        }
        if lying > 0 {
            return Err(None);
        }
        Ok(bits)
    }

    /// The largest coefficient size of `f` over the pieces (the answer's `bits`).
    pub(super) fn max_bits(&self, f: impl Fn(&ExactBezier) -> Polynomial) -> u32 {
        self.pieces
            .iter()
            .map(|c| f(c).max_bits())
            .max()
            .unwrap_or(0)
    }
}

/// The basis polynomials `N_{s−p+j,p}`, `j = 0..=p`, on the span `[u_s, u_{s+1})`.
fn span_basis(u: &[Rational], s: usize, p: usize) -> Vec<Polynomial> {
    let x = Polynomial::x();
    let left = |j: usize| &x - &Polynomial::constant(u[s + 1 - j].clone());
    let right = |j: usize| &Polynomial::constant(u[s + j].clone()) - &x;
    let mut basis = vec![Polynomial::constant(Rational::from(1))];
    for j in 1..=p {
        let mut saved = Polynomial::zero();
        for r in 0..j {
            let gap = Rational::from(&u[s + r + 1] - &u[s + 1 - j + r]);
            let temp = basis[r].scale(&gap.recip());
            basis[r] = &saved + &(&right(r + 1) * &temp);
            saved = &left(j - r) * &temp;
        }
        basis.push(saved);
    }
    basis
}

/// The curve on span `s` as an exact piece over `domain`.
fn span_piece<const D: usize>(
    c: &NurbsCurve<D>,
    s: usize,
    domain: (Rational, Rational),
) -> ExactBezier {
    let u: Vec<Rational> = c.knots().iter().map(|&k| q(k)).collect();
    let p = c.degree();
    let basis = span_basis(&u, s, p);
    let weight = |i: usize| c.weights().map_or(Rational::from(1), |w| q(w[i]));
    let mut den = Polynomial::zero();
    let mut nums = vec![Polynomial::zero(); D];
    for (j, b) in basis.iter().enumerate() {
        let i = s - p + j;
        let w = weight(i);
        den = &den + &b.scale(&w);
        for (k, num) in nums.iter_mut().enumerate() {
            *num = &*num + &b.scale(&(Rational::from(&w * &q(c.points()[i][k]))));
        }
    }
    ExactBezier { den, nums, domain }
}

/// The exact curve parameter of a reported point (`None`: irrational).
/// True if the curve's parameter of `p` is exactly `x` (a double: a knot or a domain
/// end). Only an exact root has a one-point parameter box; an isolated irrational
/// root's box has width, so it never passes for a knot whatever its estimate (the
/// other object's parameters need not be exact, e.g. a circle's angle).
fn at(p: &Point, curve_first: bool, x: &Rational) -> bool {
    let Some(b) = p
        .param_box
        .as_ref()
        .and_then(|b| b.get(usize::from(!curve_first)))
    else {
        return false;
    };
    matches!(b.first(), Some([lo, hi]) if lo == hi && Rational::from_f64(*lo).as_ref() == Some(x))
}

/// The points of every piece, each shared knot root and the seam of a closed curve
/// reported once (module doc). `piece(k, c, skip_start)` returns the points of piece
/// `k` with its roots at its lower end left out when `skip_start`, and the
/// multiplicity of such a root; `None` aborts (a number not rounded in budget).
pub(super) fn spline_points(
    curve: &ExactCurve,
    curve_first: bool,
    mut piece: impl FnMut(&ExactBezier, bool) -> Option<(Vec<Point>, Option<u32>)>,
) -> Option<Vec<Point>> {
    let mut points: Vec<Point> = Vec::new();
    for (k, c) in curve.pieces.iter().enumerate() {
        let (mut found, start) = piece(c, k > 0)?;
        if let (Some(m), Some(last)) = (start, points.last_mut()) {
            if at(last, curve_first, &c.domain.0) {
                merge_multiplicity(last, m);
            }
        }
        points.append(&mut found);
    }
    let (Some(first), Some(last)) = (curve.pieces.first(), curve.pieces.last()) else {
        return Some(points);
    };
    let at = |p: &Point, x: &Rational| at(p, curve_first, x);
    if curve.closed
        && points.len() >= 2
        && at(&points[0], &first.domain.0)
        && at(&points[points.len() - 1], &last.domain.1)
    {
        let seam = points.pop().map_or(1, |p| p.multiplicity);
        merge_multiplicity(&mut points[0], seam);
    }
    Some(points)
}

fn merge_multiplicity(p: &mut Point, m: u32) {
    p.multiplicity = p.multiplicity.min(m);
    p.tangent = p.multiplicity >= 2;
}
