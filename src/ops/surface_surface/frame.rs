//! The local geometry of the intersection at a point `P = (u, v, a, b)` (OPERATIONS.md
//! §9.3): the unit normals, the tangent (9.2), the allowed parameter steps of §2.2, the
//! guarded displacement radius (9.3), the contravariant predictor (9.4), the fixed
//! parameter (9.5) and the curvature of the intersection curve, float only.

use super::operand::Pair;
use crate::num::vector::{cross, dot, norm_f64};
use crate::surface::Surface;

/// `κ_r` of the §9.3 guard: terms of (9.3) whose direction makes `|x̂_i·t̂| < κ_r·max`
/// are left out of the minimum (impl, §9.3).
pub const KAPPA_R: f64 = 0.25;

/// The local geometry at one point.
#[derive(Debug, Clone)]
pub struct LocalFrame {
    pub x: [f64; 4],
    /// `r(u, v)` and `s(a, b)`.
    pub pr: [f64; 3],
    pub ps: [f64; 3],
    /// The jets of order 2 of `r` at `(u, v)` and `s` at `(a, b)`.
    pub jr: Vec<[f64; 3]>,
    pub js: Vec<[f64; 3]>,
    /// Unit normals `n̂_r`, `n̂_s`.
    pub nr: [f64; 3],
    pub ns: [f64; 3],
    /// `n̂_r × n̂_s` (not normalised) and its length (the sine of the surfaces' angle).
    pub cross: [f64; 3],
    pub sin: f64,
    /// The oriented unit tangent `t̂` (9.2).
    pub tangent: [f64; 3],
    /// The parameter velocity `(u', v', a', b')` for unit speed along `t̂` ((10.5)–(10.6),
    /// the contravariant form of (9.4)).
    pub velocity: [f64; 4],
}

fn unit(a: [f64; 3]) -> [f64; 3] {
    let n = norm_f64(&a);
    a.map(|c| c / n)
}

/// `(g^{11} t·x₁ + g^{12} t·x₂, g^{21} t·x₁ + g^{22} t·x₂)`: the parameter velocity of a
/// surface for the space velocity `t` ((10.5); §9.3 contravariant predictor).
pub fn contravariant(j: &[[f64; 3]], t: &[f64; 3]) -> [f64; 2] {
    let (g11, g12, g22) = (dot(&j[1], &j[1]), dot(&j[1], &j[2]), dot(&j[2], &j[2]));
    let g = g11 * g22 - g12 * g12;
    let (a, b) = (dot(t, &j[1]), dot(t, &j[2]));
    [(g22 * a - g12 * b) / g, (g11 * b - g12 * a) / g]
}

impl LocalFrame {
    /// The frame at `x`; the tangent is `σ n̂_r × n̂_s` (9.2), flipped to agree with
    /// `reference` when one is given (direction continuity, §9.3).
    pub fn at<R: Surface, S: Surface>(
        pair: &Pair<'_, R, S>,
        x: [f64; 4],
        sigma: f64,
        reference: Option<[f64; 3]>,
    ) -> LocalFrame {
        let jr = pair.r.jet(&x[0], &x[1], 2);
        let js = pair.s.jet(&x[2], &x[3], 2);
        let nr = crate::surface::differential::unit_normal(&jr);
        let ns = crate::surface::differential::unit_normal(&js);
        let w = cross(&nr, &ns);
        let sin = norm_f64(&w);
        let mut tangent = unit(w.map(|c| sigma * c));
        if let Some(r) = reference {
            if dot(&tangent, &r) < 0.0 {
                tangent = tangent.map(|c| -c);
            }
        }
        let [du, dv] = contravariant(&jr, &tangent);
        let [da, db] = contravariant(&js, &tangent);
        LocalFrame {
            x,
            pr: jr[0],
            ps: js[0],
            nr,
            ns,
            cross: w,
            sin,
            tangent,
            velocity: [du, dv, da, db],
            jr,
            js,
        }
    }

    /// The space point (1.21).
    pub fn point(&self) -> [f64; 3] {
        std::array::from_fn(|i| 0.5 * (self.pr[i] + self.ps[i]))
    }

    /// The derivative vectors `x_i ∈ {r_u, r_v, s_a, s_b}`.
    pub fn directions(&self) -> [[f64; 3]; 4] {
        [self.jr[1], self.jr[2], self.js[1], self.js[2]]
    }

    /// (9.3) with the guard of §9.3/§16.16: `r₀ = min |Δ_i x_i·t̂|` over the terms with
    /// `|x̂_i·t̂| ≥ κ_r·max_j |x̂_j·t̂|` (a term ⊥ t̂ would make it 0).
    pub fn guarded_radius(&self, allowed: &[f64; 4]) -> f64 {
        let dirs = self.directions();
        let cosines: [f64; 4] = std::array::from_fn(|i| {
            let n = norm_f64(&dirs[i]);
            if n > 0.0 {
                dot(&dirs[i], &self.tangent).abs() / n
            } else {
                0.0
            }
        });
        let top = cosines.iter().copied().fold(0.0, f64::max);
        (0..4)
            .filter(|&i| cosines[i] >= KAPPA_R * top && cosines[i] > 0.0)
            .map(|i| (allowed[i] * dot(&dirs[i], &self.tangent)).abs())
            .fold(f64::INFINITY, f64::min)
    }

    /// The literal (9.3) without the guard (for the §16.16 check).
    #[cfg(test)]
    pub fn literal_radius(&self, allowed: &[f64; 4]) -> f64 {
        let dirs = self.directions();
        (0..4)
            .map(|i| (allowed[i] * dot(&dirs[i], &self.tangent)).abs())
            .fold(f64::INFINITY, f64::min)
    }

    /// (9.5): the parameter whose derivative vector makes the smallest angle with `t̂`.
    pub fn fixed_parameter(&self) -> usize {
        let dirs = self.directions();
        let score = |i: usize| {
            let n = norm_f64(&dirs[i]);
            if n > 0.0 {
                dot(&dirs[i], &self.tangent).abs() / n
            } else {
                0.0
            }
        };
        (0..4)
            .max_by(|&a, &b| score(a).total_cmp(&score(b)))
            .unwrap_or(0)
    }

    /// The contravariant predictor (9.4): `x + h·(u', v', a', b')`.
    pub fn predict(&self, h: f64) -> [f64; 4] {
        std::array::from_fn(|i| self.x[i] + h * self.velocity[i])
    }

    /// The curvature of the intersection curve: its curvature vector lies in the normal
    /// plane with `κ⃗·n̂_r = k_r`, `κ⃗·n̂_s = k_s` (the normal curvatures in the direction
    /// `t̂`, (1.9)), so `|κ⃗|² = (k_r² + k_s² − 2 k_r k_s cos θ)/sin²θ`.
    pub fn curvature(&self) -> f64 {
        let normal_curvature = |j: &[[f64; 3]], n: &[f64; 3], d: [f64; 2]| {
            let second: [f64; 3] = std::array::from_fn(|i| {
                j[3][i] * d[0] * d[0] + 2.0 * j[4][i] * d[0] * d[1] + j[5][i] * d[1] * d[1]
            });
            dot(n, &second)
        };
        let v = self.velocity;
        let kr = normal_curvature(&self.jr, &self.nr, [v[0], v[1]]);
        let ks = normal_curvature(&self.js, &self.ns, [v[2], v[3]]);
        let c = dot(&self.nr, &self.ns);
        let s2 = self.sin * self.sin;
        let k2 = (kr * kr + ks * ks - 2.0 * kr * ks * c) / s2;
        if k2.is_finite() {
            k2.max(0.0).sqrt()
        } else {
            f64::INFINITY
        }
    }
}

/// The allowed parameter steps `[Δu, Δv, Δa, Δb]` (§2.2 with `Δα_march` and clamps).
pub fn allowed_steps<R: Surface, S: Surface>(pair: &Pair<'_, R, S>, x: &[f64; 4]) -> [f64; 4] {
    let [du, dv] = pair.steppers.0.steps(x[0], x[1]);
    let [da, db] = pair.steppers.1.steps(x[2], x[3]);
    [du, dv, da, db]
}

/// The chord `h` for the next step: the guarded `r₀` (9.3), capped so that the tangent
/// turns by at most `Δα` and the chord stays within the chord tolerance on a circle of
/// the local curvature `κ` (sagitta `h²κ/8`), clamped to `[r_min, r_max]`.
pub fn step_length<R: Surface, S: Surface>(pair: &Pair<'_, R, S>, frame: &LocalFrame) -> f64 {
    let allowed = allowed_steps(pair, &frame.x);
    let mut h = frame.guarded_radius(&allowed);
    let k = frame.curvature();
    if k > 0.0 {
        h = h.min(pair.options.delta_alpha / k);
        h = h.min((8.0 * chord_tolerance(pair) / k).sqrt());
    }
    let (lo, hi) = (pair.options.min_step * pair.length, pair.length / 4.0);
    if h.is_nan() {
        return lo;
    }
    h.clamp(lo, hi)
}

/// The chord tolerance (option, default `10⁻⁴ L`).
pub fn chord_tolerance<R, S>(pair: &Pair<'_, R, S>) -> f64 {
    pair.options.chord_tolerance.unwrap_or(1e-4 * pair.length)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ops::surface_surface::Options;
    use crate::surface::plane::Plane;
    use crate::surface::quadrics::Cylinder;

    /// §16.16: cylinder `(cos u, sin u, v)` ∩ plane `z = 0.5` at `u = 0.3`, `Δα = π/20`,
    /// `Δv = Δa = Δb = 1`: the literal (9.3) is 0, the guarded one `π/20`.
    #[test]
    fn the_guard_of_16_16() {
        let cyl = Cylinder::new([0.0; 3], [1.0, 1.0], [0.0, 0.0, 1.0], None, [0.0, 1.0]).unwrap();
        let plane = Plane::new([0.0, 0.0, 0.5], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0])
            .unwrap()
            .with_domain(([-2.0, 2.0], [-2.0, 2.0]))
            .unwrap();
        let opts = Options::default();
        let pair = Pair::new(&cyl, &plane, &opts).unwrap();
        let u = 0.3f64;
        let f = LocalFrame::at(&pair, [u, 0.5, u.cos(), u.sin()], 1.0, None);
        let t = f.tangent;
        assert!(
            (t[0].abs() - 0.2955202067).abs() < 1e-10 && (t[1].abs() - 0.9553364891).abs() < 1e-10
        );
        let allowed = [std::f64::consts::PI / 20.0, 1.0, 1.0, 1.0];
        let terms: Vec<f64> = f
            .directions()
            .iter()
            .zip(allowed)
            .map(|(x, d)| (d * dot(x, &t)).abs())
            .collect();
        let expected = [0.1570796327, 0.0, 0.2955202067, 0.9553364891];
        for (a, b) in terms.iter().zip(expected) {
            assert!((a - b).abs() < 1e-10, "{terms:?}");
        }
        assert_eq!(f.literal_radius(&allowed), 0.0);
        assert!((f.guarded_radius(&allowed) - std::f64::consts::PI / 20.0).abs() < 1e-15);
    }
}
