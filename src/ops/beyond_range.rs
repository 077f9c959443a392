//! Numbers beyond the double range (docs/FORMAT.md "Numbers beyond the double range"):
//! an exact value beyond `f64::MAX` rounds to `±∞`, so a point holding one must carry
//! its exact rationals — the only finite record of the value. [`exact_beyond_range`]
//! runs an operation again with `Options::exact` when its answer holds such a number,
//! and keeps the rationals on the points and lines that need them.

use super::answer::{Answer, LineAnswer, Point};
use super::options::Options;
use crate::certificate::Certified;
use crate::error::GeomError;

fn beyond(v: &[f64]) -> bool {
    v.iter().any(|x| !x.is_finite())
}

fn bounds_beyond(v: &[[f64; 2]]) -> bool {
    v.iter().any(|b| beyond(b))
}

/// Whether some number of the point has no finite double.
pub fn point_beyond_range(p: &Point) -> bool {
    beyond(&p.xyz)
        || bounds_beyond(&p.xyz_box)
        || p.params.iter().any(|v| beyond(v))
        || p.param_box.iter().flatten().any(|b| bounds_beyond(b))
        || beyond(&[p.distance.unwrap_or(0.0), p.signed_distance.unwrap_or(0.0)])
}

fn line_beyond_range(l: &LineAnswer) -> bool {
    beyond(&l.point)
        || beyond(&l.dir)
        || l.params
            .iter()
            .flatten()
            .any(|p| beyond(&p.origin) || beyond(&p.dir))
}

/// The points of an answer, mutably (segment ends, a classification's nearest point).
fn points_mut(a: &mut Answer) -> Vec<&mut Point> {
    match a {
        Answer::Points(p) => p.iter_mut().collect(),
        Answer::Segment(s) | Answer::Arc(s) => vec![&mut s.a, &mut s.b],
        Answer::Ray(r) => vec![&mut r.start],
        Answer::Side(_, Some(p)) => vec![p],
        _ => vec![],
    }
}

/// Whether some number of the answer has no finite double.
pub fn answer_beyond_range(a: &Answer) -> bool {
    match a {
        Answer::Points(p) => p.iter().any(point_beyond_range),
        Answer::Segment(s) | Answer::Arc(s) => point_beyond_range(&s.a) || point_beyond_range(&s.b),
        Answer::Ray(r) => point_beyond_range(&r.start) || beyond(&r.dir),
        Answer::Side(_, Some(p)) => point_beyond_range(p),
        Answer::Line(l) => line_beyond_range(l),
        _ => false,
    }
}

/// Drop the exact rationals the case did not ask for (`options.exact` false), but
/// keep them on every point or line with a number beyond the double range: there
/// they are the only finite record of the value.
pub fn keep_exact_beyond_range(a: &mut Answer) {
    for p in points_mut(a) {
        if !point_beyond_range(p) {
            p.exact = None;
        }
    }
    if let Answer::Line(l) = a {
        if !line_beyond_range(l) {
            l.exact = None;
        }
    }
    if let Answer::Ray(r) = a {
        if !beyond(&r.dir) {
            r.exact_dir = None;
        }
    }
}

/// `solve(opts)`, solved again with exact rationals when its answer holds a number
/// beyond the double range and `opts.exact` was not asked for (module doc).
pub fn exact_beyond_range(
    opts: &Options,
    solve: impl Fn(&Options) -> Result<Certified<Answer>, GeomError>,
) -> Result<Certified<Answer>, GeomError> {
    let opts = &opts.started();
    let first = solve(opts)?;
    if opts.exact || !answer_beyond_range(&first.value) {
        return Ok(first);
    }
    let exact = Options {
        exact: true,
        ..opts.clone()
    };
    let mut again = solve(&exact)?;
    keep_exact_beyond_range(&mut again.value);
    Ok(again)
}
