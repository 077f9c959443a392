//! The motion surfaces of the case format (issue 16: `revolution`, `extrusion`,
//! `ruled`) read and answered through the front door, against independent truths:
//!
//! - the revolution of a segment parallel to the axis is a cylinder, of a slanted
//!   segment a cone frustum; the extrusion of a circle is a cylinder piece; the ruled
//!   surface between two coaxial circles is a cylinder or a cone frustum. A line meets
//!   each where the closed-form quadratic of the circular cylinder / cone says
//!   (`x² + y² = ρ(z)²`, solved in MPFR at 1024 bits, kept where `z` lies in the piece);
//! - the revolution of a circle is a torus: the crossings are the roots of the quartic
//!   `(|p|² + R² − r²)² = 4R²(x² + y²)` along the line, bracketed by sign changes on a
//!   fine MPFR grid and bisected to 1024 bits, and the answer is compared with the
//!   library's own `torus`;
//! - projections onto the cylinder by revolution: the nearest point in closed form.
//!
//! Every answer must be decided and `complete`, its point boxes one-to-one with the
//! truths (strict containment). Bad input: typed errors naming the field.

mod truth_support;

use geocert::io::objects::parse_object;
use geocert::io::CaseResult;
use geocert::GeomError;
use rug::Float;
use truth_support::conics::{dot, quadratic, Gen};
use truth_support::*;

/// `o + t·d` at the parameters `ts`, in MPFR.
fn points(o: [f64; 3], d: [f64; 3], ts: &[Float]) -> Vec<Vec<Float>> {
    ts.iter()
        .map(|t| {
            (0..3)
                .map(|j| Float::with_val(BITS, t * d[j]) + o[j])
                .collect()
        })
        .collect()
}

/// Where `o + t·d` meets `x² + y² = (r₀ + k z)²` with `0 ≤ z ≤ h` (the cone frustum of
/// radius `r₀` at `z = 0`, slope `k`; `k = 0` the cylinder); `None` when a crossing of
/// the whole quadric lies within `1e-9` of an end circle (left to the end families).
fn line_frustum(o: [f64; 3], d: [f64; 3], r0: f64, k: f64, h: f64) -> Option<Vec<Vec<Float>>> {
    // ρ(t) = r₀ + k(o_z + t d_z) = p + q t.
    let p = fl(r0) + fl(k) * o[2];
    let q = fl(k) * d[2];
    let a = dot(&d[..2], &d[..2]) - Float::with_val(BITS, q.square_ref());
    let b = dot(&d[..2], &o[..2]) * 2u32 - Float::with_val(BITS, &p * &q) * 2u32;
    let c = dot(&o[..2], &o[..2]) - Float::with_val(BITS, p.square_ref());
    if a.clone().abs() < 1e-6 {
        return None;
    }
    let mut out = Vec::new();
    for pt in points(o, d, &quadratic(&a, &b, &c)) {
        let z = pt[2].to_f64();
        if (z.abs() < 1e-9) || ((z - h).abs() < 1e-9) {
            return None;
        }
        // The nappe: the radius r₀ + k z must be positive.
        let rho = fl(r0) + fl(k) * &pt[2];
        if z > 0.0 && z < h && rho > 0 {
            out.push(pt);
        }
    }
    Some(out)
}

fn check(r: &CaseResult, truths: &[Vec<Float>]) -> Result<(), String> {
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
    one_to_one(&point_boxes(r), truths).map_err(|e| format!("points: {e}"))
}

fn segment_json(o: [f64; 3], d: [f64; 3], t: f64) -> String {
    let a: [f64; 3] = std::array::from_fn(|j| o[j] - t * d[j]);
    let b: [f64; 3] = std::array::from_fn(|j| o[j] + t * d[j]);
    format!(r#"{{"type":"segment","a":{},"b":{}}}"#, nums(&a), nums(&b))
}

/// A random line across the z axis: through a dyadic point of `[-2, 2]² × [0, 2]`,
/// direction dyadic and mostly across the axis, written as the segment `t ∈ [-8, 8]` (its parameter rescaled; the
/// points are what is compared).
fn random_line(g: &mut Gen) -> ([f64; 3], [f64; 3]) {
    let o = [
        g.dyadic(-2.0, 2.0, 6),
        g.dyadic(-2.0, 2.0, 6),
        g.dyadic(0.0, 2.0, 6),
    ];
    let d = loop {
        let d = [
            g.dyadic(-1.0, 1.0, 4),
            g.dyadic(-1.0, 1.0, 4),
            g.dyadic(-0.5, 0.5, 4),
        ];
        if d[0] * d[0] + d[1] * d[1] > 0.25 {
            break d;
        }
    };
    (o, d)
}

/// The shapes of one family member.
struct Member {
    name: &'static str,
    surface: String,
    /// `(r₀, k, h)` of the frustum it equals.
    frustum: (f64, f64, f64),
}

/// The cylinder `r = 1.25`, `z ∈ [0, 2]` and the frustum `r = 1.5 − z/2`, each written
/// as a revolution of a segment, an extrusion of a circle (the cylinder only) and a
/// ruled surface between two circles (the guides start at the same angle, so the
/// rulings are the generators).
fn members() -> Vec<Member> {
    let circle = |z: f64, r: f64| {
        format!(r#"{{"type":"circle","center":[0,0,{z}],"radius":{r},"axis":[0,0,1]}}"#)
    };
    vec![
        Member {
            name: "revolution of a segment (cylinder)",
            surface: r#"{"type":"revolution","profile":{"type":"segment","a":[1.25,0,0],"b":[1.25,0,2]},"origin":[0,0,0],"axis":[0,0,1]}"#.into(),
            frustum: (1.25, 0.0, 2.0),
        },
        Member {
            name: "revolution of a segment (cone)",
            surface: r#"{"type":"revolution","profile":{"type":"segment","a":[1.5,0,0],"b":[0.5,0,2]},"origin":[0,0,-1],"axis":[0,0,3]}"#.into(),
            frustum: (1.5, -0.5, 2.0),
        },
        Member {
            name: "extrusion of a circle (cylinder)",
            surface: format!(r#"{{"type":"extrusion","profile":{},"dir":[0,0,2]}}"#, circle(0.0, 1.25)),
            frustum: (1.25, 0.0, 2.0),
        },
        Member {
            name: "ruled between two circles (cylinder)",
            surface: format!(r#"{{"type":"ruled","a":{},"b":{}}}"#, circle(0.0, 1.25), circle(2.0, 1.25)),
            frustum: (1.25, 0.0, 2.0),
        },
        Member {
            name: "ruled between two circles (cone)",
            surface: format!(r#"{{"type":"ruled","a":{},"b":{}}}"#, circle(0.0, 1.5), circle(2.0, 0.5)),
            frustum: (1.5, -0.5, 2.0),
        },
    ]
}

/// Random lines across each member: every crossing in exactly one box, none else.
#[test]
fn lines_across_cylinders_and_cones_written_as_motion_surfaces() {
    let mut fails = Failures::default();
    let mut crossings = 0;
    for (m, member) in members().into_iter().enumerate() {
        let mut g = Gen::new(0x16_00 + m as u64);
        let mut done = 0;
        while done < cases(24) {
            let (o, d) = random_line(&mut g);
            let (r0, k, h) = member.frustum;
            let Some(truths) = line_frustum(o, d, r0, k, h) else {
                continue;
            };
            done += 1;
            crossings += truths.len();
            let case = format!(
                r#"{{"id":"m{m}-{done}","op":"intersect","objects":[{},{}]}}"#,
                segment_json(o, d, 8.0),
                member.surface
            );
            let r = solve(&case);
            let res = check(&r, &truths).map_err(|e| format!("{}: {e}", member.name));
            fails.check(res, &case, &r);
        }
    }
    fails.finish("lines across motion-surface cylinders and cones");
    assert!(crossings > 80, "too few crossings: {crossings}");
}

/// The ring torus `R = 2`, `r = 1/2` about z as the revolution of its meridian circle
/// (centre `(2, 0, 0)`, axis `y`): crossings of random lines are the roots of the
/// quartic (module doc), and the answer has as many points as the library's `torus`.
#[test]
fn lines_across_a_torus_of_revolution() {
    let (big, small) = (2.0, 0.5);
    let revolution = r#"{"type":"revolution","profile":{"type":"circle","center":[2,0,0],"radius":0.5,"axis":[0,1,0]},"origin":[0,0,0],"axis":[0,0,1]}"#;
    let torus = r#"{"type":"torus","center":[0,0,0],"major":2,"minor":0.5,"axis":[0,0,1]}"#;
    let mut g = Gen::new(0x16_70);
    let mut fails = Failures::default();
    let mut crossings = 0;
    for i in 0..cases(16) {
        let o = [
            g.dyadic(-3.0, 3.0, 6),
            g.dyadic(-3.0, 3.0, 6),
            g.dyadic(-0.4, 0.4, 6),
        ];
        let d: [f64; 3] = [
            g.dyadic(-1.0, 1.0, 4),
            g.dyadic(-1.0, 1.0, 4),
            g.dyadic(-0.25, 0.25, 4),
        ];
        if d[0] == 0.0 && d[1] == 0.0 {
            continue;
        }
        let Some(truths) = line_torus(o, d, big, small, 8.0) else {
            continue;
        };
        crossings += truths.len();
        let seg = segment_json(o, d, 8.0);
        let case = format!(r#"{{"id":"t-{i}","op":"intersect","objects":[{seg},{revolution}]}}"#);
        let r = solve(&case);
        let res = check(&r, &truths);
        fails.check(res, &case, &r);
        let other = format!(r#"{{"id":"u-{i}","op":"intersect","objects":[{seg},{torus}]}}"#);
        let t = solve(&other);
        let same = if count(&t) == count(&r) {
            Ok(())
        } else {
            Err(format!("{} points, the torus has {}", count(&r), count(&t)))
        };
        fails.check(same, &case, &r);
    }
    fails.finish("lines across a torus of revolution");
    assert!(crossings > 16, "too few crossings: {crossings}");
}

/// `T(t) = (|p|² + R² − r²)² − 4R²(x² + y²)` on `p = o + t·d`, in MPFR.
fn torus_value(o: [f64; 3], d: [f64; 3], big: f64, small: f64, t: &Float) -> Float {
    let p: Vec<Float> = (0..3)
        .map(|j| Float::with_val(BITS, t * d[j]) + o[j])
        .collect();
    let sq = |x: &Float| Float::with_val(BITS, x.square_ref());
    let rho2 = sq(&p[0]) + sq(&p[1]);
    let k = fl(big * big) - fl(small * small);
    let s = Float::with_val(BITS, &rho2 + sq(&p[2])) + k;
    sq(&s) - rho2 * (4.0 * big * big)
}

/// The crossings of `o + t·d`, `|t| ≤ span`, with the torus: sign changes of the
/// quartic on a grid of 4096 steps, bisected to `BITS`; `None` if the quartic is small
/// at a grid point (a near-tangency, left to other families) or at the ends.
fn line_torus(
    o: [f64; 3],
    d: [f64; 3],
    big: f64,
    small: f64,
    span: f64,
) -> Option<Vec<Vec<Float>>> {
    let n = 4096;
    let at = |i: usize| fl(-span + 2.0 * span * i as f64 / n as f64);
    let vals: Vec<Float> = (0..=n)
        .map(|i| torus_value(o, d, big, small, &at(i)))
        .collect();
    if vals.iter().any(|v| v.clone().abs() < 1e-3) {
        return None;
    }
    let mut ts = Vec::new();
    for i in 0..n {
        if (vals[i] < 0) != (vals[i + 1] < 0) {
            let (mut lo, mut hi) = (at(i), at(i + 1));
            let neg_lo = vals[i] < 0;
            for _ in 0..BITS + 8 {
                let mid = Float::with_val(BITS, &lo + &hi) / 2u32;
                if (torus_value(o, d, big, small, &mid) < 0) == neg_lo {
                    lo = mid;
                } else {
                    hi = mid;
                }
            }
            ts.push(lo);
        }
    }
    Some(points(o, d, &ts))
}

/// Points projected onto the cylinder by revolution (`r = 1.25`, `z ∈ [0, 2]`), nearest:
/// the foot `(r x/ρ, r y/ρ, z)` in closed form for points with `z` inside, away from the
/// axis.
#[test]
fn nearest_points_on_a_cylinder_of_revolution() {
    let surface = members().remove(0).surface;
    let mut g = Gen::new(0x16_90);
    let mut fails = Failures::default();
    for i in 0..cases(24) {
        let p = [
            g.dyadic(-3.0, 3.0, 6),
            g.dyadic(-3.0, 3.0, 6),
            g.dyadic(0.25, 1.75, 6),
        ];
        let rho = (fl(p[0]) * p[0] + fl(p[1]) * p[1]).sqrt();
        if rho < 0.25 {
            continue;
        }
        let foot: Vec<Float> = vec![
            Float::with_val(BITS, fl(1.25) * p[0]) / &rho,
            Float::with_val(BITS, fl(1.25) * p[1]) / &rho,
            fl(p[2]),
        ];
        let case = format!(
            r#"{{"id":"p-{i}","op":"project","point":{},"onto":{surface},"nearest":true}}"#,
            nums(&p)
        );
        let r = solve(&case);
        let res = check(&r, &[foot]);
        fails.check(res, &case, &r);
    }
    fails.finish("nearest points on a cylinder of revolution");
}

/// A bad motion surface: the error is typed and names the field.
fn refused(surface: &str) -> GeomError {
    let value: serde_json::Value = serde_json::from_str(surface).expect("json");
    match parse_object(value, "objects[1]") {
        Err(e) => e,
        Ok(spec) => geocert::io::shape(&spec, "objects[1]").expect_err("refused"),
    }
}

#[test]
fn bad_motion_surfaces_are_typed_errors_naming_the_field() {
    let seg = r#"{"type":"segment","a":[1,0,0],"b":[1,0,2]}"#;
    let circle = r#"{"type":"circle","center":[0,0,0],"radius":1,"axis":[0,0,1]}"#;
    let cases: Vec<(String, &str)> = vec![
        (format!(r#"{{"type":"revolution","profile":{seg},"origin":[0,0,0],"axis":[0,0,0]}}"#), "objects[1].axis"),
        (r#"{"type":"revolution","origin":[0,0,0],"axis":[0,0,1]}"#.into(), "objects[1].profile"),
        (format!(r#"{{"type":"revolution","profile":{seg},"axis":[0,0,1]}}"#), "objects[1].origin"),
        (r#"{"type":"revolution","profile":{"type":"spiral"},"origin":[0,0,0],"axis":[0,0,1]}"#.into(), "objects[1].profile.type"),
        (r#"{"type":"revolution","profile":{"type":"circle","center":[0,0,0],"radius":-1,"axis":[0,0,1]},"origin":[0,0,0],"axis":[0,0,1]}"#.into(), "objects[1].profile.radius"),
        (r#"{"type":"revolution","profile":{"type":"line","origin":[1,0,0],"dir":[0,0,1]},"origin":[0,0,0],"axis":[0,0,1]}"#.into(), "objects[1].profile.range"),
        (format!(r#"{{"type":"revolution","profile":{seg},"origin":[0,0,0],"axis":[0,0,1],"dir":[1,0,0]}}"#), "objects[1].dir"),
        (format!(r#"{{"type":"revolution","profile":{seg},"origin":[0,0,0],"axis":[0,0,1],"domain":[[0,7],[0,1]]}}"#), "objects[1].domain[0][1]"),
        (format!(r#"{{"type":"revolution","profile":{seg},"origin":[0,0,0],"axis":[0,0,1],"domain":[[0,1],[0,0.5]]}}"#), "objects[1].domain[1]"),
        (format!(r#"{{"type":"extrusion","profile":{circle},"dir":[0,0,0]}}"#), "objects[1].dir"),
        (format!(r#"{{"type":"extrusion","profile":{circle}}}"#), "objects[1].dir"),
        (format!(r#"{{"type":"extrusion","profile":{circle},"dir":[0,0,1],"colour":1}}"#), "objects[1].colour"),
        (format!(r#"{{"type":"ruled","a":{circle}}}"#), "objects[1].b"),
        (format!(r#"{{"type":"ruled","a":{circle},"b":{{"type":"circle2","center":[0,0],"radius":1}}}}"#), "objects[1].b.type"),
        (format!(r#"{{"type":"ruled","a":{circle},"b":{circle},"profile":{seg}}}"#), "objects[1].profile"),
    ];
    for (json, field) in cases {
        let e = refused(&json);
        assert_eq!(e.field(), field, "{json}: {e}");
    }
}

/// A motion surface survives the round trip through its JSON.
#[test]
fn motion_surfaces_round_trip() {
    for member in members() {
        let value: serde_json::Value = serde_json::from_str(&member.surface).expect("json");
        let geocert::io::ObjectSpec::Surface(spec) =
            parse_object(value.clone(), "o").expect("reads")
        else {
            panic!("{}: not a surface", member.name)
        };
        let back = parse_object(spec.to_json(), "o").expect("reads back");
        assert_eq!(
            back,
            geocert::io::ObjectSpec::Surface(spec),
            "{}",
            member.name
        );
    }
}

// ---- quadric (a symmetric 4×4 matrix) --------------------------------------------

/// `x ↦ Σ w_i (x_i − c_i)² − k` as the matrix of the case format: `A = diag(w)`,
/// `b = −w∘c`, `c₀ = Σ w_i c_i² − k` (exact for the dyadic data used here).
fn diagonal_quadric(w: [f64; 3], c: [f64; 3], k: f64) -> String {
    let b: [f64; 3] = std::array::from_fn(|i| -w[i] * c[i]);
    let c0 = (0..3).map(|i| w[i] * c[i] * c[i]).sum::<f64>() - k;
    let rows = [
        [w[0], 0.0, 0.0, b[0]],
        [0.0, w[1], 0.0, b[1]],
        [0.0, 0.0, w[2], b[2]],
        [b[0], b[1], b[2], c0],
    ];
    let rows: Vec<String> = rows.iter().map(|r| nums(r)).collect();
    format!(r#"{{"type":"quadric","matrix":[{}]}}"#, rows.join(","))
}

/// What the two answers must share: status, completeness, the points with their boxes,
/// multiplicities and exact coordinates (the quadric reports no surface parameters).
fn same_points(q: &CaseResult, s: &CaseResult) -> Result<(), String> {
    if q.status != "exact" || s.status != "exact" || q.complete != Some(true) {
        return Err(format!("status {} / {}", q.status, s.status));
    }
    let key = |r: &CaseResult| -> Vec<String> {
        r.points
            .iter()
            .flatten()
            .map(|p| {
                format!(
                    "{:?} {:?} {} {:?}",
                    p.xyz,
                    p.bounds,
                    p.multiplicity,
                    p.exact.as_ref().map(|e| &e.xyz)
                )
            })
            .collect()
    };
    if key(q) == key(s) {
        Ok(())
    } else {
        Err(format!("quadric {:?}\nnamed   {:?}", key(q), key(s)))
    }
}

/// Random lines and segments against spheres and axis-aligned ellipsoids given as
/// matrices: the same exact answer (same numbers, bit for bit) as the named surface;
/// every fourth case scaled by 2^±500 or 2^±300.
#[test]
fn lines_against_spheres_and_ellipsoids_as_matrices() {
    let mut g = Gen::new(0x16_a0);
    let mut fails = Failures::default();
    let mut points = 0;
    for i in 0..cases(120) {
        let s = if i % 4 == 3 {
            truth_support::conics::magnitude(i / 4)
        } else {
            1.0
        };
        let c = g.vec::<3>(-1.0, 1.0, 4).map(|x| x * s);
        let semi = [[1.0, 1.0, 1.0], [2.0, 0.5, 1.0], [0.25, 1.0, 4.0]][i % 3];
        let semi = semi.map(|x| x * s);
        let w = semi.map(|a| 1.0 / (a * a));
        let quadric = diagonal_quadric(w, c, 1.0);
        let named = if i % 3 == 0 {
            format!(
                r#"{{"type":"sphere","center":{},"radius":{}}}"#,
                nums(&c),
                num(semi[0])
            )
        } else {
            format!(
                r#"{{"type":"ellipsoid","center":{},"a":{},"b":{},"c":{}}}"#,
                nums(&c),
                num(semi[0]),
                num(semi[1]),
                num(semi[2])
            )
        };
        let off = g.vec::<3>(-0.5, 0.5, 5);
        let o: [f64; 3] = std::array::from_fn(|j| c[j] + off[j] * s);
        let d = g.vec::<3>(-1.0, 1.0, 4).map(|x| x * s);
        if d == [0.0; 3] {
            continue;
        }
        let line = if i % 2 == 0 {
            format!(
                r#"{{"type":"line","origin":{},"dir":{}}}"#,
                nums(&o),
                nums(&d)
            )
        } else {
            let b: [f64; 3] = std::array::from_fn(|j| o[j] + 4.0 * d[j]);
            format!(r#"{{"type":"segment","a":{},"b":{}}}"#, nums(&o), nums(&b))
        };
        let case = |k: &str, s: &str| {
            format!(r#"{{"id":"q{i}{k}","op":"intersect","objects":[{line},{s}]}}"#)
        };
        let (cq, cs) = (case("q", &quadric), case("s", &named));
        let (rq, rs) = (solve(&cq), solve(&cs));
        points += count(&rq);
        fails.check(same_points(&rq, &rs), &cq, &rq);
    }
    fails.finish("lines against spheres and ellipsoids as matrices");
    assert!(points > 120, "too few points: {points}");
}

/// Tangent lines of a sphere given as a matrix — a proven double root — and the same
/// lines moved by one ulp inward (two simple crossings) and outward (none); exact.
#[test]
fn tangents_to_a_quadric_and_one_ulp_off() {
    let mut g = Gen::new(0x16_b0);
    for i in 0..cases(60) {
        let c = g.vec::<3>(-2.0, 2.0, 4);
        let r = g.dyadic(0.25, 2.0, 4);
        let quadric = diagonal_quadric([1.0; 3], c, r * r);
        // The tangent at c + r·e_x, along a direction in the plane x = const.
        let d = [0.0, g.dyadic(-1.0, 1.0, 3), g.dyadic(0.125, 1.0, 3)];
        let x = c[0] + r;
        for (shift, expect) in [(0i32, 1usize), (-1, 2), (1, 0)] {
            let ox = match shift {
                0 => x,
                -1 => x.next_down(),
                _ => x.next_up(),
            };
            let o = [ox, c[1], c[2]];
            let case = format!(
                r#"{{"id":"t{i}{shift}","op":"intersect","objects":[{{"type":"line","origin":{},"dir":{}}},{quadric}]}}"#,
                nums(&o),
                nums(&d)
            );
            let res = solve(&case);
            assert_eq!(res.status, "exact", "{case}: {res:?}");
            assert_eq!(count(&res), expect, "{case}: {res:?}");
            let ps = res.points.clone().unwrap_or_default();
            if shift == 0 {
                assert_eq!(ps[0].multiplicity, 2, "{case}");
                assert!(ps[0].tangent, "{case}");
                assert_eq!(ps[0].xyz, vec![x, c[1], c[2]], "{case}");
            } else {
                assert!(ps.iter().all(|p| p.multiplicity == 1), "{case}");
            }
        }
    }
}

/// The rulings of the hyperboloid `x² + y² − z² = 25` (and of the cone `x² + y² = z²`,
/// and a plane pair `x² = 1`) lie on it: a line is `coincident`, a segment is itself.
#[test]
fn rulings_lie_on_quadrics_given_as_matrices() {
    let hyperboloid = diagonal_quadric([1.0, 1.0, -1.0], [0.0; 3], 25.0);
    let cone = diagonal_quadric([1.0, 1.0, -1.0], [0.0; 3], 0.0);
    let planes = diagonal_quadric([1.0, 0.0, 0.0], [0.0; 3], 1.0);
    // Through (a, b, 0) along (−b, a, ±5), a² + b² = 25 (Pythagorean, exact).
    for (cs, sn) in [
        (5.0, 0.0),
        (3.0, 4.0),
        (-4.0, 3.0),
        (0.0, -5.0),
        (-3.0, -4.0),
    ] {
        for sign in [5.0, -5.0] {
            let o = [cs, sn, 0.0];
            let d = [-sn, cs, sign];
            let line = format!(
                r#"{{"type":"line","origin":{},"dir":{}}}"#,
                nums(&o),
                nums(&d)
            );
            let r = solve(&format!(
                r#"{{"id":"h","op":"intersect","objects":[{line},{hyperboloid}]}}"#
            ));
            assert_eq!((r.status, r.kind), ("exact", Some("line")), "{line}: {r:?}");
            let seg = format!(
                r#"{{"type":"segment","a":{},"b":{}}}"#,
                nums(&o),
                nums(&[o[0] + d[0], o[1] + d[1], o[2] + d[2]])
            );
            let r = solve(&format!(
                r#"{{"id":"s","op":"intersect","objects":[{hyperboloid},{seg}]}}"#
            ));
            assert_eq!(
                (r.status, r.kind),
                ("exact", Some("segment")),
                "{seg}: {r:?}"
            );
            // A generator of the cone through the apex.
            let gen = format!(
                r#"{{"type":"line","origin":[0,0,0],"dir":{}}}"#,
                nums(&[cs, sn, 5.0])
            );
            let r = solve(&format!(
                r#"{{"id":"c","op":"intersect","objects":[{gen},{cone}]}}"#
            ));
            assert_eq!((r.status, r.kind), ("exact", Some("line")), "{gen}: {r:?}");
        }
    }
    // The plane pair x = ±1: a line in x = 1 lies on it; a line across meets each once.
    let on = r#"{"type":"line","origin":[1,2,3],"dir":[0,1,-1]}"#;
    let r = solve(&format!(
        r#"{{"id":"p","op":"intersect","objects":[{on},{planes}]}}"#
    ));
    assert_eq!((r.status, r.kind), ("exact", Some("line")), "{r:?}");
    let across = r#"{"type":"line","origin":[0,2,3],"dir":[1,1,-1]}"#;
    let r = solve(&format!(
        r#"{{"id":"p","op":"intersect","objects":[{across},{planes}]}}"#
    ));
    assert_eq!(r.status, "exact");
    let xs: Vec<f64> = r.points.iter().flatten().map(|p| p.xyz[0]).collect();
    assert_eq!(xs, vec![-1.0, 1.0], "{r:?}");
}

/// Points against quadrics given as matrices: on, inside, outside, exactly — points on
/// the sphere `x² + y² + z² = 25` (Pythagorean) and their neighbours one ulp away.
#[test]
fn classify_points_against_a_quadric_exactly() {
    use geocert::ops::{classify, Answer, Options, Position, Side};
    let value: serde_json::Value =
        serde_json::from_str(&diagonal_quadric([1.0; 3], [0.0; 3], 25.0)).expect("json");
    let shell =
        geocert::io::shape(&parse_object(value, "shell").expect("reads"), "shell").expect("builds");
    let side = |p: [f64; 3]| {
        let r = classify(&Position::Double(p.to_vec()), &shell, &Options::default()).expect("ok");
        assert_eq!(r.status, geocert::Status::Exact);
        match r.value {
            Answer::Side(s, _) => s,
            other => panic!("{other:?}"),
        }
    };
    for p in [
        [3.0, 4.0, 0.0],
        [0.0, -3.0, 4.0],
        [-4.0, 0.0, 3.0],
        [5.0, 0.0, 0.0],
    ] {
        assert_eq!(side(p), Side::On, "{p:?}");
        for k in 0..3 {
            if p[k] == 0.0 {
                continue;
            }
            let mut out = p;
            out[k] = if p[k] > 0.0 {
                p[k].next_up()
            } else {
                p[k].next_down()
            };
            assert_eq!(side(out), Side::Outside, "{out:?}");
            let mut inn = p;
            inn[k] = if p[k] > 0.0 {
                p[k].next_down()
            } else {
                p[k].next_up()
            };
            assert_eq!(side(inn), Side::Inside, "{inn:?}");
        }
    }
    assert_eq!(side([0.0; 3]), Side::Inside);
    assert_eq!(side([1e300, 0.0, 0.0]), Side::Outside);
}

#[test]
fn bad_quadrics_are_typed_errors_naming_the_field() {
    let cases = [
        (
            r#"{"type":"quadric","matrix":[[1,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0]]}"#,
            "objects[1].matrix[3]",
        ),
        (
            r#"{"type":"quadric","matrix":[[1,2,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,-1]]}"#,
            "objects[1].matrix[0][1]",
        ),
        (
            r#"{"type":"quadric","matrix":[[0,0,0,0],[0,0,0,0],[0,0,0,0],[0,0,0,0]]}"#,
            "objects[1].matrix",
        ),
        (
            r#"{"type":"quadric","matrix":[[1,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,"1/3"]]}"#,
            "objects[1].matrix[3][3]",
        ),
        (r#"{"type":"quadric"}"#, "objects[1]"),
        (
            r#"{"type":"quadric","matrix":[[1,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,-1]],"center":[0,0,0]}"#,
            "objects[1]",
        ),
    ];
    for (json, field) in cases {
        let e = refused(json);
        assert!(
            e.field().starts_with(field),
            "{json}: {e} (field {})",
            e.field()
        );
    }
    // A conic against the quadric is answered exactly (a circle of radius 2 about the
    // unit sphere's centre misses it) ...
    let sphere = diagonal_quadric([1.0; 3], [0.0; 3], 1.0);
    let circle = r#"{"type":"circle","center":[0,0,0],"radius":2,"axis":[1,0,0]}"#;
    let r = solve(&format!(
        r#"{{"id":"c","op":"intersect","objects":[{circle},{sphere}]}}"#
    ));
    assert!(r.error.is_none(), "{r:?}");
    assert_eq!((r.status, r.kind), ("exact", Some("empty")), "{r:?}");
    assert!(r.points.as_ref().is_none_or(|p| p.is_empty()), "{r:?}");
    // ... operations the quadric does not take: typed `unsupported`, naming the object.
    let helix =
        r#"{"type":"helix","center":[0,0,0],"radius":2,"pitch":1,"axis":[1,0,0],"range":[0,6]}"#;
    let r = solve(&format!(
        r#"{{"id":"u","op":"intersect","objects":[{helix},{sphere}]}}"#
    ));
    let e = r.error.as_ref().expect("an error");
    assert_eq!(
        (e.kind, e.field.as_str()),
        ("unsupported", "objects[1].type"),
        "{r:?}"
    );
}

// ---- a plane with a domain ---------------------------------------------------------

/// Segments across the patch `origin + u·U + v·V`, `(u, v) ∈ [1/4, 3/4] × [−1, 1/2]`
/// (skew `U`, `V`): the crossing of the whole plane is exact (dyadic data), inside the
/// patch it is the one point, outside none; crossings within `1e-9` of the border are
/// left out.
#[test]
fn segments_across_a_bounded_plane() {
    let (origin, uu, vv) = ([0.5, -0.25, 1.0], [1.0, 0.5, 0.0], [0.0, 1.0, 0.25]);
    let patch = format!(
        r#"{{"type":"plane","origin":{},"u":{},"v":{},"domain":[[0.25,0.75],[-1,0.5]]}}"#,
        nums(&origin),
        nums(&uu),
        nums(&vv)
    );
    let mut g = Gen::new(0x16_c0);
    let mut fails = Failures::default();
    let (mut hits, mut misses) = (0, 0);
    for i in 0..cases(40) {
        // The crossing at (u, v) on the plane, a segment through it across the plane.
        let (u, v) = (g.dyadic(0.0, 1.0, 5), g.dyadic(-1.25, 0.75, 5));
        if [u - 0.25, u - 0.75, v + 1.0, v - 0.5]
            .iter()
            .any(|x| x.abs() < 1e-9)
        {
            continue;
        }
        let x: [f64; 3] = std::array::from_fn(|j| origin[j] + u * uu[j] + v * vv[j]);
        let d = [g.dyadic(-0.5, 0.5, 3), g.dyadic(-0.5, 0.5, 3), 1.0];
        let a: [f64; 3] = std::array::from_fn(|j| x[j] - d[j]);
        let b: [f64; 3] = std::array::from_fn(|j| x[j] + d[j]);
        let inside = (0.25..=0.75).contains(&u) && (-1.0..=0.5).contains(&v);
        let truths = if inside {
            vec![x.iter().map(|&c| fl(c)).collect()]
        } else {
            vec![]
        };
        if inside {
            hits += 1;
        } else {
            misses += 1;
        }
        let case = format!(
            r#"{{"id":"b{i}","op":"intersect","objects":[{{"type":"segment","a":{},"b":{}}},{patch}]}}"#,
            nums(&a),
            nums(&b)
        );
        let r = solve(&case);
        fails.check(check(&r, &truths), &case, &r);
    }
    fails.finish("segments across a bounded plane");
    assert!(hits > 8 && misses > 8, "{hits} hits, {misses} misses");
}
