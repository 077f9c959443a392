//! `geocert bench robustness --json FILE --plots DIR` (issue 19): the same seed gives
//! the same bytes (two runs, on 2 and 1 threads), and the files have the structure the
//! report says: the Kettner sign maps are 256×256 and count exactly the table's signs
//! per colour; each SVG chart has one series per curved family with one point per gap,
//! placed where the JSON's numbers put them.

use std::path::Path;
use std::process::Command;

use geocert::robust::curved::{Family, Gap};
use geocert::robust::plot::{COLLINEAR, FILES, NEGATIVE, POSITIVE};
use serde_json::Value;

fn run(dir: &Path, threads: &str) -> String {
    let out = Command::new(env!("CARGO_BIN_EXE_geocert"))
        .args(["bench", "robustness", "--seed", "3", "--cases", "20"])
        .args(["--curved-cases", "2", "--threads", threads])
        .arg("--json")
        .arg(dir.join("report.json"))
        .arg("--plots")
        .arg(dir)
        .output()
        .expect("run geocert");
    assert!(out.status.success(), "{out:?}");
    String::from_utf8(out.stdout).expect("utf-8")
}

fn tmp(name: &str) -> std::path::PathBuf {
    let d = std::env::temp_dir().join(format!("geocert-plots-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).expect("temp dir");
    d
}

/// Pixels of each of the three sign colours (and of any other colour) in a PNG map.
fn colour_counts(path: &Path) -> ([usize; 3], usize, (u32, u32)) {
    let decoder = png::Decoder::new(std::fs::File::open(path).expect("png"));
    let mut reader = decoder.read_info().expect("png header");
    let mut buf = vec![0; reader.output_buffer_size()];
    let info = reader.next_frame(&mut buf).expect("png frame");
    assert_eq!(info.color_type, png::ColorType::Rgb, "{path:?}");
    let mut counts = [0; 3];
    let mut other = 0;
    for px in buf[..info.buffer_size()].chunks(3) {
        let c = (px[0], px[1], px[2]);
        match [NEGATIVE, COLLINEAR, POSITIVE]
            .iter()
            .position(|k| (k.0, k.1, k.2) == c)
        {
            Some(i) => counts[i] += 1,
            None => other += 1,
        }
    }
    (counts, other, (info.width, info.height))
}

fn signs(v: &Value) -> [usize; 3] {
    ["negative", "zero", "positive"].map(|k| v[k].as_u64().expect("count") as usize)
}

/// The `points` of the polylines drawn in `colour` (`#RRGGBB`).
fn polylines(svg: &str, colour: &str) -> Vec<Vec<(i64, i64)>> {
    svg.lines()
        .filter(|l| l.starts_with("<polyline") && l.contains(&format!("stroke=\"{colour}\"")))
        .map(|l| {
            let p = l.split("points=\"").nth(1).expect("points");
            p.split('"')
                .next()
                .unwrap_or("")
                .split_whitespace()
                .map(|xy| {
                    let (x, y) = xy.split_once(',').expect("x,y");
                    (x.parse().expect("x"), y.parse().expect("y"))
                })
                .collect()
        })
        .collect()
}

fn circles(svg: &str, colour: &str) -> usize {
    svg.lines()
        .filter(|l| l.starts_with("<circle") && l.contains(&format!("fill=\"{colour}\"")))
        .count()
}

const FAMILY_COLOURS: [&str; 5] = ["#0072B2", "#D55E00", "#009E73", "#CC79A7", "#56B4E9"];

/// Each family: one series polyline with a point per gap, one legend stroke, and a
/// marker per gap; the tick labels and names are there. Returns the series.
fn check_chart(svg: &str) -> Vec<Vec<(i64, i64)>> {
    let gaps = Gap::all().len();
    assert_eq!(svg.matches("<circle").count(), Family::ALL.len() * gaps);
    let mut series = Vec::new();
    for (f, colour) in Family::ALL.iter().zip(FAMILY_COLOURS) {
        let lines = polylines(svg, colour);
        assert_eq!(lines.len(), 2, "{f:?}: series and legend");
        assert_eq!(lines[0].len(), gaps, "{f:?}: one point per gap");
        assert_eq!(lines[1].len(), 2, "{f:?}: legend stroke");
        assert_eq!(circles(svg, colour), gaps);
        assert!(svg.contains(f.name()), "{f:?} in the legend");
        // Gaps left to right.
        assert!(lines[0].windows(2).all(|w| w[0].0 < w[1].0));
        series.push(lines[0].clone());
    }
    for label in ["1e-3", "1e-15", "1ulp", ">\n0\n<"] {
        assert!(svg.contains(label), "tick {label:?}");
    }
    series
}

#[test]
fn same_seed_same_bytes_and_the_plots_have_the_reported_structure() {
    let (a, b) = (tmp("a"), tmp("b"));
    let (out_a, out_b) = (run(&a, "2"), run(&b, "1"));
    assert_eq!(out_a, out_b);
    for f in FILES.iter().chain(&["report.json"]) {
        let (x, y) = (
            std::fs::read(a.join(f)).expect("file"),
            std::fs::read(b.join(f)).expect("file"),
        );
        assert!(!x.is_empty() && x == y, "{f} differs between two runs");
    }
    let report: Value =
        serde_json::from_slice(&std::fs::read(a.join("report.json")).expect("json")).expect("json");
    assert_eq!(report["certified_failures"], 0);

    // The sign maps: one pixel per grid point, colours counting the table's signs.
    let k = &report["kettner"];
    let (plain, other, size) = colour_counts(&a.join(FILES[0]));
    assert_eq!((size, other), ((256, 256), 0));
    assert_eq!(plain, signs(&k["plain_f64_signs"]));
    let (cert, other, size) = colour_counts(&a.join(FILES[1]));
    assert_eq!((size, other), ((256, 256), 0));
    assert_eq!(cert, signs(&k["truth_signs"]));
    assert_eq!(cert[1], k["collinear"].as_u64().unwrap() as usize);
    assert_ne!(plain, cert, "plain f64 errs on the grid");

    // The charts: the failure rate's zero points sit on the x axis (the lowest y), its
    // ones on the top; so the JSON's rows and the drawn points agree.
    let rows = report["curved"].as_array().expect("rows");
    let rate = |r: &Value| {
        let f = &r["float"];
        (f["wrong_count"].as_u64().unwrap() + f["off"].as_u64().unwrap()) as f64
            / r["cases"].as_u64().unwrap() as f64
    };
    let svg = std::fs::read_to_string(a.join(FILES[2])).expect("svg");
    let series = check_chart(&svg);
    let bottom = series.iter().flatten().map(|p| p.1).max().unwrap();
    for (f, s) in Family::ALL.iter().zip(&series) {
        let fam: Vec<&Value> = rows.iter().filter(|r| r["family"] == f.name()).collect();
        assert_eq!(fam.len(), s.len());
        for (r, p) in fam.iter().zip(s) {
            assert_eq!(rate(r) == 0.0, p.1 == bottom, "{f:?} {r} at {p:?}");
        }
        // Larger rates are drawn higher (smaller y).
        for (i, j) in (0..s.len()).flat_map(|i| (0..s.len()).map(move |j| (i, j))) {
            if rate(fam[i]) > rate(fam[j]) {
                assert!(s[i].1 <= s[j].1, "{f:?}: {i} vs {j}");
            }
        }
    }
    let svg = std::fs::read_to_string(a.join(FILES[3])).expect("svg");
    let series = check_chart(&svg);
    for (f, s) in Family::ALL.iter().zip(&series) {
        let fam: Vec<f64> = rows
            .iter()
            .filter(|r| r["family"] == f.name())
            .map(|r| r["certified"]["bits_mean"].as_f64().unwrap())
            .collect();
        for i in 0..s.len() {
            for j in 0..s.len() {
                if fam[i] > fam[j] + 5.0 {
                    assert!(s[i].1 < s[j].1, "{f:?}: bits {} vs {}", fam[i], fam[j]);
                }
            }
        }
    }
    let _ = std::fs::remove_dir_all(&a);
    let _ = std::fs::remove_dir_all(&b);
}
