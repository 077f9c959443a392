//! `geocert bench robustness [--seed N] [--cases N] [--threads N]`: the robustness
//! table of [`geocert::robust::table`]. Exits non-zero when geocert's certified path
//! was wrong on any case (it must never be).

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
}

pub fn run(bench: Bench) -> ExitCode {
    match bench {
        Bench::Robustness {
            seed,
            cases,
            threads,
        } => {
            let table = robustness_table(seed, cases, threads);
            print!("{table}");
            if table.certified_failures() == 0 {
                ExitCode::SUCCESS
            } else {
                eprintln!("geocert bench robustness: the certified path was wrong");
                ExitCode::from(1)
            }
        }
    }
}
