//! A Bézier curve (polynomial or rational, OPERATIONS.md §1.5) against a plane, decided
//! exactly (issue 16; docs/CERTIFICATES.md `exact`).
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
//! (`None`).

use rug::Rational;

use super::conic_plane::ExactPlane;
use crate::certificate::{Arithmetic, Certified};
use crate::certify::univariate::{real_roots_in, Polynomial, RealRoot};
use crate::curve::bezier::Bezier;
use crate::curve::Curve;
use crate::num::round::{round_rational, Rounded};
use crate::ops::answer::{Answer, ExactPoint, Point};
use crate::ops::rational::exact::{dot, round_enclosure, RatInterval};

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

/// How many refinements a coordinate's rounding may take before giving up.
const REFINE_BUDGET: usize = 4000;

/// `num(t)/den(t)` correctly rounded at the root `t`; `None` past the budget.
fn round_at(
    t: &RealRoot,
    num: &Polynomial,
    den: &Polynomial,
) -> Option<(Rounded, Option<Rational>)> {
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
    for _ in 0..REFINE_BUDGET {
        let x = RatInterval::from_root(&t);
        if let Some(q) = x.eval(num).div(&x.eval(den)) {
            if let Some(r) = round_enclosure(&q) {
                return Some((r, None));
            }
        }
        t.refine();
    }
    None
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
}

/// The points of the curve at the roots of `n` in its domain that `keep` accepts, the
/// other object's parameters `flat_nums/den` (correctly rounded like the coordinates);
/// `None` when a number cannot be rounded within the budget.
pub(super) fn bezier_points(
    c: &ExactBezier,
    n: &Polynomial,
    flat_nums: &[Polynomial],
    mut keep: impl FnMut(&mut RealRoot) -> bool,
    curve_first: bool,
) -> Option<Vec<Point>> {
    let roots = real_roots_in(n, &c.domain.0, &c.domain.1).ok()?;
    let mut points = Vec::new();
    for mut t in roots {
        if !keep(&mut t) {
            continue;
        }
        let mut xyz = Vec::new();
        let mut exact = Vec::new();
        for num in &c.nums {
            let (r, e) = round_at(&t, num, &c.den)?;
            xyz.push(r);
            exact.push(e);
        }
        let tr = t.rounded();
        let mut ab = Vec::new();
        let mut ab_exact = Vec::new();
        for num in flat_nums {
            let (r, e) = round_at(&t, num, &c.den)?;
            ab.push(r);
            ab_exact.push(e);
        }
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
    Some(points)
}

/// A Bézier curve against a plane, exactly; `None` when a coordinate cannot be rounded
/// within the budget.
pub(crate) fn bezier_plane(
    curve: &Bezier<3>,
    plane: &ExactPlane,
    curve_first: bool,
) -> Option<Certified<Answer>> {
    let c = ExactBezier::new(curve);
    let n = c.affine(&plane.n, &-plane.h.clone());
    let bits = n.max_bits();
    if n.is_zero() {
        let mut r = Certified::exact(Answer::Coincident, Arithmetic::Rational, bits);
        r.reason = Some("the curve lies in the plane".into());
        return Some(r);
    }
    // A parametric plane's (a, b) = (A·(x − o), B·(x − o)), A, B from its Gram system.
    let plane_nums: Vec<Polynomial> = match &plane.frame {
        Some([o, u, v]) => {
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
        None => Vec::new(),
    };
    let points = bezier_points(&c, &n, &plane_nums, |_| true, curve_first)?;
    Some(Certified::exact(
        Answer::from_points(points),
        Arithmetic::Rational,
        bits,
    ))
}
