//! A line against a curve or surface given by a polynomial equation (OPERATIONS.md
//! §5.2 for the algebraic surfaces, §6.3 eq. (6.3) for conics), decided exactly.
//!
//! The equation restricted to the line `o + t·d` is a polynomial `P(t)` with rational
//! coefficients. `P ≡ 0`: the line lies on the surface. Otherwise every real root of `P`
//! is a point, with the root's multiplicity as the intersection multiplicity (1:
//! transversal, 2: tangent or a singular point, …), decided by the exact square-free
//! decomposition, and the coordinates `oᵢ + t·dᵢ` correctly rounded
//! ([`crate::ops::rational::exact::round_affine`]).

use rug::Rational;

use crate::certificate::{Arithmetic, Certified};
use crate::certify::univariate::{real_roots, Polynomial, RealRoot};
use crate::num::round::Rounded;
use crate::ops::rational::exact::round_affine;

/// One point where a line meets the surface (or curve).
#[derive(Debug, Clone)]
pub struct LineHit<const D: usize> {
    /// The line parameter `t`: exact when rational, else an isolating interval that
    /// can be refined; `t.nearest()` is correctly rounded.
    pub t: RealRoot,
    /// The point `o + t·d`, each coordinate correctly rounded, with its enclosure.
    pub point: [Rounded; D],
    /// The multiplicity of `t` as a root of the restricted equation: 1 transversal,
    /// 2 tangent (or a singular point of the surface, see `singular`), more for higher
    /// contact.
    pub multiplicity: u32,
    /// The gradient of the surface's equation vanishes at the point (a cone's apex, the
    /// centre of a horn torus): there the multiplicity reflects the singularity, not a
    /// tangency of the line.
    pub singular: bool,
}

impl<const D: usize> LineHit<D> {
    /// The correctly rounded point.
    pub fn nearest(&self) -> [f64; D] {
        std::array::from_fn(|i| self.point[i].nearest)
    }

    /// True for a contact of even multiplicity at a regular point: the line touches
    /// the surface there without crossing it.
    pub fn is_tangent(&self) -> bool {
        !self.singular && self.multiplicity >= 2
    }
}

/// The result of a line against an algebraic curve or surface.
#[derive(Debug, Clone)]
pub enum LineCut<const D: usize> {
    /// The isolated points, by increasing `t` (empty: the line misses).
    Points(Vec<LineHit<D>>),
    /// The whole line lies on the surface (kind `line`).
    Contained,
}

impl<const D: usize> LineCut<D> {
    /// The points (none when the line is contained).
    pub fn points(&self) -> &[LineHit<D>] {
        match self {
            LineCut::Points(p) => p,
            LineCut::Contained => &[],
        }
    }
}

/// Solve `P(t) = 0` on the line `o + t·d` and build the certified result. `gradient`
/// holds the components of the surface's gradient restricted to the line (polynomials
/// in `t`), to flag singular points exactly.
pub(crate) fn line_cut<const D: usize>(
    o: &[Rational; D],
    d: &[Rational; D],
    p: &Polynomial,
    gradient: &[Polynomial],
) -> Certified<LineCut<D>> {
    let bits = p.max_bits();
    if p.is_zero() {
        // P ≡ 0: every point of the line satisfies the equation.
        return Certified::exact(LineCut::Contained, Arithmetic::Rational, bits);
    }
    // real_roots only rejects the zero polynomial.
    let roots = real_roots(p).unwrap_or_default();
    let hits = roots
        .into_iter()
        .map(|mut t| {
            let point = std::array::from_fn(|i| round_affine(&mut t, &o[i], &d[i]));
            // At a singular point P and P' = ∇F·d both vanish: a simple root is regular.
            let singular = t.multiplicity() > 1 && gradient.iter().all(|g| t.is_root_of(g));
            LineHit {
                multiplicity: t.multiplicity(),
                t,
                point,
                singular,
            }
        })
        .collect();
    Certified::exact(LineCut::Points(hits), Arithmetic::Rational, bits)
}

/// `a + b·t` as a polynomial in `t`.
pub(crate) fn affine(a: &Rational, b: &Rational) -> Polynomial {
    Polynomial::from_coeffs(vec![a.clone(), b.clone()])
}
