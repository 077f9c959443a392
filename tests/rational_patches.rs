//! Certified answers on rational NURBS patches of spheres, cylinders and tori against
//! independent truths (issue 21, family 3; the polynomial graph is in
//! tests/curved_forms_3d.rs). Each surface is a surface of revolution of a rational
//! quadratic arc about the z axis, its `u` direction the full circle of
//! tests/truth_support/conics.rs (knots at `u = 1, 2, 3`, the angles `kπ/2`):
//!
//! - the sphere of radius `R` about `c`: meridian the half circle from the south pole
//!   to the north pole, net `(0,−1), (1,−1), (1,0), (1,1), (0,1)`, weights
//!   `1, 1, 2, 2, 4`, knots `0,0,0,1,1,2,2,2` (the equator is the knot `v = 1`);
//! - the cylinder: meridian the segment from `z = h₀` to `z = h₁` (degree 1);
//! - the ring torus: meridian the full circle of radius `r` at distance `R` from the
//!   axis.
//!
//! Net point `(i, j)` is `c + (x_j a_i, x_j b_i, z_j)` with weight `wᵢ w'ⱼ`, `(a, b)` the
//! circle's net and `(x, z)` the meridian's; all data dyadic. Truths from the implicit
//! equations in MPFR at 1024 bits; the parameters by the inverse of the rational maps
//! (`s = y/(1 + x)` per quadrant). Every answer must be decided and `complete`, its
//! point boxes — and the surface's parameter boxes — one-to-one with the truths, with
//! strict containment. Lines pass through exact points on the knot lines (the
//! equator, the meridians `u = 1, 2, 3`); every fourth case is scaled by 2^±500 or
//! 2^±300. Cases: `GEOCERT_CURVED_CASES` multiplies the defaults.

mod truth_support;

use geocert::io::CaseResult;
use rug::Float;
use truth_support::conics::{circle_param, dot, magnitude, quadratic, Gen, OFFSETS, WEIGHTS};
use truth_support::*;

/// A surface of revolution about the z axis through `c`: the circle's net in `u`, the
/// meridian `(x_j, z_j)` with weights `w_j` and knots in `v`, as a `nurbs_surface`.
fn revolution(
    c: [f64; 3],
    meridian: &[(f64, f64)],
    w: &[f64],
    knots_v: &[f64],
    degree_v: usize,
) -> String {
    let rows: Vec<String> = meridian
        .iter()
        .map(|&(x, z)| {
            let row: Vec<String> = OFFSETS
                .iter()
                .map(|&(a, b)| nums(&[c[0] + x * a, c[1] + x * b, c[2] + z]))
                .collect();
            format!("[{}]", row.join(","))
        })
        .collect();
    let weights: Vec<String> = w
        .iter()
        .map(|wj| nums(&WEIGHTS.map(|wi| wi * wj)))
        .collect();
    format!(
        r#"{{"type":"nurbs_surface","degree_u":2,"degree_v":{degree_v},"knots_u":{},"knots_v":{},"points":[{}],"weights":[{}]}}"#,
        nums(&truth_support::conics::KNOTS),
        nums(knots_v),
        rows.join(","),
        weights.join(",")
    )
}

fn sphere(c: [f64; 3], r: f64) -> String {
    let m: Vec<(f64, f64)> = [(0.0, -1.0), (1.0, -1.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)]
        .iter()
        .map(|&(x, z)| (x * r, z * r))
        .collect();
    revolution(
        c,
        &m,
        &[1.0, 1.0, 2.0, 2.0, 4.0],
        &[0.0, 0.0, 0.0, 1.0, 1.0, 2.0, 2.0, 2.0],
        2,
    )
}

fn cylinder(c: [f64; 3], r: f64, h: [f64; 2]) -> String {
    revolution(
        c,
        &[(r, h[0]), (r, h[1])],
        &[1.0, 1.0],
        &[0.0, 0.0, 1.0, 1.0],
        1,
    )
}

fn torus(c: [f64; 3], big: f64, small: f64) -> String {
    let m: Vec<(f64, f64)> = OFFSETS
        .iter()
        .map(|&(a, b)| (big + small * a, small * b))
        .collect();
    revolution(c, &m, &WEIGHTS, &truth_support::conics::KNOTS, 2)
}

/// `(x − c)` of a truth point, its distance `ρ` from the axis and `(cos u, sin u)`.
fn around_axis(p: &[Float], c: [f64; 3]) -> ([Float; 3], Float, [Float; 2]) {
    let d: [Float; 3] = std::array::from_fn(|k| Float::with_val(BITS, &p[k] - c[k]));
    let rho = (Float::with_val(BITS, d[0].square_ref()) + Float::with_val(BITS, d[1].square_ref()))
        .sqrt();
    let cs = [
        Float::with_val(BITS, &d[0] / &rho),
        Float::with_val(BITS, &d[1] / &rho),
    ];
    (d, rho, cs)
}

/// Near the seam `u = 0 = 4` of the circle (tests/seams_poles.rs has the seams).
fn near_seam(x: &Float, y: &Float) -> bool {
    *x > 0 && y.clone().abs() < 1e-6
}

/// Where `o + t·d` meets the quadric `(x−c)² + (y−c)² + k(z−c)² = r²` (`k` 1 for the
/// sphere, 0 for the cylinder): the points, in MPFR.
fn line_quadric(o: [f64; 3], d: [f64; 3], c: [f64; 3], r: f64, k: u32) -> Vec<Vec<Float>> {
    let e: Vec<f64> = (0..3).map(|j| o[j] - c[j]).collect(); // exact: dyadic data
    let n = if k == 1 { 3 } else { 2 };
    let a = dot(&d[..n], &d[..n]);
    let b = dot(&d[..n], &e[..n]) * 2u32;
    let cc = dot(&e[..n], &e[..n]) - fl(r) * r;
    quadratic(&a, &b, &cc)
        .into_iter()
        .map(|t| {
            (0..3)
                .map(|j| Float::with_val(BITS, &t * d[j]) + o[j])
                .collect()
        })
        .collect()
}

fn check(
    r: &CaseResult,
    truths: &[Vec<Float>],
    params: Option<(usize, Vec<Vec<Float>>)>,
) -> Result<(), String> {
    if r.complete != Some(true) || !matches!(r.status, "verified" | "exact") {
        return Err(format!("not decided: {} {:?}", r.status, r.reason));
    }
    if truths.is_empty() {
        return if count(r) == 0 {
            Ok(())
        } else {
            Err("points where none are".into())
        };
    }
    let truths = &snap_all(truths.to_vec());
    one_to_one(&point_boxes(r), truths).map_err(|e| format!("points: {e}"))?;
    if let Some((k, ps)) = params {
        one_to_one(&param_boxes(r, k), &snap_all(ps))
            .map_err(|e| format!("parameters of object {k}: {e}"))?;
    }
    Ok(())
}

/// A Pythagorean point of the sphere of radius `5k` (a permutation with signs of
/// `k(3, 4, 0)`: on the equator or on a meridian `u = kπ/2`, both knot lines).
fn knot_point(g: &mut Gen, k: f64) -> [f64; 3] {
    let base = [
        [3.0, 4.0, 0.0],
        [0.0, 3.0, 4.0],
        [4.0, 0.0, -3.0],
        [0.0, -4.0, 3.0],
    ][g.below(4)];
    base.map(|x| x * k)
}

/// A line through `q` (exactly, at `t = step`), direction dyadic.
fn line_at(g: &mut Gen, q: [f64; 3]) -> ([f64; 3], [f64; 3]) {
    let d = loop {
        let d: [f64; 3] = g.vec(-1.0, 1.0, 3);
        if d != [0.0; 3] {
            break d;
        }
    };
    let step = g.dyadic(-1.0, 1.0, 2);
    (std::array::from_fn(|j| q[j] - step * d[j]), d)
}

/// A line with the `range` the front door asks for against a NURBS surface: `|t| ≤ 64`
/// holds every crossing here (`|step| ≤ 1`, the surfaces within `3·2^3` of the
/// origin's scale, `max|dᵢ| ≥ 1/8`; unchanged by the scaling).
fn line_json(o: [f64; 3], d: [f64; 3]) -> String {
    format!(
        r#"{{"type":"line","origin":{},"dir":{},"range":[-64,64]}}"#,
        nums(&o),
        nums(&d)
    )
}

/// The sphere's parameters of a point: `u` on the circle, `v = ρ/(1 − z)` below the
/// equator and `1 + z/(1 + ρ)` above (unit sphere).
fn sphere_params(p: &[Float], c: [f64; 3], r: f64) -> Vec<Float> {
    let (d, rho, cs) = around_axis(p, c);
    let (rho, z) = (rho / r, Float::with_val(BITS, &d[2] / r));
    let v = if z <= 0 {
        rho / (Float::with_val(BITS, 1u32) - z)
    } else {
        z / (rho + 1u32) + 1u32
    };
    vec![circle_param(&cs[0], &cs[1]), v]
}

/// Lines against the NURBS sphere of radius `5k`: through a Pythagorean point on a
/// knot line, or through an inner point; lines passing near the poles (where the
/// parametrisation degenerates) or the seam are left to other families.
#[test]
fn lines_across_a_nurbs_sphere() {
    let mut g = Gen::new(2141);
    let mut fails = Failures::default();
    let (mut tried, mut spent) = (0, 0);
    for i in 0..cases(24) {
        let m = [1.0, 1.0, 1.0, magnitude(g.below(4))][i % 4];
        let k = g.dyadic(0.125, 0.5, 3);
        let c: [f64; 3] = g.vec(-2.0, 2.0, 3);
        let q = if i % 2 == 0 {
            knot_point(&mut g, k)
        } else {
            g.vec(-2.0 * k, 2.0 * k, 5)
        };
        let (o, d) = line_at(&mut g, std::array::from_fn(|j| c[j] + q[j]));
        let (c, r, o, d) = (
            c.map(|x| x * m),
            5.0 * k * m,
            o.map(|x| x * m),
            d.map(|x| x * m),
        );
        let truths = line_quadric(o, d, c, r, 1);
        let bad = truths.iter().any(|p| {
            let (dd, rho, cs) = around_axis(p, c);
            rho < r * 0.05 || near_seam(&cs[0], &cs[1]) || dd[2].is_zero() && truths.len() == 1
        });
        if truths.len() != 2 || bad {
            continue;
        }
        let case = format!(
            r#"{{"id":{i},"op":"intersect","objects":[{},{}]}}"#,
            line_json(o, d),
            sphere(c, r)
        );
        let res = solve(&case);
        let params = truths.iter().map(|p| sphere_params(p, c, r)).collect();
        if budget_spent(&res) {
            // Known limit (tests/README.md): sound, not complete.
            let t = snap_all(truths.clone());
            fails.check(
                sound_but_incomplete(&res, &point_boxes(&res), &t),
                &case,
                &res,
            );
            spent += 1;
        } else {
            fails.check(check(&res, &truths, Some((1, params))), &case, &res);
        }
        tried += 1;
    }
    fails.finish("lines_across_a_nurbs_sphere");
    assert!(tried * 4 >= cases(24), "{tried}");
    // Since the f64-first search (`ops::certified::pieces`, issue 21) every line through
    // a knot point is decided on f64 intervals, proven across the knot: none may spend
    // its budget (192 cases with GEOCERT_CURVED_CASES=8 at the time of writing).
    assert_eq!(spent, 0, "{spent} of {tried} spent their box budget");
}

/// Lines against a NURBS cylinder of radius `5k`, height `[h₀, h₁]`: through a
/// Pythagorean point on a knot meridian, or an inner point; crossings beyond the
/// height are not solutions.
#[test]
fn lines_across_a_nurbs_cylinder() {
    let mut g = Gen::new(2142);
    let mut fails = Failures::default();
    let mut tried = 0;
    for i in 0..cases(24) {
        let m = [1.0, 1.0, 1.0, magnitude(g.below(4))][i % 4];
        let k = g.dyadic(0.125, 0.5, 3);
        let c: [f64; 3] = g.vec(-2.0, 2.0, 3);
        let h = [g.dyadic(-3.0, -1.0, 3), g.dyadic(1.0, 3.0, 3)];
        let q = if i % 2 == 0 {
            let [x, y] = [[3.0, 4.0], [4.0, -3.0], [-5.0, 0.0], [0.0, 5.0]][g.below(4)];
            [x * k, y * k, g.dyadic(-0.5, 0.5, 3)]
        } else {
            let mut q: [f64; 3] = g.vec(-2.0 * k, 2.0 * k, 5);
            q[2] = g.dyadic(-0.5, 0.5, 4);
            q
        };
        let (o, d) = line_at(&mut g, std::array::from_fn(|j| c[j] + q[j]));
        if d[0] == 0.0 && d[1] == 0.0 {
            continue; // a line along the axis: its own family
        }
        let (c, r, o, d, h) = (
            c.map(|x| x * m),
            5.0 * k * m,
            o.map(|x| x * m),
            d.map(|x| x * m),
            h.map(|x| x * m),
        );
        let truths: Vec<Vec<Float>> = line_quadric(o, d, c, r, 0)
            .into_iter()
            .filter(|p| {
                let z = Float::with_val(BITS, &p[2] - c[2]);
                z >= h[0] && z <= h[1]
            })
            .collect();
        let bad = truths.iter().any(|p| {
            let (dd, _, cs) = around_axis(p, c);
            let z = dd[2].to_f64();
            near_seam(&cs[0], &cs[1]) || (z - h[0]).abs() < 1e-6 * r || (z - h[1]).abs() < 1e-6 * r
        });
        if bad || line_quadric(o, d, c, r, 0).len() == 1 {
            continue;
        }
        let case = format!(
            r#"{{"id":{i},"op":"intersect","objects":[{},{}]}}"#,
            line_json(o, d),
            cylinder(c, r, h)
        );
        let res = solve(&case);
        let params = truths
            .iter()
            .map(|p| {
                let (dd, _, cs) = around_axis(p, c);
                let v = Float::with_val(BITS, &dd[2] - h[0]) / (h[1] - h[0]);
                vec![circle_param(&cs[0], &cs[1]), v]
            })
            .collect();
        fails.check(check(&res, &truths, Some((1, params))), &case, &res);
        tried += 1;
    }
    fails.finish("lines_across_a_nurbs_cylinder");
    assert!(tried * 4 >= cases(24), "{tried}");
}

/// Lines parallel to the axis against a NURBS ring torus (`R`, `r`): at distance `ρ`
/// from the axis they meet it at `z = ±√(r² − (ρ − R)²)`. A third pass through the
/// knot meridians (`x = 0` or `y = 0`).
#[test]
fn axial_lines_across_a_nurbs_torus() {
    let mut g = Gen::new(2143);
    let mut fails = Failures::default();
    let mut tried = 0;
    for i in 0..cases(30) {
        let m = [1.0, 1.0, 1.0, magnitude(g.below(4))][i % 4];
        let c: [f64; 3] = g.vec(-2.0, 2.0, 3);
        let small = g.dyadic(0.25, 1.0, 3);
        let big = small + g.dyadic(0.25, 2.0, 3);
        let rho = g.dyadic(big - 0.9 * small, big + 0.9 * small, 6);
        let xy = if i % 3 == 0 {
            [[0.0, rho], [-rho, 0.0], [0.0, -rho]][g.below(3)]
        } else {
            let t = g.dyadic(-0.9, 0.9, 5);
            let y = rho * t;
            [-(rho * rho - y * y).sqrt(), y] // x not exact: the truth uses the double
        };
        let o = [c[0] + xy[0], c[1] + xy[1], c[2]];
        let (c, o, big, small) = (c.map(|x| x * m), o.map(|x| x * m), big * m, small * m);
        let ex = Float::with_val(BITS, fl(o[0]) - c[0]);
        let ey = Float::with_val(BITS, fl(o[1]) - c[1]);
        let rho = (Float::with_val(BITS, ex.square_ref()) + Float::with_val(BITS, ey.square_ref()))
            .sqrt();
        let off = Float::with_val(BITS, &rho - big);
        let zz = fl(small) * small - Float::with_val(BITS, off.square_ref());
        let z = zz.sqrt();
        let cs = [
            Float::with_val(BITS, &ex / &rho),
            Float::with_val(BITS, &ey / &rho),
        ];
        if near_seam(&cs[0], &cs[1]) {
            continue;
        }
        let truths: Vec<Vec<Float>> = [1i32, -1]
            .iter()
            .map(|&s| vec![fl(o[0]), fl(o[1]), Float::with_val(BITS, &z * s) + c[2]])
            .collect();
        let params = [1i32, -1]
            .iter()
            .map(|&s| {
                let (cv, sv) = (
                    Float::with_val(BITS, &off / small),
                    Float::with_val(BITS, &z * s) / small,
                );
                vec![circle_param(&cs[0], &cs[1]), circle_param(&cv, &sv)]
            })
            .collect::<Vec<_>>();
        if params.iter().any(|p: &Vec<Float>| {
            let v = p[1].to_f64();
            !(1e-6..=4.0 - 1e-6).contains(&v)
        }) {
            continue;
        }
        if m < 1e-100 && !runs(Some("nurbs_torus_axial_lines_tiny")) {
            continue;
        }
        let case = format!(
            r#"{{"id":{i},"op":"intersect","objects":[{},{}]}}"#,
            line_json(o, [0.0, 0.0, m]),
            torus(c, big, small)
        );
        let res = solve(&case);
        fails.check(check(&res, &truths, Some((1, params))), &case, &res);
        tried += 1;
    }
    fails.finish("axial_lines_across_a_nurbs_torus");
    assert!(tried * 2 >= cases(30), "{tried}");
}

/// Points projected onto the NURBS sphere restricted to `v ∈ [1/4, 7/4]` (the poles,
/// where the parametrisation degenerates, cut off): the two feet `c ± R(p − c)/|p − c|`
/// both inside, and the nearest.
#[test]
fn projections_onto_a_nurbs_sphere_zone() {
    if !runs(Some("nurbs_sphere_zone_projection")) {
        return;
    }
    let mut g = Gen::new(2144);
    let mut fails = Failures::default();
    let mut tried = 0;
    for i in 0..cases(30) {
        let m = [1.0, 1.0, 1.0, magnitude(g.below(4))][i % 4];
        let c: [f64; 3] = g.vec(-2.0, 2.0, 3);
        let r = g.dyadic(0.5, 2.0, 3);
        let q = if i % 3 == 0 {
            let s = g.dyadic(0.25, 3.0, 3);
            [[0.0, s, 0.0], [-s, 0.0, 0.0], [0.0, -s, 0.0]][g.below(3)]
        } else {
            let mut q: [f64; 3] = g.vec(-3.0, 3.0, 4);
            q[2] = g.dyadic(-0.25, 0.25, 4) * (q[0].abs() + q[1].abs());
            q
        };
        let p: [f64; 3] = std::array::from_fn(|j| (c[j] + q[j]) * m);
        let (c, r) = (c.map(|x| x * m), r * m);
        let pc: Vec<f64> = (0..3).map(|j| p[j] - c[j]).collect();
        let len = dot(&pc, &pc).sqrt();
        if len < r * 1e-3 {
            continue;
        }
        let feet: Vec<Vec<Float>> = [1i32, -1]
            .iter()
            .map(|&s| (0..3).map(|j| fl(pc[j]) * r * s / &len + c[j]).collect())
            .collect();
        let params: Vec<Vec<Float>> = feet.iter().map(|f| sphere_params(f, c, r)).collect();
        let inside = params.iter().all(|p| {
            let (u, v) = (p[0].to_f64(), p[1].to_f64());
            v > 0.3 && v < 1.7 && u > 1e-6 && u < 4.0 - 1e-6
        });
        if !inside {
            continue;
        }
        let mut onto = sphere(c, r);
        onto.insert_str(onto.len() - 1, r#","domain":[[0,4],[0.25,1.75]]"#);
        for nearest in [false, true] {
            let case = format!(
                r#"{{"id":{i},"op":"project","nearest":{nearest},"point":{},"onto":{onto}}}"#,
                nums(&p)
            );
            let res = solve(&case);
            let k = if nearest { 1 } else { 2 };
            fails.check(
                check(&res, &feet[..k], Some((0, params[..k].to_vec()))),
                &case,
                &res,
            );
        }
        tried += 1;
    }
    fails.finish("projections_onto_a_nurbs_sphere_zone");
    assert!(tried * 2 >= cases(30), "{tried}");
}
