//! `geocert bench cases`: seeded case files for measuring `solve` (JSON Lines on
//! standard output; the same seed gives the same bytes), so that no large file needs
//! to be committed. `line-plane`: generic line–plane intersections (decided by the
//! float filter). `curved`: a mix of numerically certified curved operations
//! (projections onto tori and cylinders, helix and circle intersections), each a
//! few milliseconds, to measure how `--jobs` scales.

use clap::ValueEnum;
use geocert::io::number::shortest;
use geocert::robust::rng::Rng;
use std::io::Write;

/// The kind of cases to generate.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum Family {
    LinePlane,
    Curved,
}

fn v(x: &[f64]) -> String {
    let parts: Vec<String> = x.iter().map(|&c| shortest(c)).collect();
    format!("[{}]", parts.join(","))
}

fn line_plane(i: u64, rng: &mut Rng) -> String {
    let p: Vec<f64> = (0..9).map(|_| rng.generic()).collect();
    let d = rng.generic();
    format!(
        r#"{{"id":{i},"op":"intersect","objects":[{{"type":"line","origin":{},"dir":{}}},{{"type":"plane","normal":{},"d":{}}}]}}"#,
        v(&p[0..3]),
        v(&p[3..6]),
        v(&p[6..9]),
        shortest(d)
    )
}

fn curved(i: u64, rng: &mut Rng) -> String {
    let q: Vec<f64> = (0..3).map(|_| 3.0 * rng.unit()).collect();
    let torus = r#"{"type":"torus","center":[0,0,0],"major":3,"minor":1,"axis":[0,0,1]}"#;
    let cylinder =
        r#"{"type":"cylinder","origin":[0,0,0],"radius":1,"axis":[0,0,1],"height":[0,2]}"#;
    match i % 4 {
        0 => format!(
            r#"{{"id":{i},"op":"project","point":{},"onto":{torus}}}"#,
            v(&q)
        ),
        1 => format!(
            r#"{{"id":{i},"op":"project","nearest":true,"point":{},"onto":{cylinder}}}"#,
            v(&q)
        ),
        2 => format!(
            r#"{{"id":{i},"op":"intersect","objects":[{{"type":"helix","center":[0,0,0],"radius":1,"pitch":1,"axis":[0,0,1],"range":[0,12.5]}},{{"type":"line","origin":[{},{},-5],"dir":[0,0,1]}}]}}"#,
            shortest(q[0] / 3.0),
            shortest(q[1] / 3.0)
        ),
        _ => format!(
            r#"{{"id":{i},"op":"intersect","objects":[{{"type":"circle","center":[0,0,0],"radius":1,"axis":[0,0,1]}},{{"type":"segment","a":[{},0,-1],"b":[{},1,1]}}]}}"#,
            shortest(q[0] / 3.0),
            shortest(q[1] / 3.0)
        ),
    }
}

/// Write `count` cases of `family` from `seed` to standard output.
pub fn run(family: Family, count: u64, seed: u64) -> std::io::Result<()> {
    let mut rng = Rng::new(seed);
    let mut out = std::io::BufWriter::new(std::io::stdout().lock());
    for i in 0..count {
        let line = match family {
            Family::LinePlane => line_plane(i, &mut rng),
            Family::Curved => curved(i, &mut rng),
        };
        writeln!(out, "{line}")?;
    }
    out.flush()
}
