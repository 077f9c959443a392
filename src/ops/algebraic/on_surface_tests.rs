//! One-ulp perturbations of curves lying on surfaces must not be reported on them:
//! families of exact configurations (Pythagorean data, as in
//! tests/curve_on_surface_exact.rs) with one number moved by one ulp, checked against
//! the exact truth (the moved curve is off the surface: its defining identity fails in
//! rationals, recomputed here by the point test `|x − c|² ≠ R²` at a rational point or
//! by construction) — `curve_on_surface` / `line_on_surface` answer `None` (left to the
//! numeric certifier), and the unperturbed ones a `coincident` or a segment.

use crate::curve::analytic::{Analytic, Shape as CurveShape};
use crate::curve::frame::Frame;
use crate::curve::AnyCurve3;
use crate::num::rng::Rng;
use crate::num::round::{next_down, next_up};
use crate::ops::algebraic::curve_on_surface::{curve_on_surface, line_on_surface};
use crate::ops::answer::Answer;
use crate::ops::shape::{Linear, LinearObject};
use crate::surface::quadrics::{Cylinder, Hyperboloid, Sheets, Sphere};
use crate::surface::torus::Torus;
use crate::surface::AnySurface;

fn circle(c: [f64; 3], r: f64, axis: [f64; 3]) -> AnyCurve3 {
    let f = Frame::new(c, axis, None).unwrap();
    AnyCurve3::Analytic(Analytic::new(f, CurveShape::Circle { radius: r }, None).unwrap())
}

fn bump(x: f64, rng: &mut Rng) -> f64 {
    if rng.coin() {
        next_up(x)
    } else {
        next_down(x)
    }
}

fn coincident(r: Option<crate::certificate::Certified<Answer>>) -> bool {
    matches!(r.map(|r| r.value), Some(Answer::Coincident))
}

#[test]
fn circles_one_ulp_off_spheres_and_tori_are_not_on_them() {
    let mut rng = Rng::new(77);
    for _ in 0..400 {
        let s = 2f64.powi(rng.int(-20, 20) as i32);
        let c = [
            rng.int(-50, 50) as f64 * s,
            rng.int(-50, 50) as f64 * s,
            0.0,
        ];
        // Sphere radius 5s, circle at height 3s (or 4s) of radius 4s (or 3s).
        let (h, rho) = if rng.coin() { (3.0, 4.0) } else { (4.0, 3.0) };
        let sphere = AnySurface::Sphere(Sphere::new(c, 5.0 * s, None, None).unwrap());
        let pc = [c[0], c[1], h * s];
        assert!(coincident(curve_on_surface(
            &circle(pc, rho * s, [0.0, 0.0, 1.0]),
            &sphere
        )));
        let moved = match rng.below(3) {
            0 => circle(pc, bump(rho * s, &mut rng), [0.0, 0.0, 1.0]),
            1 => circle(
                [c[0], c[1], bump(h * s, &mut rng)],
                rho * s,
                [0.0, 0.0, 1.0],
            ),
            _ => circle(pc, rho * s, [0.0, bump(0.0, &mut rng), 1.0]),
        };
        assert!(curve_on_surface(&moved, &sphere).is_none());
        // Torus R = 5s, r = 3s: the meridian through +X and its perturbations.
        let torus =
            AnySurface::Torus(Torus::new(c, 5.0 * s, 3.0 * s, [0.0, 0.0, 1.0], None).unwrap());
        let mc = [c[0] + 5.0 * s, c[1], 0.0];
        assert!(coincident(curve_on_surface(
            &circle(mc, 3.0 * s, [0.0, 1.0, 0.0]),
            &torus
        )));
        let moved = match rng.below(3) {
            0 => circle(mc, bump(3.0 * s, &mut rng), [0.0, 1.0, 0.0]),
            1 => circle(
                [bump(mc[0], &mut rng), mc[1], 0.0],
                3.0 * s,
                [0.0, 1.0, 0.0],
            ),
            _ => circle(mc, 3.0 * s, [bump(0.0, &mut rng), 1.0, 0.0]),
        };
        assert!(curve_on_surface(&moved, &torus).is_none());
    }
}

fn line(o: [f64; 3], d: [f64; 3]) -> Linear {
    let v = |x: [f64; 3]| nalgebra::Vector3::new(x[0], x[1], x[2]);
    Linear::Double(LinearObject::Line(
        crate::geom::Line::new(v(o), v(d)).unwrap(),
    ))
}

#[test]
fn lines_one_ulp_off_rulings_are_not_on_the_surface() {
    let mut rng = Rng::new(78);
    for _ in 0..400 {
        let s = 2f64.powi(rng.int(-20, 20) as i32);
        let os = [
            rng.int(-50, 50) as f64 * s,
            rng.int(-50, 50) as f64 * s,
            0.0,
        ];
        let r = rng.int(1, 40) as f64 * s;
        let (surface, d) = if rng.coin() {
            let c = Cylinder::new(os, [r, r], [0.0, 0.0, 1.0], None, [-1.0, 1.0]).unwrap();
            (AnySurface::Cylinder(c), [0.0, 0.0, 1.0])
        } else {
            let h = Hyperboloid::new(
                Sheets::One,
                os,
                [r, r, r],
                [0.0, 0.0, 1.0],
                None,
                [-1.0, 1.0],
            )
            .unwrap();
            (AnySurface::Hyperboloid(h), [0.0, 1.0, 1.0])
        };
        let o = [os[0] + r, os[1], 0.0];
        assert!(matches!(
            line_on_surface(&line(o, d), &surface, true).map(|r| r.value),
            Some(Answer::Segment(_))
        ));
        let (o2, d2) = match rng.below(3) {
            0 => ([bump(o[0], &mut rng), o[1], o[2]], d),
            1 => (o, [bump(d[0], &mut rng), d[1], d[2]]),
            _ => (o, [d[0], bump(d[1], &mut rng), d[2]]),
        };
        // A direction bumped from 0 is still a ruling only if it stays parallel: d[0]
        // moved off 0 tilts the line, d[1] moved from 0 (cylinder) or 1 (hyperboloid)
        // changes its slope; the origin moved radially leaves the surface.
        assert!(
            line_on_surface(&line(o2, d2), &surface, true).is_none(),
            "{o2:?} {d2:?}"
        );
    }
}
