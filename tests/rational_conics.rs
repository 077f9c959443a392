//! Certified answers on rational Bézier and NURBS forms of ellipses and circles against
//! independent truths (issue 21, family 3; the NURBS circle against lines and points in
//! the plane is in tests/curved_forms.rs). The forms are in tests/truth_support/conics.rs:
//! the full ellipse `c + A cos θ + B sin θ` as a NURBS of degree 2 with knots at the
//! quadrants, its first quarter as a rational quadratic Bézier, all data dyadic.
//!
//! Families (each at random places, through the knots and the ends of the patch, and
//! every fourth case scaled by 2^±500 or 2^±300, about 1e±150):
//!
//! - a NURBS ellipse in the plane against lines (a `line2` with a `range`);
//! - the quarter Bézier ellipse in the plane against lines (roots at its ends);
//! - the quarter Bézier ellipse in space against planes (roots at its ends);
//! - a NURBS circle in space against spheres (roots on the knots);
//! - two NURBS circles in the plane, and a NURBS circle against a `circle2`;
//! - points projected onto a NURBS circle in space (all feet, and `nearest`).
//!
//! Every truth comes from the implicit equations (the inverse of the affine map, the
//! circle–circle and line–conic closed forms) in MPFR at 1024 bits; the parameters by
//! the inverse of the rational parametrisation. Every answer must be decided and
//! `complete`, its point boxes and parameter boxes one-to-one with the truths, with
//! strict containment. Cases: `GEOCERT_CURVED_CASES` multiplies the defaults.

mod truth_support;

use geocert::io::CaseResult;
use rug::Float;
use truth_support::conics::{circle_param, dot, line_ellipse, magnitude, trig_solve, Ellipse, Gen};
use truth_support::*;

/// A complete, decided points answer against truths: point boxes one-to-one and, per
/// listed object `k`, its parameter boxes one-to-one with `params[k]`.
fn check(
    r: &CaseResult,
    truths: &[Vec<Float>],
    params: &[(usize, Vec<Vec<Float>>)],
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
    for (k, ps) in params {
        one_to_one(&param_boxes(r, *k), &snap_all(ps.clone()))
            .map_err(|e| format!("parameters of object {k}: {e}"))?;
    }
    Ok(())
}

/// A random ellipse in the plane: dyadic centre and axes, not too flat.
fn ellipse2(g: &mut Gen) -> Ellipse<2> {
    loop {
        let e = Ellipse {
            c: g.vec(-2.0, 2.0, 3),
            a: g.vec(-2.0, 2.0, 3),
            b: g.vec(-2.0, 2.0, 3),
        };
        let det = e.a[0] * e.b[1] - e.a[1] * e.b[0];
        let (la, lb) = (dot(&e.a, &e.a).to_f64(), dot(&e.b, &e.b).to_f64());
        if det.abs() >= 0.3 * (la * lb).sqrt() && la >= 0.25 && lb >= 0.25 {
            return e;
        }
    }
}

/// Near the seam `θ = 0` (tested in tests/seams_poles.rs): `sin θ` small, `cos θ > 0`.
fn near_seam(x: &Float, y: &Float) -> bool {
    *x > 0 && y.clone().abs() < 1e-6
}

/// A line through the ellipse: through an inner point in a random direction, or
/// (every third case) through a knot point `θ = kπ/2`, `k = 1, 2, 3`, exactly or one
/// ulp beside it.
fn line_through(g: &mut Gen, e: &Ellipse<2>, i: usize) -> ([f64; 2], [f64; 2]) {
    let d = loop {
        let d: [f64; 2] = g.vec(-1.0, 1.0, 4);
        if d != [0.0, 0.0] {
            break d;
        }
    };
    let p = if i.is_multiple_of(3) {
        let (p, q) = [(0.0, 1.0), (-1.0, 0.0), (0.0, -1.0)][g.below(3)];
        let mut k = e.net_point(p, q);
        if g.below(3) == 0 {
            k[0] = f64::from_bits(k[0].to_bits() + 1);
        }
        k
    } else {
        let (p, q) = (g.dyadic(-0.6, 0.6, 4), g.dyadic(-0.6, 0.6, 4));
        e.net_point(p, q)
    };
    // the origin a dyadic step back along d (exact), so the root is at s = step
    let step = g.dyadic(-2.0, 2.0, 2);
    ([p[0] - step * d[0], p[1] - step * d[1]], d)
}

#[test]
fn lines_across_a_nurbs_ellipse() {
    let mut g = Gen::new(2131);
    let mut fails = Failures::default();
    let mut tried = 0;
    for i in 0..cases(45) {
        let m = [1.0, 1.0, 1.0, magnitude(g.below(4))][i % 4];
        let e0 = ellipse2(&mut g);
        let (o, d) = line_through(&mut g, &e0, i);
        let (e, o, d) = (e0.scaled(m), o.map(|x| x * m), d.map(|x| x * m));
        let truths = line_ellipse(&e, o, d);
        if truths.iter().any(|t| near_seam(&t[1], &t[2])) {
            continue;
        }
        // every crossing has |s| ≤ 2 + 6/max|dᵢ| (unchanged by the scaling)
        let reach = 2.0 + 8.0 / (d[0].abs().max(d[1].abs()) / m);
        let case = format!(
            r#"{{"id":{i},"op":"intersect","objects":[{},{{"type":"line2","origin":{},"dir":{},"range":{}}}]}}"#,
            e.nurbs(),
            nums(&o),
            nums(&d),
            nums(&[-reach, reach])
        );
        let r = solve(&case);
        let pts: Vec<Vec<Float>> = truths.iter().map(|t| e.at(&t[1], &t[2])).collect();
        let tc = truths
            .iter()
            .map(|t| vec![circle_param(&t[1], &t[2])])
            .collect();
        let tl = truths.iter().map(|t| vec![t[0].clone()]).collect();
        fails.check(check(&r, &pts, &[(0, tc), (1, tl)]), &case, &r);
        tried += 1;
    }
    fails.finish("lines_across_a_nurbs_ellipse");
    assert!(tried * 2 >= cases(45), "{tried}");
}

/// The quarter Bézier ellipse against lines, including lines through its two ends
/// (roots at the patch boundary `s = 0` and `s = 1`).
#[test]
fn lines_across_a_quarter_bezier_ellipse() {
    let mut g = Gen::new(2132);
    let mut fails = Failures::default();
    let mut ends = 0;
    for i in 0..cases(90) {
        let m = [1.0, 1.0, 1.0, magnitude(g.below(4))][i % 4];
        let e0 = ellipse2(&mut g);
        let (o, d) = if i % 3 == 0 {
            let d: [f64; 2] = g.vec(-1.0, 1.0, 4);
            let p = match g.below(2) {
                0 => e0.net_point(1.0, 0.0),
                _ => e0.net_point(0.0, 1.0),
            };
            let step = g.dyadic(-2.0, 2.0, 2);
            ([p[0] - step * d[0], p[1] - step * d[1]], d)
        } else {
            line_through(&mut g, &e0, 1)
        };
        if d == [0.0, 0.0] {
            continue;
        }
        let (e, o, d) = (e0.scaled(m), o.map(|x| x * m), d.map(|x| x * m));
        let truths: Vec<[Float; 3]> = line_ellipse(&e, o, d)
            .into_iter()
            .map(|t| t.map(|x| snap(&x)))
            .filter(|t| t[1] >= 0 && t[2] >= 0)
            .collect();
        ends += truths.iter().filter(|t| t[1] == 0 || t[2] == 0).count();
        let case = format!(
            r#"{{"id":{i},"op":"intersect","objects":[{},{{"type":"line2","origin":{},"dir":{}}}]}}"#,
            e.quarter(),
            nums(&o),
            nums(&d),
        );
        let r = solve(&case);
        let pts: Vec<Vec<Float>> = truths.iter().map(|t| e.at(&t[1], &t[2])).collect();
        let tc = truths
            .iter()
            .map(|t| vec![circle_param(&t[1], &t[2])])
            .collect();
        let tl = truths.iter().map(|t| vec![t[0].clone()]).collect();
        fails.check(check(&r, &pts, &[(0, tc), (1, tl)]), &case, &r);
    }
    fails.finish("lines_across_a_quarter_bezier_ellipse");
    assert!(ends >= cases(90) / 4, "{ends} roots at the ends");
}

/// A random ellipse in space: dyadic centre and axes.
fn ellipse3(g: &mut Gen) -> Ellipse<3> {
    loop {
        let e = Ellipse {
            c: g.vec(-2.0, 2.0, 3),
            a: g.vec(-2.0, 2.0, 3),
            b: g.vec(-2.0, 2.0, 3),
        };
        let (la, lb, ab) = (
            dot(&e.a, &e.a).to_f64(),
            dot(&e.b, &e.b).to_f64(),
            dot(&e.a, &e.b).to_f64(),
        );
        if la >= 0.25 && lb >= 0.25 && ab * ab <= 0.8 * la * lb {
            return e;
        }
    }
}

/// The quarter Bézier ellipse in space against planes `n·x + d = 0`, a third of them
/// through an end (`α cos θ + β sin θ = γ`, `α = n·A`, `β = n·B`, `γ = −d − n·c`).
#[test]
fn planes_across_a_quarter_bezier_ellipse_in_space() {
    let mut g = Gen::new(2133);
    let mut fails = Failures::default();
    let mut found = 0;
    for i in 0..cases(90) {
        let m = [1.0, 1.0, 1.0, magnitude(g.below(4))][i % 4];
        let e0 = ellipse3(&mut g);
        let n: [f64; 3] = g.vec(-2.0, 2.0, 3);
        if n == [0.0; 3] {
            continue;
        }
        let through = match i % 3 {
            0 => e0.net_point(if g.below(2) == 0 { 1.0 } else { 0.0 }, 0.0),
            _ => e0.net_point(g.dyadic(0.0, 1.0, 3), g.dyadic(0.0, 1.0, 3)),
        };
        let through = if i % 3 == 0 && g.below(2) == 0 {
            e0.net_point(0.0, 1.0)
        } else {
            through
        };
        let d0 = -dot(&n, &through).to_f64(); // exact: few dyadic bits
        let (e, d) = (e0.scaled(m), d0 * m);
        let alpha = dot(&n, &e.a);
        let beta = dot(&n, &e.b);
        let gamma = -dot(&n, &e.c) - d;
        let truths: Vec<[Float; 2]> = trig_solve(&alpha, &beta, &gamma)
            .into_iter()
            .map(|t| t.map(|x| snap(&x)))
            .filter(|[x, y]| *x >= 0 && *y >= 0)
            .collect();
        found += truths.len();
        let case = format!(
            r#"{{"id":{i},"op":"intersect","objects":[{},{{"type":"plane","normal":{},"d":{}}}]}}"#,
            e.quarter(),
            nums(&n),
            num(d)
        );
        let r = solve(&case);
        let pts: Vec<Vec<Float>> = truths.iter().map(|[x, y]| e.at(x, y)).collect();
        let tc = truths
            .iter()
            .map(|[x, y]| vec![circle_param(x, y)])
            .collect();
        fails.check(check(&r, &pts, &[(0, tc)]), &case, &r);
    }
    fails.finish("planes_across_a_quarter_bezier_ellipse_in_space");
    assert!(found >= cases(90) / 2, "{found}");
}

/// A circle of radius `5k` in space with dyadic data: `A = k(3, 4, 0)` (turned) or
/// `k(5, 0, 0)`, and `B` either `k(−4, 3, 0)` (`k(0, 5, 0)`) or `k(0, 0, 5)`,
/// coordinates permuted.
fn circle3(g: &mut Gen, turned: bool) -> (Ellipse<3>, f64) {
    let k = g.dyadic(0.125, 0.5, 4);
    let a = if turned {
        [3.0 * k, 4.0 * k, 0.0]
    } else {
        [5.0 * k, 0.0, 0.0]
    };
    let b = match (g.below(2), turned) {
        (0, true) => [-4.0 * k, 3.0 * k, 0.0],
        (0, false) => [0.0, 5.0 * k, 0.0],
        _ => [0.0, 0.0, 5.0 * k],
    };
    let p = [[0, 1, 2], [1, 2, 0], [2, 0, 1]][g.below(3)];
    let perm = |v: [f64; 3]| [v[p[0]], v[p[1]], v[p[2]]];
    (
        Ellipse {
            c: g.vec(-2.0, 2.0, 3),
            a: perm(a),
            b: perm(b),
        },
        5.0 * k,
    )
}

/// A NURBS circle in space against spheres: `|c + A cos θ + B sin θ − s|² = R²` is
/// `2A·(c − s) cos θ + 2B·(c − s) sin θ = R² − |c − s|² − ρ²`. A third of the spheres
/// pass through a knot point (`θ = π/2, π, 3π/2`): centre `knot − v`, radius `|v|`
/// with `v` a Pythagorean vector.
#[test]
fn nurbs_circles_in_space_against_spheres() {
    let mut g = Gen::new(2134);
    let mut fails = Failures::default();
    let (mut tried, mut spent) = (0, 0);
    for i in 0..cases(45) {
        let m = [1.0, 1.0, 1.0, magnitude(g.below(4))][i % 4];
        let (e0, rho0) = circle3(&mut g, true);
        let (s0, r0) = if i % 3 == 0 {
            let (p, q) = [(0.0, 1.0), (-1.0, 0.0), (0.0, -1.0)][g.below(3)];
            let knot = e0.net_point(p, q);
            let k = g.dyadic(0.125, 0.5, 3);
            let which = g.below(3);
            let v = [
                [3.0 * k, 0.0, 4.0 * k],
                [0.0, 4.0 * k, 3.0 * k],
                [4.0 * k, 3.0 * k, 0.0],
            ][which];
            ([knot[0] - v[0], knot[1] - v[1], knot[2] - v[2]], 5.0 * k)
        } else {
            (g.vec(-2.0, 2.0, 3), g.dyadic(0.5, 3.0, 4))
        };
        let (e, s, r, rho) = (e0.scaled(m), s0.map(|x| x * m), r0 * m, rho0 * m);
        let cs: Vec<f64> = (0..3).map(|j| e.c[j] - s[j]).collect(); // exact: dyadic
        let alpha = dot(&e.a, &cs) * 2u32;
        let beta = dot(&e.b, &cs) * 2u32;
        let gamma = fl(r) * r - dot(&cs, &cs) - fl(rho) * rho;
        let truths = trig_solve(&alpha, &beta, &gamma);
        if truths.len() == 1 || truths.iter().any(|[x, y]| near_seam(x, y)) {
            continue; // tangency and the seam have their own families
        }
        let case = format!(
            r#"{{"id":{i},"op":"intersect","objects":[{},{{"type":"sphere","center":{},"radius":{}}}]}}"#,
            e.nurbs(),
            nums(&s),
            num(r)
        );
        let res = solve(&case);
        let pts: Vec<Vec<Float>> = truths.iter().map(|[x, y]| e.at(x, y)).collect();
        let tc = truths
            .iter()
            .map(|[x, y]| vec![circle_param(x, y)])
            .collect();
        if incomplete_at_a_knot(&res) {
            // Known limit (tests/README.md): a root at a knot that is also on the
            // sphere's seam, at 2^±500, is left undecided (or a span's search spends its
            // budget); what the answer reports must still be right.
            fails.check(
                sound_but_incomplete(&res, &point_boxes(&res), &snap_all(pts)),
                &case,
                &res,
            );
            spent += 1;
        } else {
            fails.check(check(&res, &pts, &[(0, tc)]), &case, &res);
        }
        tried += 1;
    }
    fails.finish("nurbs_circles_in_space_against_spheres");
    assert!(tried * 2 >= cases(45), "{tried}");
    eprintln!("nurbs circles against spheres: {spent} of {tried} incomplete at a knot");
    assert!(
        spent * 3 <= tried,
        "{spent} of {tried} incomplete at a knot"
    );
}

/// The crossings of the circles `|p − c₁| = r₁`, `|p − c₂| = r₂` (closed form).
fn circle_circle(c1: [f64; 2], r1: f64, c2: [f64; 2], r2: f64) -> Vec<Vec<Float>> {
    let d = [fl(c2[0]) - c1[0], fl(c2[1]) - c1[1]];
    let dd = Float::with_val(BITS, d[0].square_ref()) + Float::with_val(BITS, d[1].square_ref());
    let a = (fl(r1) * r1 - fl(r2) * r2 + &dd) / Float::with_val(BITS, &dd * 2u32);
    // the foot c₁ + a·d, and h² = r₁²/|d|² − a² (in units of |d|)
    let h2 = fl(r1) * r1 / &dd - Float::with_val(BITS, a.square_ref());
    if h2 <= 0 {
        return Vec::new();
    }
    let h = h2.sqrt();
    [1i32, -1]
        .iter()
        .map(|&s| {
            let hs = Float::with_val(BITS, &h * s);
            vec![
                Float::with_val(BITS, &a * &d[0]) - Float::with_val(BITS, &hs * &d[1]) + c1[0],
                Float::with_val(BITS, &a * &d[1]) + Float::with_val(BITS, &hs * &d[0]) + c1[1],
            ]
        })
        .collect()
}

/// `(cos, sin)` of a point of the circle about `c` of radius `r`.
fn unit_of(p: &[Float], c: [f64; 2], r: f64) -> [Float; 2] {
    [
        Float::with_val(BITS, &p[0] - c[0]) / r,
        Float::with_val(BITS, &p[1] - c[1]) / r,
    ]
}

/// Two NURBS circles in the plane, and a NURBS circle against an analytic `circle2`
/// (its parameter the angle in `[0, 2π)`). A third of the second circles pass through
/// a knot point of the first (centre `knot − v`, radius `|v|`, `v` Pythagorean).
#[test]
fn nurbs_circles_in_the_plane() {
    let mut g = Gen::new(2135);
    let mut fails = Failures::default();
    let mut tried = 0;
    for i in 0..cases(45) {
        let m = [1.0, 1.0, 1.0, magnitude(g.below(4))][i % 4];
        let (c1, r1) = (g.vec(-2.0, 2.0, 3), g.dyadic(0.5, 2.0, 3));
        let (c2, r2) = if i % 3 == 0 {
            let (p, q) = [(0.0, 1.0), (-1.0, 0.0), (0.0, -1.0)][g.below(3)];
            let knot = [c1[0] + p * r1, c1[1] + q * r1];
            let k = g.dyadic(0.125, 0.375, 3);
            let v = [[3.0 * k, 4.0 * k], [-4.0 * k, 3.0 * k], [4.0 * k, -3.0 * k]][g.below(3)];
            ([knot[0] - v[0], knot[1] - v[1]], 5.0 * k)
        } else {
            (g.vec(-2.0, 2.0, 3), g.dyadic(0.5, 2.0, 3))
        };
        let (c1, r1, c2, r2) = (c1.map(|x| x * m), r1 * m, c2.map(|x| x * m), r2 * m);
        let truths = circle_circle(c1, r1, c2, r2);
        let u1: Vec<[Float; 2]> = truths.iter().map(|p| unit_of(p, c1, r1)).collect();
        let u2: Vec<[Float; 2]> = truths.iter().map(|p| unit_of(p, c2, r2)).collect();
        if u1.iter().chain(&u2).any(|[x, y]| near_seam(x, y)) {
            continue;
        }
        let circle = |c: [f64; 2], r: f64| {
            Ellipse {
                c,
                a: [r, 0.0],
                b: [0.0, r],
            }
            .nurbs()
        };
        let second = if i % 2 == 0 {
            circle(c2, r2)
        } else {
            format!(
                r#"{{"type":"circle2","center":{},"radius":{}}}"#,
                nums(&c2),
                num(r2)
            )
        };
        let case = format!(
            r#"{{"id":{i},"op":"intersect","objects":[{},{second}]}}"#,
            circle(c1, r1)
        );
        let res = solve(&case);
        let p1 = u1.iter().map(|[x, y]| vec![circle_param(x, y)]).collect();
        let p2 = u2
            .iter()
            .map(|[x, y]| {
                if i % 2 == 0 {
                    vec![circle_param(x, y)]
                } else {
                    let t = Float::with_val(BITS, y.atan2_ref(x));
                    let two_pi = Float::with_val(BITS, rug::float::Constant::Pi) * 2u32;
                    vec![if t < 0 { t + two_pi } else { t }]
                }
            })
            .collect();
        fails.check(check(&res, &truths, &[(0, p1), (1, p2)]), &case, &res);
        tried += 1;
    }
    fails.finish("nurbs_circles_in_the_plane");
    assert!(tried * 2 >= cases(45), "{tried}");
}

/// Points projected onto a NURBS circle in space: the feet are `c ± ρ w/|w|`, `w` the
/// part of `p − c` in the circle's plane; the nearest is `+`. A quarter of the points
/// lie in the plane through the axis and a knot point (both feet on knots).
#[test]
fn projections_onto_a_nurbs_circle_in_space() {
    let mut g = Gen::new(2136);
    let mut fails = Failures::default();
    let mut tried = 0;
    for i in 0..cases(60) {
        let m = [1.0, 1.0, 1.0, magnitude(g.below(4))][i % 4];
        let turned = i % 2 == 1;
        let (e0, rho0) = circle3(&mut g, turned);
        let (u, v) = if i % 4 == 0 {
            [(0.0, 1.0), (-1.0, 0.0), (0.0, -1.0)][g.below(3)]
        } else {
            (g.dyadic(-2.0, 2.0, 4), g.dyadic(-2.0, 2.0, 4))
        };
        let k = g.dyadic(0.25, 2.0, 3);
        let h = g.dyadic(-2.0, 2.0, 3);
        // p = c + k(uA + vB) + h·N, N = A × B / ρ² (dyadic: ρ² = 25k'²... use A × B itself)
        let n = {
            let (a, b) = (e0.a, e0.b);
            [
                a[1] * b[2] - a[2] * b[1],
                a[2] * b[0] - a[0] * b[2],
                a[0] * b[1] - a[1] * b[0],
            ]
        };
        let p0: [f64; 3] =
            std::array::from_fn(|j| e0.c[j] + k * (u * e0.a[j] + v * e0.b[j]) + h * n[j]);
        let (e, p, rho) = (e0.scaled(m), p0.map(|x| x * m), rho0 * m);
        let pc: Vec<f64> = (0..3).map(|j| p[j] - e.c[j]).collect(); // exact
        let (x, y) = (dot(&e.a, &pc) / rho, dot(&e.b, &pc) / rho);
        let len =
            (Float::with_val(BITS, x.square_ref()) + Float::with_val(BITS, y.square_ref())).sqrt();
        if len < rho * 1e-3 {
            continue;
        }
        let feet: Vec<[Float; 2]> = [1i32, -1]
            .iter()
            .map(|&s| {
                [
                    Float::with_val(BITS, &x * s) / &len,
                    Float::with_val(BITS, &y * s) / &len,
                ]
            })
            .collect();
        if feet.iter().any(|[x, y]| near_seam(x, y)) {
            continue;
        }
        let pts: Vec<Vec<Float>> = feet.iter().map(|[x, y]| e.at(x, y)).collect();
        let params: Vec<Vec<Float>> = feet.iter().map(|[x, y]| vec![circle_param(x, y)]).collect();
        for nearest in [false, true] {
            let case = format!(
                r#"{{"id":{i},"op":"project","nearest":{nearest},"point":{},"onto":{}}}"#,
                nums(&p),
                e.nurbs()
            );
            let res = solve(&case);
            let k = if nearest { 1 } else { 2 };
            fails.check(
                check(&res, &pts[..k], &[(0, params[..k].to_vec())]),
                &case,
                &res,
            );
        }
        tried += 1;
    }
    fails.finish("projections_onto_a_nurbs_circle_in_space");
    assert!(tried * 5 >= cases(60), "{tried}");
}
