//! `geocert bench robustness [--seed N] [--cases N] [--curved-cases N] [--threads N]
//! [--json FILE] [--plots DIR]`: the robustness report of [`geocert::robust::report`]
//! (the linear table with the Kettner grid, and the curved near-tangency table), as
//! text on standard output, JSON in a file, and plots ([`geocert::robust::plot`]).
//! Exits non-zero when geocert's certified path was wrong on any case (it must never be). `geocert bench cases`: seeded case files
//! for measuring `solve` ([`super::generate`]).

use super::generate::{self, Family};
use super::progress;
use clap::Subcommand;
use geocert::robust::{kettner, plot, Report};
use std::path::PathBuf;
use std::process::ExitCode;

/// The benchmarks the binary runs itself (speed is measured by criterion in benches/).
#[derive(Subcommand)]
pub enum Bench {
    /// Count wrong verdicts and coordinates off by more than one ulp for plain f64,
    /// CGAL Epick (if built in), geocert's float-only filter and geocert certified, on
    /// seeded generic, grid, degenerate, one-ulp and mixed-magnitude cases, and on the
    /// Kettner et al. near-collinear orientation grid; and, on tangent and near-tangent
    /// curved pairs (gaps 1e-3 to 1e-15, 1 ulp, 0), geocert's float path against its
    /// certified path.
    Robustness {
        /// The seed: the same seed gives the same table.
        #[arg(long, default_value_t = 1)]
        seed: u64,
        /// Cases per construction and generator.
        #[arg(long, default_value_t = 10_000)]
        cases: usize,
        /// Cases per curved family and gap.
        #[arg(long, default_value_t = 40)]
        curved_cases: usize,
        /// Worker threads (the table does not depend on it).
        #[arg(long, default_value_t = 2)]
        threads: usize,
        /// Also write the whole report (linear and curved) as JSON to this file.
        #[arg(long, value_name = "FILE")]
        json: Option<PathBuf>,
        /// Also draw the plots (Kettner sign maps as PNG, float failure rate and
        /// certification cost against the gap as SVG) into this directory.
        #[arg(long, value_name = "DIR")]
        plots: Option<PathBuf>,
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
            curved_cases,
            threads,
            json,
            plots,
        } => {
            let spinner = progress::spinner(show_progress, "geocert bench robustness");
            let report = Report::run(seed, cases, curved_cases, threads);
            spinner.finish_and_clear();
            print!("{report}");
            if let Err(code) = write_outputs(&report, json, plots) {
                return code;
            }
            if report.certified_failures() == 0 {
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

/// The JSON file and the plots, if asked for.
fn write_outputs(
    report: &Report,
    json: Option<PathBuf>,
    plots: Option<PathBuf>,
) -> Result<(), ExitCode> {
    let failed = |what: &str, path: &PathBuf, e: &dyn std::fmt::Display| {
        eprintln!(
            "geocert bench robustness: cannot write {what} {}: {e}",
            path.display()
        );
        ExitCode::from(super::exit::WRITE_FAILED)
    };
    if let Some(path) = json {
        let mut text = serde_json::to_string_pretty(&report.to_json())
            .map_err(|e| failed("the JSON", &path, &e))?;
        text.push('\n');
        std::fs::write(&path, text).map_err(|e| failed("the JSON", &path, &e))?;
    }
    if let Some(dir) = plots {
        plot::write_plots(&dir, &kettner::sign_map(), &report.curved)
            .map_err(|e| failed("the plots into", &dir, &e.0))?;
    }
    Ok(())
}
