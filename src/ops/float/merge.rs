//! Duplicate merging (OPERATIONS.md §0.4, [Y 4.5] generalised): two solutions are one
//! when every parameter agrees within its δ_i, periodic parameters measured around
//! their period; the merged solution keeps the member with the smallest residual.

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
pub fn merge_duplicates<S>(
    mut solutions: Vec<S>,
    tolerances: &[ParamTolerance],
    params: impl Fn(&S) -> Vec<f64>,
    residual: impl Fn(&S) -> f64,
) -> Vec<S> {
    solutions.sort_by(|a, b| residual(a).total_cmp(&residual(b)));
    let mut kept: Vec<(Vec<f64>, S)> = Vec::new();
    for s in solutions {
        let p = params(&s);
        let duplicate = kept.iter().any(|(q, _)| {
            tolerances
                .iter()
                .zip(p.iter().zip(q))
                .all(|(t, (x, y))| t.distance(*x, *y) < t.delta)
        });
        if !duplicate {
            kept.push((p, s));
        }
    }
    kept.into_iter().map(|(_, s)| s).collect()
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
}
