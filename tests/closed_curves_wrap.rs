//! A closed curve's parameter is an angle for the certifier (`ops::certified::
//! curve_unknowns`: seam copies are merged, boxes may cross the seam), which is sound
//! only if the curve's jet beyond its domain is the curve itself, wrapped — not the end
//! pieces' continuation. A family of closed polylines and clamped closed NURBS curves
//! (control polygon closed, equal end weights: only C⁰ at the seam) with dyadic
//! parameters, so that `t + kP` is exact: the point at `t + kP` is the point at `t`,
//! and an interval box across the seam encloses the true points on both sides of it.
//! (Soak seed 26 lost a root of a closed NURBS circle near a sphere's pole: a box
//! across the seam was evaluated on the continuation.)

use geocert::curve::{Curve, NurbsCurve, Polyline};
use geocert::num::rng::Rng;
use geocert::num::Interval;

fn check<C: Curve<3>>(name: &str, c: &C, rng: &mut Rng) -> usize {
    assert!(c.is_closed(), "{name}");
    let (lo, hi) = c.domain();
    let period = hi - lo;
    let mut checked = 0;
    for _ in 0..40 {
        // A dyadic t in the domain (1/64 steps).
        let t = lo + (rng.below((period * 64.0) as usize + 1) as f64) / 64.0;
        let at = c.jet(&t, 1)[0];
        for k in [-2.0, -1.0, 1.0, 2.0] {
            let wrapped = c.jet(&(t + k * period), 1)[0];
            assert_eq!(wrapped, at, "{name}: t = {t}, {k} periods");
        }
        // A box across the seam: [hi − δ, hi + δ] holds c(hi − δ/2) and c(lo + δ/2).
        let d = (1 + rng.below(8)) as f64 / 64.0;
        let b = c.jet(&Interval::from_bounds(hi - d, hi + d), 0)[0];
        for s in [hi - d / 2.0, lo + d / 2.0] {
            let p = c.jet(&Interval::point(s), 0)[0];
            for i in 0..3 {
                assert!(
                    !b[i].intersection(&p[i]).is_empty(),
                    "{name}: the box across the seam misses c({s})[{i}]: {:?} vs {:?}",
                    b[i],
                    p[i]
                );
            }
        }
        checked += 1;
    }
    checked
}

fn closed_polygon(rng: &mut Rng, n: usize) -> Vec<[f64; 3]> {
    let mut pts: Vec<[f64; 3]> = (0..n)
        .map(|_| [0; 3].map(|_| rng.int(-9, 9) as f64))
        .collect();
    pts.push(pts[0]);
    pts
}

#[test]
fn closed_curves_wrap_their_parameter() {
    let mut rng = Rng::new(0xc105ed);
    let mut checked = 0;
    for case in 0..30 {
        let n = 3 + rng.below(5);
        let mut pts = closed_polygon(&mut rng, n);
        // Consecutive equal points would make a zero-length segment.
        pts.dedup();
        if pts.len() < 4 {
            continue;
        }
        let params: Vec<f64> = (0..pts.len()).map(|k| k as f64).collect();
        let line = Polyline::new(pts.clone(), Some(params)).unwrap();
        checked += check(&format!("polyline {case}"), &line, &mut rng);
        // The same closed polygon as a clamped NURBS of degree 2 or 3, weights 1..4
        // with equal ends.
        let p = 2 + case % 2;
        if pts.len() <= p {
            continue;
        }
        let m = pts.len();
        let mut knots = vec![0.0; p + 1];
        knots.extend((1..m - p).map(|k| k as f64));
        knots.extend(vec![(m - p) as f64; p + 1]);
        let mut w: Vec<f64> = (0..m).map(|_| (1 + rng.below(4)) as f64).collect();
        w[m - 1] = w[0];
        let nurbs = NurbsCurve::new(p, knots, pts, Some(w), None).unwrap();
        assert!(!nurbs.is_periodic(), "clamped, only C⁰ at the seam");
        checked += check(&format!("nurbs {case}"), &nurbs, &mut rng);
    }
    assert!(checked >= 1600, "{checked}");
}
