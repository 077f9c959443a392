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

/// The scales of the linear families: 1, dyadic, 2^±200, 10^±150 and 0.1 (products
/// and quotients then round, and the truth's exactness matters).
fn scales() -> [f64; 7] {
    [
        1.0,
        0.125,
        2f64.powi(200),
        2f64.powi(-200),
        1e150,
        1e-150,
        0.1,
    ]
}

/// A line, ray or segment as the truth sees it: `origin + s·dir`, `s ∈ [lo, hi]` (an
/// infinite end is `None`), all exact.
struct Lin {
    origin: Vec<Rational>,
    dir: Vec<Rational>,
    lo: Option<Rational>,
    hi: Option<Rational>,
}

/// A random line, ray (either way) or segment of dimension `v[0].len()`, often through
/// vertices of `v` or along one of its pieces so that touches and runs are frequent;
/// the shape and its exact description.
fn linear_near(rng: &mut Rng, v: &[Vec<f64>], scale: f64, on_v: bool) -> Option<(Shape, Lin)> {
    use geocert::geom::{Line, ParamRange, Segment};
    use nalgebra::SVector;
    let dim = v[0].len();
    let grid =
        |rng: &mut Rng| -> Vec<f64> { (0..dim).map(|_| rng.int(-2, 2) as f64 * scale).collect() };
    let a = if on_v || rng.coin() {
        v[rng.below(v.len())].clone()
    } else {
        grid(rng)
    };
    let b = match rng.below(3) {
        _ if on_v => v[rng.below(v.len())].clone(),
        0 => v[rng.below(v.len())].clone(),
        _ => grid(rng),
    };
    if a == b {
        return None;
    }
    let (qa, qb): (Vec<Rational>, Vec<Rational>) = (
        a.iter().map(|x| q(*x)).collect(),
        b.iter().map(|x| q(*x)).collect(),
    );
    let kind = rng.below(4);
    if kind == 0 {
        let seg = |a: &[f64], b: &[f64]| -> Option<LinearObject<f64>> {
            Some(if dim == 2 {
                LinearObject::Segment2(
                    Segment::new(
                        SVector::<f64, 2>::from_column_slice(a),
                        SVector::from_column_slice(b),
                    )
                    .ok()?,
                )
            } else {
                LinearObject::Segment(
                    Segment::new(
                        SVector::<f64, 3>::from_column_slice(a),
                        SVector::from_column_slice(b),
                    )
                    .ok()?,
                )
            })
        };
        let lin = Lin {
            dir: sub(&qb, &qa),
            origin: qa,
            lo: Some(Rational::from(0)),
            hi: Some(Rational::from(1)),
        };
        return Some((Shape::Linear(Linear::Double(seg(&a, &b)?)), lin));
    }
    // A line through `a` with direction `b − a` rounded to doubles (the truth takes the
    // direction as given), unbounded or a ray starting at a parameter of the grid.
    let d: Vec<f64> = a.iter().zip(&b).map(|(a, b)| b - a).collect();
    if d.iter().all(|x| *x == 0.0) {
        return None;
    }
    let start = rng.int(-2, 2) as f64 * 0.5;
    let range = match kind {
        1 => None,
        2 => Some(ParamRange::AtLeast(start)),
        _ => Some(ParamRange::AtMost(start)),
    };
    let (lo, hi) = match &range {
        Some(ParamRange::AtLeast(s)) => (Some(q(*s)), None),
        Some(ParamRange::AtMost(s)) => (None, Some(q(*s))),
        _ => (None, None),
    };
    let object = if dim == 2 {
        let r = range.clone();
        LinearObject::Line2(
            Line::with_param_range(
                SVector::<f64, 2>::from_column_slice(&a),
                SVector::from_column_slice(&d),
                r,
            )
            .ok()?,
        )
    } else {
        LinearObject::Line(
            Line::with_param_range(
                SVector::<f64, 3>::from_column_slice(&a),
                SVector::from_column_slice(&d),
                range,
            )
            .ok()?,
        )
    };
    let lin = Lin {
        origin: qa,
        dir: d.iter().map(|x| q(*x)).collect(),
        lo,
        hi,
    };
    Some((Shape::Linear(Linear::Double(object)), lin))
}

/// What two linear objects share: nothing, one point `(s_a, s_b)`, or an overlap
/// `s_a ∈ [lo, hi]` (`lo < hi`, an infinite end `None`) — by Cramer's rule on a
/// non-zero 2×2 minor, or along the common line when the directions are parallel.
enum LinTruth {
    None,
    Point(Rational, Rational),
    Overlap(Option<Rational>, Option<Rational>),
}

fn lin_and_lin(a: &Lin, l: &Lin) -> LinTruth {
    let (e, g, d) = (&a.dir, sub(&l.origin, &a.origin), &l.dir);
    let n = e.len();
    let in_range = |l: &Lin, s: &Rational| {
        l.lo.as_ref().is_none_or(|lo| s >= lo) && l.hi.as_ref().is_none_or(|hi| s <= hi)
    };
    let minor = |x: &[Rational], y: &[Rational], a: usize, b: usize| {
        x[a].clone() * y[b].clone() - x[b].clone() * y[a].clone()
    };
    let pairs: Vec<(usize, usize)> = (0..n)
        .flat_map(|a| (a + 1..n).map(move |b| (a, b)))
        .collect();
    if let Some(&(i, j)) = pairs.iter().find(|(i, j)| minor(e, d, *i, *j) != 0) {
        let m = minor(e, d, i, j);
        let w = minor(&g, d, i, j) / m.clone();
        let s = minor(e, &g, j, i) / m;
        let on = (0..n).all(|k| {
            a.origin[k].clone() + w.clone() * e[k].clone()
                == l.origin[k].clone() + s.clone() * d[k].clone()
        });
        return if on && in_range(a, &w) && in_range(l, &s) {
            LinTruth::Point(w, s)
        } else {
            LinTruth::None
        };
    }
    if pairs.iter().any(|(i, j)| minor(&g, d, *i, *j) != 0) {
        return LinTruth::None; // parallel, apart
    }
    // Collinear: the second's parameter along the first, s_a(s_b) = k + m·s_b.
    let ee = dot(e, e);
    let (k, m) = (dot(&g, e) / ee.clone(), dot(d, e) / ee);
    let at = |s: &Option<Rational>| s.as_ref().map(|s| k.clone() + m.clone() * s.clone());
    let (mut lo, mut hi) = if m > 0 {
        (at(&l.lo), at(&l.hi))
    } else {
        (at(&l.hi), at(&l.lo))
    };
    if let Some(x) = &a.lo {
        lo = Some(lo.map_or(x.clone(), |y| y.max(x.clone())));
    }
    if let Some(x) = &a.hi {
        hi = Some(hi.map_or(x.clone(), |y| y.min(x.clone())));
    }
    match (&lo, &hi) {
        (Some(x), Some(y)) if x > y => LinTruth::None,
        (Some(x), Some(y)) if x == y => {
            let s = (x.clone() - k.clone()) / m.clone();
            LinTruth::Point(x.clone(), s)
        }
        _ => LinTruth::Overlap(lo, hi),
    }
}

fn piece_and_line(p: &[Rational], p2: &[Rational], l: &Lin) -> LinTruth {
    let piece = Lin {
        origin: p.to_vec(),
        dir: sub(p2, p),
        lo: Some(Rational::from(0)),
        hi: Some(Rational::from(1)),
    };
    lin_and_lin(&piece, l)
}

/// The truth of a polyline against a linear object: points, one run (its two ends as
/// points, and its piece count), or `None` for what one answer cannot hold. `slot` is
/// the polyline's place in the case; a truth's parameters are in case order.
fn line_truth(
    v: &[Vec<f64>],
    t: &[Rational],
    l: &Lin,
    slot: usize,
) -> Option<(Vec<Truth>, Option<usize>)> {
    let ex: Vec<Vec<Rational>> = v
        .iter()
        .map(|p| p.iter().map(|x| q(*x)).collect())
        .collect();
    let s_of = |x: &[Rational]| dot(&sub(x, &l.origin), &l.dir) / dot(&l.dir, &l.dir);
    let truth = |i: usize, w: &Rational| {
        let xyz = lerp(&ex[i], &ex[i + 1], w);
        let tp = t[i].clone() + w.clone() * (t[i + 1].clone() - t[i].clone());
        let s = s_of(&xyz);
        let t = if slot == 0 { vec![tp, s] } else { vec![s, tp] };
        Truth { xyz, t }
    };
    let mut hits: Vec<Truth> = Vec::new();
    let mut runs: Vec<(usize, usize, Rational, Rational)> = Vec::new(); // pieces, w ends
    for i in 0..v.len() - 1 {
        if v[i] == v[i + 1] {
            let on = on_lin(&ex[i], l);
            if on {
                return None; // a continuum of parameters at one point
            }
            continue;
        }
        match piece_and_line(&ex[i], &ex[i + 1], l) {
            LinTruth::None => {}
            LinTruth::Point(w, s) => {
                let h = truth(i, &w);
                assert_eq!(h.t[1 - slot], s, "the truth's two routes to s");
                hits.push(h);
            }
            LinTruth::Overlap(w0, w1) => {
                match (runs.last_mut(), w0.expect("a piece"), w1.expect("a piece")) {
                    (Some(r), w0, w1) if r.1 + 1 == i && r.3 == 1 && w0 == 0 => {
                        r.1 = i;
                        r.3 = w1;
                    }
                    (_, w0, w1) => runs.push((i, i, w0, w1)),
                }
            }
        }
    }
    let key = |h: &Truth| h.t.clone();
    hits.sort_by_key(key);
    hits.dedup();
    match runs.as_slice() {
        [] => Some((hits, None)),
        [(a, b, w0, w1)] => {
            let ends = [truth(*a, w0), truth(*b, w1)];
            let tp = |h: &Truth| h.t[slot].clone();
            hits.retain(|h| tp(h) < tp(&ends[0]) || tp(h) > tp(&ends[1]));
            if !hits.is_empty() {
                return None;
            }
            let mut ends = ends.to_vec();
            ends.sort_by_key(key);
            Some((ends, Some(b - a + 1)))
        }
        _ => None,
    }
}

/// Moves one coordinate of one vertex by one ulp, up or down, now and then: touches
/// become near misses or near crossings on either side.
fn nudge(rng: &mut Rng, v: &mut [Vec<f64>]) {
    if rng.below(4) == 0 {
        let (i, k) = (rng.below(v.len()), rng.below(v[0].len()));
        let x = v[i][k];
        v[i][k] = if rng.coin() {
            x.next_up()
        } else {
            x.next_down()
        };
    }
}

#[test]
fn polylines_against_lines_rays_and_segments_are_decided_exactly() {
    let mut rng = Rng::new(0x9017_11e7);
    let (mut points, mut empty, mut runs, mut mixed) = (0, 0, 0, 0);
    for case in 0..cases() {
        let scale = scales()[case % 7];
        let dim = 2 + case % 2;
        let n = 2 + rng.below(5);
        let mut v = vertices(&mut rng, n, dim, 2, scale);
        if dim == 3 && rng.coin() {
            v.iter_mut().for_each(|p| p[2] = 0.0); // in a plane with many of the lines
        }
        let Some((object, lin)) = linear_near(&mut rng, &v, scale, false) else {
            continue;
        };
        nudge(&mut rng, &mut v);
        if v.windows(2).all(|w| w[0] == w[1]) {
            continue; // a polyline that is one point: not this route
        }
        let t = params(&mut rng, n);
        let tv = param_values(&v, &t);
        let first = rng.coin();
        let shapes = if first {
            vec![polyline(&v, t.clone()), object]
        } else {
            vec![object, polyline(&v, t.clone())]
        };
        let slot = usize::from(!first);
        let label = format!("case {case}: {v:?} {t:?} · {:?}", shapes[1 - slot]);
        let r = ops::intersect(&shapes, &Options::default()).expect("answers");
        match line_truth(&v, &tv, &lin, slot) {
            Some((truth, None)) => {
                if truth.is_empty() {
                    empty += 1;
                } else {
                    points += 1;
                }
                assert_points(&exact_points(&r, &label), &truth, &[0, 1], &label);
            }
            Some((ends, Some(pieces))) => {
                runs += 1;
                assert_eq!(r.status, Status::Exact, "{label}: {r:?}");
                assert!(r.complete, "{label}");
                let run = match (&r.value, pieces) {
                    (Answer::Segment(s), 1) | (Answer::Arc(s), 2..) => s,
                    (other, _) => panic!("{label}: {other:?} for {pieces} piece(s)"),
                };
                assert_points(&[run.a.clone(), run.b.clone()], &ends, &[0, 1], &label);
            }
            None => {
                mixed += 1;
                assert_eq!(r.status, Status::Undecided, "{label}: {r:?}");
                assert!(!r.complete);
            }
        }
    }
    eprintln!("polyline ∩ line/ray/segment: {points} point cases, {empty} empty, {runs} runs, {mixed} mixed");
    let n = cases();
    assert!(
        points > n / 5 && empty > n / 20 && runs > n / 50 && mixed > n / 100,
        "{points} {empty} {runs} {mixed}"
    );
}

/// Lines, rays (both ways) and segments against each other, in the plane (where a pair
/// with a ray is decided in space, in `z = 0`) and in space: the objects share grid
/// points so that crossings at ends, collinear overlaps (segments, rays, whole lines)
/// and touching ends are frequent; the truth is `lin_and_lin` on rationals.
#[test]
fn lines_rays_and_segments_against_each_other_are_decided_exactly() {
    use std::collections::BTreeMap;
    let mut rng = Rng::new(0x9017_11e8);
    let mut kinds: BTreeMap<&str, usize> = BTreeMap::new();
    for case in 0..cases() {
        let scale = scales()[case % 7];
        let dim = if case % 3 == 2 { 3 } else { 2 };
        // Half the cases on one carrier: anchors p + k·d, both objects through two.
        let collinear = rng.coin();
        let anchors = if collinear {
            let (p, d) = (
                vertices(&mut rng, 1, dim, 2, scale),
                vertices(&mut rng, 1, dim, 1, 1.0),
            );
            (-1..=2)
                .map(|k| {
                    p[0].iter()
                        .zip(&d[0])
                        .map(|(p, d)| p + k as f64 * d * scale)
                        .collect()
                })
                .collect()
        } else {
            vertices(&mut rng, 3, dim, 2, scale)
        };
        let (Some((sa, la)), Some((sb, lb))) = (
            linear_near(&mut rng, &anchors, scale, collinear),
            linear_near(&mut rng, &anchors, scale, collinear),
        ) else {
            continue;
        };
        let label = format!("case {case}: {sa:?} ∩ {sb:?}");
        let r = ops::intersect(&[sa, sb], &Options::default()).expect("answers");
        assert_eq!(r.status, Status::Exact, "{label}: {r:?}");
        assert!(r.complete, "{label}");
        let at = |s: &Rational| -> Vec<Rational> {
            la.origin
                .iter()
                .zip(&la.dir)
                .map(|(o, d)| o.clone() + s.clone() * d.clone())
                .collect()
        };
        // The second object's parameter of a point of the first, on the common carrier.
        let s_b = |x: &[Rational]| dot(&sub(x, &lb.origin), &lb.dir) / dot(&lb.dir, &lb.dir);
        let truth = |s: &Rational| {
            let xyz = at(s);
            Truth {
                t: vec![s.clone(), s_b(&xyz)],
                xyz,
            }
        };
        match (lin_and_lin(&la, &lb), &r.value) {
            (LinTruth::None, Answer::Empty) => *kinds.entry("empty").or_default() += 1,
            (LinTruth::Point(s, t), Answer::Points(p)) => {
                let h = truth(&s);
                assert_eq!(h.t[1], t, "{label}: the truth's two routes");
                assert_points(p, &[h], &[0, 1], &label);
                *kinds.entry("point").or_default() += 1;
            }
            (LinTruth::Overlap(Some(lo), Some(hi)), Answer::Segment(seg)) => {
                assert_points(
                    &[seg.a.clone(), seg.b.clone()],
                    &[truth(&lo), truth(&hi)],
                    &[0, 1],
                    &label,
                );
                *kinds.entry("segment").or_default() += 1;
            }
            (LinTruth::Overlap(lo, hi), Answer::Ray(ray)) if lo.is_some() != hi.is_some() => {
                let (start, forward) = match (&lo, &hi) {
                    (Some(lo), None) => (lo, true),
                    (None, Some(hi)) => (hi, false),
                    _ => unreachable!(),
                };
                assert_points(
                    std::slice::from_ref(&ray.start),
                    &[truth(start)],
                    &[0, 1],
                    &label,
                );
                let dir: Vec<f64> = la
                    .dir
                    .iter()
                    .map(|d| round(&if forward { d.clone() } else { -d.clone() }))
                    .collect();
                assert_eq!(ray.dir, dir, "{label}");
                *kinds.entry("ray").or_default() += 1;
            }
            (LinTruth::Overlap(None, None), Answer::Line(_) | Answer::Coincident) => {
                *kinds.entry("line").or_default() += 1
            }
            (truth, got) => panic!(
                "{label}: truth {} but {got:?}",
                match truth {
                    LinTruth::None => "none".to_string(),
                    LinTruth::Point(s, t) => format!("point {s} {t}"),
                    LinTruth::Overlap(lo, hi) => format!("overlap {lo:?} {hi:?}"),
                }
            ),
        }
    }
    eprintln!("linear pairs: {kinds:?}");
    let n = cases();
    for kind in ["empty", "point", "segment", "ray", "line"] {
        assert!(
            kinds.get(kind).copied().unwrap_or(0) > n / 200,
            "{kind}: {kinds:?}"
        );
    }
}

/// A polyline whose vertices are all one point `P` (issue 20: such pairs went to
/// subdivision and spent its budget): `empty`, exact, when `P` is off the other object;
/// `undecided` (every parameter is a solution at `P`) when it is on it. Against planes,
/// lines, rays, segments and polylines, with `P` on them, one ulp off, or anywhere.
#[test]
fn polylines_that_are_one_point_are_decided_at_once() {
    let mut rng = Rng::new(0x9017_11e9);
    let (mut on, mut off) = (0, 0);
    for case in 0..cases() {
        let scale = scales()[case % 7];
        let dim = 2 + case % 2;
        let mut p = vertices(&mut rng, 1, dim, 2, scale);
        let n = 2 + rng.below(3);
        let (other, truth_on): (Shape, bool) = match rng.below(3) {
            0 if dim == 3 => {
                let normal = [0, 1, 2].map(|_| rng.int(-2, 2) as f64);
                if normal == [0.0; 3] {
                    continue;
                }
                let d = -(0..3).map(|i| normal[i] * p[0][i]).sum::<f64>();
                let d = if rng.coin() {
                    d
                } else {
                    rng.int(-2, 2) as f64 * scale
                };
                nudge(&mut rng, &mut p);
                let value = (0..3).fold(q(d), |s, i| s + q(normal[i]) * q(p[0][i]));
                (plane(normal, d), value == 0)
            }
            1 => {
                let m = 1 + rng.below(4);
                let v = vertices(&mut rng, m, dim, 2, scale);
                let mut v: Vec<Vec<f64>> = v.into_iter().chain(p.iter().cloned()).collect();
                let turn = rng.below(v.len());
                v.rotate_left(turn);
                if v.windows(2).all(|w| w[0] == w[1]) {
                    continue;
                }
                nudge(&mut rng, &mut p);
                let x: Vec<Rational> = p[0].iter().map(|c| q(*c)).collect();
                let on = v
                    .windows(2)
                    .any(|w| w[0] != w[1] && on_lin(&x, &piece_lin(&w[0], &w[1])))
                    || v.contains(&p[0]);
                (polyline(&v, None), on)
            }
            _ => {
                let Some((shape, lin)) = linear_near(&mut rng, &p, scale, false) else {
                    continue;
                };
                nudge(&mut rng, &mut p);
                let on = on_lin(&p[0].iter().map(|c| q(*c)).collect::<Vec<_>>(), &lin);
                (shape, on)
            }
        };
        let one = polyline(&vec![p[0].clone(); n], params(&mut rng, n));
        let shapes = if rng.coin() {
            vec![one, other]
        } else {
            vec![other, one]
        };
        let label = format!("case {case}: {shapes:?}");
        let r = ops::intersect(&shapes, &Options::default()).expect("answers");
        if truth_on {
            on += 1;
            assert_eq!(r.status, Status::Undecided, "{label}: {r:?}");
            assert!(
                r.reason.as_deref().unwrap_or("").contains("continuum"),
                "{label}: {r:?}"
            );
        } else {
            off += 1;
            assert_eq!(exact_points(&r, &label), vec![], "{label}");
        }
    }
    eprintln!("one-point polylines: {on} on the other object, {off} off");
    assert!(on > cases() / 10 && off > cases() / 10, "{on} {off}");
}

/// Whether the point `x` lies on the linear object: `x − origin` parallel to `dir`
/// (every 2×2 minor zero) with its parameter in range.
fn on_lin(x: &[Rational], l: &Lin) -> bool {
    let e = sub(x, &l.origin);
    let n = e.len();
    let parallel = (0..n).all(|i| {
        (i + 1..n).all(|j| e[i].clone() * l.dir[j].clone() == e[j].clone() * l.dir[i].clone())
    });
    let s = dot(&e, &l.dir) / dot(&l.dir, &l.dir);
    parallel && l.lo.as_ref().is_none_or(|lo| s >= *lo) && l.hi.as_ref().is_none_or(|hi| s <= *hi)
}

/// A piece `a → b` as a linear object with `w ∈ [0, 1]`.
fn piece_lin(a: &[f64], b: &[f64]) -> Lin {
    let (a, b): (Vec<Rational>, Vec<Rational>) = (
        a.iter().map(|c| q(*c)).collect(),
        b.iter().map(|c| q(*c)).collect(),
    );
    Lin {
        dir: sub(&b, &a),
        origin: a,
        lo: Some(Rational::from(0)),
        hi: Some(Rational::from(1)),
    }
}
