//! What `geocert render` draws of a case (docs/FORMAT.md "Pictures"): its shapes in
//! input order (`objects`, or `onto`, or `shell`), its query point, and the view —
//! translated from the case's JSON into the typed shapes of [`crate::ops`].

use super::build::{position, shape};
use super::case::Case;
use crate::error::GeomError;
use crate::ops::shape::{Position, Shape};
use crate::ops::view::View;
use rug::Rational;

/// The shapes of a case in the order its answer's parameters follow.
pub fn shapes(case: &Case) -> Result<Vec<Shape>, GeomError> {
    let mut out = super::solve::objects(case)?;
    if let Some(onto) = &case.onto {
        out.push(shape(onto, "onto")?);
    }
    if let Some(shell) = &case.shell {
        out.push(shape(shell, "shell")?);
    }
    Ok(out)
}

/// The query point of `project` and `classify`, rounded to doubles (a picture needs no
/// more).
pub fn query_point(case: &Case) -> Result<Option<Vec<f64>>, GeomError> {
    let Some(p) = &case.point else {
        return Ok(None);
    };
    Ok(Some(match position(p, "point")? {
        Position::Double(v) => v,
        Position::Exact(v) => v.iter().map(Rational::to_f64).collect(),
    }))
}

/// The view of the picture: `given` (the `--view` option), else the case's own `view`
/// (of `silhouette`), else the isometric view.
pub fn view(case: &Case, given: Option<&serde_json::Value>) -> Result<View, GeomError> {
    match given.or(case.view.as_ref()) {
        Some(v) => super::view::view(v),
        None => Ok(View::isometric()),
    }
}
