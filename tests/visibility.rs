//! Visibility of surface points (OPERATIONS.md §13.5): generated points on spheres
//! against the closed-form truth at 300 bits — a sphere alone hides exactly its back
//! (`n̂·d < 0`), and a second sphere hides a front point exactly when the ray toward
//! the viewer meets it (the quadratic's discriminant and root signs).

use geocert::certificate::Status;
use geocert::num::rng::Rng;
use geocert::ops::view::{visibility_point_surface, View, Visibility};
use geocert::surface::quadrics::Sphere;
use geocert::surface::AnySurface;
use rug::Float;

fn mp(x: f64) -> Float {
    Float::with_val(300, x)
}

fn u01(rng: &mut Rng) -> f64 {
    0.5 * (rng.unit() + 1.0)
}

/// The exact point of the sphere net and its outward unit normal, 300 bits.
fn net(c: [f64; 3], r: f64, u: f64, v: f64) -> ([Float; 3], [Float; 3]) {
    let (cu, su, cv, sv) = (mp(u).cos(), mp(u).sin(), mp(v).cos(), mp(v).sin());
    let n = [cv.clone() * &cu, cv * &su, sv];
    let p = std::array::from_fn(|i| mp(c[i]) + mp(r) * &n[i]);
    (p, n)
}

fn dot(a: &[Float; 3], b: &[f64; 3]) -> Float {
    (0..3).fold(mp(0.0), |s, i| s + a[i].clone() * b[i])
}

#[test]
fn a_sphere_hides_its_back() {
    let mut rng = Rng::new(21);
    let (mut decided, mut total) = (0, 0);
    for case in 0..40 {
        let c = [rng.unit(), rng.unit(), rng.unit()];
        let r = 0.2 + 2.0 * u01(&mut rng);
        let d = [rng.unit(), rng.unit(), rng.unit() + 0.01];
        let (u, v) = (std::f64::consts::TAU * u01(&mut rng), 1.4 * rng.unit());
        let s = AnySurface::Sphere(Sphere::new(c, r, None, None).unwrap());
        let out = visibility_point_surface(
            &s,
            [u, v],
            &View::parallel(d).unwrap(),
            &[],
            &Default::default(),
        )
        .unwrap();
        let (_, n) = net(c, r, u, v);
        let g = dot(&n, &d);
        total += 1;
        if out.status == Status::Undecided {
            continue;
        }
        decided += 1;
        let truth = if g > 0 {
            Visibility::Visible
        } else {
            Visibility::Hidden
        };
        assert_eq!(out.value.visibility, truth, "case {case}: I = {g}");
        if truth == Visibility::Hidden {
            assert_eq!(out.value.blocker.unwrap().0, 0);
        }
    }
    assert!(decided * 10 >= total * 9, "{decided} of {total} decided");
}

#[test]
fn a_second_sphere_occludes_exactly_where_the_ray_meets_it() {
    let mut rng = Rng::new(34);
    let (mut hidden, mut visible) = (0, 0);
    for case in 0..40 {
        let c = [0.0, 0.0, 0.0];
        let r = 1.0;
        let d = [0.0, 0.0, 1.0];
        // a front point (n_z > 0.2) and a blocker above the sphere
        let (u, v) = (
            std::f64::consts::TAU * u01(&mut rng),
            0.25 + 1.2 * u01(&mut rng),
        );
        let cb = [0.8 * rng.unit(), 0.8 * rng.unit(), 3.0 + u01(&mut rng)];
        let rb = 0.2 + 0.5 * u01(&mut rng);
        let a = AnySurface::Sphere(Sphere::new(c, r, None, None).unwrap());
        let b = AnySurface::Sphere(Sphere::new(cb, rb, None, None).unwrap());
        let (p, _) = net(c, r, u, v);
        // |p + t d − cb|² = rb²: t² + 2 t (p − cb)·d + |p − cb|² − rb² = 0
        let w: [Float; 3] = std::array::from_fn(|i| p[i].clone() - cb[i]);
        let bq = dot(&w, &d);
        let cq = (0..3).fold(mp(0.0), |s, i| s + w[i].clone() * &w[i]) - mp(rb) * mp(rb);
        let disc = bq.clone() * &bq - &cq;
        if disc.clone().abs() < 1e-6 {
            continue; // grazing: either answer would need more than this test checks
        }
        let meets = disc > 0 && (-bq + disc.sqrt()) > 0;
        let out = visibility_point_surface(
            &a,
            [u, v],
            &View::parallel(d).unwrap(),
            &[&b],
            &Default::default(),
        )
        .unwrap();
        assert_eq!(
            out.status,
            Status::Verified,
            "case {case}: {:?}",
            out.reason
        );
        if meets {
            hidden += 1;
            assert_eq!(out.value.visibility, Visibility::Hidden, "case {case}");
            assert_eq!(out.value.blocker.as_ref().unwrap().0, 1);
        } else {
            visible += 1;
            assert_eq!(out.value.visibility, Visibility::Visible, "case {case}");
        }
    }
    assert!(
        hidden >= 3 && visible >= 3,
        "{hidden} hidden, {visible} visible"
    );
}

/// §16.14: the cylinder seen isometrically — contour generators at `u = 3π/4, 7π/4`,
/// `u = π/4` visible (`I > 0`).
#[test]
fn worked_example_16_14_cylinder() {
    use geocert::surface::quadrics::Cylinder;
    let s = AnySurface::Cylinder(
        Cylinder::new([0.0; 3], [1.0, 1.0], [0.0, 0.0, 1.0], None, [0.0, 2.0]).unwrap(),
    );
    let view = View::isometric();
    let out = visibility_point_surface(
        &s,
        [std::f64::consts::FRAC_PI_4, 1.0],
        &view,
        &[],
        &Default::default(),
    )
    .unwrap();
    assert_eq!(out.status, Status::Verified, "{:?}", out.reason);
    assert_eq!(out.value.visibility, Visibility::Visible);
    assert!(out.value.contour_value.lo() > 0.0);
    let c = geocert::ops::view::contour_surface(&s, &view, &Default::default()).unwrap();
    assert!(c.complete, "{:?}", c.reason);
    let mut us: Vec<f64> = c
        .value
        .curves
        .iter()
        .map(|k| k.points[0].params[0])
        .collect();
    us.sort_by(f64::total_cmp);
    assert_eq!(us.len(), 2);
    assert!(
        (us[0] - 3.0 * std::f64::consts::FRAC_PI_4).abs() < 1e-12,
        "{us:?}"
    );
    assert!(
        (us[1] - 7.0 * std::f64::consts::FRAC_PI_4).abs() < 1e-12,
        "{us:?}"
    );
}

/// The `visibility` case of the command line (docs/FORMAT.md): the same family as
/// [`a_second_sphere_occludes_exactly_where_the_ray_meets_it`], asked through
/// `geocert::io`: kind `visible` / `hidden` by the 300-bit truth, the point's box holding
/// the exact net point, `blocker` 1 exactly when hidden; a missing `params` or `view`
/// is an error naming it.
#[test]
fn the_visibility_case_answers_by_the_closed_form() {
    use geocert::io::{read_cases, solve_case};
    let mut rng = Rng::new(55);
    let (mut hidden, mut visible) = (0, 0);
    for case in 0..30 {
        let (u, v) = (
            std::f64::consts::TAU * u01(&mut rng),
            0.25 + 1.2 * u01(&mut rng),
        );
        let cb = [0.8 * rng.unit(), 0.8 * rng.unit(), 3.0 + u01(&mut rng)];
        let rb = 0.2 + 0.5 * u01(&mut rng);
        let (p, _) = net([0.0; 3], 1.0, u, v);
        let w: [Float; 3] = std::array::from_fn(|i| p[i].clone() - cb[i]);
        let bq = dot(&w, &[0.0, 0.0, 1.0]);
        let cq = (0..3).fold(mp(0.0), |s, i| s + w[i].clone() * &w[i]) - mp(rb) * mp(rb);
        let disc = bq.clone() * &bq - &cq;
        if disc.clone().abs() < 1e-6 {
            continue;
        }
        let meets = disc > 0 && (-bq + disc.sqrt()) > 0;
        let text = format!(
            r#"{{"id": {case}, "op": "visibility", "params": [{u}, {v}], "view": {{"type": "parallel", "direction": [0, 0, 1]}}, "objects": [{{"type": "sphere", "center": [0, 0, 0], "radius": 1}}, {{"type": "sphere", "center": {cb:?}, "radius": {rb}}}]}}"#
        );
        let r = solve_case(read_cases(&text).remove(0));
        let json = serde_json::to_value(&r).unwrap();
        assert_eq!(r.status, "verified", "case {case}: {json}");
        let want = if meets { "hidden" } else { "visible" };
        assert_eq!(r.kind, Some(want), "case {case}: {json}");
        assert_eq!(json["blocker"].as_u64(), meets.then_some(1), "case {case}");
        let pt = &json["points"][0];
        for k in 0..3 {
            let b = &pt["box"][k];
            let (lo, hi) = (b[0].as_f64().unwrap(), b[1].as_f64().unwrap());
            assert!(
                p[k] >= lo && p[k] <= hi,
                "case {case}: coordinate {k} outside its box"
            );
        }
        assert_eq!(pt["params"][0][0].as_f64(), Some(u));
        if meets {
            hidden += 1;
        } else {
            visible += 1;
        }
    }
    assert!(
        hidden >= 3 && visible >= 3,
        "{hidden} hidden, {visible} visible"
    );
    for (drop, field) in [
        ("\"params\": [1, 0.5], ", "params"),
        ("\"view\": \"horizontal\", ", "view"),
    ] {
        let text = r#"{"op": "visibility", "params": [1, 0.5], "view": "horizontal", "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1}]}"#
            .replace(drop, "");
        let r = solve_case(read_cases(&text).remove(0));
        let json = serde_json::to_value(&r).unwrap();
        assert_eq!(json["error"]["field"].as_str(), Some(field), "{json}");
    }
}
