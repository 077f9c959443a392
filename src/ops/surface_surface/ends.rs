//! Domain faces of surface ∩ surface decided exactly (OPERATIONS.md §9.4 "Boundary",
//! CERTIFICATION.md "Completeness"; issue 15, the curve at a cylinder's height end).
//!
//! The completeness proof solves, on every bounded face of the domain, the iso-curve of
//! the face against the other surface (module doc of `complete`). Where the intersection
//! curve only *touches* a face, that system has a double root, which interval arithmetic
//! cannot tell from two roots or none. For a circular cylinder and a sphere the face
//! system of a height end is algebraic in the input doubles and is decided here with
//! exact rationals instead.
//!
//! The cylinder is `O + ρ(cos u X + sin u Y) + v Z` with `Z = axis/|axis|` (the frame is
//! exactly orthonormal, `curve::frame`), taken only when `|axis|` is rational (so
//! `Z` is). With `w = c − O` (`c` the sphere's centre, `R` its radius), `w_z = w·Z` and
//! `d² = |w|² − w_z²` (the squared distance of `c` from the axis), the squared distance
//! minus `R²` at the point `(u, v)` of the cylinder is
//!
//! ```text
//! G(u, v) = ρ² + d² + (w_z − v)² − R² − 2ρd cos(u − φ)        (φ: the direction of c)
//! ```
//!
//! On the face `v = h`, `G = A − B cos(u − φ)` with `A = ρ² + d² + (w_z − h)² − R²` and
//! `B = 2ρd`, both known exactly through `A` and `B²`:
//! * `A² > B²` (or `d = 0`, `A ≠ 0`): `G ≠ 0` on the whole circle — the face holds no
//!   point of the intersection ([`FaceTruth::Empty`]);
//! * `A² = B² ≠ 0`: one double root `u₀` (`φ` or `φ + π`), where `G(u, h)` has the sign
//!   `σ = sign A` for every `u ≠ u₀`. Near it the curve `G = 0` is the graph
//!   `v − h ≈ −G(u, h)/G_v` with `G_v = 2(h − w_z)` (implicit function theorem, `G_v ≠
//!   0`), so it lies strictly on the side `−σ·sign(h − w_z)` of the face except at the
//!   touching point. When that side is the domain's ([`FaceTruth::TouchInside`]) the
//!   face holds at most that one point and the curve does not cross there.
//! * otherwise (two transversal roots, or the whole circle on the sphere) nothing is
//!   decided here: the interval solve of the face stands.
//!
//! A trimmed sphere only removes points: both statements stay true.

use crate::surface::quadrics::{Cylinder, Sphere};
use crate::surface::{AnySurface, Surface};
use rug::Rational;
use std::cmp::Ordering;

/// What is known exactly about one face's points of the intersection.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FaceTruth {
    /// None.
    Empty,
    /// At most one, where the curve touches the face from inside the domain.
    TouchInside,
}

/// The face `x_k = bound` (a domain bound, exactly) and what is known about it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DecidedFace {
    pub k: usize,
    pub bound: f64,
    pub truth: FaceTruth,
}

/// The faces of the pair `(r, s)` decided exactly (module doc); empty for other pairs.
pub fn decide(r: Option<&AnySurface>, s: Option<&AnySurface>) -> Vec<DecidedFace> {
    match (r, s) {
        (Some(AnySurface::Cylinder(c)), Some(AnySurface::Sphere(p))) => cylinder_sphere(c, p, 1),
        (Some(AnySurface::Sphere(p)), Some(AnySurface::Cylinder(c))) => cylinder_sphere(c, p, 3),
        _ => Vec::new(),
    }
}

fn q(x: f64) -> Option<Rational> {
    Rational::from_f64(x)
}

fn q3(x: [f64; 3]) -> Option<[Rational; 3]> {
    Some([q(x[0])?, q(x[1])?, q(x[2])?])
}

fn dot(a: &[Rational; 3], b: &[Rational; 3]) -> Rational {
    Rational::from(&a[0] * &b[0]) + Rational::from(&a[1] * &b[1]) + Rational::from(&a[2] * &b[2])
}

/// `√x` when it is rational.
fn rational_sqrt(x: &Rational) -> Option<Rational> {
    if x.cmp0() == Ordering::Less {
        return None;
    }
    let (n, d) = (x.numer(), x.denom());
    (n.is_perfect_square() && d.is_perfect_square())
        .then(|| Rational::from((n.clone().sqrt(), d.clone().sqrt())))
}

fn sign(x: &Rational) -> i32 {
    match x.cmp0() {
        Ordering::Less => -1,
        Ordering::Equal => 0,
        Ordering::Greater => 1,
    }
}

/// The height ends of the cylinder (coordinate `k` of the pair) against the sphere.
fn cylinder_sphere(c: &Cylinder, p: &Sphere, k: usize) -> Vec<DecidedFace> {
    let [a, b] = c.semi_axes();
    if a != b {
        return Vec::new();
    }
    let f = c.frame();
    let (Some(axis), Some(o), Some(centre), Some(rho), Some(big)) = (
        q3(f.axis()),
        q3(f.origin()),
        q3(p.frame().origin()),
        q(a),
        q(p.radius()),
    ) else {
        return Vec::new();
    };
    let Some(len) = rational_sqrt(&dot(&axis, &axis)) else {
        return Vec::new();
    };
    if len.cmp0() != Ordering::Greater {
        return Vec::new();
    }
    let w: [Rational; 3] = std::array::from_fn(|i| Rational::from(&centre[i] - &o[i]));
    let wz = dot(&w, &axis) / &len;
    let d2 = dot(&w, &w) - Rational::from(&wz * &wz);
    let rho2 = Rational::from(&rho * &rho);
    let b2 = Rational::from(4) * &rho2 * &d2;
    let heights = c.domain().1;
    let mut out = Vec::new();
    for (end, h) in heights.into_iter().enumerate() {
        let Some(hq) = q(h) else { continue };
        let dz = Rational::from(&hq - &wz);
        let aa = rho2.clone() + &d2 + Rational::from(&dz * &dz) - Rational::from(&big * &big);
        let a2 = Rational::from(&aa * &aa);
        let truth = if d2.cmp0() == Ordering::Equal {
            (aa.cmp0() != Ordering::Equal).then_some(FaceTruth::Empty)
        } else {
            match a2.cmp(&b2) {
                Ordering::Greater => Some(FaceTruth::Empty),
                Ordering::Equal => {
                    // inside: below the upper end, above the lower one
                    let inside = if end == 1 { -1 } else { 1 };
                    let side = -sign(&aa) * sign(&dz);
                    (side == inside).then_some(FaceTruth::TouchInside)
                }
                Ordering::Less => None,
            }
        };
        if let Some(truth) = truth {
            out.push(DecidedFace { k, bound: h, truth });
        }
    }
    out
}

#[cfg(test)]
mod tests {
    //! Families against an independent truth: the face circle `v = h` holds a point at
    //! distance `R` from the sphere's centre iff `R² ∈ [(ρ − d)² + dz², (ρ + d)² + dz²]`
    //! (nearest and farthest points of the circle), computed in MPFR at 600 bits from
    //! the unit axis — not from the exact `A² ⋛ B²` of the module. Touching cases are
    //! built exactly from Pythagorean triples; there the side of the face the curve
    //! leaves into is derived geometrically: at the nearest point the distance grows
    //! with `|w_z − v|`, so the curve runs toward `w_z`; at the farthest point away.
    use super::*;
    use crate::num::rng::Rng;
    use crate::num::round::{next_down, next_up};
    use rug::Float;

    const BITS: u32 = 600;

    /// Integer axes with an integer length, and two integer vectors orthogonal to each
    /// with the same length (so `perp/len` is a rational unit vector).
    const AXES: [([f64; 3], f64, [[f64; 3]; 2]); 5] = [
        ([0.0, 0.0, 1.0], 1.0, [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0]]),
        ([1.0, 0.0, 0.0], 1.0, [[0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]),
        ([1.0, 2.0, 2.0], 3.0, [[2.0, 1.0, -2.0], [2.0, -2.0, 1.0]]),
        ([2.0, 3.0, 6.0], 7.0, [[3.0, -6.0, 2.0], [6.0, 2.0, -3.0]]),
        ([0.0, 3.0, 4.0], 5.0, [[5.0, 0.0, 0.0], [0.0, 4.0, -3.0]]),
    ];
    const TRIPLES: [[f64; 3]; 5] = [
        [3.0, 4.0, 5.0],
        [5.0, 12.0, 13.0],
        [8.0, 15.0, 17.0],
        [7.0, 24.0, 25.0],
        [20.0, 21.0, 29.0],
    ];

    fn f(x: f64) -> Float {
        Float::with_val(BITS, x)
    }

    /// `[lo, hi]`: the squared distances of the nearest and farthest points of the face
    /// circle `v = h` from the sphere's centre, and `w_z`.
    fn face_range(c: &Cylinder, p: &Sphere, h: f64) -> (Float, Float, Float) {
        let (axis, o, centre) = (c.frame().axis(), c.frame().origin(), p.frame().origin());
        let len = (0..3)
            .fold(f(0.0), |s, i| s + f(axis[i]) * f(axis[i]))
            .sqrt();
        let w: Vec<Float> = (0..3).map(|i| f(centre[i]) - f(o[i])).collect();
        let wz = (0..3).fold(f(0.0), |s, i| s + w[i].clone() * f(axis[i])) / &len;
        let ww = (0..3).fold(f(0.0), |s, i| s + w[i].clone() * &w[i]);
        let d2 = ww - wz.clone() * &wz;
        let d = if d2 > 0 { d2.sqrt() } else { f(0.0) };
        let rho = f(c.semi_axes()[0]);
        let dz = wz.clone() - h;
        let dz2 = dz.clone() * &dz;
        let near = (rho.clone() - &d).square() + &dz2;
        let far = (rho + &d).square() + &dz2;
        (near, far, wz)
    }

    /// The decisions for the pair in both orders, with the cylinder's coordinate index.
    fn both_orders(c: &Cylinder, p: &Sphere) -> [(Vec<DecidedFace>, usize); 2] {
        let (ca, pa) = (
            AnySurface::Cylinder(c.clone()),
            AnySurface::Sphere(p.clone()),
        );
        assert!(decide(Some(&pa), Some(&pa)).is_empty());
        [
            (decide(Some(&ca), Some(&pa)), 1),
            (decide(Some(&pa), Some(&ca)), 3),
        ]
    }

    fn truth_of(decided: &[DecidedFace], k: usize, h: f64) -> Option<FaceTruth> {
        decided
            .iter()
            .find(|x| x.k == k && x.bound == h)
            .map(|x| x.truth)
    }

    /// A face is `Empty` only if `R²` is outside its range, and `TouchInside` only at
    /// an end of it (random data: never, up to 600-bit rounding).
    fn check_generic(c: &Cylinder, p: &Sphere, got: &[DecidedFace], k: usize) -> usize {
        let mut empties = 0;
        let r2 = f(p.radius()).square();
        for h in c.domain().1 {
            let (lo, hi, _) = face_range(c, p, h);
            match truth_of(got, k, h) {
                Some(FaceTruth::Empty) => {
                    assert!(r2 < lo || r2 > hi, "{c:?} {p:?}: face {h} called empty");
                    empties += 1;
                }
                Some(FaceTruth::TouchInside) => {
                    let tiny = f(1e-150) * (f(1.0) + &hi);
                    let gap = (r2.clone() - &lo).abs().min(&(r2.clone() - &hi).abs());
                    assert!(gap < tiny, "{c:?} {p:?}: face {h} called touching");
                }
                None => {}
            }
        }
        empties
    }

    #[test]
    fn random_faces_are_empty_only_when_the_sphere_misses_them() {
        let mut rng = Rng::new(1515);
        let (mut empties, mut cases) = (0, 0);
        for i in 0..3000 {
            let (axis, _, _) = AXES[rng.below(AXES.len())];
            let scale = [1.0, 0.125, 2f64.powi(200), 2f64.powi(-200)][i % 4];
            let int = |rng: &mut Rng, lo: i64, hi: i64| rng.int(lo, hi) as f64 * scale;
            let o = [
                int(&mut rng, -8, 8),
                int(&mut rng, -8, 8),
                int(&mut rng, -8, 8),
            ];
            let centre = [
                int(&mut rng, -8, 8),
                int(&mut rng, -8, 8),
                int(&mut rng, -8, 8),
            ];
            let rho = int(&mut rng, 1, 8);
            let big = int(&mut rng, 1, 16);
            let h0 = int(&mut rng, -12, 12);
            let h1 = h0 + int(&mut rng, 1, 12);
            let sign = if rng.coin() { 1.0 } else { -1.0 };
            let axis = axis.map(|x| x * sign * scale);
            let c = Cylinder::new(o, [rho, rho], axis, None, [h0, h1]).unwrap();
            let p = Sphere::new(centre, big, None, None).unwrap();
            for (got, k) in both_orders(&c, &p) {
                empties += check_generic(&c, &p, &got, k);
            }
            cases += 1;
        }
        // Anti-vacuity: more than a quarter of the faces checked miss the sphere.
        assert!(empties > cases, "{empties} empty faces in {cases} cases");
    }

    #[test]
    fn touching_faces_are_decided_on_the_side_the_curve_leaves_into() {
        let mut rng = Rng::new(1516);
        let (mut inside, mut outside, mut ulp_empty) = (0, 0, 0);
        for i in 0..2000 {
            let (axis, len, perps) = AXES[rng.below(AXES.len())];
            let scale = [1.0, 0.25, 2f64.powi(180), 2f64.powi(-180)][i % 4];
            let [t0, t1, t2] = TRIPLES[rng.below(TRIPLES.len())];
            let (m, dz, big) = if rng.coin() {
                (t0, t1, t2)
            } else {
                (t1, t0, t2)
            };
            let k = rng.int(1, 3) as f64;
            let (m, dz, big) = (m * k, dz * k, big * k);
            let near = rng.coin();
            // `d` a multiple of the perpendicular's length; ρ from `|ρ − d| = m`
            // (nearest point) or `ρ + d = m` (farthest).
            let d = len * rng.int(1, 4) as f64;
            let rho = if near {
                if rng.coin() || d <= m {
                    d + m
                } else {
                    d - m
                }
            } else if m > d {
                m - d
            } else {
                continue;
            };
            let wz = len * rng.int(-6, 6) as f64;
            let s = if rng.coin() { 1.0 } else { -1.0 };
            let h = wz - s * dz;
            let end = rng.below(2);
            let other = h + if end == 0 { 1.0 } else { -1.0 } * rng.int(1, 9) as f64;
            let heights = if end == 0 { [h, other] } else { [other, h] };
            let perp = perps[rng.below(2)];
            let o = [
                rng.int(-5, 5) as f64,
                rng.int(-5, 5) as f64,
                rng.int(-5, 5) as f64,
            ];
            // c = O + w_z·axis/len + d·perp/len, exact (len divides w_z and d).
            let centre: [f64; 3] =
                std::array::from_fn(|j| o[j] + wz / len * axis[j] + d / len * perp[j]);
            let sc = |x: [f64; 3]| x.map(|v| v * scale);
            let c = Cylinder::new(
                sc(o),
                [rho * scale; 2],
                sc(axis),
                None,
                heights.map(|x| x * scale),
            )
            .unwrap();
            let p = Sphere::new(sc(centre), big * scale, None, None).unwrap();
            let hs = h * scale;
            // The construction touches: R² is the nearest (or farthest) end of the range.
            let (lo, hi, _) = face_range(&c, &p, hs);
            let r2 = f(big * scale).square();
            let gap = if near { r2 - &lo } else { r2 - &hi };
            assert!(gap.abs() <= f(1e-170) * &hi, "not touching by construction");
            // The curve leaves into sign(w_z − h) = s at the nearest point, −s at the
            // farthest; the domain lies above the lower end, below the upper one.
            let leaves = if near { s } else { -s };
            let into = if end == 0 { 1.0 } else { -1.0 };
            let expected = (leaves == into).then_some(FaceTruth::TouchInside);
            for (got, k) in both_orders(&c, &p) {
                assert_eq!(
                    truth_of(&got, k, hs),
                    expected,
                    "{c:?} {p:?} near {near} face {hs}"
                );
                check_generic(&c, &p, &got, k);
            }
            // One ulp off touching, both ways: R² is then outside the face's range
            // (the face is empty, decided exactly) or inside it (two transversal roots,
            // left to the interval solve) — never a touch.
            for radius in [next_down(big * scale), next_up(big * scale)] {
                let q = Sphere::new(sc(centre), radius, None, None).unwrap();
                let (lo, hi, _) = face_range(&c, &q, hs);
                let r2 = f(radius).square();
                let misses = r2 < lo || r2 > hi;
                for (got, k) in both_orders(&c, &q) {
                    let want = misses.then_some(FaceTruth::Empty);
                    assert_eq!(truth_of(&got, k, hs), want, "{c:?} {q:?} face {hs}");
                    check_generic(&c, &q, &got, k);
                }
                ulp_empty += usize::from(misses);
            }
            if expected.is_some() {
                inside += 1;
            } else {
                outside += 1;
            }
        }
        assert!(
            inside > 300 && outside > 300,
            "{inside} inside, {outside} outside"
        );
        // Each touching case has exactly one one-ulp-off radius whose face misses.
        assert_eq!(ulp_empty, inside + outside, "{ulp_empty} empty one ulp off");
    }
}
