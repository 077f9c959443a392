//! A [`Scene`] drawn with plotters: SVG text (with the title) or a PNG file (no text, so
//! no font files are needed). Deterministic: the same scene gives the same bytes.
//!
//! Colours (Okabe–Ito) by role: input curves dark grey, surface nets light grey,
//! contours and polyhedron edges black, the answer's curves vermillion (wide), blend
//! spines blue, contact curves bluish green, blend nets sky blue, projection guides
//! reddish purple, certified boxes magenta. Hidden runs are dashed. Markers: answer
//! points vermillion discs, tangencies blue discs, singular points black crosses in a
//! ring, query points black discs (green inside a shell, orange outside), feet vermillion
//! rings; a hidden marker is drawn as a ring only.

use std::path::Path;

use plotters::coord::Shift;
use plotters::element::DashedPathElement;
use plotters::prelude::*;

use super::model::{MarkerKind, Role};
use super::scene::{Scene, Stroke};

/// A drawing failure, as text.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct RenderError(pub String);

impl std::fmt::Display for RenderError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for RenderError {}

fn err<E: std::fmt::Debug>(e: E) -> RenderError {
    RenderError(format!("{e:?}"))
}

/// The colour, width and drawing order of a role.
pub fn role_style(role: Role) -> (RGBColor, u32, u8) {
    match role {
        Role::Net => (RGBColor(170, 170, 170), 1, 0),
        Role::BlendNet => (RGBColor(86, 180, 233), 1, 1),
        Role::Edge => (RGBColor(0, 0, 0), 1, 2),
        Role::Curve => (RGBColor(80, 80, 80), 2, 2),
        Role::Contour => (RGBColor(0, 0, 0), 2, 3),
        Role::Guide => (RGBColor(204, 121, 167), 1, 4),
        Role::Contact => (RGBColor(0, 158, 115), 2, 5),
        Role::Spine => (RGBColor(0, 114, 178), 2, 5),
        Role::Answer => (RGBColor(213, 94, 0), 3, 6),
        Role::Box => (RGBColor(255, 0, 255), 1, 7),
    }
}

/// The colour of a marker.
pub fn marker_colour(kind: MarkerKind) -> RGBColor {
    match kind {
        MarkerKind::Point | MarkerKind::Foot => RGBColor(213, 94, 0),
        MarkerKind::Tangent => RGBColor(0, 114, 178),
        MarkerKind::Singular | MarkerKind::Query => RGBColor(0, 0, 0),
        MarkerKind::Inside => RGBColor(0, 158, 115),
        MarkerKind::Outside => RGBColor(230, 159, 0),
    }
}

fn px(p: &[f64; 2]) -> (i32, i32) {
    (p[0].round() as i32, p[1].round() as i32)
}

fn stroke<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    s: &Stroke,
) -> Result<(), RenderError> {
    let (colour, width, _) = role_style(s.role);
    let style = colour.stroke_width(width);
    let mut pts: Vec<(i32, i32)> = s.points.iter().map(px).collect();
    pts.dedup();
    if pts.len() < 2 {
        return Ok(());
    }
    if s.hidden {
        root.draw(&DashedPathElement::new(pts, 5, 4, style))
            .map_err(err)
    } else {
        root.draw(&PathElement::new(pts, style)).map_err(err)
    }
}

fn paint<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    scene: &Scene,
    text: bool,
) -> Result<(), RenderError> {
    root.fill(&WHITE).map_err(err)?;
    let mut strokes: Vec<&Stroke> = scene.strokes.iter().collect();
    // Hidden runs under visible ones, then by role (stable: the model's order within).
    strokes.sort_by_key(|s| (!s.hidden, role_style(s.role).2));
    for s in strokes {
        stroke(root, s)?;
    }
    for m in &scene.markers {
        let c = marker_colour(m.kind);
        let at = px(&m.at);
        if m.hidden {
            root.draw(&Circle::new(at, 4, c.stroke_width(1)))
                .map_err(err)?;
            continue;
        }
        match m.kind {
            MarkerKind::Singular => {
                root.draw(&Cross::new(at, 5, c.stroke_width(2)))
                    .map_err(err)?;
                root.draw(&Circle::new(at, 7, c.stroke_width(1)))
                    .map_err(err)?;
            }
            MarkerKind::Foot => root
                .draw(&Circle::new(at, 5, c.stroke_width(2)))
                .map_err(err)?,
            _ => root.draw(&Circle::new(at, 4, c.filled())).map_err(err)?,
        }
    }
    if text && !scene.title.is_empty() {
        root.draw(&Text::new(
            scene.title.clone(),
            (12, 8),
            ("sans-serif", 16).into_font().color(&BLACK),
        ))
        .map_err(err)?;
    }
    root.present().map_err(err)
}

/// The scene as SVG text.
pub fn svg(scene: &Scene) -> Result<String, RenderError> {
    let mut out = String::new();
    {
        let root =
            SVGBackend::with_string(&mut out, (scene.size[0], scene.size[1])).into_drawing_area();
        paint(&root, scene, true)?;
    }
    Ok(out)
}

/// The scene as a PNG file (no title: text would need font files).
pub fn png(scene: &Scene, path: &Path) -> Result<(), RenderError> {
    let root = BitMapBackend::new(path, (scene.size[0], scene.size[1])).into_drawing_area();
    paint(&root, scene, false)
}
