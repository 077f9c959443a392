//! `geocert render` and the library's pictures (src/render; issue 17 "Pictures").
//!
//! The truths are closed forms, independent of the drawing code: a sphere's outline is
//! the circle of its radius about the projected centre, and a point of a lone sphere is
//! hidden exactly when it lies on the far side (`(x − c)·d < 0`); the outline of the
//! ellipsoid of §16.14 lies in its conjugate plane `x/9 + y/9 + z/25 = 0`, a cylinder's
//! on the generators `u = ψ ± π/2` (13.12); answer markers sit at the projections of
//! the answer's points. Families are seeded; the SVG and PNG files are checked for
//! their element counts, colours and determinism; the command line for its files and
//! exit status.

use std::f64::consts::PI;
use std::process::Command;

use geocert::io::{answer, picture, read_cases};
use geocert::ops::shape::Shape;
use geocert::ops::view::View;
use geocert::render::{self, Input, MarkerKind, RenderOptions, Role, Scene};
use geocert::surface::quadrics::Sphere;
use geocert::surface::AnySurface;

/// A small deterministic generator (SplitMix64).
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        ((z ^ (z >> 31)) >> 11) as f64 / (1u64 << 53) as f64
    }
    fn range(&mut self, a: f64, b: f64) -> f64 {
        a + (b - a) * self.next()
    }
}

fn unit(d: [f64; 3]) -> [f64; 3] {
    let l = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
    d.map(|c| c / l)
}

fn dot(a: &[f64; 3], b: &[f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn toward(view: &View) -> [f64; 3] {
    let (x, y) = (view.e_x, view.e_y);
    unit([
        x[1] * y[2] - x[2] * y[1],
        x[2] * y[0] - x[0] * y[2],
        x[0] * y[1] - x[1] * y[0],
    ])
}

fn sphere(c: [f64; 3], r: f64) -> Shape {
    Shape::Surface(AnySurface::Sphere(
        Sphere::new(c, r, None, None).expect("a valid sphere"),
    ))
}

fn draw(shapes: &[Shape], view: &View) -> Scene {
    let input = Input {
        shapes,
        point: None,
        answer: None,
        view,
    };
    render::picture(&input, &RenderOptions::default(), String::new()).expect("a picture")
}

/// The views of the families: the named ones and seeded general directions.
fn views(rng: &mut Rng, general: usize) -> Vec<View> {
    let mut v = vec![
        View::frontal(),
        View::horizontal(),
        View::profile(),
        View::isometric(),
        View::dimetric(),
    ];
    for _ in 0..general {
        let d = [
            rng.range(-1.0, 1.0),
            rng.range(-1.0, 1.0),
            rng.range(-1.0, 1.0),
        ];
        v.push(View::parallel(d).expect("a non-zero direction"));
    }
    v
}

#[test]
fn sphere_outline_is_the_circle_of_its_radius_and_its_far_side_is_hidden() {
    let mut rng = Rng(17);
    let mut checked = [0usize; 3];
    for view in views(&mut rng, 7) {
        for _ in 0..3 {
            let c = [
                rng.range(-5.0, 5.0),
                rng.range(-5.0, 5.0),
                rng.range(-5.0, 5.0),
            ];
            let r = rng.range(0.1, 4.0);
            let scene = draw(&[sphere(c, r)], &view);
            let d = toward(&view);
            let centre_px = scene.pixel(view.project(&c));
            let radius_px = r * scene.scale;
            // The outline: every vertex on the circle, all visible, all the way round.
            let mut angles = Vec::new();
            for s in scene.strokes.iter().filter(|s| s.role == Role::Contour) {
                assert!(!s.hidden, "a lone sphere's outline is visible");
                for p in &s.points {
                    let (dx, dy) = (p[0] - centre_px[0], p[1] - centre_px[1]);
                    let rho = (dx * dx + dy * dy).sqrt();
                    assert!(
                        (rho - radius_px).abs() <= 2e-3 * radius_px,
                        "outline vertex at {rho} px, radius {radius_px} px"
                    );
                    angles.push(dy.atan2(dx));
                    checked[0] += 1;
                }
            }
            angles.sort_by(f64::total_cmp);
            let gap = angles
                .windows(2)
                .map(|w| w[1] - w[0])
                .fold(2.0 * PI - (angles[angles.len() - 1] - angles[0]), f64::max);
            assert!(gap < 0.1, "the outline leaves a gap of {gap} rad");
            // The net: hidden exactly on the far side (a band round the rim is free:
            // there the depth test's tolerance decides).
            for s in scene.strokes.iter().filter(|s| s.role == Role::Net) {
                for x in &s.source[1..s.source.len() - 1] {
                    let side = dot(&[x[0] - c[0], x[1] - c[1], x[2] - c[2]], &d) / r;
                    if side.abs() > 0.15 {
                        assert_eq!(s.hidden, side < 0.0, "net vertex {x:?} at side {side}");
                        checked[if s.hidden { 1 } else { 2 }] += 1;
                    }
                }
            }
        }
    }
    assert!(checked.iter().all(|&n| n > 1000), "{checked:?}");
}

#[test]
fn a_sphere_behind_a_bigger_one_is_hidden_and_one_beside_it_is_not() {
    let mut rng = Rng(29);
    for view in views(&mut rng, 5) {
        let d = toward(&view);
        let small = [-4.0 * d[0], -4.0 * d[1], -4.0 * d[2]];
        let beside = {
            // A direction across the view: the picture's X axis, far enough.
            let e = view.e_x;
            [6.0 * e[0], 6.0 * e[1], 6.0 * e[2]]
        };
        let scene = draw(
            &[
                sphere([0.0; 3], 2.0),
                sphere(small, 0.5),
                sphere(beside, 0.5),
            ],
            &view,
        );
        let of = |k: usize| scene.strokes.iter().filter(move |s| s.object == Some(k));
        assert!(
            of(1).count() > 0 && of(1).all(|s| s.hidden),
            "behind the big sphere"
        );
        assert!(
            of(2).filter(|s| s.role == Role::Contour).all(|s| !s.hidden),
            "the outline of the sphere beside it"
        );
    }
}

#[test]
fn quadric_outlines_match_the_closed_forms_of_16_14() {
    // §16.14: the ellipsoid of revolution a = 3, c = 5 in the isometric view: its
    // outline is its section by x/9 + y/9 + z/25 = 0.
    let case = r#"{"op": "silhouette", "view": "isometric", "objects": [{"type": "ellipsoid", "center": [0, 0, 0], "a": 3, "b": 3, "c": 5, "axis": [0, 0, 1]}]}"#;
    let read = read_cases(case).remove(0).case.expect("a case");
    let shapes = picture::shapes(&read).expect("shapes");
    let scene = draw(&shapes, &View::isometric());
    let mut n = 0;
    for s in scene.strokes.iter().filter(|s| s.role == Role::Contour) {
        for x in &s.source {
            let plane = x[0] / 9.0 + x[1] / 9.0 + x[2] / 25.0;
            assert!(
                plane.abs() < 2e-3,
                "outline vertex {x:?} off the conjugate plane"
            );
            n += 1;
        }
    }
    assert!(n > 100, "{n}");
    // A cylinder's outline: the generators u = ψ ± π/2 for every direction (13.12).
    let mut rng = Rng(5);
    for view in views(&mut rng, 8) {
        let d = toward(&view);
        if d[0].hypot(d[1]) < 1e-3 {
            continue; // along the axis: the outline is the whole circle of the ends
        }
        let psi = d[1].atan2(d[0]);
        let cyl = r#"{"op": "silhouette", "view": "isometric", "objects": [{"type": "cylinder", "origin": [0, 0, 0], "radius": 2, "axis": [0, 0, 1], "height": [-1, 3]}]}"#;
        let read = read_cases(cyl).remove(0).case.expect("a case");
        let scene = draw(&picture::shapes(&read).expect("shapes"), &view);
        let mut m = 0;
        for s in scene.strokes.iter().filter(|s| s.role == Role::Contour) {
            for x in &s.source {
                let u = x[1].atan2(x[0]);
                let off = ((u - psi).rem_euclid(PI) - PI / 2.0).abs();
                assert!(off < 2e-3, "outline vertex at u = {u}, ψ = {psi}");
                m += 1;
            }
        }
        assert!(m >= 4, "{m}");
    }
}

/// Solve a case and draw it in its default view.
fn solved(case: &str, opts: &RenderOptions) -> (Scene, geocert::Certified<geocert::ops::Answer>) {
    let read = read_cases(case).remove(0).case.expect("a case");
    let shapes = picture::shapes(&read).expect("shapes");
    let view = picture::view(&read, None).expect("a view");
    let c = answer(&read).expect("an answer");
    let input = Input {
        shapes: &shapes,
        point: picture::query_point(&read).expect("a point"),
        answer: Some(&c),
        view: &view,
    };
    let scene = render::picture(&input, opts, "t".into()).expect("a picture");
    (scene, c)
}

#[test]
fn answer_points_are_marked_where_they_project_and_hidden_on_the_far_side() {
    let mut rng = Rng(41);
    let view = View::isometric();
    let d = toward(&view);
    let mut seen = [0usize; 2];
    for _ in 0..24 {
        let c = [
            rng.range(-3.0, 3.0),
            rng.range(-3.0, 3.0),
            rng.range(-3.0, 3.0),
        ];
        let r = rng.range(0.5, 2.0);
        // A line through the sphere, across the view.
        let o = [c[0] + rng.range(-0.5, 0.5) * r, c[1], c[2]];
        let dir = [
            rng.range(-1.0, 1.0),
            rng.range(-1.0, 1.0),
            rng.range(-1.0, 1.0),
        ];
        let case = format!(
            r#"{{"op": "intersect", "objects": [{{"type": "line", "origin": {o:?}, "dir": {dir:?}}}, {{"type": "sphere", "center": {c:?}, "radius": {r}}}]}}"#
        );
        let (scene, c_ans) = solved(&case, &RenderOptions::default());
        let points = c_ans.value.points();
        let marks: Vec<_> = scene
            .markers
            .iter()
            .filter(|m| m.kind == MarkerKind::Point)
            .collect();
        assert_eq!(marks.len(), points.len(), "{case}");
        for (m, p) in marks.iter().zip(points) {
            let x = [p.xyz[0], p.xyz[1], p.xyz[2]];
            let want = scene.pixel(view.project(&x));
            assert!((m.at[0] - want[0]).abs() < 1e-9 && (m.at[1] - want[1]).abs() < 1e-9);
            let side = dot(&[x[0] - c[0], x[1] - c[1], x[2] - c[2]], &d) / r;
            if side.abs() > 0.15 {
                assert_eq!(m.hidden, side < 0.0, "{case}: point {x:?}");
                seen[usize::from(m.hidden)] += 1;
            }
        }
    }
    assert!(seen[0] > 5 && seen[1] > 5, "{seen:?}");
}

#[test]
fn curves_blends_projections_and_plane_cases_are_drawn() {
    let opts = RenderOptions::default();
    // Surface ∩ surface: answer curves and the singular points of Steinmetz's pair.
    let steinmetz = r#"{"op": "intersect", "objects": [{"type": "cylinder", "origin": [0, 0, -2], "radius": 1, "axis": [0, 0, 1], "height": [0, 4]}, {"type": "cylinder", "origin": [-2, 0, 0], "radius": 1, "axis": [1, 0, 0], "height": [0, 4]}]}"#;
    let (scene, c) = solved(steinmetz, &opts);
    let geocert::ops::Answer::Curves(curves) = &c.value else {
        panic!("curves expected, got {}", c.value.kind());
    };
    assert!(scene.strokes.iter().any(|s| s.role == Role::Answer));
    let singular = scene
        .markers
        .iter()
        .filter(|m| m.kind == MarkerKind::Singular)
        .count();
    assert_eq!(singular, curves.singular_points.len());
    // A fillet: spine, contacts and the blend's net.
    let fillet = r#"{"op": "fillet", "objects": [{"type": "plane", "normal": [0, 0, 1], "d": 0}, {"type": "plane", "normal": [1, 0, 0], "d": 0}], "radius": 1, "sector": 3, "range": [-2, 2]}"#;
    let (scene, _) = solved(fillet, &opts);
    for role in [Role::Spine, Role::Contact, Role::BlendNet, Role::Net] {
        assert!(scene.strokes.iter().any(|s| s.role == role), "{role:?}");
    }
    // A projection: the query point, the feet, the guides.
    let project = r#"{"op": "project", "point": [1, 2, 3], "onto": {"type": "torus", "center": [0, 0, 0], "major": 3, "minor": 1, "axis": [0, 0, 1]}}"#;
    let (scene, c) = solved(project, &opts);
    let feet = scene
        .markers
        .iter()
        .filter(|m| m.kind == MarkerKind::Foot)
        .count();
    assert_eq!(feet, c.value.points().len());
    assert!(feet >= 2);
    let guides = scene
        .strokes
        .iter()
        .filter(|s| s.role == Role::Guide)
        .count();
    assert!(guides >= feet, "{guides} guides for {feet} feet");
    assert_eq!(
        scene
            .markers
            .iter()
            .filter(|m| m.kind == MarkerKind::Query)
            .count(),
        1
    );
    // A plane case: drawn in its own plane, X = x and Y = y up to the picture's scale.
    let plane = r#"{"op": "intersect", "objects": [{"type": "circle2", "center": [1, 2], "radius": 2}, {"type": "line2", "origin": [0, 2], "dir": [1, 0]}]}"#;
    let (scene, c) = solved(plane, &opts);
    let pts = c.value.points();
    assert_eq!(pts.len(), 2);
    for (m, p) in scene.markers.iter().zip(pts) {
        let want = scene.pixel([p.xyz[0], p.xyz[1]]);
        assert!((m.at[0] - want[0]).abs() < 1e-9 && (m.at[1] - want[1]).abs() < 1e-9);
        assert!(!m.hidden);
    }
    // The two points at (−1, 2) and (3, 2): 4 picture units apart, horizontally.
    let dx = (scene.markers[0].at[0] - scene.markers[1].at[0]).abs();
    assert!((dx - 4.0 * scene.scale).abs() < 1e-9);
    // Boxes on request: 12 projected edges per box, or one 4-pixel square for a box
    // smaller than that (these are ~10⁻¹⁶ wide), centred on the point's marker.
    let boxed = RenderOptions {
        boxes: true,
        ..RenderOptions::default()
    };
    let (scene, c) = solved(steinmetz, &boxed);
    let n_boxes = scene.strokes.iter().filter(|s| s.role == Role::Box).count();
    let geocert::ops::Answer::Curves(curves) = &c.value else {
        panic!("curves");
    };
    assert!(!curves.singular_points.is_empty());
    assert_eq!(
        n_boxes,
        curves.singular_points.len(),
        "one square per tiny box"
    );
    for (s, m) in scene.strokes.iter().filter(|s| s.role == Role::Box).zip(
        scene
            .markers
            .iter()
            .filter(|m| m.kind == MarkerKind::Singular),
    ) {
        let c = [
            0.25 * s.points[..4].iter().map(|p| p[0]).sum::<f64>(),
            0.25 * s.points[..4].iter().map(|p| p[1]).sum::<f64>(),
        ];
        assert!(
            (c[0] - m.at[0]).abs() < 0.5 && (c[1] - m.at[1]).abs() < 0.5,
            "{c:?} vs {:?}",
            m.at
        );
    }
}

fn count(svg: &str, needle: &str) -> usize {
    svg.matches(needle).count()
}

#[test]
fn svg_and_png_files_hold_what_the_scene_holds() {
    let case = r#"{"op": "intersect", "objects": [{"type": "line", "origin": [0.6, 0, -2], "dir": [0, 0, 1]}, {"type": "sphere", "center": [0, 0, 0], "radius": 1}]}"#;
    let (scene, _) = solved(case, &RenderOptions::default());
    let svg = render::svg(&scene).expect("svg");
    assert_eq!(svg, render::svg(&scene).expect("svg"), "deterministic");
    assert!(svg.starts_with("<svg") && svg.trim_end().ends_with("</svg>"));
    // Two answer points: one visible (a filled vermillion disc), one on the far side
    // of the sphere from the isometric viewer (a ring).
    let visible = scene
        .markers
        .iter()
        .filter(|m| m.kind == MarkerKind::Point && !m.hidden)
        .count();
    let hidden = scene
        .markers
        .iter()
        .filter(|m| m.kind == MarkerKind::Point && m.hidden)
        .count();
    assert_eq!((visible, hidden), (1, 1));
    assert_eq!(count(&svg, r##"fill="#D55E00""##), visible);
    assert!(svg.contains("<text"), "the title");
    // Dashed runs are drawn as many short pieces: more polylines than strokes.
    let strokes = scene.strokes.len();
    assert!(count(&svg, "<polyline") > strokes);
    let dir = std::env::temp_dir().join(format!("geocert-render-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let path = dir.join("p.png");
    render::png(&scene, &path).expect("png");
    let decoder = png::Decoder::new(std::fs::File::open(&path).expect("the png"));
    let mut reader = decoder.read_info().expect("a png");
    let mut buf = vec![0; reader.output_buffer_size()];
    let info = reader.next_frame(&mut buf).expect("a frame");
    assert_eq!([info.width, info.height], scene.size);
    let m = scene
        .markers
        .iter()
        .find(|m| m.kind == MarkerKind::Point && !m.hidden)
        .expect("a visible point");
    let (x, y) = (m.at[0].round() as usize, m.at[1].round() as usize);
    let k = (y * info.width as usize + x) * info.color_type.samples();
    assert_eq!(&buf[k..k + 3], &[213, 94, 0], "the visible point's disc");
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn the_command_writes_one_picture_per_case_and_names_bad_ones() {
    let dir = std::env::temp_dir().join(format!("geocert-render-cli-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let cases = dir.join("cases.jsonl");
    std::fs::write(
        &cases,
        concat!(
            r#"{"id": "ls/1", "op": "intersect", "objects": [{"type": "line", "origin": [0.6, 0, -2], "dir": [0, 0, 1]}, {"type": "sphere", "center": [0, 0, 0], "radius": 1}]}"#,
            "\n",
            r#"{"id": 7, "op": "intersect", "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": -1}, {"type": "sphere", "center": [0, 0, 0], "radius": 1}]}"#,
            "\n",
            r#"{"op": "silhouette", "view": "frontal", "objects": [{"type": "torus", "center": [0, 0, 0], "major": 3, "minor": 1, "axis": [0, 1, 1]}]}"#,
            "\n",
        ),
    )
    .expect("write");
    let out = dir.join("pics");
    let run = Command::new(env!("CARGO_BIN_EXE_geocert"))
        .args([
            "render",
            cases.to_str().unwrap(),
            "--png",
            "--out",
            out.to_str().unwrap(),
        ])
        .output()
        .expect("geocert runs");
    let stdout = String::from_utf8_lossy(&run.stdout);
    let stderr = String::from_utf8_lossy(&run.stderr);
    assert_eq!(run.status.code(), Some(1), "{stdout}\n{stderr}");
    assert!(out.join("ls_1.svg").is_file() && out.join("ls_1.png").is_file());
    assert!(out.join("case-3.svg").is_file(), "{stdout}");
    assert!(!out.join("7.svg").exists());
    assert!(
        stderr.contains("case 2") && stderr.contains("radius"),
        "{stderr}"
    );
    assert_eq!(stdout.lines().count(), 2, "{stdout}");
    assert!(stdout.contains("exact\tpoints"), "{stdout}");
    // A bad view is a usage error naming the option, before any case runs.
    let bad = Command::new(env!("CARGO_BIN_EXE_geocert"))
        .args([
            "render",
            cases.to_str().unwrap(),
            "--view",
            "sideways",
            "--out",
            out.to_str().unwrap(),
        ])
        .output()
        .expect("geocert runs");
    assert_eq!(bad.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&bad.stderr).contains("--view"));
    std::fs::remove_dir_all(&dir).ok();
}

/// Outlines where the closed form is a tangency condition: a sphere seen from an eye
/// point (every outline vertex `x` has `(x − c)·(E − x) = 0`: the ray from the eye
/// touches the sphere there), and a torus in parallel views (the torus normal at `x`,
/// `x − q` with `q` the nearest point of the core circle, is perpendicular to `d`).
#[test]
fn central_and_torus_outlines_are_tangencies() {
    let mut rng = Rng(73);
    for _ in 0..8 {
        let c = [
            rng.range(-2.0, 2.0),
            rng.range(-2.0, 2.0),
            rng.range(-2.0, 2.0),
        ];
        let r = rng.range(0.5, 1.5);
        let eye = [
            c[0] + rng.range(4.0, 8.0),
            c[1] + rng.range(-6.0, 6.0),
            c[2] + rng.range(-6.0, 6.0),
        ];
        let view = View::central(eye, c, 1.0).expect("a central view");
        let scene = draw(&[sphere(c, r)], &view);
        let mut n = 0;
        for s in scene.strokes.iter().filter(|s| s.role == Role::Contour) {
            for x in &s.source {
                let (xc, ex) = (
                    [0, 1, 2].map(|k| x[k] - c[k]),
                    [0, 1, 2].map(|k| eye[k] - x[k]),
                );
                let cos = dot(&xc, &ex) / (r * dot(&ex, &ex).sqrt());
                assert!(cos.abs() < 5e-3, "central outline vertex {x:?}: cos {cos}");
                n += 1;
            }
        }
        assert!(n > 50, "{n}");
    }
    let (major, minor) = (3.0, 1.0);
    let torus = r#"{"op": "silhouette", "view": "isometric", "objects": [{"type": "torus", "center": [0, 0, 0], "major": 3, "minor": 1, "axis": [0, 0, 1]}]}"#;
    let read = read_cases(torus).remove(0).case.expect("a case");
    let shapes = picture::shapes(&read).expect("shapes");
    for view in views(&mut rng, 6) {
        let d = toward(&view);
        let scene = draw(&shapes, &view);
        let mut n = 0;
        for s in scene.strokes.iter().filter(|s| s.role == Role::Contour) {
            for x in &s.source {
                let rho = x[0].hypot(x[1]);
                let q = [major * x[0] / rho, major * x[1] / rho, 0.0];
                let normal = [x[0] - q[0], x[1] - q[1], x[2] - q[2]];
                let cos = dot(&normal, &d) / minor;
                assert!(cos.abs() < 5e-3, "torus outline vertex {x:?}: cos {cos}");
                n += 1;
            }
        }
        assert!(n > 50, "{n}");
    }
}

fn quadric(m: [[f64; 4]; 4]) -> Shape {
    Shape::Quadric(geocert::surface::implicit::ImplicitQuadric::new(m).expect("a valid matrix"))
}

#[test]
fn an_implicit_ellipsoid_is_drawn_as_the_ellipsoid_of_16_14() {
    // §16.14's ellipsoid x²/9 + y²/9 + z²/25 = 1 given by its matrix, turned (x ↔ z
    // is the same surface with c along x): its isometric outline is the section by the
    // conjugate plane x/25 + y/9 + z/9 = 0, and as an ellipsoid it occludes its far side.
    let (a, c) = (1.0 / 9.0, 1.0 / 25.0);
    let shape = quadric([
        [c, 0.0, 0.0, 0.0],
        [0.0, a, 0.0, 0.0],
        [0.0, 0.0, a, 0.0],
        [0.0, 0.0, 0.0, -1.0],
    ]);
    let scene = draw(&[shape], &View::isometric());
    let mut n = 0;
    for s in scene.strokes.iter().filter(|s| s.role == Role::Contour) {
        assert!(!s.hidden, "a lone ellipsoid's outline is visible");
        for x in &s.source {
            let surface = x[0] * x[0] * c + (x[1] * x[1] + x[2] * x[2]) * a - 1.0;
            let plane = x[0] * c + x[1] * a + x[2] * a;
            assert!(
                surface.abs() < 2e-3 && plane.abs() < 2e-3,
                "outline vertex {x:?}"
            );
            n += 1;
        }
    }
    assert!(n > 100, "{n}");
    let net: Vec<_> = scene
        .strokes
        .iter()
        .filter(|s| s.role == Role::Net)
        .collect();
    assert!(net.iter().any(|s| s.hidden) && net.iter().any(|s| !s.hidden));
    for s in &net {
        for x in &s.source {
            let surface = x[0] * x[0] * c + (x[1] * x[1] + x[2] * x[2]) * a - 1.0;
            // (a vertex where a stroke is split into hidden and visible runs lies on a
            // chord of the net line: off the surface by the chord's sag)
            assert!(surface.abs() < 2e-3, "net vertex {x:?} off the ellipsoid");
        }
    }
}

#[test]
fn an_unbounded_quadric_is_drawn_by_its_sections_and_its_contour_plane() {
    // The one-sheet hyperboloid x² + y² − z² = 1 beside a sphere that sets the window.
    // Frontal view (d = (0, −1, 0)): the contour lies on the plane (A d)·x = −y = 0,
    // so it is the hyperbola x² − z² = 1 of y = 0. Every net vertex lies on the surface
    // (within the marching squares' interpolation); the net has sections in both
    // families (planes z = const and x = const).
    let shape = quadric([
        [1.0, 0.0, 0.0, 0.0],
        [0.0, 1.0, 0.0, 0.0],
        [0.0, 0.0, -1.0, 0.0],
        [0.0, 0.0, 0.0, -1.0],
    ]);
    let scene = draw(&[sphere([0.0, 0.0, 0.0], 3.0), shape], &View::frontal());
    let of = |role: Role| {
        scene
            .strokes
            .iter()
            .filter(move |s| s.role == role && s.object == Some(1))
    };
    let f = |x: &[f64; 3]| x[0] * x[0] + x[1] * x[1] - x[2] * x[2] - 1.0;
    let (mut flat_z, mut flat_x) = (0, 0);
    for s in of(Role::Net) {
        for x in &s.source {
            assert!(f(x).abs() < 0.05 * (1.0 + x[2] * x[2]), "net vertex {x:?}");
        }
        let spread = |k: usize| {
            let (lo, hi) = s
                .source
                .iter()
                .fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), x| {
                    (l.min(x[k]), h.max(x[k]))
                });
            hi - lo
        };
        flat_z += usize::from(spread(2) == 0.0);
        flat_x += usize::from(spread(0) == 0.0);
    }
    assert!(
        flat_z >= 10 && flat_x >= 6,
        "{flat_z} sections z = const, {flat_x} x = const"
    );
    let mut n = 0;
    for s in of(Role::Contour) {
        for x in &s.source {
            assert!(
                x[1].abs() < 1e-9,
                "contour vertex {x:?} off the plane y = 0"
            );
            let h = x[0] * x[0] - x[2] * x[2] - 1.0;
            assert!(h.abs() < 0.05 * (1.0 + x[2] * x[2]), "contour vertex {x:?}");
            n += 1;
        }
    }
    assert!(n > 50, "{n}");
    // Seen along its axis the cylinder x² + y² = 1 has no contour plane (A d = 0): no
    // contour, but its sections are drawn.
    let cyl = quadric([
        [1.0, 0.0, 0.0, 0.0],
        [0.0, 1.0, 0.0, 0.0],
        [0.0, 0.0, 0.0, 0.0],
        [0.0, 0.0, 0.0, -1.0],
    ]);
    let scene = draw(&[sphere([0.0; 3], 2.0), cyl], &View::horizontal());
    let mine = |role: Role| {
        scene
            .strokes
            .iter()
            .filter(|s| s.role == role && s.object == Some(1))
            .count()
    };
    assert_eq!(mine(Role::Contour), 0);
    assert!(mine(Role::Net) > 10);
}

/// An `arc` answer is drawn along the curve between its ends, not only as two markers:
/// `A(t) = (4t, 8t(1 − t))` and its first half share the arc `t ∈ [0, 1/2]`, so every
/// vertex of the answer's stroke has `0 ≤ x ≤ 2` and `y = 8t(1 − t)` with `t = x/4`.
#[test]
fn a_shared_arc_is_drawn_along_the_curve() {
    let case = r#"{"op": "intersect", "objects": [{"type": "bezier2", "points": [[0, 0], [2, 4], [4, 0]]}, {"type": "bezier2", "points": [[0, 0], [1, 2], [2, 2]]}]}"#;
    let (scene, c) = solved(case, &RenderOptions::default());
    assert_eq!(c.value.kind(), "arc");
    let answer: Vec<_> = scene
        .strokes
        .iter()
        .filter(|s| s.role == Role::Answer)
        .flat_map(|s| s.source.iter())
        .collect();
    assert!(answer.len() > 32, "{}", answer.len());
    for p in &answer {
        let t = p[0] / 4.0;
        assert!((-1e-12..=2.0 + 1e-12).contains(&p[0]), "{p:?}");
        assert!((p[1] - 8.0 * t * (1.0 - t)).abs() < 1e-9, "{p:?}");
    }
    let (lo, hi) = answer
        .iter()
        .fold((f64::MAX, f64::MIN), |(l, h), p| (l.min(p[0]), h.max(p[0])));
    assert!(
        lo < 1e-9 && hi > 2.0 - 1e-9,
        "the stroke spans the arc: {lo} … {hi}"
    );
}
