//! Seeded configurations whose common points lie exactly on a periodic seam (`u = 0 ≡
//! 2π` of a circle, a sphere or a torus) or at a pole of a sphere, or one ulp (or
//! `10⁻ᵏ` of the size) away from them, and tangencies at those places at the gaps of
//! [`Gap`] (issue 20, the soak's seams and poles). They are cases of the same
//! [`Data`] as the tangency families, so [`super::truth`] (exact counts in rationals,
//! points at 300 bits) and [`super::paths::run`] grade them.
//!
//! The seam of a circle `c + r(cos t, sin t)` is the point `c + (r, 0)`; of a sphere or
//! torus about `+z` with the default reference `+x`, the half-plane `y = c_y`, `x > c_x`,
//! and the sphere's poles are `c ± (0, 0, r)`. Every coordinate is dyadic with few bits
//! and every direction Pythagorean or axis-aligned, so a point built on a seam is on it
//! exactly in doubles. `Gap` selects how far from the seam or pole (`Tangent`: on it,
//! `Ulp`: one ulp of a coordinate away, `Pow(k)`: `10⁻ᵏ` of the radius away) for the
//! crossings, and how far from tangency for the tangencies (a radius perturbed, as in
//! [`super::gen`]).

use super::gen::{dy, perturb, point, PYTHAGOREAN, UNIT};
use super::{Data, Family, Gap};
use crate::num::rng::Rng;
use crate::num::round::{next_down, next_up};

pub(super) fn sign(rng: &mut Rng) -> i64 {
    if rng.coin() {
        1
    } else {
        -1
    }
}

/// A triple `(p, q, h)`, maybe swapped, both legs positive.
fn triple(rng: &mut Rng) -> (i64, i64, i64) {
    let (p, q, h) = PYTHAGOREAN[rng.below(PYTHAGOREAN.len())];
    if rng.coin() {
        (q, p, h)
    } else {
        (p, q, h)
    }
}

/// `x` moved off the seam or pole: by nothing, one ulp, or `10⁻ᵏ·size` (rounded), to
/// `side`.
pub(super) fn shift(x: f64, gap: Gap, side: i8, size: f64) -> f64 {
    match gap {
        Gap::Tangent => x,
        Gap::Ulp if side > 0 => next_up(x),
        Gap::Ulp => next_down(x),
        Gap::Pow(k) => x + f64::from(side) * 10f64.powi(-k) * size,
    }
}

/// The data of a seam or pole case.
pub fn data(family: Family, rng: &mut Rng, gap: Gap, side: i8) -> Data {
    match family {
        Family::SeamCircles2 => seam_circles2(rng, gap, side),
        Family::SeamTangent2 => seam_tangent2(rng, gap, side),
        Family::SeamLineSphere => seam_line_sphere(rng, gap, side),
        Family::PoleLineSphere => pole_line_sphere(rng, gap, side),
        Family::PoleCircleSphere => pole_circle_sphere(rng, gap, side),
        Family::SeamLineTorus => seam_line_torus(rng, gap, side),
        Family::PoleNurbsCircleSphere => pole_nurbs_circle_sphere(rng, gap, side),
        _ => unreachable!("not a seam family: {family:?}"),
    }
}

/// Two circles crossing at the seam point `c₁ + (r₁, 0)` of the first: the second's
/// centre is that point minus `r₂·(p, q)/h`; then its centre's `y` is moved by the gap
/// (the crossing leaves the seam to either side).
fn seam_circles2(rng: &mut Rng, gap: Gap, side: i8) -> Data {
    let c1: [f64; 2] = point(rng);
    let r1 = dy(rng.int(1 << 16, 1 << 20));
    let (p, q, h) = triple(rng);
    let m = rng.int(1 << 12, 1 << 14);
    let (sp, sq) = (sign(rng), sign(rng));
    let r2 = dy(h * m);
    let c2 = [c1[0] + r1 - dy(sp * p * m), c1[1] - dy(sq * q * m)];
    Data::Circles2 {
        c1,
        r1,
        c2: [c2[0], shift(c2[1], gap, side, r2)],
        r2,
    }
}

/// Two circles tangent on the seam of the first (`c₁ + (r₁, 0)`, from inside — also
/// the seam of the second — or outside) or at its antipode `c₁ − (r₁, 0)` from outside
/// (the seam of the second); the second radius perturbed.
fn seam_tangent2(rng: &mut Rng, gap: Gap, side: i8) -> Data {
    let c1: [f64; 2] = point(rng);
    let k1 = rng.int(1 << 17, 1 << 20);
    let k2 = rng.int(1 << 15, k1 - 1);
    let (r1, r2) = (dy(k1), dy(k2));
    let offset = match rng.below(3) {
        0 => r1 - r2,
        1 => r1 + r2,
        _ => -(r1 + r2),
    };
    Data::Circles2 {
        c1,
        r1,
        c2: [c1[0] + offset, c1[1]],
        r2: perturb(r2, gap, side),
    }
}

/// A line through two points of the sphere's seam meridian (`y = c_y`, `x > c_x`),
/// moved off it in `y` by the gap; or a line tangent to the sphere at the seam point
/// `c + (r, 0, 0)` of its equator, the radius perturbed.
fn seam_line_sphere(rng: &mut Rng, gap: Gap, side: i8) -> Data {
    let c: [f64; 3] = point(rng);
    if rng.coin() {
        let ((p1, q1, h1), (p2, q2, h2)) = (triple(rng), triple(rng));
        let m = rng.int(1 << 4, 1 << 8);
        let r = dy(h1 * h2 * m);
        let (s1, s2) = (sign(rng), -1);
        // P₁ = c + (p₁, 0, ±q₁)·h₂m, P₂ = c + (p₂, 0, −q₂)·h₁m: on the seam (x > c_x).
        let a = [c[0] + dy(p1 * h2 * m), c[1], c[2] + dy(s1 * q1 * h2 * m)];
        let b = [c[0] + dy(p2 * h1 * m), c[1], c[2] + dy(s2 * q2 * h1 * m)];
        let d = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
        let d = if d == [0.0; 3] { [0.0, 0.0, 1.0] } else { d };
        Data::LineSphere {
            o: [a[0], shift(a[1], gap, side, r), a[2]],
            d,
            c,
            r,
        }
    } else {
        let r = dy(rng.int(1 << 16, 1 << 20));
        let (p, q, _) = triple(rng);
        Data::LineSphere {
            o: [c[0] + r, c[1], c[2]],
            d: [0.0, (sign(rng) * p) as f64, (sign(rng) * q) as f64],
            c,
            r: perturb(r, gap, side),
        }
    }
}

/// The sphere's axis as a line (through both poles), moved off it in `x` or `y` by the
/// gap; or a horizontal line tangent at a pole, the radius perturbed.
fn pole_line_sphere(rng: &mut Rng, gap: Gap, side: i8) -> Data {
    let c: [f64; 3] = point(rng);
    let r = dy(rng.int(1 << 16, 1 << 20));
    if rng.coin() {
        let mut o = c;
        let k = rng.below(2);
        o[k] = shift(o[k], gap, side, r);
        Data::LineSphere {
            o,
            d: [0.0, 0.0, sign(rng) as f64],
            c,
            r,
        }
    } else {
        let (p, q, _) = triple(rng);
        let z = c[2] + sign(rng) as f64 * r;
        Data::LineSphere {
            o: [c[0], c[1], z],
            d: [(sign(rng) * p) as f64, (sign(rng) * q) as f64, 0.0],
            c,
            r: perturb(r, gap, side),
        }
    }
}

/// A circle in the seam's plane `y = c_y` through both poles (centre `c + (a, 0, 0)`,
/// `(a, r, ρ)` Pythagorean), its plane or centre moved by the gap; or a circle in that
/// plane tangent to the sphere at a pole or at the seam point of the equator (from
/// outside or inside), its radius perturbed.
fn pole_circle_sphere(rng: &mut Rng, gap: Gap, side: i8) -> Data {
    let c: [f64; 3] = point(rng);
    let n = [0.0, sign(rng) as f64, 0.0];
    if rng.coin() {
        let (p, q, h) = triple(rng);
        let m = rng.int(1 << 12, 1 << 14);
        let (r, rho) = (dy(q * m), dy(h * m));
        let mut centre = [c[0] + dy(sign(rng) * p * m), c[1], c[2]];
        let k = rng.below(2);
        centre[k] = shift(centre[k], gap, side, r);
        Data::CircleSphere {
            q: centre,
            n,
            rho,
            c,
            r,
        }
    } else {
        let kr = rng.int(1 << 17, 1 << 20);
        let krho = rng.int(1 << 14, kr - 1);
        let (r, rho) = (dy(kr), dy(krho));
        let reach = if rng.coin() { r + rho } else { r - rho };
        let reach = sign(rng) as f64 * reach;
        let centre = if rng.coin() {
            [c[0], c[1], c[2] + reach] // at a pole
        } else {
            [c[0] + reach.abs(), c[1], c[2]] // at the seam point of the equator
        };
        Data::CircleSphere {
            q: centre,
            n,
            rho: perturb(rho, gap, side),
            c,
            r,
        }
    }
}

/// A torus about `z`: the line along `x` through its centre (four crossings on the
/// seam `u = 0` or its antipode, on the outer and inner equators `v = 0`, `v = π`),
/// moved off in `y` or `z` by the gap; or a line along `y` tangent at the seam point
/// `c + (R + r, 0, 0)` of the outer equator, or at the top `c + (R, 0, r)` of the tube
/// on the seam, the minor radius perturbed.
fn seam_line_torus(rng: &mut Rng, gap: Gap, side: i8) -> Data {
    let c: [f64; 3] = point(rng);
    let major = dy(rng.int(1 << 21, 1 << 22));
    let minor = dy(rng.int(1 << 18, 1 << 20));
    let d = [0.0, sign(rng) as f64, 0.0];
    match rng.below(3) {
        0 => {
            let mut o = c;
            let k = 1 + rng.below(2);
            o[k] = shift(o[k], gap, side, minor);
            Data::LineTorus {
                o,
                d: [sign(rng) as f64, 0.0, 0.0],
                c,
                major,
                minor,
            }
        }
        1 => Data::LineTorus {
            o: [c[0] + major + minor, c[1], c[2]],
            d,
            c,
            major,
            minor: perturb(minor, gap, side),
        },
        _ => Data::LineTorus {
            o: [c[0] + major, c[1], c[2] + sign(rng) as f64 * minor],
            d,
            c,
            major,
            minor: perturb(minor, gap, side),
        },
    }
}

/// The exact rational circle as a clamped NURBS of degree 2 in four arcs: angles `0 →
/// 2φ → π → π + 2φ → 2π` with `tan φ = 3/4`, so every arc's half-angle has a rational
/// cosine (`4/5` or `3/5`, the middle weights over end weights `5`) and every control
/// point is rational. The points in the circle's own frame, times 300 (they are
/// `(1, 0), (1, 3/4), (7/25, 24/25), (−1, 4/3), (−1, 0), …`), and the weights.
const NURBS_CIRCLE: [([i64; 2], f64); 9] = [
    ([300, 0], 5.0),
    ([300, 225], 4.0),
    ([84, 288], 5.0),
    ([-300, 400], 3.0),
    ([-300, 0], 5.0),
    ([-300, -225], 4.0),
    ([-84, -288], 5.0),
    ([300, -400], 3.0),
    ([300, 0], 5.0),
];

/// The knots of the NURBS circle of [`nurbs_circle`]: double at the arcs' joins, parameter `t ∈ [0, 4]`.
pub const NURBS_CIRCLE_KNOTS: [f64; 12] = [0., 0., 0., 1., 1., 2., 2., 3., 3., 4., 4., 4.];

/// The control points and weights of the NURBS circle of radius `rho` about `q` in the
/// plane `y = q_y`, starting (`t = 0`, its closing knot) in the direction `(p, s)/h` of
/// the `(x, z)` plane. Exact in doubles: `rho` is a multiple of `300·h` units (2⁻²⁰),
/// so every offset is an integer number of units.
pub fn nurbs_circle(q: &[f64; 3], rho: f64, start: [i64; 3]) -> (Vec<[f64; 3]>, Vec<f64>) {
    let [p, s, h] = start;
    let units = (rho / UNIT) as i64;
    assert_eq!(units % (300 * h), 0, "rho is a multiple of 300·h units");
    let k = units / (300 * h);
    NURBS_CIRCLE
        .iter()
        .map(|&([a, b], w)| {
            let (x, z) = (k * (p * a - s * b), k * (s * a + p * b));
            ([q[0] + dy(x), q[1], q[2] + dy(z)], w)
        })
        .unzip()
}

/// A direction `(p, s, h)` of the `(x, z)` plane (`p² + s² = h²`): an axis or a random
/// Pythagorean one.
fn direction(rng: &mut Rng) -> [i64; 3] {
    match rng.below(3) {
        0 => [sign(rng), 0, 1],
        1 => [0, sign(rng), 1],
        _ => {
            let (p, s, h) = triple(rng);
            [sign(rng) * p, sign(rng) * s, h]
        }
    }
}

/// [`pole_circle_sphere`] with the circle as the NURBS of [`nurbs_circle`] — a rational
/// curve through (or touching) the sphere's poles and seam meridian, its start knot
/// (`t = 0 ≡ 4`, where the curve closes) often on a pole or at the touching point. So
/// that the NURBS stays exact in doubles, the gap moves the sphere, not the circle: its
/// centre off the circle's (crossings), or its radius (tangencies; `side` keeps its
/// meaning, `+` crosses).
fn pole_nurbs_circle_sphere(rng: &mut Rng, gap: Gap, side: i8) -> Data {
    let mut c: [f64; 3] = point(rng);
    if rng.coin() {
        // Through both poles: (a, r, rho) = (p, s, h)·m, the start at a pole, on the
        // seam plane's axis or anywhere.
        let (p, s, h) = triple(rng);
        let a = sign(rng) * p;
        let pole = [-a, sign(rng) * s, h];
        let start = if rng.coin() { pole } else { direction(rng) };
        let m = 300 * start[2] * rng.int(1 << 2, 1 << 4);
        let (r, rho) = (dy(s * m), dy(h * m));
        let q = [c[0] + dy(a * m), c[1], c[2]];
        let k = if rng.coin() { 0 } else { 1 };
        c[k] = shift(c[k], gap, -side, r);
        Data::NurbsCircleSphere {
            q,
            start,
            rho,
            c,
            r,
        }
    } else {
        // Touching at a pole or at the seam point of the equator, from outside or
        // inside; the start at the touching point, on an axis or anywhere.
        let start = direction(rng);
        let krho = 300 * start[2] * rng.int(1, 8);
        let kr = rng.int(1 << 18, 1 << 20);
        let (r, rho) = (dy(kr), dy(krho));
        let outside = rng.coin();
        let reach = if outside { r + rho } else { r - rho };
        let up = sign(rng);
        let at_pole = rng.coin();
        let (q, touch) = if at_pole {
            ([c[0], c[1], c[2] + up as f64 * reach], [0, -up, 1])
        } else {
            ([c[0] + reach, c[1], c[2]], [-1, 0, 1])
        };
        let touch = if outside {
            touch
        } else {
            [-touch[0], -touch[1], 1]
        };
        // `krho` is a multiple of `300·h` for both (the touching direction has h = 1).
        let start = if rng.coin() { touch } else { start };
        // A larger sphere crosses a circle touching it from outside, and clears one
        // touching it from inside.
        let side = if outside { side } else { -side };
        Data::NurbsCircleSphere {
            q,
            start,
            rho,
            c,
            r: perturb(r, gap, side),
        }
    }
}
