//! The whole robustness benchmark (`geocert bench robustness`): the linear table with
//! the Kettner grid ([`super::table`]) and the curved near-tangency table
//! ([`super::curved`]), as text and as JSON. Deterministic from the seed: no timings.

use std::fmt;

use serde_json::{json, Value};

use super::curved::{curved_table, CurvedTable};
use super::table::{robustness_table, Errors, Table};

/// Both tables.
#[derive(Debug, Clone, PartialEq)]
pub struct Report {
    pub linear: Table,
    pub curved: CurvedTable,
}

impl Report {
    /// Run both tables: `cases` per linear row, `curved_cases` per curved family and gap.
    pub fn run(seed: u64, cases: usize, curved_cases: usize, threads: usize) -> Report {
        Report {
            linear: robustness_table(seed, cases, threads),
            curved: curved_table(seed, curved_cases, threads),
        }
    }

    /// Wrong certified answers over both tables (must be 0).
    pub fn certified_failures(&self) -> usize {
        self.linear.certified_failures() + self.curved.certified_failures()
    }

    /// The report as JSON (keys sorted; counts as integers, `bits_mean` as a double).
    pub fn to_json(&self) -> Value {
        let errors = |e: &Errors| json!({"verdict": e.verdict, "off": e.off});
        let linear: Vec<Value> = self
            .linear
            .rows
            .iter()
            .map(|r| {
                json!({
                    "construction": r.construction.name(),
                    "generator": r.generator.name(),
                    "cases": r.cases,
                    "plain_f64": errors(&r.plain),
                    "cgal_epick": r.epick.map(|e| json!({
                        "verdict": e.verdict, "off": e.off, "not_run": e.not_run
                    })),
                    "float_only": {"undecided": r.filter_undecided, "wrong": r.filter_wrong},
                    "certified": errors(&r.certified),
                })
            })
            .collect();
        let k = &self.linear.kettner;
        let kettner = json!({
            "points": k.points,
            "collinear": k.collinear,
            "plain_f64_wrong": k.plain_wrong,
            "cgal_epick_collinearity_wrong": k.epick_wrong,
            "filter_undecided": k.filter_undecided,
            "certified_wrong": k.certified_wrong,
            "truth_signs": {"negative": k.truth_signs[0], "zero": k.truth_signs[1], "positive": k.truth_signs[2]},
            "plain_f64_signs": {"negative": k.plain_signs[0], "zero": k.plain_signs[1], "positive": k.plain_signs[2]},
        });
        let curved: Vec<Value> = self
            .curved
            .rows
            .iter()
            .map(|r| {
                let arithmetic: serde_json::Map<String, Value> = r
                    .arithmetic
                    .iter()
                    .map(|(n, c)| (n.to_string(), json!(c)))
                    .collect();
                json!({
                    "family": r.family.name(),
                    "gap": r.gap.label(),
                    "gap_value": r.gap.value(),
                    "cases": r.cases,
                    "meeting": r.meeting,
                    "float": {"wrong_count": r.float_wrong_count, "off": r.float_off},
                    "certified": {
                        "wrong": r.certified_wrong,
                        "undecided": r.certified_undecided,
                        "bits_mean": r.bits_mean(),
                        "bits_max": r.bits_max,
                        "arithmetic": arithmetic,
                    },
                })
            })
            .collect();
        json!({
            "seed": self.linear.seed,
            "linear_cases": self.linear.cases,
            "curved_cases": self.curved.cases,
            "linear": linear,
            "kettner": kettner,
            "curved": curved,
            "certified_failures": self.certified_failures(),
        })
    }
}

impl fmt::Display for Report {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        self.linear.fmt_rows(f)?;
        self.linear.fmt_kettner(f)?;
        writeln!(f)?;
        write!(f, "{}", self.curved)?;
        writeln!(
            f,
            "\ngeocert certified: {} wrong answers in total.",
            self.certified_failures()
        )
    }
}
