//! Answers built from an exact plane section (OPERATIONS.md §13.2) when the section is the
//! whole intersection: a plane or a sphere against a whole sphere or ellipsoid (the
//! radical-plane argument of [`crate::ops::section`]), three spheres through one point.
//!
//! - A touching point (`ConicType::Point`) becomes a `points` answer with the exact
//!   point, multiplicity 2 and `tangent`, and each shape's parameters correctly rounded
//!   where Ziv's loop decides ([`super::params::line_hit_params`] at `t = 0`), else
//!   enclosed and the status lowered to `verified`.
//! - A circle or an ellipse becomes a closed polyline sampled on the exact conic:
//!   vertex `k` is `C + a cos θₖ·d₁ + b sin θₖ·d₂` at the double `θₖ = 2πk/n`,
//!   evaluated in outward-rounded f64 intervals from the enclosures of the exact centre,
//!   unit axes and semi-axes (their `Value` bounds), so the box of each vertex holds a
//!   point of the true curve; the reported vertex is the box's midpoint and its bound
//!   the largest distance from it to a point of the box (rounded up). `n` keeps the
//!   chord's sagitta `a(1 − cos(π/n))` under the chord tolerance (§9.3's criterion).

use rug::Rational;

use super::pairs::{closed, frame_of, not_correctly_rounded, surface_params, Closed};
use super::params::line_hit_params;
use crate::certificate::{Arithmetic, Certified, Status};
use crate::certify::univariate::{real_roots, Polynomial};
use crate::geom::Plane;
use crate::num::round::round_rational;
use crate::num::Interval;
use crate::ops::answer::{
    Answer, Bounds, CurveAnswer, CurveEnd, CurveVertex, CurvesAnswer, ExactPoint, Point,
};
use crate::ops::section::{ConicType, Section, Value};
use crate::ops::shape::{LinearObject, Shape};

type V3 = [Rational; 3];

/// Where a shape's parameters come from.
pub(crate) enum ParamSource {
    /// A whole closed surface.
    Closed(Box<Closed>),
    /// A parametric plane `o + s·u + t·v` (exact).
    Plane(Box<[V3; 3]>),
    /// No parameters (an implicit plane), or none that can be given.
    None,
}

impl ParamSource {
    /// The parameter source of an input shape.
    pub(crate) fn of(shape: &Shape) -> ParamSource {
        match shape {
            Shape::Surface(s) => {
                closed(s).map_or(ParamSource::None, |c| ParamSource::Closed(Box::new(c)))
            }
            Shape::Linear(l) => match l.exact() {
                LinearObject::Plane(Plane::Parametric { origin, u, v }) => {
                    let a = |x: &nalgebra::Vector3<Rational>| -> V3 {
                        std::array::from_fn(|i| x[i].clone())
                    };
                    ParamSource::Plane(Box::new([a(&origin), a(&u), a(&v)]))
                }
                _ => ParamSource::None,
            },
            _ => ParamSource::None,
        }
    }

    /// The parameters of the exact point `p`: estimates, enclosures, and whether the
    /// estimates are correctly rounded.
    fn exact(&self, p: &V3) -> (Vec<f64>, Vec<Bounds>, bool) {
        match self {
            ParamSource::Closed(c) => {
                // The point as the hit t = 0 of a line through it (any direction).
                let zero = real_roots(&Polynomial::x())
                    .ok()
                    .and_then(|r| r.into_iter().next());
                let d: V3 = [Rational::from(1), Rational::new(), Rational::new()];
                match zero.and_then(|z| line_hit_params(&frame_of(c), p, &d, &z)) {
                    Some(ps) => (
                        ps.iter().map(|x| x.0).collect(),
                        ps.iter().map(|x| x.1).collect(),
                        true,
                    ),
                    None => {
                        let b = p.clone().map(|x| enclose(&x));
                        let ps = surface_params(c, &b);
                        (
                            ps.iter().map(|x| x.0).collect(),
                            ps.iter().map(|x| x.1).collect(),
                            false,
                        )
                    }
                }
            }
            ParamSource::Plane(f) => {
                let st = plane_params(f, p);
                let r = st.map(|x| round_rational(&x));
                (
                    r.iter().map(|x| x.nearest).collect(),
                    r.iter().map(|x| [x.lo, x.hi]).collect(),
                    true,
                )
            }
            ParamSource::None => (vec![], vec![], true),
        }
    }

    /// Parameter estimates of a point of the box `b`.
    fn estimate(&self, b: &[Interval; 3]) -> Vec<f64> {
        match self {
            ParamSource::Closed(c) => surface_params(c, b).iter().map(|x| x.0).collect(),
            ParamSource::Plane(f) => {
                let p: V3 = b.map(|x| Rational::from_f64(x.midpoint()).unwrap_or_default());
                plane_params(f, &p).iter().map(|x| x.to_f64()).collect()
            }
            ParamSource::None => vec![],
        }
    }
}

fn enclose(x: &Rational) -> Interval {
    let r = round_rational(x);
    Interval::from_bounds(r.lo, r.hi)
}

fn dot(a: &V3, b: &V3) -> Rational {
    let mut s = Rational::new();
    for (x, y) in a.iter().zip(b) {
        s += Rational::from(x * y);
    }
    s
}

/// `(s, t)` with `o + s·u + t·v` the point of the plane nearest `p` (the normal
/// equations of the Gram matrix; `p` on the plane gives it exactly).
fn plane_params([o, u, v]: &[V3; 3], p: &V3) -> [Rational; 2] {
    let w: V3 = std::array::from_fn(|i| Rational::from(&p[i] - &o[i]));
    let (uu, uv, vv) = (dot(u, u), dot(u, v), dot(v, v));
    let (wu, wv) = (dot(&w, u), dot(&w, v));
    let det = Rational::from(&uu * &vv) - Rational::from(&uv * &uv);
    if det == 0 {
        return [Rational::new(), Rational::new()];
    }
    let s = (Rational::from(&wu * &vv) - Rational::from(&wv * &uv)) / &det;
    let t = (Rational::from(&uu * &wv) - Rational::from(&uv * &wu)) / det;
    [s, t]
}

/// The exact touching point `p` of the shapes as a `points` answer (module doc);
/// `bits` is the certificate's width.
pub(crate) fn touching_point(p: &V3, shapes: &[ParamSource], bits: u32) -> Certified<Answer> {
    let mut rounded = true;
    let (mut params, mut boxes) = (Vec::new(), Vec::new());
    for s in shapes {
        let (e, b, r) = s.exact(p);
        rounded &= r;
        params.push(e);
        boxes.push(b);
    }
    let r = p.clone().map(|x| round_rational(&x));
    let point = Point {
        xyz: r.iter().map(|x| x.nearest).collect(),
        xyz_box: r.iter().map(|x| [x.lo, x.hi]).collect(),
        params,
        param_box: Some(boxes),
        multiplicity: 2,
        tangent: true,
        exact: Some(ExactPoint {
            xyz: p.to_vec(),
            params: vec![vec![]; shapes.len()],
            distance_squared: None,
        }),
        ..Default::default()
    };
    let mut c = Certified::exact(Answer::Points(vec![point]), Arithmetic::Rational, bits);
    if !rounded {
        not_correctly_rounded(&mut c);
    }
    c
}

/// The exact touching point of a `Point` section (its centre); `None` otherwise.
pub(crate) fn section_point(s: &Section) -> Option<V3> {
    if s.kind != ConicType::Point {
        return None;
    }
    let c = s.center.as_ref()?;
    Some(c.clone())
}

fn interval(v: &Value) -> Interval {
    Interval::from_bounds(v.bounds[0], v.bounds[1])
}

/// The closed polyline of a circle or an ellipse sampled on the exact conic (module
/// doc), with the shapes' parameter estimates; `None` for other conics.
pub(crate) fn sampled_conic(
    s: &Section,
    shapes: &[ParamSource],
    chord_tolerance: Option<f64>,
) -> Option<CurveAnswer> {
    if !matches!(s.kind, ConicType::Circle | ConicType::Ellipse) || s.axes.len() != 2 {
        return None;
    }
    let centre = s.center.as_ref()?.clone().map(|x| enclose(&x));
    let (a1, a2) = (&s.axes[0], &s.axes[1]);
    let (la, lb) = (interval(&a1.length), interval(&a2.length));
    let (d1, d2) = (
        a1.dir.clone().map(|x| interval(&x)),
        a2.dir.clone().map(|x| interval(&x)),
    );
    let n = vertex_count(la.hi().max(lb.hi()), chord_tolerance);
    let mut points = Vec::with_capacity(n + 1);
    let mut distance_bound: f64 = 0.0;
    for k in 0..n {
        let theta = Interval::point(2.0 * std::f64::consts::PI * k as f64 / n as f64);
        let (c, sn) = (theta.cos() * la, theta.sin() * lb);
        let b: [Interval; 3] = std::array::from_fn(|i| centre[i] + c * d1[i] + sn * d2[i]);
        let (xyz, bound) = midpoint_and_bound(&b);
        distance_bound = distance_bound.max(bound);
        points.push(CurveVertex {
            xyz: xyz.to_vec(),
            params: shapes.iter().map(|p| p.estimate(&b)).collect(),
            bound: Some(bound),
            exact: None,
        });
    }
    points.push(points[0].clone());
    Some(CurveAnswer {
        points,
        closed: true,
        ends: [CurveEnd::Closed; 2],
        distance_bound: Some(distance_bound),
        status: Status::Verified,
        reason: None,
    })
}

/// The number of vertices whose chords stay within `tolerance` of a conic of largest
/// semi-axis `a` (default tolerance `10⁻⁴·a`), between 16 and 65,536.
fn vertex_count(a: f64, tolerance: Option<f64>) -> usize {
    // The default is relative: `1e-4·a / a` would underflow to 0 (and ask for the cap)
    // on a subnormal conic (issue 20: a sphere of radius 1e-323 sampled 65,536 times).
    let ratio = tolerance.map_or(1e-4, |tol| (tol / a).min(1.0));
    // a(1 − cos(π/n)) ≤ tol  ⇔  n ≥ π / acos(1 − tol/a)
    let n = std::f64::consts::PI / (1.0 - ratio).acos();
    if n.is_finite() {
        (n.ceil() as usize).clamp(16, 1 << 16)
    } else {
        1 << 16
    }
}

/// The midpoint of a box and the largest distance from it to a point of the box,
/// rounded up.
fn midpoint_and_bound(b: &[Interval; 3]) -> ([f64; 3], f64) {
    let m = b.map(|x| x.midpoint());
    let mut sq = Interval::point(0.0);
    for (x, mi) in b.iter().zip(m) {
        let mi = Interval::point(mi);
        let d = (mi - Interval::point(x.lo()))
            .hi()
            .max((Interval::point(x.hi()) - mi).hi());
        sq += Interval::point(d).sqr();
    }
    (m, sq.sqrt().hi())
}

/// The exact section answered as a curves answer whose conic is attached: the polyline
/// of [`sampled_conic`] beside it, `verified` (every vertex proven within its bound of
/// the exact conic, which is the whole intersection: `complete`).
pub(crate) fn sampled_answer(
    exact: &Certified<Answer>,
    s: &Section,
    shapes: &[ParamSource],
    chord_tolerance: Option<f64>,
) -> Option<Certified<Answer>> {
    let curve = sampled_conic(s, shapes, chord_tolerance)?;
    let Answer::Curves(c) = &exact.value else {
        return None;
    };
    let value = Answer::Curves(CurvesAnswer {
        curves: vec![curve],
        ..c.clone()
    });
    let mut out = exact.clone_with(value);
    out.status = Status::Verified;
    out.arithmetic = Arithmetic::Interval;
    out.bits = 53;
    out.reason = None;
    Some(out)
}

#[cfg(test)]
mod tests {
    use super::vertex_count;

    /// The default chord tolerance is relative, so the count does not depend on the
    /// conic's size — from the smallest subnormal to the largest double (issue 20: a
    /// sphere of radius 1e-323 was sampled with the 65,536-vertex cap); an explicit
    /// tolerance of `1e-4·a` gives the same count wherever that product is exact.
    #[test]
    fn the_default_vertex_count_is_the_same_at_every_magnitude() {
        let n = vertex_count(1.0, None);
        // a(1 − cos(π/n)) ≤ 1e-4·a: n = ⌈π / acos(1 − 1e-4)⌉ = 223.
        assert_eq!(n, 223);
        for e in -1074..=1023 {
            // 2^e exactly, subnormals included (`powi` would underflow on the way).
            let a = if e >= -1022 {
                f64::from_bits(((e + 1023) as u64) << 52)
            } else {
                f64::from_bits(1u64 << (e + 1074))
            };
            assert_eq!(vertex_count(a, None), n, "a = 2^{e}");
            if (-900..900).contains(&e) {
                assert_eq!(vertex_count(a, Some(1e-4 * a)), n, "a = 2^{e}, explicit");
            }
        }
        assert_eq!(vertex_count(1.0, Some(2.0)), 16);
        assert_eq!(vertex_count(1.0, Some(0.0)), 1 << 16);
    }
}
