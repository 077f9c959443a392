//! Line ∩ line in space (geom::line_line): exact values of every outcome kind, rays
//! and one-sided ranges, ±1 ulp around coplanarity and parallelism, and on every seeded
//! family the certified answer equal to the exact one correctly rounded (status exact,
//! complete), symmetric under swapping the objects.

use geocert::geom::line_line::{
    intersect_line_line, intersect_line_line_exact, intersect_line_line_f64, LineLine,
    LineLineEmpty, LineLinePoint,
};
use geocert::geom::{Line, ParamRange, Segment};
use geocert::num::round::{next_down, next_up, round_rational};
use geocert::robust::case::{q, same, LinearObj};
use geocert::robust::line_line::{case, Family, Shape};
use geocert::{Arithmetic, GeomError, Status};
use nalgebra::{Vector2, Vector3};
use rug::Rational;

type Obj = LinearObj<f64>;

fn line(o: [f64; 3], d: [f64; 3]) -> Obj {
    LinearObj::Line(Line::new(o.into(), d.into()).unwrap())
}
fn ranged(o: [f64; 3], d: [f64; 3], r: ParamRange<f64>) -> Obj {
    LinearObj::Line(Line::with_param_range(o.into(), d.into(), Some(r)).unwrap())
}
fn ray(o: [f64; 3], d: [f64; 3]) -> Obj {
    LinearObj::Line(Line::ray(o.into(), d.into()).unwrap())
}
fn seg(a: [f64; 3], b: [f64; 3]) -> Obj {
    LinearObj::Segment(Segment::new(a.into(), b.into()).unwrap())
}

/// The same object with rational coordinates.
fn exact_of(x: &Obj) -> LinearObj<Rational> {
    let v = |p: &Vector3<f64>| p.map(q);
    match x {
        LinearObj::Line(l) => {
            let r = l.param_range().map(|r| match r {
                ParamRange::Closed([a, b]) => ParamRange::Closed([q(*a), q(*b)]),
                ParamRange::AtLeast(a) => ParamRange::AtLeast(q(*a)),
                ParamRange::AtMost(b) => ParamRange::AtMost(q(*b)),
            });
            LinearObj::Line(Line::with_param_range(v(l.origin()), v(l.dir()), r).unwrap())
        }
        LinearObj::Segment(s) => LinearObj::Segment(Segment::new(v(s.a()), v(s.b())).unwrap()),
    }
}

/// The exact answer, after checking that the certified one is it correctly rounded
/// with an exact, complete certificate.
fn both(a: &Obj, b: &Obj) -> LineLine<Rational> {
    let (ae, be) = (exact_of(a), exact_of(b));
    let x = intersect_line_line_exact(ae.linear(), be.linear());
    let c = intersect_line_line(a.linear(), b.linear());
    assert_eq!(c.status, Status::Exact);
    assert!(c.complete);
    assert_eq!(
        c.value,
        x.clone().map(|v| round_rational(&v)),
        "{a:?} {b:?}"
    );
    x
}

fn r(n: i64, d: i64) -> Rational {
    Rational::from((n, d))
}
fn p3(x: Rational, y: Rational, z: Rational) -> Vector3<Rational> {
    Vector3::new(x, y, z)
}
fn i3(x: i64, y: i64, z: i64) -> Vector3<Rational> {
    p3(Rational::from(x), Rational::from(y), Rational::from(z))
}
fn point(point: Vector3<Rational>, t1: Rational, t2: Rational) -> LineLinePoint<Rational> {
    LineLinePoint { point, t1, t2 }
}

#[test]
fn crossing_lines_meet_at_the_exact_point() {
    // (3t, 0, 0) and (1, 1, 0) + s(0, 3, 0): (1, 0, 0) at t = 1/3, s = −1/3.
    let x = both(
        &line([0.0, 0.0, 0.0], [3.0, 0.0, 0.0]),
        &line([1.0, 1.0, 0.0], [0.0, 3.0, 0.0]),
    );
    assert_eq!(x, LineLine::Point(point(i3(1, 0, 0), r(1, 3), r(-1, 3))));
    // Not at a double: t(1, 1, 1) = (1, 0, 0) + s(−2, 1, 1) where t = s and
    // t = 1 − 2s: t = s = 1/3, at (1/3, 1/3, 1/3).
    let x = both(
        &line([0.0, 0.0, 0.0], [1.0, 1.0, 1.0]),
        &line([1.0, 0.0, 0.0], [-2.0, 1.0, 1.0]),
    );
    assert_eq!(
        x,
        LineLine::Point(point(p3(r(1, 3), r(1, 3), r(1, 3)), r(1, 3), r(1, 3)))
    );
    let c = intersect_line_line(
        line([0.0, 0.0, 0.0], [1.0, 1.0, 1.0]).linear(),
        line([1.0, 0.0, 0.0], [-2.0, 1.0, 1.0]).linear(),
    );
    let LineLine::Point(p) = c.value else {
        panic!("{c:?}")
    };
    assert_eq!(p.point[0].nearest, 1.0 / 3.0);
    assert!(p.point[0].lo < p.point[0].hi);
}

#[test]
fn every_empty_reason() {
    let (o, x) = ([0.0; 3], [1.0, 0.0, 0.0]);
    // skew: the x axis and a line along y at height 1
    let skew = both(&line(o, x), &line([0.0, 0.0, 1.0], [0.0, 1.0, 0.0]));
    assert_eq!(skew, LineLine::Empty(LineLineEmpty::Skew));
    let par = both(&line(o, x), &line([0.0, 1.0, 0.0], [-2.0, 0.0, 0.0]));
    assert_eq!(par, LineLine::Empty(LineLineEmpty::Parallel));
    let apart = both(
        &seg(o, [1.0, 0.0, 0.0]),
        &seg([2.0, 0.0, 0.0], [3.0, 0.0, 0.0]),
    );
    assert_eq!(apart, LineLine::Empty(LineLineEmpty::CollinearDisjoint));
    // the segments' carriers cross at (2, 0, 0), beyond the first segment's end
    let out = both(
        &seg(o, [1.0, 0.0, 0.0]),
        &seg([2.0, -1.0, 0.0], [2.0, 1.0, 0.0]),
    );
    assert_eq!(
        out,
        LineLine::Empty(LineLineEmpty::OutsideDomain(point(
            i3(2, 0, 0),
            r(2, 1),
            r(1, 2)
        )))
    );
    // rays pointing away from each other on one line
    let away = both(&ray(o, [-1.0, 0.0, 0.0]), &ray([1.0, 0.0, 0.0], x));
    assert_eq!(away, LineLine::Empty(LineLineEmpty::CollinearDisjoint));
}

#[test]
fn collinear_overlaps_are_segments_rays_points_or_lines() {
    let (o, x) = ([0.0; 3], [1.0, 0.0, 0.0]);
    // [0, 4] and [3, 1] (reversed): overlap from 1 to 3; params on the second run down.
    let s = both(
        &seg(o, [4.0, 0.0, 0.0]),
        &seg([3.0, 0.0, 0.0], [1.0, 0.0, 0.0]),
    );
    assert_eq!(
        s,
        LineLine::Segment {
            a: i3(1, 0, 0),
            b: i3(3, 0, 0),
            a_params: Vector2::new(r(1, 4), r(1, 1)),
            b_params: Vector2::new(r(3, 4), r(0, 1)),
        }
    );
    // touching end to end
    let t = both(
        &seg(o, [1.0, 0.0, 0.0]),
        &seg([2.0, 0.0, 0.0], [1.0, 0.0, 0.0]),
    );
    assert_eq!(t, LineLine::Point(point(i3(1, 0, 0), r(1, 1), r(1, 1))));
    // a line and a ray on it: the ray; with its direction on both parameters
    let lr = both(&line(o, [-2.0, 0.0, 0.0]), &ray([1.0, 0.0, 0.0], x));
    assert_eq!(
        lr,
        LineLine::Ray {
            a: i3(1, 0, 0),
            a_params: Vector2::new(r(-1, 2), r(0, 1)),
            increasing: [false, true],
        }
    );
    // two rays the same way: the later one
    let rr = both(&ray(o, x), &ray([5.0, 0.0, 0.0], [3.0, 0.0, 0.0]));
    assert!(matches!(&rr, LineLine::Ray { a, increasing: [true, true], .. } if *a == i3(5, 0, 0)));
    // opposite rays overlapping, touching
    let seg_rr = both(&ray(o, x), &ray([5.0, 0.0, 0.0], [-1.0, 0.0, 0.0]));
    assert!(matches!(seg_rr, LineLine::Segment { .. }));
    let touch = both(&ray(o, x), &ray([0.0; 3], [-1.0, 0.0, 0.0]));
    assert_eq!(touch, LineLine::Point(point(i3(0, 0, 0), r(0, 1), r(0, 1))));
    // (−∞, 2] on the first line and a segment reaching beyond it
    let at_most = ranged(o, x, ParamRange::AtMost(2.0));
    let s = both(&at_most, &seg([1.0, 0.0, 0.0], [7.0, 0.0, 0.0]));
    assert!(matches!(&s, LineLine::Segment { b, .. } if *b == i3(2, 0, 0)));
    // coincident unbounded lines
    let l = both(&line(o, x), &line([7.0, 0.0, 0.0], [-0.5, 0.0, 0.0]));
    assert_eq!(l, LineLine::Line);
    // a ranged line reduced to one point, on another line
    let dot = ranged([1.0, 1.0, 1.0], x, ParamRange::Closed([2.0, 2.0]));
    let p = both(&dot, &line([3.0, 0.0, 1.0], [0.0, 1.0, 0.0]));
    assert_eq!(p, LineLine::Point(point(i3(3, 1, 1), r(2, 1), r(1, 1))));
}

/// Segments meeting at an end point (a T and an L): `t = 0` or `1` exactly, `Point`.
#[test]
fn segments_touching_at_ends() {
    let t = both(
        &seg([0.0, 0.0, 0.0], [2.0, 0.0, 0.0]),
        &seg([1.0, 0.0, 0.0], [1.0, 5.0, 3.0]),
    );
    assert_eq!(t, LineLine::Point(point(i3(1, 0, 0), r(1, 2), r(0, 1))));
    let l = both(
        &seg([0.0, 0.0, 0.0], [2.0, 0.0, 0.0]),
        &seg([1.0, 5.0, 3.0], [2.0, 0.0, 0.0]),
    );
    assert_eq!(l, LineLine::Point(point(i3(2, 0, 0), r(1, 1), r(1, 1))));
}

/// ±1 ulp around coplanarity: generic lines crossing in the plane `z = z₀` (a
/// Point), then the first origin moved one ulp up or down in `z` (two parallel planes)
/// or the second direction tilted from `z = 0` to `±2⁻¹⁰⁷⁴`: skew, exactly, for every
/// move.
#[test]
fn one_ulp_off_coplanar_is_skew() {
    let mut rng = geocert::robust::rng::Rng::new(7);
    for k in 0..400 {
        let z0 = [1.0, -1.0, 1e-300, 3.7e5][k % 4];
        let mut v = |z: f64| [rng.generic(), rng.generic(), z];
        let (o1, d1, o2, d2) = (v(z0), v(0.0), v(z0), v(0.0));
        let x = both(&line(o1, d1), &line(o2, d2));
        assert!(matches!(x, LineLine::Point(_)), "{k}: {x:?}");
        for up in [true, false] {
            let step = |x: f64| if up { next_up(x) } else { next_down(x) };
            let lifted = both(&line([o1[0], o1[1], step(z0)], d1), &line(o2, d2));
            assert_eq!(lifted, LineLine::Empty(LineLineEmpty::Skew), "{k}");
            let tilted = both(&line(o1, d1), &line(o2, [d2[0], d2[1], step(0.0)]));
            assert_eq!(tilted, LineLine::Empty(LineLineEmpty::Skew), "{k}");
        }
    }
}

/// ±1 ulp around parallelism: coplanar lines with `d₂ = 2d₁` (parallel, or collinear),
/// then one direction coordinate moved one ulp (they cross, far away, at a point the
/// certified path rounds correctly).
#[test]
fn one_ulp_off_parallel_crosses() {
    let mut rng = geocert::robust::rng::Rng::new(11);
    for k in 0..400 {
        let d1 = [rng.generic(), rng.generic(), 0.0];
        let o1 = [rng.generic(), rng.generic(), rng.generic()];
        let off = if k % 2 == 0 { 0.0 } else { 0.5 };
        let o2 = [o1[0] + off, o1[1], o1[2]];
        let d2 = [2.0 * d1[0], 2.0 * d1[1], 0.0];
        let x = both(&line(o1, d1), &line(o2, d2));
        let expected = if off == 0.0 {
            LineLine::Line
        } else {
            LineLine::Empty(LineLineEmpty::Parallel)
        };
        // off along x may be along d₁ only if d₁ ∥ x, which generic data never is
        assert_eq!(x, expected, "{k}");
        for moved in [next_up(d2[0]), next_down(d2[0])] {
            let y = both(&line(o1, d1), &line(o2, [moved, d2[1], 0.0]));
            assert!(matches!(y, LineLine::Point(_)), "{k}: {y:?}");
        }
    }
}

/// On every family, the certified answer is the exact one correctly rounded (checked
/// in `both`), and swapping the objects swaps the parameters.
#[test]
fn certified_is_exact_rounded_on_every_family() {
    for family in Family::ALL {
        for seed in 0..1500 {
            let c = case(family, seed);
            let (a, b) = (c.a.object(same).unwrap(), c.b.object(same).unwrap());
            let x = both(&a, &b);
            let y = both(&b, &a);
            let swapped = |p: &LineLinePoint<Rational>| LineLinePoint {
                point: p.point.clone(),
                t1: p.t2.clone(),
                t2: p.t1.clone(),
            };
            match (&x, &y) {
                (LineLine::Point(p), LineLine::Point(s)) => assert_eq!(swapped(p), *s),
                (
                    LineLine::Empty(LineLineEmpty::OutsideDomain(p)),
                    LineLine::Empty(LineLineEmpty::OutsideDomain(s)),
                ) => assert_eq!(swapped(p), *s),
                (LineLine::Segment { a, b, .. }, LineLine::Segment { a: c, b: d, .. }) => {
                    assert!((a, b) == (c, d) || (a, b) == (d, c))
                }
                (LineLine::Ray { a, .. }, LineLine::Ray { a: c, .. }) => assert_eq!(a, c),
                _ => assert_eq!(x.kind(), y.kind(), "{family:?} {seed}: {x:?} vs {y:?}"),
            }
        }
    }
}

/// The tier that decides: the filter on generic (skew) input; exact integers, not
/// rationals, for the coplanarity of crossings and for the degenerate families of
/// short data (unscaled); the filter never runs out of range silently (huge input is
/// still exact).
#[test]
fn tiers_are_the_cheap_ones_where_they_can_be() {
    for seed in 0..300 {
        let c = case(Family::Generic, seed);
        let (a, b) = (c.a.object(same).unwrap(), c.b.object(same).unwrap());
        let r = intersect_line_line(a.linear(), b.linear());
        assert_eq!(r.arithmetic, Arithmetic::Filter, "{seed}");
        for family in [Family::Crossing, Family::Parallel, Family::Collinear] {
            let c = case(family, seed);
            let (a, b) = (c.a.object(same).unwrap(), c.b.object(same).unwrap());
            let r = intersect_line_line(a.linear(), b.linear());
            assert!(
                matches!(r.arithmetic, Arithmetic::Integer | Arithmetic::Filter),
                "{family:?} {seed}: {:?}",
                r.arithmetic
            );
        }
    }
}

/// Plain f64 on small integers (every product exact) gives the exact answer.
#[test]
fn f64_on_small_integers() {
    let a = line([0.0, 0.0, 0.0], [3.0, 0.0, 0.0]);
    let b = line([1.0, 1.0, 0.0], [0.0, 3.0, 0.0]);
    let LineLine::Point(p) = intersect_line_line_f64(a.linear(), b.linear()) else {
        panic!()
    };
    assert_eq!(p.point, Vector3::new(1.0, 0.0, 0.0));
    assert_eq!((p.t1, p.t2), (1.0 / 3.0, -1.0 / 3.0));
}

/// One-sided ranges: constructors, accessors and errors naming the field.
#[test]
fn rays_as_one_sided_ranges() {
    let o = Vector3::new(1.0, 2.0, 3.0);
    let d = Vector3::new(0.0, 0.0, 1.0);
    let ray = Line::ray(o, d).unwrap();
    assert!(ray.is_ray());
    assert_eq!(ray.param_range(), Some(&ParamRange::AtLeast(0.0)));
    assert_eq!(ray.bounds(), (Some(&0.0), None));
    assert_eq!(ray.range(), None);
    let back = Line::with_param_range(o, d, Some(ParamRange::AtMost(-2.0))).unwrap();
    assert_eq!(back.bounds(), (None, Some(&-2.0)));
    let closed = Line::with_range(o, d, Some([1.0, 2.0])).unwrap();
    assert!(!closed.is_ray());
    assert_eq!(closed.range(), Some(&[1.0, 2.0]));
    assert_eq!(closed.param_range(), Some(&ParamRange::Closed([1.0, 2.0])));
    let err = Line::with_param_range(o, d, Some(ParamRange::AtMost(f64::INFINITY)));
    assert!(matches!(err, Err(GeomError::NonFinite { field, .. }) if field == "range[1]"));
    let err = Line::with_param_range(o, d, Some(ParamRange::AtLeast(f64::NAN)));
    assert!(matches!(err, Err(GeomError::NonFinite { field, .. }) if field == "range[0]"));
    let err = Line::with_param_range(o, d, Some(ParamRange::Closed([2.0, 1.0])));
    assert!(matches!(err, Err(GeomError::EmptyDomain { field, .. }) if field == "range"));
    let err = Line::ray(o, Vector3::zeros());
    assert!(matches!(err, Err(GeomError::ZeroDirection { field }) if field == "dir"));
    let exact = Line::<Rational>::ray(o.map(q), d.map(q)).unwrap();
    assert_eq!(exact.bounds(), (Some(&Rational::new()), None));
}

/// Huge and tiny magnitudes: an exact crossing configuration scaled by `2^±490` keeps
/// its parameters and scales its point (the filter is out of range: exact tiers).
#[test]
fn scaled_configurations_keep_their_answers() {
    for seed in 0..200 {
        let c = case(Family::Crossing, seed);
        let (a, b) = (c.a.object(same).unwrap(), c.b.object(same).unwrap());
        let x = both(&a, &b);
        for k in [490, -490] {
            let s = 2f64.powi(k);
            let scale = |sh: Shape| match sh {
                Shape::Line { origin, dir, range } => Shape::Line {
                    origin: origin.map(|v| v * s),
                    dir: dir.map(|v| v * s),
                    range,
                },
                Shape::Segment { a, b } => Shape::Segment {
                    a: a.map(|v| v * s),
                    b: b.map(|v| v * s),
                },
            };
            let (sa, sb) = (
                scale(c.a).object(same).unwrap(),
                scale(c.b).object(same).unwrap(),
            );
            let y = both(&sa, &sb);
            let factor = q(s);
            let expected = x.clone();
            match (expected, y) {
                (LineLine::Point(p), LineLine::Point(t)) => {
                    assert_eq!(p.point.map(|v| v * &factor), t.point);
                    assert_eq!((p.t1, p.t2), (t.t1, t.t2));
                }
                (e, y) => assert_eq!(e.kind(), y.kind()),
            }
        }
    }
}

/// Segments of a mesh sharing a vertex (full 53-bit coordinates): the vertex, at
/// parameters exactly 0 or 1 — outputs that are doubles, which the filter leaves to
/// the exact tiers.
#[test]
fn segments_sharing_a_vertex() {
    let mut rng = geocert::robust::rng::Rng::new(5);
    for k in 0..300 {
        let mut v = || [rng.generic(), rng.generic(), rng.generic()];
        let (p, a, b) = (v(), v(), v());
        let vertex = || Vector3::from(p).map(q);
        let cases = [
            (seg(p, a), seg(p, b), (0, 0)),
            (seg(p, a), seg(b, p), (0, 1)),
            (seg(a, p), seg(b, p), (1, 1)),
        ];
        for (s1, s2, (t1, t2)) in cases {
            let x = both(&s1, &s2);
            let expected = point(vertex(), Rational::from(t1), Rational::from(t2));
            assert_eq!(x, LineLine::Point(expected), "{k}");
            let c = intersect_line_line(s1.linear(), s2.linear());
            let LineLine::Point(r) = c.value else {
                panic!()
            };
            assert!(r.point.iter().chain([&r.t1, &r.t2]).all(|x| x.is_exact()));
        }
    }
}
