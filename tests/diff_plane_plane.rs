//! Plane ∩ plane (OPERATIONS.md §8) against CGAL's Epeck on every generator: kinds
//! agree (line, parallel = empty, coincident = plane), the line equals Epeck's as a
//! set, and the certified point and direction are the correct rounding of the exact
//! line geocert reports (whose point lies on Epeck's line).
#![cfg(feature = "cgal")]

mod diff_support;

use diff_support::*;
use geocert::geom::plane_plane::{intersect_plane_plane, intersect_plane_plane_exact, PlanePlane};
use geocert::num::round::round_rational_scaled;
use geocert::oracle::{epeck, Intersection};
use geocert::robust::case::{q, same};
use geocert::robust::{Case, Construction};

fn check(c: &Case) -> Result<(), String> {
    let Case::PlanePlane(a, b) = c else {
        return Err("not a plane-plane case".into());
    };
    let (af, ae) = (a.object(same).expect("valid"), a.object(q).expect("valid"));
    let (bf, be) = (b.object(same).expect("valid"), b.object(q).expect("valid"));
    let exact = intersect_plane_plane_exact(&ae, &be);
    let cert = intersect_plane_plane(&af, &bf);
    certified_exact(&cert)?;
    let truth = epeck::intersect_plane_plane(&a.oracle(), &b.oracle())
        .map_err(|e| format!("Epeck refused: {e}"))?;
    match (&exact, &truth, &cert.value) {
        (PlanePlane::Line(l), Intersection::Line { point, direction }, PlanePlane::Line(r)) => {
            ensure!(
                same_line(l.point.as_slice(), l.dir.as_slice(), point, direction),
                "line {l:?} but Epeck {point:?} + t {direction:?}"
            );
            ensure!(
                on_plane(point, a) && on_plane(point, b),
                "Epeck's point is off a plane"
            );
            ensure!(
                rounds_all(l.point.iter(), r.point.iter()),
                "certified point {:?}",
                r.point
            );
            let k = r.dir_exponent;
            ensure!(
                l.dir
                    .iter()
                    .zip(r.dir.iter())
                    .all(|(x, y)| round_rational_scaled(x, k) == *y),
                "certified direction {:?} (2^{k}) vs {:?}",
                r.dir,
                l.dir
            );
            for (side, (x, y)) in [(&l.on_a, &r.on_a), (&l.on_b, &r.on_b)]
                .into_iter()
                .enumerate()
            {
                match (x, y) {
                    (Some(x), Some(y)) => ensure!(
                        rounds_all(x.origin.iter(), y.origin.iter())
                            && x.dir
                                .iter()
                                .zip(y.dir.iter())
                                .all(|(p, s)| round_rational_scaled(p, k) == *s),
                        "certified parameter line {side}: {y:?} vs {x:?}"
                    ),
                    (None, None) => {}
                    _ => return Err(format!("parameter line {side} in one answer only")),
                }
            }
        }
        (PlanePlane::Parallel, Intersection::Empty, PlanePlane::Parallel) => {}
        (PlanePlane::Coincident, Intersection::Plane(coeffs), PlanePlane::Coincident) => {
            ensure!(
                same_plane(coeffs, a) && same_plane(coeffs, b),
                "Epeck's plane {coeffs:?} is not both inputs"
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
fn plane_plane_agrees_with_epeck() {
    run(Construction::PlanePlane, check);
}
