//! A Bézier or NURBS curve (polynomial or rational, OPERATIONS.md §1.5) against a plane,
//! decided exactly (issue 16; docs/CERTIFICATES.md `exact`).
//!
//! With control points `Pᵢ` and weights `wᵢ > 0` (all 1 for a polynomial curve), the
//! plane's equation `n·x − h` on the curve is `N(t)/W(t)` with
//! `N = Σ wᵢ(n·Pᵢ − h) Bᵢⁿ(t)`, `W = Σ wᵢ Bᵢⁿ(t) > 0`: the common points are the real
//! roots of the polynomial `N` (rational coefficients, the doubles taken exactly) in the
//! curve's domain, isolated exactly with their multiplicities (2: a proven tangency) by
//! [`real_roots_in`], the domain's double ends decided exactly. `N ≡ 0`: the curve lies
//! in the plane (kind `coincident`, reason "the curve lies in the plane", as for the
//! conics in [`super::conic_plane`]). The parameter `t` is correctly rounded
//! (`RealRoot::rounded`); each coordinate `Σ wᵢPᵢBᵢ(t)/W(t)` is rounded from exact
//! rational enclosures over the refined isolating interval ([`round_enclosure`]). A
//! coordinate that is rational at an irrational root is found exactly when it is so
//! modulo the root's square-free factor (a constant remainder); any other that the
//! refinement cannot round within its budget leaves the pair to the numeric certifier
//! (`None`). A NURBS curve is the same on each knot span, piece by piece
//! ([`super::exact_spline`]).

use rug::Rational;

use super::conic_plane::ExactPlane;
use super::exact_spline::{spline_points, ExactBezier, ExactCurve};
use crate::certificate::{Arithmetic, Certified};
use crate::certify::univariate::{real_roots_in, Polynomial, RealRoot};
use crate::num::round::{round_rational, Rounded};
use crate::ops::answer::{Answer, ExactPoint, Point};
use crate::ops::rational::exact::{dot, round_enclosure, RatInterval};

/// How many refinements a coordinate's rounding may take before giving up.
const REFINE_BUDGET: usize = 4000;

/// `num(t)/den(t)` correctly rounded at the root `t`; `None` past the budget or once
/// `deadline` has passed (checked per refinement, issue 20: the caller then leaves the
/// pair to the numeric certifier, which reports the time limit).
pub(super) fn round_at(
    t: &RealRoot,
    num: &Polynomial,
    den: &Polynomial,
    deadline: Option<std::time::Instant>,
) -> Option<Exactly> {
    if let Some(x) = t.exact() {
        let v = num.eval(x) / den.eval(x);
        return Some((round_rational(&v), Some(v)));
    }
    let f = t.factor();
    let constant = |p: &Polynomial| {
        let (_, r) = p.div_rem(&f)?;
        (r.degree().unwrap_or(0) == 0).then(|| r.coeff(0))
    };
    if let (Some(a), Some(b)) = (constant(num), constant(den)) {
        if b.cmp0() != std::cmp::Ordering::Equal {
            let v = a / b;
            return Some((round_rational(&v), Some(v)));
        }
    }
    let mut t = t.clone();
    let mut tried: Option<Rational> = None;
    for _ in 0..REFINE_BUDGET {
        if crate::certify::past(deadline) {
            return None;
        }
        let x = RatInterval::from_root(&t);
        if let Some(q) = x.eval(num).div(&x.eval(den)) {
            if let Some(r) = round_enclosure(&q) {
                return Some((r, None));
            }
            // An enclosure that keeps straddling one double may be converging onto it:
            // the value is that double exactly when `t` is a root of `num − d·den`
            // (decided exactly); otherwise refinement moves the enclosure off it.
            if let Some(d) = straddled_double(&q).filter(|d| tried.as_ref() != Some(d)) {
                if t.is_root_of(&(num - &den.scale(&d))) {
                    return Some((round_rational(&d), Some(d)));
                }
                tried = Some(d);
            }
        }
        t.refine();
    }
    None
}

/// The double both ends of `q` round to, when it lies inside `q`.
fn straddled_double(q: &RatInterval) -> Option<Rational> {
    let (a, b) = (round_rational(&q.lo), round_rational(&q.hi));
    if a.nearest.to_bits() != b.nearest.to_bits() || a.overflowed() {
        return None;
    }
    let d = Rational::from_f64(a.nearest)?;
    (q.lo <= d && d <= q.hi).then_some(d)
}

/// The other object's parameters at a root `t` of the curve: correctly rounded, with
/// the exact value when it is rational; `None` when one cannot be rounded in budget.
pub(super) type OtherParams<'a> = Box<dyn FnMut(&RealRoot) -> Option<Vec<Exactly>> + 'a>;

/// A correctly rounded number and its exact value when known.
pub(super) type Exactly = (Rounded, Option<Rational>);

/// Parameters that are rational functions of the curve's: `nums/den` at the root
/// (a plane's or a line's coordinates along itself), correctly rounded like the
/// coordinates, stopping at `deadline` ([`round_at`]).
pub(super) fn ratios<'a>(
    nums: &'a [Polynomial],
    den: &'a Polynomial,
    deadline: Option<std::time::Instant>,
) -> OtherParams<'a> {
    Box::new(move |t| {
        nums.iter()
            .map(|num| round_at(t, num, den, deadline))
            .collect()
    })
}

/// The points of the curve at the roots of `n` in its domain that `keep` accepts, with
/// the other object's parameters from `other`; `None` when a number cannot be rounded
/// within the budget. With `skip_start` a root at the domain's lower end is left out
/// and its multiplicity returned (the piece on the left reports it,
/// [`super::exact_spline::spline_points`]). Rounding stops at `deadline`
/// ([`round_at`]).
pub(super) fn bezier_points(
    c: &ExactBezier,
    n: &Polynomial,
    mut other: OtherParams<'_>,
    mut keep: impl FnMut(&mut RealRoot) -> bool,
    skip_start: bool,
    curve_first: bool,
    deadline: Option<std::time::Instant>,
) -> Option<(Vec<Point>, Option<u32>)> {
    let roots = real_roots_in(n, &c.domain.0, &c.domain.1).ok()?;
    let mut points = Vec::new();
    let mut start = None;
    for mut t in roots {
        if skip_start && t.exact() == Some(&c.domain.0) {
            start = keep(&mut t).then(|| t.multiplicity());
            continue;
        }
        if !keep(&mut t) {
            continue;
        }
        let mut xyz = Vec::new();
        let mut exact = Vec::new();
        for num in &c.nums {
            let (r, e) = round_at(&t, num, &c.den, deadline)?;
            xyz.push(r);
            exact.push(e);
        }
        let tr = t.rounded();
        let (ab, ab_exact): (Vec<Rounded>, Vec<Option<Rational>>) = other(&t)?.into_iter().unzip();
        let tv = [tr];
        let (first, second) = if curve_first {
            (&tv[..], &ab[..])
        } else {
            (&ab[..], &tv[..])
        };
        let value = |v: &[Rounded]| v.iter().map(|r| r.nearest).collect::<Vec<_>>();
        let bounds = |v: &[Rounded]| v.iter().map(|r| [r.lo, r.hi]).collect::<Vec<_>>();
        let all = exact.iter().chain(&ab_exact).all(Option::is_some);
        let exact = match (t.exact(), all) {
            (Some(te), true) => {
                let c = vec![te.clone()];
                let pl: Vec<Rational> = ab_exact.into_iter().flatten().collect();
                Some(ExactPoint {
                    xyz: exact.into_iter().flatten().collect(),
                    params: if curve_first {
                        vec![c, pl]
                    } else {
                        vec![pl, c]
                    },
                    distance_squared: None,
                })
            }
            _ => None,
        };
        points.push(Point {
            xyz: value(&xyz),
            xyz_box: bounds(&xyz),
            params: vec![value(first), value(second)],
            param_box: Some(vec![bounds(first), bounds(second)]),
            multiplicity: t.multiplicity(),
            tangent: t.multiplicity() >= 2,
            exact,
            ..Default::default()
        });
    }
    Some((points, start))
}

/// A Bézier or NURBS curve (as exact pieces, [`ExactCurve`]) against a plane, exactly;
/// `None` when a coordinate cannot be rounded within the budget, or when the curve lies
/// in the plane on some pieces only (left to the numeric certifier), or when `deadline`
/// passes while rounding.
pub(crate) fn spline_plane(
    curve: &ExactCurve,
    plane: &ExactPlane,
    curve_first: bool,
    deadline: Option<std::time::Instant>,
) -> Option<Certified<Answer>> {
    let height = |c: &ExactBezier| c.affine(&plane.n, &-plane.h.clone());
    let bits = match curve.zero_set(height, true, "the curve lies in the plane") {
        Ok(bits) => bits,
        Err(r) => return r.map(|r| *r),
    };
    let points = spline_points(curve, curve_first, |c, skip_start| {
        let plane_nums = plane_params(c, plane);
        bezier_points(
            c,
            &height(c),
            ratios(&plane_nums, &c.den, deadline),
            |_| true,
            skip_start,
            curve_first,
            deadline,
        )
    })?;
    Some(Certified::exact(
        Answer::from_points(points),
        Arithmetic::Rational,
        bits,
    ))
}

/// A parametric plane's `(a, b) = (A·(x − o), B·(x − o))` on the piece, times its
/// denominator, with `A`, `B` from the plane's Gram system; none for an implicit plane.
fn plane_params(c: &ExactBezier, plane: &ExactPlane) -> Vec<Polynomial> {
    let Some([o, u, v]) = &plane.frame else {
        return Vec::new();
    };
    let (uu, uv, vv) = (dot(u, u), dot(u, v), dot(v, v));
    let det = Rational::from(&uu * &vv) - Rational::from(&uv * &uv);
    let comb = |c1: &Rational, e1: &[Rational; 3], c2: &Rational, e2: &[Rational; 3]| {
        let g: [Rational; 3] = std::array::from_fn(|i| {
            (Rational::from(c1 * &e1[i]) - Rational::from(c2 * &e2[i])) / &det
        });
        c.affine(&g, &-dot(&g, o))
    };
    vec![comb(&vv, u, &uv, v), comb(&uu, v, &uv, u)]
}
