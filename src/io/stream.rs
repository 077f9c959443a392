//! Reading a case file as a stream (spec/CASES.md: a JSON array, or JSON Lines), so
//! that memory stays flat whatever the file's size: [`CaseStream`] cuts the input
//! into [`Chunk`]s, one case each, without parsing them; [`super::read_chunk`] parses one
//! (on any thread). One bad case costs that case only:
//!
//! - JSON Lines: a line ends at LF, CRLF or a lone CR; blank lines are skipped; a
//!   byte-order mark at the start of a line is skipped (files joined with `cat`);
//!   a line that is not UTF-8 or not JSON is one error record, `field: "line N"`.
//! - JSON array (the first byte other than white space or a BOM is `[`): elements are
//!   cut at the top-level commas by tracking strings and bracket depth, so a syntax
//!   error that leaves brackets and quotes balanced costs its element only. A raw
//!   line break inside a string (never valid JSON) ends the string, so a missing
//!   closing quote costs one element too. An unbalanced bracket cannot be
//!   resynchronised: the rest of the array is then one error record (read, not
//!   stored: see [`MAX_CASE_BYTES`]). Text after the closing `]` and a missing `]`
//!   are one error record each.

use std::io::{self, BufRead};

/// A case longer than this (in bytes) is an error record, and its bytes are skipped
/// rather than stored.
pub const MAX_CASE_BYTES: usize = 16 << 20;

/// One case's text, cut from the input.
#[derive(Debug, Clone, Default)]
pub struct Chunk {
    /// The input line (1-based) the case starts on.
    pub line: usize,
    /// The column (1-based, in bytes) of the case's first byte on that line.
    pub column: usize,
    /// The byte offset in the input just after the case (for progress reports).
    pub end: u64,
    pub bytes: Vec<u8>,
    /// Set when the input around this case is broken (the error record's message).
    pub problem: Option<String>,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Form {
    Unknown,
    Lines,
    Array,
    /// The input ended after a whole element: `]` is missing (one error record).
    Unclosed,
    /// After the array's `]` (or after the input ended).
    Done,
}

/// The cases of a JSON array or JSON Lines input, one [`Chunk`] at a time.
pub struct CaseStream<R> {
    input: R,
    form: Form,
    /// Line and column (1-based, in bytes) of the next byte.
    line: usize,
    column: usize,
    /// Bytes consumed so far.
    offset: u64,
    /// The previous byte was a CR (a following LF belongs to the same line end).
    after_cr: bool,
}

impl<R: BufRead> CaseStream<R> {
    pub fn new(input: R) -> Self {
        CaseStream {
            input,
            form: Form::Unknown,
            line: 1,
            column: 1,
            offset: 0,
            after_cr: false,
        }
    }

    /// Take one byte, counting lines (LF, CRLF and lone CR each end one line).
    fn next_byte(&mut self) -> io::Result<Option<u8>> {
        let buf = loop {
            match self.input.fill_buf() {
                Ok(buf) => break buf,
                Err(e) if e.kind() == io::ErrorKind::Interrupted => continue,
                Err(e) => return Err(e),
            }
        };
        let Some(&b) = buf.first() else {
            return Ok(None);
        };
        self.input.consume(1);
        self.offset += 1;
        match b {
            b'\n' if self.after_cr => {}
            b'\n' | b'\r' => {
                self.line += 1;
                self.column = 1;
            }
            _ => self.column += 1,
        }
        self.after_cr = b == b'\r';
        Ok(Some(b))
    }

    fn peek_byte(&mut self) -> io::Result<Option<u8>> {
        loop {
            match self.input.fill_buf() {
                Ok(buf) => return Ok(buf.first().copied()),
                Err(e) if e.kind() == io::ErrorKind::Interrupted => continue,
                Err(e) => return Err(e),
            }
        }
    }

    /// Skip white space and byte-order marks; the first other byte, not consumed.
    fn skip_blank(&mut self) -> io::Result<Option<u8>> {
        loop {
            match self.peek_byte()? {
                Some(b' ' | b'\t' | b'\n' | b'\r') => {
                    self.next_byte()?;
                }
                Some(0xEF) if self.bom_ahead()? => {
                    for _ in 0..3 {
                        self.next_byte()?;
                    }
                }
                other => return Ok(other),
            }
        }
    }

    /// Whether the next three bytes are a UTF-8 byte-order mark (EF BB BF).
    fn bom_ahead(&mut self) -> io::Result<bool> {
        // A mark split across two reads is not seen here; [`super::read_chunk`] strips it.
        Ok(self.input.fill_buf()?.starts_with(&[0xEF, 0xBB, 0xBF]))
    }

    /// The next line of JSON Lines: its bytes up to the line end (not included).
    fn next_line(&mut self) -> io::Result<Option<Chunk>> {
        let Some(_) = self.skip_blank()? else {
            return Ok(None);
        };
        let mut chunk = Chunk {
            line: self.line,
            column: self.column,
            ..Chunk::default()
        };
        let mut too_long = false;
        while let Some(b) = self.peek_byte()? {
            if b == b'\n' || b == b'\r' {
                break;
            }
            // Take the rest of the line from the buffer at once.
            let buf = self.input.fill_buf()?;
            let n = buf
                .iter()
                .position(|&c| c == b'\n' || c == b'\r')
                .unwrap_or(buf.len());
            if chunk.bytes.len() + n > MAX_CASE_BYTES {
                too_long = true;
            } else {
                chunk.bytes.extend_from_slice(&buf[..n]);
            }
            self.input.consume(n);
            self.offset += n as u64;
            self.column += n;
            self.after_cr = false;
        }
        chunk.end = self.offset;
        if too_long {
            chunk.bytes.clear();
            chunk.problem = Some(too_long_message());
        }
        Ok(Some(chunk))
    }

    /// The next element of a JSON array (after `[` or a top-level `,`).
    fn next_element(&mut self) -> io::Result<Option<Chunk>> {
        let Some(first) = self.skip_blank()? else {
            self.form = Form::Done;
            return Ok(Some(
                self.problem("the file ends inside the array: `]` is missing"),
            ));
        };
        if first == b']' {
            self.next_byte()?;
            return self.after_array();
        }
        let mut chunk = Chunk {
            line: self.line,
            column: self.column,
            ..Chunk::default()
        };
        let (mut depth, mut in_string, mut escape, mut too_long) = (0usize, false, false, false);
        loop {
            let Some(b) = self.peek_byte()? else {
                // The input ends inside the element: let its parse report it, and say
                // that the array is not closed when the element itself looks whole.
                self.form = if depth == 0 && !in_string {
                    Form::Unclosed
                } else {
                    Form::Done
                };
                break;
            };
            if !in_string && depth == 0 && (b == b',' || b == b']') {
                if b == b',' {
                    self.next_byte()?;
                    if chunk.bytes.iter().all(u8::is_ascii_whitespace) {
                        chunk.problem = Some("an empty element (two commas in a row)".into());
                    }
                }
                // `]` is left for the next call, which ends the array.
                break;
            }
            self.next_byte()?;
            if in_string {
                match b {
                    _ if escape => escape = false,
                    b'\\' => escape = true,
                    b'"' | b'\n' | b'\r' => in_string = false,
                    _ => {}
                }
            } else {
                match b {
                    b'"' => in_string = true,
                    b'{' | b'[' => depth += 1,
                    b'}' | b']' => depth = depth.saturating_sub(1),
                    _ => {}
                }
            }
            if chunk.bytes.len() < MAX_CASE_BYTES {
                chunk.bytes.push(b);
            } else {
                too_long = true;
            }
        }
        chunk.end = self.offset;
        if too_long {
            chunk.bytes.clear();
            chunk.problem = Some(too_long_message());
        }
        Ok(Some(chunk))
    }

    /// After `]`: only white space may follow.
    fn after_array(&mut self) -> io::Result<Option<Chunk>> {
        self.form = Form::Done;
        let Some(_) = self.skip_blank()? else {
            return Ok(None);
        };
        let chunk = self.problem("text after the end of the array");
        // Read the rest without storing it.
        while self.next_byte()?.is_some() {}
        Ok(Some(chunk))
    }

    fn problem(&self, message: &str) -> Chunk {
        Chunk {
            line: self.line,
            column: self.column,
            end: self.offset,
            bytes: Vec::new(),
            problem: Some(message.to_string()),
        }
    }

    /// The next case, `None` at the end of the input, or the error reading it.
    pub fn next_chunk(&mut self) -> io::Result<Option<Chunk>> {
        loop {
            match self.form {
                Form::Unknown => match self.skip_blank()? {
                    Some(b'[') => {
                        self.next_byte()?;
                        self.form = Form::Array;
                    }
                    Some(_) => self.form = Form::Lines,
                    None => return Ok(None),
                },
                Form::Lines => return self.next_line(),
                Form::Array => return self.next_element(),
                Form::Unclosed => {
                    self.form = Form::Done;
                    return Ok(Some(
                        self.problem("the file ends inside the array: `]` is missing"),
                    ));
                }
                Form::Done => return Ok(None),
            }
        }
    }
}

fn too_long_message() -> String {
    format!(
        "the case is longer than {} MiB (not read)",
        MAX_CASE_BYTES >> 20
    )
}

impl<R: BufRead> Iterator for CaseStream<R> {
    type Item = io::Result<Chunk>;
    fn next(&mut self) -> Option<Self::Item> {
        self.next_chunk().transpose()
    }
}
