//! Point → surface projection, float path (OPERATIONS.md §3.4), against closed forms.
//! The surfaces are test-local so this test depends only on the Surface trait.

use geocert::num::Real;
use geocert::ops::float::Precision;
use geocert::ops::project::{project_point_on_surface_f64, SurfaceFeet};
use geocert::surface::Surface;
use std::f64::consts::{FRAC_PI_2, PI, TAU};

/// Torus `((R + r cos v) cos u, (R + r cos v) sin u, r sin v)` on `[0, 2π]²`; with
/// `r_major = 0` and `v ∈ [−π/2, π/2]` it is the sphere of §1.6.
struct Torus {
    major: f64,
    minor: f64,
    v_range: [f64; 2],
}

impl Surface for Torus {
    fn domain(&self) -> ([f64; 2], [f64; 2]) {
        ([0.0, TAU], self.v_range)
    }
    fn is_closed(&self) -> [bool; 2] {
        [true, self.v_range == [0.0, TAU]]
    }
    fn jet<T: Real>(&self, u: &T, v: &T, order: usize) -> Vec<[T; 3]> {
        let (cu, su, cv, sv) = (u.cos(), u.sin(), v.cos(), v.sin());
        let (big, r) = (u.lift(self.major), u.lift(self.minor));
        let w = big + r.clone() * &cv; // R + r cos v
        let z = u.zero_like();
        let all = vec![
            [w.clone() * &cu, w.clone() * &su, r.clone() * &sv],
            [-(w.clone() * &su), w.clone() * &cu, z.clone()],
            [
                -(r.clone() * &sv * &cu),
                -(r.clone() * &sv * &su),
                r.clone() * &cv,
            ],
            [-(w.clone() * &cu), -(w * &su), z.clone()],
            [r.clone() * &sv * &su, -(r.clone() * &sv * &cu), z],
            [
                -(r.clone() * &cv * &cu),
                -(r.clone() * &cv * &su),
                -(r * &sv),
            ],
        ];
        all.into_iter().take([1, 3, 6][order.min(2)]).collect()
    }
}

/// The unit square `(u, v, 0)`, `[0, 1]²`, open in both directions.
struct Square;

impl Surface for Square {
    fn domain(&self) -> ([f64; 2], [f64; 2]) {
        ([0.0, 1.0], [0.0, 1.0])
    }
    fn jet<T: Real>(&self, u: &T, v: &T, order: usize) -> Vec<[T; 3]> {
        let (z, o) = (u.zero_like(), u.one_like());
        let all = vec![
            [u.clone(), v.clone(), z.clone()],
            [o.clone(), z.clone(), z.clone()],
            [z.clone(), o, z.clone()],
            [z.clone(), z.clone(), z.clone()],
            [z.clone(), z.clone(), z.clone()],
            [z.clone(), z.clone(), z],
        ];
        all.into_iter().take([1, 3, 6][order.min(2)]).collect()
    }
}

fn nodes(s: &impl Surface, n: usize) -> Vec<[f64; 4]> {
    let ([u0, u1], [v0, v1]) = s.domain();
    let (du, dv) = ((u1 - u0) / n as f64, (v1 - v0) / n as f64);
    let mut out = Vec::new();
    for i in 0..=n {
        for j in 0..=n {
            out.push([u0 + i as f64 * du, v0 + j as f64 * dv, du, dv]);
        }
    }
    out
}

fn finite(r: SurfaceFeet) -> Vec<geocert::ops::project::SurfaceFoot> {
    match r {
        SurfaceFeet::Finite(f) => f,
        SurfaceFeet::Infinite => panic!("finite expected"),
    }
}

#[test]
fn a_torus_has_four_feet_from_a_generic_point() {
    // p = (1, 2, 3), R = 3, r = 1: in the half-plane of angle φ = atan2(2, 1) the tube
    // centre is at distance √((√5 − 3)² + 9); in the opposite half-plane at √((√5 + 3)² + 9).
    let torus = Torus {
        major: 3.0,
        minor: 1.0,
        v_range: [0.0, TAU],
    };
    let p = [1.0, 2.0, 3.0];
    let feet = finite(project_point_on_surface_f64(
        &torus,
        &p,
        &nodes(&torus, 20),
        &Precision::default(),
        false,
    ));
    let near = ((5f64.sqrt() - 3.0).powi(2) + 9.0).sqrt();
    let far = ((5f64.sqrt() + 3.0).powi(2) + 9.0).sqrt();
    let mut d: Vec<f64> = feet.iter().map(|f| f.distance).collect();
    d.sort_by(f64::total_cmp);
    let mut expected = [near - 1.0, near + 1.0, far - 1.0, far + 1.0];
    expected.sort_by(f64::total_cmp);
    assert_eq!(d.len(), 4, "{feet:?}");
    for (x, y) in d.iter().zip(expected) {
        assert!((x - y).abs() < 1e-12, "{d:?} vs {expected:?}");
    }
    let phi = 2f64.atan2(1.0);
    let nearest = finite(project_point_on_surface_f64(
        &torus,
        &p,
        &nodes(&torus, 20),
        &Precision::default(),
        true,
    ));
    assert_eq!(nearest.len(), 1);
    assert!((nearest[0].distance - (near - 1.0)).abs() < 1e-12);
    assert!((nearest[0].params[0] - phi).abs() < 1e-12);
}

#[test]
fn a_sphere_has_two_feet_and_its_centre_infinitely_many() {
    let sphere = Torus {
        major: 0.0,
        minor: 2.0,
        v_range: [-FRAC_PI_2, FRAC_PI_2],
    };
    let p = [1.0, 2.0, 2.0]; // |p| = 3: feet at distance 1 and 5
    let feet = finite(project_point_on_surface_f64(
        &sphere,
        &p,
        &nodes(&sphere, 16),
        &Precision::default(),
        false,
    ));
    let mut d: Vec<f64> = feet.iter().map(|f| f.distance).collect();
    d.sort_by(f64::total_cmp);
    assert_eq!(d.len(), 2, "{feet:?}");
    assert!((d[0] - 1.0).abs() < 1e-13 && (d[1] - 5.0).abs() < 1e-13);
    let centre = project_point_on_surface_f64(
        &sphere,
        &[0.0; 3],
        &nodes(&sphere, 16),
        &Precision::default(),
        false,
    );
    assert_eq!(centre, SurfaceFeet::Infinite);
}

#[test]
fn a_point_on_the_axis_projects_to_the_pole_once() {
    // p = (0, 0, 5) above the sphere of radius 2: the poles (distance 3 and 7), each a
    // single point of space although every u maps to it.
    let sphere = Torus {
        major: 0.0,
        minor: 2.0,
        v_range: [-FRAC_PI_2, FRAC_PI_2],
    };
    let feet = finite(project_point_on_surface_f64(
        &sphere,
        &[0.0, 0.0, 5.0],
        &nodes(&sphere, 16),
        &Precision::default(),
        false,
    ));
    let mut d: Vec<f64> = feet.iter().map(|f| f.distance).collect();
    d.sort_by(f64::total_cmp);
    assert_eq!(d, vec![3.0, 7.0], "{feet:?}");
    assert!(feet
        .iter()
        .all(|f| (f.params[1].abs() - FRAC_PI_2).abs() < 1e-12));
    let _ = PI;
}

#[test]
fn nearest_on_an_open_patch_may_be_a_boundary_point() {
    // Above and beside the unit square: no interior foot; the nearest point is on the
    // edge u = 1 at v = 0.5.
    let feet = finite(project_point_on_surface_f64(
        &Square,
        &[2.0, 0.5, 1.0],
        &nodes(&Square, 8),
        &Precision::default(),
        true,
    ));
    assert_eq!(feet.len(), 1);
    assert_eq!(feet[0].params, [1.0, 0.5]);
    assert!((feet[0].distance - 2f64.sqrt()).abs() < 1e-15);
    let all = finite(project_point_on_surface_f64(
        &Square,
        &[2.0, 0.5, 1.0],
        &nodes(&Square, 8),
        &Precision::default(),
        false,
    ));
    assert!(all.is_empty(), "{all:?}");
}
