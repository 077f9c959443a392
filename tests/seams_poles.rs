//! Seams and domain ends (issue 14 items 2 and 3): families of cases whose solutions
//! lie exactly on a periodic seam or a true end of a parameter domain, or one ulp away,
//! each checked against a truth computed independently (exact rationals, or MPFR at
//! 256 bits): the answer is decided (not `undecided`), `complete`, has exactly one box
//! per truth and one truth per box (periodic parameters compared modulo 2π), and the
//! right multiplicity.

use std::process::Command;

mod truth_support;

use geocert::certificate::Status;
use geocert::num::round::{next_down, next_up};
use geocert::ops::{Answer, Point};
use geocert::robust::rng::Rng;
use rug::float::Constant;
use rug::{Float, Rational};
use truth_support::front_door as solve;

const BITS: u32 = 256;

fn points(a: &Answer) -> &[Point] {
    match a {
        Answer::Points(p) => p,
        Answer::Empty => &[],
        other => panic!("expected points, got {other:?}"),
    }
}

/// `x` (exact) lies in the closed interval `[lo, hi]`, or does so shifted by a whole
/// number of turns when `periodic` (2π enclosed at 256 bits; `x` is then a float).
fn inside(x: &Float, [lo, hi]: [f64; 2], periodic: bool) -> bool {
    let shifts: &[i32] = if periodic { &[0, 1, -1] } else { &[0] };
    shifts.iter().any(|&k| {
        let turn = Float::with_val(BITS, Constant::Pi) * 2 * k;
        let y = Float::with_val(BITS, x + &turn);
        // the error of the 256-bit shift is far below the boxes' double bounds
        lo <= y && y <= hi
    })
}

/// Every truth (a list of parameters, `periodic` per parameter) lies in exactly one
/// point's `param_box`, and every point holds exactly one truth.
fn one_to_one(pts: &[Point], truths: &[Vec<Float>], periodic: &[bool], what: &str) {
    assert_eq!(pts.len(), truths.len(), "{what}: count, got {pts:?}");
    let holds = |p: &Point, t: &[Float]| {
        let b: Vec<[f64; 2]> = p.param_box.as_ref().expect("boxes").concat();
        b.len() == t.len() && (0..t.len()).all(|i| inside(&t[i], b[i], periodic[i]))
    };
    for t in truths {
        let n = pts.iter().filter(|p| holds(p, t)).count();
        assert_eq!(n, 1, "{what}: truth {t:?} in {n} boxes of {pts:?}");
    }
    for p in pts {
        let n = truths.iter().filter(|t| holds(p, t)).count();
        assert_eq!(n, 1, "{what}: box {:?} holds {n} truths", p.param_box);
    }
}

fn decided(c: &geocert::Certified<Answer>, what: &str) {
    assert_ne!(c.status, Status::Undecided, "{what}: {:?}", c.reason);
    assert!(c.complete, "{what}: not complete: {:?}", c.reason);
}

fn q(x: f64) -> Rational {
    Rational::from_f64(x).expect("finite")
}

fn fl(x: &Rational) -> Float {
    Float::with_val(BITS, x)
}

/// A quadratic Bézier `B(s)` and a segment from `B(0)` towards `B(s₁)` (its end `b`
/// possibly nudged by one ulp): the roots in exact rationals, from
/// `n·(B(s) − a) = s·(2n·(P₁−P₀) + s·n·(P₀−2P₁+P₂))` with `n ⊥ b − a`.
fn segment_bezier_truths(p: [[f64; 2]; 3], a: [f64; 2], b: [f64; 2]) -> Vec<[Rational; 2]> {
    let pq = p.map(|x| x.map(q));
    let (aq, bq) = (a.map(q), b.map(q));
    let d = [bq[0].clone() - &aq[0], bq[1].clone() - &aq[1]];
    let n = [-d[1].clone(), d[0].clone()];
    let dot = |u: &[Rational; 2], v: &[Rational; 2]| u[0].clone() * &v[0] + u[1].clone() * &v[1];
    let e1 = [
        (pq[1][0].clone() - &pq[0][0]) * 2u32,
        (pq[1][1].clone() - &pq[0][1]) * 2u32,
    ];
    let e2 = [
        pq[0][0].clone() - pq[1][0].clone() * 2u32 + &pq[2][0],
        pq[0][1].clone() - pq[1][1].clone() * 2u32 + &pq[2][1],
    ];
    let t_of = |s: &Rational| {
        let c = [
            e1[0].clone() * s + e2[0].clone() * s.clone() * s,
            e1[1].clone() * s + e2[1].clone() * s.clone() * s,
        ];
        dot(&d, &c) / dot(&d, &d)
    };
    let mut out = vec![[Rational::new(), t_of(&Rational::new())]];
    let (c1, c2) = (dot(&n, &e1), dot(&n, &e2));
    if c2 != 0 {
        let s2 = -c1 / c2;
        out.push([s2.clone(), t_of(&s2)]);
    }
    // a = B(0) exactly, so s = 0 is always a root
    let unit = |x: &Rational| *x >= 0 && *x <= 1;
    out.retain(|[s, t]| unit(s) && unit(t));
    out
}

fn bezier_at(p: &[[f64; 2]; 3], s: f64) -> [f64; 2] {
    // exact for the dyadic inputs below
    let w = [(1.0 - s) * (1.0 - s), 2.0 * s * (1.0 - s), s * s];
    [0, 1].map(|k| w[0] * p[0][k] + w[1] * p[1][k] + w[2] * p[2][k])
}

#[test]
fn segment_and_bezier_sharing_ends_exactly_and_one_ulp_apart() {
    let mut rng = Rng::new(143);
    let mut run = 0;
    while run < 60 {
        let p: [[f64; 2]; 3] = [0, 1, 2].map(|_| [0, 1].map(|_| rng.int(-32, 32) as f64 / 8.0));
        let cross =
            (p[1][0] - p[0][0]) * (p[2][1] - p[0][1]) - (p[1][1] - p[0][1]) * (p[2][0] - p[0][0]);
        let s1 = rng.int(1, 15) as f64 / 16.0;
        let end = bezier_at(&p, s1);
        if cross == 0.0 || end == p[0] {
            continue;
        }
        run += 1;
        let nudged = [end, [next_up(end[0]), end[1]], [next_down(end[0]), end[1]]];
        for (k, b) in nudged.into_iter().enumerate() {
            let truths = segment_bezier_truths(p, p[0], b);
            if k == 0 {
                assert_eq!(truths.len(), 2, "both shared ends are roots");
            }
            let seg = format!(r#"{{"type":"segment2","a":{:?},"b":{:?}}}"#, p[0], b);
            let bez = format!(r#"{{"type":"bezier2","points":{:?}}}"#, p);
            for swap in [false, true] {
                let objs = if swap {
                    format!("[{bez},{seg}]")
                } else {
                    format!("[{seg},{bez}]")
                };
                let json = format!(r#"{{"id":"sb","op":"intersect","objects":{objs}}}"#);
                let c = solve(&json);
                decided(&c, &json);
                let truths: Vec<Vec<Float>> = truths
                    .iter()
                    .map(|[s, t]| {
                        if swap {
                            vec![fl(s), fl(t)]
                        } else {
                            vec![fl(t), fl(s)]
                        }
                    })
                    .collect();
                let pts = points(&c.value);
                one_to_one(pts, &truths, &[false, false], &json);
                assert!(pts.iter().all(|p| p.multiplicity == 1), "{json}");
            }
        }
    }
}

/// Feet of `(x, y)` on the ellipse `(a cos u, b sin u)` near `u = 0` and `u = π`, by
/// Newton at 256 bits on `F(u) = −(x − a cos u)·a sin u + (y − b sin u)·b cos u`.
fn ellipse_feet(a: f64, b: f64, x: f64, y: f64) -> Vec<Float> {
    let f = |u: &Float| {
        let (s, c) = (
            Float::with_val(BITS, u.sin_ref()),
            Float::with_val(BITS, u.cos_ref()),
        );
        let val = -(Float::with_val(BITS, x - a * c.clone())) * a * s.clone()
            + (Float::with_val(BITS, y - b * s.clone())) * b * c.clone();
        // F'(u) = −a² sin² u − (x − a cos u)·a cos u − b² cos² u − (y − b sin u)·b sin u
        let der = -(Float::with_val(BITS, s.clone() * &s)) * (a * a)
            - Float::with_val(BITS, x - a * c.clone()) * a * c.clone()
            - Float::with_val(BITS, c.clone() * &c) * (b * b)
            - Float::with_val(BITS, y - b * s.clone()) * b * s;
        (val, der)
    };
    [0.0, 1.0]
        .iter()
        .map(|&k| {
            let mut u = Float::with_val(BITS, Constant::Pi) * k;
            for _ in 0..60 {
                let (v, d) = f(&u);
                u -= v / d;
            }
            u
        })
        .collect()
}

#[test]
fn points_projected_onto_ellipses_near_and_on_the_seam() {
    let mut rng = Rng::new(142);
    for _ in 0..40 {
        let a = rng.int(4, 40) as f64 / 4.0;
        let b = a * rng.int(1, 7) as f64 / 8.0;
        let x = a * (1.0 + rng.int(1, 16) as f64 / 8.0);
        let sign = if rng.coin() { 1.0 } else { -1.0 };
        for y in [0.0, f64::MIN_POSITIVE, 2f64.powi(-52), 1e-9, 1e-300] {
            let y = sign * y;
            let truths: Vec<Vec<Float>> = ellipse_feet(a, b, x, y)
                .into_iter()
                .map(|u| vec![u])
                .collect();
            for json in [
                format!(
                    r#"{{"id":"pe","op":"project","point":[{x:?},{y:?}],"onto":{{"type":"ellipse2","center":[0,0],"a":{a:?},"b":{b:?}}}}}"#
                ),
                format!(
                    r#"{{"id":"pe3","op":"project","point":[{x:?},{y:?},0],"onto":{{"type":"ellipse","center":[0,0,0],"a":{a:?},"b":{b:?},"axis":[0,0,1]}}}}"#
                ),
            ] {
                let c = solve(&json);
                decided(&c, &json);
                one_to_one(points(&c.value), &truths, &[true], &json);
            }
        }
    }
}

/// A straight quadratic Bézier along the x axis from the torus's outer equator at the
/// seam `u = v = 0`, through the torus: hits at `x = ±(R ± r)` inside the span, with
/// `u ∈ {0, π}` and `v ∈ {0, π}` (exact), `t = (x − x₀)/(x₂ − x₀)` (exact).
#[test]
fn curves_through_a_torus_seam() {
    let mut rng = Rng::new(144);
    for _ in 0..30 {
        let r = rng.int(1, 8) as f64 / 4.0;
        let big = r + rng.int(1, 16) as f64 / 4.0;
        let x0 = big + r;
        // the far end beyond the torus: an end at `u = π` is not decided yet
        let x2 = -(big + r) - rng.int(1, 8) as f64 / 4.0;
        let xs = [big + r, big - r, -(big - r), -(big + r)];
        let json = format!(
            r#"{{"id":"bt","op":"intersect","objects":[{{"type":"bezier","points":[[{x0:?},0,0],[{:?},0,0],[{x2:?},0,0]]}},{{"type":"torus","center":[0,0,0],"axis":[0,0,1],"major":{big:?},"minor":{r:?}}}]}}"#,
            (x0 + x2) / 2.0
        );
        let pi = Float::with_val(BITS, Constant::Pi);
        let zero = Float::new(BITS);
        let truths: Vec<Vec<Float>> = xs
            .iter()
            .map(|&x| {
                let t = fl(&((q(x) - q(x0)) / (q(x2) - q(x0))));
                let u = if x > 0.0 { zero.clone() } else { pi.clone() };
                let v = if x.abs() == big + r {
                    zero.clone()
                } else {
                    pi.clone()
                };
                vec![t, u, v]
            })
            .collect();
        let c = solve(&json);
        decided(&c, &json);
        let pts = points(&c.value);
        one_to_one(pts, &truths, &[false, true, true], &json);
        assert!(pts.iter().all(|p| p.multiplicity == 1), "{json}");
    }
}

/// The command line gives the decided answer too: a segment and a Bézier arc that
/// share their first point, and a Bézier ending on a torus's seam.
#[test]
fn the_command_line_decides_shared_ends() {
    let dir = std::env::temp_dir().join(format!("geocert-seams-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let file = dir.join("cases.jsonl");
    std::fs::write(
        &file,
        concat!(
            r#"{"id":"1","op":"intersect","objects":[{"type":"segment2","a":[-2,-1],"b":[2,1]},{"type":"bezier2","points":[[-2,-1],[0,3],[2,-1]]}]}"#,
            "\n",
            r#"{"id":"2","op":"intersect","objects":[{"type":"bezier","points":[[-3,0,0],[0,3,1],[3,0,0]]},{"type":"torus","center":[0.5,0,0],"major":2,"minor":0.5,"axis":[0,1,0]}]}"#,
            "\n"
        ),
    )
    .expect("writes");
    let out = Command::new(env!("CARGO_BIN_EXE_geocert"))
        .arg("solve")
        .arg(&file)
        .output()
        .expect("runs geocert");
    let text = String::from_utf8(out.stdout).expect("UTF-8");
    let lines: Vec<serde_json::Value> = text
        .lines()
        .map(|l| serde_json::from_str(l).expect("JSON"))
        .collect();
    assert_eq!(lines.len(), 2);
    // segment2 × bezier2: (t, s) = (0, 0) exactly and (0.75, 0.75), decided exactly
    // (ops::algebraic::bezier_line2)
    let first = &lines[0];
    assert_eq!(first["status"], "exact", "{first}");
    assert_eq!(first["complete"], true);
    let pts = first["points"].as_array().expect("points");
    assert_eq!(pts.len(), 2, "{first}");
    assert_eq!(
        pts[0]["param_box"],
        serde_json::json!([[[0.0, 0.0]], [[0.0, 0.0]]])
    );
    // bezier × torus: the end t = 1 at (3, 0, 0) is one point (u = v = 0), not four
    let second = &lines[1];
    assert_eq!(second["status"], "verified", "{second}");
    assert_eq!(second["complete"], true);
    let pts = second["points"].as_array().expect("points");
    assert_eq!(pts.len(), 2, "{second}");
    let end: Vec<_> = pts.iter().filter(|p| p["params"][0][0] == 1.0).collect();
    assert_eq!(end.len(), 1, "{second}");
    assert_eq!(end[0]["params"][1], serde_json::json!([0.0, 0.0]));
    let _ = std::fs::remove_dir_all(&dir);
}

/// Feet of `(ρ, z)` on the ellipse `(a cos w, c sin w)`, `w ∈ [0, 2π)`: sign changes
/// of `F(w) = −(ρ − a cos w)·a sin w + (z − c sin w)·c cos w` on a fine grid, each
/// bisected at 256 bits. `None` when two feet come too close for the grid.
fn meridian_feet(a: f64, c: f64, rho: f64, z: f64) -> Option<Vec<Float>> {
    let f = |w: &Float| {
        let (s, co) = (
            Float::with_val(BITS, w.sin_ref()),
            Float::with_val(BITS, w.cos_ref()),
        );
        -(Float::with_val(BITS, rho - a * co.clone())) * a * s.clone()
            + Float::with_val(BITS, z - c * s) * c * co
    };
    let n = 4096;
    let two_pi = Float::with_val(BITS, Constant::Pi) * 2;
    let at = |k: usize| Float::with_val(BITS, &two_pi * k as u32) / n as u32;
    let mut out = Vec::new();
    let mut prev = f(&at(0));
    for k in 1..=n {
        let next = f(&at(k));
        if prev.is_zero() {
            out.push(at(k - 1));
        } else if !next.is_zero() && (prev.is_sign_negative() != next.is_sign_negative()) {
            let (mut lo, mut hi) = (at(k - 1), at(k));
            let neg_lo = prev.is_sign_negative();
            for _ in 0..240 {
                let mid = Float::with_val(BITS, &lo + &hi) / 2u32;
                if f(&mid).is_sign_negative() == neg_lo {
                    lo = mid;
                } else {
                    hi = mid;
                }
            }
            out.push(lo);
        }
        prev = next;
    }
    let sep = out
        .windows(2)
        .all(|w| Float::with_val(BITS, &w[1] - &w[0]) > 1e-3);
    (sep && out.len() % 2 == 0).then_some(out)
}

/// Points projected onto spheroids (`a = b`), inside and outside, off the axis: every
/// foot lies in the point's meridian plane, so the truths are the feet on the
/// meridian ellipse (`w ↦ (u₀, w)` or `(u₀ + π, π − w)`). The poles solve the
/// parametric foot equations for every such point without being feet: they must be
/// proven no answer, not left undecided.
#[test]
fn points_projected_onto_spheroids_off_the_axis() {
    let mut rng = Rng::new(1441);
    let mut run = 0;
    while run < 30 {
        let a = rng.int(2, 16) as f64 / 4.0;
        let c = a * rng.int(1, 7) as f64 / 8.0;
        let p = [0, 1, 2].map(|_| rng.int(-24, 24) as f64 / 8.0);
        let rho2 = p[0] * p[0] + p[1] * p[1];
        if rho2 < 1.0 / 64.0 {
            continue;
        }
        let rho = Float::with_val(BITS, rho2).sqrt();
        let Some(ws) = meridian_feet(a, c, rho.to_f64(), p[2]) else {
            continue;
        };
        run += 1;
        let pi = Float::with_val(BITS, Constant::Pi);
        let u0 = Float::with_val(
            BITS,
            Float::with_val(BITS, p[1]).atan2_ref(&Float::with_val(BITS, p[0])),
        );
        let half = Float::with_val(BITS, &pi / 2u32);
        let truths: Vec<Vec<Float>> = ws
            .into_iter()
            .map(|w| {
                // w in (−π/2, π/2] (mod 2π) is on the u₀ half of the meridian
                let w = if w > Float::with_val(BITS, &pi * 3u32) / 2u32 {
                    Float::with_val(BITS, &w - Float::with_val(BITS, &pi * 2u32))
                } else {
                    w
                };
                if w <= half {
                    vec![u0.clone(), w]
                } else {
                    vec![
                        Float::with_val(BITS, &u0 + &pi),
                        Float::with_val(BITS, &pi - &w),
                    ]
                }
            })
            .collect();
        let json = format!(
            r#"{{"id":"sp","op":"project","point":{p:?},"onto":{{"type":"ellipsoid","center":[0,0,0],"a":{a:?},"b":{a:?},"c":{c:?}}}}}"#
        );
        let c = solve(&json);
        decided(&c, &json);
        one_to_one(points(&c.value), &truths, &[true, false], &json);
    }
}
