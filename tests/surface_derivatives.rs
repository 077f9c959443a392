//! Issue 5: the analytic derivatives of every surface primitive agree with
//! high-precision central differences (MPFR intervals at 256 bits, step h = 2⁻⁵⁰) at many
//! random parameters: `s_u = D_u s`, `s_v = D_v s`, `s_uu = D_u s_u`, `s_uv = D_v s_u =
//! D_u s_v`, `s_vv = D_v s_v`. The truncation error is `O(h²) ≈ 10⁻³⁰`; a wrong formula
//! is off by O(1).

mod surface_support;

use geocert::num::{IntervalLike, MpfrInterval, Real};
use geocert::surface::Surface;
use surface_support::{random_params, zoo, Rng, Visit};

const PREC: u32 = 256;
const H: f64 = 1.0 / (1u64 << 50) as f64;

fn m(x: f64) -> MpfrInterval {
    MpfrInterval::point(x, PREC)
}

/// `|a − b|` as an upper bound, componentwise maximum.
fn distance(a: &[MpfrInterval; 3], b: &[MpfrInterval; 3]) -> f64 {
    (0..3)
        .map(|c| (a[c].clone() - b[c].clone()).mag())
        .fold(0.0, f64::max)
}

/// Central difference `(f(x+h) − f(x−h))/(2h)` of a vector.
fn central(plus: &[MpfrInterval; 3], minus: &[MpfrInterval; 3]) -> [MpfrInterval; 3] {
    let two_h = m(2.0 * H);
    std::array::from_fn(|c| (plus[c].clone() - minus[c].clone()) / two_h.clone())
}

struct Derivatives {
    checked: usize,
}

impl Visit for Derivatives {
    fn visit<S: Surface>(&mut self, name: &str, s: &S) {
        let mut rng = Rng(0x5eed_0001 ^ name.len() as u64);
        for _ in 0..40 {
            let (u, v) = random_params(s, &mut rng);
            let (mu, mv) = (m(u), m(v));
            let h = m(H);
            let jet = s.jet(&mu, &mv, 2);
            assert_eq!(jet.len(), 6);
            let at = |du: &MpfrInterval, dv: &MpfrInterval| {
                s.jet(&(mu.clone() + du.clone()), &(mv.clone() + dv.clone()), 1)
            };
            let zero = mu.zero_like();
            let (up, um) = (at(&h, &zero), at(&(-h.clone()), &zero));
            let (vp, vm) = (at(&zero, &h), at(&zero, &(-h.clone())));
            let scale = 1.0 + jet.iter().flatten().map(|x| x.mag()).fold(0.0, f64::max);
            let tol = 1e-24 * scale;
            let checks = [
                ("s_u = D_u s", &jet[1], central(&up[0], &um[0])),
                ("s_v = D_v s", &jet[2], central(&vp[0], &vm[0])),
                ("s_uu = D_u s_u", &jet[3], central(&up[1], &um[1])),
                ("s_uv = D_v s_u", &jet[4], central(&vp[1], &vm[1])),
                ("s_uv = D_u s_v", &jet[4], central(&up[2], &um[2])),
                ("s_vv = D_v s_v", &jet[5], central(&vp[2], &vm[2])),
            ];
            for (what, analytic, difference) in checks {
                let d = distance(analytic, &difference);
                assert!(d <= tol, "{name} at ({u}, {v}): {what} off by {d:e}");
            }
            // Lower orders are prefixes of the full jet.
            let short = s.jet(&mu, &mv, 1);
            assert_eq!(short.len(), 3);
            assert_eq!(
                short[..],
                jet[..3],
                "{name}: the order-1 jet is not a prefix"
            );
            self.checked += 1;
        }
    }
}

#[test]
fn analytic_derivatives_match_mpfr_central_differences() {
    let mut v = Derivatives { checked: 0 };
    zoo(&mut v);
    assert!(v.checked >= 20 * 40);
}

#[test]
fn implicit_gradients_and_hessians_match_central_differences() {
    use geocert::surface::implicit::ImplicitQuadric;
    use geocert::surface::{AnyImplicit, Implicit};
    let mut forms: Vec<(String, AnyImplicit)> = surface_support::any_surfaces()
        .into_iter()
        .filter_map(|(name, s)| s.implicit().map(|f| (name.to_string(), f)))
        .collect();
    let q = [
        [1.0, 0.5, -0.25, 1.0],
        [0.5, -2.0, 0.75, 0.0],
        [-0.25, 0.75, 3.0, -1.5],
        [1.0, 0.0, -1.5, -4.0],
    ];
    forms.push((
        "quadric".into(),
        AnyImplicit::Quadric(ImplicitQuadric::new(q).unwrap()),
    ));
    assert!(forms.len() >= 12);
    let mut rng = Rng(404);
    for (name, f) in &forms {
        for _ in 0..30 {
            let x: [f64; 3] = std::array::from_fn(|_| rng.range(-3.0, 3.0));
            let mx = x.map(m);
            let jet = f.implicit_jet(&mx, 2);
            let (g, hess) = (jet.gradient.unwrap(), jet.hessian.unwrap());
            let scale = 1.0 + jet.value.mag() + g.iter().map(|x| x.mag()).fold(0.0, f64::max);
            for i in 0..3 {
                let shifted = |sign: f64| {
                    let mut y = mx.clone();
                    y[i] = y[i].clone() + m(sign * H);
                    f.implicit_jet(&y, 1)
                };
                let (p, q) = (shifted(1.0), shifted(-1.0));
                let two_h = m(2.0 * H);
                let dv = (p.value.clone() - q.value.clone()) / two_h.clone();
                assert!(
                    (dv - g[i].clone()).mag() <= 1e-24 * scale,
                    "{name}: ∂F/∂x{i}"
                );
                let (pg, qg) = (p.gradient.unwrap(), q.gradient.unwrap());
                for j in 0..3 {
                    let d = (pg[j].clone() - qg[j].clone()) / two_h.clone();
                    assert!(
                        (d - hess[j][i].clone()).mag() <= 1e-24 * scale,
                        "{name}: H[{j}][{i}]"
                    );
                }
            }
            assert!(f.implicit_jet(&x, 0).gradient.is_none());
        }
    }
}
