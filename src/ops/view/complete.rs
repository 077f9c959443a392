//! The completeness proof of the contour (OPERATIONS.md §13.5; CERTIFICATION.md
//! "complete").
//!
//! Cut every periodic coordinate at a line `x_k = c_k` and consider the box `D'` whose
//! sides are the bounded coordinates' search ranges and `[c_k, c_k + P_k]` for the
//! periodic ones. A component `C` of the contour either meets the boundary of `D'` — a
//! domain face or a cut line, where it is a root of `I` restricted to that line (the
//! edge systems) — or lies in the open `D'`; then, being compact, it has a point where
//! the height `x_h` is largest, and there the contour's tangent `(I_v, −I_u)` has a zero
//! `h`-component or `∇I = 0`: a root of the critical system `I = ∂I/∂x_{1−h} = 0`.
//! Every root of all these systems is found by the complete solver
//! ([`crate::certify::solve`]); when each lies in a box of a proven chain, the component
//! through it is that chain's (the box holds only the chain's arc), so the chains are
//! all of the contour.

use super::chain::{Chains, Piece};
use super::system::{CriticalSystem, EdgeSystem};
use super::types::ContourCurve;
use crate::certificate::Status;
use crate::certify::{solve, Options, Solutions};
use crate::error::GeomError;
use crate::num::round::next_up;
use crate::num::Interval;
use crate::surface::Surface;

/// What the proof found.
pub struct Proof {
    pub complete: bool,
    /// Verified roots lie on no chain: the float scan missed a component (refine).
    pub missed: bool,
    pub reasons: Vec<String>,
    pub bits: u32,
}

/// The cut of each periodic coordinate: off the grid lines, at a golden-ratio fraction
/// of the domain (`alt` picks another, after a cut that could not be decided).
fn cut(chains_lo: f64, period: f64, alt: bool) -> f64 {
    let g = if alt {
        0.723_606_797_749_979
    } else {
        0.381_966_011_250_105_1
    };
    chains_lo + g * period
}

/// The proof (module doc) for the certified chains of `traced`.
pub fn prove_complete<S: Surface>(
    chains: &Chains<'_, '_, S>,
    traced: &[(ContourCurve, Vec<Piece>)],
    opts: &Options,
) -> Result<Proof, GeomError> {
    let mut reasons = Vec::new();
    let mut bits = 53;
    let mut missed = false;
    let proven: Vec<&[Piece]> = traced
        .iter()
        .filter(|(c, p)| c.status == Status::Verified && !p.is_empty())
        .map(|(_, p)| p.as_slice())
        .collect();
    let on_chain = |b: &[Interval; 2]| {
        proven.iter().any(|ps| {
            ps.iter()
                .any(|p| chains.shifted_inside(b, &p.region(), false))
        })
    };
    let mut ok = true;
    let mut alt = false;
    for attempt in 0..2 {
        let (range, lines) = domain_and_lines(chains, alt);
        let mut all_ok = true;
        let mut cut_failed = false;
        let mut local = Vec::new();
        for (fixed, at, is_cut) in lines {
            let other = 1 - fixed;
            let sys = EdgeSystem {
                f: chains.f,
                fixed,
                at,
            };
            let sol = solve(&sys, &[range[other]], opts)?;
            bits = bits.max(sol.bits);
            let boxes = roots_of(&sol.value).map(|r| {
                let mut b = [Interval::point(at); 2];
                b[other] = r[0];
                b
            });
            let (good, miss) = check(&sol.value, boxes, &on_chain, &mut local, "edge");
            missed |= miss;
            if !good {
                all_ok = false;
                cut_failed |= is_cut;
            }
        }
        let height = pick_height(chains, &proven);
        let mut crit_ok = false;
        for h in [height, 1 - height] {
            let sys = CriticalSystem {
                f: chains.f,
                height: h,
            };
            let sol = solve(&sys, &range, opts)?;
            bits = bits.max(sol.bits);
            let boxes = roots_of(&sol.value).map(|r| [r[0], r[1]]);
            let mut notes = Vec::new();
            let (good, miss) = check(&sol.value, boxes, &on_chain, &mut notes, "critical");
            if good {
                crit_ok = true;
                break;
            }
            missed |= miss;
            if h != height {
                local.extend(notes);
            }
        }
        all_ok &= crit_ok;
        if all_ok || !cut_failed || attempt == 1 {
            ok = all_ok;
            reasons = local;
            break;
        }
        alt = true;
    }
    Ok(Proof {
        complete: ok,
        missed,
        reasons,
        bits,
    })
}

/// Every root box of a solution (interior and boundary ones).
fn roots_of(s: &Solutions) -> impl Iterator<Item = Vec<Interval>> + '_ {
    s.roots
        .iter()
        .chain(&s.boundary_roots)
        .map(|r| r.enclosure.clone())
}

/// All roots on chains and nothing undecided; `(proven, a verified root is off every
/// chain)`.
fn check(
    sol: &Solutions,
    boxes: impl Iterator<Item = [Interval; 2]>,
    on_chain: &impl Fn(&[Interval; 2]) -> bool,
    reasons: &mut Vec<String>,
    what: &str,
) -> (bool, bool) {
    let mut good = true;
    let mut missed = false;
    if let Some(u) = sol.undecided.first() {
        good = false;
        reasons.push(format!(
            "{} undecided box(es) of the {what} system (first: {:?}: {})",
            sol.undecided.len(),
            u.enclosure,
            u.reason
        ));
    }
    let statuses: Vec<Status> = sol
        .roots
        .iter()
        .chain(&sol.boundary_roots)
        .map(|r| r.status)
        .collect();
    for (b, st) in boxes.zip(statuses) {
        if !on_chain(&b) {
            good = false;
            missed |= st == Status::Verified;
            let kind = if st == Status::Verified {
                "a contour point"
            } else {
                "a possibly singular contour point"
            };
            reasons.push(format!(
                "{kind} of the {what} system at [{:.6}, {:.6}] lies on no certified chain",
                b[0].midpoint(),
                b[1].midpoint()
            ));
        }
    }
    (good, missed)
}

/// The box `D'` and the lines `(fixed coordinate, value, is a cut)` whose roots are
/// solved (module doc).
#[allow(clippy::type_complexity)]
fn domain_and_lines<S>(
    chains: &Chains<'_, '_, S>,
    alt: bool,
) -> ([[f64; 2]; 2], Vec<(usize, f64, bool)>) {
    let mut range = chains.search;
    let mut lines = Vec::new();
    for (k, side) in range.iter_mut().enumerate() {
        let [lo, hi] = *side;
        if chains.periodic[k] {
            let c = cut(lo, chains.period[k].midpoint(), alt);
            // reach at least one full period beyond the cut (the period enclosed)
            *side = [c, next_up((Interval::point(c) + chains.period[k]).hi())];
            lines.push((k, c, true));
        } else {
            lines.push((k, lo, false));
            lines.push((k, hi, false));
        }
    }
    (range, lines)
}

/// The height whose critical system has the fewest roots on the traced chains: `u`
/// unless the contour runs mostly along `u` lines (then `∂I/∂v` is small on it).
fn pick_height<S: Surface>(chains: &Chains<'_, '_, S>, proven: &[&[Piece]]) -> usize {
    let mut score = [0.0f64; 2];
    for ps in proven {
        for p in ps.iter() {
            let r = p.region();
            let (_, g) = chains.f.with_gradient(&r[0].midpoint(), &r[1].midpoint());
            let n = g[0].hypot(g[1]);
            if n > 0.0 {
                // height h: the critical equation is ∂I/∂x_{1−h}
                score[0] += (g[1] / n).abs();
                score[1] += (g[0] / n).abs();
            }
        }
    }
    usize::from(score[1] > score[0])
}
