//! The seeded generators of the curved families ([`super::Family`]).
//!
//! Every coordinate and radius is a multiple of 2⁻²⁰ below 2¹⁰ in magnitude (at most
//! 30 significant bits), so sums of a few of them are exact in doubles; directions in
//! the plane are Pythagorean, `(p, q)/h` with `p² + q² = h²`, so that a point at an
//! exact distance `h·m·2⁻²⁰` along them has dyadic coordinates `(p, q)·m·2⁻²⁰`. The
//! exactly tangent configuration is therefore exactly tangent in doubles (checked
//! against the exact truth in the tests of [`super::truth`]).

use super::{Data, Family, Gap};
use crate::num::rng::Rng;
use crate::num::round::{next_down, next_up};

/// Primitive Pythagorean triples `(p, q, h)`.
pub(super) const PYTHAGOREAN: [(i64, i64, i64); 10] = [
    (3, 4, 5),
    (5, 12, 13),
    (8, 15, 17),
    (7, 24, 25),
    (20, 21, 29),
    (12, 35, 37),
    (9, 40, 41),
    (28, 45, 53),
    (11, 60, 61),
    (33, 56, 65),
];

/// The unit of the dyadic data.
pub(super) const UNIT: f64 = 1.0 / (1u64 << 20) as f64;

/// `k·2⁻²⁰` (exact for `|k| < 2⁵³`).
pub(super) fn dy(k: i64) -> f64 {
    k as f64 * UNIT
}

/// A random point with coordinates in `[−16, 16]`, multiples of 2⁻²⁰.
pub(super) fn point<const D: usize>(rng: &mut Rng) -> [f64; D] {
    std::array::from_fn(|_| dy(rng.int(-(1 << 24), 1 << 24)))
}

/// A Pythagorean direction `(p, q)` of length `h`, randomly swapped and signed.
fn pythagorean(rng: &mut Rng) -> (i64, i64, i64) {
    let (mut p, mut q, h) = PYTHAGOREAN[rng.below(PYTHAGOREAN.len())];
    if rng.coin() {
        std::mem::swap(&mut p, &mut q);
    }
    if rng.coin() {
        p = -p;
    }
    if rng.coin() {
        q = -q;
    }
    (p, q, h)
}

/// A small nonzero integer in `[−4, 4]`.
fn small_nonzero(rng: &mut Rng) -> i64 {
    let k = rng.int(1, 4);
    if rng.coin() {
        -k
    } else {
        k
    }
}

/// The radius `r` moved off tangency by `gap` to `side` (`+1` larger, `−1` smaller).
pub fn perturb(r: f64, gap: Gap, side: i8) -> f64 {
    match gap {
        Gap::Tangent => r,
        Gap::Ulp if side > 0 => next_up(r),
        Gap::Ulp => next_down(r),
        Gap::Pow(k) => r * (1.0 + f64::from(side) * 10f64.powi(-k)),
    }
}

/// The generator of case `seed` at `gap`, and its side (`+1`, `−1`, or `0` at
/// tangency), drawn first.
pub(super) fn start(gap: Gap, seed: u64) -> (Rng, i8) {
    let mut rng = Rng::new(seed);
    let side = match gap {
        Gap::Tangent => 0,
        _ if rng.coin() => 1,
        _ => -1,
    };
    (rng, side)
}

/// The data of a tangency family's case (the seam families: [`super::seams`]).
pub(super) fn data(family: Family, rng: &mut Rng, gap: Gap, side: i8) -> Data {
    match family {
        Family::LineSphere => line_sphere(rng, gap, side),
        Family::LineTorus => line_torus(rng, gap, side),
        Family::Circle2Circle2 => circles2(rng, gap, side),
        Family::Circle2Ellipse2 => circle_ellipse2(rng, gap, side),
        _ => circle_sphere(rng, gap, side),
    }
}

/// Apply the same random axis permutation and sign flips to every vector (exact).
fn reorient(rng: &mut Rng, vs: &mut [&mut [f64; 3]]) {
    const PERMS: [[usize; 3]; 6] = [
        [0, 1, 2],
        [0, 2, 1],
        [1, 0, 2],
        [1, 2, 0],
        [2, 0, 1],
        [2, 1, 0],
    ];
    let perm = PERMS[rng.below(6)];
    let flip: [f64; 3] = std::array::from_fn(|_| if rng.coin() { -1.0 } else { 1.0 });
    for v in vs.iter_mut() {
        let w = **v;
        **v = std::array::from_fn(|i| flip[i] * w[perm[i]]);
    }
}

/// A line at distance exactly `r` from the centre: `o = c + n + s·d` with `n ⟂ d`,
/// `|n| = r`; then the radius is perturbed.
fn line_sphere(rng: &mut Rng, gap: Gap, side: i8) -> Data {
    let mut c: [f64; 3] = point(rng);
    let (p, q, h) = pythagorean(rng);
    let m = rng.int(1 << 16, 1 << 18);
    let r = dy(h * m);
    let n = [dy(p * m), dy(q * m), 0.0];
    let (alpha, beta) = (small_nonzero(rng), rng.int(-4, 4));
    let mut d = [(-q * alpha) as f64, (p * alpha) as f64, beta as f64];
    let s = rng.int(-(1 << 10), 1 << 10) as f64 / 256.0;
    let mut o = std::array::from_fn(|i| c[i] + n[i] + s * d[i]);
    reorient(rng, &mut [&mut o, &mut d, &mut c]);
    Data::LineSphere {
        o,
        d,
        c,
        r: perturb(r, gap, side),
    }
}

/// A torus about `z` with `R ∈ [2, 4]`, `r ∈ [1/4, 1]`; the line horizontal, either in
/// the top or bottom tangent plane `z = c_z ± r` at a distance below `0.75·R` from the
/// axis (tangent to the tube along two points), or in the equator plane at distance
/// exactly `R + r` (tangent to the outer equator). The minor radius is perturbed.
fn line_torus(rng: &mut Rng, gap: Gap, side: i8) -> Data {
    let c: [f64; 3] = point(rng);
    let (p, q, h) = pythagorean(rng);
    let minor = dy(rng.int(1 << 18, 1 << 20));
    let alpha = small_nonzero(rng);
    let d = [(-q * alpha) as f64, (p * alpha) as f64, 0.0];
    let s = rng.int(-(1 << 10), 1 << 10) as f64 / 256.0;
    let (major, m, z) = if rng.coin() {
        let major = dy(rng.int(1 << 21, 1 << 22));
        let m = rng.int(0, (3 << 20) / (2 * h));
        let z = if rng.coin() { minor } else { -minor };
        (major, m, z)
    } else {
        // R + r = h·M·2⁻²⁰ ∈ [3r, 3r + 2], so R ≥ 2r.
        let lo = (3.0 * minor / (h as f64 * UNIT)).ceil() as i64;
        let m = rng.int(lo, lo + (2 << 20) / h);
        (dy(h * m) - minor, m, 0.0)
    };
    let o = [
        c[0] + dy(p * m) + s * d[0],
        c[1] + dy(q * m) + s * d[1],
        c[2] + z,
    ];
    Data::LineTorus {
        o,
        d,
        c,
        major,
        minor: perturb(minor, gap, side),
    }
}

/// Two circles with radii `h·m·2⁻²⁰` whose centres are `r₁ + r₂` (external) or
/// `r₁ − r₂` (internal, `r₁ > r₂`) apart along a Pythagorean direction; `r₂` perturbed.
fn circles2(rng: &mut Rng, gap: Gap, side: i8) -> Data {
    let c1: [f64; 2] = point(rng);
    let (p, q, h) = pythagorean(rng);
    let (mut m1, mut m2) = (rng.int(1 << 16, 1 << 18), rng.int(1 << 16, 1 << 18));
    let k = if rng.coin() {
        m1 + m2
    } else {
        if m1 < m2 {
            std::mem::swap(&mut m1, &mut m2);
        }
        if m1 == m2 {
            m1 += 1;
        }
        m1 - m2
    };
    Data::Circles2 {
        c1,
        r1: dy(h * m1),
        c2: [c1[0] + dy(p * k), c1[1] + dy(q * k)],
        r2: perturb(dy(h * m2), gap, side),
    }
}

/// An ellipse with `b ∈ [1/4, 1]`, `a ∈ (b, 3b]`, and a circle touching it at the end
/// `(e_x, e_y ± b)` of its minor axis, from outside (any radius in `[1/16, 2]`) or from
/// inside (radius below `b`); the circle's radius perturbed.
fn circle_ellipse2(rng: &mut Rng, gap: Gap, side: i8) -> Data {
    let e: [f64; 2] = point(rng);
    let kb = rng.int(1 << 18, 1 << 20);
    let (a, b) = (dy(kb + rng.int(kb / 8, 2 * kb)), dy(kb));
    let (rho, offset) = if rng.coin() {
        let rho = dy(rng.int(1 << 16, 1 << 21));
        (rho, b + rho)
    } else {
        let rho = dy(rng.int(kb / 10, 9 * kb / 10));
        (rho, b - rho)
    };
    let offset = if rng.coin() { offset } else { -offset };
    Data::CircleEllipse2 {
        c: [e[0], e[1] + offset],
        rho: perturb(rho, gap, side),
        e,
        a,
        b,
    }
}

/// A sphere of radius `h·m·2⁻²⁰` and a circle in a plane through the sphere's centre
/// (normal `α(−q, p, 0) + β(0, 0, 1)`), its centre `R ± ρ` from the sphere's along
/// `(p, q, 0)/h`: tangent to the great circle of that plane from outside or inside.
/// The circle's radius is perturbed.
fn circle_sphere(rng: &mut Rng, gap: Gap, side: i8) -> Data {
    let mut c: [f64; 3] = point(rng);
    let (p, q, h) = pythagorean(rng);
    let (mut mr, mut mrho) = (rng.int(1 << 16, 1 << 18), rng.int(1 << 14, 1 << 18));
    let k = if rng.coin() {
        mr + mrho
    } else {
        if mr < mrho {
            std::mem::swap(&mut mr, &mut mrho);
        }
        if mr == mrho {
            mr += 1;
        }
        mr - mrho
    };
    let (alpha, beta) = (small_nonzero(rng), rng.int(-4, 4));
    let mut n = [(-q * alpha) as f64, (p * alpha) as f64, beta as f64];
    let mut centre = [c[0] + dy(p * k), c[1] + dy(q * k), c[2]];
    reorient(rng, &mut [&mut centre, &mut n, &mut c]);
    Data::CircleSphere {
        q: centre,
        n,
        rho: perturb(dy(h * mrho), gap, side),
        c,
        r: dy(h * mr),
    }
}
