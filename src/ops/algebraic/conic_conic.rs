//! Conic ∩ conic in the plane (OPERATIONS.md §6.3 "Conic–conic", §6.4), decided exactly
//! through resultants of degree ≤ 4 instead of the rational parametrisation (6.4), so
//! that tangencies (double roots) and points sharing an abscissa are exact.
//!
//! 1. Generic position: shear `x = x' − λy` for the first `λ` of a fixed list for which
//!    both equations have a constant non-zero leading coefficient in `y` (no point
//!    escapes to infinity along the projection) and, for two quadratics, the first
//!    subresultant coefficient `s₁ = f₂g₁ − f₁g₂` vanishes at a root of `R = Res_y` only
//!    where both quadratics in `y` are proportional with a double root (a point singular
//!    on both curves, `y = −f₁/(2f₂)`; their discriminant vanishes at every root of
//!    `gcd(R, s₁)`, checked exactly); elsewhere `y = −s₀(x')/s₁(x')`. Then every root
//!    `x'` of `R` carries exactly one common point, distinct points have distinct `x'`,
//!    and the multiplicity of `x'` in `R` is the intersection multiplicity of the point
//!    (projection in generic position: Basu, Pollack & Roy,
//!    *Algorithms in Real Algebraic Geometry*, §11.5; Fulton, *Algebraic Curves*, §1.6).
//!    `R ≡ 0` for some (hence every) shear means a common component. Finitely many `λ`
//!    fail (asymptotic directions, directions joining two of at most four points,
//!    vertical tangents), so the list of 41 always holds a good one.
//! 2. Each coordinate is identified as a root of its own elimination polynomial in the
//!    original coordinates, `P_x = Res_y(F₁, F₂)` and `P_y = Res_x(F₁, F₂)`: they vanish
//!    at every intersection point's `x`, resp. `y`. The enclosure of `y = −s₀/s₁` over
//!    the interval of `x'` and of `x = x' − λy` shrink to the point as `x'` is refined,
//!    and the isolating intervals of `P_x`, `P_y` shrink to their distinct roots, so
//!    eventually exactly one root of each meets the enclosures: those are the point's
//!    coordinates, correctly rounded by the univariate root finder (rational ones
//!    exactly).

use rug::Rational;

use super::bivariate::{common_root, resultant, Bivariate};
use crate::certificate::{Arithmetic, Certified};
use crate::certify::univariate::{gcd, real_roots, square_free_part, Polynomial, RealRoot};
use crate::error::GeomError;
use crate::num::round::Rounded;
use crate::ops::rational::exact::RatInterval;
use crate::ops::rational::Conic;

/// One intersection point of two conics.
#[derive(Debug, Clone)]
pub struct ConicHit {
    /// The abscissa, a root of `P_x = Res_y(F₁, F₂)` (its own `multiplicity` is within
    /// `P_x`, not the intersection multiplicity).
    pub x: RealRoot,
    /// The ordinate, a root of `P_y = Res_x(F₁, F₂)`.
    pub y: RealRoot,
    /// `(x, y)` correctly rounded, with enclosures.
    pub point: [Rounded; 2],
    /// The intersection multiplicity: 1 transversal, 2 tangent, 3–4 higher contact.
    pub multiplicity: u32,
}

impl ConicHit {
    /// The correctly rounded point.
    pub fn nearest(&self) -> [f64; 2] {
        [self.point[0].nearest, self.point[1].nearest]
    }
}

/// The result of conic ∩ conic.
#[derive(Debug, Clone)]
pub enum ConicCut {
    /// Isolated points, by increasing `x` then `y` (empty: disjoint).
    Points(Vec<ConicHit>),
    /// The two equations are proportional: the same conic (kind `coincident`).
    Coincident,
    /// Different equations sharing a component (degenerate conics with a common line);
    /// the isolated points besides it are not listed (`complete: false`).
    CommonComponent,
}

impl ConicCut {
    /// The points (none for the non-isolated outcomes).
    pub fn points(&self) -> &[ConicHit] {
        match self {
            ConicCut::Points(p) => p,
            _ => &[],
        }
    }
}

/// The shears tried, in order: `0, ±1, ±2, ±1/2, ±3, ±1/3, …`.
fn shears() -> impl Iterator<Item = Rational> {
    std::iter::once(Rational::new()).chain((1..=10i64).flat_map(|k| {
        [
            Rational::from(k),
            Rational::from(-k),
            Rational::from((1, k + 1)),
            Rational::from((-1, k + 1)),
        ]
    }))
}

/// A projection in generic position: the shear, `R(x')`, and `y = num/den`.
struct Projection {
    lambda: Rational,
    r: Polynomial,
    num: Polynomial,
    den: Polynomial,
    /// Fibres where both quadratics in `y` are proportional with a double root (a
    /// point singular on both curves): the square-free `h` whose roots they are, and
    /// `y = −f₁/(2f₂)` there.
    double: Option<(Polynomial, Polynomial, Polynomial)>,
}

impl Projection {
    /// `y = num(x')/den(x')` valid at the root `x'` of `R`.
    fn ordinate(&self, xp: &RealRoot) -> (&Polynomial, &Polynomial) {
        match &self.double {
            Some((h, num, den)) if xp.is_root_of(h) => (num, den),
            _ => (&self.num, &self.den),
        }
    }
}

enum Search {
    Found(Projection),
    /// `R` is a non-zero constant: no common point, even complex.
    Disjoint,
    CommonComponent,
    Exhausted,
}

fn leading_is_constant(p: &[Polynomial], degree: usize) -> bool {
    p.len() == degree + 1 && p.last().and_then(Polynomial::degree) == Some(0)
}

fn find_projection(f1: &Bivariate, f2: &Bivariate, d1: usize, d2: usize) -> Search {
    for lambda in shears() {
        let (f, g) = (f1.shear(&lambda).in_y(), f2.shear(&lambda).in_y());
        if !leading_is_constant(&f, d1) || !leading_is_constant(&g, d2) {
            continue;
        }
        let Some(r) = resultant(&f, &g) else {
            continue;
        };
        if r.is_zero() {
            return Search::CommonComponent;
        }
        if r.degree() == Some(0) {
            return Search::Disjoint;
        }
        let Some((num, den)) = common_root(&f, &g) else {
            continue;
        };
        if den.is_zero() {
            continue;
        }
        // Where s₁ = 0 (only for two quadratics) the fibre must still hold one point:
        // the quadratics are then proportional, and need a double root.
        let h = gcd(&r, &den);
        let mut double = None;
        if h.degree().unwrap_or(0) > 0 {
            let disc = &(&f[1] * &f[1]) - &(&f[0] * &f[2]).scale(&Rational::from(4));
            let hs = square_free_part(&h);
            if f.len() != 3 || !disc.div_rem(&hs).is_some_and(|(_, rem)| rem.is_zero()) {
                continue;
            }
            double = Some((hs, -&f[1], f[2].scale(&Rational::from(2))));
        }
        return Search::Found(Projection {
            lambda,
            r,
            num,
            den,
            double,
        });
    }
    Search::Exhausted
}

/// Conic ∩ conic (module documentation): every real intersection point with its exact
/// intersection multiplicity and correctly rounded coordinates; `Coincident` for
/// proportional equations. `status: exact`, `complete: true` (except for a common
/// component). Either input may be degenerate (a line pair, a double line, a point,
/// an empty conic) or of degree 1.
pub fn intersect_conic_conic(c1: &Conic, c2: &Conic) -> Result<Certified<ConicCut>, GeomError> {
    intersect_conic_conic_until(c1, c2, None)
}

/// [`intersect_conic_conic`] that stops refining when `deadline` passes (checked once
/// per refinement step of the identification, issue 20): then `undecided` with no
/// points and the reason "time limit reached". Roots of nearly equal conics (an
/// ellipse with a semi-axis of 1e-82) can need thousands of steps on huge rationals.
pub fn intersect_conic_conic_until(
    c1: &Conic,
    c2: &Conic,
    deadline: Option<std::time::Instant>,
) -> Result<Certified<ConicCut>, GeomError> {
    let (f1, f2) = (Bivariate::from_conic(c1), Bivariate::from_conic(c2));
    let (Some(d1), Some(d2)) = (f1.total_degree(), f2.total_degree()) else {
        return Err(GeomError::InvalidValue {
            field: "conic".into(),
            reason: "every coefficient is zero: the equation holds everywhere".into(),
        });
    };
    if f1.proportional(&f2) {
        return Ok(Certified::exact(
            ConicCut::Coincident,
            Arithmetic::Rational,
            0,
        ));
    }
    if d1 == 0 || d2 == 0 {
        // A non-zero constant has no zeros.
        return Ok(Certified::exact(
            ConicCut::Points(Vec::new()),
            Arithmetic::Rational,
            0,
        ));
    }
    let proj = match find_projection(&f1, &f2, d1, d2) {
        Search::Found(p) => p,
        Search::Disjoint => {
            let none = ConicCut::Points(Vec::new());
            return Ok(Certified::exact(none, Arithmetic::Rational, 0));
        }
        Search::CommonComponent => {
            let mut c = Certified::exact(ConicCut::CommonComponent, Arithmetic::Rational, 0);
            c.complete = false;
            c.reason =
                Some("the conics share a component; its isolated points are not listed".into());
            return Ok(c);
        }
        Search::Exhausted => {
            return Ok(Certified::undecided(
                ConicCut::Points(Vec::new()),
                Arithmetic::Rational,
                0,
                "no shear in generic position was found",
            ))
        }
    };
    let px = resultant(&f1.in_y(), &f2.in_y());
    let py = resultant(&f1.in_x(), &f2.in_x());
    let (Some(px), Some(py)) = (px, py) else {
        return Ok(Certified::undecided(
            ConicCut::Points(Vec::new()),
            Arithmetic::Rational,
            0,
            "elimination polynomial of unexpected degree",
        ));
    };
    let bits = proj.r.max_bits().max(px.max_bits()).max(py.max_bits());
    let roots = real_roots(&proj.r).unwrap_or_default();
    if roots.is_empty() {
        return Ok(Certified::exact(
            ConicCut::Points(Vec::new()),
            Arithmetic::Rational,
            bits,
        ));
    }
    // With points present, P_x and P_y are non-zero (no common component).
    let mut xs = real_roots(&px).unwrap_or_default();
    let mut ys = real_roots(&py).unwrap_or_default();
    let mut found: Vec<(usize, usize, u32)> = Vec::new();
    for mut xp in roots {
        let reason = match identify(&mut xp, &proj, &mut xs, &mut ys, deadline) {
            Identified::At(i, j) => {
                found.push((i, j, xp.multiplicity()));
                continue;
            }
            Identified::Missing => {
                "a coordinate was not found among the elimination polynomial's roots"
            }
            Identified::Late => crate::certify::TIME_LIMIT,
        };
        return Ok(Certified::undecided(
            ConicCut::Points(Vec::new()),
            Arithmetic::Rational,
            bits,
            reason,
        ));
    }
    found.sort();
    let hits = found
        .into_iter()
        .map(|(i, j, m)| ConicHit {
            point: [xs[i].rounded(), ys[j].rounded()],
            x: xs[i].clone(),
            y: ys[j].clone(),
            multiplicity: m,
        })
        .collect();
    Ok(Certified::exact(
        ConicCut::Points(hits),
        Arithmetic::Rational,
        bits,
    ))
}

/// What [`identify`] found.
enum Identified {
    /// The indices into the roots of `P_x` and `P_y`.
    At(usize, usize),
    /// No root met, or `MAX_IDENTIFY_STEPS` spent (the algebra excludes both).
    Missing,
    /// The deadline passed first.
    Late,
}

/// The indices of the roots of `P_x` and `P_y` that are the coordinates of the point
/// projected to `x'` (step 2 of the module documentation), refining until they are
/// told apart, the step budget is spent or `deadline` passes.
fn identify(
    xp: &mut RealRoot,
    proj: &Projection,
    xs: &mut [RealRoot],
    ys: &mut [RealRoot],
    deadline: Option<std::time::Instant>,
) -> Identified {
    for _ in 0..MAX_IDENTIFY_STEPS {
        if crate::certify::past(deadline) {
            return Identified::Late;
        }
        let x_sheared = RatInterval::from_root(xp);
        let (num, den) = proj.ordinate(xp);
        let Some(y) = x_sheared.eval(num).div(&x_sheared.eval(den)) else {
            xp.refine();
            continue;
        };
        let x = x_sheared.add(&y.scale(&-proj.lambda.clone()));
        let cx: Vec<usize> = meeting(xs, &x);
        let cy: Vec<usize> = meeting(ys, &y);
        if cx.is_empty() || cy.is_empty() {
            return Identified::Missing;
        }
        if cx.len() == 1 && cy.len() == 1 {
            return Identified::At(cx[0], cy[0]);
        }
        xp.refine();
        for &i in &cx {
            xs[i].refine();
        }
        for &j in &cy {
            ys[j].refine();
        }
    }
    Identified::Missing
}

/// A guard against a logic error turning into an endless loop: each step at least
/// halves every interval involved, so a few thousand steps separate any two roots
/// these degree-4 resultants can have.
const MAX_IDENTIFY_STEPS: usize = 100_000;

fn meeting(roots: &[RealRoot], x: &RatInterval) -> Vec<usize> {
    roots
        .iter()
        .enumerate()
        .filter(|(_, r)| RatInterval::from_root(r).meets(x))
        .map(|(i, _)| i)
        .collect()
}
