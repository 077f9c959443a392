//! The float contour (OPERATIONS.md §13.5 "row scan for sign changes + bisection"): the
//! signs of `I` on a grid over the parameter domain, the crossing on every grid edge
//! whose ends differ in sign (bisection along the edge, so each vertex lies on the
//! curve with its fixed coordinate exact), and the crossings joined cell by cell into
//! polylines (marching squares; a cell with four crossings is resolved by the sign at
//! its centre). Periodic directions are glued. No proof: loops smaller than a cell or
//! two crossings on one edge are missed here and found by the completeness proof.

use super::system::ContourFn;
use crate::surface::Surface;
use std::collections::HashMap;

/// The parameter grid: `n[k]` cells in direction `k` over `[lo[k], hi[k]]`.
#[derive(Debug, Clone)]
pub struct Grid {
    pub n: [usize; 2],
    pub lo: [f64; 2],
    pub hi: [f64; 2],
    pub periodic: [bool; 2],
}

impl Grid {
    /// The `i`-th node in direction `k` (the last one is `hi` exactly).
    pub fn node(&self, k: usize, i: usize) -> f64 {
        if i >= self.n[k] {
            return self.hi[k];
        }
        self.lo[k] + (self.hi[k] - self.lo[k]) * (i as f64 / self.n[k] as f64)
    }
}

/// One float contour polyline in the parameter plane: points on the curve, unwrapped
/// across periodic seams (consecutive points are neighbours); a closed one ends where it
/// started (shifted by whole periods when it winds around).
#[derive(Debug, Clone)]
pub struct Polyline {
    pub points: Vec<[f64; 2]>,
    pub closed: bool,
}

/// An edge of the grid: direction of the edge (0: along `u`, `v` fixed), node indices.
type Edge = (usize, usize, usize);

/// `I = 0` on the edge from `a` to `b` (moving in coordinate `dir`) whose end signs differ:
/// bisection on the sign, 80 steps at most.
fn crossing<S: Surface>(f: &ContourFn<'_, S>, a: [f64; 2], b: [f64; 2], dir: usize) -> [f64; 2] {
    let val = |t: f64| {
        let mut x = a;
        x[dir] = t;
        f.value(&x[0], &x[1])
    };
    let (mut lo, mut hi) = (a[dir], b[dir]);
    let neg_lo = val(lo) < 0.0;
    for _ in 0..80 {
        let mid = 0.5 * (lo + hi);
        if mid == lo || mid == hi {
            break;
        }
        if (val(mid) < 0.0) == neg_lo {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    let mut x = a;
    x[dir] = 0.5 * (lo + hi);
    x
}

/// The float contour on `grid` (module doc).
pub fn trace<S: Surface>(f: &ContourFn<'_, S>, grid: &Grid) -> Vec<Polyline> {
    let [n0, n1] = grid.n;
    // node values, periodic ends glued to the start
    let idx = |i: usize, j: usize| {
        let i = if grid.periodic[0] && i == n0 { 0 } else { i };
        let j = if grid.periodic[1] && j == n1 { 0 } else { j };
        (i, j)
    };
    let mut vals = vec![vec![0.0; n1 + 1]; n0 + 1];
    for (i, row) in vals.iter_mut().enumerate() {
        for (j, v) in row.iter_mut().enumerate() {
            *v = f.value(&grid.node(0, i), &grid.node(1, j));
        }
    }
    let neg = |i: usize, j: usize| {
        let (i, j) = idx(i, j);
        vals[i][j] < 0.0
    };
    let canon = |(d, i, j): Edge| -> Edge {
        match d {
            0 if grid.periodic[1] && j == n1 => (0, i, 0),
            1 if grid.periodic[0] && i == n0 => (1, 0, j),
            _ => (d, i, j),
        }
    };
    let mut points: HashMap<Edge, [f64; 2]> = HashMap::new();
    let mut links: HashMap<Edge, Vec<Edge>> = HashMap::new();
    for i in 0..n0 {
        for j in 0..n1 {
            // bottom, right, top, left
            let edges = [(0, i, j), (1, i + 1, j), (0, i, j + 1), (1, i, j)];
            let corners = [(i, j), (i + 1, j), (i + 1, j + 1), (i, j + 1)];
            let cut: Vec<usize> = (0..4)
                .filter(|&e| {
                    let (a, b) = (corners[e], corners[(e + 1) % 4]);
                    neg(a.0, a.1) != neg(b.0, b.1)
                })
                .collect();
            for &e in &cut {
                let key = canon(edges[e]);
                let (a, b) = (corners[e], corners[(e + 1) % 4]);
                let pa = [grid.node(0, a.0), grid.node(1, a.1)];
                let pb = [grid.node(0, b.0), grid.node(1, b.1)];
                let dir = if pa[0] != pb[0] { 0 } else { 1 };
                points
                    .entry(key)
                    .or_insert_with(|| crossing(f, pa, pb, dir));
            }
            let pairs: Vec<(usize, usize)> = match cut.len() {
                2 => vec![(cut[0], cut[1])],
                4 => {
                    let c = f.value(
                        &(0.5 * (grid.node(0, i) + grid.node(0, i + 1))),
                        &(0.5 * (grid.node(1, j) + grid.node(1, j + 1))),
                    );
                    if (c < 0.0) == neg(i, j) {
                        vec![(0, 1), (2, 3)]
                    } else {
                        vec![(0, 3), (1, 2)]
                    }
                }
                _ => Vec::new(),
            };
            for (a, b) in pairs {
                let (ea, eb) = (canon(edges[a]), canon(edges[b]));
                links.entry(ea).or_default().push(eb);
                links.entry(eb).or_default().push(ea);
            }
        }
    }
    join(grid, &points, &links)
}

/// Walk the crossing graph into polylines: from every end of degree one first, then the
/// loops.
fn join(
    grid: &Grid,
    points: &HashMap<Edge, [f64; 2]>,
    links: &HashMap<Edge, Vec<Edge>>,
) -> Vec<Polyline> {
    let mut keys: Vec<Edge> = links.keys().copied().collect();
    keys.sort_unstable();
    let mut used: HashMap<Edge, bool> = HashMap::new();
    let mut out = Vec::new();
    let starts = keys
        .iter()
        .filter(|k| links[k].len() == 1)
        .chain(keys.iter().filter(|k| links[k].len() != 1));
    for &s in starts {
        if used.contains_key(&s) {
            continue;
        }
        let mut path = vec![s];
        used.insert(s, true);
        let mut prev: Option<Edge> = None;
        let mut at = s;
        let closed;
        loop {
            let next = links[&at]
                .iter()
                .copied()
                .find(|e| Some(*e) != prev && !used.contains_key(e));
            match next {
                Some(e) => {
                    used.insert(e, true);
                    path.push(e);
                    prev = Some(at);
                    at = e;
                }
                None => {
                    closed = path.len() > 2 && links[&at].contains(&s);
                    break;
                }
            }
        }
        if closed {
            path.push(s);
        }
        let mut pts: Vec<[f64; 2]> = Vec::with_capacity(path.len());
        for e in &path {
            let p = points[e];
            let q = match pts.last() {
                Some(prev) => unwrap_near(grid, prev, p),
                None => p,
            };
            if pts.last() != Some(&q) {
                pts.push(q);
            }
        }
        let pts = thin(grid, pts);
        if pts.len() >= 2 {
            out.push(Polyline {
                points: pts,
                closed,
            });
        }
    }
    out
}

/// `p` shifted by whole periods to lie nearest to `prev`.
pub fn unwrap_near(grid: &Grid, prev: &[f64; 2], p: [f64; 2]) -> [f64; 2] {
    std::array::from_fn(|k| {
        if !grid.periodic[k] {
            return p[k];
        }
        let per = grid.hi[k] - grid.lo[k];
        p[k] + per * ((prev[k] - p[k]) / per).round()
    })
}

/// Drop vertices closer than half a cell to the previous kept one (the ends stay), so
/// that consecutive chords are of similar length: the chain's boxes then overlap
/// their neighbours.
fn thin(grid: &Grid, pts: Vec<[f64; 2]>) -> Vec<[f64; 2]> {
    let cell: [f64; 2] = std::array::from_fn(|k| (grid.hi[k] - grid.lo[k]) / grid.n[k] as f64);
    let far = |a: &[f64; 2], b: &[f64; 2]| {
        let d: f64 = (0..2).map(|k| ((a[k] - b[k]) / cell[k]).powi(2)).sum();
        d >= 0.25
    };
    let n = pts.len();
    let mut out: Vec<[f64; 2]> = Vec::with_capacity(n);
    for (i, p) in pts.into_iter().enumerate() {
        match out.last() {
            None => out.push(p),
            Some(last) if i + 1 == n => {
                if !far(last, &p) && out.len() >= 2 {
                    out.pop();
                }
                out.push(p);
            }
            Some(last) if far(last, &p) => out.push(p),
            Some(_) => {}
        }
    }
    out
}
