//! New poles for roots at a pole (issue 17 item 4, a library-level check; the front door
//! uses it since issue 14 item 4, tests/poles_front_door.rs): a helix through the north
//! pole of a sphere and of an ellipsoid. On the surfaces' own parameters the certifier
//! cannot isolate the pole root (the whole pole edge `v = π/2` maps to one point, so the
//! system is singular along it: `complete: false` with the root missing).
//! On the re-parametrised surface, with new poles far from the curve, every root is
//! `verified` and the answer `complete`; the pole root holds the true `t = 0` and the
//! pole itself, and the way back (14.7) puts it at `v = π/2`.

mod ops_support;

use std::f64::consts::PI;

use geocert::certificate::Status;
use geocert::curve::Curve;
use geocert::num::{IntervalLike, MpfrInterval, Real};
use geocert::ops::float::Precision;
use geocert::ops::intersect::intersect_curve_surface;
use geocert::surface::pencil::Pole;
use geocert::surface::quadrics::{Ellipsoid, Sphere};
use geocert::surface::repole::{Repole, SphereMapped};
use ops_support::{nodes, samples};

/// `(−0.5, 0, z₀) + 0.5 (cos t, sin t, 0) + (0, 0, 0.3 t/(2π))`, `t ∈ [−1, 1]`: at
/// `t = 0` the point `(0, 0, z₀)`.
#[derive(Debug, Clone)]
struct Helix {
    z0: f64,
}

impl Curve<3> for Helix {
    fn domain(&self) -> (f64, f64) {
        (-1.0, 1.0)
    }
    fn jet<T: Real>(&self, t: &T, order: usize) -> Vec<[T; 3]> {
        let (c, s) = (t.cos(), t.sin());
        let half = t.lift(0.5);
        let k = t.lift(0.3) / (t.pi_like() * t.lift(2.0));
        let zero = t.zero_like();
        let all = vec![
            [
                half.clone() * &c - &half,
                half.clone() * &s,
                t.lift(self.z0) + k.clone() * t,
            ],
            [-(half.clone() * &s), half.clone() * &c, k],
            [-(half.clone() * &c), -(half.clone() * &s), zero.clone()],
            [half.clone() * &s, -(half * &c), zero],
        ];
        all.into_iter().take(order + 1).collect()
    }
}

fn check<S: SphereMapped>(surface: S, z0: f64, label: &str) {
    let curve = Helix { z0 };
    let repoled = Repole::new(
        surface,
        Pole::Direction([0.0, 1.0, 0.0]),
        Pole::Direction([0.0, -0.6, -0.8]),
    )
    .unwrap();
    let r = intersect_curve_surface(
        &repoled,
        &curve,
        &samples(&curve, 16),
        &nodes(&repoled, 24),
        PI / 10.0,
        &Precision::default(),
        &Default::default(),
    )
    .unwrap();
    assert!(r.complete, "{label}: {:?}", r.reason);
    assert!(!r.value.is_empty());
    assert!(
        r.value.iter().all(|p| p.root.status == Status::Verified),
        "{label}"
    );
    let at_pole: Vec<_> = r
        .value
        .iter()
        .filter(|p| p.root.enclosure[2].contains_value(0.0))
        .collect();
    assert_eq!(at_pole.len(), 1, "{label}: the pole root");
    let p = at_pole[0];
    for (c, want) in [0.0, 0.0, z0].into_iter().enumerate() {
        assert!(
            p.point_box[c].contains_value(want),
            "{label}: {:?}",
            p.point_box
        );
    }
    // The way back: the original v of the pole root's box contains π/2.
    let e = &p.root.enclosure;
    let m = |i: usize| MpfrInterval::from_interval(&e[i], 256);
    let (_, v) = repoled.original_params(&m(0), &m(1));
    // v = atan2(z, ρ) ≤ π/2: an upper bound at or above π/2 means v's box holds it.
    let half_pi = m(0).pi_like() * MpfrInterval::point(0.5, 256);
    assert!(*v.hi() >= *half_pi.lo(), "{label}: {v:?}");
}

#[test]
fn helix_through_a_sphere_pole() {
    check(
        Sphere::new([0.0; 3], 1.0, None, None).unwrap(),
        1.0,
        "sphere",
    );
}

#[test]
fn helix_through_an_ellipsoid_pole() {
    let e = Ellipsoid::new([0.0; 3], [1.0, 2.0, 3.0], None, None).unwrap();
    check(e, 3.0, "ellipsoid");
}
