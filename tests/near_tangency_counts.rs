//! Near tangencies are counted right (issue 14 item 5; CERTIFICATION.md "Tangency and
//! near-tangency"): two circles at gaps `10^-k` (3 ≤ k ≤ 15) and ±1 ulp from exact
//! tangency, externally and internally, along an axis and at random angles, solved by
//! [`geocert::certify::solve`] over `[−4, 4]²`. Truth in closed form at 1100 bits
//! (`h² = ra² − ℓ²` decides 0, 1 or 2 roots; the points follow).
//!
//! Asserted for every answer: the reported boxes are pairwise disjoint; each `verified`
//! box holds exactly one true root and each `verified_singular` box at most two; with
//! `complete`, every true root lies in exactly one box and the boxes count the roots
//! (the sum of `max_roots` is at least the number of roots, and every verified box is
//! one of them); roots at least 1e-6 apart come back as two verified boxes.

mod certify_support;

use certify_support::*;
use geocert::certify::{solve, Options, Root};
use geocert::num::rng::Rng;
use geocert::num::round::{next_down, next_up};
use geocert::Status;

const DOMAIN: [[f64; 2]; 2] = [[-4.0, 4.0], [-4.0, 4.0]];

/// The checks of the module doc for one pair.
fn check(c: &Circles) -> Result<(), String> {
    let (truth, h2) = c.truth();
    let truth: Vec<Vec<rug::Float>> = truth.iter().map(as_vec).collect();
    let r = solve(c, &DOMAIN, &Options::default()).map_err(|e| format!("{e:?}"))?;
    let boxes: Vec<&Root> = r
        .value
        .roots
        .iter()
        .chain(&r.value.boundary_roots)
        .collect();
    for (i, a) in boxes.iter().enumerate() {
        for b in &boxes[i + 1..] {
            let meet = a
                .enclosure
                .iter()
                .zip(&b.enclosure)
                .all(|(x, y)| x.lo() <= y.hi() && y.lo() <= x.hi());
            if meet {
                return Err(format!("boxes meet: {a:?} and {b:?}"));
            }
        }
        let k = count_inside(a, &truth);
        match a.status {
            Status::Verified if k != 1 => return Err(format!("verified box with {k} roots")),
            Status::VerifiedSingular if k > 2 => return Err(format!("singular box, {k} roots")),
            _ => {}
        }
    }
    if r.complete {
        for t in &truth {
            let k = boxes.iter().filter(|b| encloses(b, t)).count();
            if k != 1 {
                return Err(format!("a true root in {k} boxes"));
            }
        }
        let counted: u32 = boxes.iter().map(|b| b.max_roots).sum();
        if (counted as usize) < truth.len() {
            return Err(format!("{counted} counted for {} roots", truth.len()));
        }
        if h2 > 0 {
            // two distinct roots: both proven simple (the precision cap of 512 bits
            // separates roots far closer than these)
            let v = boxes
                .iter()
                .filter(|b| b.status == Status::Verified)
                .count();
            if v != 2 || boxes.len() != 2 {
                return Err(format!(
                    "{v} verified of {} boxes for two separated roots",
                    boxes.len()
                ));
            }
        }
    }
    Ok(())
}

fn run(c: &Circles) {
    if let Err(e) = check(c) {
        panic!("{e}\ncircles: {c:?}");
    }
}

/// The case of the report: three boxes for two roots under `complete`.
#[test]
fn the_reported_pair() {
    let a = [-0.10309772611933006, 0.19004462646202946];
    run(&Circles {
        a,
        ra2: 1.0,
        ea: 0.0,
        b: [a[0] + (2.125 - 1e-11), a[1]],
        rb2: 1.265625,
    });
}

/// Gaps 10^-k and ±1 ulp around tangency, external and internal, axis-aligned and at
/// random angles.
#[test]
fn circle_pairs_near_tangency() {
    let mut g = Rng::new(1405);
    for i in 0..240 {
        let ra = 1.0 + (g.int(0, 8) as f64) / 8.0;
        let mut rb = 1.0 + (g.int(0, 8) as f64) / 8.0;
        let internal = i % 4 == 1;
        if internal && ra == rb {
            rb += 0.25;
        }
        let a = [0.5 * g.unit(), 0.5 * g.unit()];
        let touch = if internal { (ra - rb).abs() } else { ra + rb };
        let k = g.int(3, 16) as i32;
        let d = match k {
            16 => {
                // ±1 ulp of the tangent distance (or exactly it)
                match g.int(0, 2) {
                    0 => next_up(touch),
                    1 => next_down(touch),
                    _ => touch,
                }
            }
            _ => touch + 10f64.powi(-k) * if g.coin() { 1.0 } else { -1.0 },
        };
        let angle = if i % 3 == 0 {
            0.0
        } else {
            std::f64::consts::PI * (g.unit() + 1.0)
        };
        let b = [a[0] + d * angle.cos(), a[1] + d * angle.sin()];
        run(&Circles {
            a,
            ra2: ra * ra,
            ea: 0.0,
            b,
            rb2: rb * rb,
        });
    }
}
