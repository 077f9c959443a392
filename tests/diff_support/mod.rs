//! Shared machinery of the differential tests (tests/diff_*.rs): drawing cases from
//! the seeded generators of `geocert::robust` through proptest, and the exact
//! comparisons with CGAL's Epeck. A failing case is reported as one JSON line of
//! spec/CASES.md, which `geocert solve -` replays.
#![allow(dead_code)]

use geocert::num::round::{round_rational, Rounded};
use geocert::oracle::{Intersection, PlaneInput};
use geocert::robust::case::{q, PlaneIn};
use geocert::robust::{case, Case, Construction, Generator};
use geocert::{Certified, Status};
use proptest::prelude::*;
use proptest::test_runner::{Config, TestCaseError, TestError, TestRunner};
use rug::Rational;

/// The cases per construction: `GEOCERT_DIFF_CASES` (a long soak), else 100,000.
pub fn case_count() -> u32 {
    std::env::var("GEOCERT_DIFF_CASES")
        .ok()
        .and_then(|s| s.trim().replace('_', "").parse().ok())
        .unwrap_or(100_000)
}

/// Run `check` on `case_count()` cases of `construction`, drawn by proptest as
/// (generator, seed) pairs over every generator, on two threads (CI has two cores).
/// On failure, panic with the message and the case as a replayable JSON line.
pub fn run(construction: Construction, check: impl Fn(&Case) -> Result<(), String> + Sync) {
    run_seeded(
        &Generator::ALL,
        |g, seed| format!("{}/{}/{seed}", construction.name(), g.name()),
        |g, seed| case(construction, g, seed),
        |c, id| c.json_line(id),
        check,
    );
}

/// [`run`] for any seeded family of cases: proptest draws (family, seed) pairs over
/// `families`; `draw` builds a case, `id` names it and `json_line` writes it for replay.
pub fn run_seeded<F: Copy + Sync, C>(
    families: &[F],
    id: impl Fn(F, u64) -> String + Sync,
    draw: impl Fn(F, u64) -> C + Sync,
    json_line: impl Fn(&C, &str) -> String + Sync,
    check: impl Fn(&C) -> Result<(), String> + Sync,
) {
    let total = case_count();
    let halves = [total / 2, total - total / 2];
    let part = |n: u32| run_part(families, n, &id, &draw, &json_line, &check);
    std::thread::scope(|s| {
        let handles: Vec<_> = halves
            .iter()
            .map(|&n| {
                let part = &part;
                s.spawn(move || part(n))
            })
            .collect();
        let failures: Vec<String> = handles
            .into_iter()
            .filter_map(|h| match h.join() {
                Ok(Ok(())) => None,
                Ok(Err(reason)) => Some(reason),
                Err(_) => Some("a checking thread panicked".to_string()),
            })
            .collect();
        assert!(failures.is_empty(), "{}", failures.join("\n\n"));
    });
}

fn run_part<F: Copy, C>(
    families: &[F],
    cases: u32,
    id: &impl Fn(F, u64) -> String,
    draw: &impl Fn(F, u64) -> C,
    json_line: &impl Fn(&C, &str) -> String,
    check: &impl Fn(&C) -> Result<(), String>,
) -> Result<(), String> {
    let config = Config {
        cases,
        // A seed has no structure to shrink: report the first failing case.
        max_shrink_iters: 0,
        failure_persistence: None,
        ..Config::default()
    };
    let mut runner = TestRunner::new(config);
    let strategy = (0..families.len(), any::<u64>());
    let result = runner.run(&strategy, |(f, seed)| {
        let family = families[f];
        let c = draw(family, seed);
        check(&c).map_err(|msg| {
            let line = json_line(&c, &id(family, seed));
            eprintln!("{line}");
            TestCaseError::fail(format!("{msg}\nreplay with `geocert solve -`:\n{line}"))
        })
    });
    match result {
        Ok(()) => Ok(()),
        Err(TestError::Fail(reason, _)) => Err(reason.to_string()),
        Err(e) => Err(e.to_string()),
    }
}

/// Fail with `msg` unless `cond`. (Not `#[macro_export]`: several test files of one
/// suite include this module, and exported macros of the copies would collide.)
macro_rules! ensure {
    ($cond:expr, $($msg:tt)+) => {
        if !$cond {
            return Err(format!($($msg)+));
        }
    };
}
#[allow(unused_imports)]
pub(crate) use ensure;

pub type Q3 = [Rational; 3];

pub fn q3(v: &[f64; 3]) -> Q3 {
    [q(v[0]), q(v[1]), q(v[2])]
}

pub fn sub(a: &[Rational], b: &[Rational]) -> Vec<Rational> {
    a.iter()
        .zip(b)
        .map(|(x, y)| Rational::from(x - y))
        .collect()
}

pub fn dot(a: &[Rational], b: &[Rational]) -> Rational {
    a.iter().zip(b).map(|(x, y)| Rational::from(x * y)).sum()
}

/// The cross product in 3D (three components) or 2D (one).
pub fn cross(a: &[Rational], b: &[Rational]) -> Vec<Rational> {
    let c = |i: usize, j: usize| Rational::from(&a[i] * &b[j]) - Rational::from(&a[j] * &b[i]);
    if a.len() == 2 {
        vec![c(0, 1)]
    } else {
        vec![c(1, 2), c(2, 0), c(0, 1)]
    }
}

pub fn is_zero(v: &[Rational]) -> bool {
    v.iter().all(|x| x.cmp0().is_eq())
}

/// Whether two lines `p + t d` are the same set (exactly).
pub fn same_line(p1: &[Rational], d1: &[Rational], p2: &[Rational], d2: &[Rational]) -> bool {
    !is_zero(d1) && !is_zero(d2) && is_zero(&cross(d1, d2)) && is_zero(&cross(&sub(p2, p1), d1))
}

/// The plane as `n·x = k`, from the doubles taken exactly (computed here, not by geocert).
pub fn plane_equation(p: &PlaneIn) -> (Vec<Rational>, Rational) {
    match p {
        PlaneIn::Parametric { origin, u, v } => {
            let n = cross(&q3(u), &q3(v));
            let k = dot(&n, &q3(origin));
            (n, k)
        }
        PlaneIn::Implicit { normal, d } => (q3(normal).to_vec(), -q(*d)),
    }
}

pub fn on_plane(x: &[Rational], p: &PlaneIn) -> bool {
    let (n, k) = plane_equation(p);
    dot(&n, x) == k
}

/// Whether Epeck's plane `a x + b y + c z + d = 0` is the plane `p` as a set.
pub fn same_plane(coeffs: &[Rational; 4], p: &PlaneIn) -> bool {
    let (n, k) = plane_equation(p);
    let m = &coeffs[..3];
    let minus_d = Rational::from(-&coeffs[3]);
    is_zero(&cross(&n, m))
        && (0..3).all(|i| Rational::from(&k * &m[i]) == Rational::from(&minus_d * &n[i]))
}

/// `r` is exactly the correct rounding of `x` (nearest double and enclosure).
pub fn rounds(x: &Rational, r: &Rounded) -> bool {
    round_rational(x) == *r
}

pub fn rounds_all<'a>(
    xs: impl IntoIterator<Item = &'a Rational>,
    rs: impl IntoIterator<Item = &'a Rounded>,
) -> bool {
    let (xs, rs): (Vec<_>, Vec<_>) = (xs.into_iter().collect(), rs.into_iter().collect());
    xs.len() == rs.len() && xs.iter().zip(&rs).all(|(x, r)| rounds(x, r))
}

/// The certificate must claim an exact, complete answer.
pub fn certified_exact<T>(c: &Certified<T>) -> Result<(), String> {
    ensure!(
        c.status == Status::Exact && c.complete,
        "certified status {:?} (complete {}), reason {:?}",
        c.status,
        c.complete,
        c.reason
    );
    Ok(())
}

/// The kind name of an Epeck answer.
pub fn kind<T, const D: usize>(r: &Intersection<T, D>) -> &'static str {
    match r {
        Intersection::Empty => "empty",
        Intersection::Point(_) => "point",
        Intersection::Line { .. } => "line",
        Intersection::Segment { .. } => "segment",
        Intersection::Ray { .. } => "ray",
        Intersection::Plane(_) => "plane",
    }
}

pub fn oracle_plane(p: &PlaneIn) -> PlaneInput {
    p.oracle()
}
