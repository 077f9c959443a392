//! Reading cases (docs/FORMAT.md "Cases"): a text or a stream cut into one chunk per
//! case ([`super::stream`]), each read by the quick road ([`super::fast`]) when it
//! takes the case, else by the careful one ([`super::case`]), which names the field of
//! every error.

use super::case::{format_error, read_careful, record, salvaged_id, ReadCase, Record};
use super::fast::read_quick;
use super::lenient::salvage;
use super::stream::{CaseStream, Chunk};
use crate::error::GeomError;
use std::io::BufRead;

/// Read every case of a text: a JSON array of cases, or JSON Lines (one case per
/// line; blank lines ignored). A line that is not valid JSON becomes an error case
/// (field `line N`), so one bad case does not stop the others ([`super::stream`]).
pub fn read_cases(text: &str) -> Vec<ReadCase> {
    read_stream(text.as_bytes())
        .map(|r| match r {
            Ok(record) => record.read,
            // Reading from memory cannot fail; keep the error as a record anyway.
            Err(e) => input_error(&e),
        })
        .collect()
}

/// Read the cases of a stream one at a time, in input order (see [`super::stream`]
/// for what one bad line or element costs). An `Err` is a failure to read the input
/// itself; the stream ends after it.
pub fn read_stream<R: BufRead>(input: R) -> impl Iterator<Item = std::io::Result<Record>> {
    let mut stream = CaseStream::new(input);
    let mut failed = false;
    std::iter::from_fn(move || {
        if failed {
            return None;
        }
        let next = stream.next_chunk().transpose()?;
        failed = next.is_err();
        Some(next.map(|chunk| read_chunk(&chunk)))
    })
}

fn input_error(e: &std::io::Error) -> ReadCase {
    ReadCase {
        id: serde_json::Value::Null,
        case: Err(GeomError::Format {
            field: String::new(),
            message: format!("cannot read the input: {e}"),
        }),
    }
}

/// Parse one case cut from the input: UTF-8, then JSON (duplicate keys refused,
/// [`super::strict`]), then the case format. A case that is not JSON is looked at
/// again leniently ([`super::lenient`]) to name a NaN, infinite or out-of-range
/// number's field and to recover the id.
pub fn read_chunk(chunk: &Chunk) -> Record {
    let line_field = || format!("line {}", chunk.line);
    if let Some(problem) = &chunk.problem {
        let error = format_error(line_field(), problem.clone());
        return record(chunk, serde_json::Value::Null, None, Err(error));
    }
    let bytes = chunk
        .bytes
        .strip_prefix(&[0xEF, 0xBB, 0xBF])
        .unwrap_or(&chunk.bytes);
    let text = match std::str::from_utf8(bytes) {
        Ok(text) => text,
        Err(e) => {
            let salvage = salvage(&String::from_utf8_lossy(bytes));
            let message = format!(
                "not UTF-8: invalid byte {:#04x} at column {}",
                bytes[e.valid_up_to()],
                chunk.column + e.valid_up_to()
            );
            let (id, raw) = salvaged_id(salvage.id);
            return record(chunk, id, raw, Err(format_error(line_field(), message)));
        }
    };
    read_quick(text, chunk.line).unwrap_or_else(|| read_careful(text, chunk))
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
