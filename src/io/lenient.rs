//! A forgiving second look at a case that is not valid JSON (spec/CASES.md "Numbers":
//! NaN and infinities are rejected *with an error that names the field*).
//!
//! JSON has no NaN or Infinity literal and serde_json refuses a number beyond the
//! double range (`1e309`), so such a case fails as a whole with a syntax error. This
//! scanner walks the same text with a tolerant grammar (bare words and out-of-range
//! numbers are values; it gives up quietly at the first real syntax error) and reports
//! the field path of the first non-finite number, and the raw text of the top-level
//! `id`, so that even an unreadable case is echoed with the id its author gave it.
//! It only runs on cases that serde_json refused, so it costs nothing on good input.

/// What the scanner could read of a broken case.
#[derive(Debug, Default, Clone, PartialEq, Eq)]
pub struct Salvage {
    /// The raw text of the top-level `id` value, if it is a complete scalar.
    pub id: Option<String>,
    /// The path (`objects[1].d`) and text (`NaN`, `1e309`) of the first value that is
    /// a non-finite number.
    pub non_finite: Option<(String, String)>,
}

/// Scan `text` leniently (see the module documentation).
pub fn salvage(text: &str) -> Salvage {
    let mut s = Scanner {
        b: text.as_bytes(),
        i: 0,
        path: Vec::new(),
        out: Salvage::default(),
    };
    s.value(0);
    s.out
}

#[derive(Debug, Clone)]
enum Seg {
    Key(String),
    Index(usize),
}

struct Scanner<'a> {
    b: &'a [u8],
    i: usize,
    path: Vec<Seg>,
    out: Salvage,
}

/// Nesting deeper than this is not followed (the scanner must not overflow its stack).
const MAX_DEPTH: usize = 128;

impl Scanner<'_> {
    fn ws(&mut self) {
        while self.i < self.b.len() && matches!(self.b[self.i], b' ' | b'\t' | b'\n' | b'\r') {
            self.i += 1;
        }
    }

    fn peek(&self) -> Option<u8> {
        self.b.get(self.i).copied()
    }

    /// One value; `None` when the text stops making sense (the scan then ends).
    fn value(&mut self, depth: usize) -> Option<()> {
        if depth > MAX_DEPTH {
            return None;
        }
        self.ws();
        match self.peek()? {
            b'{' => self.object(depth),
            b'[' => self.array(depth),
            b'"' => self.string().map(|_| ()),
            _ => {
                let start = self.i;
                self.bare()?;
                let token = &self.b[start..self.i];
                if self.out.non_finite.is_none() && is_non_finite(token) {
                    let text = String::from_utf8_lossy(token).into_owned();
                    self.out.non_finite = Some((path_text(&self.path), text));
                }
                Some(())
            }
        }
    }

    fn object(&mut self, depth: usize) -> Option<()> {
        self.i += 1;
        self.ws();
        if self.peek()? == b'}' {
            self.i += 1;
            return Some(());
        }
        loop {
            self.ws();
            let key = self.string()?;
            self.ws();
            (self.peek()? == b':').then_some(())?;
            self.i += 1;
            self.ws();
            let start = self.i;
            self.path.push(Seg::Key(key));
            let ok = self.value(depth + 1);
            let Some(Seg::Key(key)) = self.path.pop() else {
                return None;
            };
            ok?;
            if depth == 0 && key == "id" && self.out.id.is_none() {
                let raw = String::from_utf8_lossy(&self.b[start..self.i]).into_owned();
                if !raw.starts_with(['{', '[']) {
                    self.out.id = Some(raw);
                }
            }
            self.ws();
            match self.peek()? {
                b',' => self.i += 1,
                b'}' => {
                    self.i += 1;
                    return Some(());
                }
                _ => return None,
            }
        }
    }

    fn array(&mut self, depth: usize) -> Option<()> {
        self.i += 1;
        self.ws();
        if self.peek()? == b']' {
            self.i += 1;
            return Some(());
        }
        let mut k = 0;
        loop {
            self.path.push(Seg::Index(k));
            let ok = self.value(depth + 1);
            self.path.pop();
            ok?;
            self.ws();
            match self.peek()? {
                b',' => self.i += 1,
                b']' => {
                    self.i += 1;
                    return Some(());
                }
                _ => return None,
            }
            k += 1;
        }
    }

    /// A string; its content with the simple escapes undone (others kept as written).
    fn string(&mut self) -> Option<String> {
        (self.peek()? == b'"').then_some(())?;
        self.i += 1;
        let mut out = Vec::new();
        loop {
            let c = self.peek()?;
            self.i += 1;
            match c {
                b'"' => return Some(String::from_utf8_lossy(&out).into_owned()),
                b'\\' => {
                    let e = self.peek()?;
                    self.i += 1;
                    match e {
                        b'"' | b'\\' | b'/' => out.push(e),
                        _ => out.extend_from_slice(&[b'\\', e]),
                    }
                }
                b'\n' | b'\r' => return None,
                _ => out.push(c),
            }
        }
    }

    /// A bare token: a number, `true`, `NaN`, `-Infinity`, ...
    fn bare(&mut self) -> Option<()> {
        let start = self.i;
        while self.i < self.b.len()
            && (self.b[self.i].is_ascii_alphanumeric()
                || matches!(self.b[self.i], b'+' | b'-' | b'.'))
        {
            self.i += 1;
        }
        (self.i > start).then_some(())
    }
}

/// `NaN`, `Infinity`, `-inf`, ... or a number literal beyond the double range.
fn is_non_finite(token: &[u8]) -> bool {
    let Ok(t) = std::str::from_utf8(token) else {
        return false;
    };
    let word = t.trim_start_matches(['+', '-']).to_ascii_lowercase();
    if matches!(word.as_str(), "nan" | "inf" | "infinity") {
        return true;
    }
    let numeric = t
        .bytes()
        .next()
        .is_some_and(|c| c.is_ascii_digit() || c == b'-');
    numeric && t.parse::<f64>().is_ok_and(|v| v.is_infinite())
}

fn path_text(path: &[Seg]) -> String {
    let mut s = String::new();
    for seg in path {
        match seg {
            Seg::Key(k) if s.is_empty() => s.push_str(k),
            Seg::Key(k) => {
                s.push('.');
                s.push_str(k);
            }
            Seg::Index(i) => s.push_str(&format!("[{i}]")),
        }
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_the_non_finite_field_and_keeps_the_id() {
        let s = salvage(
            r#"{"id": 12345678901234567890123, "op": "intersect", "objects": [{"type": "plane", "normal": [0, 0, 1], "d": NaN}]}"#,
        );
        assert_eq!(s.id.as_deref(), Some("12345678901234567890123"));
        assert_eq!(s.non_finite, Some(("objects[0].d".into(), "NaN".into())));
        for (bad, path) in [
            (r#"{"point": [1, -Infinity, 2]}"#, "point[1]"),
            (r#"{"point": [1, 2, 1e309]}"#, "point[2]"),
            (
                r#"{"options": {"tolerance": -1E+400}}"#,
                "options.tolerance",
            ),
        ] {
            assert_eq!(salvage(bad).non_finite.unwrap().0, path, "{bad}");
        }
    }

    #[test]
    fn gives_up_quietly_on_real_syntax_errors() {
        let s = salvage(r#"{"id": "a\"b", "op": "intersect", "objects": [}"#);
        assert_eq!(s.id.as_deref(), Some(r#""a\"b""#));
        assert_eq!(s.non_finite, None);
        assert_eq!(salvage("not json at all"), Salvage::default());
        assert_eq!(salvage(&"[".repeat(100_000)), Salvage::default());
        // Finite numbers and tiny ones (which round to zero) are not reported.
        assert_eq!(salvage(r#"{"x": [1e-400, 1e308, -0.5]"#).non_finite, None);
    }
}
