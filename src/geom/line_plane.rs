//! Line (ranged line, segment) ∩ plane, OPERATIONS.md §5.1.
//!
//! With `N` the plane's unnormalised normal and `f(x) = N·(x − o)` (or `n·x + d`), the
//! carrier `c(t) = c₀ + t c'` meets the plane where `f(c₀) + t N·c' = 0`, i.e. eq. (5.1)
//! with the normalisation of `n̂` cancelled:
//! `t = −f(c₀)/(N·c')`, `p = (c₀ (N·c') − f(c₀) c')/(N·c')`. The plane parameters follow
//! from Cramer's rule on `u·s₁ + v·s₂ − t c' = c₀ − s₀` (equivalent to (3.7)–(3.8) for a
//! point of the plane, with a lower degree): `u = det(w, s₂, c')/(N·c')`,
//! `v = det(s₁, w, c')/(N·c')`, `w = c₀ − s₀`, since `det(s₁, s₂, c') = N·c'`.
//! `N·c' = 0` exactly: `Contained` if `f(c₀) = 0`, else `Parallel`.

use std::mem::MaybeUninit;

use nalgebra::{Scalar, Vector2, Vector3};
use rug::Rational;

use super::batch::{self, lane_kernel};
use super::data::{LineData, Linear, PlaneData};
use super::exact_tier::{
    filter_certified, ring_tier, ExactRing, Rounder, SmallInteger, WideInteger,
};
use super::objects::Plane;
use super::raw::{RawLine, RawPlane};
use crate::certificate::Certified;
use crate::num::dd::{Dd, ProductMode, U};
use crate::num::expansion::Expansion;
use crate::num::filter::{bound, decide_over, dispatch_fma, Decided, Denominator};
use crate::num::lane::{Lane, Wide};
use crate::num::ratio::Ratio;
use crate::num::ring::{cross3, dot3, each, sub3, Field, Ring, V2, V3};
use crate::num::round::Rounded;

/// Where a line meets a plane: the point, the line parameter `t` and, for a parametric
/// plane, the plane parameters `(u, v)`.
#[derive(Debug, Clone, PartialEq)]
pub struct LinePlanePoint<S> {
    pub point: Vector3<S>,
    pub t: S,
    pub uv: Option<Vector2<S>>,
}

/// The result of line ∩ plane.
#[derive(Debug, Clone, PartialEq)]
pub enum LinePlane<S> {
    /// One point, inside the line's domain.
    Point(LinePlanePoint<S>),
    /// The carrier is parallel to the plane and off it: empty.
    Parallel,
    /// The whole line (segment, ranged line) lies in the plane.
    Contained,
    /// Empty: the carrier meets the plane at this point, outside the line's domain.
    OutsideDomain(LinePlanePoint<S>),
}

impl<S: Scalar> LinePlanePoint<S> {
    fn map<T: Scalar>(self, mut f: impl FnMut(S) -> T) -> LinePlanePoint<T> {
        LinePlanePoint {
            point: self.point.map(&mut f),
            t: f(self.t),
            uv: self.uv.map(|uv| uv.map(&mut f)),
        }
    }
}

impl<S: Scalar> LinePlane<S> {
    /// Apply `f` to every number of the result.
    pub fn map<T: Scalar>(self, f: impl FnMut(S) -> T) -> LinePlane<T> {
        match self {
            LinePlane::Point(p) => LinePlane::Point(p.map(f)),
            LinePlane::OutsideDomain(p) => LinePlane::OutsideDomain(p.map(f)),
            LinePlane::Parallel => LinePlane::Parallel,
            LinePlane::Contained => LinePlane::Contained,
        }
    }
}

/// The polynomials of the operation (written once for every ring).
pub(crate) struct Terms<R> {
    /// `N·c'`: the common denominator.
    pub den: R,
    /// `f(c₀)`.
    pub f0: R,
    /// Numerators of the point: `c₀ (N·c') − f(c₀) c'`.
    pub pnum: V3<R>,
    /// Numerators of `(u, v)`: `det(w, s₂, c')`, `det(s₁, w, c')`.
    pub uvnum: Option<V2<R>>,
}

#[cfg(test)] // the filter-constant tests; the kernel calls `terms_from` after its decision
#[inline(always)]
pub(crate) fn terms<R: Ring>(l: &LineData<R>, p: &PlaneData<R>) -> Terms<R> {
    let den = dot3(p.n(), &l.d);
    let f0 = p.value_at(&l.o);
    terms_from(l, p, den, f0)
}

/// The numerators given `N·c'` and `f(c₀)`.
#[inline(always)]
pub(crate) fn terms_from<R: Ring>(l: &LineData<R>, p: &PlaneData<R>, den: R, f0: R) -> Terms<R> {
    let pnum = each!(i in [0, 1, 2] => l.o[i].times(&den).minus(&f0.times(&l.d[i])));
    let uvnum = match p {
        PlaneData::Param { o, u, v, .. } | PlaneData::General { o, u, v, .. } => {
            let w = sub3(&l.o, o);
            // det(w, s₂, c') = w·(s₂ × c'), det(s₁, w, c') = w·(c' × s₁): the cross
            // products of inputs are exact products, one rounding each.
            Some([dot3(&w, &cross3(v, &l.d)), dot3(&w, &cross3(&l.d, u))])
        }
        PlaneData::Implicit { .. } => None,
    };
    Terms {
        den,
        f0,
        pnum,
        uvnum,
    }
}

fn in_range<R: Field>(t: &R, range: &Option<[R; 2]>) -> bool {
    match range {
        None => true,
        Some([a, b]) => t.compare(a).is_ge() && t.compare(b).is_le(),
    }
}

/// The exact decision procedure, generic over the field (`f64`: plain; `Rational`: exact).
pub(crate) fn core<R: Field>(l: &LineData<R>, p: &PlaneData<R>) -> LinePlane<R> {
    let den = dot3(p.n(), &l.d);
    let f0 = p.value_at(&l.o);
    if den.is_zero() {
        return if f0.is_zero() {
            LinePlane::Contained
        } else {
            LinePlane::Parallel
        };
    }
    let tm = terms_from(l, p, den, f0);
    let t = tm.f0.negate().divide(&tm.den);
    let inside = in_range(&t, &l.range);
    let [x, y, z] = tm.pnum.map(|q| q.divide(&tm.den));
    let point = LinePlanePoint {
        point: Vector3::new(x, y, z),
        t,
        uv: tm
            .uvnum
            .map(|[u, v]| Vector2::new(u.divide(&tm.den), v.divide(&tm.den))),
    };
    if inside {
        LinePlane::Point(point)
    } else {
        LinePlane::OutsideDomain(point)
    }
}

/// Plain f64 (uncertified; `N·c' == 0.0` decides parallelism).
pub fn intersect_line_plane_f64(line: Linear<f64>, plane: &Plane<f64>) -> LinePlane<f64> {
    core::<f64>(&line.data(), &PlaneData::new(plane))
}

/// Exact, on rational inputs.
pub fn intersect_line_plane_exact(
    line: Linear<Rational>,
    plane: &Plane<Rational>,
) -> LinePlane<Rational> {
    core::<Rational>(&line.data(), &PlaneData::new(plane))
}

/// Certified: the exact verdict for the double inputs, coordinates correctly rounded
/// with enclosures. Tiers: the double-double filter (generic input), fixed-width
/// integers, expansions, rationals.
pub fn intersect_line_plane(
    line: Linear<f64>,
    plane: &Plane<f64>,
) -> Certified<LinePlane<Rounded>> {
    dispatch_fma!(certified(line: Linear<f64>, plane: &Plane<f64>) -> Certified<LinePlane<Rounded>>)
}

/// The filter, then the exact tiers (instantiated once per product mode, so that the
/// answer is built in place).
#[inline(always)]
fn certified<M: ProductMode>(
    line: Linear<f64>,
    plane: &Plane<f64>,
) -> Certified<LinePlane<Rounded>> {
    match fast::<M>(line, plane) {
        Some(r) => filter_certified(r),
        None => exact_tiers(line, plane),
    }
}

/// The exact tiers in order of cost: 128-bit integers, 768-bit integers, expansions,
/// rationals (which always answer). Out of line, so that the filter's caller keeps a
/// small stack frame.
#[cold]
#[inline(never)]
fn exact_tiers(line: Linear<f64>, plane: &Plane<f64>) -> Certified<LinePlane<Rounded>> {
    ring_tier_answer::<SmallInteger>(line, plane)
        .or_else(|| ring_tier_answer::<WideInteger>(line, plane))
        .or_else(|| ring_tier_answer::<Expansion>(line, plane))
        .unwrap_or_else(|| rational_tier(line, plane))
}

/// The last tier, in `rug::Rational`.
#[inline(never)]
fn rational_tier(line: Linear<f64>, plane: &Plane<f64>) -> Certified<LinePlane<Rounded>> {
    let l: LineData<Rational> = line.data();
    let p: PlaneData<Rational> = PlaneData::new(plane);
    let mut rounder = Rounder::default();
    let r = core(&l, &p).map(|q| rounder.round(q));
    rounder.certify(r)
}

/// The exact decision in the ring `E` ([`ring_tier`]): `None` when `E` lost exactness.
#[inline(always)]
fn ring_tier_answer<E: ExactRing>(
    line: Linear<f64>,
    plane: &Plane<f64>,
) -> Option<Certified<LinePlane<Rounded>>> {
    ring_tier::<E, _>(|r| {
        let l: LineData<Ratio<E>> = line.data();
        core(&l, &PlaneData::new(plane)).map(|q| r.round(q))
    })
}

/// Filter constants, as `k·u²`, re-derived by `tests::filter_constants`: each is the
/// [`crate::num::error_bound::ErrorBound`] bound of the formula in [`terms`] for inputs
/// bounded by 1, maximised over a line or a segment and a parametric or implicit plane,
/// rounded up. Derivation of the first, to first order in u, with the rules of
/// `error_bound` (worst case: parametric plane, segment): a product of two inputs has
/// `e' = u`, `|l| ≤ u`, error `u·u + u·u + 3u² = 5u²`; `N = u × v`: the subtraction adds
/// `u(2u + u) + u·4u = 7u²`, so `e_N = 17u²`, `|N_i| ≤ 2`, `|l| ≤ 4u`; the segment's
/// `c' = b − a`: `|c'_i| ≤ 2`, `|l| ≤ 2u`, `e = 4u²`; each product `N_i c'_i` propagates
/// `17u²·2 + 4u²·2 = 42u²` and adds `u·2·2u + u·e' + u·4u·2 + u·l + 8u² + 3u²` with
/// `e' = 4u + 4u`, `l = 8u + 8u`, i.e. `4 + 8 + 8 + 16 + 8 + 3 = 47u²`: 89u² each, with
/// `|·| ≤ 4`, `|l| ≤ 16u`; the two additions add `u(4u·… )` terms for the remaining
/// `451 − 3·89 = 184u²`. The test evaluates exactly these rules.
const EPS_DEN: f64 = 452.0 * U * U;
const EPS_PNUM: f64 = 2580.0 * U * U;
const EPS_UVNUM: f64 = 1198.0 * U * U;

/// The filter's scales of one case or a lane group, `[m_P, m_L, m_G, m_G^k]`. Groups:
/// positions `P` (the line's origin or end points, the plane's origin, an implicit
/// plane's `|d|/m_n`), the line direction `L` (`P` for a segment, whose direction is
/// `b − a`), the plane vectors `G` (`u`, `v`, or the normal). Degrees (`k = 2`
/// parametric, `1` implicit): `N·c'`: `G^k L`; point numerators: `P G^k L`; `(u, v)`
/// numerators: `P G L` over `G² L`. `+∞` outside the filter's range (see
/// [`crate::num::filter::scale_of`]).
#[inline(always)]
fn scales<F: Lane>(line: &RawLine<F>, plane: &RawPlane<F>) -> [F; 4] {
    let (mp, ml) = line.scales();
    let (mg, gk, mp) = plane.scales(mp);
    [mp, ml, mg, gk]
}

/// The filter's decisions for one case or a lane group: `ok` where `N·c'` and every
/// output were decided.
struct Decisions<F: Lane> {
    ok: F::Mask,
    t: Decided<F>,
    point: [Decided<F>; 3],
    uv: Option<[Decided<F>; 2]>,
}

/// The filter tier, written once for one case (`F = f64`) and lane groups (`F4`, `F8`): the
/// formulas of [`terms_from`] in double-double, `N·c'` prepared as the denominator (its
/// sign decided: the verdict), every output's correct rounding decided against the
/// bounds `ε·scales` of the constants above. `implicit`: the lanes whose plane is
/// implicit (in a group of mixed kinds, [`PlaneData::General`], whose parameters are
/// left undecided there: the plane has none).
#[inline(always)]
fn decide<M: ProductMode, F: Lane>(
    l: &LineData<Dd<M, F>>,
    p: &PlaneData<Dd<M, F>>,
    [mp, ml, mg, gk]: [F; 4],
    implicit: F::Mask,
) -> Option<Decisions<F>> {
    let d = dot3(p.n(), &l.d);
    let (den_ok, den) = Denominator::prepare(&d, bound(EPS_DEN, &[gk, ml]));
    // Exactly degenerate (or out-of-range) input leaves here, before the numerators.
    if !F::any(den_ok) {
        return None;
    }
    let tm = terms_from(l, p, d, p.value_at(&l.o));
    let t = decide_over(&tm.f0.negate(), bound(EPS_PNUM, &[mp, gk]), &den);
    let e_pnum = bound(EPS_PNUM, &[mp, gk, ml]);
    let point = each!(i in [0, 1, 2] => decide_over(&tm.pnum[i], e_pnum, &den));
    let mut ok = den_ok & t.ok & point[0].ok & point[1].ok & point[2].ok;
    let uv = match &tm.uvnum {
        Some([un, vn]) => {
            let e_uv = bound(EPS_UVNUM, &[mp, mg, ml]);
            let uv = [decide_over(un, e_uv, &den), decide_over(vn, e_uv, &den)];
            ok = ok & (uv[0].ok & uv[1].ok | implicit);
            Some(uv)
        }
        None => None,
    };
    Some(Decisions { ok, t, point, uv })
}

/// The answer from the correctly rounded outputs: the point, or the carrier's point
/// outside the line's domain (decided on the rounded `t`: the range ends are doubles,
/// so comparing with the exact `t` is comparing with its enclosure).
#[inline(always)]
fn answer(
    line: Linear<f64>,
    t: Rounded,
    point: [Rounded; 3],
    uv: Option<[Rounded; 2]>,
) -> LinePlane<Rounded> {
    let inside = match line {
        Linear::Line(l) => match l.range() {
            None => true,
            Some([a, b]) => t.compare_f64(*a).is_ge() && t.compare_f64(*b).is_le(),
        },
        Linear::Segment(_) => t.compare_f64(0.0).is_ge() && t.compare_f64(1.0).is_le(),
    };
    let pt = LinePlanePoint {
        point: Vector3::from(point),
        t,
        uv: uv.map(Vector2::from),
    };
    if inside {
        LinePlane::Point(pt)
    } else {
        LinePlane::OutsideDomain(pt)
    }
}

/// The filter tier for one case.
#[allow(clippy::manual_map)] // `match`, not a closure: see below
#[inline(always)]
fn fast<M: ProductMode>(line: Linear<f64>, plane: &Plane<f64>) -> Option<LinePlane<Rounded>> {
    let (l, p) = (RawLine::new(line), RawPlane::new(plane));
    let dc = decide(
        &l.data::<M>(),
        &p.data(),
        scales(&l, &p),
        p.implicit_lanes(),
    )?;
    if !dc.ok {
        return None;
    }
    // (no array `map`: its closure may be compiled out of line)
    let uv = match dc.uv {
        Some([u, v]) => Some([u.value(), v.value()]),
        None => None,
    };
    let [x, y, z] = dc.point;
    Some(answer(
        line,
        dc.t.value(),
        [x.value(), y.value(), z.value()],
        uv,
    ))
}

/// A case of the batch entry point.
pub type LinePlaneCase<'a> = (Linear<'a, f64>, &'a Plane<f64>);

/// The filter tier for `F::N` cases of one shape ([`batch_shape`]) or of mixed shapes
/// in lanes: writes the answers of the decided lanes to `out` (see
/// [`batch::LaneKernel`]).
#[allow(clippy::manual_map)] // `match`, not a closure: see below
#[inline(always)]
fn fast_lanes<M: ProductMode, F: Wide>(
    cases: &[LinePlaneCase],
    idx: &[usize],
    real: usize,
    out: &mut [MaybeUninit<Certified<LinePlane<Rounded>>>],
) -> u32 {
    let c = |i: usize| cases[idx[i]];
    let p = RawPlane::<F>::gather(|i| c(i).1);
    let l = RawLine::<F>::gather(|i| c(i).0);
    let Some(dc) = decide(
        &l.data::<M>(),
        &p.data(),
        scales(&l, &p),
        p.implicit_lanes(),
    ) else {
        return 0;
    };
    let ok = F::bits(dc.ok) & ((1 << real) - 1);
    // (no closures over lanes here: a closure may be compiled out of line, without
    // this function's target features)
    let t = dc.t.lanes();
    let point = [
        dc.point[0].lanes(),
        dc.point[1].lanes(),
        dc.point[2].lanes(),
    ];
    let uv = match &dc.uv {
        Some([u, v]) => Some([u.lanes(), v.lanes()]),
        None => None,
    };
    for (i, &j) in idx.iter().enumerate().take(real) {
        if ok >> i & 1 == 1 {
            // (in a mixed group, only the parametric lanes have parameters)
            let uv = match (&uv, c(i).1) {
                (Some([u, v]), Plane::Parametric { .. }) => Some([u.get(i), v.get(i)]),
                _ => None,
            };
            let p = [point[0].get(i), point[1].get(i), point[2].get(i)];
            out[j].write(filter_certified(answer(c(i).0, t.get(i), p, uv)));
        }
    }
    ok
}

/// The batch shape: line or segment, parametric or implicit plane.
fn batch_shape((l, p): &LinePlaneCase) -> usize {
    usize::from(matches!(l, Linear::Segment(_))) * 2
        + usize::from(matches!(p, Plane::Implicit { .. }))
}

/// Certified line ∩ plane for many cases: appends to `out`, in order, exactly the
/// answer [`intersect_line_plane`] gives for each case (see `geom::batch`: lane groups
/// through the lane filter, one shape each, then what is left of the shapes mixed).
/// `out` only allocates when it grows.
pub fn intersect_line_plane_batch(
    cases: &[LinePlaneCase],
    out: &mut Vec<Certified<LinePlane<Rounded>>>,
) {
    let lanes = lane_kernel!(fast_lanes, LinePlaneCase, Certified<LinePlane<Rounded>>);
    batch::run(
        cases,
        out,
        batch_shape,
        lanes,
        |&(l, p)| intersect_line_plane(l, p),
        |&(l, p)| exact_tiers(l, p),
    );
}

/// For `robust`'s tests, which drive it with every robustness generator: the
/// four-lane (AVX) kernel end to end, whatever the CPU's widest — `batch::run` answers
/// `cases` as the scalar path does (nothing to run on a CPU without AVX and FMA).
#[cfg(test)]
pub(crate) fn assert_four_lane_run_equals_scalar(cases: &[LinePlaneCase]) {
    let lanes = lane_kernel!(fast_lanes, LinePlaneCase, Certified<LinePlane<Rounded>>, 4);
    if lanes.is_none() {
        return; // no AVX/FMA
    }
    batch::testing::assert_run_equals_scalar(
        cases,
        batch_shape,
        lanes,
        |&(l, p)| intersect_line_plane(l, p),
        |&(l, p)| exact_tiers(l, p),
    );
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geom::Line;
    use crate::num::error_bound::ErrorBound;
    use crate::num::lane::MAX_LANES;

    /// The lane kernels themselves decide a lane group of generic cases (lines and one
    /// plane) and write the scalar answers; a lane whose scale is out of range (a 1e200
    /// origin) is left undecided, without disturbing the others.
    #[test]
    fn lane_kernel_decides_generic_lanes() {
        let plane = Plane::parametric(
            [0.3, -1.7, 2.9].into(),
            [1.1, 0.2, -0.7].into(),
            [-0.4, 1.3, 0.6].into(),
        )
        .unwrap();
        let lines: Vec<Line<f64>> = (0..MAX_LANES)
            .map(|i| {
                let o = if i % 4 == 2 {
                    1e200
                } else {
                    0.1 * i as f64 + 0.37
                };
                Line::new([o, -2.3, 0.71].into(), [0.9, 0.33 + i as f64, -1.21].into()).unwrap()
            })
            .collect();
        let cases: Vec<LinePlaneCase> = lines.iter().map(|l| (Linear::Line(l), &plane)).collect();
        for kernel in
            batch::test_lane_kernels!(fast_lanes, LinePlaneCase, Certified<LinePlane<Rounded>>)
        {
            let w = kernel.width;
            let (bits, out) =
                batch::testing::run_once(&kernel, &cases, filter_certified(LinePlane::Parallel));
            for i in 0..w {
                if i % 4 == 2 {
                    assert_eq!(bits >> i & 1, 0, "lane {i}");
                    assert_eq!(out[i], filter_certified(LinePlane::Parallel));
                } else {
                    assert_eq!(bits >> i & 1, 1, "lane {i}");
                    assert_eq!(out[i], intersect_line_plane(cases[i].0, cases[i].1));
                }
            }
        }
    }

    /// A mixed lane computes the values of its own shape (so the bounds derived for the
    /// shapes hold for it): for lines and segments with planes of either kind, the
    /// scales and every numerator (lines and segments as [`MixedLines`], planes as
    /// [`PlaneData::General`]; `(u, v)` for the parametric planes) equal those of the
    /// shape's own formulas, double-double part by part.
    #[test]
    fn mixed_terms_are_the_shapes_terms() {
        use crate::geom::raw::{MixedLines, MixedPlanes};
        type D = Dd<crate::num::dd::WithFma>;
        for seed in 0..40u64 {
            let (line, segment) = segment_and_line(seed);
            for l in [Linear::Line(&line), Linear::Segment(&segment)] {
                for implicit in [false, true] {
                    let p = batch::testing::generic_plane(1000 * seed + 20, implicit);
                    let (r, ml) = (RawLine::new(l), MixedLines::of(l));
                    let (u, m) = (RawPlane::new(&p), MixedPlanes::of(&p));
                    let (mp, ml_scale) = ml.scales();
                    let (mg, gk, mp) = m.scales(mp);
                    assert_eq!(scales(&r, &u), [mp, ml_scale, mg, gk]);
                    let (lu, lm): (LineData<D>, LineData<D>) = (r.data(), ml.data());
                    assert_eq!((&lu.o, &lu.d), (&lm.o, &lm.d));
                    let (pu, pm): (PlaneData<D>, PlaneData<D>) = (u.data(), m.data());
                    let tu = terms(&lu, &pu);
                    let tm = terms(&lm, &pm);
                    assert_eq!((tu.den, tu.f0, tu.pnum), (tm.den, tm.f0, tm.pnum));
                    if !implicit {
                        assert_eq!(tu.uvnum, tm.uvnum);
                    }
                }
            }
        }
    }

    /// A generic line and segment from the seed `k`.
    fn segment_and_line(k: u64) -> (Line<f64>, crate::geom::Segment<f64>) {
        let mut r = crate::num::rng::Rng::new(k);
        let mut v = || batch::testing::unit_vector(&mut r);
        (
            Line::new(v(), v()).unwrap(),
            crate::geom::Segment::new(v(), v()).unwrap(),
        )
    }

    /// A lane group of lines and segments with planes of both kinds (every combination
    /// in turn) is decided in every lane, with the scalar answers (`(u, v)` only on the
    /// parametric planes; the point outside a segment's domain where it is).
    #[test]
    fn lane_kernel_decides_mixed_lanes() {
        let objs: Vec<_> = (0..MAX_LANES as u64)
            .map(|i| {
                let p = batch::testing::generic_plane(1000 * i + 20, i & 1 == 1);
                (segment_and_line(i), p)
            })
            .collect();
        let cases: Vec<LinePlaneCase> = objs
            .iter()
            .enumerate()
            .map(|(i, ((l, s), p))| {
                let l = if i & 2 == 2 {
                    Linear::Segment(s)
                } else {
                    Linear::Line(l)
                };
                (l, p)
            })
            .collect();
        for kernel in
            batch::test_lane_kernels!(fast_lanes, LinePlaneCase, Certified<LinePlane<Rounded>>)
        {
            batch::testing::assert_kernel_decides_all(
                &kernel,
                &cases,
                filter_certified(LinePlane::Parallel),
                |&(l, p)| intersect_line_plane(l, p),
            );
        }
    }

    /// Derive the filter constants from the formulas and check the written ones cover them.
    #[test]
    fn filter_constants() {
        let i = ErrorBound::INPUT;
        let lines = [
            LineData {
                o: [i; 3],
                d: [i; 3],
                range: None,
            },
            LineData {
                o: [i; 3],
                d: [i.minus(&i); 3],
                range: None,
            },
        ];
        let planes = [
            PlaneData::Param {
                o: [i; 3],
                u: [i; 3],
                v: [i; 3],
                n: crate::num::ring::cross3(&[i; 3], &[i; 3]),
            },
            PlaneData::Implicit { n: [i; 3], d: i },
        ];
        let mut worst = [ErrorBound::zero(); 4];
        for l in &lines {
            for p in &planes {
                let t = terms(l, p);
                worst[0] = worst[0].max(t.den);
                worst[1] = worst[1].max(t.pnum[0]).max(t.f0);
                if let Some([u, v]) = t.uvnum {
                    worst[2] = worst[2].max(u).max(v);
                }
            }
        }
        println!("derived (u²): {:?}", worst.map(|w| w.e_in_u2()));
        for (w, c) in worst.iter().zip([EPS_DEN, EPS_PNUM, EPS_UVNUM]) {
            assert!(
                c >= w.e,
                "constant {} u² below the derived {} u²",
                c / (U * U),
                w.e_in_u2()
            );
        }
    }
}
