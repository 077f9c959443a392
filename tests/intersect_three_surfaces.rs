//! Three surfaces, float path (OPERATIONS.md §7.2), with guesses found by the search.

use geocert::ops::float::Precision;
use geocert::ops::intersect::intersect_three_surfaces_f64;
use geocert::surface::Surface;
use std::f64::consts::FRAC_PI_2;

mod ops_support;
use ops_support::{nodes, Torus};

/// A sphere of radius `r` centred at `c` (the §1.6 parametrisation, translated).
struct Sphere {
    c: [f64; 3],
    r: f64,
}

impl Surface for Sphere {
    fn domain(&self) -> ([f64; 2], [f64; 2]) {
        Torus {
            major: 0.0,
            minor: self.r,
            v_range: [-FRAC_PI_2, FRAC_PI_2],
        }
        .domain()
    }
    fn is_closed(&self) -> [bool; 2] {
        [true, false]
    }
    fn domain_rounded(&self) -> [bool; 2] {
        [true, true]
    }
    fn jet<T: geocert::num::Real>(&self, u: &T, v: &T, order: usize) -> Vec<[T; 3]> {
        let base = Torus {
            major: 0.0,
            minor: self.r,
            v_range: [-FRAC_PI_2, FRAC_PI_2],
        };
        let mut j = base.jet(u, v, order);
        for (x, c) in j[0].iter_mut().zip(self.c) {
            *x = x.clone() + u.lift(c);
        }
        j
    }
}

#[test]
fn three_unit_spheres_meet_in_two_points() {
    // Centres (0,0,0), (1,0,0), (0,1,0), radius 1: x = y = 1/2, z = ±1/√2.
    let a = Sphere {
        c: [0.0, 0.0, 0.0],
        r: 1.0,
    };
    let b = Sphere {
        c: [1.0, 0.0, 0.0],
        r: 1.0,
    };
    let c = Sphere {
        c: [0.0, 1.0, 0.0],
        r: 1.0,
    };
    let (na, nb, nc) = (nodes(&a, 16), nodes(&b, 16), nodes(&c, 16));
    let pts = intersect_three_surfaces_f64((&a, &b, &c), [&na, &nb, &nc], &Precision::default());
    assert_eq!(pts.len(), 2, "{pts:?}");
    let z = 0.5f64.sqrt();
    for (p, sign) in pts.iter().zip([-1.0, 1.0]) {
        assert!(
            (p.point[0] - 0.5).abs() < 1e-13 && (p.point[1] - 0.5).abs() < 1e-13,
            "{p:?}"
        );
        assert!((p.point[2] - sign * z).abs() < 1e-13);
        // Every parameter pair maps to the point on its own sphere.
        for (s, params) in [&a, &b, &c].iter().zip(p.params) {
            let q = s.jet(&params[0], &params[1], 0)[0];
            assert!((0..3).all(|i| (q[i] - p.point[i]).abs() < 1e-12));
        }
    }
}

#[test]
fn spheres_too_far_apart_have_no_common_point() {
    let a = Sphere {
        c: [0.0, 0.0, 0.0],
        r: 1.0,
    };
    let b = Sphere {
        c: [1.0, 0.0, 0.0],
        r: 1.0,
    };
    let c = Sphere {
        c: [0.0, 3.0, 0.0],
        r: 1.0,
    };
    let (na, nb, nc) = (nodes(&a, 16), nodes(&b, 16), nodes(&c, 16));
    let pts = intersect_three_surfaces_f64((&a, &b, &c), [&na, &nb, &nc], &Precision::default());
    assert!(pts.is_empty(), "{pts:?}");
}

#[test]
fn certified_three_spheres() {
    use geocert::ops::intersect::intersect_three_surfaces;
    use geocert::Status;
    let a = Sphere {
        c: [0.0, 0.0, 0.0],
        r: 1.0,
    };
    let b = Sphere {
        c: [1.0, 0.0, 0.0],
        r: 1.0,
    };
    let c = Sphere {
        c: [0.0, 1.0, 0.0],
        r: 1.0,
    };
    let (na, nb, nc) = (nodes(&a, 16), nodes(&b, 16), nodes(&c, 16));
    let r = intersect_three_surfaces(
        (&a, &b, &c),
        [&na, &nb, &nc],
        &Precision::default(),
        &Default::default(),
    )
    .expect("valid");
    assert_eq!(r.value.len(), 2, "{r:?}");
    assert!(r.complete, "{:?}", r.reason);
    // (1/2, 1/2, ±1/√2) at 1024 bits, one-to-one with the two point boxes; and on each
    // sphere the parameters (u, v) = (atan2(d_y, d_x) mod 2π, asin d_z) of the unit
    // direction d = p − c in the parameter boxes.
    let prec = 1024;
    let z = rug::Float::with_val(prec, 0.5f64).sqrt();
    let tau = rug::Float::with_val(prec, rug::float::Constant::Pi) * 2u32;
    let truths: Vec<[rug::Float; 3]> = [1, -1]
        .iter()
        .map(|&s| {
            let h = rug::Float::with_val(prec, 0.5);
            [h.clone(), h, z.clone() * s]
        })
        .collect();
    let holds = |b: &geocert::num::Interval, t: &rug::Float| *t >= b.lo() && *t <= b.hi();
    for p in &r.value {
        assert_eq!(p.root.status, Status::Verified);
        let inside: Vec<&[rug::Float; 3]> = truths
            .iter()
            .filter(|t| (0..3).all(|k| holds(&p.point_box[k], &t[k])))
            .collect();
        assert_eq!(inside.len(), 1, "{:?}", p.point_box);
        for (i, centre) in [a.c, b.c, c.c].iter().enumerate() {
            let d: Vec<rug::Float> = (0..3)
                .map(|k| rug::Float::with_val(prec, &inside[0][k] - centre[k]))
                .collect();
            let mut u = d[1].clone().atan2(&d[0]);
            if u < 0 {
                u += &tau;
            }
            let v = d[2].clone().asin();
            let e = &p.root.enclosure;
            assert!(
                holds(&e[2 * i], &u) && holds(&e[2 * i + 1], &v),
                "sphere {i}: ({u}, {v}) not in {:?}",
                &e[2 * i..2 * i + 2]
            );
        }
    }
    for t in &truths {
        let k = r
            .value
            .iter()
            .filter(|p| (0..3).all(|k| holds(&p.point_box[k], &t[k])))
            .count();
        assert_eq!(k, 1, "{} in {k} boxes", t[2]);
    }
}
