//! Issue 5: facts that hold exactly for the surface primitives, checked in 200-bit MPFR
//! intervals: the implicit form vanishes on the parametric surface (and its gradient is
//! normal to it); the curvatures of a sphere (`K = 1/r²`, `k₁ = k₂ = −1/r` for the
//! outward normal) and of ring and spindle tori (closed forms); NURBS with Bézier knots
//! and after knot insertion equal the Bézier patch; the frame rule of CASES.md; the §1.3
//! limit normal at a cone apex; the Weingarten derivatives (1.10).

mod surface_support;

use geocert::num::vector::{cross, norm_sq};
use geocert::num::{IntervalLike, MpfrInterval, Real};
use geocert::surface::nurbs::NurbsSurface;
use geocert::surface::quadrics::{Cone, Cylinder, Sphere};
use geocert::surface::torus::Torus;
use geocert::surface::{Implicit, Surface};
use surface_support::{any_surfaces, bezier_rational, random_params, Rng};

const PREC: u32 = 200;

fn m(x: f64) -> MpfrInterval {
    MpfrInterval::point(x, PREC)
}

/// `|a − b| ≤ tol` for an enclosure `a` and an exact real given as an enclosure `b`.
fn close(a: &MpfrInterval, b: &MpfrInterval, tol: f64) -> bool {
    (a.clone() - b.clone()).mag() <= tol
}

#[test]
fn implicit_forms_vanish_on_the_parametric_surfaces() {
    let mut checked = 0;
    for (name, s) in any_surfaces() {
        let Some(f) = s.implicit() else {
            continue;
        };
        let mut rng = Rng(31 + name.len() as u64);
        for _ in 0..50 {
            let (u, v) = random_params(&s, &mut rng);
            let jet = s.jet(&m(u), &m(v), 1);
            let point = jet[0].clone();
            let scale = 1.0 + point.iter().map(|x| x.mag()).fold(0.0, f64::max);
            let imp = f.implicit_jet(&point, 1);
            assert!(
                imp.value.contains_zero(),
                "{name}: F(s) = {:?} excludes 0",
                imp.value
            );
            assert!(
                imp.value.mag() <= 1e-45 * scale.powi(4),
                "{name}: F(s) = {:?}",
                imp.value
            );
            // ∇F is parallel to s_u × s_v.
            let g = imp.gradient.unwrap();
            let n = cross(&jet[1], &jet[2]);
            let c = norm_sq(&cross(&g, &n)).sqrt();
            let size = (norm_sq(&g) * norm_sq(&n)).sqrt();
            assert!(
                c.mag() <= 1e-40 * (1.0 + size.mag()),
                "{name}: ∇F ∦ N at ({u}, {v})"
            );
            checked += 1;
        }
    }
    assert!(checked >= 50 * 11, "{checked}");
}

#[test]
fn implicit_side_convention_positive_outside() {
    for (name, s) in any_surfaces() {
        let Some(f) = s.implicit() else {
            continue;
        };
        let (u, v) = random_params(&s, &mut Rng(5));
        let jet = s.jet(&u, &v, 1);
        let n = cross(&jet[1], &jet[2]);
        let g = f.implicit_jet(&jet[0], 1).gradient.unwrap();
        // F grows along ∇F; the sign of ∇F·N is the orientation of the parametrisation.
        let along: f64 = (0..3).map(|i| g[i] * n[i]).sum();
        assert!(along != 0.0, "{name}");
    }
    let sphere = Sphere::new([1.0, 2.0, 3.0], 2.0, None, None).unwrap();
    assert!(sphere.implicit_jet(&[1.0, 2.0, 3.0], 0).value < 0.0);
    assert!(sphere.implicit_jet(&[1.0, 2.0, 6.0], 0).value > 0.0);
    let torus = Torus::new([0.0; 3], 3.0, 1.0, [0.0, 0.0, 1.0], None).unwrap();
    assert!(torus.implicit_jet(&[0.0, 0.0, 0.0], 0).value > 0.0); // the hole is outside
    assert!(torus.implicit_jet(&[3.0, 0.0, 0.0], 0).value < 0.0); // the tube's core is inside
}

#[test]
fn sphere_curvatures_are_one_over_r_everywhere() {
    let r = 2.5;
    let s = Sphere::new([0.3, -1.0, 2.0], r, Some([1.0, 1.0, 1.0]), None).unwrap();
    let mut rng = Rng(3);
    for _ in 0..200 {
        let (u, v) = random_params(&s, &mut rng);
        let f = s.fundamental_forms(&m(u), &m(v));
        let inv_r = m(1.0) / m(r);
        assert!(close(&f.gaussian_curvature(), &inv_r.sqr(), 1e-50));
        // The normal (1.6) points outward, so the sphere curves away from it: H = −1/r.
        assert!(close(&f.mean_curvature(), &(-inv_r.clone()), 1e-50));
        let (k1, k2) = f.principal_curvatures();
        assert!(close(&k1, &(-inv_r.clone()), 1e-20), "k1 = {k1:?}");
        assert!(close(&k2, &(-inv_r.clone()), 1e-20), "k2 = {k2:?}");
        let kn = f.normal_curvature(&m(rng.unit()), &m(rng.unit() - 0.5));
        assert!(close(&kn, &(-inv_r), 1e-45));
    }
    // f64 at an umbilic: H² − K rounds to either sign; the principal curvatures stay finite.
    let (k1, k2) = s.principal_curvatures(&0.7, &0.3);
    assert!(
        (k1 + 1.0 / r).abs() < 1e-7 && (k2 + 1.0 / r).abs() < 1e-7,
        "{k1} {k2}"
    );
}

#[test]
fn torus_curvatures_follow_the_closed_form() {
    for (big_r, r) in [(3.0, 1.0), (1.0, 2.0), (2.0, 0.25)] {
        let s = Torus::new([1.0, 0.0, -1.0], big_r, r, [0.0, 1.0, 0.0], None).unwrap();
        let mut rng = Rng(17);
        for _ in 0..100 {
            let (u, v) = random_params(&s, &mut rng);
            let f = s.fundamental_forms(&m(u), &m(v));
            let (cv, big, rr) = (m(v).cos(), m(big_r), m(r));
            let ring = big.clone() + rr.clone() * cv.clone();
            // Outward normal: k_meridian = −1/r, k_parallel = −cos v/(R + r cos v).
            let k_meridian = -(m(1.0) / rr.clone());
            let k_parallel = -(cv.clone() / ring.clone());
            let k = cv / (rr * ring);
            assert!(
                close(&f.gaussian_curvature(), &k, 1e-40),
                "R={big_r} r={r} K"
            );
            let h = (k_meridian.clone() + k_parallel.clone()) / m(2.0);
            assert!(close(&f.mean_curvature(), &h, 1e-40), "R={big_r} r={r} H");
            let (k1, k2) = f.principal_curvatures();
            let (hi, lo) = if k_meridian.mid() > k_parallel.mid() {
                (k_meridian, k_parallel)
            } else {
                (k_parallel, k_meridian)
            };
            assert!(
                close(&k1, &hi, 1e-30) && close(&k2, &lo, 1e-30),
                "R={big_r} r={r} k"
            );
        }
    }
}

#[test]
fn cylinder_and_plane_curvatures() {
    let c = Cylinder::new([0.0; 3], [2.0, 2.0], [1.0, 2.0, 2.0], None, [0.0, 1.0]).unwrap();
    let f = c.fundamental_forms(&m(1.1), &m(0.4));
    assert!(close(&f.gaussian_curvature(), &m(0.0), 1e-50));
    assert!(close(&f.mean_curvature(), &m(-0.25), 1e-50));
    let (_, plane) = &any_surfaces()[12];
    assert_eq!(plane.gaussian_curvature(&0.3, &0.2), 0.0);
    assert_eq!(plane.mean_curvature(&0.3, &0.2), 0.0);
}

#[test]
fn weingarten_derivatives_match_differences_of_the_normal() {
    let h = 1.0 / (1u64 << 50) as f64;
    for (name, s) in any_surfaces() {
        let mut rng = Rng(77);
        for _ in 0..10 {
            let (u, v) = random_params(&s, &mut rng);
            let f = s.fundamental_forms(&m(u), &m(v));
            let (nu, nv) = f.normal_derivatives();
            let d = |du: f64, dv: f64| {
                let p = s.normal(&(m(u) + m(du)), &(m(v) + m(dv)));
                let q = s.normal(&(m(u) - m(du)), &(m(v) - m(dv)));
                let two_h = m(2.0 * h);
                [0, 1, 2].map(|i| (p[i].clone() - q[i].clone()) / two_h.clone())
            };
            let (du, dv) = (d(h, 0.0), d(0.0, h));
            for i in 0..3 {
                assert!(close(&nu[i], &du[i], 1e-20), "{name}: n_u[{i}]");
                assert!(close(&nv[i], &dv[i], 1e-20), "{name}: n_v[{i}]");
            }
        }
    }
}

/// Insert the knot `t` once into `knots` for a net of `n` points (Boehm), in the
/// homogeneous coordinates `(wP, w)` of each line of the net.
fn insert_knot(knots: &[f64], p: usize, t: f64, line: &[[f64; 4]]) -> (Vec<f64>, Vec<[f64; 4]>) {
    let k = (0..knots.len() - 1)
        .find(|&i| knots[i] <= t && t < knots[i + 1])
        .unwrap();
    let mut out = Vec::new();
    for i in 0..=line.len() {
        let q = if i + p <= k {
            line[i]
        } else if i > k {
            line[i - 1]
        } else {
            let a = (t - knots[i]) / (knots[i + p] - knots[i]);
            std::array::from_fn(|c| a * line[i][c] + (1.0 - a) * line[i - 1][c])
        };
        out.push(q);
    }
    let mut new_knots = knots.to_vec();
    new_knots.insert(k + 1, t);
    (new_knots, out)
}

#[test]
fn nurbs_equals_bezier_with_bezier_knots_and_after_knot_insertion() {
    let b = bezier_rational();
    let (du, dv) = b.degrees();
    let (points, weights) = (b.points(), b.weights().unwrap());
    let ends = |d: usize| [vec![0.0; d + 1], vec![1.0; d + 1]].concat();
    let same = NurbsSurface::new([du, dv], ends(du), ends(dv), &points, Some(&weights)).unwrap();
    // Homogeneous net, knot 0.3 inserted in u (each row), then 0.6 in v (each column).
    let hom: Vec<Vec<[f64; 4]>> = points
        .iter()
        .zip(&weights)
        .map(|(r, w)| {
            r.iter()
                .zip(w)
                .map(|(p, &w)| [w * p[0], w * p[1], w * p[2], w])
                .collect()
        })
        .collect();
    let mut knots_u = ends(du);
    let mut rows = Vec::new();
    for r in &hom {
        let (k, line) = insert_knot(&ends(du), du, 0.3, r);
        knots_u = k;
        rows.push(line);
    }
    let cols = rows[0].len();
    let mut knots_v = ends(dv);
    let mut columns = Vec::new();
    for j in 0..cols {
        let col: Vec<[f64; 4]> = rows.iter().map(|r| r[j]).collect();
        let (k, line) = insert_knot(&ends(dv), dv, 0.6, &col);
        knots_v = k;
        columns.push(line);
    }
    let n_rows = columns[0].len();
    let net: Vec<Vec<[f64; 3]>> = (0..n_rows)
        .map(|i| {
            columns
                .iter()
                .map(|c| [c[i][0] / c[i][3], c[i][1] / c[i][3], c[i][2] / c[i][3]])
                .collect()
        })
        .collect();
    let w: Vec<Vec<f64>> = (0..n_rows)
        .map(|i| columns.iter().map(|c| c[i][3]).collect())
        .collect();
    let refined = NurbsSurface::new([du, dv], knots_u, knots_v, &net, Some(&w)).unwrap();
    let mut rng = Rng(2024);
    for k in 0..200 {
        let (u, v) = if k < 4 {
            ([0.0, 1.0, 0.3, 0.3][k], [0.0, 1.0, 0.6, 0.2][k])
        } else {
            (rng.unit(), rng.unit())
        };
        let reference = b.jet(&u, &v, 2);
        for other in [same.jet(&u, &v, 2), refined.jet(&u, &v, 2)] {
            for (e, (x, y)) in reference.iter().zip(&other).enumerate() {
                for c in 0..3 {
                    assert!(
                        (x[c] - y[c]).abs() <= 1e-10 * (1.0 + x[c].abs()),
                        "entry {e} at ({u}, {v})"
                    );
                }
            }
        }
    }
}

#[test]
fn frame_rule_of_cases_md() {
    // axis +z: X = +x, Y = +y, so s(0, 0) = center + r·X and s(π/2, 0) = center + r·Y.
    let s = Sphere::new([1.0, 2.0, 3.0], 2.0, None, None).unwrap();
    assert_eq!(s.jet(&0.0, &0.0, 0)[0], [3.0, 2.0, 3.0]);
    let axes = s.frame().axes(&0.0);
    assert_eq!(axes, [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]);
    // axis −z: e = x (first on the tie), X = x, Y = Z × X = −y.
    let s = Sphere::new([0.0; 3], 1.0, Some([0.0, 0.0, -5.0]), None).unwrap();
    assert_eq!(
        s.frame().axes(&0.0),
        [[1.0, 0.0, 0.0], [0.0, -1.0, 0.0], [0.0, 0.0, -1.0]]
    );
    // axis x: the least aligned coordinate vector is y (first of y, z).
    let s = Sphere::new([0.0; 3], 1.0, Some([2.0, 0.0, 0.0]), None).unwrap();
    assert_eq!(s.frame().axes(&0.0)[0], [0.0, 1.0, 0.0]);
    // ref is made orthogonal to the axis and normalised; the interval frame encloses it.
    let s = Sphere::new([0.0; 3], 1.0, Some([0.0, 0.0, 1.0]), Some([3.0, 4.0, 7.0])).unwrap();
    assert_eq!(s.frame().axes(&0.0)[0], [0.6, 0.8, 0.0]);
    let exact = s.frame().axes(&m(0.0));
    assert!(exact[0][0].contains(0.6) || close(&exact[0][0], &(m(3.0) / m(5.0)), 1e-55));
}

#[test]
fn cone_apex_normal_is_the_limit_of_1_3() {
    let cone = Cone::new([0.0; 3], 0.0, 0.4, [0.0, 0.0, 1.0], None, [0.0, 2.0]).unwrap();
    for u in [0.0, 1.0, 2.5, 4.0] {
        let jet = cone.jet(&u, &0.0, 1);
        assert_eq!(jet[1], [0.0, 0.0, 0.0], "s_u vanishes at the apex");
        let at_apex = cone.normal(&u, &0.0);
        let near = cone.normal(&u, &1e-9);
        for c in 0..3 {
            assert!(
                (at_apex[c] - near[c]).abs() < 1e-12,
                "u = {u}: {at_apex:?} vs {near:?}"
            );
        }
    }
}

#[test]
fn closed_surfaces_meet_at_their_seams() {
    for (name, s) in any_surfaces() {
        let closed = s.is_closed();
        let (du, dv) = s.domain();
        for (d, &is_closed) in closed.iter().enumerate() {
            if !is_closed {
                continue;
            }
            let other = if d == 0 { dv } else { du };
            for k in 0..5 {
                let t = other[0] + (other[1] - other[0]) * k as f64 / 4.0;
                let range = if d == 0 { du } else { dv };
                let (a, b) = if d == 0 {
                    (s.jet(&range[0], &t, 0)[0], s.jet(&range[1], &t, 0)[0])
                } else {
                    (s.jet(&t, &range[0], 0)[0], s.jet(&t, &range[1], 0)[0])
                };
                for c in 0..3 {
                    assert!(
                        (a[c] - b[c]).abs() < 1e-12,
                        "{name} not closed in direction {d}"
                    );
                }
            }
        }
    }
    let closed: Vec<_> = any_surfaces()
        .iter()
        .map(|(n, s)| (*n, s.is_closed()))
        .collect();
    assert!(closed.contains(&("torus", [true, true])));
    assert!(closed.contains(&("torus_spindle", [true, false])));
    assert!(closed.contains(&("sphere", [true, false])));
    assert!(closed.contains(&("nurbs", [false, false])));
}
