//! Two Bézier or NURBS curves sharing an arc (issue 20), a generated family with exact
//! truth: integer control points (so that every split below is exact in doubles), one
//! curve built from the other in rationals — a half or a middle piece of a de Casteljau
//! split, the reversed polygon, the same curve as a NURBS with a knot inserted (Boehm),
//! two overlapping pieces — in the plane and in space, degrees 1 to 5. The truth (which
//! arc, its end parameters on both curves) is known from the construction; the answer
//! must be `coincident`, or kind `arc` with exactly those end parameters (as exact
//! rationals), `complete` exactly when the arc is all of one curve.

use geocert::io::{read_cases, solve_case};
use geocert::num::rng::Rng;
mod exact_bezier_support;
use exact_bezier_support::*;
use rug::Rational;
use serde_json::{json, Value};

fn run(case: &Value) -> Value {
    let read = read_cases(&case.to_string()).into_iter().next().unwrap();
    serde_json::from_str(&solve_case(read).to_json_line()).unwrap()
}

/// The Bézier curve `p` as a NURBS of the same degree with the knot 1/2 inserted.
fn knotted(p: &Poly) -> Value {
    let deg = p.len() - 1;
    let half = Rational::from((1, 2));
    let mut q = vec![p[0].clone()];
    for j in 1..=deg {
        // α_j = (u − u_j)/(u_{j+p} − u_j) with u_j = 0, u_{j+p} = 1.
        q.push(lerp(&p[j - 1], &p[j], &half));
    }
    q.push(p[deg].clone());
    let mut knots = vec![0.0; deg + 1];
    knots.push(0.5);
    knots.extend(vec![1.0; deg + 1]);
    let t = if p[0].len() == 2 {
        "nurbs_curve2"
    } else {
        "nurbs_curve"
    };
    json!({"type": t, "degree": deg, "knots": knots, "points": doubles(&q)})
}

fn q(n: i64, d: i64) -> Rational {
    Rational::from((n, d))
}

/// The exact parameter `i` (0: first curve, 1: second) of an end of the arc.
fn param(end: &Value, i: usize) -> Rational {
    let s = end["exact"]["params"][i][0].as_str().unwrap();
    s.parse::<Rational>().unwrap()
}

/// The arc's ends as `[(t, s); 2]`, in either order.
fn ends(r: &Value) -> Vec<(Rational, Rational)> {
    let arc = &r["arc"];
    let mut e: Vec<_> = ["a", "b"]
        .iter()
        .map(|k| (param(&arc[k], 0), param(&arc[k], 1)))
        .collect();
    e.sort();
    e
}

#[test]
fn curves_sharing_an_arc_are_decided_exactly() {
    let mut rng = Rng::new(2030);
    let mut seen = [0usize; 5];
    for i in 0..100 {
        let dim = 2 + i % 2;
        let deg = 1 + (i / 2) % 5;
        let p: Poly = (0..=deg)
            .map(|_| (0..dim).map(|_| Rational::from(rng.int(-64, 64))).collect())
            .collect();
        let how = (i / 10) % 5;
        seen[how] += 1;
        // (first, second, truth): truth None = coincident, else the ends (t, s) and
        // whether the answer is complete.
        let (a, b, truth) = match how {
            0 => {
                let h = q(1, 2);
                let (l, _) = split(&p, &h);
                (
                    bezier(&p),
                    bezier(&l),
                    Some((vec![(q(0, 1), q(0, 1)), (h, q(1, 1))], true)),
                )
            }
            1 => {
                let r: Poly = p.iter().rev().cloned().collect();
                (bezier(&p), bezier(&r), None)
            }
            2 => (knotted(&p), bezier(&p), None),
            3 => {
                let m = piece(&p, &q(1, 4), &q(3, 4));
                let t = vec![(q(1, 4), q(0, 1)), (q(3, 4), q(1, 1))];
                (bezier(&p), bezier(&m), Some((t, true)))
            }
            _ => {
                // [0, 3/4] against [1/4, 1]: they share [1/4, 3/4], each goes on beyond.
                let (l, _) = split(&p, &q(3, 4));
                let (_, r) = split(&p, &q(1, 4));
                // On l (t = 4u/3) and r (s = (4u − 1)/3): u = 1/4 → (1/3, 0), u = 3/4 → (1, 2/3).
                let t = vec![(q(1, 3), q(0, 1)), (q(1, 1), q(2, 3))];
                (bezier(&l), bezier(&r), Some((t, false)))
            }
        };
        let case = json!({"op": "intersect", "objects": [a, b], "options": {"time_limit": 30}});
        let r = run(&case);
        assert_eq!(r["status"], "exact", "{case}: {r}");
        match truth {
            None => {
                assert_eq!(r["kind"], "coincident", "{case}: {r}");
                assert_eq!(r["complete"], true, "{case}: {r}");
            }
            Some((t, complete)) => {
                assert_eq!(r["kind"], "arc", "{case}: {r}");
                assert_eq!(r["complete"], complete, "{case}: {r}");
                assert_eq!(ends(&r), t, "{case}: {r}");
                // The same pair the other way round: the parameters swap.
                let swapped = json!({"op": "intersect", "objects": [b, a]});
                let s = run(&swapped);
                let mut flip: Vec<_> = t.iter().map(|(x, y)| (y.clone(), x.clone())).collect();
                flip.sort();
                assert_eq!(ends(&s), flip, "{swapped}: {s}");
            }
        }
    }
    assert!(seen.iter().all(|&n| n == 20));
}

/// A rational Bézier against its reversed copy (weights reversed too) is the same
/// curve; against the copy with every weight doubled it is the same parametrisation.
#[test]
fn rational_copies_are_coincident() {
    let mut rng = Rng::new(2031);
    for i in 0..40 {
        let n = 2 + i % 5;
        let pts: Vec<Vec<f64>> = (0..n)
            .map(|_| (0..2 + i % 2).map(|_| rng.int(-50, 50) as f64).collect())
            .collect();
        let w: Vec<f64> = (0..n).map(|_| rng.int(1, 40) as f64 / 8.0).collect();
        let t = if i % 2 == 0 { "bezier2" } else { "bezier" };
        let a = json!({"type": t, "points": pts, "weights": w});
        let b = if i % 4 < 2 {
            let (mut p, mut v) = (pts.clone(), w.clone());
            p.reverse();
            v.reverse();
            json!({"type": t, "points": p, "weights": v})
        } else {
            let v: Vec<f64> = w.iter().map(|x| 2.0 * x).collect();
            json!({"type": t, "points": pts, "weights": v})
        };
        let case = json!({"op": "intersect", "objects": [a, b]});
        let r = run(&case);
        assert_eq!(r["status"], "exact", "{case}: {r}");
        assert_eq!(r["kind"], "coincident", "{case}: {r}");
    }
}
