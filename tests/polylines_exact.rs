//! Polylines against planes, segments and polylines, decided exactly through the
//! front door (issue 16: "polyline against a plane — exact"; issue 20: polyline2 pairs
//! the fuzzer found running past their time limit). Families on small integer grids,
//! so that vertices on the plane, pieces lying in it, collinear overlaps, crossings at
//! vertices and collapsed pieces are frequent; scaled by 2^±200 and with
//! non-dyadic parameters (multiples of 0.1) so that rounding matters. The truth is
//! computed here with exact rationals by another route (the plane's value at the
//! vertices; Cramer's rule and projections for two segments), and every reported
//! parameter and coordinate must be the truth correctly rounded, one to one.
//! `GEOCERT_POLYLINE_CASES` sets the number of cases per family (default 400).

use geocert::curve::{AnyCurve2, AnyCurve3, Polyline};
use geocert::geom::Plane;
use geocert::num::rng::Rng;
use geocert::ops::{self, Answer, Linear, LinearObject, Options, Point, Shape};
use geocert::{Certified, Status};
use nalgebra::Vector3;
use rug::float::Round;
use rug::{Float, Rational};

fn cases() -> usize {
    std::env::var("GEOCERT_POLYLINE_CASES")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(400)
}

fn q(x: f64) -> Rational {
    Rational::from_f64(x).expect("finite")
}

/// The double nearest to `x` (ties to even), through MPFR at 53 bits.
fn round(x: &Rational) -> f64 {
    Float::with_val_round(53, x, Round::Nearest).0.to_f64()
}

/// Vertices on a grid of `-r..=r` scaled by `scale`, with repeats now and then.
fn vertices(rng: &mut Rng, n: usize, dim: usize, r: i64, scale: f64) -> Vec<Vec<f64>> {
    let mut v: Vec<Vec<f64>> = Vec::new();
    for _ in 0..n {
        if !v.is_empty() && rng.below(12) == 0 {
            v.push(v[v.len() - 1].clone());
        } else {
            v.push((0..dim).map(|_| rng.int(-r, r) as f64 * scale).collect());
        }
    }
    v
}

/// Increasing parameters: the default `0, 1, 2, …`, or steps of 0.1 (not dyadic).
fn params(rng: &mut Rng, n: usize) -> Option<Vec<f64>> {
    rng.coin().then(|| {
        let mut t = rng.int(-5, 5) as f64 * 0.1;
        (0..n)
            .map(|_| {
                t += rng.int(1, 4) as f64 * 0.1;
                t
            })
            .collect()
    })
}

fn polyline(v: &[Vec<f64>], t: Option<Vec<f64>>) -> Shape {
    if v[0].len() == 2 {
        let pts = v.iter().map(|p| [p[0], p[1]]).collect();
        Shape::Curve2(AnyCurve2::Polyline(
            Polyline::new(pts, t).expect("polyline2"),
        ))
    } else {
        let pts = v.iter().map(|p| [p[0], p[1], p[2]]).collect();
        Shape::Curve(AnyCurve3::Polyline(
            Polyline::new(pts, t).expect("polyline"),
        ))
    }
}

fn param_values(v: &[Vec<f64>], t: &Option<Vec<f64>>) -> Vec<Rational> {
    match t {
        Some(t) => t.iter().map(|x| q(*x)).collect(),
        None => (0..v.len()).map(|i| Rational::from(i as i64)).collect(),
    }
}

/// A common point of the truth: the point and the polyline parameter(s).
#[derive(Debug, Clone, PartialEq)]
struct Truth {
    xyz: Vec<Rational>,
    t: Vec<Rational>,
}

fn lerp(a: &[Rational], b: &[Rational], w: &Rational) -> Vec<Rational> {
    a.iter()
        .zip(b)
        .map(|(a, b)| a.clone() + w.clone() * (b.clone() - a.clone()))
        .collect()
}

/// Every reported point equals one truth (coordinates and polyline parameters
/// correctly rounded, and the parameter boxes hold the exact parameter) and every
/// truth is reported once, in order of the first polyline's parameter.
fn assert_points(got: &[Point], truth: &[Truth], slots: &[usize], case: &str) {
    assert_eq!(got.len(), truth.len(), "{case}: {got:?} vs {truth:?}");
    for (p, t) in got.iter().zip(truth) {
        let xyz: Vec<f64> = t.xyz.iter().map(round).collect();
        assert_eq!(p.xyz, xyz, "{case}");
        for (k, &slot) in slots.iter().enumerate() {
            assert_eq!(p.params[slot], vec![round(&t.t[k])], "{case}");
            let b = p.param_box.as_ref().expect("boxes")[slot][0];
            assert!(q(b[0]) <= t.t[k] && t.t[k] <= q(b[1]), "{case}: box {b:?}");
        }
    }
}

/// The points of an answer that must be exact and complete (none for `empty`).
fn exact_points(r: &Certified<Answer>, label: &str) -> Vec<Point> {
    assert_eq!(r.status, Status::Exact, "{label}: {r:?}");
    assert!(r.complete, "{label}");
    match &r.value {
        Answer::Empty => vec![],
        Answer::Points(p) => p.clone(),
        other => panic!("{label}: {other:?}"),
    }
}

/// The plane `n·x + d = 0` as an implicit plane.
fn plane(n: [f64; 3], d: f64) -> Shape {
    Shape::Linear(Linear::Double(LinearObject::Plane(
        Plane::implicit(Vector3::from(n), d).expect("plane"),
    )))
}

/// What a polyline against a plane must give: isolated points, or one run of pieces
/// in the plane (its end parameters, its piece count), or an answer the format cannot
/// hold (`None`: isolated points beside a run, several runs, a collapsed piece on the
/// plane).
enum PlaneTruth {
    Points(Vec<Truth>),
    Run {
        ends: [Rational; 2],
        pieces: usize,
        whole: bool,
    },
    Mixed,
}

fn plane_truth(v: &[Vec<f64>], t: &[Rational], n: [f64; 3], d: f64) -> PlaneTruth {
    let f: Vec<Rational> = v
        .iter()
        .map(|p| p.iter().zip(n).fold(q(d), |s, (x, n)| s + q(*x) * q(n)))
        .collect();
    let exact: Vec<Vec<Rational>> = v
        .iter()
        .map(|p| p.iter().map(|x| q(*x)).collect())
        .collect();
    let mut hits: Vec<Truth> = Vec::new();
    let mut runs: Vec<(usize, usize)> = Vec::new(); // pieces [first, last]
    let pieces = v.len() - 1;
    for i in 0..pieces {
        let collapsed = v[i] == v[i + 1];
        if f[i] == 0 && f[i + 1] == 0 {
            if collapsed {
                return PlaneTruth::Mixed; // every parameter of the piece is a solution
            }
            match runs.last_mut() {
                Some(r) if r.1 + 1 == i => r.1 = i,
                _ => runs.push((i, i)),
            }
            continue;
        }
        if collapsed {
            continue;
        }
        for (end, fe) in [(i, &f[i]), (i + 1, &f[i + 1])] {
            if *fe == 0 {
                hits.push(Truth {
                    xyz: exact[end].clone(),
                    t: vec![t[end].clone()],
                });
            }
        }
        if f[i].cmp0() != f[i + 1].cmp0() && f[i] != 0 && f[i + 1] != 0 {
            let w = f[i].clone() / (f[i].clone() - f[i + 1].clone());
            hits.push(Truth {
                xyz: lerp(&exact[i], &exact[i + 1], &w),
                t: vec![t[i].clone() + w * (t[i + 1].clone() - t[i].clone())],
            });
        }
    }
    hits.sort_by(|a, b| a.t[0].cmp(&b.t[0]));
    hits.dedup();
    match runs.as_slice() {
        [] => PlaneTruth::Points(hits),
        [(a, b)] => {
            let (ta, tb) = (t[*a].clone(), t[*b + 1].clone());
            hits.retain(|h| h.t[0] < ta || h.t[0] > tb);
            if !hits.is_empty() {
                return PlaneTruth::Mixed;
            }
            PlaneTruth::Run {
                whole: *a == 0 && *b == pieces - 1,
                ends: [ta, tb],
                pieces: b - a + 1,
            }
        }
        _ => PlaneTruth::Mixed,
    }
}

#[test]
fn polylines_against_planes_are_decided_exactly() {
    let mut rng = Rng::new(0x9017_11e5);
    let (mut points, mut runs, mut mixed) = (0, 0, 0);
    for case in 0..cases() {
        let scale = [1.0, 0.125, 2f64.powi(200), 2f64.powi(-200)][case % 4];
        let n = 2 + rng.below(6);
        let mut v = vertices(&mut rng, n, 3, 2, scale);
        let flat = rng.below(4) == 0;
        if flat {
            // a stretch of vertices in the plane z = 0 (runs of pieces in the plane)
            let first = rng.below(n);
            for p in v.iter_mut().skip(first).take(1 + rng.below(n)) {
                p[2] = 0.0;
            }
        }
        if v.windows(2).all(|w| w[0] == w[1]) {
            continue; // a polyline that is one point: not this route
        }
        let t = params(&mut rng, n);
        let tv = param_values(&v, &t);
        let (normal, d) = if flat {
            ([0.0, 0.0, rng.int(1, 3) as f64], 0.0)
        } else {
            (
                [0, 1, 2].map(|_| rng.int(-2, 2) as f64),
                rng.int(-2, 2) as f64 * scale,
            )
        };
        if normal == [0.0; 3] {
            continue;
        }
        let curve_first = rng.coin();
        let shapes = if curve_first {
            vec![polyline(&v, t.clone()), plane(normal, d)]
        } else {
            vec![plane(normal, d), polyline(&v, t.clone())]
        };
        let slot = usize::from(!curve_first);
        let label = format!("case {case}: {v:?} {t:?} · {normal:?} + {d}");
        let r = ops::intersect(&shapes, &Options::default()).expect("answers");
        match plane_truth(&v, &tv, normal, d) {
            PlaneTruth::Points(truth) => {
                points += 1;
                assert_points(&exact_points(&r, &label), &truth, &[slot], &label);
            }
            PlaneTruth::Run {
                ends,
                pieces,
                whole,
            } => {
                runs += 1;
                assert_eq!(r.status, Status::Exact, "{label}: {r:?}");
                let run = match (&r.value, whole, pieces) {
                    (Answer::Coincident, true, _) => continue,
                    (Answer::Segment(s), false, 1) | (Answer::Arc(s), false, 2..) => s,
                    (other, ..) => panic!("{label}: {other:?} for {pieces} piece(s)"),
                };
                assert_eq!(run.a.params[slot], vec![round(&ends[0])], "{label}");
                assert_eq!(run.b.params[slot], vec![round(&ends[1])], "{label}");
            }
            PlaneTruth::Mixed => {
                mixed += 1;
                assert_eq!(r.status, Status::Undecided, "{label}: {r:?}");
                assert!(!r.complete);
            }
        }
    }
    eprintln!("polyline ∩ plane: {points} point cases, {runs} runs, {mixed} mixed");
    // Anti-vacuity: every kind of truth occurs often.
    let n = cases();
    assert!(
        points > n / 4 && runs > n / 50 && mixed > n / 50,
        "{points} {runs} {mixed}"
    );
}

/// Two plane segments exactly: a crossing or touching point `(w, v)`, a collinear
/// overlap, or nothing.
enum SegTruth {
    None,
    Point(Rational, Rational),
    Overlap,
}

fn cross(a: &[Rational], b: &[Rational]) -> Rational {
    a[0].clone() * b[1].clone() - a[1].clone() * b[0].clone()
}

fn sub(a: &[Rational], b: &[Rational]) -> Vec<Rational> {
    a.iter()
        .zip(b)
        .map(|(a, b)| a.clone() - b.clone())
        .collect()
}

fn dot(a: &[Rational], b: &[Rational]) -> Rational {
    a.iter().zip(b).map(|(a, b)| a.clone() * b.clone()).sum()
}

fn segments(p: &[Rational], q: &[Rational], r: &[Rational], s: &[Rational]) -> SegTruth {
    let (e, f, g) = (sub(q, p), sub(s, r), sub(r, p));
    let den = cross(&e, &f);
    let unit = |x: &Rational| *x >= 0 && *x <= 1;
    if den != 0 {
        let w = cross(&g, &f) / den.clone();
        let v = cross(&g, &e) / den;
        return if unit(&w) && unit(&v) {
            SegTruth::Point(w, v)
        } else {
            SegTruth::None
        };
    }
    if cross(&g, &e) != 0 {
        return SegTruth::None; // parallel, apart
    }
    // Collinear: r and s along p→q.
    let ee = dot(&e, &e);
    let (wr, ws) = (dot(&g, &e) / ee.clone(), dot(&sub(s, p), &e) / ee);
    let (lo, hi) = if wr <= ws { (wr, ws) } else { (ws, wr) };
    let (a, b) = (lo.max(Rational::from(0)), hi.min(Rational::from(1)));
    match a.cmp(&b) {
        std::cmp::Ordering::Greater => SegTruth::None,
        std::cmp::Ordering::Less => SegTruth::Overlap,
        std::cmp::Ordering::Equal => {
            // one touching point: its parameter on r→s
            let x = lerp(p, q, &a);
            let v = dot(&sub(&x, r), &f) / dot(&f, &f);
            SegTruth::Point(a, v)
        }
    }
}

#[test]
fn polyline2_pairs_without_overlap_are_decided_exactly() {
    let mut rng = Rng::new(0x9017_11e6);
    let (mut checked, mut other) = (0, 0);
    for case in 0..cases() {
        let scale = [1.0, 0.5, 2f64.powi(200), 2f64.powi(-200)][case % 4];
        let (na, nb) = (2 + rng.below(5), 2 + rng.below(5));
        let (va, vb) = (
            vertices(&mut rng, na, 2, 3, scale),
            vertices(&mut rng, nb, 2, 3, scale),
        );
        if va.windows(2).all(|w| w[0] == w[1]) || vb.windows(2).all(|w| w[0] == w[1]) {
            continue;
        }
        let (ta, tb) = (params(&mut rng, na), params(&mut rng, nb));
        let (tva, tvb) = (param_values(&va, &ta), param_values(&vb, &tb));
        let label = format!("case {case}: {va:?} {ta:?} ∩ {vb:?} {tb:?}");
        let shapes = [polyline(&va, ta.clone()), polyline(&vb, tb.clone())];
        if shapes[0] == shapes[1] {
            continue;
        }
        let r = ops::intersect(&shapes, &Options::default()).expect("answers");
        let ex = |v: &[Vec<f64>]| -> Vec<Vec<Rational>> {
            v.iter()
                .map(|p| p.iter().map(|x| q(*x)).collect())
                .collect()
        };
        let (ea, eb) = (ex(&va), ex(&vb));
        let mut truth: Vec<Truth> = Vec::new();
        let mut simple = true;
        for i in 0..na - 1 {
            for j in 0..nb - 1 {
                let (ca, cb) = (va[i] == va[i + 1], vb[j] == vb[j + 1]);
                if ca || cb {
                    // a collapsed piece: a solution only if its point is on the other
                    // polyline, which the neighbouring pieces then find as well
                    continue;
                }
                match segments(&ea[i], &ea[i + 1], &eb[j], &eb[j + 1]) {
                    SegTruth::None => {}
                    SegTruth::Overlap => simple = false,
                    SegTruth::Point(w, v) => truth.push(Truth {
                        xyz: lerp(&ea[i], &ea[i + 1], &w),
                        t: vec![
                            tva[i].clone() + w * (tva[i + 1].clone() - tva[i].clone()),
                            tvb[j].clone() + v * (tvb[j + 1].clone() - tvb[j].clone()),
                        ],
                    }),
                }
            }
        }
        // A collapsed piece whose point is a common point makes a continuum.
        for v in [&va, &vb] {
            for i in 0..v.len() - 1 {
                if v[i] == v[i + 1] && truth.iter().any(|h| h.xyz == ex(&v[i..=i])[0]) {
                    simple = false;
                }
            }
        }
        if !simple {
            // Overlaps and continua: exact (a run) or undecided, never points.
            other += 1;
            assert!(
                matches!(r.status, Status::Exact | Status::Undecided),
                "{label}: {r:?}"
            );
            assert!(!matches!(r.value, Answer::Points(_)), "{label}: {r:?}");
            continue;
        }
        checked += 1;
        truth.sort_by(|a, b| a.t.cmp(&b.t));
        truth.dedup();
        assert_points(&exact_points(&r, &label), &truth, &[0, 1], &label);
    }
    eprintln!("polyline2 pairs: {checked} checked, {other} with overlaps or continua");
    assert!(checked > cases() / 2 && other > 0, "{checked} {other}");
}
