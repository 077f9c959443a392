//! Point → surface projection, float path (OPERATIONS.md §3.4), against closed forms.
//! The surfaces are test-local so this test depends only on the Surface trait.

use geocert::ops::float::Precision;
use geocert::ops::project::{project_point_surface_f64, SurfaceFeet};
use std::f64::consts::{FRAC_PI_2, TAU};

mod ops_support;
use ops_support::{nodes, Square, Torus};

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
    let feet = finite(project_point_surface_f64(
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
    let nearest = finite(project_point_surface_f64(
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
    let feet = finite(project_point_surface_f64(
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
    let centre = project_point_surface_f64(
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
    let feet = finite(project_point_surface_f64(
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
}

#[test]
fn nearest_on_an_open_patch_may_be_a_boundary_point() {
    // Above and beside the unit square: no interior foot; the nearest point is on the
    // edge u = 1 at v = 0.5.
    let feet = finite(project_point_surface_f64(
        &Square,
        &[2.0, 0.5, 1.0],
        &nodes(&Square, 8),
        &Precision::default(),
        true,
    ));
    assert_eq!(feet.len(), 1);
    assert_eq!(feet[0].params, [1.0, 0.5]);
    assert!((feet[0].distance - 2f64.sqrt()).abs() < 1e-15);
    let all = finite(project_point_surface_f64(
        &Square,
        &[2.0, 0.5, 1.0],
        &nodes(&Square, 8),
        &Precision::default(),
        false,
    ));
    assert!(all.is_empty(), "{all:?}");
}

#[test]
fn projection_along_a_direction_onto_a_sphere() {
    use geocert::ops::project::project_point_surface_along_f64;
    // From (0.6, 0, 5) straight down onto the sphere of radius 1: hits at z = ±0.8,
    // travel t = 4.2 and 5.8 with the unit direction (0, 0, −1); with dir (0, 0, −2)
    // the travel halves.
    let sphere = Torus {
        major: 0.0,
        minor: 1.0,
        v_range: [-FRAC_PI_2, FRAC_PI_2],
    };
    let n = nodes(&sphere, 16);
    let pts = project_point_surface_along_f64(
        &sphere,
        &[0.6, 0.0, 5.0],
        &[0.0, 0.0, -2.0],
        &n,
        0.3,
        &Precision::default(),
        false,
    );
    assert_eq!(pts.len(), 2, "{pts:?}");
    assert!(
        (pts[0].t - 2.1).abs() < 1e-12 && (pts[1].t - 2.9).abs() < 1e-12,
        "{pts:?}"
    );
    assert!((pts[0].point[2] - 0.8).abs() < 1e-12 && (pts[1].point[2] + 0.8).abs() < 1e-12);
    let nearest = project_point_surface_along_f64(
        &sphere,
        &[0.6, 0.0, 5.0],
        &[0.0, 0.0, 1.0],
        &n,
        0.3,
        &Precision::default(),
        true,
    );
    assert_eq!(nearest.len(), 1);
    assert!((nearest[0].t + 4.2).abs() < 1e-12, "{nearest:?}");
    let miss = project_point_surface_along_f64(
        &sphere,
        &[1.5, 0.0, 5.0],
        &[0.0, 0.0, 1.0],
        &n,
        0.3,
        &Precision::default(),
        false,
    );
    assert!(miss.is_empty());
}

#[test]
fn certified_torus_feet_contain_the_closed_form_parameters() {
    use geocert::ops::project::project_point_surface;
    use geocert::Status;
    let torus = Torus {
        major: 3.0,
        minor: 1.0,
        v_range: [0.0, TAU],
    };
    let r = project_point_surface(
        &torus,
        &[1.0, 2.0, 3.0],
        &nodes(&torus, 16),
        &Precision::default(),
        &Default::default(),
    )
    .expect("valid");
    assert!(r.complete, "{:?}", r.reason);
    assert_eq!(r.status, Status::Verified);
    assert_eq!(r.value.len(), 4, "{r:?}");
    // u = φ or φ + π with φ = atan2(2, 1); on the near tube circle v = atan2(3, √5 − 3)
    // (towards p) or that + π; on the far one v = atan2(3, −√5 − 3) (ρ measured along
    // −(cos φ, sin φ)), or that + π.
    let prec = 200;
    let f = |x: f64| rug::Float::with_val(prec, x);
    let tau = f(TAU);
    let wrap = |x: rug::Float| if x < 0 { x + &tau } else { x };
    let phi = f(2.0).atan2(&f(1.0));
    let s5 = f(5.0).sqrt();
    let near_v = f(3.0).atan2(&(s5.clone() - 3u32));
    let far_v = f(3.0).atan2(&(-s5 - 3u32));
    let pi_exact = rug::Float::with_val(prec, rug::float::Constant::Pi);
    let expected = [
        (phi.clone(), wrap(near_v.clone())),
        (phi.clone(), wrap(near_v.clone() + &pi_exact)),
        (phi.clone() + &pi_exact, wrap(far_v.clone())),
        (phi.clone() + &pi_exact, wrap(far_v.clone() + &pi_exact)),
    ];
    for (u, v) in expected {
        let hit = r.value.iter().filter(|p| {
            let e = &p.root.enclosure;
            e[0].lo() <= u && u <= e[0].hi() && e[1].lo() <= v && v <= e[1].hi()
        });
        assert_eq!(hit.count(), 1, "({u}, {v}) not in exactly one box: {r:?}");
    }
}
