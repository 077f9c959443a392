//! The robustness table (`geocert bench robustness`): reproducible from its seed,
//! geocert certified never wrong, and the known failures of plain f64 visible — on the
//! near-collinear grid of Kettner et al. and on exactly degenerate planes.

use geocert::robust::gen::{Construction, Generator};
use geocert::robust::kettner::{self, Q, R, SIDE};
use geocert::robust::robustness_table;
use std::cmp::Ordering;

#[test]
fn same_seed_same_table_whatever_the_threads() {
    let a = robustness_table(7, 200, 2);
    let b = robustness_table(7, 200, 1);
    assert_eq!(a, b);
    assert_eq!(a.to_string(), b.to_string());
    let c = robustness_table(8, 200, 2);
    assert_ne!(a.rows, c.rows, "a different seed draws different cases");
}

#[test]
fn certified_is_never_wrong_and_plain_f64_is() {
    let t = robustness_table(1, 400, 2);
    assert_eq!(t.rows.len(), Construction::ALL.len() * Generator::ALL.len());
    assert!(t.rows.iter().all(|r| r.cases == 400));
    assert_eq!(t.certified_failures(), 0, "{t}");
    // Plain f64 decides exact degeneracy with `== 0.0` on rounded values: on one-ulp
    // perturbations of dependent planes it gets verdicts wrong.
    let row = |c, g| {
        t.rows
            .iter()
            .find(|r| r.construction == c && r.generator == g)
            .expect("row")
    };
    assert!(
        row(Construction::ThreePlanes, Generator::Perturbed)
            .plain
            .verdict
            > 0,
        "{t}"
    );
    assert!(
        row(Construction::ThreePlanes, Generator::Generic).plain.off > 0,
        "{t}"
    );
    // ...and on exactly degenerate inputs geocert's filter abstains rather than errs.
    let d = row(Construction::ThreePlanes, Generator::Degenerate);
    assert_eq!((d.filter_undecided, d.filter_wrong), (d.cases, 0));
    let text = t.to_string();
    assert!(
        text.contains("geocert certified: 0 wrong answers"),
        "{text}"
    );
    if cfg!(feature = "cgal") {
        assert!(t.rows.iter().all(|r| r.epick.is_some()));
    } else {
        assert!(text.contains("CGAL is not built in"), "{text}");
    }
}

#[test]
fn kettner_grid_plain_f64_fails_certified_does_not() {
    let k = kettner::grid();
    assert_eq!(k.points, SIDE * SIDE);
    // p lies on the line y = x through q and r exactly when its coordinates are equal,
    // i.e. on the grid's diagonal i = j.
    assert_eq!(k.collinear, SIDE);
    assert_eq!(k.certified_wrong, 0);
    // The classroom result: the float determinant gets many signs wrong.
    assert!(k.plain_wrong > 0);
    // The exact signs on either side of the diagonal: at (1, 0), p = (0.5 + h, 0.5)
    // and (q − p) × (r − p) = −12h < 0 (h = 2⁻⁵³); at (0, 1) it is +12h.
    assert_eq!(kettner::exact(kettner::point(1, 0), Q, R), Ordering::Less);
    assert_eq!(
        kettner::exact(kettner::point(0, 1), Q, R),
        Ordering::Greater
    );
    let wrong: Vec<(usize, usize)> = (0..SIDE)
        .flat_map(|i| (0..SIDE).map(move |j| (i, j)))
        .filter(|&(i, j)| {
            let p = kettner::point(i, j);
            kettner::plain(p, Q, R) != kettner::exact(p, Q, R)
        })
        .collect();
    assert_eq!(wrong.len(), k.plain_wrong);
    for &(i, j) in wrong.iter().take(50) {
        let p = kettner::point(i, j);
        assert_eq!(
            kettner::certified(p, Q, R).map(|c| c.0),
            Some(kettner::exact(p, Q, R))
        );
    }
}
