//! Certification machinery (ARCHITECTURE.md layer `certify/`, docs/CERTIFICATES.md):
//! proofs of existence, uniqueness and absence of roots of square systems `F(x) = 0` of
//! size 1 to 6, independent of geometry. An operation writes its system once, generic
//! over [`crate::num::Real`] ([`System`]); this module evaluates it in f64 (Newton), in
//! f64 intervals and in MPFR intervals, and differentiates it by dual numbers.
//!
//! * [`certify_root`] — certify one float answer: Krawczyk with epsilon-inflation around
//!   it, escalating f64 intervals → MPFR 128, 256, 512, … bits up to
//!   [`Options::max_bits`], then the singular certificate.
//! * [`solve`] — every root in a parameter box: subdivision with exclusion tests
//!   (the interval image misses 0, or the Krawczyk image misses the box), uniqueness
//!   tests, a box budget and precision escalation; `complete` exactly when nothing is
//!   left undecided.
//!
//! Verdicts (docs/CERTIFICATES.md "The four statuses"):
//! * `verified` ([`Status::Verified`]): `Root::enclosure` contains exactly one root — the
//!   Krawczyk operator ([`krawczyk`]) maps a box into its interior;
//! * `verified_singular` ([`Status::VerifiedSingular`]): `Root::enclosure` contains at
//!   most two roots counted with multiplicity ([`count`]: a reduction to one variable
//!   and Rolle's theorem) and a double root of the system with one equation perturbed by
//!   a constant of size at most `Root::perturbation` ([`deflate`], after Rump and
//!   Graillat, Numer. Algorithms 54, 2010);
//! * exclusion: a box is dropped only with a proof that it holds no root (its image
//!   misses 0 or is empty — the system is defined nowhere in it —, its Krawczyk image
//!   misses it, or the one-variable reduction is bounded away from 0).
//!
//! Nothing is concluded where the system is not proven smooth ([`guarded`]): a system
//! may be defined on part of space only (a `sqrt`, a division).
//!
//! * [`univariate`] — exact real roots of univariate polynomials with rational
//!   coefficients (square-free decomposition, Sturm sequences, correct rounding), so
//!   that algebraic problems are decided `exact` (double roots with multiplicity 2).
//!
//! Precision: each root reports the precision (`bits`: 53 for f64 intervals) of the
//! proof that decided it; a result's `bits` is the highest precision that decided any
//! part of it.

pub mod boxes;
pub mod cluster;
pub mod count;
pub mod deflate;
pub mod dual;
pub mod graph;
pub mod guarded;
pub mod joined;
pub mod krawczyk;
mod ledger;
pub mod level;
pub mod linalg;
pub mod newton;
mod root;
mod solve;
pub mod subdivide;
pub mod system;
pub mod univariate;

pub use root::{certify_root, certify_root_at};
pub use solve::solve;
pub use system::System;

use crate::certificate::Status;
use crate::error::GeomError;
use crate::num::{Interval, MpfrInterval};

/// Limits of a certification run.
#[derive(Debug, Clone, PartialEq)]
pub struct Options {
    /// The most boxes [`solve`] may process, all precisions together (a cluster attempt
    /// counts as 16). Boxes left when it is spent are reported undecided.
    pub max_boxes: usize,
    /// The highest MPFR precision escalation may use (bits); below 128 only f64
    /// intervals are used. Default 512.
    pub max_bits: u32,
    /// Boxes narrower than this in every coordinate are not split further at the current
    /// precision but handed to the cluster tests and escalation (0: only the
    /// precision-based width of [`subdivide::stuck_width`]).
    pub min_width: f64,
    /// A wall-clock deadline, checked with every box taken from the budget: once it has
    /// passed, the boxes left are reported undecided ("time limit reached"), as when the
    /// budget is spent. `None`: no limit (the answer then never depends on timing).
    pub deadline: Option<std::time::Instant>,
}

impl Default for Options {
    fn default() -> Self {
        Options {
            max_boxes: 20_000,
            max_bits: 512,
            min_width: 0.0,
            deadline: None,
        }
    }
}

/// The reason recorded when the deadline has passed (also `Ledger::spent`).
pub const TIME_LIMIT: &str = "time limit reached";

/// Whether `deadline` has passed (one `Instant::now()`; `None` never passes). The
/// cooperative check of issue 20: every long loop of the certifier and of the float
/// searches before it calls this once per iteration (batch).
pub fn past(deadline: Option<std::time::Instant>) -> bool {
    deadline.is_some_and(|d| std::time::Instant::now() >= d)
}

impl Options {
    /// Whether [`Options::deadline`] has passed ([`past`]).
    pub fn late(&self) -> bool {
        past(self.deadline)
    }

    /// Reject a negative or non-finite `min_width` (field `options.min_width`).
    pub fn check(&self) -> Result<(), GeomError> {
        if !(self.min_width >= 0.0 && self.min_width.is_finite()) {
            return Err(GeomError::InvalidValue {
                field: "options.min_width".into(),
                reason: format!("{} is not a finite width ≥ 0", self.min_width),
            });
        }
        Ok(())
    }
}

/// A certified root (or, for `verified_singular`, a certified box of at most two roots).
#[derive(Debug, Clone, PartialEq)]
pub struct Root {
    /// The box, outward rounded to doubles: it contains the root (`verified`: exactly one
    /// root; `verified_singular`: at most two counted with multiplicity, and the double
    /// root of the perturbed system).
    pub enclosure: Vec<Interval>,
    /// The same box at the precision that decided it (narrower than `enclosure` when the
    /// root was resolved below f64 resolution).
    pub enclosure_mpfr: Vec<MpfrInterval>,
    /// A point estimate (the enclosure's midpoint; for `verified_singular`, the double
    /// root of the perturbed system).
    pub estimate: Vec<f64>,
    /// `Verified`, `VerifiedSingular` (or `Undecided` from [`certify_root`]).
    pub status: Status,
    /// The precision of the deciding proof (53 = f64 intervals).
    pub bits: u32,
    /// For `verified_singular`: an upper bound of `|e|`, the constant by which one
    /// equation is perturbed to have a double root in the box.
    pub perturbation: Option<f64>,
    /// The most roots the box holds, counted with multiplicity (1 for `verified`, 2 for
    /// `verified_singular`, 0 when nothing is claimed).
    pub max_roots: u32,
}

/// A box [`solve`] could not decide, and why (budget spent, precision cap reached, ...).
#[derive(Debug, Clone, PartialEq)]
pub struct UndecidedBox {
    /// The box (outward in doubles); any root not in a reported root box lies in one of these.
    pub enclosure: Vec<Interval>,
    /// Why it is undecided.
    pub reason: String,
}

/// All roots of a system in a domain, as proven by [`solve`].
#[derive(Debug, Clone, PartialEq)]
pub struct Solutions {
    /// Roots whose enclosure lies in the (closed) domain.
    pub roots: Vec<Root>,
    /// Roots proven to exist whose enclosure straddles the domain's boundary: each lies on
    /// or near the boundary, possibly just outside.
    pub boundary_roots: Vec<Root>,
    /// The parts of the domain not decided. Empty exactly when the result is `complete`:
    /// then every root in the domain lies in a box of `roots` or `boundary_roots`.
    pub undecided: Vec<UndecidedBox>,
    /// The volume of the boxes proven root-free (an f64 sum, for reporting).
    pub excluded_volume: f64,
    /// The volume of the domain.
    pub domain_volume: f64,
    /// The boxes processed (against [`Options::max_boxes`]).
    pub boxes: usize,
}
