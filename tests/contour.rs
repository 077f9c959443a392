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
fn each_vertex(c: &Certified<Contour>, check: impl FnMut(&[f64; 3], f64)) -> usize {
    each_vertex_within(c, 1e-6, check)
}

/// As [`each_vertex`], with every bound below `tight`.
fn each_vertex_within(
    c: &Certified<Contour>,
    tight: f64,
    mut check: impl FnMut(&[f64; 3], f64),
) -> usize {
    let mut n = 0;
    for curve in &c.value.curves {
        assert_eq!(curve.status, Status::Verified, "{:?}", curve.reason);
        for p in &curve.points {
            let b = p.bound.as_ref().expect("certified vertex");
            assert!(
                b.distance.is_finite() && b.distance < tight,
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

/// A central view (§13.5, `I = n·(E − s)`): seen from an eye `E` outside, the contour
/// of a sphere is the circle where the tangent cone from `E` touches it, in the plane
/// `(x − c)·(E − c) = r²`; eyes from just outside (1.05 r) to far away (40 r), and on
/// the axis's side where the circle stays off the net's poles.
#[test]
fn sphere_contour_from_an_eye_is_the_tangent_cone_circle() {
    let mut rng = Rng::new(29);
    let mut cases = 0;
    while cases < 40 {
        let c = [2.0 * rng.unit(), 2.0 * rng.unit(), 2.0 * rng.unit()];
        let r = 0.1 + 3.0 * u01(&mut rng);
        let d = direction(&mut rng);
        let dn = d.iter().map(|x| x * x).sum::<f64>().sqrt();
        let dist = r * (1.05 + 40.0 * u01(&mut rng).powi(2));
        let eye: [f64; 3] = std::array::from_fn(|i| c[i] + d[i] * (dist / dn));
        // the circle through a pole: the pole's tangent plane holds the eye
        if ((eye[2] - c[2]).abs() - r).abs() < 0.1 * r {
            continue;
        }
        let case = cases;
        cases += 1;
        let s = AnySurface::Sphere(Sphere::new(c, r, None, None).unwrap());
        let out = run(&s, &View::central(eye, c, 1.0).unwrap());
        assert_eq!(out.value.curves.len(), 1, "case {case}: {:?}", out.reason);
        assert!(out.complete, "case {case}: {:?}", out.reason);
        assert!(out.value.curves[0].closed);
        let (cq, e) = (vq(&c), sub_q(&vq(&eye), &vq(&c)));
        let (r2, ee) = (q(r).square(), dot_q(&e, &e));
        let n = each_vertex(&out, |x, b| {
            // |(x − c)·e − r²| ≤ b |e|: x within b of a point of the plane
            let lhs = (dot_q(&sub_q(&vq(x), &cq), &e) - &r2).square();
            assert!(lhs <= q(b).square() * &ee, "case {case}: off the plane");
            assert!(near_sphere(&c, r, x, b), "case {case}: off the sphere");
        });
        assert!(n >= 8);
    }
}

/// 300-bit float.
fn mp(x: f64) -> rug::Float {
    rug::Float::with_val(300, x)
}

/// The distance from `x` to the line `p0 + λ e` (300 bits).
fn line_distance(x: &[f64; 3], p0: &[rug::Float; 3], e: &[rug::Float; 3]) -> rug::Float {
    let w: Vec<rug::Float> = (0..3).map(|i| mp(x[i]) - &p0[i]).collect();
    let c = [
        w[1].clone() * &e[2] - w[2].clone() * &e[1],
        w[2].clone() * &e[0] - w[0].clone() * &e[2],
        w[0].clone() * &e[1] - w[1].clone() * &e[0],
    ];
    let n2 = |v: &[rug::Float]| v.iter().fold(mp(0.0), |a, t| a + t.clone() * t);
    (n2(&c) / n2(e)).sqrt()
}

/// Cylinders (`tan α = 0`) and truncated cones about `z` through `c`: the contour is the
/// generators `u* = ψ ± arccos(d_z tan α / ρ_d)` (13.12), present iff
/// `|d_z tan α| < ρ_d`; every vertex within its bound of one of them (300 bits).
#[test]
fn cylinder_and_cone_contours_are_generators() {
    let mut rng = Rng::new(1312);
    let mut with_curves = 0;
    for case in 0..60 {
        let c = [2.0 * rng.unit(), 2.0 * rng.unit(), 2.0 * rng.unit()];
        let r0 = 0.2 + u01(&mut rng);
        let cone = case % 2 == 1;
        // widening cones: the apex stays outside the domain (a singular point)
        let alpha = if cone {
            0.05 + 0.55 * u01(&mut rng)
        } else {
            0.0
        };
        let h = [0.0, 0.5 + u01(&mut rng)];
        let d = direction(&mut rng);
        let rho = d[0].hypot(d[1]);
        let t = alpha.tan();
        let ratio = d[2] * t / rho;
        if rho < 0.05 || (ratio.abs() - 1.0).abs() < 1e-3 {
            continue;
        }
        let s = if cone {
            AnySurface::Cone(Cone::new(c, r0, alpha, [0.0, 0.0, 1.0], None, h).unwrap())
        } else {
            AnySurface::Cylinder(Cylinder::new(c, [r0, r0], [0.0, 0.0, 1.0], None, h).unwrap())
        };
        let out = run(&s, &View::parallel(d).unwrap());
        assert!(out.complete, "case {case}: {:?}", out.reason);
        let expect = if ratio.abs() < 1.0 { 2 } else { 0 };
        assert_eq!(
            out.value.curves.len(),
            expect,
            "case {case}: {:?}",
            out.reason
        );
        with_curves += usize::from(expect > 0);
        let psi = mp(d[1]).atan2(&mp(d[0]));
        let acos = (mp(d[2]) * mp(t) / mp(rho)).acos();
        let gens: Vec<([rug::Float; 3], [rug::Float; 3])> = [psi.clone() + &acos, psi - acos]
            .into_iter()
            .map(|u| {
                let (cu, su) = (u.clone().cos(), u.sin());
                let p0 = [mp(c[0]) + mp(r0) * &cu, mp(c[1]) + mp(r0) * &su, mp(c[2])];
                (p0, [mp(t) * cu, mp(t) * su, mp(1.0)])
            })
            .collect();
        for curve in &out.value.curves {
            assert!(!curve.closed);
        }
        each_vertex(&out, |x, b| {
            let best = gens
                .iter()
                .map(|(p0, e)| line_distance(x, p0, e))
                .min_by(|a, b| a.partial_cmp(b).unwrap())
                .unwrap();
            assert!(
                best <= b,
                "case {case}: {x:?} is {best} from the generators, bound {b}"
            );
        });
    }
    assert!(with_curves >= 30);
}

/// Ellipsoids of revolution: the contour is the conjugate section
/// `x d_x/a² + y d_y/a² + z d_z/c² = 0` (13.12), one closed curve.
#[test]
fn ellipsoid_contour_is_the_conjugate_section() {
    let mut rng = Rng::new(99);
    for case in 0..30 {
        let a = 0.5 + 2.0 * u01(&mut rng);
        let cc = 0.5 + 4.0 * u01(&mut rng);
        let c = [rng.unit(), rng.unit(), rng.unit()];
        let mut d = direction(&mut rng);
        if d[2].abs() < 0.05 {
            d[2] = -0.4;
        }
        let s = AnySurface::Ellipsoid(Ellipsoid::new(c, [a, a, cc], None, None).unwrap());
        let out = run(&s, &View::parallel(d).unwrap());
        assert!(out.complete, "case {case}: {:?}", out.reason);
        assert_eq!(out.value.curves.len(), 1);
        // the plane's normal, exact: (d_x c², d_y c², d_z a²) ∝ (d_x/a², d_y/a², d_z/c²)
        let (a2, c2) = (q(a).square(), q(cc).square());
        let nrm = [q(d[0]) * &c2, q(d[1]) * &c2, q(d[2]) * &a2];
        each_vertex(&out, |x, b| {
            let lhs = dot_q(&nrm, &sub_q(&vq(x), &vq(&c))).square();
            assert!(lhs <= q(b).square() * dot_q(&nrm, &nrm), "case {case}");
        });
    }
}

/// §16.14: the isometric view of the ellipsoid `a = 3, c = 5`: the contour crosses
/// `u = π/4` at `t = −1.1695491849`, the point `(0.8285171561, 0.8285171561, −4.6028730895)`.
#[test]
fn worked_example_16_14_ellipsoid() {
    let s = AnySurface::Ellipsoid(Ellipsoid::new([0.0; 3], [3.0, 3.0, 5.0], None, None).unwrap());
    let view = View::isometric();
    let out = run(&s, &view);
    assert!(out.complete, "{:?}", out.reason);
    assert_eq!(out.value.curves.len(), 1);
    // the polyline crosses u = π/4 between two certified vertices
    let u0 = std::f64::consts::FRAC_PI_4;
    let pts = &out.value.curves[0].points;
    let mut hit = None;
    for w in pts.windows(2) {
        let (a, b) = (w[0].params, w[1].params);
        if (a[0] - u0) * (b[0] - u0) <= 0.0 && (a[0] - b[0]).abs() < 1.0 {
            let lam = (u0 - a[0]) / (b[0] - a[0]);
            hit = Some(a[1] + lam * (b[1] - a[1]));
        }
    }
    let t = hit.expect("the contour crosses u = π/4");
    assert!((t + 1.1695491849).abs() < 1e-3, "t = {t}");
    let f = geocert::ops::view::ContourFn {
        surface: &s,
        implicit: s.implicit(),
        view: &view,
    };
    let (p, _) = f.point_normal(&u0, &-1.1695491849);
    for (a, b) in p.iter().zip([0.8285171561, 0.8285171561, -4.6028730895]) {
        assert!((a - b).abs() < 1e-9, "{p:?}");
    }
    assert!(f.value(&u0, &-1.1695491849f64).abs() < 1e-8);
}

/// A ring torus about `z`: viewed along its axis, the outline is the two circles
/// `R ± r` in `z = 0`; viewed obliquely (`d_z ≠ 0`), two closed curves
/// `tan v = −ρ cos(u − ψ)/d_z` whose vertices satisfy `(x − C(x))·d̂ = 0` within the
/// bound times the Lipschitz constant `1 + R/(R − r)` (`C` the tube centre).
#[test]
fn torus_outlines() {
    let mut rng = Rng::new(7);
    for case in 0..24 {
        let big = 1.0 + 3.0 * u01(&mut rng);
        let small = big * (0.1 + 0.7 * u01(&mut rng));
        let c = [rng.unit(), rng.unit(), rng.unit()];
        let s = AnySurface::Torus(Torus::new(c, big, small, [0.0, 0.0, 1.0], None).unwrap());
        let d = if case % 3 == 0 {
            [0.0, 0.0, if case % 2 == 0 { 1.0 } else { -2.0 }]
        } else {
            let mut d = direction(&mut rng);
            if d[2].abs() < 0.1 {
                d[2] = 0.5;
            }
            d
        };
        let out = run(&s, &View::parallel(d).unwrap());
        assert!(out.complete, "case {case}: {:?}", out.reason);
        assert_eq!(out.value.curves.len(), 2, "case {case}");
        assert!(out.value.curves.iter().all(|c| c.closed));
        let lip = 1.0 + big / (big - small);
        let dn = d.iter().map(|x| x * x).sum::<f64>().sqrt();
        // every bound below 0.5: most vertex boxes are now proven around a Newton
        // point (`view::chain::vertex_box`), but some still fall back to contraction
        // from the piece's enclosure and reach 0.27 (the quadrics stay below 1e-6)
        each_vertex_within(&out, 0.5, |x, b| {
            let w: Vec<rug::Float> = (0..3).map(|i| mp(x[i]) - mp(c[i])).collect();
            let rxy = (w[0].clone() * &w[0] + w[1].clone() * &w[1]).sqrt();
            let ctr = [mp(big) * &w[0] / &rxy, mp(big) * &w[1] / &rxy, mp(0.0)];
            let g = (0..3).fold(mp(0.0), |acc, i| acc + (w[i].clone() - &ctr[i]) * mp(d[i]));
            let g = g.abs() / mp(dn);
            // C is R/(|x_xy| − b)-Lipschitz on the ball of radius b about x
            let lip = lip.max(1.0 + big / (big - small - b));
            assert!(g <= mp(lip * b * 1.001), "case {case}: {g} vs {b}");
            if d[0] == 0.0 && d[1] == 0.0 {
                let r = if rxy > mp(big) {
                    big + small
                } else {
                    big - small
                };
                assert!((rxy.clone() - mp(r)).abs() <= mp(b) && w[2].clone().abs() <= mp(b));
            }
        });
    }
}

fn solve_json(text: &str) -> serde_json::Value {
    let case = geocert::io::read_cases(text).remove(0);
    serde_json::to_value(geocert::io::solve_case(case)).unwrap()
}

/// The command line's `silhouette` op: named and general views, kind `curves`, and
/// errors naming the field.
#[test]
fn silhouette_cases_through_the_case_format() {
    let r = solve_json(
        r#"{"id": "s1", "op": "silhouette", "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 2}], "view": {"type": "parallel", "direction": [1, 2, 3]}}"#,
    );
    assert_eq!(r["status"], "verified", "{r}");
    assert_eq!(r["kind"], "curves");
    assert_eq!(r["complete"], true);
    assert_eq!(r["curves"].as_array().unwrap().len(), 1);
    let p = &r["curves"][0]["points"][0];
    assert_eq!(p["params"].as_array().unwrap().len(), 1);
    let r = solve_json(
        r#"{"op": "silhouette", "objects": [{"type": "torus", "center": [0, 0, 0], "major": 3, "minor": 1, "axis": [0, 0, 1]}], "view": "horizontal"}"#,
    );
    assert_eq!(r["curves"].as_array().unwrap().len(), 2, "{r}");
    assert_eq!(r["complete"], true);
    for (text, field) in [
        (
            r#"{"op": "silhouette", "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 2}]}"#,
            "view",
        ),
        (
            r#"{"op": "silhouette", "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 2}], "view": "sideways"}"#,
            "view",
        ),
        (
            r#"{"op": "silhouette", "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 2}], "view": {"type": "parallel", "direction": [0, 0, 0]}}"#,
            "view.direction",
        ),
        (
            r#"{"op": "silhouette", "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 2}], "view": {"type": "central", "eye": [0, 0, 5], "target": [0, 0, 0], "zoom": 2}}"#,
            "view.zoom",
        ),
    ] {
        let r = solve_json(text);
        assert_eq!(r["status"], "error", "{r}");
        assert_eq!(r["error"]["field"], field, "{r}");
    }
}
