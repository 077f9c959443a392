//! Surface ∩ surface, float path (OPERATIONS.md §9, §10): the worked examples §16.12 and
//! §16.16 by marching, Dragilev (all three forms) and plane stepping.

use geocert::ops::surface_surface::{
    intersect_surface_surface_f64, CurveEnd, DragilevForm, Method, Options,
};
use geocert::surface::plane::Plane;
use geocert::surface::quadrics::{Cylinder, Paraboloid, Sphere};
use geocert::surface::AnySurface;

fn methods() -> Vec<Options> {
    let mut out = Vec::new();
    for method in [Method::Marching, Method::Dragilev, Method::PlaneStep] {
        out.push(Options {
            method,
            chord_tolerance: Some(1e-6),
            ..Options::default()
        });
    }
    out
}

#[test]
fn cylinder_and_plane_of_16_16_is_one_circle_of_length_2pi() {
    let cyl = Cylinder::new([0.0; 3], [1.0, 1.0], [0.0, 0.0, 1.0], None, [0.0, 1.0]).unwrap();
    let plane = Plane::new([0.0, 0.0, 0.5], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0])
        .unwrap()
        .with_domain(([-2.0, 2.0], [-2.0, 2.0]))
        .unwrap();
    for o in methods() {
        let r = intersect_surface_surface_f64(&any(&cyl), &any(&plane), &o).unwrap();
        assert_eq!(
            r.curves.len(),
            1,
            "{:?}: {:?}",
            o.method,
            r.curves
                .iter()
                .map(|c| (c.points.len(), c.closed, c.ends))
                .collect::<Vec<_>>()
        );
        let c = &r.curves[0];
        assert!(c.closed, "{:?}", c.ends);
        let len = c.polyline_length();
        eprintln!("{:?} points {} length {}", o.method, c.points.len(), len);
        assert!((len - std::f64::consts::TAU).abs() < 1e-4, "{len}");
        for p in &c.points {
            assert!((p.xyz[2] - 0.5).abs() < 1e-12);
            assert!(((p.xyz[0].powi(2) + p.xyz[1].powi(2)).sqrt() - 1.0).abs() < 1e-12);
        }
        assert!(r.singular_points.is_empty());
    }
}

#[test]
fn sphere_and_paraboloid_of_16_12() {
    let sphere = Sphere::new([0.0; 3], 2.0, None, None).unwrap();
    let par = Paraboloid::new([0.0; 3], [1.0, 1.0], [0.0, 0.0, 1.0], None, [0.0, 2.0]).unwrap();
    let z = (17f64.sqrt() - 1.0) / 2.0;
    for o in methods() {
        let r = intersect_surface_surface_f64(&any(&sphere), &any(&par), &o).unwrap();
        assert_eq!(
            r.curves.len(),
            1,
            "{:?}: {:?}",
            o.method,
            r.curves
                .iter()
                .map(|c| (c.points.len(), c.closed, c.ends))
                .collect::<Vec<_>>()
        );
        let c = &r.curves[0];
        assert!(c.closed);
        eprintln!(
            "{:?} points {} length {}",
            o.method,
            c.points.len(),
            c.polyline_length()
        );
        assert!((c.polyline_length() - 7.8516007320).abs() < 1e-4);
        for p in &c.points {
            assert!((p.xyz[2] - z).abs() < 1e-10, "{p:?}");
        }
    }
}

#[test]
fn offset_sphere_and_paraboloid_of_16_12_is_a_loop_of_length_6_6277432655() {
    let sphere = Sphere::new([0.5, 0.0, 1.0], 1.0, None, None).unwrap();
    let par = Paraboloid::new([0.0; 3], [1.0, 1.0], [0.0, 0.0, 1.0], None, [0.0, 2.0]).unwrap();
    for (o, form) in methods().into_iter().zip([DragilevForm::Auto; 3]).chain([
        (
            Options {
                method: Method::Dragilev,
                form: DragilevForm::Parametric,
                chord_tolerance: Some(1e-6),
                ..Options::default()
            },
            DragilevForm::Parametric,
        ),
        (
            Options {
                method: Method::Dragilev,
                form: DragilevForm::ParametricImplicit,
                chord_tolerance: Some(1e-6),
                ..Options::default()
            },
            DragilevForm::ParametricImplicit,
        ),
    ]) {
        let r = intersect_surface_surface_f64(&any(&sphere), &any(&par), &o).unwrap();
        assert_eq!(r.curves.len(), 1, "{:?} {form:?}", o.method);
        let c = &r.curves[0];
        assert!(c.closed);
        eprintln!(
            "{:?} {form:?} points {} length {}",
            o.method,
            c.points.len(),
            c.polyline_length()
        );
        assert!((c.polyline_length() - 6.6277432655).abs() < 1e-4);
        for p in &c.points {
            let [x, y, z] = p.xyz;
            assert!((x - (z - 0.5).powi(2)).abs() < 1e-9 && (y * y - (z - x * x)).abs() < 1e-9);
        }
    }
    let _ = CurveEnd::Boundary;
}

/// Through [`AnySurface`]: the tracer is compiled once, not once per pair of types.
fn any<S: Into<AnySurface> + Clone>(s: &S) -> AnySurface {
    s.clone().into()
}
