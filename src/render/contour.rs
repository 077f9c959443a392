//! The zero set of a function sampled on a grid, as polylines (marching squares): the
//! contours of surfaces (`I = 0`, OPERATIONS.md (13.10)) and implicit plane conics in
//! pictures. A float approximation for drawing only — the certified contour is
//! [`crate::ops::view::contour_surface`].

use std::collections::HashMap;

/// An edge of the grid: `(0, i, j)` from node `(i, j)` to `(i+1, j)`, `(1, i, j)` from
/// `(i, j)` to `(i, j+1)`.
type EdgeKey = (u8, usize, usize);

/// The polylines where `f` changes sign on the `(nx+1) × (ny+1)` node grid, in grid
/// coordinates (`[i, j]` with fractional parts; nodes at whole numbers). Each crossing
/// lies on a grid edge whose end values have opposite signs (zero counts as positive),
/// placed by linear interpolation; in a cell with four crossings (a saddle) the pairing
/// follows the sign of the mean of the corners. Segments sharing a crossing are joined;
/// a closed polyline repeats its first point last. Nodes where `f` is not finite cut
/// no edge.
pub fn zero_polylines(nx: usize, ny: usize, f: impl Fn(usize, usize) -> f64) -> Vec<Vec<[f64; 2]>> {
    let values: Vec<f64> = (0..=nx)
        .flat_map(|i| (0..=ny).map(move |j| (i, j)))
        .map(|(i, j)| f(i, j))
        .collect();
    let val = |i: usize, j: usize| values[i * (ny + 1) + j];
    let mut points: HashMap<EdgeKey, [f64; 2]> = HashMap::new();
    let mut crossing = |key: EdgeKey| -> Option<EdgeKey> {
        let (dir, i, j) = key;
        let (a, b, end) = if dir == 0 {
            (val(i, j), val(i + 1, j), (i + 1, j))
        } else {
            (val(i, j), val(i, j + 1), (i, j + 1))
        };
        if !(a.is_finite() && b.is_finite()) || (a >= 0.0) == (b >= 0.0) {
            return None;
        }
        let s = a / (a - b);
        let p = [
            i as f64 + s * (end.0 as f64 - i as f64),
            j as f64 + s * (end.1 as f64 - j as f64),
        ];
        points.insert(key, p);
        Some(key)
    };
    let mut segments: Vec<[EdgeKey; 2]> = Vec::new();
    for i in 0..nx {
        for j in 0..ny {
            // Bottom, right, top, left.
            let edges = [(0, i, j), (1, i + 1, j), (0, i, j + 1), (1, i, j)];
            let hits: Vec<Option<EdgeKey>> = edges.iter().map(|&e| crossing(e)).collect();
            let found: Vec<EdgeKey> = hits.iter().flatten().copied().collect();
            match found.len() {
                2 => segments.push([found[0], found[1]]),
                4 => {
                    let mean =
                        (val(i, j) + val(i + 1, j) + val(i + 1, j + 1) + val(i, j + 1)) / 4.0;
                    if (mean >= 0.0) == (val(i, j) >= 0.0) {
                        segments.push([found[0], found[1]]);
                        segments.push([found[2], found[3]]);
                    } else {
                        segments.push([found[3], found[0]]);
                        segments.push([found[1], found[2]]);
                    }
                }
                _ => {}
            }
        }
    }
    join(&segments)
        .into_iter()
        .map(|chain| chain.iter().map(|k| points[k]).collect())
        .collect()
}

/// Chains of segments that share end keys: open chains from their free ends first,
/// then the closed ones.
fn join(segments: &[[EdgeKey; 2]]) -> Vec<Vec<EdgeKey>> {
    let mut at: HashMap<EdgeKey, Vec<usize>> = HashMap::new();
    for (k, s) in segments.iter().enumerate() {
        for e in s {
            at.entry(*e).or_default().push(k);
        }
    }
    let mut used = vec![false; segments.len()];
    let mut chains = Vec::new();
    let free_end = |k: usize| segments[k].iter().find(|e| at[e].len() == 1).copied();
    let order: Vec<usize> = (0..segments.len())
        .filter(|&k| free_end(k).is_some())
        .chain(0..segments.len())
        .collect();
    for start in order {
        if used[start] {
            continue;
        }
        used[start] = true;
        let s = segments[start];
        let first = free_end(start).unwrap_or(s[0]);
        let mut cur = if first == s[0] { s[1] } else { s[0] };
        let mut chain = vec![first, cur];
        while let Some(&next) = at[&cur].iter().find(|&&k| !used[k]) {
            used[next] = true;
            let n = segments[next];
            cur = if n[0] == cur { n[1] } else { n[0] };
            chain.push(cur);
        }
        chains.push(chain);
    }
    chains
}
