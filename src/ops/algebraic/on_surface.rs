//! Does a curve lie on a surface? Decided exactly from the rational data (issue 14
//! items 8–9; OPERATIONS.md §1.6 for the implicit forms, §5.2 for the restriction).
//!
//! The surface is its exact implicit polynomial `S(x)`: a quadric `xᵀAx + 2bᵀx + c₀`
//! ([`crate::ops::section::form::quadric_of_surface`]) or the torus quartic
//! `|a|²(|q|² + K)² − 4R²(|a|²|q|² − (q·a)²)` of [`super::line_surface`]. The curve is
//! substituted:
//!
//! - a line `o + t·d`: `S(o + t·d)` is a polynomial in `t`; the line lies on the
//!   implicit surface iff it is the zero polynomial;
//! - a circle or ellipse with centre `p`, axis `Z̃` and the unnormalised frame
//!   `X̃ = ref − (ref·Z̃/|Z̃|²)Z̃`, `Ỹ = Z̃ × X̃` (rational, orthogonal; the curve's unit
//!   vectors `X̃/|X̃|`, `Ỹ/|Ỹ|` are not): its points are `p + αX̃ + βỸ` with
//!   `α = a cos t/|X̃|`, `β = b sin t/|Ỹ|`, i.e. the points of the plane conic
//!   `E: k₁α² + k₂β² = 1`, `k₁ = |X̃|²/a²`, `k₂ = |Ỹ|²/b²` (rational). `G(α, β) =
//!   S(p + αX̃ + βỸ)` has rational coefficients; reducing it modulo `E` (replacing `α²`
//!   by `(1 − k₂β²)/k₁` until `α` has degree ≤ 1) leaves `R = A(β) + αB(β)` with
//!   `G = R` on `E`. The curve (or any arc of it) lies on the surface iff `A = B = 0`:
//!   if `R` vanishes on an arc then `A² = α²B² = (1 − k₂β²)B²/k₁` on an interval of
//!   `β`, a polynomial identity, impossible unless `B = 0` (the right side has simple
//!   roots, so it is no square times `k₁`) and then `A = 0`; conversely `R = 0`
//!   makes `G` vanish on all of `E`.
//!
//! No rounding and no tolerance enter: the answer is a polynomial identity in exact
//! rationals, so a curve one ulp off the surface is never reported on it.

use rug::Rational;
use std::cmp::Ordering;

use crate::curve::analytic::{Analytic, Shape as CurveShape};
use crate::ops::closed_surface::frame_x_unnormalised;
use crate::ops::rational::exact::dot;
use crate::ops::rational::QuadricForm;
use crate::surface::AnySurface;

pub(super) type V3 = [Rational; 3];

/// `Σ c[i][j] αⁱ βʲ`, degree ≤ 4 in each variable (dense, 5 × 5).
#[derive(Clone, Debug)]
struct P2(Vec<Vec<Rational>>);

const N: usize = 5;

impl P2 {
    fn zero() -> P2 {
        P2(vec![vec![Rational::new(); N]; N])
    }

    fn constant(c: Rational) -> P2 {
        let mut p = P2::zero();
        p.0[0][0] = c;
        p
    }

    /// `c + aα + bβ`.
    fn affine(c: &Rational, a: &Rational, b: &Rational) -> P2 {
        let mut p = P2::constant(c.clone());
        p.0[1][0] = a.clone();
        p.0[0][1] = b.clone();
        p
    }

    fn add(&self, o: &P2) -> P2 {
        let mut p = self.clone();
        for (i, row) in p.0.iter_mut().enumerate() {
            for (j, x) in row.iter_mut().enumerate() {
                *x += &o.0[i][j];
            }
        }
        p
    }

    fn scale(&self, k: &Rational) -> P2 {
        P2(self
            .0
            .iter()
            .map(|row| row.iter().map(|x| Rational::from(x * k)).collect())
            .collect())
    }

    /// The product; the degrees stay below `N` for the forms used here (≤ 4).
    fn mul(&self, o: &P2) -> P2 {
        let mut p = P2::zero();
        for (i, row) in self.0.iter().enumerate() {
            for (j, x) in row.iter().enumerate() {
                if x.cmp0() == Ordering::Equal {
                    continue;
                }
                for (k, orow) in o.0.iter().enumerate() {
                    for (l, y) in orow.iter().enumerate() {
                        if y.cmp0() != Ordering::Equal {
                            debug_assert!(i + k < N && j + l < N, "degree above 4");
                            p.0[i + k][j + l] += Rational::from(x * y);
                        }
                    }
                }
            }
        }
        p
    }

    fn is_zero(&self) -> bool {
        self.0.iter().flatten().all(|x| x.cmp0() == Ordering::Equal)
    }

    /// The remainder modulo `k₁α² + k₂β² − 1` (module doc), zero iff `self` vanishes
    /// on the conic.
    fn vanishes_on_conic(&self, k1: &Rational, k2: &Rational) -> bool {
        let mut c = self.0.clone();
        // Rows of degree ≥ 2 in α fold down, highest first; β may reach 4 + 4 = 8.
        for row in c.iter_mut() {
            row.resize(2 * N, Rational::new());
        }
        for i in (2..N).rev() {
            for j in 0..2 * N - 2 {
                let x = std::mem::take(&mut c[i][j]);
                if x.cmp0() == Ordering::Equal {
                    continue;
                }
                let x = x / k1;
                c[i - 2][j + 2] -= Rational::from(&x * k2);
                c[i - 2][j] += x;
            }
        }
        c.iter().flatten().all(|x| x.cmp0() == Ordering::Equal)
    }
}

/// The exact implicit polynomial of a surface.
pub(super) enum Implicit {
    Quadric(QuadricForm<3>),
    /// Centre, axis, `R²`, `r²` of a torus.
    Torus(V3, V3, Rational, Rational),
}

fn q3(v: [f64; 3]) -> Option<V3> {
    let [a, b, c] = v.map(Rational::from_f64);
    Some([a?, b?, c?])
}

impl Implicit {
    /// The implicit polynomial of a quadric with a rational form or of a torus;
    /// `None` otherwise (a cone by its half-angle, free-form surfaces).
    pub(super) fn of(surface: &AnySurface) -> Option<Implicit> {
        if let AnySurface::Torus(t) = surface {
            let f = t.frame();
            let sq = |x: f64| Rational::from_f64(x).map(Rational::square);
            return Some(Implicit::Torus(
                q3(f.origin())?,
                q3(f.axis())?,
                sq(t.major())?,
                sq(t.minor())?,
            ));
        }
        crate::ops::section::form::quadric_of_surface(surface).map(Implicit::Quadric)
    }

    /// `S(p + αu + βv)` as a polynomial in `(α, β)`.
    fn on_plane(&self, p: &V3, u: &V3, v: &V3) -> P2 {
        match self {
            Implicit::Quadric(f) => {
                let x: Vec<P2> = (0..3).map(|i| P2::affine(&p[i], &u[i], &v[i])).collect();
                let (a, b) = (f.matrix(), f.linear());
                let mut s = P2::constant(f.constant().clone());
                for i in 0..3 {
                    s = s.add(&x[i].scale(&(Rational::from(&b[i] * 2u32))));
                    for j in 0..3 {
                        s = s.add(&x[i].mul(&x[j]).scale(&a[i][j]));
                    }
                }
                s
            }
            Implicit::Torus(c, a, r2, m2) => {
                let q: Vec<P2> = (0..3)
                    .map(|i| P2::affine(&Rational::from(&p[i] - &c[i]), &u[i], &v[i]))
                    .collect();
                let qq = (0..3).fold(P2::zero(), |s, i| s.add(&q[i].mul(&q[i])));
                let qa = (0..3).fold(P2::zero(), |s, i| s.add(&q[i].scale(&a[i])));
                let aa = dot(a, a);
                let k = P2::constant(Rational::from(r2 - m2));
                let s = qq.add(&k);
                let radial = qq.scale(&aa).add(&qa.mul(&qa).scale(&Rational::from(-1)));
                s.mul(&s)
                    .scale(&aa)
                    .add(&radial.scale(&(Rational::from(r2 * 4u32) * -1i32)))
            }
        }
    }

    /// The line `o + t·d` lies on the implicit surface.
    pub(super) fn contains_line(&self, o: &V3, d: &V3) -> bool {
        let zero: V3 = std::array::from_fn(|_| Rational::new());
        self.on_plane(o, d, &zero).is_zero()
    }

    /// A quadric restricted to the plane of `c`, as the conic
    /// `[a, b, c, d, e, f]` in the plane coordinates `(α, β)` of [`ConicFrame`]; `None`
    /// for a torus.
    pub(super) fn plane_conic(&self, c: &ConicFrame) -> Option<[Rational; 6]> {
        let Implicit::Quadric(_) = self else {
            return None;
        };
        let g = self.on_plane(&c.p, &c.x, &c.y).0;
        Some([
            g[2][0].clone(),
            g[1][1].clone(),
            g[0][2].clone(),
            g[1][0].clone(),
            g[0][1].clone(),
            g[0][0].clone(),
        ])
    }

    /// The circle or ellipse lies on the implicit surface (module doc); `None` for
    /// other curves.
    pub(super) fn contains_conic(&self, c: &ConicFrame) -> Option<bool> {
        let g = self.on_plane(&c.p, &c.x, &c.y);
        Some(g.vanishes_on_conic(&c.k1, &c.k2))
    }
}

/// A circle or ellipse of space, exactly: centre `p`, the orthogonal rational frame
/// `X̃`, `Ỹ`, `Z̃` and the conic `k₁α² + k₂β² = 1` of its points `p + αX̃ + βỸ`.
pub(super) struct ConicFrame {
    pub(super) p: V3,
    pub(super) x: V3,
    pub(super) y: V3,
    pub(super) z: V3,
    k1: Rational,
    k2: Rational,
}

pub(super) fn cross(a: &V3, b: &V3) -> V3 {
    std::array::from_fn(|i| {
        let (j, k) = ((i + 1) % 3, (i + 2) % 3);
        Rational::from(&a[j] * &b[k]) - Rational::from(&a[k] * &b[j])
    })
}

impl ConicFrame {
    /// The curve in its plane coordinates: `k₁α² + k₂β² − 1` as `[a, b, c, d, e, f]`.
    pub(super) fn own_conic(&self) -> [Rational; 6] {
        let z = Rational::new;
        [
            self.k1.clone(),
            z(),
            self.k2.clone(),
            z(),
            z(),
            Rational::from(-1),
        ]
    }
}

/// The exact frame of a circle or ellipse (arc or whole); `None` for other curves.
pub(super) fn conic_frame(c: &Analytic) -> Option<ConicFrame> {
    let (a, b) = match c.shape() {
        CurveShape::Circle { radius } => (radius, radius),
        CurveShape::Ellipse { a, b } => (a, b),
        _ => return None,
    };
    let f = c.frame();
    let z = q3(f.axis())?;
    let x = frame_x_unnormalised(&f.axis(), f.reference().as_ref());
    let y = cross(&z, &x);
    let (a2, b2) = (
        Rational::from_f64(a)?.square(),
        Rational::from_f64(b)?.square(),
    );
    Some(ConicFrame {
        p: q3(f.origin())?,
        k1: dot(&x, &x) / a2,
        k2: dot(&y, &y) / b2,
        x,
        y,
        z,
    })
}

#[cfg(test)]
#[path = "on_surface_tests.rs"]
mod tests;
