//! Duplicate merging (OPERATIONS.md §0.4, [Y 4.5] generalised): two solutions are one
//! when every parameter agrees within its δ_i, periodic parameters measured around
//! their period; the merged solution keeps the member with the smallest residual.

use std::collections::HashMap;

/// How one parameter of a solution is compared.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ParamTolerance {
    /// δ_i.
    pub delta: f64,
    /// The period `P_i`, for a periodic parameter.
    pub period: Option<f64>,
}

impl ParamTolerance {
    /// `dist_i`: `|x − y|`, or `min_k |x − y + kP|` for a periodic parameter.
    pub fn distance(&self, x: f64, y: f64) -> f64 {
        let d = (x - y).abs();
        match self.period {
            Some(p) if p > 0.0 => {
                let r = d.rem_euclid(p);
                r.min(p - r)
            }
            _ => d,
        }
    }
}

/// Merge duplicates among `solutions`: `params(s)` gives a solution's parameters (one
/// per entry of `tolerances`) and `residual(s)` its residual. Solutions are grouped
/// greedily in order of increasing residual, so every kept solution is the
/// best-residual member of its group.
///
/// The kept solutions are indexed by a grid over the first two parameters, of cell `δ_i`
/// (a period wrapped into `[0, P_i)`): a kept solution within `δ_i` of a new one lies
/// within two cells of it on each axis (±2 absorbs the rounding of `x/δ_i` and the
/// shorter last cell of a period). Only those are compared, so the result is the
/// quadratic greedy one at a near-linear cost: tens of thousands of float solutions
/// along a degenerate piece (a polyline whose points are all equal) once took seconds
/// here (issue 20, fuzz findings `curve_curve` timeouts).
pub fn merge_duplicates<S>(
    mut solutions: Vec<S>,
    tolerances: &[ParamTolerance],
    params: impl Fn(&S) -> Vec<f64>,
    residual: impl Fn(&S) -> f64,
) -> Vec<S> {
    solutions.sort_by(|a, b| residual(a).total_cmp(&residual(b)));
    let grid: Vec<Axis> = tolerances.iter().take(2).map_while(Axis::new).collect();
    let mut kept: Vec<(Vec<f64>, S)> = Vec::new();
    let mut cells: HashMap<[i64; 2], Vec<usize>> = HashMap::new();
    let matches = |p: &[f64], q: &[f64]| {
        tolerances
            .iter()
            .zip(p.iter().zip(q))
            .all(|(t, (x, y))| t.distance(*x, *y) < t.delta)
    };
    for s in solutions {
        let p = params(&s);
        let cell = key(&grid, &p);
        let duplicate = match cell {
            Some(c) => neighbours(&grid, c)
                .filter_map(|n| cells.get(&n))
                .flatten()
                .any(|&i| matches(&p, &kept[i].0)),
            None => kept.iter().any(|(q, _)| matches(&p, q)),
        };
        if !duplicate {
            if let Some(c) = cell {
                cells.entry(c).or_default().push(kept.len());
            }
            kept.push((p, s));
        }
    }
    kept.into_iter().map(|(_, s)| s).collect()
}

/// The cell of a solution (unused axes are 0), or `None` when the grid does not apply
/// (no usable axis, or a NaN parameter: compared with every kept solution, never
/// matching).
fn key(grid: &[Axis], p: &[f64]) -> Option<[i64; 2]> {
    if grid.is_empty() || p.len() < grid.len() {
        return None;
    }
    let mut k = [0; 2];
    for (i, axis) in grid.iter().enumerate() {
        k[i] = axis.cell(p[i])?;
    }
    Some(k)
}

/// The cells within two of `c` on every axis of the grid.
fn neighbours(grid: &[Axis], c: [i64; 2]) -> impl Iterator<Item = [i64; 2]> + '_ {
    let span = |i: usize| if i < grid.len() { -2..=2 } else { 0..=0 };
    span(0).flat_map(move |d0| {
        span(1).map(move |d1| {
            let mut n = c;
            for (i, d) in [d0, d1].into_iter().enumerate().take(grid.len()) {
                n[i] = grid[i].wrap(c[i].saturating_add(d));
            }
            n
        })
    })
}

/// One axis of the grid used by [`merge_duplicates`].
struct Axis {
    delta: f64,
    period: Option<f64>,
    /// The number of cells of one period (periodic parameters).
    period_cells: Option<i64>,
}

impl Axis {
    /// `None` (the grid stops before this axis) when `δ_i` is not a positive finite
    /// number or a period holds too many cells to count.
    fn new(t: &ParamTolerance) -> Option<Axis> {
        if !(t.delta.is_finite() && t.delta > 0.0) {
            return None;
        }
        let period = t.period.filter(|p| *p > 0.0 && p.is_finite());
        let period_cells = match period {
            Some(p) => {
                let n = (p / t.delta).ceil();
                if n.is_nan() || n >= 1e15 {
                    return None;
                }
                Some((n as i64).max(1))
            }
            None => None,
        };
        Some(Axis {
            delta: t.delta,
            period,
            period_cells,
        })
    }

    /// The cell of `x` (`None` for a NaN). The cast saturates, which only puts far
    /// values in a shared cell.
    fn cell(&self, x: f64) -> Option<i64> {
        if x.is_nan() {
            return None;
        }
        let x = self.period.map_or(x, |p| x.rem_euclid(p));
        // `rem_euclid` may round up to the period itself: wrap that cell too.
        Some(self.wrap((x / self.delta).floor() as i64))
    }

    fn wrap(&self, c: i64) -> i64 {
        self.period_cells.map_or(c, |m| c.rem_euclid(m))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::TAU;

    #[test]
    fn periodic_neighbours_across_the_seam_merge_keeping_the_best_residual() {
        let tol = [ParamTolerance {
            delta: 1e-9,
            period: Some(TAU),
        }];
        // (t, residual): 1e-12 and TAU − 1e-12 are the same point; 3.0 is another.
        let sols = vec![(TAU - 1e-12, 1e-14), (1e-12, 1e-16), (3.0, 1e-15)];
        let merged = merge_duplicates(sols, &tol, |s| vec![s.0], |s| s.1);
        assert_eq!(merged, vec![(1e-12, 1e-16), (3.0, 1e-15)]);
    }

    #[test]
    fn every_parameter_must_agree() {
        let tol = [ParamTolerance {
            delta: 1e-9,
            period: None,
        }; 2];
        let sols = vec![([0.0, 0.0], 0.0), ([0.0, 1.0], 0.0), ([1e-10, 0.0], 1.0)];
        let merged = merge_duplicates(sols, &tol, |s| s.0.to_vec(), |s| s.1);
        assert_eq!(merged.len(), 2);
        assert_eq!(merged[0].0, [0.0, 0.0]);
        assert_eq!(merged[1].0, [0.0, 1.0]);
    }

    /// The plain quadratic greedy merge the grid must reproduce exactly.
    fn reference(sols: &[(Vec<f64>, f64)], tol: &[ParamTolerance]) -> Vec<(Vec<f64>, f64)> {
        let mut sorted = sols.to_vec();
        sorted.sort_by(|a, b| a.1.total_cmp(&b.1));
        let mut kept: Vec<(Vec<f64>, f64)> = Vec::new();
        for s in sorted {
            let dup = kept.iter().any(|(q, _)| {
                tol.iter()
                    .zip(s.0.iter().zip(q))
                    .all(|(t, (x, y))| t.distance(*x, *y) < t.delta)
            });
            if !dup {
                kept.push(s);
            }
        }
        kept
    }

    /// Random clusters around the seam of a period, at the period's ends, and far from
    /// it, with deltas from 1e-12 to more than the period: the grid merge keeps exactly
    /// the solutions the quadratic merge keeps, in the same order.
    #[test]
    fn the_grid_merge_equals_the_quadratic_merge() {
        let mut seed = 0x2545_f491_4f6c_dd1du64;
        let mut next = move || {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            (seed >> 11) as f64 / (1u64 << 53) as f64
        };
        let deltas = [1e-12, 1e-6, 0.01, 0.3, 1.0, 7.0];
        let periods = [None, Some(TAU), Some(1.0), Some(0.25)];
        for case in 0..600 {
            let delta = deltas[case % deltas.len()];
            let period = periods[(case / deltas.len()) % periods.len()];
            let tol = [
                ParamTolerance { delta, period },
                ParamTolerance {
                    delta: 2.0 * delta,
                    period: if case % 2 == 0 { None } else { Some(1.5) },
                },
                ParamTolerance {
                    delta: 0.5 * delta,
                    period: None,
                },
            ];
            let span = period.unwrap_or(4.0);
            let centres: Vec<f64> = (0..3)
                .map(|_| match (next() * 3.0) as u32 {
                    0 => 0.0,
                    1 => span,
                    _ => next() * span,
                })
                .collect();
            let sols: Vec<(Vec<f64>, f64)> = (0..60)
                .map(|_| {
                    let c = centres[(next() * 3.0) as usize];
                    let x = c + (next() - 0.5) * 3.0 * delta;
                    let y = if next() < 0.3 { 1.5 } else { 0.0 } + (next() - 0.5) * 3.0 * delta;
                    let z = (next() - 0.5) * 3.0 * delta;
                    (vec![x, y, z], next())
                })
                .collect();
            let got = merge_duplicates(sols.clone(), &tol, |s| s.0.clone(), |s| s.1);
            assert_eq!(got, reference(&sols, &tol), "case {case}");
        }
    }

    /// 100,000 solutions at one point (a degenerate piece) merge into one without the
    /// quadratic cost (10¹⁰ comparisons); NaN parameters never merge and never panic.
    #[test]
    fn a_crowd_at_one_point_merges_into_one() {
        let tol = [ParamTolerance {
            delta: 1e-9,
            period: Some(TAU),
        }];
        let mut sols: Vec<(f64, f64)> = (0..100_000).map(|i| (1.0, i as f64)).collect();
        sols.push((f64::NAN, -1.0));
        let merged = merge_duplicates(sols, &tol, |s| vec![s.0], |s| s.1);
        assert_eq!(merged.len(), 2);
        assert!(merged[0].0.is_nan());
        assert_eq!(merged[1], (1.0, 0.0));
    }

    /// 20,000 distinct solutions sharing their first parameter (the foot on a collapsed
    /// piece, every parameter of the other curve): all kept, through the second axis of
    /// the grid rather than 2·10⁸ comparisons.
    #[test]
    fn a_line_of_distinct_solutions_is_kept_whole() {
        let tol = [ParamTolerance {
            delta: 1e-9,
            period: None,
        }; 2];
        let sols: Vec<([f64; 2], f64)> =
            (0..20_000).map(|i| ([3.0, i as f64 * 1e-4], 0.0)).collect();
        let merged = merge_duplicates(sols.clone(), &tol, |s| s.0.to_vec(), |s| s.1);
        assert_eq!(merged, sols);
    }
}
