//! NURBS patch of OPERATIONS.md §1.6 (1.18) (CASES `nurbs_surface`): degrees `p` (in
//! `u`) and `q` (in `v`), full knot vectors (`cols + p + 1` and `rows + q + 1` knots),
//! net row `i` ↔ `v`, position `j` ↔ `u`, optional positive weights. Domain
//! `[knots_u[p], knots_u[cols]] × [knots_v[q], knots_v[rows]]` (0-based).
//!
//! An interval box is evaluated in the centred form of `surface::taylor` (tight on small
//! boxes). A parameter interval that straddles knots is evaluated on every span it
//! touches and the results are joined ([`super::sets::hull`]), so the jet encloses the
//! surface over the whole box; a parameter exactly on a knot takes the right span, as
//! f64 does.

use super::basis::{bspline_jet, spans_touching, BasisJet};
use super::patch_hull::{meet_point, point_hull, SpanPair};
use super::sets::hull;
use super::taylor::{centre, is_point, taylor_tensor_jet};
use super::taylor_fast::{try_centred_jet, BasisSource};
use super::tensor::{tensor_jet, validate_net, Net};
use super::validate::{degree, knot_vector, restrict_domain, Domain};
use super::Surface;
use crate::error::GeomError;
use crate::num::Real;

/// A validated NURBS patch.
#[derive(Debug, Clone, PartialEq)]
pub struct NurbsSurface {
    pub(crate) degrees: [usize; 2],
    pub(crate) knots: [Vec<f64>; 2],
    pub(crate) net: Net,
    domain: Domain,
    /// [`Surface::pinned_at`]: the spans `[in u, in v]` whose formula
    /// [`Surface::jet`] evaluates everywhere.
    pin: Option<[usize; 2]>,
}

/// How wide a box must be against a knot span, in `u` or in `v`, for the hull of the
/// Bézier net to narrow its point (or else the centred form's point is unbounded). The
/// hull is what keeps a whole span's enclosure bounded (the centred form of the
/// weight can reach 0 there); on smaller boxes the centred form's excess, quadratic
/// in the width, is small, and the hull's 2(p+1)(q+1) blossoms cost several times the
/// rest of the evaluation: with it on every box wider than 1e-6, 60–77 % of the
/// certified NURBS benches' time went into it, and still 75 % with a share of 1/8
/// (BENCHMARKS.md, 2026-11-28). Sound either way: the hull only narrows.
const HULL_SHARE: f64 = 0.5;

impl NurbsSurface {
    /// A NURBS patch; errors name `degree_u`, `degree_v`, `knots_u`, `knots_v`
    /// (length, order, multiplicity, empty domain), `points` and `weights`.
    pub fn new(
        [degree_u, degree_v]: [usize; 2],
        knots_u: Vec<f64>,
        knots_v: Vec<f64>,
        points: &[Vec<[f64; 3]>],
        weights: Option<&[Vec<f64>]>,
    ) -> Result<NurbsSurface, GeomError> {
        let p = degree("degree_u", degree_u)?;
        let q = degree("degree_v", degree_v)?;
        let net = validate_net(points, weights, q + 1, p + 1)?;
        let du = knot_vector("knots_u", &knots_u, net.cols, p)?;
        let dv = knot_vector("knots_v", &knots_v, net.rows, q)?;
        net.check_spans()?;
        Ok(NurbsSurface {
            degrees: [p, q],
            knots: [knots_u, knots_v],
            net,
            domain: (du, dv),
            pin: None,
        })
    }

    /// The same patch on a sub-rectangle of its domain.
    pub fn with_domain(mut self, domain: Domain) -> Result<NurbsSurface, GeomError> {
        self.domain = restrict_domain(self.domain, Some(domain))?;
        Ok(self)
    }

    /// `[degree in u, degree in v]`.
    pub fn degrees(&self) -> [usize; 2] {
        self.degrees
    }
    /// `[knots_u, knots_v]`.
    pub fn knots(&self) -> &[Vec<f64>; 2] {
        &self.knots
    }
    /// The control points, row by row.
    pub fn points(&self) -> Vec<Vec<[f64; 3]>> {
        self.net.point_rows()
    }
    /// The weights, row by row, if rational.
    pub fn weights(&self) -> Option<Vec<Vec<f64>>> {
        self.net.weight_rows()
    }

    /// The jet by the direct sums `Σ N_j(u) N_i(v) w_ij P_ij` even over interval boxes:
    /// a valid enclosure, cheaper than [`Surface::jet`]'s centred form but looser by a
    /// roughly constant factor (it loses the cancellation `Σ N_j' = 0`), however small
    /// the box.
    pub fn direct_jet<T: Real>(&self, u: &T, v: &T, order: usize) -> Vec<[T; 3]> {
        self.evaluate(u, v, order, false)
    }

    fn evaluate<T: Real>(&self, u: &T, v: &T, order: usize, centred: bool) -> Vec<[T; 3]> {
        let ((cu, du, iu), (cv, dv, iv)) = if centred {
            (centre(u), centre(v))
        } else {
            (
                (u.clone(), u.zero_like(), true),
                (v.clone(), v.zero_like(), true),
            )
        };
        let [p, q] = self.degrees;
        let mut result: Option<Vec<[T; 3]>> = None;
        let (us, vs): (Vec<usize>, Vec<usize>) =
            (self.spans(0, u).collect(), self.spans(1, v).collect());
        for &sv in &vs {
            let mut jv = None;
            for &su in &us {
                let fast = if centred {
                    try_centred_jet(
                        &self.net,
                        self.source(0, su),
                        u,
                        self.source(1, sv),
                        v,
                        order,
                    )
                } else {
                    None
                };
                if let Some(jet) = fast {
                    // (fast: centred only)
                    let jet = self.narrow(jet, [u, v], [su, sv], [&us, &vs]);
                    result = Some(join(result, jet));
                    continue;
                }
                let jv =
                    jv.get_or_insert_with(|| self.basis(1, sv, v, centred.then_some(&cv), order));
                let ju = self.basis(0, su, u, centred.then_some(&cu), order);
                let jet = if centred {
                    taylor_tensor_jet(
                        &self.net,
                        &ju,
                        &du,
                        su - p,
                        jv,
                        &dv,
                        sv - q,
                        order,
                        iu && iv,
                    )
                } else {
                    tensor_jet(&self.net, &ju, su - p, jv, sv - q, order)
                };
                let jet = if centred {
                    self.narrow(jet, [u, v], [su, sv], [&us, &vs])
                } else {
                    jet // direct_jet: the plain sums, as documented
                };
                result = Some(join(result, jet));
            }
        }
        result.expect("at least one span")
    }

    /// The point of the jet of span pair `spans` narrowed by the hull of its Bézier net
    /// over the box ([`super::patch_hull`]), the box cut at the span's knots on the
    /// sides where a neighbouring span of `touched` takes over (the first and last span
    /// touched are continued over all of the box, as the basis evaluation is, so that
    /// parameters beyond the domain stay enclosed). Only boxes at least [`HULL_SHARE`]
    /// times as wide as the span in `u` or in `v` are narrowed (or whose point is
    /// unbounded).
    fn narrow<T: Real>(
        &self,
        jet: Vec<[T; 3]>,
        [u, v]: [&T; 2],
        spans: [usize; 2],
        touched: [&[usize]; 2],
    ) -> Vec<[T; 3]> {
        let clip = |d: usize, [a, b]: [f64; 2]| {
            let (s, k) = (spans[d], &self.knots[d]);
            let lo = if touched[d].first() == Some(&s) {
                a
            } else {
                a.max(k[s])
            };
            let hi = if touched[d].last() == Some(&s) {
                b
            } else {
                b.min(k[s + 1])
            };
            [lo, hi]
        };
        let (bu, bv) = (u.bounds(), v.bounds());
        // The whole box's width against the span's: a box straddling a knot counts as
        // wide on both sides when it is, however the knot cuts it.
        let share = |d: usize, [a, b]: [f64; 2]| {
            let (s, k) = (spans[d], &self.knots[d]);
            (b - a) / (k[s + 1] - k[s])
        };
        let unbounded = jet.first().is_some_and(|p| {
            p.iter().any(|x| {
                let (lo, hi) = x.bounds();
                !(lo.is_finite() && hi.is_finite())
            })
        });
        if share(0, [bu.0, bu.1]).max(share(1, [bv.0, bv.1])) < HULL_SHARE && !unbounded {
            return jet;
        }
        meet_point(jet, u, v, |bu, bv| {
            let pair = SpanPair {
                knots: [&self.knots[0], &self.knots[1]],
                degrees: self.degrees,
                spans,
            };
            point_hull(&self.net, &pair, clip(0, bu), clip(1, bv))
        })
    }

    /// The basis of span `s` in `direction`, for the fast centred form.
    fn source(&self, direction: usize, s: usize) -> BasisSource<'_> {
        BasisSource::BSpline {
            knots: &self.knots[direction],
            degree: self.degrees[direction],
            span: s,
        }
    }

    /// The number of control points in `direction`.
    fn count(&self, direction: usize) -> usize {
        if direction == 0 {
            self.net.cols
        } else {
            self.net.rows
        }
    }

    /// The basis jet on span `s` in `direction`: at `t` up to `order`, or, for a
    /// centred evaluation, at the centre `c` up to the degree.
    fn basis<T: Real>(
        &self,
        direction: usize,
        s: usize,
        t: &T,
        centre: Option<&T>,
        order: usize,
    ) -> BasisJet<T> {
        let p = self.degrees[direction];
        let knots = &self.knots[direction];
        match centre {
            Some(c) => bspline_jet(knots, p, s, c, p),
            None => bspline_jet(knots, p, s, t, order),
        }
    }

    /// The non-empty spans that `t` touches in `direction` (only the pinned one for a
    /// pinned patch: its polynomial continued over all of `t`).
    fn spans<T: Real>(&self, direction: usize, t: &T) -> impl Iterator<Item = usize> + '_ {
        let knots = &self.knots[direction];
        let (a, b) = match self.pin {
            Some(pin) => (pin[direction], pin[direction]),
            None => spans_touching(
                knots,
                self.degrees[direction],
                self.count(direction),
                t.bounds(),
            ),
        };
        (a..=b).filter(move |&s| a == b || knots[s] < knots[s + 1])
    }
}

/// The hull of the jets of the spans seen so far and `jet`.
fn join<T: Real>(acc: Option<Vec<[T; 3]>>, jet: Vec<[T; 3]>) -> Vec<[T; 3]> {
    match acc {
        None => jet,
        Some(acc) => acc
            .iter()
            .zip(&jet)
            .map(|(a, b)| std::array::from_fn(|c| hull(&a[c], &b[c])))
            .collect(),
    }
}

impl Surface for NurbsSurface {
    fn domain(&self) -> ([f64; 2], [f64; 2]) {
        self.domain
    }

    /// The distinct knots strictly inside the domain, per direction (none once pinned).
    fn piece_breaks(&self) -> [Vec<f64>; 2] {
        let (du, dv) = self.domain;
        let inner = |k: &[f64], [lo, hi]: [f64; 2]| {
            let mut b: Vec<f64> = k.iter().copied().filter(|&x| lo < x && x < hi).collect();
            b.dedup();
            b
        };
        match self.pin {
            Some(_) => [Vec::new(), Vec::new()],
            None => [inner(&self.knots[0], du), inner(&self.knots[1], dv)],
        }
    }
    /// The same patch with `pin` set to the spans holding `(u, v)` (right-continuous,
    /// as [`super::basis::find_span`]).
    fn pinned_at(&self, u: f64, v: f64) -> Option<Self> {
        let span = |d: usize, t: f64| {
            super::basis::find_span(&self.knots[d], self.degrees[d], self.count(d), t)
        };
        Some(NurbsSurface {
            pin: Some([span(0, u), span(1, v)]),
            ..self.clone()
        })
    }

    fn knot_span(&self, direction: usize, t: f64) -> Option<(f64, f64)> {
        let p = self.degrees[direction];
        let n = if direction == 0 {
            self.net.cols
        } else {
            self.net.rows
        };
        let knots = &self.knots[direction];
        let s = super::basis::find_span(knots, p, n, t);
        Some((knots[s], knots[s + 1]))
    }

    fn jet<T: Real>(&self, u: &T, v: &T, order: usize) -> Vec<[T; 3]> {
        // Interval boxes: the centred form (super::taylor); points: the direct sums.
        self.evaluate(u, v, order, !is_point(u) || !is_point(v))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::num::Interval;
    use crate::surface::taylor_fast::tests::{patch_points, KNOTS};

    /// An f64 interval box inside one span pair takes the fast centred form of
    /// `taylor_fast`, at scales from 1e−250 to 1e250.
    #[test]
    fn interval_boxes_take_the_fast_path() {
        for scale in [1e-250, 1e-12, 1e250] {
            let (points, weights) = patch_points(scale);
            let knots = KNOTS.to_vec();
            let s =
                NurbsSurface::new([3, 3], knots.clone(), knots, &points, Some(&weights)).unwrap();
            let (u, v) = (
                Interval::from_bounds(0.3, 0.3 + 1e-4),
                Interval::from_bounds(0.6, 0.6 + 1e-4),
            );
            let fast = try_centred_jet(&s.net, s.source(0, 3), &u, s.source(1, 3), &v, 2).unwrap();
            let jet = s.jet(&u, &v, 2);
            // The derivatives are the fast path's; the point is it narrowed by the hull
            // of the Bézier net on the box (patch_hull).
            assert_eq!(jet[1..], fast[1..], "scale {scale:e}");
            for c in 0..3 {
                assert!(jet[0][c].is_subset(&fast[0][c]), "scale {scale:e}");
            }
        }
    }
}
