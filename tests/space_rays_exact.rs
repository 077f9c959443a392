//! Rays of space at the front door (`ops::intersect`, issue 16): every pairing of line,
//! ray (both ways), ranged line and segment, and rays against planes, decided exactly.
//!
//! The truth is built, not computed by the library: each family places the answer
//! first (a crossing point `P` with its parameters, or a common carrier with affine
//! reparametrisations `t₁ = k + m·t₂`) and derives the objects from it in exact
//! doubles; which outcome is true (point, `extensions_meet`, `collinear_disjoint`,
//! segment, ray, coincident, parallel, skew) follows from comparing rationals
//! (`rug::Rational`). Domain ends sit on the crossing parameter, one unit away, and one
//! ulp away; carriers are moved by one ulp to make them skew or parallel (the exact
//! determinant decides which is true). Asserted: status `exact`, `complete`, the kind
//! and the reason, every coordinate and parameter equal to the correctly rounded truth
//! and inside its box, a ray's start, direction and `increasing` flags, and that every
//! outcome occurred often.

use geocert::geom::{Line, ParamRange, Plane, Segment};
use geocert::num::rng::Rng;
use geocert::ops::{self, Answer, Options, Point, Shape};
use geocert::{Certified, Status};
use nalgebra::Vector3;
use rug::float::Round;
use rug::{Float, Rational};
use std::collections::BTreeMap;

fn q(x: f64) -> Rational {
    Rational::from_f64(x).expect("finite")
}

fn nearest(x: &Rational) -> f64 {
    Float::with_val_round(53, x, Round::Nearest).0.to_f64()
}

fn v3(a: [f64; 3]) -> Vector3<f64> {
    Vector3::new(a[0], a[1], a[2])
}

fn run(a: &Shape, b: &Shape, exact: bool) -> Certified<Answer> {
    let opts = Options::new(None, None, None, None, exact).expect("options");
    let r = ops::intersect(&[a.clone(), b.clone()], &opts).expect("answered");
    assert_eq!(r.status, Status::Exact, "{r:?}");
    assert!(r.complete, "{r:?}");
    r
}

fn check_rational(v: f64, b: [f64; 2], x: &Rational, what: &str) {
    assert_eq!(v, nearest(x), "{what}: not the correctly rounded {x}");
    assert!(q(b[0]) <= *x && *x <= q(b[1]), "{what}: {x} outside {b:?}");
}

/// A point against its truth: coordinates and the parameter on each input (`None`:
/// the input has no parameter).
fn check_point(p: &Point, xyz: &[Rational; 3], params: [Option<&Rational>; 2], what: &str) {
    for (i, x) in xyz.iter().enumerate() {
        check_rational(p.xyz[i], p.xyz_box[i], x, &format!("{what} xyz[{i}]"));
    }
    let boxes = p.param_box.as_ref().expect("param boxes");
    for (k, t) in params.iter().enumerate() {
        match t {
            Some(t) => check_rational(p.params[k][0], boxes[k][0], t, &format!("{what} t{k}")),
            None => assert!(p.params[k].is_empty(), "{what}: params[{k}]"),
        }
    }
}

/// One object on a carrier: `o + t·d` for `t` between the ends (`None`: infinite); a
/// segment (`b` given) is `a = o` to `b`, its carrier `o + t(b − a)`, ends `[0, 1]`.
#[derive(Debug, Clone, Copy)]
struct Obj {
    o: [f64; 3],
    d: [f64; 3],
    ends: [Option<f64>; 2],
    b: Option<[f64; 3]>,
}

impl Obj {
    /// The same object with its origin moved by one ulp in one coordinate.
    fn nudged(&self, rng: &mut Rng) -> Obj {
        let mut moved = *self;
        let i = rng.below(3);
        moved.o[i] = if rng.coin() {
            moved.o[i].next_up()
        } else {
            moved.o[i].next_down()
        };
        moved
    }

    /// The exact direction of the carrier (a segment's `b − a`).
    fn dq(&self) -> [Rational; 3] {
        match self.b {
            Some(b) => std::array::from_fn(|i| q(b[i]) - q(self.o[i])),
            None => qv(self.d),
        }
    }
    fn shape(&self) -> Shape {
        if let Some(b) = self.b {
            return Segment::new(v3(self.o), v3(b)).expect("segment").into();
        }
        let range = match self.ends {
            [Some(a), Some(b)] => Some(ParamRange::Closed([a, b])),
            [Some(a), None] => Some(ParamRange::AtLeast(a)),
            [None, Some(b)] => Some(ParamRange::AtMost(b)),
            [None, None] => None,
        };
        Line::with_param_range(v3(self.o), v3(self.d), range)
            .expect("line")
            .into()
    }
    fn contains(&self, t: &Rational) -> bool {
        self.ends[0].is_none_or(|a| *t >= q(a)) && self.ends[1].is_none_or(|b| *t <= q(b))
    }
    fn at(&self, t: &Rational) -> [Rational; 3] {
        let d = self.dq();
        std::array::from_fn(|i| q(self.o[i]) + Rational::from(t * &d[i]))
    }
}

/// Ends around the parameter `t` (a small integer): on it, a unit or one ulp either
/// side, or infinite; `kind` 0 line, 1 ray up, 2 ray down, 3 ranged line, 4 segment
/// (placed by the caller).
fn ends_around(rng: &mut Rng, t: f64, kind: usize) -> [Option<f64>; 2] {
    let mut near = || match rng.below(6) {
        0 => t,
        1 => t + 1.0,
        2 => t - 1.0,
        3 => t.next_up(),
        4 => t.next_down(),
        _ => t + rng.int(-3, 3) as f64,
    };
    match kind {
        0 => [None, None],
        1 => [Some(near()), None],
        2 => [None, Some(near())],
        _ => {
            let (a, b) = (near(), near());
            [Some(a.min(b)), Some(a.max(b))]
        }
    }
}

fn tally(kinds: &mut BTreeMap<String, usize>, r: &Certified<Answer>) {
    let key = format!("{}/{}", r.value.kind(), r.reason.as_deref().unwrap_or(""));
    *kinds.entry(key).or_default() += 1;
}

fn int3(rng: &mut Rng, m: i64) -> [f64; 3] {
    std::array::from_fn(|_| rng.int(-m, m) as f64)
}

fn cross(a: &[Rational; 3], b: &[Rational; 3]) -> [Rational; 3] {
    std::array::from_fn(|i| {
        let (j, k) = ((i + 1) % 3, (i + 2) % 3);
        Rational::from(&a[j] * &b[k]) - Rational::from(&a[k] * &b[j])
    })
}

fn dot(a: &[Rational; 3], b: &[Rational; 3]) -> Rational {
    (0..3).map(|i| Rational::from(&a[i] * &b[i])).sum()
}

fn qv(a: [f64; 3]) -> [Rational; 3] {
    a.map(q)
}

/// An object through `p` at its parameter `s` (so `o = p − s·d`), of kind `kind`; a
/// segment runs from `p + lo·d` to `p + hi·d` with `lo < 0 < hi` or beyond.
fn through(rng: &mut Rng, p: [f64; 3], d: [f64; 3], s: f64, kind: usize) -> (Obj, Rational) {
    if kind == 4 {
        let lo = rng.int(-3, 2) as f64;
        let hi = lo + rng.int(1, 3) as f64;
        let o = std::array::from_fn(|i| p[i] + lo * d[i]);
        let b = std::array::from_fn(|i| p[i] + hi * d[i]);
        // p = o + t(b − o): t = −lo/(hi − lo).
        let t = Rational::from((-(lo as i64), (hi - lo) as i64));
        let obj = Obj {
            o,
            d: std::array::from_fn(|i| (hi - lo) * d[i]),
            ends: [Some(0.0), Some(1.0)],
            b: Some(b),
        };
        return (obj, t);
    }
    let o = std::array::from_fn(|i| p[i] - s * d[i]);
    let obj = Obj {
        o,
        d,
        ends: ends_around(rng, s, kind),
        b: None,
    };
    (obj, q(s))
}

/// Crossing carriers in every pairing of the five kinds, magnitudes `2^−200 … 2^200`:
/// the point exactly when both parameters lie in their domains, else
/// `extensions_meet`; then one origin moved by one ulp: skew unless the exact
/// coplanarity determinant still vanishes.
#[test]
fn crossing_rays_in_every_pairing() {
    let mut rng = Rng::new(0x16_01);
    let mut kinds = BTreeMap::new();
    for case in 0..600 {
        let scale = 2f64.powi([0, 200, -200, 30][case % 4]);
        let p = int3(&mut rng, 40).map(|x| x * scale);
        let (d1, d2) = (
            int3(&mut rng, 6).map(|x| x * scale),
            int3(&mut rng, 6).map(|x| x * scale),
        );
        if cross(&qv(d1), &qv(d2)).iter().all(|x| *x == 0) {
            continue;
        }
        let (s, u) = (rng.int(-4, 4) as f64, rng.int(-4, 4) as f64);
        let (ka, kb) = (case % 5, (case / 5) % 5);
        let (a, ta) = through(&mut rng, p, d1, s, ka);
        let (b, tb) = through(&mut rng, p, d2, u, kb);
        let exact = case % 3 == 0;
        let what = format!("case {case} {a:?} {b:?}");
        let r = run(&a.shape(), &b.shape(), exact);
        tally(&mut kinds, &r);
        let inside = a.contains(&ta) && b.contains(&tb);
        match &r.value {
            Answer::Points(pts) if inside => {
                assert_eq!(pts.len(), 1, "{what}");
                check_point(&pts[0], &qv(p), [Some(&ta), Some(&tb)], &what);
                if exact {
                    let e = pts[0].exact.as_ref().expect("exact");
                    assert_eq!(e.params, vec![vec![ta.clone()], vec![tb.clone()]], "{what}");
                }
            }
            Answer::Empty if !inside => {
                assert_eq!(r.reason.as_deref(), Some("extensions_meet"), "{what}")
            }
            other => panic!("{what}: inside = {inside}, answered {other:?}"),
        }
        // One ulp off: b's origin moved in one coordinate.
        let moved = b.nudged(&mut rng);
        let w: [Rational; 3] = std::array::from_fn(|k| q(moved.o[k]) - q(a.o[k]));
        let coplanar = dot(&w, &cross(&a.dq(), &moved.dq())) == 0;
        let r = run(&a.shape(), &moved.shape(), exact);
        tally(&mut kinds, &r);
        if !coplanar {
            assert!(matches!(r.value, Answer::Empty), "{what}: {r:?}");
            assert_eq!(r.reason.as_deref(), Some("skew"), "{what}");
        }
    }
    for k in ["points/", "empty/extensions_meet", "empty/skew"] {
        assert!(kinds.get(k).is_some_and(|&n| n > 40), "{k}: {kinds:?}");
    }
}

/// The truth of two collinear objects: the second's parameter `t₂` is `t₁ = k + m·t₂`
/// on the first's; the common part in `t₁` between `lo` and `hi` (`None`: infinite).
fn common(a: &Obj, b: &Obj, k: &Rational, m: &Rational) -> [Option<Rational>; 2] {
    let map = |t: Option<f64>| t.map(|t| k + m * q(t));
    let (mut lo2, mut hi2) = (map(b.ends[0]), map(b.ends[1]));
    if *m < 0 {
        std::mem::swap(&mut lo2, &mut hi2);
    }
    let lo = match (a.ends[0].map(q), lo2) {
        (Some(x), Some(y)) => Some(x.max(y)),
        (x, y) => x.or(y),
    };
    let hi = match (a.ends[1].map(q), hi2) {
        (Some(x), Some(y)) => Some(x.min(y)),
        (x, y) => x.or(y),
    };
    [lo, hi]
}

/// An object on the carrier `o + t₁·d` with its own parametrisation `t₁ = k + m·t`
/// (`o + k·d`, `m·d`), kind as in [`ends_around`] (4: a segment from `t₁ = k` to
/// `k + m`), its ends around `t₁ = c` mapped to its own parameter.
fn on_carrier(
    rng: &mut Rng,
    o: [f64; 3],
    d: [f64; 3],
    c: i64,
    kind: usize,
) -> (Obj, Rational, Rational) {
    let m = [1.0, -1.0, 2.0, -2.0, 0.5, -0.5][rng.below(6)];
    let k = (c + rng.int(-2, 2)) as f64;
    let own_o = std::array::from_fn(|i| o[i] + k * d[i]);
    let own_d = std::array::from_fn(|i| m * d[i]);
    // Ends near t₁ = c in the object's own parameter: t = (c − k)/m, a small dyadic.
    let t_c = (c as f64 - k) / m;
    let ends = if kind == 4 {
        [Some(0.0), Some(1.0)]
    } else {
        ends_around(rng, t_c, kind)
    };
    let obj = Obj {
        o: own_o,
        d: own_d,
        ends,
        b: (kind == 4).then(|| std::array::from_fn(|i| own_o[i] + own_d[i])),
    };
    (obj, q(k), q(m))
}

/// Collinear objects in every pairing, each with its own parametrisation of the common
/// carrier (shifted, scaled, reversed): empty `collinear_disjoint`, a point, a segment,
/// a ray, `coincident` — as the exact common interval says; then the second carrier
/// moved off by one ulp: `parallel` unless it is still on the carrier.
#[test]
fn collinear_rays_in_every_pairing() {
    let mut rng = Rng::new(0x16_02);
    let mut kinds = BTreeMap::new();
    for case in 0..800 {
        let scale = 2f64.powi([0, 100, -100][case % 3]);
        let o = int3(&mut rng, 30).map(|x| x * scale);
        let d = int3(&mut rng, 5).map(|x| x * scale);
        if d.iter().all(|x| *x == 0.0) {
            continue;
        }
        let c = rng.int(-3, 3);
        let (ka, kb) = (case % 5, (case / 5) % 5);
        let (a, ka0, ma) = on_carrier(&mut rng, o, d, c, ka);
        let (b, kb0, mb) = on_carrier(&mut rng, o, d, c, kb);
        // b's parameter on a's: a's t = (t₁ − ka0)/ma, t₁ = kb0 + mb·t₂.
        let k = Rational::from(&kb0 - &ka0) / &ma;
        let m = Rational::from(&mb / &ma);
        let exact = case % 2 == 1;
        let what = format!("case {case} {a:?} {b:?}");
        let r = run(&a.shape(), &b.shape(), exact);
        tally(&mut kinds, &r);
        let to_b = |t: &Rational| Rational::from(t - &k) / &m;
        let end = |t: &Rational| (a.at(t), to_b(t));
        match (&common(&a, &b, &k, &m), &r.value) {
            ([None, None], Answer::Coincident) => {
                assert!(a.ends == [None, None] && b.ends == [None, None], "{what}")
            }
            ([Some(lo), Some(hi)], Answer::Empty) if lo > hi => {
                assert_eq!(r.reason.as_deref(), Some("collinear_disjoint"), "{what}")
            }
            ([Some(lo), Some(hi)], Answer::Points(p)) if lo == hi => {
                assert_eq!(p.len(), 1, "{what}");
                let (x, t2) = end(lo);
                check_point(&p[0], &x, [Some(lo), Some(&t2)], &what);
            }
            ([Some(lo), Some(hi)], Answer::Segment(s)) if lo < hi => {
                let (x, t2) = end(lo);
                check_point(&s.a, &x, [Some(lo), Some(&t2)], &what);
                let (x, t2) = end(hi);
                check_point(&s.b, &x, [Some(hi), Some(&t2)], &what);
            }
            ([lo, hi], Answer::Ray(ray)) if lo.is_none() != hi.is_none() => {
                let up = lo.is_some();
                let t = lo.as_ref().or(hi.as_ref()).expect("one end");
                let (x, t2) = end(t);
                check_point(&ray.start, &x, [Some(t), Some(&t2)], &what);
                let sign = if up { 1 } else { -1 };
                let truth: Vec<Rational> =
                    a.dq().iter().map(|v| Rational::from(v * sign)).collect();
                let rounded: Vec<f64> = truth.iter().map(nearest).collect();
                assert_eq!(ray.dir, rounded, "{what}: dir");
                assert_eq!(
                    ray.increasing,
                    vec![Some(up), Some(up == (m > 0))],
                    "{what}: increasing"
                );
                assert_eq!(ray.exact_dir.is_some(), exact, "{what}");
                if let Some(e) = &ray.exact_dir {
                    assert_eq!(*e, truth, "{what}: exact dir");
                }
            }
            (truth, other) => panic!("{what}: common {truth:?}, answered {other:?}"),
        }
        // The second carrier moved by one ulp in one coordinate: parallel.
        let moved = b.nudged(&mut rng);
        let w: [Rational; 3] = std::array::from_fn(|k| q(moved.o[k]) - q(a.o[k]));
        let r = run(&a.shape(), &moved.shape(), exact);
        tally(&mut kinds, &r);
        // (A segment's moved end turns its carrier: then it is not parallel at all.)
        let zero = |v: [Rational; 3]| v.iter().all(|x| *x == 0);
        if zero(cross(&moved.dq(), &a.dq())) && !zero(cross(&w, &a.dq())) {
            assert!(matches!(r.value, Answer::Empty), "{what}: {r:?}");
            assert_eq!(r.reason.as_deref(), Some("parallel"), "{what}");
        }
    }
    for k in [
        "coincident/the two lines coincide",
        "empty/collinear_disjoint",
        "points/",
        "segment/",
        "ray/",
        "empty/parallel",
    ] {
        assert!(kinds.get(k).is_some_and(|&n| n > 15), "{k}: {kinds:?}");
    }
}

/// Rays, ranged lines and segments against planes (implicit and parametric, either
/// order): the crossing when its parameter lies in the domain, else `outside_domain`;
/// an object lying in the plane is its line, ray or segment (a ray: its start, `±dir`
/// and `increasing` with `null` for the plane).
#[test]
fn rays_against_planes() {
    let mut rng = Rng::new(0x16_03);
    let mut kinds = BTreeMap::new();
    for case in 0..600 {
        let scale = 2f64.powi([0, 150, -150][case % 3]);
        let p = int3(&mut rng, 40).map(|x| x * scale);
        let (u, v) = (int3(&mut rng, 5), int3(&mut rng, 5));
        let n = cross(&qv(u), &qv(v));
        if n.iter().all(|x| *x == 0) {
            continue;
        }
        let plane: Shape = Plane::parametric(v3(p), v3(u), v3(v))
            .expect("plane")
            .into();
        let lying = case % 4 == 0;
        let d = if lying {
            let (a, b) = (rng.int(-2, 2) as f64, rng.int(-2, 2) as f64);
            std::array::from_fn(|i| (a * u[i] + b * v[i]) * scale)
        } else {
            int3(&mut rng, 6).map(|x| x * scale)
        };
        if d.iter().all(|x| *x == 0.0) {
            continue;
        }
        let s = rng.int(-4, 4) as f64;
        let kind = (case / 4) % 5;
        let (obj, t) = through(&mut rng, p, d, s, kind);
        let first = rng.coin();
        let exact = case % 2 == 0;
        let what = format!("case {case} {obj:?}");
        let r = if first {
            run(&obj.shape(), &plane, exact)
        } else {
            run(&plane, &obj.shape(), exact)
        };
        tally(&mut kinds, &r);
        let slot = |t: &Rational| -> [Option<Rational>; 2] {
            if first {
                [Some(t.clone()), None]
            } else {
                [None, Some(t.clone())]
            }
        };
        let check = |pt: &Point, t: &Rational| {
            let s = slot(t);
            for (i, x) in obj.at(t).iter().enumerate() {
                check_rational(pt.xyz[i], pt.xyz_box[i], x, &what);
            }
            let k = usize::from(!first);
            let b = pt.param_box.as_ref().expect("boxes");
            check_rational(pt.params[k][0], b[k][0], s[k].as_ref().unwrap(), &what);
        };
        let dot_nd = dot(&n, &qv(d));
        if dot_nd != 0 {
            match &r.value {
                Answer::Points(pts) if obj.contains(&t) => check(&pts[0], &t),
                Answer::Empty if !obj.contains(&t) => {
                    assert_eq!(r.reason.as_deref(), Some("outside_domain"), "{what}")
                }
                other => panic!("{what}: answered {other:?}"),
            }
            continue;
        }
        match (obj.ends, &r.value) {
            ([None, None], Answer::Line(_)) => {}
            ([Some(lo), Some(hi)], Answer::Segment(sg)) => {
                check(&sg.a, &q(lo));
                check(&sg.b, &q(hi));
            }
            ([lo, hi], Answer::Ray(ray)) if lo.is_none() != hi.is_none() => {
                let up = lo.is_some();
                check(&ray.start, &q(lo.or(hi).unwrap()));
                let sign = if up { 1.0 } else { -1.0 };
                assert_eq!(ray.dir, obj.d.map(|x| sign * x).to_vec(), "{what}");
                let inc = if first {
                    vec![Some(up), None]
                } else {
                    vec![None, Some(up)]
                };
                assert_eq!(ray.increasing, inc, "{what}");
            }
            (e, other) => panic!("{what}: ends {e:?}, answered {other:?}"),
        }
    }
    for k in [
        "points/",
        "empty/outside_domain",
        "ray/",
        "segment/",
        "line/",
    ] {
        assert!(kinds.get(k).is_some_and(|&n| n > 10), "{k}: {kinds:?}");
    }
}
