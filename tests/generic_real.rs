//! One formula written once, generic over `Real`, evaluated in f64, `Interval` and
//! `MpfrInterval` (ARCHITECTURE.md "Numbers"): a torus point and its first derivatives
//! over a parameter box. The box enclosures must contain the f64 values and the 200-bit
//! values at random points of the box, and the 200-bit enclosure must lie inside the f64
//! one (each MPFR operation is at least as tight). Also: nalgebra matrices of intervals.

use geocert::num::{Interval, IntervalLike, MpfrInterval, Real};
use nalgebra::{Matrix3, Matrix3x2, Vector3};
use rug::{Float, Rational};

/// A torus with major radius `big_r` and minor radius `r` around the z-axis: the point at
/// `(u, v)` and the partial derivatives `∂/∂u`, `∂/∂v`.
fn torus<T: Real>(big_r: f64, r: f64, u: &T, v: &T) -> [Vector3<T>; 3] {
    let (rr, r_) = (u.lift(big_r), u.lift(r));
    let (cu, su, cv, sv) = (u.cos(), u.sin(), v.cos(), v.sin());
    let ring = rr + r_.clone() * cv.clone();
    let zero = u.zero_like();
    [
        Vector3::new(
            ring.clone() * cu.clone(),
            ring.clone() * su.clone(),
            r_.clone() * sv.clone(),
        ),
        Vector3::new(-(ring.clone() * su.clone()), ring * cu.clone(), zero),
        Vector3::new(
            -(r_.clone() * sv.clone() * cu),
            -(r_.clone() * sv * su),
            r_ * cv,
        ),
    ]
}

/// The Jacobian `[∂/∂u ∂/∂v]` as a nalgebra matrix, generic over the number type.
fn jacobian<T: Real>(u: &T, v: &T) -> Matrix3x2<T> {
    let [_, du, dv] = torus(3.0, 1.25, u, v);
    Matrix3x2::from_columns(&[du, dv])
}

struct Rng(u64);
impl Rng {
    fn unit(&mut self) -> f64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }
}

fn mpfr_contains(x: &MpfrInterval, y: &MpfrInterval) -> bool {
    y.is_subset(x)
}

#[test]
fn torus_enclosures_contain_point_values_in_all_three_number_types() {
    let boxes = [
        ((0.3, 0.35), (1.1, 1.15)),
        ((-2.0, -1.9), (3.0, 3.2)),
        ((10.0, 10.5), (-0.2, 0.1)),
    ];
    let mut rng = Rng(42);
    for ((u0, u1), (v0, v1)) in boxes {
        let (ui, vi) = (Interval::from_bounds(u0, u1), Interval::from_bounds(v0, v1));
        let (um, vm) = (
            MpfrInterval::from_bounds(u0, u1, 200),
            MpfrInterval::from_bounds(v0, v1, 200),
        );
        let box_f64 = torus(3.0, 1.25, &ui, &vi);
        let box_mpfr = torus(3.0, 1.25, &um, &vm);
        for (bi, bm) in box_f64.iter().zip(&box_mpfr) {
            for k in 0..3 {
                assert_eq!(bm[k].prec(), 200, "lifted constants keep the precision");
                assert!(
                    bm[k].to_interval().is_subset(&bi[k]),
                    "MPFR(200) ⊆ f64 enclosure: {:?} vs {:?}",
                    bm[k],
                    bi[k]
                );
            }
        }
        for _ in 0..500 {
            // Points of the box, 5% away from its faces.
            let u = u0 + (u1 - u0) * (0.05 + 0.9 * rng.unit());
            let v = v0 + (v1 - v0) * (0.05 + 0.9 * rng.unit());
            let value_f64 = torus(3.0, 1.25, &u, &v);
            let (up, vp) = (MpfrInterval::point(u, 200), MpfrInterval::point(v, 200));
            let value_hp = torus(3.0, 1.25, &up, &vp);
            for j in 0..3 {
                for k in 0..3 {
                    let (bi, bm) = (&box_f64[j][k], &box_mpfr[j][k]);
                    assert!(
                        bi.contains(value_f64[j][k]),
                        "f64 value {} ∉ {bi:?}",
                        value_f64[j][k]
                    );
                    assert!(bm.contains(value_f64[j][k]));
                    assert!(
                        value_hp[j][k].to_interval().is_subset(bi),
                        "200-bit value ∉ f64 enclosure"
                    );
                    assert!(
                        mpfr_contains(bm, &value_hp[j][k]),
                        "200-bit value ∉ MPFR box enclosure"
                    );
                    // The 200-bit point enclosure is thin: the formula is well conditioned.
                    assert!(value_hp[j][k].wid() < 1e-50);
                }
            }
        }
    }
}

#[test]
fn derivatives_match_difference_quotients_at_200_bits() {
    // The derivative formula is right: a central difference at 200 bits with step 2^-60
    // agrees with it to about 2^-120 (truncation error ~h² ≈ 1e-36).
    let (u, v) = (0.7, -0.4);
    let h = MpfrInterval::point(2f64.powi(-60), 200);
    let (up, vp) = (MpfrInterval::point(u, 200), MpfrInterval::point(v, 200));
    let [_, du, dv] = torus(3.0, 1.25, &up, &vp);
    let p_u1 = torus(3.0, 1.25, &(&up + &h), &vp)[0].clone();
    let p_u0 = torus(3.0, 1.25, &(&up - &h), &vp)[0].clone();
    let p_v1 = torus(3.0, 1.25, &up, &(&vp + &h))[0].clone();
    let p_v0 = torus(3.0, 1.25, &up, &(&vp - &h))[0].clone();
    for k in 0..3 {
        let two_h = &h * 2.0;
        let qu = (&p_u1[k] - &p_u0[k]) / &two_h;
        let qv = (&p_v1[k] - &p_v0[k]) / &two_h;
        assert!((&qu - &du[k]).mag() < 1e-30, "∂u[{k}]");
        assert!((&qv - &dv[k]).mag() < 1e-30, "∂v[{k}]");
    }
}

#[test]
fn nalgebra_matrices_of_intervals_multiply_and_enclose_the_exact_product() {
    let a = [[0.1, -2.5, 3.0], [1e-3, 7.0, -0.3], [2.0, 0.0, 1.0 / 3.0]];
    let x = [1.0 / 7.0, -4.0, 1e10];
    let exact = |i: usize| {
        (0..3).fold(Rational::new(), |s, j| {
            s + Rational::from_f64(a[i][j]).unwrap() * Rational::from_f64(x[j]).unwrap()
        })
    };
    let mi = Matrix3::from_fn(|i, j| Interval::point(a[i][j]));
    let vi = Vector3::from_fn(|i, _| Interval::point(x[i]));
    let yi = mi * vi;
    let mm = Matrix3::from_fn(|i, j| MpfrInterval::point(a[i][j], 128));
    let vm = Vector3::from_fn(|i, _| MpfrInterval::point(x[i], 128));
    let ym = &mm * &vm;
    for i in 0..3 {
        let e = exact(i);
        let enclosure = Interval::from_rational(&e);
        assert!(enclosure.is_subset(&yi[i]), "row {i}: {:?} ∌ {e}", yi[i]);
        assert_eq!(ym[i].prec(), 128);
        assert!(*ym[i].lo() <= Float::with_val(300, &e) && *ym[i].hi() >= Float::with_val(300, &e));
    }
    // Identity times a vector is the vector (Zero and One are exact).
    let id = Matrix3::<Interval>::identity();
    assert_eq!(id * vi, vi);
    // The generic Jacobian in interval and MPFR form.
    let (u, v) = (
        Interval::from_bounds(0.2, 0.21),
        Interval::from_bounds(1.0, 1.01),
    );
    let j = jacobian(&u, &v);
    let j0 = jacobian(&0.205, &1.005);
    for r in 0..3 {
        for c in 0..2 {
            assert!(j[(r, c)].contains(j0[(r, c)]));
        }
    }
    let jm = jacobian(
        &MpfrInterval::point(0.2, 256),
        &MpfrInterval::point(1.0, 256),
    );
    assert!(jm[(0, 0)].wid() < 1e-70);
}
