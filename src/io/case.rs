//! Cases of the command line (spec/CASES.md "Cases"): reading a file of cases and
//! turning each into a typed [`Case`], or an error naming the offending field.

use super::de::deserialize_at;
use super::number::{Double, Num};
use super::objects::{parse_object, ObjectSpec};
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
            Op::Walk => "walk",
        }
    }
}

/// `options` of a case (CASES.md; OPERATIONS.md §12 for ε and δ).
#[derive(Debug, Clone, Default, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Options {
    /// The operation tolerance ε of the float path (§12).
    pub tolerance: Option<Double>,
    /// The equality tolerance δ of the float path (§12).
    pub equal_tolerance: Option<Double>,
    /// The precision cap of MPFR escalation, in bits (default 512; CERTIFICATION.md
    /// names 4096, reachable by setting it).
    pub max_bits: Option<u32>,
    /// The box budget of subdivision.
    pub max_boxes: Option<u64>,
    /// Surface ∩ surface: the largest chord-to-curve distance of the polylines.
    pub chord_tolerance: Option<Double>,
    /// Also report the exact rationals of exact results (`"p/q"` strings).
    #[serde(default)]
    pub exact: bool,
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
    pub options: Options,
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

/// Parse one JSON value into a case, naming the field path of any error
/// (`objects[1].dir[2]`).
pub fn parse_case(value: serde_json::Value) -> ReadCase {
    let id = value.get("id").cloned().unwrap_or(serde_json::Value::Null);
    let case = deserialize_at::<RawCase>(value, "").and_then(|raw| {
        let objects = raw
            .objects
            .into_iter()
            .enumerate()
            .map(|(i, v)| parse_object(v, &format!("objects[{i}]")))
            .collect::<Result<Vec<_>, _>>()?;
        let onto = raw.onto.map(|v| parse_object(v, "onto")).transpose()?;
        let shell = raw.shell.map(|v| parse_object(v, "shell")).transpose()?;
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
            options: raw.options,
        })
    });
    ReadCase { id, case }
}

/// Read every case of a file: a JSON array of cases, or JSON Lines (one case per
/// line; blank lines ignored). A line that is not valid JSON becomes an error case
/// (field `line N`), so one bad case does not stop the others.
pub fn read_cases(text: &str) -> Vec<ReadCase> {
    let trimmed = text.trim_start();
    if trimmed.starts_with('[') {
        return match serde_json::from_str::<Vec<serde_json::Value>>(trimmed) {
            Ok(values) => values.into_iter().map(parse_case).collect(),
            Err(e) => vec![syntax_error("", &e)],
        };
    }
    text.lines()
        .enumerate()
        .filter(|(_, line)| !line.trim().is_empty())
        .map(
            |(n, line)| match serde_json::from_str::<serde_json::Value>(line) {
                Ok(value) => parse_case(value),
                Err(e) => syntax_error(&format!("line {}", n + 1), &e),
            },
        )
        .collect()
}

fn syntax_error(field: &str, e: &serde_json::Error) -> ReadCase {
    ReadCase {
        id: serde_json::Value::Null,
        case: Err(GeomError::Format {
            field: field.to_string(),
            message: e.to_string(),
        }),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn json_lines_and_arrays_read_alike() {
        let lines = r#"{"id": "a", "op": "project", "point": [1,2,3], "onto": {"type": "plane", "normal": [0,0,1], "d": 0}}

{"id": "b", "op": "intersect", "objects": []}"#;
        let cases = read_cases(lines);
        assert_eq!(cases.len(), 2);
        assert!(cases.iter().all(|c| c.case.is_ok()));
        let array = format!("[{}]", lines.replace("\n\n", ","));
        let again = read_cases(&array);
        assert_eq!(again.len(), 2);
        assert_eq!(again[1].id, serde_json::json!("b"));
        assert_eq!(
            again[0].case.as_ref().unwrap(),
            cases[0].case.as_ref().unwrap()
        );
    }

    #[test]
    fn unknown_fields_are_errors_naming_the_field() {
        let cases = read_cases(r#"{"id": 7, "op": "intersect", "objectz": []}"#);
        let err = cases[0].case.as_ref().unwrap_err();
        assert_eq!(err.kind(), "format");
        assert!(err.to_string().contains("objectz"), "{err}");
        assert_eq!(cases[0].id, serde_json::json!(7));

        let cases = read_cases(
            r#"{"op": "intersect", "objects": [{"type": "line", "origin": [0,0,0], "dir": [1,0,0], "colour": 1}]}"#,
        );
        let err = cases[0].case.as_ref().unwrap_err();
        assert!(err.to_string().contains("colour"), "{err}");
        assert!(err.field().starts_with("objects[0]"), "{}", err.field());
    }

    #[test]
    fn bad_lines_do_not_stop_the_others() {
        let cases = read_cases("{\"op\": \"project\"\nnot json\n{\"op\": \"intersect\"}\n");
        assert_eq!(cases.len(), 3);
        assert_eq!(cases[0].case.as_ref().unwrap_err().field(), "line 1");
        assert_eq!(cases[1].case.as_ref().unwrap_err().field(), "line 2");
        assert!(cases[2].case.is_ok());
    }

    #[test]
    fn wrong_vector_length_names_the_field() {
        let cases = read_cases(
            r#"{"op": "intersect", "objects": [{"type": "line", "origin": [0,0], "dir": [1,0,0]}]}"#,
        );
        let err = cases[0].case.as_ref().unwrap_err();
        assert_eq!(err.field(), "objects[0].origin");
    }
}
