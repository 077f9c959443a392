//! A framed conic of space (circle, ellipse, hyperbola, parabola, OPERATIONS.md §1.5)
//! against a plane, decided exactly (issue 16; docs/CERTIFICATES.md `exact`).
//!
//! The conic lies in its own plane `Z̃·(x − p) = 0` (`Z̃ = axis`). The frame's unit
//! vectors are irrational in general, but with the unnormalised `X̃`, `Ỹ = Z̃ × X̃`
//! ([`frame_x_unnormalised`]) the local coordinates are `x = (q·X̃)/|X̃|`,
//! `y = (q·Ỹ)/|Ỹ|` (`q = x − p`), so every squared local coordinate is rational:
//!
//! - planes parallel (`Z̃ × n = 0`, exact): the conic lies in the plane (`n·p = h`) —
//!   answered as kind `coincident` with the reason "the curve lies in the plane" (every
//!   point of the curve is common; as a line lying in a plane is answered by the line
//!   itself) — or misses it (`empty`, reason `parallel`);
//! - else the two planes meet in the rational line `L = o + s·m`, `m = Z̃ × n`, and the
//!   common points are the points of `L` on the conic (a line ∩ conic in the conic's
//!   plane, §6.3): with `X(s) = (o−p)·X̃ + s m·X̃`, `Y(s)` likewise (affine, rational),
//!   circle `X²/|X̃|² + Y²/|Ỹ|² = r²`, ellipse `X²/(a²|X̃|²) + Y²/(b²|Ỹ|²) = 1`,
//!   hyperbola `… − … = 1` with the branch `sign X = ±1`, parabola `y² = 2p·x`, i.e.
//!   `Y²|X̃| = 2p|Ỹ|²X`, squared to the rational quartic `Y⁴ = 4p²|Ỹ|⁴X²/|X̃|²` whose
//!   roots with `X > 0` are exactly those of the true factor (the other factor
//!   `Y²|X̃| + 2p|Ỹ|²X` is positive there) and whose root `X = Y = 0` (the vertex) has
//!   twice the true multiplicity (both factors vanish to the same order there).
//!
//! The multiplicity of a root of the restricted polynomial is the intersection
//! multiplicity (the planes are transversal): 2 is a proven tangency. Coordinates are
//! `oᵢ + s·mᵢ` correctly rounded ([`round_affine`]). The curve's parameter is an angle
//! `atan2(y/b, x/a)` (circle, ellipse), `asinh(y/b)` (hyperbola) or `y` (parabola),
//! correctly rounded by Ziv's loop ([`super::rounding`]); its exact value is zero only
//! when `y = 0` (decided exactly), and otherwise never a double for the angle and the
//! asinh (Lindemann–Weierstrass: `e^{iθ}` and `sinh t` are transcendental at a non-zero
//! rational), so an arc's end points are compared with the correctly rounded value
//! (which lies strictly between two consecutive doubles). The parabola's `y` is
//! algebraic and compared with the ends exactly. Where Ziv's loop reaches its cap, the
//! pair is left to the numeric certifier (`None`).

use rug::Rational;
use std::cmp::Ordering;
use std::f64::consts::TAU;

use super::line::affine;
use crate::certificate::{Arithmetic, Certified};
use crate::certify::univariate::{real_roots, Polynomial, RealRoot};
use crate::curve::analytic::{Analytic, Shape as CurveShape};
use crate::curve::Curve;
use crate::geom::Plane as LinearPlane;
use crate::num::round::{round_rational, Rounded};
use crate::num::{MpfrInterval, Real};
use crate::ops::answer::{Answer, ExactPoint, Point};
use crate::ops::closed_surface::frame_x_unnormalised;
use crate::ops::rational::exact::{dot, round_affine, sign_at_root};
use crate::ops::rational::rounding::{correctly_rounded, enclose_root, wrapped_angle};
use crate::ops::shape::{Linear, LinearObject};

type V3 = [Rational; 3];

/// A plane `n·x = h`, exactly, with its parametrisation `origin + a·u + b·v` when it was
/// given so (its points then report `(a, b)`).
pub(crate) struct ExactPlane {
    pub(crate) n: V3,
    pub(crate) h: Rational,
    pub(crate) frame: Option<[V3; 3]>,
}

fn v3(v: impl Fn(usize) -> Rational) -> V3 {
    std::array::from_fn(v)
}

pub(crate) fn cross(a: &V3, b: &V3) -> V3 {
    v3(|i| {
        let (j, k) = ((i + 1) % 3, (i + 2) % 3);
        Rational::from(&a[j] * &b[k]) - Rational::from(&a[k] * &b[j])
    })
}

pub(super) fn is_zero(v: &V3) -> bool {
    v.iter().all(|x| x.cmp0() == Ordering::Equal)
}

/// The plane of the linear kernel, exactly (`normal·x + d = 0`: `h = −d`).
pub(crate) fn exact_plane(l: &Linear) -> Option<ExactPlane> {
    let LinearObject::Plane(p) = l.exact() else {
        return None;
    };
    Some(match p {
        LinearPlane::Implicit { normal, d } => ExactPlane {
            n: v3(|i| normal[i].clone()),
            h: -d,
            frame: None,
        },
        LinearPlane::Parametric { origin, u, v } => {
            let (o, u, v) = (
                v3(|i| origin[i].clone()),
                v3(|i| u[i].clone()),
                v3(|i| v[i].clone()),
            );
            let n = cross(&u, &v);
            ExactPlane {
                h: dot(&n, &o),
                n,
                frame: Some([o, u, v]),
            }
        }
    })
}

impl ExactPlane {
    /// `(a, b)` of the point `q0 + s·m` of the plane, as affine functions of `s`
    /// (`[constant, slope]` each), from the Gram system of `u`, `v`.
    pub(crate) fn params_affine(&self, q0: &V3, m: &V3) -> Option<[[Rational; 2]; 2]> {
        let [o, u, v] = self.frame.as_ref()?;
        let w = v3(|i| Rational::from(&q0[i] - &o[i]));
        let (uu, uv, vv) = (dot(u, u), dot(u, v), dot(v, v));
        let det = Rational::from(&uu * &vv) - Rational::from(&uv * &uv);
        let solve = |ru: Rational, rv: Rational| {
            let a = (Rational::from(&vv * &ru) - Rational::from(&uv * &rv)) / &det;
            let b = (Rational::from(&uu * &rv) - Rational::from(&uv * &ru)) / &det;
            [a, b]
        };
        let c = solve(dot(u, &w), dot(v, &w));
        let d = solve(dot(u, m), dot(v, m));
        Some([[c[0].clone(), d[0].clone()], [c[1].clone(), d[1].clone()]])
    }
}

/// The conic's frame, exactly: origin, `X̃`, `Ỹ`, `Z̃`.
pub(super) struct ExactFrame {
    pub(super) p: V3,
    pub(super) x: V3,
    pub(super) y: V3,
    pub(super) z: V3,
}

pub(super) fn exact_frame(c: &Analytic) -> ExactFrame {
    let f = c.frame();
    let q = |v: [f64; 3]| v3(|i| Rational::from_f64(v[i]).unwrap_or_default());
    let z = q(f.axis());
    let x = frame_x_unnormalised(&f.axis(), f.reference().as_ref());
    let y = cross(&z, &x);
    ExactFrame {
        p: q(f.origin()),
        x,
        y,
        z,
    }
}

/// A common point before its parameters: the line parameter `s`.
pub(super) struct Hit {
    pub(super) s: RealRoot,
    pub(super) multiplicity: u32,
    /// Exact signs of the local `x` and `y`.
    pub(super) sx: Ordering,
    pub(super) sy: Ordering,
}

/// Everything the parameters of a hit need.
pub(super) struct Local<'a> {
    pub(super) frame: &'a ExactFrame,
    pub(super) o: &'a V3,
    pub(super) m: &'a V3,
    pub(super) shape: CurveShape,
}

impl Local<'_> {
    /// `(x, y)` local coordinates (divided by the semi-axes for circle and ellipse)
    /// enclosed at `bits`.
    fn xy(&self, s: &mut RealRoot, bits: u32) -> (MpfrInterval, MpfrInterval) {
        let ss = enclose_root(s, bits);
        let q = |v: &Rational| MpfrInterval::from_rational(v, bits);
        let at = |e: &V3| {
            let w = v3(|i| Rational::from(&self.o[i] - &self.frame.p[i]));
            q(&dot(&w, e)) + ss.clone() * q(&dot(self.m, e))
        };
        let len = |e: &V3| q(&dot(e, e)).sqrt();
        let (x, y) = (
            at(&self.frame.x) / len(&self.frame.x),
            at(&self.frame.y) / len(&self.frame.y),
        );
        let (a, b) = match self.shape {
            CurveShape::Circle { radius } => (radius, radius),
            CurveShape::Ellipse { a, b } | CurveShape::Hyperbola { a, b, .. } => (a, b),
            _ => (1.0, 1.0),
        };
        (
            x / MpfrInterval::point(a, bits),
            y / MpfrInterval::point(b, bits),
        )
    }

    /// An enclosure of the curve parameter of the hit at `bits`.
    fn param(&self, hit: &Hit, s: &mut RealRoot, bits: u32) -> MpfrInterval {
        let (x, y) = self.xy(s, bits);
        match self.shape {
            CurveShape::Circle { .. } | CurveShape::Ellipse { .. } => {
                if hit.sy == Ordering::Equal {
                    // x < 0 (x = 0 = y is not on the curve): θ = π.
                    x.pi_like()
                } else {
                    wrapped_angle(&y, &x)
                }
            }
            // asinh(y) = sign(y)·ln(|y| + √(y² + 1)); y's sign is known and non-zero.
            CurveShape::Hyperbola { .. } => {
                let one = MpfrInterval::point(1.0, bits);
                let ay = if hit.sy == Ordering::Less { -y } else { y };
                let v = (ay.clone() + (ay.sqr() + one).sqrt()).ln();
                if hit.sy == Ordering::Less {
                    -v
                } else {
                    v
                }
            }
            _ => y,
        }
    }
}

/// The restricted equation of the conic on `L` (module doc), with the local `X(s)`,
/// `Y(s)` (unnormalised).
pub(super) fn restricted(
    shape: CurveShape,
    f: &ExactFrame,
    o: &V3,
    m: &V3,
) -> Option<(Polynomial, Polynomial, Polynomial)> {
    let w = v3(|i| Rational::from(&o[i] - &f.p[i]));
    let fx = affine(&dot(&w, &f.x), &dot(m, &f.x));
    let fy = affine(&dot(&w, &f.y), &dot(m, &f.y));
    let gx = Rational::from(1) / dot(&f.x, &f.x);
    let gy = Rational::from(1) / dot(&f.y, &f.y);
    let sq = |p: &Polynomial| p * p;
    let q = |v: f64| Rational::from_f64(v);
    let one = Polynomial::constant(Rational::from(1));
    let p = match shape {
        CurveShape::Circle { radius } => {
            let r2 = q(radius)?.square();
            &(&sq(&fx).scale(&gx) + &sq(&fy).scale(&gy)) - &Polynomial::constant(r2)
        }
        CurveShape::Ellipse { a, b } | CurveShape::Hyperbola { a, b, .. } => {
            let (a2, b2) = (q(a)?.square(), q(b)?.square());
            let ty = sq(&fy).scale(&(gy / b2));
            let tx = sq(&fx).scale(&(gx / a2));
            if matches!(shape, CurveShape::Ellipse { .. }) {
                &(&tx + &ty) - &one
            } else {
                &(&tx - &ty) - &one
            }
        }
        CurveShape::Parabola { p } => {
            // Y⁴/|Ỹ|⁴ = 4p²X²/|X̃|².
            let k = q(p)?.square() * 4u32 * gx;
            &sq(&sq(&fy)).scale(&gy.square()) - &sq(&fx).scale(&k)
        }
        CurveShape::Helix { .. } => return None,
    };
    Some((p, fx, fy))
}

/// The hits of `L` on the conic (branch and vertex rules of the module doc).
pub(super) fn hits(
    shape: CurveShape,
    p: &Polynomial,
    fx: &Polynomial,
    fy: &Polynomial,
) -> Vec<Hit> {
    let roots = real_roots(p).unwrap_or_default();
    roots
        .into_iter()
        .filter_map(|mut s| {
            let sx = sign_at_root(&mut s, fx);
            let sy = sign_at_root(&mut s, fy);
            let mut multiplicity = s.multiplicity();
            if !on_branch(shape, sx) {
                return None;
            }
            if matches!(shape, CurveShape::Parabola { .. }) && sx == Ordering::Equal {
                multiplicity /= 2;
            }
            Some(Hit {
                s,
                multiplicity,
                sx,
                sy,
            })
        })
        .collect()
}

/// Whether a zero of the restricted equation with local `x` of sign `sx` is a point of
/// the curve: the hyperbola's branch (`sign x = ±1`), the parabola's true factor
/// (`x ≥ 0`, module doc); every zero for circle and ellipse.
pub(super) fn on_branch(shape: CurveShape, sx: Ordering) -> bool {
    match shape {
        CurveShape::Hyperbola { second_branch, .. } => {
            sx == if second_branch {
                Ordering::Less
            } else {
                Ordering::Greater
            }
        }
        CurveShape::Parabola { .. } => sx != Ordering::Less,
        _ => true,
    }
}

/// `Y/|Ỹ|` compared with the double `e`, exactly (the parabola's parameter).
fn compare_y(s: &mut RealRoot, sy: Ordering, fy: &Polynomial, yy: &Rational, e: f64) -> Ordering {
    let se = e.partial_cmp(&0.0).unwrap_or(Ordering::Equal);
    if sy != se || sy == Ordering::Equal {
        return sy.cmp(&se);
    }
    let e2 = Rational::from_f64(e).unwrap_or_default().square() * yy;
    let c = sign_at_root(s, &(&(fy * fy) - &Polynomial::constant(e2)));
    if sy == Ordering::Greater {
        c
    } else {
        c.reverse()
    }
}

/// The parabola's parameter `y = Y/|Ỹ|` when it is rational: at a rational `s` with
/// `Y²/|Ỹ|²` the square of a rational (Ziv's loop never ends on a value that is a double).
fn exact_y(s: &RealRoot, sy: Ordering, fy: &Polynomial, yy: &Rational) -> Option<Rational> {
    if sy == Ordering::Equal {
        return Some(Rational::new());
    }
    let y2 = fy.eval(s.exact()?).square() / yy;
    let (n, d) = y2.into_numer_denom();
    if !n.is_perfect_square() || !d.is_perfect_square() {
        return None;
    }
    let y = Rational::from((n.sqrt(), d.sqrt()));
    Some(if sy == Ordering::Less { -y } else { y })
}

/// The correctly rounded curve parameters of a hit inside the curve's domain (an arc
/// or a long domain may pass a point more than once); `None`: Ziv's loop reached its
/// cap.
pub(super) fn curve_params(
    curve: &Analytic,
    local: &Local<'_>,
    hit: &Hit,
    fy: &Polynomial,
) -> Option<Vec<Rounded>> {
    let (lo, hi) = curve.domain();
    let mut s = hit.s.clone();
    // The value is exact (r.lo = r.hi) or strictly between the adjacent doubles
    // r.lo < r.hi (module doc), so comparing those with the double ends decides.
    let inside = |r: &Rounded| r.lo >= lo && r.hi <= hi;
    match local.shape {
        CurveShape::Circle { .. } | CurveShape::Ellipse { .. } => {
            let zero = hit.sy == Ordering::Equal && hit.sx == Ordering::Greater;
            if curve.is_closed() {
                let r = if zero {
                    Rounded::exact(0.0)
                } else {
                    correctly_rounded(|bits| local.param(hit, &mut s, bits))?
                };
                return Some(vec![r]);
            }
            if hi - lo > 1e6 {
                return None;
            }
            let (k0, k1) = ((lo / TAU).floor() as i64 - 1, (hi / TAU).ceil() as i64 + 1);
            let mut out = Vec::new();
            for k in k0..=k1 {
                let r = if zero && k == 0 {
                    Rounded::exact(0.0)
                } else {
                    correctly_rounded(|bits| {
                        let t = local.param(hit, &mut s, bits);
                        let two_pi = t.pi_like() * MpfrInterval::point(2.0 * k as f64, bits);
                        t + two_pi
                    })?
                };
                if inside(&r) {
                    out.push(r);
                }
            }
            Some(out)
        }
        CurveShape::Hyperbola { .. } => {
            let r = if hit.sy == Ordering::Equal {
                Rounded::exact(0.0)
            } else {
                correctly_rounded(|bits| local.param(hit, &mut s, bits))?
            };
            Some(if inside(&r) { vec![r] } else { vec![] })
        }
        _ => {
            let yy = dot(&local.frame.y, &local.frame.y);
            let mut s2 = s.clone();
            let ok = compare_y(&mut s2, hit.sy, fy, &yy, lo) != Ordering::Less
                && compare_y(&mut s2, hit.sy, fy, &yy, hi) != Ordering::Greater;
            if !ok {
                return Some(vec![]);
            }
            let r = match exact_y(&hit.s, hit.sy, fy, &yy) {
                Some(y) => round_rational(&y),
                None => correctly_rounded(|bits| local.param(hit, &mut s, bits))?,
            };
            Some(vec![r])
        }
    }
}

/// A conic against a plane, exactly; `None` for the helix (transcendental) or when a
/// parameter cannot be correctly rounded within the cap.
pub(crate) fn conic_plane(
    curve: &Analytic,
    plane: &ExactPlane,
    curve_first: bool,
) -> Option<Certified<Answer>> {
    let shape = curve.shape();
    if matches!(shape, CurveShape::Helix { .. }) {
        return None;
    }
    let f = exact_frame(curve);
    let m = cross(&f.z, &plane.n);
    let bits = 53;
    if is_zero(&m) {
        let on = dot(&plane.n, &f.p) == plane.h;
        let mut r = Certified::exact(
            if on {
                Answer::Coincident
            } else {
                Answer::Empty
            },
            Arithmetic::Rational,
            bits,
        );
        r.reason = Some(
            if on {
                "the curve lies in the plane"
            } else {
                "parallel"
            }
            .into(),
        );
        return Some(r);
    }
    // o = (h₁(n₂ × m) + h₂(m × n₁))/|m|², on both planes.
    let (h1, h2) = (dot(&f.z, &f.p), plane.h.clone());
    let (a, b) = (cross(&plane.n, &m), cross(&m, &f.z));
    let mm = dot(&m, &m);
    let o = v3(|i| (Rational::from(&h1 * &a[i]) + Rational::from(&h2 * &b[i])) / &mm);
    let (p, fx, fy) = restricted(shape, &f, &o, &m)?;
    let local = Local {
        frame: &f,
        o: &o,
        m: &m,
        shape,
    };
    let plane_affine = plane.params_affine(&o, &m);
    let mut points = Vec::new();
    for hit in hits(shape, &p, &fx, &fy) {
        for t in curve_params(curve, &local, &hit, &fy)? {
            points.push(point(
                &hit,
                &o,
                &m,
                t,
                plane_affine.as_ref().map(|a| &a[..]),
                curve_first,
            ));
        }
    }
    Some(Certified::exact(
        Answer::from_points(points),
        Arithmetic::Rational,
        p.max_bits(),
    ))
}

/// One reported point: coordinates `o + s·m` and the other object's parameters (affine
/// in `s`: the plane's `(a, b)`, a line's `t`) correctly rounded, the curve parameter
/// `t`, in input order.
pub(super) fn point(
    hit: &Hit,
    o: &V3,
    m: &V3,
    t: Rounded,
    plane: Option<&[[Rational; 2]]>,
    curve_first: bool,
) -> Point {
    let mut s = hit.s.clone();
    let xyz: Vec<Rounded> = (0..3).map(|i| round_affine(&mut s, &o[i], &m[i])).collect();
    let ab: Vec<Rounded> = plane
        .map(|pa| pa.iter().map(|[c, d]| round_affine(&mut s, c, d)).collect())
        .unwrap_or_default();
    let exact = hit.s.exact().map(|s| {
        let at = |c: &Rational, d: &Rational| Rational::from(d * s) + c;
        let curve = if t.lo == t.hi {
            vec![Rational::from_f64(t.nearest).unwrap_or_default()]
        } else {
            vec![]
        };
        let pl = plane
            .map(|pa| pa.iter().map(|[c, d]| at(c, d)).collect())
            .unwrap_or_default();
        let params = if curve_first {
            vec![curve, pl]
        } else {
            vec![pl, curve]
        };
        ExactPoint {
            xyz: (0..3).map(|i| at(&o[i], &m[i])).collect(),
            params,
            distance_squared: None,
        }
    });
    let value = |v: &[Rounded]| v.iter().map(|r| r.nearest).collect::<Vec<_>>();
    let bounds = |v: &[Rounded]| v.iter().map(|r| [r.lo, r.hi]).collect::<Vec<_>>();
    let tv = [t];
    let (first, second) = if curve_first {
        (&tv[..], &ab[..])
    } else {
        (&ab[..], &tv[..])
    };
    Point {
        xyz: value(&xyz),
        xyz_box: bounds(&xyz),
        params: vec![value(first), value(second)],
        param_box: Some(vec![bounds(first), bounds(second)]),
        multiplicity: hit.multiplicity,
        tangent: hit.multiplicity >= 2,
        exact,
        ..Default::default()
    }
}
