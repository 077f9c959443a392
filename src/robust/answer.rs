//! Every method's answer reduced to what the robustness table compares: the kind
//! (CGAL's result kinds) and, where the answer is a point, a projection foot or a
//! segment, its coordinates. Lines and planes are compared by kind only here (their
//! representatives differ between kernels; tests/diff_*.rs compares them as sets).

use nalgebra::Scalar;
use rug::Rational;

use crate::geom::line_plane::LinePlane;
use crate::geom::lines2::{Empty2, Intersection2};
use crate::geom::plane_plane::PlanePlane;
use crate::geom::project::{LineProjection, PlaneProjection};
use crate::geom::three_planes::ThreePlanes;
use crate::num::round::{round_rational, Rounded};

/// The kind of an answer, as CGAL names them, plus `Error` for a refused input.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Kind {
    Empty,
    Point,
    Line,
    Segment,
    Plane,
    /// The method refused the input or failed (e.g. Epick's rounded normal was zero).
    Error,
}

/// A kind and the coordinates of its point, foot or segment end points.
#[derive(Debug, Clone, PartialEq)]
pub struct Answer<S> {
    pub kind: Kind,
    pub coords: Vec<S>,
}

impl<S> Answer<S> {
    pub fn kind(kind: Kind) -> Self {
        Answer {
            kind,
            coords: Vec::new(),
        }
    }
    fn with(kind: Kind, coords: impl IntoIterator<Item = S>) -> Self {
        Answer {
            kind,
            coords: coords.into_iter().collect(),
        }
    }
}

pub fn three_planes<S: Scalar>(r: ThreePlanes<S>) -> Answer<S> {
    match r {
        ThreePlanes::Point { point, .. } => Answer::with(Kind::Point, point.iter().cloned()),
        ThreePlanes::Line { .. } => Answer::kind(Kind::Line),
        ThreePlanes::Plane => Answer::kind(Kind::Plane),
        ThreePlanes::Empty => Answer::kind(Kind::Empty),
    }
}

/// Line ∩ plane, or segment ∩ plane (`segment`: a contained one is a `Segment`).
pub fn line_plane<S: Scalar>(r: LinePlane<S>, segment: bool) -> Answer<S> {
    match r {
        LinePlane::Point(p) => Answer::with(Kind::Point, p.point.iter().cloned()),
        LinePlane::Contained if segment => Answer::kind(Kind::Segment),
        LinePlane::Contained => Answer::kind(Kind::Line),
        LinePlane::Parallel | LinePlane::OutsideDomain(_) => Answer::kind(Kind::Empty),
    }
}

pub fn plane_plane<S: Scalar>(r: PlanePlane<S>) -> Answer<S> {
    match r {
        PlanePlane::Line(_) => Answer::kind(Kind::Line),
        PlanePlane::Parallel => Answer::kind(Kind::Empty),
        PlanePlane::Coincident => Answer::kind(Kind::Plane),
    }
}

/// The foot on an unbounded line (always stationary).
pub fn project_line<S: Scalar, L>(r: LineProjection<S, L>) -> Answer<S> {
    Answer::with(Kind::Point, r.nearest.foot.iter().cloned())
}

pub fn project_plane<S: Scalar, L>(r: PlaneProjection<S, L>) -> Answer<S> {
    Answer::with(Kind::Point, r.foot.iter().cloned())
}

pub fn linear2<S: Scalar>(r: Intersection2<S>) -> Answer<S> {
    match r {
        Intersection2::Point { point, .. } => Answer::with(Kind::Point, point.iter().cloned()),
        Intersection2::Segment { a, b, .. } => {
            Answer::with(Kind::Segment, a.iter().chain(b.iter()).cloned())
        }
        Intersection2::Line => Answer::kind(Kind::Line),
        Intersection2::Empty(Empty2::Parallel | Empty2::CollinearDisjoint) => {
            Answer::kind(Kind::Empty)
        }
        Intersection2::Empty(Empty2::OutsideDomain { .. }) => Answer::kind(Kind::Empty),
    }
}

/// The distance in ulps between two doubles (their positions in the ordered sequence
/// of doubles; `u64::MAX` if either is NaN).
pub fn ulps(a: f64, b: f64) -> u64 {
    if a.is_nan() || b.is_nan() {
        return u64::MAX;
    }
    let ord = |x: f64| {
        let bits = x.to_bits() as i64;
        if bits < 0 {
            i64::MIN - bits
        } else {
            bits
        }
    };
    ord(a).abs_diff(ord(b))
}

/// The truth's coordinates correctly rounded.
pub fn rounded_truth(truth: &Answer<Rational>) -> Vec<Rounded> {
    truth.coords.iter().map(round_rational).collect()
}

/// The possible orders of the coordinates: a segment's end points may come in
/// either order.
fn orders<S: Clone>(kind: Kind, coords: &[S]) -> Vec<Vec<S>> {
    let mut all = vec![coords.to_vec()];
    if kind == Kind::Segment && coords.len().is_multiple_of(2) {
        let h = coords.len() / 2;
        all.push(coords[h..].iter().chain(&coords[..h]).cloned().collect());
    }
    all
}

/// How a float answer compares with the truth.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Grade {
    Right,
    /// The right kind, a coordinate more than one ulp from the correctly rounded truth.
    Off,
    WrongKind,
}

/// Grade a float answer against the truth (rounded coordinates `truth_r`).
pub fn grade(answer: &Answer<f64>, truth: &Answer<Rational>, truth_r: &[Rounded]) -> Grade {
    if answer.kind != truth.kind {
        return Grade::WrongKind;
    }
    if answer.coords.len() != truth_r.len() {
        return Grade::Off;
    }
    let close = orders(answer.kind, &answer.coords).iter().any(|xs| {
        xs.iter()
            .zip(truth_r)
            .all(|(x, t)| ulps(*x, t.nearest) <= 1)
    });
    if close {
        Grade::Right
    } else {
        Grade::Off
    }
}

/// Grade a certified answer: right only when its kind is the truth's and every
/// coordinate is exactly the correct rounding (nearest double and enclosure).
pub fn grade_certified(
    answer: &Answer<Rounded>,
    truth: &Answer<Rational>,
    truth_r: &[Rounded],
) -> Grade {
    if answer.kind != truth.kind {
        return Grade::WrongKind;
    }
    let exact = orders(answer.kind, &answer.coords)
        .iter()
        .any(|xs| xs.as_slice() == truth_r);
    if exact {
        Grade::Right
    } else {
        Grade::Off
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::num::round::next_up;

    #[test]
    fn ulp_distance() {
        assert_eq!(ulps(1.0, 1.0), 0);
        assert_eq!(ulps(1.0, next_up(1.0)), 1);
        assert_eq!(ulps(-0.0, 0.0), 0);
        assert_eq!(ulps(f64::from_bits(1), -f64::from_bits(1)), 2);
        assert_eq!(ulps(1.0, f64::NAN), u64::MAX);
        assert_eq!(ulps(f64::MAX, f64::INFINITY), 1);
    }

    #[test]
    fn segments_match_in_either_order() {
        let truth = Answer::with(Kind::Segment, [0, 1, 2, 3].map(Rational::from));
        let t = rounded_truth(&truth);
        let swapped = Answer::with(Kind::Segment, [2.0, 3.0, 0.0, 1.0]);
        assert_eq!(grade(&swapped, &truth, &t), Grade::Right);
        let off = Answer::with(Kind::Segment, [2.0, 3.0, 0.0, next_up(next_up(1.0))]);
        assert_eq!(grade(&off, &truth, &t), Grade::Off);
        assert_eq!(
            grade(&Answer::kind(Kind::Empty), &truth, &t),
            Grade::WrongKind
        );
    }
}
