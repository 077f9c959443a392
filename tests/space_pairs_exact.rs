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
use geocert::io::objects::parse_object;
use geocert::io::shape;
use geocert::num::rng::Rng;
use geocert::ops::{self, Answer, Options, Point, Shape};
use geocert::{Certified, GeomError, Status};
use nalgebra::Vector3;
use rug::float::Round;
use rug::{Float, Rational};
use serde_json::Value;

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
    for (i, x) in xyz.iter().enumerate() {
        check_rational(p.xyz[i], p.xyz_box[i], x, &format!("{what} xyz[{i}]"));
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
        check_point(
            &p[0],
            &x.p,
            [std::slice::from_ref(&x.s), std::slice::from_ref(&x.u)],
            &what,
        );
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
            check_point(
                &p[0],
                &x.p,
                [std::slice::from_ref(&x.u), std::slice::from_ref(&x.s)],
                &what,
            );
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
        // way → the later ray (kind `ray`, from p1 along d; tests/space_rays_exact.rs
        // checks rays in every pairing).
        let (p0, p1) = (at(o, d, lo1), at(o, d, hi1));
        let r = run(&ray(p0, d), &ray(p1, d.map(|v| -v)), exact).unwrap();
        assert_exact(&r, &what);
        assert!(matches!(r.value, Answer::Segment(_)), "{what}: {r:?}");
        let r = run(&ray(p0, d), &ray(p1, d), exact).unwrap();
        assert_exact(&r, &what);
        match &r.value {
            Answer::Ray(ray) => {
                assert_eq!(ray.dir, d.to_vec(), "{what}");
                assert_eq!(ray.increasing, vec![Some(true), Some(true)], "{what}");
                assert_eq!(ray.start.params[1], vec![0.0], "{what}: from p1");
            }
            other => panic!("{what}: {other:?}"),
        }
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
        check_point(
            &pts[0],
            &p,
            [std::slice::from_ref(&s), std::slice::from_ref(&u)],
            &what,
        );
        assert_eq!(pts[0].exact.as_ref().unwrap().xyz, p.to_vec(), "{what}");
    }
}

// ---------------------------------------------------------------- helpers for conics

fn conic(v: Value) -> Shape {
    let spec = parse_object(v, "conic").expect("valid conic");
    shape(&spec, "conic").expect("valid shape")
}

// ---------------------------------------------------------------- lines × conics

const BITS: u32 = 1024;

/// `2^k`, exactly.
fn pow2(k: i32) -> Rational {
    if k >= 0 {
        Rational::from(1) << k.unsigned_abs()
    } else {
        Rational::from(1) >> k.unsigned_abs()
    }
}

fn fl(x: &Rational) -> Float {
    Float::with_val(BITS, x)
}

/// An exact frame with rational unit vectors: `axis`, `ref` ⊥ `axis` and `Y = Z × X`, each
/// of length `len` (Pythagorean quadruples), so local coordinates are rational.
struct Frame {
    n: [i64; 3],
    u: [i64; 3],
    v: [i64; 3],
    len: i64,
}

const FRAMES: [Frame; 3] = [
    Frame {
        n: [0, 0, 1],
        u: [1, 0, 0],
        v: [0, 1, 0],
        len: 1,
    },
    Frame {
        n: [1, 2, 2],
        u: [2, 1, -2],
        v: [-2, 2, -1],
        len: 3,
    },
    Frame {
        n: [2, 3, 6],
        u: [6, 2, -3],
        v: [-3, 6, -2],
        len: 7,
    },
];

#[derive(Clone, Copy, Debug)]
enum Kind {
    Circle,
    Ellipse,
    Hyperbola,
    Parabola,
}

/// A conic of the case format with everything its truth needs.
struct Conic {
    kind: Kind,
    frame: &'static Frame,
    c: [Rational; 3],
    /// `r` (circle), `a, b` (ellipse, hyperbola), `p` (parabola).
    a: Rational,
    b: Rational,
    /// The parameter range (hyperbola, parabola).
    range: [f64; 2],
    shape: Shape,
}

impl Conic {
    fn new(kind: Kind, frame: &'static Frame, c: [f64; 3], a: f64, b: f64, sc: f64) -> Conic {
        let range = match kind {
            Kind::Hyperbola => [-3.0, 3.0],
            Kind::Parabola => [-40.0 * sc, 40.0 * sc],
            _ => [0.0, std::f64::consts::TAU],
        };
        let json = match kind {
            Kind::Circle => serde_json::json!({"type": "circle", "center": c, "radius": a,
                "axis": frame.n, "ref": frame.u}),
            Kind::Ellipse => serde_json::json!({"type": "ellipse", "center": c, "a": a, "b": b,
                "axis": frame.n, "ref": frame.u}),
            Kind::Hyperbola => serde_json::json!({"type": "hyperbola", "center": c, "a": a,
                "b": b, "axis": frame.n, "ref": frame.u, "range": range}),
            Kind::Parabola => serde_json::json!({"type": "parabola", "vertex": c, "p": a,
                "axis": frame.n, "ref": frame.u, "range": range}),
        };
        Conic {
            kind,
            frame,
            c: qv(c),
            a: q(a),
            b: q(b),
            range,
            shape: conic(json),
        }
    }

    /// Local `(x, y, z)` of a point.
    fn local(&self, p: &[Rational; 3]) -> [Rational; 3] {
        let w: [Rational; 3] = std::array::from_fn(|i| Rational::from(&p[i] - &self.c[i]));
        let f = self.frame;
        let dot = |e: [i64; 3]| -> Rational {
            (0..3)
                .map(|i| Rational::from(&w[i] * e[i]))
                .sum::<Rational>()
                / f.len
        };
        [dot(f.u), dot(f.v), dot(f.n)]
    }

    /// The point of local `(x, y)` (in the plane).
    fn point(&self, x: &Rational, y: &Rational) -> [Rational; 3] {
        let f = self.frame;
        std::array::from_fn(|i| {
            Rational::from(x * f.u[i]) / f.len + Rational::from(y * f.v[i]) / f.len + &self.c[i]
        })
    }

    /// A direction of local `(x, y, z)`.
    fn dir(&self, x: &Rational, y: &Rational, z: &Rational) -> [Rational; 3] {
        let f = self.frame;
        std::array::from_fn(|i| {
            (Rational::from(x * f.u[i]) + Rational::from(y * f.v[i]) + Rational::from(z * f.n[i]))
                / f.len
        })
    }

    /// The implicit equation on local `(x, y)` as `[c0, c1, c2]` of `x = x0 + t x1`,
    /// `y = y0 + t y1` (`[x0, x1]`, `[y0, y1]`).
    fn restricted(&self, x: [Rational; 2], y: [Rational; 2]) -> [Rational; 3] {
        let sq = |v: &[Rational; 2]| -> [Rational; 3] {
            [
                v[0].clone().square(),
                Rational::from(&v[0] * &v[1]) * 2u32,
                v[1].clone().square(),
            ]
        };
        let comb =
            |p: [Rational; 3], s: Rational, r: [Rational; 3], t: Rational| -> [Rational; 3] {
                std::array::from_fn(|i| Rational::from(&p[i] * &s) + Rational::from(&r[i] * &t))
            };
        let one = Rational::from(1);
        match self.kind {
            Kind::Circle => {
                let mut e = comb(sq(&x), one.clone(), sq(&y), one);
                e[0] -= self.a.clone().square();
                e
            }
            Kind::Ellipse | Kind::Hyperbola => {
                let sy = if matches!(self.kind, Kind::Ellipse) {
                    1
                } else {
                    -1
                };
                let mut e = comb(
                    sq(&x),
                    Rational::from(1) / self.a.clone().square(),
                    sq(&y),
                    Rational::from(sy) / self.b.clone().square(),
                );
                e[0] -= 1;
                e
            }
            Kind::Parabola => {
                let p2 = Rational::from(&self.a * 2u32);
                let mut e = sq(&y);
                e[0] -= Rational::from(&p2 * &x[0]);
                e[1] -= Rational::from(&p2 * &x[1]);
                e
            }
        }
    }

    /// The implicit equation at a point of the plane.
    fn value(&self, x: &Rational, y: &Rational) -> Rational {
        self.restricted([x.clone(), Rational::new()], [y.clone(), Rational::new()])[0].clone()
    }

    /// The curve parameter at local `(x, y)` (MPFR), `None` off the curve's branch or
    /// range.
    fn param(&self, x: &Float, y: &Float) -> Option<Float> {
        let (a, b) = (fl(&self.a), fl(&self.b));
        let t = match self.kind {
            Kind::Circle => {
                let t = Float::with_val(BITS, y.atan2_ref(x));
                if t < 0 {
                    t + Float::with_val(BITS, rug::float::Constant::Pi) * 2u32
                } else {
                    t
                }
            }
            Kind::Ellipse => {
                let t = Float::with_val(BITS, (y.clone() / &b).atan2(&(x.clone() / &a)));
                if t < 0 {
                    t + Float::with_val(BITS, rug::float::Constant::Pi) * 2u32
                } else {
                    t
                }
            }
            Kind::Hyperbola => {
                if *x <= 0 {
                    return None;
                }
                (y.clone() / &b).asinh()
            }
            Kind::Parabola => y.clone(),
        };
        let inside = matches!(self.kind, Kind::Circle | Kind::Ellipse)
            || (t >= self.range[0] && t <= self.range[1]);
        inside.then_some(t)
    }

    /// A rational point on the curve from the rational `m` (module doc of the family),
    /// with a tangent and an in-plane normal (local), and its parameter.
    fn sample(&self, m: &Rational) -> ([Rational; 2], [Rational; 2], [Rational; 2]) {
        let one = Rational::from(1);
        let (a, b) = (&self.a, &self.b);
        let (x, y, tx, ty) = match self.kind {
            Kind::Circle | Kind::Ellipse => {
                let bb = if matches!(self.kind, Kind::Circle) {
                    a
                } else {
                    b
                };
                let den = &one + m.clone().square();
                let c = (&one - m.clone().square()) / &den;
                let s = Rational::from(m * 2u32) / &den;
                (
                    Rational::from(a * &c),
                    Rational::from(bb * &s),
                    -Rational::from(a * &s),
                    Rational::from(bb * &c),
                )
            }
            Kind::Hyperbola => {
                // w = e^t > 0.
                let w = m.clone().abs() + Rational::from((1, 3));
                let (ch, sh) = (
                    (&w + w.clone().recip()) / 2u32,
                    (&w - w.clone().recip()) / 2u32,
                );
                (
                    Rational::from(a * &ch),
                    Rational::from(b * &sh),
                    Rational::from(a * &sh),
                    Rational::from(b * &ch),
                )
            }
            Kind::Parabola => (
                m.clone().square() / Rational::from(a * 2u32),
                m.clone(),
                m.clone() / a,
                one,
            ),
        };
        ([x, y], [tx.clone(), ty.clone()], [ty, -tx])
    }
}

fn vector(v: &[Rational; 3]) -> Vector3<Rational> {
    Vector3::new(v[0].clone(), v[1].clone(), v[2].clone())
}

/// The line `o + t·d` exactly: as doubles when every number is one, else rationals.
fn exact_line(o: &[Rational; 3], d: &[Rational; 3]) -> Shape {
    let doubles = o.iter().chain(d.iter()).all(|x| q(nearest(x)) == *x);
    if doubles {
        line(o.clone().map(|x| x.to_f64()), d.clone().map(|x| x.to_f64()))
    } else {
        Line::new(vector(o), vector(d)).expect("line").into()
    }
}

fn exact_segment(a: &[Rational; 3], b: &[Rational; 3]) -> Shape {
    Segment::new(vector(a), vector(b)).expect("segment").into()
}

/// The float `x` lies in `b`.
fn holds(b: [f64; 2], x: &Float) -> bool {
    *x >= b[0] && *x <= b[1]
}

/// An angle box holds `t` (modulo 2π: a box across the seam).
fn holds_angle(b: [f64; 2], t: &Float) -> bool {
    let tau = Float::with_val(BITS, rug::float::Constant::Pi) * 2u32;
    holds(b, t) || holds(b, &(t.clone() - &tau)) || holds(b, &(t.clone() + &tau))
}

/// The expected common points of an in-plane line `o + t·d` with the conic: the real
/// roots of the restricted quadratic (MPFR), on the branch and in the range, with their
/// multiplicity.
/// A truth root `t` of the line: in MPFR, exactly when rational, with its multiplicity.
type Root = (Float, u32, Option<Rational>);

fn root(t: Rational, mult: u32) -> Root {
    (fl(&t), mult, Some(t))
}

fn in_plane_truth(cn: &Conic, o: &[Rational; 3], d: &[Rational; 3]) -> Vec<Root> {
    let lo = cn.local(o);
    // The local coordinates of the direction: those of the point c + d.
    let dz = cn.local(&std::array::from_fn(|i| Rational::from(&d[i] + &cn.c[i])));
    let e = cn.restricted(
        [lo[0].clone(), dz[0].clone()],
        [lo[1].clone(), dz[1].clone()],
    );
    let mut roots = Vec::new();
    if e[2] == 0 {
        if e[1] != 0 {
            roots.push(root(-e[0].clone() / &e[1], 1));
        }
    } else {
        let disc = e[1].clone().square() - Rational::from(&e[0] * &e[2]) * 4u32;
        let two_a = Rational::from(&e[2] * 2u32);
        let (n, dd) = disc.clone().into_numer_denom();
        if disc == 0 {
            roots.push(root(-e[1].clone() / two_a, 2));
        } else if disc > 0 && n.is_perfect_square() && dd.is_perfect_square() {
            let s = Rational::from((n.sqrt(), dd.sqrt()));
            let r1 = (-e[1].clone() - &s) / &two_a;
            let r2 = (-e[1].clone() + &s) / &two_a;
            roots.push(root(r1, 1));
            roots.push(root(r2, 1));
        } else if disc > 0 {
            let (two_a, s) = (fl(&two_a), fl(&disc).sqrt());
            let r1 = (fl(&-e[1].clone()) - s.clone()) / &two_a;
            let r2 = (fl(&-e[1].clone()) + s) / &two_a;
            roots.push((r1, 1, None));
            roots.push((r2, 1, None));
        }
    }
    roots.sort_by(|a, b| a.0.partial_cmp(&b.0).unwrap());
    let xy = |t: &Float| {
        (
            fl(&lo[0]) + t.clone() * fl(&dz[0]),
            fl(&lo[1]) + t.clone() * fl(&dz[1]),
        )
    };
    roots
        .into_iter()
        .filter(|(t, _, _)| {
            let (x, y) = xy(t);
            cn.param(&x, &y).is_some()
        })
        .collect()
}

/// The answer of the line (first) against the conic matches the truth roots one to one:
/// the line parameter and every coordinate in their boxes and correctly rounded, the
/// curve parameter in its box, the multiplicity.
fn check_roots(
    cn: &Conic,
    r: &Certified<Answer>,
    o: &[Rational; 3],
    d: &[Rational; 3],
    truth: &[Root],
    what: &str,
) {
    assert_exact(r, what);
    let mut pts: Vec<&Point> = points(r).iter().collect();
    assert_eq!(pts.len(), truth.len(), "{what}: {r:?} vs {truth:?}");
    pts.sort_by(|a, b| a.params[0][0].partial_cmp(&b.params[0][0]).unwrap());
    for (p, (t, mult, exact)) in pts.iter().zip(truth) {
        let boxes = p.param_box.as_ref().unwrap();
        let th = if let Some(t) = exact {
            // A rational root: everything exactly.
            check_rational(p.params[0][0], boxes[0][0], t, &format!("{what} line t"));
            let xyz: [Rational; 3] = std::array::from_fn(|i| Rational::from(&d[i] * t) + &o[i]);
            for (i, x) in xyz.iter().enumerate() {
                check_rational(p.xyz[i], p.xyz_box[i], x, &format!("{what} xyz[{i}]"));
            }
            let l = cn.local(&xyz);
            assert_eq!(l[2], 0, "{what}: the truth is in the plane");
            cn.param(&fl(&l[0]), &fl(&l[1]))
        } else {
            assert!(
                holds(boxes[0][0], t),
                "{what}: line parameter {t} outside {boxes:?}"
            );
            assert_eq!(
                p.params[0][0],
                t.to_f64(),
                "{what}: line parameter rounding"
            );
            let xyz: Vec<Float> = (0..3).map(|i| fl(&o[i]) + t.clone() * fl(&d[i])).collect();
            for (i, x) in xyz.iter().enumerate() {
                assert!(holds(p.xyz_box[i], x), "{what}: xyz[{i}] {} outside", x);
                assert_eq!(p.xyz[i], x.to_f64(), "{what}: xyz[{i}] rounding");
            }
            let w: Vec<Float> = (0..3).map(|i| xyz[i].clone() - fl(&cn.c[i])).collect();
            let loc = |e: [i64; 3]| -> Float {
                (0..3)
                    .map(|i| w[i].clone() * e[i])
                    .fold(Float::with_val(BITS, 0), |a, b| a + b)
                    / cn.frame.len
            };
            cn.param(&loc(cn.frame.u), &loc(cn.frame.v))
        };
        let th = th.expect("on the curve");
        let ok = match cn.kind {
            Kind::Circle | Kind::Ellipse => holds_angle(boxes[1][0], &th),
            _ => holds(boxes[1][0], &th),
        };
        assert!(ok, "{what}: curve parameter {th} outside {:?}", boxes[1]);
        assert_eq!(p.multiplicity, *mult, "{what}: multiplicity");
        assert_eq!(p.tangent, *mult == 2, "{what}: tangent");
    }
}

fn conics_for(rng: &mut Rng, k: i32) -> Vec<Conic> {
    let sc = 2f64.powi(k);
    let mut out = Vec::new();
    for frame in &FRAMES {
        let c = [0; 3].map(|_| rng.int(-20, 20) as f64 * sc);
        let (a, b) = (rng.int(2, 9) as f64 * sc, rng.int(2, 9) as f64 * sc);
        for kind in [Kind::Circle, Kind::Ellipse, Kind::Hyperbola, Kind::Parabola] {
            let b = if matches!(kind, Kind::Circle) { a } else { b };
            out.push(Conic::new(kind, frame, c, a, b, sc));
        }
    }
    out
}

fn small_q(rng: &mut Rng) -> Rational {
    Rational::from((rng.int(-12, 12), rng.int(1, 8)))
}

/// Lines crossing the conic's plane at a rational point of the conic (unbounded, a
/// segment around it, a segment beyond it, a ray), one ulp off it (empty), parallel to
/// the plane (empty), in both orders; frames with axes `(0,0,1)`, `(1,2,2)`, `(2,3,6)`,
/// magnitudes `2^−300 … 2^300`.
#[test]
fn lines_crossing_the_plane_of_a_conic() {
    let mut rng = Rng::new(1604);
    let mut hits = 0;
    for round in 0..12 {
        let k = [0, 300, -300, 20][round % 4];
        let sc = pow2(k);
        for cn in conics_for(&mut rng, k) {
            let what = format!("round {round} {:?} frame {:?}", cn.kind, cn.frame.n);
            let m = small_q(&mut rng);
            let ([x, y], _, nrm) = cn.sample(&m);
            let on_range = cn.param(&fl(&x), &fl(&y)).is_some();
            let p = cn.point(&x, &y);
            let gz = Rational::from(rng.int(1, 5) * if rng.coin() { 1 } else { -1 });
            let d = cn.dir(&small_q(&mut rng), &small_q(&mut rng), &gz);
            let d: [Rational; 3] = d.map(|v| v * &sc);
            let tau = small_q(&mut rng);
            let o: [Rational; 3] = std::array::from_fn(|i| &p[i] - Rational::from(&tau * &d[i]));
            let truth = if on_range {
                vec![root(tau.clone(), 1)]
            } else {
                vec![]
            };
            hits += truth.len();
            let r = run(&exact_line(&o, &d), &cn.shape, false).unwrap();
            check_roots(&cn, &r, &o, &d, &truth, &what);
            // The conic first: the same point, parameters swapped.
            let r2 = run(&cn.shape, &exact_line(&o, &d), false).unwrap();
            assert_exact(&r2, &what);
            assert_eq!(points(&r2).len(), truth.len(), "{what}");
            for (a, b) in points(&r2).iter().zip(points(&r)) {
                assert_eq!(a.params, vec![b.params[1].clone(), b.params[0].clone()]);
            }
            // A segment around the point (t = 1/2), and one beyond it.
            let (a, b): ([Rational; 3], [Rational; 3]) = (
                std::array::from_fn(|i| Rational::from(&p[i] - &d[i])),
                std::array::from_fn(|i| Rational::from(&p[i] + &d[i])),
            );
            let half = vec![root(Rational::from((1, 2)), 1)];
            let r = run(&exact_segment(&a, &b), &cn.shape, false).unwrap();
            let a_d: [Rational; 3] = std::array::from_fn(|i| Rational::from(&d[i] * 2u32));
            check_roots(&cn, &r, &a, &a_d, if on_range { &half } else { &[] }, &what);
            let c2: [Rational; 3] = std::array::from_fn(|i| Rational::from(&b[i] + &d[i]));
            let r = run(&exact_segment(&b, &c2), &cn.shape, false).unwrap();
            check_roots(&cn, &r, &b, &d, &[], &what);
            // Rays: from the point along d (t = 0) and from beyond it (empty).
            let from_p: Shape = Line::ray(vector(&p), vector(&d)).expect("ray").into();
            let r = run(&from_p, &cn.shape, false).unwrap();
            let zero_root = vec![root(Rational::new(), 1)];
            check_roots(
                &cn,
                &r,
                &p,
                &d,
                if on_range { &zero_root } else { &[] },
                &what,
            );
            let beyond: Shape = Line::ray(vector(&b), vector(&d)).expect("ray").into();
            let r = run(&beyond, &cn.shape, true).unwrap();
            check_roots(&cn, &r, &b, &d, &[], &what);
            // One ulp off the curve along its in-plane normal: the plane point is off.
            let ulp = pow2(-52) * &sc;
            let (x1, y1) = (
                (&x + Rational::from(&nrm[0] * &ulp)),
                (&y + Rational::from(&nrm[1] * &ulp)),
            );
            assert_ne!(
                cn.value(&x1, &y1),
                0,
                "{what}: the shifted point is off the curve"
            );
            let p1 = cn.point(&x1, &y1);
            let r = run(&exact_line(&p1, &d), &cn.shape, rng.coin()).unwrap();
            check_roots(&cn, &r, &p1, &d, &[], &what);
            // Parallel to the plane, one unit above the point.
            let dp = cn.dir(&small_q(&mut rng), &Rational::from(1), &Rational::new());
            let up: [Rational; 3] =
                std::array::from_fn(|i| &p[i] + Rational::from(cn.frame.n[i]) * &sc);
            let r = run(&exact_line(&up, &dp), &cn.shape, false).unwrap();
            check_roots(&cn, &r, &up, &dp, &[], &what);
            assert_eq!(r.reason.as_deref(), Some("parallel"), "{what}");
        }
    }
    assert!(hits > 100, "hits: {hits}");
}

/// Lines in the conic's plane: tangent at a rational point (a proven double root),
/// shifted off the tangent by ±1 ulp and ±1e-9 (two crossings or none, by the exact
/// discriminant), and random chords; the truth is the restricted quadratic solved in
/// MPFR at 1024 bits.
#[test]
fn lines_in_the_plane_of_a_conic() {
    let mut rng = Rng::new(1605);
    let (mut tangents, mut two) = (0, 0);
    for round in 0..10 {
        let k = [0, 300, -300, 20, -20][round % 5];
        let sc = pow2(k);
        for cn in conics_for(&mut rng, k) {
            let what = format!("round {round} {:?} frame {:?}", cn.kind, cn.frame.n);
            let m = small_q(&mut rng);
            let ([x, y], tan, nrm) = cn.sample(&m);
            let zero = Rational::new();
            let d = cn.dir(&tan[0], &tan[1], &zero);
            let p = cn.point(&x, &y);
            let check = |o: &[Rational; 3], what: &str| -> usize {
                let truth = in_plane_truth(&cn, o, &d);
                let r = run(&exact_line(o, &d), &cn.shape, false).unwrap();
                check_roots(&cn, &r, o, &d, &truth, what);
                truth.len()
            };
            let n = check(&p, &format!("{what} tangent"));
            if cn.param(&fl(&x), &fl(&y)).is_some() {
                assert_eq!(n, 1, "{what}: the tangent touches");
                tangents += 1;
            }
            for off in [pow2(-52), -pow2(-52), q(1e-9), -q(1e-9)] {
                let e = Rational::from(&off * &sc);
                let o = cn.point(
                    &(&x + Rational::from(&nrm[0] * &e)),
                    &(&y + Rational::from(&nrm[1] * &e)),
                );
                two += usize::from(check(&o, &format!("{what} off {off}")) == 2);
            }
            // Random chords through a random point of the plane.
            for _ in 0..3 {
                let o = cn.point(
                    &Rational::from(&small_q(&mut rng) * &sc),
                    &Rational::from(&small_q(&mut rng) * &sc),
                );
                let dd = cn.dir(&small_q(&mut rng), &small_q(&mut rng), &zero);
                if dd.iter().all(|v| *v == 0) {
                    continue;
                }
                let truth = in_plane_truth(&cn, &o, &dd);
                let r = run(&exact_line(&o, &dd), &cn.shape, false).unwrap();
                check_roots(&cn, &r, &o, &dd, &truth, &format!("{what} chord"));
            }
        }
    }
    assert!(
        tangents > 60 && two > 60,
        "tangents {tangents}, two crossings {two}"
    );
}
