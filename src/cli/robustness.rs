//! `geocert bench robustness [--seed N] [--cases N] [--threads N]`: the robustness
//! table of [`geocert::robust::table`]. Exits non-zero when geocert's certified path
//! was wrong on any case (it must never be). `geocert bench cases`: seeded case files
//! for measuring `solve` ([`super::generate`]).

use super::generate::{self, Family};
use super::progress;
use clap::Subcommand;
use geocert::robust::robustness_table;
use std::process::ExitCode;

/// The benchmarks the binary runs itself (speed is measured by criterion in benches/).
#[derive(Subcommand)]
pub enum Bench {
    /// Count wrong verdicts and coordinates off by more than one ulp for plain f64,
    /// CGAL Epick (if built in), geocert's float-only filter and geocert certified, on
    /// seeded generic, grid, degenerate, one-ulp and mixed-magnitude cases, and on the
    /// Kettner et al. near-collinear orientation grid.
    Robustness {
        /// The seed: the same seed gives the same table.
        #[arg(long, default_value_t = 1)]
        seed: u64,
        /// Cases per construction and generator.
        #[arg(long, default_value_t = 10_000)]
        cases: usize,
        /// Worker threads (the table does not depend on it).
        #[arg(long, default_value_t = 2)]
        threads: usize,
    },
    /// Write a seeded file of cases to standard output (JSON Lines), to time
    /// `geocert solve` on large inputs without storing them.
    Cases {
        /// `line-plane` (fast, filter-decided) or `curved` (certified numerically).
        #[arg(value_enum)]
        family: Family,
        /// How many cases.
        #[arg(long, default_value_t = 1000)]
        count: u64,
        /// The seed: the same seed gives the same bytes.
        #[arg(long, default_value_t = 1)]
        seed: u64,
    },
}

pub fn run(bench: Bench, show_progress: bool) -> ExitCode {
    match bench {
        Bench::Robustness {
            seed,
            cases,
            threads,
        } => {
            let spinner = progress::spinner(show_progress, "geocert bench robustness");
            let table = robustness_table(seed, cases, threads);
            spinner.finish_and_clear();
            print!("{table}");
            if table.certified_failures() == 0 {
                ExitCode::SUCCESS
            } else {
                eprintln!("geocert bench robustness: the certified path was wrong");
                ExitCode::from(1)
            }
        }
        Bench::Cases {
            family,
            count,
            seed,
        } => match generate::run(family, count, seed) {
            Ok(()) => ExitCode::SUCCESS,
            Err(e) => {
                eprintln!("geocert bench cases: cannot write to standard output: {e}");
                ExitCode::from(super::exit::WRITE_FAILED)
            }
        },
    }
}
