//! Pictures of a case and its answer (`geocert render`; issue 17 "Pictures"): the input
//! shapes and the certified answer drawn in any projection of OPERATIONS.md §13.6.
//!
//! The picture is built in three steps, each a plain function of the one before, so that
//! the same input gives the same bytes:
//!
//! 1. [`model`](mod@model): the 3D drawing — curves sampled as polylines, surfaces as iso-parameter
//!    nets with their contours (`I = n·w = 0` of (13.10) found by marching squares over
//!    the parameter domain, [`contour`]), polyhedra as edges, and the answer's points,
//!    curves, singular points, blend surfaces and (on request) certified boxes. Every
//!    surface is also tessellated into triangles, the occluders. Unbounded objects (lines,
//!    planes) are cut to a window around the bounded ones.
//! 2. [`scene`](mod@scene): the projection to the picture plane (§13.6) and the hidden-line split:
//!    a depth buffer of the occluders at picture resolution ([`depth`]) decides for each
//!    sample of each polyline whether a surface lies in front of it; hidden runs are
//!    drawn dashed. This is a picture, not a certificate: the visibility a case can rely
//!    on is the certified `visibility_point_surface` of [`crate::ops::view`].
//! 3. [`draw`]: SVG (with a title) and PNG (no text: no fonts are needed) through
//!    plotters.
//!
//! An implicit `quadric` has no parameters: an ellipsoid is drawn as the named ellipsoid
//! it is, any other quadric by plane sections inside the window ([`quadric`]).
//!
//! Plane cases (2D objects) are drawn in the plane itself (`X = x`, `Y = y`).

pub mod contour;
pub mod depth;
pub mod draw;
pub mod model;
pub mod quadric;
pub mod scene;

pub use draw::{png, svg, RenderError};
pub use model::{model, Input, MarkerKind, Model, Role};
pub use scene::{scene, Marker, Scene, Stroke};

/// How a picture is drawn.
#[derive(Debug, Clone, PartialEq)]
pub struct RenderOptions {
    /// The picture's width and height in pixels (the drawing keeps its aspect ratio
    /// inside them).
    pub size: [u32; 2],
    /// Draw the certified boxes of the answer's points and curve vertices.
    pub boxes: bool,
    /// Iso-parameter lines of each surface's net, per parameter direction.
    pub net: [usize; 2],
    /// Samples per curve and per net line (the contour grid has twice as many per side).
    pub samples: usize,
}

impl Default for RenderOptions {
    fn default() -> Self {
        RenderOptions {
            size: [900, 700],
            boxes: false,
            net: [16, 10],
            samples: 96,
        }
    }
}

/// The picture of a case: its [`Model`] projected by `input.view` ([`scene()`]).
pub fn picture(
    input: &Input,
    opts: &RenderOptions,
    title: String,
) -> Result<Scene, crate::error::GeomError> {
    let m = model::model(input, opts)?;
    Ok(scene::scene(&m, input.view, opts.size, title))
}
