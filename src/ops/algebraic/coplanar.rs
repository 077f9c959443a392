//! Two conics in one plane of space, exactly (issue 16; OPERATIONS.md §6.3 with §1.5,
//! docs/CERTIFICATES.md `exact`): two framed conics whose planes coincide, and a framed
//! conic against an implicit `quadric` (whose restriction to the conic's plane is a
//! conic, §13.2 (13.4)).
//!
//! The plane gets the rational chart `P(U, V) = p + U·X̃ + V·Ỹ` of the first conic's
//! exact frame ([`super::conic_plane::exact_frame`]: `X̃ ⊥ Ỹ` unnormalised, rational).
//! Every quantity of a point is an affine form `c₀ + c₁U + c₂V` with rational
//! coefficients: its coordinates, and each conic's unnormalised local coordinates
//! `X = (P − pᵢ)·X̃ᵢ`, `Y = (P − pᵢ)·Ỹᵢ` (true local `x = X/|X̃ᵢ|`, `y = Y/|Ỹᵢ|`). So each
//! conic's equation is a rational conic in `(U, V)`: circle `X²/|X̃|² + Y²/|Ỹ|² = r²`,
//! ellipse and hyperbola `X²/(a²|X̃|²) ± Y²/(b²|Ỹ|²) = 1`, parabola
//! `Y²/|Ỹ|² = 2p·X/|X̃|` — rational only when `|X̃|` is (else the pair is left to the
//! numeric certifier, `None`). A quadric `F` restricts to `F(P(U, V))`, rational.
//!
//! The two conics of the chart are intersected by the exact conic ∩ conic of §6.3
//! ([`super::intersect_conic_conic_until`]): every real common point, its intersection
//! multiplicity in the plane (an affine chart keeps it; for a curve against a quadric it
//! is the contact order of the curve with the surface), and its `U`, `V` as algebraic
//! numbers. The value of any affine form `ℓ` at a point is then identified exactly, the
//! way conic ∩ conic identifies its coordinates: in coordinates `(ℓ, w)` (`w` the other
//! of `U`, `V`) the resultant `R_ℓ = Res_w` of the two equations vanishes at every
//! common point's `ℓ` (`R_ℓ = A·F₁ + B·F₂`) and is not zero (two conics without a common
//! component); the enclosure `c₀ + c₁[U] + c₂[V]` shrinks to the point while the
//! isolating intervals of the distinct roots of `R_ℓ` shrink to them, so eventually
//! exactly one root meets it: that root is `ℓ`. Coordinates are then correctly rounded
//! by the root finder (rational ones exactly), signs (branch, the zero angle) are exact,
//! and the curve parameters are rounded by Ziv's loop from enclosures of `X`, `Y`.
//!
//! Equal equations: two whole circles or ellipses are `coincident`; a conic whose
//! equation is the quadric's restriction (or whose plane lies in the quadric) lies on
//! the quadric: `coincident` with the reason "the curve lies on the quadric". Other
//! equal pairs (arcs, branches of one hyperbola) are left to the numeric certifier.

use rug::Rational;
use std::cmp::Ordering;
use std::f64::consts::TAU;

use super::bivariate::{resultant, Bivariate};
use super::conic_plane::{exact_frame, ExactFrame};
use super::{intersect_conic_conic_until, Conic, ConicCut, ConicHit, QuadricForm};
use crate::certificate::{Arithmetic, Certified, Status};
use crate::certify::univariate::{real_roots, RealRoot};
use crate::curve::analytic::{Analytic, Shape as CurveShape};
use crate::curve::Curve;
use crate::num::round::{round_rational, Rounded};
use crate::num::{MpfrInterval, Real};
use crate::ops::answer::{Answer, ExactPoint, Point};
use crate::ops::rational::exact::{compare_root, dot, RatInterval};
use crate::ops::rational::rounding::{
    correctly_rounded, enclose_root, special_angle, wrapped_angle,
};

type V3 = [Rational; 3];
/// `c₀ + c₁U + c₂V`.
type Affine = [Rational; 3];
/// A symmetric matrix on `(U, V, 1)`.
type Sym = [[Rational; 3]; 3];

fn zero_sym() -> Sym {
    std::array::from_fn(|_| std::array::from_fn(|_| Rational::new()))
}

/// `(c₁, c₂, c₀)`: the form on `(U, V, 1)`.
fn hom(l: &Affine) -> [Rational; 3] {
    [l[1].clone(), l[2].clone(), l[0].clone()]
}

/// `m += k·ℓ²`.
fn add_square(m: &mut Sym, l: &Affine, k: &Rational) {
    let h = hom(l);
    for i in 0..3 {
        for j in 0..3 {
            m[i][j] += Rational::from(&h[i] * &h[j]) * k;
        }
    }
}

/// `m += k·ℓ`.
fn add_linear(m: &mut Sym, l: &Affine, k: &Rational) {
    let h = hom(l);
    for i in 0..3 {
        let half = Rational::from(&h[i] * k) / 2u32;
        m[i][2] += &half;
        m[2][i] += half;
    }
}

fn to_conic(m: &Sym) -> Conic {
    let a = [
        [m[0][0].clone(), m[0][1].clone()],
        [m[1][0].clone(), m[1][1].clone()],
    ];
    QuadricForm::from_parts(a, [m[0][2].clone(), m[1][2].clone()], m[2][2].clone())
}

/// `Tᵀ m T` for `(U, V, 1) = T·(ℓ, w, 1)`.
fn congruent(m: &Sym, t: &Sym) -> Sym {
    std::array::from_fn(|i| {
        std::array::from_fn(|j| {
            let mut s = Rational::new();
            for k in 0..3 {
                for l in 0..3 {
                    s += Rational::from(&t[k][i] * &m[k][l]) * &t[l][j];
                }
            }
            s
        })
    })
}

/// The rational chart `p + U·X̃ + V·Ỹ` of a conic's plane.
struct Chart<'a>(&'a ExactFrame);

impl Chart<'_> {
    /// `q·(P − p)` as an affine form.
    fn along(&self, q: &V3, p: &V3) -> Affine {
        let f = self.0;
        let w: V3 = std::array::from_fn(|i| Rational::from(&f.p[i] - &p[i]));
        [dot(q, &w), dot(q, &f.x), dot(q, &f.y)]
    }

    /// The coordinate `i` of `P`.
    fn coordinate(&self, i: usize) -> Affine {
        let f = self.0;
        [f.p[i].clone(), f.x[i].clone(), f.y[i].clone()]
    }

    /// `F(P(U, V))` of a quadric.
    fn restrict(&self, q: &QuadricForm<3>) -> Sym {
        let f = self.0;
        let e = [&f.x, &f.y];
        let g = q.half_gradient(&f.p);
        let mut m = zero_sym();
        for i in 0..2 {
            let ae = q.mul_a(e[i]);
            for j in 0..2 {
                m[j][i] = dot(e[j], &ae);
            }
            m[i][2] = dot(e[i], &g);
            m[2][i] = m[i][2].clone();
        }
        m[2][2] = q.eval(&f.p);
        m
    }
}

/// A framed conic seen in the chart: its local `X`, `Y` forms and its equation.
struct Placed<'a> {
    curve: &'a Analytic,
    gx: Rational,
    gy: Rational,
    x: Affine,
    y: Affine,
    equation: Sym,
}

fn place<'a>(curve: &'a Analytic, chart: &Chart<'_>) -> Option<Placed<'a>> {
    let f = exact_frame(curve);
    let (x, y) = (chart.along(&f.x, &f.p), chart.along(&f.y, &f.p));
    let (gx, gy) = (dot(&f.x, &f.x), dot(&f.y, &f.y));
    let q = |v: f64| Rational::from_f64(v);
    let one = Rational::from(1);
    let mut m = zero_sym();
    match curve.shape() {
        CurveShape::Circle { radius } => {
            add_square(&mut m, &x, &(Rational::from(1) / &gx));
            add_square(&mut m, &y, &(Rational::from(1) / &gy));
            m[2][2] -= q(radius)?.square();
        }
        CurveShape::Ellipse { a, b } | CurveShape::Hyperbola { a, b, .. } => {
            let sign = if matches!(curve.shape(), CurveShape::Ellipse { .. }) {
                1
            } else {
                -1
            };
            add_square(&mut m, &x, &(Rational::from(1) / (q(a)?.square() * &gx)));
            add_square(&mut m, &y, &(Rational::from(sign) / (q(b)?.square() * &gy)));
            m[2][2] -= &one;
        }
        CurveShape::Parabola { p } => {
            let (n, d) = gx.clone().into_numer_denom();
            if !n.is_perfect_square() || !d.is_perfect_square() {
                return None;
            }
            let len = Rational::from((n.sqrt(), d.sqrt()));
            add_square(&mut m, &y, &(Rational::from(1) / &gy));
            add_linear(&mut m, &x, &(-(q(p)? * 2u32) / len));
        }
        CurveShape::Helix { .. } => return None,
    }
    Some(Placed {
        curve,
        gx,
        gy,
        x,
        y,
        equation: m,
    })
}

/// The distinct real roots of `R_ℓ` (module doc); `None` if it vanishes identically.
fn form_roots(f1: &Sym, f2: &Sym, l: &Affine) -> Option<Vec<RealRoot>> {
    let (z, one) = (Rational::new, || Rational::from(1));
    // (U, V, 1) = T·(ℓ, w, 1).
    let t: Sym = if l[1].cmp0() != Ordering::Equal {
        let c = &l[1];
        [
            [
                one() / c,
                -Rational::from(&l[2] / c),
                -Rational::from(&l[0] / c),
            ],
            [z(), one(), z()],
            [z(), z(), one()],
        ]
    } else {
        let c = &l[2];
        [
            [z(), one(), z()],
            [
                one() / c,
                -Rational::from(&l[1] / c),
                -Rational::from(&l[0] / c),
            ],
            [z(), z(), one()],
        ]
    };
    let poly = |m: &Sym| Bivariate::from_conic(&to_conic(&congruent(m, &t))).in_y();
    let r = resultant(&poly(f1), &poly(f2))?;
    if r.is_zero() {
        return None;
    }
    real_roots(&r).ok()
}

/// A guard against a logic error turning into an endless loop (as in conic ∩ conic).
const MAX_STEPS: usize = 100_000;

/// The exact value of `ℓ` at the hit (module doc).
fn value_at(hit: &ConicHit, f1: &Sym, f2: &Sym, l: &Affine) -> Option<RealRoot> {
    if l[1].cmp0() == Ordering::Equal && l[2].cmp0() == Ordering::Equal {
        return real_roots(&crate::certify::univariate::Polynomial::from_coeffs(vec![
            -l[0].clone(),
            Rational::from(1),
        ]))
        .ok()?
        .pop();
    }
    let mut roots = form_roots(f1, f2, l)?;
    let (mut u, mut v) = (hit.x.clone(), hit.y.clone());
    for _ in 0..MAX_STEPS {
        let e = RatInterval::from_root(&u)
            .scale(&l[1])
            .add(&RatInterval::from_root(&v).scale(&l[2]))
            .add(&RatInterval::point(l[0].clone()));
        let meet: Vec<usize> = (0..roots.len())
            .filter(|&i| RatInterval::from_root(&roots[i]).meets(&e))
            .collect();
        match meet.as_slice() {
            [] => return None,
            [i] => return Some(roots[*i].clone()),
            _ => {
                u.refine();
                v.refine();
                for &i in &meet {
                    roots[i].refine();
                }
            }
        }
    }
    None
}

/// The correctly rounded parameters of the curve at local `X`, `Y` (exact), inside its
/// domain (an arc may pass a point more than once); `None`: Ziv's loop reached its cap.
fn curve_params(c: &Placed<'_>, x: &RealRoot, y: &RealRoot) -> Option<Vec<Rounded>> {
    let (sx, sy) = (
        compare_root(&mut x.clone(), &Rational::new()),
        compare_root(&mut y.clone(), &Rational::new()),
    );
    let (a, b) = match c.curve.shape() {
        CurveShape::Circle { radius } => (radius, radius),
        CurveShape::Ellipse { a, b } | CurveShape::Hyperbola { a, b, .. } => (a, b),
        _ => (1.0, 1.0),
    };
    let (mut xe, mut ye) = (x.clone(), y.clone());
    let mut local = |bits: u32| {
        let len = |g: &Rational| MpfrInterval::from_rational(g, bits).sqrt();
        (
            enclose_root(&mut xe, bits) / len(&c.gx) / MpfrInterval::point(a, bits),
            enclose_root(&mut ye, bits) / len(&c.gy) / MpfrInterval::point(b, bits),
        )
    };
    let (lo, hi) = c.curve.domain();
    let inside = |r: &Rounded| r.lo >= lo && r.hi <= hi;
    match c.curve.shape() {
        CurveShape::Circle { .. } | CurveShape::Ellipse { .. } => {
            let zero = sy == Ordering::Equal && sx == Ordering::Greater;
            let pi = sy == Ordering::Equal && sx == Ordering::Less;
            let mut at = |k: i64| -> Option<Rounded> {
                if zero && k == 0 {
                    return Some(Rounded::exact(0.0));
                }
                if pi && k == 0 {
                    return special_angle(true);
                }
                correctly_rounded(|bits| {
                    let (x, y) = local(bits);
                    let t = if sy == Ordering::Equal {
                        x.pi_like() * MpfrInterval::point(if zero { 0.0 } else { 1.0 }, bits)
                    } else {
                        wrapped_angle(&y, &x)
                    };
                    let turns = t.pi_like() * MpfrInterval::point(2.0 * k as f64, bits);
                    t + turns
                })
            };
            if c.curve.is_closed() {
                return Some(vec![at(0)?]);
            }
            if hi - lo > 1e6 {
                return None;
            }
            let (k0, k1) = ((lo / TAU).floor() as i64 - 1, (hi / TAU).ceil() as i64 + 1);
            let mut out = Vec::new();
            for k in k0..=k1 {
                let r = at(k)?;
                if inside(&r) {
                    out.push(r);
                }
            }
            Some(out)
        }
        CurveShape::Hyperbola { .. } => {
            let r = if sy == Ordering::Equal {
                Rounded::exact(0.0)
            } else {
                // asinh(y) = sign(y)·ln(|y| + √(y² + 1)).
                correctly_rounded(|bits| {
                    let (_, y) = local(bits);
                    let one = MpfrInterval::point(1.0, bits);
                    let ay = if sy == Ordering::Less { -y } else { y };
                    let v = (ay.clone() + (ay.sqr() + one).sqrt()).ln();
                    if sy == Ordering::Less {
                        -v
                    } else {
                        v
                    }
                })?
            };
            Some(if inside(&r) { vec![r] } else { vec![] })
        }
        _ => {
            // The parabola's y = Y/|Ỹ|: exact when it is rational.
            let exact = y.exact().and_then(|y| {
                let (n, d) = (y.clone().square() / &c.gy).into_numer_denom();
                (n.is_perfect_square() && d.is_perfect_square()).then(|| {
                    let v = Rational::from((n.sqrt(), d.sqrt()));
                    if sy == Ordering::Less {
                        -v
                    } else {
                        v
                    }
                })
            });
            let r = match exact {
                Some(v) => round_rational(&v),
                None => correctly_rounded(|bits| local(bits).1)?,
            };
            Some(if inside(&r) { vec![r] } else { vec![] })
        }
    }
}

/// Whether the hit's local `X` is on the curve's branch (hyperbola) — every point of
/// the other conics' equations is on them.
fn on_branch(c: &Placed<'_>, x: &RealRoot) -> bool {
    match c.curve.shape() {
        CurveShape::Hyperbola { second_branch, .. } => {
            compare_root(&mut x.clone(), &Rational::new())
                == if second_branch {
                    Ordering::Less
                } else {
                    Ordering::Greater
                }
        }
        _ => true,
    }
}

/// The two conics of the chart intersected, and what is reported for each hit.
enum Cut {
    Same,
    Hits(Certified<ConicCut>),
}

fn cut(f1: &Sym, f2: &Sym, deadline: Option<std::time::Instant>) -> Option<Cut> {
    let c = intersect_conic_conic_until(&to_conic(f1), &to_conic(f2), deadline).ok()?;
    Some(match c.value {
        ConicCut::Coincident => Cut::Same,
        ConicCut::CommonComponent => return None,
        ConicCut::Points(_) => Cut::Hits(c),
    })
}

/// The reported point of a hit on the curves `curves` (the first one's parameters first
/// unless `swap`), with `None` slots for a shape without parameters.
fn points_of(
    cut: &Certified<ConicCut>,
    chart: &Chart<'_>,
    f: [&Sym; 2],
    curves: [Option<&Placed<'_>>; 2],
) -> Option<Vec<Point>> {
    let mut out = Vec::new();
    for hit in cut.value.points() {
        let value = |l: &Affine| value_at(hit, f[0], f[1], l);
        let mut params: Vec<Vec<Rounded>> = Vec::new();
        let mut keep = true;
        for c in curves {
            let Some(c) = c else {
                params.push(Vec::new());
                continue;
            };
            let (x, y) = (value(&c.x)?, value(&c.y)?);
            if !on_branch(c, &x) {
                keep = false;
                break;
            }
            let ts = curve_params(c, &x, &y)?;
            keep &= !ts.is_empty();
            params.push(ts);
        }
        if !keep {
            continue;
        }
        let xyz: Vec<RealRoot> = (0..3)
            .map(|i| value(&chart.coordinate(i)))
            .collect::<Option<_>>()?;
        let rounded: Vec<Rounded> = xyz.iter().map(RealRoot::rounded).collect();
        let exact_xyz: Option<Vec<Rational>> = xyz.iter().map(|r| r.exact().cloned()).collect();
        // Every combination of the two curves' parameters (an arc may pass twice).
        let slots = |k: usize| -> Vec<Option<Rounded>> {
            if curves[k].is_none() {
                vec![None]
            } else {
                params[k].iter().copied().map(Some).collect()
            }
        };
        for t0 in slots(0) {
            for t1 in slots(1) {
                let ts = [t0, t1];
                let value = |t: &Option<Rounded>| t.iter().map(|r| r.nearest).collect();
                let bounds = |t: &Option<Rounded>| t.iter().map(|r| [r.lo, r.hi]).collect();
                let exact_t = |t: &Option<Rounded>| {
                    t.iter()
                        .filter(|r| r.lo == r.hi)
                        .filter_map(|r| Rational::from_f64(r.nearest))
                        .collect::<Vec<_>>()
                };
                out.push(Point {
                    xyz: rounded.iter().map(|r| r.nearest).collect(),
                    xyz_box: rounded.iter().map(|r| [r.lo, r.hi]).collect(),
                    params: ts.iter().map(value).collect(),
                    param_box: Some(ts.iter().map(bounds).collect()),
                    multiplicity: hit.multiplicity,
                    tangent: hit.multiplicity >= 2,
                    exact: exact_xyz.clone().map(|xyz| ExactPoint {
                        xyz,
                        params: ts.iter().map(exact_t).collect(),
                        distance_squared: None,
                    }),
                    ..Default::default()
                });
            }
        }
    }
    Some(out)
}

fn answer(cut: &Certified<ConicCut>, points: Vec<Point>) -> Certified<Answer> {
    let mut r = cut.clone_with(Answer::from_points(points));
    if r.status == Status::Undecided {
        r.value = Answer::Empty;
    }
    r
}

/// Two conics in one plane (module doc), the first one's parameters first; `None`
/// where the module doc leaves the pair to the numeric certifier.
pub(crate) fn coplanar_conics(
    a: &Analytic,
    b: &Analytic,
    deadline: Option<std::time::Instant>,
) -> Option<Certified<Answer>> {
    let frame = exact_frame(a);
    let chart = Chart(&frame);
    let (pa, pb) = (place(a, &chart)?, place(b, &chart)?);
    match cut(&pa.equation, &pb.equation, deadline)? {
        Cut::Same => {
            if !(a.is_closed() && b.is_closed()) {
                return None;
            }
            let mut r = Certified::exact(Answer::Coincident, Arithmetic::Rational, 53);
            r.reason = Some("the two conics are the same curve".into());
            Some(r)
        }
        Cut::Hits(c) => {
            let f = [&pa.equation, &pb.equation];
            let pts = points_of(&c, &chart, f, [Some(&pa), Some(&pb)])?;
            Some(answer(&c, pts))
        }
    }
}

/// A framed conic against an implicit quadric (module doc), the curve's parameter first
/// or second as in the input; `None` where the module doc leaves the pair to the
/// numeric certifier.
pub(crate) fn conic_quadric(
    curve: &Analytic,
    quadric: &QuadricForm<3>,
    curve_first: bool,
    deadline: Option<std::time::Instant>,
) -> Option<Certified<Answer>> {
    let frame = exact_frame(curve);
    let chart = Chart(&frame);
    let placed = place(curve, &chart)?;
    let section = chart.restrict(quadric);
    let on = || {
        let mut r = Certified::exact(Answer::Coincident, Arithmetic::Rational, 53);
        r.reason = Some("the curve lies on the quadric".into());
        Some(r)
    };
    if section
        .iter()
        .flatten()
        .all(|x| x.cmp0() == Ordering::Equal)
    {
        return on();
    }
    match cut(&placed.equation, &section, deadline)? {
        Cut::Same => on(),
        Cut::Hits(c) => {
            let f = [&placed.equation, &section];
            let mut pts = points_of(&c, &chart, f, [Some(&placed), None])?;
            if !curve_first {
                for p in &mut pts {
                    p.params.swap(0, 1);
                    if let Some(b) = &mut p.param_box {
                        b.swap(0, 1);
                    }
                    if let Some(e) = &mut p.exact {
                        e.params.swap(0, 1);
                    }
                }
            }
            Some(answer(&c, pts))
        }
    }
}
