//! The batch entry points (`*_batch`: lane groups of cases through the lane filter)
//! answer every case exactly as the scalar entry point does — verdict,
//! correctly rounded values, enclosures, arithmetic tier — on every generator of
//! `geocert::robust` interleaved (so that lanes mix shapes, and decided lanes sit next
//! to lanes that fall through to the exact tiers), in input order, appended after what
//! `out` already holds.

use geocert::geom::line_plane::{
    intersect_line_plane, intersect_line_plane_batch, LinePlane, LinePlaneCase,
};
use geocert::geom::plane_plane::{
    intersect_plane_plane, intersect_plane_plane_batch, PlanePlaneCase,
};
use geocert::geom::three_planes::{intersect_three_planes, intersect_three_planes_batch};
use geocert::geom::{Line, Linear, Plane};
use geocert::robust::case::{same, LinearIn, LinearObj};
use geocert::robust::{case, Case, Construction, Generator};
use geocert::Arithmetic;

/// `n` cases per generator, interleaved generator by generator.
fn cases(c: Construction, n: u64) -> Vec<Case> {
    (0..n)
        .flat_map(|i| Generator::ALL.map(|g| case(c, g, 0xBA7C_0000 + i)))
        .collect()
}

#[test]
fn three_planes_batch_equals_scalar() {
    let triples: Vec<[Plane<f64>; 3]> = cases(Construction::ThreePlanes, 1500)
        .iter()
        .map(|c| {
            let Case::ThreePlanes(p) = c else {
                unreachable!()
            };
            p.map(|q| q.object(same).expect("valid"))
        })
        .collect();
    // What `out` already holds stays in front.
    let mut out = vec![intersect_three_planes(&triples[0])];
    intersect_three_planes_batch(&triples, &mut out);
    assert_eq!(out.len(), triples.len() + 1);
    let mut filter = 0;
    for (i, (p, got)) in triples.iter().zip(&out[1..]).enumerate() {
        let want = intersect_three_planes(p);
        assert_eq!(got, &want, "case {i}: {p:?}");
        filter += usize::from(want.arithmetic == Arithmetic::Filter);
    }
    // Not vacuous: the generic fifth (at least) went through the filter.
    assert!(filter >= 1500, "{filter}");
}

#[test]
fn line_plane_batch_equals_scalar() {
    let mut objs: Vec<(LinearObj<f64>, Plane<f64>)> = Vec::new();
    for (k, c) in cases(Construction::LinePlane, 1500).iter().enumerate() {
        let Case::LinePlane(l, p) = c else {
            unreachable!()
        };
        let mut lo = l.object(same).expect("valid");
        // Every third line gets a range, so that some answers are outside the domain.
        if let (LinearIn::Line { origin, dir }, 0) = (l, k % 3) {
            let v = |a: [f64; 3]| nalgebra::Vector3::from(a);
            lo = LinearObj::Line(
                Line::with_range(v(*origin), v(*dir), Some([-0.5, 0.25])).expect("valid"),
            );
        }
        objs.push((lo, p.object(same).expect("valid")));
    }
    let batch: Vec<LinePlaneCase> = objs.iter().map(|(l, p)| (l.linear(), p)).collect();
    let mut out = Vec::new();
    intersect_line_plane_batch(&batch, &mut out);
    assert_eq!(out.len(), batch.len());
    let (mut filter, mut outside) = (0, 0);
    for (i, (&(l, p), got)) in batch.iter().zip(&out).enumerate() {
        let want = intersect_line_plane(l, p);
        assert_eq!(got, &want, "case {i}: {l:?} {p:?}");
        filter += usize::from(want.arithmetic == Arithmetic::Filter);
        outside += usize::from(matches!(
            (want.arithmetic, &want.value),
            (Arithmetic::Filter, LinePlane::OutsideDomain(_))
        ));
    }
    assert!(filter >= 1500, "{filter}");
    assert!(outside >= 100, "{outside}");
}

#[test]
fn plane_plane_batch_equals_scalar() {
    let pairs: Vec<(Plane<f64>, Plane<f64>)> = cases(Construction::PlanePlane, 1500)
        .iter()
        .map(|c| {
            let Case::PlanePlane(a, b) = c else {
                unreachable!()
            };
            (
                a.object(same).expect("valid"),
                b.object(same).expect("valid"),
            )
        })
        .collect();
    let batch: Vec<PlanePlaneCase> = pairs.iter().map(|(a, b)| (a, b)).collect();
    let mut out = Vec::new();
    intersect_plane_plane_batch(&batch, &mut out);
    assert_eq!(out.len(), batch.len());
    let mut filter = 0;
    for (i, (&(a, b), got)) in batch.iter().zip(&out).enumerate() {
        let want = intersect_plane_plane(a, b);
        assert_eq!(got, &want, "case {i}: {a:?} {b:?}");
        filter += usize::from(want.arithmetic == Arithmetic::Filter);
    }
    assert!(filter >= 1500, "{filter}");
}

/// `batch` over `cases` in chunks of 13 equals `scalar` case by case: in a chunk the
/// shapes (kinds of planes, lines or segments) rarely fill a lane group alone, so most
/// lane groups pool what is left of several shapes.
fn chunks_equal_scalar<C: std::fmt::Debug, T: PartialEq + std::fmt::Debug>(
    cases: &[C],
    batch: impl Fn(&[C], &mut Vec<T>),
    scalar: impl Fn(&C) -> T,
) {
    let mut out = Vec::new();
    for chunk in cases.chunks(13) {
        out.clear();
        batch(chunk, &mut out);
        assert_eq!(out.len(), chunk.len());
        for (c, got) in chunk.iter().zip(&out) {
            assert_eq!(got, &scalar(c), "{c:?}");
        }
    }
}

#[test]
fn small_batches_pool_shapes() {
    let triples: Vec<[Plane<f64>; 3]> = cases(Construction::ThreePlanes, 300)
        .iter()
        .map(|c| match c {
            Case::ThreePlanes(p) => p.map(|q| q.object(same).expect("valid")),
            _ => unreachable!(),
        })
        .collect();
    chunks_equal_scalar(
        &triples,
        intersect_three_planes_batch,
        intersect_three_planes,
    );
    let pairs: Vec<(Plane<f64>, Plane<f64>)> = cases(Construction::PlanePlane, 300)
        .iter()
        .map(|c| match c {
            Case::PlanePlane(a, b) => (a.object(same).unwrap(), b.object(same).unwrap()),
            _ => unreachable!(),
        })
        .collect();
    let pp: Vec<PlanePlaneCase> = pairs.iter().map(|(a, b)| (a, b)).collect();
    chunks_equal_scalar(&pp, intersect_plane_plane_batch, |&(a, b)| {
        intersect_plane_plane(a, b)
    });
    let objs: Vec<(LinearObj<f64>, Plane<f64>)> = cases(Construction::LinePlane, 300)
        .iter()
        .map(|c| match c {
            Case::LinePlane(l, p) => (l.object(same).unwrap(), p.object(same).unwrap()),
            _ => unreachable!(),
        })
        .collect();
    let lp: Vec<LinePlaneCase> = objs.iter().map(|(l, p)| (l.linear(), p)).collect();
    chunks_equal_scalar(&lp, intersect_line_plane_batch, |&(l, p)| {
        intersect_line_plane(l, p)
    });
}

/// Batches of every length up to 20 of one shape (full lane groups of 4 or 8, and
/// every size of what is left over: case by case, or a lane group padded with copies)
/// answer as the scalar path does, generic lanes and an undecided one mixed.
#[test]
fn every_batch_length() {
    let mut planes: Vec<[Plane<f64>; 3]> = (0..20)
        .map(|i| {
            let c = Case::ThreePlanes(
                match case(Construction::ThreePlanes, Generator::Generic, i) {
                    Case::ThreePlanes(p) => p.map(|mut q| {
                        // one shape for all: parametric planes only
                        if let geocert::robust::case::PlaneIn::Implicit { normal, d } = q {
                            q = geocert::robust::case::PlaneIn::Parametric {
                                origin: [d, 0.5, 0.25],
                                u: [normal[1], -normal[0], 0.0],
                                v: [0.0, normal[2], -normal[1]],
                            };
                        }
                        q
                    }),
                    _ => unreachable!(),
                },
            );
            let Case::ThreePlanes(p) = c else {
                unreachable!()
            };
            p.map(|q| q.object(same).expect("valid"))
        })
        .collect();
    // Case 5: two coincident planes (D = 0 exactly), which the filter leaves undecided.
    planes[5][2] = planes[5][0].clone();
    assert_ne!(
        intersect_three_planes(&planes[5]).arithmetic,
        Arithmetic::Filter
    );
    for n in 0..=planes.len() {
        let mut out = Vec::new();
        intersect_three_planes_batch(&planes[..n], &mut out);
        let want: Vec<_> = planes[..n].iter().map(intersect_three_planes).collect();
        assert_eq!(out, want, "length {n}");
    }
}

/// An empty batch appends nothing; a batch of one (no full lane group) is the scalar
/// answer.
#[test]
fn small_batches() {
    let p = Plane::implicit([1.0, 2.0, 3.0].into(), 4.0).unwrap();
    let l = Line::new([0.5, 0.0, 0.0].into(), [1.0, 1.0, 1.0].into()).unwrap();
    let mut out = Vec::new();
    intersect_line_plane_batch(&[], &mut out);
    assert!(out.is_empty());
    intersect_line_plane_batch(&[(Linear::Line(&l), &p)], &mut out);
    assert_eq!(out, vec![intersect_line_plane(Linear::Line(&l), &p)]);
}
