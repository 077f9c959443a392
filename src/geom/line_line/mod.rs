//! Two 3D lines, rays, ranged lines or segments (the 3D analogue of OPERATIONS.md §6.1–6.2;
//! the closest-approach system of §6.5 eq. (6.11) for lines, decided exactly).
//!
//! `l₁(t₁) = o₁ + t₁d₁`, `l₂(t₂) = o₂ + t₂d₂` (a segment `(a, b)` is `a + t(b − a)`,
//! `t ∈ [0, 1]`; a ray or ranged line carries its [`crate::geom::ParamRange`]),
//! `w = o₂ − o₁`, `n = d₁ × d₂`:
//!
//! * `n ≠ 0` and `w·n ≠ 0` (`det(w, d₁, d₂)`, the coplanarity test): skew;
//! * `n ≠ 0`, `w·n = 0`: the carriers cross where `t₁d₁ − t₂d₂ = w`; crossing with `d₂`
//!   and `d₁` gives `t₁ n = w × d₂`, `t₂ n = w × d₁`, so with `k` any axis where
//!   `n_k ≠ 0` (the largest is taken): `t₁ = (w × d₂)_k/n_k`, `t₂ = (w × d₁)_k/n_k`,
//!   `p = (o₁n_k + (w × d₂)_k d₁)/n_k` — (6.1) in the plane of the two lines, and
//!   the solution of (6.11) with `AC − B² = |n|²` once `w·n = 0`. Inside both domains a
//!   point, else the carriers meet outside a domain;
//! * `n = 0`: parallel unless `w × d₁ = 0` (collinear); collinear unbounded lines
//!   coincide (`Line`), otherwise the second domain is mapped onto the first parameter,
//!   `t₁(t₂) = (w·d₁ + t₂ d₁·d₂)/|d₁|²` (back: `t₂(t₁) = (t₁ d₁·d₂ − w·d₂)/|d₂|²`) and
//!   intersected with the first: empty, a point, a segment or — with rays — a ray.
//!
//! Every verdict is exact (CERTIFICATION.md `exact`): the certified path evaluates the
//! formulas in double-double with static error bounds ([`crate::num::filter`]); the
//! coplanarity of crossing lines is an exact zero, which no filter can prove, so its
//! sign goes to exact rings of rising cost when the filter cannot decide it; parallel
//! and collinear objects, and coordinates the filter cannot round, go to the whole
//! decision procedure in exact rings (`exact_tier`).

mod filter;
mod procedure;

use nalgebra::{Scalar, Vector2, Vector3};
use rug::Rational;

use self::filter::{Filtered, Tier};
use self::procedure::{carrier, core, crossing, domain, normal_component};
use super::data::Linear;
use super::exact_tier::{ring_tier, ExactRing, Rounder, SmallInteger, WideInteger};
use crate::certificate::Certified;
use crate::num::expansion::Expansion;
use crate::num::filter::dispatch_fma;
use crate::num::ratio::Ratio;
use crate::num::round::Rounded;

/// A point of both objects with its parameters.
#[derive(Debug, Clone, PartialEq)]
pub struct LineLinePoint<S: Scalar> {
    pub point: Vector3<S>,
    pub t1: S,
    pub t2: S,
}

/// Why two linear objects do not meet.
#[derive(Debug, Clone, PartialEq)]
pub enum LineLineEmpty<S: Scalar> {
    /// Parallel, distinct carriers.
    Parallel,
    /// Not coplanar.
    Skew,
    /// Collinear, with disjoint domains.
    CollinearDisjoint,
    /// The carriers cross at this point (parameters `t1`, `t2`), outside a domain.
    OutsideDomain(LineLinePoint<S>),
}

/// The result of line ∩ line (lines, rays, ranged lines, segments).
#[derive(Debug, Clone, PartialEq)]
pub enum LineLine<S: Scalar> {
    /// One point: a crossing, or collinear objects touching at an end point.
    Point(LineLinePoint<S>),
    /// Collinear overlap from `a` to `b`; `a_params = (t1, t2)` of `a`, likewise `b`
    /// (`a` has the smaller `t1`).
    Segment {
        a: Vector3<S>,
        b: Vector3<S>,
        a_params: Vector2<S>,
        b_params: Vector2<S>,
    },
    /// Collinear overlap that is a ray (one object at least is a ray): from `a`
    /// (parameters `a_params = (t1, t2)`) on; `increasing[i]` says whether it runs
    /// towards increasing `t_i` (so its direction is `d₁` or `−d₁`).
    Ray {
        a: Vector3<S>,
        a_params: Vector2<S>,
        increasing: [bool; 2],
    },
    /// Two coincident unbounded lines.
    Line,
    Empty(LineLineEmpty<S>),
}

impl<S: Scalar> LineLinePoint<S> {
    fn map<T: Scalar>(self, f: &mut impl FnMut(S) -> T) -> LineLinePoint<T> {
        LineLinePoint {
            point: self.point.map(&mut *f),
            t1: f(self.t1),
            t2: f(self.t2),
        }
    }
}

impl<S: Scalar> LineLine<S> {
    /// Apply `f` to every number of the result.
    pub fn map<T: Scalar>(self, mut f: impl FnMut(S) -> T) -> LineLine<T> {
        match self {
            LineLine::Point(p) => LineLine::Point(p.map(&mut f)),
            LineLine::Segment {
                a,
                b,
                a_params,
                b_params,
            } => LineLine::Segment {
                a: a.map(&mut f),
                b: b.map(&mut f),
                a_params: a_params.map(&mut f),
                b_params: b_params.map(&mut f),
            },
            LineLine::Ray {
                a,
                a_params,
                increasing,
            } => LineLine::Ray {
                a: a.map(&mut f),
                a_params: a_params.map(&mut f),
                increasing,
            },
            LineLine::Line => LineLine::Line,
            LineLine::Empty(e) => LineLine::Empty(match e {
                LineLineEmpty::Parallel => LineLineEmpty::Parallel,
                LineLineEmpty::Skew => LineLineEmpty::Skew,
                LineLineEmpty::CollinearDisjoint => LineLineEmpty::CollinearDisjoint,
                LineLineEmpty::OutsideDomain(p) => LineLineEmpty::OutsideDomain(p.map(&mut f)),
            }),
        }
    }

    /// The kind's name (`point`, `segment`, `ray`, `line`, `empty`).
    pub fn kind(&self) -> &'static str {
        match self {
            LineLine::Point(_) => "point",
            LineLine::Segment { .. } => "segment",
            LineLine::Ray { .. } => "ray",
            LineLine::Line => "line",
            LineLine::Empty(_) => "empty",
        }
    }
}

/// Plain f64 (uncertified: `n == 0.0` decides parallelism, `w·n == 0.0` coplanarity,
/// so generic crossing lines mostly come out skew).
pub fn intersect_line_line_f64(a: Linear<f64>, b: Linear<f64>) -> LineLine<f64> {
    core::<f64>(&carrier(a), &domain(a), &carrier(b), &domain(b))
}

/// Exact, on rational inputs.
pub fn intersect_line_line_exact(a: Linear<Rational>, b: Linear<Rational>) -> LineLine<Rational> {
    core::<Rational>(&carrier(a), &domain(a), &carrier(b), &domain(b))
}

/// Certified: the exact verdict for the double inputs, coordinates and parameters
/// correctly rounded with enclosures. Tiers: the double-double filter (with the
/// coplanarity of crossing objects decided in exact rings), then the whole procedure
/// in 128-bit and 768-bit integers, expansions, rationals.
pub fn intersect_line_line(a: Linear<f64>, b: Linear<f64>) -> Certified<LineLine<Rounded>> {
    dispatch_fma!(certified(a: Linear<f64>, b: Linear<f64>) -> Certified<LineLine<Rounded>>)
}

/// The filter, then the exact tiers (instantiated once per product mode).
#[inline(always)]
fn certified<M: crate::num::dd::ProductMode>(
    a: Linear<f64>,
    b: Linear<f64>,
) -> Certified<LineLine<Rounded>> {
    match filter::fast::<M>(a, b) {
        Filtered::Done(r) => r,
        Filtered::Crossing { k, from } => crossing_tiers(a, b, k, from),
        Filtered::Undecided => exact_tiers(a, b),
    }
}

/// Coplanar carriers, `n_k ≠ 0`, both proven: the crossing formulas alone in the exact
/// tiers from `from` on (rationals always answer).
#[cold]
#[inline(never)]
fn crossing_tiers(
    a: Linear<f64>,
    b: Linear<f64>,
    k: usize,
    from: Tier,
) -> Certified<LineLine<Rounded>> {
    let small = || crossing_in::<SmallInteger>(a, b, k);
    let wide = || crossing_in::<WideInteger>(a, b, k);
    let expansion = || crossing_in::<Expansion>(a, b, k);
    (from <= Tier::Small)
        .then(small)
        .flatten()
        .or_else(|| (from <= Tier::Wide).then(wide).flatten())
        .or_else(|| (from <= Tier::Expansion).then(expansion).flatten())
        .unwrap_or_else(|| {
            let mut r = Rounder::default();
            let value = crossing_answer::<Rational>(a, b, k).map(|q| r.round(q));
            r.certify(value)
        })
}

/// [`crossing_tiers`] in the ring `E`: `None` when `E` lost exactness.
#[inline(always)]
fn crossing_in<E: ExactRing>(
    a: Linear<f64>,
    b: Linear<f64>,
    k: usize,
) -> Option<Certified<LineLine<Rounded>>> {
    ring_tier::<E, _>(|r| crossing_answer::<Ratio<E>>(a, b, k).map(|q| r.round(q)))
}

/// The crossing answer of coplanar carriers on the axis `k` (`n_k ≠ 0`), in `R`.
#[inline(always)]
fn crossing_answer<R: crate::num::ring::Field>(
    a: Linear<f64>,
    b: Linear<f64>,
    k: usize,
) -> LineLine<R>
where
    f64: super::data::Lift<R>,
{
    let (x, y) = (carrier(a), carrier(b));
    let w = crate::num::ring::sub3(&y.o, &x.o);
    let den = normal_component(&x, &y, k);
    crossing(&x, &domain(a), &y, &domain(b), &w, den, k)
}

/// The exact tiers in order of cost: 128-bit integers, 768-bit integers, expansions,
/// rationals (which always answer).
#[cold]
#[inline(never)]
pub(crate) fn exact_tiers(a: Linear<f64>, b: Linear<f64>) -> Certified<LineLine<Rounded>> {
    ring_tier_answer::<SmallInteger>(a, b)
        .or_else(|| ring_tier_answer::<WideInteger>(a, b))
        .or_else(|| ring_tier_answer::<Expansion>(a, b))
        .unwrap_or_else(|| rational_tier(a, b))
}

/// The last tier, in `rug::Rational`.
#[inline(never)]
fn rational_tier(a: Linear<f64>, b: Linear<f64>) -> Certified<LineLine<Rounded>> {
    let mut r = Rounder::default();
    let value =
        core::<Rational>(&carrier(a), &domain(a), &carrier(b), &domain(b)).map(|q| r.round(q));
    r.certify(value)
}

/// The exact decision in the ring `E` ([`ring_tier`]): `None` when `E` lost exactness.
#[inline(always)]
fn ring_tier_answer<E: ExactRing>(
    a: Linear<f64>,
    b: Linear<f64>,
) -> Option<Certified<LineLine<Rounded>>> {
    ring_tier::<E, _>(|r| {
        core::<Ratio<E>>(&carrier(a), &domain(a), &carrier(b), &domain(b)).map(|q| r.round(q))
    })
}
