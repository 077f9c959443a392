//! The curved operation families: curve ∩ curve (space and plane), curve ∩ surface,
//! projections onto curves and surfaces, surface ∩ surface. Half the time the case is a
//! built adversarial configuration — tangency at a relative gap of 0, 10^-k or a few
//! ulps, a query point at a sphere's centre or on an axis (infinitely many feet), a
//! line through a pole or along a seam, coincident objects — the rest random pairs.
//! Checks: the record (check.rs), and each certified point on each sphere and plane of
//! the case: the exact range of the implicit equation over the point's box, computed
//! with rationals, must contain 0.

use super::check;
use super::num::{double, positive};
use super::objects::{self, axis, gap};
use arbitrary::{Result, Unstructured};
use geocert::io::case::parse_case;
use geocert::io::solve_case;
use rug::Rational;
use serde_json::{json, Value};

fn options(u: &mut Unstructured) -> Result<Value> {
    let mut o = json!({"time_limit": super::TIME_LIMIT, "max_boxes": super::MAX_BOXES});
    if u.ratio(1u8, 4)? {
        o["exact"] = json!(true);
    }
    Ok(o)
}

fn run(case: Option<Value>) {
    let Some(case) = case else {
        return;
    };
    if std::env::var_os("GEOCERT_FUZZ_SHOW").is_some() {
        eprintln!("case: {case}");
    }
    let _shown = check::ShowOnPanic(&case);
    let line = solve_case(parse_case(case.clone())).to_json_line();
    let v = check::record(&line);
    if v["status"] == "error" || v["status"] == "undecided" || v["kind"] != "points" {
        return;
    }
    let on: Vec<&Value> = match case["op"].as_str() {
        Some("project") => vec![&case["onto"]],
        _ => case["objects"].as_array().unwrap().iter().collect(),
    };
    for p in v["points"].as_array().unwrap() {
        for obj in &on {
            on_object(p, obj, &line);
        }
    }
}

/// Curve ∩ curve.
pub fn curve_curve(data: &[u8]) {
    let mut u = Unstructured::new(data);
    run(curve_curve_case(&mut u).ok());
}

fn curve_curve_case(u: &mut Unstructured) -> Result<Value> {
    let (a, b) = match u.int_in_range(0u8..=4)? {
        0 => (objects::curve3(u)?, objects::curve3(u)?),
        1 => (objects::curve2(u)?, objects::curve2(u)?),
        2 => {
            // Two circles touching (or nearly) from outside or inside.
            let (r1, r2) = (positive(u)?, positive(u)?);
            let inside = u.arbitrary::<bool>()?;
            let d = if inside { (r1 - r2).abs() } else { r1 + r2 } * (1.0 + gap(u)?);
            let c = [double(u)?, double(u)?];
            (
                json!({"type": "circle2", "center": c, "radius": r1}),
                json!({"type": "circle2", "center": [c[0] + d, c[1]], "radius": r2}),
            )
        }
        3 => {
            // A line tangent (or nearly) to a circle, in space or in the plane.
            let r = positive(u)?;
            let y = r * (1.0 + gap(u)?);
            if u.arbitrary()? {
                (
                    json!({"type": "circle2", "center": [0, 0], "radius": r}),
                    json!({"type": "line2", "origin": [double(u)?, y], "dir": [1, 0]}),
                )
            } else {
                (
                    json!({"type": "circle", "center": [0, 0, 0], "radius": r, "axis": [0, 0, 1]}),
                    json!({"type": "line", "origin": [double(u)?, y, 0], "dir": [1, 0, 0]}),
                )
            }
        }
        _ => {
            // A curve against itself or a copy: infinitely many common points.
            let a = if u.arbitrary()? {
                objects::curve3(u)?
            } else {
                objects::curve2(u)?
            };
            (a.clone(), a)
        }
    };
    Ok(json!({"op": "intersect", "objects": [a, b], "options": options(u)?}))
}

/// Curve ∩ surface.
pub fn curve_surface(data: &[u8]) {
    let mut u = Unstructured::new(data);
    run(curve_surface_case(&mut u).ok());
}

fn curve_surface_case(u: &mut Unstructured) -> Result<Value> {
    let r = positive(u)?;
    let g = 1.0 + gap(u)?;
    let (c, s) = match u.int_in_range(0u8..=6)? {
        0 | 1 => (objects::curve3(u)?, objects::surface(u)?),
        2 => {
            // A line tangent to a sphere, or through its poles.
            let s = json!({"type": "sphere", "center": [0, 0, 0], "radius": r});
            let l = if u.arbitrary()? {
                json!({"type": "line", "origin": [r * g, double(u)?, 0], "dir": [0, 1, 0]})
            } else {
                json!({"type": "line", "origin": [0, 0, double(u)?], "dir": [0, 0, 1]})
            };
            (l, s)
        }
        3 => {
            // A circle nearly on a sphere, or touching it, or crossing the seam.
            let s = json!({"type": "sphere", "center": [0, 0, 0], "radius": r});
            let h = r * double(u)?.clamp(-1.0, 1.0);
            let rc = (r * r - h * h).max(0.0).sqrt() * g;
            (
                json!({"type": "circle", "center": [0, 0, h], "radius": rc, "axis": axis(u)?}),
                s,
            )
        }
        4 => {
            // A line parallel to a cylinder's axis at distance r·g, or along the axis.
            let s = json!({"type": "cylinder", "origin": [0, 0, 0], "radius": r, "axis": [0, 0, 1],
                           "height": [-1, 1]});
            let x = if u.arbitrary()? { r * g } else { 0.0 };
            (
                json!({"type": "line", "origin": [x, 0, 0], "dir": [0, double(u)?, 1]}),
                s,
            )
        }
        5 => {
            // A line tangent to a torus's outer or inner equator, or along its axis.
            let (big, small) = (positive(u)? + r, r);
            let t = json!({"type": "torus", "center": [0, 0, 0], "major": big, "minor": small,
                           "axis": [0, 0, 1]});
            let x = [big + small, big - small, 0.0][u.int_in_range(0usize..=2)?] * g;
            let dir = if x == 0.0 { [0, 0, 1] } else { [0, 1, 0] };
            (json!({"type": "line", "origin": [x, 0, 0], "dir": dir}), t)
        }
        _ => {
            // A circle touching a plane (its centre at distance r·g, its axis in the plane).
            let p = json!({"type": "plane", "normal": [0, 0, 1], "d": 0});
            (
                json!({"type": "circle", "center": [0, 0, r * g], "radius": r, "axis": [1, 0, 0]}),
                p,
            )
        }
    };
    Ok(json!({"op": "intersect", "objects": [c, s], "options": options(u)?}))
}

/// A point projected onto a curve or a surface (perpendicular feet, the nearest point,
/// or along a direction).
pub fn project(data: &[u8]) {
    let mut u = Unstructured::new(data);
    run(project_case(&mut u).ok());
}

fn project_case(u: &mut Unstructured) -> Result<Value> {
    let r = positive(u)?;
    let (point, onto) = match u.int_in_range(0u8..=5)? {
        0 => (vec![double(u)?, double(u)?], objects::curve2(u)?),
        1 => (objects::dvec(u)?, objects::curve3(u)?),
        2 => (objects::dvec(u)?, objects::surface(u)?),
        3 => {
            // The centre of a sphere (every point a foot), or near it, or near a pole.
            let z = [0.0, r * gap(u)?, r * (1.0 + gap(u)?)][u.int_in_range(0usize..=2)?];
            (
                vec![0.0, 0.0, z],
                json!({"type": "sphere", "center": [0, 0, 0], "radius": r}),
            )
        }
        4 => {
            // On a torus's axis (a circle of feet), or near it.
            let t = json!({"type": "torus", "center": [0, 0, 0], "major": r + positive(u)?,
                           "minor": r, "axis": [0, 0, 1]});
            (vec![gap(u)?, 0.0, double(u)?], t)
        }
        _ => {
            // On or near a circle's axis; on the seam side (the +X direction).
            let c = json!({"type": "circle", "center": [0, 0, 0], "radius": r, "axis": [0, 0, 1]});
            (vec![r * gap(u)?, 0.0, double(u)?], c)
        }
    };
    let mut case = json!({"op": "project", "point": point, "onto": onto, "options": options(u)?});
    match u.int_in_range(0u8..=3)? {
        0 => case["nearest"] = json!(true),
        1 if point_dim(&case) == 3 => case["direction"] = json!(axis(u)?),
        _ => {}
    }
    Ok(case)
}

fn point_dim(case: &Value) -> usize {
    case["point"].as_array().map_or(0, Vec::len)
}

/// Surface ∩ surface.
pub fn surface_surface(data: &[u8]) {
    let mut u = Unstructured::new(data);
    run(surface_surface_case(&mut u).ok());
}

fn surface_surface_case(u: &mut Unstructured) -> Result<Value> {
    let (r1, r2) = (positive(u)?, positive(u)?);
    let g = 1.0 + gap(u)?;
    let (a, b) = match u.int_in_range(0u8..=5)? {
        0 | 1 => (objects::surface(u)?, objects::surface(u)?),
        2 => {
            // Two spheres touching from outside or inside (or nearly), or the same.
            let d = [r1 + r2, (r1 - r2).abs(), 0.0][u.int_in_range(0usize..=2)?] * g;
            (
                json!({"type": "sphere", "center": [0, 0, 0], "radius": r1}),
                json!({"type": "sphere", "center": [d, 0, 0], "radius": r2}),
            )
        }
        3 => {
            // A plane touching a sphere at a pole (or nearly).
            (
                json!({"type": "sphere", "center": [0, 0, 0], "radius": r1}),
                json!({"type": "plane", "normal": [0, 0, 1], "d": -r1 * g}),
            )
        }
        4 => {
            // Two cylinders with axes crossing at right angles, radii nearly equal
            // (Steinmetz: two ellipses crossing at singular points).
            (
                json!({"type": "cylinder", "origin": [0, 0, 0], "radius": r1, "axis": [0, 0, 1],
                    "height": [-2.0 * r1, 2.0 * r1]}),
                json!({"type": "cylinder", "origin": [0, 0, 0], "radius": r1 * g, "axis": [1, 0, 0],
                    "height": [-2.0 * r1, 2.0 * r1]}),
            )
        }
        _ => {
            // A cylinder inside a sphere touching it along a circle, or nearly.
            (
                json!({"type": "sphere", "center": [0, 0, 0], "radius": r1}),
                json!({"type": "cylinder", "origin": [0, 0, -2.0 * r1], "radius": r1 * g,
                    "axis": [0, 0, 1], "height": [0, 4.0 * r1]}),
            )
        }
    };
    Ok(json!({"op": "intersect", "objects": [a, b], "options": options(u)?}))
}

fn q(x: f64) -> Rational {
    Rational::from_f64(x).unwrap()
}

/// The exact range of `Σ kᵢ (xᵢ − cᵢ)²` (with `square`) or `Σ kᵢ xᵢ` over the box.
fn range(b: &[(f64, f64)], k: &[f64], c: &[f64], square: bool) -> (Rational, Rational) {
    let (mut lo, mut hi) = (Rational::new(), Rational::new());
    for (i, &(l, h)) in b.iter().enumerate() {
        let (l, h) = (q(l) - q(c[i]), q(h) - q(c[i]));
        let (a, z) = if square {
            let (sl, sh) = (Rational::from(&l * &l), Rational::from(&h * &h));
            let min = if l <= 0 && h >= 0 {
                Rational::new()
            } else {
                sl.clone().min(sh.clone())
            };
            (min, sl.max(sh))
        } else {
            (l, h)
        };
        let (a, z) = (a * q(k[i]), z * q(k[i]));
        lo += a.clone().min(z.clone());
        hi += a.max(z);
    }
    (lo, hi)
}

fn f3(v: &Value) -> Option<Vec<f64>> {
    v.as_array()?.iter().map(Value::as_f64).collect()
}

/// A certified point lies on a sphere or a plane (normal form) of the case: its box
/// meets the surface.
fn on_object(p: &Value, obj: &Value, line: &str) {
    let Some(b) = check::bounds(p, line) else {
        return;
    };
    if b.len() != 3 || b.iter().any(|(l, h)| !l.is_finite() || !h.is_finite()) {
        return;
    }
    let (lo, hi) = match obj["type"].as_str() {
        Some("sphere") if obj.get("domain").is_none() => {
            let (Some(c), Some(r)) = (f3(&obj["center"]), obj["radius"].as_f64()) else {
                return;
            };
            let (lo, hi) = range(&b, &[1.0; 3], &c, true);
            (lo - q(r) * q(r), hi - q(r) * q(r))
        }
        Some("plane") if obj.get("normal").is_some() => {
            let (Some(n), Some(d)) = (f3(&obj["normal"]), obj["d"].as_f64()) else {
                return;
            };
            let (lo, hi) = range(&b, &n, &[0.0; 3], false);
            (lo + q(d), hi + q(d))
        }
        _ => return,
    };
    assert!(
        lo <= 0 && hi >= 0,
        "a certified point off the {}: {obj}\n{line}",
        obj["type"]
    );
}
