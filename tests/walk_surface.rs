//! Issue 5, walking (OPERATIONS.md §2.2–§2.3, §16.1): the (2.2) steps of the §16.1
//! sphere, the analytic shortcuts, the clamps (B-spline: half a knot span), the row
//! traversal invariants of §2.3, and the proven mode, whose turning bounds must hold for
//! the true normals sampled in each window and whose windows cover the rectangle.

mod surface_support;

use std::f64::consts::PI;

use geocert::num::{Interval, MpfrInterval};
use geocert::surface::motion::Extrusion;
use geocert::surface::quadrics::Sphere;
use geocert::surface::{AnySurface, Surface};
use geocert::walk::surface::{
    proven_surface_steps, turning_bounds, SurfaceNode, SurfaceStepper, SurfaceWalk,
    SurfaceWalkOptions,
};
use surface_support::{any_surfaces, nurbs_bicubic, Rng, TestHelix};

fn surface(name: &str) -> AnySurface {
    any_surfaces()
        .into_iter()
        .find(|(n, _)| *n == name)
        .unwrap()
        .1
}

#[test]
fn sphere_steps_of_16_1() {
    let s = Sphere::new([0.0; 3], 2.0, None, None).unwrap();
    let stepper = SurfaceStepper::new(&s, SurfaceWalkOptions::new(PI / 10.0)).unwrap();
    let [du, dv] = stepper.curvature_steps(0.3, 0.5);
    assert!((du - 0.3579825751).abs() < 1e-9, "{du}");
    assert!((dv - 0.3141592654).abs() < 1e-9, "{dv}");
    // The analytic shortcut of §2.2 for spheres: Δu = Δv = Δα.
    assert_eq!(stepper.steps(0.3, 0.5), [PI / 10.0, PI / 10.0]);
}

#[test]
fn analytic_shortcuts_of_2_2() {
    let a = PI / 20.0;
    let steps = |name: &str, u: f64, v: f64| {
        let s = surface(name);
        SurfaceStepper::new(&s, SurfaceWalkOptions::new(a))
            .unwrap()
            .steps(u, v)
    };
    assert_eq!(steps("torus", 1.0, 2.0), [a, a]);
    assert_eq!(
        steps("plane", 0.0, 0.0),
        [4.0, 4.0],
        "one step covers the range"
    );
    assert_eq!(steps("cylinder", 1.0, 0.5), [a, 4.0]);
    assert_eq!(steps("cone", 1.0, 0.5), [a, 2.0]);
    // Extrusion: (2.1) on the helix, Δt = Δα|c'|²/|c'×c''| = Δα·√1.09; whole range in v.
    let e = Extrusion::new(TestHelix, [0.0, 1.0, 1.0]).unwrap();
    let [du, dv] = SurfaceStepper::new(&e, SurfaceWalkOptions::new(a))
        .unwrap()
        .steps(2.0, 0.3);
    assert!((du - a * 1.09f64.sqrt()).abs() < 1e-14, "{du}");
    assert_eq!(dv, 1.0);
}

#[test]
fn clamps_bound_every_step() {
    let s = nurbs_bicubic();
    let stepper = SurfaceStepper::new(&s, SurfaceWalkOptions::new(PI / 10.0)).unwrap();
    let mut rng = Rng(8);
    for _ in 0..200 {
        let (u, v) = (rng.unit(), rng.range(-1.0, 2.0));
        let [du, dv] = stepper.steps(u, v);
        let (a, b) = s.knot_span(0, u).unwrap();
        assert!(
            du >= 1e-4 && du <= (1.0f64 / 8.0).min((b - a) / 2.0) + 1e-15,
            "{du}"
        );
        let (a, b) = s.knot_span(1, v).unwrap();
        assert!(
            dv >= 3e-4 && dv <= (3.0f64 / 8.0).min((b - a) / 2.0) + 1e-15,
            "{dv}"
        );
    }
    // A flat coordinate line takes Δ_max: the hyperbolic paraboloid's u-lines are
    // parabolas, the plane's lines are straight.
    let h = surface("hyperbolic_paraboloid");
    let [du, _] = SurfaceStepper::new(&h, SurfaceWalkOptions::new(PI / 10.0))
        .unwrap()
        .steps(0.0, 0.0);
    assert!(du > 0.0 && du <= 2.0 / 8.0);
}

/// The §2.3 invariants of a walk, and the row starts.
fn check_traversal<S: Surface>(name: &str, s: &S, nodes: &[SurfaceNode], proven: bool) -> Vec<f64> {
    let ([u0, u1], [v0, v1]) = s.domain();
    assert_eq!(
        (nodes[0].u, nodes[0].v),
        (u0, v0),
        "{name}: starts at (u_min, v_min)"
    );
    let mut rows: Vec<Vec<SurfaceNode>> = Vec::new();
    for n in nodes {
        if n.row == rows.len() {
            rows.push(Vec::new());
        }
        assert_eq!(n.row + 1, rows.len(), "{name}: rows in order");
        rows.last_mut().unwrap().push(*n);
    }
    let mut starts = Vec::new();
    for (j, row) in rows.iter().enumerate() {
        assert_eq!(row[0].u, u0, "{name}: row {j} starts at u_min");
        assert_eq!(
            row.last().unwrap().u,
            u1,
            "{name}: row {j} ends exactly at u_max"
        );
        for w in row.windows(2) {
            assert_eq!(w[1].u, (w[0].u + w[0].du).min(u1), "{name}: u step");
            assert_eq!(w[1].v, w[0].v);
        }
        starts.push(row[0].v);
        if let Some(next) = rows.get(j + 1) {
            let advance = if proven {
                row.iter().map(|n| n.dv).fold(f64::INFINITY, f64::min)
            } else {
                row.iter().map(|n| n.dv).sum::<f64>() / row.len() as f64
            };
            assert_eq!(
                next[0].v,
                (row[0].v + advance).min(v1),
                "{name}: row advance"
            );
            assert!(next[0].v > row[0].v);
        }
    }
    assert_eq!(
        *starts.last().unwrap(),
        v1,
        "{name}: last row exactly at v_max"
    );
    starts
}

#[test]
fn rows_follow_2_3() {
    for name in [
        "nurbs",
        "torus",
        "hyperbolic_paraboloid",
        "ellipsoid",
        "bezier",
        "cone_apex",
    ] {
        let s = surface(name);
        let nodes: Vec<_> = SurfaceWalk::new(&s, SurfaceWalkOptions::default())
            .unwrap()
            .collect();
        assert!(nodes.len() < 20_000, "{name}: {}", nodes.len());
        check_traversal(name, &s, &nodes, false);
    }
    // A torus at Δα = π/10: 21 nodes per row (20 steps of π/10 and the end), 21 rows.
    let t = surface("torus");
    let nodes: Vec<_> = SurfaceWalk::new(&t, SurfaceWalkOptions::default())
        .unwrap()
        .collect();
    assert_eq!(nodes.len(), 21 * 21);
}

/// The angle between two vectors.
fn angle(a: [f64; 3], b: [f64; 3]) -> f64 {
    let dot: f64 = (0..3).map(|i| a[i] * b[i]).sum();
    let cross = [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ];
    (cross.iter().map(|x| x * x).sum::<f64>().sqrt()).atan2(dot)
}

#[test]
fn proven_walk_bounds_the_turning_of_the_normal() {
    let alpha = PI / 10.0;
    for name in [
        "nurbs",
        "torus",
        "sphere",
        "hyperbolic_paraboloid",
        "bilinear",
        "cylinder",
    ] {
        let s = surface(name);
        let nodes: Vec<_> = SurfaceWalk::proven(&s, SurfaceWalkOptions::new(alpha))
            .unwrap()
            .collect();
        check_traversal(name, &s, &nodes, true);
        let ([_, u1], [_, v1]) = s.domain();
        let mut rng = Rng(55);
        let mut within = 0;
        for n in &nodes {
            let p = n.proven.unwrap();
            assert_eq!((p.du, p.dv), (n.du, n.dv));
            // The sphere's poles are singular points of the parametrisation: near them
            // |N × N_d|/|N|² is hard to bound (and unbounded on a window that contains
            // one). Away from them (|v| ≤ 1.4 over the window) every node is proven.
            let away = n.v >= -1.4 && n.v + n.dv <= 1.4;
            assert!(
                p.within || !away || name != "sphere",
                "sphere at ({}, {})",
                n.u,
                n.v
            );
            if p.within {
                within += 1;
                assert!(p.angle_bound[0] <= alpha && p.angle_bound[1] <= alpha);
            }
            let bound = p.angle_bound[0] + p.angle_bound[1];
            let n0 = s.normal(&n.u, &n.v);
            for _ in 0..4 {
                let u = (n.u + rng.unit() * n.du).min(u1);
                let v = (n.v + rng.unit() * n.dv).min(v1);
                let turned = angle(n0, s.normal(&u, &v));
                assert!(
                    turned <= bound * (1.0 + 1e-9) + 1e-12,
                    "{name}: {turned} > {bound}"
                );
            }
        }
        if name != "sphere" {
            let n = nodes.len();
            assert!(within * 10 >= n * 9, "{name}: {within} of {n}");
        }
    }
    // The sphere's normal turns at the rate cos v along u and 1 along v: the proven
    // bounds are at least the true turning, and not far above it on a small window.
    let s = surface("sphere");
    let mpfr = MpfrInterval::point(0.0, 128);
    let p = proven_surface_steps(&s, &mpfr, [0.5, 0.2], [0.05, 0.02], alpha, [1e-4; 2]);
    assert!(p.within, "{p:?}");
    let (b, true_u, true_v) = (p.angle_bound, 0.05 * 0.2f64.cos(), 0.02);
    assert!(b[0] >= true_u && b[0] <= 1.5 * true_u, "{b:?}");
    assert!(b[1] >= true_v && b[1] <= 1.5 * true_v, "{b:?}");
}

#[test]
fn proven_steps_shrink_until_the_bound_holds() {
    // Δα = π/100 on a torus from steps of 0.2 rad: halved until proven.
    let t = surface("torus");
    let alpha = PI / 100.0;
    let at = [0.1, 0.2];
    let p = proven_surface_steps(&t, &Interval::ZERO, at, [0.2, 0.2], alpha, [1e-4; 2]);
    assert!(p.within && p.du < 0.2 && p.dv < 0.2, "{p:?}");
    assert!(p.angle_bound[0] <= alpha && p.angle_bound[1] <= alpha);
    // The doubled steps were not provable (that is why they were halved).
    let doubled: Vec<[f64; 2]> = [1, 2, 4]
        .iter()
        .map(|&k| turning_bounds(&t, &Interval::ZERO, at, [2.0 * p.du, 2.0 * p.dv], k))
        .collect();
    let best = |d: usize| doubled.iter().map(|b| b[d]).fold(f64::INFINITY, f64::min);
    assert!(best(0) > alpha || best(1) > alpha);
    // The true turning of the torus normal along u at v: |n̂_u| = |cos v| per radian.
    assert!(p.angle_bound[0] >= p.du * (0.2f64).cos());
    assert!(p.angle_bound[1] >= p.dv);
}
