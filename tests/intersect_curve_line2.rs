//! Bézier2 (plain and rational) ∩ `line2` / `segment2` through the front door (issue 16,
//! step 2), decided exactly. Families: quadratics whose signed distance to the line is
//! `k(t − r₁)(t − r₂)` (dyadic roots by construction, exact rationals compared), double
//! roots (tangency, multiplicity 2) and the line moved by ±1 ulp (0 or 2 points),
//! segments ending exactly on the curve and 1 ulp off it, curves lying on the line; the
//! truth is exact rationals (de Casteljau), compared bit for bit after rounding.
//! `GEOCERT_CURVE_LINE2_CASES` sets the number of cases per family (default 200).

use geocert::curve::{AnyCurve2, Bezier};
use geocert::geom::{Line2, Segment2};
use geocert::ops::{self, Answer, Linear, LinearObject, Options, Point, Shape};
use geocert::robust::rng::Rng;
use geocert::Status;
use nalgebra::Vector2;
use rug::float::Round;
use rug::{Float, Rational};

fn cases() -> usize {
    std::env::var("GEOCERT_CURVE_LINE2_CASES")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(200)
}

fn q(x: f64) -> Rational {
    Rational::from_f64(x).expect("finite")
}

fn line(o: [f64; 2], d: [f64; 2]) -> Shape {
    Shape::Linear(Linear::Double(LinearObject::Line2(
        Line2::new(Vector2::from(o), Vector2::from(d)).expect("line"),
    )))
}

fn segment(a: [f64; 2], b: [f64; 2]) -> Shape {
    Shape::Linear(Linear::Double(LinearObject::Segment2(
        Segment2::new(Vector2::from(a), Vector2::from(b)).expect("segment"),
    )))
}

fn bezier(pts: &[[f64; 2]], w: Option<Vec<f64>>) -> Shape {
    Shape::Curve2(AnyCurve2::Bezier(
        Bezier::new(pts.to_vec(), w, None).expect("bezier"),
    ))
}

/// The exact answer's points, curve parameter first.
fn solve(curve: &Shape, l: &Shape, curve_first: bool) -> Vec<Point> {
    let shapes = if curve_first {
        vec![curve.clone(), l.clone()]
    } else {
        vec![l.clone(), curve.clone()]
    };
    let c = ops::intersect(&shapes, &Options::default()).expect("answers");
    assert_eq!(c.status, Status::Exact, "{c:?}");
    assert!(c.complete);
    let mut pts = match &c.value {
        Answer::Empty => vec![],
        Answer::Points(p) => p.clone(),
        other => panic!("points expected, got {other:?}"),
    };
    for p in &mut pts {
        if !curve_first {
            p.params.swap(0, 1);
            if let Some(b) = p.param_box.as_mut() {
                b.swap(0, 1);
            }
        }
    }
    pts.sort_by(|x, y| x.params[0][0].total_cmp(&y.params[0][0]));
    pts
}

/// Exact point of a polynomial Bézier at `t` (de Casteljau).
fn bezier_at(pts: &[[f64; 2]], t: &Rational) -> [Rational; 2] {
    let mut v: Vec<[Rational; 2]> = pts.iter().map(|p| p.map(q)).collect();
    while v.len() > 1 {
        v = v
            .windows(2)
            .map(|w| {
                std::array::from_fn(|i| {
                    (&w[0][i] * (Rational::from(1) - t)) + Rational::from(&w[1][i] * t)
                })
            })
            .collect();
    }
    v.swap_remove(0)
}

fn round(x: &Rational) -> f64 {
    Float::with_val(2000, x).to_f64_round(Round::Nearest)
}

/// Quadratics `y = h + k·(t − r₁)(t − r₂)` (Bernstein ordinates) against `y = h` as a
/// line of random x-direction scale: the roots in `[0, 1]` exactly, tangency when
/// `r₁ = r₂`, and the line moved 1 ulp off a tangency (2 points on the inner side, none
/// on the outer, decided exactly); the curve lying on the line is `coincident`.
#[test]
fn known_roots_tangency_and_ulp() {
    let mut rng = Rng::new(16_201);
    for case in 0..cases() {
        let r1 = rng.int(-4, 12) as f64 / 8.0;
        let r2 = if case % 4 == 0 {
            r1
        } else {
            rng.int(-4, 12) as f64 / 8.0
        };
        let h = rng.small_int();
        let k = [1.0, 3.0, -0.25][case % 3];
        let b = [r1 * r2, r1 * r2 - (r1 + r2) / 2.0, (1.0 - r1) * (1.0 - r2)];
        let pts: Vec<[f64; 2]> = (0..3).map(|i| [rng.generic(), h + k * b[i]]).collect();
        let curve = bezier(&pts, None);
        let dx = [1.0, 0.5, -3.0][case % 3];
        let ox = rng.small_int();
        let got = solve(&curve, &line([ox, h], [dx, 0.0]), case % 2 == 0);
        let mut want: Vec<f64> = [r1, r2]
            .into_iter()
            .filter(|r| (0.0..=1.0).contains(r))
            .collect();
        want.sort_by(f64::total_cmp);
        want.dedup();
        assert_eq!(got.len(), want.len(), "case {case}: {r1} {r2} {got:?}");
        for (p, &t) in got.iter().zip(&want) {
            assert_eq!(p.params[0][0], t);
            let x = bezier_at(&pts, &q(t));
            let e = p.exact.as_ref().expect("exact values");
            for (i, xi) in x.iter().enumerate().take(2) {
                assert_eq!(p.xyz[i], round(xi), "case {case} xyz[{i}]");
                assert_eq!(e.xyz[i], *xi);
            }
            let s = (x[0].clone() - q(ox)) / q(dx);
            assert_eq!(p.params[1][0], round(&s), "case {case} s");
            assert_eq!(p.multiplicity, if r1 == r2 { 2 } else { 1 });
            assert_eq!(p.tangent, r1 == r2);
        }
        if r1 == r2 && (0.0..=1.0).contains(&r1) {
            // Inside the parabola (towards k's side) two crossings, outside none.
            for up in [true, false] {
                let hh = if up { h.next_up() } else { h.next_down() };
                let inside = (k > 0.0) == up;
                let got = solve(&curve, &line([ox, hh], [dx, 0.0]), case % 2 == 1);
                if !inside {
                    assert!(got.is_empty(), "case {case} ulp {up}: {got:?}");
                } else if r1 > 0.0 && r1 < 1.0 {
                    assert_eq!(got.len(), 2, "case {case} ulp {up}: {got:?}");
                }
                assert!(got.iter().all(|p| p.multiplicity == 1 && !p.tangent));
            }
        }
        let on: Vec<[f64; 2]> = pts.iter().map(|p| [p[0], h]).collect();
        let r = ops::intersect(
            &[bezier(&on, None), line([ox, h], [dx, 0.0])],
            &Options::default(),
        );
        let r = r.unwrap();
        assert_eq!(r.value, Answer::Coincident);
        assert_eq!(r.status, Status::Exact);
    }
}

/// Segments from a dyadic point of a dyadic quadratic, at a dyadic parameter, to a
/// point off the curve: the end is found, at its exact parameters (segment 0 or 1);
/// the same segment with that end moved 1 ulp answers only points whose segment
/// parameter is proven inside `[0, 1]`.
#[test]
fn segment_ends_on_the_curve() {
    let mut rng = Rng::new(16_202);
    for case in 0..cases() {
        let pts: Vec<[f64; 2]> = (0..3)
            .map(|_| [rng.int(-8, 8) as f64 / 4.0, rng.int(-8, 8) as f64 / 4.0])
            .collect();
        let t = rng.int(1, 15) as f64 / 16.0;
        let x = bezier_at(&pts, &q(t));
        let e = [x[0].to_f64(), x[1].to_f64()];
        assert_eq!([q(e[0]), q(e[1])], x, "dyadic point");
        let other = [e[0] + rng.int(-9, 9) as f64 + 0.5, e[1] + 10.0];
        let w = (case % 2 == 1).then(|| vec![1.0, 1.0, 1.0]);
        let curve = bezier(&pts, w);
        let (a, b, at) = if case % 4 < 2 {
            (e, other, 0.0)
        } else {
            (other, e, 1.0)
        };
        let got = solve(&curve, &segment(a, b), case % 3 == 0);
        let hit: Vec<&Point> = got.iter().filter(|p| p.params[0][0] == t).collect();
        assert_eq!(hit.len(), 1, "case {case}: {got:?}");
        assert_eq!(hit[0].params[1][0], at);
        assert_eq!(hit[0].xyz, e.to_vec());
        // 1 ulp short: move the end off the curve along x towards the other end.
        let short = |p: [f64; 2]| {
            let nx = if other[0] > p[0] {
                p[0].next_up()
            } else {
                p[0].next_down()
            };
            [nx, p[1]]
        };
        let (a2, b2) = if at == 0.0 {
            (short(a), b)
        } else {
            (a, short(b))
        };
        let got = solve(&curve, &segment(a2, b2), case % 3 == 1);
        for p in &got {
            let s = &p.param_box.as_ref().unwrap()[1][0];
            assert!(s[0] >= 0.0 && s[1] <= 1.0, "case {case}: {p:?}");
        }
    }
}
