//! The robustness table: for every construction and generator, how often each method
//! is wrong against the exact truth (OPERATIONS.md constructions, truth from geocert's
//! `_exact` rational procedures, which tests/diff_*.rs checks against CGAL's Epeck).
//!
//! Columns: plain f64 (geocert `_f64`), CGAL Epick (feature `cgal`), geocert's
//! float-only path (the double-double filter tier alone: it answers only when its
//! error bound decides, so it is never wrong, and the table counts how often it
//! abstains), and geocert certified (must be 0). "verdict" counts wrong kinds, ">1ulp"
//! answers of the right kind with a coordinate more than one ulp from the correctly
//! rounded truth; for the certified path any coordinate that is not exactly the
//! correct rounding (nearest and enclosure) counts.

use std::fmt;

use super::answer::{grade, grade_certified, rounded_truth, Grade};
use super::gen::{case, Construction, Generator};
use super::kettner::{self, KettnerCounts};
use super::methods;
use crate::certificate::Arithmetic;
use crate::num::rng::Rng;

/// Wrong verdicts and coordinates off by more than one ulp.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct Errors {
    pub verdict: usize,
    pub off: usize,
    /// Cases the method was not asked (CGAL Epick outside its safe window,
    /// [`super::methods::epick_safe`]).
    pub not_run: usize,
}

impl Errors {
    fn add(&mut self, g: Grade) {
        match g {
            Grade::Right => {}
            Grade::Off => self.off += 1,
            Grade::WrongKind => self.verdict += 1,
        }
    }
    pub fn total(&self) -> usize {
        self.verdict + self.off
    }
}

/// One row: a construction on one generator.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Row {
    pub construction: Construction,
    pub generator: Generator,
    pub cases: usize,
    pub plain: Errors,
    /// `None` without the `cgal` feature.
    pub epick: Option<Errors>,
    /// Cases the filter tier left to the exact tiers.
    pub filter_undecided: usize,
    /// Wrong answers of the filter tier where it decided (0 unless its bound is wrong).
    pub filter_wrong: usize,
    pub certified: Errors,
}

/// The whole table.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Table {
    pub seed: u64,
    pub cases: usize,
    pub rows: Vec<Row>,
    pub kettner: KettnerCounts,
}

impl Table {
    /// Wrong certified answers over all rows and the Kettner grid (must be 0).
    pub fn certified_failures(&self) -> usize {
        self.rows
            .iter()
            .map(|r| r.certified.total() + r.filter_wrong)
            .sum::<usize>()
            + self.kettner.certified_wrong
    }
}

/// The seed of case `i` of a row: a stream per (seed, construction, generator).
pub fn case_seeds(seed: u64, c: Construction, g: Generator) -> impl Iterator<Item = u64> {
    let ci = Construction::ALL.iter().position(|&x| x == c).unwrap_or(0) as u64;
    let gi = Generator::ALL.iter().position(|&x| x == g).unwrap_or(0) as u64;
    let mut rng = Rng::new(seed ^ (ci << 56) ^ (gi << 48));
    std::iter::from_fn(move || Some(rng.next_u64()))
}

/// One row of the table.
pub fn row(seed: u64, cases: usize, c: Construction, g: Generator) -> Row {
    let mut r = Row {
        construction: c,
        generator: g,
        cases: 0,
        plain: Errors::default(),
        epick: if cfg!(feature = "cgal") {
            Some(Errors::default())
        } else {
            None
        },
        filter_undecided: 0,
        filter_wrong: 0,
        certified: Errors::default(),
    };
    for s in case_seeds(seed, c, g).take(cases) {
        let case = case(c, g, s);
        let Some(a) = methods::geocert(&case) else {
            // Unreachable: generated cases are valid for geocert. Count as a failure.
            r.certified.verdict += 1;
            continue;
        };
        r.cases += 1;
        let truth_r = rounded_truth(&a.truth);
        r.plain.add(grade(&a.plain, &a.truth, &truth_r));
        let gc = grade_certified(&a.certified, &a.truth, &truth_r);
        r.certified.add(gc);
        if a.arithmetic == Arithmetic::Filter {
            r.filter_wrong += (gc != Grade::Right) as usize;
        } else {
            r.filter_undecided += 1;
        }
        #[cfg(feature = "cgal")]
        if let Some(e) = r.epick.as_mut() {
            match methods::epick(&case) {
                Some(ans) => e.add(grade(&ans, &a.truth, &truth_r)),
                None => e.not_run += 1,
            }
        }
    }
    r
}

/// The table for `seed`, `cases` cases per row, rows on up to `threads` threads
/// (the result does not depend on the thread count).
pub fn robustness_table(seed: u64, cases: usize, threads: usize) -> Table {
    let jobs: Vec<(Construction, Generator)> = Construction::ALL
        .iter()
        .flat_map(|&c| Generator::ALL.iter().map(move |&g| (c, g)))
        .collect();
    let threads = threads.clamp(1, jobs.len());
    let mut rows: Vec<Option<Row>> = vec![None; jobs.len()];
    std::thread::scope(|s| {
        let handles: Vec<_> = (0..threads)
            .map(|t| {
                let jobs = &jobs;
                s.spawn(move || {
                    (t..jobs.len())
                        .step_by(threads)
                        .map(|k| (k, row(seed, cases, jobs[k].0, jobs[k].1)))
                        .collect::<Vec<_>>()
                })
            })
            .collect();
        for h in handles {
            if let Ok(done) = h.join() {
                for (k, r) in done {
                    rows[k] = Some(r);
                }
            }
        }
    });
    Table {
        seed,
        cases,
        rows: rows.into_iter().flatten().collect(),
        kettner: kettner::grid(),
    }
}

fn errors(e: &Option<Errors>) -> (String, String, String) {
    match e {
        Some(e) => (
            e.verdict.to_string(),
            e.off.to_string(),
            e.not_run.to_string(),
        ),
        None => ("-".into(), "-".into(), "-".into()),
    }
}

impl fmt::Display for Table {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        self.fmt_rows(f)?;
        self.fmt_kettner(f)?;
        writeln!(
            f,
            "\ngeocert certified: {} wrong answers in total.",
            self.certified_failures()
        )
    }
}

impl Table {
    /// The header (seed, what the columns count) and a row per construction and generator.
    pub(crate) fn fmt_rows(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let cgal = self.rows.first().is_some_and(|r| r.epick.is_some());
        writeln!(
            f,
            "geocert robustness table: seed {}, {} cases per row; truth: exact rationals.",
            self.seed, self.cases
        )?;
        if !cgal {
            writeln!(
                f,
                "CGAL is not built in (build with --features cgal for the Epick columns)."
            )?;
        }
        writeln!(
            f,
            "Counts of wrong answers: verdict = wrong kind; >1ulp = right kind, a coordinate more than one ulp\n\
             from the correctly rounded truth (certified: not exactly the correct rounding); coordinates\n\
             are compared for points, feet and segment ends (lines and planes: kind only).\n\
             float-only = geocert's filter tier alone: abstains (undecided) rather than errs.\n\
             Epick \"not run\": inputs outside [2^-60, 2^60] (2D: 2^-200..2^200), where an overflowing\n\
             Epick construction makes GMP raise SIGFPE and kills the process.\n"
        )?;
        writeln!(
            f,
            "{:<19} {:<13} {:>7} | {:>8} {:>6} | {:>8} {:>6} {:>7} | {:>10} {:>6} | {:>8} {:>6}",
            "", "", "", "plain", "f64", "CGAL", "Epick", "", "float-only", "", "certi", "fied"
        )?;
        writeln!(
            f,
            "{:<19} {:<13} {:>7} | {:>8} {:>6} | {:>8} {:>6} {:>7} | {:>10} {:>6} | {:>8} {:>6}",
            "construction",
            "generator",
            "cases",
            "verdict",
            ">1ulp",
            "verdict",
            ">1ulp",
            "not run",
            "undecided",
            "wrong",
            "verdict",
            ">1ulp"
        )?;
        writeln!(f, "{}", "-".repeat(120))?;
        for r in &self.rows {
            let (ev, eo, en) = errors(&r.epick);
            writeln!(
                f,
                "{:<19} {:<13} {:>7} | {:>8} {:>6} | {:>8} {:>6} {:>7} | {:>10} {:>6} | {:>8} {:>6}",
                r.construction.name(),
                r.generator.name(),
                r.cases,
                r.plain.verdict,
                r.plain.off,
                ev,
                eo,
                en,
                r.filter_undecided,
                r.filter_wrong,
                r.certified.verdict,
                r.certified.off
            )?;
        }
        Ok(())
    }

    /// The Kettner et al. near-collinear grid's line.
    pub(crate) fn fmt_kettner(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let k = &self.kettner;
        writeln!(f)?;
        writeln!(
            f,
            "Kettner et al. near-collinear grid: p = (0.5 + i*2^-53, 0.5 + j*2^-53), 0 <= i, j < 256, q = (12, 12), r = (24, 24)"
        )?;
        writeln!(
            f,
            "  {} points, {} exactly collinear; wrong orientation signs: plain f64 {}, geocert certified {} \
             (filter undecided on {});",
            k.points, k.collinear, k.plain_wrong, k.certified_wrong, k.filter_undecided
        )?;
        match k.epick_wrong {
            Some(w) => writeln!(
                f,
                "  CGAL Epick (collinearity only: the oracle has no orientation predicate; decided by\n  \
                 intersecting Line_2(p, r-q) with Line_2(q, r-q)): {w} wrong collinear/not-collinear verdicts."
            )?,
            None => writeln!(f, "  CGAL Epick: not built in.")?,
        }
        Ok(())
    }
}
