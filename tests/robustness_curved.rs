//! The curved robustness families (geocert::robust::curved): the generators build what
//! they say (exactly tangent, or crossing / apart by the gap) as the exact truth
//! counts it; the truth's points lie on both shapes (checked at 300 bits with the
//! implicit equations, a route independent of how the truth solved them); the
//! certified path is never wrong on any family and gap; the table does not depend on
//! the thread count. The seam and pole families (`Family::SEAMS`) put a common point
//! exactly on a seam or pole (checked at 300 bits) at gap 0, and are never wrong either.

use geocert::robust::curved::truth::{truth, TruePoint, PREC};
use geocert::robust::curved::{case, curved_table, CurvedCase, Data, Family, Gap};
use rug::Float;

fn fl(x: f64) -> Float {
    Float::with_val(PREC, x)
}

fn sq(x: Float) -> Float {
    Float::with_val(PREC, &x * &x)
}

/// `|p − c|² − r²` at 300 bits.
fn sphere_residual(p: &[Float], c: &[f64], r: f64) -> Float {
    let mut s = Float::with_val(PREC, 0);
    for (x, y) in p.iter().zip(c) {
        s += sq(Float::with_val(PREC, x - *y));
    }
    s - sq(fl(r))
}

/// `|(p − o) × d|` (3D) or `|(p − o) × d|` (2D cross) at 300 bits: 0 on the line.
fn line_residual(p: &[Float], o: &[f64; 3], d: &[f64; 3]) -> Float {
    let w: Vec<Float> = (0..3)
        .map(|i| Float::with_val(PREC, &p[i] - o[i]))
        .collect();
    let mut s = Float::with_val(PREC, 0);
    for i in 0..3 {
        let (j, k) = ((i + 1) % 3, (i + 2) % 3);
        s += sq(Float::with_val(PREC, &w[j] * d[k]) - Float::with_val(PREC, &w[k] * d[j]));
    }
    s
}

/// The torus about z: `(|p_xy − c_xy| − R)² + (p_z − c_z)² − r²`.
fn torus_residual(p: &[Float], c: &[f64; 3], major: f64, minor: f64) -> Float {
    let rho =
        (sq(Float::with_val(PREC, &p[0] - c[0])) + sq(Float::with_val(PREC, &p[1] - c[1]))).sqrt();
    sq(rho - major) + sq(Float::with_val(PREC, &p[2] - c[2])) - sq(fl(minor))
}

fn small(x: Float, scale: f64) -> bool {
    x.abs() <= Float::with_val(PREC, scale) * Float::with_val(PREC, 2f64.powi(-200))
}

/// Every true point lies on both shapes.
fn on_shapes(c: &CurvedCase, p: &TruePoint) -> bool {
    let x = &p.xyz;
    let s = c.scale() * c.scale() * 1e6;
    match &c.data {
        Data::LineSphere { o, d, c: cc, r } => {
            small(line_residual(x, o, d), s) && small(sphere_residual(x, cc, *r), s)
        }
        Data::LineTorus {
            o,
            d,
            c: cc,
            major,
            minor,
        } => small(line_residual(x, o, d), s) && small(torus_residual(x, cc, *major, *minor), s),
        Data::Circles2 { c1, r1, c2, r2 } => {
            small(sphere_residual(x, c1, *r1), s) && small(sphere_residual(x, c2, *r2), s)
        }
        Data::CircleEllipse2 {
            c: cc,
            rho,
            e,
            a,
            b,
        } => {
            let u = Float::with_val(PREC, &x[0] - e[0]) / *a;
            let v = Float::with_val(PREC, &x[1] - e[1]) / *b;
            small(sphere_residual(x, cc, *rho), s) && small(sq(u) + sq(v) - 1u32, s)
        }
        Data::CircleSphere {
            q,
            n,
            rho,
            c: cc,
            r,
        } => {
            let mut plane = Float::with_val(PREC, 0);
            for i in 0..3 {
                plane += Float::with_val(PREC, &x[i] - q[i]) * n[i];
            }
            small(plane, s)
                && small(sphere_residual(x, q, *rho), s)
                && small(sphere_residual(x, cc, *r), s)
        }
    }
}

#[test]
fn the_generators_build_what_they_say_and_the_truth_is_on_both_shapes() {
    for family in Family::ALL {
        for gap in Gap::all() {
            for seed in 0..40u64 {
                let c = case(family, gap, seed * 7919 + 3);
                let t = truth(&c);
                let what = format!("{family:?} {gap:?} seed {seed}: {c:?} -> {t:?}");
                match c.side {
                    0 => {
                        assert!(t.count() >= 1, "{what}");
                        assert!(t.points.iter().all(|p| p.multiplicity >= 2), "{what}");
                    }
                    1 => {
                        assert!(t.count() >= 2, "{what}");
                        assert!(t.points.iter().all(|p| p.multiplicity == 1), "{what}");
                    }
                    _ => assert_eq!(t.count(), 0, "{what}"),
                }
                for p in &t.points {
                    assert!(on_shapes(&c, p), "{what}: {p:?} is not on both shapes");
                }
            }
        }
    }
}

#[test]
fn tangent_counts_per_family() {
    // Line–sphere, circles, circle–ellipse, circle–sphere touch in one point; the torus
    // in one (outer equator) or two (top or bottom tangent plane across the tube).
    for family in Family::ALL {
        for seed in 0..60u64 {
            let c = case(family, Gap::Tangent, seed);
            let n = truth(&c).count();
            match family {
                Family::LineTorus => assert!(n == 1 || n == 2, "{c:?}: {n}"),
                _ => assert_eq!(n, 1, "{c:?}"),
            }
        }
    }
}

#[test]
fn the_certified_path_is_never_wrong_and_the_table_is_reproducible() {
    let a = curved_table(5, 3, 2);
    assert_eq!(a.rows.len(), Family::ALL.len() * Gap::all().len());
    assert_eq!(a.certified_failures(), 0, "{a}");
    for r in &a.rows {
        assert_eq!(r.cases, 3);
        assert_eq!(r.arithmetic.iter().map(|(_, k)| k).sum::<usize>(), 3);
        // The gap decides whether the shapes meet: never at `−` side, always at `+`/0.
        assert!(r.meeting <= r.cases);
        if r.gap == Gap::Tangent {
            assert_eq!(r.meeting, r.cases, "{r:?}");
        }
    }
    let b = curved_table(5, 3, 1);
    assert_eq!(a, b);
    assert_eq!(a.to_string(), b.to_string());
}

/// Whether the point is on a seam (`y = c_y`, `x ≥ c_x`: the angle-0 half-plane of a
/// circle, sphere or torus about `c` with reference `+x`, its poles included) of one of
/// the case's curved shapes, exactly up to 2⁻²⁰⁰.
fn on_a_seam(c: &CurvedCase, p: &TruePoint) -> bool {
    let centres: Vec<&[f64]> = match &c.data {
        Data::Circles2 { c1, c2, .. } => vec![c1, c2],
        Data::LineSphere { c, .. } | Data::LineTorus { c, .. } => vec![c],
        Data::CircleSphere { c, .. } => vec![c],
        Data::CircleEllipse2 { .. } => vec![],
    };
    let tiny = Float::with_val(PREC, 2f64.powi(-200));
    centres.iter().any(|k| {
        let dy = Float::with_val(PREC, &p.xyz[1] - k[1]);
        let dx = Float::with_val(PREC, &p.xyz[0] - k[0]);
        dy.abs() <= tiny && dx >= -tiny.clone()
    })
}

#[test]
fn the_seam_and_pole_families_put_their_points_on_seams() {
    for family in Family::SEAMS {
        for gap in Gap::all() {
            let mut on = 0;
            for seed in 0..40u64 {
                let c = case(family, gap, seed * 7919 + 5);
                let t = truth(&c);
                let what = format!("{family:?} {gap:?} seed {seed}: {c:?} -> {t:?}");
                for p in &t.points {
                    assert!(on_shapes(&c, p), "{what}: {p:?} is not on both shapes");
                }
                if gap == Gap::Tangent {
                    // Exactly on the seam or pole: some common point is on a seam,
                    // tangencies touch there (one point of multiplicity 2, or the torus's
                    // axis line's four crossings).
                    assert!(t.points.iter().any(|p| on_a_seam(&c, p)), "{what}");
                    on += 1;
                } else if t.points.iter().any(|p| on_a_seam(&c, p)) {
                    on += 1;
                }
            }
            // Off the seam by one ulp or 10⁻ᵏ: the crossings leave it (the tangency
            // halves of the families may keep a point on it when the radius shrinks).
            if gap != Gap::Tangent {
                assert!(on < 40, "{family:?} {gap:?}: every case still on a seam");
            }
        }
    }
}

#[test]
fn the_certified_path_is_never_wrong_at_seams_and_poles() {
    use geocert::robust::curved::paths::run;
    let mut undecided = 0;
    for family in Family::SEAMS {
        for gap in Gap::all() {
            for seed in 0..4u64 {
                let c = case(family, gap, seed * 104_729 + 11);
                let o = run(&c);
                assert!(!o.certified_wrong, "{c:?}: {o:?}");
                undecided += usize::from(o.certified_undecided);
            }
        }
    }
    // All decided when written (the soak's seeds too); a change that leaves one
    // undecided is not wrong, but should be looked at.
    assert_eq!(undecided, 0);
}
