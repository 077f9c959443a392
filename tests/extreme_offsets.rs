//! Extreme offsets and the promise on every reported number (issues 14 and 20; the
//! fuzz findings of docs/RELIABILITY.md items 1, 2, 4, 5): generated families of
//!
//! - lines along a coordinate axis against cylinders, cones, spheres and tori placed
//!   far along it (1e150, 1e200, 5.9e208) or scaled by powers of two (1e±150), with the
//!   line passing the seam `u = 0` exactly, or 1e-3 … 1e-15 and a few ulps off it;
//! - projections onto parabolas, ellipses and hyperbolas with tiny (down to subnormal)
//!   and huge parameters and axis components.
//!
//! Every answer must keep the invariant of `geocert::ops::promise` (no `NaN`, every
//! estimate in its box, every `param_box` in its object's domain). Certified
//! intersections must be `complete` with one box per truth: the truths are the
//! roots of the surfaces' implicit equations on the line, computed in MPFR at 3000
//! bits from the doubles of the case (independently of the library), with their
//! parameters `u` (modulo 2π), `v` and the line's `t`. Certified projection feet must
//! hold a sign change of the foot condition `(c(t) − q)·c'(t)` (MPFR) or a range end.

#![allow(clippy::needless_range_loop)]

mod truth_support;

use geocert::certificate::Status;
use geocert::num::rng::Rng;
use geocert::ops::{Answer, Point};
use geocert::Certified;
use rug::float::Constant;
use rug::Float;
use truth_support::front_door as solve;

/// `(u, v)` of the hit at the offset `w` along the line, if it is one.
type UvAt = Box<dyn FnMut(&Float) -> Option<[Float; 2]>>;

const BITS: u32 = 3000;

fn f(x: f64) -> Float {
    Float::with_val(BITS, x)
}

fn two_pi() -> Float {
    Float::with_val(BITS, Constant::Pi) * 2u32
}

/// One parameter's domain: `[lo, hi]` and whether it is periodic (the ends of a whole
/// turn are `0` and `2π` rounded up, as reported).
#[derive(Clone, Copy)]
struct Dom {
    lo: f64,
    hi: f64,
}

const TURN: Dom = Dom {
    lo: 0.0,
    hi: 6.283185307179587, // 2π rounded up
};

/// `lo ≤ x ≤ hi`, `x` not NaN, and an infinite `x` only at an infinite end of its box.
fn in_box(x: f64, [lo, hi]: [f64; 2], what: &str) {
    assert!(!x.is_nan() && !lo.is_nan() && !hi.is_nan(), "{what}: NaN");
    assert!(lo <= x && x <= hi, "{what}: {x} outside [{lo}, {hi}]");
}

/// The invariant on every point of an answer; `domains[i]` per object (`None`: not
/// checked, a line's parameter).
fn invariant(c: &Certified<Answer>, domains: &[Option<Vec<Dom>>], case: &str) {
    let pts: &[Point] = match &c.value {
        Answer::Points(p) => p,
        Answer::Empty => &[],
        other => panic!("expected points, got {other:?}: {case}"),
    };
    for p in pts {
        assert_eq!(p.xyz.len(), p.xyz_box.len(), "{case}");
        for (x, b) in p.xyz.iter().zip(&p.xyz_box) {
            in_box(*x, *b, &format!("xyz of {case}"));
        }
        for d in [p.distance, p.signed_distance].into_iter().flatten() {
            assert!(!d.is_nan(), "a NaN distance: {case}");
        }
        let Some(pb) = p.param_box.as_ref() else {
            assert!(p.params.iter().flatten().all(|x| !x.is_nan()), "{case}");
            continue;
        };
        for (i, (ps, bs)) in p.params.iter().zip(pb).enumerate() {
            assert_eq!(ps.len(), bs.len(), "{case}");
            for (j, (x, b)) in ps.iter().zip(bs).enumerate() {
                in_box(*x, *b, &format!("params[{i}][{j}] of {case}"));
                if let Some(d) = domains.get(i).and_then(|d| d.as_ref()).map(|d| d[j]) {
                    assert!(
                        d.lo <= b[0] && b[1] <= d.hi,
                        "param_box[{i}][{j}] {b:?} outside [{}, {}]: {case}",
                        d.lo,
                        d.hi
                    );
                }
            }
        }
    }
}

/// `x` in `[lo, hi]`, as MPFR.
fn holds(b: [f64; 2], x: &Float) -> bool {
    *x >= b[0] && *x <= b[1]
}

/// An angle truth in `[0, 2π)` inside a box of the domain, modulo 2π.
fn holds_angle(b: [f64; 2], x: &Float) -> bool {
    holds(b, x) || holds(b, &(x.clone() + two_pi()))
}

/// `atan2(y, x)` in `[0, 2π)`.
fn angle(y: &Float, x: &Float) -> Float {
    let a = Float::with_val(BITS, y.atan2_ref(x));
    if a < 0 {
        a + two_pi()
    } else {
        a
    }
}

/// One truth: the line's `t`, the point, and the surface's `(u, v)` (`u`, and for a
/// torus `v`, periodic).
struct Truth {
    t: Float,
    xyz: [Float; 3],
    uv: [Float; 2],
    v_periodic: bool,
}

/// The surfaces of the family, each met by the line `(x0, y0, oz) + t·(0, 0, 1)`.
#[derive(Debug, Clone, Copy)]
enum Kind {
    /// Axis +x, origin `c`, radius `r`, height `[-h, h]`.
    Cylinder { r: f64 },
    /// Axis +x, origin `c`, radius `r` at `v = 0`, half-angle `a`, height `[-h, h]`.
    Cone { r: f64, a: f64 },
    /// Centre `c`, radius `r`, axis +z.
    Sphere { r: f64 },
    /// Centre `c`, axis +z, radii `R`, `r`.
    Torus { big: f64, r: f64 },
}

struct Case {
    kind: Kind,
    c: [f64; 3],
    h: f64,
    x0: f64,
    y0: f64,
    oz: f64,
}

impl Case {
    fn json(&self) -> String {
        let line = format!(
            r#"{{"type":"line","origin":[{:e},{:e},{:e}],"dir":[0,0,1]}}"#,
            self.x0, self.y0, self.oz
        );
        let c = format!("[{:e},{:e},{:e}]", self.c[0], self.c[1], self.c[2]);
        let h = self.h;
        let surface = match self.kind {
            Kind::Cylinder { r } => format!(
                r#"{{"type":"cylinder","origin":{c},"axis":[1,0,0],"radius":{r:e},"height":[{:e},{h:e}]}}"#,
                -h
            ),
            Kind::Cone { r, a } => format!(
                r#"{{"type":"cone","origin":{c},"axis":[1,0,0],"radius":{r:e},"half_angle":{a:e},"height":[{:e},{h:e}]}}"#,
                -h
            ),
            Kind::Sphere { r } => format!(r#"{{"type":"sphere","center":{c},"radius":{r:e}}}"#),
            Kind::Torus { big, r } => format!(
                r#"{{"type":"torus","center":{c},"axis":[0,0,1],"major":{big:e},"minor":{r:e}}}"#
            ),
        };
        format!(r#"{{"op":"intersect","objects":[{line},{surface}],"options":{{"time_limit":1}}}}"#)
    }

    fn domains(&self) -> Vec<Option<Vec<Dom>>> {
        let h = Dom {
            lo: -self.h,
            hi: self.h,
        };
        let v = match self.kind {
            Kind::Cylinder { .. } | Kind::Cone { .. } => h,
            Kind::Sphere { .. } => Dom {
                lo: -1.5707963267948968,
                hi: 1.5707963267948968,
            },
            Kind::Torus { .. } => TURN,
        };
        vec![None, Some(vec![TURN, v])]
    }

    /// The truths by increasing `t` (module doc).
    fn truths(&self) -> Vec<Truth> {
        let [cx, cy, cz] = self.c.map(f);
        let (x0, y0, oz) = (f(self.x0), f(self.y0), f(self.oz));
        let (dx, dy) = (x0.clone() - &cx, y0.clone() - &cy);
        // Each kind: offsets `w = z − cz` of the hits, with (u, v) at each.
        let mut hits: Vec<(Float, [Float; 2])> = Vec::new();
        let mut push_pm = |d2: Float, mut uv: UvAt| {
            if d2 > 0 {
                let s = d2.sqrt();
                for w in [-s.clone(), s] {
                    if let Some(p) = uv(&w) {
                        hits.push((w, p));
                    }
                }
            }
        };
        match self.kind {
            Kind::Cylinder { r } | Kind::Cone { r, .. } => {
                let k = match self.kind {
                    Kind::Cone { a, .. } => f(a).tan(),
                    _ => f(0.0),
                };
                // Axis x: X = +y, Y = +z; ζ = x0 − cx along the whole line.
                let rho = f(r) + k * &dx;
                let inside = dx >= -self.h && dx <= self.h;
                let flip = rho < 0;
                let d2 = rho.clone() * &rho - dy.clone() * &dy;
                let (dx, dy) = (dx.clone(), dy.clone());
                push_pm(
                    d2,
                    Box::new(move |w: &Float| {
                        let u = if flip {
                            angle(&(-w.clone()), &(-dy.clone()))
                        } else {
                            angle(w, &dy)
                        };
                        inside.then(|| [u, dx.clone()])
                    }),
                );
            }
            Kind::Sphere { r } => {
                let rho2 = dx.clone() * &dx + dy.clone() * &dy;
                let rho = rho2.clone().sqrt();
                let u = angle(&dy, &dx);
                push_pm(
                    f(r) * f(r) - rho2,
                    Box::new(move |w: &Float| {
                        Some([u.clone(), Float::with_val(BITS, w.atan2_ref(&rho))])
                    }),
                );
            }
            Kind::Torus { big, r } => {
                let rho = (dx.clone() * &dx + dy.clone() * &dy).sqrt();
                let u = angle(&dy, &dx);
                let off = rho - f(big);
                push_pm(
                    f(r) * f(r) - off.clone() * &off,
                    Box::new(move |w: &Float| Some([u.clone(), angle(w, &off)])),
                );
            }
        }
        let mut out: Vec<Truth> = hits
            .into_iter()
            .map(|(w, uv)| {
                let z = w + &cz;
                Truth {
                    t: z.clone() - &oz,
                    xyz: [x0.clone(), y0.clone(), z],
                    uv,
                    v_periodic: matches!(self.kind, Kind::Torus { .. }),
                }
            })
            .collect();
        out.sort_by(|a, b| a.t.partial_cmp(&b.t).unwrap());
        out
    }
}

/// Whether the point's boxes hold the truth.
fn matches(p: &Point, t: &Truth) -> bool {
    let pb = p.param_box.as_ref().unwrap();
    let v_ok = if t.v_periodic {
        holds_angle(pb[1][1], &t.uv[1])
    } else {
        holds(pb[1][1], &t.uv[1])
    };
    (0..3).all(|i| holds(p.xyz_box[i], &t.xyz[i]))
        && holds(pb[0][0], &t.t)
        && holds_angle(pb[1][0], &t.uv[0])
        && v_ok
}

/// Solve, check the invariant, and for a certified answer one box per truth.
fn check(case: &Case, stats: &mut [usize; 3]) {
    let json = case.json();
    let c = solve(&json);
    invariant(&c, &case.domains(), &json);
    // The cases carry a one-second time limit: on a loaded machine the search may stop
    // there, which must be said (reason "time limit reached"); otherwise a certified
    // answer here is complete.
    let timed_out = c
        .reason
        .as_deref()
        .is_some_and(|r| r.contains(geocert::certify::TIME_LIMIT));
    if c.status == Status::Undecided || (!c.complete && timed_out) {
        stats[2] += 1;
        return;
    }
    let truths = case.truths();
    let pts = c.value.points();
    assert!(c.complete, "certified but not complete: {json}");
    // Each truth in exactly one box; a simple box holds exactly one truth, a singular
    // box (a double root of a perturbation no larger than `perturbation`) at most two.
    for t in &truths {
        let n = pts.iter().filter(|p| matches(p, t)).count();
        assert_eq!(
            n,
            1,
            "truth t = {} in {n} boxes: {json}\n{c:?}",
            t.t.to_f64()
        );
    }
    for p in pts {
        let n = truths.iter().filter(|t| matches(p, t)).count();
        if p.multiplicity == 1 {
            assert_eq!(n, 1, "a simple box with {n} truths: {json}\n{c:?}");
        } else {
            assert!(n <= 2, "a singular box with {n} truths: {json}\n{c:?}");
        }
    }
    stats[usize::from(!truths.is_empty())] += 1;
}

/// A dyadic in `[-4, 4)` with a few bits (exact transverse positions).
fn small(rng: &mut Rng) -> f64 {
    f64::from(rng.int(-64, 63) as i32) / 16.0
}

/// Offsets from the seam: exactly on it, 1e-3 … 1e-15 off, a few ulps off.
fn seam_gap(rng: &mut Rng, x: f64) -> f64 {
    match rng.below(6) {
        0 => 0.0,
        1 => 1e-3,
        2 => 1e-9,
        3 => 1e-15,
        4 => x.abs() * f64::EPSILON * (1 + rng.below(4)) as f64,
        _ => -(x.abs() * f64::EPSILON * (1 + rng.below(4)) as f64),
    }
}

/// Far along the line: `T·m` with `T` among 1e150, 1e200, 5.9e208 and the fuzz
/// finding's own offset, or small.
fn far(rng: &mut Rng) -> f64 {
    let t = [1e150, 1e200, 5.907379186307079e208, 1.0][rng.below(4)];
    let m = 1.0 + rng.unit();
    if rng.coin() {
        t * m
    } else {
        -t * m
    }
}

fn line_case(rng: &mut Rng, kind: usize) -> Case {
    let (x0, y0, oz) = (small(rng), small(rng), small(rng));
    let cz = far(rng);
    match kind {
        0 | 1 => {
            // Axis x through (cx, cy, cz): hits at u near 0 / 2π when |y0 − cy| ≈ ρ.
            let r = 1.0 + rng.below(4) as f64;
            // ζ = x0 − cx, the height of the whole line on the axis.
            let zeta = small(rng);
            let (kind, rho) = if kind == 0 {
                (Kind::Cylinder { r }, r)
            } else {
                let a = [-0.5, 0.25, std::f64::consts::FRAC_PI_4][rng.below(3)];
                (Kind::Cone { r, a }, (r + a.tan() * zeta).abs())
            };
            // ρ·(1 − gap) from the line: the two hits straddle the seam at w = 0.
            // (a gap of at least 1e-12: the rounding of cy stays far below it).
            let gap = seam_gap(rng, 1.0).abs().max(1e-12);
            let cy = y0 - rho * (1.0 - gap);
            let cx = x0 - zeta;
            Case {
                kind,
                c: [cx, cy, cz],
                h: 10.0,
                x0,
                y0,
                oz,
            }
        }
        _ => {
            // Sphere or torus about z: u = atan2(y0 − cy, x0 − cx), on the seam when
            // y0 = cy and x0 > cx, just off it with cy moved by the gap.
            let cy = y0 - seam_gap(rng, y0);
            let kind = if kind == 2 {
                Kind::Sphere {
                    r: 2.0 + rng.below(3) as f64,
                }
            } else {
                Kind::Torus { big: 3.0, r: 1.5 }
            };
            let cx = x0 - [0.5, 1.0, 2.0, 3.25][rng.below(4)];
            Case {
                kind,
                c: [cx, cy, cz],
                h: 0.0,
                x0,
                y0,
                oz,
            }
        }
    }
}

/// Lines along z against each quadric and torus placed far along z (1e150 … 5.9e208),
/// passing the seam exactly or within 1e-3 … a few ulps.
#[test]
fn lines_meet_far_surfaces_at_and_near_the_seam() {
    let mut rng = Rng::new(0x5eed_0014);
    let mut stats = [0usize; 3];
    for i in 0..80 {
        let case = line_case(&mut rng, i % 4);
        check(&case, &mut stats);
    }
    // Most cases are decided, and most decided ones have hits.
    assert!(
        stats[1] >= 40,
        "empty / decided with hits / undecided: {stats:?}"
    );
}

/// The same configurations scaled by powers of two (exact): 2^±500 ≈ 1e±150.
#[test]
fn scaled_configurations_keep_their_truths() {
    let mut rng = Rng::new(0x5eed_0020);
    let mut stats = [0usize; 3];
    for i in 0..40 {
        let mut case = line_case(&mut rng, i % 4);
        case.c[2] = small(&mut rng) * 4.0;
        let s = [2f64.powi(500), 2f64.powi(-500)][i % 2];
        case.c = case.c.map(|x| x * s);
        (case.x0, case.y0, case.oz) = (case.x0 * s, case.y0 * s, case.oz * s);
        case.h *= s;
        case.kind = match case.kind {
            Kind::Cylinder { r } => Kind::Cylinder { r: r * s },
            Kind::Cone { r, a } => Kind::Cone { r: r * s, a },
            Kind::Sphere { r } => Kind::Sphere { r: r * s },
            Kind::Torus { big, r } => Kind::Torus {
                big: big * s,
                r: r * s,
            },
        };
        check(&case, &mut stats);
    }
    assert!(
        stats[1] >= 18,
        "empty / decided with hits / undecided: {stats:?}"
    );
}

/// The fuzz finding of item 2 itself, with its neighbours: the line meets the far cone
/// twice, verified and complete, each `u` box in `[0, 2π]` around its estimate.
#[test]
fn the_far_cone_finding_and_its_neighbours() {
    for dz in [-8.0, 0.0, 8.0, 1e100] {
        let case = Case {
            kind: Kind::Cone { r: 0.0, a: -0.5 },
            c: [-8.0, -1.0000000000000004, 5.907379186307079e208],
            h: 0.0,
            x0: -0.9999999999999999,
            y0: -2.0000000000000013,
            oz: dz,
        };
        let json = case.json().replace(
            r#""height":[-0e0,0e0]"#,
            r#""height":[0,7.999999999999999]"#,
        );
        let c = solve(&json);
        let doms = vec![
            None,
            Some(vec![
                TURN,
                Dom {
                    lo: 0.0,
                    hi: 7.999999999999999,
                },
            ]),
        ];
        invariant(&c, &doms, &json);
        assert_ne!(c.status, Status::Undecided, "{json}");
        assert!(c.complete);
        assert_eq!(c.value.points().len(), 2, "{json}\n{c:?}");
    }
}

/// The foot condition `g(t) = (c(t) − q)·c'(t)` of a parabola `vertex + t²/(2p)·X +
/// t·Y` (frame of FORMAT.md "Frames" from `axis`, computed here in MPFR).
fn parabola_foot(axis: [f64; 3], vertex: [f64; 3], p: f64, q: [f64; 3], t: &Float) -> Float {
    let a = axis.map(f);
    let mags = axis.map(f64::abs);
    let mut i = 0;
    for j in 1..3 {
        if mags[j] < mags[i] {
            i = j;
        }
    }
    let mut e = [f(0.0), f(0.0), f(0.0)];
    e[i] = f(1.0);
    let dot = |x: &[Float; 3], y: &[Float; 3]| {
        x[0].clone() * &y[0] + x[1].clone() * &y[1] + x[2].clone() * &y[2]
    };
    let aa = dot(&a, &a);
    let ea = dot(&e, &a);
    let w: [Float; 3] = std::array::from_fn(|k| e[k].clone() * &aa - ea.clone() * &a[k]);
    let wl = dot(&w, &w).sqrt();
    let x: [Float; 3] = std::array::from_fn(|k| w[k].clone() / &wl);
    let al = aa.sqrt();
    let z: [Float; 3] = std::array::from_fn(|k| a[k].clone() / &al);
    let y: [Float; 3] = std::array::from_fn(|k| {
        let (j, l) = ((k + 1) % 3, (k + 2) % 3);
        z[j].clone() * &x[l] - z[l].clone() * &x[j]
    });
    let pp = f(p);
    let c: [Float; 3] = std::array::from_fn(|k| {
        f(vertex[k]) + t.clone() * t / (pp.clone() * 2u32) * &x[k] + t.clone() * &y[k] - f(q[k])
    });
    let d: [Float; 3] = std::array::from_fn(|k| t.clone() / &pp * &x[k] + &y[k]);
    dot(&c, &d)
}

/// Projections onto parabolas with subnormal to huge `p` and huge axis components
/// (the fuzz finding of item 4 and its neighbours), and onto ellipses and hyperbolas
/// with tiny and huge semi-axes: the invariant on every answer; each certified foot
/// of a parabola holds a sign change of the foot condition or an end of the range.
#[test]
fn projections_onto_conics_with_extreme_parameters() {
    let mut rng = Rng::new(0x5eed_0004);
    let tiny_huge: [f64; 7] = [5.7348403e-317, 1e-300, 1e-150, 1e-8, 4.35, 1e150, 1e300];
    let mut certified = 0;
    for i in 0..60 {
        let p = tiny_huge[rng.below(tiny_huge.len())];
        let mut axis = [small(&mut rng), small(&mut rng), small(&mut rng)];
        if axis.iter().all(|&x| x == 0.0) {
            axis[2] = 1.0;
        }
        if rng.coin() {
            axis[rng.below(3)] = [-4.603453896634276e294, 1e200, -1e-300][rng.below(3)];
        }
        let vertex = [small(&mut rng), small(&mut rng), small(&mut rng)];
        let q = [small(&mut rng), small(&mut rng), small(&mut rng)];
        let nearest = i % 2 == 0;
        let onto = match i % 6 {
            0..=3 => format!(
                r#"{{"type":"parabola","vertex":{vertex:?},"axis":{axis:?},"p":{p:e},"range":[-2,2]}}"#
            ),
            4 => format!(
                r#"{{"type":"ellipse","center":{vertex:?},"axis":{axis:?},"a":{:e},"b":{p:e}}}"#,
                p.max(1e-300) * 2.0
            ),
            _ => format!(
                r#"{{"type":"hyperbola","center":{vertex:?},"axis":{axis:?},"a":{p:e},"b":1.5,"range":[-2,2]}}"#
            ),
        };
        let json = format!(
            r#"{{"op":"project","nearest":{nearest},"point":{q:?},"onto":{onto},"options":{{"time_limit":0.25,"max_boxes":2000}}}}"#
        );
        let c = solve(&json);
        invariant(&c, &[None], &json);
        if c.status == Status::Undecided || i % 6 > 3 {
            continue;
        }
        certified += 1;
        for pt in c.value.points() {
            if pt.multiplicity > 1 {
                continue; // a double root of the foot condition need not change sign
            }
            let [lo, hi] = pt.param_box.as_ref().unwrap()[0][0];
            if lo <= -2.0 || hi >= 2.0 {
                continue; // an end of the range (nearest) or a foot beside it
            }
            let g = |t: f64| parabola_foot(axis, vertex, p, q, &f(t));
            let (a, b) = (g(lo), g(hi));
            assert!(
                a.is_sign_negative() != b.is_sign_negative() || a.is_zero() || b.is_zero(),
                "no sign change of the foot condition over [{lo}, {hi}]: {json}\n{c:?}"
            );
        }
    }
    assert!(certified >= 6, "only {certified} certified projections");
}
