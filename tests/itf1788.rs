//! ITF1788 conformance (Interval Test Framework for IEEE 1788, Apache-2.0; the vectors
//! are copied into tests/data/itf1788/ by tools/import-itf1788.sh and parsed here at
//! test time).
//!
//! For every vector of every supported operation (decorated test cases are skipped:
//! geocert has no decorations; unsupported operations are listed in the table):
//! * `Interval` contains the expected (tightest) interval, EQUALS it for the
//!   operations it documents as tightest (+ − × ÷ √ and others, see `TIGHTEST_F64`),
//!   and is within 8 ulps of it for the others (Taylor paths, powi);
//! * `MpfrInterval` at 53 and 128 bits is a subset of the expected interval, and at
//!   53 bits its outward rounding to f64 equals it;
//! * scalar and boolean results are equal.
//!
//! Number literals are read exactly and rounded to the nearest double, as the C++ tests
//! the vectors come from (libieeep1788) did: `[13.1, 13.1]` is the point interval at the
//! double nearest to 13.1 (`pown [13.1,13.1] 2` expects its square's tightest
//! enclosure). Results are hexadecimal or exact.
//! The counts of checked vectors are printed and must equal the counts found by an
//! independent line scan of the files, so a broken parser cannot pass silently.

use geocert::num::{Interval, IntervalLike, MpfrInterval};

use rug::{Integer, Rational};
use std::collections::BTreeMap;
use std::path::Path;

/// Operations whose f64 result must equal the expected tightest interval.
const TIGHTEST_F64: &[&str] = &[
    "add",
    "sub",
    "mul",
    "div",
    "sqrt",
    "neg",
    "sqr",
    "recip",
    "abs",
    "intersection",
    "convexHull",
    "log",
    "sinh",
    "cosh",
    "atan2",
];
/// Interval-valued operations checked for containment only in f64 (Taylor paths, powi).
const ENCLOSING_F64: &[&str] = &["exp", "sin", "cos", "tan", "pown"];
const SCALAR_OPS: &[&str] = &["inf", "sup", "mid", "rad", "wid", "mag", "mig"];
const BOOL_OPS: &[&str] = &[
    "subset", "interior", "isEmpty", "isEntire", "equal", "disjoint",
];

/// Minimum number of non-decorated vectors per supported operation in the files
/// (counted with awk when the files were imported), so that a shrunken copy fails.
const MIN_COUNTS: &[(&str, usize)] = &[
    ("abs", 12),
    ("add", 31),
    ("atan2", 169),
    ("convexHull", 5),
    ("cos", 52),
    ("cosh", 11),
    ("disjoint", 10),
    ("div", 341),
    ("equal", 15),
    ("exp", 19),
    ("inf", 14),
    ("interior", 16),
    ("intersection", 5),
    ("isEmpty", 14),
    ("isEntire", 14),
    ("log", 21),
    ("mag", 7),
    ("mid", 7),
    ("mig", 10),
    ("mul", 116),
    ("neg", 11),
    ("pown", 163),
    ("rad", 5),
    ("recip", 18),
    ("sin", 52),
    ("sinh", 11),
    ("sqr", 12),
    ("sqrt", 13),
    ("sub", 31),
    ("subset", 27),
    ("sup", 14),
    ("tan", 33),
    ("wid", 5),
];

fn supported(op: &str) -> bool {
    TIGHTEST_F64.contains(&op)
        || ENCLOSING_F64.contains(&op)
        || SCALAR_OPS.contains(&op)
        || BOOL_OPS.contains(&op)
}

/// A number of the ITL format: a finite rational or ±∞.
#[derive(Clone, Debug)]
enum Num {
    Finite(Rational),
    PosInf,
    NegInf,
}

#[derive(Clone, Debug)]
enum Value {
    Interval(Interval),
    Number(Num),
    Bool(bool),
}

struct Vector {
    place: String,
    op: String,
    args: Vec<Value>,
    expected: Value,
}

/// Parse a decimal (`-7451.145`, `1e-3`) or hexadecimal (`0X1.921FB54442D18P+0`)
/// literal exactly.
fn parse_num(tok: &str) -> Num {
    let t = tok.trim();
    match t.to_ascii_lowercase().as_str() {
        "infinity" | "+infinity" | "inf" | "+inf" => return Num::PosInf,
        "-infinity" | "-inf" => return Num::NegInf,
        _ => {}
    }
    let (neg, body) = match t.as_bytes()[0] {
        b'-' => (true, &t[1..]),
        b'+' => (false, &t[1..]),
        _ => (false, t),
    };
    let lower = body.to_ascii_lowercase();
    let value = if let Some(hex) = lower.strip_prefix("0x") {
        let (mant, exp) = hex.split_once('p').unwrap_or((hex, "0"));
        let (int, frac) = mant.split_once('.').unwrap_or((mant, ""));
        let digits = format!("{int}{frac}");
        let m = Integer::from_str_radix(if digits.is_empty() { "0" } else { &digits }, 16)
            .unwrap_or_else(|e| panic!("bad hex {tok}: {e}"));
        let e: i64 = exp
            .parse()
            .unwrap_or_else(|e| panic!("bad exponent {tok}: {e}"));
        let shift = e - 4 * frac.len() as i64;
        let mut q = Rational::from(m);
        if shift >= 0 {
            q <<= shift as u32;
        } else {
            q >>= (-shift) as u32;
        }
        q
    } else {
        let (mant, exp) = lower.split_once('e').unwrap_or((&lower, "0"));
        let (int, frac) = mant.split_once('.').unwrap_or((mant, ""));
        let digits = format!("{int}{frac}");
        let m = Integer::from_str_radix(&digits, 10)
            .unwrap_or_else(|e| panic!("bad decimal {tok}: {e}"));
        let e: i32 = exp
            .parse::<i32>()
            .unwrap_or_else(|e| panic!("bad exponent {tok}: {e}"))
            - frac.len() as i32;
        let p = Rational::from(Integer::from(Integer::u_pow_u(10, e.unsigned_abs())));
        if e >= 0 {
            Rational::from(m) * p
        } else {
            Rational::from(m) / p
        }
    };
    Num::Finite(if neg { -value } else { value })
}

/// The double nearest to an exact number.
fn nearest(q: &Rational) -> f64 {
    rug::Float::with_val(53, q).to_f64()
}

/// Bounds of an ITL interval literal, each rounded to the nearest double.
fn parse_interval(tok: &str) -> Interval {
    let inner = tok
        .trim()
        .trim_start_matches('[')
        .trim_end_matches(']')
        .trim();
    match inner {
        "empty" => return Interval::EMPTY,
        "entire" => return Interval::ENTIRE,
        _ => {}
    }
    let (a, b) = inner.split_once(',').unwrap_or((inner, inner));
    let lo = match parse_num(a) {
        Num::Finite(q) => nearest(&q),
        Num::NegInf => f64::NEG_INFINITY,
        Num::PosInf => panic!("lower bound +inf in {tok}"),
    };
    let hi = match parse_num(b) {
        Num::Finite(q) => nearest(&q),
        Num::PosInf => f64::INFINITY,
        Num::NegInf => panic!("upper bound -inf in {tok}"),
    };
    Interval::from_bounds(lo, hi)
}

/// Split `[a, b] [c, d] 3` into tokens, keeping bracketed literals (and any decoration
/// suffix) together.
fn tokens(s: &str) -> Vec<String> {
    let mut out = vec![];
    let mut cur = String::new();
    let mut depth = 0;
    for ch in s.chars() {
        match ch {
            '[' => {
                depth += 1;
                cur.push(ch);
            }
            ']' => {
                depth -= 1;
                cur.push(ch);
            }
            c if c.is_whitespace() && depth == 0 => {
                if !cur.is_empty() {
                    out.push(std::mem::take(&mut cur));
                }
            }
            c => cur.push(c),
        }
    }
    if !cur.is_empty() {
        out.push(cur);
    }
    out
}

fn parse_value(tok: &str) -> Value {
    if tok.starts_with('[') {
        Value::Interval(parse_interval(tok))
    } else if tok == "true" || tok == "false" {
        Value::Bool(tok == "true")
    } else {
        Value::Number(parse_num(tok))
    }
}

/// Remove `/* … */` and `// …` comments.
fn strip_comments(text: &str) -> String {
    let mut out = String::new();
    let mut rest = text;
    while let Some(i) = rest.find("/*") {
        out.push_str(&rest[..i]);
        rest = rest[i + 2..].split_once("*/").map_or("", |(_, r)| r);
    }
    out.push_str(rest);
    out.lines()
        .map(|l| l.split("//").next().unwrap_or(""))
        .collect::<Vec<_>>()
        .join("\n")
}

fn data_dir() -> std::path::PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/itf1788")
}

fn itl_files() -> Vec<std::path::PathBuf> {
    let mut files: Vec<_> = std::fs::read_dir(data_dir())
        .expect("tests/data/itf1788 exists (run tools/import-itf1788.sh)")
        .map(|e| e.expect("dir entry").path())
        .filter(|p| p.extension().is_some_and(|e| e == "itl"))
        .collect();
    files.sort();
    files
}

/// Every statement of every non-decorated test case, with its operation; `None` for
/// vectors that use decorations.
fn parse_all() -> Vec<(String, Option<Vector>)> {
    let mut out = vec![];
    for path in itl_files() {
        let text = strip_comments(&std::fs::read_to_string(&path).expect("readable"));
        let name = path.file_name().unwrap().to_string_lossy().to_string();
        let mut decorated_case = false;
        for (n, line) in text.lines().enumerate() {
            let line = line.trim();
            if let Some(rest) = line.strip_prefix("testcase") {
                decorated_case = rest
                    .trim()
                    .trim_end_matches('{')
                    .trim()
                    .ends_with("_dec_test");
                continue;
            }
            let Some(stmt) = line.strip_suffix(';') else {
                continue;
            };
            if decorated_case {
                out.push(("(any, in a *_dec_test case)".to_string(), None));
                continue;
            }
            let (lhs, rhs) = stmt.split_once('=').expect("statement has '='");
            let toks = tokens(lhs);
            let op = toks[0].clone();
            let place = format!("{name}:{}: {line}", n + 1);
            let decorated = toks
                .iter()
                .chain(tokens(rhs).iter())
                .any(|t| t.contains("]_"));
            if decorated || !supported(&op) {
                out.push((op, None));
                continue;
            }
            let args = toks[1..].iter().map(|t| parse_value(t)).collect();
            let rtoks = tokens(rhs);
            assert_eq!(rtoks.len(), 1, "one result in {place}");
            out.push((
                op.clone(),
                Some(Vector {
                    place,
                    op,
                    args,
                    expected: parse_value(&rtoks[0]),
                }),
            ));
        }
    }
    out
}

/// Independent count: lines of non-decorated test cases whose first word is `op`.
fn raw_counts() -> BTreeMap<String, usize> {
    let mut counts = BTreeMap::new();
    for path in itl_files() {
        let text = std::fs::read_to_string(&path).expect("readable");
        let mut dec = false;
        for line in text.lines() {
            let words: Vec<&str> = line.split_whitespace().collect();
            if words.first() == Some(&"testcase") {
                dec = words.get(1).is_some_and(|w| w.ends_with("_dec_test"));
            } else if !dec
                && line.contains('=')
                && line.trim_end().ends_with(';')
                && line.starts_with(char::is_whitespace)
            {
                *counts.entry(words[0].to_string()).or_insert(0) += 1;
            }
        }
    }
    counts
}

fn interval_arg(v: &Value) -> Interval {
    match v {
        Value::Interval(x) => *x,
        other => panic!("expected an interval, found {other:?}"),
    }
}

fn int_arg(v: &Value) -> i32 {
    match v {
        Value::Number(Num::Finite(q)) => q.numer().to_i32().expect("small integer"),
        other => panic!("expected an integer, found {other:?}"),
    }
}

/// Apply an interval-valued operation in the type `T` (created from f64 intervals by
/// `mk`).
fn apply<T: IntervalLike>(op: &str, args: &[Value], mk: &dyn Fn(&Interval) -> T) -> T {
    let x = mk(&interval_arg(&args[0]));
    let y = || mk(&interval_arg(&args[1]));
    match op {
        "add" => x + y(),
        "sub" => x - y(),
        "mul" => x * y(),
        "div" => x / y(),
        "neg" => -x,
        "recip" => x.lift(1.0) / x,
        "sqr" => x.sqr(),
        "sqrt" => x.sqrt(),
        "abs" => IntervalLike::abs(&x),
        "pown" => x.powi(int_arg(&args[1])),
        "exp" => x.exp(),
        "log" => x.ln(),
        "sin" => x.sin(),
        "cos" => x.cos(),
        "tan" => x.tan(),
        "sinh" => x.sinh(),
        "cosh" => x.cosh(),
        "atan2" => x.atan2(&y()),
        "intersection" => x.intersection(&y()),
        "convexHull" => x.hull(&y()),
        _ => unreachable!("{op}"),
    }
}

fn scalar<T: IntervalLike>(op: &str, x: &T) -> f64 {
    match op {
        "inf" => x.inf(),
        "sup" => x.sup(),
        "mid" => x.mid(),
        "rad" => x.rad(),
        "wid" => x.wid(),
        "mag" => x.mag(),
        "mig" => x.mig(),
        _ => unreachable!("{op}"),
    }
}

fn boolean<T: IntervalLike>(op: &str, x: &T, y: Option<&T>) -> bool {
    match op {
        "subset" => x.is_subset(y.unwrap()),
        "interior" => x.is_interior_subset(y.unwrap()),
        "isEmpty" => x.is_empty(),
        "isEntire" => x.is_entire(),
        "equal" => x == y.unwrap(),
        "disjoint" => x.intersection(y.unwrap()).is_empty(),
        _ => unreachable!("{op}"),
    }
}

/// Distance in doubles between two finite doubles (across zero too).
fn ulps_apart(x: f64, y: f64) -> u64 {
    let key = |v: f64| {
        let b = v.to_bits() as i64;
        if b < 0 {
            i64::MIN - b
        } else {
            b
        }
    };
    (key(x) - key(y)).unsigned_abs()
}

fn expected_f64(v: &Value, place: &str) -> f64 {
    match v {
        Value::Number(Num::PosInf) => f64::INFINITY,
        Value::Number(Num::NegInf) => f64::NEG_INFINITY,
        Value::Number(Num::Finite(q)) => {
            let x = Interval::from_rational(q);
            assert!(x.is_point(), "{place}: expected value is not a double");
            x.lo()
        }
        other => panic!("{place}: expected a number, found {other:?}"),
    }
}

/// Check one vector in one interval type; `f64_type` selects the f64 rules.
fn check<T: IntervalLike>(
    v: &Vector,
    mk: &dyn Fn(&Interval) -> T,
    back: &dyn Fn(&T) -> Interval,
    f64_type: bool,
    bits: u32,
) {
    let p = &v.place;
    if SCALAR_OPS.contains(&v.op.as_str()) {
        let x = mk(&interval_arg(&v.args[0]));
        let got = scalar(&v.op, &x);
        let want = expected_f64(&v.expected, p);
        assert!(
            got == want || (got.is_nan() && want.is_nan()),
            "{p}: {bits} bits: {got:e} != {want:e}"
        );
        return;
    }
    if BOOL_OPS.contains(&v.op.as_str()) {
        let x = mk(&interval_arg(&v.args[0]));
        let y = v.args.get(1).map(|a| mk(&interval_arg(a)));
        let want = matches!(v.expected, Value::Bool(true));
        assert_eq!(boolean(&v.op, &x, y.as_ref()), want, "{p}: {bits} bits");
        return;
    }
    let want = interval_arg(&v.expected);
    let got = apply(&v.op, &v.args, mk);
    let got_f64 = back(&got);
    if f64_type {
        assert!(
            want.is_subset(&got_f64),
            "{p}: Interval gives {got_f64:?}, not a superset of {want:?}"
        );
        let small_pown = v.op == "pown" && [-1, 0, 1, 2].contains(&int_arg(&v.args[1]));
        if TIGHTEST_F64.contains(&v.op.as_str()) || small_pown {
            assert_eq!(got_f64, want, "{p}: Interval is not tightest");
        } else if want.is_empty() {
            assert!(got_f64.is_empty(), "{p}: expected empty");
        } else {
            // Taylor paths and powi: each finite bound within 8 ulps of the tightest,
            // infinite bounds equal.
            let close = |g: f64, w: f64| {
                if w.is_finite() {
                    ulps_apart(g, w) <= 8
                } else {
                    g == w
                }
            };
            assert!(
                close(got_f64.lo(), want.lo()) && close(got_f64.hi(), want.hi()),
                "{p}: Interval {got_f64:?} too wide"
            );
        }
    } else {
        assert!(
            got_f64.is_subset(&want),
            "{p}: MpfrInterval({bits}) gives {got:?}, not a subset of {want:?}"
        );
        if bits == 53 {
            assert_eq!(
                got_f64, want,
                "{p}: MpfrInterval(53) rounded to f64 is not the tightest"
            );
        }
    }
}

#[test]
fn itf1788_vectors() {
    let parsed = parse_all();
    let raw = raw_counts();
    let mut checked: BTreeMap<String, [usize; 3]> = BTreeMap::new();
    let mut skipped: BTreeMap<String, usize> = BTreeMap::new();
    for (op, v) in &parsed {
        let Some(v) = v else {
            *skipped.entry(op.clone()).or_insert(0) += 1;
            continue;
        };
        let c = checked.entry(op.clone()).or_insert([0; 3]);
        check(v, &|x: &Interval| *x, &|x: &Interval| *x, true, 53);
        c[0] += 1;
        check(
            v,
            &|x: &Interval| MpfrInterval::from_interval(x, 53),
            &MpfrInterval::to_interval,
            false,
            53,
        );
        c[1] += 1;
        check(
            v,
            &|x: &Interval| MpfrInterval::from_interval(x, 128),
            &MpfrInterval::to_interval,
            false,
            128,
        );
        c[2] += 1;
    }
    println!(
        "{:<14} {:>8} {:>10} {:>10} {:>10}",
        "operation", "in files", "Interval", "Mpfr(53)", "Mpfr(128)"
    );
    for (op, c) in &checked {
        println!(
            "{:<14} {:>8} {:>10} {:>10} {:>10}",
            op,
            raw.get(op).copied().unwrap_or(0),
            c[0],
            c[1],
            c[2]
        );
    }
    println!("skipped (unsupported operation or decorated): {skipped:?}");
    for (op, min) in MIN_COUNTS {
        let in_files = raw.get(*op).copied().unwrap_or(0);
        let c = checked.get(*op).copied().unwrap_or([0; 3]);
        assert!(
            in_files >= *min,
            "{op}: only {in_files} vectors in the files, expected ≥ {min}"
        );
        assert_eq!(
            c, [in_files; 3],
            "{op}: checked {c:?} of {in_files} vectors"
        );
    }
    let supported_ops: Vec<_> = checked.keys().cloned().collect();
    assert_eq!(
        supported_ops.len(),
        MIN_COUNTS.len(),
        "operations checked: {supported_ops:?}"
    );
}

#[test]
fn literal_parsing_rounds_to_nearest() {
    // [0.1, 0.1] is the double nearest to 1/10.
    assert_eq!(parse_interval("[0.1,0.1]"), Interval::point(0.1));
    assert_eq!(parse_interval("[13.1, 13.1]"), Interval::point(13.1));
    assert_eq!(
        parse_interval("[0X1.921FB54442D18P+1,0X1.921FB54442D19P+1]").lo(),
        std::f64::consts::PI
    );
    assert_eq!(
        parse_interval("[-0x0.0000000000001p-1022, 1.0]").lo(),
        -f64::from_bits(1)
    );
    assert_eq!(parse_interval("[-infinity,+infinity]"), Interval::ENTIRE);
    assert!(matches!(parse_num("-7451.145"), Num::Finite(q) if q == (-7451145, 1000)));
}
