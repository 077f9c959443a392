//! Point → ellipsoid and point → elliptic paraboloid projections through the foot
//! polynomial (OPERATIONS.md §3.4 with the implicit quadrics of §1.6; issue 14 items 4
//! and 9): every foot, poles and vertices included, with `complete: true` — where the
//! parametric search meets a continuum of `(u, v)` roots at a pole and stops undecided.
//!
//! In the local frame (axis-aligned with the world axes, so that local coordinates of
//! the double input are exact) write `F = Σ wᵢ ξᵢ² − 1` (ellipsoid, `wᵢ = 1/aᵢ²`) or
//! `F = w₁ξ² + w₂η² − ζ` (paraboloid). A foot `q` satisfies `p − q = λ ∇F(q)/2`:
//! `qᵢ = pᵢ/(1 + λwᵢ)` (and `ζ = p₃ + λ/2` on the paraboloid). Grouping coordinates of
//! equal `w` (`P_g = Σ_{i∈g} pᵢ²`) and keeping the groups with `P_g ≠ 0` (the set S),
//! `F(q) = 0` becomes the polynomial
//!
//! `Σ_{g∈S} w_g P_g Π_{h∈S∖g}(1 + λw_h)² − R(λ) Π_{h∈S}(1 + λw_h)² = 0`,
//!
//! `R = 1` (ellipsoid) or `R = p₃ + λ/2` (paraboloid); it has no root at `λ = −1/w_h`,
//! `h ∈ S` (the `w_h` are distinct), so every real root gives one foot. A group with
//! `P_g = 0` adds the branch `λ = −1/w_g`, where `w_g Σ_{i∈g} qᵢ² = R_g` (the rest
//! rational): no foot for `R_g < 0`, the main branch's foot for `R_g = 0` (then
//! degenerate: multiplicity reported 2), two feet `±√(R_g/w_g)` for one coordinate, and
//! for two or more a whole circle of feet — a continuum, left to the numeric path
//! (`None`). Roots are isolated exactly ([`crate::certify::univariate`]); coordinates
//! are enclosed from the isolating intervals by exact rational interval arithmetic,
//! then MPFR (square roots rounded outward). The paraboloid's `v` range bounds
//! `ζ = v²`, a closed interval of `λ` for the main branch.

use rug::Rational;
use std::cmp::Ordering;

use super::pairs::{angle, closed, param, surface_params};
use crate::certificate::{Arithmetic, Certified, Status};
use crate::certify::univariate::{real_roots, real_roots_in, Polynomial};
use crate::num::{Interval, MpfrInterval};
use crate::ops::answer::{Answer, Point};
use crate::ops::closed_surface::is_closed_shell;
use crate::ops::rational::exact::{exact_vec, RatInterval};
use crate::surface::{AnySurface, Surface};

const BITS: u32 = 256;

struct Setup {
    centre: [Rational; 3],
    axes: [[f64; 3]; 3],
    /// `wᵢ` of the quadratic coordinates (3: ellipsoid, 2: paraboloid).
    w: Vec<Rational>,
    p: [Rational; 3],
    /// Paraboloid: the closed range of `ζ`, and whether `v ≤ 0`.
    zeta: Option<([Rational; 2], bool)>,
    semi: [f64; 3],
}

fn q(x: f64) -> Rational {
    Rational::from_f64(x).unwrap_or_default()
}

/// Axes each a signed unit coordinate vector.
fn axis_aligned(axes: &[[f64; 3]; 3]) -> bool {
    axes.iter().all(|a| {
        a.iter().filter(|&&x| x != 0.0).count() == 1
            && a.iter().all(|&x| x == 0.0 || x.abs() == 1.0)
    })
}

fn setup(p: &[f64; 3], surface: &AnySurface) -> Option<Setup> {
    let (frame, semi, zeta) = match surface {
        AnySurface::Ellipsoid(e) if is_closed_shell(surface) => (e.frame(), e.semi_axes(), None),
        AnySurface::Paraboloid(s) if s.is_closed()[0] => {
            let [v0, v1] = s.domain().1;
            let sq = |x: f64| q(x) * q(x);
            let range = if v0 >= 0.0 {
                ([sq(v0), sq(v1)], false)
            } else if v1 <= 0.0 {
                ([sq(v1), sq(v0)], true)
            } else {
                return None;
            };
            let [a, b] = s.semi_axes();
            (s.frame(), [a, b, 1.0], Some(range))
        }
        _ => return None,
    };
    let axes = frame.axes(&0.0f64);
    if !axis_aligned(&axes) {
        return None;
    }
    let centre = exact_vec("center", &frame.origin()).ok()?;
    let pq = exact_vec("point", p).ok()?;
    let local = std::array::from_fn(|i| {
        (0..3)
            .map(|j| Rational::from(&pq[j] - &centre[j]) * q(axes[i][j]))
            .sum()
    });
    let n = if zeta.is_some() { 2 } else { 3 };
    let w = (0..n)
        .map(|i| Rational::from(1) / (q(semi[i]) * q(semi[i])))
        .collect();
    Some(Setup {
        centre,
        axes,
        w,
        p: local,
        zeta,
        semi,
    })
}

/// Coordinates grouped by equal `w`: `(w, members, P_g)`.
fn groups(s: &Setup) -> Vec<(Rational, Vec<usize>, Rational)> {
    let mut g: Vec<(Rational, Vec<usize>, Rational)> = Vec::new();
    for (i, wi) in s.w.iter().enumerate() {
        let p2 = Rational::from(&s.p[i] * &s.p[i]);
        match g.iter_mut().find(|x| &x.0 == wi) {
            Some(x) => {
                x.1.push(i);
                x.2 += p2;
            }
            None => g.push((wi.clone(), vec![i], p2)),
        }
    }
    g
}

/// `R(λ)`: 1, or `p₃ + λ/2` on the paraboloid.
fn r_poly(s: &Setup) -> Polynomial {
    match s.zeta {
        None => Polynomial::constant(Rational::from(1)),
        Some(_) => Polynomial::from_coeffs(vec![s.p[2].clone(), Rational::from((1, 2))]),
    }
}

/// A foot in local coordinates.
struct Foot {
    local: [MpfrInterval; 3],
    multiplicity: u32,
}

fn enclose(x: &RatInterval) -> MpfrInterval {
    MpfrInterval::from_rational(&x.lo, BITS).hull(&MpfrInterval::from_rational(&x.hi, BITS))
}

/// The main branch (module doc).
fn main_feet(s: &Setup, gs: &[(Rational, Vec<usize>, Rational)]) -> Vec<Foot> {
    let lin = |w: &Rational| Polynomial::from_coeffs(vec![Rational::from(1), w.clone()]);
    let live: Vec<_> = gs
        .iter()
        .filter(|g| g.2.cmp0() != Ordering::Equal)
        .collect();
    let square = |w: &Rational| &lin(w) * &lin(w);
    let product = |skip: Option<usize>| {
        live.iter()
            .enumerate()
            .filter(|(j, _)| Some(*j) != skip)
            .fold(Polynomial::constant(Rational::from(1)), |acc, (_, g)| {
                &acc * &square(&g.0)
            })
    };
    let mut poly = &Polynomial::zero() - &(&r_poly(s) * &product(None));
    for (j, g) in live.iter().enumerate() {
        poly = &poly + &product(Some(j)).scale(&Rational::from(&g.0 * &g.2));
    }
    let roots = match &s.zeta {
        None => real_roots(&poly).unwrap_or_default(),
        Some(([lo, hi], _)) => {
            let l = |z: &Rational| Rational::from(z - &s.p[2]) * 2u32;
            real_roots_in(&poly, &l(lo), &l(hi)).unwrap_or_default()
        }
    };
    let dead: Vec<Polynomial> = gs
        .iter()
        .filter(|g| g.2.cmp0() == Ordering::Equal)
        .map(|g| lin(&g.0))
        .collect();
    roots
        .into_iter()
        .map(|mut r| {
            r.refine_to_width(&(Rational::from(1) >> 200u32));
            let local = loop {
                if let Some(l) = main_coordinates(s, &RatInterval::from_root(&r)) {
                    break l;
                }
                // 1 + λwᵢ ≠ 0 at the root (module doc): narrower intervals exclude 0
                r.refine();
            };
            let degenerate = dead.iter().any(|d| r.is_root_of(d));
            Foot {
                local,
                multiplicity: if degenerate {
                    r.multiplicity().max(2)
                } else {
                    r.multiplicity()
                },
            }
        })
        .collect()
}

/// `qᵢ = pᵢ/(1 + λwᵢ)` (0 for `pᵢ = 0`) and the paraboloid's `ζ = p₃ + λ/2` over the
/// interval `lam`; `None` when a denominator's enclosure holds 0.
fn main_coordinates(s: &Setup, lam: &RatInterval) -> Option<[MpfrInterval; 3]> {
    let mut out: [MpfrInterval; 3] = std::array::from_fn(|_| MpfrInterval::point(0.0, BITS));
    for (i, slot) in out.iter_mut().enumerate().take(s.w.len()) {
        if s.p[i].cmp0() != Ordering::Equal {
            let den = lam
                .scale(&s.w[i])
                .add(&RatInterval::point(Rational::from(1)));
            *slot = enclose(&RatInterval::point(s.p[i].clone()).div(&den)?);
        }
    }
    if s.zeta.is_some() {
        let half = lam.scale(&Rational::from((1, 2)));
        out[2] = enclose(&half.add(&RatInterval::point(s.p[2].clone())));
    }
    Some(out)
}

/// The branches `λ = −1/w_g` of the groups with `P_g = 0`; `None`: a circle of feet.
fn branch_feet(s: &Setup, gs: &[(Rational, Vec<usize>, Rational)]) -> Option<Vec<Foot>> {
    let mut out = Vec::new();
    for g in gs.iter().filter(|g| g.2.cmp0() == Ordering::Equal) {
        let lam = -Rational::from(g.0.recip_ref());
        let mut local: Vec<Rational> = (0..3).map(|_| Rational::new()).collect();
        let mut rest = r_poly(s).eval(&lam);
        for i in (0..s.w.len()).filter(|i| !g.1.contains(i)) {
            local[i] = &s.p[i] / (Rational::from(&lam * &s.w[i]) + 1u32);
            rest -= Rational::from(&local[i] * &local[i]) * &s.w[i];
        }
        if let Some(([lo, hi], _)) = &s.zeta {
            local[2] = Rational::from(&lam / 2u32) + &s.p[2];
            if local[2] < *lo || local[2] > *hi {
                continue;
            }
        }
        if rest.cmp0() != Ordering::Greater {
            continue;
        }
        if g.1.len() > 1 {
            return None;
        }
        let root = MpfrInterval::from_rational(&(rest / &g.0), BITS).sqrt();
        for sign in [-1.0, 1.0] {
            let mut l: [MpfrInterval; 3] =
                std::array::from_fn(|i| MpfrInterval::from_rational(&local[i], BITS));
            l[g.1[0]] = root.mul(&MpfrInterval::point(sign, BITS));
            out.push(Foot {
                local: l,
                multiplicity: 1,
            });
        }
    }
    Some(out)
}

/// Every foot of the perpendicular from `p` onto a whole ellipsoid or a whole-turn
/// paraboloid with an axis-aligned frame; with `nearest` (ellipsoid only) the one
/// nearest foot when proven strictly nearest. `None`: not such a surface, a
/// continuum of feet, or an unresolved nearest tie.
pub(crate) fn project_point_quadric(
    p: [f64; 3],
    surface: &AnySurface,
    nearest: bool,
) -> Option<Certified<Answer>> {
    let s = setup(&p, surface)?;
    if nearest && s.zeta.is_some() {
        // the nearest point may lie on the paraboloid's rim
        return None;
    }
    let gs = groups(&s);
    let mut feet = main_feet(&s, &gs);
    feet.extend(branch_feet(&s, &gs)?);
    let mut points: Vec<(Point, MpfrInterval)> =
        feet.iter().map(|f| point(&s, surface, &p, f)).collect();
    if nearest {
        let best =
            (0..points.len()).min_by(|&i, &j| points[i].1.lo().total_cmp(points[j].1.lo()))?;
        let proven = (0..points.len()).all(|j| j == best || points[best].1.hi() < points[j].1.lo());
        if !proven {
            return None;
        }
        let mut keep = points.swap_remove(best);
        keep.0.nearest = Some(true);
        points = vec![keep];
    }
    Some(Certified {
        value: Answer::from_points(points.into_iter().map(|x| x.0).collect()),
        status: Status::Verified,
        complete: true,
        arithmetic: Arithmetic::Mpfr,
        bits: BITS,
        reason: None,
        perturbation: None,
    })
}

/// The reported point and its squared distance from `p`.
fn point(s: &Setup, surface: &AnySurface, p: &[f64; 3], f: &Foot) -> (Point, MpfrInterval) {
    let world: [MpfrInterval; 3] = std::array::from_fn(|j| {
        (0..3).fold(MpfrInterval::from_rational(&s.centre[j], BITS), |acc, i| {
            acc.add(&f.local[i].mul(&MpfrInterval::point(s.axes[i][j], BITS)))
        })
    });
    let d2 = (0..3).fold(MpfrInterval::point(0.0, BITS), |acc, j| {
        acc.add(&world[j].sub(&MpfrInterval::point(p[j], BITS)).sqr())
    });
    let b: [Interval; 3] = std::array::from_fn(|j| world[j].to_interval());
    let uv = match &s.zeta {
        None => closed(surface)
            .map(|c| surface_params(&c, &b))
            .unwrap_or_default(),
        Some((_, negative)) => paraboloid_params(s, f, *negative),
    };
    let distance = d2.sqrt().to_interval().midpoint();
    let pt = Point {
        xyz: b.iter().map(|x| x.midpoint()).collect(),
        xyz_box: b.iter().map(|x| [x.lo(), x.hi()]).collect(),
        params: vec![uv.iter().map(|x| x.0).collect()],
        param_box: Some(vec![uv.iter().map(|x| x.1).collect()]),
        multiplicity: f.multiplicity,
        distance: Some(distance),
        ..Default::default()
    };
    (pt, d2)
}

/// `u = atan2(η/b, ξ/a)` (turned by π for `v ≤ 0`; the whole circle at the vertex),
/// `v = ±√ζ`.
fn paraboloid_params(s: &Setup, f: &Foot, negative: bool) -> Vec<(f64, [f64; 2])> {
    let l: [Interval; 3] = std::array::from_fn(|i| f.local[i].to_interval());
    let sign = Interval::point(if negative { -1.0 } else { 1.0 });
    let x = l[0] / Interval::point(s.semi[0]) * sign;
    let y = l[1] / Interval::point(s.semi[1]) * sign;
    let u = if x.contains(0.0) && y.contains(0.0) {
        param(Interval::EMPTY)
    } else {
        param(angle(&y, &x))
    };
    let z = &l[2];
    let v = Interval::from_bounds(z.lo().max(0.0), z.hi().max(0.0)).sqrt() * sign;
    vec![u, (v.midpoint(), [v.lo(), v.hi()])]
}
