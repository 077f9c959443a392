//! The quick road for the common case (issue 19: 10⁶ linear cases in seconds): a case
//! whose objects (and `onto`) are all linear (`line`, `segment`, an unbounded `plane`,
//! `line2`, `segment2`) and whose other fields are plain numbers is read straight from its text
//! into the typed [`Case`], without building a `serde_json::Value` and without tracking
//! field paths.
//!
//! The quick road only ever *accepts*: any case it does not take in full — another
//! object type, a field it does not know, a duplicate key, a syntax error, a value of
//! the wrong type — goes the careful road of [`super::read_chunk`] (strict
//! parse, path-tracking deserialisation), which alone writes error messages. So what
//! the quick road returns must equal what the careful road would: the same serde
//! types (`LineSpec`, ..., `Options`) read the same numbers from the same parser
//! (`Num` through `deserialize_any`; serde_json's `float_roundtrip` on both roads);
//! duplicate keys are refused by serde's derived struct visitors (a duplicate field is
//! an error), and `deny_unknown_fields` holds on every struct. A test replays the
//! golden cases and the fuzz corpus through both roads and compares the records.

use super::case::{check_options, Case, Op, Options, ReadCase, Record};
use super::number::Num;
use super::objects::{Line2Spec, LineSpec, ObjectSpec, PlaneSpec, Segment2Spec, SegmentSpec};
use serde::de::value::{BorrowedStrDeserializer, MapAccessDeserializer};
use serde::de::{self, DeserializeSeed, Deserializer, IgnoredAny, MapAccess, Visitor};
use serde::Deserialize;
use serde_json::value::RawValue;
use std::fmt;

/// The fields of a case the quick road reads; any other field sends the case the
/// careful road.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct QuickCase<'a> {
    #[serde(borrow, default)]
    id: Option<&'a RawValue>,
    op: Op,
    #[serde(default)]
    objects: Vec<QuickObject>,
    point: Option<Vec<Num>>,
    onto: Option<QuickObject>,
    direction: Option<Vec<Num>>,
    #[serde(default)]
    nearest: bool,
    #[serde(default)]
    options: Options,
}

/// The linear objects, by `type` (anywhere in the object). A `plane` with a `domain`
/// is a surface: its unknown field sends it the careful road.
#[allow(clippy::large_enum_variant)] // read once per object, then moved into ObjectSpec
enum QuickObject {
    Line(LineSpec),
    Segment(SegmentSpec),
    Plane(PlaneSpec),
    Line2(Line2Spec),
    Segment2(Segment2Spec),
}

impl<'de> Deserialize<'de> for QuickObject {
    /// Two looks at the object's text, neither buffering its values (as serde's
    /// internally tagged enums would): the first finds `type` (skipping the other
    /// values; a second `type` is refused), the second reads the spec with `type`
    /// left out. Keys with escapes are not borrowed: careful road.
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let raw: &'de RawValue = Deserialize::deserialize(d)?;
        let text = raw.get();
        let kind = serde_json::from_str::<TypeOf>(text)
            .map_err(de::Error::custom)?
            .0;
        let spec = |e: serde_json::Error| de::Error::custom(e);
        fn read<'de, T: Deserialize<'de>>(text: &'de str) -> Result<T, serde_json::Error> {
            let mut de = serde_json::Deserializer::from_str(text);
            let value = de.deserialize_map(WithoutType(std::marker::PhantomData))?;
            de.end()?;
            Ok(value)
        }
        Ok(match kind {
            "line" => QuickObject::Line(read(text).map_err(spec)?),
            "segment" => QuickObject::Segment(read(text).map_err(spec)?),
            "plane" => QuickObject::Plane(read(text).map_err(spec)?),
            "line2" => QuickObject::Line2(read(text).map_err(spec)?),
            "segment2" => QuickObject::Segment2(read(text).map_err(spec)?),
            _ => return Err(de::Error::custom("not a linear object")),
        })
    }
}

/// The `type` of an object (exactly one), the other values skipped.
struct TypeOf<'a>(&'a str);

impl<'de> Deserialize<'de> for TypeOf<'de> {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        struct V;
        impl<'de> Visitor<'de> for V {
            type Value = TypeOf<'de>;
            fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
                f.write_str("an object with one `type`")
            }
            fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<TypeOf<'de>, A::Error> {
                let mut kind = None;
                while let Some(key) = map.next_key::<&'de str>()? {
                    if key != "type" {
                        map.next_value::<IgnoredAny>()?;
                    } else if kind.replace(map.next_value::<&'de str>()?).is_some() {
                        return Err(de::Error::custom("duplicate `type`"));
                    }
                }
                kind.map(TypeOf)
                    .ok_or_else(|| de::Error::custom("no `type`"))
            }
        }
        d.deserialize_map(V)
    }
}

/// Reads a `T` from an object, leaving its `type` key out.
struct WithoutType<T>(std::marker::PhantomData<T>);

impl<'de, T: Deserialize<'de>> Visitor<'de> for WithoutType<T> {
    type Value = T;
    fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
        f.write_str("an object")
    }
    fn visit_map<A: MapAccess<'de>>(self, map: A) -> Result<T, A::Error> {
        T::deserialize(MapAccessDeserializer::new(SkipType(map)))
    }
}

/// The entries of a map but its `type`.
struct SkipType<A>(A);

impl<'de, A: MapAccess<'de>> MapAccess<'de> for SkipType<A> {
    type Error = A::Error;
    fn next_key_seed<K: DeserializeSeed<'de>>(
        &mut self,
        seed: K,
    ) -> Result<Option<K::Value>, A::Error> {
        loop {
            let Some(key) = self.0.next_key::<&'de str>()? else {
                return Ok(None);
            };
            if key == "type" {
                self.0.next_value::<IgnoredAny>()?;
                continue;
            }
            return seed
                .deserialize(BorrowedStrDeserializer::new(key))
                .map(Some);
        }
    }
    fn next_value_seed<V: DeserializeSeed<'de>>(&mut self, seed: V) -> Result<V::Value, A::Error> {
        self.0.next_value_seed(seed)
    }
}

impl From<QuickObject> for ObjectSpec {
    fn from(o: QuickObject) -> ObjectSpec {
        match o {
            QuickObject::Line(l) => ObjectSpec::Line(l),
            QuickObject::Segment(s) => ObjectSpec::Segment(s),
            QuickObject::Plane(p) => ObjectSpec::Plane(p),
            QuickObject::Line2(l) => ObjectSpec::Line2(l),
            QuickObject::Segment2(s) => ObjectSpec::Segment2(s),
        }
    }
}

/// The case of `text` (one case, BOM already removed) read the quick road, or `None`
/// when it must go the careful road (see the module documentation). `line` is the
/// input line the case starts on.
pub(super) fn read_quick(text: &str, line: usize) -> Option<Record> {
    let quick: QuickCase = serde_json::from_str(text).ok()?;
    let (id, raw_id) = match quick.id {
        Some(raw) => {
            let text = raw.get();
            let id = serde_json::from_str(text).ok()?;
            let numeric = text.starts_with(|c: char| c == '-' || c.is_ascii_digit());
            (id, numeric.then(|| text.to_string()))
        }
        None => (serde_json::Value::Null, None),
    };
    let case = check_options(&quick.options).map(|()| Case {
        id: id.clone(),
        op: quick.op,
        objects: quick.objects.into_iter().map(ObjectSpec::from).collect(),
        point: quick.point,
        onto: quick.onto.map(ObjectSpec::from),
        direction: quick.direction,
        nearest: quick.nearest,
        shell: None,
        claim: None,
        view: None,
        params: None,
        blend: Default::default(),
        options: quick.options,
    });
    Some(Record {
        read: ReadCase { id, case },
        line,
        raw_id,
    })
}

#[cfg(test)]
mod tests {
    use super::super::case::read_careful;
    use super::super::stream::Chunk;
    use super::*;
    use std::path::Path;

    /// Both roads on one text: when the quick one answers, the careful one agrees.
    fn agree(text: &str) -> bool {
        let Some(quick) = read_quick(text, 1) else {
            return false;
        };
        let careful = read_careful(text, &Chunk::default());
        assert_eq!(quick.read.id, careful.read.id, "{text}");
        assert_eq!(quick.read.case, careful.read.case, "{text}");
        assert_eq!(quick.raw_id, careful.raw_id, "{text}");
        true
    }

    fn texts() -> Vec<String> {
        let root = Path::new(env!("CARGO_MANIFEST_DIR"));
        let mut out: Vec<String> = ["tests/data/cases.jsonl", "tests/data/cases/mixed.jsonl"]
            .iter()
            .flat_map(|f| {
                let bytes = std::fs::read(root.join(f)).expect("the golden cases");
                let text = String::from_utf8_lossy(&bytes).into_owned();
                text.lines().map(str::to_string).collect::<Vec<_>>()
            })
            .collect();
        for dir in ["fuzz/corpus/json_lines", "fuzz/corpus/linear"] {
            let mut files: Vec<_> = std::fs::read_dir(root.join(dir))
                .expect("the fuzz corpus")
                .map(|e| e.expect("a corpus entry").path())
                .collect();
            files.sort();
            for f in files {
                let bytes = std::fs::read(f).expect("a corpus file");
                let text = String::from_utf8_lossy(&bytes).into_owned();
                out.extend(text.lines().map(str::to_string));
            }
        }
        out
    }

    #[test]
    fn quick_road_agrees_with_the_careful_road() {
        let texts = texts();
        let taken = texts.iter().filter(|t| agree(t)).count();
        // Anti-vacuity: the quick road takes a good share of the linear cases.
        assert!(taken > 200, "{taken} of {} texts taken", texts.len());
    }

    #[test]
    fn what_the_quick_road_leaves_to_the_careful_one() {
        let line = r#"{"type": "line", "origin": [0, 0, 0], "dir": [1, 0, 0]}"#;
        let plane = r#"{"type": "plane", "normal": [0, 0, 1], "d": "1/3"}"#;
        let case = |objects: &str, extra: &str| {
            format!(r#"{{"id": 7, "op": "intersect", "objects": [{objects}]{extra}}}"#)
        };
        assert!(agree(&case(&format!("{line}, {plane}"), "")));
        let project = format!(r#"{{"op": "project", "point": [1, "2", 3], "onto": {plane}}}"#);
        assert!(agree(&project));
        assert!(agree(&case(
            &format!("{line}, {plane}"),
            r#", "options": {"exact": true, "time_limit": 2}"#
        )));
        // Refused quick, answered carefully (with the error where there is one).
        for text in [
            case(&format!("{line}, {plane}"), r#", "op": "project""#),
            case(
                &format!("{line}, {plane}"),
                r#", "options": {"time_limit": -1}"#,
            ),
            case(
                r#"{"type": "plane", "normal": [0, 0, 1], "d": 1, "d": 2}"#,
                "",
            ),
            case(
                r#"{"type": "line", "type": "line", "origin": [0, 0, 0], "dir": [1, 0, 0]}"#,
                "",
            ),
            case(
                r#"{"type": "plane", "origin": [0, 0, 0], "u": [1, 0, 0], "v": [0, 1, 0], "domain": [[0, 1], [0, 1]]}"#,
                "",
            ),
            case(
                r#"{"type": "sphere", "center": [0, 0, 0], "radius": 1}"#,
                "",
            ),
            case(line, r#", "colour": 1"#),
            r#"{"id": 18446744073709551616, "op": "intersect", "objects": [], "id": 1}"#.into(),
            "[1, 2]".into(),
        ] {
            if let Some(quick) = read_quick(&text, 1) {
                // Taken only if it is right: the time limit is checked on both roads.
                let careful = read_careful(&text, &Chunk::default());
                assert_eq!(quick.read.case, careful.read.case, "{text}");
                assert!(careful.read.case.is_err(), "{text}");
            }
        }
        assert!(read_quick(&case(line, r#", "colour": 1"#), 1).is_none());
        // `type` after the other keys: the same object.
        let late = r#"{"origin": [0, 0, 0], "dir": [1, 0, 0], "type": "line"}"#;
        assert!(agree(&case(late, "")));
        assert_eq!(
            read_quick(&case(late, ""), 1)
                .unwrap()
                .read
                .case
                .unwrap()
                .objects,
            read_quick(&case(line, ""), 1)
                .unwrap()
                .read
                .case
                .unwrap()
                .objects
        );
        // An escaped key is not borrowed: careful road (which reads it alike).
        let escaped = r#"{"typ\u0065": "line", "origin": [0, 0, 0], "dir": [1, 0, 0]}"#;
        assert!(read_quick(&case(escaped, ""), 1).is_none());
        assert!(read_careful(&case(escaped, ""), &Chunk::default())
            .read
            .case
            .is_ok());
        // Raw ids echo as written.
        let big = r#"{"id": 18446744073709551616, "op": "intersect", "objects": []}"#;
        assert!(agree(big));
        assert_eq!(
            read_quick(big, 1).unwrap().raw_id.as_deref(),
            Some("18446744073709551616")
        );
        for id in [r#""s""#, "null", "1.50", "-0", "true"] {
            assert!(
                agree(&format!(r#"{{"id": {id}, "op": "intersect"}}"#)),
                "{id}"
            );
        }
    }
}
