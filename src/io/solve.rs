//! Solving one case of the command line (docs/FORMAT.md "Cases"): translate its objects and
//! options into the front door's types ([`crate::ops`]), call the operation, and write
//! the answer as a result record.

use std::time::Instant;

use super::answer_out;
use super::build::{position, shape};
use super::case::{Case, Op, ReadCase};
use super::result::CaseResult;
use crate::certificate::Certified;
use crate::error::GeomError;
use crate::ops::fillet::SectorChoice;
use crate::ops::{self, Answer, BlendSpec, Options, ProjectOptions};

/// Solve one case read from the input. Errors (unreadable cases, invalid objects,
/// unsupported operations) become error records naming the field.
///
/// ```
/// // One case of the command line's format (docs/FORMAT.md), solved from the library.
/// let text = r#"{"id": 1, "op": "intersect", "objects": [
///     {"type": "line", "origin": [0.6, 0, -2], "dir": [0, 0, 1]},
///     {"type": "sphere", "center": [0, 0, 0], "radius": 1}]}"#;
/// let case = geocert::io::read_cases(&text.replace('\n', " ")).remove(0);
/// let result = geocert::io::solve_case(case);
/// assert_eq!(result.status, "exact");
/// assert_eq!(result.kind, Some("points"));
/// let json = serde_json::to_string(&result).unwrap();
/// assert!(json.contains(r#""xyz":[0.6,0.0,-0.8]"#), "{json}");
/// ```
pub fn solve_case(read: ReadCase) -> CaseResult {
    let start = Instant::now();
    let case = match read.case {
        Ok(case) => case,
        Err(e) => return CaseResult::error(read.id, &e),
    };
    match answer(&case) {
        Ok(c) => {
            let mut result = answer_out::result(case.id.clone(), &c);
            result.micros = Some(start.elapsed().as_micros() as u64);
            result
        }
        Err(e) => CaseResult::error(case.id.clone(), &e),
    }
}

/// The options of a case.
pub fn options(case: &Case) -> Result<Options, GeomError> {
    let o = &case.options;
    let mut out = Options::new(
        o.tolerance.map(|d| d.0),
        o.equal_tolerance.map(|d| d.0),
        o.max_boxes,
        o.max_bits,
        o.exact,
    )?;
    if let Some(c) = o.chord_tolerance {
        if !(c.0 > 0.0 && c.0.is_finite()) {
            return Err(GeomError::InvalidValue {
                field: "options.chord_tolerance".into(),
                reason: format!("the chord tolerance must be positive, found {}", c.0),
            });
        }
        out.chord_tolerance = Some(c.0);
    }
    if let Some(m) = &o.method {
        out.method = crate::ops::Method::parse(m)?;
    }
    // Validated positive when the case was read; beyond ~10¹¹ years it is no limit.
    out.time_limit = o
        .time_limit
        .and_then(|t| std::time::Duration::try_from_secs_f64(t.0).ok());
    Ok(out)
}

fn missing(field: &str, op: Op) -> GeomError {
    GeomError::Format {
        field: field.into(),
        message: format!("`{}` needs `{field}`", op.as_str()),
    }
}

/// The case's `objects` as shapes, errors naming `objects[i]`.
pub fn objects(case: &Case) -> Result<Vec<crate::ops::Shape>, GeomError> {
    case.objects
        .iter()
        .enumerate()
        .map(|(i, s)| shape(s, &format!("objects[{i}]")))
        .collect()
}

/// The certified answer of a case, through the front door.
pub fn answer(case: &Case) -> Result<Certified<Answer>, GeomError> {
    match case.op {
        Op::Intersect => {
            let shapes = objects(case)?;
            ops::intersect(&shapes, &options(case)?)
        }
        Op::Project => {
            let point = case
                .point
                .as_ref()
                .ok_or_else(|| missing("point", case.op))?;
            let onto = case.onto.as_ref().ok_or_else(|| missing("onto", case.op))?;
            let how = ProjectOptions {
                nearest: case.nearest,
                direction: case
                    .direction
                    .as_ref()
                    .map(|d| position(d, "direction"))
                    .transpose()?,
                options: options(case)?,
            };
            ops::project(&position(point, "point")?, &shape(onto, "onto")?, &how)
        }
        Op::Classify => {
            let point = case
                .point
                .as_ref()
                .ok_or_else(|| missing("point", case.op))?;
            let shell = case
                .shell
                .as_ref()
                .ok_or_else(|| missing("shell", case.op))?;
            ops::classify(
                &position(point, "point")?,
                &shape(shell, "shell")?,
                &options(case)?,
            )
        }
        Op::Section => {
            if case.objects.len() != 2 {
                return Err(GeomError::CountMismatch {
                    field: "objects".into(),
                    expected: "2 objects (the shape, then the cutting plane)".into(),
                    found: case.objects.len().to_string(),
                });
            }
            let shape_at = |i: usize| shape(&case.objects[i], &format!("objects[{i}]"));
            ops::section(&shape_at(0)?, &shape_at(1)?, &options(case)?)
        }
        Op::Fillet | Op::Chamfer => blend(case),
        Op::Silhouette => {
            if case.objects.len() != 1 {
                return Err(GeomError::CountMismatch {
                    field: "objects".into(),
                    expected: "1 object (the surface)".into(),
                    found: case.objects.len().to_string(),
                });
            }
            let view = case.view.as_ref().ok_or_else(|| missing("view", case.op))?;
            ops::view::contour(
                &shape(&case.objects[0], "objects[0]")?,
                &super::view::view(view)?,
                &options(case)?,
            )
        }
        Op::Visibility => {
            let shapes = objects(case)?;
            let params = case.params.ok_or_else(|| missing("params", case.op))?;
            let view = case.view.as_ref().ok_or_else(|| missing("view", case.op))?;
            ops::view::visibility_answer(
                &shapes,
                params.map(|d| d.0),
                &super::view::view(view)?,
                &options(case)?,
            )
        }
        other => Err(GeomError::Unsupported {
            field: "op".into(),
            reason: format!("`{}` is not implemented in this build", other.as_str()),
        }),
    }
}

/// `fillet` and `chamfer`: two objects and the blend fields (docs/FORMAT.md "Blends").
fn blend(case: &Case) -> Result<Certified<Answer>, GeomError> {
    if case.objects.len() != 2 {
        return Err(GeomError::CountMismatch {
            field: "objects".into(),
            expected: "2 objects (the two faces)".into(),
            found: case.objects.len().to_string(),
        });
    }
    let shape_at = |i: usize| shape(&case.objects[i], &format!("objects[{i}]"));
    let b = &case.blend;
    let sector = match (b.sector, b.side) {
        (Some(_), Some(_)) => {
            return Err(GeomError::Format {
                field: "side".into(),
                message: "give either `sector` or `side`, not both".into(),
            })
        }
        (Some(k), None) => SectorChoice::Number(k),
        (None, Some(x)) => SectorChoice::Side(x.map(|d| d.0)),
        (None, None) => return Err(missing("sector", case.op)),
    };
    let mut spec = BlendSpec {
        sector,
        range: b.range.map(|r| r.map(|d| d.0)),
        ..BlendSpec::default()
    };
    if let Some(g) = b.grid {
        spec.grid = g;
    }
    let (a, s) = (shape_at(0)?, shape_at(1)?);
    let opts = options(case)?;
    if case.op == Op::Fillet {
        if b.legs.is_some() {
            return Err(GeomError::Format {
                field: "legs".into(),
                message: "`legs` belongs to `chamfer`".into(),
            });
        }
        let radius = b
            .radius
            .as_ref()
            .ok_or_else(|| missing("radius", case.op))?;
        let radius = super::blend_law::law(radius, "radius")?;
        ops::fillet::fillet_law(&a, &s, &radius, &spec, &opts)
    } else {
        if b.radius.is_some() {
            return Err(GeomError::Format {
                field: "radius".into(),
                message: "`radius` belongs to `fillet`".into(),
            });
        }
        let legs = b.legs.as_ref().ok_or_else(|| missing("legs", case.op))?;
        let legs = [
            super::blend_law::law(&legs[0], "legs[0]")?,
            super::blend_law::law(&legs[1], "legs[1]")?,
        ];
        ops::fillet::chamfer_laws(&a, &s, &legs, &spec, &opts)
    }
}
