//! Plane Bézier and NURBS curves against whole circles, ellipses and implicit conics are
//! decided exactly (issues 14 and 16): tangencies of every order are proven
//! multiplicities, not undecided boxes. Families with closed-form truths, computed in
//! MPFR far above the answer's precision:
//!
//! - **Osculating circles.** The parabola `y = c·x²` (`c` a power of two) as a quadratic
//!   Bézier over `x = 2t − 1`, scaled by `2^k` (magnitudes 1e-150 … 1e150) and moved;
//!   the circle of radius `ρ = (1 + ε)/(2c)` centred on its axis at height `ρ` passes
//!   through the vertex. On the curve `x² + (c x² − ρ)² − ρ² = c²x²·(x² − ε/c²)`: the
//!   vertex `t = ½` is a root of multiplicity 4 for `ε = 0` (the osculating circle), 2
//!   otherwise, and `ε > 0` adds the crossings `x = ±√ε/c`. `ε = ±2⁻ᵏ` from 2⁻¹⁰ down
//!   to 2⁻⁵², so near-tangencies down to one ulp. The same curve with a knot inserted
//!   at ½ (a NURBS whose double root lies on its knot), and the same circle as an
//!   implicit `conic2`.
//! - **Rounded quarter circles.** The rational quadratic arc `(r,0), (r,r), (0,r)` of
//!   weight `w` (a double, so never `1/√2`) is tangent to the circle of radius `r` at both
//!   ends and meets it nowhere else: on it `x² + y² − r²W² = 2r²t²(1 − t)²(2w² − 1)`. A
//!   whole NURBS circle of four such arcs touches its circle exactly at the four knots,
//!   its seam reported once. Stretched by `(a, b)`, against the ellipse of semi-axes
//!   `(a, b)`, the same.
//!
//! Every answer must be `exact` and complete, with the truth's count and multiplicities;
//! every box must hold its truth (curve parameter, point, and the circle's angle), and
//! the curve parameter must be the correctly rounded truth.

mod truth_support;

use geocert::io::CaseResult;
use rug::Float;
use truth_support::{cases, fl, holds, num, solve, BITS};

/// A truth: the curve parameter `t` and the multiplicity.
type Root = (Float, u32);

/// Checks one answer against its truths (sorted by `t`); `circle` is the centre and
/// semi-axes of a circle or ellipse whose angle is reported, in the order given by
/// `curve_first`, and `point` maps `t` to the exact point.
fn check(
    what: &str,
    r: &CaseResult,
    truths: &[Root],
    point: impl Fn(&Float) -> [Float; 2],
    circle: Option<([f64; 2], [f64; 2])>,
) {
    assert_eq!(r.status, "exact", "{what}: {r:?}");
    assert_eq!(r.complete, Some(true), "{what}");
    let points = r.points.as_deref().unwrap_or_default();
    assert_eq!(points.len(), truths.len(), "{what}: {points:?}");
    for (p, (t, m)) in points.iter().zip(truths) {
        assert_eq!(p.multiplicity, *m, "{what}: multiplicity at t = {t}");
        assert_eq!(p.tangent, *m >= 2, "{what}");
        let pb = p.param_box.as_ref().expect("param_box");
        assert!(holds(&pb[0][0], t), "{what}: t = {t} not in {:?}", pb[0]);
        assert_eq!(p.params[0][0], t.to_f64(), "{what}: t correctly rounded");
        let x = point(t);
        for (k, xk) in x.iter().enumerate() {
            assert!(holds(&p.bounds[k], xk), "{what}: coordinate {k}");
            assert_eq!(p.xyz[k], xk.to_f64(), "{what}: coordinate {k} rounded");
        }
        if let Some((c, axes)) = circle {
            let (cy, cx) = (
                (x[1].clone() - c[1]) / axes[1],
                (x[0].clone() - c[0]) / axes[0],
            );
            let mut a = cy.atan2(&cx);
            if a < 0 {
                a += Float::with_val(BITS, rug::float::Constant::Pi) * 2u32;
            }
            assert!(holds(&pb[1][0], &a), "{what}: angle {a} not in {:?}", pb[1]);
            assert_eq!(
                p.params[1][0],
                a.to_f64(),
                "{what}: angle correctly rounded"
            );
        }
    }
}

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

/// The parabola family: (scale exponent, c exponent, ε sign and exponent).
#[test]
fn osculating_circles_of_a_parabola_give_proven_contact_orders() {
    let mut n = 0;
    for (i, k) in [-500i32, -40, 0, 3, 60, 490].into_iter().enumerate() {
        for ce in [-2i32, 0, 1] {
            for eps in [
                None,
                Some((1, 10)),
                Some((-1, 10)),
                Some((1, 30)),
                Some((-1, 52)),
            ] {
                if n >= cases(90) {
                    return;
                }
                n += 1;
                let s = 2f64.powi(k);
                let c = 2f64.powi(ce);
                let e = eps.map_or(0.0, |(sg, ex)| sg as f64 * 2f64.powi(-ex));
                let rho = (1.0 + e) / (2.0 * c);
                let shift = [3.0 * s * (i as f64 - 2.0), 0.0];
                let loc = |x: f64, y: f64| [shift[0] + s * x, shift[1] + s * y];
                let ctrl = [loc(-1.0, c), loc(0.0, -c), loc(1.0, c)];
                let centre = loc(0.0, rho);
                let radius = s * rho;
                // Truth: t = ½ (multiplicity 4 or 2) and t = (1 ± √ε/c)/2 for ε > 0.
                let half = fl(0.5);
                let mut truths: Vec<Root> = vec![(half, if e == 0.0 { 4 } else { 2 })];
                if e > 0.0 {
                    let x = fl(e).sqrt() / c;
                    truths.push(((fl(1) - &x) / 2u32, 1));
                    truths.push(((fl(1) + &x) / 2u32, 1));
                    truths.sort_by(|a, b| a.0.partial_cmp(&b.0).expect("ordered"));
                }
                let at = |t: &Float| -> [Float; 2] {
                    let x = fl(2) * t - 1u32;
                    let y = x.clone() * &x * c;
                    [x * s + shift[0], y * s + shift[1]]
                };
                let bez = format!(r#"{{"type":"bezier2","points":{}}}"#, pts(&ctrl));
                let mid = |a: [f64; 2], b: [f64; 2]| [(a[0] + b[0]) / 2.0, (a[1] + b[1]) / 2.0];
                let knotted = format!(
                    r#"{{"type":"nurbs_curve2","degree":2,"knots":[0,0,0,0.5,1,1,1],"points":{}}}"#,
                    pts(&[
                        ctrl[0],
                        mid(ctrl[0], ctrl[1]),
                        mid(ctrl[1], ctrl[2]),
                        ctrl[2]
                    ])
                );
                let circ = format!(
                    r#"{{"type":"circle2","center":[{},{}],"radius":{}}}"#,
                    num(centre[0]),
                    num(centre[1]),
                    num(radius)
                );
                let what = format!("s=2^{k} c=2^{ce} ε={e:e}");
                let circle = Some((centre, [radius; 2]));
                check(&what, &solve(&case(&bez, &circ)), &truths, at, circle);
                check(
                    &format!("{what} (knot at ½)"),
                    &solve(&case(&knotted, &circ)),
                    &truths,
                    at,
                    circle,
                );
                // The same circle as an implicit conic (x−a)² + (y−b)² − r² = 0: exact
                // in doubles only where the squares are; try it at unit scale.
                if k == 0 {
                    let (a0, b0) = (centre[0], centre[1]);
                    let f = a0 * a0 + b0 * b0 - radius * radius;
                    let exact_f = fl(a0) * a0 + fl(b0) * b0 - fl(radius) * radius;
                    if exact_f == f {
                        let conic = format!(
                            r#"{{"type":"conic2","coeffs":[1,0,1,{},{},{}]}}"#,
                            num(-2.0 * a0),
                            num(-2.0 * b0),
                            num(f)
                        );
                        let r = solve(&case(&conic, &bez));
                        check_swapped(&format!("{what} (conic2)"), &r, &truths, at);
                    }
                }
            }
        }
    }
}

/// The curve second: its parameter is object 1's; the conic has none.
fn check_swapped(what: &str, r: &CaseResult, truths: &[Root], at: impl Fn(&Float) -> [Float; 2]) {
    let mut flipped = r.clone();
    for p in flipped.points.iter_mut().flatten() {
        p.params.reverse();
        if let Some(b) = p.param_box.as_mut() {
            b.reverse();
        }
    }
    check(what, &flipped, truths, at, None);
}

/// Weights of the quarter arcs: the rounded 1/√2 and others.
const WEIGHTS: [f64; 5] = [std::f64::consts::FRAC_1_SQRT_2, 0.5, 0.7, 0.75, 1.25];

#[test]
fn rounded_quarter_circles_touch_their_circle_at_both_ends() {
    for (i, &w) in WEIGHTS.iter().enumerate() {
        for k in [-300i32, 0, 7, 300] {
            for stretch in [[1.0, 1.0], [2.0, 0.75]] {
                let r = 2f64.powi(k);
                let (a, b) = (r * stretch[0], r * stretch[1]);
                let c = [a * (i as f64 - 1.0), -b * 3.0];
                let ctrl = [[c[0] + a, c[1]], [c[0] + a, c[1] + b], [c[0], c[1] + b]];
                let arc = format!(
                    r#"{{"type":"nurbs_curve2","degree":2,"knots":[0,0,0,1,1,1],"points":{},"weights":[1,{},1]}}"#,
                    pts(&ctrl),
                    num(w)
                );
                let conic = if stretch == [1.0, 1.0] {
                    format!(
                        r#"{{"type":"circle2","center":[{},{}],"radius":{}}}"#,
                        num(c[0]),
                        num(c[1]),
                        num(r)
                    )
                } else {
                    format!(
                        r#"{{"type":"ellipse2","center":[{},{}],"a":{},"b":{}}}"#,
                        num(c[0]),
                        num(c[1]),
                        num(a),
                        num(b)
                    )
                };
                let at = |t: &Float| quarter(t, w, c, [a, b]);
                let truths = vec![(fl(0), 2), (fl(1), 2)];
                let what = format!("w={w} r=2^{k} stretch {stretch:?}");
                let res = solve(&case(&arc, &conic));
                check(&what, &res, &truths, at, Some((c, [a, b])));
            }
        }
    }
}

/// The point at `t` of the rational quarter arc from `(a, 0)` to `(0, b)` about `c`.
fn quarter(t: &Float, w: f64, c: [f64; 2], ab: [f64; 2]) -> [Float; 2] {
    let u = fl(1) - t;
    let b0 = u.clone() * &u;
    let b1 = u * t * 2u32 * w;
    let b2 = t.clone() * t;
    let den = b0.clone() + &b1 + &b2;
    [
        (b0 + &b1) / &den * ab[0] + c[0],
        (b1 + b2) / &den * ab[1] + c[1],
    ]
}

#[test]
fn a_rounded_nurbs_circle_touches_its_circle_at_the_four_knots() {
    for &w in &WEIGHTS {
        for k in [-200i32, 0, 200] {
            let r = 2f64.powi(k);
            let p = |x: f64, y: f64| [r * x, r * y];
            let ctrl = [
                p(1.0, 0.0),
                p(1.0, 1.0),
                p(0.0, 1.0),
                p(-1.0, 1.0),
                p(-1.0, 0.0),
                p(-1.0, -1.0),
                p(0.0, -1.0),
                p(1.0, -1.0),
                p(1.0, 0.0),
            ];
            let ws = [1.0, w, 1.0, w, 1.0, w, 1.0, w, 1.0];
            let ring = format!(
                r#"{{"type":"nurbs_curve2","degree":2,"knots":[0,0,0,0.25,0.25,0.5,0.5,0.75,0.75,1,1,1],"points":{},"weights":[{}]}}"#,
                pts(&ctrl),
                ws.iter().map(|&x| num(x)).collect::<Vec<_>>().join(",")
            );
            let circ = format!(r#"{{"type":"circle2","center":[0,0],"radius":{}}}"#, num(r));
            let truths: Vec<Root> = [0.0, 0.25, 0.5, 0.75]
                .into_iter()
                .map(|t| (fl(t), 2))
                .collect();
            let at = |t: &Float| {
                let k = t.to_f64();
                let exact = |x: f64, y: f64| [fl(x * r), fl(y * r)];
                match k {
                    0.0 => exact(1.0, 0.0),
                    0.25 => exact(0.0, 1.0),
                    0.5 => exact(-1.0, 0.0),
                    _ => exact(0.0, -1.0),
                }
            };
            let what = format!("ring w={w} r=2^{k}");
            check(
                &what,
                &solve(&case(&ring, &circ)),
                &truths,
                at,
                Some(([0.0; 2], [r; 2])),
            );
        }
    }
}

/// The circle's equation at the rational Bézier's point (de Casteljau in MPFR,
/// [`truth_support::bezier2_at`]).
fn circle_at(ctrl: &[[f64; 2]], w: &[f64], c: [f64; 2], r: f64, t: &Float) -> Float {
    let [x, y] = truth_support::bezier2_at(ctrl, w, t);
    let dx = x - c[0];
    let dy = y - c[1];
    dx.clone() * &dx + dy.clone() * &dy - fl(r) * r
}

/// Random rational cubics against random circles: every sign change of the circle's
/// equation along the curve (a 2048-cell scan in MPFR, each bracket bisected to
/// 1024 bits), and an end point lying on the circle, lies in exactly one reported
/// parameter box, and the points of odd multiplicity are exactly as many.
#[test]
fn random_rational_cubics_cross_circles_where_an_independent_scan_says() {
    let mut g = truth_support::conics::Gen::new(2301);
    let mut crossings = 0;
    for i in 0..cases(120) {
        let ctrl: Vec<[f64; 2]> = (0..4).map(|_| g.vec::<2>(-2.0, 2.0, 4)).collect();
        let w: Vec<f64> = (0..4).map(|_| g.dyadic(0.25, 2.0, 4)).collect();
        let (c, r) = (g.vec::<2>(-1.0, 1.0, 4), g.dyadic(0.25, 2.0, 4));
        let bez = format!(
            r#"{{"type":"bezier2","points":{},"weights":[{}]}}"#,
            pts(&ctrl),
            w.iter().map(|&x| num(x)).collect::<Vec<_>>().join(",")
        );
        let circ = format!(
            r#"{{"type":"circle2","center":[{},{}],"radius":{}}}"#,
            num(c[0]),
            num(c[1]),
            num(r)
        );
        let res = solve(&case(&bez, &circ));
        let what = format!("case {i}: {bez} × {circ}");
        assert_eq!(res.status, "exact", "{what}");
        assert_eq!(res.complete, Some(true), "{what}");
        let f = |t: &Float| circle_at(&ctrl, &w, c, r, t);
        const CELLS: u32 = 2048;
        let mut roots = Vec::new();
        let mut prev = f(&fl(0));
        if prev == 0 {
            roots.push(fl(0)); // a control point on the circle: a root at the end
        }
        for k in 1..=CELLS {
            let t = fl(k) / CELLS;
            let v = f(&t);
            if k == CELLS && v == 0 {
                roots.push(t.clone());
            }
            if (prev < 0 && v > 0) || (prev > 0 && v < 0) {
                let (mut lo, mut hi) = (fl(k - 1) / CELLS, t.clone());
                let lo_neg = prev < 0;
                for _ in 0..1000 {
                    let mid = (lo.clone() + &hi) / 2u32;
                    if (f(&mid) < 0) == lo_neg {
                        lo = mid;
                    } else {
                        hi = mid;
                    }
                }
                roots.push(lo);
            }
            prev = v;
        }
        crossings += roots.len();
        let points = res.points.as_deref().unwrap_or_default();
        let odd = points.iter().filter(|p| p.multiplicity % 2 == 1).count();
        assert_eq!(odd, roots.len(), "{what}: {points:?}");
        for t in &roots {
            let holding = points
                .iter()
                .filter(|p| holds(&p.param_box.as_ref().expect("param_box")[0][0], t))
                .count();
            assert_eq!(holding, 1, "{what}: the crossing at t = {t}");
        }
    }
    assert!(crossings > 50, "the family crosses: {crossings}");
}
