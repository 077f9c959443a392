//! The proof that a closed-form centre curve is the fillet's over its whole range
//! (OPERATIONS.md §11.2, §11.4): the range is covered by parameter boxes, and over
//! each box every quantity of [`CentreCurve::conditions`] is evaluated in f64
//! intervals (outward rounded, so each enclosure holds the exact value for every `t`
//! of the box). All positive on every box proves, for every `t`: the closed form is
//! real, the faces are transversal at the contacts (`1 + cos φ > 0`, an arc of positive
//! angle), and both contacts lie inside their faces' domains. A box where a condition
//! is not decided is bisected down to a width floor or a box budget.

use super::centre::{CentreCurve, Condition};
use crate::num::{Interval, Real};

/// The verdict on one box or one whole curve.
#[derive(Debug, Clone, PartialEq)]
pub enum Verdict {
    /// Every condition is proven positive over the whole range.
    Proven,
    /// `condition` is proven negative over the box `t` (the whole box fails).
    Fails { condition: Condition, t: [f64; 2] },
    /// `condition` could not be decided on the box `t` (its midpoint value `value`).
    Undecided {
        condition: Condition,
        t: [f64; 2],
        value: f64,
    },
}

/// The outcome over the whole range.
#[derive(Debug, Clone, PartialEq)]
pub struct Cover {
    /// The first failure or undecided box, or `Proven`.
    pub verdict: Verdict,
    /// The `Real` condition is proven negative on every box (the curve does not
    /// exist: the offsets do not meet).
    pub absent: bool,
}

const INITIAL_BOXES: usize = 64;
const BOX_BUDGET: usize = 20_000;

fn classify(curve: &CentreCurve, t: [f64; 2]) -> Verdict {
    let ti = Interval::from_bounds(t[0], t[1]);
    let conditions = curve.conditions(&ti);
    let mut undecided = None;
    for (value, condition) in &conditions {
        let (lo, hi) = value.bounds();
        if value.is_empty() || hi < 0.0 {
            return Verdict::Fails {
                condition: *condition,
                t,
            };
        }
        if (lo.is_nan() || lo <= 0.0) && undecided.is_none() {
            undecided = Some(*condition);
        }
    }
    match undecided {
        None => Verdict::Proven,
        Some(condition) => {
            let mid = 0.5 * (t[0] + t[1]);
            let value = curve
                .conditions(&mid)
                .into_iter()
                .find(|(_, c)| *c == condition)
                .map_or(f64::NAN, |(v, _)| v);
            Verdict::Undecided {
                condition,
                t,
                value,
            }
        }
    }
}

/// Cover `curve.range` by boxes and decide every condition on each (module doc).
pub fn cover(curve: &CentreCurve) -> Cover {
    let [t0, t1] = curve.range;
    let floor = (t1 - t0).abs() * 1e-9;
    let mut stack: Vec<[f64; 2]> = (0..INITIAL_BOXES)
        .rev()
        .map(|i| {
            let at = |k: usize| {
                if k == INITIAL_BOXES {
                    t1
                } else {
                    t0 + (t1 - t0) * k as f64 / INITIAL_BOXES as f64
                }
            };
            [at(i), at(i + 1)]
        })
        .collect();
    let mut first_problem = None;
    let mut all_absent = true;
    let mut spent = 0;
    while let Some(t) = stack.pop() {
        spent += 1;
        match classify(curve, t) {
            Verdict::Proven => all_absent = false,
            Verdict::Fails { condition, .. } if condition == Condition::Real => {
                first_problem.get_or_insert(Verdict::Fails { condition, t });
            }
            Verdict::Undecided { .. } if t[1] - t[0] > floor && spent < BOX_BUDGET => {
                let mid = 0.5 * (t[0] + t[1]);
                stack.push([mid, t[1]]);
                stack.push([t[0], mid]);
            }
            other => {
                all_absent = false;
                first_problem.get_or_insert(other);
            }
        }
    }
    Cover {
        absent: all_absent && first_problem.is_some(),
        verdict: first_problem.unwrap_or(Verdict::Proven),
    }
}
