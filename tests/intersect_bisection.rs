//! Curve ∩ implicit surface by bisection (OPERATIONS.md §13.4, (13.8)), through the
//! case format with `options.method = "bisection"`: seeded families of segments against
//! spheres, ellipsoids, cylinders (a patch: its `height`), tori and general `quadric`
//! matrices, and of circles against spheres and cylinders.
//!
//! Truth: the roots in closed form in MPFR at `truth_support::BITS` bits from the exact
//! double inputs — a quadratic in `t` for a segment against a quadric, two quadratics
//! for a segment in a plane `z = const` across a torus about `z` (the section is two
//! circles), `A cos t + B sin t + D = 0` for a circle against a sphere or a coaxial
//! cylinder. Each case checks that
//!
//! 1. the float path (`ops::intersect_bisection_f64`) finds exactly as many roots as
//!    the truth has sign changes (simple roots on the object), each within `1e-10` of
//!    its truth;
//! 2. the certified answer is `verified` and `complete`, one parameter box per truth
//!    and one truth per box, and the same for the point boxes.
//!
//! Cases whose roots lie closer than 1/100 of the range to each other or to an end of
//! the curve (or of a cylinder's height) are drawn again: there the sampling of §13.4
//! may see no sign change, which is the method's documented limit (the certified answer
//! still finds such roots: the tangency tests below).

use geocert::io::{options, read_cases, shape};
use geocert::num::rng::Rng;
use geocert::ops;
use rug::Float;

mod truth_support;
use truth_support::{
    box_holds, cases, count, docs_frame, fl, nums, one_to_one, param_boxes, point_boxes, solve,
    BITS,
};

/// `F(x) = xᵀAx + 2bᵀx + c`, exactly from doubles.
struct QuadricTruth {
    a: [[Float; 3]; 3],
    b: [Float; 3],
    c: Float,
}

impl QuadricTruth {
    fn from_matrix(q: &[[f64; 4]; 4]) -> QuadricTruth {
        QuadricTruth {
            a: std::array::from_fn(|i| std::array::from_fn(|j| fl(q[i][j]))),
            b: std::array::from_fn(|i| fl(q[i][3])),
            c: fl(q[3][3]),
        }
    }

    /// `Σ (xᵢ − cᵢ)²·kᵢ − r²`: an axis-aligned quadric about `centre`.
    fn axis_aligned(centre: [f64; 3], k: [Float; 3], r2: Float) -> QuadricTruth {
        let c: [Float; 3] = centre.map(fl);
        QuadricTruth {
            a: std::array::from_fn(|i| {
                std::array::from_fn(|j| if i == j { k[i].clone() } else { fl(0.0) })
            }),
            b: std::array::from_fn(|i| -(k[i].clone() * &c[i])),
            c: (0..3).fold(-r2, |s, i| s + k[i].clone() * &c[i] * &c[i]),
        }
    }

    /// The roots in `[0, 1]` of `F(a + t·(b − a))`, simple roots only (a double root
    /// is no sign change), increasing.
    fn segment_roots(&self, p: &[f64; 3], q: &[f64; 3]) -> Vec<Float> {
        let a: [Float; 3] = p.map(fl);
        let d: [Float; 3] = std::array::from_fn(|i| fl(q[i]) - fl(p[i]));
        let mul = |v: &[Float; 3]| -> [Float; 3] {
            std::array::from_fn(|i| (0..3).fold(fl(0.0), |s, j| s + self.a[i][j].clone() * &v[j]))
        };
        let dot =
            |x: &[Float; 3], y: &[Float; 3]| (0..3).fold(fl(0.0), |s, i| s + x[i].clone() * &y[i]);
        let (ad, aa) = (mul(&d), mul(&a));
        let alpha = dot(&d, &ad);
        let beta = dot(&d, &aa) + dot(&d, &self.b);
        let gamma = dot(&a, &aa) + fl(2.0) * dot(&a, &self.b) + &self.c;
        quadratic_roots(alpha, beta, gamma)
    }
}

/// The simple real roots in `[0, 1]` of `α t² + 2β t + γ` (α ≠ 0), increasing.
fn quadratic_roots(alpha: Float, beta: Float, gamma: Float) -> Vec<Float> {
    let disc = beta.clone() * &beta - alpha.clone() * &gamma;
    if disc <= 0 {
        return Vec::new();
    }
    let w = disc.sqrt();
    let mut r = vec![(-beta.clone() - &w) / &alpha, (-beta + &w) / &alpha];
    r.sort_by(|x, y| x.partial_cmp(y).expect("finite"));
    r.retain(|t| *t >= 0 && *t <= 1);
    r
}

/// The roots of `A cos t + B sin t + D = 0` in `[0, 2π)`, simple ones only.
fn trig_roots(a: Float, b: Float, d: Float) -> Vec<Float> {
    let rho = (a.clone() * &a + b.clone() * &b).sqrt();
    let c = -d / &rho;
    if c.clone().abs() >= 1 {
        return Vec::new();
    }
    let phi = b.atan2(&a);
    let delta = c.acos();
    let tau = Float::with_val(BITS, rug::float::Constant::Pi) * 2u32;
    let mut r: Vec<Float> = [phi.clone() - &delta, phi + &delta]
        .into_iter()
        .map(|t| {
            let mut t = t % &tau;
            if t < 0 {
                t += &tau;
            }
            t
        })
        .collect();
    r.sort_by(|x, y| x.partial_cmp(y).expect("finite"));
    r
}

/// The family's cases are drawn until their roots are separated ([`separated`]).
fn separated(roots: &[f64], range: [f64; 2]) -> bool {
    let gap = 0.01 * (range[1] - range[0]);
    roots
        .iter()
        .all(|&t| t - range[0] > gap && range[1] - t > gap)
        && roots.windows(2).all(|w| w[1] - w[0] > gap)
}

fn to_f64(v: &[Float]) -> Vec<f64> {
    v.iter().map(Float::to_f64).collect()
}

/// A case checked (module doc): `objects` is the JSON of the two objects, the curve
/// first; `implicit` the curve parameters of the roots of `F(c(t))` (what the float
/// path sees), `truths` those of the points on the object (fewer on a patch), `points`
/// their points.
fn check(id: &str, objects: &str, implicit: &[Float], truths: &[Float], points: &[[Float; 3]]) {
    let json = format!(
        r#"{{"id":"{id}","op":"intersect","objects":[{objects}],"options":{{"method":"bisection"}}}}"#
    );
    // 1. The float path.
    let case = read_cases(&json)
        .pop()
        .expect("one case")
        .case
        .expect("valid");
    let shapes: Vec<_> = case
        .objects
        .iter()
        .map(|o| shape(o, "objects").expect("shape"))
        .collect();
    let float = ops::intersect_bisection_f64(&shapes, &options(&case).expect("options"))
        .expect("the float path runs");
    assert_eq!(
        float.len(),
        implicit.len(),
        "{id}: {float:?} for {:?}",
        to_f64(implicit)
    );
    for (t, truth) in float.iter().zip(implicit) {
        let err = (Float::with_val(BITS, *t) - truth).abs().to_f64();
        assert!(err <= 1e-10, "{id}: root {t} is {err:e} from its truth");
    }
    // 2. The certified answer.
    let r = solve(&json);
    assert_eq!(r.status, "verified", "{id}: {r:?}");
    assert_eq!(r.complete, Some(true), "{id}: {r:?}");
    assert_eq!(count(&r), truths.len(), "{id}: {r:?}");
    let boxes = param_boxes(&r, 0);
    let ts: Vec<Vec<Float>> = truths.iter().map(|t| vec![t.clone()]).collect();
    one_to_one(&boxes, &ts).unwrap_or_else(|e| panic!("{id}: {e}: {r:?}"));
    let xyz: Vec<Vec<Float>> = points.iter().map(|p| p.to_vec()).collect();
    one_to_one(&point_boxes(&r), &xyz).unwrap_or_else(|e| panic!("{id}: {e}: {r:?}"));
}

/// The point `a + t·(b − a)` of a segment.
fn on_segment(p: &[f64; 3], q: &[f64; 3], t: &Float) -> [Float; 3] {
    std::array::from_fn(|i| fl(p[i]) + (fl(q[i]) - fl(p[i])) * t)
}

fn segment_json(p: &[f64; 3], q: &[f64; 3]) -> String {
    format!(r#"{{"type":"segment","a":{},"b":{}}}"#, nums(p), nums(q))
}

fn dot3(a: &[f64; 3], b: &[f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn point_in(rng: &mut Rng, half: f64) -> [f64; 3] {
    std::array::from_fn(|_| half * rng.unit())
}

/// Draw segments against one surface until `n` cases with separated roots are checked;
/// `truth` gives the roots of `F(c(t))` and those on the object (`None`: draw again),
/// `json` the surface. Three segments in four are aimed through a point near `aim`, so
/// that most cases cross the surface.
fn segment_family(
    name: &str,
    seed: u64,
    half: f64,
    aim: [f64; 3],
    json: &str,
    truth: impl Fn(&[f64; 3], &[f64; 3]) -> Option<(Vec<Float>, Vec<Float>)>,
) {
    let mut rng = Rng::new(seed);
    let (mut done, mut implicit_seen, mut roots_seen) = (0, 0, 0);
    let n = cases(10);
    for k in 0..50 * n {
        if done == n {
            break;
        }
        let aimed = rng.below(4) != 0;
        let p = if aimed {
            // from the sphere of radius `half` about `aim`, through the surface
            let u = point_in(&mut rng, 1.0);
            let l = dot3(&u, &u).sqrt().max(1e-3);
            std::array::from_fn(|i| aim[i] + half * u[i] / l)
        } else {
            point_in(&mut rng, half)
        };
        let q = if !aimed {
            point_in(&mut rng, half)
        } else {
            let m = point_in(&mut rng, 0.3);
            std::array::from_fn(|i| 2.0 * (aim[i] + m[i]) - p[i])
        };
        let Some((implicit, roots)) = truth(&p, &q) else {
            continue;
        };
        if !separated(&to_f64(&implicit), [0.0, 1.0]) {
            continue;
        }
        let points: Vec<[Float; 3]> = roots.iter().map(|t| on_segment(&p, &q, t)).collect();
        check(
            &format!("{name}-{seed}-{k}"),
            &format!("{},{json}", segment_json(&p, &q)),
            &implicit,
            &roots,
            &points,
        );
        done += 1;
        implicit_seen += implicit.len();
        roots_seen += roots.len();
    }
    assert_eq!(done, n, "{name}: only {done} separated cases drawn");
    assert!(
        implicit_seen >= n && 2 * roots_seen >= n,
        "{name}: the family met the surface only {roots_seen} times ({implicit_seen} F = 0)"
    );
}

/// The roots of a surface that is its whole implicit surface: the same for both.
fn whole(roots: Vec<Float>) -> Option<(Vec<Float>, Vec<Float>)> {
    Some((roots.clone(), roots))
}

#[test]
fn segments_against_spheres() {
    for seed in 0..3u64 {
        let mut rng = Rng::new(100 + seed);
        let c = point_in(&mut rng, 1.0);
        let r = 1.0 + rng.unit().abs();
        let json = format!(r#"{{"type":"sphere","center":{},"radius":{r}}}"#, nums(&c));
        let q = QuadricTruth::axis_aligned(c, [fl(1.0), fl(1.0), fl(1.0)], fl(r) * fl(r));
        segment_family("sphere", seed, 3.0, c, &json, |a, b| {
            whole(q.segment_roots(a, b))
        });
    }
}

#[test]
fn segments_against_ellipsoids() {
    for seed in 0..3u64 {
        let mut rng = Rng::new(200 + seed);
        let c = point_in(&mut rng, 1.0);
        let ax: [f64; 3] = std::array::from_fn(|_| 0.5 + 2.0 * rng.unit().abs());
        let json = format!(
            r#"{{"type":"ellipsoid","center":{},"a":{},"b":{},"c":{},"axis":[0,0,1]}}"#,
            nums(&c),
            ax[0],
            ax[1],
            ax[2]
        );
        let k = ax.map(|x| fl(1.0) / (fl(x) * fl(x)));
        let q = QuadricTruth::axis_aligned(c, k, fl(1.0));
        segment_family("ellipsoid", seed, 3.5, c, &json, |a, b| {
            whole(q.segment_roots(a, b))
        });
    }
}

#[test]
fn segments_against_cylinder_patches() {
    // The roots beyond the height are points of the implicit cylinder, not of the
    // object: the certified answer must drop them (decided on the patch).
    for seed in 0..3u64 {
        let mut rng = Rng::new(300 + seed);
        let o = point_in(&mut rng, 1.0);
        let r = 0.8 + rng.unit().abs();
        let height = [-1.5, 1.0];
        let json = format!(
            r#"{{"type":"cylinder","origin":{},"radius":{r},"axis":[0,0,1],"height":{}}}"#,
            nums(&o),
            nums(&height)
        );
        let q = QuadricTruth::axis_aligned(o, [fl(1.0), fl(1.0), fl(0.0)], fl(r) * fl(r));
        let (z0, z1) = (fl(o[2]) + height[0], fl(o[2]) + height[1]);
        let truth = |a: &[f64; 3], b: &[f64; 3]| {
            let gap = (z1.clone() - &z0) * 0.01;
            let implicit = q.segment_roots(a, b);
            let z = |t: &Float| on_segment(a, b, t)[2].clone();
            if implicit
                .iter()
                .any(|t| (z(t) - &z0).abs() < gap || (z(t) - &z1).abs() < gap)
            {
                return None; // near an end of the height: drawn again
            }
            let mut on = implicit.clone();
            on.retain(|t| z(t) > z0 && z(t) < z1);
            Some((implicit, on))
        };
        segment_family("cylinder", seed, 3.0, o, &json, truth);
    }
}

#[test]
fn segments_against_quadric_matrices() {
    // Ellipsoids, hyperboloids of one and two sheets, elliptic and hyperbolic cylinders
    // in general position: `A = R·diag(sᵢ/aᵢ²)·Rᵀ` (R a rotation, sᵢ ∈ {1, −1, 0} with
    // one 1 at least), `b = −A·x₀`, `c = x₀ᵀAx₀ − 1`, rounded to doubles and mirrored so
    // that the matrix is symmetric; the truth is computed from those doubles.
    for seed in 0..3u64 {
        let mut rng = Rng::new(400 + seed);
        let x0 = point_in(&mut rng, 0.5);
        let signs = [
            1.0,
            [1.0, -1.0, 0.0][rng.below(3)],
            [1.0, -1.0][rng.below(2)],
        ];
        let d: [f64; 3] = std::array::from_fn(|i| {
            let a = 0.7 + 0.8 * rng.unit().abs();
            signs[i] / (a * a)
        });
        // A rotation from a random unit quaternion.
        let w: [f64; 4] = std::array::from_fn(|_| rng.unit());
        let l = w.iter().map(|x| x * x).sum::<f64>().sqrt();
        let [qw, qx, qy, qz] = w.map(|x| x / l);
        let r = [
            [
                1.0 - 2.0 * (qy * qy + qz * qz),
                2.0 * (qx * qy - qz * qw),
                2.0 * (qx * qz + qy * qw),
            ],
            [
                2.0 * (qx * qy + qz * qw),
                1.0 - 2.0 * (qx * qx + qz * qz),
                2.0 * (qy * qz - qx * qw),
            ],
            [
                2.0 * (qx * qz - qy * qw),
                2.0 * (qy * qz + qx * qw),
                1.0 - 2.0 * (qx * qx + qy * qy),
            ],
        ];
        let mut m = [[0.0f64; 4]; 4];
        for i in 0..3 {
            for j in i..3 {
                let v: f64 = (0..3).map(|k| r[i][k] * d[k] * r[j][k]).sum();
                m[i][j] = v;
                m[j][i] = v;
            }
        }
        let b: [f64; 3] = std::array::from_fn(|i| -(0..3).map(|j| m[i][j] * x0[j]).sum::<f64>());
        for (i, &v) in b.iter().enumerate() {
            m[i][3] = v;
            m[3][i] = v;
        }
        m[3][3] = (0..3).map(|i| -m[i][3] * x0[i]).sum::<f64>() - 1.0;
        let rows: Vec<String> = m.iter().map(|r| nums(r)).collect();
        let json = format!(r#"{{"type":"quadric","matrix":[{}]}}"#, rows.join(","));
        let q = QuadricTruth::from_matrix(&m);
        segment_family(&format!("quadric{seed}"), seed, 2.5, x0, &json, |a, b| {
            whole(q.segment_roots(a, b))
        });
    }
}

#[test]
fn segments_across_tori() {
    // A segment in the plane z = z_c + h meets the torus where it meets the two circles
    // of radii R ± √(r² − h²) about the axis.
    for seed in 0..3u64 {
        let mut rng = Rng::new(500 + seed);
        let c = point_in(&mut rng, 1.0);
        let (major, minor) = (2.0 + rng.unit().abs(), 0.5 + 0.5 * rng.unit().abs());
        let json = format!(
            r#"{{"type":"torus","center":{},"major":{major},"minor":{minor},"axis":[0,0,1]}}"#,
            nums(&c)
        );
        let n = cases(8);
        let mut done = 0;
        for k in 0..50 * n {
            if done == n {
                break;
            }
            let z = c[2] + 0.9 * minor * rng.unit();
            let mut p = point_in(&mut rng, 4.0);
            let mut q = point_in(&mut rng, 4.0);
            p[2] = z;
            q[2] = z;
            let h = fl(z) - fl(c[2]);
            let w = (fl(minor) * fl(minor) - h.clone() * &h).sqrt();
            let mut roots = Vec::new();
            for radius in [fl(major) - &w, fl(major) + &w] {
                let circle = QuadricTruth::axis_aligned(
                    c,
                    [fl(1.0), fl(1.0), fl(0.0)],
                    radius.clone() * &radius,
                );
                roots.extend(circle.segment_roots(&p, &q));
            }
            roots.sort_by(|x, y| x.partial_cmp(y).expect("finite"));
            if !separated(&to_f64(&roots), [0.0, 1.0]) {
                continue;
            }
            let points: Vec<[Float; 3]> = roots.iter().map(|t| on_segment(&p, &q, t)).collect();
            let objects = format!("{},{json}", segment_json(&p, &q));
            check(
                &format!("torus-{seed}-{k}"),
                &objects,
                &roots,
                &roots,
                &points,
            );
            done += 1;
        }
        assert_eq!(done, n, "torus {seed}: only {done} separated cases");
    }
}

/// A circle `centre + ρ(cos t·X + sin t·Y)` against `|P(x) − S|² = R²`, where `P`
/// keeps the coordinates of `mask` (all three: a sphere; x and y: a cylinder about z):
/// the roots of `A cos t + B sin t + D` and their points.
fn circle_roots(
    centre: [f64; 3],
    rho: f64,
    axis: [f64; 3],
    s: [f64; 3],
    r: f64,
    mask: [bool; 3],
) -> (Vec<Float>, Vec<[Float; 3]>) {
    let [x, y, _] = docs_frame(axis, None, BITS);
    let keep = |v: &[Float; 3]| -> [Float; 3] {
        std::array::from_fn(|i| if mask[i] { v[i].clone() } else { fl(0.0) })
    };
    let dot =
        |a: &[Float; 3], b: &[Float; 3]| (0..3).fold(fl(0.0), |t, i| t + a[i].clone() * &b[i]);
    let w = keep(&std::array::from_fn(|i| fl(centre[i]) - fl(s[i])));
    let (xm, ym) = (keep(&x), keep(&y));
    let two_rho = fl(2.0) * rho;
    let a = two_rho.clone() * dot(&w, &xm);
    let b = two_rho * dot(&w, &ym);
    // |w + ρ(cos t·Xm + sin t·Ym)|² has cos², sin² terms unless Xm, Ym are orthonormal:
    // the families use masks for which they are (both for a sphere, a horizontal circle
    // for the cylinder).
    let d = dot(&w, &w) + fl(rho) * fl(rho) - fl(r) * fl(r);
    let roots = trig_roots(a, b, d);
    let points = roots
        .iter()
        .map(|t| {
            let (cos, sin) = (t.clone().cos(), t.clone().sin());
            std::array::from_fn(|i| {
                fl(centre[i]) + fl(rho) * (cos.clone() * &x[i] + sin.clone() * &y[i])
            })
        })
        .collect();
    (roots, points)
}

fn circle_family(name: &str, seed: u64, cylinder: bool) {
    let mut rng = Rng::new(seed);
    let n = cases(10);
    let mut done = 0;
    let tau = std::f64::consts::TAU;
    for k in 0..50 * n {
        if done == n {
            break;
        }
        let s = point_in(&mut rng, 1.0);
        let r = 1.0 + rng.unit().abs();
        let centre = point_in(&mut rng, 2.0);
        let rho = 0.5 + 1.5 * rng.unit().abs();
        let axis: [f64; 3] = if cylinder {
            [0.0, 0.0, 1.0]
        } else {
            std::array::from_fn(|_| rng.int(-3, 3) as f64)
        };
        if axis == [0.0; 3] {
            continue;
        }
        let mask = [true, true, !cylinder];
        let (roots, points) = circle_roots(centre, rho, axis, s, r, mask);
        if !separated(&to_f64(&roots), [0.0, tau]) {
            continue;
        }
        let circle = format!(
            r#"{{"type":"circle","center":{},"radius":{rho},"axis":{}}}"#,
            nums(&centre),
            nums(&axis)
        );
        let surface = if cylinder {
            // tall enough that the circle is inside the height
            format!(
                r#"{{"type":"cylinder","origin":{},"radius":{r},"axis":[0,0,1],"height":[-5,5]}}"#,
                nums(&s)
            )
        } else {
            format!(r#"{{"type":"sphere","center":{},"radius":{r}}}"#, nums(&s))
        };
        check(
            &format!("{name}-{k}"),
            &format!("{circle},{surface}"),
            &roots,
            &roots,
            &points,
        );
        done += 1;
    }
    assert_eq!(done, n, "{name}: only {done} separated cases");
}

#[test]
fn circles_against_spheres() {
    circle_family("circle-sphere", 600, false);
}

#[test]
fn circles_against_cylinders() {
    circle_family("circle-cylinder", 700, true);
}

/// A tangency has no sign change: the float path finds nothing (as the truth's
/// sign-change count says), and the certified answer still reports the double point —
/// proven singular, its box holding the touching point — instead of losing it.
#[test]
fn a_tangent_segment_is_found_by_the_certified_path_only() {
    // The sphere of radius 2 at the origin, touched at (0, 2, 0) by y = 2, z = 0, at
    // t = 3/4.3 (not a sample: an exact zero at a sample is a root of (13.8)).
    let objects = r#"{"type":"segment","a":[-3,2,0],"b":[1.3,2,0]},{"type":"sphere","center":[0,0,0],"radius":2}"#;
    let json = format!(
        r#"{{"id":"touch","op":"intersect","objects":[{objects}],"options":{{"method":"bisection"}}}}"#
    );
    let case = read_cases(&json).pop().expect("one").case.expect("valid");
    let shapes: Vec<_> = case
        .objects
        .iter()
        .map(|o| shape(o, "objects").expect("shape"))
        .collect();
    let float =
        ops::intersect_bisection_f64(&shapes, &options(&case).expect("options")).expect("runs");
    assert!(float.is_empty(), "{float:?}");
    let r = solve(&json);
    assert_eq!(count(&r), 1, "{r:?}");
    let p = &r.points.as_ref().expect("points")[0];
    assert!(p.tangent && p.multiplicity == 2, "{r:?}");
    assert_eq!(r.status, "verified_singular", "{r:?}");
    assert!(box_holds(&p.bounds, &[fl(0.0), fl(2.0), fl(0.0)]), "{r:?}");
    let t = fl(3.0) / (fl(1.3) + 3.0);
    assert!(box_holds(&param_boxes(&r, 0)[0], &[t]), "{r:?}");
}

#[test]
fn bad_methods_are_typed_errors() {
    let kind = |json: &str| {
        let r = solve(json);
        assert_eq!(r.status, "error", "{r:?}");
        let e = serde_json::to_value(&r).expect("json");
        (
            e["error"]["kind"].as_str().unwrap_or("").to_string(),
            e["error"]["field"].as_str().unwrap_or("").to_string(),
        )
    };
    let sphere = r#"{"type":"sphere","center":[0,0,0],"radius":1}"#;
    let segment = r#"{"type":"segment","a":[-2,0,0],"b":[2,0,0]}"#;
    let (k, m) = kind(&format!(
        r#"{{"id":1,"op":"intersect","objects":[{segment},{sphere}],"options":{{"method":"newton"}}}}"#
    ));
    assert_eq!(
        (k.as_str(), m.as_str()),
        ("invalid_value", "options.method")
    );
    // Two curves: nothing to bisect against.
    let (k, m) = kind(&format!(
        r#"{{"id":2,"op":"intersect","objects":[{segment},{segment}],"options":{{"method":"bisection"}}}}"#
    ));
    assert_eq!((k.as_str(), m.as_str()), ("unsupported", "options.method"));
    // A Bézier patch has no implicit form.
    let bezier = r#"{"type":"bezier_surface","points":[[[0,0,0],[1,0,0]],[[0,1,0],[1,1,1]]]}"#;
    let (k, m) = kind(&format!(
        r#"{{"id":3,"op":"intersect","objects":[{segment},{bezier}],"options":{{"method":"bisection"}}}}"#
    ));
    assert_eq!((k.as_str(), m.as_str()), ("unsupported", "objects[1].type"));
}
