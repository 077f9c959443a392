//! `nearest` at and near ties (issue 21, family 5): a point on the major axis of an
//! ellipse, inside its evolute (`|x₀| < (a² − b²)/a`), has two nearest points at exactly
//! equal distance, mirror images `(a cos t, ±b sin t)` with `cos t = a x₀/(a² − b²)` (the
//! foot equation `−(a² − b²) sin t cos t + a x₀ sin t − b y₀ cos t = 0` at `y₀ = 0`), both
//! nearer than the axis ends `(±a, 0)`. Moved by `δ` across the major axis, the foot on
//! the side of `δ` is strictly nearer (each point of the other half has a nearer mirror
//! image), by about `2δ|y_f|/dist`: `δ` of one ulp, 1e-15, 1e-12 and 1e-9 of the scale,
//! on both sides.
//!
//! The truth: the foot by Newton's method on the foot equation in MPFR at 1024 bits
//! from the tie's root (its residual checked), a route independent of geocert's.
//! Checks, for an `ellipse2` (exact route), an `ellipse` in space and the NURBS form
//! of the ellipse in the plane (numeric routes), each at unit scale and at 2^±500 and
//! 2^±300 (about 1e±150):
//!
//! - a decided answer has one point, whose box holds the true nearest point (at the
//!   tie: one of the two), and never the farther foot;
//! - at gaps of 1e-12 and more, the answer is decided (the tie is told apart);
//! - at the exact tie a decided answer is allowed (either point is nearest) and an
//!   undecided one must say why.
//!
//! Cases: `GEOCERT_CURVED_CASES` multiplies the default.

mod truth_support;

use geocert::io::CaseResult;
use rug::Float;
use truth_support::conics::{magnitude, Ellipse, Gen};
use truth_support::*;

/// The foot of `(x₀, y₀)` on the ellipse `(a cos t, b sin t)` near `(cos t, sin t) = s`,
/// by Newton on the foot equation; `None` if it does not settle.
fn foot(a: &Float, b: &Float, x0: &Float, y0: &Float, start: [Float; 2]) -> Option<[Float; 2]> {
    let mut t = Float::with_val(BITS, start[1].atan2_ref(&start[0]));
    let k = Float::with_val(BITS, a.square_ref()) - Float::with_val(BITS, b.square_ref());
    let mut last = Float::with_val(BITS, 1u32);
    for _ in 0..400 {
        let (s, c) = (t.clone().sin(), t.clone().cos());
        let g = -Float::with_val(BITS, &k * &s) * &c + Float::with_val(BITS, a * x0) * &s
            - Float::with_val(BITS, b * y0) * &c;
        let dg = -Float::with_val(BITS, &k * &c) * &c
            + Float::with_val(BITS, &k * &s) * &s
            + Float::with_val(BITS, a * x0) * &c
            + Float::with_val(BITS, b * y0) * &s;
        let step = g / dg;
        t -= &step;
        let size = step.clone().abs();
        if size < Float::with_val(BITS, 1u32) >> 900u32 {
            return Some([t.clone().cos(), t.sin()]);
        }
        last = size;
    }
    eprintln!("Newton: last step {last:.3e} a {a:.5e} b {b:.5e} x0 {x0:.5e} y0 {y0:.5e} t {t:.5e}");
    None
}

/// The squared distance from `(x₀, y₀)` to the ellipse point at `(cos, sin)`.
fn dist2(a: &Float, b: &Float, x0: &Float, y0: &Float, cs: &[Float; 2]) -> Float {
    let dx = Float::with_val(BITS, a * &cs[0]) - x0;
    let dy = Float::with_val(BITS, b * &cs[1]) - y0;
    dx.square() + dy.square()
}

#[derive(Clone, Copy, Debug)]
enum Form {
    Ellipse2,
    Ellipse3,
    Nurbs2,
}

fn case(form: Form, c: [f64; 3], a: f64, b: f64, p: [f64; 3]) -> String {
    let onto = match form {
        Form::Ellipse2 => format!(
            r#"{{"type":"ellipse2","center":{},"a":{},"b":{}}}"#,
            nums(&c[..2]),
            num(a),
            num(b)
        ),
        Form::Ellipse3 => format!(
            r#"{{"type":"ellipse","center":{},"a":{},"b":{},"axis":[0,0,1]}}"#,
            nums(&c),
            num(a),
            num(b)
        ),
        Form::Nurbs2 => Ellipse {
            c: [c[0], c[1]],
            a: [a, 0.0],
            b: [0.0, b],
        }
        .nurbs(),
    };
    let n = if matches!(form, Form::Ellipse3) { 3 } else { 2 };
    format!(
        r#"{{"id":0,"op":"project","nearest":true,"point":{},"onto":{onto}}}"#,
        nums(&p[..n])
    )
}

/// `Ok(true)` decided and right, `Ok(false)` undecided with a reason.
fn judge(
    r: &CaseResult,
    nearest: &[Vec<Float>],
    farther: Option<&Vec<Float>>,
) -> Result<bool, String> {
    if r.status == "undecided" {
        return match &r.reason {
            Some(_) => Ok(false),
            None => Err("undecided without a reason".into()),
        };
    }
    let boxes = point_boxes(r);
    if boxes.len() != 1 {
        return Err(format!("{} points for the nearest", boxes.len()));
    }
    if let Some(f) = farther {
        if box_holds(&boxes[0], f) {
            return Err(format!("the farther foot {} is in the box", show(f)));
        }
    }
    if nearest.iter().any(|t| box_holds(&boxes[0], t)) {
        Ok(true)
    } else {
        Err("the box misses the nearest point".into())
    }
}

#[test]
fn nearest_at_and_near_a_tie_on_an_ellipse() {
    let mut g = Gen::new(2161);
    let forms = [Form::Ellipse2, Form::Ellipse3, Form::Nurbs2];
    let (mut decided_near, mut near_total) = (0, 0);
    for i in 0..cases(72) {
        let form = forms[i % 3];
        let m = [1.0, 1.0, magnitude(g.below(4))][(i / 3) % 3];
        let b = g.dyadic(0.5, 1.5, 4);
        let a = b + g.dyadic(0.5, 2.0, 4);
        let c: [f64; 3] = g.vec(-2.0, 2.0, 3);
        let lim = (a * a - b * b) / a;
        let x0 = g.dyadic(-0.7 * lim, 0.7 * lim, 6).clamp(-0.9 * a, 0.9 * a);
        if x0 == 0.0 {
            continue;
        }
        let gap = [0.0, 1e-9, 1e-12, 1e-15, f64::EPSILON][g.below(5)] * [1.0, -1.0][g.below(2)];
        let (c, a, b, x0) = (c.map(|x| x * m), a * m, b * m, x0 * m);
        // one ulp: the next double up or down from c_y (also from 0)
        let up = |x: f64| match x {
            0.0 => f64::from_bits(1),
            x if x > 0.0 => f64::from_bits(x.to_bits() + 1),
            x => f64::from_bits(x.to_bits() - 1),
        };
        let py = if gap.abs() == f64::EPSILON {
            if gap > 0.0 {
                up(c[1])
            } else {
                -up(-c[1])
            }
        } else {
            c[1] + gap * m
        };
        let p = [c[0] + x0, py, c[2]];
        let (af, bf) = (fl(a), fl(b));
        let x0f = fl(p[0]) - c[0];
        let y0 = fl(p[1]) - c[1];
        // the tie's roots (y₀ = 0): cos t = a x₀/(a² − b²), sin t = ±√(1 − cos²)
        let k = Float::with_val(BITS, af.square_ref()) - Float::with_val(BITS, bf.square_ref());
        let co = Float::with_val(BITS, &af * &x0f) / &k;
        let si = (Float::with_val(BITS, 1u32) - Float::with_val(BITS, co.square_ref())).sqrt();
        let feet: Vec<[Float; 2]> = [1i32, -1]
            .iter()
            .map(|&sg| {
                let start = [co.clone(), Float::with_val(BITS, &si * sg)];
                foot(&af, &bf, &x0f, &y0, start).expect("Newton settles")
            })
            .collect();
        // the on-axis feet (±a, 0) must be farther: the tie is the global minimum
        let d: Vec<Float> = feet.iter().map(|f| dist2(&af, &bf, &x0f, &y0, f)).collect();
        let on_axis = [
            Float::with_val(BITS, &af - &x0f).abs(),
            Float::with_val(BITS, &af + &x0f).abs(),
        ];
        assert!(on_axis
            .iter()
            .all(|o| Float::with_val(BITS, o.square_ref()) > d[0].clone().max(&d[1])));
        let point = |cs: &[Float; 2]| {
            let mut v = vec![
                Float::with_val(BITS, &af * &cs[0]) + c[0],
                Float::with_val(BITS, &bf * &cs[1]) + c[1],
            ];
            if matches!(form, Form::Ellipse3) {
                v.push(fl(c[2]));
            }
            v
        };
        let pts: Vec<Vec<Float>> = feet.iter().map(point).collect();
        let text = case(form, c, a, b, p);
        let r = solve(&text);
        let verdict = if y0.is_zero() {
            assert_eq!(d[0], d[1], "the tie is exact");
            judge(&r, &pts, None)
        } else {
            let (near, far) = if d[0] < d[1] { (0, 1) } else { (1, 0) };
            assert_eq!(near == 0, y0 > 0, "the nearer foot is on the side of δ");
            judge(&r, &pts[near..=near], Some(&pts[far]))
        };
        match verdict {
            Ok(decided) => {
                if gap.abs() >= 1e-12 {
                    near_total += 1;
                    decided_near += usize::from(decided);
                    assert!(
                        decided,
                        "gap {gap:e} not told apart ({form:?})\ncase: {text}\nresult: {r:?}"
                    );
                }
            }
            Err(e) => panic!("{e} ({form:?}, gap {gap:e})\ncase: {text}\nresult: {r:?}"),
        }
    }
    assert!(
        near_total >= cases(72) / 4,
        "{decided_near} of {near_total}"
    );
}
