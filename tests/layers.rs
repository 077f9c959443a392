//! The library's layers point only down, and no module's submodules import each other
//! in a cycle (ARCHITECTURE.md "Layers"; issue 13).
//!
//! Reads every `src/**/*.rs` of the library (not `main.rs` and `cli/`, the binary),
//! collects the paths it names through `crate::`, `super::` and `self::` (in `use`
//! trees and inline, tests included; comments and literals skipped), and takes each as
//! a dependency on the module it names and on the module that defines the item
//! (following `use` re-exports), then checks:
//!
//! * (a) every import from one top-level module to another goes to a lower layer of
//!   [`LAYERS`] (modules of one layer sit beside each other and import neither);
//! * (b) for every module, the graph of its direct submodules (an edge `A → B` when
//!   code in `A` names an item of `B`) has no cycle: each module can be read after the
//!   ones it uses.
//!
//! The io/ops front door is being rewritten: the violations there today are listed in
//! [`ALLOWED_UPWARD`] and [`ALLOWED_CYCLES`] (reported, not failed); an entry that no
//! longer matches fails the test, so the list only shrinks.

use std::collections::{BTreeMap, BTreeSet};
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

/// The layers, lowest first: a module may import only from layers below its own.
/// `oracle` (the CGAL bridge, which needs only `error`) sits beside `ops`; `robust`
/// (the robustness generators and table, which run geom and the oracle) and `render` (the
/// pictures, which draw ops' shapes and answers) beside `io`.
const LAYERS: &[&[&str]] = &[
    &["certificate", "error"],
    &["num"],
    &["geom"],
    &["curve"],
    &["surface"],
    &["walk"],
    &["certify"],
    &["ops", "oracle"],
    &["io", "robust", "prelude", "render"],
];

/// Imports to a higher or the same layer, `(from module, to module)`, allowed while
/// the front door is rewritten. None today.
const ALLOWED_UPWARD: &[(&str, &str)] = &[];

/// Cycles among the submodules of a module, as the set of submodules in the cycle
/// (one strongly connected component), allowed while the front door is rewritten.
const ALLOWED_CYCLES: &[&[&str]] = &[];

#[test]
fn imports_point_down_the_layers() {
    let crate_ = Crate::read(&Path::new(env!("CARGO_MANIFEST_DIR")).join("src"));
    let mut report = String::new();
    let mut used_allowances = BTreeSet::new();
    for (from, to, examples) in crate_.top_level_edges() {
        let (Some(rf), Some(rt)) = (layer_of(&from), layer_of(&to)) else {
            let unknown = if layer_of(&from).is_none() {
                &from
            } else {
                &to
            };
            writeln!(
                report,
                "module `{unknown}` is in no layer: add it to LAYERS"
            )
            .unwrap();
            continue;
        };
        if rt < rf {
            continue;
        }
        if ALLOWED_UPWARD.contains(&(from.as_str(), to.as_str())) {
            used_allowances.insert((from.clone(), to.clone()));
            println!("allowed (front door work in progress): {from} → {to}: {examples}");
            continue;
        }
        let kind = if rt == rf { "the same" } else { "a higher" };
        writeln!(report, "{from} imports {to}, {kind} layer: {examples}").unwrap();
    }
    for &(from, to) in ALLOWED_UPWARD {
        if !used_allowances.contains(&(from.to_string(), to.to_string())) {
            writeln!(report, "ALLOWED_UPWARD has ({from}, {to}), gone: remove it").unwrap();
        }
    }
    assert!(report.is_empty(), "\n{report}");
}

#[test]
fn no_cycles_among_submodules() {
    let crate_ = Crate::read(&Path::new(env!("CARGO_MANIFEST_DIR")).join("src"));
    let mut report = String::new();
    let mut seen = BTreeSet::new();
    for (parent, graph) in crate_.sibling_graphs() {
        for cycle in strongly_connected(&graph) {
            let names: Vec<String> = cycle.iter().map(|c| join(&parent, c)).collect();
            let edges = cycle_edges(&graph, &cycle, &parent);
            if ALLOWED_CYCLES
                .iter()
                .any(|a| a.iter().copied().eq(names.iter().map(String::as_str)))
            {
                println!("allowed (front door work in progress): {names:?}: {edges}");
                seen.insert(names);
                continue;
            }
            writeln!(report, "cycle among {names:?}: {edges}").unwrap();
        }
    }
    for allowed in ALLOWED_CYCLES {
        let names: Vec<String> = allowed.iter().map(|s| s.to_string()).collect();
        if !seen.contains(&names) {
            writeln!(report, "ALLOWED_CYCLES has {names:?}, gone: remove it").unwrap();
        }
    }
    assert!(report.is_empty(), "\n{report}");
}

/// The scanner sees paths in `use` trees and inline, resolves `super` through inline
/// modules and re-exports, and skips comments, strings and character literals.
#[test]
fn the_scanner_reads_paths_as_rustc_does() {
    let files = [
        (
            "a/mod.rs",
            "mod b; mod c; mod d; pub use b::Thing; pub use self::c::{Other as Renamed};",
        ),
        ("a/b.rs", "pub struct Thing; use super::Renamed;"),
        (
            "a/c.rs",
            r##"pub struct Other;
            // use crate::z::Commented;
            /* use crate::z::Block; /* nested */ */
            const S: &str = "crate::z::InString";
            const R: &str = r#"crate::z::"Raw""#;
            const Q: char = '"';
            fn f<'a>(x: &'a u8) -> u8 { crate::z::inline(x) }
            mod tests { use super::super::Thing; use crate::{z::{self, W}, y::*}; }"##,
        ),
        // `b`'s import of `Renamed` is private: `d` names an item of `b`, not of `c`.
        ("a/d.rs", "use super::b::Renamed;"),
        ("z.rs", ""),
        ("y.rs", ""),
    ];
    let crate_ = Crate::parse(
        files
            .iter()
            .map(|(p, s)| (PathBuf::from(p), s.to_string()))
            .collect(),
    );
    let refs: BTreeSet<(String, String)> = crate_
        .refs
        .iter()
        .map(|r| {
            (
                r.from.join("::"),
                crate_.resolve(&r.from, &r.path).join("::"),
            )
        })
        .collect();
    let expect = [
        ("a", "a::b"),
        ("a", "a::c"),
        ("a::b", "a::c"),
        ("a::c", "z"),
        ("a::c::tests", "a::b"),
        ("a::c::tests", "z"),
        ("a::c::tests", "y"),
        ("a::d", "a::b"),
    ];
    let expect: BTreeSet<(String, String)> = expect
        .iter()
        .map(|(a, b)| (a.to_string(), b.to_string()))
        .collect();
    assert_eq!(refs, expect);
    // As written, `super::Renamed` names `a` too.
    let b_deps: BTreeSet<String> = crate_
        .resolved()
        .filter(|(from, _, _)| from.join("::") == "a::b")
        .map(|(_, to, _)| to.join("::"))
        .collect();
    assert_eq!(
        b_deps,
        BTreeSet::from(["a".to_string(), "a::c".to_string()])
    );
    // a::b → a::c (through a's re-export) and a::c → a::b (its tests): one cycle.
    let graphs = crate_.sibling_graphs();
    let cycles = strongly_connected(&graphs[&vec!["a".to_string()]]);
    assert_eq!(cycles, vec![vec!["b".to_string(), "c".to_string()]]);
}

fn layer_of(module: &str) -> Option<usize> {
    LAYERS.iter().position(|l| l.contains(&module))
}

fn join(parent: &[String], child: &str) -> String {
    parent
        .iter()
        .map(String::as_str)
        .chain([child])
        .collect::<Vec<_>>()
        .join("::")
}

/// One path named in a file: `path` is absolute (from the crate root), unresolved.
struct Ref {
    file: PathBuf,
    from: Vec<String>,
    path: Vec<String>,
}

/// A module's `use` bindings: name → (absolute path, whether the `use` is `pub`).
type Bindings = BTreeMap<String, (Vec<String>, bool)>;

/// The crate's modules, the names its `use` declarations bind, and the paths it names.
struct Crate {
    modules: BTreeSet<Vec<String>>,
    /// Per module: a name bound by `use` → the absolute path it stands for, and whether
    /// the `use` is `pub` (visible outside the module; a private one only inside).
    bindings: BTreeMap<Vec<String>, Bindings>,
    refs: Vec<Ref>,
}

/// A graph of sibling modules: node → (neighbour → one example "file: path").
type Graph = BTreeMap<String, BTreeMap<String, String>>;

impl Crate {
    /// Every library file under `src` (the binary's `main.rs` and `cli/` excluded).
    fn read(src: &Path) -> Crate {
        let mut files = Vec::new();
        let mut stack = vec![src.to_path_buf()];
        while let Some(dir) = stack.pop() {
            for entry in std::fs::read_dir(&dir).unwrap() {
                let path = entry.unwrap().path();
                let rel = path.strip_prefix(src).unwrap().to_path_buf();
                if rel == Path::new("main.rs") || rel == Path::new("cli") {
                    continue;
                }
                if path.is_dir() {
                    stack.push(path);
                } else if path.extension().is_some_and(|e| e == "rs") {
                    files.push((rel, std::fs::read_to_string(&path).unwrap()));
                }
            }
        }
        assert!(files.len() > 50, "read {} files under {src:?}", files.len());
        Crate::parse(files)
    }

    fn parse(files: Vec<(PathBuf, String)>) -> Crate {
        let mut crate_ = Crate {
            modules: BTreeSet::new(),
            bindings: BTreeMap::new(),
            refs: Vec::new(),
        };
        let files: Vec<(PathBuf, Vec<String>, Vec<Token>)> = files
            .into_iter()
            .map(|(rel, text)| {
                let module = module_of(&rel);
                crate_.modules.insert(module.clone());
                (rel, module, tokens(&text))
            })
            .collect();
        // Inline modules first, so that relative `use` paths can see them.
        for (_, module, toks) in &files {
            inline_modules(module, toks, &mut crate_.modules);
        }
        for (rel, module, toks) in &files {
            crate_.scan(rel, module, toks);
        }
        crate_
    }

    /// The `use` trees and inline paths of one file (module doc).
    fn scan(&mut self, file: &Path, module: &[String], toks: &[Token]) {
        let mut stack: Vec<(Vec<String>, usize)> = vec![(module.to_vec(), 0)];
        let mut depth = 0;
        let mut i = 0;
        while i < toks.len() {
            let current = stack.last().unwrap().0.clone();
            match toks[i].as_str() {
                "{" => depth += 1,
                "}" => {
                    if stack.last().unwrap().1 == depth {
                        stack.pop();
                    }
                    depth -= 1;
                }
                "mod" if toks.get(i + 2).map(String::as_str) == Some("{") => {
                    depth += 1;
                    stack.push(([current.clone(), vec![toks[i + 1].clone()]].concat(), depth));
                    i += 3;
                    continue;
                }
                "use" => {
                    let public = i > 0 && (toks[i - 1] == "pub" || toks[i - 1] == ")");
                    let mut uses = Vec::new();
                    i = use_tree(toks, i + 1, &mut Vec::new(), &mut uses);
                    for (path, bound) in uses {
                        self.record_use(file, &current, path, bound, public);
                    }
                    continue;
                }
                "crate" | "super" | "self"
                    if toks.get(i + 1).map(String::as_str) == Some("::")
                        && (i == 0 || toks[i - 1] != "::") =>
                {
                    let mut path = vec![toks[i].clone()];
                    let mut j = i + 1;
                    while toks.get(j).map(String::as_str) == Some("::")
                        && toks.get(j + 1).is_some_and(|t| is_ident(t))
                    {
                        path.push(toks[j + 1].clone());
                        j += 2;
                    }
                    if let Some(path) = absolute(&current, &path) {
                        self.refs.push(Ref {
                            file: file.to_path_buf(),
                            from: current,
                            path,
                        });
                    }
                    i = j;
                    continue;
                }
                _ => {}
            }
            i += 1;
        }
    }

    /// A `use` of `path` in `module`, binding the name `bound` (None for a glob),
    /// `public` for `pub use` and `pub(…) use`.
    fn record_use(
        &mut self,
        file: &Path,
        module: &[String],
        path: Vec<String>,
        bound: Option<String>,
        public: bool,
    ) {
        let first = path.first().map(String::as_str);
        let relative_child = first.is_some_and(|f| {
            self.modules
                .contains(&[module.to_vec(), vec![f.to_string()]].concat())
        });
        let path = if matches!(first, Some("crate" | "super" | "self")) {
            absolute(module, &path)
        } else if relative_child {
            Some([module.to_vec(), path].concat())
        } else {
            None // an external crate or the standard library
        };
        let Some(path) = path else { return };
        if let Some(name) = bound {
            self.bindings
                .entry(module.to_vec())
                .or_default()
                .insert(name, (path.clone(), public));
        }
        self.refs.push(Ref {
            file: file.to_path_buf(),
            from: module.to_vec(),
            path,
        });
    }

    /// The module defining the item `path` names from `from`: its longest module
    /// prefix, through the `use` bindings of that module when the next name is one of
    /// them and visible from `from` (public, or `from` lies inside that module).
    fn resolve(&self, from: &[String], path: &[String]) -> Vec<String> {
        let mut path = path.to_vec();
        for _ in 0..16 {
            let mut k = path.len();
            while k > 0 && !self.modules.contains(&path[..k]) {
                k -= 1;
            }
            let next = path.get(k);
            let binding = next.and_then(|n| self.bindings.get(&path[..k])?.get(n));
            let visible = |public: bool| public || from.starts_with(&path[..k]);
            match binding {
                Some((t, public)) if visible(*public) && t[..] != path[..=k] => {
                    path = [t.clone(), path[k + 1..].to_vec()].concat()
                }
                _ => return path[..k].to_vec(),
            }
        }
        panic!("re-exports loop at {path:?}")
    }

    /// The longest module prefix of `path`, as written (no re-export followed).
    fn written(&self, path: &[String]) -> Vec<String> {
        let mut k = path.len();
        while k > 0 && !self.modules.contains(&path[..k]) {
            k -= 1;
        }
        path[..k].to_vec()
    }

    /// Every reference as `(from, to, ref)`, `to` both the module the path names as
    /// written and the one defining the item: `crate::surface::Implicit` in `curve`
    /// depends on `surface` even if `surface` only re-exports it from below.
    fn resolved(&self) -> impl Iterator<Item = (&[String], Vec<String>, &Ref)> {
        self.refs.iter().flat_map(|r| {
            let (written, defining) = (self.written(&r.path), self.resolve(&r.from, &r.path));
            let both = if written == defining {
                vec![written]
            } else {
                vec![written, defining]
            };
            both.into_iter().map(move |to| (&r.from[..], to, r))
        })
    }

    /// Imports between distinct top-level modules: `(from, to, examples)`.
    fn top_level_edges(&self) -> Vec<(String, String, String)> {
        let mut edges: BTreeMap<(String, String), BTreeSet<String>> = BTreeMap::new();
        for (from, to, r) in self.resolved() {
            let (Some(a), Some(b)) = (from.first(), to.first()) else {
                continue;
            };
            if a != b {
                let example = format!("{} names {}", r.file.display(), to.join("::"));
                edges
                    .entry((a.clone(), b.clone()))
                    .or_default()
                    .insert(example);
            }
        }
        edges
            .into_iter()
            .map(|((a, b), ex)| (a, b, ex.into_iter().collect::<Vec<_>>().join("; ")))
            .collect()
    }

    /// For every module with submodules, the graph of its direct submodules.
    fn sibling_graphs(&self) -> BTreeMap<Vec<String>, Graph> {
        let mut graphs: BTreeMap<Vec<String>, Graph> = BTreeMap::new();
        for (from, to, r) in self.resolved() {
            let common = from.iter().zip(&to).take_while(|(a, b)| a == b).count();
            if common < from.len() && common < to.len() {
                let example = format!("{} names {}", r.file.display(), to.join("::"));
                graphs
                    .entry(from[..common].to_vec())
                    .or_default()
                    .entry(from[common].clone())
                    .or_default()
                    .entry(to[common].clone())
                    .or_insert(example);
            }
        }
        graphs
    }
}

/// `a/b.rs` and `a/b/mod.rs` are `a::b`; `lib.rs` is the root.
fn module_of(rel: &Path) -> Vec<String> {
    let mut parts: Vec<String> = rel
        .with_extension("")
        .iter()
        .map(|p| p.to_string_lossy().into_owned())
        .collect();
    if matches!(parts.last().map(String::as_str), Some("mod" | "lib")) {
        parts.pop();
    }
    parts
}

/// The `mod name { … }` blocks of a file, as modules.
fn inline_modules(module: &[String], toks: &[Token], modules: &mut BTreeSet<Vec<String>>) {
    let mut stack: Vec<(Vec<String>, usize)> = vec![(module.to_vec(), 0)];
    let mut depth = 0;
    for (i, t) in toks.iter().enumerate() {
        match t.as_str() {
            "{" => {
                depth += 1;
                if i >= 2 && toks[i - 2] == "mod" {
                    let m = [stack.last().unwrap().0.clone(), vec![toks[i - 1].clone()]].concat();
                    modules.insert(m.clone());
                    stack.push((m, depth));
                }
            }
            "}" => {
                if stack.last().unwrap().1 == depth {
                    stack.pop();
                }
                depth -= 1;
            }
            _ => {}
        }
    }
}

/// `crate::…`, `super::…`, `self::…` relative to `module`, from the crate root
/// (`None` for a `super` above the root).
fn absolute(module: &[String], path: &[String]) -> Option<Vec<String>> {
    let mut base = module.to_vec();
    let mut rest = path;
    if rest.first().map(String::as_str) == Some("crate") {
        base.clear();
        rest = &rest[1..];
    }
    while let Some(first) = rest.first() {
        match first.as_str() {
            "super" => {
                base.pop()?;
            }
            "self" => {}
            _ => break,
        }
        rest = &rest[1..];
    }
    Some([base, rest.to_vec()].concat())
}

/// Parse the use tree starting at `toks[i]` under `prefix`, push `(path, bound name)`
/// for each leaf; returns the index after it (after the `;` at the top).
fn use_tree(
    toks: &[Token],
    mut i: usize,
    prefix: &mut Vec<String>,
    out: &mut Vec<(Vec<String>, Option<String>)>,
) -> usize {
    let depth = prefix.len();
    if toks.get(i).map(String::as_str) == Some("::") {
        i += 1; // `use ::std::…`
    }
    loop {
        match toks.get(i).map(String::as_str) {
            Some("{") => {
                i += 1;
                while i < toks.len() && toks[i] != "}" {
                    let before = i;
                    i = use_tree(toks, i, prefix, out);
                    if toks.get(i).map(String::as_str) == Some(",") {
                        i += 1;
                    }
                    assert!(i > before, "unreadable use tree at {:?}", &toks[before..]);
                }
                i += 1;
                break;
            }
            Some("*") => {
                out.push((prefix.clone(), None));
                i += 1;
                break;
            }
            Some(name) if is_ident(name) => {
                i += 1;
                if toks.get(i).map(String::as_str) == Some("::") {
                    prefix.push(name.to_string());
                    i += 1;
                    continue;
                }
                let mut bound = name.to_string();
                if toks.get(i).map(String::as_str) == Some("as") {
                    bound = toks[i + 1].clone();
                    i += 2;
                }
                if name == "self" {
                    let last = prefix.last().cloned().unwrap_or_default();
                    let bound = if bound == "self" { last } else { bound };
                    out.push((prefix.clone(), Some(bound)));
                } else {
                    out.push((
                        [prefix.clone(), vec![name.to_string()]].concat(),
                        Some(bound),
                    ));
                }
                break;
            }
            _ => break,
        }
    }
    prefix.truncate(depth);
    if depth == 0 && toks.get(i).map(String::as_str) == Some(";") {
        i += 1;
    }
    i
}

type Token = String;

fn is_ident(t: &str) -> bool {
    t.chars()
        .next()
        .is_some_and(|c| c.is_alphabetic() || c == '_')
}

/// Identifiers, `::` and single punctuation characters, without comments, string and
/// character literals (lifetimes are dropped with them).
fn tokens(text: &str) -> Vec<Token> {
    let c: Vec<char> = text.chars().collect();
    let mut out = Vec::new();
    let mut i = 0;
    let at = |i: usize, s: &str| s.chars().enumerate().all(|(k, x)| c.get(i + k) == Some(&x));
    while i < c.len() {
        if at(i, "//") {
            while i < c.len() && c[i] != '\n' {
                i += 1;
            }
        } else if at(i, "/*") {
            let mut nest = 0;
            while i < c.len() {
                if at(i, "/*") {
                    nest += 1;
                    i += 2;
                } else if at(i, "*/") {
                    nest -= 1;
                    i += 2;
                    if nest == 0 {
                        break;
                    }
                } else {
                    i += 1;
                }
            }
        } else if c[i] == '"' || ((c[i] == 'r' || c[i] == 'b') && raw_or_byte_string(&c, i)) {
            i = skip_string(&c, i);
        } else if c[i] == '\'' {
            i = skip_char_or_lifetime(&c, i);
        } else if c[i].is_alphanumeric() || c[i] == '_' {
            let start = i;
            while i < c.len() && (c[i].is_alphanumeric() || c[i] == '_') {
                i += 1;
            }
            out.push(c[start..i].iter().collect());
        } else if at(i, "::") {
            out.push("::".to_string());
            i += 2;
        } else {
            if !c[i].is_whitespace() {
                out.push(c[i].to_string());
            }
            i += 1;
        }
    }
    out
}

/// `r"`, `r#"`, `b"`, `br"`, `br#"` starting a literal (not inside an identifier).
fn raw_or_byte_string(c: &[char], i: usize) -> bool {
    if i > 0 && (c[i - 1].is_alphanumeric() || c[i - 1] == '_') {
        return false;
    }
    let mut j = i;
    if c[j] == 'b' {
        j += 1;
    }
    if c.get(j) == Some(&'r') {
        j += 1;
        while c.get(j) == Some(&'#') {
            j += 1;
        }
    }
    j > i && c.get(j) == Some(&'"')
}

/// The index after the string literal at `i` (plain, byte or raw).
fn skip_string(c: &[char], mut i: usize) -> usize {
    if c[i] == 'b' {
        i += 1;
    }
    if c[i] == 'r' {
        i += 1;
        let mut hashes = 0;
        while c[i] == '#' {
            hashes += 1;
            i += 1;
        }
        i += 1; // the opening quote
        loop {
            if c[i] == '"' && (1..=hashes).all(|k| c.get(i + k) == Some(&'#')) {
                return i + 1 + hashes;
            }
            i += 1;
        }
    }
    i += 1;
    while c[i] != '"' {
        i += if c[i] == '\\' { 2 } else { 1 };
    }
    i + 1
}

/// The index after a character literal at `i`, or after the `'` of a lifetime.
fn skip_char_or_lifetime(c: &[char], i: usize) -> usize {
    if c.get(i + 1) == Some(&'\\') {
        let mut j = i + 3; // after the escaped character
        while c[j] != '\'' {
            j += 1;
        }
        return j + 1;
    }
    if c.get(i + 2) == Some(&'\'') {
        return i + 3;
    }
    i + 1
}

/// The strongly connected components of more than one node (Tarjan), each sorted.
fn strongly_connected(graph: &Graph) -> Vec<Vec<String>> {
    struct State<'g> {
        graph: &'g Graph,
        index: BTreeMap<&'g str, usize>,
        low: BTreeMap<&'g str, usize>,
        stack: Vec<&'g str>,
        out: Vec<Vec<String>>,
    }
    fn visit<'g>(s: &mut State<'g>, v: &'g str) {
        let n = s.index.len();
        s.index.insert(v, n);
        s.low.insert(v, n);
        s.stack.push(v);
        for w in s.graph.get(v).into_iter().flat_map(|m| m.keys()) {
            if !s.index.contains_key(w.as_str()) {
                visit(s, w);
                let lw = s.low[w.as_str()];
                s.low.insert(v, s.low[v].min(lw));
            } else if s.stack.contains(&w.as_str()) {
                let iw = s.index[w.as_str()];
                s.low.insert(v, s.low[v].min(iw));
            }
        }
        if s.low[v] == s.index[v] {
            let mut comp = Vec::new();
            while let Some(w) = s.stack.pop() {
                comp.push(w.to_string());
                if w == v {
                    break;
                }
            }
            if comp.len() > 1 {
                comp.sort();
                s.out.push(comp);
            }
        }
    }
    let mut s = State {
        graph,
        index: BTreeMap::new(),
        low: BTreeMap::new(),
        stack: Vec::new(),
        out: Vec::new(),
    };
    for v in graph.keys() {
        if !s.index.contains_key(v.as_str()) {
            visit(&mut s, v);
        }
    }
    s.out.sort();
    s.out
}

/// The edges inside a cycle, with an example of each.
fn cycle_edges(graph: &Graph, cycle: &[String], parent: &[String]) -> String {
    let mut out = Vec::new();
    for a in cycle {
        for (b, example) in &graph[a] {
            if cycle.contains(b) {
                out.push(format!(
                    "{} → {} ({example})",
                    join(parent, a),
                    join(parent, b)
                ));
            }
        }
    }
    out.join("; ")
}
