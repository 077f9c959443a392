//! Line ∩ plane and segment ∩ plane (OPERATIONS.md §5.1) against CGAL's Epeck on every
//! generator: kinds agree, points are equal rationals, a contained line or segment is
//! the input itself, certified coordinates are the correct rounding of Epeck's.
#![cfg(feature = "cgal")]

mod diff_support;

use diff_support::*;
use geocert::geom::line_plane::{intersect_line_plane, intersect_line_plane_exact, LinePlane};
use geocert::oracle::{epeck, Intersection};
use geocert::robust::case::{line, q, same, segment, LinearIn};
use geocert::robust::{Case, Construction};
use rug::Rational;

fn check(c: &Case) -> Result<(), String> {
    let Case::LinePlane(l, p) = c else {
        return Err("not a line-plane case".into());
    };
    let (lf, le) = (l.object(same).expect("valid"), l.object(q).expect("valid"));
    let (pf, pe) = (p.object(same).expect("valid"), p.object(q).expect("valid"));
    let exact = intersect_line_plane_exact(le.linear(), &pe);
    let cert = intersect_line_plane(lf.linear(), &pf);
    certified_exact(&cert)?;
    let truth = match l {
        LinearIn::Line { origin, dir } => {
            epeck::intersect_line_plane(&line(*origin, *dir), &p.oracle())
        }
        LinearIn::Segment { a, b } => epeck::intersect_segment_plane(&segment(*a, *b), &p.oracle()),
    }
    .map_err(|e| format!("Epeck refused: {e}"))?;
    match (&exact, &truth, &cert.value) {
        (LinePlane::Point(x), Intersection::Point(pt), LinePlane::Point(r)) => {
            ensure!(
                x.point.as_slice() == pt.as_slice(),
                "point {:?} but Epeck {pt:?}",
                x.point
            );
            ensure!(
                rounds_all(pt.iter(), r.point.iter()),
                "certified {:?} vs {pt:?}",
                r.point
            );
            // t reproduces Epeck's point exactly: o + t d, or (1 − t) a + t b.
            let (o, d) = match l {
                LinearIn::Line { origin, dir } => (q3(origin), q3(dir)),
                LinearIn::Segment { a, b } => (q3(a), q3(b)),
            };
            let on_line: Vec<Rational> = match l {
                LinearIn::Line { .. } => (0..3)
                    .map(|i| o[i].clone() + Rational::from(&x.t * &d[i]))
                    .collect(),
                LinearIn::Segment { .. } => {
                    let one_minus_t = Rational::from(1 - &x.t);
                    (0..3)
                        .map(|i| {
                            Rational::from(&one_minus_t * &o[i]) + Rational::from(&x.t * &d[i])
                        })
                        .collect()
                }
            };
            ensure!(on_line == pt.to_vec(), "t = {} misses the point", x.t);
            ensure!(
                rounds_all([&x.t], [&r.t]),
                "certified t {:?} vs {}",
                r.t,
                x.t
            );
            match (&x.uv, &r.uv) {
                (Some(uv), Some(ruv)) => {
                    ensure!(
                        rounds_all(uv.iter(), ruv.iter()),
                        "certified uv {ruv:?} vs {uv:?}"
                    )
                }
                (None, None) => {}
                _ => return Err("parameters present in one answer only".into()),
            }
        }
        (LinePlane::Contained, Intersection::Line { point, direction }, LinePlane::Contained) => {
            let LinearIn::Line { origin, dir } = l else {
                return Err("a segment answered as a line".into());
            };
            ensure!(
                same_line(&q3(origin), &q3(dir), point, direction),
                "Epeck's line is not the input"
            );
            ensure!(on_plane(point, p), "Epeck's line point is off the plane");
        }
        (LinePlane::Contained, Intersection::Segment { source, target }, LinePlane::Contained) => {
            let LinearIn::Segment { a, b } = l else {
                return Err("a line answered as a segment".into());
            };
            let (a, b) = (q3(a).to_vec(), q3(b).to_vec());
            let (s, t) = (source.to_vec(), target.to_vec());
            ensure!(
                (s == a && t == b) || (s == b && t == a),
                "Epeck's segment is not the input"
            );
        }
        (LinePlane::Parallel, Intersection::Empty, LinePlane::Parallel) => {}
        (LinePlane::OutsideDomain(x), Intersection::Empty, LinePlane::OutsideDomain(r)) => {
            ensure!(
                matches!(l, LinearIn::Segment { .. }),
                "a line missed the plane outside its domain"
            );
            ensure!(
                rounds_all(x.point.iter(), r.point.iter()),
                "certified carrier point {:?}",
                r.point
            );
            ensure!(
                on_plane(x.point.as_slice(), p),
                "the carrier point is off the plane"
            );
        }
        _ => {
            return Err(format!(
                "kinds differ: geocert exact {exact:?}, certified {:?}, Epeck {} ({truth:?})",
                cert.value,
                kind(&truth)
            ))
        }
    }
    Ok(())
}

#[test]
fn line_and_segment_plane_agree_with_epeck() {
    run(Construction::LinePlane, check);
}
