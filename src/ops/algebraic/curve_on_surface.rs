//! A curve lying on a surface, answered exactly (issue 14 items 8–9): a circle or
//! ellipse on a whole sphere, ellipsoid or ring torus (parallels, meridians, Villarceau
//! circles, the circular sections of an ellipsoid), a circle on a cylinder, hyperboloid
//! or paraboloid about the same axis, and a line on a cylinder or a hyperboloid of one
//! sheet (its rulings). Whether the curve lies on the implicit surface is the exact
//! polynomial identity of [`super::on_surface`]; this module decides which part of it
//! the surface's domain covers and shapes the answer.
//!
//! - Whole closed surfaces (natural domain): the curve lies on the surface, kind
//!   `coincident` (every point of the curve is common), reason "the curve lies on the
//!   surface" — as a conic lying in a plane ([`super::conic_plane`]).
//! - Surfaces trimmed along their axis (`height`, `range`, a `v` domain) over the full
//!   turn in `u`: with `ζ(x) = (x − o)·Z̃/|Z̃|` the local height, the surface covers the
//!   implicit quadric where `ζ ∈ [ζ₀, ζ₁]`: `[h₀, h₁]` for a cylinder, `c·sinh` of the
//!   range for a hyperboloid of one sheet, `c·cosh` of `[min |v|, max |v|]` for one of
//!   two sheets (only its `+Z` sheet), `[min v², max v²]` for a paraboloid. A circle
//!   in a plane normal to the axis has one height `ζ` (`coincident` when it lies in
//!   `[ζ₀, ζ₁]`, else `empty`); a line `o + t·d` covers `t` from `ζ₀` to `ζ₁`,
//!   `t = (ζ|Z̃| − (o − o_s)·Z̃)/(d·Z̃)`, cut to the line's own range: a segment (kind
//!   `segment`, its ends with their line parameter), one point, or `empty`.
//!
//! Every comparison is exact: rationals directly; an irrational height or parameter
//! (a quotient by `|Z̃|` when `|Z̃|²` is not a rational square, or `c·sinh v`,
//! `c·cosh v` with `v ≠ 0`, transcendental by Lindemann–Weierstrass) by MPFR
//! enclosures refined until they separate, which ends because the two numbers
//! compared are different (an irrational against a rational, an algebraic against a
//! transcendental). End coordinates are correctly rounded: rationals directly,
//! irrational ones (`oᵢ + t·dᵢ`, `dᵢ ≠ 0`) by Ziv's loop ([`correctly_rounded`]). Where
//! a loop reaches its cap the pair is left to the numeric certifier (`None`), as are
//! tilted circles on trimmed surfaces, restricted `u` domains, and cones (whose
//! half-angle has a transcendental tangent: a line or circle of rational data never lies
//! exactly on such a cone).

use rug::Rational;
use std::cmp::Ordering;
use std::rc::Rc;

use super::on_surface::{conic_frame, cross, Implicit, V3};
use super::pairs::{line3, ExactLine};
use crate::certificate::{Arithmetic, Certified};
use crate::curve::AnyCurve3;
use crate::num::round::{round_rational, Rounded};
use crate::num::MpfrInterval;
use crate::ops::answer::{Answer, ExactPoint, Point, SegmentAnswer};
use crate::ops::closed_surface::is_closed_shell;
use crate::ops::rational::exact::dot;
use crate::ops::rational::rounding::{correctly_rounded, PRECISION_CAP};
use crate::ops::rational::surd::rational_sqrt;
use crate::ops::shape::Linear;
use crate::surface::quadrics::Sheets;
use crate::surface::validate::FULL_TURN;
use crate::surface::{AnySurface, Surface};

/// A real number: rational, or proven irrational and known by its enclosures.
#[derive(Clone)]
enum Num {
    Exact(Rational),
    Irrational(Rc<dyn Fn(u32) -> MpfrInterval>),
}

impl Num {
    fn enclose(&self, bits: u32) -> MpfrInterval {
        match self {
            Num::Exact(q) => MpfrInterval::from_rational(q, bits),
            Num::Irrational(f) => f(bits),
        }
    }

    /// The exact order; `None` when the enclosures do not separate within the cap
    /// (never for two different numbers of which one is irrational, module doc).
    fn cmp(&self, o: &Num) -> Option<Ordering> {
        if let (Num::Exact(a), Num::Exact(b)) = (self, o) {
            return Some(a.cmp(b));
        }
        let mut bits = 64;
        while bits <= PRECISION_CAP {
            let d = self.enclose(bits) - o.enclose(bits);
            if *d.lo() > 0 {
                return Some(Ordering::Greater);
            }
            if *d.hi() < 0 {
                return Some(Ordering::Less);
            }
            bits *= 2;
        }
        None
    }

    /// `(self·√l2 − n0)/n1` (`n1 ≠ 0`): rational when `self` is zero or rational with
    /// `l2` a rational square; otherwise irrational.
    fn affine_over_sqrt(&self, l2: &Rational, n0: &Rational, n1: &Rational) -> Num {
        if let Num::Exact(z) = self {
            let l = if z.cmp0() == Ordering::Equal {
                Some(Rational::new())
            } else {
                rational_sqrt(l2)
            };
            if let Some(l) = l {
                return Num::Exact((Rational::from(z * &l) - n0) / n1);
            }
        }
        let (z, l2, n0, n1) = (self.clone(), l2.clone(), n0.clone(), n1.clone());
        Num::Irrational(Rc::new(move |bits| {
            let q = |x: &Rational| MpfrInterval::from_rational(x, bits);
            (z.enclose(bits) * q(&l2).sqrt() - q(&n0)) / q(&n1)
        }))
    }
}

/// The height interval `[ζ₀, ζ₁]` a trimmed axial surface covers, with its frame
/// origin and axis; `None` for other surfaces or a restricted `u`.
struct Axial {
    origin: V3,
    axis: V3,
    zeta: [Num; 2],
}

fn q3(v: [f64; 3]) -> Option<V3> {
    let [a, b, c] = v.map(Rational::from_f64);
    Some([a?, b?, c?])
}

/// `[min |v|, max |v|]` over `[v0, v1]`.
fn abs_range([v0, v1]: [f64; 2]) -> [f64; 2] {
    if v0 <= 0.0 && 0.0 <= v1 {
        [0.0, v0.abs().max(v1.abs())]
    } else {
        [v0.abs().min(v1.abs()), v0.abs().max(v1.abs())]
    }
}

/// `c·f(v)` for `f` = sinh or cosh: rational at `v = 0`, transcendental otherwise.
fn hyperbolic(c: f64, v: f64, cosh: bool) -> Option<Num> {
    let cq = Rational::from_f64(c)?;
    if v == 0.0 {
        return Some(Num::Exact(if cosh { cq } else { Rational::new() }));
    }
    Some(Num::Irrational(Rc::new(move |bits| {
        let x = MpfrInterval::point(v, bits);
        let f = if cosh { x.cosh() } else { x.sinh() };
        MpfrInterval::from_rational(&cq, bits) * f
    })))
}

fn axial(surface: &AnySurface) -> Option<Axial> {
    let (u, [v0, v1]) = surface.domain();
    if u != FULL_TURN {
        return None;
    }
    let exact = |x: f64| Rational::from_f64(x).map(Num::Exact);
    let (frame, zeta) = match surface {
        AnySurface::Cylinder(c) => (c.frame(), [exact(v0)?, exact(v1)?]),
        AnySurface::Paraboloid(p) => {
            let [m, big] = abs_range([v0, v1]);
            let sq = |x: f64| Rational::from_f64(x).map(|q| Num::Exact(q.square()));
            (p.frame(), [sq(m)?, sq(big)?])
        }
        AnySurface::Hyperboloid(h) => {
            let c = h.semi_axes()[2];
            let zeta = match h.sheets() {
                Sheets::One => [hyperbolic(c, v0, false)?, hyperbolic(c, v1, false)?],
                Sheets::Two => {
                    let [m, big] = abs_range([v0, v1]);
                    [hyperbolic(c, m, true)?, hyperbolic(c, big, true)?]
                }
            };
            (h.frame(), zeta)
        }
        _ => return None,
    };
    Some(Axial {
        origin: q3(frame.origin())?,
        axis: q3(frame.axis())?,
        zeta,
    })
}

fn sub(a: &V3, b: &V3) -> V3 {
    std::array::from_fn(|i| Rational::from(&a[i] - &b[i]))
}

fn exact_answer(value: Answer, reason: &str) -> Certified<Answer> {
    let mut r = Certified::exact(value, Arithmetic::Rational, 53);
    r.reason = Some(reason.into());
    r
}

const ON: &str = "the curve lies on the surface";
const OFF: &str = "the curve lies on the surface's implicit form, outside its height or range";

/// A circle or ellipse lying on the surface: `coincident` or `empty` (module doc);
/// `None` when the curve does not lie on the implicit surface or the case is left to
/// the numeric certifier.
pub(crate) fn curve_on_surface(
    curve: &AnyCurve3,
    surface: &AnySurface,
) -> Option<Certified<Answer>> {
    let AnyCurve3::Analytic(c) = curve else {
        return None;
    };
    let frame = conic_frame(c)?;
    let closed = is_closed_shell(surface)
        && !matches!(surface, AnySurface::Torus(t) if t.minor() >= t.major());
    let trimmed = if closed { None } else { Some(axial(surface)?) };
    if !Implicit::of(surface)?.contains_conic(&frame)? {
        return None;
    }
    let Some(ax) = trimmed else {
        return Some(exact_answer(Answer::Coincident, ON));
    };
    // One height only when the curve's plane is normal to the axis.
    if cross(&frame.z, &ax.axis)
        .iter()
        .any(|x| x.cmp0() != Ordering::Equal)
    {
        return None;
    }
    let l2 = dot(&ax.axis, &ax.axis);
    let n = dot(&sub(&frame.p, &ax.origin), &ax.axis);
    // ζ = n/√l2 = (n·√(1/l2) − 0)/1.
    let zeta = Num::Exact(n).affine_over_sqrt(&l2.recip(), &Rational::new(), &Rational::from(1));
    let inside =
        zeta.cmp(&ax.zeta[0])? != Ordering::Less && zeta.cmp(&ax.zeta[1])? != Ordering::Greater;
    Some(if inside {
        exact_answer(Answer::Coincident, ON)
    } else {
        exact_answer(Answer::Empty, OFF)
    })
}

/// A line or segment lying on a trimmed cylinder or hyperboloid: the covered part
/// (module doc); `None` when it does not lie on the implicit surface or the case is
/// left to the numeric certifier.
pub(crate) fn line_on_surface(
    line: &Linear,
    surface: &AnySurface,
    line_first: bool,
) -> Option<Certified<Answer>> {
    let ax = axial(surface)?;
    let line = line3(line)?;
    if !Implicit::of(surface)?.contains_line(&line.o, &line.d) {
        return None;
    }
    let l2 = dot(&ax.axis, &ax.axis);
    let n0 = dot(&sub(&line.o, &ax.origin), &ax.axis);
    let n1 = dot(&line.d, &ax.axis);
    if n1.cmp0() == Ordering::Equal {
        return None;
    }
    let [t0, t1] = ax.zeta.map(|z| z.affine_over_sqrt(&l2, &n0, &n1));
    let [mut lo, mut hi] = if n1.cmp0() == Ordering::Greater {
        [t0, t1]
    } else {
        [t1, t0]
    };
    if let Some([r0, r1]) = &line.range {
        let (r0, r1) = (Num::Exact(r0.clone()), Num::Exact(r1.clone()));
        if lo.cmp(&r0)? == Ordering::Less {
            lo = r0;
        }
        if hi.cmp(&r1)? == Ordering::Greater {
            hi = r1;
        }
    }
    let value = match lo.cmp(&hi)? {
        Ordering::Greater => return Some(exact_answer(Answer::Empty, OFF)),
        Ordering::Equal => Answer::Points(vec![end(&line, &lo, line_first)?]),
        Ordering::Less => Answer::Segment(SegmentAnswer {
            a: end(&line, &lo, line_first)?,
            b: end(&line, &hi, line_first)?,
        }),
    };
    Some(exact_answer(
        value,
        "the line lies on the surface along this part",
    ))
}

/// `x` correctly rounded: rationals directly, irrationals by Ziv's loop.
fn rounded(x: &Num) -> Option<Rounded> {
    match x {
        Num::Exact(q) => Some(round_rational(q)),
        Num::Irrational(_) => correctly_rounded(|bits| x.enclose(bits)),
    }
}

/// An end of the covered part at the line parameter `t`: the point `o + t·d` and `t`,
/// correctly rounded, with the exact rationals when `t` is rational.
fn end(line: &ExactLine<3>, t: &Num, line_first: bool) -> Option<Point> {
    let coords: Vec<Num> = (0..3)
        .map(|i| match t {
            Num::Exact(t) => Num::Exact(Rational::from(&line.d[i] * t) + &line.o[i]),
            _ if line.d[i].cmp0() == Ordering::Equal => Num::Exact(line.o[i].clone()),
            _ => {
                let (t, o, d) = (t.clone(), line.o[i].clone(), line.d[i].clone());
                Num::Irrational(Rc::new(move |bits| {
                    let q = |x: &Rational| MpfrInterval::from_rational(x, bits);
                    q(&o) + t.enclose(bits) * q(&d)
                }))
            }
        })
        .collect();
    let xyz: Vec<Rounded> = coords.iter().map(rounded).collect::<Option<_>>()?;
    let tr = rounded(t)?;
    let order = |mine: Vec<f64>| {
        if line_first {
            vec![mine, vec![]]
        } else {
            vec![vec![], mine]
        }
    };
    let order_box = |mine: Vec<[f64; 2]>| {
        if line_first {
            vec![mine, vec![]]
        } else {
            vec![vec![], mine]
        }
    };
    let exact = match t {
        Num::Exact(tq) => Some(ExactPoint {
            xyz: (0..3)
                .map(|i| Rational::from(&line.d[i] * tq) + &line.o[i])
                .collect(),
            params: if line_first {
                vec![vec![tq.clone()], vec![]]
            } else {
                vec![vec![], vec![tq.clone()]]
            },
            distance_squared: None,
        }),
        Num::Irrational(_) => None,
    };
    Some(Point {
        xyz: xyz.iter().map(|r| r.nearest).collect(),
        xyz_box: xyz.iter().map(|r| [r.lo, r.hi]).collect(),
        params: order(vec![tr.nearest]),
        param_box: Some(order_box(vec![[tr.lo, tr.hi]])),
        multiplicity: 1,
        exact,
        ..Default::default()
    })
}
