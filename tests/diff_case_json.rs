//! The JSON line a failing differential case prints (spec/CASES.md) reads back, via
//! `geocert::io::read_cases`, to the same objects bit for bit, and `solve_case`
//! replays it: the result's kind is the certified kind of the same case.

use geocert::io::objects::{Line2Spec, LineSpec, PlaneSpec, Segment2Spec, SegmentSpec};
use geocert::io::{read_cases, solve_case, Num, ObjectSpec, Op};
use geocert::robust::answer::Kind;
use geocert::robust::case::{Case, Linear2In, LinearIn, PlaneIn};
use geocert::robust::{case, methods, Construction, Generator};

fn nums<const N: usize>(v: &[f64; N]) -> [Num; N] {
    v.map(Num::Double)
}

/// The objects the case format must produce for a case, built here from its numbers.
fn plane(p: &PlaneIn) -> ObjectSpec {
    ObjectSpec::Plane(match p {
        PlaneIn::Parametric { origin, u, v } => PlaneSpec {
            origin: Some(nums(origin)),
            u: Some(nums(u)),
            v: Some(nums(v)),
            normal: None,
            d: None,
            points: None,
        },
        PlaneIn::Implicit { normal, d } => PlaneSpec {
            origin: None,
            u: None,
            v: None,
            normal: Some(nums(normal)),
            d: Some(Num::Double(*d)),
            points: None,
        },
    })
}

fn linear(l: &LinearIn) -> ObjectSpec {
    match l {
        LinearIn::Line { origin, dir } => ObjectSpec::Line(LineSpec {
            origin: nums(origin),
            dir: nums(dir),
            range: None,
        }),
        LinearIn::Segment { a, b } => ObjectSpec::Segment(SegmentSpec {
            a: nums(a),
            b: nums(b),
        }),
    }
}

fn linear2(l: &Linear2In) -> ObjectSpec {
    match l {
        Linear2In::Line { origin, dir } => ObjectSpec::Line2(Line2Spec {
            origin: nums(origin),
            dir: nums(dir),
            range: None,
        }),
        Linear2In::Segment { a, b } => ObjectSpec::Segment2(Segment2Spec {
            a: nums(a),
            b: nums(b),
        }),
    }
}

/// Every number of an object spec, as bits (`-0.0` and `0.0` differ).
fn bits(o: &ObjectSpec) -> Vec<u64> {
    let n = |xs: &[Num]| -> Vec<u64> {
        xs.iter()
            .map(|x| x.as_double().expect("a JSON number").to_bits())
            .collect()
    };
    match o {
        ObjectSpec::Line(l) => [n(&l.origin), n(&l.dir)].concat(),
        ObjectSpec::Segment(s) => [n(&s.a), n(&s.b)].concat(),
        ObjectSpec::Plane(p) => [
            p.origin.as_ref().map_or(vec![], |v| n(v)),
            p.u.as_ref().map_or(vec![], |v| n(v)),
            p.v.as_ref().map_or(vec![], |v| n(v)),
            p.normal.as_ref().map_or(vec![], |v| n(v)),
            p.d.as_ref().map_or(vec![], |d| n(std::slice::from_ref(d))),
        ]
        .concat(),
        ObjectSpec::Line2(l) => [n(&l.origin), n(&l.dir)].concat(),
        ObjectSpec::Segment2(s) => [n(&s.a), n(&s.b)].concat(),
        ObjectSpec::Polyhedron(p) => p.vertices.iter().flat_map(|v| n(v)).collect(),
        // The linear generators never write curved objects.
        ObjectSpec::Curve3(_)
        | ObjectSpec::Curve2(_)
        | ObjectSpec::Surface(_)
        | ObjectSpec::Quadric(_) => vec![],
    }
}

/// The objects (intersect) or the point and target (project) a case must read back as.
fn expected(c: &Case) -> (Op, Vec<ObjectSpec>, Option<[f64; 3]>) {
    match c {
        Case::ThreePlanes(p) => (Op::Intersect, p.iter().map(plane).collect(), None),
        Case::LinePlane(l, p) => (Op::Intersect, vec![linear(l), plane(p)], None),
        Case::PlanePlane(a, b) => (Op::Intersect, vec![plane(a), plane(b)], None),
        Case::ProjectLine(p, o, d) => (
            Op::Project,
            vec![linear(&LinearIn::Line {
                origin: *o,
                dir: *d,
            })],
            Some(*p),
        ),
        Case::ProjectPlane(p, pl) => (Op::Project, vec![plane(pl)], Some(*p)),
        Case::Linear2(a, b) => (Op::Intersect, vec![linear2(a), linear2(b)], None),
    }
}

/// The result kind `geocert solve` must report for the certified answer (CASES.md
/// "Results"; two equal planes are `coincident`).
fn result_kind(c: Construction, k: Kind) -> &'static str {
    match k {
        Kind::Empty => "empty",
        Kind::Point => "points",
        Kind::Line => "line",
        Kind::Segment => "segment",
        Kind::Plane if c == Construction::PlanePlane => "coincident",
        Kind::Plane => "plane",
        Kind::Error => "error",
    }
}

#[test]
fn printed_cases_read_back_to_the_same_doubles_and_replay() {
    let mut replayed = 0;
    for (ci, &construction) in Construction::ALL.iter().enumerate() {
        for (gi, &generator) in Generator::ALL.iter().enumerate() {
            for s in 0..300u64 {
                let seed = s * 7919 + (ci * 31 + gi) as u64;
                let c = case(construction, generator, seed);
                let line = c.json_line(&format!("case-{seed}"));
                assert!(!line.contains('\n'), "{line}");
                let read = read_cases(&line);
                assert_eq!(read.len(), 1);
                let got = read[0]
                    .case
                    .as_ref()
                    .unwrap_or_else(|e| panic!("{e}: {line}"));
                let (op, objects, point) = expected(&c);
                assert_eq!(got.op, op, "{line}");
                assert_eq!(got.id, serde_json::json!(format!("case-{seed}")));
                let got_objects: Vec<ObjectSpec> = match op {
                    Op::Project => got.onto.iter().cloned().collect(),
                    _ => got.objects.clone(),
                };
                assert_eq!(got_objects, objects, "{line}");
                for (g, e) in got_objects.iter().zip(&objects) {
                    assert_eq!(bits(g), bits(e), "{line}");
                }
                if let Some(p) = point {
                    let gp: Vec<u64> = got
                        .point
                        .as_ref()
                        .expect("a point")
                        .iter()
                        .map(|x| x.as_double().expect("a number").to_bits())
                        .collect();
                    assert_eq!(gp, p.map(f64::to_bits).to_vec(), "{line}");
                }
                // Replay a sample through the solver: the same certified kind.
                if s % 10 == 0 {
                    let answers = methods::geocert(&c).expect("valid case");
                    let result = solve_case(read.into_iter().next().expect("one case"));
                    assert_eq!(result.status, "exact", "{line}");
                    assert_eq!(
                        result.kind,
                        Some(result_kind(construction, answers.certified.kind)),
                        "{line}"
                    );
                    replayed += 1;
                }
            }
        }
    }
    assert_eq!(replayed, 35 * 30);
}

#[test]
fn extreme_doubles_survive_the_round_trip() {
    let xs = [
        -0.0,
        5e-324,
        -2.2250738585072014e-308,
        f64::MAX,
        0.1 + 0.2,
        1e150 * (1.0 + f64::EPSILON),
        9007199254740993.0,
        123456789.0,
    ];
    for w in xs.windows(3) {
        let c = Case::ProjectLine([w[0], w[1], w[2]], [w[2], w[1], w[0]], [1.0, w[0], 2.0]);
        let read = read_cases(&c.json_line("x"));
        let got = read[0].case.as_ref().expect("parses");
        let p: Vec<u64> = got
            .point
            .as_ref()
            .expect("point")
            .iter()
            .map(|x| x.as_double().expect("number").to_bits())
            .collect();
        assert_eq!(p, vec![w[0].to_bits(), w[1].to_bits(), w[2].to_bits()]);
        let onto = got.onto.as_ref().expect("onto");
        assert_eq!(
            bits(onto),
            [w[2], w[1], w[0], 1.0, w[0], 2.0]
                .map(f64::to_bits)
                .to_vec()
        );
    }
}
