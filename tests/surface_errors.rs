//! Issue 5: bad surface input gives a typed error naming the field, never a panic:
//! radii and axes (zero or non-finite), reference directions, parameter intervals and
//! domains (empty, inverted, outside the natural domain), knot vectors (length, order,
//! multiplicity, empty domain), weights, net shapes, degrees, quadric matrices, motion
//! surfaces and walk options. The JSON route prefixes the object's path.

use geocert::io::shapes::surface::parse_surface;
use geocert::surface::bezier::BezierSurface;
use geocert::surface::implicit::ImplicitQuadric;
use geocert::surface::motion::{Extrusion, Revolution};
use geocert::surface::nurbs::NurbsSurface;
use geocert::surface::plane::Plane;
use geocert::surface::quadrics::{Cone, Sphere};
use geocert::walk::surface::{SurfaceWalk, SurfaceWalkOptions};
use geocert::GeomError;
use serde_json::{json, Value};

/// Parse and build one JSON surface at `objects[0]`: the error's (kind, field).
fn error(v: Value) -> (&'static str, String) {
    let e = parse_surface(&v, "objects[0]")
        .and_then(|s| s.build().map_err(|e| e.at("objects[0]")))
        .unwrap_err();
    (
        e.kind(),
        e.field().trim_start_matches("objects[0].").to_string(),
    )
}

fn kind_field(e: GeomError) -> (&'static str, String) {
    (e.kind(), e.field().to_string())
}

fn pair(kind: &'static str, field: &str) -> (&'static str, String) {
    (kind, field.to_string())
}

#[test]
fn analytic_surfaces_name_the_bad_field() {
    let cases = [
        (
            json!({"type": "sphere", "center": [0, 0, 0], "radius": 0}),
            pair("invalid_value", "radius"),
        ),
        (
            json!({"type": "sphere", "center": [0, 0, 0], "radius": -2}),
            pair("invalid_value", "radius"),
        ),
        (
            json!({"type": "sphere", "center": [0, 0, 0], "radius": 1, "axis": [0, 0, 0]}),
            pair("zero_direction", "axis"),
        ),
        (
            json!({"type": "sphere", "center": [0, 0, 0], "radius": 1, "axis": [0, 0, 2], "ref": [0, 0, -1]}),
            pair("invalid_value", "ref"),
        ),
        (
            json!({"type": "sphere", "center": [0, 0, 0], "radius": 1, "ref": [0, 0, 0]}),
            pair("zero_direction", "ref"),
        ),
        (
            json!({"type": "sphere", "center": [0, 0, 0], "radius": 1, "domain": [[0, 1], [-2, 0]]}),
            pair("parameter_outside_domain", "domain[1][0]"),
        ),
        (
            json!({"type": "sphere", "center": [0, 0, 0], "radius": 1, "domain": [[1, 0], [0, 1]]}),
            pair("empty_domain", "domain[0]"),
        ),
        (
            json!({"type": "ellipsoid", "center": [0, 0, 0], "a": 1, "b": 0, "c": 1}),
            pair("invalid_value", "b"),
        ),
        (
            json!({"type": "hyperboloid1", "center": [0, 0, 0], "a": 1, "b": 1, "c": 1, "axis": [0, 0, 1], "range": [1, -1]}),
            pair("empty_domain", "range"),
        ),
        (
            json!({"type": "hyperboloid2", "center": [0, 0, 0], "a": 1, "b": 1, "c": -1, "axis": [0, 0, 1], "range": [0, 1]}),
            pair("invalid_value", "c"),
        ),
        (
            json!({"type": "paraboloid", "center": [0, 0, 0], "a": 0, "b": 1, "axis": [0, 0, 1], "range": [0, 1]}),
            pair("invalid_value", "a"),
        ),
        (
            json!({"type": "paraboloid", "center": [0, 0, 0], "a": 1, "b": 1, "axis": [0, 0, 1], "range": [1, 1]}),
            pair("empty_domain", "range"),
        ),
        (
            json!({"type": "hyperbolic_paraboloid", "center": [0, 0, 0], "a": 1, "b": 1, "domain": [[0, 1], [2, 1]]}),
            pair("empty_domain", "domain[1]"),
        ),
        (
            json!({"type": "cylinder", "origin": [0, 0, 0], "radius": 0, "axis": [0, 0, 1], "height": [0, 1]}),
            pair("invalid_value", "radius"),
        ),
        (
            json!({"type": "cylinder", "origin": [0, 0, 0], "radius": 1, "axis": [0, 0, 1], "height": [2, 1]}),
            pair("empty_domain", "height"),
        ),
        (
            json!({"type": "elliptic_cylinder", "origin": [0, 0, 0], "a": 1, "b": -1, "axis": [0, 0, 1], "height": [0, 1]}),
            pair("invalid_value", "b"),
        ),
        (
            json!({"type": "cone", "origin": [0, 0, 0], "radius": -1, "half_angle": 0.5, "axis": [0, 0, 1], "height": [0, 1]}),
            pair("invalid_value", "radius"),
        ),
        (
            json!({"type": "cone", "origin": [0, 0, 0], "radius": 1, "half_angle": 0, "axis": [0, 0, 1], "height": [0, 1]}),
            pair("invalid_value", "half_angle"),
        ),
        (
            json!({"type": "cone", "origin": [0, 0, 0], "radius": 1, "half_angle": std::f64::consts::FRAC_PI_2, "axis": [0, 0, 1], "height": [0, 1]}),
            pair("invalid_value", "half_angle"),
        ),
        (
            json!({"type": "torus", "center": [0, 0, 0], "major": 3, "minor": 0, "axis": [0, 0, 1]}),
            pair("invalid_value", "minor"),
        ),
        (
            json!({"type": "torus", "center": [0, 0, 0], "major": -3, "minor": 1, "axis": [0, 0, 1]}),
            pair("invalid_value", "major"),
        ),
        (
            json!({"type": "torus", "center": [0, 0, 0], "major": 3, "minor": 1, "axis": [0, 0, 0]}),
            pair("zero_direction", "axis"),
        ),
        (
            json!({"type": "plane", "origin": [0, 0, 0], "u": [1, 2, 3], "v": [-2, -4, -6]}),
            pair("collinear_plane_vectors", "v"),
        ),
        (
            json!({"type": "plane", "origin": [0, 0, 0], "u": [0, 0, 0], "v": [1, 0, 0]}),
            pair("collinear_plane_vectors", "v"),
        ),
    ];
    for (value, expected) in cases {
        assert_eq!(error(value.clone()), expected, "{value}");
    }
}

fn nurbs(v: Value) -> Value {
    let mut base = json!({"type": "nurbs_surface", "degree_u": 2, "degree_v": 1,
        "knots_u": [0, 0, 0, 0.5, 1, 1, 1], "knots_v": [0, 0, 1, 1],
        "points": [[[0, 0, 0], [1, 0, 1], [2, 0, 0], [3, 0, 1]],
                   [[0, 1, 0], [1, 1, 2], [2, 1, 0], [3, 1, 1]]],
        "weights": [[1, 0.5, 1, 1], [1, 2, 1, 0.25]]});
    for (k, x) in v.as_object().unwrap() {
        base[k] = x.clone();
    }
    base
}

#[test]
fn nurbs_and_bezier_validation() {
    assert!(parse_surface(&nurbs(json!({})), "")
        .unwrap()
        .build()
        .is_ok());
    let cases = [
        (
            json!({"knots_u": [0, 0, 0, 1, 1, 1]}),
            pair("count_mismatch", "knots_u"),
        ),
        (
            json!({"knots_u": [0, 0, 0, 0.7, 0.5, 1, 1]}),
            pair("invalid_knots", "knots_u"),
        ),
        (
            json!({"knots_u": [0, 0, 0, 0, 1, 1, 1]}),
            pair("invalid_knots", "knots_u"),
        ),
        (
            json!({"knots_u": [0, 0, 1, 1, 1, 2, 3]}),
            pair("empty_domain", "knots_u"),
        ),
        (
            json!({"knots_v": [0, 0, 0, 1]}),
            pair("invalid_knots", "knots_v"),
        ),
        (json!({"degree_u": 0}), pair("invalid_value", "degree_u")),
        (
            json!({"degree_v": 2, "knots_v": [0, 0, 0, 1, 1]}),
            pair("count_mismatch", "points"),
        ),
        (
            json!({"weights": [[1, 0.5, 1, 1], [1, 0, 1, 0.25]]}),
            pair("non_positive_weight", "weights[1][1]"),
        ),
        (
            json!({"weights": [[1, 0.5, 1, 1], [1, -2, 1, 0.25]]}),
            pair("non_positive_weight", "weights[1][1]"),
        ),
        (
            json!({"weights": [[1, 0.5, 1], [1, 2, 1, 0.25]]}),
            pair("count_mismatch", "weights[0]"),
        ),
        (
            json!({"weights": [[1, 0.5, 1, 1]]}),
            pair("count_mismatch", "weights"),
        ),
        (
            json!({"points": [[[0, 0, 0], [1, 0, 1], [2, 0, 0], [3, 0, 1]], [[0, 1, 0], [1, 1, 2], [2, 1, 0]]]}),
            pair("count_mismatch", "points[1]"),
        ),
        (json!({"points": []}), pair("count_mismatch", "points")),
        (
            json!({"domain": [[0, 2], [0, 1]]}),
            pair("parameter_outside_domain", "domain[0][1]"),
        ),
    ];
    for (patch, expected) in cases {
        assert_eq!(error(nurbs(patch.clone())), expected, "{patch}");
    }
    let bez = |points: Value| error(json!({"type": "bezier_surface", "points": points}));
    assert_eq!(
        bez(json!([[[0, 0, 0], [1, 0, 0]]])),
        pair("count_mismatch", "points")
    );
    assert_eq!(
        bez(json!([[[0, 0, 0]], [[1, 0, 0]]])),
        pair("count_mismatch", "points[0]")
    );
    // Non-finite values only arrive through the API.
    let mut points = vec![vec![[0.0; 3]; 2]; 2];
    points[1][0][2] = f64::NAN;
    let e = BezierSurface::new(&points, None).unwrap_err();
    assert_eq!(kind_field(e), pair("non_finite", "points[1][0][2]"));
    let e = NurbsSurface::new(
        [1, 1],
        vec![0.0, 0.0, f64::INFINITY, 1.0],
        vec![0.0, 0.0, 1.0, 1.0],
        &vec![vec![[0.0; 3]; 2]; 2],
        None,
    )
    .unwrap_err();
    assert_eq!(kind_field(e), pair("non_finite", "knots_u[2]"));
    let e = NurbsSurface::new(
        [1, 1],
        vec![0.0, 0.0, 1.0, 1.0],
        vec![0.0, 0.0, 1.0, 1.0],
        &vec![vec![[0.0; 3]; 2]; 2],
        Some(&[vec![1.0, f64::NAN], vec![1.0, 1.0]]),
    )
    .unwrap_err();
    assert_eq!(kind_field(e), pair("non_finite", "weights[0][1]"));
}

#[test]
fn api_constructors_name_the_bad_field() {
    let e = Sphere::new([0.0, f64::NAN, 0.0], 1.0, None, None).unwrap_err();
    assert_eq!(kind_field(e), pair("non_finite", "center[1]"));
    let e = Sphere::new([0.0; 3], 1.0, Some([0.0, f64::INFINITY, 0.0]), None).unwrap_err();
    assert_eq!(kind_field(e), pair("non_finite", "axis[1]"));
    let e = Cone::new([0.0; 3], 1.0, f64::NAN, [0.0, 0.0, 1.0], None, [0.0, 1.0]).unwrap_err();
    assert_eq!(kind_field(e), pair("non_finite", "half_angle"));
    let e = Cone::new([0.0; 3], 1.0, 0.3, [0.0, 0.0, 1.0], None, [0.0, f64::NAN]).unwrap_err();
    assert_eq!(kind_field(e), pair("non_finite", "height[1]"));
    let mut q = [[0.0; 4]; 4];
    q[0][1] = 1.0;
    assert_eq!(
        kind_field(ImplicitQuadric::new(q).unwrap_err()),
        pair("invalid_value", "matrix[0][1]")
    );
    assert_eq!(
        kind_field(ImplicitQuadric::new([[0.0; 4]; 4]).unwrap_err()),
        pair("invalid_value", "matrix")
    );
    q[1][0] = 1.0;
    q[3][3] = f64::NAN;
    assert_eq!(
        kind_field(ImplicitQuadric::new(q).unwrap_err()),
        pair("non_finite", "matrix[3][3]")
    );
}

#[derive(Debug, Clone)]
struct Segment;
impl geocert::curve::Curve<3> for Segment {
    fn domain(&self) -> (f64, f64) {
        (0.0, 1.0)
    }
    fn jet<T: geocert::num::Real>(&self, t: &T, order: usize) -> Vec<[T; 3]> {
        let z = t.zero_like();
        let mut j = vec![
            [t.clone(), z.clone(), z.clone()],
            [t.one_like(), z.clone(), z.clone()],
        ];
        j.extend((1..order).map(|_| [z.clone(), z.clone(), z.clone()]));
        j.truncate(order + 1);
        j
    }
}

#[test]
fn motion_surfaces_and_walks_name_the_bad_field() {
    assert_eq!(
        kind_field(Extrusion::new(Segment, [0.0; 3]).unwrap_err()),
        pair("zero_direction", "dir")
    );
    assert_eq!(
        kind_field(Extrusion::new(Segment, [0.0, f64::NAN, 1.0]).unwrap_err()),
        pair("non_finite", "dir[1]")
    );
    assert_eq!(
        kind_field(Revolution::new(Segment, [0.0; 3], [0.0; 3]).unwrap_err()),
        pair("zero_direction", "axis")
    );
    let r = Revolution::new(Segment, [0.0; 3], [0.0, 0.0, 1.0]).unwrap();
    assert_eq!(
        kind_field(r.with_angle([1.0, 0.5]).unwrap_err()),
        pair("empty_domain", "angle")
    );
    let plane = Plane::new([0.0; 3], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]).unwrap();
    let e = SurfaceWalk::new(&plane, SurfaceWalkOptions::default()).unwrap_err();
    assert_eq!(kind_field(e), pair("unsupported", "domain"));
    let bounded = plane.with_domain(([0.0, 1.0], [0.0, 1.0])).unwrap();
    for bad in [0.0, -0.1, f64::NAN, 4.0] {
        let e = SurfaceWalk::new(&bounded, SurfaceWalkOptions::new(bad)).unwrap_err();
        assert_eq!(kind_field(e), pair("invalid_value", "delta_alpha"));
    }
    let o = SurfaceWalkOptions {
        delta: -1.0,
        ..Default::default()
    };
    assert_eq!(
        kind_field(SurfaceWalk::new(&bounded, o).unwrap_err()),
        pair("invalid_value", "delta")
    );
}
