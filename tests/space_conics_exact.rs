//! Conic × conic in space and the implicit `quadric` against planes and conics, decided
//! exactly (issue 16), driven through the front door (`geocert::io::solve_case`).
//!
//! Families are seeded and built from rational orthonormal frames (Pythagorean
//! quadruples), so every local coordinate is rational. Truths are computed independently
//! of the library: crossing planes by the quadratics of each conic on the common line
//! (found from the first plane by a different formula) and their exact common roots;
//! coplanar circles by the radical-line closed form; a circle against a quadric by the
//! tangent half-angle substitution (a quartic in `t`, divided exactly by the two roots
//! built into the quadric, the quotient solved in MPFR at 1024 bits); plane sections by
//! the signs of the quadric's diagonal form in its own frame. Every family asserts the
//! status, the kind and count, coordinates and parameters equal to the correctly rounded
//! truth and held by their boxes, multiplicities and tangency.

mod cli_support;

use cli_support::f64s;
use geocert::io::{read_cases, solve_case};
use geocert::num::rng::Rng;
use rug::float::{Constant, Round};
use rug::{Float, Rational};
use serde_json::{json, Value};

const BITS: u32 = 1024;

fn run(objects: Value) -> Value {
    let case = json!({"op": "intersect", "objects": objects});
    let read = read_cases(&case.to_string()).into_iter().next().unwrap();
    serde_json::from_str(&solve_case(read).to_json_line()).unwrap()
}

fn fl(x: &Rational) -> Float {
    Float::with_val(BITS, x)
}

fn nearest(x: &Float) -> f64 {
    Float::with_val_round(53, x, Round::Nearest).0.to_f64()
}

/// `v` is the correctly rounded `x` and `b` holds `x`, up to the truth's own error:
/// `x` is computed in 1024-bit MPFR, so a value that is exactly a double (a constant
/// coordinate of an irrational point) may come out `2⁻¹⁰⁰⁰`-close to it; within
/// `ε = 2⁻⁹⁰⁰(1 + |x|)` of the double `v` the truth is taken to be `v`.
fn check(v: &Value, b: &Value, x: &Float, what: &str) -> bool {
    let (v, b) = (v.as_f64().unwrap(), f64s(b));
    let eps = (Float::with_val(BITS, x.abs_ref()) + 1u32) >> 900u32;
    let close = (Float::with_val(BITS, x - v)).abs() <= eps;
    let rounds = v == nearest(x) || close;
    let held = (b[0] <= *x || close && b[0] == v) && (*x <= b[1] || close && b[1] == v);
    rounds && held || {
        eprintln!("{what}: {v} {b:?} vs {x}");
        false
    }
}

fn two_pi() -> Float {
    Float::with_val(BITS, Constant::Pi) * 2u32
}

// ---------------------------------------------------------------- frames and conics

#[derive(Clone, Copy, Debug)]
struct Frame {
    n: [i64; 3],
    u: [i64; 3],
    v: [i64; 3],
    len: i64,
}

/// 18 rational orthonormal frames (`v = n × u`, each vector of length `len`): three
/// base frames, their cyclic relabellings and the flip `(−n, v, u)`.
fn frames() -> Vec<Frame> {
    let base = [
        ([0, 0, 1], [1, 0, 0], [0, 1, 0], 1),
        ([1, 2, 2], [2, 1, -2], [-2, 2, -1], 3),
        ([2, 3, 6], [6, 2, -3], [-3, 6, -2], 7),
    ];
    let mut out = Vec::new();
    for (n, u, v, len) in base {
        for (n, u, v) in [(n, u, v), (u, v, n), (v, n, u)] {
            out.push(Frame { n, u, v, len });
            out.push(Frame {
                n: n.map(|x| -x),
                u: v,
                v: u,
                len,
            });
        }
    }
    out
}

fn cross(a: [i64; 3], b: [i64; 3]) -> [i64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

fn dot_i(a: [i64; 3], b: [i64; 3]) -> i64 {
    (0..3).map(|i| a[i] * b[i]).sum()
}

#[derive(Clone, Copy, Debug, PartialEq)]
enum Kind {
    Circle,
    Ellipse,
    Hyperbola,
    Parabola,
}

#[derive(Clone, Copy, Debug)]
struct Conic {
    kind: Kind,
    f: Frame,
    c: [i64; 3],
    a: i64,
    b: i64,
}

/// `(x₀ + x₁s, y₀ + y₁s)`: affine local coordinates along a line.
type Along = [[Rational; 2]; 2];

impl Conic {
    fn json(&self) -> Value {
        let f = &self.f;
        match self.kind {
            Kind::Circle => json!({"type": "circle", "center": self.c, "radius": self.a,
                "axis": f.n, "ref": f.u}),
            Kind::Ellipse => json!({"type": "ellipse", "center": self.c, "a": self.a,
                "b": self.b, "axis": f.n, "ref": f.u}),
            Kind::Hyperbola => json!({"type": "hyperbola", "center": self.c, "a": self.a,
                "b": self.b, "axis": f.n, "ref": f.u, "range": [-3, 3]}),
            Kind::Parabola => json!({"type": "parabola", "vertex": self.c, "p": self.a,
                "axis": f.n, "ref": f.u, "range": [-1000, 1000]}),
        }
    }

    /// The world point of integer local `(x, y)` (multiples of `len`).
    fn world(&self, x: i64, y: i64) -> [i64; 3] {
        let f = &self.f;
        std::array::from_fn(|i| {
            let w = x * f.u[i] + y * f.v[i];
            assert_eq!(w % f.len, 0);
            self.c[i] + w / f.len
        })
    }

    /// Local `(x, y)` of `o + s·m` as affine functions of `s`.
    fn along(&self, o: &[Rational; 3], m: &[Rational; 3]) -> Along {
        let f = &self.f;
        let form = |e: [i64; 3]| -> [Rational; 2] {
            let mut c0 = Rational::new();
            let mut c1 = Rational::new();
            for i in 0..3 {
                c0 += Rational::from(&o[i] - self.c[i]) * e[i];
                c1 += Rational::from(&m[i] * e[i]);
            }
            [c0 / f.len, c1 / f.len]
        };
        [form(f.u), form(f.v)]
    }

    /// The implicit equation along the line, `[c₀, c₁, c₂]`.
    fn quadratic(&self, l: &Along) -> [Rational; 3] {
        let sq = |v: &[Rational; 2]| -> [Rational; 3] {
            [
                v[0].clone().square(),
                Rational::from(&v[0] * &v[1]) * 2u32,
                v[1].clone().square(),
            ]
        };
        let (x, y) = (sq(&l[0]), sq(&l[1]));
        let (a2, b2) = (
            Rational::from(self.a * self.a),
            Rational::from(self.b * self.b),
        );
        let mut e: [Rational; 3] = match self.kind {
            Kind::Circle => std::array::from_fn(|i| Rational::from(&x[i] + &y[i])),
            Kind::Ellipse => {
                std::array::from_fn(|i| Rational::from(&x[i] / &a2) + Rational::from(&y[i] / &b2))
            }
            Kind::Hyperbola => {
                std::array::from_fn(|i| Rational::from(&x[i] / &a2) - Rational::from(&y[i] / &b2))
            }
            Kind::Parabola => {
                let p2 = 2 * self.a;
                [
                    y[0].clone() - Rational::from(&l[0][0] * p2),
                    y[1].clone() - Rational::from(&l[0][1] * p2),
                    y[2].clone(),
                ]
            }
        };
        match self.kind {
            Kind::Circle => e[0] -= a2,
            Kind::Ellipse | Kind::Hyperbola => e[0] -= 1,
            Kind::Parabola => {}
        }
        e
    }

    /// The curve parameter at local `(x, y)`; `None` off the branch or the range.
    fn param(&self, x: &Float, y: &Float) -> Option<Float> {
        let (a, b) = (Float::with_val(BITS, self.a), Float::with_val(BITS, self.b));
        let wrap = |t: Float| if t < 0 { t + two_pi() } else { t };
        match self.kind {
            Kind::Circle => Some(wrap(Float::with_val(BITS, y.atan2_ref(x)))),
            Kind::Ellipse => Some(wrap((y.clone() / &b).atan2(&(x.clone() / &a)))),
            Kind::Hyperbola => {
                let t = (y.clone() / &b).asinh();
                (*x > 0 && (-3..=3).contains(&t)).then_some(t)
            }
            Kind::Parabola => (*y >= -1000 && *y <= 1000).then(|| y.clone()),
        }
    }
}

/// A random conic of `kind` in `f` centred at `c` and an integer local point on it
/// (`vertex`: the point on the local `x` axis, where the tangent is along `y`).
fn conic_with_point(
    rng: &mut Rng,
    kind: Kind,
    f: Frame,
    c: [i64; 3],
    vertex: bool,
) -> (Conic, [i64; 2]) {
    let l = f.len;
    let (k1, k2) = (l * rng.int(1, 3), l * rng.int(1, 3));
    let sg = |rng: &mut Rng| if rng.coin() { 1 } else { -1 };
    let (a, b, p) = match kind {
        Kind::Circle => {
            let (p, q, h) = [(3, 4, 5), (5, 12, 13), (8, 15, 17)][rng.below(3)];
            let pt = if vertex {
                [sg(rng) * h * k1, 0]
            } else if rng.coin() {
                [sg(rng) * p * k1, sg(rng) * q * k1]
            } else {
                [sg(rng) * q * k1, sg(rng) * p * k1]
            };
            (h * k1, h * k1, pt)
        }
        Kind::Ellipse => {
            let pt = if vertex {
                [sg(rng) * 5 * k1, 0]
            } else if rng.coin() {
                [sg(rng) * 3 * k1, sg(rng) * 4 * k2]
            } else {
                [sg(rng) * 4 * k1, sg(rng) * 3 * k2]
            };
            (5 * k1, 5 * k2, pt)
        }
        Kind::Hyperbola => {
            let pt = if vertex {
                [3 * k1, 0]
            } else {
                [5 * k1, sg(rng) * 4 * k2]
            };
            (3 * k1, 3 * k2, pt)
        }
        Kind::Parabola => {
            let j = if vertex { 0 } else { rng.int(-3, 3) };
            (k1, 0, [2 * k1 * j * j, 2 * k1 * j])
        }
    };
    (Conic { kind, f, c, a, b }, p)
}

fn kind(rng: &mut Rng) -> Kind {
    [Kind::Circle, Kind::Ellipse, Kind::Hyperbola, Kind::Parabola][rng.below(4)]
}

fn center(rng: &mut Rng) -> [i64; 3] {
    [rng.int(-9, 9), rng.int(-9, 9), rng.int(-9, 9)]
}

// ---------------------------------------------------------------- exact truths

/// A real root `s` of the common line, with its multiplicity as a tangency (2 when the
/// line touches both conics there).
struct Root {
    s: Float,
    tangent: bool,
}

fn q_eval(q: &[Rational; 3], s: &Rational) -> Rational {
    Rational::from(&q[2] * s) * s + Rational::from(&q[1] * s) + &q[0]
}

fn rational_sqrt(x: &Rational) -> Option<Rational> {
    let (n, d) = x.clone().into_numer_denom();
    (n.is_perfect_square() && d.is_perfect_square()).then(|| Rational::from((n.sqrt(), d.sqrt())))
}

/// The real roots of `q` (not identically zero): rational ones exactly, the others as
/// 1024-bit floats; with whether each is double.
fn roots(q: &[Rational; 3]) -> Vec<(Result<Rational, Float>, bool)> {
    if q[2].cmp0().is_eq() {
        if q[1].cmp0().is_eq() {
            return vec![];
        }
        return vec![(Ok(-Rational::from(&q[0] / &q[1])), false)];
    }
    let disc = q[1].clone().square() - Rational::from(&q[2] * &q[0]) * 4u32;
    let two_a = Rational::from(&q[2] * 2u32);
    match disc.cmp0() {
        std::cmp::Ordering::Less => vec![],
        std::cmp::Ordering::Equal => vec![(Ok(-Rational::from(&q[1] / &two_a)), true)],
        std::cmp::Ordering::Greater => match rational_sqrt(&disc) {
            Some(r) => [-1, 1]
                .iter()
                .map(|sg| (Ok((Rational::from(&r * *sg) - &q[1]) / &two_a), false))
                .collect(),
            None => [-1, 1]
                .iter()
                .map(|sg| {
                    let r = fl(&disc).sqrt() * *sg;
                    (Err((r - fl(&q[1])) / fl(&two_a)), false)
                })
                .collect(),
        },
    }
}

/// The common real roots of two quadratics with rational coefficients (module doc).
fn common(qa: &[Rational; 3], qb: &[Rational; 3]) -> Vec<Root> {
    let proportional = (0..3).all(|i| {
        (0..3).all(|j| Rational::from(&qa[i] * &qb[j]) == Rational::from(&qa[j] * &qb[i]))
    });
    let rb = roots(qb);
    roots(qa)
        .into_iter()
        .filter_map(|(r, double)| match r {
            Ok(s) => {
                if !q_eval(qb, &s).cmp0().is_eq() {
                    return None;
                }
                let double_b = rb.iter().any(|(x, d)| *d && x.as_ref().ok() == Some(&s));
                Some(Root {
                    s: fl(&s),
                    tangent: double && double_b,
                })
            }
            Err(s) => proportional.then_some(Root { s, tangent: false }),
        })
        .collect()
}

/// A truth point: coordinates and each object's parameters (empty for a quadric).
struct Truth {
    xyz: [Float; 3],
    params: [Vec<Float>; 2],
    tangent: bool,
}

/// The reported points match the truth one to one: coordinates, parameters, tangency.
fn check_points(r: &Value, truth: &[Truth], what: &str) {
    assert_eq!(r["status"], "exact", "{what}: {r}");
    assert_eq!(r["complete"], true, "{what}");
    let pts = r["points"].as_array().cloned().unwrap_or_default();
    let kind = if truth.is_empty() { "empty" } else { "points" };
    assert_eq!(r["kind"], kind, "{what}: {r}");
    assert_eq!(pts.len(), truth.len(), "{what}: {r}");
    for t in truth {
        let found = pts
            .iter()
            .find(|p| (0..3).all(|i| p["xyz"][i].as_f64().unwrap() == nearest(&t.xyz[i])));
        let p = found.unwrap_or_else(|| panic!("{what}: no point at {:?} in {r}", t.xyz));
        for i in 0..3 {
            assert!(
                check(&p["xyz"][i], &p["box"][i], &t.xyz[i], what),
                "{what}: {p}"
            );
        }
        for k in 0..2 {
            assert_eq!(
                p["params"][k].as_array().unwrap().len(),
                t.params[k].len(),
                "{what}: {p}"
            );
            for (j, tp) in t.params[k].iter().enumerate() {
                assert!(
                    check(&p["params"][k][j], &p["param_box"][k][j], tp, what),
                    "{what}: param {k} {p}"
                );
            }
        }
        assert_eq!(p["tangent"], t.tangent, "{what}: {p}");
        assert_eq!(
            p["multiplicity"],
            if t.tangent { 2 } else { 1 },
            "{what}: {p}"
        );
    }
}

/// The truth of two conics in crossing planes (module doc): the common line from the
/// first plane, `o = c_A + τ w` with `w = n_A × m` in the first plane.
fn crossing_truth(a: &Conic, b: &Conic) -> Vec<Truth> {
    let m = cross(a.f.n, b.f.n);
    let w = cross(a.f.n, m);
    let hb = dot_i(b.f.n, b.c) - dot_i(b.f.n, a.c);
    let tau = Rational::from((hb, dot_i(b.f.n, w)));
    let o: [Rational; 3] = std::array::from_fn(|i| Rational::from(&tau * w[i]) + a.c[i]);
    let mq: [Rational; 3] = m.map(Rational::from);
    let (la, lb) = (a.along(&o, &mq), b.along(&o, &mq));
    let mut out = Vec::new();
    for root in common(&a.quadratic(&la), &b.quadratic(&lb)) {
        let at = |l: &[Rational; 2]| fl(&l[0]) + fl(&l[1]) * &root.s;
        let pa = a.param(&at(&la[0]), &at(&la[1]));
        let pb = b.param(&at(&lb[0]), &at(&lb[1]));
        let (Some(pa), Some(pb)) = (pa, pb) else {
            continue;
        };
        out.push(Truth {
            xyz: std::array::from_fn(|i| fl(&o[i]) + root.s.clone() * m[i]),
            params: [vec![pa], vec![pb]],
            tangent: root.tangent,
        });
    }
    out
}

// ---------------------------------------------------------------- conic × conic

/// Two conics through a common integer point `P` in crossing planes, in random frames;
/// a quarter of them shifted off `P` (then usually disjoint, decided by the truth).
#[test]
fn conics_in_crossing_planes_meet_exactly() {
    let fs = frames();
    let mut rng = Rng::new(0x5ace_c0de);
    let (mut met, mut tangent, mut missed) = (0, 0, 0);
    for case in 0..160 {
        let fa = fs[rng.below(fs.len())];
        // Half the pairs in the frame that puts the common line along the first conic's
        // local y axis: vertices of both then make a tangency.
        let special = rng.coin();
        let fb = if special {
            Frame {
                n: fa.u,
                u: fa.n,
                v: fa.v.map(|x| -x),
                len: fa.len,
            }
        } else {
            fs[rng.below(fs.len())]
        };
        if cross(fa.n, fb.n) == [0, 0, 0] {
            continue;
        }
        let (ka, kb) = (kind(&mut rng), kind(&mut rng));
        let (ca, va, vb) = (
            center(&mut rng),
            special && rng.coin(),
            special && rng.coin(),
        );
        let (a, pa) = conic_with_point(&mut rng, ka, fa, ca, va);
        let p = a.world(pa[0], pa[1]);
        let (mut b, pb) = conic_with_point(&mut rng, kb, fb, [0; 3], vb);
        let off = b.world(pb[0], pb[1]);
        b.c = std::array::from_fn(|i| p[i] - off[i]);
        if rng.below(4) == 0 {
            b.c[rng.below(3)] += rng.int(1, 3);
        }
        let truth = crossing_truth(&a, &b);
        let r = run(json!([a.json(), b.json()]));
        check_points(&r, &truth, &format!("case {case}: {a:?} {b:?}"));
        met += usize::from(!truth.is_empty());
        tangent += truth.iter().filter(|t| t.tangent).count();
        missed += usize::from(truth.is_empty());
    }
    assert!(
        met > 60 && tangent > 5 && missed > 10,
        "{met} {tangent} {missed}"
    );
}

/// Conics in parallel distinct planes are disjoint, exactly.
#[test]
fn conics_in_parallel_planes_are_disjoint() {
    let fs = frames();
    let mut rng = Rng::new(7);
    for case in 0..40 {
        let f = fs[rng.below(fs.len())];
        let (ka, ca) = (kind(&mut rng), center(&mut rng));
        let (a, _) = conic_with_point(&mut rng, ka, f, ca, false);
        let g = if rng.coin() {
            f
        } else {
            Frame {
                n: f.n.map(|x| -x),
                u: f.v,
                v: f.u,
                len: f.len,
            }
        };
        let shift = rng.int(1, 3) * if rng.coin() { 1 } else { -1 };
        let c = std::array::from_fn(|i| a.c[i] + shift * f.n[i]);
        let kb = kind(&mut rng);
        let (b, _) = conic_with_point(&mut rng, kb, g, c, false);
        let r = run(json!([a.json(), b.json()]));
        assert_eq!(r["status"], "exact", "case {case}: {r}");
        assert_eq!(r["kind"], "empty", "case {case}: {r}");
        assert_eq!(r["reason"], "parallel", "case {case}: {r}");
    }
}

/// Two circles in one plane (frames rotated in the plane), by the radical line:
/// crossing, tangent (internally and externally) and disjoint; the same circle given
/// twice in different frames is `coincident`.
#[test]
fn coplanar_circles_meet_exactly() {
    let fs = frames();
    let mut rng = Rng::new(0xc0_91a4);
    let (mut two, mut one) = (0, 0);
    for case in 0..80 {
        let f = fs[rng.below(fs.len())];
        let l = f.len;
        let g = Frame {
            n: f.n,
            u: f.v,
            v: f.u.map(|x| -x),
            len: l,
        };
        let (ra, rb) = (rng.int(1, 4), rng.int(1, 4));
        let (dx, dy) = if rng.coin() {
            let d = if rng.coin() { ra + rb } else { (ra - rb).abs() };
            (d * if rng.coin() { 1 } else { -1 }, 0)
        } else {
            (rng.int(-5, 5), rng.int(-5, 5))
        };
        if dx == 0 && dy == 0 {
            continue;
        }
        let a = Conic {
            kind: Kind::Circle,
            f,
            c: center(&mut rng),
            a: ra * l,
            b: 0,
        };
        let b = Conic {
            kind: Kind::Circle,
            f: if rng.coin() { f } else { g },
            c: a.world(dx * l, dy * l),
            a: rb * l,
            b: 0,
        };
        // In a's local units of `l`: d² = dx² + dy², foot = along·(dx, dy).
        let d2 = Rational::from(dx * dx + dy * dy);
        let along = (Rational::from(ra * ra - rb * rb) + &d2) / (d2.clone() * 2u32);
        let h2 = Rational::from((ra * ra, 1)) / &d2 - along.clone().square();
        let mut truth = Vec::new();
        let signs: &[i32] = match h2.cmp0() {
            std::cmp::Ordering::Less => &[],
            std::cmp::Ordering::Equal => &[0],
            std::cmp::Ordering::Greater => &[-1, 1],
        };
        for &sg in signs {
            let h = fl(&h2).sqrt() * sg;
            let x = (fl(&along) * dx - h.clone() * dy) * l;
            let y = (fl(&along) * dy + h * dx) * l;
            let world = |fr: &Frame, cc: [i64; 3], x: &Float, y: &Float| -> [Float; 3] {
                std::array::from_fn(|i| {
                    (x.clone() * fr.u[i] + y.clone() * fr.v[i]) / fr.len + cc[i]
                })
            };
            let xyz = world(&f, a.c, &x, &y);
            let local_b = |e: [i64; 3]| -> Float {
                let mut s = Float::new(BITS);
                for i in 0..3 {
                    s += (xyz[i].clone() - b.c[i]) * e[i];
                }
                s / b.f.len
            };
            let (xb, yb) = (local_b(b.f.u), local_b(b.f.v));
            truth.push(Truth {
                params: [
                    vec![a.param(&x, &y).unwrap()],
                    vec![b.param(&xb, &yb).unwrap()],
                ],
                xyz,
                tangent: sg == 0,
            });
        }
        let r = run(json!([a.json(), b.json()]));
        check_points(&r, &truth, &format!("case {case}: {a:?} {b:?}"));
        two += usize::from(truth.len() == 2);
        one += usize::from(truth.len() == 1);
    }
    assert!(two > 10 && one > 10, "{two} {one}");
    let f = frames()[4];
    let c = [1, 2, 3];
    let a = json!({"type": "circle", "center": c, "radius": 6, "axis": f.n, "ref": f.u});
    let b =
        json!({"type": "circle", "center": c, "radius": 6, "axis": f.n.map(|x| -x), "ref": f.v});
    let r = run(json!([a, b]));
    assert_eq!(r["status"], "exact", "{r}");
    assert_eq!(r["kind"], "coincident", "{r}");
}

// ---------------------------------------------------------------- quadrics

/// `Σ dᵢ ((x − t)·eᵢ)² (+ 2k·len·((x − t)·e₃)) + d₄·len²`, as the 4×4 matrix (integers):
/// the quadric `Σ dᵢ ξᵢ² + 2kξ₃ + d₄ = 0` in the local coordinates `ξ` of the frame.
fn quadric_matrix(f: &Frame, d: [i64; 4], k: i64, t: [i64; 3]) -> [[i64; 4]; 4] {
    let e = [f.u, f.v, f.n];
    let mut m = [[0i64; 4]; 4];
    for i in 0..3 {
        for j in 0..3 {
            m[i][j] = (0..3).map(|r| d[r] * e[r][i] * e[r][j]).sum();
        }
    }
    // b = −A t + k·len·e₃, c = tᵀAt − 2k·len·(t·e₃) + d₄·len².
    let at: [i64; 3] = std::array::from_fn(|i| (0..3).map(|j| m[i][j] * t[j]).sum());
    for i in 0..3 {
        m[i][3] = -at[i] + k * f.len * e[2][i];
        m[3][i] = m[i][3];
    }
    m[3][3] = dot_i(t, at) - 2 * k * f.len * dot_i(t, e[2]) + d[3] * f.len * f.len;
    m
}

/// Plane `ξ₃ = h` against quadrics of every signature in rotated frames: the section's
/// conic type from the signs of the local form, its centre `t + h·e₃/len`.
#[test]
fn quadric_plane_sections_are_exact() {
    let fs = frames();
    let mut rng = Rng::new(0x9ad);
    let mut seen = std::collections::BTreeSet::new();
    for case in 0..120 {
        let f = fs[rng.below(fs.len())];
        let s = |rng: &mut Rng| rng.int(1, 4);
        let (d, k) = match rng.below(7) {
            0 => ([s(&mut rng), s(&mut rng), s(&mut rng), -s(&mut rng) * 9], 0), // ellipsoid
            1 => ([s(&mut rng), s(&mut rng), -s(&mut rng), -s(&mut rng)], 0),    // one sheet
            2 => ([s(&mut rng), -s(&mut rng), -s(&mut rng), -s(&mut rng)], 0),   // two sheets
            3 => ([s(&mut rng), s(&mut rng), -s(&mut rng), 0], 0),               // cone
            4 => ([s(&mut rng), s(&mut rng), 0, 0], -s(&mut rng)),               // paraboloid
            5 => ([s(&mut rng), s(&mut rng), 0, -s(&mut rng) * 4], 0),           // cylinder
            _ => ([s(&mut rng), -s(&mut rng), 0, 0], 0),                         // plane pair
        };
        let t = center(&mut rng);
        let h = rng.int(-3, 3);
        let m = quadric_matrix(&f, d, k, t);
        // The plane ξ₃ = h: n·x = n·t + h·len.
        let plane = json!({"type": "plane", "normal": f.n, "d": -(dot_i(f.n, t) + h * f.len)});
        let r = run(json!([{"type": "quadric", "matrix": m}, plane]));
        // Section: d₁ξ₁² + d₂ξ₂² = κ, κ = −(d₃h² + 2kh + d₄).
        let kappa = -(d[2] * h * h + 2 * k * h + d[3]);
        let (d1, d2) = (d[0], d[1]);
        let expect = if d1 * d2 > 0 {
            match (kappa * d1).signum() {
                1 if d1 == d2 => "circle",
                1 => "ellipse",
                0 => "point",
                _ => "empty",
            }
        } else {
            if kappa == 0 {
                "intersecting_lines"
            } else {
                "hyperbola"
            }
        };
        let what = format!("case {case}: d {d:?} k {k} h {h}: {r}");
        // A closed conic comes with a proven polyline on it (`verified`), as the
        // sections of named quadrics do; the conic itself is exact.
        assert!(
            r["status"] == "exact" || r["status"] == "verified",
            "{what}"
        );
        seen.insert(expect);
        match expect {
            "empty" => assert_eq!(r["kind"], "empty", "{what}"),
            "point" => {
                let truth = Truth {
                    xyz: std::array::from_fn(|i| {
                        Float::with_val(BITS, t[i]) + Float::with_val(BITS, h * f.n[i]) / f.len
                    }),
                    params: [vec![], vec![]],
                    tangent: true,
                };
                assert_eq!(r["kind"], "points", "{what}");
                let p = &r["points"][0];
                for i in 0..3 {
                    assert!(check(&p["xyz"][i], &p["box"][i], &truth.xyz[i], &what));
                }
            }
            ty => {
                let conic = &r["conic"];
                assert_eq!(conic["type"], ty, "{what}");
                let c = &conic["center"];
                for i in 0..3 {
                    let x = Float::with_val(BITS, t[i]) + Float::with_val(BITS, h * f.n[i]) / f.len;
                    assert!(check(&c["value"][i], &c["box"][i], &x, &what));
                }
            }
        }
    }
    assert!(seen.len() >= 5, "{seen:?}");
}

// ---- polynomials in t (ascending coefficients) for the circle ∩ quadric truth

type Poly = Vec<Rational>;

fn pmul(a: &Poly, b: &Poly) -> Poly {
    let mut out = vec![Rational::new(); a.len() + b.len() - 1];
    for (i, x) in a.iter().enumerate() {
        for (j, y) in b.iter().enumerate() {
            out[i + j] += Rational::from(x * y);
        }
    }
    out
}

fn padd(a: &Poly, b: &Poly) -> Poly {
    (0..a.len().max(b.len()))
        .map(|i| a.get(i).cloned().unwrap_or_default() + b.get(i).cloned().unwrap_or_default())
        .collect()
}

fn pscale(a: &Poly, k: &Rational) -> Poly {
    a.iter().map(|x| Rational::from(x * k)).collect()
}

/// `a / (t − r)`, asserting a zero remainder.
fn pdiv_root(a: &Poly, r: &Rational) -> Poly {
    let n = a.len() - 1;
    let mut q = vec![Rational::new(); n];
    let mut acc = Rational::new();
    for i in (0..=n).rev() {
        acc = Rational::from(&acc * r) + &a[i];
        if i > 0 {
            q[i - 1] = acc.clone();
        }
    }
    assert!(acc.cmp0().is_eq(), "construction: r is a root");
    q
}

/// A circle or an ellipse in a rational frame against a quadric built through two of its
/// rational points `t₁, t₂` (tangent half-angle `t`), the quadratic part of every
/// signature: the quartic `W²·F(x(t))` divided by `(t − t₁)(t − t₂)` leaves a quadratic
/// whose roots are the other points (a root equal to `tᵢ`: a tangency).
#[test]
fn quadric_against_circles_and_ellipses() {
    let fs = frames();
    let mut rng = Rng::new(0x0dd);
    let (mut total, mut tangents) = (0, 0);
    for case in 0..120 {
        let f = fs[rng.below(fs.len())];
        let g = fs[rng.below(fs.len())];
        let circle = rng.coin();
        let l = f.len;
        let (ra, rb) = (l * rng.int(1, 3), l * rng.int(1, 3));
        let conic = Conic {
            kind: if circle { Kind::Circle } else { Kind::Ellipse },
            f,
            c: center(&mut rng),
            a: ra,
            b: if circle { ra } else { rb },
        };
        let ts = |rng: &mut Rng| Rational::from((rng.int(-4, 4), rng.int(1, 3)));
        let (t1, t2) = (ts(&mut rng), ts(&mut rng));
        // A tangency at t₁ in a quarter of the cases.
        let tangent_case = rng.below(4) == 0;
        if t1 == t2 && !tangent_case {
            continue;
        }
        // x(t) = c + (a(1 − t²)u + 2bt·v)/(len(1 + t²)): numerators over W = 1 + t².
        let num: [Poly; 3] = std::array::from_fn(|i| {
            let (a, b) = (conic.a * f.u[i], conic.b * f.v[i]);
            vec![
                Rational::from((a, l)) + conic.c[i],
                Rational::from((2 * b, l)),
                Rational::from((-a, l)) + conic.c[i],
            ]
        });
        let w: Poly = vec![Rational::from(1), Rational::new(), Rational::from(1)];
        let point = |t: &Rational| -> [Rational; 3] {
            let wt = Rational::from(1) + t.clone().square();
            std::array::from_fn(|i| {
                (Rational::from(&num[i][2] * t) * t + Rational::from(&num[i][1] * t) + &num[i][0])
                    / &wt
            })
        };
        let s = |rng: &mut Rng| rng.int(1, 3) * if rng.coin() { 1 } else { -1 };
        let d = [
            s(&mut rng),
            s(&mut rng),
            if rng.coin() { 0 } else { s(&mut rng) },
        ];
        let a_int = quadric_matrix(&g, [d[0], d[1], d[2], 0], 0, [0; 3]);
        let a: [[Rational; 3]; 3] =
            std::array::from_fn(|i| std::array::from_fn(|j| Rational::from(a_int[i][j])));
        let quad = |p: &[Rational; 3]| -> Rational {
            let mut s = Rational::new();
            for i in 0..3 {
                for j in 0..3 {
                    s += Rational::from(&a[i][j] * &p[i]) * &p[j];
                }
            }
            s
        };
        // b = β·wv, c: F(P₁) = F(P₂) = 0; for a tangency at P₁ the gradient ⊥ the
        // tangent there instead of the second point.
        let wv = [rng.int(-3, 3), rng.int(-3, 3), rng.int(-3, 3)];
        let (p1, p2) = (point(&t1), point(&t2));
        let wdot =
            |p: &[Rational; 3]| -> Rational { (0..3).map(|i| Rational::from(&p[i] * wv[i])).sum() };
        let (beta, c0) = if tangent_case {
            // d/dt F(x(t)) = 2(A x + β w)·x'(t) = 0 at t₁.
            let dx: [Rational; 3] = {
                // x'(t) ∝ (−a·2t·u·W − ...) — use the exact derivative of the numerators
                // over W: (N'W − N W')/W², N' = [n1, 2n2], W' = 2t.
                let wt = Rational::from(1) + t1.clone().square();
                std::array::from_fn(|i| {
                    let n = Rational::from(&num[i][2] * &t1) * &t1
                        + Rational::from(&num[i][1] * &t1)
                        + &num[i][0];
                    let dn = Rational::from(&num[i][2] * &t1) * 2u32 + &num[i][1];
                    Rational::from(&dn * &wt) - n * Rational::from(&t1 * 2u32)
                })
            };
            let ax: [Rational; 3] =
                std::array::from_fn(|i| (0..3).map(|j| Rational::from(&a[i][j] * &p1[j])).sum());
            let num_b: Rational = (0..3).map(|i| Rational::from(&ax[i] * &dx[i])).sum();
            let den_b: Rational = (0..3).map(|i| Rational::from(&dx[i] * wv[i])).sum();
            if den_b.cmp0().is_eq() {
                continue;
            }
            let beta = -num_b / den_b;
            let c0 = -quad(&p1) - (&beta * wdot(&p1)) * 2u32;
            (beta, c0)
        } else {
            let den = (wdot(&p1) - wdot(&p2)) * 2u32;
            if den.cmp0().is_eq() {
                continue;
            }
            let beta = -(quad(&p1) - quad(&p2)) / den;
            let c0 = -quad(&p1) - (&beta * wdot(&p1)) * 2u32;
            (beta, c0)
        };
        // Scale to integers.
        let mut all: Vec<Rational> = a.iter().flatten().cloned().collect();
        all.extend(wv.iter().map(|x| Rational::from(&beta * *x)));
        all.push(c0.clone());
        let mut lcm = rug::Integer::from(1);
        for x in &all {
            lcm.lcm_mut(x.denom());
        }
        let k = Rational::from(lcm);
        let ints: Vec<Rational> = all.iter().map(|x| Rational::from(x * &k)).collect();
        if ints.iter().any(|x| x.clone().abs() > (1i64 << 50)) {
            continue;
        }
        let e = |x: &Rational| x.to_f64();
        let m: Vec<Vec<f64>> = (0..4)
            .map(|i| {
                (0..4)
                    .map(|j| match (i, j) {
                        (3, 3) => e(&ints[12]),
                        (3, j) => e(&ints[9 + j]),
                        (i, 3) => e(&ints[9 + i]),
                        (i, j) => e(&ints[3 * i + j]),
                    })
                    .collect()
            })
            .collect();
        // The quartic W²F(x(t)) = Nᵀ A N + 2W bᵀN + c W² (unscaled).
        let mut quartic: Poly = vec![Rational::new()];
        for i in 0..3 {
            for j in 0..3 {
                quartic = padd(&quartic, &pscale(&pmul(&num[i], &num[j]), &a[i][j]));
            }
            let bi = Rational::from(&beta * wv[i]) * 2u32;
            quartic = padd(&quartic, &pscale(&pmul(&w, &num[i]), &bi));
        }
        quartic = padd(&quartic, &pscale(&pmul(&w, &w), &c0));
        if quartic.iter().all(|x| x.cmp0().is_eq()) || quartic[4].cmp0().is_eq() {
            continue; // the circle lies on the quadric, or (−a, 0) is on it
        }
        let rest = pdiv_root(
            &pdiv_root(&quartic, &t1),
            if tangent_case { &t1 } else { &t2 },
        );
        let quadratic = [rest[0].clone(), rest[1].clone(), rest[2].clone()];
        // Every real root with its multiplicity (merging equal rational roots).
        let mut rts: Vec<(Result<Rational, Float>, u32)> = vec![(Ok(t1.clone()), 1)];
        let mut add = |r: Result<Rational, Float>, mult: u32| {
            if let Ok(x) = &r {
                if let Some(e) = rts.iter_mut().find(|(y, _)| y.as_ref().ok() == Some(x)) {
                    e.1 += mult;
                    return;
                }
            }
            rts.push((r, mult));
        };
        add(Ok(if tangent_case { t1.clone() } else { t2.clone() }), 1);
        for (r, double) in roots(&quadratic) {
            add(r, if double { 2 } else { 1 });
        }
        if rts.iter().any(|(_, m)| *m > 2) {
            continue; // higher contact: the multiplicity check below assumes ≤ 2
        }
        let mut truth = Vec::new();
        for (r, mult) in &rts {
            let t = match r {
                Ok(x) => fl(x),
                Err(x) => x.clone(),
            };
            let wt = Float::with_val(BITS, 1) + t.clone().square();
            let xyz = std::array::from_fn(|i| {
                (fl(&num[i][2]) * t.clone() * &t + fl(&num[i][1]) * &t + fl(&num[i][0])) / &wt
            });
            // θ = 2 atan t in [0, 2π).
            let th = Float::with_val(BITS, t.atan_ref()) * 2u32;
            let th = if th < 0 { th + two_pi() } else { th };
            truth.push(Truth {
                xyz,
                params: [vec![th], vec![]],
                tangent: *mult == 2,
            });
        }
        let r = run(json!([conic.json(), {"type": "quadric", "matrix": m}]));
        check_points(&r, &truth, &format!("case {case}: {conic:?} d {d:?}"));
        total += truth.len();
        tangents += truth.iter().filter(|t| t.tangent).count();
    }
    assert!(total > 150 && tangents > 10, "{total} {tangents}");
}

/// A circle lying on a sphere given as a quadric is `coincident`; projecting onto a
/// quadric says why it is not available.
#[test]
fn circle_on_a_quadric_and_projection() {
    // Sphere x² + y² + z² = 25 and the circle z = 3, radius 4.
    let sphere = json!({"type": "quadric", "matrix":
        [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, -25]]});
    let circle = json!({"type": "circle", "center": [0, 0, 3], "radius": 4, "axis": [0, 0, 1]});
    let r = run(json!([circle, sphere]));
    assert_eq!(r["status"], "exact", "{r}");
    assert_eq!(r["kind"], "coincident", "{r}");
    assert_eq!(r["reason"], "the curve lies on the quadric", "{r}");
    let case = json!({"op": "project", "point": [1, 2, 3], "onto": sphere});
    let read = read_cases(&case.to_string()).into_iter().next().unwrap();
    let r: Value = serde_json::from_str(&solve_case(read).to_json_line()).unwrap();
    assert_eq!(r["status"], "error", "{r}");
    assert_eq!(r["error"]["kind"], "unsupported", "{r}");
    assert!(
        r["error"]["message"]
            .as_str()
            .unwrap()
            .contains("principal axes"),
        "{r}"
    );
}
