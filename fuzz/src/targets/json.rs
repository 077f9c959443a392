//! The JSON case reader: the bytes are a case file (JSON Lines or an array), read and
//! solved case by case as `geocert solve` does (`geocert::io::stream`, `read_chunk`,
//! `solve_case`), with a small time limit applied as `--time-limit` would.

use super::check;
use geocert::io::read_chunk;
use geocert::io::stream::CaseStream;
use geocert::io::{solve_case, verify_case, Double};

/// Cases read from one input at most (the rest of the input is left unread).
const MAX_CASES: usize = 16;

/// Read `data` as a case file and solve (or, for a case with a `claim`, verify) every
/// case in it; check each result record.
pub fn json_lines(data: &[u8]) {
    let mut stream = CaseStream::new(data);
    for _ in 0..MAX_CASES {
        let chunk = match stream.next_chunk() {
            Ok(Some(chunk)) => chunk,
            Ok(None) => break,
            Err(e) => panic!("reading from memory failed: {e}"),
        };
        let mut record = read_chunk(&chunk);
        let verify = String::from_utf8_lossy(&chunk.bytes).contains("\"claim\"");
        if let Ok(case) = &mut record.read.case {
            let o = &mut case.options;
            // The command line's defaults apply to cases that set none; the fuzzer's
            // budgets also cap what a case asks for, so that one input stays cheap.
            let t = o
                .time_limit
                .map_or(super::TIME_LIMIT, |t| t.0.min(super::TIME_LIMIT));
            o.time_limit = Some(Double(t));
            o.max_boxes = Some(
                o.max_boxes
                    .unwrap_or(super::MAX_BOXES)
                    .min(super::MAX_BOXES),
            );
            o.max_bits = Some(o.max_bits.unwrap_or(512).min(1024));
        }
        let result = if verify {
            verify_case(record.read)
        } else {
            solve_case(record.read)
        };
        check::record(&result.to_json_line());
    }
}
