//! Cases of the command line (docs/FORMAT.md "Cases"): reading a file of cases and
//! turning each into a typed [`Case`], or an error naming the offending field.

use super::de::deserialize_at;
use super::lenient::salvage;
use super::number::{abbreviate, shortest, Double, Num};
use super::objects::{parse_object, ObjectSpec};
use super::stream::Chunk;
use super::strict::{parse_strict, Parsed, StrictError};
use crate::error::GeomError;
use serde::Deserialize;

/// The operation a case asks for.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Op {
    Intersect,
    Project,
    Classify,
    Section,
    Fillet,
    Chamfer,
    Silhouette,
    Visibility,
    Walk,
}

impl Op {
    /// The name used in JSON.
    pub fn as_str(self) -> &'static str {
        match self {
            Op::Intersect => "intersect",
            Op::Project => "project",
            Op::Classify => "classify",
            Op::Section => "section",
            Op::Fillet => "fillet",
            Op::Chamfer => "chamfer",
            Op::Silhouette => "silhouette",
            Op::Visibility => "visibility",
            Op::Walk => "walk",
        }
    }
}

/// `options` of a case (docs/FORMAT.md; OPERATIONS.md §12 for ε and δ).
#[derive(Debug, Clone, Default, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Options {
    /// The operation tolerance ε of the float path (§12).
    pub tolerance: Option<Double>,
    /// The equality tolerance δ of the float path (§12).
    pub equal_tolerance: Option<Double>,
    /// The precision cap of MPFR escalation, in bits (default 512; the specification's
    /// 4096 is reachable by setting it; docs/CERTIFICATES.md "Escalation").
    pub max_bits: Option<u32>,
    /// The box budget of subdivision.
    pub max_boxes: Option<u64>,
    /// Surface ∩ surface: the largest chord-to-curve distance of the polylines.
    pub chord_tolerance: Option<Double>,
    /// A time budget for the case, in seconds (`geocert solve --time-limit` gives the
    /// default): the certifier stops taking boxes when it runs out (ops::Options::time_limit).
    pub time_limit: Option<Double>,
    /// Also report the exact rationals of exact results (`"p/q"` strings).
    #[serde(default)]
    pub exact: bool,
    /// The float path (`"default"`, `"bisection"`: ops::Method), checked when solved.
    pub method: Option<String>,
}

/// One case, as parsed; objects are validated when the case is solved.
#[derive(Debug, Clone, PartialEq)]
pub struct Case {
    pub id: serde_json::Value,
    pub op: Op,
    pub objects: Vec<ObjectSpec>,
    pub point: Option<Vec<Num>>,
    pub onto: Option<ObjectSpec>,
    pub direction: Option<Vec<Num>>,
    pub nearest: bool,
    pub shell: Option<ObjectSpec>,
    pub claim: Option<serde_json::Value>,
    /// `silhouette`, `visibility`: the view (docs/FORMAT.md "Views"), read by
    /// [`super::view::view`].
    pub view: Option<serde_json::Value>,
    /// `visibility`: the parameters `[u, v]` of the point on `objects[0]`.
    pub params: Option<[Double; 2]>,
    /// `fillet`, `chamfer`: what the blend asks besides its two objects.
    pub blend: BlendFields,
    pub options: Options,
}

/// The fields of `fillet` and `chamfer` cases (docs/FORMAT.md "Blends").
#[derive(Debug, Clone, Default, PartialEq)]
pub struct BlendFields {
    /// `fillet`: the ball radius ρ, a number or a law (read by `blend_law`).
    pub radius: Option<serde_json::Value>,
    /// `chamfer`: the legs on the first and the second object, each a number or a law.
    pub legs: Option<[serde_json::Value; 2]>,
    /// The sector of OPERATIONS.md §11.1 (1–4).
    pub sector: Option<u8>,
    /// A point of the sector (the caller's side), instead of `sector`.
    pub side: Option<[Double; 3]>,
    /// The arc-length range of the spine of two planes.
    pub range: Option<[Double; 2]>,
    /// `[stations along the spine, points across]`.
    pub grid: Option<[usize; 2]>,
}

/// The case as written; objects stay JSON values until [`parse_object`] reads them
/// with their own field paths (serde loses paths inside internally tagged enums).
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
struct RawCase {
    /// The caller's name for the case, echoed in the result (any JSON scalar).
    #[serde(default)]
    pub id: serde_json::Value,
    pub op: Op,
    /// The operands of `intersect` (2 or 3).
    #[serde(default)]
    pub objects: Vec<serde_json::Value>,
    /// The point of `project` and `classify`.
    pub point: Option<Vec<Num>>,
    /// The object `project` projects onto.
    pub onto: Option<serde_json::Value>,
    /// Projection along a direction (OPERATIONS.md §3.5).
    pub direction: Option<Vec<Num>>,
    /// `project`: only the nearest point of the closed domain.
    #[serde(default)]
    pub nearest: bool,
    /// The closed shell of `classify`.
    pub shell: Option<serde_json::Value>,
    /// The answer of another program, for `geocert verify`.
    pub claim: Option<serde_json::Value>,
    /// `silhouette`, `visibility`: the view (a name or an object).
    pub view: Option<serde_json::Value>,
    /// `visibility`: the parameters `[u, v]` of the point on `objects[0]`.
    pub params: Option<[Double; 2]>,
    /// `fillet`: the ball radius ρ (a number or a law).
    pub radius: Option<serde_json::Value>,
    /// `chamfer`: the legs on the first and the second object (numbers or laws).
    pub legs: Option<[serde_json::Value; 2]>,
    /// `fillet`, `chamfer`: the sector of OPERATIONS.md §11.1 (1–4).
    pub sector: Option<u8>,
    /// `fillet`, `chamfer`: a point of the sector, instead of `sector`.
    pub side: Option<[Double; 3]>,
    /// `fillet`, `chamfer`: the arc-length range of the spine of two planes.
    pub range: Option<[Double; 2]>,
    /// `fillet`, `chamfer`: `[stations along the spine, points across]`.
    pub grid: Option<[usize; 2]>,
    #[serde(default)]
    pub options: Options,
}

/// A case as read from the input: its id (as far as it could be read) and either the
/// parsed case or the error that names the offending field.
#[derive(Debug, Clone)]
pub struct ReadCase {
    pub id: serde_json::Value,
    pub case: Result<Case, GeomError>,
}

/// A case read from a stream ([`super::read_stream`]): the [`ReadCase`], the line it starts
/// on, and the raw text of its `id` when that is a number, so that the id can be
/// echoed exactly as written (serde_json reads `18446744073709551616` or `1.50` as a
/// double, which prints differently).
#[derive(Debug, Clone)]
pub struct Record {
    pub read: ReadCase,
    pub line: usize,
    pub raw_id: Option<String>,
}

/// Parse one JSON value into a case, naming the field path of any error
/// (`objects[1].dir[2]`; a missing `op` is reported as field `op`).
pub fn parse_case(value: serde_json::Value) -> ReadCase {
    let id = value.get("id").cloned().unwrap_or(serde_json::Value::Null);
    if !value.is_object() {
        let error = GeomError::Format {
            field: String::new(),
            message: format!("a case is a JSON object, not {}", json_kind(&value)),
        };
        return ReadCase {
            id,
            case: Err(error),
        };
    }
    // Plain serde first (no path tracking); on an error, again with paths to name it.
    let raw = match RawCase::deserialize(&value) {
        Ok(raw) => Ok(raw),
        Err(_) => deserialize_at::<RawCase>(value, "").map_err(name_missing_field),
    };
    let case = raw.and_then(|raw| {
        let objects = raw
            .objects
            .into_iter()
            .enumerate()
            .map(|(i, v)| parse_object(v, &format!("objects[{i}]")))
            .collect::<Result<Vec<_>, _>>()?;
        let onto = raw.onto.map(|v| parse_object(v, "onto")).transpose()?;
        let shell = raw.shell.map(|v| parse_object(v, "shell")).transpose()?;
        check_options(&raw.options)?;
        Ok(Case {
            id: raw.id,
            op: raw.op,
            objects,
            point: raw.point,
            onto,
            direction: raw.direction,
            nearest: raw.nearest,
            shell,
            claim: raw.claim,
            view: raw.view,
            params: raw.params,
            blend: BlendFields {
                radius: raw.radius,
                legs: raw.legs,
                sector: raw.sector,
                side: raw.side,
                range: raw.range,
                grid: raw.grid,
            },
            options: raw.options,
        })
    });
    ReadCase { id, case }
}

/// What `options` must satisfy beyond their types: a positive `time_limit`.
pub(super) fn check_options(options: &Options) -> Result<(), GeomError> {
    match options.time_limit {
        Some(Double(t)) if t.is_nan() || t <= 0.0 => Err(GeomError::InvalidValue {
            field: "options.time_limit".into(),
            reason: format!("{} is not a positive number of seconds", shortest(t)),
        }),
        _ => Ok(()),
    }
}

/// serde reports a missing required field at the path of the object that lacks it;
/// the field to name is the missing one (`op`, not the whole case).
fn name_missing_field(e: GeomError) -> GeomError {
    match e {
        GeomError::Format { field, message } if field.is_empty() => {
            let missing = message
                .strip_prefix("missing field `")
                .and_then(|rest| rest.split('`').next())
                .map(str::to_string);
            GeomError::Format {
                field: missing.unwrap_or(field),
                message,
            }
        }
        other => other,
    }
}

fn json_kind(value: &serde_json::Value) -> &'static str {
    match value {
        serde_json::Value::Null => "null",
        serde_json::Value::Bool(_) => "a boolean",
        serde_json::Value::Number(_) => "a number",
        serde_json::Value::String(_) => "a string",
        serde_json::Value::Array(_) => "an array",
        serde_json::Value::Object(_) => "an object",
    }
}

/// The careful road of [`super::read_chunk`]: strict JSON, then the case format with every
/// error naming its field (the quick road, [`super::fast`], only ever accepts).
pub(super) fn read_careful(text: &str, chunk: &Chunk) -> Record {
    match parse_strict(text) {
        Ok(Parsed { value, raw_id }) => {
            let raw = raw_id.map(|r| r.get().to_string()).filter(|r| is_number(r));
            let read = parse_case(value);
            Record {
                read,
                line: chunk.line,
                raw_id: raw,
            }
        }
        Err(StrictError::Duplicate { field, message }) => {
            let (id, raw) = salvaged_id(salvage(text).id);
            record(chunk, id, raw, Err(format_error(field, message)))
        }
        Err(StrictError::Syntax(e)) => {
            let found = salvage(text);
            let (id, raw) = salvaged_id(found.id);
            let error = match found.non_finite {
                Some((field, value)) => GeomError::NonFinite {
                    field,
                    value: abbreviate(&value),
                },
                None => syntax_error(chunk, &e),
            };
            record(chunk, id, raw, Err(error))
        }
    }
}

pub(super) fn record(
    chunk: &Chunk,
    id: serde_json::Value,
    raw_id: Option<String>,
    case: Result<Case, GeomError>,
) -> Record {
    Record {
        read: ReadCase { id, case },
        line: chunk.line,
        raw_id,
    }
}

pub(super) fn format_error(field: String, message: String) -> GeomError {
    GeomError::Format { field, message }
}

/// The id recovered from a broken case: its value, and its raw text if a number.
pub(super) fn salvaged_id(raw: Option<String>) -> (serde_json::Value, Option<String>) {
    match raw {
        Some(raw) if is_number(&raw) => {
            let value = serde_json::from_str(&raw).unwrap_or(serde_json::Value::Null);
            (value, Some(raw))
        }
        Some(raw) => (
            serde_json::from_str(&raw).unwrap_or(serde_json::Value::Null),
            None,
        ),
        None => (serde_json::Value::Null, None),
    }
}

/// Whether a raw JSON value is a number literal that serde_json accepts.
fn is_number(raw: &str) -> bool {
    raw.starts_with(|c: char| c == '-' || c.is_ascii_digit())
        && serde_json::from_str::<serde_json::Number>(raw).is_ok()
}

/// A syntax error, at its line of the input (`field: "line N"`) and column.
fn syntax_error(chunk: &Chunk, e: &serde_json::Error) -> GeomError {
    let text = e.to_string();
    let suffix = format!(" at line {} column {}", e.line(), e.column());
    let message = text.strip_suffix(&suffix).unwrap_or(&text);
    // serde_json counts a line break as the start of the next line (column 0).
    let (l, c) = (e.line().max(1), e.column());
    let (line, at) = match (l, c) {
        (l, 0) if l > 1 => (chunk.line + l - 2, "at the end of the line".to_string()),
        (1, c) => (
            chunk.line,
            format!("column {}", chunk.column + c.max(1) - 1),
        ),
        (l, c) => (chunk.line + l - 1, format!("column {c}")),
    };
    format_error(format!("line {line}"), format!("{message} ({at})"))
}
