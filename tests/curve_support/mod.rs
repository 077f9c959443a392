//! Shared fixtures of the curve tests: one sample of every curve primitive (3D and
//! 2D), a small seeded generator, and MPFR helpers.
#![allow(dead_code)]

use geocert::curve::{
    circular_arc, conic_arc, elliptic_arc, Analytic, Analytic2, AnyCurve2, AnyCurve3, Bezier,
    Curve, Frame, Line, NurbsCurve, Polyline, Reparametrised, Segment, Shape,
};
use geocert::num::MpfrInterval;
use rug::Float;

/// A seeded xorshift generator (deterministic tests without extra dependencies).
pub struct Rng(u64);

impl Rng {
    pub fn new(seed: u64) -> Rng {
        Rng(seed.wrapping_mul(0x9E37_79B9_7F4A_7C15) | 1)
    }
    pub fn next_u64(&mut self) -> u64 {
        let mut x = self.0;
        x ^= x << 13;
        x ^= x >> 7;
        x ^= x << 17;
        self.0 = x;
        x
    }
    /// Uniform in `[0, 1)`.
    pub fn unit(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64
    }
    /// Uniform in `[a, b)`.
    pub fn range(&mut self, a: f64, b: f64) -> f64 {
        a + (b - a) * self.unit()
    }
}

fn frame(origin: [f64; 3], axis: [f64; 3], reference: Option<[f64; 3]>) -> Frame {
    Frame::new(origin, axis, reference).unwrap()
}

/// One space curve of every kind, with a name.
pub fn space_curves() -> Vec<(&'static str, AnyCurve3)> {
    let f1 = frame([1.0, -1.0, 2.0], [1.0, 2.0, 2.0], Some([1.0, 0.0, 0.0]));
    let f2 = frame([0.5, 0.25, -1.0], [0.0, 1.0, 1.0], None);
    let f3 = frame([0.0, 0.0, 0.0], [1.0, 1.0, 1.0], Some([0.0, 0.3, -1.0]));
    let analytic = |f: &Frame, s: Shape, d: Option<(f64, f64)>| {
        AnyCurve3::Analytic(Analytic::new(f.clone(), s, d).unwrap())
    };
    let nurbs = NurbsCurve::new(
        3,
        vec![0.0, 0.0, 0.0, 0.0, 0.7, 1.5, 1.5, 2.25, 3.0, 3.0, 3.0, 3.0],
        vec![
            [0.0, 0.0, 0.0],
            [1.0, 2.0, 0.5],
            [2.0, -1.0, 1.0],
            [3.0, 0.5, -0.5],
            [4.0, 2.0, 0.0],
            [5.0, 1.0, 2.0],
            [5.5, -1.0, 1.0],
            [6.0, 0.0, 0.0],
        ],
        Some(vec![1.0, 0.5, 2.0, 1.5, 0.75, 1.0, 3.0, 1.0]),
        None,
    )
    .unwrap();
    let bspline = NurbsCurve::new(
        2,
        vec![-1.0, 0.0, 0.5, 1.0, 2.0, 2.5, 4.0, 4.5],
        vec![
            [0.0, 1.0, 0.0],
            [1.0, 3.0, -1.0],
            [2.0, 0.0, 1.0],
            [3.0, 2.0, 2.0],
            [4.0, -1.0, 0.0],
        ],
        None,
        None,
    )
    .unwrap();
    let periodic = NurbsCurve::periodic(
        3,
        vec![
            [1.0, 0.0, 0.0],
            [0.5, 1.0, 0.2],
            [-0.5, 1.0, 0.4],
            [-1.0, 0.0, 0.0],
            [-0.5, -1.0, -0.3],
            [0.5, -1.0, 0.1],
        ],
        Some(vec![1.0, 2.0, 1.0, 0.5, 1.0, 1.5]),
    )
    .unwrap();
    let bezier = Bezier::new(
        vec![
            [0.0, 0.0, 0.0],
            [1.0, 2.0, 0.0],
            [3.0, 2.0, 1.0],
            [4.0, 0.0, -1.0],
        ],
        None,
        None,
    )
    .unwrap();
    let rational = Bezier::new(
        vec![
            [0.0, 0.0, 0.0],
            [1.0, 2.0, 0.0],
            [3.0, 2.0, 1.0],
            [4.0, 0.0, -1.0],
            [5.0, 1.0, 0.0],
        ],
        Some(vec![1.0, 2.0, 0.5, 3.0, 1.0]),
        None,
    )
    .unwrap();
    vec![
        (
            "line",
            AnyCurve3::Line(
                Line::new([1.0, 2.0, 3.0], [0.5, -1.0, 2.0], Some((-2.0, 3.0))).unwrap(),
            ),
        ),
        (
            "segment",
            AnyCurve3::Segment(Segment::new([1.0, 2.0, 3.0], [-2.0, 0.5, 4.0], None).unwrap()),
        ),
        ("circle", analytic(&f1, Shape::Circle { radius: 2.5 }, None)),
        (
            "ellipse",
            analytic(&f2, Shape::Ellipse { a: 3.0, b: 1.5 }, None),
        ),
        (
            "hyperbola",
            analytic(
                &f3,
                Shape::Hyperbola {
                    a: 2.0,
                    b: 1.0,
                    second_branch: false,
                },
                Some((-1.5, 1.5)),
            ),
        ),
        (
            "hyperbola-2",
            analytic(
                &f1,
                Shape::Hyperbola {
                    a: 0.5,
                    b: 1.25,
                    second_branch: true,
                },
                Some((-1.0, 2.0)),
            ),
        ),
        (
            "parabola",
            analytic(&f2, Shape::Parabola { p: 0.7 }, Some((-2.0, 2.0))),
        ),
        (
            "helix",
            analytic(
                &f3,
                Shape::Helix {
                    radius: 1.5,
                    pitch: 0.8,
                },
                Some((0.0, 12.0)),
            ),
        ),
        (
            "circular-arc",
            AnyCurve3::Reparametrised(Box::new(
                Reparametrised::trimmed(
                    AnyCurve3::Analytic(
                        Analytic::new(f1.clone(), Shape::Circle { radius: 2.0 }, None).unwrap(),
                    ),
                    0.3,
                    -1.0,
                    0.0,
                    2.0,
                )
                .unwrap(),
            )),
        ),
        ("bezier", AnyCurve3::Bezier(bezier.clone())),
        ("rational-bezier", AnyCurve3::Bezier(rational)),
        (
            "conic-arc",
            AnyCurve3::Bezier(
                conic_arc([1.0, 0.0, 0.0], [1.0, 1.0, 0.5], [0.0, 1.0, 1.0], 0.6).unwrap(),
            ),
        ),
        ("nurbs", AnyCurve3::Nurbs(nurbs.clone())),
        ("bspline", AnyCurve3::Nurbs(bspline)),
        ("periodic-nurbs", AnyCurve3::Nurbs(periodic)),
        (
            "polyline",
            AnyCurve3::Polyline(
                Polyline::new(
                    vec![
                        [0.0, 0.0, 0.0],
                        [1.0, 1.0, 0.0],
                        [2.0, 0.0, 1.0],
                        [2.0, -1.0, 3.0],
                    ],
                    Some(vec![0.0, 0.5, 2.0, 2.25]),
                )
                .unwrap(),
            ),
        ),
        (
            "reversed-nurbs",
            AnyCurve3::Reparametrised(Box::new(
                Reparametrised::reversed(AnyCurve3::Nurbs(nurbs)).unwrap(),
            )),
        ),
        (
            "reparametrised-bezier",
            AnyCurve3::Reparametrised(Box::new(
                Reparametrised::reparametrised(AnyCurve3::Bezier(bezier), -3.0, 7.0).unwrap(),
            )),
        ),
    ]
}

/// The §1.5 arc constructors (as their own types, for tests that need them).
pub fn arcs() -> Vec<(&'static str, Reparametrised<Analytic>)> {
    let f = frame([0.0, 1.0, 0.0], [0.0, 0.0, 1.0], None);
    vec![
        (
            "circular_arc",
            circular_arc(f.clone(), 2.0, 0.5, 1.0, 1.5).unwrap(),
        ),
        (
            "elliptic_arc",
            elliptic_arc(f, 3.0, 1.0, 0.25, -1.0, 2.5).unwrap(),
        ),
    ]
}

/// One plane curve of every kind, with a name.
pub fn plane_curves() -> Vec<(&'static str, AnyCurve2)> {
    let nurbs2 = NurbsCurve::new(
        3,
        vec![0.0, 0.0, 0.0, 0.0, 1.0, 2.0, 2.0, 3.0, 3.0, 3.0, 3.0],
        vec![
            [0.0, 0.0],
            [1.0, 2.0],
            [2.0, -1.0],
            [3.0, 0.5],
            [4.0, 2.0],
            [5.0, 1.0],
            [6.0, 0.0],
        ],
        Some(vec![1.0, 0.5, 2.0, 1.5, 0.75, 1.0, 1.0]),
        None,
    )
    .unwrap();
    vec![
        (
            "line2",
            AnyCurve2::Line(Line::new([1.0, 2.0], [0.5, -1.0], Some((-1.0, 1.0))).unwrap()),
        ),
        (
            "segment2",
            AnyCurve2::Segment(Segment::new([1.0, 2.0], [3.0, -1.0], None).unwrap()),
        ),
        (
            "circle2",
            AnyCurve2::Analytic(
                Analytic2::new([1.0, -2.0], Shape::Circle { radius: 0.75 }, None).unwrap(),
            ),
        ),
        (
            "ellipse2",
            AnyCurve2::Analytic(
                Analytic2::new(
                    [0.5, 0.5],
                    Shape::Ellipse { a: 2.0, b: 0.5 },
                    Some((1.0, 4.0)),
                )
                .unwrap(),
            ),
        ),
        (
            "bezier2",
            AnyCurve2::Bezier(
                Bezier::new(
                    vec![[0.0, 0.0], [1.0, 3.0], [2.0, -1.0]],
                    Some(vec![1.0, 0.25, 2.0]),
                    None,
                )
                .unwrap(),
            ),
        ),
        ("nurbs2", AnyCurve2::Nurbs(nurbs2.clone())),
        (
            "polyline2",
            AnyCurve2::Polyline(
                Polyline::new(vec![[0.0, 0.0], [1.0, 1.0], [2.0, 0.0]], None).unwrap(),
            ),
        ),
        (
            "trimmed-nurbs2",
            AnyCurve2::Reparametrised(Box::new(
                Reparametrised::restricted(AnyCurve2::Nurbs(nurbs2), 0.5, 2.5).unwrap(),
            )),
        ),
    ]
}

/// The breaks (knots, vertices) of a curve where derivatives may jump, and the
/// domain, for choosing sample parameters away from them.
pub fn breaks3(c: &AnyCurve3) -> Vec<f64> {
    match c {
        AnyCurve3::Nurbs(n) => n.knots().to_vec(),
        AnyCurve3::Polyline(p) => p.params().to_vec(),
        AnyCurve3::Reparametrised(r) => {
            let (lo, hi) = r.domain();
            let base = breaks3(r.base());
            base.iter()
                .flat_map(|&b| {
                    // Map base breaks back through the affine map by sampling its ends.
                    let (t_lo, t_hi) = (r.base_parameter(lo), r.base_parameter(hi));
                    let s = (b - t_lo) / (t_hi - t_lo);
                    [lo + s * (hi - lo)]
                })
                .collect()
        }
        _ => vec![],
    }
}

pub fn breaks2(c: &AnyCurve2) -> Vec<f64> {
    match c {
        AnyCurve2::Nurbs(n) => n.knots().to_vec(),
        AnyCurve2::Polyline(p) => p.params().to_vec(),
        AnyCurve2::Reparametrised(r) => {
            let (lo, hi) = r.domain();
            let (t_lo, t_hi) = (r.base_parameter(lo), r.base_parameter(hi));
            breaks2(r.base())
                .iter()
                .map(|&b| lo + (b - t_lo) / (t_hi - t_lo) * (hi - lo))
                .collect()
        }
        _ => vec![],
    }
}

/// A random parameter of `[lo, hi]` at least `gap` away from every break.
pub fn sample_away(rng: &mut Rng, (lo, hi): (f64, f64), breaks: &[f64], gap: f64) -> f64 {
    loop {
        let t = rng.range(lo, hi);
        if breaks.iter().all(|&b| (t - b).abs() > gap) {
            return t;
        }
    }
}

/// `x` as a 200-bit MPFR point interval.
pub fn mp(x: &Float) -> MpfrInterval {
    MpfrInterval::from_float(x, 200)
}

/// Does every component of every derivative of `inner` lie within `outer`?
pub fn jet_contains<const D: usize>(
    outer: &[[MpfrInterval; D]],
    inner: &[[MpfrInterval; D]],
) -> bool {
    outer
        .iter()
        .zip(inner)
        .all(|(o, i)| o.iter().zip(i).all(|(a, b)| b.is_subset(a)))
}
