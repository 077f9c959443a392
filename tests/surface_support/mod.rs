//! Shared test support for the surface tests: a seeded generator, two small space curves
//! (the concrete curve types live elsewhere) and a zoo of every surface primitive.
#![allow(dead_code)]

use geocert::curve::Curve;
use geocert::num::Real;
use geocert::surface::frame::Frame;
use geocert::surface::motion::{Extrusion, Revolution, Ruled, Sectorial};
use geocert::surface::plane::{ParaboloidRect, Plane};
use geocert::surface::quadrics::{
    Cone, Cylinder, Ellipsoid, Hyperboloid, Paraboloid, Sheets, Sphere,
};
use geocert::surface::torus::Torus;
use geocert::surface::{bezier::BezierSurface, bilinear::Bilinear, nurbs::NurbsSurface};
use geocert::surface::{AnySurface, Surface};

/// xorshift64: reproducible test input without a dependency.
pub struct Rng(pub u64);
impl Rng {
    pub fn unit(&mut self) -> f64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }
    pub fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.unit()
    }
}

/// A helix `(cos t, sin t, 0.3 t) + (0.5, 0, 0)` on `[0.2, 4]`.
#[derive(Debug, Clone)]
pub struct TestHelix;
impl Curve<3> for TestHelix {
    fn domain(&self) -> (f64, f64) {
        (0.2, 4.0)
    }
    fn jet<T: Real>(&self, t: &T, order: usize) -> Vec<[T; 3]> {
        let (c, s) = (t.cos(), t.sin());
        let zero = t.zero_like();
        let k = t.lift(0.3);
        let all = vec![
            [c.clone() + t.lift(0.5), s.clone(), k.clone() * t],
            [-s.clone(), c.clone(), k],
            [-c.clone(), -s.clone(), zero.clone()],
            [s, -c, zero],
        ];
        all.into_iter().take(order + 1).collect()
    }
}

/// The cubic `(1 + t, 2t² − t, 0.5 t³ + 1)` on `[-1, 1.5]`.
#[derive(Debug, Clone)]
pub struct TestCubic;
impl Curve<3> for TestCubic {
    fn domain(&self) -> (f64, f64) {
        (-1.0, 1.5)
    }
    fn jet<T: Real>(&self, t: &T, order: usize) -> Vec<[T; 3]> {
        let l = |x: f64| t.lift(x);
        let zero = l(0.0);
        let all = vec![
            [
                l(1.0) + t,
                l(2.0) * t.sqr() - t,
                l(0.5) * t.sqr() * t + l(1.0),
            ],
            [l(1.0), l(4.0) * t - l(1.0), l(1.5) * t.sqr()],
            [zero.clone(), l(4.0), l(3.0) * t],
            [zero.clone(), zero, l(3.0)],
        ];
        all.into_iter().take(order + 1).collect()
    }
}

/// A visitor over surfaces of different types (the trait is generic, not object-safe).
pub trait Visit {
    fn visit<S: Surface>(&mut self, name: &str, surface: &S);
}

/// A rational bicubic NURBS patch with interior knots (one of them double).
pub fn nurbs_bicubic() -> NurbsSurface {
    let mut rng = Rng(7);
    let rows = 5;
    let cols = 6;
    let points: Vec<Vec<[f64; 3]>> = (0..rows)
        .map(|i| {
            (0..cols)
                .map(|j| {
                    [
                        j as f64 + rng.range(-0.2, 0.2),
                        i as f64,
                        rng.range(-1.0, 1.0),
                    ]
                })
                .collect()
        })
        .collect();
    let weights: Vec<Vec<f64>> = (0..rows)
        .map(|_| (0..cols).map(|_| rng.range(0.5, 2.0)).collect())
        .collect();
    NurbsSurface::new(
        [3, 3],
        vec![0.0, 0.0, 0.0, 0.0, 0.4, 0.4, 1.0, 1.0, 1.0, 1.0],
        vec![-1.0, -1.0, -1.0, -1.0, 0.5, 2.0, 2.0, 2.0, 2.0],
        &points,
        Some(&weights),
    )
    .unwrap()
}

/// A rational Bézier patch of degree 3 in u and 2 in v.
pub fn bezier_rational() -> BezierSurface {
    let mut rng = Rng(11);
    let points: Vec<Vec<[f64; 3]>> = (0..3)
        .map(|i| {
            (0..4)
                .map(|j| {
                    [
                        j as f64,
                        i as f64 + rng.range(-0.3, 0.3),
                        rng.range(-1.0, 1.0),
                    ]
                })
                .collect()
        })
        .collect();
    let weights: Vec<Vec<f64>> = (0..3)
        .map(|_| (0..4).map(|_| rng.range(0.5, 2.0)).collect())
        .collect();
    BezierSurface::new(&points, Some(&weights)).unwrap()
}

/// Every primitive that does not need a curve, as `AnySurface`, with a name.
pub fn any_surfaces() -> Vec<(&'static str, AnySurface)> {
    let tilted = Some([1.0, 2.0, 3.0]);
    let frame = Frame::new([0.5, -1.0, 2.0], [0.0, 1.0, 1.0], Some([1.0, 0.0, 0.0])).unwrap();
    vec![
        (
            "sphere",
            AnySurface::Sphere(Sphere::new([1.0, -2.0, 0.5], 2.0, tilted, None).unwrap()),
        ),
        (
            "ellipsoid",
            AnySurface::Ellipsoid(
                Ellipsoid::new([0.0; 3], [3.0, 2.0, 1.5], Some([0.0, 1.0, 1.0]), None).unwrap(),
            ),
        ),
        (
            "hyperboloid1",
            AnySurface::Hyperboloid(
                Hyperboloid::new(
                    Sheets::One,
                    [1.0, 0.0, 0.0],
                    [1.0, 2.0, 0.5],
                    [1.0, 1.0, 0.0],
                    None,
                    [-1.0, 1.5],
                )
                .unwrap(),
            ),
        ),
        (
            "hyperboloid2",
            AnySurface::Hyperboloid(
                Hyperboloid::new(
                    Sheets::Two,
                    [0.0; 3],
                    [1.5, 1.0, 2.0],
                    [0.0, 0.0, 1.0],
                    Some([1.0, 1.0, 0.0]),
                    [0.2, 1.5],
                )
                .unwrap(),
            ),
        ),
        (
            "paraboloid",
            AnySurface::Paraboloid(
                Paraboloid::new(
                    [0.0, 1.0, 0.0],
                    [1.0, 3.0],
                    [1.0, 0.0, 0.0],
                    None,
                    [0.0, 2.0],
                )
                .unwrap(),
            ),
        ),
        (
            "elliptic_paraboloid_rect",
            AnySurface::ParaboloidRect(
                ParaboloidRect::elliptic(frame.clone(), [2.0, 1.0], ([-1.0, 1.0], [-0.5, 2.0]))
                    .unwrap(),
            ),
        ),
        (
            "hyperbolic_paraboloid",
            AnySurface::ParaboloidRect(
                ParaboloidRect::hyperbolic(frame, [1.0, 0.5], ([-1.0, 1.0], [-1.0, 1.0])).unwrap(),
            ),
        ),
        (
            "cylinder",
            AnySurface::Cylinder(
                Cylinder::new([0.0; 3], [2.0, 1.0], [1.0, -1.0, 2.0], None, [-1.0, 3.0]).unwrap(),
            ),
        ),
        (
            "cone",
            AnySurface::Cone(
                Cone::new([0.0; 3], 1.0, 0.4, [0.0, 0.0, 1.0], None, [0.0, 2.0]).unwrap(),
            ),
        ),
        (
            "cone_apex",
            AnySurface::Cone(
                Cone::new(
                    [1.0, 1.0, 1.0],
                    0.0,
                    -0.7,
                    [0.0, 3.0, 4.0],
                    None,
                    [-2.0, 0.0],
                )
                .unwrap(),
            ),
        ),
        (
            "torus",
            AnySurface::Torus(Torus::new([0.0; 3], 3.0, 1.0, [0.0, 0.0, 1.0], None).unwrap()),
        ),
        (
            "torus_spindle",
            AnySurface::Torus(
                Torus::new([1.0, 2.0, 3.0], 1.0, 2.0, [1.0, 0.0, 0.0], None).unwrap(),
            ),
        ),
        (
            "plane",
            AnySurface::Plane(
                Plane::new([1.0, 2.0, 3.0], [2.0, 0.0, 1.0], [1.0, 1.0, 0.0])
                    .unwrap()
                    .with_domain(([-2.0, 2.0], [-1.0, 3.0]))
                    .unwrap(),
            ),
        ),
        (
            "bilinear",
            AnySurface::Bilinear(
                Bilinear::new([
                    [0.0, 0.0, 0.0],
                    [1.0, 0.0, 0.5],
                    [0.0, 1.0, -0.5],
                    [1.2, 1.1, 1.0],
                ])
                .unwrap(),
            ),
        ),
        ("bezier", AnySurface::Bezier(bezier_rational())),
        ("nurbs", AnySurface::Nurbs(nurbs_bicubic())),
    ]
}

/// Visit every primitive: the `AnySurface` zoo and the motion surfaces over the test
/// curves.
pub fn zoo(v: &mut impl Visit) {
    for (name, s) in any_surfaces() {
        v.visit(name, &s);
    }
    v.visit(
        "extrusion",
        &Extrusion::new(TestHelix, [0.5, -1.0, 2.0]).unwrap(),
    );
    v.visit(
        "revolution",
        &Revolution::new(TestCubic, [0.0, 0.5, -1.0], [1.0, 1.0, 2.0]).unwrap(),
    );
    v.visit("ruled", &Ruled::new(TestHelix, TestCubic));
    v.visit(
        "sectorial",
        &Sectorial::new(TestCubic, [3.0, -1.0, 2.0]).unwrap(),
    );
}

/// A random parameter pair in the interior of the domain (margin 1% of each range).
pub fn random_params<S: Surface>(s: &S, rng: &mut Rng) -> (f64, f64) {
    let (du, dv) = s.domain();
    let pick = |d: [f64; 2], rng: &mut Rng| {
        let m = 0.01 * (d[1] - d[0]);
        rng.range(d[0] + m, d[1] - m)
    };
    (pick(du, rng), pick(dv, rng))
}
