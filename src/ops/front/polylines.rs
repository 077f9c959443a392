//! Polylines against linear shapes and against polylines, decided exactly: a polyline
//! is its segments (OPERATIONS.md §1.5, `c(t) = (1−w)P_i + w P_{i+1}`), each pair of
//! pieces goes through the linear kernel on exact rationals (§5.1, §6.1–6.2, §8), and
//! each piece parameter `w ∈ [0, 1]` maps back exactly to `t = t_i + w (t_{i+1} − t_i)`,
//! correctly rounded. Subdivision of such pairs could only prove what the kernel
//! decides at once, and ran past its time limit on pieces of 1e305 or collapsed
//! pieces (issue 20's fuzz findings); a polyline against a plane is an exact pair of
//! issue 16.
//!
//! A common point at a vertex shared by two pieces is reported once. A run of pieces
//! lying along the other object is one `segment` (one piece) or one `arc` (several), a
//! polyline lying in a plane is `coincident`. What one answer of the format cannot
//! hold — isolated points beside an overlap, several overlaps, a collapsed piece (a
//! continuum of parameters at one point) on the other object — is `undecided` with
//! the reason, at once.

use rug::Rational;

use crate::certificate::{Arithmetic, Certified};
use crate::curve::{AnyCurve2, AnyCurve3};
use crate::geom::{Plane, Segment, Segment2};
use crate::num::round::round_rational;
use crate::ops::answer::{Answer, Point, SegmentAnswer};
use crate::ops::linear;
use crate::ops::options::Options;
use crate::ops::shape::{Linear, LinearObject, Shape};

/// One side of the pair: a linear object (no parameter to map), or a polyline as its
/// pieces.
enum Side<'a> {
    Linear(&'a Linear),
    Polyline {
        points: Vec<Vec<f64>>,
        params: &'a [f64],
    },
}

impl Side<'_> {
    fn pieces(&self) -> usize {
        match self {
            Side::Linear(_) => 1,
            Side::Polyline { points, .. } => points.len() - 1,
        }
    }

    /// Piece `i` as a linear object; `None` for a collapsed piece (`P_i = P_{i+1}`).
    fn piece(&self, i: usize) -> Option<Linear> {
        match self {
            Side::Linear(l) => Some((*l).clone()),
            Side::Polyline { points, .. } => {
                let (p, q) = (&points[i], &points[i + 1]);
                let object = match p.len() {
                    2 => LinearObject::Segment2(
                        Segment2::new([p[0], p[1]].into(), [q[0], q[1]].into()).ok()?,
                    ),
                    _ => LinearObject::Segment(
                        Segment::new([p[0], p[1], p[2]].into(), [q[0], q[1], q[2]].into()).ok()?,
                    ),
                };
                Some(Linear::Double(object))
            }
        }
    }

    /// The bounding box of piece `i` (exact: the coordinates are the doubles given);
    /// `None` for a linear object, which is not boxed.
    fn piece_box(&self, i: usize) -> Option<Vec<[f64; 2]>> {
        let Side::Polyline { points, .. } = self else {
            return None;
        };
        let (p, q) = (&points[i], &points[i + 1]);
        Some(
            p.iter()
                .zip(q)
                .map(|(a, b)| [a.min(*b), a.max(*b)])
                .collect(),
        )
    }

    /// `t_i + w (t_{i+1} − t_i)` exactly, for a polyline.
    fn map(&self, i: usize, w: &Rational) -> Option<Rational> {
        let Side::Polyline { params, .. } = self else {
            return None;
        };
        let (a, b) = (
            Rational::from_f64(params[i])?,
            Rational::from_f64(params[i + 1])?,
        );
        Some(a.clone() + w.clone() * (b - a))
    }
}

/// A common point with its exact values, the key of deduplication.
struct Found {
    point: Point,
    xyz: Vec<Rational>,
    params: [Vec<Rational>; 2],
}

impl Found {
    fn same(&self, other: &Found) -> bool {
        self.xyz == other.xyz && self.params == other.params
    }
}

/// A polyline against a linear object or another polyline of the same dimension,
/// exactly; `None` for other pairs (and for a polyline whose points are all equal,
/// left to the identical-curve and numeric paths).
pub(super) fn pair(a: &Shape, b: &Shape, opts: &Options) -> Option<Certified<Answer>> {
    let sides = [side(a)?, side(b)?];
    if !sides.iter().any(|s| matches!(s, Side::Polyline { .. })) || a.is_2d() != b.is_2d() {
        return None;
    }
    let sub = Options {
        exact: true,
        ..opts.clone()
    };
    let mut points: Vec<Found> = Vec::new();
    let mut overlaps: Vec<[Found; 2]> = Vec::new();
    let mut collapsed: Vec<(usize, usize)> = Vec::new();
    let mut usable = [false; 2];
    let mut bits = 53;
    for i in 0..sides[0].pieces() {
        for j in 0..sides[1].pieces() {
            if opts
                .deadline
                .is_some_and(|d| std::time::Instant::now() >= d)
            {
                return Some(Certified::undecided(
                    Answer::from_points(points.into_iter().map(|f| f.point).collect()),
                    Arithmetic::Rational,
                    bits,
                    "time limit reached",
                ));
            }
            let (pa, pb) = (sides[0].piece(i), sides[1].piece(j));
            usable[0] |= pa.is_some();
            usable[1] |= pb.is_some();
            let (Some(pa), Some(pb)) = (pa, pb) else {
                // A collapsed piece: decided below, once the hits are known.
                if sides[0].piece(i).is_none() {
                    collapsed.push((0, i));
                }
                if sides[1].piece(j).is_none() {
                    collapsed.push((1, j));
                }
                continue;
            };
            if let (Some(ba), Some(bb)) = (sides[0].piece_box(i), sides[1].piece_box(j)) {
                if ba.iter().zip(&bb).any(|(x, y)| x[1] < y[0] || y[1] < x[0]) {
                    continue; // disjoint boxes: disjoint pieces
                }
            }
            let answer = linear::intersect(&[&pa, &pb], &sub).ok()?;
            bits = bits.max(answer.bits);
            let map = |p: &Point| found(p, &sides, [i, j], opts.exact);
            match &answer.value {
                Answer::Empty => {}
                Answer::Points(ps) => {
                    for p in ps {
                        let f = map(p)?;
                        if !points.iter().any(|q| q.same(&f)) {
                            points.push(f);
                        }
                    }
                }
                Answer::Segment(s) => overlaps.push([map(&s.a)?, map(&s.b)?]),
                _ => return None,
            }
        }
    }
    if let Some(k) = usable.iter().position(|u| !*u) {
        return Some(one_point(&sides, k));
    }
    let mut r = assemble(points, overlaps, &collapsed, &sides);
    r.bits = bits;
    Some(r)
}

/// A polyline `sides[k]` whose points are all one point `P`: `empty` when `P` is not
/// on the other object (decided exactly), else every parameter of the polyline is a
/// solution at `P` — a continuum a list of points cannot hold: `undecided` with that
/// reason. (Subdivision could only spend its budget on such a pair: issue 20.)
fn one_point(sides: &[Side; 2], k: usize) -> Certified<Answer> {
    let Side::Polyline { points, params } = &sides[k] else {
        unreachable!("only a polyline has pieces that are all collapsed")
    };
    let at: Vec<Rational> = points[0]
        .iter()
        .map(|x| Rational::from_f64(*x).expect("finite by construction"))
        .collect();
    let on = match &sides[1 - k] {
        Side::Linear(l) => on_linear(&at, &l.exact()),
        Side::Polyline { points: other, .. } => {
            let q = |p: &Vec<f64>| -> Vec<Rational> {
                p.iter()
                    .map(|x| Rational::from_f64(*x).expect("finite by construction"))
                    .collect()
            };
            other.len() == 1
                || other.windows(2).any(|w| between(&at, &q(&w[0]), &q(&w[1])))
                || other.iter().any(|p| q(p) == at)
        }
    };
    if on {
        return Certified::undecided(
            Answer::Empty,
            Arithmetic::Rational,
            53,
            format!(
                "objects[{k}] stays at the common point {:?} for every parameter in [{}, {}]: \
                 a continuum of parameters, which a list of points cannot hold",
                points[0],
                params[0],
                params[params.len() - 1]
            ),
        );
    }
    let mut r = Certified::exact(Answer::Empty, Arithmetic::Rational, 53);
    r.reason = Some(format!(
        "objects[{k}] is one point, not on the other object"
    ));
    r
}

/// Whether the point `x` lies on the linear object, exactly.
fn on_linear(x: &[Rational], l: &LinearObject<Rational>) -> bool {
    let sub = |a: &[Rational], b: &[Rational]| -> Vec<Rational> {
        a.iter()
            .zip(b)
            .map(|(a, b)| Rational::from(a - b))
            .collect()
    };
    let dot = |a: &[Rational], b: &[Rational]| -> Rational {
        a.iter().zip(b).map(|(a, b)| Rational::from(a * b)).sum()
    };
    let on_carrier =
        |o: &[Rational], d: &[Rational], lo: Option<&Rational>, hi: Option<&Rational>| {
            // x − o parallel to d (every 2×2 minor zero), its parameter within the range
            let e = sub(x, o);
            let parallel = (0..d.len()).all(|i| {
                (i + 1..d.len())
                    .all(|j| Rational::from(&d[i] * &e[j]) == Rational::from(&d[j] * &e[i]))
            });
            let t = dot(&e, d) / dot(d, d);
            parallel && lo.is_none_or(|lo| t >= *lo) && hi.is_none_or(|hi| t <= *hi)
        };
    match l {
        LinearObject::Line(line) => {
            let (lo, hi) = line.bounds();
            on_carrier(line.origin().as_slice(), line.dir().as_slice(), lo, hi)
        }
        LinearObject::Line2(line) => {
            let (lo, hi) = line.bounds();
            on_carrier(line.origin().as_slice(), line.dir().as_slice(), lo, hi)
        }
        LinearObject::Segment(seg) => between(x, seg.a().as_slice(), seg.b().as_slice()),
        LinearObject::Segment2(seg) => between(x, seg.a().as_slice(), seg.b().as_slice()),
        LinearObject::Plane(Plane::Implicit { normal, d }) => {
            dot(normal.as_slice(), x) + d.clone() == 0
        }
        LinearObject::Plane(Plane::Parametric { origin, u, v }) => {
            let c =
                |i: usize, j: usize| Rational::from(&u[i] * &v[j]) - Rational::from(&u[j] * &v[i]);
            let n = [c(1, 2), c(2, 0), c(0, 1)];
            dot(&n, &sub(x, origin.as_slice())) == 0
        }
    }
}

fn side(s: &Shape) -> Option<Side<'_>> {
    match s {
        Shape::Linear(l) => Some(Side::Linear(l)),
        Shape::Curve(AnyCurve3::Polyline(p)) => Some(Side::Polyline {
            points: p.points().iter().map(|x| x.to_vec()).collect(),
            params: p.params(),
        }),
        Shape::Curve2(AnyCurve2::Polyline(p)) => Some(Side::Polyline {
            points: p.points().iter().map(|x| x.to_vec()).collect(),
            params: p.params(),
        }),
        _ => None,
    }
}

/// A point of pieces `pieces` with its polyline parameters mapped back (estimate,
/// correctly rounded, and its tight enclosure); the exact values are kept on the point
/// only when the caller asked for them.
fn found(p: &Point, sides: &[Side; 2], pieces: [usize; 2], keep: bool) -> Option<Found> {
    let exact = p.exact.as_ref()?;
    let mut point = p.clone();
    let mut params = [exact.params[0].clone(), exact.params[1].clone()];
    for k in 0..2 {
        if let Side::Polyline { .. } = sides[k] {
            let t = sides[k].map(pieces[k], params[k].first()?)?;
            let r = round_rational(&t);
            point.params[k] = vec![r.nearest];
            if let Some(b) = point.param_box.as_mut() {
                b[k] = vec![[r.lo, r.hi]];
            }
            params[k] = vec![t];
        }
    }
    let xyz = exact.xyz.clone();
    point.exact = keep.then(|| {
        let mut e = exact.clone();
        e.params = params.to_vec();
        e
    });
    Some(Found { point, xyz, params })
}

/// The answer from the deduplicated points and the overlapping pieces.
fn assemble(
    mut points: Vec<Found>,
    overlaps: Vec<[Found; 2]>,
    collapsed: &[(usize, usize)],
    sides: &[Side; 2],
) -> Certified<Answer> {
    let undecided =
        |reason: String| Certified::undecided(Answer::Empty, Arithmetic::Rational, 53, reason);
    // A collapsed piece at a common point: every parameter of the piece is a solution.
    for &(k, i) in collapsed {
        let Side::Polyline { points: v, params } = &sides[k] else {
            continue;
        };
        let at: Vec<Rational> = v[i].iter().filter_map(|x| Rational::from_f64(*x)).collect();
        let on = points.iter().any(|f| f.xyz == at)
            || overlaps.iter().flatten().any(|f| f.xyz == at)
            || overlaps.iter().any(|[a, b]| between(&at, &a.xyz, &b.xyz));
        if on {
            return undecided(format!(
                "objects[{k}] stays at the common point {:?} for every parameter in [{}, {}]: \
                 a continuum of parameters, which a list of points cannot hold",
                v[i],
                params[i],
                params[i + 1]
            ));
        }
    }
    let nodes: Vec<&Found> = overlaps.iter().flatten().collect();
    // A point at a node of the run (its ends, or a joint of two pieces) is a point of it.
    points.retain(|p| !nodes.iter().any(|e| e.same(p)));
    let chain = chain(overlaps);
    let Some(chain) = chain else {
        return undecided(
            "the polylines overlap along several separate runs, which one answer cannot hold"
                .into(),
        );
    };
    let Some(pieces) = chain else {
        points.sort_by(order);
        let pts = points.into_iter().map(|f| f.point).collect();
        return Certified::exact(Answer::from_points(pts), Arithmetic::Rational, 53);
    };
    let (ends, count) = pieces;
    if !points.is_empty() {
        return undecided(format!(
            "{} isolated common point(s) beside an overlapping run: one answer of the format \
             cannot hold both",
            points.len()
        ));
    }
    let [a, b] = ends;
    let whole = |k: usize| match &sides[k] {
        Side::Polyline { params, .. } => {
            let ends = [&a.params[k], &b.params[k]];
            let lo = Rational::from_f64(params[0]);
            let hi = Rational::from_f64(params[params.len() - 1]);
            ends.iter().any(|e| e.first() == lo.as_ref())
                && ends.iter().any(|e| e.first() == hi.as_ref())
        }
        Side::Linear(_) => false,
    };
    let in_plane = (0..2)
        .any(|k| matches!(&sides[1 - k], Side::Linear(l) if l.type_name() == "plane") && whole(k));
    if in_plane {
        let mut r = Certified::exact(Answer::Coincident, Arithmetic::Rational, 53);
        r.reason = Some("the polyline lies in the plane".into());
        return r;
    }
    let (a, b) = if order(&a, &b).is_le() {
        (a, b)
    } else {
        (b, a)
    };
    let run = SegmentAnswer {
        a: a.point,
        b: b.point,
    };
    let value = if count == 1 {
        Answer::Segment(run)
    } else {
        Answer::Arc(run)
    };
    Certified::exact(value, Arithmetic::Rational, 53)
}

/// Order by the first object's parameter, then the second's (a plane has none).
fn order(p: &Found, q: &Found) -> std::cmp::Ordering {
    p.params[0]
        .cmp(&q.params[0])
        .then(p.params[1].cmp(&q.params[1]))
}

/// Whether `x` lies on the segment from `a` to `b`, exactly: `x − a` parallel to
/// `b − a` (every 2×2 minor zero) and `x` in the segment's box.
fn between(x: &[Rational], a: &[Rational], b: &[Rational]) -> bool {
    let d: Vec<Rational> = b
        .iter()
        .zip(a)
        .map(|(b, a)| Rational::from(b - a))
        .collect();
    let e: Vec<Rational> = x
        .iter()
        .zip(a)
        .map(|(x, a)| Rational::from(x - a))
        .collect();
    let parallel = (0..d.len()).all(|i| {
        (i + 1..d.len()).all(|j| Rational::from(&d[i] * &e[j]) == Rational::from(&d[j] * &e[i]))
    });
    parallel
        && x.iter().zip(a.iter().zip(b)).all(|(x, (a, b))| {
            let (lo, hi) = if a <= b { (a, b) } else { (b, a) };
            lo <= x && x <= hi
        })
}

/// The overlapping pieces as one run: `Some(None)` when there are none,
/// `Some(Some((ends, pieces)))` for a single open run (pieces sharing an end, exactly:
/// the same point with the same parameters), `None` for several runs or a closed one.
#[allow(clippy::type_complexity)]
fn chain(mut overlaps: Vec<[Found; 2]>) -> Option<Option<([Found; 2], usize)>> {
    let Some([mut first, mut last]) = overlaps.pop() else {
        return Some(None);
    };
    let mut count = 1;
    while !overlaps.is_empty() {
        let k = overlaps
            .iter()
            .position(|[a, b]| [&first, &last].iter().any(|end| end.same(a) || end.same(b)))?;
        let [a, b] = overlaps.swap_remove(k);
        if first.same(&a) {
            first = b;
        } else if first.same(&b) {
            first = a;
        } else if last.same(&a) {
            last = b;
        } else {
            last = a;
        }
        count += 1;
    }
    (!first.same(&last)).then_some(Some(([first, last], count)))
}
