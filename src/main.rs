//! The `geocert` command line: `solve`, `verify`, `demo`, `bench`, `render`.

mod cli;

use clap::{Args, Parser, Subcommand};
use cli::output::{Context, Defaults, Format, Mode};
use std::process::ExitCode;

#[derive(Parser)]
#[command(
    name = "geocert",
    version,
    about = "Geometric operations with certified answers",
    after_help = cli::exit::HELP
)]
struct Cli {
    /// Show progress on standard error even when it is not a terminal (by default
    /// progress is shown only on a terminal, and never when `CI` is set).
    #[arg(long, global = true)]
    progress: bool,
    #[command(subcommand)]
    command: Command,
}

/// The options of `solve` and `verify`.
#[derive(Args)]
struct RunArgs {
    /// The case file (a JSON array or JSON Lines), or `-` for standard input.
    file: String,
    /// Worker threads (default: one per core). The output does not depend on it.
    #[arg(long, short = 'j', value_parser = clap::value_parser!(u16).range(1..))]
    jobs: Option<u16>,
    /// Add `micros`, the time each case took, to the results. Without it the same
    /// input and options give the same bytes.
    #[arg(long)]
    timings: bool,
    /// `jsonl`: one JSON result per line (docs/FORMAT.md); `table`: for people.
    #[arg(long, value_enum, default_value_t = Format::Jsonl)]
    format: Format,
    /// Box budget of subdivision for cases whose `options` do not set `max_boxes`.
    #[arg(long, value_name = "N")]
    max_boxes: Option<u64>,
    /// Precision cap of MPFR escalation, in bits, for cases whose `options` do not set
    /// `max_bits`.
    #[arg(long, value_name = "BITS")]
    max_bits: Option<u32>,
    /// Time budget per case in seconds, for cases whose `options` do not set
    /// `time_limit`: when it runs out the certifier stops subdividing and the rest is
    /// `undecided` ("time limit reached"), so a pathological case cannot hold the run.
    #[arg(long, value_name = "SECONDS", value_parser = positive_seconds, default_value_t = 60.0)]
    time_limit: f64,
}

fn positive_seconds(s: &str) -> Result<f64, String> {
    match s.parse::<f64>() {
        Ok(t) if t.is_finite() && t > 0.0 => Ok(t),
        _ => Err(format!("{s:?} is not a positive number of seconds")),
    }
}

#[derive(Subcommand)]
enum Command {
    /// Solve the cases of FILE and write one result per case, in input order, as JSON
    /// Lines (docs/FORMAT.md). A bad case gives an `error` record naming the field (a
    /// line that is not JSON: `line N`) and the other cases go on.
    #[command(after_help = cli::exit::HELP)]
    Solve(RunArgs),
    /// Certify or refute the `claim` of each case of FILE (another program's answer,
    /// docs/FORMAT.md "Claims"): confirmed / refuted / undecided per claimed item, and
    /// the certified solutions the claim missed.
    #[command(after_help = cli::exit::HELP)]
    Verify(RunArgs),
    /// Solve the worked examples of OPERATIONS.md §16 and a few degenerate cases, and
    /// print a table of status, kind, point and time.
    Demo,
    /// Built-in benchmarks: `robustness` (the robustness table), `cases` (seeded case
    /// files for timing `solve`).
    Bench {
        #[command(subcommand)]
        which: cli::robustness::Bench,
    },
    /// Draw each case of FILE and its certified answer as a picture (SVG, and PNG with
    /// `--png`) in a view of OPERATIONS.md §13.6: surfaces as iso-parameter nets with
    /// their contours, hidden parts dashed, the answer's curves and points highlighted.
    Render(cli::render::RenderArgs),
}

fn run(mode: Mode, args: RunArgs, progress: bool) -> ExitCode {
    let ctx = Context {
        mode,
        format: args.format,
        timings: args.timings,
        defaults: Defaults {
            max_boxes: args.max_boxes,
            max_bits: args.max_bits,
            time_limit: Some(args.time_limit),
        },
        panic_id: std::env::var("GEOCERT_TEST_PANIC_ID").ok(),
    };
    let show = cli::progress::wanted(progress);
    let jobs = args.jobs.map(usize::from);
    cli::run::run(&args.file, ctx, jobs, show).code()
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    match cli.command {
        Command::Solve(args) => run(Mode::Solve, args, cli.progress),
        Command::Verify(args) => run(Mode::Verify, args, cli.progress),
        Command::Demo => cli::demo::run(),
        Command::Bench { which } => {
            cli::robustness::run(which, cli::progress::wanted(cli.progress))
        }
        Command::Render(args) => cli::render::run(args),
    }
}
