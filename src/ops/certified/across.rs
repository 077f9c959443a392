//! Roots on a knot, proven across it (issue 21; [`super::pieces`] module doc).
//!
//! A root left undecided where its box straddles a face between tiles (a knot of a
//! NURBS curve, a knot line of a patch) is proven by Krawczyk over the whole box with
//! the hull of the tiles' Jacobians ([`crate::certify::joined`]): the system must be
//! continuous there (the caller's obligation: it uses the objects' points only).
//!
//! **Stretching.** At a knot where the curve is only `G¹` (a NURBS circle's knot
//! between arcs of different weights) the speed jumps by a factor `λ`, and the hull of
//! the two Jacobians' columns, taken component by component, is too wide for Krawczyk
//! to contract. So the knot's coordinate is re-parametrised on the far side by a
//! linear map `x = b + ρ (s − b)` (`ρ ≈ 1/λ`, a double: any `ρ > 0` gives a
//! homeomorphism of the box, and the map is evaluated in the interval arithmetic of
//! the system, so the stretched system is still continuous and piecewise `C¹`, and
//! its parts' Jacobians are the true ones times `ρ` in that column). Its zeros are the
//! original zeros mapped by `s ↦ x`; the enclosure is mapped back outward.

use super::{shifted_inside, CertifiedRoot, Unknowns};
use crate::certificate::Status;
use crate::certify::{joined, System, UndecidedBox};
use crate::num::round::{next_down, next_up};
use crate::num::{Interval, Real};

/// A knot `b` in coordinate `i`, with the far side (`x_i ≥ b`) stretched by `rho`.
#[derive(Debug, Clone, Copy)]
struct Cut {
    i: usize,
    b: f64,
    rho: f64,
}

/// A tile's system seen through the stretch: on a tile beyond the cut (`far`),
/// `x_i = b + ρ (s_i − b)`; elsewhere `x = s`.
struct Stretched<'a, S> {
    sys: &'a S,
    cut: Option<Cut>,
}

impl<S: System> Stretched<'_, S> {
    fn to_x<T: Real>(&self, s: &[T]) -> Vec<T> {
        let mut x = s.to_vec();
        if let Some(c) = self.cut {
            let b = s[c.i].lift(c.b);
            x[c.i] = b.clone() + &((s[c.i].clone() - &b) * &s[c.i].lift(c.rho));
        }
        x
    }
}

impl<S: System> System for Stretched<'_, S> {
    fn dim(&self) -> usize {
        self.sys.dim()
    }
    fn eval<T: Real>(&self, s: &[T]) -> Vec<T> {
        self.sys.eval(&self.to_x(s))
    }
    /// The inner system's Jacobian at the mapped point, column `i` times `ρ` (the
    /// chain rule for a linear map; exact in the interval arithmetic of `T`).
    fn eval_with_jacobian<T: Real>(&self, s: &[T]) -> (Vec<T>, Vec<Vec<T>>) {
        let (f, mut j) = self.sys.eval_with_jacobian(&self.to_x(s));
        if let Some(c) = self.cut {
            for row in &mut j {
                if let Some(v) = row.get_mut(c.i) {
                    *v = v.clone() * &s[c.i].lift(c.rho);
                }
            }
        }
        (f, j)
    }
}

/// Roots left undecided where they straddle a face between `tiles`, proven across it
/// (module doc). Every other root whose box lies inside the proven region is that root
/// and is dropped; if another box meets the region without lying inside it, the root
/// is left as it was (the two might be one root reported twice).
pub fn across<S: System>(
    tiles: &[(S, Unknowns)],
    whole: &Unknowns,
    roots: &mut Vec<CertifiedRoot>,
) {
    let mut i = 0;
    while i < roots.len() {
        if roots[i].status != Status::Undecided {
            i += 1;
            continue;
        }
        let Some((region, e)) = prove(tiles, whole, &roots[i].enclosure) else {
            i += 1;
            continue;
        };
        let old = roots[i].clone();
        if install(roots, Some(i), &region, e, &old.params, old.bits, whole) {
            i = 0; // the list changed: look again from the start
        } else {
            i += 1;
        }
    }
}

/// Boxes the search left undecided (a cluster on a knot line that no smooth Krawczyk
/// test could prove, at every precision), decided across the knot where they meet
/// one: a box that touches a face between tiles from one side (a knot span's own
/// search ends there) is mirrored across it first. A box is decided when a root is
/// proven unique in a region that holds it: every root of the box is that root, which
/// is added to `roots` (once: boxes and roots inside the region are its copies).
/// Returns the boxes still undecided.
pub fn decide_boxes<S: System>(
    tiles: &[(S, Unknowns)],
    whole: &Unknowns,
    roots: &mut Vec<CertifiedRoot>,
    undecided: Vec<UndecidedBox>,
) -> Vec<UndecidedBox> {
    let mut regions: Vec<Vec<Interval>> = Vec::new();
    let mut left = Vec::new();
    for b in undecided {
        let x = &b.enclosure;
        if regions.iter().any(|r| shifted_inside(x, r, whole)) {
            continue; // decided with an earlier box
        }
        let decided = across_face(tiles, x).and_then(|start| {
            let (region, e) = prove(tiles, whole, &start)?;
            let mid: Vec<f64> = e.iter().map(Interval::midpoint).collect();
            (shifted_inside(x, &region, whole) && install(roots, None, &region, e, &mid, 53, whole))
                .then_some(region)
        });
        match decided {
            Some(region) => regions.push(region),
            None => left.push(b),
        }
    }
    left
}

/// `x`, mirrored across a face between tiles that it touches from one side (its
/// lower or upper bound is the face), so that the face lies inside it; `x` itself
/// when a face already does; `None` when it meets no face.
fn across_face<S>(tiles: &[(S, Unknowns)], x: &[Interval]) -> Option<Vec<Interval>> {
    for i in 0..x.len() {
        let faces = tiles
            .iter()
            .filter(|(_, u)| !u.periodic[i])
            .flat_map(|(_, u)| u.domain[i])
            .filter(|b| {
                tiles
                    .iter()
                    .any(|(_, u)| !u.periodic[i] && u.domain[i][1] == *b)
            })
            .filter(|b| {
                tiles
                    .iter()
                    .any(|(_, u)| !u.periodic[i] && u.domain[i][0] == *b)
            });
        for b in faces {
            let (lo, hi) = (x[i].lo(), x[i].hi());
            let side = if lo < b && b < hi {
                x[i]
            } else if hi == b {
                Interval::from_bounds(lo, b) + Interval::from_bounds(0.0, b - lo)
            } else if lo == b {
                Interval::from_bounds(b, hi) - Interval::from_bounds(0.0, hi - b)
            } else {
                continue;
            };
            let mut y = x.to_vec();
            y[i] = side;
            return Some(y);
        }
    }
    None
}

/// The root proven unique in `region` (enclosure `e`; estimate `params` where `e`
/// holds them, else its midpoint) added to `roots` in place of every root whose box
/// lies in `region` (their copies; `replacing` is the undecided root it was proven
/// from). `false`, and nothing changed, when another root's box meets `region`
/// without lying in it (the two might be one root reported twice).
fn install(
    roots: &mut Vec<CertifiedRoot>,
    replacing: Option<usize>,
    region: &[Interval],
    e: Vec<Interval>,
    params: &[f64],
    bits: u32,
    whole: &Unknowns,
) -> bool {
    let clash = roots.iter().enumerate().any(|(k, r)| {
        Some(k) != replacing
            && meets_shifted(&r.enclosure, region, whole)
            && !shifted_inside(&r.enclosure, region, whole)
    });
    if clash {
        return false;
    }
    let params = params
        .iter()
        .zip(&e)
        .map(|(&p, b)| if b.contains(p) { p } else { b.midpoint() })
        .collect();
    let root = CertifiedRoot {
        params,
        enclosure: e,
        status: Status::Verified,
        max_roots: 1,
        bits: bits.max(53),
        perturbation: None,
        reason: None,
    };
    roots.retain(|r| !shifted_inside(&r.enclosure, region, whole));
    roots.push(root);
    true
}

/// One root proven in a region around `start`: `(region, enclosure)` in the original
/// coordinates, or `None`.
fn prove<S: System>(
    tiles: &[(S, Unknowns)],
    whole: &Unknowns,
    start: &[Interval],
) -> Option<(Vec<Interval>, Vec<Interval>)> {
    if !covered(tiles, whole, start) {
        return None;
    }
    let cut = stretch(tiles, start);
    let parts_of = |s: &[Interval]| -> Vec<(Stretched<S>, Vec<Interval>)> {
        let x = to_x(cut, s);
        if !covered(tiles, whole, &x) {
            return Vec::new(); // the tiles do not cover the box: no theorem applies
        }
        let meets = |u: &Unknowns| {
            x.iter().enumerate().all(|(i, xi)| {
                u.periodic[i] || (xi.lo() <= u.domain[i][1] && u.domain[i][0] <= xi.hi())
            })
        };
        if let Some(c) = cut {
            // Only the two tiles on either side of the knot may be met in its
            // coordinate: the stretched ranges of tiles further on are not computed.
            let beyond = tiles.iter().any(|(_, u)| {
                !u.periodic[c.i] && meets(u) && u.domain[c.i][0] != c.b && u.domain[c.i][1] != c.b
            });
            if beyond {
                return Vec::new();
            }
        }
        tiles
            .iter()
            .filter(|(_, u)| {
                // Tiles further on in the cut's coordinate do not meet the box (checked
                // above); their stretched ranges are not computed, so they are left out
                // (taken with the far tile's range they would add a wrong part).
                cut.is_none_or(|c| {
                    u.periodic[c.i] || u.domain[c.i][0] == c.b || u.domain[c.i][1] == c.b
                })
            })
            .filter_map(|(sys, u)| {
                let far = cut.filter(|c| !u.periodic[c.i] && u.domain[c.i][0] >= c.b);
                let part: Option<Vec<Interval>> = s
                    .iter()
                    .enumerate()
                    .map(|(i, si)| {
                        let p = if u.periodic[i] {
                            *si
                        } else {
                            let [lo, hi] = u.domain[i];
                            let range = match cut {
                                // the far tile's range in s: [b, b + (hi − b)/ρ] (its
                                // upper end is never reached: x stays below hi)
                                Some(c) if c.i == i && far.is_some() => Interval::from_bounds(
                                    c.b,
                                    to_s_far(c, Interval::point(hi)).hi(),
                                ),
                                _ => Interval::from_bounds(lo, hi),
                            };
                            si.intersection(&range)
                        };
                        (!p.is_empty()).then_some(p)
                    })
                    .collect();
                part.map(|p| (Stretched { sys, cut: far }, p))
            })
            .collect()
    };
    let s0 = to_s(cut, start);
    let (region, e) = joined::verify_in_parts(&parts_of, &s0, 6)?;
    Some((to_x(cut, &region), to_x(cut, &e)))
}

/// The cut to stretch at: the one knot (a tile face) strictly inside `start` in a
/// coordinate the tiles restrict, with `ρ` the ratio of the near and far tiles'
/// Jacobian columns there (f64; `None` without exactly one such knot, or when the
/// ratio is not a positive finite number).
fn stretch<S: System>(tiles: &[(S, Unknowns)], start: &[Interval]) -> Option<Cut> {
    let mid: Vec<f64> = start.iter().map(Interval::midpoint).collect();
    let mut found = None;
    for i in 0..start.len() {
        let mut faces: Vec<f64> = tiles
            .iter()
            .filter(|(_, u)| !u.periodic[i])
            .map(|(_, u)| u.domain[i][0])
            .filter(|&b| start[i].lo() < b && b < start[i].hi())
            .collect();
        faces.sort_by(f64::total_cmp);
        faces.dedup();
        if faces.len() != 1 || found.is_some() {
            if !faces.is_empty() {
                return None; // two knots in the box, or cuts in two coordinates
            }
            continue;
        }
        let b = faces[0];
        let mut at = mid.clone();
        at[i] = b;
        let column = |side: &dyn Fn(&Unknowns) -> bool| -> Option<f64> {
            let (sys, _) = tiles.iter().find(|(_, u)| {
                side(u)
                    && u.domain
                        .iter()
                        .zip(&at)
                        .enumerate()
                        .all(|(k, ([lo, hi], x))| u.periodic[k] || (lo <= x && x <= hi))
            })?;
            let j = sys.jacobian::<f64>(&at);
            Some(j.iter().map(|r| r[i] * r[i]).sum::<f64>().sqrt())
        };
        let near = column(&|u: &Unknowns| u.domain[i][1] <= b)?;
        let far = column(&|u: &Unknowns| u.domain[i][0] >= b)?;
        let rho = near / far;
        if !(rho.is_finite() && rho > 0.0) {
            return None;
        }
        found = Some(Cut { i, b, rho });
    }
    found
}

/// `s` mapped to `x` (outward): the near side as it is, the far side
/// `b + ρ (s − b)`, hulled.
fn to_x(cut: Option<Cut>, s: &[Interval]) -> Vec<Interval> {
    let mut x = s.to_vec();
    if let Some(c) = cut {
        let near = s[c.i].intersection(&Interval::from_bounds(f64::NEG_INFINITY, c.b));
        let far = s[c.i].intersection(&Interval::from_bounds(c.b, f64::INFINITY));
        let b = Interval::point(c.b);
        let far = if far.is_empty() {
            far
        } else {
            b + (far - b) * Interval::point(c.rho)
        };
        x[c.i] = near.hull(&far);
    }
    x
}

/// `x` mapped to `s` (outward): the inverse of [`to_x`].
fn to_s(cut: Option<Cut>, x: &[Interval]) -> Vec<Interval> {
    let mut s = x.to_vec();
    if let Some(c) = cut {
        let near = x[c.i].intersection(&Interval::from_bounds(f64::NEG_INFINITY, c.b));
        let far = x[c.i].intersection(&Interval::from_bounds(c.b, f64::INFINITY));
        let far = if far.is_empty() {
            far
        } else {
            to_s_far(c, far)
        };
        s[c.i] = near.hull(&far);
    }
    s
}

/// A far-side `x` interval in `s`: `b + (x − b)/ρ`, outward.
fn to_s_far(c: Cut, x: Interval) -> Interval {
    let b = Interval::point(c.b);
    b + (x - b) / Interval::point(c.rho)
}

/// The tiles cover `x`, and `x` lies in the domain: in every coordinate that is not
/// periodic, or that some tile restricts (a pinned piece: the tiles tile one period),
/// `x` lies in `whole`'s range (one ulp inside a rounded bound, whose exact value is
/// within one ulp of the double). A root proven in such an `x` is an answer.
fn covered<S>(tiles: &[(S, Unknowns)], whole: &Unknowns, x: &[Interval]) -> bool {
    x.iter().enumerate().all(|(i, xi)| {
        let cut = tiles.iter().any(|(_, u)| !u.periodic[i]);
        let [lo, hi] = whole.domain[i];
        let [lo, hi] = if whole.rounded[i] {
            [next_up(lo), next_down(hi)]
        } else {
            [lo, hi]
        };
        (whole.periodic[i] && !cut) || (lo <= xi.lo() && xi.hi() <= hi)
    })
}

/// `a`, shifted by a whole number of periods in its periodic coordinates (by 0, +P or
/// −P, P an enclosure of the period), meets `b` (a root on a seam found in two pieces
/// at both ends of the period).
pub fn meets_shifted(a: &[Interval], b: &[Interval], whole: &Unknowns) -> bool {
    shifted_to_meet(a, b, whole).is_some()
}

/// `a` shifted as in [`meets_shifted`] so that it meets `b` (an enclosure of the
/// shifted box), or `None`: the hull of the two is then the tight box across a seam,
/// not the whole period.
pub fn shifted_to_meet(a: &[Interval], b: &[Interval], whole: &Unknowns) -> Option<Vec<Interval>> {
    (0..a.len())
        .map(|i| {
            let shifts = if whole.periodic[i] {
                let p = whole.period(i);
                vec![Interval::point(0.0), p, -p]
            } else {
                vec![Interval::point(0.0)]
            };
            shifts
                .into_iter()
                .map(|s| a[i] + s)
                .find(|s| !s.intersection(&b[i]).is_empty())
        })
        .collect()
}

#[cfg(test)]
mod tests {
    //! [`decide_boxes`] on its own: one-dimensional tiles `[0, 1]`, `[1, 2]` whose
    //! systems agree at the knot `x = 1` (continuous, with a kink: the slope jumps).
    use super::*;

    /// `f(x) = slope·(x − 1)² ·square + slope·(x − 1) + shift` on one tile.
    struct Piece {
        slope: f64,
        square: f64,
        shift: f64,
    }

    impl System for Piece {
        fn dim(&self) -> usize {
            1
        }
        fn eval<T: Real>(&self, x: &[T]) -> Vec<T> {
            let d = x[0].clone() - &x[0].lift(1.0);
            let s = x[0].lift(self.slope);
            let quad = d.sqr() * &x[0].lift(self.square);
            vec![(quad + &d) * &s + &x[0].lift(self.shift)]
        }
    }

    fn unknowns(lo: f64, hi: f64) -> Unknowns {
        Unknowns {
            domain: vec![[lo, hi]],
            periodic: vec![false],
            rounded: vec![false],
        }
    }

    fn tiles(square: f64, shift: f64) -> Vec<(Piece, Unknowns)> {
        vec![
            (
                Piece {
                    slope: 1.0,
                    square,
                    shift,
                },
                unknowns(0.0, 1.0),
            ),
            (
                Piece {
                    slope: 2.0,
                    square,
                    shift,
                },
                unknowns(1.0, 2.0),
            ),
        ]
    }

    fn undecided(lo: f64, hi: f64) -> UndecidedBox {
        UndecidedBox {
            enclosure: vec![Interval::from_bounds(lo, hi)],
            reason: "test".into(),
        }
    }

    /// A box touching the knot from either side, or straddling it, over the simple
    /// root at the knot: decided, one verified root holding `x = 1`, nothing left;
    /// the same box twice gives the root once.
    #[test]
    fn a_box_at_the_knot_is_proven_across_it() {
        for (lo, hi) in [(0.9, 1.0), (1.0, 1.05), (0.999, 1.001), (0.5, 1.0)] {
            let mut roots = Vec::new();
            let left = decide_boxes(
                &tiles(0.0, 0.0),
                &unknowns(0.0, 2.0),
                &mut roots,
                vec![undecided(lo, hi), undecided(lo, hi)],
            );
            assert!(left.is_empty(), "[{lo}, {hi}]: {left:?}");
            assert_eq!(roots.len(), 1, "[{lo}, {hi}]");
            assert_eq!(roots[0].status, Status::Verified);
            assert!(roots[0].enclosure[0].contains(1.0));
        }
    }

    /// Nothing wrong is decided: every root added holds exactly one true root, and a box
    /// taken off the undecided list has each of its true roots in an added root. Cases:
    /// a box away from every knot (stays, adds nothing); a box at the knot with no root
    /// (the root 0.75 lies outside: it stays, or the proof reaches 0.75 and proves it
    /// unique in a region holding the box); two roots `0.98995…` and `1.00702…` on
    /// either side of the knot (no unique root to prove across it).
    #[test]
    fn what_is_decided_is_right() {
        let two = |slope: f64| {
            // 10⁴d² + d − 1/slope = 0, the root on the tile's side of the knot
            let disc = (1.0 + 4e4 / slope).sqrt();
            if slope == 1.0 {
                1.0 + (-1.0 - disc) / 2e4
            } else {
                1.0 + (-1.0 + disc) / 2e4
            }
        };
        for (square, shift, lo, hi, truths, stays) in [
            (0.0, 0.0, 0.3, 0.4, vec![1.0], true),
            (0.0, 0.25, 0.9, 1.0, vec![0.75], false),
            (1e4, -1.0, 0.985, 1.0, vec![two(1.0), two(2.0)], true),
        ] {
            let mut roots = Vec::new();
            let left = decide_boxes(
                &tiles(square, shift),
                &unknowns(0.0, 2.0),
                &mut roots,
                vec![undecided(lo, hi)],
            );
            let holds = |e: &Interval, t: f64| e.lo() - 1e-12 <= t && t <= e.hi() + 1e-12;
            for r in &roots {
                let k = truths
                    .iter()
                    .filter(|&&t| holds(&r.enclosure[0], t))
                    .count();
                assert_eq!(k, 1, "[{lo}, {hi}]: {r:?}");
            }
            if left.is_empty() {
                for &t in truths.iter().filter(|&&t| lo <= t && t <= hi) {
                    assert!(
                        roots.iter().any(|r| holds(&r.enclosure[0], t)),
                        "[{lo}, {hi}]: {t}"
                    );
                }
            }
            if stays {
                assert_eq!(left.len(), 1, "[{lo}, {hi}]");
                assert!(roots.is_empty(), "[{lo}, {hi}]: {roots:?}");
            }
        }
    }
}
