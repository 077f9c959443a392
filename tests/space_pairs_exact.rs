//! Two objects of space at the front door (`ops::intersect`), decided exactly (issue 16):
//! lines, rays, ranged lines and segments against each other, and against the framed
//! conics (circle, ellipse, hyperbola, parabola).
//!
//! Every family computes its truth independently of the library, in exact rationals
//! (`rug::Rational`: Cramer's rule on the construction's own data, the conic's implicit
//! equation in its frame) or, for irrational points, in MPFR at 1024 bits from the closed
//! forms, and asserts: status `exact`, `complete`, the kind and count, every coordinate
//! equal to the correctly rounded truth with the truth in its box, every parameter box
//! holding the truth.

use geocert::geom::{Line, Segment};
use geocert::num::rng::Rng;
use geocert::ops::{self, Answer, Options, Point, Shape};
use geocert::{Certified, GeomError, Status};
use nalgebra::Vector3;
use rug::float::Round;
use rug::{Float, Rational};

// ---------------------------------------------------------------- shared checks

fn options(exact: bool) -> Options {
    Options::new(None, None, None, None, exact).expect("valid options")
}

fn run(a: &Shape, b: &Shape, exact: bool) -> Result<Certified<Answer>, GeomError> {
    ops::intersect(&[a.clone(), b.clone()], &options(exact))
}

fn q(x: f64) -> Rational {
    Rational::from_f64(x).expect("finite")
}

/// The double nearest to `x` (ties to even), from a 53-bit float rounded once.
fn nearest(x: &Rational) -> f64 {
    Float::with_val_round(53, x, Round::Nearest).0.to_f64()
}

fn assert_exact(r: &Certified<Answer>, what: &str) {
    assert_eq!(r.status, Status::Exact, "{what}: {r:?}");
    assert!(r.complete, "{what}: complete");
}

/// The rational truth `x` is correctly rounded to `v` and lies in `b`.
fn check_rational(v: f64, b: [f64; 2], x: &Rational, what: &str) {
    assert_eq!(v, nearest(x), "{what}: not the correctly rounded {x}");
    assert!(q(b[0]) <= *x && *x <= q(b[1]), "{what}: {x} outside {b:?}");
}

/// A point against its rational truth: coordinates and the two objects' parameters.
fn check_point(p: &Point, xyz: &[Rational], params: [&[Rational]; 2], what: &str) {
    for i in 0..xyz.len() {
        check_rational(p.xyz[i], p.xyz_box[i], &xyz[i], &format!("{what} xyz[{i}]"));
    }
    let boxes = p.param_box.as_ref().expect("param boxes");
    for (k, truth) in params.iter().enumerate() {
        assert_eq!(p.params[k].len(), truth.len(), "{what}: params[{k}]");
        for (i, t) in truth.iter().enumerate() {
            check_rational(p.params[k][i], boxes[k][i], t, &format!("{what} t{k}"));
        }
    }
}

fn v3(a: [f64; 3]) -> Vector3<f64> {
    Vector3::new(a[0], a[1], a[2])
}

fn qv(a: [f64; 3]) -> [Rational; 3] {
    a.map(q)
}

fn line(o: [f64; 3], d: [f64; 3]) -> Shape {
    Line::new(v3(o), v3(d)).expect("line").into()
}

fn ranged(o: [f64; 3], d: [f64; 3], r: [f64; 2]) -> Shape {
    Line::with_range(v3(o), v3(d), Some(r))
        .expect("line")
        .into()
}

fn ray(o: [f64; 3], d: [f64; 3]) -> Shape {
    Line::ray(v3(o), v3(d)).expect("ray").into()
}

fn segment(a: [f64; 3], b: [f64; 3]) -> Shape {
    Segment::new(v3(a), v3(b)).expect("segment").into()
}

fn points(r: &Certified<Answer>) -> &[Point] {
    match &r.value {
        Answer::Points(p) => p,
        Answer::Empty => &[],
        other => panic!("expected points, found {other:?}"),
    }
}

// ---------------------------------------------------------------- lines × lines

/// Four integer points `A, B, C, D` on the plane `z = αx + βy + γ` (integers), scaled by
/// `2^k`: the lines `AB`, `CD` are coplanar and cross at a rational point (generally not
/// a double), found by Cramer's rule on the `xy` projection.
struct Crossing {
    a: [f64; 3],
    b: [f64; 3],
    c: [f64; 3],
    d: [f64; 3],
    /// The crossing point and the parameters on `A + s(B − A)`, `C + u(D − C)`.
    p: [Rational; 3],
    s: Rational,
    u: Rational,
}

fn crossing(rng: &mut Rng, k: i32) -> Option<Crossing> {
    let (al, be, ga) = (rng.int(-5, 5), rng.int(-5, 5), rng.int(-9, 9));
    let scale = 2f64.powi(k);
    let mut pt = || {
        let (x, y) = (rng.int(-40, 40), rng.int(-40, 40));
        [x, y, al * x + be * y + ga].map(|v| v as f64 * scale)
    };
    let (a, b, c, d) = (pt(), pt(), pt(), pt());
    let (qa, qb, qc, qd) = (qv(a), qv(b), qv(c), qv(d));
    let e: [Rational; 3] = std::array::from_fn(|i| Rational::from(&qb[i] - &qa[i]));
    let f: [Rational; 3] = std::array::from_fn(|i| Rational::from(&qd[i] - &qc[i]));
    if e.iter().all(|x| *x == 0) || f.iter().all(|x| *x == 0) {
        return None;
    }
    // s e − u f = C − A on x, y.
    let g: [Rational; 2] = std::array::from_fn(|i| Rational::from(&qc[i] - &qa[i]));
    let det = Rational::from(&f[0] * &e[1]) - Rational::from(&e[0] * &f[1]);
    if det == 0 {
        return None;
    }
    let s = (Rational::from(&f[0] * &g[1]) - Rational::from(&g[0] * &f[1])) / &det;
    let u = (Rational::from(&e[0] * &g[1]) - Rational::from(&g[0] * &e[1])) / &det;
    let p = std::array::from_fn(|i| Rational::from(&e[i] * &s) + &qa[i]);
    Some(Crossing {
        a,
        b,
        c,
        d,
        p,
        s,
        u,
    })
}

fn in_unit(t: &Rational) -> bool {
    *t >= 0 && *t <= 1
}

/// Crossing carriers as lines (parameters `s`, `u` on `A + s(B − A)`), as segments
/// (a point or `extensions_meet`), as rays, with magnitudes `2^−300 … 2^300`, in doubles
/// and with the exact rationals requested.
#[test]
fn crossing_lines_segments_rays_are_exact() {
    let mut rng = Rng::new(16);
    let mut counts = [0usize; 3];
    for case in 0..400 {
        let k = [0, 300, -300, 40, -40][case % 5];
        let Some(x) = crossing(&mut rng, k) else {
            continue;
        };
        let sub = |p: [f64; 3], o: [f64; 3]| std::array::from_fn(|i| p[i] - o[i]);
        let (da, dc) = (sub(x.b, x.a), sub(x.d, x.c));
        let exact = case % 2 == 1;
        let what = format!("case {case}");
        // Unbounded lines: always the point.
        let r = run(&line(x.a, da), &line(x.c, dc), exact).unwrap();
        assert_exact(&r, &what);
        let p = points(&r);
        assert_eq!(p.len(), 1, "{what}: {r:?}");
        check_point(&p[0], &x.p, [&[x.s.clone()], &[x.u.clone()]], &what);
        if exact {
            let e = p[0].exact.as_ref().expect("exact values asked for");
            assert_eq!(e.xyz, x.p.to_vec(), "{what}: exact point");
            assert_eq!(e.params, vec![vec![x.s.clone()], vec![x.u.clone()]]);
        }
        // Segments: the point when both parameters are in [0, 1].
        let r = run(&segment(x.c, x.d), &segment(x.a, x.b), exact).unwrap();
        assert_exact(&r, &what);
        if in_unit(&x.s) && in_unit(&x.u) {
            counts[0] += 1;
            let p = points(&r);
            assert_eq!(p.len(), 1, "{what}: {r:?}");
            check_point(&p[0], &x.p, [&[x.u.clone()], &[x.s.clone()]], &what);
        } else {
            counts[1] += 1;
            assert!(points(&r).is_empty(), "{what}: {r:?}");
            assert_eq!(r.reason.as_deref(), Some("extensions_meet"), "{what}");
        }
        // A ray from A along AB against the line CD: the point when s ≥ 0.
        let r = run(&ray(x.a, da), &line(x.c, dc), exact).unwrap();
        assert_exact(&r, &what);
        assert_eq!(points(&r).len(), usize::from(x.s >= 0), "{what}: {r:?}");
        // The opposite ray.
        let back = da.map(|v| -v);
        let r = run(&line(x.c, dc), &ray(x.a, back), exact).unwrap();
        assert_eq!(points(&r).len(), usize::from(x.s <= 0), "{what}: {r:?}");
        if x.s > 0 && x.s < 1 {
            counts[2] += 1;
        }
    }
    assert!(
        counts.iter().all(|&c| c > 20),
        "every branch exercised: {counts:?}"
    );
}

/// `det(C − A, B − A, D − C)`, exactly: zero iff the carriers are coplanar.
fn coplanarity(a: &[f64; 3], b: &[f64; 3], c: &[f64; 3], d: &[f64; 3]) -> Rational {
    let sub = |p: &[f64; 3], o: &[f64; 3]| -> [Rational; 3] {
        std::array::from_fn(|i| q(p[i]) - q(o[i]))
    };
    let (w, e, f) = (sub(c, a), sub(b, a), sub(d, c));
    let m = |x: &Rational, y: &Rational| Rational::from(x * y);
    m(&w[0], &(m(&e[1], &f[2]) - m(&e[2], &f[1]))) - m(&w[1], &(m(&e[0], &f[2]) - m(&e[2], &f[0])))
        + m(&w[2], &(m(&e[0], &f[1]) - m(&e[1], &f[0])))
}

/// One end moved by one ulp (up or down, one coordinate): skew unless the exact
/// coplanarity determinant still vanishes.
#[test]
fn one_ulp_off_is_skew() {
    let mut rng = Rng::new(1601);
    let (mut skew, mut still) = (0, 0);
    for case in 0..300 {
        let k = [0, 300, -300][case % 3];
        let Some(x) = crossing(&mut rng, k) else {
            continue;
        };
        let mut d = x.d;
        let i = rng.below(3);
        d[i] = if rng.coin() {
            d[i].next_up()
        } else {
            d[i].next_down()
        };
        if d == x.c {
            continue;
        }
        let what = format!("case {case}");
        let r = run(&segment(x.a, x.b), &segment(x.c, d), case % 2 == 0).unwrap();
        assert_exact(&r, &what);
        if coplanarity(&x.a, &x.b, &x.c, &d) != 0 {
            skew += 1;
            assert!(points(&r).is_empty(), "{what}: {r:?}");
            assert_eq!(r.reason.as_deref(), Some("skew"), "{what}");
        } else {
            still += 1;
        }
    }
    assert!(skew > 200, "skew cases: {skew} (still coplanar: {still})");
}

fn sub3(p: [f64; 3], o: [f64; 3]) -> [f64; 3] {
    std::array::from_fn(|i| p[i] - o[i])
}

fn at(o: [f64; 3], d: [f64; 3], s: f64) -> [f64; 3] {
    std::array::from_fn(|i| o[i] + s * d[i])
}

/// Collinear objects on `O + s·D` (integers, scaled by `2^k`, so every end is exact):
/// two segments `[s0, s1]`, `[s2, s3]` overlap in a segment, touch at an end (a point)
/// or are disjoint, by the interval truth; a ranged line with a degenerate range
/// `[s, s]` is one point; parallel carriers are empty; two identical unbounded lines
/// coincide; two collinear rays that overlap in a ray are refused, typed.
#[test]
fn collinear_and_parallel_objects() {
    let mut rng = Rng::new(1602);
    let mut kinds = [0usize; 3];
    for case in 0..300 {
        let k = [0, 300, -300][case % 3];
        let sc = 2f64.powi(k);
        let o = [0; 3].map(|_| rng.int(-20, 20) as f64 * sc);
        let d = [0; 3].map(|_| rng.int(-6, 6) as f64 * sc);
        if d == [0.0; 3] {
            continue;
        }
        let mut s = [0; 4].map(|_| rng.int(-10, 10) as f64);
        if case % 4 == 0 {
            s[2] = s[1]; // touching at an end
        }
        if s[0] == s[1] || s[2] == s[3] {
            continue;
        }
        let what = format!("case {case}: {s:?}");
        let exact = case % 2 == 1;
        let r = run(
            &segment(at(o, d, s[0]), at(o, d, s[1])),
            &segment(at(o, d, s[2]), at(o, d, s[3])),
            exact,
        )
        .unwrap();
        assert_exact(&r, &what);
        let (lo1, hi1) = (s[0].min(s[1]), s[0].max(s[1]));
        let (lo2, hi2) = (s[2].min(s[3]), s[2].max(s[3]));
        let (lo, hi) = (lo1.max(lo2), hi1.min(hi2));
        // The parameter of O + s·D on the segment (a, b): (s − s_a)/(s_b − s_a).
        let t = |s: f64, sa: f64, sb: f64| (q(s) - q(sa)) / (q(sb) - q(sa));
        match lo.partial_cmp(&hi).unwrap() {
            std::cmp::Ordering::Greater => {
                kinds[0] += 1;
                assert!(points(&r).is_empty(), "{what}: {r:?}");
                assert_eq!(r.reason.as_deref(), Some("collinear_disjoint"), "{what}");
            }
            std::cmp::Ordering::Equal => {
                kinds[1] += 1;
                let p = points(&r);
                assert_eq!(p.len(), 1, "{what}: {r:?}");
                let xyz = at(o, d, lo).map(q);
                let (t1, t2) = (t(lo, s[0], s[1]), t(lo, s[2], s[3]));
                check_point(&p[0], &xyz, [&[t1], &[t2]], &what);
            }
            std::cmp::Ordering::Less => {
                kinds[2] += 1;
                let Answer::Segment(seg) = &r.value else {
                    panic!("{what}: expected a segment, found {r:?}");
                };
                let mut ends = [lo, hi];
                // `a` has the smaller parameter on the first segment.
                if s[1] < s[0] {
                    ends.reverse();
                }
                for (p, e) in [(&seg.a, ends[0]), (&seg.b, ends[1])] {
                    let xyz = at(o, d, e).map(q);
                    let (t1, t2) = (t(e, s[0], s[1]), t(e, s[2], s[3]));
                    check_point(p, &xyz, [&[t1], &[t2]], &what);
                }
            }
        }
        // A degenerate range [s0, s0] on the same carrier against the first segment.
        let r = run(
            &ranged(o, d, [s[2], s[2]]),
            &segment(at(o, d, s[0]), at(o, d, s[1])),
            exact,
        )
        .unwrap();
        assert_exact(&r, &what);
        assert_eq!(
            points(&r).len(),
            usize::from(lo1 <= s[2] && s[2] <= hi1),
            "{what}: {r:?}"
        );
        // A parallel carrier, shifted off the line by an axis vector not along d.
        let shift = if cross_zero(d, [sc, 0.0, 0.0]) {
            [0.0, sc, 0.0]
        } else {
            [sc, 0.0, 0.0]
        };
        let r = run(
            &line(o, d),
            &line(at(o, shift, 1.0), d.map(|v| -2.0 * v)),
            exact,
        )
        .unwrap();
        assert_exact(&r, &what);
        assert!(points(&r).is_empty(), "{what}: {r:?}");
        assert_eq!(r.reason.as_deref(), Some("parallel"), "{what}");
        // Identical carriers given differently: coincident.
        let r = run(
            &line(o, d),
            &line(at(o, d, s[3]), d.map(|v| 4.0 * v)),
            exact,
        )
        .unwrap();
        assert_exact(&r, &what);
        assert!(matches!(r.value, Answer::Coincident), "{what}: {r:?}");
        // Two rays along the carrier: opposite and overlapping → a segment; the same
        // way → a ray, which the answer has no kind for (typed refusal).
        let (p0, p1) = (at(o, d, lo1), at(o, d, hi1));
        let r = run(&ray(p0, d), &ray(p1, d.map(|v| -v)), exact).unwrap();
        assert_exact(&r, &what);
        assert!(matches!(r.value, Answer::Segment(_)), "{what}: {r:?}");
        let e = run(&ray(p0, d), &ray(p1, d), exact).unwrap_err();
        assert!(matches!(e, GeomError::Unsupported { .. }), "{what}: {e:?}");
    }
    assert!(
        kinds.iter().all(|&c| c > 20),
        "every kind exercised: {kinds:?}"
    );
}

fn cross_zero(a: [f64; 3], b: [f64; 3]) -> bool {
    let (a, b) = (qv(a), qv(b));
    (0..3).all(|i| {
        let (j, k) = ((i + 1) % 3, (i + 2) % 3);
        Rational::from(&a[j] * &b[k]) == Rational::from(&a[k] * &b[j])
    })
}

/// Rational inputs that are not doubles (`1/3`, …): lines through rational points cross
/// at the exact rational point, returned exactly.
#[test]
fn rational_lines_cross_exactly() {
    let mut rng = Rng::new(1603);
    for case in 0..200 {
        let mut r3 = || -> [Rational; 3] {
            std::array::from_fn(|_| Rational::from((rng.int(-50, 50), rng.int(1, 9))))
        };
        let (p, d1, d2) = (r3(), r3(), r3());
        let (s, u) = (
            Rational::from((rng.int(-9, 9), rng.int(1, 7))),
            Rational::from((rng.int(-9, 9), rng.int(1, 7))),
        );
        let n: Vec<Rational> = (0..3)
            .map(|i| {
                let (j, k) = ((i + 1) % 3, (i + 2) % 3);
                Rational::from(&d1[j] * &d2[k]) - Rational::from(&d1[k] * &d2[j])
            })
            .collect();
        if n.iter().all(|x| *x == 0) {
            continue;
        }
        let o1: [Rational; 3] = std::array::from_fn(|i| &p[i] - Rational::from(&s * &d1[i]));
        let o2: [Rational; 3] = std::array::from_fn(|i| &p[i] - Rational::from(&u * &d2[i]));
        let vr = |v: &[Rational; 3]| Vector3::new(v[0].clone(), v[1].clone(), v[2].clone());
        let a: Shape = Line::new(vr(&o1), vr(&d1)).unwrap().into();
        let b: Shape = Line::new(vr(&o2), vr(&d2)).unwrap().into();
        let what = format!("case {case}");
        let r = run(&a, &b, true).unwrap();
        assert_exact(&r, &what);
        let pts = points(&r);
        assert_eq!(pts.len(), 1, "{what}: {r:?}");
        check_point(&pts[0], &p, [&[s.clone()], &[u.clone()]], &what);
        assert_eq!(pts[0].exact.as_ref().unwrap().xyz, p.to_vec(), "{what}");
    }
}
