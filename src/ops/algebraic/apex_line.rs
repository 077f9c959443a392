//! A line or segment against a cone or an elliptic paraboloid, decided through the
//! implicit form (OPERATIONS.md §5.2 with §1.6; issue 14 item 4): the apex of a cone
//! and the vertex of a paraboloid are poles of their parametrisations (`s_u ≡ 0`, a
//! continuum of `u`), where the parametric certifier cannot finish; the implicit
//! equation has no such defect. Solved by [`super::kquad`], with the domain `v ∈ [v₀, v₁]`
//! as an affine constraint on the local height `ζ` (cone: `ζ = v`; paraboloid:
//! `ζ = v²`, so `ζ ∈ [v₀², v₁²]` for `0 ≤ v₀`, `[v₁², v₀²]` for `v₁ ≤ 0`).
//!
//! Cone with radius `r` at `v = 0`, `k = tan α`, unit axis `Ẑ`, `q = x − origin`,
//! `ζ = Ẑ·q`: `F = |q|² − (1 + k²)ζ² − 2rkζ − r² = 0` (both nappes; the parametrisation
//! with `r + kv < 0` covers the second), half-gradient `q − ((1 + k²)ζ + rk)Ẑ`.
//! Paraboloid: the exact [`QuadricForm`] `ξ²/a² + η²/b² − ζ = 0`.
//!
//! Taken only for a whole turn in `u`, a rational axis length `|Z̃|` (so that `ζ` is
//! rational on rational points) and, for a paraboloid, an exact orthonormal frame
//! ([`QuadricForm::diagonal_in_frame`]) and a `v` range of one sign; else `None`.
//!
//! Parameters: `u = atan2(η, ξ)` (turned by π on a cone's second nappe, where
//! `r + kζ < 0`) by interval inverses, the whole circle `[0, 2π]` where the point's box
//! meets the axis (the apex, the vertex: every `u` is a parameter there); `v = ζ` (cone)
//! or `±√ζ` (paraboloid), enclosed from the root's enclosure.

use rug::Rational;
use std::cmp::Ordering;

use super::exact_line::{angle, param, ExactLine};
use super::kquad::{solve, Constraint, KQuad, KRoot};
use crate::certificate::{Arithmetic, Certified, Status};
use crate::certify::univariate::Polynomial;
use crate::num::round::round_rational;
use crate::num::{Interval, MpfrInterval};
use crate::ops::answer::{Answer, ExactPoint, Point};
use crate::ops::rational::exact::{dot, exact_vec};
use crate::ops::rational::{inv_sq, QuadricForm};
use crate::surface::frame::Frame;
use crate::surface::{AnySurface, Surface};

type V3 = [Rational; 3];

fn poly(c: &[Rational]) -> Polynomial {
    Polynomial::from_coeffs(c.to_vec())
}

fn sub(a: &V3, b: &V3) -> V3 {
    std::array::from_fn(|i| Rational::from(&a[i] - &b[i]))
}

/// The unit axis `Z̃/|Z̃|` when `|Z̃|` is rational.
fn unit_axis(frame: &Frame) -> Option<V3> {
    let z = exact_vec("axis", &frame.axis()).ok()?;
    let zz = dot(&z, &z);
    let (n, d) = (zz.numer(), zz.denom());
    if zz.cmp0() != Ordering::Greater || !(n.is_perfect_square() && d.is_perfect_square()) {
        return None;
    }
    let len = Rational::from((
        rug::Integer::from(n.sqrt_ref()),
        rug::Integer::from(d.sqrt_ref()),
    ));
    Some(z.map(|x| x / &len))
}

/// What the answer needs of the surface besides the quadratic.
enum Kind {
    Cone { half_angle: f64, radius: f64 },
    Paraboloid { semi: [f64; 2], negative: bool },
}

struct Setup {
    quad: KQuad,
    kind: Kind,
    frame: Frame,
    /// `ζ = z₀ + z₁ t`.
    zeta: [Rational; 2],
}

fn setup(line: &ExactLine<3>, surface: &AnySurface) -> Option<Setup> {
    if !surface.is_closed()[0] {
        return None;
    }
    let [v0, v1] = surface.domain().1;
    let (frame, kind) = match surface {
        AnySurface::Cone(c) => (
            c.frame().clone(),
            Kind::Cone {
                half_angle: c.half_angle(),
                radius: c.radius(),
            },
        ),
        AnySurface::Paraboloid(p) if v0 >= 0.0 || v1 <= 0.0 => (
            p.frame().clone(),
            Kind::Paraboloid {
                semi: p.semi_axes(),
                negative: v1 <= 0.0 && v0 < 0.0,
            },
        ),
        _ => return None,
    };
    let z = unit_axis(&frame)?;
    let origin = exact_vec("origin", &frame.origin()).ok()?;
    let w = sub(&line.o, &origin);
    let (z0, z1) = (dot(&z, &w), dot(&z, &line.d));
    let [e0, e1] = [v0, v1].map(|v| Rational::from_f64(v).unwrap_or_default());
    let (quad, range) = match &kind {
        Kind::Cone { radius, .. } => {
            let r = Rational::from_f64(*radius)?;
            (cone(line, &w, &z, &z0, &z1, &r), [e0, e1])
        }
        Kind::Paraboloid { semi, negative } => {
            let (a, b) = (inv_sq("a", semi[0]).ok()?, inv_sq("b", semi[1]).ok()?);
            let half = Rational::from((-1, 2));
            let form = QuadricForm::diagonal_in_frame(
                frame.origin(),
                frame.axis(),
                frame.reference(),
                [a, b, Rational::new()],
                half,
                Rational::new(),
            )
            .ok()??;
            let sq = |x: &Rational| Rational::from(x * x);
            let range = if *negative {
                [sq(&e1), sq(&e0)]
            } else {
                [sq(&e0), sq(&e1)]
            };
            (quadric(line, &form), range)
        }
    };
    let mut quad = quad;
    quad.constraints.push(Constraint {
        z: [z0.clone(), z1.clone()],
        range,
    });
    if let Some(r) = &line.range {
        quad.constraints.push(Constraint {
            z: [Rational::new(), Rational::from(1)],
            range: r.clone(),
        });
    }
    Some(Setup {
        quad,
        kind,
        frame,
        zeta: [z0, z1],
    })
}

/// The cone's quadratic in `t` with coefficients in `ℚ[k]` (module doc).
fn cone(line: &ExactLine<3>, w: &V3, z: &V3, z0: &Rational, z1: &Rational, r: &Rational) -> KQuad {
    let d = &line.d;
    let (dd, wd, ww) = (dot(d, d), dot(w, d), dot(w, w));
    let z00 = Rational::from(z0 * z0);
    let z01 = Rational::from(z0 * z1);
    let z11 = Rational::from(z1 * z1);
    let rz0 = Rational::from(r * z0);
    let rz1 = Rational::from(r * z1);
    let a = poly(&[dd - &z11, Rational::new(), -z11]);
    let b = poly(&[wd - &z01, -rz1, -z01]);
    let c = poly(&[ww - &z00 - Rational::from(r * r), -rz0 * 2u32, -z00]);
    let grad = std::array::from_fn(|i| {
        let g0 = poly(&[
            &w[i] - Rational::from(z0 * &z[i]),
            -Rational::from(r * &z[i]),
            -Rational::from(z0 * &z[i]),
        ]);
        let g1 = poly(&[
            &d[i] - Rational::from(z1 * &z[i]),
            Rational::new(),
            -Rational::from(z1 * &z[i]),
        ]);
        [g0, g1]
    });
    KQuad {
        a,
        b,
        c,
        grad,
        constraints: Vec::new(),
    }
}

/// An exact quadric on the line (eq. (6.3)), as constant polynomials in `k`.
fn quadric(line: &ExactLine<3>, form: &QuadricForm<3>) -> KQuad {
    let ad = form.mul_a(&line.d);
    let g0 = form.half_gradient(&line.o);
    let k = |x: Rational| Polynomial::constant(x);
    KQuad {
        a: k(dot(&line.d, &ad)),
        b: k(dot(&line.d, &g0)),
        c: k(form.eval(&line.o)),
        grad: std::array::from_fn(|i| [k(g0[i].clone()), k(ad[i].clone())]),
        constraints: Vec::new(),
    }
}

/// A line or segment against a whole-turn cone or paraboloid (module doc); `None` for
/// other pairs, a line on the surface, or a sign not decided within the cap.
pub(crate) fn line_apex_surface(
    line: &ExactLine<3>,
    surface: &AnySurface,
    line_first: bool,
) -> Option<Certified<Answer>> {
    let s = setup(line, surface)?;
    let k = |bits: u32| match s.kind {
        Kind::Cone { half_angle, .. } => MpfrInterval::point(half_angle, bits).tan(),
        Kind::Paraboloid { .. } => MpfrInterval::point(0.0, bits),
    };
    let (roots, bits) = solve(&s.quad, k)?;
    let k53 = k(64).to_interval();
    let points = roots
        .iter()
        .map(|r| point(line, &s, r, &k53, line_first))
        .collect();
    Some(Certified {
        value: Answer::from_points(points),
        status: Status::Verified,
        complete: true,
        arithmetic: Arithmetic::Mpfr,
        bits,
        reason: None,
        perturbation: None,
    })
}

fn bounds(x: &Interval) -> [f64; 2] {
    [x.lo(), x.hi()]
}

/// One reported point: coordinates and parameters enclosed from the root.
fn point(line: &ExactLine<3>, s: &Setup, r: &KRoot, k: &Interval, line_first: bool) -> Point {
    let bits = r.t.prec();
    let xyz: [Interval; 3] = std::array::from_fn(|i| {
        let o = MpfrInterval::from_rational(&line.o[i], bits);
        o.add(&MpfrInterval::from_rational(&line.d[i], bits).mul(&r.t))
            .to_interval()
    });
    let exact = r.exact.as_ref().map(|t| {
        let v: Vec<Rational> = (0..3)
            .map(|i| Rational::from(&line.d[i] * t) + &line.o[i])
            .collect();
        (t.clone(), v)
    });
    let nearest: Vec<f64> = match &exact {
        Some((_, v)) => v.iter().map(|x| round_rational(x).nearest).collect(),
        None => xyz.iter().map(|x| x.midpoint()).collect(),
    };
    let t = r.t.to_interval();
    let zeta = MpfrInterval::from_rational(&s.zeta[0], bits)
        .add(&MpfrInterval::from_rational(&s.zeta[1], bits).mul(&r.t))
        .to_interval();
    let surface = surface_params(s, &xyz, &zeta, k);
    let line_param = (t.midpoint(), bounds(&t));
    let (first, second) = if line_first {
        (vec![line_param], surface)
    } else {
        (surface, vec![line_param])
    };
    Point {
        xyz: nearest,
        xyz_box: xyz.iter().map(bounds).collect(),
        params: vec![
            first.iter().map(|p| p.0).collect(),
            second.iter().map(|p| p.0).collect(),
        ],
        param_box: Some(vec![
            first.iter().map(|p| p.1).collect(),
            second.iter().map(|p| p.1).collect(),
        ]),
        multiplicity: r.multiplicity,
        tangent: r.multiplicity >= 2 && !r.singular,
        exact: exact.map(|(t, xyz)| ExactPoint {
            xyz,
            params: if line_first {
                vec![vec![t], vec![]]
            } else {
                vec![vec![], vec![t]]
            },
            distance_squared: None,
        }),
        ..Default::default()
    }
}

/// `(u, v)` of a point of the surface from its box (module doc).
fn surface_params(
    s: &Setup,
    xyz: &[Interval; 3],
    zeta: &Interval,
    k: &Interval,
) -> Vec<(f64, [f64; 2])> {
    let (local, _) = s.frame.to_local(xyz);
    let (mut x, mut y) = (local[0], local[1]);
    let mut on_axis = false;
    let v = match s.kind {
        Kind::Cone { radius, .. } => {
            let rho = Interval::point(radius) + *k * *zeta;
            if rho.hi() < 0.0 {
                (x, y) = (x.neg(), y.neg());
            }
            on_axis = rho.contains(0.0);
            *zeta
        }
        Kind::Paraboloid { semi, negative } => {
            x /= Interval::point(semi[0]);
            y /= Interval::point(semi[1]);
            let root = Interval::from_bounds(zeta.lo().max(0.0), zeta.hi().max(0.0)).sqrt();
            if negative {
                (x, y) = (x.neg(), y.neg());
                root.neg()
            } else {
                root
            }
        }
    };
    let u = if on_axis || (x.contains(0.0) && y.contains(0.0)) {
        param(Interval::EMPTY)
    } else {
        param(angle(&y, &x))
    };
    vec![u, (v.midpoint(), bounds(&v))]
}
