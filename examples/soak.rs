//! The soak harness of issue 20 (docs/RELIABILITY.md): many seeded adversarial cases
//! through the certified paths, each graded against an independent truth, each run
//! under `catch_unwind`, reporting cases, time, wrong certificates, panics, undecided
//! answers and the slowest case per family.
//!
//! - linear: the robustness generators (`geocert::robust::gen`: generic, grid, exactly
//!   degenerate, one-ulp perturbed, magnitudes 1e±150) for the seven linear
//!   constructions, graded exactly against rational truth (`robust::methods`,
//!   `robust::answer::grade_certified`: the kind and every coordinate's correct
//!   rounding);
//! - curved: the tangency families of `geocert::robust::curved` (line–sphere,
//!   line–torus, circle–circle, circle–ellipse, circle–sphere) at gaps 1e-3 … 1e-15,
//!   1 ulp and 0, graded against MPFR truth (`robust::curved::paths::run`);
//! - seams and poles: the families of `geocert::robust::curved::seams` (common points
//!   exactly on the seam `u = 0 ≡ 2π` of a circle, sphere or torus, at a sphere's poles,
//!   one ulp or `10⁻ᵏ` off them, and tangencies there at the same gaps), graded the same
//!   way: every certified box holds one true point (a seam copy twice would be a second
//!   box on the same truth and a wrong count), a `complete` answer misses none; every
//!   parameter box holds the true parameter (angles modulo `2π`);
//! - surface ∩ surface across seams and poles (`geocert::robust::curved::ssi`): two
//!   spheres meeting in a circle through the first one's pole and seam, or touching it
//!   there, graded against the exact circle (topology, every vertex within its bound,
//!   one turn around the axis, parameters that give back the vertex).
//!
//! ```sh
//! GEOCERT_SOAK_LINEAR=1000000 GEOCERT_SOAK_CURVED=20000 GEOCERT_SOAK_SEAMS=20000 \
//!     GEOCERT_SOAK_SSI=2000 GEOCERT_SOAK_THREADS=2 cargo run --release --example soak
//! ```
//! `GEOCERT_SOAK_SEED` picks the stream (default 20). The exit status is 1 when any
//! certificate is wrong or any case panicked. Every failing case is printed with its
//! family and seed, so that it can be replayed alone.

use geocert::robust::answer::{grade_certified, rounded_truth, Grade};
use geocert::robust::curved::{self, Family, Gap};
use geocert::robust::gen::{self, Construction, Generator};
use geocert::robust::methods;
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::time::Instant;

/// How one case went.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Verdict {
    Right,
    Undecided,
    Wrong,
}

/// The counts of one family.
#[derive(Default, Clone)]
struct Tally {
    cases: u64,
    wrong: u64,
    panics: u64,
    undecided: u64,
    nanos: u128,
    slowest: (u128, String),
    failures: Vec<String>,
}

impl Tally {
    fn run(&mut self, label: impl Fn() -> String, f: impl FnOnce() -> Verdict) {
        let start = Instant::now();
        let verdict = catch_unwind(AssertUnwindSafe(f));
        let nanos = start.elapsed().as_nanos();
        self.cases += 1;
        self.nanos += nanos;
        if nanos > self.slowest.0 {
            self.slowest = (nanos, label());
        }
        let failure = match verdict {
            Ok(Verdict::Right) => None,
            Ok(Verdict::Undecided) => {
                self.undecided += 1;
                None
            }
            Ok(Verdict::Wrong) => {
                self.wrong += 1;
                Some("wrong certificate")
            }
            Err(_) => {
                self.panics += 1;
                Some("panic")
            }
        };
        if let Some(what) = failure {
            let line = format!("{what}: {}", label());
            eprintln!("soak: {line}");
            if self.failures.len() < 20 {
                self.failures.push(line);
            }
        }
    }

    fn merge(&mut self, o: Tally) {
        self.cases += o.cases;
        self.wrong += o.wrong;
        self.panics += o.panics;
        self.undecided += o.undecided;
        self.nanos += o.nanos;
        if o.slowest.0 > self.slowest.0 {
            self.slowest = o.slowest;
        }
        self.failures.extend(o.failures);
    }
}

fn env(name: &str, default: u64) -> u64 {
    match std::env::var(name) {
        Ok(v) => v
            .trim()
            .parse()
            .unwrap_or_else(|_| panic!("{name}={v} is not a count")),
        Err(_) => default,
    }
}

/// The seed of case `i` (splitmix64 of the stream seed and the index).
fn seed_of(base: u64, i: u64) -> u64 {
    let mut z = base ^ i.wrapping_mul(0x9e37_79b9_7f4a_7c15);
    z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    z ^ (z >> 31)
}

/// Linear case `i`: construction, generator and seed, graded exactly.
fn linear(t: &mut [Tally], base: u64, i: u64) {
    let nc = Construction::ALL.len() as u64;
    let c = Construction::ALL[(i % nc) as usize];
    let g = Generator::ALL[((i / nc) % Generator::ALL.len() as u64) as usize];
    let s = seed_of(base, i);
    let label = || format!("linear {} / {} seed {s}", c.name(), g.name());
    t[(i % nc) as usize].run(label, || {
        let case = gen::case(c, g, s);
        let Some(a) = methods::geocert(&case) else {
            // The generators make valid objects: a refusal is a lost answer.
            return Verdict::Wrong;
        };
        let truth = rounded_truth(&a.truth);
        match grade_certified(&a.certified, &a.truth, &truth) {
            Grade::Right => Verdict::Right,
            _ => Verdict::Wrong,
        }
    });
}

/// Curved case `i`: family, gap and seed, graded against MPFR truth.
fn curved(t: &mut [Tally], base: u64, i: u64) {
    curved_of(&Family::ALL, base ^ 0xc0ffee, t, i);
}

/// Seam and pole case `i` (`geocert::robust::curved::seams`), graded the same way.
fn seams(t: &mut [Tally], base: u64, i: u64) {
    curved_of(&Family::SEAMS, base ^ 0x5ea_5ea, t, i);
}

/// Surface ∩ surface case `i` across seams and poles (`robust::curved::ssi`), the gap
/// in turn.
fn ssi(t: &mut [Tally], base: u64, i: u64) {
    let gaps = Gap::all();
    let gap = gaps[(i % gaps.len() as u64) as usize];
    let s = seed_of(base ^ 0x551, i);
    let label = || format!("ssi seam sphere-sphere gap {} seed {s}", gap.label());
    t[0].run(label, || {
        grade(curved::ssi::run(&curved::ssi::case(gap, s)))
    });
}

/// Case `i` of `families` (family, then gap, in turn) from the stream `stream`.
fn curved_of(families: &[Family], stream: u64, t: &mut [Tally], i: u64) {
    let gaps = Gap::all();
    let nf = families.len() as u64;
    let f = families[(i % nf) as usize];
    let gap = gaps[((i / nf) % gaps.len() as u64) as usize];
    let s = seed_of(stream, i);
    let label = || format!("curved {} gap {} seed {s}", f.name(), gap.label());
    t[(i % nf) as usize].run(label, || {
        grade(curved::paths::run(&curved::case(f, gap, s)))
    });
}

/// A curved case's grade against its truth.
fn grade(o: curved::paths::Outcome) -> Verdict {
    if o.certified_wrong {
        Verdict::Wrong
    } else if o.certified_undecided {
        Verdict::Undecided
    } else {
        Verdict::Right
    }
}

/// Run `count` cases of `kind` (`families` tallies) on `threads` threads.
fn soak(
    families: usize,
    count: u64,
    threads: u64,
    base: u64,
    one: fn(&mut [Tally], u64, u64),
) -> Vec<Tally> {
    let mut all = vec![Tally::default(); families];
    let step = (count / 10).max(1);
    std::thread::scope(|s| {
        let handles: Vec<_> = (0..threads)
            .map(|k| {
                s.spawn(move || {
                    let mut t = vec![Tally::default(); families];
                    let mut i = k;
                    while i < count {
                        one(&mut t, base, i);
                        if k == 0 && i % step < threads {
                            eprintln!("soak: {i} of {count}");
                        }
                        i += threads;
                    }
                    t
                })
            })
            .collect();
        for h in handles {
            for (a, t) in all.iter_mut().zip(h.join().expect("a soak thread")) {
                a.merge(t);
            }
        }
    });
    all
}

fn print(names: &[&str], tallies: &[Tally], total: &mut Tally) {
    for (name, t) in names.iter().zip(tallies) {
        println!(
            "| {name} | {} | {:.1} | {} | {} | {} | {:.1} ms: {} |",
            t.cases,
            t.nanos as f64 * 1e-9,
            t.wrong,
            t.panics,
            t.undecided,
            t.slowest.0 as f64 * 1e-6,
            t.slowest.1
        );
        total.merge(t.clone());
    }
}

fn main() {
    let n_linear = env("GEOCERT_SOAK_LINEAR", 10_000);
    let n_curved = env("GEOCERT_SOAK_CURVED", 200);
    let threads = env("GEOCERT_SOAK_THREADS", 1).max(1);
    let n_seams = env("GEOCERT_SOAK_SEAMS", 120);
    let base = env("GEOCERT_SOAK_SEED", 20);
    let start = Instant::now();
    let lin = soak(Construction::ALL.len(), n_linear, threads, base, linear);
    let cur = soak(Family::ALL.len(), n_curved, threads, base, curved);
    let sea = soak(Family::SEAMS.len(), n_seams, threads, base, seams);
    let n_ssi = env("GEOCERT_SOAK_SSI", 30);
    let surf = soak(1, n_ssi, threads, base, ssi);
    println!(
        "geocert soak: seed {base}, {threads} thread(s), {:.1} s wall\n",
        start.elapsed().as_secs_f64()
    );
    println!("| family | cases | time (s, summed) | wrong certificates | panics | undecided | slowest case |");
    println!("|---|--:|--:|--:|--:|--:|---|");
    let mut total = Tally::default();
    let names: Vec<&str> = Construction::ALL.iter().map(|c| c.name()).collect();
    print(&names, &lin, &mut total);
    let names: Vec<&str> = Family::ALL.iter().map(|f| f.name()).collect();
    print(&names, &cur, &mut total);
    let names: Vec<&str> = Family::SEAMS.iter().map(|f| f.name()).collect();
    print(&names, &sea, &mut total);
    print(&["ssi seam sphere-sphere"], &surf, &mut total);
    println!(
        "| **total** | {} | {:.1} | {} | {} | {} | {:.1} ms: {} |",
        total.cases,
        total.nanos as f64 * 1e-9,
        total.wrong,
        total.panics,
        total.undecided,
        total.slowest.0 as f64 * 1e-6,
        total.slowest.1
    );
    for f in &total.failures {
        println!("- {f}");
    }
    if total.wrong > 0 || total.panics > 0 {
        std::process::exit(1);
    }
}
