//! A certified chain of boxes along a traced curve (CERTIFICATION.md "verified" for a
//! curve).
//!
//! Each piece is a box `X = Z × T` of `[u, v, a, b]` with a fixed parameter `j` (§9.3
//! (9.5)) on which [`crate::certify::graph`] proves that over every value of `x_j ∈ T`
//! the other three parameters have exactly one solution of (9.1) in `Z`: the curve in
//! `X` is a single smooth arc entering and leaving through the faces `x_j = inf T` and
//! `x_j = sup T`. Consecutive pieces are joined: the enclosure of the arc's point on the
//! exit face of a piece lies in the interior of the next piece, and the entry point of
//! the next in the interior of the previous — so the two arcs share a point (the arc of a
//! box is all of the curve in it) and the curve leaves neither through a face except into
//! its neighbour. A closed chain joins its last piece to the first; an open chain's end
//! face is either a face of the domain (the fixed parameter is the bounded one and the
//! slab ends exactly on the bound) or lies in the interior of a singular point's box.
//! Then the connected component of the intersection containing the chain lies in the
//! union of its boxes and of those singular boxes.
//!
//! A closed chain may reach past a domain face in a parameter whose surface continues
//! beyond it by the same formula ([`super::SurfaceOperand::extends`], a cylinder's
//! height): its boxes then prove the loop of the continued surfaces, and the caller
//! must show that the loop does not leave the domain ([`ChainContext::reaching`]; a
//! loop touching a face, as at a cylinder's height end, is proven this way).
//!
//! Boxes may reach beyond the domain of a periodic parameter (the surfaces' formulas are
//! periodic in their angles); joins compare boxes shifted by whole periods, with the
//! period enclosed.

use super::corrector::fixed_parameter_newton;
use super::equations::{PairJet, PairSystem};
use super::operand::Pair;
use crate::certify::graph::{enclose_at, prove_graph, GraphBox};
use crate::num::round::{next_down, next_up};
use crate::num::vector::norm_f64;
use crate::num::Interval;
use crate::surface::Surface;

/// One proven piece: the graph box and the values of its fixed parameter at the entry and
/// exit faces (in the direction of travel).
#[derive(Debug, Clone)]
pub struct Piece {
    pub graph: GraphBox<Interval>,
    pub entry: f64,
    pub exit: f64,
}

impl Piece {
    fn fixed(&self) -> usize {
        self.graph.fixed
    }

    /// The same piece travelled the other way.
    fn reversed(mut self) -> Piece {
        std::mem::swap(&mut self.entry, &mut self.exit);
        self
    }
}

/// How an end of an arc is anchored.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Anchor {
    /// On the domain face `x_k = bound` (the bound of the search box).
    Face(usize, f64),
    /// In the interior of this singular box.
    Singular(usize),
}

/// What the chain builder needs: the pair, the system (9.1), the search box (the box
/// the certified domain is) and the periods.
pub struct ChainContext<'p, 'a, R, S> {
    pub pair: &'p Pair<'a, R, S>,
    pub sys: PairSystem<'a, R, S>,
    /// The search box: the domain, rounded bounds moved outward by one ulp.
    pub search: [[f64; 2]; 4],
    /// The singular boxes, in the tracer's numbering.
    pub singular: Vec<[Interval; 4]>,
    /// Boxes may reach past the domain faces of extendable parameters (set while a
    /// closed chain is proven, module doc).
    extended: std::cell::Cell<bool>,
}

/// How far a box's slab reaches beyond the segment's ends, relative to the segment.
const OVERLAP: f64 = 1.0 / 32.0;
/// The deepest splitting of one segment.
const MAX_DEPTH: usize = 14;
/// At most this many times an arc's points are doubled when boxes do not join.
const MAX_DENSIFY: usize = 2;
/// At most this many pieces approach a singular box.
const MAX_APPROACH: usize = 80;

impl<'p, 'a, R: Surface, S: Surface> ChainContext<'p, 'a, R, S> {
    pub fn new(pair: &'p Pair<'a, R, S>, singular: Vec<[Interval; 4]>) -> Self {
        let search = std::array::from_fn(|k| {
            let c = &pair.coords[k];
            if pair.rounded[k] && !c.periodic {
                [next_down(c.lo), next_up(c.hi)]
            } else {
                [c.lo, c.hi]
            }
        });
        ChainContext {
            pair,
            sys: PairSystem {
                r: pair.r,
                s: pair.s,
            },
            search,
            singular,
            extended: std::cell::Cell::new(false),
        }
    }

    /// The piece's box is not inside the search box (it reaches past a domain face).
    pub fn reaching(&self, p: &Piece) -> bool {
        (0..4).any(|k| {
            let [lo, hi] = self.search[k];
            let r = &p.graph.region[k];
            let inside = self.pair.coords[k].periodic || (lo <= r.lo() && r.hi() <= hi);
            !inside
        })
    }

    /// An enclosure of the period of coordinate `k` (its bounds may be roundings of the
    /// exact ends: then by an ulp either way).
    pub fn period(&self, k: usize) -> Interval {
        let c = &self.pair.coords[k];
        let exact = Interval::point(c.hi) - Interval::point(c.lo);
        if self.pair.rounded[k] {
            let a = Interval::point(next_down(c.hi)) - Interval::point(next_up(c.lo));
            let b = Interval::point(next_up(c.hi)) - Interval::point(next_down(c.lo));
            exact.hull(&a).hull(&b)
        } else {
            exact
        }
    }

    /// `a`, shifted by whole periods in its periodic coordinates, lies in the interior
    /// (`interior`) or in `b`.
    pub fn shifted_inside(&self, a: &[Interval; 4], b: &[Interval; 4], interior: bool) -> bool {
        (0..4).all(|k| {
            let fits = |x: &Interval| {
                if interior {
                    x.is_interior_subset(&b[k])
                } else {
                    x.is_subset(&b[k])
                }
            };
            if !self.pair.coords[k].periodic {
                return fits(&a[k]);
            }
            let p = self.period(k);
            let turns = ((b[k].midpoint() - a[k].midpoint()) / p.midpoint()).round();
            [turns - 1.0, turns, turns + 1.0]
                .iter()
                .any(|&m| fits(&(a[k] + p * Interval::point(m))))
        })
    }

    /// `a` shifted by whole periods in its periodic coordinates to lie nearest to `b`.
    pub fn shift_near(&self, a: &[Interval; 4], b: &[Interval; 4]) -> [Interval; 4] {
        std::array::from_fn(|k| {
            if !self.pair.coords[k].periodic {
                return a[k];
            }
            let p = self.period(k);
            let m = ((b[k].midpoint() - a[k].midpoint()) / p.midpoint()).round();
            if m == 0.0 {
                a[k]
            } else {
                a[k] + p * Interval::point(m)
            }
        })
    }

    /// The limit boxes may not leave: the search box in bounded coordinates (widened by
    /// a quarter of the range on each side in extendable ones while a closed chain is
    /// proven, module doc).
    fn limit(&self) -> Vec<Interval> {
        (0..4)
            .map(|k| {
                let [lo, hi] = self.search[k];
                if self.pair.coords[k].periodic {
                    Interval::from_bounds(-f64::MAX, f64::MAX)
                } else if self.extended.get() && self.pair.extends[k] {
                    let m = 0.25 * (hi - lo);
                    Interval::from_bounds(lo - m, hi + m)
                } else {
                    Interval::from_bounds(lo, hi)
                }
            })
            .collect()
    }

    /// The fixed parameter for the segment `a → b`: the one whose share of the curve's
    /// parameter velocity, weighted by the parameter's space speed, is largest at both
    /// ends (§9.3 (9.5) in parameter form).
    fn choose_fixed(&self, a: &[f64; 4], b: &[f64; 4]) -> usize {
        let score = |x: &[f64; 4]| -> [f64; 4] {
            let j = PairJet::at(self.pair.r, self.pair.s, x, 1);
            let v = j.param_tangent();
            let speed = [
                norm_f64(&j.r[1]),
                norm_f64(&j.r[2]),
                norm_f64(&j.s[1]),
                norm_f64(&j.s[2]),
            ];
            let s: [f64; 4] = std::array::from_fn(|k| (v[k] * speed[k]).abs());
            let top = s.iter().copied().fold(0.0, f64::max);
            s.map(|x| if top > 0.0 { x / top } else { 0.0 })
        };
        let (sa, sb) = (score(a), score(b));
        (0..4)
            .max_by(|&i, &k| sa[i].min(sb[i]).total_cmp(&sa[k].min(sb[k])))
            .unwrap_or(0)
    }

    /// Prove the segment `a → b` of the curve (both on it), splitting it at curve points
    /// where one box does not prove. `forced`: the fixed parameter to use (a domain face
    /// at `a`: the slab then starts exactly at `a`'s value, which is the bound).
    fn segment(
        &self,
        a: &[f64; 4],
        b: &[f64; 4],
        forced: Option<usize>,
        depth: usize,
    ) -> Option<Vec<Piece>> {
        // The case's deadline ends the subdivision: the chain is then not proven (a
        // sphere against a cylinder of nearly its radius split its near-tangent loop
        // for two minutes under a 0.25 s `time_limit`: fuzz pass, issue 20).
        if self.pair.options.certify.late() {
            return None;
        }
        let j = forced.unwrap_or_else(|| self.choose_fixed(a, b));
        if let Some(p) = self.one_box(a, b, j, forced.is_some()) {
            return Some(vec![p]);
        }
        if depth >= MAX_DEPTH {
            return None;
        }
        let mid = self.curve_point_between(a, b, j)?;
        let mut first = self.segment(a, &mid, forced, depth + 1)?;
        let second = self.segment(&mid, b, None, depth + 1)?;
        let second = match first.last() {
            Some(p) => self.rejoined(p, second, &mid, b, depth + 1),
            None => second,
        };
        first.extend(second);
        Some(first)
    }

    /// The pieces `next` of the segment `a → b` that follows the piece `prev`, or, when
    /// they are not proven to join, the segment proven again over `prev`'s fixed
    /// parameter with its slab starting exactly at `a` (the shared curve point): then
    /// `a`'s value lies inside `prev`'s slab (which overlaps beyond it) and `prev`'s exit
    /// face inside the new slab, so the join fails no more because the two slabs run
    /// over different parameters or are of very different lengths (the cause of loops
    /// left undecided by "pieces k and k+1 are not proven to join"). The join itself is
    /// still checked by the caller; this only chooses the boxes.
    fn rejoined(
        &self,
        prev: &Piece,
        next: Vec<Piece>,
        a: &[f64; 4],
        b: &[f64; 4],
        depth: usize,
    ) -> Vec<Piece> {
        if next.first().is_none_or(|q| self.joined(prev, q)) {
            return next;
        }
        match self.segment(a, b, Some(prev.fixed()), depth) {
            Some(s) if s.first().is_some_and(|q| self.joined(prev, q)) => s,
            _ => next,
        }
    }

    /// A closed chain whose last piece does not join its first: the first segment
    /// (`pieces[..count]`, from `xs[0]` to `xs[1]`) proven again over the last piece's
    /// fixed parameter, starting exactly at `xs[0]` ([`Self::rejoined`]), if both of its
    /// joins then hold.
    fn reclosed(&self, pieces: &mut Vec<Piece>, count: usize, xs: &[[f64; 4]]) {
        let (Some(last), Some(first)) = (pieces.last(), pieces.first()) else {
            return;
        };
        if count == 0 || count >= pieces.len() || self.joined(last, first) {
            return;
        }
        // xs[0] in the last piece's unwrapped coordinates is xs[n − 1]; the first segment
        // is proven where it is, joins compare boxes shifted by whole periods
        let Some(s) = self.segment(&xs[0], &xs[1], Some(last.fixed()), 0) else {
            return;
        };
        let ok = s.first().is_some_and(|q| self.joined(last, q))
            && s.last().is_some_and(|q| self.joined(q, &pieces[count]));
        if ok {
            pieces.splice(0..count, s);
        }
    }

    /// The curve point with `x_j` halfway between `a_j` and `b_j` (Newton on (9.6) from
    /// the interpolated point), or the halfway point in another parameter if `x_j` does
    /// not move.
    fn curve_point_between(&self, a: &[f64; 4], b: &[f64; 4], j: usize) -> Option<[f64; 4]> {
        let k = if a[j] != b[j] {
            j
        } else {
            (0..4).max_by(|&i, &k| (b[i] - a[i]).abs().total_cmp(&(b[k] - a[k]).abs()))?
        };
        let x0: [f64; 4] = std::array::from_fn(|i| 0.5 * (a[i] + b[i]));
        let m = fixed_parameter_newton(self.pair, x0, k)?;
        // Newton wraps periodic coordinates: bring them back next to the segment.
        Some(std::array::from_fn(|i| {
            self.pair.unwrap_near(i, x0[i], m[i])
        }))
    }

    /// One box over the segment: the slab of `x_j` from `a_j` to `b_j` widened by
    /// [`OVERLAP`] of it on each side (not on `a`'s side when `exact_start`), the other
    /// coordinates around the chord with a margin of a quarter of their change; proven by
    /// epsilon-inflation. (The overlap is small against the margins, so that the exit
    /// face lies inside the next box even when the next segment is several times
    /// shorter.)
    fn one_box(&self, a: &[f64; 4], b: &[f64; 4], j: usize, exact_start: bool) -> Option<Piece> {
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
        let (lo, hi) = if forward {
            (entry, exit)
        } else {
            (exit, entry)
        };
        let slab = Interval::from_bounds(lo, hi);
        let limit = self.limit();
        if !slab.is_subset(&limit[j]) {
            return None;
        }
        let scale = a.iter().chain(b).fold(1.0f64, |m, v| m.max(v.abs()));
        let z: Vec<Interval> = (0..4)
            .filter(|&k| k != j)
            .map(|k| {
                let (p, q) = (a[k].min(b[k]), a[k].max(b[k]));
                // a floor against rounding where the chord does not move in x_k (a
                // straight line): relative to the slab, so long slabs get room too
                let m = 0.25 * (q - p) + 1e-9 * (t1 - t0).abs() + 1e-13 * scale;
                Interval::from_bounds(p - m, q + m)
            })
            .collect();
        let graph = prove_graph(&self.sys, &slab, &z, j, &limit, 6)?;
        Some(Piece { graph, entry, exit })
    }

    /// The enclosure of the arc's point on the face `x_j = t` of a piece.
    fn face(&self, p: &Piece, t: f64) -> Option<[Interval; 4]> {
        let e = enclose_at(&self.sys, &p.graph, &Interval::point(t), 3)?;
        Some(std::array::from_fn(|k| e[k]))
    }

    fn region(p: &Piece) -> [Interval; 4] {
        std::array::from_fn(|k| p.graph.region[k])
    }

    /// Consecutive pieces `p → q` are joined (module doc).
    fn joined(&self, p: &Piece, q: &Piece) -> bool {
        let (Some(out), Some(into)) = (self.face(p, p.exit), self.face(q, q.entry)) else {
            return false;
        };
        self.shifted_inside(&out, &Self::region(q), true)
            && self.shifted_inside(&into, &Self::region(p), true)
    }

    /// Pieces from the curve point `from` towards the singular point `to`, halving the
    /// remaining parameter distance each time, until a piece's exit face lies inside the
    /// singular box `target`. The pieces run from `from` to the box.
    fn approach(&self, from: &[f64; 4], to: &[f64; 4], target: usize) -> Option<Vec<Piece>> {
        let bx = self.singular.get(target)?;
        let mut pieces: Vec<Piece> = Vec::new();
        let mut at = *from;
        for _ in 0..MAX_APPROACH {
            let j = self.choose_fixed(&at, to);
            let next = if (to[j] - at[j]).abs() > 0.0 {
                let mut x0: [f64; 4] = std::array::from_fn(|i| 0.5 * (at[i] + to[i]));
                x0[j] = at[j] + 0.5 * (to[j] - at[j]);
                let m = fixed_parameter_newton(self.pair, x0, j)?;
                std::array::from_fn(|i| self.pair.unwrap_near(i, x0[i], m[i]))
            } else {
                return None;
            };
            let mut seg = self.segment(&at, &next, None, MAX_DEPTH - 4)?;
            let done = seg
                .last()
                .and_then(|p| self.face(p, p.exit))
                .is_some_and(|f| self.shifted_inside(&f, bx, true));
            pieces.append(&mut seg);
            if done {
                return Some(pieces);
            }
            at = next;
        }
        None
    }

    /// The chain of an arc through the curve points `xs` (unwrapped, consecutive), with
    /// its ends anchored (`None` at both ends: a closed curve, `xs` ending where it
    /// started). `Err` says why it could not be proven. When two consecutive boxes are
    /// not proven to join (their slabs, over different fixed parameters, are too long
    /// for the exit face of one to fit in the next), the proof is repeated through
    /// curve points halfway between the given ones, up to [`MAX_DENSIFY`] times.
    pub fn arc(
        &self,
        xs: &[[f64; 4]],
        start: Option<Anchor>,
        end: Option<Anchor>,
    ) -> Result<Vec<Piece>, String> {
        self.extended.set(start.is_none() && end.is_none());
        let result = self.arc_densified(xs, start, end);
        self.extended.set(false);
        result
    }

    fn arc_densified(
        &self,
        xs: &[[f64; 4]],
        start: Option<Anchor>,
        end: Option<Anchor>,
    ) -> Result<Vec<Piece>, String> {
        let mut points = xs.to_vec();
        let mut result = self.arc_once(&points, start, end);
        for _ in 0..MAX_DENSIFY {
            match &result {
                Err(e) if e.contains("not proven to join") => {}
                _ => break,
            }
            points = self.densified(&points, start, end);
            result = self.arc_once(&points, start, end);
        }
        result
    }

    /// `xs` with the curve point halfway inserted in every segment (not next to a
    /// singular anchor, where Newton may not converge).
    fn densified(
        &self,
        xs: &[[f64; 4]],
        start: Option<Anchor>,
        end: Option<Anchor>,
    ) -> Vec<[f64; 4]> {
        let n = xs.len();
        let mut out = Vec::with_capacity(2 * n);
        for (w, pair) in xs.windows(2).enumerate() {
            out.push(pair[0]);
            let near_singular = (w == 0 && matches!(start, Some(Anchor::Singular(_))))
                || (w + 2 == n && matches!(end, Some(Anchor::Singular(_))));
            if near_singular {
                continue;
            }
            let j = self.choose_fixed(&pair[0], &pair[1]);
            if let Some(m) = self.curve_point_between(&pair[0], &pair[1], j) {
                out.push(m);
            }
        }
        out.extend(xs.last());
        out
    }

    fn arc_once(
        &self,
        xs: &[[f64; 4]],
        start: Option<Anchor>,
        end: Option<Anchor>,
    ) -> Result<Vec<Piece>, String> {
        let n = xs.len();
        if n < 2 {
            return Err("fewer than two points".into());
        }
        // A face anchor: the end point's bounded coordinate is the face (the search box's
        // bound, which differs by an ulp from a rounded domain bound).
        let mut owned = xs.to_vec();
        for (anchor, at) in [(start, 0), (end, n - 1)] {
            if let Some(Anchor::Face(k, bound)) = anchor {
                owned[at][k] = bound;
            }
        }
        let xs = &owned[..];
        let mut pieces: Vec<Piece> = Vec::new();
        let (first, last) = (
            usize::from(matches!(start, Some(Anchor::Singular(_)))),
            n - 1 - usize::from(matches!(end, Some(Anchor::Singular(_)))),
        );
        if let Some(Anchor::Singular(i)) = start {
            let mut back = self
                .approach(&xs[1], &xs[0], i)
                .ok_or("the chain does not reach the singular box at the start")?;
            back.reverse();
            pieces.extend(back.into_iter().map(Piece::reversed));
        }
        // the pieces up to the end of the first segment (a closed chain may redo them)
        let mut first_count = 0;
        for w in first..last {
            let forced = match (w, start) {
                (0, Some(Anchor::Face(k, _))) => Some(k),
                _ => None,
            };
            let face_end = w + 1 == n - 1 && matches!(end, Some(Anchor::Face(..)));
            let seg = if face_end {
                let Some(Anchor::Face(k, _)) = end else {
                    unreachable!()
                };
                // prove from the face backwards, so that the slab ends on the bound
                self.segment(&xs[w + 1], &xs[w], Some(k), 0).map(|mut s| {
                    s.reverse();
                    s.into_iter().map(Piece::reversed).collect()
                })
            } else {
                self.segment(&xs[w], &xs[w + 1], forced, 0)
            };
            let seg = seg.ok_or_else(|| format!("no proof between points {w} and {}", w + 1))?;
            let seg = match pieces.last() {
                Some(p) if !face_end => self.rejoined(p, seg, &xs[w], &xs[w + 1], 0),
                _ => seg,
            };
            pieces.extend(seg);
            if w == first {
                first_count = pieces.len();
            }
        }
        if start.is_none() && end.is_none() {
            self.reclosed(&mut pieces, first_count, xs);
        }
        if let Some(Anchor::Singular(i)) = end {
            let ahead = self
                .approach(&xs[n - 2], &xs[n - 1], i)
                .ok_or("the chain does not reach the singular box at the end")?;
            pieces.extend(ahead);
        }
        for (k, w) in pieces.windows(2).enumerate() {
            if !self.joined(&w[0], &w[1]) {
                return Err(format!("pieces {k} and {} are not proven to join", k + 1));
            }
        }
        self.anchored(&pieces, start, end)?;
        Ok(pieces)
    }

    /// The chain's ends: joined into a loop, on a domain face, or inside a singular box.
    fn anchored(
        &self,
        pieces: &[Piece],
        start: Option<Anchor>,
        end: Option<Anchor>,
    ) -> Result<(), String> {
        let (Some(first), Some(last)) = (pieces.first(), pieces.last()) else {
            return Err("no pieces".into());
        };
        if start.is_none() && end.is_none() {
            return if pieces.len() >= 2 && self.joined(last, first) {
                Ok(())
            } else {
                Err("the chain is not proven to close".into())
            };
        }
        let check = |piece: &Piece, t: f64, anchor: Option<Anchor>| -> bool {
            match anchor {
                Some(Anchor::Face(k, bound)) => piece.fixed() == k && t == bound,
                Some(Anchor::Singular(i)) => {
                    let (Some(f), Some(b)) = (self.face(piece, t), self.singular.get(i)) else {
                        return false;
                    };
                    self.shifted_inside(&f, b, true)
                }
                None => false,
            }
        };
        if !check(first, first.entry, start) {
            return Err(
                "the start is not proven to lie on the boundary or in a singular box".into(),
            );
        }
        if !check(last, last.exit, end) {
            return Err("the end is not proven to lie on the boundary or in a singular box".into());
        }
        Ok(())
    }

    /// A tight enclosure of the curve point with the same fixed parameter as the point
    /// `x` (unwrapped), from a piece whose slab holds it.
    pub fn vertex_box(&self, pieces: &[Piece], x: &[f64; 4]) -> Option<[Interval; 4]> {
        let inside = |p: &Piece| {
            let j = p.fixed();
            let r = &p.graph.region;
            r[j].contains(x[j]) && (0..4).all(|k| r[k].contains(x[k]))
        };
        let p = pieces.iter().find(|p| inside(p))?;
        let e = enclose_at(&self.sys, &p.graph, &Interval::point(x[p.fixed()]), 4)?;
        Some(std::array::from_fn(|k| e[k]))
    }
}

/// The proven distance from `xyz` to the space points of the parameter box `b`: the
/// points `r(u, v)` and `s(a, b)` are both enclosed; their intersection holds the curve
/// point, and the distance is bounded over that box (outward rounded).
pub fn distance_bound<R: Surface, S: Surface>(
    pair: &Pair<'_, R, S>,
    b: &[Interval; 4],
    xyz: &[f64; 3],
) -> ([Interval; 3], f64) {
    let pr = pair.r.jet(&b[0], &b[1], 0).swap_remove(0);
    let ps = pair.s.jet(&b[2], &b[3], 0).swap_remove(0);
    let q: [Interval; 3] = std::array::from_fn(|i| {
        let both = pr[i].intersection(&ps[i]);
        if both.is_empty() {
            pr[i].hull(&ps[i])
        } else {
            both
        }
    });
    let mut sum = Interval::ZERO;
    for i in 0..3 {
        let d = (Interval::point(xyz[i]) - q[i]).abs();
        sum += d.sqr();
    }
    (q, sum.sqrt().hi())
}
