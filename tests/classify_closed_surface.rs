//! Point against a closed analytic surface (OPERATIONS.md §4, §1.6), decided exactly:
//! exact facts on the surfaces, one-ulp neighbours, huge and tiny magnitudes, and a
//! property against an independent exact MPFR evaluation of the implicit polynomial.

use geocert::num::round::{next_down, next_up};
use geocert::ops::classify::Side;
use geocert::ops::closed_surface::classify_point_surface;
use geocert::surface::quadrics::{Ellipsoid, Sphere};
use geocert::surface::torus::Torus;
use geocert::surface::AnySurface;
use geocert::Status;
use proptest::prelude::*;
use rug::Float;

fn side(p: [f64; 3], s: &AnySurface) -> Side {
    let c = classify_point_surface(&p, s).expect("a closed shell");
    assert_eq!(c.status, Status::Exact);
    assert!(c.complete);
    c.value
}

#[test]
fn sphere_on_and_one_ulp_either_side() {
    let s = AnySurface::Sphere(Sphere::new([0.0; 3], 1.0, None, None).unwrap());
    assert_eq!(side([1.0, 0.0, 0.0], &s), Side::On);
    assert_eq!(side([next_up(1.0), 0.0, 0.0], &s), Side::Outside);
    assert_eq!(side([next_down(1.0), 0.0, 0.0], &s), Side::Inside);
    // 0.6² + 0.8² of the doubles nearest 0.6 and 0.8 is not 1: decided exactly.
    let exact =
        Float::with_val(400, 0.6f64).square() + Float::with_val(400, 0.8f64).square() - 1u32;
    let expected = if exact > 0 {
        Side::Outside
    } else {
        Side::Inside
    };
    assert!(exact != 0);
    assert_eq!(side([0.6, 0.8, 0.0], &s), expected);
}

#[test]
fn huge_and_tiny_spheres_are_decided() {
    for scale in [1e150, 1e-150, 1e300, 1e-300] {
        let s =
            AnySurface::Sphere(Sphere::new([0.0, -scale, 0.0], 4.0 * scale, None, None).unwrap());
        // 4·scale is exact (a power of two times a double), so the point is on.
        assert_eq!(side([4.0 * scale, -scale, 0.0], &s), Side::On, "{scale}");
        assert_eq!(side([next_up(4.0 * scale), -scale, 0.0], &s), Side::Outside);
        assert_eq!(side([scale, -scale, scale], &s), Side::Inside);
    }
}

#[test]
fn ellipsoid_vertices_on_a_tilted_frame() {
    // Axis (1, 1, 0): the default X is +z (the least aligned coordinate vector), so
    // the vertex along X is centre + a·(0, 0, 1).
    let s = AnySurface::Ellipsoid(
        Ellipsoid::new(
            [1.0, 2.0, 3.0],
            [3.0, 2.0, 1.0],
            Some([1.0, 1.0, 0.0]),
            None,
        )
        .unwrap(),
    );
    assert_eq!(side([1.0, 2.0, 6.0], &s), Side::On);
    assert_eq!(side([1.0, 2.0, next_up(6.0)], &s), Side::Outside);
    assert_eq!(side([1.0, 2.0, next_down(6.0)], &s), Side::Inside);
    // Along Z: (1,1,0)/√2 · 0.7 is inside (0.7 < c = 1), 1.5 outside.
    assert_eq!(side([1.5, 2.5, 3.0], &s), Side::Inside);
    assert_eq!(side([2.5, 3.5, 3.0], &s), Side::Outside);
    // With ref = y the X axis is +y: the vertex centre + 3·(0, 1, 0)·... lies off the
    // Z axis (Z ⟂ y fails: ref is made orthogonal, X = (−1, 1, 0)/√2, Y = z).
    let r = AnySurface::Ellipsoid(
        Ellipsoid::new(
            [0.0; 3],
            [3.0, 2.0, 1.0],
            Some([0.0, 0.0, 1.0]),
            Some([0.0, 5.0, 0.0]),
        )
        .unwrap(),
    );
    assert_eq!(side([0.0, 3.0, 0.0], &r), Side::On);
    assert_eq!(side([2.0, 0.0, 0.0], &r), Side::On);
    assert_eq!(side([0.0, 0.0, 1.0], &r), Side::On);
}

#[test]
fn torus_on_inside_and_outside() {
    let t = AnySurface::Torus(Torus::new([0.0; 3], 3.0, 1.0, [0.0, 0.0, 1.0], None).unwrap());
    for p in [
        [4.0, 0.0, 0.0],
        [2.0, 0.0, 0.0],
        [3.0, 0.0, 1.0],
        [0.0, -4.0, 0.0],
    ] {
        assert_eq!(side(p, &t), Side::On, "{p:?}");
    }
    assert_eq!(side([3.0, 0.0, 0.0], &t), Side::Inside);
    assert_eq!(side([0.0, 0.0, 0.0], &t), Side::Outside);
    assert_eq!(side([5.0, 0.0, 0.0], &t), Side::Outside);
    assert_eq!(side([next_up(4.0), 0.0, 0.0], &t), Side::Outside);
    assert_eq!(side([next_down(2.0), 0.0, 0.0], &t), Side::Outside);
    // Axis y, unnormalised: the tube circle of the point (0, 1, 3) has h = 1, ρ² = 10.
    let ty = AnySurface::Torus(Torus::new([0.0; 3], 3.0, 1.0, [0.0, 7.0, 0.0], None).unwrap());
    assert_eq!(side([0.0, 1.0, 3.0], &ty), Side::On);
    assert_eq!(side([0.0, 0.5, 3.0], &ty), Side::Inside);
}

fn mpfr_sign_sphere(p: [f64; 3], c: [f64; 3], r: f64) -> std::cmp::Ordering {
    let mut f = Float::with_val(2000, 0);
    for i in 0..3 {
        let d = Float::with_val(2000, p[i]) - c[i];
        f += d.square();
    }
    f -= Float::with_val(2000, r).square();
    f.cmp0().expect("finite")
}

fn mpfr_sign_torus(p: [f64; 3], big: f64, small: f64) -> std::cmp::Ordering {
    let prec = 2000;
    let sq = |x: f64| Float::with_val(prec, x).square();
    let rho2 = sq(p[0]) + sq(p[1]) + sq(p[2]);
    let s = rho2.clone() + sq(big) - sq(small);
    let f = s.square() - Float::with_val(prec, 4) * sq(big) * (rho2 - sq(p[2]));
    f.cmp0().expect("finite")
}

fn expected(o: std::cmp::Ordering) -> Side {
    match o {
        std::cmp::Ordering::Less => Side::Inside,
        std::cmp::Ordering::Equal => Side::On,
        std::cmp::Ordering::Greater => Side::Outside,
    }
}

fn coordinate() -> impl Strategy<Value = f64> {
    (-1000i64..1000, -20i32..20).prop_map(|(m, e)| m as f64 * 2f64.powi(e))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]

    #[test]
    fn sphere_side_is_the_sign_of_the_exact_implicit_value(
        p in [coordinate(), coordinate(), coordinate()],
        c in [coordinate(), coordinate(), coordinate()],
        r in (1i64..1000, -20i32..20).prop_map(|(m, e)| m as f64 * 2f64.powi(e)),
    ) {
        let s = AnySurface::Sphere(Sphere::new(c, r, None, None).unwrap());
        prop_assert_eq!(side(p, &s), expected(mpfr_sign_sphere(p, c, r)));
    }

    #[test]
    fn torus_side_is_the_sign_of_the_exact_implicit_value(
        p in [coordinate(), coordinate(), coordinate()],
        big in (1i64..100, -4i32..4).prop_map(|(m, e)| m as f64 * 2f64.powi(e)),
        small in (1i64..100, -4i32..4).prop_map(|(m, e)| m as f64 * 2f64.powi(e)),
    ) {
        let t = AnySurface::Torus(Torus::new([0.0; 3], big, small, [0.0, 0.0, 1.0], None).unwrap());
        prop_assert_eq!(side(p, &t), expected(mpfr_sign_torus(p, big, small)));
    }

    #[test]
    fn points_built_on_the_sphere_are_on(
        c in [coordinate(), coordinate(), coordinate()],
        k in 1i64..50,
        e in -30i32..30,
    ) {
        // (3k, 4k, 0)·2^e lies exactly at distance 5k·2^e from the centre... when the
        // sums are exact doubles; keep the centre on a coarser grid so they are.
        let s = 2f64.powi(e);
        let c = c.map(|x| (x * 64.0).round() * s);
        let p = [c[0] + 3.0 * k as f64 * s, c[1] + 4.0 * k as f64 * s, c[2]];
        prop_assume!(p[0] - c[0] == 3.0 * k as f64 * s && p[1] - c[1] == 4.0 * k as f64 * s);
        let sphere = AnySurface::Sphere(Sphere::new(c, 5.0 * k as f64 * s, None, None).unwrap());
        prop_assert_eq!(side(p, &sphere), Side::On);
    }
}
