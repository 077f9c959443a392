//! The CGAL oracle against exact facts known independently (OPERATIONS.md §16 and
//! hand computation), checked as equalities of rationals.
#![cfg(feature = "cgal")]

mod oracle_support;

use geocert::oracle::{
    epeck, epick, Intersection, Line2Input, LineInput, OracleError, PlaneInput, Segment2Input,
    SegmentInput,
};
use geocert::GeomError;
use oracle_support::*;
use rug::Rational;

/// OPERATIONS.md §16.7.
fn planes_16_7() -> [PlaneInput; 3] {
    [
        parametric([0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 1.0]),
        parametric([1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]),
        parametric([0.0, 0.0, 2.0], [1.0, 0.0, 0.0], [1.0, 1.0, 0.0]),
    ]
}

#[test]
fn three_planes_of_16_7_meet_at_1_2_2() {
    let [r, s, q] = planes_16_7();
    assert_eq!(
        epeck::intersect_three_planes(&r, &s, &q).unwrap(),
        Intersection::Point(ints3([1, 2, 2]))
    );
    match epick::intersect_three_planes(&r, &s, &q).unwrap() {
        Intersection::Point(p) => assert!(close(&p, &[1.0, 2.0, 2.0], 1e-15), "{p:?}"),
        other => panic!("Epick: {other:?}"),
    }
}

/// Checks that an Epeck line lies in every plane: its point on each, its direction
/// non-zero and orthogonal to each normal.
fn assert_line_in_planes(result: &Intersection<Rational, 3>, planes: &[PlaneInput]) {
    let Intersection::Line { point, direction } = result else {
        panic!("expected a line, got {result:?}");
    };
    assert!(!is_zero3(direction));
    for p in planes {
        assert!(on_plane(point, p), "{point:?} not on {p:?}");
        assert_eq!(
            dot(&plane_equation(p).0, direction),
            0,
            "direction vs {p:?}"
        );
    }
}

#[test]
fn exactly_dependent_planes_meet_in_a_line() {
    // Implicit: the third plane is the sum of the first two.
    let implicit_triple = [
        implicit(1.0, 1.0, 1.0, -1.0),
        implicit(1.0, -1.0, 0.0, 0.0),
        implicit(2.0, 0.0, 1.0, -1.0),
    ];
    let [a, b, c] = implicit_triple;
    assert_line_in_planes(
        &epeck::intersect_three_planes(&a, &b, &c).unwrap(),
        &implicit_triple,
    );
    // Parametric with non-dyadic-looking data: three planes through the common
    // line origin + t·u, each spanned by u and a different second vector.
    let (origin, u) = ([0.1, -0.7, 0.3], [0.3, 0.11, -0.9]);
    let pencil = [
        parametric(origin, u, [1.0, 0.2, 0.0]),
        parametric(origin, u, [0.0, 0.7, 0.45]),
        parametric(origin, u, [-0.6, 0.0, 1.3]),
    ];
    let [a, b, c] = pencil;
    let line = epeck::intersect_three_planes(&a, &b, &c).unwrap();
    assert_line_in_planes(&line, &pencil);
    let Intersection::Line { direction, .. } = &line else {
        unreachable!()
    };
    assert!(is_zero3(&cross(direction, &q3(u))), "direction ∥ u");
}

#[test]
fn coincident_planes_give_the_plane() {
    // z = 0 three ways.
    let planes = [
        parametric([0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]),
        parametric([1.0, 1.0, 0.0], [2.0, 3.0, 0.0], [-1.0, 5.0, 0.0]),
        implicit(0.0, 0.0, 2.0, 0.0),
    ];
    let [a, b, c] = planes;
    let Intersection::Plane([pa, pb, pc, pd]) = epeck::intersect_three_planes(&a, &b, &c).unwrap()
    else {
        panic!("expected a plane")
    };
    assert!(pa == 0 && pb == 0 && pd == 0 && pc != 0);
    assert!(matches!(
        epeck::intersect_plane_plane(&b, &c).unwrap(),
        Intersection::Plane(_)
    ));
}

#[test]
fn parallel_planes_do_not_meet() {
    let (z0, z1, x0) = (
        implicit(0.0, 0.0, 1.0, 0.0),
        parametric([5.0, -3.0, 1.0], [1.0, 1.0, 0.0], [1.0, -1.0, 0.0]),
        implicit(1.0, 0.0, 0.0, 0.0),
    );
    assert_eq!(
        epeck::intersect_three_planes(&z0, &x0, &z1).unwrap(),
        Intersection::Empty
    );
    assert_eq!(
        epeck::intersect_plane_plane(&z0, &z1).unwrap(),
        Intersection::Empty
    );
    assert_eq!(
        epick::intersect_plane_plane(&z0, &z1).unwrap(),
        Intersection::Empty
    );
}

#[test]
fn plane_plane_of_16_8_is_the_line_through_2_0_0_along_y() {
    let r = parametric([0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]);
    let s = parametric([2.0, 0.0, 0.0], [0.0, 1.0, 0.0], [-1.0, 0.0, 1.0]);
    let Intersection::Line { point, direction } = epeck::intersect_plane_plane(&r, &s).unwrap()
    else {
        panic!("expected a line")
    };
    // (2,0,0) is on the line and the direction is a non-zero multiple of (0,1,0).
    assert!(is_zero3(&cross(
        &sub(&point, &ints3([2, 0, 0])),
        &direction
    )));
    assert!(direction[0] == 0 && direction[2] == 0 && direction[1] != 0);
    let Intersection::Line { point, direction } = epick::intersect_plane_plane(&r, &s).unwrap()
    else {
        panic!("Epick: expected a line")
    };
    assert!(point[0] == 2.0 && point[2] == 0.0 && direction[0] == 0.0 && direction[2] == 0.0);
}

#[test]
fn projection_onto_the_skew_plane_of_16_2() {
    let plane = parametric([1.0, 2.0, 3.0], [2.0, 0.0, 1.0], [1.0, 1.0, 0.0]);
    let p = [4.0, -1.0, 5.0];
    assert_eq!(
        epeck::project_point_plane(&p, &plane).unwrap(),
        [frac(11, 3), frac(-2, 3), frac(17, 3)]
    );
    let f = epick::project_point_plane(&p, &plane).unwrap();
    assert!(
        close(&f, &[11.0 / 3.0, -2.0 / 3.0, 17.0 / 3.0], 1e-15),
        "{f:?}"
    );
}

#[test]
fn projection_onto_a_line() {
    // (p − c0)·c' / |c'|² = −1/5 (OPERATIONS.md (3.1)): (1,0,0) − (1,2,0)/5.
    let line = LineInput {
        point: [1.0, 0.0, 0.0],
        direction: [1.0, 2.0, 0.0],
    };
    assert_eq!(
        epeck::project_point_line(&[0.0, 0.0, 0.0], &line).unwrap(),
        [frac(4, 5), frac(-2, 5), frac(0, 1)]
    );
    let f = epick::project_point_line(&[0.0, 0.0, 0.0], &line).unwrap();
    assert!(close(&f, &[0.8, -0.4, 0.0], 1e-15), "{f:?}");
}

#[test]
fn line_and_segment_against_a_plane() {
    let plane = implicit(1.0, 1.0, 1.0, -3.0); // x + y + z = 3
    let diagonal = LineInput {
        point: [0.0, 0.0, 0.0],
        direction: [1.0, 1.0, 1.0],
    };
    assert_eq!(
        epeck::intersect_line_plane(&diagonal, &plane).unwrap(),
        Intersection::Point(ints3([1, 1, 1]))
    );
    let inside = LineInput {
        point: [3.0, 0.0, 0.0],
        direction: [1.0, -1.0, 0.0],
    };
    let line = epeck::intersect_line_plane(&inside, &plane).unwrap();
    assert_line_in_planes(&line, &[plane]);
    let parallel = LineInput {
        point: [0.0, 0.0, 0.0],
        direction: [1.0, -1.0, 0.0],
    };
    assert_eq!(
        epeck::intersect_line_plane(&parallel, &plane).unwrap(),
        Intersection::Empty
    );

    let z0 = implicit(0.0, 0.0, 1.0, 0.0);
    // (0,0,−1) + t(3,0,3) meets z = 0 at t = 1/3.
    let crossing = SegmentInput {
        source: [0.0, 0.0, -1.0],
        target: [3.0, 0.0, 2.0],
    };
    assert_eq!(
        epeck::intersect_segment_plane(&crossing, &z0).unwrap(),
        Intersection::Point(ints3([1, 0, 0]))
    );
    let short = SegmentInput {
        source: [0.0, 0.0, 1.0],
        target: [3.0, 0.0, 2.0],
    };
    assert_eq!(
        epeck::intersect_segment_plane(&short, &z0).unwrap(),
        Intersection::Empty
    );
    let lying = SegmentInput {
        source: [0.5, 0.25, 0.0],
        target: [-3.0, 7.0, 0.0],
    };
    let Intersection::Segment { source, target } =
        epeck::intersect_segment_plane(&lying, &z0).unwrap()
    else {
        panic!("expected the segment itself")
    };
    let ends = [q3(lying.source), q3(lying.target)];
    assert!([source.clone(), target.clone()] == ends || [target, source] == ends);
}

#[test]
fn two_dimensional_segments() {
    let seg = |s: [f64; 2], t: [f64; 2]| Segment2Input {
        source: s,
        target: t,
    };
    let diagonal = seg([0.0, 0.0], [4.0, 4.0]);
    let q2 = |x: i64, y: i64| [Rational::from(x), Rational::from(y)];
    assert_eq!(
        epeck::intersect_segment2_segment2(&diagonal, &seg([0.0, 4.0], [4.0, 0.0])).unwrap(),
        Intersection::Point(q2(2, 2))
    );
    // Collinear, overlapping on (2,2)–(4,4), in either orientation.
    match epeck::intersect_segment2_segment2(&diagonal, &seg([6.0, 6.0], [2.0, 2.0])).unwrap() {
        Intersection::Segment { source, target } => {
            let ends = [q2(2, 2), q2(4, 4)];
            assert!(
                [source.clone(), target.clone()] == ends || [target, source] == ends,
                "overlap"
            );
        }
        other => panic!("expected the overlap segment, got {other:?}"),
    }
    // Touching at an end point.
    assert_eq!(
        epeck::intersect_segment2_segment2(&diagonal, &seg([4.0, 4.0], [8.0, 0.0])).unwrap(),
        Intersection::Point(q2(4, 4))
    );
    // Collinear, touching end to end.
    assert_eq!(
        epeck::intersect_segment2_segment2(&diagonal, &seg([4.0, 4.0], [5.0, 5.0])).unwrap(),
        Intersection::Point(q2(4, 4))
    );
    // Only the extensions meet.
    assert_eq!(
        epeck::intersect_segment2_segment2(&diagonal, &seg([5.0, 0.0], [9.0, -4.0])).unwrap(),
        Intersection::Empty
    );
    match epick::intersect_segment2_segment2(&diagonal, &seg([0.0, 4.0], [4.0, 0.0])).unwrap() {
        Intersection::Point(p) => assert!(close(&p, &[2.0, 2.0], 1e-15)),
        other => panic!("Epick: {other:?}"),
    }
}

#[test]
fn two_dimensional_lines() {
    let line = |p: [f64; 2], d: [f64; 2]| Line2Input {
        point: p,
        direction: d,
    };
    // t(1,2) = (3,0) + s(−1,1) at t = 1.
    let (a, b) = (line([0.0, 0.0], [1.0, 2.0]), line([3.0, 0.0], [-1.0, 1.0]));
    assert_eq!(
        epeck::intersect_line2_line2(&a, &b).unwrap(),
        Intersection::Point([Rational::from(1), Rational::from(2)])
    );
    assert_eq!(
        epeck::intersect_line2_line2(&a, &line([1.0, 0.0], [-2.0, -4.0])).unwrap(),
        Intersection::Empty
    );
    let Intersection::Line { point, direction } =
        epeck::intersect_line2_line2(&a, &line([2.0, 4.0], [-0.5, -1.0])).unwrap()
    else {
        panic!("equal lines give a line")
    };
    // On y = 2x, direction ∥ (1,2).
    assert_eq!(Rational::from(&point[0] * 2), point[1]);
    assert_eq!(Rational::from(&direction[0] * 2), direction[1]);
    assert!(direction[0] != 0);
}

/// Mixed magnitudes are not bad input: Epeck answers exactly.
#[test]
fn mixed_magnitudes_come_back_exactly() {
    for (tiny, huge) in [(1e-150, 1e150), (1e-300, 1e300)] {
        // x = tiny, y = huge, x + y + z = 0: z = −(tiny + huge) exactly.
        let planes = [
            implicit(1.0, 0.0, 0.0, -tiny),
            implicit(0.0, 1.0, 0.0, -huge),
            implicit(1.0, 1.0, 1.0, 0.0),
        ];
        let [a, b, c] = planes;
        let z = -(q(tiny) + q(huge));
        assert_eq!(
            epeck::intersect_three_planes(&a, &b, &c).unwrap(),
            Intersection::Point([q(tiny), q(huge), z])
        );
        // Tilted planes mixing both scales in one plane: the point is on all three.
        let planes = [
            parametric([tiny, huge, 1.0], [huge, tiny, 0.0], [0.0, 1.0, tiny]),
            parametric([huge, -tiny, tiny], [tiny, 0.0, 1.0], [1.0, huge, 0.0]),
            parametric([0.0, tiny, -huge], [1.0, 1.0, huge], [tiny, -1.0, 0.0]),
        ];
        let [a, b, c] = planes;
        match epeck::intersect_three_planes(&a, &b, &c).unwrap() {
            Intersection::Point(p) => {
                for plane in &planes {
                    assert!(on_plane(&p, plane), "tiny = {tiny:e}");
                }
            }
            other => panic!("tiny = {tiny:e}: {other:?}"),
        }
        let plane = parametric([tiny, huge, 1.0], [huge, tiny, 0.0], [0.0, 1.0, tiny]);
        let foot = epeck::project_point_plane(&[tiny, -huge, huge], &plane).unwrap();
        let (n, _) = plane_equation(&plane);
        assert!(on_plane(&foot, &plane));
        // The foot minus the point is a multiple of the normal.
        assert!(is_zero3(&cross(&sub(&foot, &q3([tiny, -huge, huge])), &n)));
    }
}

#[test]
fn bad_input_comes_back_as_typed_errors() {
    let good = implicit(0.0, 0.0, 1.0, 0.0);
    // u ∥ v exactly: decided by the kernel in C++, thrown, caught by cxx.
    let flat = parametric([1.0, 2.0, 3.0], [0.1, 0.2, 0.3], [0.2, 0.4, 0.6]);
    let expect = OracleError::Input(GeomError::CollinearPlaneVectors { field: "b".into() });
    assert_eq!(
        epeck::intersect_plane_plane(&good, &flat),
        Err(expect.clone())
    );
    assert_eq!(epick::intersect_plane_plane(&good, &flat), Err(expect));
    assert_eq!(
        epeck::intersect_three_planes(&good, &good, &implicit(0.0, 0.0, 0.0, 1.0)),
        Err(OracleError::Input(GeomError::ZeroNormal {
            field: "c".into()
        }))
    );
    let still = LineInput {
        point: [1.0, 2.0, 3.0],
        direction: [0.0, 0.0, 0.0],
    };
    assert_eq!(
        epeck::project_point_line(&[0.0; 3], &still),
        Err(OracleError::Input(GeomError::ZeroDirection {
            field: "line".into()
        }))
    );
    let dot_segment = Segment2Input {
        source: [1.0, 1.0],
        target: [1.0, 1.0],
    };
    assert!(matches!(
        epeck::intersect_segment2_segment2(&dot_segment, &dot_segment),
        Err(OracleError::Input(GeomError::InvalidValue { field, .. })) if field == "a"
    ));
    let nan = parametric([0.0, f64::NAN, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]);
    match epeck::project_point_plane(&[0.0; 3], &nan) {
        Err(OracleError::Input(e)) => {
            assert_eq!((e.kind(), e.field()), ("non_finite", "plane.origin[1]"))
        }
        other => panic!("{other:?}"),
    }
}

/// Epick's overflowing constructions would make GMP raise SIGFPE (an abort); such
/// magnitudes are refused with a typed error naming the field, while Epeck answers.
#[test]
fn epick_refuses_magnitudes_it_would_abort_on() {
    let seg = SegmentInput {
        source: [1e150, -3e150, 2e150],
        target: [-1e150, 2e150, -4e150],
    };
    let plane = PlaneInput::Parametric {
        origin: [1e150, 1e150, 1e150],
        u: [1e150, 0.0, 3e150],
        v: [0.0, 2e150, 1e150],
    };
    match epick::intersect_segment_plane(&seg, &plane) {
        Err(OracleError::Input(e)) => {
            assert_eq!(e.kind(), "unsupported");
            assert_eq!(e.field(), "segment[0]");
        }
        other => panic!("expected a refusal, got {other:?}"),
    }
    let tiny = Line2Input {
        point: [1e-300, 0.0],
        direction: [1.0, 1.0],
    };
    assert!(epick::intersect_line2_line2(&tiny, &tiny).is_err());
    assert!(epeck::intersect_segment_plane(&seg, &plane).is_ok());
}
