//! `--format table`: one human-readable row per result (status, kind, completeness,
//! the arithmetic that decided it, and the answer), the same rows as `geocert demo`.
//! Columns have fixed widths so rows can be written as they come; a longer id or
//! status pushes its row's later columns right.

use geocert::io::number::shortest;
use geocert::io::result::CaseResult;

/// The header line (with a time column when `timings`).
pub fn header(timings: bool) -> String {
    let time = if timings {
        format!("  {:>8}", "µs")
    } else {
        String::new()
    };
    let head = format!(
        "{:<16}  {:<17}  {:<10}  {:<8}  {:<10}{time}  answer",
        "case", "status", "kind", "complete", "decided by"
    );
    format!("{head}\n{}\n", "-".repeat(head.chars().count() + 20))
}

/// One row for a result; `id` is the id as written.
pub fn row(r: &CaseResult, id: &str, timings: bool) -> String {
    let complete = match r.complete {
        Some(true) => "yes",
        Some(false) => "no",
        None => "-",
    };
    let time = if timings {
        format!(
            "  {:>8}",
            r.micros.map_or("-".to_string(), |m| m.to_string())
        )
    } else {
        String::new()
    };
    format!(
        "{id:<16}  {:<17}  {:<10}  {complete:<8}  {:<10}{time}  {}\n",
        r.status,
        r.kind.unwrap_or("-"),
        r.arithmetic.unwrap_or("-"),
        answer_text(r)
    )
}

/// The id as text: a string without its quotes, anything else as JSON.
pub fn id_text(id: &serde_json::Value) -> String {
    match id {
        serde_json::Value::String(s) => s.clone(),
        other => other.to_string(),
    }
}

fn vector_text(v: &[f64]) -> String {
    let parts: Vec<String> = v.iter().map(|&x| shortest(x)).collect();
    format!("({})", parts.join(", "))
}

/// The answer in one line: the error, the points, the line or segment, or the reason.
pub fn answer_text(r: &CaseResult) -> String {
    if let Some(e) = &r.error {
        return format!("{}: {}", e.kind, e.message);
    }
    let mut text = if let Some(points) = &r.points {
        let texts: Vec<String> = points.iter().map(point_text).collect();
        texts.join("; ")
    } else if let Some(line) = &r.line {
        format!(
            "point {} dir {}",
            vector_text(&line.point),
            vector_text(&line.dir)
        )
    } else if let Some(seg) = &r.segment {
        format!("{} – {}", vector_text(&seg.a.xyz), vector_text(&seg.b.xyz))
    } else if let Some(conic) = &r.conic {
        // A plane section of a quadric: the exact conic (its curve list may be empty).
        let mut t = conic.kind.to_string();
        if let Some(c) = &conic.center {
            t.push_str(&format!(", centre {}", vector_text(&c.value)));
        }
        let axes: Vec<String> = conic
            .axes
            .iter()
            .filter_map(|a| a.length.value.first().map(|l| format!("{l}")))
            .collect();
        if !axes.is_empty() {
            t.push_str(&format!(", semi-axes {}", axes.join(", ")));
        }
        t
    } else if let Some(curves) = &r.curves {
        curves_text(curves, r.singular_points.as_deref().unwrap_or(&[]))
    } else {
        r.reason.clone().unwrap_or_default()
    };
    if let Some(claims) = &r.claims {
        let verdicts: Vec<String> = claims
            .iter()
            .map(|c| format!("{} {}", c.item, c.verdict))
            .collect();
        text = format!("{text} | claims: {}", verdicts.join(", "));
    }
    if let Some(missed) = r.missed.as_ref().filter(|m| !m.is_empty()) {
        text = format!("{text} | missed {}", missed.len());
    }
    text
}

/// Kind `curves`: one phrase per curve (closed or open, vertices, its status and proven
/// distance bound) and per singular point (where, its status, how many branches meet).
fn curves_text(
    curves: &[geocert::io::result::CurveOut],
    singular: &[geocert::io::result::SingularPointOut],
) -> String {
    let mut parts: Vec<String> = curves
        .iter()
        .map(|c| {
            let shape = if c.closed { "closed" } else { "open" };
            let mut s = format!("{shape} curve, {} vertices, {}", c.points.len(), c.status);
            if let Some(d) = c.distance_bound {
                s += &format!(" within {}", shortest(d));
            }
            if let Some(reason) = &c.reason {
                s += &format!(" ({reason})");
            }
            s
        })
        .collect();
    parts.extend(singular.iter().map(|p| {
        format!(
            "singular point {} {}, {} branches",
            vector_text(&p.point.xyz),
            p.status,
            p.branches
        )
    }));
    if parts.is_empty() {
        "no curve".to_string()
    } else {
        parts.join("; ")
    }
}

fn point_text(p: &geocert::io::result::PointOut) -> String {
    let params: Vec<String> = p
        .params
        .iter()
        .filter(|ps| !ps.is_empty())
        .map(|ps| vector_text(ps))
        .collect();
    let mut s = vector_text(&p.xyz);
    if !params.is_empty() {
        s += &format!(" params {}", params.join(" "));
    }
    if let Some(d) = p.signed_distance.or(p.distance) {
        s += &format!(" distance {}", shortest(d));
    }
    if let Some(exact) = p.exact.as_ref().filter(|e| !e.xyz.is_empty()) {
        s += &format!(" exact ({})", exact.xyz.join(", "));
    }
    s
}
