//! Three planes (OPERATIONS.md §7.1): geocert against CGAL's Epeck on every generator
//! of `geocert::robust` (generic, grid, degenerate, one-ulp, mixed magnitudes). The
//! kinds must agree; points must be equal rationals; lines and planes equal as sets
//! (their representatives differ); certified coordinates must be exactly the correct
//! rounding of the agreed exact values.
#![cfg(feature = "cgal")]

mod diff_support;

use diff_support::*;
use geocert::geom::three_planes::{
    intersect_three_planes, intersect_three_planes_exact, ThreePlanes,
};
use geocert::num::round::round_rational_scaled;
use geocert::oracle::{epeck, Intersection};
use geocert::robust::case::{q, same, PlaneIn};
use geocert::robust::{Case, Construction};
use rug::Rational;

fn check(c: &Case) -> Result<(), String> {
    let Case::ThreePlanes(ps) = c else {
        return Err("not a three-plane case".into());
    };
    let f = ps.map(|p| p.object(same).expect("generated planes are valid"));
    let e = ps.map(|p| p.object(q).expect("generated planes are valid"));
    let exact = intersect_three_planes_exact(&e);
    let cert = intersect_three_planes(&f);
    certified_exact(&cert)?;
    let truth = epeck::intersect_three_planes(&ps[0].oracle(), &ps[1].oracle(), &ps[2].oracle())
        .map_err(|e| format!("Epeck refused: {e}"))?;
    match (&exact, &truth, &cert.value) {
        (
            ThreePlanes::Point { point, params },
            Intersection::Point(p),
            ThreePlanes::Point {
                point: rp,
                params: rparams,
            },
        ) => {
            ensure!(
                point.as_slice() == p.as_slice(),
                "point {point:?} but Epeck {p:?}"
            );
            ensure!(
                rounds_all(p.iter(), rp.iter()),
                "certified {rp:?} is not the rounding of {p:?}"
            );
            for (k, (pl, (uv, ruv))) in ps.iter().zip(params.iter().zip(rparams)).enumerate() {
                let PlaneIn::Parametric { origin, u, v } = pl else {
                    ensure!(
                        uv.is_none() && ruv.is_none(),
                        "parameters on implicit plane {k}"
                    );
                    continue;
                };
                let (Some(uv), Some(ruv)) = (uv, ruv) else {
                    return Err(format!("no parameters on parametric plane {k}"));
                };
                // origin + s·u + t·v is Epeck's point, exactly.
                let (o, u, v) = (q3(origin), q3(u), q3(v));
                let at: Vec<Rational> = (0..3)
                    .map(|i| {
                        o[i].clone()
                            + Rational::from(&uv[0] * &u[i])
                            + Rational::from(&uv[1] * &v[i])
                    })
                    .collect();
                ensure!(
                    at == p.to_vec(),
                    "parameters {uv:?} on plane {k} miss the point"
                );
                ensure!(
                    rounds_all(uv.iter(), ruv.iter()),
                    "certified parameters {ruv:?} vs {uv:?}"
                );
            }
        }
        (
            ThreePlanes::Line { line, pair },
            Intersection::Line { point, direction },
            ThreePlanes::Line {
                line: rl,
                pair: rpair,
            },
        ) => {
            ensure!(
                same_line(line.point.as_slice(), line.dir.as_slice(), point, direction),
                "line {line:?} but Epeck {point:?} + t {direction:?}"
            );
            for p in ps {
                ensure!(on_plane(point, p), "Epeck's line point is off a plane");
            }
            ensure!(pair == rpair, "certified pair {rpair:?} vs exact {pair:?}");
            ensure!(
                rounds_all(line.point.iter(), rl.point.iter()),
                "certified line point {:?}",
                rl.point
            );
            let k = rl.dir_exponent;
            ensure!(
                line.dir
                    .iter()
                    .zip(rl.dir.iter())
                    .all(|(x, r)| round_rational_scaled(x, k) == *r),
                "certified direction {:?} (2^{k}) vs {:?}",
                rl.dir,
                line.dir
            );
        }
        (ThreePlanes::Plane, Intersection::Plane(coeffs), ThreePlanes::Plane) => {
            ensure!(
                ps.iter().all(|p| same_plane(coeffs, p)),
                "Epeck's plane {coeffs:?} is not every input plane"
            );
        }
        (ThreePlanes::Empty, Intersection::Empty, ThreePlanes::Empty) => {}
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
fn three_planes_agree_with_epeck() {
    run(Construction::ThreePlanes, check);
}
