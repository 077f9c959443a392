//! Surface ∩ surface, certified (exploration).

use geocert::ops::surface_surface::{intersect_surface_surface, Options};
use geocert::surface::plane::Plane;
use geocert::surface::quadrics::{Cylinder, Paraboloid, Sphere};
use std::time::Instant;

fn show(
    name: &str,
    r: &geocert::Certified<geocert::ops::surface_surface::SurfaceIntersection>,
    t: f64,
) {
    eprintln!(
        "{name}: {:?} complete {} bits {} time {t:.3}s reason {:?}",
        r.status, r.complete, r.bits, r.reason
    );
    for c in &r.value.curves {
        let maxb = c.bounds.iter().map(|b| b.distance).fold(0.0, f64::max);
        eprintln!(
            "  curve {:?} closed {} points {} chain {} max bound {maxb:e} ends {:?} {:?}",
            c.status,
            c.curve.closed,
            c.curve.points.len(),
            c.chain.len(),
            c.curve.ends,
            c.reason
        );
    }
    for p in &r.value.singular_points {
        eprintln!(
            "  singular {:?} {:?} pert {:?} ends {} {:?}",
            p.status, p.point.xyz, p.perturbation, p.branch_ends, p.reason
        );
    }
}

#[test]
fn explore() {
    let cyl = Cylinder::new([0.0; 3], [1.0, 1.0], [0.0, 0.0, 1.0], None, [0.0, 1.0]).unwrap();
    let plane = Plane::new([0.0, 0.0, 0.5], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0])
        .unwrap()
        .with_domain(([-2.0, 2.0], [-2.0, 2.0]))
        .unwrap();
    let o = Options::default();
    let t = Instant::now();
    let r = intersect_surface_surface(&cyl, &plane, &o).unwrap();
    show("cyl-plane", &r, t.elapsed().as_secs_f64());
    let sphere = Sphere::new([0.5, 0.0, 1.0], 1.0, None, None).unwrap();
    let par = Paraboloid::new([0.0; 3], [1.0, 1.0], [0.0, 0.0, 1.0], None, [0.0, 2.0]).unwrap();
    let t = Instant::now();
    let r = intersect_surface_surface(&sphere, &par, &o).unwrap();
    show("sphere-par", &r, t.elapsed().as_secs_f64());
    let s1 = Sphere::new([0.0; 3], 1.0, None, None).unwrap();
    let s2 = Sphere::new([1.5, 0.2, 0.1], 1.0, None, None).unwrap();
    let t = Instant::now();
    let r = intersect_surface_surface(&s1, &s2, &o).unwrap();
    show("sphere-sphere", &r, t.elapsed().as_secs_f64());
    let s3 = Sphere::new([2.0, 0.0, 0.0], 1.0, None, None).unwrap();
    let t = Instant::now();
    let r = intersect_surface_surface(&s1, &s3, &o).unwrap();
    show("tangent spheres", &r, t.elapsed().as_secs_f64());
}

#[test]
fn explore_singular() {
    use geocert::surface::quadrics::Cone;
    use geocert::surface::torus::Torus;
    let o = Options::default();
    let torus = Torus::new([0.0; 3], 2.0, 1.0, [0.0, 0.0, 1.0], None).unwrap();
    let sphere = Sphere::new([-2.0, 0.0, 3.0], 4.0, None, None).unwrap();
    let t = Instant::now();
    let r = intersect_surface_surface(&torus, &sphere, &o).unwrap();
    show("villarceau", &r, t.elapsed().as_secs_f64());
    let sphere2 = Sphere::new([-2.0, 0.0, 3.0], 4.0, Some([0.0, 1.0, 0.0]), None).unwrap();
    let t = Instant::now();
    let r = intersect_surface_surface(&torus, &sphere2, &o).unwrap();
    show("villarceau y-axis sphere", &r, t.elapsed().as_secs_f64());
    let c1 = Cylinder::new([0.0; 3], [1.0, 1.0], [0.0, 0.0, 1.0], None, [-2.0, 2.0]).unwrap();
    let c2 = Cylinder::new([0.0; 3], [1.0, 1.0], [1.0, 0.0, 0.0], None, [-2.0, 2.0]).unwrap();
    let t = Instant::now();
    let r = intersect_surface_surface(&c1, &c2, &o).unwrap();
    show("steinmetz", &r, t.elapsed().as_secs_f64());
    let cone = Cone::new(
        [0.0; 3],
        0.0,
        std::f64::consts::FRAC_PI_6,
        [0.0, 0.0, 1.0],
        None,
        [-1.0, 1.0],
    )
    .unwrap();
    let plane = Plane::new([0.0; 3], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0])
        .unwrap()
        .with_domain(([-2.0, 2.0], [-2.0, 2.0]))
        .unwrap();
    let t = Instant::now();
    let r = intersect_surface_surface(&plane, &cone, &o).unwrap();
    show("cone apex", &r, t.elapsed().as_secs_f64());
    let tilted = Plane::new(
        [0.0; 3],
        [1.0, 0.0, (30f64).to_radians().tan()],
        [0.0, 1.0, 0.0],
    )
    .unwrap()
    .with_domain(([-4.0, 4.0], [-4.0, 4.0]))
    .unwrap();
    let t = Instant::now();
    let r = intersect_surface_surface(&torus, &tilted, &o).unwrap();
    show("torus bitangent plane", &r, t.elapsed().as_secs_f64());
}

#[test]
fn explore_float_singular() {
    use geocert::ops::surface_surface::intersect_surface_surface_f64;
    use geocert::surface::quadrics::Cone;
    let o = Options::default();
    let c1 = Cylinder::new([0.0; 3], [1.0, 1.0], [0.0, 0.0, 1.0], None, [-2.0, 2.0]).unwrap();
    let c2 = Cylinder::new([0.0; 3], [1.0, 1.0], [1.0, 0.0, 0.0], None, [-2.0, 2.0]).unwrap();
    let r = intersect_surface_surface_f64(&c1, &c2, &o).unwrap();
    eprintln!("steinmetz float: {} curves", r.curves.len());
    for c in &r.curves {
        let sing: Vec<_> = c
            .points
            .iter()
            .enumerate()
            .filter(|(_, p)| p.singular.is_some())
            .map(|(i, p)| (i, p.singular))
            .collect();
        eprintln!(
            "  {} pts closed {} ends {:?} first {:?} singular at {:?}",
            c.points.len(),
            c.closed,
            c.ends,
            c.points[0].xyz,
            sing
        );
    }
    for p in &r.singular_points {
        eprintln!("  sp {:?} {:?} gap {:e}", p.kind, p.xyz, p.gap);
    }
    let cone = Cone::new(
        [0.0; 3],
        0.0,
        std::f64::consts::FRAC_PI_6,
        [0.0, 0.0, 1.0],
        None,
        [-1.0, 1.0],
    )
    .unwrap();
    let plane = Plane::new([0.0; 3], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0])
        .unwrap()
        .with_domain(([-2.0, 2.0], [-2.0, 2.0]))
        .unwrap();
    let r = intersect_surface_surface_f64(&plane, &cone, &o).unwrap();
    eprintln!("cone float: {} curves", r.curves.len());
    for c in r.curves.iter().take(12) {
        eprintln!(
            "  {} pts closed {} ends {:?} pts {:?}",
            c.points.len(),
            c.closed,
            c.ends,
            c.points.iter().map(|p| p.params).collect::<Vec<_>>()
        );
    }
    for p in &r.singular_points {
        eprintln!("  sp {:?} {:?} gap {:e}", p.kind, p.params, p.gap);
    }
}
