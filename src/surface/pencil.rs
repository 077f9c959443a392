//! New poles on the unit sphere (OPERATIONS.md §14.2, with the corrected (14.5)): the
//! net of circles cut from the sphere by the pencil of planes through the line
//! `ℓ = Σ₁ ∩ Σ₂` of the tangent planes at two chosen points `P₁`, `P₂`.
//!
//! # The formulas, and the form they are evaluated in
//!
//! (14.2): `N₁ = P₁`, `N₂ = −P₂`, `E₁ = N₂×N₁/|N₂×N₁| = P₁×P₂/|P₁×P₂|`,
//! `L₁ = N₁×E₁/|N₁×E₁|`; then `P₂ = cos γ N₁ − sin γ L₁` (`γ = ∠P₁OP₂`), and (14.3)
//! `Ψ = ½ arccos(L₁·L₂) = (π − γ)/2`, so `sin Ψ = cos(γ/2) = |P₁ + P₂|/2` and
//! `cos Ψ = sin(γ/2) = |P₁ − P₂|/2` (both well conditioned, unlike the arccos).
//!
//! The corrected point of `ℓ` (14.5) is `P = N₁ − cot Ψ L₁`. The plane of the pencil at
//! angle `β` from `Σ₁` contains `ℓ` and has the unit normal `n(β) = sin β L₁ + cos β N₁`;
//! its distance from the centre is `d(β) = P·n(β) = sin(Ψ − β)/sin Ψ`. The centre (14.4)
//! is `C = P + k(cos β L₁ − sin β N₁)` with `k = cos(Ψ − β)/sin Ψ`, which equals
//! `d(β) n(β)`, and `H₁ = (P − C)/|P − C| = m(β) = −cos β L₁ + sin β N₁` (`k > 0` for
//! `β ∈ [0, 2Ψ]`). So (14.6) reads
//!
//! `X(α, β) = d(β) n(β) + ρ(β) (cos α m(β) + sin α E₁)`,  `ρ = √(1 − d²)`,
//!
//! a combination of three orthonormal vectors with `d² + ρ² = 1`: `|X| = 1` up to
//! rounding for every pole pair, where the literal (14.4)–(14.6) cancel the large `P`
//! (`|P| = 1/sin Ψ`) against `C` near antipodal poles. The test suite checks the two
//! forms against each other at 256 bits (tests/poles_repole.rs).
//!
//! # The parameters of the net as a surface
//!
//! `β` runs linearly between the pencil's planes, and `ρ(β) ~ √β` at the poles, so
//! `X_β` is unbounded there (spec normalisation `β = 2Ψu'/u_p`). The surface form uses
//! instead the latitude `λ ∈ [−π/2, π/2]` of the circle, `sin λ = d(β)`, i.e.
//! `β = Ψ − μ`, `sin μ = sin Ψ sin λ`; then `ρ = cos λ` and
//!
//! `X(α, λ) = sin λ n(β) + cos λ (cos α m(β) + sin α E₁)`
//!
//! is smooth up to the poles (`λ = π/2` is `P₁`, `λ = −π/2` is `P₂`, and `X_α = 0`
//! there), like the library's sphere `(cos v cos u, cos v sin u, sin v)`. With
//! `cos μ = √(1 − sin²Ψ sin²λ) = √(cos²Ψ + sin²Ψ cos²λ) ≥ cos Ψ > 0`: `cos β = cos Ψ cos μ + sin Ψ sin μ`,
//! `sin β = sin Ψ cos μ − cos Ψ sin μ`, `β' = −sin Ψ cos λ / cos μ`,
//! `β'' = sin Ψ cos²Ψ sin λ / cos³μ`; and `n' = −β' m`, `m' = β' n`.
//!
//! Antipodal poles (`|P₁ × P₂| ≤ δ_ang`, `P₁·P₂ < 0`): §14.2 falls back to ordinary
//! spherical coordinates with axis `P₁`; that is the formula above with `Ψ = 0` (then
//! `β ≡ 0`, `X = sin λ N₁ + cos λ(−cos α L₁ + sin α E₁)`), `E₁` made from the
//! coordinate axis least aligned with `P₁` instead of `P₂`, which is then `−P₁`.
//!
//! # Enclosures
//!
//! The poles are kept as given (exact doubles). For an interval type every quantity is
//! computed from them by enclosing [`Real`] operations, so it encloses the exact
//! quantity of the exact poles; the identities used (`E₁ = L₁ × N₁`, the half-angle
//! lengths) are exact, so the enclosures hold the exact net. For `f64` the frame is
//! evaluated once by the same formula and cached.

use crate::error::{require_finite_all, GeomError};
use crate::num::vector::{add, add_scaled, cross, dot, lift, norm_sq, normalize, scale, sub};
use crate::num::Real;

/// `δ_ang` of OPERATIONS.md §12: poles with `|P₁ × P₂|` at or below it are antipodal
/// or equal (§14.2).
pub const POLE_ANGLE_TOL: f64 = 1e-10;

/// A new pole, as given.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Pole {
    /// The parameters `(u, v)` of the sphere map (14.1) in the library's convention:
    /// the point `(cos v cos u, cos v sin u, sin v)`.
    Params([f64; 2]),
    /// A direction (any non-zero length), normalised in the evaluation's number type.
    Direction([f64; 3]),
}

impl Pole {
    /// The unit vector of the pole, enclosing the exact one for interval types.
    pub fn unit<T: Real>(&self, like: &T) -> [T; 3] {
        match self {
            Pole::Params([u, v]) => sphere_point(&like.lift(*u), &like.lift(*v)),
            Pole::Direction(d) => normalize(&lift(like, d)),
        }
    }

    fn validate(&self, field: &str) -> Result<(), GeomError> {
        match self {
            Pole::Params(p) => require_finite_all(field, p),
            Pole::Direction(d) => {
                require_finite_all(field, d)?;
                // |d|² must be a positive finite double for the f64 frame.
                let n = d.iter().map(|x| x * x).sum::<f64>();
                if n > 0.0 && n.is_finite() {
                    Ok(())
                } else {
                    Err(GeomError::ZeroDirection {
                        field: field.into(),
                    })
                }
            }
        }
    }
}

/// The unit-sphere point of the library's sphere map, (14.1) with `ϑ = π/2 − v` and
/// `φ = u`: `S = (cos v cos u, cos v sin u, sin v)`.
pub fn sphere_point<T: Real>(u: &T, v: &T) -> [T; 3] {
    let cv = v.cos();
    [cv.clone() * u.cos(), cv * u.sin(), v.sin()]
}

/// Which net §14.2 builds.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum NetKind {
    /// The pencil of planes through `ℓ` (distinct, non-antipodal poles).
    Pencil,
    /// `P₂ = −P₁` within `δ_ang`: spherical coordinates with axis `P₁`; the second pole
    /// is `−P₁`.
    Antipodal,
}

/// The orthonormal frame `N₁, L₁, E₁` and `sin Ψ`, `cos Ψ` of a pole pair.
#[derive(Debug, Clone, PartialEq)]
pub struct PoleFrame<T> {
    pub n1: [T; 3],
    pub l1: [T; 3],
    pub e1: [T; 3],
    pub sin_psi: T,
    pub cos_psi: T,
}

impl<T: Real> PoleFrame<T> {
    /// `Ψ` (14.3), in `[0, π/2)`.
    pub fn psi(&self) -> T {
        self.sin_psi.atan2(&self.cos_psi)
    }
}

/// The circle net of two new poles on the unit sphere (module doc).
#[derive(Debug, Clone, PartialEq)]
pub struct PencilNet {
    poles: [Pole; 2],
    kind: NetKind,
    /// The vector `E₁` is made from together with `P₁`: `P₂` for a pencil, a coordinate
    /// axis for the antipodal fallback.
    partner: Option<[f64; 3]>,
    cached: PoleFrame<f64>,
}

impl PencilNet {
    /// The net with new poles `pole1` (`P₁`, at `λ = π/2`) and `pole2` (`P₂`, at
    /// `λ = −π/2`). Errors name `pole1`/`pole2`: `non_finite`, `zero_direction`, and
    /// `invalid_value` on `pole2` when the poles coincide within `δ_ang`.
    pub fn new(pole1: Pole, pole2: Pole) -> Result<PencilNet, GeomError> {
        pole1.validate("pole1")?;
        pole2.validate("pole2")?;
        let (p1, p2) = (pole1.unit(&0.0f64), pole2.unit(&0.0f64));
        let c = norm_sq(&cross(&p1, &p2)).sqrt();
        let (kind, partner) = if c > POLE_ANGLE_TOL {
            (NetKind::Pencil, None)
        } else if dot(&p1, &p2) > 0.0 {
            return Err(GeomError::InvalidValue {
                field: "pole2".into(),
                reason: format!(
                    "the new poles coincide (|P1 x P2| = {c:e} <= {POLE_ANGLE_TOL:e}): \
                     every circle of the pencil would touch the others there"
                ),
            });
        } else {
            (NetKind::Antipodal, Some(least_aligned_axis(&p1)))
        };
        let mut net = PencilNet {
            poles: [pole1, pole2],
            kind,
            partner,
            cached: PoleFrame {
                n1: [0.0; 3],
                l1: [0.0; 3],
                e1: [0.0; 3],
                sin_psi: 0.0,
                cos_psi: 0.0,
            },
        };
        net.cached = net.compute_frame(&0.0f64);
        Ok(net)
    }

    pub fn kind(&self) -> NetKind {
        self.kind
    }

    pub fn poles(&self) -> [Pole; 2] {
        self.poles
    }

    /// The frame (module doc), cached for `f64`, else computed in `T`.
    pub fn frame<T: Real>(&self, like: &T) -> PoleFrame<T> {
        if T::IS_F64 {
            let c = &self.cached;
            return PoleFrame {
                n1: lift(like, &c.n1),
                l1: lift(like, &c.l1),
                e1: lift(like, &c.e1),
                sin_psi: like.lift(c.sin_psi),
                cos_psi: like.lift(c.cos_psi),
            };
        }
        self.compute_frame(like)
    }

    fn compute_frame<T: Real>(&self, like: &T) -> PoleFrame<T> {
        let p1 = self.poles[0].unit(like);
        let w = match self.partner {
            Some(axis) => lift(like, &axis),
            None => self.poles[1].unit(like),
        };
        // E₁ ∝ N₂ × N₁ = P₁ × P₂ (or P₁ × axis), L₁ = N₁ × E₁/|·|, E₁ = L₁ × N₁ exactly.
        let l1 = normalize(&cross(&p1, &cross(&p1, &w)));
        let e1 = cross(&l1, &p1);
        let half = like.lift(0.5);
        let (sin_psi, cos_psi) = match self.kind {
            NetKind::Antipodal => (like.zero_like(), like.one_like()),
            NetKind::Pencil => {
                let p2 = w;
                (
                    norm_sq(&add(&p1, &p2)).sqrt() * &half,
                    norm_sq(&sub(&p1, &p2)).sqrt() * &half,
                )
            }
        };
        PoleFrame {
            n1: p1,
            l1,
            e1,
            sin_psi,
            cos_psi,
        }
    }

    /// `Ψ` (14.3); `0` for the antipodal net.
    pub fn psi<T: Real>(&self, like: &T) -> T {
        self.frame(like).psi()
    }

    /// The corrected point `P` of `ℓ` (14.5), `P = N₁ − ((N₁+N₂)·N₂)/(L₁·N₂) L₁`, as
    /// written; `None` for the antipodal net (`ℓ` at infinity).
    pub fn pencil_point<T: Real>(&self, like: &T) -> Option<[T; 3]> {
        if self.kind == NetKind::Antipodal {
            return None;
        }
        let f = self.frame(like);
        let n2 = scale(&like.lift(-1.0), &self.poles[1].unit(like));
        let c = dot(&add(&f.n1, &n2), &n2) / dot(&f.l1, &n2);
        Some(add_scaled(&f.n1, &-c, &f.l1))
    }

    /// `β` (the pencil angle from `Σ₁`) of the circle at latitude `λ`:
    /// `β = Ψ − asin(sin Ψ sin λ)`.
    pub fn beta_at<T: Real>(&self, lambda: &T) -> T {
        let f = self.frame(lambda);
        let q = f.sin_psi.clone() * lambda.sin();
        let cm = (f.cos_psi.sqr() + (f.sin_psi.clone() * lambda.cos()).sqr()).sqrt();
        f.psi() - q.atan2(&cm)
    }

    /// The latitude `λ` of the circle at pencil angle `β ∈ [0, 2Ψ]`:
    /// `sin λ = sin(Ψ − β)/sin Ψ`; `None` for the antipodal net.
    pub fn lambda_at<T: Real>(&self, beta: &T) -> Option<T> {
        if self.kind == NetKind::Antipodal {
            return None;
        }
        let (d, rho) = height_radius(&self.frame(beta), beta);
        Some(d.atan2(&rho))
    }

    /// (14.4)–(14.6) in the spec's parameters `(α, β)`, `β ∈ [0, 2Ψ]` (module doc:
    /// `X = d n + ρ (cos α m + sin α E₁)`); `None` for the antipodal net, whose pencil
    /// is degenerate (use [`PencilNet::jet`]).
    pub fn point_at_beta<T: Real>(&self, alpha: &T, beta: &T) -> Option<[T; 3]> {
        if self.kind == NetKind::Antipodal {
            return None;
        }
        let f = self.frame(alpha);
        let (d, rho) = height_radius(&f, beta);
        let (n, m) = rotating_pair(&f, &beta.cos(), &beta.sin());
        let circle = add_scaled(&scale(&alpha.cos(), &m), &alpha.sin(), &f.e1);
        Some(add_scaled(&scale(&d, &n), &rho, &circle))
    }

    /// `X(α, λ)` and its partial derivatives up to `order` (0, 1, 2) in the order
    /// `[X, X_α, X_λ, X_αα, X_αλ, X_λλ]` (the [`crate::surface::Surface::jet`] order with
    /// `u = α`, `v = λ`); module doc for the formulas.
    pub fn jet<T: Real>(&self, alpha: &T, lambda: &T, order: usize) -> Vec<[T; 3]> {
        let f = self.frame(alpha);
        let (ca, sa) = (alpha.cos(), alpha.sin());
        let (cl, sl) = (lambda.cos(), lambda.sin());
        let (s, c) = (&f.sin_psi, &f.cos_psi);
        // μ = asin(sin Ψ sin λ), β = Ψ − μ.
        // cos²μ = 1 − sin²Ψ sin²λ = cos²Ψ + sin²Ψ cos²λ: no cancellation near
        // coinciding poles (cos Ψ → 0), where 1 − sin²μ would lose every digit.
        let sin_mu = s.clone() * &sl;
        let cos_mu = (c.sqr() + (s.clone() * &cl).sqr()).sqrt();
        let cb = c.clone() * &cos_mu + s.clone() * &sin_mu;
        let sb = s.clone() * &cos_mu - c.clone() * &sin_mu;
        let (n, m) = rotating_pair(&f, &cb, &sb);
        // X = a n + b m + e E₁.
        let a = [sl.clone(), cl.clone(), -sl.clone()]; // a, a_λ, a_λλ
        let b = cl.clone() * &ca;
        let e = cl.clone() * &sa;
        let combine = |a: &T, b: &T, e: &T| add_scaled(&add_scaled(&scale(a, &n), b, &m), e, &f.e1);
        let mut jet = vec![combine(&a[0], &b, &e)];
        if order == 0 {
            return jet;
        }
        let zero = alpha.zero_like();
        let d1 = -(s.clone() * &cl) / &cos_mu; // β'
        let (b_a, e_a) = (-(cl.clone() * &sa), cl.clone() * &ca);
        let (b_l, e_l) = (-(sl.clone() * &ca), -(sl.clone() * &sa));
        jet.push(combine(&zero, &b_a, &e_a));
        jet.push(combine(
            &(a[1].clone() + d1.clone() * &b),
            &(b_l.clone() - d1.clone() * &a[0]),
            &e_l,
        ));
        if order == 1 {
            return jet;
        }
        // β'' = sin Ψ cos²Ψ sin λ / cos³μ.
        let d2 = s.clone() * c.sqr() * &sl / cos_mu.powi(3);
        let two = alpha.lift(2.0);
        jet.push(combine(&zero, &-b.clone(), &-e.clone()));
        jet.push(combine(
            &(d1.clone() * &b_a),
            &(sl.clone() * &sa),
            &-(sl.clone() * &ca),
        ));
        let d1_sq = d1.sqr();
        jet.push(combine(
            &(a[2].clone() + d2.clone() * &b + two.clone() * &d1 * &b_l - d1_sq.clone() * &a[0]),
            &(-b.clone() - d2 * &a[0] - two * &d1 * &a[1] - d1_sq * &b),
            &-e,
        ));
        jet
    }
}

/// The distance `d = sin(Ψ − β)/sin Ψ` of the circle's plane from the centre and the
/// radius `ρ = √(sin β sin(2Ψ − β))/sin Ψ` (`= √(1 − d²)`), both from the stored
/// `sin Ψ`, `cos Ψ`: `β = 0` gives exactly `d = 1`, `ρ = 0` (through `√(1 − d²)` a
/// rounding of `d` would become `ρ ≈ 1e-8`).
fn height_radius<T: Real>(f: &PoleFrame<T>, beta: &T) -> (T, T) {
    let (cb, sb) = (beta.cos(), beta.sin());
    let d = (f.sin_psi.clone() * &cb - f.cos_psi.clone() * &sb) / &f.sin_psi;
    let far = (f.psi() * beta.lift(2.0) - beta).sin();
    let rho = (sb * far).sqrt() / &f.sin_psi;
    (d, rho)
}

/// `n = sin β L₁ + cos β N₁`, `m = −cos β L₁ + sin β N₁` (module doc).
fn rotating_pair<T: Real>(f: &PoleFrame<T>, cb: &T, sb: &T) -> ([T; 3], [T; 3]) {
    let n = add_scaled(&scale(sb, &f.l1), cb, &f.n1);
    let m = add_scaled(&scale(&-cb.clone(), &f.l1), sb, &f.n1);
    (n, m)
}

/// The coordinate unit vector least aligned with `p` (the smallest `|p_i|`, first on
/// ties), as [`crate::surface::frame::Frame`] picks its default `X`.
fn least_aligned_axis(p: &[f64; 3]) -> [f64; 3] {
    let mut i = 0;
    for j in 1..3 {
        if p[j].abs() < p[i].abs() {
            i = j;
        }
    }
    let mut e = [0.0; 3];
    e[i] = 1.0;
    e
}
