//! Plane ∩ quadric, exactly (OPERATIONS.md §13.2 eq. (13.4), classified by §1.7
//! (1.19)): the quadric's rational form restricted to the plane's rational frame
//! ([`super::plane::PlaneFrame`]) is a conic `Q(s,t) = yᵀA₂y + 2b₂ᵀy + c₂` with
//! rational coefficients; its type is decided from exact invariants, and its centre,
//! vertex, axes and semi-axes are computed in `Q(√disc)` ([`super::surd`]).
//!
//! Invariants: `δ = det A₂`, `Δ = det [[A₂, b₂], [b₂ᵀ, c₂]]`. The frame coordinates
//! `(s, t)` are the true-size ones scaled by `|f₁|`, `|f₂|` (a positive diagonal
//! change of coordinates), which keeps the signs of `δ`, `Δ` and `a₁₁Δ`:
//! `δ > 0`: ellipse (`a₁₁Δ < 0`), point (`Δ = 0`) or empty (`a₁₁Δ > 0`), a circle when
//! the true-size matrix `diag(1/|fᵢ|)·A₂·diag(1/|fᵢ|)` is scalar; `δ < 0`: hyperbola
//! (`Δ ≠ 0`) or two crossing lines; `δ = 0, A₂ ≠ 0`: parabola (`Δ ≠ 0`), else with
//! `A₂ = α aaᵀ`, `b₂ = βa`, `Q = α w² + 2βw + c₂` in `w = a·y`: two parallel lines,
//! one double line or empty by the sign of `β² − αc₂`; `A₂ = 0`: one line (`b₂ ≠ 0`),
//! empty (`c₂ ≠ 0`) or the whole plane.
//!
//! Lengths in the plane are true size: the eigenvalues `λ` of the true-size matrix
//! solve `λ² − Tλ + δ/(g₁g₂) = 0` (`T = a₁₁/g₁ + a₂₂/g₂`), and the semi-axes are
//! `√(κ/λ)`, `κ = −Q(centre)` (§13.2). The axis of `λ` is `y = (a₁₂, λg₁ − a₁₁)` in frame
//! coordinates (`A₂y = λGy`).

use rug::Rational;
use std::cmp::Ordering;

use super::plane::{ExactPlane, PlaneFrame};
use super::surd::{Surd, Value};
use crate::num::ring::V3;
use crate::ops::rational::QuadricForm;

/// The type of a plane section of a quadric.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ConicType {
    Ellipse,
    Circle,
    Hyperbola,
    Parabola,
    IntersectingLines,
    ParallelLines,
    /// A double line (the plane touches the quadric along it).
    DoubleLine,
    /// A single line (the restricted form is linear).
    Line,
    /// One point (the plane touches the quadric there).
    Point,
    Empty,
    /// The plane lies in the quadric.
    Plane,
}

impl ConicType {
    /// The name the case format uses.
    pub fn as_str(self) -> &'static str {
        match self {
            ConicType::Ellipse => "ellipse",
            ConicType::Circle => "circle",
            ConicType::Hyperbola => "hyperbola",
            ConicType::Parabola => "parabola",
            ConicType::IntersectingLines => "intersecting_lines",
            ConicType::ParallelLines => "parallel_lines",
            ConicType::DoubleLine => "double_line",
            ConicType::Line => "line",
            ConicType::Point => "point",
            ConicType::Empty => "empty",
            ConicType::Plane => "plane",
        }
    }
}

/// One axis of a central conic or of a parabola.
#[derive(Debug, Clone, PartialEq)]
pub struct ConicAxis {
    /// The unit direction (3D).
    pub dir: [Value; 3],
    /// The semi-axis (ellipse, hyperbola: the transverse axis first), or the focal
    /// parameter `p` of `Y² = 2pX` (parabola, whose axis points into its opening).
    pub length: Value,
}

/// A line of a degenerate section: a point on it and its unit direction.
#[derive(Debug, Clone, PartialEq)]
pub struct ConicLine {
    pub point: [Value; 3],
    pub dir: [Value; 3],
}

/// A plane section of a quadric, exactly.
#[derive(Debug, Clone, PartialEq)]
pub struct Section {
    pub kind: ConicType,
    /// The conic in the plane's frame: `A₂`, `b₂`, `c₂` over `(s, t)` of [`PlaneFrame`].
    pub form: QuadricForm<2>,
    pub frame: PlaneFrame,
    /// Centre (ellipse, circle, hyperbola, crossing point of two lines, the point),
    /// or vertex (parabola), exactly.
    pub center: Option<V3<Rational>>,
    /// The centre in true-size plane coordinates `(u, v)` of (13.2).
    pub center_uv: Option<[Value; 2]>,
    /// Ellipse, circle, hyperbola: the two axes (hyperbola: transverse, conjugate);
    /// parabola: its axis.
    pub axes: Vec<ConicAxis>,
    /// The line components of degenerate sections.
    pub lines: Vec<ConicLine>,
}

fn q0() -> Rational {
    Rational::new()
}

/// The restriction of `F` to `x = O + s f₁ + t f₂` (13.4).
pub fn restrict(quadric: &QuadricForm<3>, frame: &PlaneFrame) -> QuadricForm<2> {
    let a = quadric.matrix();
    let mul = |x: &V3<Rational>| -> V3<Rational> {
        std::array::from_fn(|i| {
            let mut s = q0();
            for (j, xj) in x.iter().enumerate() {
                s += Rational::from(&a[i][j] * xj);
            }
            s
        })
    };
    let dot = |x: &V3<Rational>, y: &V3<Rational>| -> Rational {
        let mut s = q0();
        for k in 0..3 {
            s += Rational::from(&x[k] * &y[k]);
        }
        s
    };
    let af = [mul(&frame.f[0]), mul(&frame.f[1])];
    let a2: [[Rational; 2]; 2] =
        std::array::from_fn(|i| std::array::from_fn(|j| dot(&frame.f[i], &af[j])));
    let half = quadric.half_gradient(&frame.origin);
    let b2: [Rational; 2] = std::array::from_fn(|i| dot(&frame.f[i], &half));
    let c2 = quadric.eval(&frame.origin);
    QuadricForm::<2>::from_parts(a2, b2, c2)
}

/// The section of `quadric` by `plane`, classified and described exactly.
pub fn section_plane_quadric(plane: &ExactPlane, quadric: &QuadricForm<3>) -> Section {
    let frame = plane.frame();
    let form = restrict(quadric, &frame);
    let a = form.matrix().clone();
    let b = form.linear().clone();
    let c = form.constant().clone();
    let det_a = Rational::from(&a[0][0] * &a[1][1]) - Rational::from(&a[0][1] * &a[0][1]);
    // Δ = c·δ − (b₁²a₂₂ − 2b₁b₂a₁₂ + b₂²a₁₁).
    let adj = Rational::from(&b[0] * &b[0]) * &a[1][1]
        - Rational::from(&b[0] * &b[1]) * &a[0][1] * 2u32
        + Rational::from(&b[1] * &b[1]) * &a[0][0];
    let big = Rational::from(&c * &det_a) - adj;
    let mut out = Section {
        kind: ConicType::Empty,
        form,
        frame,
        center: None,
        center_uv: None,
        axes: vec![],
        lines: vec![],
    };
    match det_a.cmp0() {
        Ordering::Equal => degenerate_a(&mut out, &a, &b, &c, &big),
        sign => central(&mut out, &a, &b, &c, &det_a, &big, sign),
    }
    out
}

fn surd(q: &Rational) -> Surd {
    Surd::rational(q.clone())
}

fn pair(s: &Rational, t: &Rational) -> [Surd; 2] {
    [surd(s), surd(t)]
}

/// A point `O + y₁f₁ + y₂f₂` with surd coordinates, as values.
fn point_values(frame: &PlaneFrame, y: &[Surd; 2]) -> [Value; 3] {
    let v = frame.vector(y);
    std::array::from_fn(|k| Value::surd(&v[k].add(&surd(&frame.origin[k]))))
}

/// Ellipse, circle, point, empty (`δ > 0`); hyperbola, crossing lines (`δ < 0`).
#[allow(clippy::too_many_arguments)]
fn central(
    out: &mut Section,
    a: &[[Rational; 2]; 2],
    b: &[Rational; 2],
    c: &Rational,
    det_a: &Rational,
    big: &Rational,
    sign: Ordering,
) {
    // Centre: A₂y = −b₂ (Cramer).
    let s = (Rational::from(&a[0][1] * &b[1]) - Rational::from(&a[1][1] * &b[0])) / det_a;
    let t = (Rational::from(&a[0][1] * &b[0]) - Rational::from(&a[0][0] * &b[1])) / det_a;
    // κ = −Q(centre) = −(b₂·y + c₂).
    let kappa = -(Rational::from(&b[0] * &s) + Rational::from(&b[1] * &t) + c);
    let centre = out.frame.point(&s, &t);
    out.center_uv = Some(out.frame.true_size_coords(&surd(&s), &surd(&t)));
    out.center = Some(centre.clone());
    let g = out.frame.g.clone();
    if sign == Ordering::Greater {
        let real = Rational::from(&a[0][0] * big).cmp0();
        out.kind = match real {
            Ordering::Equal => ConicType::Point,
            Ordering::Greater => ConicType::Empty,
            Ordering::Less => ConicType::Ellipse,
        };
        if out.kind != ConicType::Ellipse {
            if out.kind == ConicType::Empty {
                out.center = None;
                out.center_uv = None;
            }
            return;
        }
    } else if big.cmp0() == Ordering::Equal {
        out.kind = ConicType::IntersectingLines;
        crossing_lines(out, a, det_a, &centre);
        return;
    } else {
        out.kind = ConicType::Hyperbola;
    }
    // Eigenvalues of the true-size matrix: λ = (T ± √disc)/2.
    let a11 = Rational::from(&a[0][0] / &g[0]);
    let a22 = Rational::from(&a[1][1] / &g[1]);
    let tr = Rational::from(&a11 + &a22);
    let diff = Rational::from(&a11 - &a22);
    let disc = Rational::from(&diff * &diff)
        + Rational::from(&a[0][1] * &a[0][1]) * 4u32 / (Rational::from(&g[0] * &g[1]));
    if disc.cmp0() == Ordering::Equal {
        out.kind = ConicType::Circle;
    }
    let half = Rational::from((1, 2));
    let lambdas = [
        Surd::new(Rational::from(&tr * &half), half.clone(), disc.clone()),
        Surd::new(Rational::from(&tr * &half), -half.clone(), disc.clone()),
    ];
    let mut axes: Vec<(Surd, [Value; 3])> = lambdas
        .iter()
        .enumerate()
        .map(|(i, l)| {
            let sq = surd(&kappa).div(l).expect("δ ≠ 0: no eigenvalue is zero");
            (sq, out.frame.unit(&eigenvector(a, &g, l, i)))
        })
        .collect();
    // Hyperbola: the transverse axis (κ/λ > 0) first; ellipse: the major axis first.
    axes.sort_by(|x, y| y.0.sub(&x.0).sign());
    out.axes = axes
        .into_iter()
        .map(|(sq, dir)| {
            let len = if sq.sign() == Ordering::Less {
                sq.neg()
            } else {
                sq
            };
            ConicAxis {
                dir,
                length: Value::signed_sqrt(Ordering::Greater, &len),
            }
        })
        .collect();
}

/// The frame-coordinate axis of eigenvalue `λ` (`A₂y = λGy`); for a diagonal `A₂` the
/// coordinate axes (`i` chooses which when both eigenvalues agree: a circle).
fn eigenvector(a: &[[Rational; 2]; 2], g: &[Rational; 2], l: &Surd, i: usize) -> [Surd; 2] {
    let one = || surd(&Rational::from(1));
    let zero = || surd(&q0());
    if a[0][1].cmp0() != Ordering::Equal {
        return [surd(&a[0][1]), l.scale(&g[0]).sub(&surd(&a[0][0]))];
    }
    let first = l.scale(&g[0]).sub(&surd(&a[0][0])).sign() == Ordering::Equal;
    let second = l.scale(&g[1]).sub(&surd(&a[1][1])).sign() == Ordering::Equal;
    match (first, second) {
        (true, false) => [one(), zero()],
        (false, true) => [zero(), one()],
        _ if i == 0 => [one(), zero()],
        _ => [zero(), one()],
    }
}

/// Two lines crossing at the centre: directions `y` with `yᵀA₂y = 0`.
fn crossing_lines(out: &mut Section, a: &[[Rational; 2]; 2], det_a: &Rational, c: &V3<Rational>) {
    let root = Rational::from(-det_a);
    let dirs: Vec<[Surd; 2]> = if a[0][0].cmp0() != Ordering::Equal {
        [Rational::from(1), Rational::from(-1)]
            .iter()
            .map(|sg| {
                [
                    Surd::new(-a[0][1].clone(), sg.clone(), root.clone()),
                    surd(&a[0][0]),
                ]
            })
            .collect()
    } else {
        vec![
            pair(&Rational::from(1), &q0()),
            pair(&a[1][1], &(Rational::from(&a[0][1] * 2u32) * -1i32)),
        ]
    };
    let point: [Value; 3] = std::array::from_fn(|k| Value::rational(&c[k]));
    out.lines = dirs
        .iter()
        .map(|y| ConicLine {
            point: point.clone(),
            dir: out.frame.unit(y),
        })
        .collect();
}

/// `δ = 0`: parabola, parallel or double lines, a single line, empty, the plane.
fn degenerate_a(
    out: &mut Section,
    a: &[[Rational; 2]; 2],
    b: &[Rational; 2],
    c: &Rational,
    big: &Rational,
) {
    let Some(i) = (0..2).find(|&i| a[i][i].cmp0() != Ordering::Equal) else {
        return linear(out, b, c);
    };
    let row = [a[i][0].clone(), a[i][1].clone()];
    let d = [-row[1].clone(), row[0].clone()]; // A₂d = 0
    if big.cmp0() != Ordering::Equal {
        return parabola(out, a, b, c, &d);
    }
    // A₂ = α·aaᵀ with a = row i, α = 1/a_ii; b₂ = β·a.
    let alpha = a[i][i].clone().recip();
    let aa = Rational::from(&row[0] * &row[0]) + Rational::from(&row[1] * &row[1]);
    let beta = (Rational::from(&b[0] * &row[0]) + Rational::from(&b[1] * &row[1])) / &aa;
    let disc = Rational::from(&beta * &beta) - Rational::from(&alpha * c);
    out.kind = match disc.cmp0() {
        Ordering::Less => return,
        Ordering::Equal => ConicType::DoubleLine,
        Ordering::Greater => ConicType::ParallelLines,
    };
    // w± = (−β ± √disc)/α, point y = w·a/|a|².
    let signs: &[i32] = if out.kind == ConicType::DoubleLine {
        &[1]
    } else {
        &[1, -1]
    };
    let dir = out.frame.unit(&pair(&d[0], &d[1]));
    for sg in signs {
        let w = Surd::new(-beta.clone(), Rational::from(*sg), disc.clone()).scale(&a[i][i]);
        let y = [
            w.scale(&Rational::from(&row[0] / &aa)),
            w.scale(&Rational::from(&row[1] / &aa)),
        ];
        out.lines.push(ConicLine {
            point: point_values(&out.frame, &y),
            dir: dir.clone(),
        });
    }
}

/// `A₂ = 0`: `2b₂·y + c₂ = 0`.
fn linear(out: &mut Section, b: &[Rational; 2], c: &Rational) {
    let bb = Rational::from(&b[0] * &b[0]) + Rational::from(&b[1] * &b[1]);
    if bb.cmp0() == Ordering::Equal {
        out.kind = if c.cmp0() == Ordering::Equal {
            ConicType::Plane
        } else {
            ConicType::Empty
        };
        return;
    }
    out.kind = ConicType::Line;
    let k = -Rational::from(c / &bb) / 2u32;
    let y = pair(&Rational::from(&b[0] * &k), &Rational::from(&b[1] * &k));
    out.lines.push(ConicLine {
        point: point_values(&out.frame, &y),
        dir: out.frame.unit(&pair(&-b[1].clone(), &b[0])),
    });
}

/// The parabola: vertex, axis into the opening, focal parameter (module doc of
/// [`super`]; OPERATIONS.md §13.2 "hyperbola/parabola analogously").
fn parabola(
    out: &mut Section,
    a: &[[Rational; 2]; 2],
    b: &[Rational; 2],
    c: &Rational,
    d: &[Rational; 2],
) {
    out.kind = ConicType::Parabola;
    let g = &out.frame.g;
    // τ ⟂_G d; the vertex lies on (A₂τ)·y + b₂·τ = 0 (the tangent there is along τ).
    let tau = [
        -Rational::from(&g[1] * &d[1]),
        Rational::from(&g[0] * &d[0]),
    ];
    let at = [
        Rational::from(&a[0][0] * &tau[0]) + Rational::from(&a[0][1] * &tau[1]),
        Rational::from(&a[1][0] * &tau[0]) + Rational::from(&a[1][1] * &tau[1]),
    ];
    let at2 = Rational::from(&at[0] * &at[0]) + Rational::from(&at[1] * &at[1]);
    let bt = Rational::from(&b[0] * &tau[0]) + Rational::from(&b[1] * &tau[1]);
    let k = -Rational::from(&bt / &at2);
    let y0 = [Rational::from(&at[0] * &k), Rational::from(&at[1] * &k)];
    let q = |y: &[Rational; 2]| out.form.eval(y);
    let bd = Rational::from(&b[0] * &d[0]) + Rational::from(&b[1] * &d[1]);
    let lam = -q(&y0) / Rational::from(&bd * 2u32);
    let v = [
        &y0[0] + Rational::from(&lam * &d[0]),
        &y0[1] + Rational::from(&lam * &d[1]),
    ];
    out.center = Some(out.frame.point(&v[0], &v[1]));
    out.center_uv = Some(out.frame.true_size_coords(&surd(&v[0]), &surd(&v[1])));
    let tat = Rational::from(&tau[0] * &at[0]) + Rational::from(&tau[1] * &at[1]);
    // Points at μd + ντ from the vertex: ν²τᵀA₂τ + 2μ b₂·d = 0, so μ has the sign of
    // −b₂·d·τᵀA₂τ.
    let opening = Rational::from(-&bd) * &tat;
    let dir = if opening.cmp0() == Ordering::Less {
        [-d[0].clone(), -d[1].clone()]
    } else {
        d.clone()
    };
    let tgt = Rational::from(&tau[0] * &tau[0]) * &g[0] + Rational::from(&tau[1] * &tau[1]) * &g[1];
    let dgd = Rational::from(&d[0] * &d[0]) * &g[0] + Rational::from(&d[1] * &d[1]) * &g[1];
    // p = |b·d|·τᵀGτ / (|τᵀAτ|·|d|_G).
    let p2 = Rational::from(&bd * &bd) * Rational::from(&tgt * &tgt)
        / (Rational::from(&tat * &tat) * &dgd);
    let _ = c;
    out.axes.push(ConicAxis {
        dir: out.frame.unit(&pair(&dir[0], &dir[1])),
        length: Value::signed_sqrt(Ordering::Greater, &surd(&p2)),
    });
}
