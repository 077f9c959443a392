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
        Data::NurbsCircleSphere {
            q, rho, c: cc, r, ..
        } => {
            small(Float::with_val(PREC, &x[1] - q[1]), s)
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
        Data::CircleSphere { c, .. } | Data::NurbsCircleSphere { c, .. } => vec![c],
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
    let (mut undecided, mut nurbs_undecided) = (0, 0);
    for family in Family::SEAMS {
        for gap in Gap::all() {
            for seed in 0..4u64 {
                let c = case(family, gap, seed * 104_729 + 11);
                let o = run(&c);
                assert!(!o.certified_wrong, "{c:?}: {o:?}");
                if family == Family::PoleNurbsCircleSphere {
                    nurbs_undecided += usize::from(o.certified_undecided);
                } else {
                    undecided += usize::from(o.certified_undecided);
                }
            }
        }
    }
    // All decided when written (the soak's seeds too); a change that leaves one
    // undecided is not wrong, but should be looked at. The NURBS circle against the
    // sphere is decided exactly (`ops::algebraic::spline_quadric`): a tangency at a pole
    // too (through the numeric certifier 7 % were undecided after its box budget).
    assert_eq!(undecided, 0);
    assert_eq!(nurbs_undecided, 0, "{nurbs_undecided} of 60");
}

/// The NURBS circle of the pole family is exactly its circle: each of its four
/// rational quadratic arcs, evaluated in exact rationals at five parameters (so its
/// conic is the circle's: five common points), lies in the plane `y = q_y` at distance
/// `rho` from `q`; the arcs join end to end and the last ends where the first begins.
#[test]
fn the_nurbs_circles_are_exactly_their_circles() {
    use geocert::robust::case::q as rat;
    use geocert::robust::curved::seams::{nurbs_circle, NURBS_CIRCLE_KNOTS};
    use rug::Rational;
    assert_eq!(NURBS_CIRCLE_KNOTS.len(), 9 + 3);
    let mut cases = 0;
    for gap in Gap::all() {
        for seed in 0..40u64 {
            let c = case(Family::PoleNurbsCircleSphere, gap, seed * 31 + 1);
            let Data::NurbsCircleSphere { q, start, rho, .. } = c.data else {
                panic!("{c:?}")
            };
            let (points, weights) = nurbs_circle(&q, rho, start);
            assert_eq!(points.len(), 9);
            assert_eq!(points[0], points[8], "{c:?}");
            let rho2 = rat(rho) * rat(rho);
            for arc in 0..4 {
                for k in 0..=4 {
                    let t = Rational::from((k, 4));
                    let s = Rational::from(1 - &t);
                    let b = [
                        Rational::from(&s * &s),
                        2 * Rational::from(&s * &t),
                        Rational::from(&t * &t),
                    ];
                    let mut num = [Rational::new(), Rational::new(), Rational::new()];
                    let mut den = Rational::new();
                    for i in 0..3 {
                        let bw = &b[i] * rat(weights[2 * arc + i]);
                        for (n, x) in num.iter_mut().zip(points[2 * arc + i]) {
                            *n += &bw * rat(x);
                        }
                        den += bw;
                    }
                    let x: Vec<Rational> = num.iter().map(|n| Rational::from(n / &den)).collect();
                    assert_eq!(x[1], rat(q[1]), "{c:?} arc {arc} t {t}");
                    let d2: Rational = (0..3)
                        .map(|i| {
                            let d = &x[i] - rat(q[i]);
                            Rational::from(&d * &d)
                        })
                        .sum();
                    assert_eq!(d2, rho2, "{c:?} arc {arc} t {t}");
                }
            }
            cases += 1;
        }
    }
    assert_eq!(cases, 40 * Gap::all().len());
}

/// No case of `family` at these (gap, seed) pairs gets a wrong certificate.
fn never_wrong(family: Family, cases: &[(Gap, u64)]) {
    for &(gap, seed) in cases {
        let c = case(family, gap, seed);
        let o = geocert::robust::curved::paths::run(&c);
        assert!(!o.certified_wrong, "{c:?}: {o:?}");
    }
}

/// The soak's first runs of the NURBS pole family: 19 of 200 cases reported a root on
/// the sphere's seam twice, at `u = 0` and at `u = 2π`, under `complete` (the f64
/// Krawczyk step that proves two boxes one root could not absorb the rounding of
/// coordinates ~12 around a circle of radius 0.01: now retried in MPFR,
/// `ops::certified::seam`); 5 of 2000 (gap 1e-13, near a pole, on the re-poled chart)
/// reported one root twice in two overlapping boxes, neither inside the other (now
/// proven one root by the same step with no shift). Each is now graded right: one box
/// per root.
#[test]
fn seam_copies_of_nurbs_roots_are_merged() {
    let cases: [(Gap, u64); 24] = [
        (Gap::Pow(13), 17989168351094150835),
        (Gap::Pow(13), 321638165372927327),
        (Gap::Pow(13), 2675845178122629730),
        (Gap::Pow(13), 3454362131990628106),
        (Gap::Pow(13), 18025339290331058772),
        (Gap::Pow(6), 1563716787258903655),
        (Gap::Pow(9), 17872784330540610676),
        (Gap::Pow(15), 727625115803955241),
        (Gap::Pow(8), 9187031078814708782),
        (Gap::Pow(13), 1729849171728707488),
        (Gap::Ulp, 18267763662831674501),
        (Gap::Pow(14), 878338855627686265),
        (Gap::Pow(6), 1060430943369537460),
        (Gap::Pow(3), 15296310815876367826),
        (Gap::Ulp, 6340329515716401675),
        (Gap::Pow(9), 15204328210275600662),
        (Gap::Pow(11), 2975613731386703320),
        (Gap::Pow(7), 15928165615112736395),
        (Gap::Pow(9), 5948620557442944583),
        (Gap::Pow(10), 12365892806858287200),
        (Gap::Pow(13), 4372761561409714858),
        (Gap::Pow(12), 12557064836077103221),
        (Gap::Pow(13), 3329527391710511594),
        (Gap::Pow(12), 1448512625304892860),
    ];
    never_wrong(Family::PoleNurbsCircleSphere, &cases);
}

/// The soak of seed 25 (2000 NURBS pole cases): 1 wrong at gap 1e-12 — two roots
/// 6·10⁻⁷ apart on either side of a pole, the circle at x ≈ −12, and the first root's
/// point box 2·10⁻⁶ wide held both (the NURBS evaluated in intervals over a parameter
/// box 2·10⁻⁸ wide: the box grows with the coordinates, not with the circle). A point
/// box is now the intersection of the curve's and the surface's enclosures
/// (`ops::certified::meet`). That seed, and more cases of the same gaps. (Both NURBS
/// seed lists now go through the exact path, `ops::algebraic::spline_quadric`: they
/// guard the answers, no longer the numeric certifier's seam and box fixes.)
#[test]
fn nurbs_point_boxes_near_a_pole_hold_one_root_each() {
    let mut cases = vec![(Gap::Pow(12), 18384491836664908020u64)];
    let mut rng = geocert::num::rng::Rng::new(0x6001e);
    for k in 0..12 {
        cases.push((Gap::Pow(11 + k % 3), rng.next_u64()));
    }
    never_wrong(Family::PoleNurbsCircleSphere, &cases);
}

/// Two spheres meeting across the first one's seam and pole (`robust::curved::ssi`):
/// never a wrong certificate at any gap, all three topologies met, nearly all decided.
#[test]
fn sphere_pairs_across_seams_and_poles_are_never_wrong() {
    use geocert::robust::curved::ssi;
    use std::cmp::Ordering;
    let (mut kinds, mut undecided, mut n) = ([0usize; 3], 0, 0);
    for gap in Gap::all() {
        // More seeds at gap 0: a third of them touch.
        let seeds = if gap == Gap::Tangent { 30 } else { 8 };
        for seed in 0..seeds {
            let c = ssi::case(gap, seed * 7_919 + 13);
            let t = ssi::truth(&c);
            kinds[match t.kind() {
                Ordering::Less => 0,
                Ordering::Equal => 1,
                Ordering::Greater => 2,
            }] += 1;
            let o = ssi::run(&c);
            assert!(!o.certified_wrong, "{c:?}: {o:?}");
            undecided += usize::from(o.certified_undecided);
            n += 1;
        }
    }
    assert!(kinds.iter().all(|&k| k >= 5), "{kinds:?}");
    assert!(undecided * 20 <= n, "{undecided} of {n} undecided");
}
