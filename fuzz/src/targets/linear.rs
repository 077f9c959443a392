//! Linear constructions (OPERATIONS.md §2–§4): line or segment ∩ plane, plane ∩ plane,
//! three planes, a point projected onto a plane or a line; near-degenerate often
//! (near-parallel normals, a direction nearly in the plane, a third plane nearly the
//! sum of two). The exact truth is computed here with rationals; a certified answer
//! must match it: same kind, the exact `"p/q"` values equal, each box around the truth.

use super::check;
use super::num::{self, Coord};
use super::objects::Plane;
use arbitrary::{Result, Unstructured};
use geocert::io::case::parse_case;
use geocert::io::solve_case;
use rug::Rational;
use serde_json::{json, Value};

type Q3 = [Rational; 3];

/// The fuzz target: a linear case from `data`, solved, checked against exact truth.
pub fn linear(data: &[u8]) {
    let mut u = Unstructured::new(data);
    let Ok((case, truth)) = build(&mut u) else {
        return;
    };
    let line = solve_case(parse_case(case.clone())).to_json_line();
    let v = check::record(&line);
    if v["status"] == "error" {
        // Only a degenerate input (a zero direction or normal) may be refused.
        assert!(
            truth.is_none(),
            "a valid linear case refused: {case}\n{line}"
        );
        return;
    }
    let truth = truth.unwrap_or_else(|| panic!("a degenerate input answered: {case}\n{line}"));
    if v["status"] != "undecided" {
        truth.check(&v, &line);
    }
}

/// What the answer must be.
enum Truth {
    /// One point (and the parameter of the first object when it has one).
    Point(Q3, Option<Rational>),
    /// A line: every point `p` with `n·p + d = 0` for each of these planes.
    Line(Vec<(Q3, Rational)>),
    /// A segment or a ranged line lying in the plane: its two ends.
    Segment(Q3, Q3),
    Coincident,
    Empty,
    /// A projection's foot and squared distance.
    Foot(Q3, Rational, Option<Rational>),
}

fn build(u: &mut Unstructured) -> Result<(Value, Option<Truth>)> {
    let options = json!({"exact": true, "time_limit": super::TIME_LIMIT});
    let p1 = Plane::arbitrary(u)?;
    Ok(match u.int_in_range(0u8..=4)? {
        0 => {
            let (obj, o, d, range) = line_near(u, &p1)?;
            let case = json!({"op": "intersect", "objects": [obj, p1.json()], "options": options});
            let truth = p1
                .exact()
                .zip(nonzero(&d))
                .map(|((n, dd), _)| line_plane(&o, &d, range, &n, &dd));
            (case, truth)
        }
        1 => {
            let p2 = p1.near(u)?;
            let case =
                json!({"op": "intersect", "objects": [p1.json(), p2.json()], "options": options});
            let truth = p1.exact().zip(p2.exact()).map(|(a, b)| planes(vec![a, b]));
            (case, truth)
        }
        2 => {
            let p2 = Plane::arbitrary(u)?;
            let p3 = if u.arbitrary()? {
                p1.near_sum(u, &p2)?
            } else {
                Plane::arbitrary(u)?
            };
            let objs = [p1.json(), p2.json(), p3.json()];
            let case = json!({"op": "intersect", "objects": objs, "options": options});
            let truth = match (p1.exact(), p2.exact(), p3.exact()) {
                (Some(a), Some(b), Some(c)) => Some(planes(vec![a, b, c])),
                _ => None,
            };
            (case, truth)
        }
        3 => {
            let p = num::vec3(u)?;
            let case = json!({"op": "project", "point": num::json3(&p), "onto": p1.json(), "options": options});
            (case, p1.exact().map(|(n, d)| foot_plane(&q3(&p), &n, &d)))
        }
        _ => {
            let (o, d) = (num::vec3(u)?, num::vec3(u)?);
            let p = num::vec3(u)?;
            let onto = json!({"type": "line", "origin": num::json3(&o), "dir": num::json3(&d)});
            let case =
                json!({"op": "project", "point": num::json3(&p), "onto": onto, "options": options});
            let (o, d) = (q3(&o), q3(&d));
            (case, nonzero(&d).map(|_| foot_line(&q3(&p), &o, &d)))
        }
    })
}

/// A line or segment, its direction often nearly in the plane `p`: the object, its
/// origin, direction and parameter range.
fn line_near(u: &mut Unstructured, p: &Plane) -> Result<(Value, Q3, Q3, Option<[Rational; 2]>)> {
    let o = num::vec3(u)?;
    let d = if u.arbitrary()? {
        let w = num::vec3(u)?;
        let d = num::cross_f64(&p.normal_f64(), &w);
        if u.arbitrary()? {
            num::near_copy(u, &d)?
        } else {
            d
        }
    } else {
        num::vec3(u)?
    };
    if u.ratio(1u8, 3)? {
        // A segment from o to o + d (rounded): c(t) = (1 − t)·a + t·b.
        let bc: [Coord; 3] = std::array::from_fn(|i| {
            let x = o[i].f64() + d[i].f64();
            Coord::F(if x.is_finite() { x } else { 0.0 })
        });
        let (a, b) = (q3(&o), q3(&bc));
        let dir = sub(&b, &a);
        let obj = json!({"type": "segment", "a": num::json3(&o), "b": num::json3(&bc)});
        return Ok((obj, a, dir, Some([Rational::new(), Rational::from(1)])));
    }
    let range = if u.ratio(1u8, 3)? {
        let (a, b) = (num::double(u)?, num::double(u)?);
        (a != b).then(|| [a.min(b), a.max(b)])
    } else {
        None
    };
    let mut obj = json!({"type": "line", "origin": num::json3(&o), "dir": num::json3(&d)});
    if let Some(r) = range {
        obj["range"] = json!(r);
    }
    let range = range.map(|r| r.map(|x| Rational::from_f64(x).unwrap()));
    Ok((obj, q3(&o), q3(&d), range))
}

pub fn q3(v: &[Coord; 3]) -> Q3 {
    v.map(Coord::rational)
}

fn sub(a: &Q3, b: &Q3) -> Q3 {
    std::array::from_fn(|i| Rational::from(&a[i] - &b[i]))
}

pub fn dot(a: &Q3, b: &Q3) -> Rational {
    let mut s = Rational::new();
    for i in 0..3 {
        s += Rational::from(&a[i] * &b[i]);
    }
    s
}

fn nonzero(d: &Q3) -> Option<()> {
    d.iter().any(|x| *x != 0).then_some(())
}

fn at(o: &Q3, d: &Q3, t: &Rational) -> Q3 {
    std::array::from_fn(|i| &o[i] + Rational::from(&d[i] * t))
}

fn line_plane(o: &Q3, d: &Q3, range: Option<[Rational; 2]>, n: &Q3, dd: &Rational) -> Truth {
    let nd = dot(n, d);
    let r = dot(n, o) + dd;
    if nd == 0 {
        return match (r == 0, range) {
            (false, _) => Truth::Empty,
            (true, None) => Truth::Line(vec![(n.clone(), dd.clone())]),
            (true, Some([t0, t1])) => Truth::Segment(at(o, d, &t0), at(o, d, &t1)),
        };
    }
    let t = -r / nd;
    if let Some([t0, t1]) = &range {
        if t < *t0 || t > *t1 {
            return Truth::Empty;
        }
    }
    Truth::Point(at(o, d, &t), Some(t))
}

/// The rank of a matrix of rationals (Gaussian elimination).
fn rank(mut rows: Vec<Vec<Rational>>) -> usize {
    let cols = rows.first().map_or(0, Vec::len);
    let mut r = 0;
    for c in 0..cols {
        let Some(p) = (r..rows.len()).find(|&i| rows[i][c] != 0) else {
            continue;
        };
        rows.swap(r, p);
        let pivot = rows[r].clone();
        for row in rows.iter_mut().skip(r + 1) {
            let f = Rational::from(&row[c] / &pivot[c]);
            for (x, p) in row[c..].iter_mut().zip(&pivot[c..]) {
                *x -= Rational::from(&f * p);
            }
        }
        r += 1;
    }
    r
}

/// Two or three planes `n·x + d = 0`: the kind of their common set, by the ranks of
/// the normals and of the augmented system; the point by Cramer's rule.
fn planes(ps: Vec<(Q3, Rational)>) -> Truth {
    let m: Vec<Vec<Rational>> = ps.iter().map(|(n, _)| n.to_vec()).collect();
    let aug: Vec<Vec<Rational>> = ps
        .iter()
        .map(|(n, d)| n.iter().cloned().chain([d.clone()]).collect())
        .collect();
    let (rm, ra) = (rank(m.clone()), rank(aug));
    if ra > rm {
        return Truth::Empty;
    }
    match rm {
        1 => Truth::Coincident,
        2 => Truth::Line(ps),
        _ => {
            let det = det3(&m);
            let rhs: Vec<Rational> = ps.iter().map(|(_, d)| Rational::from(-d)).collect();
            let x = std::array::from_fn(|c| {
                let mut mc = m.clone();
                for (row, b) in mc.iter_mut().zip(&rhs) {
                    row[c] = b.clone();
                }
                det3(&mc) / &det
            });
            Truth::Point(x, None)
        }
    }
}

fn det3(m: &[Vec<Rational>]) -> Rational {
    let t = |a: usize, b: usize, c: usize| Rational::from(&m[0][a] * &m[1][b]) * &m[2][c];
    t(0, 1, 2) - t(0, 2, 1) - t(1, 0, 2) + t(1, 2, 0) + t(2, 0, 1) - t(2, 1, 0)
}

fn foot_plane(p: &Q3, n: &Q3, d: &Rational) -> Truth {
    let r = dot(n, p) + d;
    let nn = dot(n, n);
    let s = Rational::from(&r / &nn);
    let foot = std::array::from_fn(|i| &p[i] - Rational::from(&s * &n[i]));
    Truth::Foot(foot, Rational::from(&r * &r) / nn, None)
}

fn foot_line(p: &Q3, o: &Q3, d: &Q3) -> Truth {
    let t = dot(&sub(p, o), d) / dot(d, d);
    let foot = at(o, d, &t);
    let e = sub(p, &foot);
    Truth::Foot(foot, dot(&e, &e), Some(t))
}

fn parse_q(x: &Value, line: &str) -> Rational {
    let s = x
        .as_str()
        .unwrap_or_else(|| panic!("exact value {x} not a string: {line}"));
    s.parse()
        .unwrap_or_else(|_| panic!("exact value {s} not a rational: {line}"))
}

fn parse_q3(x: &Value, line: &str) -> Q3 {
    std::array::from_fn(|i| parse_q(&x[i], line))
}

/// A certified point equal to `truth`: its exact values, its box around them, its
/// doubles the correct roundings.
fn same_point(p: &Value, truth: &Q3, line: &str) {
    let exact = parse_q3(&p["exact"]["xyz"], line);
    assert!(
        &exact == truth,
        "exact {exact:?} is not the truth {truth:?}: {line}"
    );
    let bounds = check::bounds(p, line).unwrap_or_else(|| panic!("no box: {line}"));
    for i in 0..3 {
        let (lo, hi) = bounds[i];
        assert!(
            (lo == f64::NEG_INFINITY || truth[i] >= lo) && (hi == f64::INFINITY || truth[i] <= hi),
            "the truth {} is outside the box [{lo}, {hi}]: {line}",
            truth[i]
        );
        let x = check::number(&p["xyz"][i], line).unwrap();
        let nearest = rug::Float::with_val(53, &truth[i]).to_f64();
        let size = truth[i].clone().abs();
        if size > Rational::from_f64(1e-290).unwrap()
            && size <= Rational::from_f64(f64::MAX).unwrap()
        {
            assert_eq!(
                x, nearest,
                "xyz[{i}] is not the nearest double to {}: {line}",
                truth[i]
            );
        }
    }
}

impl Truth {
    fn check(&self, v: &Value, line: &str) {
        let kind = v["kind"].as_str().unwrap();
        match self {
            Truth::Point(x, t) => {
                assert_eq!(kind, "points", "expected one point: {line}");
                assert_eq!(v["points"].as_array().map(Vec::len), Some(1), "{line}");
                let p = &v["points"][0];
                same_point(p, x, line);
                if let Some(t) = t {
                    assert_eq!(&parse_q(&p["exact"]["params"][0][0], line), t, "{line}");
                }
            }
            Truth::Foot(x, d2, t) => {
                assert_eq!(kind, "points", "expected the foot: {line}");
                let p = &v["points"][0];
                same_point(p, x, line);
                assert_eq!(
                    &parse_q(&p["exact"]["distance_squared"], line),
                    d2,
                    "{line}"
                );
                if let Some(t) = t {
                    assert_eq!(&parse_q(&p["exact"]["params"][0][0], line), t, "{line}");
                }
            }
            Truth::Line(ps) => {
                assert_eq!(kind, "line", "expected a line: {line}");
                if let Some(e) = v["line"].get("exact") {
                    let (pt, dir) = (parse_q3(&e["point"], line), parse_q3(&e["dir"], line));
                    assert!(nonzero(&dir).is_some(), "a zero direction: {line}");
                    for (n, d) in ps {
                        assert!(dot(n, &pt) + d == 0, "the point is off a plane: {line}");
                        assert!(dot(n, &dir) == 0, "the direction leaves a plane: {line}");
                    }
                }
            }
            Truth::Segment(a, b) => {
                assert_eq!(kind, "segment", "expected a segment: {line}");
                let s = &v["segment"];
                let (pa, pb) = (&s["a"], &s["b"]);
                let ea = parse_q3(&pa["exact"]["xyz"], line);
                // Its ends in either order.
                let (ta, tb) = if &ea == a { (a, b) } else { (b, a) };
                same_point(pa, ta, line);
                same_point(pb, tb, line);
            }
            // Two equal planes are `coincident`; three, `plane`.
            Truth::Coincident => assert!(kind == "coincident" || kind == "plane", "{line}"),
            Truth::Empty => assert_eq!(kind, "empty", "expected empty: {line}"),
        }
    }
}
