//! Near tangencies of curves against surfaces and curves, through the front door (issue
//! 14 item 5; CERTIFICATION.md "Tangency and near-tangency"): a circle passing a torus
//! tube or a sphere, and a line passing a circle in the plane, at gaps `10^-k`
//! (3 ≤ k ≤ 15) on either side of tangency, ±1 ulp around it, and exactly on it.
//!
//! Truth, independent of the code: every family reduces to two circles (or a line and
//! a circle) in one coordinate plane, whose data are exact rationals (the doubles of
//! the case). The number of roots is decided exactly — for circles of squared radii
//! `a`, `b` whose centres are `d` apart, `D = 4ab − (d² − a − b)²` is positive (two
//! crossings), zero (a tangency) or negative (none); for a line, the discriminant of
//! its quadratic — and the points are computed at 300 bits in closed form.
//!
//! * the circle lies in the plane `x = 0` (axis `(1, 0, 0)`, ref `(0, 1, 0)`, so that
//!   `c(t) = (0, y₀ + ρ cos t, z₀ + ρ sin t)` exactly); the torus (centre 0, axis z)
//!   cuts that plane in its meridian circles of radius `r` about `(0, ±R, 0)`;
//! * the circle lies in the plane `x = x₀`; the sphere (centre 0, radius `s`) cuts it in
//!   the circle of squared radius `s² − x₀²` about `(x₀, 0, 0)`;
//! * `line2` against `circle2`.
//!
//! Asserted for every answer: `complete`; two crossings come back as two points, status
//! `verified` or `exact`, one box per truth and one truth per box (strict containment);
//! a tangency as one point whose box holds it, `exact` or `verified_singular`
//! (multiplicity 2); no crossing as an empty answer (a proven miss). A statement about
//! a near miss is never a tangency, and two close crossings are never one singular box:
//! the certifier raises the precision until they separate (512 bits by default, far
//! beyond these gaps).

mod truth_support;

use geocert::io::CaseResult;
use geocert::num::rng::Rng;
use geocert::num::round::{next_down, next_up};
use rug::{Float, Rational};
use truth_support::{box_holds, num, nums, one_to_one, point_boxes, solve};

const BITS: u32 = 300;

fn q(x: f64) -> Rational {
    Rational::from_f64(x).expect("finite")
}

fn fq(x: &Rational) -> Float {
    Float::with_val(BITS, x)
}

/// What the truth says: the true points (coordinates at 300 bits) and whether they
/// form a tangency.
#[derive(Debug)]
struct Truth {
    points: Vec<Vec<Float>>,
    tangent: bool,
}

/// Two circles in a plane with coordinates `(p, q)`: centres `a`, `b` (exact), squared
/// radii `ra2`, `rb2` (exact). The crossings in the plane's coordinates (module doc).
fn circles_meet(a: [Rational; 2], ra2: Rational, b: [Rational; 2], rb2: Rational) -> Truth {
    let dx = Rational::from(&b[0] - &a[0]);
    let dy = Rational::from(&b[1] - &a[1]);
    let d2 = Rational::from(dx.square_ref()) + Rational::from(dy.square_ref());
    let s = Rational::from(&d2 - &ra2) - &rb2;
    let disc = Rational::from(&ra2 * &rb2) * 4u32 - s.square();
    if disc < 0 || d2 == 0 {
        return Truth {
            points: Vec::new(),
            tangent: false,
        };
    }
    let d = fq(&d2).sqrt();
    // ℓ = (ra² − rb² + d²)/(2d) along b − a, h = √D/(2d) across
    let l = fq(&(Rational::from(&ra2 - &rb2) + &d2)) / Float::with_val(BITS, &d * 2u32);
    let h = fq(&disc).sqrt() / Float::with_val(BITS, &d * 2u32);
    let (ux, uy) = (fq(&dx) / &d, fq(&dy) / &d);
    let base = [
        fq(&a[0]) + Float::with_val(BITS, &l * &ux),
        fq(&a[1]) + Float::with_val(BITS, &l * &uy),
    ];
    let signs: &[i32] = if disc == 0 { &[1] } else { &[1, -1] };
    let points = signs
        .iter()
        .map(|&sg| {
            let hs = Float::with_val(BITS, &h * sg);
            vec![
                Float::with_val(BITS, &base[0] - Float::with_val(BITS, &hs * &uy)),
                Float::with_val(BITS, &base[1] + Float::with_val(BITS, &hs * &ux)),
            ]
        })
        .collect();
    Truth {
        points,
        tangent: disc == 0,
    }
}

/// The checks of the module doc.
fn verdict(r: &CaseResult, truth: &Truth) -> Result<(), String> {
    if r.complete != Some(true) {
        return Err(format!("not complete: {} {:?}", r.status, r.reason));
    }
    let boxes = point_boxes(r);
    match truth.points.len() {
        0 => {
            if !boxes.is_empty() {
                return Err(format!("a miss answered with {} point(s)", boxes.len()));
            }
            Ok(())
        }
        1 => {
            if !matches!(r.status, "exact" | "verified_singular") {
                return Err(format!("a tangency answered {}", r.status));
            }
            if boxes.len() != 1 || !box_holds(&boxes[0], &truth.points[0]) {
                return Err(format!("tangency point not in one box: {boxes:?}"));
            }
            Ok(())
        }
        _ => {
            if !matches!(r.status, "exact" | "verified") {
                return Err(format!(
                    "two crossings answered {} with {} box(es)",
                    r.status,
                    boxes.len()
                ));
            }
            let simple = r.points.iter().flatten().all(|p| p.multiplicity == 1);
            if !simple {
                return Err("a crossing reported with multiplicity 2".into());
            }
            one_to_one(&boxes, &truth.points)
        }
    }
}

fn run(case: &str, truth: &Truth) {
    let r = solve(case);
    if let Err(e) = verdict(&r, truth) {
        panic!(
            "{e}\ncase: {case}\ntruth: {truth:?}\nanswer: {}",
            serde_json::to_string(&r).unwrap_or_default()
        );
    }
    let _ = truth.tangent;
    eprintln!(
        "STAT {} {} {} {:?} {case}",
        r.status,
        truth.points.len(),
        r.points.as_ref().map_or(0, Vec::len),
        r.micros
    );
}

/// A distance `touch ± 10^-k`, `touch ± 1 ulp` or `touch` itself (k = 16, 17).
fn near(g: &mut Rng, touch: f64) -> f64 {
    let k = g.int(3, 17) as i32;
    let side = if g.coin() { 1.0 } else { -1.0 };
    match k {
        16 => {
            if side > 0.0 {
                next_up(touch)
            } else {
                next_down(touch)
            }
        }
        17 => touch,
        _ => touch + side * 10f64.powi(-k),
    }
}

/// A circle of radius `rho` in the plane `x = x0` about `(x0, y0, z0)`.
fn circle_x(x0: f64, y0: f64, z0: f64, rho: f64) -> String {
    format!(
        r#"{{"type":"circle","center":{},"radius":{},"axis":[1,0,0],"ref":[0,1,0]}}"#,
        nums(&[x0, y0, z0]),
        num(rho)
    )
}

fn intersect(a: &str, b: &str) -> String {
    format!(r#"{{"id":"nt","op":"intersect","objects":[{a},{b}]}}"#)
}

/// A centre `touch`-ish away from `(y, z)` along the angle `alpha` (rounded to doubles:
/// the truth is computed from the rounded centre).
fn centre_near(g: &mut Rng, y: f64, z: f64, touch: f64, alpha: f64) -> [f64; 2] {
    let d = near(g, touch);
    [y + d * alpha.cos(), z + d * alpha.sin()]
}

/// The truth of the circle `circle_x(x0, c, rho)` against the circle of squared radius
/// `a2` about `(x0, a)` in the same plane, lifted to 3D points.
fn lifted(x0: f64, a: [f64; 2], a2: Rational, c: [f64; 2], rho: f64) -> Truth {
    let t = circles_meet(a.map(q), a2, c.map(q), q(rho).square());
    Truth {
        points: t
            .points
            .into_iter()
            .map(|p| {
                let mut v = vec![Float::with_val(BITS, x0)];
                v.extend(p);
                v
            })
            .collect(),
        tangent: t.tangent,
    }
}

/// Circles in the plane `x = 0` passing the tube of a torus, outside it and inside it,
/// at gaps 1e-3 … 1e-15, ±1 ulp and exactly tangent (at the top of the tube, where the
/// data are dyadic), and along random directions.
#[test]
fn circles_passing_a_torus_tube() {
    let mut g = Rng::new(1451);
    for i in 0..cases(120) {
        let big = g.int(8, 16) as f64 / 4.0;
        let r = g.int(2, 6) as f64 / 8.0;
        let inside = i % 3 == 2;
        let rho = if inside {
            r * g.int(1, 6) as f64 / 8.0
        } else {
            g.int(1, 8) as f64 / 8.0
        };
        let touch = if inside { r - rho } else { r + rho };
        let alpha = match i % 4 {
            0 => std::f64::consts::FRAC_PI_2,
            _ => std::f64::consts::PI * 0.5 * (g.unit() + 1.0) - 0.2,
        };
        let c = centre_near(&mut g, big, 0.0, touch, alpha);
        let truth = lifted(0.0, [big, 0.0], q(r).square(), c, rho);
        let torus = format!(
            r#"{{"type":"torus","center":[0,0,0],"major":{},"minor":{},"axis":[0,0,1]}}"#,
            num(big),
            num(r)
        );
        run(&intersect(&circle_x(0.0, c[0], c[1], rho), &torus), &truth);
    }
}

/// Circles in the plane `x = x₀` passing a sphere's small circle there, outside and
/// inside, at the same gaps.
#[test]
fn circles_passing_a_sphere() {
    let mut g = Rng::new(1452);
    for i in 0..cases(120) {
        let s = g.int(4, 12) as f64 / 4.0;
        let x0 = s * g.int(-6, 6) as f64 / 8.0;
        let a2 = q(s).square() - q(x0).square();
        let ra = fq(&a2).sqrt().to_f64();
        let inside = i % 3 == 2;
        let rho = if inside {
            ra * g.int(2, 6) as f64 / 8.0
        } else {
            g.int(1, 8) as f64 / 8.0
        };
        let touch = if inside { ra - rho } else { ra + rho };
        let alpha = std::f64::consts::PI * (g.unit() + 1.0);
        let c = centre_near(&mut g, 0.0, 0.0, touch, alpha);
        let truth = lifted(x0, [0.0, 0.0], a2, c, rho);
        let sphere = format!(
            r#"{{"type":"sphere","center":[0,0,0],"radius":{}}}"#,
            num(s)
        );
        run(&intersect(&circle_x(x0, c[0], c[1], rho), &sphere), &truth);
    }
}

/// `line2` against `circle2`: a line through a point at distance `ρ ± gap` from the
/// centre, along a random direction perpendicular (up to rounding) to the radius.
#[test]
fn lines_passing_a_circle_in_the_plane() {
    let mut g = Rng::new(1453);
    for _ in 0..cases(200) {
        let c = [g.unit(), g.unit()];
        let rho = g.int(2, 16) as f64 / 8.0;
        let beta = std::f64::consts::PI * g.unit();
        let d = near(&mut g, rho);
        let foot = [c[0] + d * beta.cos(), c[1] + d * beta.sin()];
        let dir = [-beta.sin(), beta.cos()];
        // |o + s·dir − c|² = ρ²: A s² + 2B s + C = 0, exact in rationals
        let (o, u, cq) = (foot.map(q), dir.map(q), c.map(q));
        let w = [
            Rational::from(&o[0] - &cq[0]),
            Rational::from(&o[1] - &cq[1]),
        ];
        let a = Rational::from(u[0].square_ref()) + Rational::from(u[1].square_ref());
        let b = Rational::from(&u[0] * &w[0]) + Rational::from(&u[1] * &w[1]);
        let c0 =
            Rational::from(w[0].square_ref()) + Rational::from(w[1].square_ref()) - q(rho).square();
        let disc = Rational::from(b.square_ref()) - Rational::from(&a * &c0);
        let mut points = Vec::new();
        if disc >= 0 {
            let h = fq(&disc).sqrt();
            let signs: &[i32] = if disc == 0 { &[1] } else { &[1, -1] };
            for &sg in signs {
                let s = (Float::with_val(BITS, -fq(&b)) + Float::with_val(BITS, &h * sg)) / fq(&a);
                points.push(
                    (0..2)
                        .map(|k| fq(&o[k]) + Float::with_val(BITS, &s * &fq(&u[k])))
                        .collect(),
                );
            }
        }
        let truth = Truth {
            points,
            tangent: disc == 0,
        };
        let line = format!(
            r#"{{"type":"line2","origin":{},"dir":{}}}"#,
            nums(&foot),
            nums(&dir)
        );
        let circle = format!(
            r#"{{"type":"circle2","center":{},"radius":{}}}"#,
            nums(&c),
            num(rho)
        );
        run(&intersect(&line, &circle), &truth);
    }
}

fn cases(default: usize) -> usize {
    truth_support::cases(default)
}

/// A known defect (run with `GEOCERT_KNOWN_DEFECTS=1`; found with
/// `GEOCERT_CURVED_CASES=6`): a circle 1e-11 inside tangency with a torus tube, two
/// crossings 3.5e-6 apart, comes back `complete` with the two verified points and a
/// third, `verified_singular` box between them that holds neither (sound: at most two
/// roots; but a near miss shown as a tangency), after 5 s.
#[test]
fn two_crossings_and_an_empty_singular_box_between_them() {
    if std::env::var_os("GEOCERT_KNOWN_DEFECTS").is_none() {
        return;
    }
    let (c, rho, big, r) = ([3.845140829310223, 0.2574714814357457], 0.75, 2.75, 0.375);
    let truth = lifted(0.0, [big, 0.0], q(r).square(), c, rho);
    assert_eq!(truth.points.len(), 2);
    let torus = format!(
        r#"{{"type":"torus","center":[0,0,0],"major":{},"minor":{},"axis":[0,0,1]}}"#,
        num(big),
        num(r)
    );
    run(&intersect(&circle_x(0.0, c[0], c[1], rho), &torus), &truth);
}
