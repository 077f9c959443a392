//! The `geocert` command line: `solve`, `verify`, `demo` (and, as later issues land,
//! `bench`, `render`).

mod cli;

use clap::{Parser, Subcommand};
use std::process::ExitCode;

#[derive(Parser)]
#[command(
    name = "geocert",
    version,
    about = "Geometric operations with certified answers"
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Solve the cases of FILE (a JSON array or JSON Lines; `-` is standard input) and
    /// write one result per case as JSON Lines (docs/FORMAT.md).
    Solve {
        /// The case file, or `-` for standard input.
        file: String,
    },
    /// Certify or refute the `claim` of each case of FILE (another program's answer,
    /// docs/FORMAT.md "Claims"): confirmed / refuted / undecided per claimed item, and
    /// the certified solutions the claim missed. Exit status 3 if any item is not
    /// confirmed or a solution was missed.
    Verify {
        /// The case file, or `-` for standard input.
        file: String,
    },
    /// Solve the worked examples of OPERATIONS.md §16 and a few degenerate cases, and
    /// print a table of status, kind, point and time.
    Demo,
    /// Built-in benchmarks: `robustness` (the robustness table).
    Bench {
        #[command(subcommand)]
        which: cli::robustness::Bench,
    },
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    match cli.command {
        Command::Solve { file } => cli::solve::run(&file),
        Command::Verify { file } => cli::verify::run(&file),
        Command::Demo => cli::demo::run(),
        Command::Bench { which } => cli::robustness::run(which),
    }
}
