//! Certify one root given as a float estimate (for instance a Newton result of an
//! operation's fast path): docs/CERTIFICATES.md "verified" for a single solution, with the
//! escalation f64 intervals → MPFR 128, 256, … bits, and the singular certificate when
//! the root is (nearly) double.

use super::boxes::{self, IBox};
use super::cluster::{decide_cluster, ClusterVerdict};
use super::krawczyk::{verify_near, VerifiedRoot};
use super::level::{box_to_f64, box_to_mpfr, levels, CertInterval};
use super::newton::{newton_f64, newton_point};
use super::system::{check_point, check_system, System};
use super::{Options, Root};
use crate::certificate::{Certified, Status};
use crate::error::GeomError;
use crate::num::{Interval, MpfrInterval};

/// Certify a root of `sys` near `guess` (module doc): the root that f64 Newton from
/// `guess` converges to, proven in a box of width at most `10⁻³·max(1, |x|)` around
/// Newton's answer (or, failing that, the cluster tests on a box of radius
/// `10⁻⁶·max(1, |x|)` around it and the guess). The result is `verified` (a box in
/// which the root exists and is unique; `max_roots = 1`), `verified_singular` (a box with
/// at most two roots counted with multiplicity and a double root of a perturbed system),
/// or `undecided` with the reason (the estimate is then the f64 Newton iterate). It says
/// nothing about other roots elsewhere, so `complete` is false.
///
/// Errors: a guess of the wrong length or with a non-finite coordinate (field `guess`),
/// invalid options, a system of unsupported size or whose `eval` returns the wrong
/// number of values.
pub fn certify_root<S: System>(
    sys: &S,
    guess: &[f64],
    opts: &Options,
) -> Result<Certified<Root>, GeomError> {
    opts.check()?;
    check_point("guess", guess, sys.dim())?;
    check_system(sys, guess)?;
    let (x, step) = newton_f64(sys, guess, 12)
        .filter(|(x, _)| x.iter().all(|v| v.is_finite()))
        .unwrap_or((guess.to_vec(), f64::INFINITY));
    let levels = levels(opts.max_bits);
    for &bits in &levels {
        if opts.late() {
            return Ok(undecided(&x, super::TIME_LIMIT.into()));
        }
        let found = if bits == 53 {
            certify_at::<S, Interval>(sys, &x, step, bits)
        } else {
            certify_at::<S, MpfrInterval>(sys, &x, step, bits)
        };
        if let Some(root) = found {
            return Ok(verified(root));
        }
    }
    let mut singular = None;
    for &bits in &levels {
        if opts.late() {
            break;
        }
        let found = if bits == 53 {
            singular_at::<S, Interval>(sys, &x, guess, bits)
        } else {
            singular_at::<S, MpfrInterval>(sys, &x, guess, bits)
        };
        match found {
            Some(Outcome::Root(root)) if root.status == Status::Verified => {
                return Ok(verified(root))
            }
            // the weakest verdict: a higher precision may still separate two roots
            Some(Outcome::Root(root)) => {
                singular.get_or_insert(root);
            }
            Some(Outcome::NoRoot(reason)) => return Ok(undecided(&x, reason)),
            None => {}
        }
    }
    if let Some(root) = singular {
        return Ok(verified(root));
    }
    if opts.late() {
        return Ok(undecided(&x, super::TIME_LIMIT.into()));
    }
    let reason = format!(
        "no proof up to the precision cap of {} bits",
        levels.last().copied().unwrap_or(53)
    );
    Ok(undecided(&x, reason))
}

/// One escalation level of [`certify_root`]: certify the root near the point `x` with
/// Krawczyk at `bits` bits only (53: f64 intervals; more: MPFR, after Newton at that
/// precision), without the singular test; `Ok(None)` if that precision does not prove it.
/// Errors as [`certify_root`].
pub fn certify_root_at<S: System>(
    sys: &S,
    x: &[f64],
    bits: u32,
) -> Result<Option<Root>, GeomError> {
    check_point("guess", x, sys.dim())?;
    check_system(sys, x)?;
    Ok(if bits <= 53 {
        certify_at::<S, Interval>(sys, x, 0.0, 53)
    } else {
        certify_at::<S, MpfrInterval>(sys, x, 0.0, bits)
    })
}

/// Certify the root near `x` at one precision: refine by Newton at that precision, then
/// Krawczyk with epsilon-inflation from a box of the refined point's expected accuracy.
fn certify_at<S: System, I: CertInterval>(
    sys: &S,
    x: &[f64],
    step: f64,
    bits: u32,
) -> Option<Root> {
    let x0: IBox<I> = x
        .iter()
        .map(|&v| I::from_mpfr(&MpfrInterval::point(v, 53), bits))
        .collect();
    let (xc, r_rel) = if bits == 53 {
        (x0, step)
    } else {
        (newton_point(sys, &x0, 30)?.0, 0.0)
    };
    // a box a few hundred units in the last place wide: wider than the Newton point's
    // error and K's rounding, so one Krawczyk step usually proves it
    let scale = xc.iter().map(|v| v.mag()).fold(1.0, f64::max);
    let ulps = (-(f64::from(bits) - 8.0)).exp2() * scale;
    let radius: Vec<f64> = xc.iter().map(|_| (2.0 * r_rel).max(ulps)).collect();
    let v = verify_near(sys, &xc, &radius, 1e-3 * scale)?;
    Some(root_of(&v, bits))
}

enum Outcome {
    Root(Root),
    NoRoot(String),
}

/// The cluster tests on a small box around `x` (and the guess).
fn singular_at<S: System, I: CertInterval>(
    sys: &S,
    x: &[f64],
    guess: &[f64],
    bits: u32,
) -> Option<Outcome> {
    let r = 1e-6 * x.iter().fold(1.0f64, |m, v| m.max(v.abs()));
    let around = |p: &[f64]| -> IBox<I> {
        p.iter()
            .map(|&v| I::from_mpfr(&MpfrInterval::from_bounds(v - r, v + r, 53), bits))
            .collect()
    };
    let hull = boxes::hull(&around(x), &around(guess));
    match decide_cluster(sys, &hull)? {
        ClusterVerdict::NoRoot => Some(Outcome::NoRoot(format!(
            "proven: no root within {r:e} of the estimate"
        ))),
        ClusterVerdict::TwoRoots(roots) => {
            // the root nearer to the guess
            let dist = |v: &VerifiedRoot<I>| {
                boxes::midpoint_f64(&v.enclosure)
                    .iter()
                    .zip(guess)
                    .map(|(a, b)| (a - b).abs())
                    .fold(0.0, f64::max)
            };
            let best = roots.iter().min_by(|a, b| dist(a).total_cmp(&dist(b)))?;
            Some(Outcome::Root(root_of(best, bits)))
        }
        ClusterVerdict::Singular {
            enclosure,
            double_root,
        } => Some(Outcome::Root(Root {
            enclosure: box_to_f64(&enclosure),
            enclosure_mpfr: box_to_mpfr(&enclosure),
            estimate: boxes::midpoint_f64(&double_root.x),
            status: Status::VerifiedSingular,
            bits,
            perturbation: Some(double_root.perturbation()),
            max_roots: 2,
        })),
    }
}

fn root_of<I: CertInterval>(v: &VerifiedRoot<I>, bits: u32) -> Root {
    Root {
        enclosure: box_to_f64(&v.enclosure),
        enclosure_mpfr: box_to_mpfr(&v.enclosure),
        estimate: boxes::midpoint_f64(&v.enclosure),
        status: Status::Verified,
        bits,
        perturbation: None,
        max_roots: 1,
    }
}

fn verified(root: Root) -> Certified<Root> {
    Certified {
        status: root.status,
        complete: false,
        arithmetic: crate::certificate::Arithmetic::of_interval_bits(root.bits),
        bits: root.bits,
        reason: None,
        perturbation: root.perturbation,
        value: root,
    }
}

fn undecided(x: &[f64], reason: String) -> Certified<Root> {
    let root = Root {
        enclosure: x.iter().map(|&v| Interval::point(v)).collect(),
        enclosure_mpfr: x.iter().map(|&v| MpfrInterval::point(v, 53)).collect(),
        estimate: x.to_vec(),
        status: Status::Undecided,
        bits: 53,
        perturbation: None,
        max_roots: 0,
    };
    Certified::undecided(root, crate::certificate::Arithmetic::Float, 53, reason)
}
