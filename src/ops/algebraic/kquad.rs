//! A quadratic `F(t) = A t² + 2B t + C` on a line whose coefficients are polynomials
//! with rational coefficients in one transcendental number `k`, solved with every
//! decision proven (OPERATIONS.md §5.2 with the implicit quadrics of §1.6; issue 14
//! item 4: the apex of a cone, the vertex of a paraboloid).
//!
//! `k` is a cone's `tan α` for its half-angle `α` given as a double: α is a non-zero
//! rational, so `tan α` is transcendental (Lindemann–Weierstrass), and a polynomial in
//! `k` with rational coefficients vanishes at `k` exactly when it is the zero
//! polynomial — decided exactly. A non-zero one has the sign of an MPFR enclosure of
//! its value (Horner's rule on outward-rounded MPFR intervals, `k` enclosed by MPFR's
//! `tan` with directed rounding) once that excludes 0, which happens at some finite
//! precision; a precision cap ends the loop with `None` (the caller then certifies
//! numerically). A surface without `k` (a paraboloid) has constant polynomials and the
//! same proofs.
//!
//! Cases: `A ≡ 0` — a linear equation (`B ≢ 0`: one simple root `−C/2B`; `B ≡ C ≡ 0`:
//! the line lies on the surface, `None`); `D = B² − AC ≡ 0` — one double root `−B/A`
//! (a tangency, or a singular point where the half-gradient `g₀ + t g₁` vanishes, as at
//! a cone's apex); else two simple roots `(−B ± √D)/A` when `D(k) > 0`, none when
//! `D(k) < 0`. A root is kept when it satisfies every affine constraint
//! `z₀ + z₁t ∈ [lo, hi]` (rational data): decided on enclosures, and at a bound `h`
//! exactly — `t_h = (h − z₀)/z₁` is a root iff `F(t_h) ≡ 0` in `k`.

use rug::Rational;

use crate::certify::univariate::Polynomial;
use crate::num::MpfrInterval;

/// The cap on the MPFR precision of the sign decisions.
const CAP: u32 = 4096;

/// An affine constraint `z₀ + z₁ t ∈ [lo, hi]` on a root (closed bounds).
pub(crate) struct Constraint {
    pub(crate) z: [Rational; 2],
    pub(crate) range: [Rational; 2],
}

/// `F(t) = A t² + 2B t + C` with `A, B, C ∈ ℚ[k]`, the half-gradient of the surface on
/// the line `g₀ + t g₁` (per coordinate, in `ℚ[k]`) and the constraints on the roots.
pub(crate) struct KQuad {
    pub(crate) a: Polynomial,
    pub(crate) b: Polynomial,
    pub(crate) c: Polynomial,
    pub(crate) grad: [[Polynomial; 2]; 3],
    pub(crate) constraints: Vec<Constraint>,
}

/// A root kept: its enclosure, its exact value when rational, its multiplicity and
/// whether the surface is singular there.
pub(crate) struct KRoot {
    pub(crate) t: MpfrInterval,
    pub(crate) exact: Option<Rational>,
    pub(crate) multiplicity: u32,
    pub(crate) singular: bool,
}

#[derive(Clone, Copy, PartialEq)]
enum Kind {
    Linear,
    Double,
    Pair,
}

/// `q` with `num = q·den` as polynomials, if any (`den ≢ 0`).
fn ratio(num: &Polynomial, den: &Polynomial) -> Option<Rational> {
    let i = den.degree()?;
    let q = Rational::from(&num.coeff(i) / den.leading()?);
    (num - &den.scale(&q)).is_zero().then_some(q)
}

/// `F(t)` at a rational `t`, as a polynomial in `k`.
fn f_at(q: &KQuad, t: &Rational) -> Polynomial {
    let t2 = Rational::from(t * t);
    &(&q.a.scale(&t2) + &q.b.scale(&(t.clone() * 2u32))) + &q.c
}

/// The kept roots (by increasing enclosure) and the precision that decided them;
/// `None` when the line lies on the surface or the cap was reached.
pub(crate) fn solve(q: &KQuad, k: impl Fn(u32) -> MpfrInterval) -> Option<(Vec<KRoot>, u32)> {
    let kind = if q.a.is_zero() {
        if q.b.is_zero() {
            return (!q.c.is_zero()).then(|| (Vec::new(), 53));
        }
        Kind::Linear
    } else if (&(&q.b * &q.b) - &(&q.a * &q.c)).is_zero() {
        Kind::Double
    } else {
        Kind::Pair
    };
    let disc = &(&q.b * &q.b) - &(&q.a * &q.c);
    let exact = match kind {
        Kind::Linear => vec![ratio(&q.c, &q.b).map(|r| -r / 2u32)],
        Kind::Double => vec![ratio(&q.b, &q.a).map(|r| -r)],
        Kind::Pair => rational_pair(q, &disc),
    };
    let singular = kind == Kind::Double && singular_at_double(q, exact[0].as_ref());
    let mut bits = 64;
    while bits <= CAP {
        if let Some(roots) = attempt(q, kind, &disc, &exact, &k(bits), bits) {
            let roots = roots
                .into_iter()
                .map(|(t, exact)| KRoot {
                    exact,
                    multiplicity: if kind == Kind::Double { 2 } else { 1 },
                    singular,
                    t,
                })
                .collect();
            return Some((roots, bits));
        }
        bits *= 2;
    }
    None
}

/// The two roots exactly when the coefficients do not involve `k` and the
/// discriminant is a rational square; else unknown.
fn rational_pair(q: &KQuad, disc: &Polynomial) -> Vec<Option<Rational>> {
    let constant = |p: &Polynomial| p.degree().is_none_or(|d| d == 0);
    if !(constant(&q.a) && constant(&q.b) && constant(disc)) {
        return vec![None, None];
    }
    let d = disc.coeff(0);
    let (n, m) = (d.numer(), d.denom());
    if d.cmp0() != std::cmp::Ordering::Greater || !(n.is_perfect_square() && m.is_perfect_square())
    {
        return vec![None, None];
    }
    let s = Rational::from((
        rug::Integer::from(n.sqrt_ref()),
        rug::Integer::from(m.sqrt_ref()),
    ));
    let (a, b) = (q.a.coeff(0), q.b.coeff(0));
    let mut r = [(-b.clone() - &s) / &a, (-b + &s) / &a];
    r.sort();
    r.into_iter().map(Some).collect()
}

/// The half-gradient vanishes at the double root `−B/A`: `A g₀ − B g₁ ≡ 0` (or
/// `g₀ + t g₁ ≡ 0` at a rational `t`).
fn singular_at_double(q: &KQuad, exact: Option<&Rational>) -> bool {
    q.grad.iter().all(|[g0, g1]| match exact {
        Some(t) => (g0 + &g1.scale(t)).is_zero(),
        None => (&(&q.a * g0) - &(&q.b * g1)).is_zero(),
    })
}

/// The kept roots at one precision (with their exact values when rational), or `None`
/// when a sign is not decided there.
fn attempt(
    q: &KQuad,
    kind: Kind,
    disc: &Polynomial,
    exact: &[Option<Rational>],
    k: &MpfrInterval,
    bits: u32,
) -> Option<Vec<(MpfrInterval, Option<Rational>)>> {
    let (a, b, c) = (
        q.a.enclose(k, bits),
        q.b.enclose(k, bits),
        q.c.enclose(k, bits),
    );
    let roots = if exact.iter().all(Option::is_some) {
        exact
            .iter()
            .flatten()
            .map(|t| MpfrInterval::from_rational(t, bits))
            .collect()
    } else {
        match kind {
            Kind::Linear if !b.contains_zero() => {
                vec![c.div(&b).mul(&MpfrInterval::point(-0.5, bits))]
            }
            Kind::Double if !a.contains_zero() => vec![b.neg().div(&a)],
            Kind::Pair if !a.contains_zero() => {
                let d = disc.enclose(k, bits);
                if d.contains_zero() {
                    return None;
                }
                if *d.hi() < 0 {
                    return Some(Vec::new());
                }
                let s = d.sqrt();
                let mut r = vec![b.neg().sub(&s).div(&a), b.neg().add(&s).div(&a)];
                if *a.hi() < 0 {
                    r.swap(0, 1);
                }
                if !r[0].intersection(&r[1]).is_empty() {
                    return None;
                }
                r
            }
            _ => return None,
        }
    };
    let mut kept = Vec::new();
    for (i, t) in roots.iter().enumerate() {
        let others: Vec<&MpfrInterval> = roots
            .iter()
            .enumerate()
            .filter(|&(j, _)| j != i)
            .map(|p| p.1)
            .collect();
        let x = exact.get(i).cloned().flatten();
        let mut keep = true;
        for con in &q.constraints {
            keep &= inside(q, con, t, x.as_ref(), &others, bits)?;
        }
        if keep {
            kept.push((t.clone(), x));
        }
    }
    Some(kept)
}

/// Whether the root in `t` satisfies the constraint; `None`: not decided at this
/// precision.
fn inside(
    q: &KQuad,
    con: &Constraint,
    t: &MpfrInterval,
    exact: Option<&Rational>,
    others: &[&MpfrInterval],
    bits: u32,
) -> Option<bool> {
    let [z0, z1] = &con.z;
    let [lo, hi] = &con.range;
    if z1.cmp0() == std::cmp::Ordering::Equal {
        return Some(z0 >= lo && z0 <= hi);
    }
    if let Some(t) = exact {
        let z = Rational::from(z1 * t) + z0;
        return Some(&z >= lo && &z <= hi);
    }
    let z =
        MpfrInterval::from_rational(z0, bits).add(&MpfrInterval::from_rational(z1, bits).mul(t));
    let (l, h) = (
        MpfrInterval::from_rational(lo, bits),
        MpfrInterval::from_rational(hi, bits),
    );
    if z.lo() > h.hi() || z.hi() < l.lo() {
        return Some(false);
    }
    if z.lo() > l.hi() && z.hi() < h.lo() {
        return Some(true);
    }
    // The root may lie on a bound: exactly there iff F(t_h) ≡ 0 and no other root
    // can be t_h.
    for bound in [lo, hi] {
        let th = Rational::from(bound - z0) / z1;
        let thi = MpfrInterval::from_rational(&th, bits);
        let here = !t.intersection(&thi).is_empty();
        let elsewhere = others.iter().any(|o| !o.intersection(&thi).is_empty());
        if here && !elsewhere && f_at(q, &th).is_zero() {
            return Some(true);
        }
    }
    None
}
