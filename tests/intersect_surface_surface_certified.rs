//! Surface ∩ surface, certified (OPERATIONS.md §9, §10; CERTIFICATION.md): families of
//! pairs with closed-form intersections. Each verified curve's vertices are checked
//! against the true surfaces with exact rationals (spheres, planes, cylinders with
//! axis-aligned frames, whose parametrisations have exactly these images) or MPFR at 256
//! bits (cones, tori, the true circles): every vertex lies within its proven bound of
//! both surfaces and of the true curve. Component counts, `closed` and `complete` are
//! asserted where the truth is known; near-singular inputs that the certifier cannot
//! resolve are held to the promise only (never a wrong proven answer).

use geocert::ops::surface_surface::{
    intersect_surface_surface, CertifiedCurve, Options, SurfaceIntersection,
};
use geocert::robust::rng::Rng;
use geocert::surface::plane::Plane;
use geocert::surface::quadrics::{Cone, Cylinder, Paraboloid, Sphere};
use geocert::surface::torus::Torus;
use geocert::surface::AnySurface;
use geocert::{Certified, Status};
use rug::ops::Pow;
use rug::{Float, Rational};

const BITS: u32 = 256;

fn q(x: f64) -> Rational {
    Rational::from_f64(x).expect("finite")
}

fn mp(x: f64) -> Float {
    Float::with_val(BITS, x)
}

/// `|p − c|² ∈ [(r − b)², (r + b)²]`, exactly: `p` within `b` of the sphere.
fn near_sphere(p: &[f64; 3], c: [f64; 3], r: f64, b: f64) -> bool {
    let d2: Rational = (0..3).map(|k| (q(p[k]) - q(c[k])).pow(2u32)).sum();
    let lo = if b < r {
        (q(r) - q(b)).pow(2u32)
    } else {
        Rational::new()
    };
    lo <= d2 && d2 <= (q(r) + q(b)).pow(2u32)
}

/// `((p − o)·n)² ≤ b²|n|²` with `n = a × c` exact: `p` within `b` of the plane.
fn near_plane(p: &[f64; 3], o: [f64; 3], a: [f64; 3], c: [f64; 3], b: f64) -> bool {
    let (a, c) = (a.map(q), c.map(q));
    let n = [
        a[1].clone() * &c[2] - a[2].clone() * &c[1],
        a[2].clone() * &c[0] - a[0].clone() * &c[2],
        a[0].clone() * &c[1] - a[1].clone() * &c[0],
    ];
    let s: Rational = (0..3).map(|k| (q(p[k]) - q(o[k])) * &n[k]).sum();
    let nn: Rational = n.iter().map(|x| x.clone().pow(2u32)).sum();
    s.pow(2u32) <= q(b).pow(2u32) * nn
}

/// Within `b` of the cylinder of radius `r` around the coordinate axis `axis` through 0.
fn near_cylinder(p: &[f64; 3], axis: usize, r: f64, b: f64) -> bool {
    let d2: Rational = (0..3)
        .filter(|&k| k != axis)
        .map(|k| q(p[k]).pow(2u32))
        .sum();
    let lo = if b < r {
        (q(r) - q(b)).pow(2u32)
    } else {
        Rational::new()
    };
    lo <= d2 && d2 <= (q(r) + q(b)).pow(2u32)
}

/// MPFR distance from `p` to the torus (centre 0, axis z) ≤ `b` (plus 2⁻²⁰⁰ for the
/// 256-bit rounding).
fn near_torus(p: &[f64; 3], big: f64, small: f64, b: f64) -> bool {
    let rho = (mp(p[0]).square() + mp(p[1]).square()).sqrt();
    let d = ((rho - mp(big)).square() + mp(p[2]).square()).sqrt() - mp(small);
    d.abs() <= mp(b) + Float::with_val(BITS, Float::i_exp(1, -200))
}

/// MPFR distance from `p` to the cone `ρ = z tan α` (apex 0, axis z) ≤ `b`, measured in
/// the meridian half-plane (the nearest point lies on the upper nappe near the curve).
fn near_cone(p: &[f64; 3], alpha: f64, b: f64) -> bool {
    let rho = (mp(p[0]).square() + mp(p[1]).square()).sqrt();
    let a = mp(alpha);
    let d = rho * a.clone().cos() - mp(p[2]) * a.sin();
    d.abs() <= mp(b) + Float::with_val(BITS, Float::i_exp(1, -200))
}

/// MPFR distance from `p` to the circle of centre `c`, unit normal `n` (given exactly
/// by its direction `n`, normalised in MPFR) and radius² `rr` ≤ `b`.
fn near_circle(p: &[f64; 3], c: [f64; 3], n: [f64; 3], rr: &Float, b: f64) -> bool {
    let d: Vec<Float> = (0..3).map(|k| mp(p[k]) - mp(c[k])).collect();
    let nn = (0..3)
        .map(|k| mp(n[k]).square())
        .fold(mp(0.0), |s, x| s + x);
    let h = (0..3)
        .map(|k| d[k].clone() * mp(n[k]))
        .fold(mp(0.0), |s, x| s + x)
        / nn.sqrt();
    let dd = d
        .iter()
        .map(|x| x.clone().square())
        .fold(mp(0.0), |s, x| s + x);
    let radial = (dd - h.clone().square()).sqrt();
    let dist = ((radial - rr.clone().sqrt()).square() + h.square()).sqrt();
    dist <= mp(b) + Float::with_val(BITS, Float::i_exp(1, -200))
}

/// Every vertex of every verified curve satisfies `near(xyz, bound)`; returns the
/// number of vertices checked.
fn check_vertices(
    r: &Certified<SurfaceIntersection>,
    near: impl Fn(&[f64; 3], f64) -> bool,
    what: &str,
) -> usize {
    let mut n = 0;
    for c in r
        .value
        .curves
        .iter()
        .filter(|c| c.status == Status::Verified)
    {
        assert_eq!(c.bounds.len(), c.curve.points.len(), "{what}");
        for (p, b) in c.curve.points.iter().zip(&c.bounds) {
            assert!(b.distance.is_finite() && b.distance >= 0.0, "{what}");
            assert!(
                near(&p.xyz, b.distance),
                "{what}: vertex {:?} not within its bound {:e}",
                p.xyz,
                b.distance
            );
            n += 1;
        }
    }
    n
}

/// Proven: status verified, complete, `loops` closed curves and nothing else.
fn assert_loops(r: &Certified<SurfaceIntersection>, loops: usize, what: &str) {
    let summary: Vec<_> = r
        .value
        .curves
        .iter()
        .map(|c| {
            (
                c.status,
                c.curve.closed,
                c.curve.points.len(),
                c.reason.clone(),
            )
        })
        .collect();
    assert_eq!(
        r.status,
        Status::Verified,
        "{what}: {:?} {summary:?}",
        r.reason
    );
    assert!(r.complete, "{what}: {:?}", r.reason);
    assert_eq!(r.value.curves.len(), loops, "{what}: {summary:?}");
    assert!(r.value.singular_points.is_empty(), "{what}");
    for c in &r.value.curves {
        assert!(c.curve.closed, "{what}");
        assert_eq!(c.status, Status::Verified, "{what}");
    }
}

/// [`assert_loops`] where the answer is proven; else the promise only (an undecided
/// answer's reason is kept). Returns whether it was proven. (Some closed loops are not
/// proven: two consecutive boxes of the chain near where the loop closes are not proven
/// to join; the families assert the rate.)
fn proven_loops(r: &Certified<SurfaceIntersection>, loops: usize, what: &str) -> bool {
    if r.status == Status::Verified && r.complete {
        assert_loops(r, loops, what);
        true
    } else {
        assert_eq!(r.status, Status::Undecided, "{what}");
        assert!(r.reason.is_some(), "{what}");
        false
    }
}

/// At least `percent` % of `n` cases proven.
fn assert_rate(proven: usize, n: usize, percent: usize, what: &str) {
    eprintln!("{what}: {proven} of {n} proven");
    assert!(
        proven * 100 >= n * percent,
        "{what}: only {proven} of {n} proven"
    );
}

/// The promise on answers the certifier may not resolve: a proven complete answer has
/// the true number of components (`truth`), and a verified curve's ends are proven.
fn assert_sound(r: &Certified<SurfaceIntersection>, truth: usize, what: &str) {
    if r.complete && r.status != Status::Undecided {
        let components = r.value.curves.len() + r.value.singular_points.len();
        assert_eq!(components, truth, "{what}: proven with the wrong count");
    }
}

fn options() -> Options {
    Options::default()
}

/// Through [`AnySurface`]: the certifier is compiled once for every pair (concrete types
/// would instantiate it once per pair of surface types — minutes of build time).
fn run<A: Into<AnySurface> + Clone, B: Into<AnySurface> + Clone>(
    a: &A,
    b: &B,
) -> Certified<SurfaceIntersection> {
    let (a, b): (AnySurface, AnySurface) = (a.clone().into(), b.clone().into());
    intersect_surface_surface(&a, &b, &options()).expect("valid input")
}

/// Uniform in `[0, 1)`.
fn u01(rng: &mut Rng) -> f64 {
    0.5 * (rng.unit() + 1.0)
}

/// A random point with dyadic coordinates in `[-s, s]³`.
fn centre(rng: &mut Rng, s: f64) -> [f64; 3] {
    std::array::from_fn(|_| (rng.unit() * s * 1024.0).round() / 1024.0)
}

#[test]
fn intersecting_spheres_are_one_proven_circle() {
    let mut rng = Rng::new(15);
    let (mut checked, mut proven) = (0, 0);
    for i in 0..60 {
        let scale = [1.0, 1e-3, 1e3][i % 3];
        let c1 = centre(&mut rng, 4.0 * scale);
        let r1 = (0.5 + 3.0 * u01(&mut rng)) * scale;
        let dir = centre(&mut rng, 1.0);
        let len = dir.iter().map(|x| x * x).sum::<f64>().sqrt().max(1e-3);
        let d = r1 * (0.2 + 1.5 * u01(&mut rng));
        let c2: [f64; 3] = std::array::from_fn(|k| c1[k] + dir[k] / len * d);
        let d = (0..3).map(|k| (c2[k] - c1[k]).powi(2)).sum::<f64>().sqrt();
        // r2 strictly between |d − r1| and d + r1, 5 % away from both
        let (lo, hi) = ((d - r1).abs(), d + r1);
        let r2 = lo + (hi - lo) * (0.05 + 0.9 * u01(&mut rng));
        let s1 = Sphere::new(c1, r1, None, None).unwrap();
        let s2 = Sphere::new(c2, r2, None, None).unwrap();
        let what = format!("case {i}: {c1:?} {r1} / {c2:?} {r2}");
        let r = run(&s1, &s2);
        proven += usize::from(proven_loops(&r, 1, &what));
        // the true circle: centre on the line of centres, radius² = r1² − h²
        let (dm, r1m, r2m) = (mp(d), mp(r1), mp(r2));
        let h =
            (dm.clone().square() + r1m.clone().square() - r2m.square()) / (mp(2.0) * dm.clone());
        let rr = r1m.square() - h.clone().square();
        let cc: [f64; 3] = std::array::from_fn(|k| {
            (mp(c1[k]) + (mp(c2[k]) - mp(c1[k])) * h.clone() / dm.clone()).to_f64()
        });
        // the rounded centre moves the circle by at most an ulp of it: allow that
        let slack = 4.0 * f64::EPSILON * (cc.iter().map(|x| x.abs()).sum::<f64>() + d);
        let n: [f64; 3] = std::array::from_fn(|k| c2[k] - c1[k]);
        checked += check_vertices(
            &r,
            |p, b| {
                near_sphere(p, c1, r1, b)
                    && near_sphere(p, c2, r2, b)
                    && near_circle(p, cc, n, &rr, b + slack)
            },
            &what,
        );
    }
    assert!(checked > 1000);
    assert_rate(proven, 60, 95, "sphere ∩ sphere");
}

#[test]
fn apart_and_nested_spheres_are_proven_empty() {
    let mut rng = Rng::new(16);
    for i in 0..40 {
        let c1 = centre(&mut rng, 4.0);
        let r1 = 0.5 + 2.0 * u01(&mut rng);
        let dir = centre(&mut rng, 1.0);
        let len = dir.iter().map(|x| x * x).sum::<f64>().sqrt().max(1e-3);
        let (d, r2) = if i % 2 == 0 {
            let r2 = 0.5 + 2.0 * u01(&mut rng);
            ((r1 + r2) * (1.05 + u01(&mut rng)), r2)
        } else {
            let r2 = r1 * (0.2 + 0.5 * u01(&mut rng));
            ((r1 - r2) * 0.9 * u01(&mut rng), r2)
        };
        let c2: [f64; 3] = std::array::from_fn(|k| c1[k] + dir[k] / len * d);
        let s1 = Sphere::new(c1, r1, None, None).unwrap();
        let s2 = Sphere::new(c2, r2, None, None).unwrap();
        let r = run(&s1, &s2);
        assert!(r.value.is_empty(), "case {i}");
        assert!(r.complete, "case {i}: {:?}", r.reason);
        assert_eq!(r.status, Status::Verified, "case {i}");
    }
}

/// Spheres whose centres lie `5k` apart along a Pythagorean direction `(3, 4, 0)·k`
/// (dyadic `k`, exact in f64), with radii summing to `5k` exactly (external) or
/// differing by `5k` (internal): tangent at one exactly known point.
#[test]
fn tangent_spheres_touch_at_one_proven_point_and_perturbations_are_never_wrong() {
    let mut rng = Rng::new(17);
    for i in 0..16 {
        let k = [1.0, 0.5, 0.25, 2.0][i % 4];
        let c1 = centre(&mut rng, 3.0);
        let c2 = [c1[0] + 3.0 * k, c1[1] + 4.0 * k, c1[2]];
        let internal = i % 2 == 1;
        let r1 = 5.0 * k * (0.25 + 0.5 * (u01(&mut rng) * 64.0).round() / 64.0);
        let r1 = if internal { r1 + 5.0 * k } else { r1 };
        let r2 = if internal { r1 - 5.0 * k } else { 5.0 * k - r1 };
        // the touching point c1 + r1 (c2 − c1)/|c2 − c1|, exact
        let t = q(r1) / q(5.0 * k);
        let touch: Vec<Rational> = (0..3)
            .map(|j| q(c1[j]) + (q(c2[j]) - q(c1[j])) * t.clone())
            .collect();
        let s1 = Sphere::new(c1, r1, None, None).unwrap();
        let s2 = Sphere::new(c2, r2, None, None).unwrap();
        let r = run(&s1, &s2);
        let what = format!(
            "case {i} ({}): {c1:?} {r1} / {c2:?} {r2}",
            if internal { "internal" } else { "external" }
        );
        assert_eq!(r.status, Status::VerifiedSingular, "{what}: {:?}", r.reason);
        assert!(r.complete, "{what}");
        assert!(r.value.curves.is_empty(), "{what}");
        assert_eq!(r.value.singular_points.len(), 1, "{what}");
        let p = &r.value.singular_points[0];
        for (j, (b, t)) in p.xyz_box.iter().zip(&touch).enumerate() {
            assert!(q(b.lo()) <= *t && *t <= q(b.hi()), "{what}: {j} {b:?}");
        }
        // ±1e-9 on the second radius: a tiny circle (+) or nothing (−) — for internal
        // tangency too, the grown inner sphere pokes out — and never a wrong proof
        for (sign, truth) in [(1.0, 1), (-1.0, 0)] {
            let s2 = Sphere::new(c2, r2 + sign * 1e-9, None, None).unwrap();
            let r = run(&s1, &s2);
            assert_sound(&r, truth, &format!("{what} radius {sign:+}1e-9"));
            if truth == 0 {
                assert!(r.value.curves.is_empty(), "{what}");
            }
        }
    }
}

#[test]
fn planes_cut_spheres_in_proven_circles() {
    let mut rng = Rng::new(18);
    let (mut proven, mut cases) = (0, 0);
    for i in 0..40 {
        let c = centre(&mut rng, 3.0);
        let r = 0.5 + 2.0 * u01(&mut rng);
        let (a, b) = (centre(&mut rng, 1.0), centre(&mut rng, 1.0));
        let n = [
            a[1] * b[2] - a[2] * b[1],
            a[2] * b[0] - a[0] * b[2],
            a[0] * b[1] - a[1] * b[0],
        ];
        let nl = n.iter().map(|x| x * x).sum::<f64>().sqrt();
        if nl < 0.1 {
            continue;
        }
        let h = r * 0.9 * (2.0 * u01(&mut rng) - 1.0);
        let o: [f64; 3] = std::array::from_fn(|k| c[k] + n[k] / nl * h);
        let plane = Plane::new(o, a, b)
            .unwrap()
            .with_domain(([-200.0, 200.0], [-200.0, 200.0]))
            .unwrap();
        let sphere = Sphere::new(c, r, None, None).unwrap();
        let what = format!("case {i}");
        let res = run(&plane, &sphere);
        cases += 1;
        proven += usize::from(proven_loops(&res, 1, &what));
        check_vertices(
            &res,
            |p, bd| near_plane(p, o, a, b, bd) && near_sphere(p, c, r, bd),
            &what,
        );
    }
    assert_rate(proven, cases, 85, "plane ∩ sphere");
}

#[test]
fn tilted_planes_cut_cylinders_in_proven_ellipses_and_cones_in_proven_conics() {
    let mut rng = Rng::new(19);
    let mut proven = [0, 0];
    for i in 0..30 {
        let r = 0.5 + u01(&mut rng);
        let tilt = 0.8 * u01(&mut rng);
        let z0 = 0.5 * (2.0 * u01(&mut rng) - 1.0);
        let (a, b) = ([1.0, 0.0, tilt], [0.0, 1.0, 0.3 * tilt]);
        let o = [0.0, 0.0, z0];
        let plane = Plane::new(o, a, b)
            .unwrap()
            .with_domain(([-5.0, 5.0], [-5.0, 5.0]))
            .unwrap();
        let cyl = Cylinder::new([0.0; 3], [r, r], [0.0, 0.0, 1.0], None, [-3.0, 3.0]).unwrap();
        let what = format!("cylinder case {i}");
        let res = run(&cyl, &plane);
        proven[0] += usize::from(proven_loops(&res, 1, &what));
        check_vertices(
            &res,
            |p, bd| near_plane(p, o, a, b, bd) && near_cylinder(p, 2, r, bd),
            &what,
        );
        // the cone z = ρ / tan α (apex at 0, upper nappe), cut above its apex
        let alpha = 0.3 + 0.5 * u01(&mut rng);
        let cone = Cone::new([0.0; 3], 0.0, alpha, [0.0, 0.0, 1.0], None, [0.0, 4.0]).unwrap();
        let o = [0.0, 0.0, 1.0 + u01(&mut rng)];
        let plane = Plane::new(o, [1.0, 0.0, 0.2 * tilt], b)
            .unwrap()
            .with_domain(([-8.0, 8.0], [-8.0, 8.0]))
            .unwrap();
        let what = format!("cone case {i}");
        let res = run(&plane, &cone);
        proven[1] += usize::from(proven_loops(&res, 1, &what));
        check_vertices(
            &res,
            |p, bd| near_plane(p, o, [1.0, 0.0, 0.2 * tilt], b, bd) && near_cone(p, alpha, bd),
            &what,
        );
    }
    assert_rate(proven[0], 30, 85, "plane ∩ cylinder");
    assert_rate(proven[1], 30, 85, "plane ∩ cone");
}

#[test]
fn planes_cut_tori_in_two_proven_circles() {
    let mut rng = Rng::new(20);
    let mut proven = 0;
    for i in 0..24 {
        let (big, small) = (2.0 + u01(&mut rng), 0.5 + 0.5 * u01(&mut rng));
        let torus = Torus::new([0.0; 3], big, small, [0.0, 0.0, 1.0], None).unwrap();
        let (o, a, b) = if i % 2 == 0 {
            // perpendicular to the axis: circles of radius R ± √(r² − h²)
            (
                [0.0, 0.0, small * 0.9 * (2.0 * u01(&mut rng) - 1.0)],
                [1.0, 0.0, 0.0],
                [0.0, 1.0, 0.0],
            )
        } else {
            // through the axis: two meridian circles
            let t = 2.0 * u01(&mut rng) - 1.0;
            ([0.0; 3], [1.0, t, 0.0], [0.0, 0.0, 1.0])
        };
        let plane = Plane::new(o, a, b)
            .unwrap()
            .with_domain(([-6.0, 6.0], [-6.0, 6.0]))
            .unwrap();
        let what = format!("case {i}");
        let res = run(&plane, &torus);
        proven += usize::from(proven_loops(&res, 2, &what));
        check_vertices(
            &res,
            |p, bd| near_plane(p, o, a, b, bd) && near_torus(p, big, small, bd),
            &what,
        );
    }
    assert_rate(proven, 24, 80, "plane ∩ torus");
}

fn cylinders(r1: f64, r2: f64) -> Certified<SurfaceIntersection> {
    let c1 = Cylinder::new([0.0; 3], [r1, r1], [0.0, 0.0, 1.0], None, [-2.0, 2.0]).unwrap();
    let c2 = Cylinder::new([0.0; 3], [r2, r2], [1.0, 0.0, 0.0], None, [-2.0, 2.0]).unwrap();
    run(&c1, &c2)
}

#[test]
fn perpendicular_cylinders_of_different_radii_are_two_proven_loops() {
    for (i, r2) in [0.5, 0.6, 0.7, 0.8].into_iter().enumerate() {
        let res = cylinders(1.0, r2);
        let what = format!("case {i}: radius {r2}");
        assert_loops(&res, 2, &what);
        check_vertices(
            &res,
            |p, b| near_cylinder(p, 2, 1.0, b) && near_cylinder(p, 0, r2, b),
            &what,
        );
    }
}

/// Steinmetz: equal radii cross at `(0, ±1, 0)`; radii off by 1e-9 either way give two
/// loops (around the thinner cylinder) that pass within ~√1e-9 of each other.
#[test]
fn steinmetz_singular_points_are_proven_and_near_singular_radii_never_wrong() {
    let res = cylinders(1.0, 1.0);
    assert_eq!(res.value.singular_points.len(), 2, "{:?}", res.reason);
    let mut ys: Vec<f64> = Vec::new();
    for p in &res.value.singular_points {
        assert_eq!(p.status, Status::VerifiedSingular, "{:?}", p.reason);
        // the truth (0, ±1, 0) lies in the certified box
        let y = if p.point.xyz[1] > 0.0 { 1.0 } else { -1.0 };
        for (j, t) in [0.0, y, 0.0].into_iter().enumerate() {
            assert!(p.xyz_box[j].contains(t), "{j}: {:?}", p.xyz_box[j]);
        }
        ys.push(y);
    }
    ys.sort_by(f64::total_cmp);
    assert_eq!(ys, [-1.0, 1.0]);
    // four arcs between the two points (float), each verified arc within its bound
    assert_eq!(res.value.curves.len(), 4);
    check_vertices(
        &res,
        |p, b| near_cylinder(p, 2, 1.0, b) && near_cylinder(p, 0, 1.0, b),
        "steinmetz",
    );
    assert_sound(&res, 6, "steinmetz");
    for r2 in [1.0 + 1e-9, 1.0 - 1e-9] {
        let res = cylinders(1.0, r2);
        let closed = res.value.curves.iter().filter(|c| c.curve.closed).count();
        assert_eq!(closed, 2, "radius {r2}: the float answer has the two loops");
        assert_sound(&res, 2, &format!("radius {r2}"));
        check_vertices(
            &res,
            |p, b| near_cylinder(p, 2, 1.0, b) && near_cylinder(p, 0, r2, b),
            "near steinmetz",
        );
    }
}

/// §16.12: sphere `x² + y² + z² = 4` ∩ paraboloid `z = x² + y²` is the circle
/// `z = (√17 − 1)/2`, radius `√z`.
#[test]
fn sphere_and_paraboloid_of_16_12_is_one_proven_circle() {
    let sphere = Sphere::new([0.0; 3], 2.0, None, None).unwrap();
    let par = Paraboloid::new([0.0; 3], [1.0, 1.0], [0.0, 0.0, 1.0], None, [0.0, 2.0]).unwrap();
    let res = run(&sphere, &par);
    assert_loops(&res, 1, "16.12");
    let z: Float = (Float::with_val(BITS, 17).sqrt() - 1u32) / 2u32;
    let rr = z.clone();
    let zc = z.to_f64();
    let slack = f64::EPSILON;
    let n = check_vertices(
        &res,
        |p, b| {
            near_sphere(p, [0.0; 3], 2.0, b)
                && near_circle(p, [0.0, 0.0, zc], [0.0, 0.0, 1.0], &rr, b + slack)
        },
        "16.12",
    );
    assert!(n > 20);
}

/// §16.12: the torus `R = 2, r = 1` and the doubly tangent sphere (centre (−2, 0, 3),
/// radius 4) meet in two Villarceau circles through `T_A = (6/5, 0, 3/5)` and
/// `T_B = (−2, 0, −1)`, where the surfaces touch.
#[test]
fn villarceau_circles_of_16_12_cross_at_two_proven_contacts() {
    let torus = Torus::new([0.0; 3], 2.0, 1.0, [0.0, 0.0, 1.0], None).unwrap();
    let sphere = Sphere::new([-2.0, 0.0, 3.0], 4.0, None, None).unwrap();
    let res = run(&torus, &sphere);
    assert_eq!(res.value.singular_points.len(), 2, "{:?}", res.reason);
    // 6/5 and 3/5 are not doubles: compare with the exact fractions
    let exact = [
        [
            Rational::from((6, 5)),
            Rational::new(),
            Rational::from((3, 5)),
        ],
        [Rational::from(-2), Rational::new(), Rational::from(-1)],
    ];
    for t in &exact {
        let n = res
            .value
            .singular_points
            .iter()
            .filter(|p| {
                p.status == Status::VerifiedSingular
                    && (0..3).all(|j| {
                        let b = &p.xyz_box[j];
                        q(b.lo()) <= t[j] && t[j] <= q(b.hi())
                    })
            })
            .count();
        assert_eq!(n, 1, "{t:?}");
    }
    assert_eq!(res.value.curves.len(), 4, "four arcs between T_A and T_B");
    check_vertices(
        &res,
        |p, b| near_torus(p, 2.0, 1.0, b) && near_sphere(p, [-2.0, 0.0, 3.0], 4.0, b),
        "villarceau",
    );
    assert_sound(&res, 6, "villarceau");
}

/// §16.16: the cylinder `(cos u, sin u, v)` ∩ the plane `z = 0.5` is the unit circle —
/// one closed curve of length 2π (the guarded march of §9.3 moves where the literal
/// step is 0).
#[test]
fn cylinder_and_plane_of_16_16_is_one_proven_circle() {
    let cyl = Cylinder::new([0.0; 3], [1.0, 1.0], [0.0, 0.0, 1.0], None, [0.0, 1.0]).unwrap();
    let (o, a, b) = ([0.0, 0.0, 0.5], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]);
    let plane = Plane::new(o, a, b)
        .unwrap()
        .with_domain(([-2.0, 2.0], [-2.0, 2.0]))
        .unwrap();
    let res = run(&cyl, &plane);
    assert_loops(&res, 1, "16.16");
    let c: &CertifiedCurve = &res.value.curves[0];
    let len = c.curve.polyline_length();
    // a polygon inscribed in the circle, within the bounds: shorter than 2π, not by much
    assert!(
        len < std::f64::consts::TAU + 1e-9 && len > std::f64::consts::TAU - 1e-2,
        "{len}"
    );
    check_vertices(
        &res,
        |p, bd| near_plane(p, o, a, b, bd) && near_cylinder(p, 2, 1.0, bd),
        "16.16",
    );
}
