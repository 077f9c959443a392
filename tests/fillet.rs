//! Fillets and chamfers (OPERATIONS.md §11, §16.13; issue 18): the worked example's
//! exact values; plane/cylinder, cylinder/cylinder and sphere/plane families against
//! independent closed forms in 256-bit MPFR intervals (every certified box contains the
//! truth); the property that every fillet point lies at distance ρ from its centre and
//! the surface is G1 with both faces along the contact curves (MPFR intervals over
//! generated radii, angles and sectors); the degenerate cases of §11.4 as typed errors.

#[path = "fillet_support/mod.rs"]
mod fillet_support;

use fillet_support::*;
use geocert::num::rng::Rng;
use geocert::ops::fillet::{
    end_tangency, BlendSpec, CentreCurve, Face, FilletSurface, Law, SectorChoice,
};
use geocert::ops::{Answer, Options, Shape};
use geocert::surface::Surface;
use geocert::Status;

/// §16.13: faces z = 0 and x = 0, body x ≤ 0, z ≤ 0, sector 3, ρ = 1.
#[test]
fn worked_example_16_13_fillet() {
    let r = plane([0.0; 3], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]);
    let s = plane([0.0; 3], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]);
    let (b, status) = blend(&r, &s, 1.0, &spec(3, Some([-2.0, 2.0]), [5, 5]));
    assert_eq!(status, Status::Verified);
    assert_eq!(b.sector, 3);
    assert_eq!(b.components.len(), 1);
    let c = &b.components[0];
    let sqrt_half = m(0.5).sqrt();
    let one = m(1.0);
    let den = m(10.0) / m(16.0) + m(3.0) / m(8.0) * sqrt_half.clone();
    for (i, &y) in c.grid.t.iter().enumerate() {
        // centre (−1, y, −1), contact lines (−1, y, 0) and (0, y, −1), exactly
        assert_eq!(c.spine.points[i].xyz, vec![-1.0, y, -1.0]);
        assert_eq!(c.contacts[0][i].xyz, vec![-1.0, y, 0.0]);
        assert_eq!(c.contacts[1][i].xyz, vec![0.0, y, -1.0]);
        assert_eq!(c.contacts[0][i].params, vec![vec![-1.0, y]]);
        assert_eq!(c.contacts[1][i].params, vec![vec![y, -1.0]]);
        let row = &c.grid.points[i];
        assert_eq!(c.grid.z, vec![0.0, 0.25, 0.5, 0.75, 1.0]);
        // the printed values of §16.13
        let near = |a: f64, b: f64| (a - b).abs() < 1e-10;
        assert!(near(row[1][0], -0.6319052904) && near(row[1][2], -0.0702116989));
        assert!(near(row[2][0], -0.2928932188) && near(row[2][2], -0.2928932188));
        assert_eq!(row[1][1], y);
        // the closed forms: f(·, ½) = (1/√2 − 1)(1, 0, 1) + (0, y, 0);
        // f(·, ¼) = (−9/16, y, −1/16)/(10/16 + 3/(8√2))
        let half = sqrt_half.clone() - one.clone();
        let quarter_x = -(m(9.0) / m(16.0)) / den.clone();
        let quarter_z = -(m(1.0) / m(16.0)) / den.clone();
        assert_box_contains(&c.grid.boxes[i][2], &[half.clone(), m(y), half], "f(½)");
        assert_box_contains(&c.grid.boxes[i][1], &[quarter_x, m(y), quarter_z], "f(¼)");
    }
    // cos φ = 0, w = 1/√2, p_m = (0, y, 0) (11.5)–(11.6)
    let f = fillet_surface(&r, &s, 1.0, 3, Some([-2.0, 2.0])).remove(0);
    let st = f.centre.station(&0.5f64);
    assert_eq!(st.cos_phi, 0.0);
}

fn fillet_surface(
    a: &Shape,
    b: &Shape,
    rho: f64,
    sector: u8,
    range: Option<[f64; 2]>,
) -> Vec<FilletSurface> {
    let faces = [
        Face::of_shape(a, "a").unwrap(),
        Face::of_shape(b, "b").unwrap(),
    ];
    let signs = geocert::ops::fillet::Sector::from_number(sector)
        .unwrap()
        .signs();
    CentreCurve::new(faces, signs, Law::Constant(rho), range)
        .unwrap()
        .into_iter()
        .map(|centre| FilletSurface { centre })
        .collect()
}

/// §16.13: chamfer legs 1 and 2: lines (−1, y, 0) and (0, y, −2), transversals meeting
/// on the edge (0, y, 0); the sector taken from the caller's side.
#[test]
fn worked_example_16_13_chamfer() {
    let r = plane([0.0; 3], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]);
    let s = plane([0.0; 3], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]);
    let side = BlendSpec {
        sector: SectorChoice::Side([-0.5, 3.0, -0.25]),
        range: Some([0.0, 4.0]),
        grid: [5, 3],
    };
    let c = geocert::ops::chamfer(&r, &s, [1.0, 2.0], &side, &Options::default()).unwrap();
    assert_eq!(c.status, Status::Verified);
    let Answer::Blend(b) = c.value else { panic!() };
    assert_eq!(b.sector, 3);
    let k = &b.components[0];
    for (i, &y) in k.grid.t.iter().enumerate() {
        assert_eq!(k.spine.points[i].xyz, vec![0.0, y, 0.0]);
        assert_eq!(k.contacts[0][i].xyz, vec![-1.0, y, 0.0]);
        assert_eq!(k.contacts[1][i].xyz, vec![0.0, y, -2.0]);
        assert_eq!(k.grid.points[i][1], [-0.5, y, -1.0]);
    }
}

/// Plane z = h and a cylinder about a vertical axis (dyadic data, both orders, every
/// sector the radius allows): centres at radius R ± ρ and height h ± ρ, contacts on the
/// cylinder at `(t, h ± ρ − o_z)` and on the plane below the centre — each reported box
/// contains the 256-bit truth at its station.
#[test]
fn plane_cylinder_contact_curves_are_the_closed_forms() {
    let mut rng = Rng::new(18);
    let mut checked = 0;
    for _ in 0..120 {
        let o = [rng.dyadic(), rng.dyadic(), rng.dyadic()];
        let r = 0.5 + rng.int(0, 40) as f64 / 8.0;
        let rho = r * rng.int(1, 7) as f64 / 8.0;
        let h = o[2] + rng.int(-16, 16) as f64 / 8.0;
        let pl = plane([0.0, 0.0, h], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]);
        let cy = cylinder(o, r, [0.0, 0.0, 1.0], [-8.0, 8.0]);
        let cyl_first = rng.coin();
        let (sp, sc) = (
            if rng.coin() { 1.0 } else { -1.0 },
            if rng.coin() { 1.0 } else { -1.0 },
        );
        let sector = match if cyl_first { (sc, sp) } else { (sp, sc) } {
            (a, b) if a > 0.0 && b > 0.0 => 1,
            (a, _) if a > 0.0 => 2,
            (_, b) if b < 0.0 => 3,
            _ => 4,
        };
        let (a, b) = if cyl_first { (&cy, &pl) } else { (&pl, &cy) };
        let (ans, status) = blend(a, b, rho, &spec(sector, None, [9, 3]));
        assert_eq!(status, Status::Verified);
        assert_eq!(ans.components.len(), 1);
        let k = &ans.components[0];
        let (ic, ip) = if cyl_first { (0, 1) } else { (1, 0) };
        for (i, &t) in k.grid.t.iter().enumerate() {
            let (ti, rr) = (m(t), m(r) + m(sc * rho));
            let zc = m(h) + m(sp * rho);
            let centre = [
                m(o[0]) + rr.clone() * ti.cos(),
                m(o[1]) + rr.clone() * ti.sin(),
                zc.clone(),
            ];
            let on_cyl = [
                m(o[0]) + m(r) * ti.cos(),
                m(o[1]) + m(r) * ti.sin(),
                zc.clone(),
            ];
            let on_plane = [centre[0].clone(), centre[1].clone(), m(h)];
            assert_box_contains(&k.contacts[ic][i].xyz_box, &on_cyl, "cylinder contact");
            assert_box_contains(&k.contacts[ip][i].xyz_box, &on_plane, "plane contact");
            let pb = k.contacts[ic][i].param_box.as_ref().unwrap();
            assert!(contains(pb[0][1], &(zc.clone() - m(o[2]))));
            // the centre lies within the certified bound of the reported vertex
            let d = dist(&k.spine.points[i].xyz, &centre);
            assert!(d <= k.spine.points[i].bound.unwrap(), "{d}");
            checked += 1;
        }
    }
    assert!(checked > 1000);
}

/// Two cylinders with perpendicular intersecting axes (z and x), the second wider: the
/// centre curves are `(R₁' cos t, R₁' sin t, ±√(R₂'² − R₁'² sin² t))`, two closed branches
/// in every sector whose offsets keep `R₂' > R₁'`.
#[test]
fn cylinder_cylinder_contact_curves_are_the_closed_forms() {
    let mut rng = Rng::new(1818);
    let mut components = 0;
    for _ in 0..60 {
        let r1 = 0.5 + rng.int(0, 16) as f64 / 8.0;
        let r2 = r1 + 1.0 + rng.int(0, 16) as f64 / 8.0;
        let rho = 0.25 * rng.int(1, 3) as f64 / 2.0;
        let a = cylinder([0.0; 3], r1, [0.0, 0.0, 1.0], [-16.0, 16.0]);
        let b = cylinder([-16.0, 0.0, 0.0], r2, [1.0, 0.0, 0.0], [0.0, 32.0]);
        let sector = [1, 2, 3, 4][rng.below(4)];
        let signs = geocert::ops::fillet::Sector::from_number(sector)
            .unwrap()
            .signs();
        let (ans, status) = blend(&a, &b, rho, &spec(sector, None, [13, 3]));
        assert_eq!(status, Status::Verified, "{sector}");
        assert_eq!(ans.components.len(), 2);
        for k in &ans.components {
            let sign = k.spine.points[0].xyz[2].signum();
            for (i, &t) in k.grid.t.iter().enumerate() {
                let ti = m(t);
                let (r1i, r2i) = (m(r1) + m(signs[0] * rho), m(r2) + m(signs[1] * rho));
                let v = (r2i.sqr() - r1i.sqr() * ti.sin().sqr()).sqrt() * m(sign);
                let centre = [r1i.clone() * ti.cos(), r1i * ti.sin(), v.clone()];
                let on_a = [m(r1) * ti.cos(), m(r1) * ti.sin(), v];
                let scale = m(r2) / r2i;
                let on_b = [
                    centre[0].clone(),
                    centre[1].clone() * scale.clone(),
                    centre[2].clone() * scale,
                ];
                assert_box_contains(&k.contacts[0][i].xyz_box, &on_a, "contact on A");
                assert_box_contains(&k.contacts[1][i].xyz_box, &on_b, "contact on B");
                assert!(dist(&k.spine.points[i].xyz, &centre) <= k.spine.points[i].bound.unwrap());
            }
            components += 1;
        }
    }
    assert_eq!(components, 120);
}

/// A sphere and a horizontal plane: the centres form the circle of radius
/// `√(R'² − (h' − c_z)²)` at height `h' = h ± ρ` about the sphere's axis; every vertex
/// is within its certified bound of that circle; offsets that miss give `empty`.
#[test]
fn sphere_plane_centres_lie_on_the_closed_form_circle() {
    let mut rng = Rng::new(99);
    let (mut circles, mut empty) = (0, 0);
    for _ in 0..150 {
        let c = [rng.dyadic(), rng.dyadic(), rng.dyadic()];
        let r = 1.0 + rng.int(0, 24) as f64 / 8.0;
        let h = c[2] + r * rng.int(-7, 7) as f64 / 8.0;
        let rho = r * rng.int(1, 6) as f64 / 8.0;
        let (sa, sb) = (rng.coin(), rng.coin());
        let sector = match (sa, sb) {
            (true, true) => 1,
            (true, false) => 2,
            (false, false) => 3,
            (false, true) => 4,
        };
        let signs = [if sa { 1.0 } else { -1.0 }, if sb { 1.0 } else { -1.0 }];
        let (rp, hp) = (r + signs[0] * rho, h + signs[1] * rho);
        let rc2 = rp * rp - (hp - c[2]) * (hp - c[2]);
        if rc2.abs() < 1e-9 {
            continue; // a touching pair: the degenerate test covers it
        }
        let sp = sphere(c, r);
        let pl = plane([0.0, 0.0, h], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]);
        let got = geocert::ops::fillet(
            &sp,
            &pl,
            rho,
            &spec(sector, None, [17, 3]),
            &Options::default(),
        );
        let got = match got {
            Err(e) => {
                assert_eq!(e.kind(), "degenerate_blend", "{e}");
                continue;
            }
            Ok(g) => g,
        };
        let Answer::Blend(b) = got.value else {
            panic!()
        };
        if rc2 < 0.0 {
            assert!(b.components.is_empty());
            assert!(got.complete);
            empty += 1;
            continue;
        }
        assert_eq!(got.status, Status::Verified);
        let rc = (m(rp).sqr() - (m(hp) - m(c[2])).sqr()).sqrt();
        for v in &b.components[0].spine.points {
            let (dx, dy) = (m(v.xyz[0]) - m(c[0]), m(v.xyz[1]) - m(c[1]));
            let radial = (dx.sqr() + dy.sqr()).sqrt() - rc.clone();
            let off = (radial.sqr() + (m(v.xyz[2]) - m(hp)).sqr()).sqrt();
            assert!(
                off.lo_f64() <= v.bound.unwrap(),
                "{} > {:?}",
                off.lo_f64(),
                v.bound
            );
        }
        circles += 1;
    }
    assert!(circles > 40 && empty > 5, "{circles} {empty}");
}

/// Property: over generated faces, radii and sectors, at random `(t, z)` in 256-bit
/// MPFR intervals: `|f − c|² − ρ²` encloses 0 (tightly), the arc's end tangents lie in
/// the faces' tangent planes (`f_z·m`, `f_z·n` enclose 0 at `z = 0`, `1`), and the
/// surface normal `f_t × f_z` is parallel to the face normal along each contact curve
/// (G1).
#[test]
fn fillet_points_lie_at_distance_rho_and_are_g1_with_both_faces() {
    let mut rng = Rng::new(7);
    let mut samples = 0;
    for case in 0..160 {
        let rho = 0.05 + 2.0 * (rng.unit() + 1.0);
        let sector = 1 + rng.below(4) as u8;
        let surfaces = match case % 4 {
            0 => {
                let theta = 0.05 + (std::f64::consts::PI - 0.1) * (rng.unit() + 1.0) / 2.0;
                let a = plane([0.0; 3], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]);
                let b = plane([0.0; 3], [0.0, 1.0, 0.0], [theta.cos(), 0.0, theta.sin()]);
                fillet_surface(&a, &b, rho, sector, Some([-3.0, 3.0]))
            }
            1 => {
                let r = rho * (1.5 + rng.unit().abs() * 4.0);
                let n = [rng.unit() * 0.5, rng.unit() * 0.5, 1.0];
                let a = implicit_plane(n, rng.unit());
                let b = cylinder(
                    [rng.unit(), rng.unit(), -50.0],
                    r,
                    [0.0, 0.0, 1.0],
                    [0.0, 100.0],
                );
                fillet_surface(&a, &b, rho, sector, None)
            }
            2 => {
                let r1 = rho * (1.2 + rng.unit().abs());
                let r2 = r1 + 2.5 * rho + rng.unit().abs();
                let a = cylinder([0.0; 3], r1, [0.0, 0.0, 1.0], [-50.0, 50.0]);
                let b = cylinder(
                    [-50.0, 0.0, rng.unit() * 0.1],
                    r2,
                    [1.0, 0.0, rng.unit() * 0.1],
                    [0.0, 100.0],
                );
                fillet_surface(&a, &b, rho, sector, None)
            }
            _ => {
                let r = rho * (1.5 + rng.unit().abs() * 3.0);
                let a = sphere([rng.unit(), rng.unit(), rng.unit()], r);
                let b = plane(
                    [0.0, 0.0, rng.unit() * 0.3 * r],
                    [1.0, 0.0, 0.0],
                    [0.0, 1.0, 0.0],
                );
                fillet_surface(&a, &b, rho, sector, None)
            }
        };
        for f in &surfaces {
            let [t0, t1] = f.domain().0;
            for _ in 0..4 {
                let t = t0 + (t1 - t0) * (rng.unit() + 1.0) / 2.0;
                let z = (rng.unit() + 1.0) / 2.0;
                let (ti, zi) = (m(t), m(z));
                let st = f.centre.station(&ti);
                if !st.cos_phi.lo_f64().is_finite() || st.centre[0].is_empty() {
                    continue; // t outside where this configuration's closed form is real
                }
                let p = f.jet(&ti, &zi, 0).remove(0);
                let d2 = (0..3)
                    .map(|k| (p[k].clone() - st.centre[k].clone()).sqr())
                    .fold(m(0.0), |a, b| a + b)
                    - m(rho).sqr();
                assert!(
                    d2.contains(0.0) && d2.width() < 1e-60,
                    "case {case}: {d2:?}"
                );
                for (k, tan) in end_tangency(f, &ti).iter().enumerate() {
                    assert!(
                        tan.contains(0.0) && tan.width() < 1e-60,
                        "case {case} end {k}"
                    );
                }
                for (k, zend) in [0.0, 1.0].into_iter().enumerate() {
                    let j = f.jet(&ti, &m(zend), 1);
                    let normal = cross(&j[1], &j[2]);
                    let par = cross(&normal, &st.normal[k]);
                    let scale = norm(&normal).hi_f64().max(1.0);
                    for c in &par {
                        assert!(
                            c.contains(0.0) && c.width() < 1e-60 * scale,
                            "case {case} G1 {k}"
                        );
                    }
                }
                samples += 1;
            }
        }
    }
    assert!(samples > 400, "{samples}");
}

/// §11.4 degenerate cases and bad input: typed errors naming the field.
#[test]
fn degenerate_cases_are_typed_errors() {
    let o = Options::default();
    let ground = plane([0.0; 3], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]);
    let ball = sphere([0.0; 3], 1.0);
    let pipe = cylinder([0.0, 0.0, -5.0], 2.0, [0.0, 0.0, 1.0], [0.0, 10.0]);
    // a radius at or above the curvature radius on the concave side (inside)
    for rho in [1.0, 1.5, 1.0f64.next_up()] {
        let got = geocert::ops::fillet(&ball, &ground, rho, &spec(3, None, [5, 3]), &o);
        assert_eq!(
            error_kind(got),
            ("degenerate_blend".into(), "radius".into())
        );
    }
    for rho in [2.0, 3.0] {
        let got = geocert::ops::fillet(&ground, &pipe, rho, &spec(2, None, [5, 3]), &o);
        assert_eq!(
            error_kind(got),
            ("degenerate_blend".into(), "radius".into())
        );
    }
    // just below: a fillet
    let got = geocert::ops::fillet(
        &ground,
        &pipe,
        2.0f64.next_down(),
        &spec(2, None, [5, 3]),
        &o,
    );
    assert!(got.is_ok());
    // a sphere touching the plane z = 1 from below: the faces are tangent there
    let lid = plane([0.0, 0.0, 1.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]);
    let got = geocert::ops::fillet(&ball, &lid, 0.25, &spec(3, None, [5, 3]), &o);
    assert_eq!(
        error_kind(got),
        ("degenerate_blend".into(), "objects".into())
    );
    // parallel and coincident planes
    for h in [0.0, 1.0] {
        let other = plane([0.0, 0.0, h], [0.0, 1.0, 0.0], [1.0, 0.0, 0.0]);
        let got =
            geocert::ops::fillet(&ground, &other, 0.5, &spec(1, Some([0.0, 1.0]), [5, 3]), &o);
        assert_eq!(
            error_kind(got),
            ("degenerate_blend".into(), "objects".into())
        );
        let got = geocert::ops::chamfer(
            &ground,
            &other,
            [0.5, 0.5],
            &spec(1, Some([0.0, 1.0]), [5, 3]),
            &o,
        );
        assert_eq!(
            error_kind(got),
            ("degenerate_blend".into(), "objects".into())
        );
    }
    // bad input
    let wall = plane([0.0; 3], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]);
    let cases: Vec<(Result<_, _>, (&str, &str))> = vec![
        (
            geocert::ops::fillet(&ground, &wall, -1.0, &spec(3, Some([0.0, 1.0]), [5, 3]), &o),
            ("invalid_value", "radius"),
        ),
        (
            geocert::ops::fillet(
                &ground,
                &wall,
                f64::NAN,
                &spec(3, Some([0.0, 1.0]), [5, 3]),
                &o,
            ),
            ("invalid_value", "radius"),
        ),
        (
            geocert::ops::fillet(&ground, &wall, 1.0, &spec(5, Some([0.0, 1.0]), [5, 3]), &o),
            ("invalid_value", "sector"),
        ),
        (
            geocert::ops::fillet(&ground, &wall, 1.0, &spec(3, None, [5, 3]), &o),
            ("format", "range"),
        ),
        (
            geocert::ops::fillet(&ground, &wall, 1.0, &spec(3, Some([1.0, 0.0]), [5, 3]), &o),
            ("empty_domain", "range"),
        ),
        (
            geocert::ops::fillet(&ground, &wall, 1.0, &spec(3, Some([0.0, 1.0]), [1, 3]), &o),
            ("invalid_value", "grid"),
        ),
        (
            geocert::ops::chamfer(&ground, &pipe, [1.0, 1.0], &spec(3, None, [5, 3]), &o),
            ("unsupported", "objects"),
        ),
        (
            geocert::ops::chamfer(
                &ground,
                &wall,
                [1.0, 0.0],
                &spec(3, Some([0.0, 1.0]), [5, 3]),
                &o,
            ),
            ("invalid_value", "legs[1]"),
        ),
    ];
    for (got, (kind, field)) in cases {
        assert_eq!(error_kind(got), (kind.to_string(), field.to_string()));
    }
    let side_on_face = BlendSpec {
        sector: SectorChoice::Side([0.5, 0.5, 0.0]),
        range: Some([0.0, 1.0]),
        grid: [5, 3],
    };
    let got = geocert::ops::fillet(&ground, &wall, 1.0, &side_on_face, &o);
    assert_eq!(error_kind(got), ("invalid_value".into(), "side".into()));
}

/// The command line: a `fillet` case answers kind `surface` with the spine, contacts
/// and grid; missing fields are format errors naming them.
#[test]
fn cli_cases_answer_and_name_missing_fields() {
    let r = solve(
        r#"{"id": 1, "op": "fillet", "objects": [{"type": "plane", "normal": [0,0,1], "d": 0}, {"type": "cylinder", "origin": [0,0,-5], "radius": 2, "axis": [0,0,1], "height": [0,10]}], "radius": 0.5, "side": [3,0,1], "grid": [5, 3]}"#,
    );
    assert_eq!(r["kind"], "surface", "{r}");
    assert_eq!(r["status"], "verified");
    assert_eq!(r["blend"]["sector"], 1);
    // a closed spine: 5 stations, the first repeated last
    assert_eq!(r["curves"][0]["points"].as_array().unwrap().len(), 6);
    assert_eq!(
        r["blend"]["components"][0]["grid"]["points"][0]
            .as_array()
            .unwrap()
            .len(),
        3
    );
    assert_eq!(
        r["curves"][0]["points"][0]["xyz"],
        serde_json::json!([2.5, 0.0, 0.5])
    );
    let r = solve(
        r#"{"op": "fillet", "objects": [{"type": "plane", "normal": [0,0,1], "d": 0}, {"type": "plane", "normal": [1,0,0], "d": 0}], "sector": 3, "range": [0, 1]}"#,
    );
    assert_eq!(r["error"]["field"], "radius", "{r}");
    let r = solve(
        r#"{"op": "chamfer", "objects": [{"type": "plane", "normal": [0,0,1], "d": 0}, {"type": "plane", "normal": [1,0,0], "d": 0}], "legs": [1, 1], "range": [0, 1]}"#,
    );
    assert_eq!(r["error"]["field"], "sector", "{r}");
    let r = solve(
        r#"{"op": "chamfer", "objects": [{"type": "plane", "normal": [0,0,1], "d": 0}, {"type": "cone", "origin": [0,0,0], "radius": 1, "half_angle": 0.3, "axis": [0,0,1], "height": [0,1]}], "legs": [1, 1], "sector": 3}"#,
    );
    assert_eq!(r["error"]["field"], "objects[1].type", "{r}");
}
