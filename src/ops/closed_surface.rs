//! Point against a closed analytic surface — sphere, ellipsoid, torus (OPERATIONS.md
//! §4, with the implicit forms of §1.4/§1.6), decided exactly.
//!
//! The side is the sign of the implicit function `F` (§1.4: `F > 0` outside), and for
//! double inputs `F(p)` is a rational number: the docs/FORMAT.md frame is built from the
//! unnormalised axis `Z'` and `X' = e − (e·Z')Z'/|Z'|²` (or `ref` in place of `e`),
//! `Y' = Z' × X'`, and every normalisation enters `F` squared, as `(w·X')²/|X'|²`. So
//! the sign of `F(p)` is decided exactly in `rug::Rational` — a point one ulp off the
//! sphere is `inside` or `outside`, never `on` (docs/CERTIFICATES.md).
//!
//! For a torus with `r ≥ R` (self-intersecting), `inside` is the region `F < 0` of the
//! quartic `(|w|² + R² − r²)² − 4R²(|w|² − (w·Z)²)`.

use super::classify::Side;
use crate::certificate::{Arithmetic, Certified};
use crate::num::ring::{cross3, dot3, sub3, Field, Ring, V3};
use crate::surface::quadrics::{Ellipsoid, Sphere};
use crate::surface::torus::Torus;
use crate::surface::{AnySurface, Surface};
use rug::Rational;
use std::cmp::Ordering;

fn q(x: f64) -> Rational {
    <Rational as Field>::from_f64(x)
}

fn qv(v: &[f64; 3]) -> V3<Rational> {
    v.map(q)
}

/// The unnormalised X axis of the docs/FORMAT.md frame: `ref` (or the coordinate vector least
/// aligned with `Z`, first on ties) minus its component along `Z`, exactly.
pub fn frame_x_unnormalised(axis: &[f64; 3], reference: Option<&[f64; 3]>) -> V3<Rational> {
    let z = qv(axis);
    let e = match reference {
        Some(r) => qv(r),
        None => {
            let mut k = 0;
            for i in 1..3 {
                if axis[i].abs() < axis[k].abs() {
                    k = i;
                }
            }
            std::array::from_fn(|i| {
                if i == k {
                    Rational::from(1)
                } else {
                    Rational::new()
                }
            })
        }
    };
    let along = dot3(&e, &z).divide(&dot3(&z, &z));
    std::array::from_fn(|i| e[i].minus(&along.times(&z[i])))
}

/// The surface is a whole sphere, ellipsoid or torus (its domain is the natural one),
/// so a closed shell with an inside.
pub fn is_closed_shell(surface: &AnySurface) -> bool {
    // The same shape built afresh has the natural domain.
    let natural = match surface {
        AnySurface::Sphere(s) => {
            let f = s.frame();
            Sphere::new(f.origin(), s.radius(), Some(f.axis()), f.reference())
                .map(AnySurface::Sphere)
        }
        AnySurface::Ellipsoid(e) => {
            let f = e.frame();
            Ellipsoid::new(f.origin(), e.semi_axes(), Some(f.axis()), f.reference())
                .map(AnySurface::Ellipsoid)
        }
        AnySurface::Torus(t) => {
            let f = t.frame();
            Torus::new(f.origin(), t.major(), t.minor(), f.axis(), f.reference())
                .map(AnySurface::Torus)
        }
        _ => return false,
    };
    natural.is_ok_and(|n| n.domain() == surface.domain())
}

/// `F(p)` of the surface's implicit form (§1.4, §1.6), exactly; `None` for surfaces
/// other than spheres, ellipsoids and tori.
pub fn implicit_value_exact(surface: &AnySurface, p: &[f64; 3]) -> Option<Rational> {
    let p = qv(p);
    Some(match surface {
        AnySurface::Sphere(s) => {
            let w = sub3(&p, &qv(&s.frame().origin()));
            let r = q(s.radius());
            dot3(&w, &w).minus(&r.times(&r))
        }
        AnySurface::Ellipsoid(e) => {
            let frame = e.frame();
            let w = sub3(&p, &qv(&frame.origin()));
            let z = qv(&frame.axis());
            let x = frame_x_unnormalised(&frame.axis(), frame.reference().as_ref());
            let y = cross3(&z, &x);
            let mut f = Rational::from(-1);
            for (dir, r) in [x, y, z].iter().zip(e.semi_axes()) {
                let c = dot3(&w, dir);
                let r2 = q(r).times(&q(r));
                f = f.plus(&c.times(&c).divide(&dot3(dir, dir).times(&r2)));
            }
            f
        }
        AnySurface::Torus(t) => {
            let frame = t.frame();
            let w = sub3(&p, &qv(&frame.origin()));
            let z = qv(&frame.axis());
            let rho2 = dot3(&w, &w);
            let h = dot3(&w, &z);
            let h2 = h.times(&h).divide(&dot3(&z, &z));
            let (big2, small2) = (
                q(t.major()).times(&q(t.major())),
                q(t.minor()).times(&q(t.minor())),
            );
            let s = rho2.plus(&big2).minus(&small2);
            let four_r2 = Rational::from(4).times(&big2);
            s.times(&s).minus(&four_r2.times(&rho2.minus(&h2)))
        }
        _ => return None,
    })
}

/// The side of `p` relative to a closed sphere, ellipsoid or torus, decided exactly
/// (`Status::Exact`, complete); `None` when the surface is not such a closed shell
/// ([`is_closed_shell`]).
pub fn classify_point_surface(p: &[f64; 3], surface: &AnySurface) -> Option<Certified<Side>> {
    if !is_closed_shell(surface) {
        return None;
    }
    let f = implicit_value_exact(surface, p)?;
    let bits = f
        .numer()
        .significant_bits()
        .max(f.denom().significant_bits());
    let side = match f.cmp0() {
        Ordering::Less => Side::Inside,
        Ordering::Equal => Side::On,
        Ordering::Greater => Side::Outside,
    };
    Some(Certified::exact(side, Arithmetic::Rational, bits))
}

/// The feet of `p` on the sphere `|x − c| = r` (§3.4 in closed form): the critical
/// points of `|p − x|²` on the sphere are where `p − x` is normal, `x = c ± r·e` with
/// `e = (p − c)/|p − c|` — the nearest (`+`, at distance `| |p − c| − r |`) and the
/// farthest (`−`, at `|p − c| + r`). Each point and distance is enclosed in f64 interval
/// arithmetic (outward rounding, `num::interval`). `None` when `p` may be the centre
/// (then every point of the sphere is a foot).
pub fn sphere_feet(
    p: &[f64; 3],
    center: &[f64; 3],
    radius: f64,
) -> Option<[([crate::num::Interval; 3], crate::num::Interval); 2]> {
    use crate::num::Interval;
    let d: [Interval; 3] =
        std::array::from_fn(|i| Interval::point(p[i]) - Interval::point(center[i]));
    let len = (d[0].sqr() + d[1].sqr() + d[2].sqr()).sqrt();
    if len.contains_zero() {
        return None;
    }
    let r = Interval::point(radius);
    let foot = |sign: f64| -> [Interval; 3] {
        std::array::from_fn(|i| Interval::point(center[i]) + d[i] * r * Interval::point(sign) / len)
    };
    Some([(foot(1.0), (len - r).abs()), (foot(-1.0), len + r)])
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_default_frame_x_is_orthogonal_to_the_axis() {
        let axis = [1.0, 2.0, 0.5];
        let x = frame_x_unnormalised(&axis, None);
        assert_eq!(dot3(&x, &qv(&axis)), Rational::new());
        // e = +z (|0.5| is the smallest component).
        assert_eq!(x[2].clone().cmp0(), Ordering::Greater);
        assert_eq!(
            frame_x_unnormalised(&[0.0, 0.0, 2.0], None),
            qv(&[1.0, 0.0, 0.0])
        );
    }
}
