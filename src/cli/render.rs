//! `geocert render FILE`: one picture per case — its shapes and its certified answer in a
//! view of OPERATIONS.md §13.6 ([`geocert::render`]) — written as `DIR/<id>.svg` (and
//! `.png` with `--png`). One line per case on standard output: the file, the case's
//! status and kind. A case that cannot be read or drawn is named on standard error and
//! the others go on (exit status 1, as `solve`).

use std::collections::HashSet;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

use clap::Args;
use geocert::error::GeomError;
use geocert::io::{answer, picture, read_cases, Case, Double};
use geocert::render::{self, Input, RenderOptions};

use super::exit::{self, Status};

/// The options of `render`.
#[derive(Args)]
pub struct RenderArgs {
    /// The case file (a JSON array or JSON Lines), or `-` for standard input.
    file: String,
    /// The directory the pictures go to (created if missing).
    #[arg(long, default_value = "pictures")]
    out: PathBuf,
    /// The view: a name (frontal, horizontal, profile, isometric, dimetric, cabinet,
    /// cavalier) or a JSON object as in the cases' `view` (docs/FORMAT.md "Views").
    /// Default: the case's own `view`, else isometric.
    #[arg(long)]
    view: Option<String>,
    /// Also write a PNG of each picture (without the title).
    #[arg(long)]
    png: bool,
    /// Draw the certified boxes of the answer's points.
    #[arg(long)]
    boxes: bool,
    /// Picture size in pixels, `WIDTHxHEIGHT`.
    #[arg(long, default_value = "900x700", value_parser = size)]
    size: [u32; 2],
    /// Draw the shapes only, without solving the cases.
    #[arg(long)]
    no_solve: bool,
    /// Time budget per case in seconds (for cases whose `options` do not set
    /// `time_limit`).
    #[arg(long, default_value_t = 10.0)]
    time_limit: f64,
}

fn size(text: &str) -> Result<[u32; 2], String> {
    let (w, h) = text
        .split_once('x')
        .ok_or_else(|| format!("expected WIDTHxHEIGHT, found {text:?}"))?;
    let n = |s: &str| {
        s.parse::<u32>()
            .ok()
            .filter(|v| (64..=8192).contains(v))
            .ok_or_else(|| format!("{s:?} is not a size from 64 to 8192 pixels"))
    };
    Ok([n(w)?, n(h)?])
}

/// The `--view` option as the JSON value a case's `view` would hold.
fn view_value(text: &str) -> Result<serde_json::Value, GeomError> {
    if text.trim_start().starts_with('{') {
        serde_json::from_str(text).map_err(|e| GeomError::Format {
            field: "--view".into(),
            message: format!("not a JSON object: {e}"),
        })
    } else {
        Ok(serde_json::Value::String(text.into()))
    }
}

/// A file name from the case's id (letters, digits, `.`, `_`, `-`; the rest `_`), or
/// `case-N` (1-based) without one; a repeated name gets `-2`, `-3`, ...
fn file_stem(id: &serde_json::Value, n: usize, taken: &mut HashSet<String>) -> String {
    let raw = match id {
        serde_json::Value::String(s) if !s.is_empty() => s.clone(),
        serde_json::Value::Number(x) => x.to_string(),
        _ => format!("case-{n}"),
    };
    let base: String = raw
        .chars()
        .map(|c| {
            if c.is_ascii_alphanumeric() || "._-".contains(c) {
                c
            } else {
                '_'
            }
        })
        .collect();
    let base = base.trim_start_matches('.').to_string();
    let mut name = base.clone();
    let mut k = 2;
    while !taken.insert(name.clone()) {
        name = format!("{base}-{k}");
        k += 1;
    }
    name
}

/// The picture of one case, written next to `stem` in `dir`; the line to print.
fn one(
    case: &Case,
    stem: &str,
    args: &RenderArgs,
    view: Option<&serde_json::Value>,
) -> Result<String, String> {
    let fail = |e: GeomError| e.to_string();
    let shapes = picture::shapes(case).map_err(fail)?;
    let point = picture::query_point(case).map_err(fail)?;
    let view = picture::view(case, view).map_err(fail)?;
    let solved = if args.no_solve {
        None
    } else {
        Some(answer(case).map_err(fail)?)
    };
    let (status, kind) = match &solved {
        Some(c) => (c.status.as_str(), c.value.kind()),
        None => ("-", "-"),
    };
    let id = match &case.id {
        serde_json::Value::Null => stem.to_string(),
        other => other.to_string(),
    };
    let title = format!("{id} · {} · {status} {kind}", case.op.as_str());
    let input = Input {
        shapes: &shapes,
        point,
        answer: solved.as_ref(),
        view: &view,
    };
    let opts = RenderOptions {
        size: args.size,
        boxes: args.boxes,
        ..RenderOptions::default()
    };
    let scene = render::picture(&input, &opts, title).map_err(fail)?;
    let svg_path = args.out.join(format!("{stem}.svg"));
    let text = render::svg(&scene).map_err(|e| e.to_string())?;
    std::fs::write(&svg_path, text).map_err(|e| format!("{}: {e}", svg_path.display()))?;
    let mut line = format!("{}\t{status}\t{kind}", svg_path.display());
    if args.png {
        let png_path = args.out.join(format!("{stem}.png"));
        render::png(&scene, &png_path).map_err(|e| e.to_string())?;
        line.push_str(&format!("\t{}", png_path.display()));
    }
    Ok(line)
}

fn read(file: &str) -> std::io::Result<String> {
    if file == "-" {
        std::io::read_to_string(std::io::stdin())
    } else {
        std::fs::read_to_string(Path::new(file))
    }
}

pub fn run(args: RenderArgs) -> ExitCode {
    let mut status = Status::default();
    let view = match args.view.as_deref().map(view_value).transpose() {
        Ok(v) => v,
        Err(e) => {
            eprintln!("geocert render: {e}");
            return ExitCode::from(2);
        }
    };
    // A bad view fails once, before any case is read.
    if let Some(v) = &view {
        if let Err(e) = geocert::io::view::view(v) {
            eprintln!("geocert render: --view: {e}");
            return ExitCode::from(2);
        }
    }
    let text = match read(&args.file) {
        Ok(t) => t,
        Err(e) => {
            eprintln!("geocert render: {}: {e}", args.file);
            status.set(exit::UNREADABLE);
            return status.code();
        }
    };
    if let Err(e) = std::fs::create_dir_all(&args.out) {
        eprintln!("geocert render: {}: {e}", args.out.display());
        status.set(exit::UNREADABLE);
        return status.code();
    }
    let mut taken = HashSet::new();
    for (n, read) in read_cases(&text).into_iter().enumerate() {
        let stem = file_stem(&read.id, n + 1, &mut taken);
        let outcome = match read.case {
            Ok(mut case) => {
                case.options.time_limit = case.options.time_limit.or(Some(Double(args.time_limit)));
                one(&case, &stem, &args, view.as_ref())
            }
            Err(e) => Err(e.to_string()),
        };
        match outcome {
            Ok(line) => println!("{line}"),
            Err(e) => {
                eprintln!("geocert render: case {} ({stem}): {e}", n + 1);
                status.set(exit::BAD_CASE);
            }
        }
    }
    status.code()
}
