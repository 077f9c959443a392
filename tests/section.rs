//! Exact plane sections (issue 17; OPERATIONS.md §13.1–§13.3, §16.10, §16.11): worked
//! examples, families of planes × quadrics with the type decided independently
//! (exact invariants in another frame of the plane, and closed-form truths for
//! spheres, cylinders, cones), tangent planes and their 1-ulp neighbours, cones cut
//! through the apex, polyhedron sections through vertices, edges and faces with
//! rational truth, and typed errors.

#![allow(clippy::needless_range_loop)]

use geocert::num::rng::Rng;
use geocert::ops::algebraic::QuadricForm;
use geocert::ops::section::{
    plane_through_points_exact, quadric_of_surface, section_plane_polyhedron,
    section_plane_quadric, ConicType, ExactPlane, Section, Value,
};
use geocert::ops::Polyhedron;
use geocert::surface::quadrics::{Ellipsoid, Hyperboloid, Sheets};
use geocert::surface::AnySurface;
use rug::{Float, Rational};
use std::cmp::Ordering;

fn q(x: f64) -> Rational {
    Rational::from_f64(x).unwrap()
}

fn qi(n: i64) -> Rational {
    Rational::from(n)
}

fn plane(n: [f64; 3], d: f64) -> ExactPlane {
    ExactPlane {
        normal: n.map(q),
        d: q(d),
    }
}

fn near(v: &Value, want: f64, tol: f64) {
    assert!((v.value - want).abs() <= tol, "{} vs {want}", v.value);
    assert!(v.bounds[0] <= v.value && v.value <= v.bounds[1]);
}

/// The section's every reported value is correctly rounded (status exact).
fn all_rounded(s: &Section) -> bool {
    s.axes
        .iter()
        .all(|a| a.length.rounded && a.dir.iter().all(|d| d.rounded))
        && s.lines
            .iter()
            .all(|l| l.point.iter().chain(&l.dir).all(|v| v.rounded))
}

// ---------------------------------------------------------------- §16.10

#[test]
fn worked_example_16_10_ellipsoid_and_hyperboloid() {
    let cut = plane([1.0, 3.0, 16.0], -16.0);
    let ell = AnySurface::Ellipsoid(Ellipsoid::new([0.0; 3], [3.0, 3.0, 5.0], None, None).unwrap());
    let s = section_plane_quadric(&cut, &quadric_of_surface(&ell).unwrap());
    assert_eq!(s.kind, ConicType::Ellipse);
    let c = s.center.clone().unwrap();
    let want = [0.0221879815, 0.0665639445, 0.9861325116];
    for k in 0..3 {
        assert!((c[k].to_f64() - want[k]).abs() < 1e-9);
    }
    let uv = s.center_uv.clone().unwrap();
    near(&uv[0], 0.0, 0.0);
    near(&uv[1], -0.1223698515, 1e-9);
    near(&s.axes[0].length, 2.9762593965, 1e-9); // along e2
    near(&s.axes[1].length, 2.9402367755, 1e-9); // along e1
    let e2: [f64; 3] = [0.3102266937, 0.9306800812, -0.1938916836];
    for k in 0..3 {
        assert!((s.axes[0].dir[k].value.abs() - e2[k].abs()).abs() < 1e-9);
    }
    assert_eq!(s.axes[1].dir[2].exact, Some(qi(0)));
    assert!(all_rounded(&s));

    let hyp = AnySurface::Hyperboloid(
        Hyperboloid::new(
            Sheets::One,
            [0.0; 3],
            [3.0, 3.0, 5.0],
            [0.0, 0.0, 1.0],
            None,
            [-1.0, 1.0],
        )
        .unwrap(),
    );
    let s = section_plane_quadric(&cut, &quadric_of_surface(&hyp).unwrap());
    assert_eq!(s.kind, ConicType::Ellipse);
    let c = s.center.clone().unwrap();
    let want = [-0.0228209192, -0.0684627575, 1.0142630745];
    for k in 0..3 {
        assert!((c[k].to_f64() - want[k]).abs() < 1e-9);
    }
    near(&s.axes[0].length, 3.1416164140, 1e-9);
    near(&s.axes[1].length, 3.0602507588, 1e-9);
}

// ------------------------------------------------ independent type truth

/// The 4×4 matrix of a form: [[A, b], [bᵀ, c]].
fn m4(f: &QuadricForm<3>) -> [[Rational; 4]; 4] {
    std::array::from_fn(|i| {
        std::array::from_fn(|j| match (i < 3, j < 3) {
            (true, true) => f.matrix()[i][j].clone(),
            (true, false) => f.linear()[i].clone(),
            (false, true) => f.linear()[j].clone(),
            (false, false) => f.constant().clone(),
        })
    })
}

fn det3(m: &[[Rational; 3]; 3]) -> Rational {
    let t = |a: &Rational, b: &Rational| Rational::from(a * b);
    t(&m[0][0], &(t(&m[1][1], &m[2][2]) - t(&m[1][2], &m[2][1])))
        - t(&m[0][1], &(t(&m[1][0], &m[2][2]) - t(&m[1][2], &m[2][0])))
        + t(&m[0][2], &(t(&m[1][0], &m[2][1]) - t(&m[1][1], &m[2][0])))
}

/// The type from the invariants of the restriction to the plane `p₀ + a·u + b·v`
/// (any rational basis, independent of the frame of (13.2)); circles are not told
/// apart from ellipses here.
fn truth_type(
    f: &QuadricForm<3>,
    p0: &[Rational; 3],
    u: &[Rational; 3],
    v: &[Rational; 3],
) -> &'static str {
    let m = m4(f);
    let cols: [[Rational; 4]; 3] = [
        [u[0].clone(), u[1].clone(), u[2].clone(), qi(0)],
        [v[0].clone(), v[1].clone(), v[2].clone(), qi(0)],
        [p0[0].clone(), p0[1].clone(), p0[2].clone(), qi(1)],
    ];
    let r: [[Rational; 3]; 3] = std::array::from_fn(|i| {
        std::array::from_fn(|j| {
            let mut s = qi(0);
            for k in 0..4 {
                for l in 0..4 {
                    s += Rational::from(&cols[i][k] * &m[k][l]) * &cols[j][l];
                }
            }
            s
        })
    });
    let delta = Rational::from(&r[0][0] * &r[1][1]) - Rational::from(&r[0][1] * &r[1][0]);
    let big = det3(&r);
    let a_zero = r[0][0] == 0 && r[0][1] == 0 && r[1][1] == 0;
    match (delta.cmp0(), big.cmp0()) {
        (Ordering::Greater, Ordering::Equal) => "point",
        (Ordering::Greater, _) => {
            if Rational::from(&r[0][0] * &big).cmp0() == Ordering::Less {
                "ellipse"
            } else {
                "empty"
            }
        }
        (Ordering::Less, Ordering::Equal) => "intersecting_lines",
        (Ordering::Less, _) => "hyperbola",
        (Ordering::Equal, Ordering::Equal) if a_zero => {
            if r[0][2] != 0 || r[1][2] != 0 {
                "line"
            } else if r[2][2] == 0 {
                "plane"
            } else {
                "empty"
            }
        }
        (Ordering::Equal, Ordering::Equal) => {
            // Q = α(w)² + 2βw + c on the parabolic cylinder: the 2×2 minors with c.
            let k = Rational::from(&r[0][0] * &r[2][2]) - Rational::from(&r[0][2] * &r[0][2])
                + Rational::from(&r[1][1] * &r[2][2])
                - Rational::from(&r[1][2] * &r[1][2]);
            // With δ = Δ = 0 both minors have the sign of β² − αc times −a_ii.
            let tr = Rational::from(&r[0][0] + &r[1][1]);
            match Rational::from(&k * &tr).cmp0() {
                Ordering::Less => "parallel_lines",
                Ordering::Equal => "double_line",
                Ordering::Greater => "empty",
            }
        }
        (Ordering::Equal, _) => "parabola",
    }
}

fn cross(a: &[Rational; 3], b: &[Rational; 3]) -> [Rational; 3] {
    std::array::from_fn(|i| {
        let (j, k) = ((i + 1) % 3, (i + 2) % 3);
        Rational::from(&a[j] * &b[k]) - Rational::from(&a[k] * &b[j])
    })
}

fn dot(a: &[Rational; 3], b: &[Rational; 3]) -> Rational {
    let mut s = qi(0);
    for k in 0..3 {
        s += Rational::from(&a[k] * &b[k]);
    }
    s
}

/// A rational basis `p₀, u, v` of the plane `n·x + d = 0` unrelated to (13.2).
fn basis(p: &ExactPlane, rng: &mut Rng) -> ([Rational; 3], [Rational; 3], [Rational; 3]) {
    let n = &p.normal;
    let k = n.iter().position(|x| *x != 0).unwrap();
    let mut p0: [Rational; 3] = std::array::from_fn(|_| qi(rng.int(-5, 5)));
    p0[k] = qi(0);
    p0[k] = -(dot(n, &p0) + &p.d) / &n[k];
    loop {
        let w: [Rational; 3] = std::array::from_fn(|_| qi(rng.int(-4, 4)));
        let u = cross(n, &w);
        let w2: [Rational; 3] = std::array::from_fn(|_| qi(rng.int(-4, 4)));
        let v = cross(n, &w2);
        if cross(&u, &v).iter().any(|x| *x != 0) {
            return (p0, u, v);
        }
    }
}

fn type_name(t: ConicType) -> &'static str {
    match t {
        ConicType::Circle => "ellipse",
        other => other.as_str(),
    }
}

/// Points of the answer lie on both surfaces: exactly for rational points, and the
/// correctly rounded ellipse points within a relative 1e-9.
fn check_points(f: &QuadricForm<3>, p: &ExactPlane, s: &Section) {
    if let Some(c) = &s.center {
        assert_eq!(p.eval(c), 0, "centre on the plane");
        if s.kind == ConicType::Point {
            assert_eq!(f.eval(c), 0, "the point is on the quadric");
        }
        if s.kind == ConicType::Parabola {
            assert_eq!(f.eval(c), 0, "the vertex is on the quadric");
        }
    }
    for l in &s.lines {
        if let Some(x) = l
            .point
            .iter()
            .map(|v| v.exact.clone())
            .collect::<Option<Vec<_>>>()
        {
            let x: [Rational; 3] = x.try_into().unwrap();
            assert_eq!(f.eval(&x), 0, "a rational line point is on the quadric");
            assert_eq!(p.eval(&x), 0);
        }
    }
    if matches!(
        s.kind,
        ConicType::Ellipse | ConicType::Circle | ConicType::Hyperbola
    ) {
        let c: Vec<f64> = s
            .center
            .as_ref()
            .unwrap()
            .iter()
            .map(|x| x.to_f64())
            .collect();
        let (a0, a1) = (&s.axes[0], &s.axes[1]);
        for i in 0..8 {
            let t = i as f64 * 0.7;
            let (ca, sa) = if s.kind == ConicType::Hyperbola {
                (t.cosh(), t.sinh())
            } else {
                (t.cos(), t.sin())
            };
            let x: [Rational; 3] = std::array::from_fn(|k| {
                q(c[k]
                    + a0.length.value * ca * a0.dir[k].value
                    + a1.length.value * sa * a1.dir[k].value)
            });
            let scale = 1.0
                + c.iter().map(|v| v.abs()).fold(0.0, f64::max)
                + a0.length.value * ca.abs()
                + a1.length.value * sa.abs();
            let fx = f.eval(&x).to_f64().abs();
            let grad = f
                .half_gradient(&x)
                .iter()
                .map(|g| g.to_f64().abs())
                .fold(0.0, f64::max);
            assert!(
                fx <= 1e-9 * (1.0 + grad) * scale,
                "off the quadric: {fx} (grad {grad})"
            );
            let px = p.eval(&x).to_f64().abs();
            let nn = p
                .normal
                .iter()
                .map(|v| v.to_f64().abs())
                .fold(0.0, f64::max);
            assert!(px <= 1e-9 * nn * scale, "off the plane: {px}");
        }
    }
}

fn random_form(rng: &mut Rng) -> QuadricForm<3> {
    loop {
        let mut a: [[Rational; 3]; 3] = Default::default();
        for i in 0..3 {
            for j in i..3 {
                let v = if rng.below(3) == 0 { 0 } else { rng.int(-6, 6) };
                a[i][j] = qi(v);
                a[j][i] = qi(v);
            }
        }
        let b: [Rational; 3] = std::array::from_fn(|_| qi(rng.int(-4, 4)));
        if let Ok(f) = QuadricForm::from_rationals(a, b, qi(rng.int(-9, 9))) {
            return f;
        }
    }
}

#[test]
fn random_planes_and_quadrics_classify_like_an_independent_frame() {
    let mut rng = Rng::new(0x5ec7_1017);
    let mut seen = std::collections::BTreeMap::new();
    for _ in 0..600 {
        let f = random_form(&mut rng);
        let normal: [Rational; 3] = loop {
            let n: [Rational; 3] = std::array::from_fn(|_| qi(rng.int(-3, 3)));
            if n.iter().any(|x| *x != 0) {
                break n;
            }
        };
        let p = ExactPlane {
            normal,
            d: Rational::from((rng.int(-20, 20), rng.int(1, 4) as u32)),
        };
        let s = section_plane_quadric(&p, &f);
        let (p0, u, v) = basis(&p, &mut rng);
        assert_eq!(
            type_name(s.kind),
            truth_type(&f, &p0, &u, &v),
            "{f:?} cut by {p:?}"
        );
        // The same plane through three of its points (13.1): the same section.
        let q3 = [
            p0.clone(),
            std::array::from_fn(|k| Rational::from(&p0[k] + &u[k])),
            std::array::from_fn(|k| Rational::from(&p0[k] + &v[k])),
        ];
        let again = plane_through_points_exact(&q3).unwrap();
        let s2 = section_plane_quadric(&again, &f);
        assert_eq!(s2.kind, s.kind);
        assert_eq!(s2.center, s.center);
        check_points(&f, &p, &s);
        *seen.entry(type_name(s.kind)).or_insert(0) += 1;
    }
    for t in ["ellipse", "hyperbola", "empty", "parabola"] {
        assert!(seen.get(t).copied().unwrap_or(0) > 5, "{seen:?}");
    }
}

// ------------------------------------------------ tangency and 1 ulp

fn next_up(x: f64) -> f64 {
    f64::from_bits(if x >= 0.0 {
        x.to_bits() + 1
    } else {
        x.to_bits() - 1
    })
}
fn next_down(x: f64) -> f64 {
    -next_up(-x)
}

#[test]
fn spheres_cut_at_and_one_ulp_around_tangency() {
    let mut rng = Rng::new(17);
    for i in 0..200 {
        let r = (rng.int(1, 1 << 20) as f64) * 2f64.powi(rng.int(-40, 40) as i32);
        let mut c = [
            rng.int(-9, 9) as f64,
            rng.int(-9, 9) as f64,
            rng.int(-9, 9) as f64,
        ];
        let axis = i % 3;
        if q(c[axis] + r) != q(c[axis]) + q(r) {
            c[axis] = 0.0; // keep the tangent plane c + r a double
        }
        let sphere = QuadricForm::sphere(c, r).unwrap();
        let mut n = [0.0; 3];
        n[axis] = 1.0;
        let at = c[axis] + r;
        for (h, want) in [
            (at, ConicType::Point),
            (next_up(at), ConicType::Empty),
            (next_down(at), ConicType::Circle),
        ] {
            let s = section_plane_quadric(&plane(n, -h), &sphere);
            assert_eq!(s.kind, want, "r {r} h {h}");
            if want == ConicType::Circle {
                // radius² = r² − (h − c)², correctly rounded.
                let k = q(r) * q(r) - (q(h) - q(c[axis])).square();
                let truth = Float::with_val(2000, &k).sqrt().to_f64();
                assert_eq!(s.axes[0].length.value, truth);
                assert_eq!(s.axes[1].length.value, truth);
                assert!(all_rounded(&s));
            }
        }
    }
}

#[test]
fn cylinders_cut_parallel_to_the_axis_at_and_around_tangency() {
    let mut rng = Rng::new(18);
    for _ in 0..200 {
        let r = (rng.int(1, 1 << 30) as f64) * 2f64.powi(rng.int(-30, 30) as i32);
        let cyl = QuadricForm::circular_cylinder([0.0; 3], [0.0, 0.0, 1.0], r).unwrap();
        for (h, want) in [
            (r, ConicType::DoubleLine),
            (next_up(r), ConicType::Empty),
            (next_down(r), ConicType::ParallelLines),
            (0.0, ConicType::ParallelLines),
        ] {
            let s = section_plane_quadric(&plane([1.0, 0.0, 0.0], -h), &cyl);
            assert_eq!(s.kind, want, "r {r} h {h}");
            check_points(&cyl, &plane([1.0, 0.0, 0.0], -h), &s);
        }
        // Tilted planes: ellipses, circles when perpendicular to the axis.
        let s = section_plane_quadric(&plane([0.0, 0.0, 1.0], -r), &cyl);
        assert_eq!(s.kind, ConicType::Circle);
        assert_eq!(s.axes[0].length.exact, Some(q(r)));
        let s = section_plane_quadric(&plane([1.0, 0.0, 1.0], 0.0), &cyl);
        assert_eq!(s.kind, ConicType::Ellipse);
        // Semi-axes r√2 and r, the longer first.
        assert_eq!(s.axes[1].length.exact, Some(q(r)));
        assert_eq!(
            s.axes[0].length.value,
            (Float::with_val(200, 2).sqrt() * r).to_f64()
        );
    }
}

/// Cone `|q|²|a|² = (1 + k²)(q·a)²` about a random integer axis: a plane with normal
/// `n` makes the angle `φ` with the axis, `sin²φ = (n·a)²/(|n|²|a|²)`, against
/// `sin²α = k²/(1 + k²)`: through the apex two lines (`φ < α`), a double line (`=`) or
/// the apex (`>`); off the apex a hyperbola, a parabola or an ellipse.
#[test]
fn cones_through_and_off_the_apex() {
    let mut rng = Rng::new(19);
    let mut counts = [0usize; 6];
    for _ in 0..400 {
        let apex = [
            rng.int(-5, 5) as f64,
            rng.int(-5, 5) as f64,
            rng.int(-5, 5) as f64,
        ];
        let axis = loop {
            let a = [
                rng.int(-3, 3) as f64,
                rng.int(-3, 3) as f64,
                rng.int(-3, 3) as f64,
            ];
            if a != [0.0; 3] {
                break a;
            }
        };
        let k = [0.5, 1.0, 0.75, 2.0][rng.below(4)];
        let cone = QuadricForm::circular_cone(apex, axis, k).unwrap();
        let n = loop {
            let n = [
                rng.int(-3, 3) as f64,
                rng.int(-3, 3) as f64,
                rng.int(-3, 3) as f64,
            ];
            if n != [0.0; 3] {
                break n;
            }
        };
        let (nq, aq) = (n.map(q), axis.map(q));
        let lhs = dot(&nq, &aq).square() * (q(k).square() + 1u32);
        let rhs = q(k).square() * dot(&nq, &nq) * dot(&aq, &aq);
        let side = lhs.cmp(&rhs); // Less: φ < α
        let d0 = -dot(&nq, &apex.map(q)).to_f64();
        let through = section_plane_quadric(&plane(n, d0), &cone);
        let want = match side {
            Ordering::Less => ConicType::IntersectingLines,
            Ordering::Equal => ConicType::DoubleLine,
            Ordering::Greater => ConicType::Point,
        };
        assert_eq!(through.kind, want);
        check_points(&cone, &plane(n, d0), &through);
        if want == ConicType::Point {
            assert_eq!(through.center.clone().unwrap(), apex.map(q));
        }
        let off = section_plane_quadric(&plane(n, d0 + 1.0), &cone);
        let want = match side {
            Ordering::Less => ConicType::Hyperbola,
            Ordering::Equal => ConicType::Parabola,
            Ordering::Greater => ConicType::Ellipse,
        };
        let got = if off.kind == ConicType::Circle {
            ConicType::Ellipse
        } else {
            off.kind
        };
        assert_eq!(got, want);
        check_points(&cone, &plane(n, d0 + 1.0), &off);
        counts[match side {
            Ordering::Less => 0,
            Ordering::Equal => 1,
            Ordering::Greater => 2,
        }] += 1;
    }
    assert!(counts[0] > 10 && counts[2] > 10, "{counts:?}");
}

/// Planes at exactly the cone's half-angle (`tan α` = 3/4 or 1 with Pythagorean
/// normals): through the apex a double line, one ulp of offset either side a
/// parabola; steeper or flatter normals 1 ulp away in direction change the type.
#[test]
fn cones_at_the_half_angle_and_one_ulp_off_the_apex() {
    let mut rng = Rng::new(21);
    for _ in 0..100 {
        let apex = [
            rng.int(-50, 50) as f64,
            rng.int(-50, 50) as f64,
            rng.int(-50, 50) as f64 / 8.0,
        ];
        for (k, normals) in [
            (0.75, [[4.0, 0.0, 3.0], [0.0, -4.0, 3.0]]),
            (1.0, [[1.0, 0.0, 1.0], [3.0, 4.0, -5.0]]),
        ] {
            let cone = QuadricForm::circular_cone(apex, [0.0, 0.0, 1.0], k).unwrap();
            for n in normals {
                let d0 = -(n[0] * apex[0] + n[1] * apex[1] + n[2] * apex[2]);
                assert_eq!(q(d0), -dot(&n.map(q), &apex.map(q)), "exact offset");
                let s = section_plane_quadric(&plane(n, d0), &cone);
                assert_eq!(s.kind, ConicType::DoubleLine);
                check_points(&cone, &plane(n, d0), &s);
                for d in [next_up(d0), next_down(d0)] {
                    let s = section_plane_quadric(&plane(n, d), &cone);
                    assert_eq!(s.kind, ConicType::Parabola, "d {d} vs {d0}");
                    check_points(&cone, &plane(n, d), &s);
                }
                // Tilt the normal by one ulp in z: flatter → two lines, steeper → point.
                let mut up = n;
                up[2] = next_up(n[2].abs()) * n[2].signum();
                let mut down = n;
                down[2] = next_down(n[2].abs()) * n[2].signum();
                let through = |m: [f64; 3]| {
                    let d = -dot(&m.map(q), &apex.map(q));
                    section_plane_quadric(
                        &ExactPlane {
                            normal: m.map(q),
                            d,
                        },
                        &cone,
                    )
                    .kind
                };
                assert_eq!(through(up), ConicType::Point);
                assert_eq!(through(down), ConicType::IntersectingLines);
            }
        }
    }
}

// ------------------------------------------------ polyhedra

fn cube() -> Polyhedron {
    let v: Vec<[Rational; 3]> = (0..8)
        .map(|i| [qi(i & 1), qi((i >> 1) & 1), qi((i >> 2) & 1)])
        .collect();
    let faces = vec![
        vec![0, 2, 3, 1],
        vec![4, 5, 7, 6],
        vec![0, 1, 5, 4],
        vec![2, 6, 7, 3],
        vec![0, 4, 6, 2],
        vec![1, 3, 7, 5],
    ];
    Polyhedron::new(v, faces).unwrap()
}

fn area2(n: &[Rational; 3], v: &[[Rational; 3]]) -> Rational {
    // (n·Σ pᵢ × pᵢ₊₁)² / (4|n|²)
    let mut s = qi(0);
    for i in 0..v.len() {
        s += dot(n, &cross(&v[i], &v[(i + 1) % v.len()]));
    }
    assert!(s.cmp0() != Ordering::Less, "counter-clockwise seen from +n");
    s.square() / (dot(n, n) * 4u32)
}

#[test]
fn cube_sections_through_vertices_edges_and_faces() {
    let cube = cube();
    let n = [qi(1), qi(1), qi(1)];
    let mut rng = Rng::new(20);
    let mut ks: Vec<Rational> = (0..=6).map(|i| Rational::from((i, 2))).collect();
    ks.extend((0..100).map(|_| Rational::from((rng.int(-10, 310), 100))));
    for k in ks {
        let p = ExactPlane {
            normal: n.clone(),
            d: -k.clone(),
        };
        let loops = section_plane_polyhedron(&p, &cube);
        if !(0..=3).contains(&k) {
            assert!(loops.is_empty());
            continue;
        }
        assert_eq!(loops.len(), 1, "k = {k}");
        let v = &loops[0].vertices;
        for x in v {
            assert_eq!(p.eval(x), 0);
            assert!(x.iter().all(|c| *c >= 0 && *c <= 1), "on the cube");
        }
        // Area of x + y + z = k in the unit cube: (√3/2)(k² − 3(k−1)₊² + 3(k−2)₊²).
        let pos = |x: Rational| {
            if x.cmp0() == Ordering::Greater {
                x
            } else {
                qi(0)
            }
        };
        let poly = Rational::from(k.square_ref()) - pos(k.clone() - 1u32).square() * 3u32
            + pos(k.clone() - 2u32).square() * 3u32;
        let want = Rational::from(poly.square_ref()) * 3u32 / 4u32;
        assert_eq!(area2(&n, v), want, "k = {k}");
        let count = if k == 0 || k == 3 {
            1
        } else if !(1..=2).contains(&k) || k == 1 || k == 2 {
            3
        } else {
            6
        };
        assert_eq!(v.len(), count, "k = {k}: {v:?}");
    }
    // A face: z = 1 and z = 0 give the face squares; an edge: x + y = 2 gives it.
    for h in [0, 1] {
        let p = ExactPlane {
            normal: [qi(0), qi(0), qi(1)],
            d: qi(-h),
        };
        let loops = section_plane_polyhedron(&p, &cube);
        assert_eq!(loops.len(), 1);
        assert_eq!(loops[0].vertices.len(), 4);
        assert_eq!(area2(&p.normal, &loops[0].vertices), 1);
    }
    let edge = ExactPlane {
        normal: [qi(1), qi(1), qi(0)],
        d: qi(-2),
    };
    let loops = section_plane_polyhedron(&edge, &cube);
    assert_eq!(loops.len(), 1);
    let mut v = loops[0].vertices.clone();
    v.sort();
    assert_eq!(v, vec![[qi(1), qi(1), qi(0)], [qi(1), qi(1), qi(1)]]);
    // The diagonal plane x = y through two opposite edges: a √2 × 1 rectangle.
    let diag = ExactPlane {
        normal: [qi(1), qi(-1), qi(0)],
        d: qi(0),
    };
    let loops = section_plane_polyhedron(&diag, &cube);
    assert_eq!(loops[0].vertices.len(), 4);
    assert_eq!(area2(&diag.normal, &loops[0].vertices), 2);
}

/// A regular prism (13.6) or pyramid (13.7) with vertices rounded to doubles (the
/// section is exact for these doubles).
fn regular(n: usize, r: f64, theta0: f64, top: Option<f64>, apex: Option<f64>) -> Polyhedron {
    let mut v: Vec<[Rational; 3]> = (0..n)
        .map(|k| {
            let t = theta0 + 2.0 * std::f64::consts::PI * k as f64 / n as f64;
            [q(r * t.cos()), q(r * t.sin()), qi(0)]
        })
        .collect();
    let mut faces = vec![(0..n).rev().collect::<Vec<_>>()];
    if let Some(h) = top {
        let upper: Vec<[Rational; 3]> = v
            .iter()
            .map(|p| [p[0].clone(), p[1].clone(), q(h)])
            .collect();
        v.extend(upper);
        faces.push((n..2 * n).collect());
        for k in 0..n {
            let k1 = (k + 1) % n;
            faces.push(vec![k, k1, n + k1, n + k]);
        }
    }
    if let Some(h) = apex {
        v.push([qi(0), qi(0), q(h)]);
        for k in 0..n {
            faces.push(vec![k, (k + 1) % n, n]);
        }
    }
    Polyhedron::new(v, faces).unwrap()
}

fn polygon_area_perimeter(v: &[[Rational; 3]]) -> (f64, f64) {
    let f: Vec<[f64; 3]> = v.iter().map(|p| p.clone().map(|x| x.to_f64())).collect();
    let (mut s, mut per) = ([0.0; 3], 0.0);
    for i in 0..f.len() {
        let (a, b) = (f[i], f[(i + 1) % f.len()]);
        s[0] += a[1] * b[2] - a[2] * b[1];
        s[1] += a[2] * b[0] - a[0] * b[2];
        s[2] += a[0] * b[1] - a[1] * b[0];
        per += ((b[0] - a[0]).powi(2) + (b[1] - a[1]).powi(2) + (b[2] - a[2]).powi(2)).sqrt();
    }
    (0.5 * (s[0] * s[0] + s[1] * s[1] + s[2] * s[2]).sqrt(), per)
}

#[test]
fn worked_example_16_11_prism_and_pyramid() {
    let cut = plane([1.0, 3.0, 16.0], -16.0);
    let prism = regular(12, 5.0, 0.13, Some(12.0), None);
    let loops = section_plane_polyhedron(&cut, &prism);
    assert_eq!(loops.len(), 1);
    let v = &loops[0].vertices;
    assert_eq!(v.len(), 12);
    for x in v {
        assert_eq!(cut.eval(x), 0);
    }
    let first = [4.95780947, 0.64817071, 0.56860490];
    assert!(v
        .iter()
        .any(|x| (0..3).all(|k| (x[k].to_f64() - first[k]).abs() < 1e-8)));
    let (area, per) = polygon_area_perimeter(v);
    assert!((area - 76.4508113920).abs() < 1e-8, "{area}");
    assert!((per - 31.3594029218).abs() < 1e-8, "{per}");

    let (h, psi, n) = (12.0f64, 0.35f64, 12usize);
    let rb = h * psi.tan() / (std::f64::consts::PI / n as f64).cos();
    let pyramid = regular(n, rb, 0.26, None, Some(h));
    let loops = section_plane_polyhedron(&cut, &pyramid);
    assert_eq!(loops.len(), 1);
    let v = &loops[0].vertices;
    assert_eq!(v.len(), 12);
    let p0 = [4.18917181, 1.11440994, 0.52922490];
    assert!(v
        .iter()
        .any(|x| (0..3).all(|k| (x[k].to_f64() - p0[k]).abs() < 1e-7)));
    let (area, per) = polygon_area_perimeter(v);
    assert!((area - 53.2690043984).abs() < 1e-7, "{area}");
    assert!((per - 26.1796573775).abs() < 1e-7, "{per}");
}

#[test]
fn prism_sections_through_vertices_and_edges() {
    // Horizontal planes at the base and the top give the 12-gon; through a lateral
    // edge of the rounded prism (the vertical plane through the axis and vertex k).
    let prism = regular(12, 5.0, 0.13, Some(12.0), None);
    for h in [0.0, 12.0, 6.0] {
        let loops = section_plane_polyhedron(&plane([0.0, 0.0, 1.0], -h), &prism);
        assert_eq!(loops.len(), 1);
        assert_eq!(loops[0].vertices.len(), 12);
    }
    let vs = prism.vertices().to_vec();
    for k in 0..12 {
        // The vertical plane through vertex k and its opposite vertex k + 6.
        let (a, b) = (&vs[k], &vs[k + 6]);
        let normal = [
            Rational::from(&b[1] - &a[1]),
            Rational::from(&a[0] - &b[0]),
            qi(0),
        ];
        let d = -dot(&normal, a);
        let p = ExactPlane { normal, d };
        let loops = section_plane_polyhedron(&p, &prism);
        assert_eq!(loops.len(), 1);
        let v = &loops[0].vertices;
        assert_eq!(v.len(), 4, "a rectangle through two lateral edges");
        for x in v {
            assert_eq!(p.eval(x), 0);
        }
        // A plane touching the prism along lateral edge k only (its supporting plane
        // rotated about the edge): a two-point loop, the edge.
        let t = std::f64::consts::PI * (0.13 + 2.0 * std::f64::consts::PI * k as f64 / 12.0)
            / std::f64::consts::PI;
        let normal = [q(t.cos()), q(t.sin()), qi(0)];
        let d = -dot(&normal, a);
        let loops = section_plane_polyhedron(&ExactPlane { normal, d }, &prism);
        if let Some(l) = loops.first() {
            assert!(l.vertices.len() <= 2 || loops.len() == 1);
        }
    }
}

// ------------------------------------------------ CLI and errors

fn solve(case: &str) -> serde_json::Value {
    let case = case.replace('\n', " ");
    let mut read = geocert::io::read_cases(&case);
    let r = geocert::io::solve_case(read.remove(0));
    serde_json::to_value(&r).unwrap()
}

#[test]
fn section_cases_through_the_command_line() {
    let r = solve(
        r#"{"id": 1, "op": "section", "objects": [{"type": "ellipsoid", "center": [0,0,0], "a": 3, "b": 3, "c": 5},
            {"type": "plane", "points": [[16,0,0], [1,5,0], [0,0,1]]}]}"#,
    );
    assert_eq!(r["status"], "exact", "{r}");
    assert_eq!(r["kind"], "curves");
    assert_eq!(r["conic"]["type"], "ellipse");
    let len = r["conic"]["axes"][0]["length"]["value"][0]
        .as_f64()
        .unwrap();
    assert!((len - 2.9762593965).abs() < 1e-9);
    let r = solve(
        r#"{"op": "section", "objects": [{"type": "sphere", "center": [0,0,0], "radius": 1},
            {"type": "plane", "normal": [0,0,1], "d": -2}]}"#,
    );
    assert_eq!(r["kind"], "empty", "{r}");
    let r = solve(
        r#"{"op": "section", "objects": [{"type": "polyhedron", "vertices": [[0,0,0],[1,0,0],[0,1,0],[0,0,1]],
            "faces": [[0,2,1],[0,1,3],[0,3,2],[1,2,3]]}, {"type": "plane", "normal": [0,0,1], "d": "-1/2"}]}"#,
    );
    assert_eq!(r["status"], "exact", "{r}");
    let pts = r["curves"][0]["points"].as_array().unwrap();
    assert_eq!(pts.len(), 4, "a closed triangle repeats its first vertex");
    assert!(
        pts.iter()
            .any(|p| p["exact"] == serde_json::json!(["1/2", "0", "1/2"])),
        "{r}"
    );
}

#[test]
fn typed_errors_name_the_field() {
    let e = |case: &str| {
        let r = solve(case);
        assert_eq!(r["status"], "error", "{r}");
        r["error"]["field"].as_str().unwrap().to_string()
    };
    assert_eq!(
        e(
            r#"{"op": "section", "objects": [{"type": "sphere", "center": [0,0,0], "radius": 1},
              {"type": "plane", "points": [[0,0,0], [1,1,1], [2,2,2]]}]}"#
        ),
        "objects[1].points[2]"
    );
    assert_eq!(
        e(
            r#"{"op": "section", "objects": [{"type": "sphere", "center": [0,0,0], "radius": 1},
              {"type": "plane", "points": [[0,0,0], [0,0,0], [2,2,2]]}]}"#
        ),
        "objects[1].points[1]"
    );
    assert_eq!(
        e(
            r#"{"op": "section", "objects": [{"type": "torus", "center": [0,0,0], "major": 3, "minor": 1, "axis": [0,0,1]},
              {"type": "plane", "normal": [0,0,1], "d": 0}]}"#
        ),
        "objects[0].type"
    );
    assert_eq!(
        e(
            r#"{"op": "section", "objects": [{"type": "sphere", "center": [0,0,0], "radius": 1},
              {"type": "line", "origin": [0,0,0], "dir": [1,0,0]}]}"#
        ),
        "objects[1].type"
    );
    assert_eq!(
        e(r#"{"op": "section", "objects": [{"type": "sphere", "center": [0,0,0], "radius": 1}]}"#),
        "objects"
    );
}

#[test]
fn intersect_plane_and_whole_sphere_decides_the_section_exactly_first() {
    let case = |d: &str| {
        format!(
            r#"{{"op": "intersect", "objects": [{{"type": "plane", "normal": [0, 0, 1], "d": {d}}},
                {{"type": "sphere", "center": [0, 0, 0], "radius": 1}}]}}"#
        )
    };
    // One ulp beyond the tangent plane z = 1: exactly empty, complete.
    let r = solve(&case(&format!("{:e}", -next_up(1.0))));
    assert_eq!(r["kind"], "empty", "{r}");
    assert_eq!(r["status"], "exact");
    assert_eq!(r["complete"], true);
    // z = 1/2: the traced circle carries the exact conic (radius √3/2).
    let r = solve(&case("-0.5"));
    assert_eq!(r["kind"], "curves", "{r}");
    assert_eq!(r["conic"]["type"], "circle");
    let len = r["conic"]["axes"][0]["length"]["value"][0]
        .as_f64()
        .unwrap();
    assert_eq!(len, 3f64.sqrt() / 2.0);
}
