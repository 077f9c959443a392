//! Certification of the curved operations (docs/CERTIFICATES.md): each operation's
//! system, written once generic over [`crate::num::Real`] beside its float path, is
//! handed to [`crate::certify`]:
//!
//! 1. [`crate::certify::solve`] over the whole parameter domain — subdivision with
//!    exclusion, Krawczyk uniqueness, MPFR escalation, the singular certificate — so
//!    that `complete: true` means that no other solution exists;
//! 2. when the box budget or precision cap leaves part of the domain undecided, the
//!    float answers are certified one by one ([`crate::certify::certify_root`]) so that
//!    every answer the fast path found still carries its proof (`complete: false`).
//!
//! Periodic parameters: a root on the seam of a closed curve or surface can be found at
//! both ends of the domain; the copy whose enclosure, shifted by the period, lies inside
//! the other's (where that root is proven unique) is dropped.

use crate::certificate::{Arithmetic, Certified, Status};
use crate::certify::{self, Root, System};
use crate::error::GeomError;
use crate::num::round::{next_down, next_up};
use crate::num::Interval;

pub use crate::certify::Options;

pub mod across;
pub mod boundary;
pub mod pieces;
mod seam;

use boundary::{decide_boundary, Decided};

/// The unknowns of an operation: their domain and which are periodic.
#[derive(Debug, Clone, PartialEq)]
pub struct Unknowns {
    pub domain: Vec<[f64; 2]>,
    pub periodic: Vec<bool>,
    /// The bounds are roundings of irrational ends (`Curve::domain_rounded`): covered
    /// outward by one ulp.
    pub rounded: Vec<bool>,
}

impl Unknowns {
    /// The box the certifier searches: the domain, with rounded bounds moved outward
    /// by one ulp so that it contains the exact domain.
    pub fn search_box(&self) -> Vec<[f64; 2]> {
        self.domain
            .iter()
            .zip(&self.rounded)
            .map(|(&[lo, hi], &r)| {
                if r {
                    [next_down(lo), next_up(hi)]
                } else {
                    [lo, hi]
                }
            })
            .collect()
    }

    /// An enclosure of the period of coordinate `i` (the exact domain's length).
    pub(crate) fn period(&self, i: usize) -> Interval {
        let [lo, hi] = self.domain[i];
        let exact = Interval::point(hi) - Interval::point(lo);
        if self.rounded[i] {
            let [a, b] = self.search_box()[i];
            exact.hull(&(Interval::point(b) - Interval::point(a)))
        } else {
            exact
        }
    }
}

/// One certified solution: a root of the operation's system.
#[derive(Debug, Clone, PartialEq)]
pub struct CertifiedRoot {
    /// The parameters (estimate).
    pub params: Vec<f64>,
    /// An enclosure of the parameters, outward rounded; with `status` verified it holds
    /// exactly this one root.
    pub enclosure: Vec<Interval>,
    /// `Verified`, `VerifiedSingular` or `Undecided` (e.g. a root proven to exist in a
    /// box that straddles a non-periodic domain boundary).
    pub status: Status,
    /// The most roots the enclosure holds, with multiplicity (2 for a tangency).
    pub max_roots: u32,
    pub bits: u32,
    pub perturbation: Option<f64>,
    /// Why the status is undecided.
    pub reason: Option<String>,
}

impl CertifiedRoot {
    fn from_root(r: &Root, boundary: bool) -> CertifiedRoot {
        let (status, reason) = if boundary && r.status != Status::Undecided {
            (
                Status::Undecided,
                Some("a root exists in a box that straddles the domain boundary".to_string()),
            )
        } else {
            (r.status, None)
        };
        CertifiedRoot {
            params: r.estimate.clone(),
            enclosure: r.enclosure.clone(),
            status,
            max_roots: r.max_roots,
            bits: r.bits,
            perturbation: r.perturbation,
            reason,
        }
    }

    /// A tangential (double) solution.
    pub fn is_singular(&self) -> bool {
        self.status == Status::VerifiedSingular
    }
}

/// What a float guess whose certification proved nothing costs from the budget of
/// [`certify_roots_with`]'s guesses: the cluster tests ran at each of the four
/// precisions up to 512 bits, each counted as 16 boxes, as in [`certify::solve`].
pub const FAILED_GUESS_COST: usize = 64;

/// Every root of `sys` over `unknowns`, certified (module doc); `guesses` are the float
/// answers, certified one by one when the subdivision is not complete.
pub fn certify_roots<S: System>(
    sys: &S,
    unknowns: &Unknowns,
    guesses: &[Vec<f64>],
    opts: &Options,
) -> Result<Certified<Vec<CertifiedRoot>>, GeomError> {
    certify_roots_with(sys, unknowns, guesses, opts, |_| false)
}

/// [`certify_roots`], where `not_an_answer` may prove a `verified` root whose box
/// straddles a true end of the domain (and that [`boundary`] could not place) to be no
/// answer of the operation — a root of the system that the operation's geometry
/// rules out, such as a pole of the parametrisation (OPERATIONS.md §14.1) that is not
/// a foot. Such roots are dropped; it must return `true` only with a proof.
pub fn certify_roots_with<S: System>(
    sys: &S,
    unknowns: &Unknowns,
    guesses: &[Vec<f64>],
    opts: &Options,
    not_an_answer: impl Fn(&Root) -> bool,
) -> Result<Certified<Vec<CertifiedRoot>>, GeomError> {
    let found = find_roots(sys, unknowns, guesses, opts, not_an_answer)?;
    let status = found
        .roots
        .iter()
        .fold(Status::Verified, |s, r| s.weakest(r.status));
    let mut reason = found.reason;
    let undecided = found.roots.iter().any(|r| r.status == Status::Undecided);
    if undecided {
        reason.get_or_insert_with(|| "a root straddles the domain boundary".into());
    }
    let complete = found.searched && !undecided;
    Ok(answer(found.roots, status, complete, found.bits, reason))
}

/// What a root search found, before the answer's status is set: the roots, whether
/// the search itself covered the whole box (`searched`: nothing left but the roots'
/// own undecided boxes), the precision used and the reason the search stopped short.
pub(crate) struct Found {
    pub roots: Vec<CertifiedRoot>,
    /// The boxes the search left undecided (empty exactly when `searched`).
    pub undecided: Vec<certify::UndecidedBox>,
    pub searched: bool,
    pub bits: u32,
    pub reason: Option<String>,
}

/// The search of [`certify_roots_with`], without the answer's assembly (shared with
/// the knot-span search of [`pieces`], which decides roots across knots before it).
pub(crate) fn find_roots<S: System>(
    sys: &S,
    unknowns: &Unknowns,
    guesses: &[Vec<f64>],
    opts: &Options,
    not_an_answer: impl Fn(&Root) -> bool,
) -> Result<Found, GeomError> {
    let search = unknowns.search_box();
    let solved = certify::solve(sys, &search, opts)?;
    let mut roots: Vec<CertifiedRoot> = Vec::new();
    for r in &solved.value.roots {
        push_unique(&mut roots, CertifiedRoot::from_root(r, false), unknowns);
    }
    for r in &solved.value.boundary_roots {
        let on_seam_only = search
            .iter()
            .zip(&unknowns.periodic)
            .zip(&r.enclosure)
            .all(|((&[lo, hi], &p), x)| p || (lo <= x.lo() && x.hi() <= hi));
        let root = if on_seam_only {
            Some(CertifiedRoot::from_root(r, false))
        } else {
            at_boundary(sys, r, unknowns, opts, &not_an_answer)
        };
        if let Some(root) = root {
            push_unique(&mut roots, root, unknowns);
        }
    }
    let complete = solved.complete;
    let undecided = solved.value.undecided.clone();
    let mut bits = solved.bits;
    let mut reason = solved.reason.clone();
    if !complete {
        // The guesses draw on a budget of their own, `max_boxes`: a proven one costs a
        // box, one that proves nothing (the cluster tests failed at every precision)
        // [`FAILED_GUESS_COST`]; and the deadline is checked per guess (issue 20: a
        // line lying in a flat degree-30 patch gives hundreds of guesses, each
        // escalating to the precision cap for half a second).
        let mut tried = 0usize;
        for g in guesses {
            if roots.iter().any(|r| contains(&r.enclosure, g, unknowns)) {
                continue;
            }
            if opts.late() || tried >= opts.max_boxes {
                let why = if opts.late() {
                    certify::TIME_LIMIT
                } else {
                    "box budget spent"
                };
                let r = reason.get_or_insert_with(String::new);
                if !r.contains(why) {
                    r.push_str(&format!("; {why} before every float candidate was tried"));
                }
                break;
            }
            let c = certify::certify_root(sys, g, opts)?;
            if c.status == Status::Undecided {
                tried += FAILED_GUESS_COST;
                continue;
            }
            tried += 1;
            // The float answer may lie just outside the domain: a root proven outside
            // is not an answer, one whose box crosses the boundary is undecided.
            let place = placement(&c.value.enclosure, &search, unknowns);
            if place == Placement::Outside {
                continue;
            }
            bits = bits.max(c.bits);
            let root = if place == Placement::Straddles {
                at_boundary(sys, &c.value, unknowns, opts, &not_an_answer)
            } else {
                Some(CertifiedRoot::from_root(&c.value, false))
            };
            if let Some(root) = root {
                push_unique(&mut roots, root, unknowns);
            }
        }
    }
    seam::drop_copies(sys, &mut roots, unknowns);
    Ok(Found {
        roots,
        undecided,
        searched: complete,
        bits,
        reason,
    })
}

/// The certified answer of a root search: the roots sorted by parameter, the largest
/// perturbation of a singular root, the reason only when incomplete, and `undecided`
/// when an incomplete search certified no root at all (nothing proven). Shared by
/// [`certify_roots_with`] and the knot-span search ([`pieces`]).
pub(crate) fn answer(
    mut roots: Vec<CertifiedRoot>,
    status: Status,
    complete: bool,
    bits: u32,
    reason: Option<String>,
) -> Certified<Vec<CertifiedRoot>> {
    let perturbation = roots.iter().filter_map(|r| r.perturbation).reduce(f64::max);
    roots.sort_by(|a, b| {
        a.params
            .partial_cmp(&b.params)
            .unwrap_or(std::cmp::Ordering::Equal)
    });
    let status = if !complete && roots.is_empty() {
        Status::Undecided
    } else {
        status
    };
    Certified {
        value: roots,
        status,
        complete,
        arithmetic: if bits > 53 {
            Arithmetic::Mpfr
        } else {
            Arithmetic::Interval
        },
        bits,
        reason: if complete { None } else { reason },
        perturbation,
    }
}

/// A root whose box straddles a true end of the domain, decided where possible
/// ([`boundary`]): `None` when it is proven outside the domain, `undecided` when it
/// cannot be placed, dropped when `not_an_answer` proves it no answer.
fn at_boundary<S: System>(
    sys: &S,
    r: &Root,
    unknowns: &Unknowns,
    opts: &Options,
    not_an_answer: &impl Fn(&Root) -> bool,
) -> Option<CertifiedRoot> {
    match decide_boundary(sys, r, unknowns, opts.max_bits) {
        Decided::Inside(root) => Some(root),
        Decided::Outside => None,
        Decided::Open if not_an_answer(r) => None,
        Decided::Open => Some(CertifiedRoot::from_root(r, true)),
    }
}

/// Add `root` unless it is the seam copy of a root already found (module doc).
///
/// A root whose box lies (shifted by whole periods) inside a kept box is dropped: a
/// `verified` box holds that one root, a `verified_singular` box counts up to two. A
/// root whose box holds kept boxes replaces them when it may hold more roots than
/// they count (a singular box over a simple one: dropping it would lose a root);
/// otherwise the narrower kept box stays.
pub(crate) fn push_unique(
    roots: &mut Vec<CertifiedRoot>,
    root: CertifiedRoot,
    unknowns: &Unknowns,
) {
    if let Some(r) = roots
        .iter_mut()
        .find(|r| shifted_inside(&root.enclosure, &r.enclosure, unknowns))
    {
        // An undecided box may hold more roots than this one: both stay, and
        // `seam::drop_copies` drops the box when one root is proven in it. (Replacing
        // the box by the root lost a second root it held: soak seed 26, two roots
        // 7·10⁻⁷ apart across a closed NURBS curve's seam near a sphere's pole.)
        if r.status == Status::Undecided && root.status != Status::Undecided {
            roots.push(root);
        }
        return;
    }
    let inside: Vec<usize> = (0..roots.len())
        .filter(|&i| shifted_inside(&roots[i].enclosure, &root.enclosure, unknowns))
        .collect();
    if inside.is_empty() {
        roots.push(root);
        return;
    }
    let counted: u32 = inside.iter().map(|&i| roots[i].max_roots.max(1)).sum();
    if root.max_roots > counted {
        for &i in inside.iter().rev() {
            roots.remove(i);
        }
        roots.push(root);
    }
}

/// Where a root's enclosure lies against the domain in its non-periodic coordinates.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Placement {
    Inside,
    Straddles,
    Outside,
}

fn placement(enclosure: &[Interval], search: &[[f64; 2]], unknowns: &Unknowns) -> Placement {
    let mut straddles = false;
    for ((x, &[lo, hi]), &periodic) in enclosure.iter().zip(search).zip(&unknowns.periodic) {
        if periodic {
            continue;
        }
        if x.hi() < lo || x.lo() > hi {
            return Placement::Outside;
        }
        straddles |= x.lo() < lo || x.hi() > hi;
    }
    if straddles {
        Placement::Straddles
    } else {
        Placement::Inside
    }
}

/// `a`, shifted by a whole number of periods in its periodic coordinates (by 0, +P or
/// −P), lies inside `b`.
pub(crate) fn shifted_inside(a: &[Interval], b: &[Interval], unknowns: &Unknowns) -> bool {
    // Each coordinate independently: the shifts are 0, +P, −P (P an enclosure of the
    // period), so every shifted copy is an enclosure of the shifted set.
    (0..a.len()).all(|i| {
        let shifts = if unknowns.periodic[i] {
            let p = unknowns.period(i);
            vec![Interval::point(0.0), p, -p]
        } else {
            vec![Interval::point(0.0)]
        };
        shifts.into_iter().any(|s| {
            let shifted = a[i] + s;
            !shifted.is_empty() && shifted.is_subset(&b[i])
        })
    })
}

/// The point `x`, shifted by whole periods, lies in the box.
fn contains(enclosure: &[Interval], x: &[f64], unknowns: &Unknowns) -> bool {
    let point: Vec<Interval> = x.iter().map(|&v| Interval::point(v)).collect();
    shifted_inside(&point, enclosure, unknowns)
}

/// A certified solution with its point: the parameters' root and the point's
/// estimate and enclosure (the shape evaluated in intervals over the parameter box).
#[derive(Debug, Clone, PartialEq)]
pub struct CertifiedPoint<const D: usize> {
    pub root: CertifiedRoot,
    /// The point at the parameters' estimate (f64 evaluation).
    pub point: [f64; D],
    /// An enclosure of the point over the parameter enclosure.
    pub point_box: [Interval; D],
}

/// `Unknowns` of a curve's parameter.
pub fn curve_unknowns<C: crate::curve::Curve<D>, const D: usize>(c: &C) -> Unknowns {
    let (lo, hi) = c.domain();
    Unknowns {
        domain: vec![[lo, hi]],
        periodic: vec![c.is_closed()],
        rounded: vec![c.domain_rounded()],
    }
}

/// `Unknowns` of a surface's two parameters.
pub fn surface_unknowns<S: crate::surface::Surface>(s: &S) -> Unknowns {
    let (u, v) = s.domain();
    let closed = s.is_closed();
    Unknowns {
        domain: vec![u, v],
        periodic: closed.to_vec(),
        rounded: s.domain_rounded().to_vec(),
    }
}

impl Unknowns {
    /// The unknowns of several objects, one after the other.
    pub fn concat(parts: &[Unknowns]) -> Unknowns {
        Unknowns {
            domain: parts.iter().flat_map(|p| p.domain.clone()).collect(),
            periodic: parts.iter().flat_map(|p| p.periodic.clone()).collect(),
            rounded: parts.iter().flat_map(|p| p.rounded.clone()).collect(),
        }
    }
}

/// A curve's point and its enclosure over the parameter box `t`.
pub fn curve_point<C: crate::curve::Curve<D>, const D: usize>(
    c: &C,
    t: f64,
    t_box: &Interval,
) -> ([f64; D], [Interval; D]) {
    let p = c.jet(&t, 0)[0];
    let b = c.jet(t_box, 0).swap_remove(0);
    (p, b)
}

/// Two enclosures of one point (a root's point on each of two objects): their
/// intersection, which holds every point both hold. A far smaller box where one
/// enclosure is loose — a NURBS curve evaluated in intervals far from the origin, whose
/// box grows with the coordinates, not with the curve. Where the two miss (a singular
/// box may hold no root at all) the first is kept.
pub fn meet<const D: usize>(a: [Interval; D], b: &[Interval; D]) -> [Interval; D] {
    let both: [Interval; D] = std::array::from_fn(|i| a[i].intersection(&b[i]));
    if both.iter().any(Interval::is_empty) {
        a
    } else {
        both
    }
}

/// Roots in a curve's one parameter as points of the curve ([`curve_point`]).
pub fn curve_points<C: crate::curve::Curve<D>, const D: usize>(
    c: &C,
    roots: Certified<Vec<CertifiedRoot>>,
) -> Certified<Vec<CertifiedPoint<D>>> {
    roots.map(|rs| {
        rs.into_iter()
            .map(|root| {
                let (point, point_box) = curve_point(c, root.params[0], &root.enclosure[0]);
                CertifiedPoint {
                    root,
                    point,
                    point_box,
                }
            })
            .collect()
    })
}

/// A surface's point and its enclosure over the parameter box.
pub fn surface_point<S: crate::surface::Surface>(
    s: &S,
    uv: [f64; 2],
    u_box: &Interval,
    v_box: &Interval,
) -> ([f64; 3], [Interval; 3]) {
    let p = s.jet(&uv[0], &uv[1], 0)[0];
    let b = s.jet(u_box, v_box, 0).swap_remove(0);
    (p, b)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::num::Real;

    fn root(lo: f64, hi: f64, status: Status, max_roots: u32) -> CertifiedRoot {
        CertifiedRoot {
            params: vec![(lo + hi) / 2.0],
            enclosure: vec![Interval::from_bounds(lo, hi)],
            status,
            max_roots,
            bits: 53,
            perturbation: None,
            reason: None,
        }
    }

    fn line(periodic: bool) -> Unknowns {
        Unknowns {
            domain: vec![[0.0, 1.0]],
            periodic: vec![periodic],
            rounded: vec![false],
        }
    }

    #[test]
    fn a_singular_box_over_a_simple_one_is_kept_with_its_count() {
        let u = line(false);
        let mut roots = vec![root(0.45, 0.55, Status::Verified, 1)];
        push_unique(&mut roots, root(0.3, 0.7, Status::VerifiedSingular, 2), &u);
        assert_eq!(roots.len(), 1);
        assert_eq!(
            roots[0].max_roots, 2,
            "the box that may hold two roots stays"
        );
        // The other order: the simple root inside the singular box adds nothing.
        let mut roots = vec![root(0.3, 0.7, Status::VerifiedSingular, 2)];
        push_unique(&mut roots, root(0.45, 0.55, Status::Verified, 1), &u);
        assert_eq!((roots.len(), roots[0].max_roots), (1, 2));
        // A simple root inside a simple box is that root.
        let mut roots = vec![root(0.3, 0.7, Status::Verified, 1)];
        push_unique(&mut roots, root(0.45, 0.55, Status::Verified, 1), &u);
        assert_eq!((roots.len(), roots[0].enclosure[0].lo()), (1, 0.3));
        // A verified root inside an undecided box: the box may hold another root, so
        // both stay (`seam::drop_copies` drops the box only with a proof). Also across
        // the seam of a periodic coordinate.
        for (periodic, shift) in [(false, 0.0), (true, 1.0)] {
            let u = line(periodic);
            let mut roots = vec![root(-0.2, 0.2, Status::Undecided, 1)];
            push_unique(
                &mut roots,
                root(0.05 + shift, 0.1 + shift, Status::Verified, 1),
                &u,
            );
            let kinds: Vec<Status> = roots.iter().map(|r| r.status).collect();
            assert_eq!(kinds, [Status::Undecided, Status::Verified]);
        }
    }

    #[test]
    fn placement_against_the_domain() {
        let search = [[0.0, 1.0]];
        let at = |lo, hi| vec![Interval::from_bounds(lo, hi)];
        assert_eq!(
            placement(&at(0.2, 0.3), &search, &line(false)),
            Placement::Inside
        );
        assert_eq!(
            placement(&at(0.99, 1.01), &search, &line(false)),
            Placement::Straddles
        );
        assert_eq!(
            placement(&at(1.1, 1.2), &search, &line(false)),
            Placement::Outside
        );
        assert_eq!(
            placement(&at(1.1, 1.2), &search, &line(true)),
            Placement::Inside
        );
    }

    /// `(t − 0.5)(t − 1.5) = 0`: one root in the domain [0, 1], one outside.
    struct Shifted;
    impl System for Shifted {
        fn dim(&self) -> usize {
            1
        }
        fn eval<T: Real>(&self, x: &[T]) -> Vec<T> {
            vec![(x[0].clone() - &x[0].lift(0.5)) * &(x[0].clone() - &x[0].lift(1.5))]
        }
    }

    #[test]
    fn a_float_answer_outside_the_domain_is_not_certified_as_an_answer() {
        // One box: the search cannot finish, so the guesses are certified one by one.
        let opts = Options {
            max_boxes: 1,
            ..Options::default()
        };
        let guesses = [vec![0.5], vec![1.5]];
        let c = certify_roots(&Shifted, &line(false), &guesses, &opts).expect("runs");
        assert!(!c.complete);
        assert_eq!(c.value.len(), 1, "{:?}", c.value);
        assert!(c.value[0].enclosure[0].contains(0.5));
        assert_eq!(c.value[0].status, Status::Verified);
    }
}
