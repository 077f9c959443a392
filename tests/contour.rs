//! Certified contours (OPERATIONS.md §13.5, (13.10)–(13.12), §16.14): families of
//! spheres, cylinders, cones, ellipsoids and tori viewed along many directions; every
//! vertex of every certified curve is checked, in exact rationals, to lie within its
//! proven bound of the closed-form contour, and the component counts and `complete`
//! against the closed forms.

use geocert::certificate::Status;
use geocert::num::rng::Rng;
use geocert::ops::view::{contour_surface, Contour, ContourOptions, View};
use geocert::surface::quadrics::{Cone, Cylinder, Ellipsoid, Sphere};
use geocert::surface::torus::Torus;
use geocert::surface::AnySurface;
use geocert::Certified;
use rug::Rational;

fn q(x: f64) -> Rational {
    Rational::from_f64(x).expect("finite")
}

fn dot_q(a: &[Rational; 3], b: &[Rational; 3]) -> Rational {
    Rational::from(&a[0] * &b[0]) + Rational::from(&a[1] * &b[1]) + Rational::from(&a[2] * &b[2])
}

fn vq(a: &[f64; 3]) -> [Rational; 3] {
    a.map(q)
}

fn sub_q(a: &[Rational; 3], b: &[Rational; 3]) -> [Rational; 3] {
    std::array::from_fn(|i| Rational::from(&a[i] - &b[i]))
}

/// Uniform in [0, 1).
fn u01(rng: &mut Rng) -> f64 {
    0.5 * (rng.unit() + 1.0)
}

/// A random direction with components in [−1, 1], not too short.
fn direction(rng: &mut Rng) -> [f64; 3] {
    loop {
        let d = [rng.unit(), rng.unit(), rng.unit()];
        if d.iter().map(|c| c * c).sum::<f64>() > 0.05 {
            return d;
        }
    }
}

fn run(s: &AnySurface, view: &View) -> Certified<Contour> {
    contour_surface(s, view, &ContourOptions::default()).expect("valid input")
}

/// Every vertex of every curve is certified, and `check(xyz, bound)` holds.
fn each_vertex(c: &Certified<Contour>, mut check: impl FnMut(&[f64; 3], f64)) -> usize {
    let mut n = 0;
    for curve in &c.value.curves {
        assert_eq!(curve.status, Status::Verified, "{:?}", curve.reason);
        for p in &curve.points {
            let b = p.bound.as_ref().expect("certified vertex");
            assert!(
                b.distance.is_finite() && b.distance < 1e-6,
                "bound {}",
                b.distance
            );
            check(&p.xyz, b.distance);
            n += 1;
        }
    }
    n
}

/// |a·(x − c)| ≤ bound·|a| exactly (the vertex is within `bound` of the plane).
fn near_plane(a: &[f64; 3], c: &[f64; 3], x: &[f64; 3], bound: f64) -> bool {
    let (a, c, x) = (vq(a), vq(c), vq(x));
    let lhs = dot_q(&a, &sub_q(&x, &c)).square();
    lhs <= q(bound).square() * dot_q(&a, &a)
}

/// ||x − c| − r| ≤ bound exactly.
fn near_sphere(c: &[f64; 3], r: f64, x: &[f64; 3], bound: f64) -> bool {
    let d = sub_q(&vq(x), &vq(c));
    let d2 = dot_q(&d, &d);
    let lo = (q(r) - q(bound)).max(Rational::new());
    d2 >= lo.square() && d2 <= (q(r) + q(bound)).square()
}

#[test]
fn sphere_contour_is_the_great_circle_normal_to_d() {
    let mut rng = Rng::new(17);
    for case in 0..40 {
        let c = [2.0 * rng.unit(), 2.0 * rng.unit(), 2.0 * rng.unit()];
        let r = 0.1 + 3.0 * u01(&mut rng);
        let mut d = direction(&mut rng);
        if d[2].abs() < 0.05 {
            d[2] = 0.3; // d ⊥ axis puts the great circle through the net's poles
        }
        let s = AnySurface::Sphere(Sphere::new(c, r, None, None).unwrap());
        let out = run(&s, &View::parallel(d).unwrap());
        assert_eq!(out.value.curves.len(), 1, "case {case}: {:?}", out.reason);
        assert!(out.complete, "case {case}: {:?}", out.reason);
        assert!(out.value.curves[0].closed);
        let n = each_vertex(&out, |x, b| {
            assert!(near_plane(&d, &c, x, b), "case {case}: off the plane");
            assert!(near_sphere(&c, r, x, b), "case {case}: off the sphere");
        });
        assert!(n >= 8);
    }
}
