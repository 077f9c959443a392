//! A plane Bézier or NURBS curve against a spline of conic arcs (rational quadratic
//! pieces: a NURBS circle, a quadratic Bézier) is decided exactly (issues 14 and 16),
//! by implicitising each arc — not by subdividing both curves until the box budget.
//!
//! The arcs are an **exact** circle of rational weights: the quarter
//! `((1 − t²), 2t)/(1 + t²)` is the rational quadratic with control points
//! `(1,0), (1,1), (0,1)` and weights `(1, 1, 2)`; four such quarters (weights doubling
//! from quarter to quarter) make a whole NURBS circle of knots `0,0,0,1,1,2,2,3,3,4,4,4`
//! on which the knot parameter is `k + tan(φ/2)`, `φ` the angle from the start of
//! quarter `k`. So every answer against the NURBS circle must equal the answer against
//! the same `circle2` (decided exactly by another route, `tests/spline_conic_exact.rs`):
//! the same points, coordinates and curve parameters to the bit, the same
//! multiplicities — and the circle's knot parameter, computed from the point in MPFR at
//! 1024 bits, must lie in its box and be correctly rounded.
//!
//! - **Osculating parabolas** touching the circle at a knot (the bottom of the circle,
//!   between quarters 2 and 3): contact 4, or 2 with two crossings `±√ε/c` off, at
//!   scales 2^±500 — a knot root reported once.
//! - **Random rational cubics** against random circles, both orders.
//! - **The golden case**: the parabola `y = 1 − x²/2` against the rounded NURBS quarter
//!   circle of weight `0.7071067811865476` (tangent at its end point): exact.

mod truth_support;

use geocert::io::CaseResult;
use rug::Float;
use truth_support::{bezier2_at, cases, fl, holds, num, solve};

fn pts(ps: &[[f64; 2]]) -> String {
    let v: Vec<String> = ps
        .iter()
        .map(|p| format!("[{},{}]", num(p[0]), num(p[1])))
        .collect();
    format!("[{}]", v.join(","))
}

fn case(a: &str, b: &str) -> String {
    format!(r#"{{"op":"intersect","objects":[{a},{b}]}}"#)
}

/// The exact NURBS circle of centre `c` and radius `r` (module doc).
fn nurbs_circle(c: [f64; 2], r: f64) -> String {
    let unit: [[f64; 2]; 9] = [
        [1.0, 0.0],
        [1.0, 1.0],
        [0.0, 1.0],
        [-1.0, 1.0],
        [-1.0, 0.0],
        [-1.0, -1.0],
        [0.0, -1.0],
        [1.0, -1.0],
        [1.0, 0.0],
    ];
    let p: Vec<[f64; 2]> = unit
        .iter()
        .map(|u| [c[0] + r * u[0], c[1] + r * u[1]])
        .collect();
    format!(
        r#"{{"type":"nurbs_curve2","degree":2,"knots":[0,0,0,1,1,2,2,3,3,4,4,4],"points":{},"weights":[1,1,2,2,4,4,8,8,16]}}"#,
        pts(&p)
    )
}

fn circle2(c: [f64; 2], r: f64) -> String {
    format!(
        r#"{{"type":"circle2","center":[{},{}],"radius":{}}}"#,
        num(c[0]),
        num(c[1]),
        num(r)
    )
}

/// The knot parameter of the point `x` of the NURBS circle (module doc): `k + t` with
/// `t = y′/(1 + x′)` in the coordinates of quarter `k` (rotated by `−k·90°`).
fn knot_parameter(x: &[Float; 2], c: [f64; 2], r: f64) -> Float {
    let u = (x[0].clone() - c[0]) / r;
    let v = (x[1].clone() - c[1]) / r;
    let (k, xr, yr) = match (v >= 0, u >= 0) {
        (true, true) => (0u32, u.clone(), v.clone()),
        (true, false) => (1, v.clone(), -u.clone()),
        (false, false) => (2, -u.clone(), -v.clone()),
        (false, true) => (3, -v.clone(), u.clone()),
    };
    yr / (xr + 1u32) + k
}

/// The curve's parameter boxes and points in `with_circle` (against `circle2`) and
/// `with_arcs` (against the NURBS circle) must agree to the bit; the circle's knot
/// parameter of each point in `with_arcs` must hold the truth computed from the
/// point's exact location `truth(i)` (`None`: only the agreement is checked).
fn agree(
    what: &str,
    with_circle: &CaseResult,
    with_arcs: &CaseResult,
    curve_first: bool,
    c: [f64; 2],
    r: f64,
    truth: impl Fn(usize) -> Option<[Float; 2]>,
) {
    assert_eq!(
        with_circle.status, "exact",
        "{what}: circle2 {with_circle:?}"
    );
    assert_eq!(with_arcs.status, "exact", "{what}: arcs {with_arcs:?}");
    assert_eq!(with_arcs.complete, Some(true), "{what}");
    let (a, b) = (
        with_circle.points.as_deref().unwrap_or_default(),
        with_arcs.points.as_deref().unwrap_or_default(),
    );
    assert_eq!(a.len(), b.len(), "{what}: {a:?} vs {b:?}");
    let (cs, ks) = if curve_first { (0, 1) } else { (1, 0) };
    for (i, (p, q)) in a.iter().zip(b).enumerate() {
        assert_eq!(p.xyz, q.xyz, "{what}: point {i}");
        assert_eq!(p.params[0], q.params[cs], "{what}: curve parameter {i}");
        assert_eq!(p.multiplicity, q.multiplicity, "{what}: multiplicity {i}");
        assert_eq!(p.tangent, q.tangent, "{what}");
        if let Some(x) = truth(i) {
            let k = knot_parameter(&x, c, r);
            let kb = &q.param_box.as_ref().expect("param_box")[ks][0];
            assert!(holds(kb, &k), "{what}: knot parameter {k} not in {kb:?}");
            assert_eq!(
                q.params[ks][0],
                k.to_f64(),
                "{what}: knot parameter rounded"
            );
        }
    }
}

/// Parabolas `y = c·x²` (a quadratic Bézier) against the circle through the vertex with
/// centre on the axis and radius `(1 + ε)/(2c)` — the osculating circle at `ε = 0`:
/// the vertex is the knot between quarters 2 and 3 of the NURBS circle.
#[test]
fn osculating_parabolas_touch_the_nurbs_circle_at_a_knot_once() {
    let mut n = 0;
    for k in [-500i32, -40, 0, 7, 490] {
        for ce in [-2i32, 0, 1] {
            for eps in [0.0, 2f64.powi(-10), -2f64.powi(-10), 2f64.powi(-40)] {
                if n >= cases(60) {
                    return;
                }
                n += 1;
                let s = 2f64.powi(k);
                let c = 2f64.powi(ce);
                let rho = s * (1.0 + eps) / (2.0 * c);
                let ctrl = [[-s, s * c], [0.0, -s * c], [s, s * c]];
                let bez = format!(r#"{{"type":"bezier2","points":{}}}"#, pts(&ctrl));
                let centre = [0.0, rho];
                let what = format!("s=2^{k} c=2^{ce} ε={eps:e}");
                let truth = |x: f64| -> [Float; 2] {
                    // y = c·x²/s on the scaled parabola (x in the scaled frame).
                    let xf = fl(x);
                    [xf.clone() * s, xf.clone() * &xf * c * s]
                };
                let mut truths = vec![truth(0.0)];
                if eps > 0.0 {
                    let x = eps.sqrt() / c; // exact: eps is an even power of two
                    truths = vec![truth(-x), truth(0.0), truth(x)];
                }
                let with_circle = solve(&case(&bez, &circle2(centre, rho)));
                let with_arcs = solve(&case(&bez, &nurbs_circle(centre, rho)));
                let m = with_arcs.points.as_deref().unwrap_or_default();
                let vertex = m.iter().find(|p| p.xyz == [0.0, 0.0]);
                let want = if eps == 0.0 { 4 } else { 2 };
                assert_eq!(vertex.map(|p| p.multiplicity), Some(want), "{what}: {m:?}");
                assert_eq!(m.len(), truths.len(), "{what}: {m:?}");
                agree(&what, &with_circle, &with_arcs, true, centre, rho, |i| {
                    truths.get(i).cloned()
                });
            }
        }
    }
}

/// Random rational cubics against random circles given both ways, in both orders: the
/// same answer to the bit, and every knot parameter holding its truth (the point
/// computed in MPFR at the root that the circle2 answer's parameter box isolates,
/// refined by bisection on the circle's equation).
#[test]
fn random_rational_cubics_meet_the_nurbs_circle_as_they_meet_the_circle() {
    let mut g = truth_support::conics::Gen::new(2311);
    let mut met = 0;
    for i in 0..cases(100) {
        let ctrl: Vec<[f64; 2]> = (0..4).map(|_| g.vec::<2>(-2.0, 2.0, 4)).collect();
        let w: Vec<f64> = (0..4).map(|_| g.dyadic(0.25, 2.0, 4)).collect();
        let (c, r) = (g.vec::<2>(-1.0, 1.0, 4), g.dyadic(0.25, 2.0, 4));
        let bez = format!(
            r#"{{"type":"bezier2","points":{},"weights":[{}]}}"#,
            pts(&ctrl),
            w.iter().map(|&x| num(x)).collect::<Vec<_>>().join(",")
        );
        let what = format!("case {i}: {bez} × circle {c:?} r={r}");
        let with_circle = solve(&case(&bez, &circle2(c, r)));
        let with_arcs = solve(&case(&bez, &nurbs_circle(c, r)));
        let f = |t: &Float| {
            let x = bezier2_at(&ctrl, &w, t);
            let (dx, dy) = (x[0].clone() - c[0], x[1].clone() - c[1]);
            dx.clone() * &dx + dy.clone() * &dy - fl(r) * r
        };
        let circle_points = with_circle.points.as_deref().unwrap_or_default();
        met += circle_points.len();
        let truth = |i: usize| -> Option<[Float; 2]> {
            let p = circle_points.get(i)?;
            if p.multiplicity != 1 {
                return None;
            }
            let b = p.param_box.as_ref()?[0][0];
            let (mut lo, mut hi) = (fl(b[0]), fl(b[1]));
            let lo_neg = f(&lo) < 0;
            for _ in 0..1000 {
                let mid = (lo.clone() + &hi) / 2u32;
                if (f(&mid) < 0) == lo_neg {
                    lo = mid;
                } else {
                    hi = mid;
                }
            }
            Some(bezier2_at(&ctrl, &w, &lo))
        };
        agree(&what, &with_circle, &with_arcs, true, c, r, truth);
        if i % 4 == 0 {
            let swapped = solve(&case(&nurbs_circle(c, r), &bez));
            agree(
                &format!("{what} (swapped)"),
                &with_circle,
                &swapped,
                false,
                c,
                r,
                truth,
            );
        }
    }
    assert!(met > 40, "the family meets: {met}");
}

/// The golden case g533/g547: the parabola `y = 1 − x²/2` and the rounded NURBS quarter
/// circle share the tangent at its end `(0, 1)` (the weight is not `1/√2`, so the arc is
/// not the osculating circle): exact, one tangent point at the end, in both orders.
#[test]
fn the_parabola_and_the_rounded_quarter_circle_are_decided_exactly() {
    let bez = r#"{"type":"bezier2","points":[[-2,-1],[0,3],[2,-1]]}"#;
    let arc = r#"{"type":"nurbs_curve2","degree":2,"knots":[0,0,0,1,1,1],"points":[[1,0],[1,1],[0,1]],"weights":[1,0.7071067811865476,1]}"#;
    for (a, b, arc_side) in [(bez, arc, 1), (arc, bez, 0)] {
        let r = solve(&case(a, b));
        assert_eq!(r.status, "exact", "{r:?}");
        assert_eq!(r.complete, Some(true));
        let p = r.points.as_deref().unwrap_or_default();
        let top = p
            .iter()
            .find(|p| p.xyz == [0.0, 1.0])
            .expect("the end point");
        assert!(top.multiplicity >= 2 && top.tangent, "{p:?}");
        assert_eq!(top.params[arc_side], vec![1.0], "the arc's end");
        assert_eq!(top.params[1 - arc_side], vec![0.5], "the parabola's vertex");
    }
}
