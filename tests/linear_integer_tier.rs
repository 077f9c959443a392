//! The integer tier of the linear kernel (`Arithmetic::Integer`, between the filter and
//! the expansions): exactly degenerate input is decided there, exactly (every answer
//! equals the exact rational answer, correctly rounded); full 53-bit data needing more
//! than 128 bits is decided by the wide (768-bit) attempt; mixed magnitudes 1e±150,
//! whose sums need ~1000-bit shifts, overflow the fixed width and fall through to
//! expansions or rationals — still exactly right.

use geocert::geom::line_plane::{intersect_line_plane, intersect_line_plane_exact, LinePlane};
use geocert::geom::plane_plane::{
    intersect_plane_plane, intersect_plane_plane_exact, ParamLine, PlaneLine, PlanePlane,
};
use geocert::geom::three_planes::{
    intersect_three_planes, intersect_three_planes_exact, ThreePlanes,
};
use geocert::geom::Plane;
use geocert::num::round::{round_rational, scale_pow2, Rounded};
use geocert::robust::case::{q, same};
use geocert::robust::{case, Case, Construction, Generator};
use geocert::Arithmetic;
use nalgebra::Vector3;
use rug::Rational;
use std::collections::BTreeMap;

/// An exact plane line rounded the way the certified path reports it (directions
/// scaled by `2^k`, see `PlaneLine`).
fn rounded_line(l: PlaneLine<Rational>, k: i32) -> PlaneLine<Rounded> {
    let scaled = |x: Rational| round_rational(&scale_pow2(&x, k));
    let pl = |p: ParamLine<Rational>| ParamLine {
        origin: p.origin.map(|x| round_rational(&x)),
        dir: p.dir.map(scaled),
    };
    PlaneLine {
        point: l.point.map(|x| round_rational(&x)),
        dir: l.dir.map(scaled),
        dir_exponent: k,
        on_a: l.on_a.map(pl),
        on_b: l.on_b.map(pl),
    }
}

fn three_truth(exact: ThreePlanes<Rational>, k: i32) -> ThreePlanes<Rounded> {
    match exact {
        ThreePlanes::Line { line, pair } => ThreePlanes::Line {
            line: rounded_line(line, k),
            pair,
        },
        other => other.map(|x| round_rational(&x)),
    }
}

fn line_exponent<S: nalgebra::Scalar>(r: &ThreePlanes<S>) -> i32 {
    match r {
        ThreePlanes::Line { line, .. } => line.dir_exponent,
        _ => 0,
    }
}

/// Run every case of a generator through the certified path, check it against the
/// exact answer, and count the deciding tiers.
fn run(construction: Construction, generator: Generator, n: u64) -> BTreeMap<&'static str, usize> {
    let mut tiers = BTreeMap::new();
    for seed in 0..n {
        let c = case(construction, generator, seed);
        let arithmetic = match &c {
            Case::ThreePlanes(p) => {
                let f = p.map(|x| x.object(same).unwrap());
                let e = p.map(|x| x.object(q).unwrap());
                let cert = intersect_three_planes(&f);
                let k = line_exponent(&cert.value);
                assert_eq!(
                    cert.value,
                    three_truth(intersect_three_planes_exact(&e), k),
                    "{}",
                    c.json_line("tier")
                );
                cert.arithmetic
            }
            Case::LinePlane(l, p) => {
                let (lf, pf) = (l.object(same).unwrap(), p.object(same).unwrap());
                let (le, pe) = (l.object(q).unwrap(), p.object(q).unwrap());
                let cert = intersect_line_plane(lf.linear(), &pf);
                let truth: LinePlane<Rounded> =
                    intersect_line_plane_exact(le.linear(), &pe).map(|x| round_rational(&x));
                assert_eq!(cert.value, truth, "{}", c.json_line("tier"));
                cert.arithmetic
            }
            Case::PlanePlane(a, b) => {
                let (af, bf) = (a.object(same).unwrap(), b.object(same).unwrap());
                let (ae, be) = (a.object(q).unwrap(), b.object(q).unwrap());
                let cert = intersect_plane_plane(&af, &bf);
                let truth = match intersect_plane_plane_exact(&ae, &be) {
                    PlanePlane::Line(l) => {
                        let k = match &cert.value {
                            PlanePlane::Line(c) => c.dir_exponent,
                            _ => 0,
                        };
                        PlanePlane::Line(rounded_line(l, k))
                    }
                    PlanePlane::Parallel => PlanePlane::Parallel,
                    PlanePlane::Coincident => PlanePlane::Coincident,
                };
                assert_eq!(cert.value, truth, "{}", c.json_line("tier"));
                cert.arithmetic
            }
            _ => unreachable!(),
        };
        *tiers.entry(arithmetic.as_str()).or_default() += 1;
    }
    tiers
}

const CONSTRUCTIONS: [Construction; 3] = [
    Construction::ThreePlanes,
    Construction::LinePlane,
    Construction::PlanePlane,
];

/// Exactly degenerate configurations on short dyadic data (a quarter scaled by
/// `2^k`, `|k| ≤ 200`): all decided by the integer tier, all exactly right.
#[test]
fn degenerate_input_is_decided_exactly_in_integers() {
    for c in CONSTRUCTIONS {
        let tiers = run(c, Generator::Degenerate, 400);
        assert_eq!(tiers.get("integer"), Some(&400), "{c:?}: {tiers:?}");
    }
}

/// Magnitudes `m·2^e`, `e ∈ [−498, 498]`, mixed in one object: beyond the filter's
/// range, and (for the formulas' sums) beyond the integers' width. Every answer is
/// exactly right, and the integer tier answers only the few cases whose exponents
/// happen to lie close together.
#[test]
fn mixed_magnitudes_fall_through_to_expansions_and_rationals() {
    for c in CONSTRUCTIONS {
        let tiers = run(c, Generator::Mixed, 300);
        assert_eq!(tiers.get("filter"), None, "{c:?}: {tiers:?}");
        let integer = tiers.get("integer").copied().unwrap_or(0);
        assert!(integer < 30, "{c:?}: {tiers:?}");
        let fell = tiers.get("expansion").copied().unwrap_or(0)
            + tiers.get("rational").copied().unwrap_or(0);
        assert!(fell >= 270, "{c:?}: {tiers:?}");
    }
}

/// One-ulp perturbations of degenerate configurations: the filter abstains on most,
/// the integer tier decides most, and every answer is exactly right.
#[test]
fn perturbed_input_is_exactly_right() {
    for c in CONSTRUCTIONS {
        let tiers = run(c, Generator::Perturbed, 300);
        // The perturbed coordinate has a full significand: the wide integers decide
        // nearly all (the rest are scaled cases with exponent spreads of hundreds).
        let integer = tiers.get("integer").copied().unwrap_or(0);
        assert!(integer >= 250, "{c:?}: {tiers:?}");
    }
}

/// Three planes through one line given by full 53-bit doubles: the degree-11 line test
/// needs ~580-bit integers, beyond 128 bits; the wide attempt decides it (`bits`
/// reports integers longer than 128 bits), exactly.
#[test]
fn full_significands_use_the_wide_integers() {
    let mut seed = 0x0123_4567_89AB_CDEFu64;
    let mut next = || {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        1.0 + (seed >> 12) as f64 / (1u64 << 52) as f64
    };
    for _ in 0..50 {
        let v = |n: &mut dyn FnMut() -> f64| Vector3::new(n(), -n(), n());
        let (o, d) = (v(&mut next), v(&mut next));
        let planes =
            [v(&mut next), v(&mut next), v(&mut next)].map(|w| Plane::parametric(o, d, w).unwrap());
        let cert = intersect_three_planes(&planes);
        assert_eq!(cert.arithmetic, Arithmetic::Integer);
        assert!(cert.bits > 128, "{}", cert.bits);
        let r = |x: f64| Rational::from_f64(x).unwrap();
        let exact = planes.clone().map(|p| match p {
            Plane::Parametric { origin, u, v } => {
                Plane::parametric(origin.map(r), u.map(r), v.map(r)).unwrap()
            }
            Plane::Implicit { .. } => unreachable!(),
        });
        let k = line_exponent(&cert.value);
        let truth = three_truth(intersect_three_planes_exact(&exact), k);
        assert!(matches!(truth, ThreePlanes::Line { .. }));
        assert_eq!(cert.value, truth);
    }
}
