//! The curved table: per family and gap, how often geocert's float path gets the
//! number of points wrong or a point off, whether the certified path was ever wrong
//! (it must never be), how often it is undecided, and what its certificate cost in
//! deterministic units: the precision in bits that decided it ([`crate::Certified`]'s
//! `bits`: the MPFR precision for the numeric certifier, the largest exact number's bit
//! length for the exact solvers), never wall time.

use std::fmt;

use super::paths::{run, Outcome, TOLERANCE};
use super::{case, Family, Gap};
use crate::num::rng::Rng;

/// One family at one gap.
#[derive(Debug, Clone, PartialEq)]
pub struct CurvedRow {
    pub family: Family,
    pub gap: Gap,
    pub cases: usize,
    /// Cases whose truth has at least one common point.
    pub meeting: usize,
    pub float_wrong_count: usize,
    pub float_off: usize,
    pub certified_wrong: usize,
    pub certified_undecided: usize,
    /// The sum and the largest of the certificates' `bits`.
    pub bits_sum: u64,
    pub bits_max: u32,
    /// How many certificates each arithmetic decided, by name, in the order of
    /// [`crate::Arithmetic`]'s first appearance.
    pub arithmetic: Vec<(&'static str, usize)>,
}

impl CurvedRow {
    /// The mean of the certificates' `bits` (0 without cases).
    pub fn bits_mean(&self) -> f64 {
        if self.cases == 0 {
            0.0
        } else {
            self.bits_sum as f64 / self.cases as f64
        }
    }

    /// The fraction of cases where the float path was wrong (count or points).
    pub fn float_failure_rate(&self) -> f64 {
        if self.cases == 0 {
            0.0
        } else {
            (self.float_wrong_count + self.float_off) as f64 / self.cases as f64
        }
    }

    fn add(&mut self, o: &Outcome) {
        self.cases += 1;
        self.meeting += (o.truth_count > 0) as usize;
        self.float_wrong_count += o.float_wrong_count as usize;
        self.float_off += o.float_off as usize;
        self.certified_wrong += o.certified_wrong as usize;
        self.certified_undecided += o.certified_undecided as usize;
        self.bits_sum += u64::from(o.bits);
        self.bits_max = self.bits_max.max(o.bits);
        let name = o.arithmetic.map_or("error", |a| a.as_str());
        match self.arithmetic.iter_mut().find(|(n, _)| *n == name) {
            Some((_, k)) => *k += 1,
            None => self.arithmetic.push((name, 1)),
        }
    }
}

/// The whole curved table.
#[derive(Debug, Clone, PartialEq)]
pub struct CurvedTable {
    pub seed: u64,
    /// Cases per family and gap.
    pub cases: usize,
    pub rows: Vec<CurvedRow>,
}

impl CurvedTable {
    /// Wrong certified answers (must be 0).
    pub fn certified_failures(&self) -> usize {
        self.rows.iter().map(|r| r.certified_wrong).sum()
    }
}

/// The seeds of the cases of one row: a stream per (seed, family, gap).
fn case_seeds(seed: u64, family: Family, gap_index: usize) -> impl Iterator<Item = u64> {
    let fi = Family::ALL.iter().position(|&x| x == family).unwrap_or(0) as u64;
    // Distinct from the linear rows' streams (their tag bits are 48..63 of the seed).
    let mut rng = Rng::new(seed ^ 0x00c0_ffee ^ (fi << 40) ^ ((gap_index as u64) << 32));
    std::iter::from_fn(move || Some(rng.next_u64()))
}

/// One row.
pub fn curved_row(seed: u64, cases: usize, family: Family, gap_index: usize) -> CurvedRow {
    let gap = Gap::all()[gap_index];
    let mut row = CurvedRow {
        family,
        gap,
        cases: 0,
        meeting: 0,
        float_wrong_count: 0,
        float_off: 0,
        certified_wrong: 0,
        certified_undecided: 0,
        bits_sum: 0,
        bits_max: 0,
        arithmetic: Vec::new(),
    };
    for s in case_seeds(seed, family, gap_index).take(cases) {
        row.add(&run(&case(family, gap, s)));
    }
    row
}

/// Run `f` on every job on up to `threads` threads; the results in job order.
pub(crate) fn in_parallel<J: Sync, R: Send>(
    jobs: &[J],
    threads: usize,
    f: impl Fn(&J) -> R + Sync,
) -> Vec<R> {
    let threads = threads.clamp(1, jobs.len().max(1));
    let mut out: Vec<Option<R>> = (0..jobs.len()).map(|_| None).collect();
    std::thread::scope(|s| {
        let f = &f;
        let handles: Vec<_> = (0..threads)
            .map(|t| {
                s.spawn(move || {
                    (t..jobs.len())
                        .step_by(threads)
                        .map(|k| (k, f(&jobs[k])))
                        .collect::<Vec<_>>()
                })
            })
            .collect();
        for h in handles {
            match h.join() {
                Ok(done) => done.into_iter().for_each(|(k, r)| out[k] = Some(r)),
                Err(e) => std::panic::resume_unwind(e),
            }
        }
    });
    out.into_iter().flatten().collect()
}

/// The curved table for `seed`, `cases` cases per family and gap, on up to `threads`
/// threads (the result does not depend on the thread count).
pub fn curved_table(seed: u64, cases: usize, threads: usize) -> CurvedTable {
    let jobs: Vec<(Family, usize)> = Family::ALL
        .iter()
        .flat_map(|&f| (0..Gap::all().len()).map(move |g| (f, g)))
        .collect();
    let rows = in_parallel(&jobs, threads, |&(f, g)| curved_row(seed, cases, f, g));
    CurvedTable { seed, cases, rows }
}

impl fmt::Display for CurvedTable {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        writeln!(
            f,
            "Curved near-tangencies: seed {}, {} cases per family and gap (a radius scaled by 1 +- gap,\n\
             moved by one ulp, or exactly tangent); truth: exact rational root counts, points at 300 bits.\n\
             meet = cases whose truth has common points. float = geocert's _f64 solvers seeded by the walks\n\
             (no proof): count = wrong number of points, off = a point farther than {:e} x scale from the truth.\n\
             certified = ops::intersect: wrong must be 0; undec = undecided or not complete; bits = the\n\
             precision that decided (MPFR bits, or the largest exact number's bit length), mean and max.\n",
            self.seed, self.cases, TOLERANCE
        )?;
        writeln!(
            f,
            "{:<17} {:>5} {:>5} {:>4} | {:>5} {:>5} | {:>5} {:>5} | {:>7} {:>5} | arithmetic",
            "family", "gap", "cases", "meet", "count", "off", "wrong", "undec", "bits", "max"
        )?;
        writeln!(f, "{}", "-".repeat(96))?;
        for r in &self.rows {
            let arith: Vec<String> = r
                .arithmetic
                .iter()
                .map(|(n, k)| format!("{n} {k}"))
                .collect();
            writeln!(
                f,
                "{:<17} {:>5} {:>5} {:>4} | {:>5} {:>5} | {:>5} {:>5} | {:>7.1} {:>5} | {}",
                r.family.name(),
                r.gap.label(),
                r.cases,
                r.meeting,
                r.float_wrong_count,
                r.float_off,
                r.certified_wrong,
                r.certified_undecided,
                r.bits_mean(),
                r.bits_max,
                arith.join(", ")
            )?;
        }
        Ok(())
    }
}
