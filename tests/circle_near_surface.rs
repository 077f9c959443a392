//! A circle near, tangent to, or crossing a sphere (issue 14 item 5 and defect 8),
//! decided exactly in the circle's plane: circles in planes `z = h` meeting a sphere
//! whose section there has a rational radius `s`, at gaps from tangency of 1e-3 … 1e-15
//! and 0 (both sides). Truth in exact rationals: the section circle (centre on the
//! axis, radius `s`) and the circle (centre at distance `d`, radius `ρ`) meet in two
//! points when `(s − ρ)² < d² < (s + ρ)²`, one (tangent) at equality, none otherwise;
//! the points are `x = (d² + s² − ρ²)/2d`, `y = ±√(s² − x²)` (MPFR, 2000 bits).

#![allow(
    clippy::needless_range_loop,
    clippy::cmp_owned,
    clippy::useless_conversion
)]

use geocert::certificate::Status;
use geocert::io::{read_cases, shape};
use geocert::num::rng::Rng;
use geocert::ops::{self, Answer, Point};
use rug::{Float, Rational};

const BITS: u32 = 2000;

fn solve(json: &str) -> geocert::Certified<Answer> {
    let read = read_cases(json).pop().expect("one case");
    let case = read.case.expect("a valid case");
    let options = geocert::io::options(&case).expect("options");
    let shapes: Vec<_> = case
        .objects
        .iter()
        .map(|o| shape(o, "objects").expect("shape"))
        .collect();
    ops::intersect(&shapes, &options).expect("solves")
}

fn points(a: &Answer) -> &[Point] {
    match a {
        Answer::Points(p) => p,
        Answer::Empty => &[],
        other => panic!("expected points, got {other:?}"),
    }
}

fn q(x: f64) -> Rational {
    Rational::from_f64(x).expect("finite")
}

#[test]
fn circles_at_gaps_from_tangency_to_a_sphere() {
    let mut rng = Rng::new(1407);
    // (R, h, s) with R² − h² = s², dyadic
    let sections = [
        (1.25, 0.75, 1.0),
        (1.25, -0.75, 1.0),
        (2.5, 2.0, 1.5),
        (1.0, 0.0, 1.0),
    ];
    let gaps = [1e-3, 1e-6, 1e-9, 1e-12, 1e-15, 0.0];
    let mut counts = [0usize; 3];
    for case in 0..300 {
        let (r_big, h, s) = sections[rng.below(sections.len())];
        let rho = 0.25 + (rng.below(8) as f64) / 8.0;
        let gap = gaps[case % gaps.len()] * if rng.coin() { 1.0 } else { -1.0 };
        // external (d = s + ρ) or internal (d = |s − ρ|) tangency, moved by the gap
        let d = if rng.coin() || rho == s {
            s + rho + gap
        } else {
            (s - rho).abs() + gap
        };
        if d <= 0.0 {
            continue;
        }
        let sign = if rng.coin() { 1.0 } else { -1.0 };
        let json = format!(
            r#"{{"id":"t","op":"intersect","objects":[{{"type":"circle","center":[{:?},0.0,{h:?}],"radius":{rho:?},"axis":[0.0,0.0,{sign:?}]}},{{"type":"sphere","center":[0.0,0.0,0.0],"radius":{r_big:?}}}]}}"#,
            d
        );
        let r = solve(&json);
        assert_ne!(r.status, Status::Undecided, "{json}: {:?}", r.reason);
        assert!(r.complete, "{json}");
        let (dq, sq, pq) = (q(d), q(s), q(rho));
        let d2 = Rational::from(&dq * &dq);
        let lo = (sq.clone() - &pq).square();
        let hi = (sq.clone() + &pq).square();
        let pts = points(&r.value);
        let x = (d2.clone() + sq.clone().square() - pq.clone().square()) / (dq.clone() * 2u32);
        let y2 = sq.square() - x.clone().square();
        let truths: Vec<[Float; 2]> = if d2 > lo && d2 < hi {
            counts[0] += 1;
            let y = Float::with_val(BITS, &y2).sqrt();
            vec![
                [Float::with_val(BITS, &x), -y.clone()],
                [Float::with_val(BITS, &x), y],
            ]
        } else if d2 == lo || d2 == hi {
            counts[1] += 1;
            assert_eq!(pts.len(), 1, "{json}: tangent: {pts:?}");
            assert_eq!(pts[0].multiplicity, 2, "{json}");
            assert!(pts[0].tangent, "{json}");
            vec![[Float::with_val(BITS, &x), Float::with_val(BITS, 0)]]
        } else {
            counts[2] += 1;
            Vec::new()
        };
        assert_eq!(pts.len(), truths.len(), "{json}: {pts:?}");
        let holds = |p: &Point, t: &[Float; 2]| {
            p.xyz_box[0][0] <= t[0]
                && t[0] <= p.xyz_box[0][1]
                && p.xyz_box[1][0] <= t[1]
                && t[1] <= p.xyz_box[1][1]
                && p.xyz_box[2][0] <= h
                && h <= p.xyz_box[2][1]
        };
        for t in &truths {
            assert_eq!(
                pts.iter().filter(|p| holds(p, t)).count(),
                1,
                "{json}: {t:?} in {pts:?}"
            );
        }
        for p in pts {
            assert_eq!(
                truths.iter().filter(|t| holds(p, t)).count(),
                1,
                "{json}: {p:?}"
            );
        }
    }
    assert!(
        counts.iter().all(|&c| c > 10),
        "every kind exercised: {counts:?}"
    );
}
