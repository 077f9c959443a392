//! A certified chain of boxes along a float contour polyline (CERTIFICATION.md
//! "verified" for a curve), the one-equation form of the surface ∩ surface chain
//! (`ops::surface_surface`'s `chain`).
//!
//! Each piece is a box `X = Z × T` of `[u, v]` with a fixed coordinate `j` on which
//! [`crate::certify::graph::prove_graph`] proves that over every `x_j ∈ T` the contour
//! `I = 0` has exactly one point in `Z` (and `∂I/∂x_{1−j} ≠ 0` on `X`): the contour in
//! `X` is one smooth arc entering and leaving through the faces `x_j = inf T`,
//! `x_j = sup T`. Consecutive pieces are joined when the enclosure of the arc's point on
//! the exit face of one lies in the interior of the next and the entry point of the next
//! in the interior of the previous (then the two arcs share a point). A closed chain
//! joins its last piece to its first; an open chain ends on a domain face (its end piece
//! has the bounded coordinate as fixed coordinate and its slab ends exactly on the
//! search bound). Then the whole connected component of the contour through the chain
//! lies in the union of its boxes. Periodic coordinates are compared shifted by whole
//! periods, the period enclosed.

use super::system::ContourFn;
use crate::certify::graph::{enclose_at, graph_krawczyk, prove_graph, Graph, GraphBox};
use crate::num::vector::norm_f64;
use crate::num::Interval;
use crate::surface::Surface;

/// One proven piece and the values of its fixed coordinate at entry and exit.
#[derive(Debug, Clone)]
pub struct Piece {
    pub graph: GraphBox<Interval>,
    pub entry: f64,
    pub exit: f64,
}

impl Piece {
    fn reversed(mut self) -> Piece {
        std::mem::swap(&mut self.entry, &mut self.exit);
        self
    }
    pub fn region(&self) -> [Interval; 2] {
        [self.graph.region[0], self.graph.region[1]]
    }
}

/// What the chain builder needs.
pub struct Chains<'c, 'a, S> {
    pub f: &'c ContourFn<'a, S>,
    /// The search box: the domain, rounded bounds moved outward by one ulp.
    pub search: [[f64; 2]; 2],
    pub periodic: [bool; 2],
    /// An enclosure of each periodic coordinate's period.
    pub period: [Interval; 2],
}

const OVERLAP: f64 = 1.0 / 32.0;
const MAX_DEPTH: usize = 12;

impl<S: Surface> Chains<'_, '_, S> {
    /// `a`, shifted by whole periods, lies in (the interior of, `interior`) `b`.
    pub fn shifted_inside(&self, a: &[Interval; 2], b: &[Interval; 2], interior: bool) -> bool {
        (0..2).all(|k| {
            let fits = |x: &Interval| {
                if interior {
                    x.is_interior_subset(&b[k])
                } else {
                    x.is_subset(&b[k])
                }
            };
            if !self.periodic[k] {
                return fits(&a[k]);
            }
            let p = self.period[k];
            let turns = ((b[k].midpoint() - a[k].midpoint()) / p.midpoint()).round();
            [turns - 1.0, turns, turns + 1.0]
                .iter()
                .any(|&m| fits(&(a[k] + p * Interval::point(m))))
        })
    }

    fn limit(&self) -> Vec<Interval> {
        (0..2)
            .map(|k| {
                if self.periodic[k] {
                    Interval::from_bounds(-f64::MAX, f64::MAX)
                } else {
                    Interval::from_bounds(self.search[k][0], self.search[k][1])
                }
            })
            .collect()
    }

    /// The fixed coordinate for `a → b`: the larger share of the tangent `(I_v, −I_u)`,
    /// weighted by the parameter's space speed, at both ends.
    fn choose_fixed(&self, a: &[f64; 2], b: &[f64; 2]) -> usize {
        let score = |x: &[f64; 2]| -> [f64; 2] {
            let (_, g) = self.f.with_gradient(&x[0], &x[1]);
            let j = self.f.surface.jet(&x[0], &x[1], 1);
            let s = [
                (g[1] * norm_f64(&j[1])).abs(),
                (g[0] * norm_f64(&j[2])).abs(),
            ];
            let top = s[0].max(s[1]);
            s.map(|x| if top > 0.0 { x / top } else { 0.0 })
        };
        let (sa, sb) = (score(a), score(b));
        usize::from(sa[1].min(sb[1]) > sa[0].min(sb[0]))
    }

    /// The contour point with `x_j = t` near the chord `a → b` (Newton in `x_{1−j}`).
    pub fn point_at(&self, a: &[f64; 2], b: &[f64; 2], j: usize, t: f64) -> Option<[f64; 2]> {
        let z = 1 - j;
        let span = (b[z] - a[z]).abs() + (b[j] - a[j]).abs();
        let lam = if b[j] != a[j] {
            (t - a[j]) / (b[j] - a[j])
        } else {
            0.5
        };
        let mut x = [0.0; 2];
        x[j] = t;
        x[z] = a[z] + lam * (b[z] - a[z]);
        for _ in 0..40 {
            let (v, g) = self.f.with_gradient(&x[0], &x[1]);
            if g[z] == 0.0 || !v.is_finite() {
                return None;
            }
            let step = v / g[z];
            x[z] -= step;
            if step.abs() <= 1e-15 * (1.0 + x[z].abs()) {
                let lo = a[z].min(b[z]) - span;
                let hi = a[z].max(b[z]) + span;
                return (x[z] >= lo && x[z] <= hi).then_some(x);
            }
        }
        None
    }

    fn segment(
        &self,
        a: &[f64; 2],
        b: &[f64; 2],
        forced: Option<usize>,
        depth: usize,
    ) -> Option<Vec<Piece>> {
        let j = forced.unwrap_or_else(|| self.choose_fixed(a, b));
        if let Some(p) = self.one_box(a, b, j, forced.is_some()) {
            return Some(vec![p]);
        }
        if depth >= MAX_DEPTH {
            return None;
        }
        let k = if a[j] != b[j] { j } else { 1 - j };
        let mid = self.point_at(a, b, k, 0.5 * (a[k] + b[k]))?;
        let mut first = self.segment(a, &mid, forced, depth + 1)?;
        first.extend(self.segment(&mid, b, None, depth + 1)?);
        Some(first)
    }

    /// One graph box over the segment `a → b` (as the surface ∩ surface chain: the slab
    /// of `x_j` widened by [`OVERLAP`], the other coordinate around the chord with a
    /// quarter of its change as margin), proven by epsilon-inflation.
    fn one_box(&self, a: &[f64; 2], b: &[f64; 2], j: usize, exact_start: bool) -> Option<Piece> {
        let (t0, t1) = (a[j], b[j]);
        if t0 == t1 {
            return None;
        }
        let o = OVERLAP * (t1 - t0).abs();
        let forward = t1 > t0;
        let entry = if exact_start {
            t0
        } else if forward {
            t0 - o
        } else {
            t0 + o
        };
        let exit = if forward { t1 + o } else { t1 - o };
        let slab = Interval::from_bounds(entry.min(exit), entry.max(exit));
        let limit = self.limit();
        if !slab.is_subset(&limit[j]) {
            return None;
        }
        let k = 1 - j;
        let scale = a.iter().chain(b).fold(1.0f64, |m, v| m.max(v.abs()));
        let (p, q) = (a[k].min(b[k]), a[k].max(b[k]));
        let m = 0.25 * (q - p) + 0.125 * (t1 - t0).abs() + 1e-13 * scale;
        let z = [Interval::from_bounds(p - m, q + m)];
        let graph = prove_graph(self.f, &slab, &z, j, &limit, 6)?;
        Some(Piece { graph, entry, exit })
    }

    /// The enclosure of the arc's point on the face `x_j = t` of a piece.
    pub fn face(&self, p: &Piece, t: f64) -> Option<[Interval; 2]> {
        let e = enclose_at(self.f, &p.graph, &Interval::point(t), 3)?;
        Some([e[0], e[1]])
    }

    fn joined(&self, p: &Piece, q: &Piece) -> bool {
        let (Some(out), Some(into)) = (self.face(p, p.exit), self.face(q, q.entry)) else {
            return false;
        };
        self.shifted_inside(&out, &q.region(), true)
            && self.shifted_inside(&into, &p.region(), true)
    }

    /// The chain through the polyline `xs` (consecutive points on the contour), closed
    /// when `faces` is `None`, else open with its ends on the domain faces
    /// `faces = [(k₀, bound₀), (k₁, bound₁)]` (coordinate, search bound). `Err` says why
    /// it is not proven.
    pub fn arc(
        &self,
        xs: &[[f64; 2]],
        faces: Option<[(usize, f64); 2]>,
    ) -> Result<Vec<Piece>, String> {
        let n = xs.len();
        if n < 2 {
            return Err("fewer than two points".into());
        }
        let mut xs = xs.to_vec();
        if let Some([(k0, b0), (k1, b1)]) = faces {
            xs[0][k0] = b0;
            xs[n - 1][k1] = b1;
        }
        let mut pieces: Vec<Piece> = Vec::new();
        for w in 0..n - 1 {
            let seg = match faces {
                Some([(k, _), _]) if w == 0 => self.segment(&xs[0], &xs[1], Some(k), 0),
                Some([_, (k, _)]) if w + 2 == n => {
                    // prove from the face backwards, so that the slab ends on the bound
                    self.segment(&xs[n - 1], &xs[n - 2], Some(k), 0)
                        .map(|s| s.into_iter().rev().map(Piece::reversed).collect())
                }
                _ => self.segment(&xs[w], &xs[w + 1], None, 0),
            };
            pieces.extend(seg.ok_or_else(|| format!("no proof between points {w} and {}", w + 1))?);
        }
        for (k, w) in pieces.windows(2).enumerate() {
            if !self.joined(&w[0], &w[1]) {
                return Err(format!("pieces {k} and {} are not proven to join", k + 1));
            }
        }
        let (first, last) = (&pieces[0], &pieces[pieces.len() - 1]);
        match faces {
            None if pieces.len() >= 2 && self.joined(last, first) => Ok(pieces),
            None => Err("the chain is not proven to close".into()),
            Some([(k0, b0), (k1, b1)]) => {
                let ok = first.graph.fixed == k0
                    && first.entry == b0
                    && last.graph.fixed == k1
                    && last.exit == b1;
                if ok {
                    Ok(pieces)
                } else {
                    Err("an end of the chain is not proven to lie on the domain boundary".into())
                }
            }
        }
    }

    /// A tight box of the contour point with the vertex's fixed coordinate, from the
    /// piece holding the vertex `x` (unwrapped like the pieces).
    ///
    /// The piece proves one contour point `z(t)` in its region over every `t` of its slab.
    /// A float Newton point `ẑ` at `t = x_j` is proven by epsilon-inflation
    /// ([`prove_graph`], clipped to the piece's region): `K(Z, t) ⊆ int Z` for a box
    /// `Z ∋ ẑ` inside the region proves one solution in `Z`, which is then `z(t)` — a
    /// box a few ulps wide. Only when that fails is the piece's own enclosure contracted
    /// (`E ← E ∩ K(E, t)`, each `K` holds the point), which from a wide start can stall
    /// far from the point (the loose torus bounds of issue 17).
    pub fn vertex_box(&self, pieces: &[Piece], x: &[f64; 2]) -> Option<[Interval; 2]> {
        let holding = || {
            pieces.iter().filter(|p| {
                let r = p.region();
                r[0].contains(x[0]) && r[1].contains(x[1])
            })
        };
        if let Some(b) = holding().find_map(|p| self.newton_box(p, x)) {
            return Some(b);
        }
        let p = holding().next()?;
        let j = p.graph.fixed;
        let t = Interval::point(x[j]);
        let mut b = [t; 2];
        let e = enclose_at(self.f, &p.graph, &t, 3)?;
        let mut z = e[1 - j];
        for _ in 0..40 {
            b[1 - j] = z;
            let k = match graph_krawczyk(self.f, &b, j) {
                Graph::Unique(k) | Graph::Image(k) => k[0],
                Graph::Inconclusive => break,
            };
            let next = z.intersection(&k);
            if next.is_empty() || next.width() >= z.width() {
                break;
            }
            z = next;
        }
        b[1 - j] = z;
        Some(b)
    }

    /// The box of [`Chains::vertex_box`] proven around a float Newton point in the piece
    /// `p` (its region clips the inflation, so the one solution found is the piece's).
    fn newton_box(&self, p: &Piece, x: &[f64; 2]) -> Option<[Interval; 2]> {
        let j = p.graph.fixed;
        let t = Interval::point(x[j]);
        let z = self.newton_at(x, j)?;
        let w = 4.0 * f64::EPSILON * z.abs().max(1.0);
        let start = [Interval::from_bounds(z - w, z + w)];
        let g = prove_graph(self.f, &t, &start, j, &p.graph.region, 12)?;
        let mut b = [t; 2];
        b[1 - j] = g.enclosure[1 - j];
        Some(b)
    }

    /// Float Newton in `x_{1−j}` for `I = 0` at `x_j` fixed, from `x` (no proof).
    fn newton_at(&self, x: &[f64; 2], j: usize) -> Option<f64> {
        let z = 1 - j;
        let mut y = *x;
        for _ in 0..20 {
            let (v, g) = self.f.with_gradient(&y[0], &y[1]);
            if g[z] == 0.0 || !v.is_finite() || !g[z].is_finite() {
                return None;
            }
            let step = v / g[z];
            y[z] -= step;
            if step.abs() <= 2.0 * f64::EPSILON * y[z].abs().max(1e-300) {
                break;
            }
        }
        y[z].is_finite().then_some(y[z])
    }
}
