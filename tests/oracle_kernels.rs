//! The oracle's kernels on many inputs: Epeck's answers checked exactly against the
//! defining equations (in rug, from the input doubles), Epick and the rounded Epeck
//! variants against Epeck, and Epick's known failure on exactly dependent planes.
#![cfg(feature = "cgal")]

mod oracle_support;

use geocert::oracle::{
    epeck, epeck_f64, epick, EpeckToDouble, Intersection, Line2Input, LineInput, PlaneInput,
};
use oracle_support::*;
use rug::Rational;

/// Three planes through the common line `origin + t·u`, each spanned by `u` and a
/// random second vector: exactly dependent, meeting in exactly that line.
fn pencil(rng: &mut Rng) -> [PlaneInput; 3] {
    let (origin, u) = (rng.vec3(), rng.vec3());
    [(); 3].map(|_| parametric(origin, u, rng.vec3()))
}

/// Three implicit planes, the third the sum of the first two (exact: the random
/// values are multiples of 2⁻⁵² in [−1, 1)).
fn implicit_sum(rng: &mut Rng) -> [PlaneInput; 3] {
    let (a, b) = ([(); 4].map(|_| rng.unit()), [(); 4].map(|_| rng.unit()));
    let c: [f64; 4] = std::array::from_fn(|i| a[i] + b[i]);
    [a, b, c].map(|p| implicit(p[0], p[1], p[2], p[3]))
}

/// BUILD-NOTES.md: Epick decides `is_zero(determinant)` on rounded plane
/// coefficients, so on exactly dependent triples it answers a point or the empty
/// set instead of the line. Confirmed: with this test's data (g++ 12, -O2, no FMA
/// contraction) Epick said "line" for only 20 of the 300 pencils and 63 of the 300
/// implicit sums, the rest points or empty (about 5:1 in a 1000-case run), while
/// Epeck answered the exact line every time. The robustness table relies on this.
#[test]
fn epick_misses_the_line_of_exactly_dependent_planes_and_epeck_does_not() {
    let mut rng = Rng::new(7);
    for make in [pencil as fn(&mut Rng) -> [PlaneInput; 3], implicit_sum] {
        let mut epick_lines = 0;
        let n = 300;
        for _ in 0..n {
            let planes = make(&mut rng);
            let [a, b, c] = planes;
            let exact = epeck::intersect_three_planes(&a, &b, &c).unwrap();
            let Intersection::Line { point, direction } = &exact else {
                panic!("Epeck: {exact:?} for {planes:?}");
            };
            assert!(!is_zero3(direction));
            for p in &planes {
                assert!(on_plane(point, p));
                assert_eq!(dot(&plane_equation(p).0, direction), 0);
            }
            let fast = epick::intersect_three_planes(&a, &b, &c).unwrap();
            assert!(matches!(
                fast,
                Intersection::Line { .. } | Intersection::Point(_) | Intersection::Empty
            ));
            epick_lines += matches!(fast, Intersection::Line { .. }) as usize;
        }
        // Epick is wrong on most of them (a majority, not a fixed count: it depends
        // on compiler flags).
        assert!(
            epick_lines < n / 2,
            "Epick found {epick_lines} of {n} lines"
        );
    }
}

/// Triple product of the unit normals, in f64: keeps the random tests to
/// well-conditioned triples where Epick's error is near u.
fn well_conditioned(planes: &[PlaneInput; 3]) -> bool {
    let n = planes.map(|p| {
        let (n, _) = plane_equation(&p);
        let v = n.map(|x| x.to_f64());
        let len = v.iter().map(|x| x * x).sum::<f64>().sqrt();
        v.map(|x| x / len)
    });
    let c = [
        n[1][1] * n[2][2] - n[1][2] * n[2][1],
        n[1][2] * n[2][0] - n[1][0] * n[2][2],
        n[1][0] * n[2][1] - n[1][1] * n[2][0],
    ];
    (n[0][0] * c[0] + n[0][1] * c[1] + n[0][2] * c[2]).abs() > 0.1
}

#[test]
fn three_planes_exact_point_and_the_rounded_kernels() {
    let mut rng = Rng::new(11);
    let mut checked = 0;
    while checked < 200 {
        let planes = [(); 3].map(|_| parametric(rng.vec3(), rng.vec3(), rng.vec3()));
        if !well_conditioned(&planes) {
            continue;
        }
        checked += 1;
        let [a, b, c] = planes;
        let Intersection::Point(p) = epeck::intersect_three_planes(&a, &b, &c).unwrap() else {
            panic!("a well-conditioned triple meets in a point")
        };
        for plane in &planes {
            assert!(on_plane(&p, plane));
        }
        let nearest_p = [nearest(&p[0]), nearest(&p[1]), nearest(&p[2])];
        // Forced exact then rounded: the nearest double, bit for bit.
        assert_eq!(
            epeck_f64::intersect_three_planes(EpeckToDouble::Exact, &a, &b, &c).unwrap(),
            Intersection::Point(nearest_p)
        );
        // The lazy approximation: close (observed ≤ 1.5e-12 relative), not nearest.
        match epeck_f64::intersect_three_planes(EpeckToDouble::Approx, &a, &b, &c).unwrap() {
            Intersection::Point(x) => assert!(close(&x, &nearest_p, 1e-9), "{x:?}"),
            other => panic!("{other:?}"),
        }
        match epick::intersect_three_planes(&a, &b, &c).unwrap() {
            Intersection::Point(x) => assert!(close(&x, &nearest_p, 1e-12), "{x:?}"),
            other => panic!("{other:?}"),
        }
    }
}

#[test]
fn line_plane_and_projections_satisfy_their_equations_exactly() {
    let mut rng = Rng::new(13);
    for _ in 0..200 {
        let plane = parametric(rng.vec3(), rng.vec3(), rng.vec3());
        let line = LineInput {
            point: rng.vec3(),
            direction: rng.vec3(),
        };
        let (lp, ld) = (q3(line.point), q3(line.direction));
        let (n, _) = plane_equation(&plane);
        match epeck::intersect_line_plane(&line, &plane).unwrap() {
            Intersection::Point(x) => {
                assert!(on_plane(&x, &plane));
                assert!(is_zero3(&cross(&sub(&x, &lp), &ld)), "on the line");
            }
            other => panic!("a random line crosses a random plane: {other:?}"),
        }
        let p = rng.vec3();
        let foot = epeck::project_point_plane(&p, &plane).unwrap();
        assert!(on_plane(&foot, &plane));
        assert!(is_zero3(&cross(&sub(&q3(p), &foot), &n)), "p − foot ∥ n");
        let foot = epeck::project_point_line(&p, &line).unwrap();
        assert!(is_zero3(&cross(&sub(&foot, &lp), &ld)), "foot on the line");
        assert_eq!(dot(&sub(&q3(p), &foot), &ld), 0, "p − foot ⟂ d");
        let fast = epick::project_point_line(&p, &line).unwrap();
        assert!(close(&fast, &foot.clone().map(|x| nearest(&x)), 1e-10));
    }
}

#[test]
fn two_dimensional_lines_meet_exactly_on_both() {
    let mut rng = Rng::new(17);
    let on = |x: &[Rational; 2], l: &Line2Input| {
        let (dx, dy) = (&x[0] - q(l.point[0]), &x[1] - q(l.point[1]));
        dx * q(l.direction[1]) == dy * q(l.direction[0])
    };
    for _ in 0..200 {
        let [a, b] = [(); 2].map(|_| Line2Input {
            point: [rng.unit(), rng.unit()],
            direction: [rng.unit(), rng.unit()],
        });
        let Intersection::Point(x) = epeck::intersect_line2_line2(&a, &b).unwrap() else {
            panic!("random lines meet in a point")
        };
        assert!(on(&x, &a) && on(&x, &b));
    }
}

/// Each call builds its own Epeck objects, so calls may run on several threads.
#[test]
fn epeck_calls_run_in_parallel() {
    let handles: Vec<_> = (0..4)
        .map(|t| {
            std::thread::spawn(move || {
                let mut rng = Rng::new(100 + t);
                for _ in 0..100 {
                    let planes = pencil(&mut rng);
                    let [a, b, c] = planes;
                    match epeck::intersect_three_planes(&a, &b, &c).unwrap() {
                        Intersection::Line { point, .. } => {
                            assert!(planes.iter().all(|p| on_plane(&point, p)))
                        }
                        other => panic!("{other:?}"),
                    }
                }
            })
        })
        .collect();
    for h in handles {
        h.join().expect("a thread panicked");
    }
}
