//! Point → line and point → plane projections (OPERATIONS.md §3.1, §3.3) against
//! CGAL's Epeck on every generator: equal feet (rationals), certified feet the correct
//! rounding of Epeck's, certified distances the correctly rounded `|p − foot|` computed
//! here from Epeck's foot (signed by the side of the plane's normal).
#![cfg(feature = "cgal")]

mod diff_support;

use diff_support::*;
use geocert::geom::project::{
    project_point_line, project_point_line_exact, project_point_plane, project_point_plane_exact,
};
use geocert::geom::{Line, Linear};
use geocert::num::round::{sqrt_rational, Rounded};
use geocert::oracle::epeck;
use geocert::robust::case::{line, q, same};
use geocert::robust::{Case, Construction};
use nalgebra::Vector3;
use rug::Rational;

/// The correctly rounded `±√(|p − foot|²)` from rationals.
fn distance(p: &[Rational], foot: &[Rational], negative: bool) -> Rounded {
    let w = sub(p, foot);
    let r = sqrt_rational(&dot(&w, &w));
    if negative {
        Rounded {
            nearest: -r.nearest,
            lo: -r.hi,
            hi: -r.lo,
        }
    } else {
        r
    }
}

fn check_line(c: &Case) -> Result<(), String> {
    let Case::ProjectLine(p, o, d) = c else {
        return Err("not a point-line case".into());
    };
    let v = |x: &[f64; 3]| Vector3::from(*x);
    let vq = |x: &[f64; 3]| Vector3::from(q3(x));
    let lf = Line::new(v(o), v(d)).expect("valid");
    let le = Line::new(vq(o), vq(d)).expect("valid");
    let exact = project_point_line_exact(&vq(p), Linear::Line(&le));
    let cert = project_point_line(&v(p), Linear::Line(&lf));
    certified_exact(&cert)?;
    let foot =
        epeck::project_point_line(p, &line(*o, *d)).map_err(|e| format!("Epeck refused: {e}"))?;
    let x = &exact.nearest;
    ensure!(
        x.foot.as_slice() == foot.as_slice(),
        "foot {:?} but Epeck {foot:?}",
        x.foot
    );
    let (Some(s), Some(rs)) = (&exact.stationary, &cert.value.stationary) else {
        return Err("an unbounded line has a stationary foot".into());
    };
    ensure!(s.foot == x.foot, "stationary and nearest feet differ");
    let r = &cert.value.nearest;
    ensure!(
        rounds_all(foot.iter(), r.foot.iter()),
        "certified foot {:?} vs {foot:?}",
        r.foot
    );
    ensure!(rs == r, "certified stationary and nearest differ");
    let dist = distance(&q3(p), &foot, false);
    ensure!(
        r.distance == dist,
        "certified distance {:?}, truth {dist:?}",
        r.distance
    );
    ensure!(
        x.distance.rounded == dist,
        "exact distance {:?}, truth {dist:?}",
        x.distance
    );
    Ok(())
}

fn check_plane(c: &Case) -> Result<(), String> {
    let Case::ProjectPlane(p, pl) = c else {
        return Err("not a point-plane case".into());
    };
    let (pf, pe) = (
        pl.object(same).expect("valid"),
        pl.object(q).expect("valid"),
    );
    let exact = project_point_plane_exact(&Vector3::from(q3(p)), &pe);
    let cert = project_point_plane(&Vector3::from(*p), &pf);
    certified_exact(&cert)?;
    let foot =
        epeck::project_point_plane(p, &pl.oracle()).map_err(|e| format!("Epeck refused: {e}"))?;
    ensure!(
        exact.foot.as_slice() == foot.as_slice(),
        "foot {:?} but Epeck {foot:?}",
        exact.foot
    );
    ensure!(on_plane(&foot, pl), "Epeck's foot is off the plane");
    let r = &cert.value;
    ensure!(
        rounds_all(foot.iter(), r.foot.iter()),
        "certified foot {:?} vs {foot:?}",
        r.foot
    );
    let (n, _) = plane_equation(pl);
    let negative = dot(&n, &sub(&q3(p), &foot)).cmp0().is_lt();
    let dist = distance(&q3(p), &foot, negative);
    ensure!(
        r.distance == dist,
        "certified distance {:?}, truth {dist:?}",
        r.distance
    );
    match (&exact.uv, &r.uv) {
        (Some(uv), Some(ruv)) => ensure!(
            rounds_all(uv.iter(), ruv.iter()),
            "certified uv {ruv:?} vs {uv:?}"
        ),
        (None, None) => {}
        _ => return Err("parameters in one answer only".into()),
    }
    Ok(())
}

#[test]
fn point_line_projection_agrees_with_epeck() {
    run(Construction::ProjectLine, check_line);
}

#[test]
fn point_plane_projection_agrees_with_epeck() {
    run(Construction::ProjectPlane, check_plane);
}
