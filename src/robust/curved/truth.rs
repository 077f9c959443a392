//! The truth of a curved case by a route independent of geocert's solvers: the number
//! of common points decided exactly in rationals from the doubles given (signs of
//! discriminants and of `x + s·√y` compared by squaring), and the points themselves at
//! [`PREC`] bits (MPFR, each operation correctly rounded, so their error is far below
//! 2⁻²⁸⁰ relative for these well-scaled data).
//!
//! Each family reduces to circles in a plane or a quadratic in one unknown:
//! - line ∩ sphere: `|o + t·d − c|² = r²`, a quadratic in `t` (OPERATIONS.md §5.2);
//! - line ∩ torus (horizontal line, axis `z`): the plane `z = o_z` cuts the torus in
//!   the circles of radii `R ± √(r² − δ²)`, `δ = o_z − c_z` (§1.6); the line meets each
//!   as a circle in that plane;
//! - circle ∩ circle: `h² = r₁² − a²`, `a = (D² + r₁² − r₂²)/(2D)`;
//! - circle ∩ ellipse (circle centred on the ellipse's minor axis): `x²` eliminated, a
//!   quadratic in `y`; each root with `|y| < b` gives the points `(±x, y)`;
//! - space circle ∩ sphere: the sphere's section by the circle's plane is a circle
//!   (centre and radius² rational), then circle ∩ circle in that plane.

use rug::{Float, Rational};
use std::cmp::Ordering;

use super::{CurvedCase, Data};
use crate::robust::case::q;

/// The precision of the true points.
pub const PREC: u32 = 300;

/// One true point and its multiplicity (2 or more at a tangency).
#[derive(Debug, Clone)]
pub struct TruePoint {
    pub xyz: Vec<Float>,
    pub multiplicity: u32,
}

/// The common points of a case (distinct, each with its multiplicity).
#[derive(Debug, Clone)]
pub struct Truth {
    pub points: Vec<TruePoint>,
}

impl Truth {
    pub fn count(&self) -> usize {
        self.points.len()
    }
}

fn f(x: &Rational) -> Float {
    Float::with_val(PREC, x)
}

fn fsqrt(x: &Rational) -> Float {
    f(x).sqrt()
}

/// `sign(x + s·√y)`, `y ≥ 0`, exactly.
pub fn sign_surd(x: &Rational, s: i32, y: &Rational) -> Ordering {
    let root = if y.cmp0() == Ordering::Equal { 0 } else { s };
    match (x.cmp0(), root.cmp(&0)) {
        (a, Ordering::Equal) => a,
        (Ordering::Equal, b) => b,
        (a, b) if a == b => a,
        // Opposite signs: the larger magnitude wins (compare x² with y).
        (a, _) => match Rational::from(x * x).cmp(y) {
            Ordering::Greater => a,
            Ordering::Less => a.reverse(),
            Ordering::Equal => Ordering::Equal,
        },
    }
}

fn qv<const D: usize>(v: &[f64; D]) -> [Rational; D] {
    std::array::from_fn(|i| q(v[i]))
}

fn dot<const D: usize>(a: &[Rational; D], b: &[Rational; D]) -> Rational {
    let mut s = Rational::new();
    for i in 0..D {
        s += Rational::from(&a[i] * &b[i]);
    }
    s
}

fn sub<const D: usize>(a: &[Rational; D], b: &[Rational; D]) -> [Rational; D] {
    std::array::from_fn(|i| Rational::from(&a[i] - &b[i]))
}

/// The truth of `case`.
pub fn truth(case: &CurvedCase) -> Truth {
    let points = match &case.data {
        Data::LineSphere { o, d, c, r } => line_sphere(o, d, c, *r),
        Data::LineTorus {
            o,
            d,
            c,
            major,
            minor,
        } => line_torus(o, d, c, *major, *minor),
        Data::Circles2 { c1, r1, c2, r2 } => {
            let r1 = q(*r1) * q(*r1);
            circles(&qv(c1), &r1, &qv(c2), *r2, None)
        }
        Data::CircleEllipse2 { c, rho, e, a, b } => circle_ellipse(c, *rho, e, *a, *b),
        Data::CircleSphere {
            q: qc,
            n,
            rho,
            c,
            r,
        } => circle_sphere(qc, n, *rho, c, *r),
        Data::NurbsCircleSphere {
            q: qc, rho, c, r, ..
        } => circle_sphere(qc, &[0.0, 1.0, 0.0], *rho, c, *r),
    };
    Truth { points }
}

/// The roots of `a t² + b t + k` on the line `o + t·d` (`a > 0`).
fn line_quadratic<const D: usize>(
    o: &[Rational; D],
    d: &[Rational; D],
    a: &Rational,
    b: &Rational,
    k: &Rational,
) -> Vec<TruePoint> {
    let disc: Rational = Rational::from(b * b) - 4 * Rational::from(a * k);
    let at = |t: Float| -> Vec<Float> {
        (0..D)
            .map(|i| f(&o[i]) + Float::with_val(PREC, &t * &f(&d[i])))
            .collect()
    };
    let two_a = f(&Rational::from(2 * a));
    match disc.cmp0() {
        Ordering::Less => vec![],
        Ordering::Equal => vec![TruePoint {
            xyz: at(-f(b) / &two_a),
            multiplicity: 2,
        }],
        Ordering::Greater => [-1.0, 1.0]
            .iter()
            .map(|&s| TruePoint {
                xyz: at((-f(b) + fsqrt(&disc) * s) / &two_a),
                multiplicity: 1,
            })
            .collect(),
    }
}

fn line_sphere(o: &[f64; 3], d: &[f64; 3], c: &[f64; 3], r: f64) -> Vec<TruePoint> {
    let (o, d, c) = (qv(o), qv(d), qv(c));
    let w = sub(&o, &c);
    let a = dot(&d, &d);
    let b = 2 * dot(&d, &w);
    let k = dot(&w, &w) - q(r) * q(r);
    line_quadratic(&o, &d, &a, &b, &k)
}

/// A horizontal line against the torus about `z`: the circles of radii `R ± w`,
/// `w = √(r² − δ²)`, in the plane `z = o_z` (§1.6).
fn line_torus(o: &[f64; 3], d: &[f64; 3], c: &[f64; 3], major: f64, minor: f64) -> Vec<TruePoint> {
    debug_assert_eq!(d[2], 0.0, "the torus family's lines are horizontal");
    let (o, d, c) = (qv(o), qv(d), qv(c));
    let (big, small) = (q(major), q(minor));
    let delta = Rational::from(&o[2] - &c[2]);
    let w2 = Rational::from(&small * &small) - Rational::from(&delta * &delta);
    if w2.cmp0() == Ordering::Less {
        return vec![];
    }
    let (o2, d2) = ([o[0].clone(), o[1].clone()], [d[0].clone(), d[1].clone()]);
    let p = sub(&o2, &[c[0].clone(), c[1].clone()]);
    let a = dot(&d2, &d2);
    let b = 2 * dot(&d2, &p);
    let cc = dot(&p, &p);
    // Squared distance from the axis to the line: C − B²/(4A).
    let dist2 = &cc - Rational::from(&b * &b) / Rational::from(4 * &a);
    let big2 = Rational::from(&big * &big);
    let mut points = Vec::new();
    let sides: &[i32] = if w2.cmp0() == Ordering::Equal {
        &[1]
    } else {
        &[1, -1]
    };
    for &s in sides {
        // sign(ρ² − dist²) with ρ = R + s·w: sign(R² + w² − dist² + 2sR·w).
        let x = Rational::from(&big2 + &w2) - &dist2;
        let y = 4 * Rational::from(&big2 * &w2);
        let disc_sign = sign_surd(&x, s, &y);
        if disc_sign == Ordering::Less {
            continue;
        }
        let rho = f(&big) + fsqrt(&w2) * s;
        let rho2 = Float::with_val(PREC, &rho * &rho);
        // A t² + B t + (C − ρ²) = 0, roots (−B ± √(4A(ρ² − dist²)))/(2A).
        let disc = Float::with_val(PREC, (rho2 - f(&dist2)) * f(&Rational::from(4 * &a)));
        let disc = if disc_sign == Ordering::Equal {
            Float::with_val(PREC, 0)
        } else {
            disc
        };
        let two_a = f(&Rational::from(2 * &a));
        let roots: Vec<Float> = if disc_sign == Ordering::Equal {
            vec![-f(&b) / &two_a]
        } else {
            let sq = disc.sqrt();
            vec![(-f(&b) - &sq) / &two_a, (-f(&b) + sq) / &two_a]
        };
        let base = if disc_sign == Ordering::Equal { 2 } else { 1 };
        let mult = if sides.len() == 1 { 2 * base } else { base };
        for t in roots {
            let xyz = (0..3)
                .map(|i| f(&o[i]) + Float::with_val(PREC, &t * &f(&d[i])))
                .collect();
            points.push(TruePoint {
                xyz,
                multiplicity: mult,
            });
        }
    }
    points
}

/// The circle `|x − c₁|² = r1sq` and the circle about `c₂` of radius `r2` in a plane;
/// `frame = Some((origin, e₁, e₂))` maps plane coordinates into space (`e₁`, `e₂`
/// orthonormal, as 300-bit numbers), `None` keeps them.
fn circles<const D: usize>(
    c1: &[Rational; D],
    r1sq: &Rational,
    c2: &[Rational; D],
    r2: f64,
    frame: Option<&Plane>,
) -> Vec<TruePoint> {
    let r2sq = q(r2) * q(r2);
    let dd = sub(c2, c1);
    let d2 = dot(&dd, &dd);
    let m = Rational::from(&d2 + r1sq) - &r2sq;
    // 4D²·h² = 4D²r₁² − (D² + r₁² − r₂²)²
    let h4: Rational = 4 * Rational::from(&d2 * r1sq) - Rational::from(&m * &m);
    let dist = fsqrt(&d2);
    let a = f(&m) / Float::with_val(PREC, 2 * &dist);
    let u: Vec<Float> = dd.iter().map(|x| f(x) / &dist).collect();
    let h = match h4.cmp0() {
        Ordering::Less => return vec![],
        Ordering::Equal => Float::with_val(PREC, 0),
        Ordering::Greater => fsqrt(&h4) / Float::with_val(PREC, 2 * &dist),
    };
    let signs: &[f64] = if h4.cmp0() == Ordering::Equal {
        &[0.0]
    } else {
        &[-1.0, 1.0]
    };
    let mult = if h4.cmp0() == Ordering::Equal { 2 } else { 1 };
    signs
        .iter()
        .map(|&s| {
            let along = Float::with_val(PREC, &h * s);
            let xyz = match frame {
                None => {
                    // In the plane: c₁ + a·u + s·h·u⊥, u⊥ = (−u_y, u_x).
                    let perp = [-u[1].clone(), u[0].clone()];
                    (0..D)
                        .map(|i| {
                            f(&c1[i])
                                + Float::with_val(PREC, &a * &u[i])
                                + Float::with_val(PREC, &along * &perp[i])
                        })
                        .collect()
                }
                Some(plane) => (0..D)
                    .map(|i| {
                        f(&c1[i])
                            + Float::with_val(PREC, &a * &u[i])
                            + Float::with_val(PREC, &along * &plane.perp(&u, i))
                    })
                    .collect(),
            };
            TruePoint {
                xyz,
                multiplicity: mult,
            }
        })
        .collect()
}

/// A plane through the origin given by its normal (for space circles).
struct Plane {
    n: Vec<Float>,
}

impl Plane {
    /// Component `i` of `n̂ × u` (a unit vector in the plane, perpendicular to `u`).
    fn perp(&self, u: &[Float], i: usize) -> Float {
        let (j, k) = ((i + 1) % 3, (i + 2) % 3);
        Float::with_val(PREC, &self.n[j] * &u[k]) - Float::with_val(PREC, &self.n[k] * &u[j])
    }
}

/// A circle centred on the ellipse's minor axis (`c_x = e_x`): `x² = a²(1 − y²/b²)`
/// substituted into `x² + (y − k)² = ρ²` (coordinates relative to `e`):
/// `(1 − a²/b²)y² − 2ky + (a² + k² − ρ²) = 0`.
fn circle_ellipse(c: &[f64; 2], rho: f64, e: &[f64; 2], a: f64, b: f64) -> Vec<TruePoint> {
    debug_assert_eq!(c[0], e[0], "the circle is centred on the minor axis");
    let (a, b, rho) = (q(a), q(b), q(rho));
    let k = q(c[1]) - q(e[1]);
    let (a2, b2) = (Rational::from(&a * &a), Rational::from(&b * &b));
    let qa = Rational::from(1) - Rational::from(&a2 / &b2);
    let qb = Rational::from(-2 * &k);
    let qc = &a2 + Rational::from(&k * &k) - Rational::from(&rho * &rho);
    let disc: Rational = Rational::from(&qb * &qb) - 4 * Rational::from(&qa * &qc);
    if disc.cmp0() == Ordering::Less {
        return vec![];
    }
    let double = disc.cmp0() == Ordering::Equal;
    let signs: &[i32] = if double { &[1] } else { &[-1, 1] };
    let mut points = Vec::new();
    for &s in signs {
        // y − b and y + b, y = (−B + s√Δ)/(2A): sign(−B ∓ 2Ab + s√Δ)·sign(A).
        let side = |pm: i32| {
            let x = Rational::from(-&qb) - pm * (2 * Rational::from(&qa * &b));
            let sg = sign_surd(&x, s, &disc);
            if qa.cmp0() == Ordering::Less {
                sg.reverse()
            } else {
                sg
            }
        };
        let (above, below) = (side(1), side(-1)); // signs of y − b and y + b
        if above == Ordering::Greater || below == Ordering::Less {
            continue;
        }
        let y = (-f(&qb) + fsqrt(&disc) * s) / f(&Rational::from(2 * &qa));
        let y_abs = f(&q(e[1])) + &y;
        let base = if double { 2 } else { 1 };
        if above == Ordering::Equal || below == Ordering::Equal {
            points.push(TruePoint {
                xyz: vec![f(&q(e[0])), y_abs],
                multiplicity: 2 * base,
            });
            continue;
        }
        let x2 = f(&a2) * (Float::with_val(PREC, 1) - Float::with_val(PREC, &y * &y) / f(&b2));
        let x = x2.sqrt();
        for sx in [-1.0, 1.0] {
            points.push(TruePoint {
                xyz: vec![f(&q(e[0])) + Float::with_val(PREC, &x * sx), y_abs.clone()],
                multiplicity: base,
            });
        }
    }
    points
}

/// The sphere's section by the circle's plane (centre `c + ((q − c)·n/|n|²) n`, radius²
/// `r² − ((q − c)·n)²/|n|²`), then two circles in that plane.
fn circle_sphere(qc: &[f64; 3], n: &[f64; 3], rho: f64, c: &[f64; 3], r: f64) -> Vec<TruePoint> {
    let (qc, nq, c) = (qv(qc), qv(n), qv(c));
    let nn = dot(&nq, &nq);
    let e = dot(&sub(&qc, &c), &nq);
    let lambda = Rational::from(&e / &nn);
    let centre: [Rational; 3] = std::array::from_fn(|i| &c[i] + Rational::from(&lambda * &nq[i]));
    let r1sq = q(r) * q(r) - Rational::from(&e * &lambda);
    if r1sq.cmp0() != Ordering::Greater {
        return vec![];
    }
    let norm = fsqrt(&nn);
    let plane = Plane {
        n: nq.iter().map(|x| f(x) / &norm).collect(),
    };
    circles(&centre, &r1sq, &qc, rho, Some(&plane))
}
