//! The robustness benchmark's plots (`geocert bench robustness --plots DIR`), drawn with
//! plotters: deterministic from the report (no clock, no fonts: the SVG text is left
//! to the viewer, the PNG maps carry no text), so the same seed gives the same bytes.
//!
//! - `kettner-plain-f64.png`, `kettner-certified.png`: the sign maps of the Kettner et
//!   al. near-collinear orientation grid ([`super::kettner`]), one pixel per grid point
//!   (`i` to the right, `j` upwards), coloured by the orientation each method reports:
//!   [`NEGATIVE`], [`COLLINEAR`], [`POSITIVE`] ([`NO_ANSWER`] if none).
//! - `float-failure-rate.svg`: per curved family, the fraction of cases where geocert's
//!   float path got the number of points wrong or a point off, against the gap (log
//!   axis: `10⁻ᵏ` at `k`, then 1 ulp and exact tangency).
//! - `certification-cost.svg`: per family, the mean precision in bits that decided the
//!   certified answer, against the gap.

use std::cmp::Ordering;
use std::path::{Path, PathBuf};

use plotters::prelude::*;

use super::curved::{CurvedTable, Family, Gap};
use super::kettner::{SignMap, SIDE};

pub const NEGATIVE: RGBColor = RGBColor(0, 114, 178);
pub const COLLINEAR: RGBColor = RGBColor(0, 0, 0);
pub const POSITIVE: RGBColor = RGBColor(230, 159, 0);
pub const NO_ANSWER: RGBColor = RGBColor(255, 0, 255);

/// The file names, in the order [`write_plots`] writes them.
pub const FILES: [&str; 4] = [
    "kettner-plain-f64.png",
    "kettner-certified.png",
    "float-failure-rate.svg",
    "certification-cost.svg",
];

/// The colour of a sign on the maps.
pub fn sign_colour(s: Option<Ordering>) -> RGBColor {
    match s {
        Some(Ordering::Less) => NEGATIVE,
        Some(Ordering::Equal) => COLLINEAR,
        Some(Ordering::Greater) => POSITIVE,
        None => NO_ANSWER,
    }
}

/// The series colours of the families (Okabe–Ito).
fn family_colour(f: Family) -> RGBColor {
    match f {
        Family::LineSphere => RGBColor(0, 114, 178),
        Family::LineTorus => RGBColor(213, 94, 0),
        Family::Circle2Circle2 => RGBColor(0, 158, 115),
        Family::Circle2Ellipse2 => RGBColor(204, 121, 167),
        Family::CircleSphere => RGBColor(86, 180, 233),
        _ => RGBColor(0, 0, 0), // the seam families are not plotted
    }
}

/// Where a gap sits on the x axis: `k` for `10⁻ᵏ` (a log axis), then 1 ulp at 16 and
/// exact tangency at 17.
pub fn gap_x(g: Gap) -> f64 {
    match g {
        Gap::Pow(k) => f64::from(k),
        Gap::Ulp => 16.0,
        Gap::Tangent => 17.0,
    }
}

fn gap_tick(x: &f64) -> String {
    let k = x.round();
    if (x - k).abs() > 1e-9 {
        String::new()
    } else if k == 17.0 {
        "0".into()
    } else if k == 16.0 {
        "1ulp".into()
    } else {
        format!("1e-{k}")
    }
}

/// A drawing failure, as text.
#[derive(Debug)]
pub struct PlotError(pub String);

fn err<E: std::fmt::Debug>(e: E) -> PlotError {
    PlotError(format!("{e:?}"))
}

/// Draw one sign map into a PNG of `SIDE × SIDE` pixels.
pub fn sign_map_png(path: &Path, signs: &[Option<Ordering>]) -> Result<(), PlotError> {
    let side = SIDE as u32;
    let root = BitMapBackend::new(path, (side, side)).into_drawing_area();
    for i in 0..SIDE {
        for j in 0..SIDE {
            let c = sign_colour(signs[i * SIDE + j]);
            root.draw_pixel((i as i32, (SIDE - 1 - j) as i32), &c)
                .map_err(err)?;
        }
    }
    root.present().map_err(err)
}

/// One series per family of `value(row)` against the gap, as an SVG string.
fn gap_chart(
    table: &CurvedTable,
    caption: &str,
    y_desc: &str,
    y_max: f64,
    value: impl Fn(&super::curved::CurvedRow) -> f64,
) -> Result<String, PlotError> {
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (720, 440)).into_drawing_area();
        root.fill(&WHITE).map_err(err)?;
        let mut chart = ChartBuilder::on(&root)
            .caption(caption, ("sans-serif", 18))
            .margin(12)
            .x_label_area_size(40)
            .y_label_area_size(56)
            .build_cartesian_2d(2.5f64..17.5f64, 0f64..y_max)
            .map_err(err)?;
        chart
            .configure_mesh()
            .x_labels(16)
            .x_label_formatter(&gap_tick)
            .x_desc("gap (log scale; 1ulp = next double, 0 = exactly tangent)")
            .y_desc(y_desc)
            .draw()
            .map_err(err)?;
        for f in Family::ALL {
            let points: Vec<(f64, f64)> = table
                .rows
                .iter()
                .filter(|r| r.family == f)
                .map(|r| (gap_x(r.gap), value(r)))
                .collect();
            let colour = family_colour(f);
            chart
                .draw_series(LineSeries::new(points.clone(), colour.stroke_width(2)))
                .map_err(err)?
                .label(f.name())
                .legend(move |(x, y)| {
                    PathElement::new(vec![(x, y), (x + 18, y)], colour.stroke_width(2))
                });
            chart
                .draw_series(points.iter().map(|&p| Circle::new(p, 3, colour.filled())))
                .map_err(err)?;
        }
        chart
            .configure_series_labels()
            .position(SeriesLabelPosition::UpperLeft)
            .background_style(WHITE.mix(0.85))
            .border_style(BLACK)
            .draw()
            .map_err(err)?;
        root.present().map_err(err)?;
    }
    Ok(svg)
}

/// The float failure-rate chart (SVG text).
pub fn failure_rate_svg(table: &CurvedTable) -> Result<String, PlotError> {
    gap_chart(
        table,
        "geocert float path: wrong count or point off, by gap",
        "fraction of cases",
        1.05,
        |r| r.float_failure_rate(),
    )
}

/// The certification-cost chart (SVG text).
pub fn cost_svg(table: &CurvedTable) -> Result<String, PlotError> {
    let top = table
        .rows
        .iter()
        .map(|r| r.bits_mean())
        .fold(64.0, f64::max);
    gap_chart(
        table,
        "geocert certified: precision that decided, by gap",
        "bits, mean (MPFR precision, or the largest exact number's size)",
        top * 1.1,
        |r| r.bits_mean(),
    )
}

/// Write the four plots of [`FILES`] into `dir` (created if missing).
pub fn write_plots(
    dir: &Path,
    signs: &SignMap,
    curved: &CurvedTable,
) -> Result<Vec<PathBuf>, PlotError> {
    std::fs::create_dir_all(dir).map_err(err)?;
    let paths: Vec<PathBuf> = FILES.iter().map(|f| dir.join(f)).collect();
    let plain: Vec<Option<Ordering>> = signs.plain.iter().map(|&s| Some(s)).collect();
    sign_map_png(&paths[0], &plain)?;
    sign_map_png(&paths[1], &signs.certified)?;
    std::fs::write(&paths[2], failure_rate_svg(curved)?).map_err(err)?;
    std::fs::write(&paths[3], cost_svg(curved)?).map_err(err)?;
    Ok(paths)
}
