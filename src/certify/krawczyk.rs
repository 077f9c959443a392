//! The Krawczyk operator (docs/CERTIFICATES.md "verified"): existence, uniqueness and
//! exclusion of roots of a square system in a box, at any interval precision.
//!
//! For a box `X`, its midpoint `m`, the interval Jacobian `J(X)` and a preconditioner
//! `Y ≈ mid(J(X))⁻¹`,
//!
//! ```text
//! K(X) = m − Y·F(m) + (I − Y·J(X))·(X − m).
//! ```
//!
//! If `F` is `C¹` on `X` (proven by [`super::guarded::Guarded`]), then by the mean value
//! theorem applied to each component, every root `x*` in `X` satisfies
//! `x* = m − Y F(m) + (I − Y J̃)(x* − m)` for a real matrix `J̃` whose rows lie in `J(X)`,
//! so `x* ∈ K(X)`: roots of `X` lie in `X ∩ K(X)`, and none exist if that is empty. If
//! `K(X) ⊆ int X`, then `X` contains exactly one root (Krawczyk 1969, Moore 1977; with the
//! interior inclusion, Rump 1983: `Y` and every `J̃` are nonsingular). All operations are
//! outward rounded, so the computed `K(X)` contains the exact one.

use super::boxes::{self, IBox};
use super::guarded::{all_smooth, Guarded};
use super::level::CertInterval;
use super::linalg::{identity_minus_product, mat_vec, mid_matrix};
use super::system::System;
use crate::num::IntervalLike;

/// What one Krawczyk step proves about a box `X`.
#[derive(Debug, Clone)]
pub enum Krawczyk<I> {
    /// Nothing: `F` is not proven `C¹` on `X`, or `mid(J(X))` is numerically singular.
    Inconclusive,
    /// `K(X) ⊆ int X`: exactly one root in `X`, and it lies in the given `K(X)`.
    Unique(IBox<I>),
    /// Every root in `X` lies in `X ∩ K(X)` (none if that is empty); `K(X)` given.
    Image(IBox<I>),
}

/// `F(X)` in the set semantics of the interval type (points where `F` is undefined are
/// dropped, so an empty component means `F` is nowhere defined on `X`).
pub fn image<S: System, I: CertInterval>(sys: &S, x: &[I]) -> Vec<I> {
    sys.eval(x)
}

/// True if `F` has no root in `X`, proven by its image: some component's enclosure is
/// empty (that component is defined nowhere on `X`, so no point of `X` is a root) or
/// misses 0.
pub fn excluded_by_image<I: IntervalLike>(values: &[I], n: usize) -> bool {
    values.len() == n && values.iter().any(|v| v.is_empty() || !v.contains_zero())
}

/// `F(X)` and `J(X)` if `F` is proven `C^∞` on the box `x` — every value and every
/// derivative entry computed by smooth operations (a value may be non-smooth where its
/// derivative formula is not, as `atan2` across its branch cut) — and the shapes are
/// square; else `None`.
pub fn smooth_jacobian<S: System, I: IntervalLike>(
    sys: &S,
    x: &[I],
) -> Option<(Vec<I>, Vec<Vec<I>>)> {
    let n = x.len();
    let gx: Vec<Guarded<I>> = x.iter().cloned().map(Guarded::new).collect();
    let (values, jac) = sys.eval_with_jacobian(&gx);
    let square = values.len() == n && jac.len() == n && jac.iter().all(|r| r.len() == n);
    if !square || !all_smooth(&values) || !jac.iter().all(|r| all_smooth(r)) {
        return None;
    }
    let unguard = |v: Vec<Guarded<I>>| v.into_iter().map(|g| g.value).collect::<Vec<I>>();
    Some((unguard(values), jac.into_iter().map(unguard).collect()))
}

/// One Krawczyk step on the box `x` (module doc), about its midpoint.
pub fn krawczyk<S: System, I: CertInterval>(sys: &S, x: &[I]) -> Krawczyk<I> {
    krawczyk_about(sys, x, &boxes::midpoint(x))
}

/// One Krawczyk step on the box `x` about the point `m ∈ x` (any point of the box will
/// do: the mean value theorem is applied on segments from `m`, which stay in the box).
/// A fixed `m` over several steps avoids the jitter that re-rounding `F` at a moving
/// midpoint adds when `F(m)`'s rounding dominates `K(X)`. `Inconclusive` if `m ∉ x`.
pub fn krawczyk_about<S: System, I: CertInterval>(sys: &S, x: &[I], m: &[I]) -> Krawczyk<I> {
    if !boxes::is_subset(m, x) {
        return Krawczyk::Inconclusive;
    }
    let Some((_, j)) = smooth_jacobian(sys, x) else {
        return Krawczyk::Inconclusive;
    };
    let Some(fm) = value_at(sys, m) else {
        return Krawczyk::Inconclusive;
    };
    krawczyk_with(x, m, &j, &fm)
}

/// `F(m)` at a point box `m`, if proven smooth there and of the system's size.
pub fn value_at<S: System, I: CertInterval>(sys: &S, m: &[I]) -> Option<Vec<I>> {
    let gm: Vec<Guarded<I>> = m.iter().cloned().map(Guarded::new).collect();
    let fm = sys.eval(&gm);
    if fm.len() != m.len() || !all_smooth(&fm) {
        return None;
    }
    Some(fm.into_iter().map(|g| g.value).collect())
}

/// The Krawczyk step from its parts: the box `x`, the point `m ∈ x`, an interval
/// matrix `j` of slopes over `x` (every `F(z) − F(m)`, `z ∈ x`, is `J̃ (z − m)` for some
/// real `J̃` with rows in `j`: the Jacobian's enclosure of a `C¹` map, by the mean value
/// theorem, or the hull of the pieces' Jacobians of a continuous piecewise-`C¹` map,
/// [`super::joined`]) and `fm ∋ F(m)`.
pub fn krawczyk_with<I: CertInterval>(x: &[I], m: &[I], j: &[Vec<I>], fm: &[I]) -> Krawczyk<I> {
    let n = x.len();
    let Some(y) = I::approx_inverse(&mid_matrix(j)) else {
        return Krawczyk::Inconclusive;
    };
    let c = identity_minus_product(&y, j);
    let yf = mat_vec(&y, fm);
    let d: Vec<I> = x.iter().zip(m).map(|(a, b)| a.clone() - b).collect();
    let cd = mat_vec(&c, &d);
    let k: IBox<I> = (0..n).map(|i| m[i].clone() - &yf[i] + &cd[i]).collect();
    if k.iter().any(|v| v.is_empty()) {
        return Krawczyk::Inconclusive;
    }
    if boxes::is_interior(&k, x) {
        Krawczyk::Unique(k)
    } else {
        Krawczyk::Image(k)
    }
}

/// A root proven to exist and to be unique in `region`, and to lie in `enclosure`.
#[derive(Debug, Clone)]
pub struct VerifiedRoot<I> {
    /// The box in which the root is the only one.
    pub region: IBox<I>,
    /// A narrower box containing the root (`⊆ region`).
    pub enclosure: IBox<I>,
}

/// Narrow the enclosure of the unique root of `region` by iterating `E ← E ∩ K(E)` (every
/// `K(E)` contains the root, since it lies in `E`).
pub fn tighten<S: System, I: CertInterval>(sys: &S, mut e: IBox<I>, steps: usize) -> IBox<I> {
    // already within a few units in the last place of the box's scale: nothing to gain
    let bits = e.first().map_or(53, |v| v.precision_bits());
    let scale = e.iter().map(|v| v.mag()).fold(1.0, f64::max);
    let ulps = (-(f64::from(bits) - 4.0)).exp2() * scale;
    if e.iter().all(|v| v.wid() <= ulps) {
        return e;
    }
    for _ in 0..steps {
        let before: f64 = boxes::widths(&e).into_iter().fold(0.0, f64::max);
        let k = match krawczyk(sys, &e) {
            Krawczyk::Unique(k) | Krawczyk::Image(k) => k,
            Krawczyk::Inconclusive => break,
        };
        match boxes::intersection(&e, &k) {
            Some(next) => e = next,
            None => break,
        }
        let after: f64 = boxes::widths(&e).into_iter().fold(0.0, f64::max);
        if after.is_nan() || after >= 0.5 * before {
            break;
        }
    }
    e
}

/// The enclosure of the root proven unique in `region` (`k` a Krawczyk image that
/// holds it), narrowed to a few units in the last place: [`tighten`] first; where that
/// stalls on a wide box (`K(E)` about the midpoint of a wide `E` shrinks by less than
/// half, so a root proven in a box of width 0.4 kept that width and its midpoint as the
/// estimate, 5e-4 off the foot: issue 14, the `ellipse2` projection of (3, 1)), Newton
/// at this precision from the enclosure's midpoint and [`verify_near`] about Newton's
/// point. A box `B ⊆ region` proven to hold a root holds *the* root of `region`, so the
/// enclosure becomes `E ∩ B` — which holds the root, as both do. Newton only guides:
/// when it leaves `E` or the proof fails, `E` is kept as it is.
pub fn narrow_unique<S: System, I: CertInterval>(sys: &S, region: &[I], k: IBox<I>) -> IBox<I> {
    let e = tighten(sys, k, 4);
    let bits = match e.first() {
        Some(v) => v.precision_bits(),
        None => return e,
    };
    let scale = e.iter().map(|v| v.mag()).fold(1.0, f64::max);
    let ulps = (-(f64::from(bits) - 8.0)).exp2() * scale;
    if e.iter().all(|v| v.wid() <= 16.0 * ulps) {
        return e;
    }
    let Some((x, _)) = super::newton::newton_point(sys, &boxes::midpoint(&e), 40) else {
        return e;
    };
    if !boxes::is_subset(&x, &e) {
        return e;
    }
    let max_width = boxes::widths(&e).into_iter().fold(0.0, f64::max);
    let radius = vec![ulps; x.len()];
    match verify_near(sys, &x, &radius, max_width) {
        Some(v) if boxes::is_subset(&v.enclosure, region) => {
            boxes::intersection(&e, &v.enclosure).unwrap_or(e)
        }
        _ => e,
    }
}

/// Prove a root near the point `center` by Krawczyk about `center` with
/// epsilon-inflation (Rump 1983): start from `center ± radius`, and after each failed
/// step continue with the hull of `center` and `K(X)` grown by a tenth of its width plus
/// a few units in the last place. Gives up when a side would exceed `max_width`, or after
/// a few steps.
pub fn verify_near<S: System, I: CertInterval>(
    sys: &S,
    center: &[I],
    radius: &[f64],
    max_width: f64,
) -> Option<VerifiedRoot<I>> {
    let bits = center.first()?.precision_bits();
    let ulps = (-(f64::from(bits) - 4.0)).exp2();
    let mut x: IBox<I> = center
        .iter()
        .zip(radius)
        .map(|(c, &r)| c.clone() + c.with_bounds(-r, r))
        .collect();
    for _ in 0..8 {
        if boxes::widths(&x)
            .iter()
            .any(|w| w.is_nan() || *w > max_width)
        {
            return None;
        }
        match krawczyk_about(sys, &x, center) {
            Krawczyk::Unique(k) => {
                let enclosure = tighten(sys, k, 4);
                return Some(VerifiedRoot {
                    region: x,
                    enclosure,
                });
            }
            Krawczyk::Image(k) => {
                x = boxes::hull(&boxes::inflate_scaled(&k, 0.1, ulps), center);
            }
            Krawczyk::Inconclusive => return None,
        }
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::certify::boxes::test_box as b;
    use crate::num::{MpfrInterval, Real};

    /// x² + y² = 4, x = y: roots ±(√2, √2).
    struct Circle;
    impl System for Circle {
        fn dim(&self) -> usize {
            2
        }
        fn eval<T: Real>(&self, x: &[T]) -> Vec<T> {
            vec![
                x[0].sqr() + x[1].sqr() - x[0].lift(4.0),
                x[0].clone() - &x[1],
            ]
        }
    }

    #[test]
    fn unique_root_proven_and_enclosed() {
        let x = b(&[(1.3, 1.5), (1.3, 1.5)]);
        let Krawczyk::Unique(k) = krawczyk(&Circle, &x) else {
            panic!("expected a proof")
        };
        let s = std::f64::consts::SQRT_2;
        assert!(k[0].contains(s) && k[1].contains(s));
        let e = tighten(&Circle, k, 6);
        assert!(e[0].width() < 1e-14 && e[0].contains(s));
    }

    #[test]
    fn rootless_box_is_excluded() {
        // x = y holds on the diagonal, but the circle is far: K(X) misses X
        let x = b(&[(0.2, 0.4), (0.2, 0.4)]);
        match krawczyk(&Circle, &x) {
            Krawczyk::Image(k) => assert!(boxes::intersection(&k, &x).is_none()),
            other => panic!("{other:?}"),
        }
    }

    #[test]
    fn epsilon_inflation_from_a_point_at_mpfr_precision() {
        let c: Vec<MpfrInterval> = vec![MpfrInterval::point(1.414, 256); 2];
        let v = verify_near(&Circle, &c, &[1e-70, 1e-70], 1.0).unwrap();
        let root = MpfrInterval::point(2.0, 256).sqrt();
        assert!(root.is_subset(&v.region[0]) && root.is_subset(&v.enclosure[0]));
        assert!(v.enclosure[0].wid() < 1e-70);
    }

    /// √x − 1/2 on a box that reaches below 0: not smooth there, so nothing is proven.
    struct Root;
    impl System for Root {
        fn dim(&self) -> usize {
            1
        }
        fn eval<T: Real>(&self, x: &[T]) -> Vec<T> {
            vec![x[0].sqrt() - x[0].lift(0.5)]
        }
    }

    #[test]
    fn partial_domain_is_inconclusive() {
        assert!(matches!(
            krawczyk(&Root, &b(&[(-0.5, 0.5)])),
            Krawczyk::Inconclusive
        ));
        assert!(matches!(
            krawczyk(&Root, &b(&[(0.2, 0.3)])),
            Krawczyk::Unique(_)
        ));
        // where √ is undefined the image is empty: no root, soundly
        assert!(excluded_by_image(&image(&Root, &b(&[(-2.0, -1.0)])), 1));
        assert!(!excluded_by_image(&image(&Root, &b(&[(-2.0, 1.0)])), 1));
    }

    /// atan2(x, −1) − (π − 1/20): the value jumps by 2π where x crosses 0 (the branch
    /// cut) while the derivative formula −1/(1 + x²) does not see it.
    struct AcrossTheCut;
    impl System for AcrossTheCut {
        fn dim(&self) -> usize {
            1
        }
        fn eval<T: Real>(&self, x: &[T]) -> Vec<T> {
            let pi = x[0].pi_like();
            vec![x[0].atan2(&x[0].lift(-1.0)) - pi + &x[0].lift(0.05)]
        }
    }

    #[test]
    fn a_discontinuity_is_not_smooth() {
        assert!(matches!(
            krawczyk(&AcrossTheCut, &b(&[(-0.1, 0.1)])),
            Krawczyk::Inconclusive
        ));
        // right of the cut the root tan(0.05) is proven (0.05 the double, taken as exact)
        let Krawczyk::Unique(k) = krawczyk(&AcrossTheCut, &b(&[(0.01, 0.1)])) else {
            panic!("expected a proof")
        };
        let truth = rug::Float::with_val(200, 0.05f64).tan();
        let e = tighten(&AcrossTheCut, k, 6);
        assert!(MpfrInterval::from_interval(&e[0], 200).contains_float(&truth));
        assert!(e[0].width() < 1e-15);
    }
}
