//! `exact` answers are the exact values correctly rounded — the angle parameters too
//! (issue 14, defect 1). Families of lines against spheres, ellipsoids and ring tori in
//! random frames, and of 2D lines and circles against circles and ellipses, including
//! hits on the seam `u = 0` (and at `u = π`), at the poles, tangencies, and 1e±150
//! magnitudes; every coordinate and parameter of every `exact` point is compared with
//! a truth computed at 300 bits by a separate route (the quadratic's closed form, or
//! Newton on the geometric equation, and the frame and angles written here from the
//! definitions), bit for bit, and must lie in its box. `GEOCERT_ROUNDING_CASES` sets
//! the number of cases per family (default 400).

mod truth_support;

use geocert::geom::{Line, Line2};
use geocert::ops::{self, Answer, Linear, LinearObject, Options, Point, Shape};
use geocert::robust::rng::Rng;
use geocert::surface::quadrics::{Ellipsoid, Sphere};
use geocert::surface::torus::Torus;
use geocert::surface::AnySurface;
use geocert::Status;
use nalgebra::{Vector2, Vector3};
use rug::float::{Constant, Round};
use rug::Float;

const BITS: u32 = 300;

fn cases() -> usize {
    std::env::var("GEOCERT_ROUNDING_CASES")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(400)
}

fn f(x: f64) -> Float {
    Float::with_val(BITS, x)
}

fn rounded(x: &Float) -> f64 {
    x.to_f64_round(Round::Nearest)
}

/// The CASES.md frame at 300 bits: Z = axis/|axis|, X = (e − (e·Z)Z)/|…| with `e` =
/// ref or the coordinate vector least aligned with Z (first on ties), Y = Z × X.
fn frame(axis: [f64; 3], reference: Option<[f64; 3]>) -> [[Float; 3]; 3] {
    truth_support::docs_frame(axis, reference, BITS)
}

fn dot(a: &[Float], b: &[Float]) -> Float {
    a.iter().zip(b).fold(f(0.0), |s, (x, y)| s + x.clone() * y)
}

/// The angle in [0, 2π) of (x, y).
fn wrapped(y: &Float, x: &Float) -> Float {
    let a = y.clone().atan2(x);
    if a < 0 {
        a + Float::with_val(BITS, Constant::Pi) * 2u32
    } else {
        a
    }
}

fn assert_in(value: &Float, reported: f64, bounds: [f64; 2], what: &str) {
    // A point box: the value is that double; the truth here carries the 300-bit
    // rounding of its own route (a square root), far below one ulp.
    if bounds[0] == bounds[1] {
        let err = Float::with_val(BITS, value - reported).abs();
        let tol = Float::with_val(BITS, reported.abs().max(f64::MIN_POSITIVE)) >> 200u32;
        assert!(err <= tol, "{what}: exact {reported:e}, truth {value:.30e}");
        return;
    }
    // A tie (the exact value halfway between two doubles, e.g. 5 + a for a double a)
    // rounds to even; the truth's own 300-bit rounding may put it on either side.
    let mid = (f(reported) + rounded(value)) / 2u32;
    let tol = Float::with_val(BITS, reported.abs().max(f64::MIN_POSITIVE)) >> 200u32;
    let tie = Float::with_val(BITS, value - &mid).abs() <= tol
        && reported.to_bits().abs_diff(rounded(value).to_bits()) == 1;
    assert!(
        tie || reported.to_bits() == rounded(value).to_bits(),
        "{what}: reported {reported:e}, truth {value:.30e} rounds to {:e}",
        rounded(value)
    );
    let tol = if tie { tol } else { f(0.0) };
    assert!(
        f(bounds[0]) - &tol <= *value && *value <= bounds[1],
        "{what}: truth {value:.30e} outside its box {bounds:?}"
    );
}

fn line(o: [f64; 3], d: [f64; 3]) -> Shape {
    Shape::Linear(Linear::Double(LinearObject::Line(
        Line::new(Vector3::from(o), Vector3::from(d)).expect("a line"),
    )))
}

fn exact_points(shapes: &[Shape]) -> Vec<Point> {
    let c = ops::intersect(shapes, &Options::default()).expect("answers");
    assert_eq!(c.status, Status::Exact, "{c:?}");
    assert!(c.complete);
    match c.value {
        Answer::Empty => vec![],
        Answer::Points(p) => p,
        other => panic!("unexpected {other:?}"),
    }
}

/// A closed surface in a frame: the surface, and at 300 bits its frame, centre, the
/// semi-axes (quadric) or radii (torus).
struct Closed {
    shape: Shape,
    axes: [[Float; 3]; 3],
    center: [f64; 3],
    radii: [f64; 3],
    torus: Option<(f64, f64)>,
}

fn local(c: &Closed, p: &[Float; 3]) -> [Float; 3] {
    let w: [Float; 3] = std::array::from_fn(|i| p[i].clone() - c.center[i]);
    std::array::from_fn(|i| dot(&w, &c.axes[i]))
}

/// The exact surface parameters `(u, v)` of a point at 300 bits (CASES.md); `None` for
/// `u` at a pole.
fn surface_params(c: &Closed, p: &[Float; 3]) -> (Option<Float>, Float) {
    let q = local(c, p);
    let q: [Float; 3] = std::array::from_fn(|i| q[i].clone() / c.radii[i]);
    let rho = (q[0].clone().square() + q[1].clone().square()).sqrt();
    let u = (rho > 1e-60).then(|| wrapped(&q[1], &q[0]));
    let v = match c.torus {
        Some((major, _)) => wrapped(&q[2], &(rho - major)),
        None => q[2].clone().atan2(&rho),
    };
    (u, v)
}

/// The local coordinates of `o + t·d` and their derivatives in `t`.
fn local_on_line(c: &Closed, o: &[f64; 3], d: &[f64; 3], t: &Float) -> ([Float; 3], [Float; 3]) {
    let p: [Float; 3] = std::array::from_fn(|i| f(o[i]) + t.clone() * d[i]);
    let dv: [Float; 3] = d.map(f);
    let q = local(c, &p);
    let dq: [Float; 3] = std::array::from_fn(|i| dot(&dv, &c.axes[i]));
    (q, dq)
}

/// The line parameters of the hits at 300 bits: a quadric's two roots from the
/// quadratic's closed form; a torus's root nearest the reported estimate by Newton on
/// `(ρ − R)² + z² − r²` with its analytic derivative.
fn truth_t(c: &Closed, o: &[f64; 3], d: &[f64; 3], t0: f64) -> Float {
    match c.torus {
        None => {
            let (q0, dq) = local_on_line(c, o, d, &f(0.0));
            let s = |i: usize| f(c.radii[i]).square();
            let a = (0..3).fold(f(0.0), |acc, i| acc + dq[i].clone().square() / s(i));
            let b = (0..3).fold(f(0.0), |acc, i| acc + q0[i].clone() * &dq[i] / s(i)) * 2u32;
            let cc = (0..3).fold(f(-1.0), |acc, i| acc + q0[i].clone().square() / s(i));
            let disc = (b.clone().square() - a.clone() * &cc * 4u32)
                .max(&f(0.0))
                .sqrt();
            let roots = [
                (-b.clone() - &disc) / (a.clone() * 2u32),
                (-b + &disc) / (a * 2u32),
            ];
            let near = |r: &Float| Float::with_val(BITS, r - t0).abs();
            if near(&roots[0]) <= near(&roots[1]) {
                roots[0].clone()
            } else {
                roots[1].clone()
            }
        }
        Some((major, minor)) => {
            let mut t = f(t0);
            for _ in 0..80 {
                let (q, dq) = local_on_line(c, o, d, &t);
                let rho = (q[0].clone().square() + q[1].clone().square()).sqrt();
                let g = (rho.clone() - major).square() + q[2].clone().square() - f(minor).square();
                let drho = (q[0].clone() * &dq[0] + q[1].clone() * &dq[1]) / &rho;
                let dg = (rho - major) * drho * 2u32 + q[2].clone() * &dq[2] * 2u32;
                if dg == 0 {
                    break;
                }
                t -= g / dg;
            }
            t
        }
    }
}

fn check_line_hits(c: &Closed, o: [f64; 3], d: [f64; 3], what: &str) -> usize {
    let pts = exact_points(&[line(o, d), c.shape.clone()]);
    for p in &pts {
        let t = truth_t(c, &o, &d, p.params[0][0]);
        let tb = p.param_box.as_ref().expect("param boxes");
        assert_in(&t, p.params[0][0], tb[0][0], &format!("{what} t"));
        let x: [Float; 3] = std::array::from_fn(|i| f(o[i]) + t.clone() * d[i]);
        for (i, xi) in x.iter().enumerate() {
            assert_in(xi, p.xyz[i], p.xyz_box[i], &format!("{what} xyz[{i}]"));
        }
        let (u, v) = surface_params(c, &x);
        if p.multiplicity == 1 {
            if let Some(u) = u {
                assert_in(&u, p.params[1][0], tb[1][0], &format!("{what} u"));
            }
            assert_in(&v, p.params[1][1], tb[1][1], &format!("{what} v"));
        }
    }
    pts.len()
}

fn random_axis(rng: &mut Rng) -> [f64; 3] {
    loop {
        let a = [rng.unit(), rng.unit(), rng.unit()];
        if a.iter().any(|&x| x.abs() > 0.1) {
            return a;
        }
    }
}

fn sphere(rng: &mut Rng, scale: f64) -> Closed {
    let center = [
        rng.dyadic() * scale,
        rng.dyadic() * scale,
        rng.dyadic() * scale,
    ];
    let r = (1.0 + rng.unit().abs() * 4.0) * scale;
    let (axis, reference) = if rng.coin() {
        ([0.0, 0.0, 1.0], None)
    } else {
        (random_axis(rng), rng.coin().then(|| random_axis(rng)))
    };
    Closed {
        shape: Shape::Surface(AnySurface::Sphere(
            Sphere::new(center, r, Some(axis), reference).expect("sphere"),
        )),
        axes: frame(axis, reference),
        center,
        radii: [r; 3],
        torus: None,
    }
}

fn ellipsoid(rng: &mut Rng) -> Closed {
    let center = [rng.dyadic(), rng.dyadic(), rng.dyadic()];
    let radii = [
        1.0 + rng.unit().abs() * 3.0,
        1.0 + rng.unit().abs() * 3.0,
        0.5 + rng.unit().abs(),
    ];
    let axis = random_axis(rng);
    let reference = rng.coin().then(|| random_axis(rng));
    Closed {
        shape: Shape::Surface(AnySurface::Ellipsoid(
            Ellipsoid::new(center, radii, Some(axis), reference).expect("ellipsoid"),
        )),
        axes: frame(axis, reference),
        center,
        radii,
        torus: None,
    }
}

fn torus(rng: &mut Rng) -> Closed {
    let center = [rng.dyadic(), rng.dyadic(), rng.dyadic()];
    let major = 2.0 + rng.unit().abs() * 2.0;
    let minor = 0.25 + rng.unit().abs();
    let axis = if rng.coin() {
        [0.0, 0.0, 1.0]
    } else {
        random_axis(rng)
    };
    Closed {
        shape: Shape::Surface(AnySurface::Torus(
            Torus::new(center, major, minor, axis, None).expect("torus"),
        )),
        axes: frame(axis, None),
        center,
        radii: [1.0; 3],
        torus: Some((major, minor)),
    }
}

/// A line through the surface's region: through a random point near the centre, or
/// (axis +z) in the plane through the centre along X (hits on the seam u ∈ {0, π}), or
/// along the axis (the poles).
fn line_through(rng: &mut Rng, c: &Closed, scale: f64) -> ([f64; 3], [f64; 3]) {
    let aligned = c.axes[2][2] == 1.0;
    match rng.below(4) {
        0 if aligned => {
            let o = [
                c.center[0] - 10.0 * scale,
                c.center[1],
                c.center[2] + rng.dyadic() * scale / 4.0,
            ];
            (o, [1.0, 0.0, 0.0])
        }
        1 if aligned => (
            [c.center[0], c.center[1], c.center[2] - 10.0 * scale],
            [0.0, 0.0, 1.0],
        ),
        _ => {
            let o: [f64; 3] = std::array::from_fn(|i| c.center[i] + rng.unit() * scale);
            (o, random_axis(rng))
        }
    }
}

#[test]
fn lines_against_spheres_have_correctly_rounded_parameters() {
    let mut rng = Rng::new(11);
    let mut hits = 0;
    for k in 0..cases() {
        let scale = [1.0, 1e150, 1e-150][k % 3];
        let s = sphere(&mut rng, scale);
        let (o, d) = line_through(&mut rng, &s, scale);
        hits += check_line_hits(&s, o, d, &format!("sphere case {k}"));
    }
    assert!(hits > cases(), "the family hits: {hits}");
}

#[test]
fn lines_against_ellipsoids_have_correctly_rounded_parameters() {
    let mut rng = Rng::new(12);
    let mut hits = 0;
    for k in 0..cases() {
        let e = ellipsoid(&mut rng);
        let (o, d) = line_through(&mut rng, &e, 1.0);
        hits += check_line_hits(&e, o, d, &format!("ellipsoid case {k}"));
    }
    assert!(hits > cases(), "the family hits: {hits}");
}

#[test]
fn lines_against_tori_have_correctly_rounded_parameters() {
    let mut rng = Rng::new(13);
    let mut hits = 0;
    for k in 0..cases() {
        let t = torus(&mut rng);
        let (o, d) = line_through(&mut rng, &t, 2.0);
        hits += check_line_hits(&t, o, d, &format!("torus case {k}"));
    }
    // Lines through the hole miss the tube: more than one hit per two cases on average.
    assert!(hits > cases() / 2, "the family hits: {hits}");
}

#[test]
fn seam_and_pole_hits_are_exact_zeros_and_correctly_rounded_pi() {
    // Axis +z, centre 0: the line y = 0 hits at u = 0 and u = π, the z axis at the poles.
    let s = Closed {
        shape: Shape::Surface(AnySurface::Sphere(
            Sphere::new([0.0; 3], 2.0, None, None).expect("sphere"),
        )),
        axes: frame([0.0, 0.0, 1.0], None),
        center: [0.0; 3],
        radii: [2.0; 3],
        torus: None,
    };
    let pts = exact_points(&[line([-3.0, 0.0, 0.0], [1.0, 0.0, 0.0]), s.shape.clone()]);
    assert_eq!(pts.len(), 2);
    assert_eq!(pts[0].params[1], vec![std::f64::consts::PI, 0.0]);
    assert_eq!(pts[1].params[1], vec![0.0, 0.0]);
    assert_eq!(
        pts[1].param_box.as_ref().expect("boxes")[1][0],
        [0.0, 0.0],
        "u = 0 exactly"
    );
    let pts = exact_points(&[line([0.0, 0.0, -3.0], [0.0, 0.0, 1.0]), s.shape.clone()]);
    assert_eq!(pts.len(), 2);
    assert_eq!(pts[0].params[1][1], -std::f64::consts::FRAC_PI_2);
    assert_eq!(pts[1].params[1][1], std::f64::consts::FRAC_PI_2);
    assert_eq!(
        check_line_hits(&s, [-3.0, 0.0, 0.0], [1.0, 0.0, 0.0], "seam"),
        2
    );
}

/// 2D: lines and circles against circles and ellipses (whole), truths by Newton on the
/// two implicit equations at 300 bits from the reported point.
#[test]
fn plane_conic_parameters_are_correctly_rounded() {
    let mut rng = Rng::new(14);
    let mut hits = 0;
    for k in 0..cases() {
        let c1 = [rng.dyadic(), rng.dyadic()];
        let (a1, b1) = (1.0 + rng.unit().abs() * 2.0, 1.0 + rng.unit().abs() * 2.0);
        let ellipse = geocert::curve::analytic::Analytic2::new(
            c1,
            geocert::curve::analytic::Shape::Ellipse { a: a1, b: b1 },
            None,
        )
        .expect("ellipse");
        let target = Shape::Curve2(geocert::curve::AnyCurve2::Analytic(ellipse));
        let o = if rng.coin() {
            [c1[0] - 5.0, c1[1]]
        } else {
            [c1[0] + rng.unit(), c1[1] + rng.unit()]
        };
        let d = if o[1] == c1[1] {
            [1.0, 0.0]
        } else {
            [rng.unit(), rng.unit()]
        };
        if d == [0.0, 0.0] {
            continue;
        }
        let l = Shape::Linear(Linear::Double(LinearObject::Line2(
            Line2::new(Vector2::from(o), Vector2::from(d)).expect("line"),
        )));
        let pts = exact_points(&[l, target]);
        for p in &pts {
            // The exact hit: t on the line from the quadratic, at 300 bits.
            let (dx, dy) = (f(d[0]) / a1, f(d[1]) / b1);
            let (wx, wy) = ((f(o[0]) - c1[0]) / a1, (f(o[1]) - c1[1]) / b1);
            let qa = dx.clone().square() + dy.clone().square();
            let qb = (dx * &wx + dy * &wy) * 2u32;
            let qc = wx.square() + wy.square() - 1u32;
            let disc = (qb.clone().square() - qa.clone() * &qc * 4u32).max(&f(0.0));
            let roots = [
                (-qb.clone() - disc.clone().sqrt()) / (qa.clone() * 2u32),
                (-qb + disc.sqrt()) / (qa * 2u32),
            ];
            let t = roots
                .iter()
                .min_by(|x, y| {
                    let dx = (Float::with_val(BITS, *x - p.params[0][0])).abs();
                    let dy = (Float::with_val(BITS, *y - p.params[0][0])).abs();
                    dx.partial_cmp(&dy).expect("ordered")
                })
                .expect("two roots")
                .clone();
            let x = [f(o[0]) + t.clone() * d[0], f(o[1]) + t.clone() * d[1]];
            let tb = p.param_box.as_ref().expect("boxes");
            if p.multiplicity == 1 {
                assert_in(&t, p.params[0][0], tb[0][0], &format!("conic case {k} s"));
                let angle = wrapped(
                    &((x[1].clone() - c1[1]) / b1),
                    &((x[0].clone() - c1[0]) / a1),
                );
                assert_in(
                    &angle,
                    p.params[1][0],
                    tb[1][0],
                    &format!("conic case {k} t"),
                );
            }
            hits += 1;
        }
    }
    assert!(hits > cases(), "the family hits: {hits}");
}
