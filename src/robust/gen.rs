//! Seeded case generators, one per (construction, kind of input): generic doubles,
//! integer and dyadic grids, exactly degenerate configurations, their one-ulp
//! perturbations, and magnitudes mixed from about 1e-150 to 1e150. Every case is a
//! function of its seed alone ([`case`]), so a property test draws seeds and the
//! robustness table walks a seeded stream of them.
//!
//! Degenerate configurations are built from dyadic data (`k/8`, `|k| ≤ 64`), on which
//! every combination used (sums, cross products, dot products) is exact in doubles, so
//! the degeneracy holds for the doubles themselves; a quarter of them are then scaled by
//! a power of two `2^k`, `|k| ≤ 200` (positions, vectors and implicit offsets; normals
//! kept), which preserves every incidence exactly.

use super::case::{Case, Linear2In, LinearIn, PlaneIn, P2, P3};
use crate::num::rng::Rng;
use crate::num::round::{next_down, next_up};

/// The constructions of OPERATIONS.md §3.1, §3.3, §5.1, §6.1–6.2, §7.1, §8.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Construction {
    ThreePlanes,
    LinePlane,
    PlanePlane,
    ProjectLine,
    ProjectPlane,
    Lines2,
    Segments2,
}

impl Construction {
    pub const ALL: [Construction; 7] = [
        Construction::ThreePlanes,
        Construction::LinePlane,
        Construction::PlanePlane,
        Construction::ProjectLine,
        Construction::ProjectPlane,
        Construction::Lines2,
        Construction::Segments2,
    ];
    pub fn name(self) -> &'static str {
        match self {
            Construction::ThreePlanes => "three planes",
            Construction::LinePlane => "line/segment-plane",
            Construction::PlanePlane => "plane-plane",
            Construction::ProjectLine => "point->line",
            Construction::ProjectPlane => "point->plane",
            Construction::Lines2 => "2D lines",
            Construction::Segments2 => "2D segments",
        }
    }
}

/// The kind of input.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Generator {
    /// Uniform doubles in `[−10, 10)` with full significands.
    Generic,
    /// Small integers or dyadics `k/8`.
    Grid,
    /// Exactly degenerate configurations (see the module documentation).
    Degenerate,
    /// A degenerate case with one coordinate moved by one ulp.
    Perturbed,
    /// Every coordinate `±m·2^e`, `e ∈ [−498, 498]`.
    Mixed,
}

impl Generator {
    pub const ALL: [Generator; 5] = [
        Generator::Generic,
        Generator::Grid,
        Generator::Degenerate,
        Generator::Perturbed,
        Generator::Mixed,
    ];
    pub fn name(self) -> &'static str {
        match self {
            Generator::Generic => "generic",
            Generator::Grid => "grid",
            Generator::Degenerate => "degenerate",
            Generator::Perturbed => "one-ulp",
            Generator::Mixed => "mixed 1e±150",
        }
    }
}

/// The case of `construction` and `generator` determined by `seed` (geocert accepts
/// all its objects: invalid draws are redrawn from the same stream).
pub fn case(construction: Construction, generator: Generator, seed: u64) -> Case {
    let mut rng = Rng::new(seed);
    loop {
        let c = draw(construction, generator, &mut rng);
        if c.is_valid() {
            return c;
        }
    }
}

type Src = fn(&mut Rng) -> f64;

fn draw(c: Construction, g: Generator, rng: &mut Rng) -> Case {
    let src: Src = match g {
        Generator::Generic => Rng::generic,
        Generator::Mixed => Rng::mixed,
        Generator::Grid if rng.coin() => Rng::small_int,
        _ => Rng::dyadic,
    };
    match g {
        Generator::Degenerate => degenerate(c, rng),
        Generator::Perturbed => {
            let mut case = degenerate(c, rng);
            perturb(&mut case, rng);
            case
        }
        _ => random(c, src, rng),
    }
}

fn p3(src: Src, rng: &mut Rng) -> P3 {
    [src(rng), src(rng), src(rng)]
}
fn p2(src: Src, rng: &mut Rng) -> P2 {
    [src(rng), src(rng)]
}

fn plane(src: Src, rng: &mut Rng) -> PlaneIn {
    if rng.below(4) < 3 {
        PlaneIn::Parametric {
            origin: p3(src, rng),
            u: p3(src, rng),
            v: p3(src, rng),
        }
    } else {
        PlaneIn::Implicit {
            normal: p3(src, rng),
            d: src(rng),
        }
    }
}

fn random(c: Construction, src: Src, rng: &mut Rng) -> Case {
    match c {
        Construction::ThreePlanes => {
            Case::ThreePlanes([plane(src, rng), plane(src, rng), plane(src, rng)])
        }
        Construction::LinePlane => {
            let l = if rng.coin() {
                LinearIn::Line {
                    origin: p3(src, rng),
                    dir: p3(src, rng),
                }
            } else {
                LinearIn::Segment {
                    a: p3(src, rng),
                    b: p3(src, rng),
                }
            };
            Case::LinePlane(l, plane(src, rng))
        }
        Construction::PlanePlane => Case::PlanePlane(plane(src, rng), plane(src, rng)),
        Construction::ProjectLine => Case::ProjectLine(p3(src, rng), p3(src, rng), p3(src, rng)),
        Construction::ProjectPlane => Case::ProjectPlane(p3(src, rng), plane(src, rng)),
        Construction::Lines2 => Case::Linear2(
            Linear2In::Line {
                origin: p2(src, rng),
                dir: p2(src, rng),
            },
            Linear2In::Line {
                origin: p2(src, rng),
                dir: p2(src, rng),
            },
        ),
        Construction::Segments2 => Case::Linear2(
            Linear2In::Segment {
                a: p2(src, rng),
                b: p2(src, rng),
            },
            Linear2In::Segment {
                a: p2(src, rng),
                b: p2(src, rng),
            },
        ),
    }
}

// ---- exact vector arithmetic on dyadic data (exact by the module's argument) ----

fn add(a: P3, b: P3) -> P3 {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}
fn mul(k: f64, a: P3) -> P3 {
    [k * a[0], k * a[1], k * a[2]]
}
fn cross(a: P3, b: P3) -> P3 {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}
fn dot(a: P3, b: P3) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}
/// `o + a·u + b·v`.
fn comb(o: P3, a: f64, u: P3, b: f64, v: P3) -> P3 {
    add(o, add(mul(a, u), mul(b, v)))
}
fn add2(a: P2, b: P2) -> P2 {
    [a[0] + b[0], a[1] + b[1]]
}
fn mul2(k: f64, a: P2) -> P2 {
    [k * a[0], k * a[1]]
}

/// A non-zero small integer.
fn nonzero(rng: &mut Rng) -> f64 {
    let k = rng.int(1, 4) as f64;
    if rng.coin() {
        -k
    } else {
        k
    }
}

/// A dyadic plane with a point `o` on it and two spanning vectors `u`, `v`: its own
/// parametric form, or the implicit form `(u × v)·x − (u × v)·o = 0` times a small
/// integer.
struct Frame {
    o: P3,
    u: P3,
    v: P3,
}

impl Frame {
    fn new(rng: &mut Rng) -> Frame {
        let d = Rng::dyadic;
        Frame {
            o: p3(d, rng),
            u: p3(d, rng),
            v: p3(d, rng),
        }
    }
    fn n(&self) -> P3 {
        cross(self.u, self.v)
    }
    /// The plane in one of several exact representations of the same set.
    fn plane(&self, rng: &mut Rng) -> PlaneIn {
        let (a, b) = (rng.small_int(), rng.small_int());
        match rng.below(4) {
            0 => PlaneIn::Parametric {
                origin: self.o,
                u: self.u,
                v: self.v,
            },
            // another origin, another basis of the same plane
            1 => PlaneIn::Parametric {
                origin: comb(self.o, a, self.u, b, self.v),
                u: comb(self.v, 0.0, self.u, nonzero(rng), self.v),
                v: mul(nonzero(rng), self.u),
            },
            _ => {
                let k = nonzero(rng);
                let n = mul(k, self.n());
                PlaneIn::Implicit {
                    normal: n,
                    d: -dot(n, self.o),
                }
            }
        }
    }
    /// A point of the plane.
    fn point(&self, rng: &mut Rng) -> P3 {
        comb(self.o, rng.dyadic(), self.u, rng.dyadic(), self.v)
    }
    /// A vector parallel to the plane (possibly zero: the case is then redrawn).
    fn along(&self, rng: &mut Rng) -> P3 {
        comb([0.0; 3], rng.small_int(), self.u, rng.small_int(), self.v)
    }
    /// The same plane moved off itself along a random dyadic offset.
    fn shifted(&self, rng: &mut Rng) -> Frame {
        Frame {
            o: add(self.o, p3(Rng::dyadic, rng)),
            u: self.u,
            v: self.v,
        }
    }
}

fn degenerate(c: Construction, rng: &mut Rng) -> Case {
    let mut case = degenerate_unscaled(c, rng);
    if rng.below(4) == 0 {
        let k = rng.int(-200, 200) as i32;
        scale(&mut case, 2f64.powi(k));
    }
    case
}

fn degenerate_unscaled(c: Construction, rng: &mut Rng) -> Case {
    // (both frames drawn first whatever the construction: the streams stay as they were)
    let (f, g) = (Frame::new(rng), Frame::new(rng));
    match c {
        Construction::ThreePlanes => Case::ThreePlanes(degenerate_three_planes(&f, &g, rng)),
        Construction::LinePlane => degenerate_line_plane(&f, rng),
        Construction::PlanePlane => degenerate_plane_plane(&f, &g, rng),
        Construction::ProjectLine => degenerate_project_line(&f, rng),
        Construction::ProjectPlane => degenerate_project_plane(&f, rng),
        Construction::Lines2 => degenerate_lines2(rng),
        Construction::Segments2 => degenerate_segments2(rng),
    }
}

/// Three planes: a pencil, one plane thrice, two coincident and a third, two
/// parallel and a third, a prism, or an integer combination.
fn degenerate_three_planes(f: &Frame, g: &Frame, rng: &mut Rng) -> [PlaneIn; 3] {
    match rng.below(6) {
        // a pencil: three planes through one line
        0 => {
            let w = g.u;
            let mk = |rng: &mut Rng| Frame {
                o: add(f.o, mul(rng.small_int(), w)),
                u: mul(nonzero(rng), w),
                v: p3(Rng::dyadic, rng),
            };
            let (a, b, c) = (mk(rng), mk(rng), mk(rng));
            [a.plane(rng), b.plane(rng), c.plane(rng)]
        }
        // the same plane three times, written differently
        1 => [f.plane(rng), f.plane(rng), f.plane(rng)],
        // two coincident planes and a third crossing them
        2 => [f.plane(rng), g.plane(rng), f.plane(rng)],
        // two parallel planes and a third
        3 => [f.plane(rng), f.shifted(rng).plane(rng), g.plane(rng)],
        // a prism: three planes sharing a direction, no common line
        4 => {
            let w = g.u;
            let mk = |rng: &mut Rng| Frame {
                o: p3(Rng::dyadic, rng),
                u: w,
                v: p3(Rng::dyadic, rng),
            };
            let (a, b, c) = (mk(rng), mk(rng), mk(rng));
            [a.plane(rng), b.plane(rng), c.plane(rng)]
        }
        // the third plane an integer combination of the first two (implicit)
        _ => {
            let (na, nb) = (f.n(), g.n());
            let (ha, hb) = (dot(na, f.o), dot(nb, g.o));
            let (a, b) = (rng.small_int(), nonzero(rng));
            let n = add(mul(a, na), mul(b, nb));
            [
                f.plane(rng),
                g.plane(rng),
                PlaneIn::Implicit {
                    normal: n,
                    d: -(a * ha + b * hb),
                },
            ]
        }
    }
}

/// A line or segment in, parallel to, or touching a plane.
fn degenerate_line_plane(f: &Frame, rng: &mut Rng) -> Case {
    let plane = f.plane(rng);
    let line = match rng.below(5) {
        // a line in the plane
        0 => LinearIn::Line {
            origin: f.point(rng),
            dir: f.along(rng),
        },
        // a line parallel to the plane (off it, unless the offset is in it)
        1 => LinearIn::Line {
            origin: add(f.point(rng), p3(Rng::dyadic, rng)),
            dir: f.along(rng),
        },
        // a segment in the plane
        2 => LinearIn::Segment {
            a: f.point(rng),
            b: f.point(rng),
        },
        // a segment touching the plane at an end point
        3 => {
            let (a, b) = (f.point(rng), p3(Rng::dyadic, rng));
            if rng.coin() {
                LinearIn::Segment { a, b }
            } else {
                LinearIn::Segment { a: b, b: a }
            }
        }
        // a segment parallel to the plane
        _ => {
            let a = add(f.point(rng), p3(Rng::dyadic, rng));
            LinearIn::Segment {
                a,
                b: add(a, f.along(rng)),
            }
        }
    };
    Case::LinePlane(line, plane)
}

/// Two planes: the same, parallel, or parallel through a point of `g`.
fn degenerate_plane_plane(f: &Frame, g: &Frame, rng: &mut Rng) -> Case {
    let other = match rng.below(3) {
        0 => f.plane(rng),
        1 => f.shifted(rng).plane(rng),
        // parallel through a point of g
        _ => Frame { o: g.o, ..*f }.plane(rng),
    };
    Case::PlanePlane(f.plane(rng), other)
}

/// A point on a line, or off it along a perpendicular.
fn degenerate_project_line(f: &Frame, rng: &mut Rng) -> Case {
    let (o, d) = (f.o, f.u);
    let on = add(o, mul(rng.dyadic(), d));
    let point = match rng.below(2) {
        // on the line
        0 => on,
        // off it along a perpendicular: the foot is `on`, exactly
        _ => add(on, mul(rng.small_int(), cross(d, f.v))),
    };
    Case::ProjectLine(point, o, d)
}

/// A point on a plane, or off it along the normal.
fn degenerate_project_plane(f: &Frame, rng: &mut Rng) -> Case {
    let on = f.point(rng);
    let point = match rng.below(2) {
        0 => on,
        _ => add(on, mul(rng.small_int(), f.n())),
    };
    Case::ProjectPlane(point, f.plane(rng))
}

/// Two 2D lines: the same line through another point, or parallel.
fn degenerate_lines2(rng: &mut Rng) -> Case {
    let (o, d) = (p2(Rng::dyadic, rng), p2(Rng::dyadic, rng));
    let o2 = match rng.below(2) {
        // the same line through another point
        0 => add2(o, mul2(rng.dyadic(), d)),
        // a parallel line (or the same, if the offset happens to be along d)
        _ => add2(o, p2(Rng::dyadic, rng)),
    };
    Case::Linear2(
        Linear2In::Line { origin: o, dir: d },
        Linear2In::Line {
            origin: o2,
            dir: mul2(nonzero(rng), d),
        },
    )
}

/// Two 2D segments: collinear, touching at an end point, or parallel.
fn degenerate_segments2(rng: &mut Rng) -> Case {
    let (o, d) = (p2(Rng::dyadic, rng), p2(Rng::dyadic, rng));
    let at = |k: i64| add2(o, mul2(k as f64 / 2.0, d));
    let k: [i64; 4] = [(); 4].map(|_| rng.int(-4, 4));
    let a = Linear2In::Segment {
        a: at(k[0]),
        b: at(k[1]),
    };
    let b = match rng.below(3) {
        // collinear: overlapping, touching or disjoint
        0 => Linear2In::Segment {
            a: at(k[2]),
            b: at(k[3]),
        },
        // an end point on the other segment (a T or an end-to-end touch)
        1 => Linear2In::Segment {
            a: at(k[2]),
            b: p2(Rng::dyadic, rng),
        },
        // parallel
        _ => {
            let off = p2(Rng::dyadic, rng);
            Linear2In::Segment {
                a: add2(at(k[2]), off),
                b: add2(at(k[3]), off),
            }
        }
    };
    Case::Linear2(a, b)
}

/// Visit every coordinate of a case, with whether it is position-like (scaled with the
/// configuration) or an implicit plane's normal (not scaled).
fn for_each_coord(case: &mut Case, f: &mut dyn FnMut(&mut f64, bool)) {
    fn plane(p: &mut PlaneIn, f: &mut dyn FnMut(&mut f64, bool)) {
        match p {
            PlaneIn::Parametric { origin, u, v } => all(&mut [origin, u, v], f),
            PlaneIn::Implicit { normal, d } => {
                normal.iter_mut().for_each(|x| f(x, false));
                f(d, true);
            }
        }
    }
    fn all(xs: &mut [&mut P3], f: &mut dyn FnMut(&mut f64, bool)) {
        xs.iter_mut()
            .for_each(|v| v.iter_mut().for_each(|x| f(x, true)));
    }
    fn linear2(l: &mut Linear2In, f: &mut dyn FnMut(&mut f64, bool)) {
        match l {
            Linear2In::Line { origin: a, dir: b } | Linear2In::Segment { a, b } => {
                a.iter_mut().chain(b.iter_mut()).for_each(|x| f(x, true))
            }
        }
    }
    match case {
        Case::ThreePlanes(ps) => ps.iter_mut().for_each(|p| plane(p, f)),
        Case::LinePlane(l, p) => {
            match l {
                LinearIn::Line { origin: a, dir: b } | LinearIn::Segment { a, b } => {
                    all(&mut [a, b], f)
                }
            }
            plane(p, f);
        }
        Case::PlanePlane(a, b) => {
            plane(a, f);
            plane(b, f);
        }
        Case::ProjectLine(p, o, d) => all(&mut [p, o, d], f),
        Case::ProjectPlane(p, pl) => {
            all(&mut [p], f);
            plane(pl, f);
        }
        Case::Linear2(a, b) => {
            linear2(a, f);
            linear2(b, f);
        }
    }
}

/// Scale the configuration by `s` (a power of two): positions, vectors and implicit
/// offsets; implicit normals stay.
fn scale(case: &mut Case, s: f64) {
    for_each_coord(case, &mut |x, scaled| {
        if scaled {
            *x *= s;
        }
    });
}

/// Move one coordinate one ulp up or down.
fn perturb(case: &mut Case, rng: &mut Rng) {
    let mut n = 0;
    for_each_coord(case, &mut |_, _| n += 1);
    let (target, up) = (rng.below(n), rng.coin());
    let mut i = 0;
    for_each_coord(case, &mut |x, _| {
        if i == target {
            *x = if up { next_up(*x) } else { next_down(*x) };
        }
        i += 1;
    });
}
