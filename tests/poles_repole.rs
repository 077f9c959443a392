//! New poles on sphere-mapped surfaces (issue 17, OPERATIONS.md §14.1–§14.2, worked
//! example §16.15). The truth is the spec's literal construction (14.1)–(14.7) — with
//! `arccos`, the point `P` of (14.5) and the centre/radius of (14.4) — evaluated here
//! in MPFR at 256 bits with rug, independently of the library, which evaluates the
//! equivalent orthonormal form of `surface::pencil`. Families of seeded pole pairs
//! (generic, near-antipodal, near-equal) check that the generated points stay on the
//! sphere (an MPFR enclosure of `|X|² − 1` containing 0, the f64 value within a few
//! ulps), that they agree with the truth, and that `β = 0`, `β = 2Ψ` are the poles.

use std::f64::consts::{FRAC_PI_2, FRAC_PI_6, PI, TAU};

use geocert::error::GeomError;
use geocert::num::rng::Rng;
use geocert::num::{Interval, IntervalLike, MpfrInterval, Real};
use geocert::surface::pencil::{sphere_point, NetKind, PencilNet, Pole};
use geocert::surface::quadrics::{Ellipsoid, Sphere};
use geocert::surface::repole::{unit_params, Repole};
use geocert::surface::Surface;
use rug::float::Constant;
use rug::Float;

const BITS: u32 = 256;
const EPS: f64 = f64::EPSILON;

// ---------------------------------------------------------------------------------
// The truth: §14 literally, in rug at 256 bits.

type V = [Float; 3];

fn f(x: f64) -> Float {
    Float::with_val(BITS, x)
}
fn pi() -> Float {
    Float::with_val(BITS, Constant::Pi)
}
fn dotv(a: &V, b: &V) -> Float {
    let t = |i: usize| Float::with_val(BITS, &a[i] * &b[i]);
    t(0) + t(1) + t(2)
}
fn crossv(a: &V, b: &V) -> V {
    [
        Float::with_val(BITS, &a[1] * &b[2]) - &a[2] * &b[1],
        Float::with_val(BITS, &a[2] * &b[0]) - &a[0] * &b[2],
        Float::with_val(BITS, &a[0] * &b[1]) - &a[1] * &b[0],
    ]
}
fn unitv(a: &V) -> V {
    let n = dotv(a, a).sqrt();
    a.clone().map(|x| x / &n)
}
/// `a + s b`.
fn axpy(a: &V, s: &Float, b: &V) -> V {
    std::array::from_fn(|i| Float::with_val(BITS, s * &b[i]) + &a[i])
}
fn to_f64(a: &V) -> [f64; 3] {
    std::array::from_fn(|i| a[i].to_f64())
}

/// (14.1): `S(ϑ, φ)`.
fn spec_sphere(theta: &Float, phi: &Float) -> V {
    let st = theta.clone().sin();
    [
        st.clone() * phi.clone().cos(),
        st * phi.clone().sin(),
        theta.clone().cos(),
    ]
}

/// The pole of library parameters `(u, v)` in the spec's angles: `ϑ = π/2 − v`, `φ = u`.
fn spec_angles_of(p: [f64; 2]) -> (Float, Float) {
    (pi() / 2 - f(p[1]), f(p[0]))
}

/// Which `P` of (14.5).
#[derive(Clone, Copy, PartialEq)]
enum Which {
    Corrected,
    Source,
}

/// (14.2)–(14.5) for two poles given as library parameters.
struct Truth {
    n1: V,
    n2: V,
    e1: V,
    l1: V,
    psi: Float,
    p: V,
}

impl Truth {
    fn new(p1: [f64; 2], p2: [f64; 2], which: Which) -> Truth {
        let (t1, f1) = spec_angles_of(p1);
        let (t2, f2) = spec_angles_of(p2);
        let n1 = spec_sphere(&t1, &f1);
        let n2 = spec_sphere(&t2, &f2).map(|x| -x);
        let e1 = unitv(&crossv(&n2, &n1));
        let l1 = unitv(&crossv(&n1, &e1));
        let l2 = unitv(&crossv(&n2, &e1));
        let psi = dotv(&l1, &l2).acos() / 2;
        let sum = std::array::from_fn(|i| Float::with_val(BITS, &n1[i] + &n2[i]));
        let diff = std::array::from_fn(|i| Float::with_val(BITS, &n1[i] - &n2[i]));
        let p = match which {
            Which::Corrected => axpy(&n1, &(-dotv(&sum, &n2) / dotv(&l1, &n2)), &l1),
            Which::Source => axpy(&n1, &(dotv(&diff, &n2) / dotv(&l1, &n2)), &l1),
        };
        Truth {
            n1,
            n2,
            e1,
            l1,
            psi,
            p,
        }
    }

    /// (14.4), (14.6).
    fn point(&self, alpha: f64, beta: &Float) -> V {
        let sp = self.psi.clone().sin();
        let pb = Float::with_val(BITS, &self.psi - beta);
        let k = pb.clone().cos() / &sp;
        let (cx, cy) = (k.clone() * beta.clone().cos(), k * beta.clone().sin());
        let ratio = pb.sin() / &sp;
        let rho = (f(1.0) - ratio.square()).max(&f(0.0)).sqrt();
        let c = axpy(&axpy(&self.p, &cx, &self.l1), &-cy, &self.n1);
        let h1 = unitv(&std::array::from_fn(|i| {
            Float::with_val(BITS, &self.p[i] - &c[i])
        }));
        let (ca, sa) = (f(alpha).cos(), f(alpha).sin());
        let dir = std::array::from_fn(|i| {
            Float::with_val(BITS, &ca * &h1[i]) + Float::with_val(BITS, &sa * &self.e1[i])
        });
        axpy(&c, &rho, &dir)
    }
}

/// (14.7): `ϑ = arccos(Z/|X|)`, `φ = atan2(Y, X) ∈ [0, 2π)`.
fn way_back(x: &V) -> (Float, Float) {
    let theta = (x[2].clone() / dotv(x, x).sqrt()).acos();
    let mut phi = x[1].clone().atan2(&x[0]);
    if phi < 0 {
        phi += pi() * 2;
    }
    (theta, phi)
}

// ---------------------------------------------------------------------------------
// Helpers.

fn m(x: f64) -> MpfrInterval {
    MpfrInterval::point(x, BITS)
}

fn norm(x: &[f64; 3]) -> f64 {
    (x[0] * x[0] + x[1] * x[1] + x[2] * x[2]).sqrt()
}

fn dist(a: &[f64; 3], b: &[f64; 3]) -> f64 {
    norm(&[a[0] - b[0], a[1] - b[1], a[2] - b[2]])
}

/// The largest distance from the rug point `t` to the MPFR enclosure `x` (0 inside).
fn outside(x: &[MpfrInterval; 3], t: &V) -> f64 {
    (0..3)
        .map(|i| {
            let lo = Float::with_val(BITS, x[i].lo() - &t[i]);
            let hi = Float::with_val(BITS, &t[i] - x[i].hi());
            lo.max(&hi).max(&f(0.0)).to_f64()
        })
        .fold(0.0, f64::max)
}

/// `|x|² − 1` enclosed.
fn norm_sq_minus_one(x: &[MpfrInterval; 3]) -> MpfrInterval {
    x[0].sqr() + x[1].sqr() + x[2].sqr() - m(1.0)
}

/// Library parameters `(u, v)` of the unit vector `d` (f64).
fn params_of(d: [f64; 3]) -> [f64; 2] {
    let mut u = d[1].atan2(d[0]);
    if u < 0.0 {
        u += TAU;
    }
    [u, d[2].atan2((d[0] * d[0] + d[1] * d[1]).sqrt())]
}

/// A unit vector making the angle `angle` with the unit vector `p`.
fn at_angle(p: [f64; 3], angle: f64, rng: &mut Rng) -> [f64; 3] {
    let r = random_unit(rng);
    let dp = r[0] * p[0] + r[1] * p[1] + r[2] * p[2];
    let w = [r[0] - dp * p[0], r[1] - dp * p[1], r[2] - dp * p[2]];
    let n = norm(&w);
    let (c, s) = (angle.cos(), angle.sin());
    std::array::from_fn(|i| c * p[i] + s * w[i] / n)
}

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

/// The worked example's poles (§16.15) in library parameters: `(ϑ, φ) = (π/3, 0)` is
/// `(u, v) = (0, π/6)`, `(2π/3, π/2)` is `(π/2, −π/6)`.
const EXAMPLE: [[f64; 2]; 2] = [[0.0, FRAC_PI_6], [FRAC_PI_2, -FRAC_PI_6]];

fn example_net() -> PencilNet {
    PencilNet::new(Pole::Params(EXAMPLE[0]), Pole::Params(EXAMPLE[1])).unwrap()
}

fn close(a: f64, b: f64, tol: f64) -> bool {
    (a - b).abs() <= tol
}

// ---------------------------------------------------------------------------------
// §16.15.

#[test]
fn worked_example_numbers() {
    let net = example_net();
    let fr = net.frame(&0.0f64);
    let tol = 1e-10;
    let p1 = [0.8660254038, 0.0, 0.5];
    let p2 = [0.0, 0.8660254038, -0.5];
    assert!(dist(&fr.n1, &p1) < tol, "P1 {:?}", fr.n1);
    assert!(dist(&sphere_point(&EXAMPLE[1][0], &EXAMPLE[1][1]), &p2) < tol);
    assert!(close(net.psi(&0.0), 0.6590580358, tol));
    assert!(close(PI - 2.0 * net.psi(&0.0), 1.8234765819, tol), "γ");
    let p = net.pencil_point(&0.0f64).unwrap();
    assert!(
        dist(&p, &[1.1547005384, 1.1547005384, 0.0]) < tol,
        "P {p:?}"
    );
    let dot = |a: &[f64; 3], b: &[f64; 3]| a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    assert!(close(dot(&p, &fr.n1), 1.0, 4.0 * EPS), "P·N1");
    assert!(close(dot(&p, &p2), 1.0, tol), "P·(−N2)");
    // The sample point and the way back.
    let x = net.point_at_beta(&1.0, &0.4).unwrap();
    let want = [0.2220260841, 0.6003983339, 0.7682618425];
    assert!(dist(&x, &want) < tol, "X(1.0, 0.4) = {x:?}");
    let (u, v) = unit_params(&x);
    let (theta, phi) = (FRAC_PI_2 - v, u);
    assert!(close(theta, 0.6946749125, tol) && close(phi, 1.2165941233, tol));
    assert!(close(theta / PI, 0.2211218923, tol) && close(phi / TAU, 0.1936269685, tol));
    // The surface form at the same circle gives the same point.
    let lambda = net.lambda_at(&0.4).unwrap();
    assert!(close(net.beta_at(&lambda), 0.4, 4.0 * EPS));
    assert!(dist(&net.jet(&1.0, &lambda, 0)[0], &x) < 4.0 * EPS);
}

/// The 7×9 grid of §16.15: `β` in 7 steps over `[0, 2Ψ]`, `α` in 9 over `[0, 2π]`.
fn grid(psi: f64) -> Vec<(f64, f64)> {
    let mut g = Vec::new();
    for i in 0..7 {
        for j in 0..9 {
            g.push((TAU * j as f64 / 8.0, 2.0 * psi * i as f64 / 6.0));
        }
    }
    g
}

#[test]
fn worked_example_grid_stays_on_the_sphere() {
    let net = example_net();
    let psi = net.psi(&0.0);
    let worst = grid(psi)
        .into_iter()
        .map(|(a, b)| (norm(&net.point_at_beta(&a, &b).unwrap()) - 1.0).abs())
        .fold(0.0, f64::max);
    assert!(worst <= 4.5e-16, "max ||X| − 1| = {worst:e}");
    // X(α, 0) = P₁, X(α, 2Ψ) = P₂ for every α.
    let fr = net.frame(&0.0f64);
    let p2 = sphere_point(&EXAMPLE[1][0], &EXAMPLE[1][1]);
    for j in 0..9 {
        let a = TAU * j as f64 / 8.0;
        assert_eq!(net.point_at_beta(&a, &0.0).unwrap(), fr.n1);
        assert!(dist(&net.point_at_beta(&a, &(2.0 * psi)).unwrap(), &p2) < 4.0 * EPS);
    }
}

/// [S]'s `P` lies in `Σ₁` but not in `Σ₂` (`P·(−N₂) = 0.5`), and the points it
/// generates leave the sphere by up to 0.5154 on the grid; the corrected one gives the
/// sphere to 256 bits. Both through the literal (14.4)–(14.6).
#[test]
fn source_pole_point_leaves_the_sphere() {
    let max_off = |which| {
        let t = Truth::new(EXAMPLE[0], EXAMPLE[1], which);
        let psi = t.psi.to_f64();
        let minus_n2 = t.n2.clone().map(|x| -x);
        let on_sigma2 = dotv(&t.p, &minus_n2).to_f64();
        let on_sigma1 = dotv(&t.p, &t.n1).to_f64();
        let worst = grid(psi)
            .into_iter()
            .map(|(a, b)| {
                let x = t.point(a, &(f(b)));
                (dotv(&x, &x).sqrt() - f(1.0)).abs().to_f64()
            })
            .fold(0.0, f64::max);
        (to_f64(&t.p), on_sigma1, on_sigma2, worst)
    };
    let (p, s1, s2, worst) = max_off(Which::Source);
    assert!(dist(&p, &[1.0392304845, 0.6928203230, 0.2]) < 1e-10);
    assert!(close(s1, 1.0, 1e-60) && close(s2, 0.5, 1e-60));
    assert!(close(worst, 0.5154, 5e-5), "[S]: {worst}");
    let (p, s1, s2, worst) = max_off(Which::Corrected);
    assert!(dist(&p, &[1.1547005384, 1.1547005384, 0.0]) < 1e-10);
    assert!(close(s1, 1.0, 1e-60) && close(s2, 1.0, 1e-60));
    // The grid's last β is 2Ψ rounded to a double, up to 1e-17 beyond the pencil's
    // range; (14.4)'s radius is clamped at 0 there.
    assert!(worst < 1e-15, "corrected: {worst:e}");
}

// ---------------------------------------------------------------------------------
// Families.

/// A seeded pole pair: generic, near-antipodal or near-equal (angle `10^-k` off,
/// `k ∈ [1, max_k]`, `max_k ≤ 9`: above `δ_ang = 1e-10`), as library parameters.
fn pole_pair(rng: &mut Rng, kind: usize, max_k: f64) -> ([f64; 2], [f64; 2]) {
    let p1 = random_unit(rng);
    let off = 10f64.powf(-range(rng, 1.0, max_k));
    let p2 = match kind {
        0 => random_unit(rng),
        1 => at_angle(p1.map(|x| -x), off, rng),
        _ => at_angle(p1, off, rng),
    };
    (params_of(p1), params_of(p2))
}

/// `|P₁ × P₂|` of the exact poles (rug), the conditioning of `E₁`.
fn sin_gamma(t: &Truth) -> f64 {
    let c = crossv(&t.n2, &t.n1);
    dotv(&c, &c).sqrt().to_f64()
}

#[test]
fn families_stay_on_the_sphere_and_match_the_truth() {
    let mut rng = Rng::new(0x1717_0001);
    let mut checked = [0usize; 3];
    for case in 0..300 {
        let kind = case % 3;
        let (q1, q2) = pole_pair(&mut rng, kind, 9.0);
        let net = PencilNet::new(Pole::Params(q1), Pole::Params(q2)).unwrap();
        assert_eq!(net.kind(), NetKind::Pencil, "case {case}");
        let truth = Truth::new(q1, q2, Which::Corrected);
        let sg = sin_gamma(&truth);
        let psi = net.psi(&0.0);
        let psi_m = net.psi(&m(0.0));
        let off = (psi_m.clone() - MpfrInterval::from_float(&truth.psi, BITS)).mag();
        assert!(
            off < 1e-60,
            "case {case}: Ψ enclosure misses the truth by {off:e}"
        );
        for _ in 0..6 {
            let alpha = range(&mut rng, 0.0, TAU);
            let beta = range(&mut rng, 0.0, 2.0 * psi);
            let t = truth.point(alpha, &f(beta));
            // f64: on the sphere to a few ulps, at the truth to the conditioning.
            let x = net.point_at_beta(&alpha, &beta).unwrap();
            let r = norm(&x) - 1.0;
            assert!(
                r.abs() <= 4.0 * EPS,
                "case {case} kind {kind}: |X| − 1 = {r:e}"
            );
            let err = dist(&x, &to_f64(&t));
            assert!(
                err <= 64.0 * EPS / sg,
                "case {case} kind {kind}: {err:e} (sin γ {sg:e})"
            );
            // MPFR through the library's generic formula: on the sphere, at the truth.
            let xm = net.point_at_beta(&m(alpha), &m(beta)).unwrap();
            let n = norm_sq_minus_one(&xm);
            assert!(n.contains_zero() && n.mag() < 1e-60, "case {case}: {n:?}");
            // The literal truth cancels |P| ~ 1/sin Ψ (up to 1e9 here) and takes
            // √(1 − ratio²) near ρ = 0: good to ~1e-30 at 256 bits, not to 1e-77.
            assert!(
                outside(&xm, &t) < 1e-25,
                "case {case}: MPFR point misses the truth"
            );
            // The surface form on the same circle.
            let lambda = net.lambda_at(&m(beta)).unwrap();
            let xj = net.jet(&m(alpha), &lambda, 0).swap_remove(0);
            assert!(
                outside(&xj, &t) < 1e-25,
                "case {case}: jet misses the truth"
            );
            let n = norm_sq_minus_one(&xj);
            assert!(n.contains_zero() && n.mag() < 1e-60);
            let xf = net.jet(&alpha, &lambda.mid(), 0).swap_remove(0);
            assert!((norm(&xf) - 1.0).abs() <= 4.0 * EPS);
            // The way back (14.7) against the truth's arccos/atan2.
            let (theta, phi) = way_back(&t);
            let (u, v) = unit_params(&xm);
            let dphi = (u - MpfrInterval::from_float(&phi, BITS)).mag();
            let dphi = dphi.min((dphi - TAU).abs());
            let dtheta = (m(FRAC_PI_2) - v - MpfrInterval::from_float(&theta, BITS)).mag();
            assert!(dtheta < 1e-15, "case {case}: ϑ off by {dtheta:e}");
            if theta.to_f64().sin() > 1e-6 {
                assert!(dphi < 1e-9, "case {case}: φ off by {dphi:e}");
            }
        }
        // The poles: β = 0 and β = 2Ψ, λ = ±π/2.
        let fr = net.frame(&0.0f64);
        let (p1, p2) = (to_f64(&truth.n1), to_f64(&truth.n2).map(|x| -x));
        for alpha in [0.0, 1.0, 4.0] {
            assert_eq!(net.point_at_beta(&alpha, &0.0).unwrap(), fr.n1);
            let at_far = net.point_at_beta(&alpha, &(2.0 * psi)).unwrap();
            assert!(
                dist(&at_far, &p2) <= 64.0 * EPS / sg,
                "case {case}: X(α, 2Ψ)"
            );
            let top = net.jet(&alpha, &FRAC_PI_2, 0).swap_remove(0);
            let bottom = net.jet(&alpha, &-FRAC_PI_2, 0).swap_remove(0);
            assert!(dist(&top, &p1) <= 4.0 * EPS, "case {case}: λ = π/2");
            assert!(
                dist(&bottom, &p2) <= 64.0 * EPS / sg,
                "case {case}: λ = −π/2"
            );
        }
        checked[kind] += 1;
    }
    assert_eq!(checked, [100, 100, 100]);
}

/// Antipodal poles (exactly, and within `δ_ang`): spherical coordinates with axis `P₁`;
/// equal poles: a typed error naming `pole2`; bad input: typed errors naming the field.
#[test]
fn degenerate_pole_pairs() {
    let mut rng = Rng::new(0x1717_0002);
    for case in 0..50 {
        let p1 = random_unit(&mut rng);
        let p2 = if case % 2 == 0 {
            p1.map(|x| -x)
        } else {
            at_angle(p1.map(|x| -x), 1e-12, &mut rng)
        };
        let net = PencilNet::new(Pole::Direction(p1), Pole::Direction(p2)).unwrap();
        assert_eq!(net.kind(), NetKind::Antipodal);
        assert!(net.point_at_beta(&0.5, &0.1).is_none() && net.pencil_point(&0.0).is_none());
        let fr = net.frame(&m(0.0));
        let axis = p1.map(|x| x / norm(&p1));
        for _ in 0..5 {
            let (alpha, lambda) = (
                range(&mut rng, 0.0, TAU),
                range(&mut rng, -FRAC_PI_2, FRAC_PI_2),
            );
            let x = net.jet(&m(alpha), &m(lambda), 0).swap_remove(0);
            let n = norm_sq_minus_one(&x);
            assert!(n.contains_zero() && n.mag() < 1e-60);
            // The latitude about P₁ is λ: X·N₁ = sin λ.
            let h = x[0].clone() * &fr.n1[0] + x[1].clone() * &fr.n1[1] + x[2].clone() * &fr.n1[2];
            assert!((h - m(lambda).sin()).mag() < 1e-60);
        }
        let bottom = net.jet(&0.3, &-FRAC_PI_2, 0).swap_remove(0);
        assert!(dist(&bottom, &axis.map(|x| -x)) < 4.0 * EPS);
    }
    let err = |p1, p2| PencilNet::new(p1, p2).unwrap_err();
    let p = [0.3, 0.4, 0.5];
    match err(Pole::Direction(p), Pole::Direction(p.map(|x| 2.0 * x))) {
        GeomError::InvalidValue { field, .. } => assert_eq!(field, "pole2"),
        e => panic!("{e:?}"),
    }
    match err(Pole::Params([0.1, 0.2]), Pole::Params([0.1 + 1e-12, 0.2])) {
        GeomError::InvalidValue { field, .. } => assert_eq!(field, "pole2"),
        e => panic!("{e:?}"),
    }
    match err(Pole::Params([f64::NAN, 0.2]), Pole::Params([1.0, 0.2])) {
        GeomError::NonFinite { field, .. } => assert!(field.starts_with("pole1"), "{field}"),
        e => panic!("{e:?}"),
    }
    match err(Pole::Params([0.0, 0.2]), Pole::Direction([0.0; 3])) {
        GeomError::ZeroDirection { field } => assert_eq!(field, "pole2"),
        e => panic!("{e:?}"),
    }
    let part = Sphere::new([0.0; 3], 1.0, None, None)
        .unwrap()
        .with_domain(([0.0, 1.0], [-1.0, 1.0]))
        .unwrap();
    match Repole::new(part, Pole::Params([0.0, 0.0]), Pole::Params([1.0, 0.0])) {
        Err(GeomError::InvalidValue { field, .. }) => assert_eq!(field, "domain"),
        other => panic!("{other:?}"),
    }
}

// ---------------------------------------------------------------------------------
// The re-parametrised surfaces.

const H: f64 = 1.0 / (1u64 << 50) as f64;

fn central(p: &[MpfrInterval; 3], q: &[MpfrInterval; 3]) -> [MpfrInterval; 3] {
    std::array::from_fn(|c| (p[c].clone() - q[c].clone()) / m(2.0 * H))
}

fn far(a: &[MpfrInterval; 3], b: &[MpfrInterval; 3]) -> f64 {
    (0..3)
        .map(|c| (a[c].clone() - b[c].clone()).mag())
        .fold(0.0, f64::max)
}

/// A random sphere and ellipsoid (tilted frames) with a random pole pair.
fn surfaces(rng: &mut Rng) -> (Repole<Sphere>, Repole<Ellipsoid>) {
    let centre = [
        range(rng, -3.0, 3.0),
        range(rng, -3.0, 3.0),
        range(rng, -3.0, 3.0),
    ];
    let axis = random_unit(rng);
    // Near-equal poles only to 1e-3: closer ones make β'' ~ 1/γ³, beyond the
    // central differences' reach (the on-sphere families go to 1e-9).
    let kind = rng.below(3);
    let (q1, q2) = pole_pair(rng, kind, 3.0);
    let sphere = Sphere::new(centre, range(rng, 0.5, 4.0), Some(axis), None).unwrap();
    let abc = [
        range(rng, 0.5, 4.0),
        range(rng, 0.5, 4.0),
        range(rng, 0.5, 4.0),
    ];
    let ellipsoid = Ellipsoid::new(centre, abc, Some(axis), None).unwrap();
    (
        Repole::new(sphere, Pole::Params(q1), Pole::Params(q2)).unwrap(),
        Repole::new(ellipsoid, Pole::Params(q1), Pole::Params(q2)).unwrap(),
    )
}

/// The analytic jet agrees with MPFR central differences (`h = 2⁻⁵⁰`, truncation
/// `O(h²)`), at random parameters and on the new poles.
fn check_derivatives<S: Surface>(s: &S, rng: &mut Rng, label: &str) {
    for k in 0..12 {
        let alpha = range(rng, 0.0, TAU);
        let lambda = match k {
            0 => FRAC_PI_2,
            1 => -FRAC_PI_2,
            _ => range(rng, -FRAC_PI_2, FRAC_PI_2),
        };
        let (ma, ml) = (m(alpha), m(lambda));
        let jet = s.jet(&ma, &ml, 2);
        let at = |da: f64, dl: f64| s.jet(&(ma.clone() + m(da)), &(ml.clone() + m(dl)), 1);
        let (ap, am, lp, lm) = (at(H, 0.0), at(-H, 0.0), at(0.0, H), at(0.0, -H));
        let scale = 1.0 + jet.iter().flatten().map(|x| x.mag()).fold(0.0, f64::max);
        let tol = 1e-24 * scale * scale;
        let checks = [
            (1, central(&ap[0], &am[0])),
            (2, central(&lp[0], &lm[0])),
            (3, central(&ap[1], &am[1])),
            (4, central(&lp[1], &lm[1])),
            (4, central(&ap[2], &am[2])),
            (5, central(&lp[2], &lm[2])),
        ];
        for (i, d) in checks {
            let e = far(&jet[i], &d);
            assert!(e < tol, "{label} entry {i} at ({alpha}, {lambda}): {e:e}");
        }
        if lambda.abs() == FRAC_PI_2 {
            assert!(
                jet[1].iter().all(|x| x.mag() < 1e-15),
                "{label}: s_α ≠ 0 at a pole"
            );
        }
    }
}

#[test]
fn surface_jets_are_derivatives() {
    let mut rng = Rng::new(0x1717_0003);
    for case in 0..30 {
        let (s, e) = surfaces(&mut rng);
        check_derivatives(&s, &mut rng, &format!("sphere {case}"));
        check_derivatives(&e, &mut rng, &format!("ellipsoid {case}"));
    }
}

/// Every point of `R̃` is on the original surface (its implicit equation in the local
/// frame, enclosed at 256 bits, contains 0), `R̃(α, λ) = R(u(α, λ), v(α, λ))` through the
/// way back, and f64 interval jets over small boxes enclose MPFR values inside them.
#[test]
fn surfaces_are_the_original_ones() {
    let mut rng = Rng::new(0x1717_0004);
    for case in 0..30 {
        let (s, e) = surfaces(&mut rng);
        for _ in 0..10 {
            let (alpha, lambda) = (
                range(&mut rng, 0.0, TAU),
                range(&mut rng, -FRAC_PI_2, FRAC_PI_2),
            );
            // Implicit equation of the ellipsoid, in its local frame.
            let x = e.jet(&m(alpha), &m(lambda), 0).swap_remove(0);
            let frame = e.surface().frame();
            let axes = frame.axes(&m(0.0));
            let o = frame.origin();
            let k = e.surface().semi_axes();
            let mut q = m(-1.0);
            for (i, ax) in axes.iter().enumerate() {
                let l = (0..3)
                    .map(|c| (x[c].clone() - m(o[c])) * ax[c].clone())
                    .fold(m(0.0), |a, b| a + b);
                q += (l / m(k[i])).sqr();
            }
            assert!(q.contains_zero() && q.mag() < 1e-55, "case {case}: {q:?}");
            // The way back and the original surface.
            let (u, v) = e.original_params(&alpha, &lambda);
            let direct = e.surface().jet(&u, &v, 0).swap_remove(0);
            let via = e.jet(&alpha, &lambda, 0).swap_remove(0);
            assert!(dist(&direct, &via) < 1e-13, "case {case}: R(u, v) ≠ R̃");
            let (u, v) = s.original_params(&alpha, &lambda);
            let direct = s.surface().jet(&u, &v, 0).swap_remove(0);
            assert!(dist(&direct, &s.jet(&alpha, &lambda, 0)[0]) < 1e-13);
            // Interval enclosure over a box around (α, λ).
            let w = 10f64.powf(-range(&mut rng, 2.0, 8.0));
            let ba = Interval::from_bounds(alpha - w, alpha + w);
            let bl = Interval::from_bounds(lambda - w, (lambda + w).min(FRAC_PI_2));
            let boxed = e.jet(&ba, &bl, 2);
            for _ in 0..4 {
                let pa = range(&mut rng, ba.lo(), ba.hi());
                let pl = range(&mut rng, bl.lo(), bl.hi());
                let exact = e.jet(&m(pa), &m(pl), 2);
                for (bx, ex) in boxed.iter().zip(&exact) {
                    for c in 0..3 {
                        let inner = ex[c].to_interval();
                        assert!(inner.is_subset(&bx[c]), "case {case}: enclosure");
                    }
                }
            }
        }
    }
}
