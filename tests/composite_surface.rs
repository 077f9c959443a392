//! Composite surfaces (issue 17, OPERATIONS.md §14.3, (14.8) with the corrected map
//! (14.9)): a seeded family of unions of the unit sphere and a second sphere that cuts
//! a cap out of it. The unit sphere gets new poles (`P₁` random, `P₂` the cap's axis),
//! so that the intersection circle is a graph `u = u_c(v)` on it; the second sphere is
//! parametrised from its far pole (`t_far = 0`) with its angle synchronised with `v`.
//! The composite must be continuous across the seam (a Lipschitz bound at gaps
//! `10⁻³ … 10⁻¹²`), keep the right pieces (every point of one piece outside the other
//! sphere), and end at `G`'s far pole; [S]'s map jumps there by more than 0.1.

use std::f64::consts::{FRAC_PI_2, PI, TAU};

use geocert::error::GeomError;
use geocert::num::rng::Rng;
use geocert::num::Real;
use geocert::surface::composite::{Composite, Seam};
use geocert::surface::pencil::Pole;
use geocert::surface::quadrics::Sphere;
use geocert::surface::repole::Repole;
use geocert::surface::Surface;

/// Uniform in `[0, 1)` (`Rng::unit` is uniform in `[−1, 1)`).
fn u01(rng: &mut Rng) -> f64 {
    0.5 * (rng.unit() + 1.0)
}

fn range(rng: &mut Rng, lo: f64, hi: f64) -> f64 {
    lo + (hi - lo) * u01(rng)
}

fn random_unit(rng: &mut Rng) -> [f64; 3] {
    let z = rng.unit();
    let t = TAU * u01(rng);
    let r = (1.0 - z * z).sqrt();
    [r * t.cos(), r * t.sin(), z]
}

fn dot(a: &[f64; 3], b: &[f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn dist(a: &[f64; 3], b: &[f64; 3]) -> f64 {
    let d = [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
    dot(&d, &d).sqrt()
}

/// The re-poled unit sphere in the spec's convention (§14.1): `u ∈ [0, π]` from `P₁`
/// (`u = 0`) to `P₂` (`u = π`), `v = α ∈ [0, 2π]`; `λ = π/2 − u`.
#[derive(Debug, Clone)]
struct SpecOrder(Repole<Sphere>);

impl Surface for SpecOrder {
    fn domain(&self) -> ([f64; 2], [f64; 2]) {
        ([0.0, PI], [0.0, TAU])
    }
    fn jet<T: Real>(&self, u: &T, v: &T, order: usize) -> Vec<[T; 3]> {
        let lambda = u.lift(FRAC_PI_2) - u;
        let j = self.0.jet(v, &lambda, order);
        let neg = |x: &[T; 3]| x.clone().map(|c| -c);
        let mut out = vec![j[0].clone()];
        if order >= 1 {
            out.extend([neg(&j[2]), j[1].clone()]);
        }
        if order >= 2 {
            out.extend([j[5].clone(), neg(&j[4]), j[3].clone()]);
        }
        out
    }
}

/// The intersection circle `a·X = h` on the unit sphere, found on each `v`-line by
/// bisection in f64 (test support: the generic methods evaluate at the midpoint of an
/// interval argument, so they are no enclosures; the test uses f64 only).
#[derive(Debug, Clone)]
struct Circle {
    r: SpecOrder,
    a: [f64; 3],
    h: f64,
    t_c: f64,
}

impl Circle {
    fn g(&self, u: f64, v: f64) -> f64 {
        dot(&self.a, &self.r.jet(&u, &v, 0)[0]) - self.h
    }
    /// The crossing nearest to `P₂` (`u = π`, where `g = 1 − h > 0`).
    fn u_c_f64(&self, v: f64) -> f64 {
        let mut hi = PI;
        let mut lo = PI;
        while self.g(lo, v) > 0.0 {
            hi = lo;
            lo -= PI / 256.0;
            assert!(lo > 0.0, "no crossing");
        }
        for _ in 0..200 {
            let mid = 0.5 * (lo + hi);
            if mid <= lo || mid >= hi {
                break;
            }
            if self.g(mid, v) > 0.0 {
                hi = mid;
            } else {
                lo = mid;
            }
        }
        lo
    }
    fn seam_point(&self, v: f64) -> [f64; 3] {
        self.r.jet(&self.u_c_f64(v), &v, 0)[0]
    }
}

impl Seam for Circle {
    fn u_c<T: Real>(&self, v: &T) -> T {
        v.lift(self.u_c_f64(v.mid()))
    }
    fn t_c<T: Real>(&self, v: &T) -> T {
        v.lift(self.t_c)
    }
}

/// The second sphere `c₂ + r₂ (cos t a + sin t w(v))`, `t ∈ [0, π]` from its far pole
/// (`t = 0`), `w(v)` the unit radial direction of the seam point on the `v`-line.
#[derive(Debug, Clone)]
struct Cap {
    seam: Circle,
    d: f64,
    r2: f64,
}

impl Surface for Cap {
    fn domain(&self) -> ([f64; 2], [f64; 2]) {
        ([0.0, PI], [0.0, TAU])
    }
    fn jet<T: Real>(&self, t: &T, v: &T, _order: usize) -> Vec<[T; 3]> {
        let a = self.seam.a;
        let x = self.seam.seam_point(v.mid());
        let ax = dot(&a, &x);
        let radial = [x[0] - ax * a[0], x[1] - ax * a[1], x[2] - ax * a[2]];
        let n = dot(&radial, &radial).sqrt();
        let (c, s) = (t.cos(), t.sin());
        let r2 = t.lift(self.r2);
        vec![std::array::from_fn(|i| {
            t.lift(self.d * a[i])
                + r2.clone() * (c.clone() * t.lift(a[i]) + s.clone() * t.lift(radial[i] / n))
        })]
    }
}

fn union(rng: &mut Rng) -> (Composite<SpecOrder, Cap, Circle>, Circle, Cap) {
    let a = random_unit(rng);
    let h = range(rng, 0.6, 0.95);
    let d = range(rng, 0.6, 1.4);
    let r2 = (1.0 + d * d - 2.0 * d * h).sqrt();
    let p1 = loop {
        let p = random_unit(rng);
        if dot(&p, &a) < h - 0.3 && dot(&p, &a) > -0.9 {
            break p;
        }
    };
    let sphere = Sphere::new([0.0; 3], 1.0, None, None).unwrap();
    let r = SpecOrder(Repole::new(sphere, Pole::Direction(p1), Pole::Direction(a)).unwrap());
    let t_c = ((h - d) / r2).acos();
    let seam = Circle {
        r: r.clone(),
        a,
        h,
        t_c,
    };
    let cap = Cap {
        seam: seam.clone(),
        d,
        r2,
    };
    let composite = Composite::new(r, cap.clone(), seam.clone(), 0.0).unwrap();
    (composite, seam, cap)
}

#[test]
fn union_is_continuous_across_the_seam() {
    let mut rng = Rng::new(0x1717_00c0);
    for case in 0..60 {
        let (s, seam, cap) = union(&mut rng);
        let far_pole = seam.a.map(|x| (cap.d + cap.r2) * x);
        let c2 = seam.a.map(|x| cap.d * x);
        for _ in 0..6 {
            let v = range(&mut rng, 0.0, TAU);
            let uc = seam.u_c_f64(v);
            // The derivative bound: |R_u| at the seam and |G_t dt/du| (14.9).
            let r_u = seam.r.jet(&uc, &v, 1)[1];
            let lip = dot(&r_u, &r_u).sqrt() + cap.r2 * seam.t_c / (PI - uc);
            for k in [3, 6, 9, 12] {
                let eps = 10f64.powi(-k);
                let (below, above) = (s.point(&(uc - eps), &v), s.point(&(uc + eps), &v));
                let jump = dist(&below, &above);
                assert!(
                    jump <= 3.0 * lip * eps + 1e-13,
                    "case {case}: jump {jump:e} at gap {eps:e} (bound {lip})"
                );
            }
            // (14.9) sends the seam to t_c and u_p to t_far.
            assert!((s.g_parameter(&uc, &v) - seam.t_c).abs() < 1e-15);
            assert!(s.g_parameter(&PI, &v).abs() < 1e-15);
            assert!(
                dist(&s.point(&PI, &v), &far_pole) < 1e-15,
                "case {case}: far pole"
            );
            // [S]'s map sends the seam to t = 0, G's far pole: a jump.
            let source_t = seam.t_c * 1e-9 / (PI - uc);
            let source = cap.jet(&source_t, &v, 0)[0];
            assert!(
                dist(&source, &s.point(&uc, &v)) > 0.1,
                "case {case}: [S] continuous?"
            );
            // The union keeps the pieces outside the other sphere.
            for _ in 0..4 {
                let u = range(&mut rng, 0.0, PI);
                let x = s.point(&u, &v);
                if u <= uc {
                    assert!(dist(&x, &c2) >= cap.r2 - 1e-12, "case {case}: R inside G");
                } else {
                    assert!(dot(&x, &x).sqrt() >= 1.0 - 1e-12, "case {case}: G inside R");
                }
            }
        }
    }
}

#[test]
fn far_end_must_be_an_end_of_g() {
    let mut rng = Rng::new(0x1717_00c1);
    let (_, seam, cap) = union(&mut rng);
    match Composite::new(seam.r.clone(), cap, seam, 1.0) {
        Err(GeomError::InvalidValue { field, .. }) => assert_eq!(field, "t_far"),
        other => panic!("{:?}", other.map(|_| ())),
    }
}
