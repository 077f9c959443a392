//! Properties of the exact linear kernel on generic, exactly degenerate, one-ulp
//! perturbed and mixed-magnitude (1e-150..1e150) input:
//! * the exact result satisfies every input equation exactly, in rationals computed here;
//! * the verdict matches an independent rank computation (Gaussian elimination below);
//! * rounded values are the correctly rounded exact values (checked by comparing with
//!   the neighbouring doubles in rationals);
//! * the certified f64 path agrees with the `_exact` path on the same inputs.

use geocert::geom::line_plane::{intersect_line_plane, intersect_line_plane_exact, LinePlane};
use geocert::geom::plane_plane::{intersect_plane_plane, intersect_plane_plane_exact, PlanePlane};
use geocert::geom::three_planes::{
    intersect_three_planes, intersect_three_planes_exact, ThreePlanes,
};
use geocert::geom::{Line, Linear, Plane, Segment};
use geocert::num::round::next_up;
use geocert::num::Rounded;
use nalgebra::{Vector2, Vector3};
use proptest::prelude::*;
use rug::Rational;

type Q = Rational;
type V = [f64; 3];

fn q(x: f64) -> Q {
    Q::from_f64(x).unwrap()
}
fn qv(v: &V) -> [Q; 3] {
    [q(v[0]), q(v[1]), q(v[2])]
}
fn vec3(v: &V) -> Vector3<f64> {
    Vector3::new(v[0], v[1], v[2])
}
fn qvec(v: &V) -> Vector3<Q> {
    Vector3::new(q(v[0]), q(v[1]), q(v[2]))
}
fn dot(a: &[Q; 3], b: &[Q; 3]) -> Q {
    Q::from(&a[0] * &b[0]) + Q::from(&a[1] * &b[1]) + Q::from(&a[2] * &b[2])
}
fn cross(a: &[Q; 3], b: &[Q; 3]) -> [Q; 3] {
    let c = |i: usize, j: usize| Q::from(&a[i] * &b[j]) - Q::from(&a[j] * &b[i]);
    [c(1, 2), c(2, 0), c(0, 1)]
}
fn arr(v: &Vector3<Q>) -> [Q; 3] {
    [v[0].clone(), v[1].clone(), v[2].clone()]
}

/// A plane given by generated doubles: parametric (origin, u, v) or implicit.
#[derive(Debug, Clone)]
enum P {
    Param(V, V, V),
    Implicit(V, f64),
}

impl P {
    fn f64(&self) -> Option<Plane<f64>> {
        match self {
            P::Param(o, u, v) => Plane::parametric(vec3(o), vec3(u), vec3(v)).ok(),
            P::Implicit(n, d) => Plane::implicit(vec3(n), *d).ok(),
        }
    }
    fn exact(&self) -> Plane<Q> {
        match self {
            P::Param(o, u, v) => Plane::parametric(qvec(o), qvec(u), qvec(v)).unwrap(),
            P::Implicit(n, d) => Plane::implicit(qvec(n), q(*d)).unwrap(),
        }
    }
    /// `(N, h)` with the plane `N·x = h`, computed here independently.
    fn eq(&self) -> ([Q; 3], Q) {
        match self {
            P::Param(o, u, v) => {
                let n = cross(&qv(u), &qv(v));
                let h = dot(&n, &qv(o));
                (n, h)
            }
            P::Implicit(n, d) => (qv(n), -q(*d)),
        }
    }
    fn contains(&self, x: &[Q; 3]) -> bool {
        let (n, h) = self.eq();
        dot(&n, x) == h
    }
    /// `o + a u + b v` for a parametric plane.
    fn at(&self, a: &Q, b: &Q) -> Option<[Q; 3]> {
        let P::Param(o, u, v) = self else { return None };
        let (o, u, v) = (qv(o), qv(u), qv(v));
        Some([0, 1, 2].map(|i| o[i].clone() + Q::from(a * &u[i]) + Q::from(b * &v[i])))
    }
}

/// Rank of a matrix of rationals (rows), by Gaussian elimination.
fn rank(mut m: Vec<Vec<Q>>) -> usize {
    let cols = m.first().map_or(0, |r| r.len());
    let mut r = 0;
    for c in 0..cols {
        let Some(p) = (r..m.len()).find(|&i| m[i][c] != 0) else {
            continue;
        };
        m.swap(r, p);
        for i in 0..m.len() {
            if i != r && m[i][c] != 0 {
                let f = Q::from(&m[i][c] / &m[r][c]);
                let pivot = m[r].clone();
                for (x, y) in m[i][c..].iter_mut().zip(&pivot[c..]) {
                    *x -= Q::from(&f * y);
                }
            }
        }
        r += 1;
    }
    r
}

/// `r` is the correctly rounded value of `x` with a valid tight enclosure.
fn rounds(x: &Q, r: &Rounded) -> bool {
    if r.overflowed() {
        // Beyond MAX + ulp(MAX)/2 = 2^1024 − 2^970, on the side of the sign.
        let limit = q(f64::MAX) + q(2f64.powi(970));
        return Q::from(x.abs_ref()) >= limit && (x.cmp0() == r.nearest.partial_cmp(&0.0).unwrap());
    }
    if r.is_exact() {
        return *x == q(r.nearest);
    }
    if !(q(r.lo) < *x && *x < q(r.hi)) || next_up(r.lo) != r.hi {
        return false;
    }
    let c = q(r.nearest);
    let d = Q::from(x - &c).abs();
    d <= Q::from(x - q(r.lo)).abs() && d <= Q::from(x - q(r.hi)).abs()
}

fn rounds3(x: &Vector3<Q>, r: &Vector3<Rounded>) -> bool {
    (0..3).all(|i| rounds(&x[i], &r[i]))
}
fn rounds2(x: &Vector2<Q>, r: &Vector2<Rounded>) -> bool {
    (0..2).all(|i| rounds(&x[i], &r[i]))
}
fn scaled(x: &Q, k: i32) -> Q {
    let mut y = x.clone();
    if k >= 0 {
        y <<= k as u32;
    } else {
        y >>= k.unsigned_abs();
    }
    y
}

// ---- generators -------------------------------------------------------------

/// Small dyadic numbers k/4, k ∈ [-12, 12]: exact degeneracies stay exact in doubles.
fn dyadic() -> impl Strategy<Value = f64> + Clone {
    (-12i32..=12).prop_map(|k| k as f64 / 4.0)
}
fn generic() -> impl Strategy<Value = f64> + Clone {
    -10.0f64..10.0
}
/// Mixed magnitudes m·2^e, |m| ∈ [0.5, 1), e ∈ [-498, 498] (≈ 1e-150..1e150).
fn mixed() -> impl Strategy<Value = f64> + Clone {
    (0.5f64..1.0, -498i32..=498, any::<bool>()).prop_map(|(m, e, s)| {
        let x = m * 2f64.powi(e / 2) * 2f64.powi(e - e / 2);
        if s {
            -x
        } else {
            x
        }
    })
}
fn v3(s: impl Strategy<Value = f64> + Clone) -> impl Strategy<Value = V> {
    [s.clone(), s.clone(), s]
}
fn plane(s: impl Strategy<Value = f64> + Clone + 'static) -> BoxedStrategy<P> {
    prop_oneof![
        3 => (v3(s.clone()), v3(s.clone()), v3(s.clone())).prop_map(|(o, u, v)| P::Param(o, u, v)),
        1 => (v3(s.clone()), s).prop_map(|(n, d)| P::Implicit(n, d)),
    ]
    .boxed()
}
/// `v` with component `i mod 3` moved up by one ulp.
fn bump(v: &V, i: usize) -> V {
    let mut v = *v;
    v[i % 3] = next_up(v[i % 3]);
    v
}

/// Perturb one coordinate of a plane by one ulp.
fn perturb(p: &P, which: usize) -> P {
    let bump = |v: &V| bump(v, which);
    match p {
        P::Param(o, u, v) => match which / 3 % 3 {
            0 => P::Param(bump(o), *u, *v),
            1 => P::Param(*o, bump(u), *v),
            _ => P::Param(*o, *u, bump(v)),
        },
        P::Implicit(n, d) => {
            if which.is_multiple_of(2) {
                P::Implicit(bump(n), *d)
            } else {
                P::Implicit(*n, next_up(*d))
            }
        }
    }
}
/// A third plane that is an exact combination of the first two (dyadic data), or a
/// copy of one of them through a different origin, or a parallel shift.
fn degenerate_triple() -> impl Strategy<Value = [P; 3]> {
    (
        plane(dyadic()),
        plane(dyadic()),
        0usize..4,
        v3(dyadic()),
        -2i32..=2,
    )
        .prop_map(|(a, b, kind, off, k)| {
            let c = match (kind, &a, &b) {
                // the normal of a third plane through the common line: implicit N_a + k N_b
                (0, _, _) => {
                    let ((na, ha), (nb, hb)) = (a.eq(), b.eq());
                    let kk = Q::from(k);
                    let n: [Q; 3] = [0, 1, 2].map(|i| na[i].clone() + Q::from(&kk * &nb[i]));
                    let h = ha + Q::from(&kk * &hb);
                    let f = |x: &Q| x.to_f64();
                    P::Implicit([f(&n[0]), f(&n[1]), f(&n[2])], f(&-h))
                }
                // the first plane again, through a different origin on it
                (1, P::Param(o, u, v), _) => P::Param(
                    [o[0] + u[0] + v[0], o[1] + u[1] + v[1], o[2] + u[2] + v[2]],
                    *v,
                    *u,
                ),
                // a parallel shift of the first plane
                (2, P::Param(o, u, v), _) => {
                    P::Param([o[0] + off[0], o[1] + off[1], o[2] + off[2]], *u, *v)
                }
                _ => b.clone(),
            };
            [a, b, c]
        })
}

// ---- three planes -------------------------------------------------------------

fn check_three(ps: &[P; 3]) -> Result<(), TestCaseError> {
    let (Some(a), Some(b), Some(c)) = (ps[0].f64(), ps[1].f64(), ps[2].f64()) else {
        return Ok(());
    };
    // A degenerate generator may produce an exact value that is not a double: skip it.
    let exact = intersect_three_planes_exact(&[ps[0].exact(), ps[1].exact(), ps[2].exact()]);
    let eqs: Vec<([Q; 3], Q)> = ps.iter().map(P::eq).collect();
    let ra = rank(eqs.iter().map(|(n, _)| n.to_vec()).collect());
    let rb = rank(
        eqs.iter()
            .map(|(n, h)| [n.to_vec(), vec![h.clone()]].concat())
            .collect(),
    );
    match &exact {
        ThreePlanes::Point { point, params } => {
            prop_assert!(ra == 3);
            let p = arr(point);
            for (k, pl) in ps.iter().enumerate() {
                prop_assert!(pl.contains(&p));
                if let Some(uv) = &params[k] {
                    prop_assert_eq!(pl.at(&uv[0], &uv[1]).unwrap(), p.clone());
                }
            }
        }
        ThreePlanes::Line { line, .. } => {
            prop_assert!(ra == 2 && rb == 2);
            let (p, d) = (arr(&line.point), arr(&line.dir));
            prop_assert!(d.iter().any(|x| *x != 0));
            for (n, h) in &eqs {
                prop_assert!(dot(n, &p) == *h && dot(n, &d) == 0);
            }
        }
        ThreePlanes::Plane => prop_assert!(ra == 1 && rb == 1),
        ThreePlanes::Empty => prop_assert!(rb > ra),
    }
    let cert = intersect_three_planes(&[a, b, c]);
    match (&cert.value, &exact) {
        (
            ThreePlanes::Point {
                point: rp,
                params: rpar,
            },
            ThreePlanes::Point { point, params },
        ) => {
            prop_assert!(rounds3(point, rp));
            for k in 0..3 {
                match (&rpar[k], &params[k]) {
                    (Some(r), Some(x)) => prop_assert!(rounds2(x, r)),
                    (None, None) => {}
                    _ => prop_assert!(false, "parameters of plane {k} differ"),
                }
            }
        }
        (ThreePlanes::Line { line: r, pair: pr }, ThreePlanes::Line { line, pair }) => {
            prop_assert_eq!(pr, pair);
            prop_assert!(rounds3(&line.point, &r.point));
            let k = r.dir_exponent;
            prop_assert!(rounds3(&line.dir.map(|x| scaled(&x, k)), &r.dir));
        }
        (ThreePlanes::Plane, ThreePlanes::Plane) | (ThreePlanes::Empty, ThreePlanes::Empty) => {}
        (x, y) => prop_assert!(false, "certified {x:?} but exact {y:?}"),
    }
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]

    #[test]
    fn three_planes_generic(a in plane(generic()), b in plane(generic()), c in plane(generic())) {
        check_three(&[a, b, c])?;
    }

    #[test]
    fn three_planes_mixed_magnitudes(a in plane(mixed()), b in plane(mixed()), c in plane(mixed())) {
        check_three(&[a, b, c])?;
    }

    #[test]
    fn three_planes_degenerate(t in degenerate_triple(), which in 0usize..27, who in 0usize..3) {
        check_three(&t)?;
        let mut p = t.clone();
        p[who] = perturb(&t[who], which);
        check_three(&p)?;
    }

    #[test]
    fn plane_pairs(a in plane(generic()), b in plane(dyadic()), t in degenerate_triple()) {
        check_pair(&a, &b)?;
        check_pair(&t[0], &t[2])?;
        check_pair(&t[0], &perturb(&t[2], 4))?;
    }

    #[test]
    fn plane_pairs_mixed(a in plane(mixed()), b in plane(mixed())) {
        check_pair(&a, &b)?;
    }

    #[test]
    fn line_plane_all(o in v3(generic()), d in v3(dyadic()), pl in plane(dyadic()), m in (plane(mixed()), v3(mixed()), v3(mixed())), lo in -2.0f64..0.5, which in 0usize..9) {
        check_line_plane(&o, &d, Some([lo, lo + 1.0]), &pl)?;
        check_line_plane(&o, &d, None, &pl)?;
        // a direction exactly orthogonal to the normal: along u of a parametric plane
        if let P::Param(po, u, _) = &pl {
            check_line_plane(&o, u, None, &pl)?;
            check_line_plane(po, u, None, &pl)?;
            check_line_plane(po, &bump(u, which), None, &pl)?;
        }
        check_line_plane(&m.1, &m.2, None, &m.0)?;
        check_segment_plane(&o, &d, &pl)?;
    }
}

// ---- plane–plane ------------------------------------------------------------

fn check_pair(a: &P, b: &P) -> Result<(), TestCaseError> {
    let (Some(fa), Some(fb)) = (a.f64(), b.f64()) else {
        return Ok(());
    };
    let exact = intersect_plane_plane_exact(&a.exact(), &b.exact());
    let (ea, eb) = (a.eq(), b.eq());
    let ra = rank(vec![ea.0.to_vec(), eb.0.to_vec()]);
    let rb = rank(vec![
        [ea.0.to_vec(), vec![ea.1.clone()]].concat(),
        [eb.0.to_vec(), vec![eb.1.clone()]].concat(),
    ]);
    match &exact {
        PlanePlane::Line(l) => {
            prop_assert!(ra == 2);
            let (p, d) = (arr(&l.point), arr(&l.dir));
            prop_assert!(a.contains(&p) && b.contains(&p));
            prop_assert!(dot(&ea.0, &d) == 0 && dot(&eb.0, &d) == 0);
            for (pl, on) in [(a, &l.on_a), (b, &l.on_b)] {
                if let Some(on) = on {
                    prop_assert_eq!(pl.at(&on.origin[0], &on.origin[1]).unwrap(), p.clone());
                    let q1 = pl
                        .at(
                            &(on.origin[0].clone() + &on.dir[0]),
                            &(on.origin[1].clone() + &on.dir[1]),
                        )
                        .unwrap();
                    let p1: [Q; 3] = [0, 1, 2].map(|i| p[i].clone() + &d[i]);
                    prop_assert_eq!(q1, p1);
                }
            }
        }
        PlanePlane::Coincident => prop_assert!(ra == 1 && rb == 1),
        PlanePlane::Parallel => prop_assert!(ra == 1 && rb == 2),
    }
    let cert = intersect_plane_plane(&fa, &fb);
    match (&cert.value, &exact) {
        (PlanePlane::Line(r), PlanePlane::Line(l)) => {
            let k = r.dir_exponent;
            prop_assert!(rounds3(&l.point, &r.point));
            prop_assert!(rounds3(&l.dir.map(|x| scaled(&x, k)), &r.dir));
            for (ro, lo) in [(&r.on_a, &l.on_a), (&r.on_b, &l.on_b)] {
                match (ro, lo) {
                    (Some(ro), Some(lo)) => {
                        prop_assert!(rounds2(&lo.origin, &ro.origin));
                        prop_assert!(rounds2(&lo.dir.map(|x| scaled(&x, k)), &ro.dir));
                    }
                    (None, None) => {}
                    _ => prop_assert!(false),
                }
            }
        }
        (PlanePlane::Coincident, PlanePlane::Coincident)
        | (PlanePlane::Parallel, PlanePlane::Parallel) => {}
        (x, y) => prop_assert!(false, "certified {x:?} but exact {y:?}"),
    }
    Ok(())
}

// ---- line–plane -------------------------------------------------------------

fn check_line_plane(o: &V, d: &V, range: Option<[f64; 2]>, pl: &P) -> Result<(), TestCaseError> {
    let (Ok(line), Some(fp)) = (Line::with_range(vec3(o), vec3(d), range), pl.f64()) else {
        return Ok(());
    };
    let ql = Line::with_range(qvec(o), qvec(d), range.map(|[a, b]| [q(a), q(b)])).unwrap();
    let exact = intersect_line_plane_exact(Linear::Line(&ql), &pl.exact());
    let (n, h) = pl.eq();
    let (qo, qd) = (qv(o), qv(d));
    let nd = dot(&n, &qd);
    match &exact {
        LinePlane::Point(x) | LinePlane::OutsideDomain(x) => {
            prop_assert!(nd != 0);
            let p = arr(&x.point);
            prop_assert!(pl.contains(&p));
            let on_line: [Q; 3] = [0, 1, 2].map(|i| qo[i].clone() + Q::from(&x.t * &qd[i]));
            prop_assert_eq!(&on_line, &p);
            if let Some(uv) = &x.uv {
                prop_assert_eq!(pl.at(&uv[0], &uv[1]).unwrap(), p);
            }
            let inside = range.is_none_or(|[a, b]| q(a) <= x.t && x.t <= q(b));
            prop_assert_eq!(inside, matches!(exact, LinePlane::Point(_)));
        }
        LinePlane::Contained => prop_assert!(nd == 0 && dot(&n, &qo) == h),
        LinePlane::Parallel => prop_assert!(nd == 0 && dot(&n, &qo) != h),
    }
    let cert = intersect_line_plane(Linear::Line(&line), &fp);
    compare_line_plane(&cert.value, &exact)
}

fn compare_line_plane(
    cert: &LinePlane<Rounded>,
    exact: &LinePlane<Q>,
) -> Result<(), TestCaseError> {
    match (cert, exact) {
        (LinePlane::Point(r), LinePlane::Point(x))
        | (LinePlane::OutsideDomain(r), LinePlane::OutsideDomain(x)) => {
            prop_assert!(rounds3(&x.point, &r.point) && rounds(&x.t, &r.t));
            match (&r.uv, &x.uv) {
                (Some(a), Some(b)) => prop_assert!(rounds2(b, a)),
                (None, None) => {}
                _ => prop_assert!(false),
            }
        }
        (LinePlane::Parallel, LinePlane::Parallel)
        | (LinePlane::Contained, LinePlane::Contained) => {}
        (x, y) => prop_assert!(false, "certified {x:?} but exact {y:?}"),
    }
    Ok(())
}

fn check_segment_plane(a: &V, b: &V, pl: &P) -> Result<(), TestCaseError> {
    let (Ok(s), Some(fp)) = (Segment::new(vec3(a), vec3(b)), pl.f64()) else {
        return Ok(());
    };
    let qs = Segment::new(qvec(a), qvec(b)).unwrap();
    let exact = intersect_line_plane_exact(Linear::Segment(&qs), &pl.exact());
    if let LinePlane::Point(x) = &exact {
        prop_assert!(x.t >= 0 && x.t <= 1 && pl.contains(&arr(&x.point)));
    }
    compare_line_plane(
        &intersect_line_plane(Linear::Segment(&s), &fp).value,
        &exact,
    )
}

// ---- 2D lines and segments -----------------------------------------------------

mod two_d {
    use super::*;
    use geocert::geom::lines2::{
        intersect_line2_line2, intersect_line2_line2_exact, Empty2, Intersection2,
    };
    use geocert::geom::{Line2, Linear2, Segment2};

    type W = [f64; 2];
    #[derive(Debug, Clone)]
    pub enum L2 {
        Line(W, W),
        Ranged(W, W, [f64; 2]),
        Seg(W, W),
    }
    fn q2(v: &W) -> Vector2<Q> {
        Vector2::new(q(v[0]), q(v[1]))
    }
    fn cross2(a: &[Q; 2], b: &[Q; 2]) -> Q {
        Q::from(&a[0] * &b[1]) - Q::from(&a[1] * &b[0])
    }
    impl L2 {
        /// Origin, direction and domain, in rationals, computed here.
        fn carrier(&self) -> ([Q; 2], [Q; 2], Option<[Q; 2]>) {
            match self {
                L2::Line(o, d) => ([q(o[0]), q(o[1])], [q(d[0]), q(d[1])], None),
                L2::Ranged(o, d, r) => (
                    [q(o[0]), q(o[1])],
                    [q(d[0]), q(d[1])],
                    Some([q(r[0]), q(r[1])]),
                ),
                L2::Seg(a, b) => (
                    [q(a[0]), q(a[1])],
                    [q(b[0]) - q(a[0]), q(b[1]) - q(a[1])],
                    Some([Q::new(), Q::from(1)]),
                ),
            }
        }
        fn at(&self, t: &Q) -> [Q; 2] {
            let (o, d, _) = self.carrier();
            [
                o[0].clone() + Q::from(t * &d[0]),
                o[1].clone() + Q::from(t * &d[1]),
            ]
        }
        fn inside(&self, t: &Q) -> bool {
            self.carrier().2.is_none_or(|[a, b]| a <= *t && *t <= b)
        }
    }

    fn with<R>(l: &L2, f: &mut dyn FnMut(Linear2<f64>, Linear2<Q>) -> R) -> Option<R> {
        Some(match l {
            L2::Line(o, d) => f(
                Linear2::Line(&Line2::new((*o).into(), (*d).into()).ok()?),
                Linear2::Line(&Line2::new(q2(o), q2(d)).ok()?),
            ),
            L2::Ranged(o, d, r) => f(
                Linear2::Line(&Line2::with_range((*o).into(), (*d).into(), Some(*r)).ok()?),
                Linear2::Line(&Line2::with_range(q2(o), q2(d), Some([q(r[0]), q(r[1])])).ok()?),
            ),
            L2::Seg(a, b) => f(
                Linear2::Segment(&Segment2::new((*a).into(), (*b).into()).ok()?),
                Linear2::Segment(&Segment2::new(q2(a), q2(b)).ok()?),
            ),
        })
    }

    pub fn check(a: &L2, b: &L2) -> Result<(), TestCaseError> {
        let run = with(a, &mut |fa, qa| {
            with(b, &mut |fb, qb| {
                (
                    intersect_line2_line2(fa, fb),
                    intersect_line2_line2_exact(qa, qb),
                )
            })
        });
        let Some(Some((cert, exact))) = run else {
            return Ok(());
        };
        let ((_, da, _), (_, db, _)) = (a.carrier(), b.carrier());
        let parallel = cross2(&da, &db) == 0;
        match &exact {
            Intersection2::Point { point, t1, t2 } => {
                let p = [point[0].clone(), point[1].clone()];
                prop_assert!(a.at(t1) == p && b.at(t2) == p && a.inside(t1) && b.inside(t2));
            }
            Intersection2::Segment {
                a: pa,
                b: pb,
                a_params,
                b_params,
            } => {
                prop_assert!(parallel);
                for (p, t) in [(pa, a_params), (pb, b_params)] {
                    let p = [p[0].clone(), p[1].clone()];
                    prop_assert!(
                        a.at(&t[0]) == p && b.at(&t[1]) == p && a.inside(&t[0]) && b.inside(&t[1])
                    );
                }
                prop_assert!(a_params[0] < b_params[0]);
            }
            Intersection2::Line => {
                prop_assert!(parallel && a.carrier().2.is_none() && b.carrier().2.is_none())
            }
            Intersection2::Empty(Empty2::OutsideDomain { point, t1, t2 }) => {
                let p = [point[0].clone(), point[1].clone()];
                prop_assert!(
                    !parallel && a.at(t1) == p && b.at(t2) == p && !(a.inside(t1) && b.inside(t2))
                );
            }
            Intersection2::Empty(Empty2::Parallel) => {
                let (oa, ob) = (a.carrier().0, b.carrier().0);
                let d = [ob[0].clone() - &oa[0], ob[1].clone() - &oa[1]];
                prop_assert!(parallel && cross2(&d, &da) != 0);
            }
            Intersection2::Empty(Empty2::CollinearDisjoint) => {
                prop_assert!(parallel);
                // no end point of one domain lies on the other object
                for (x, y) in [(a, b), (b, a)] {
                    if let Some(r) = x.carrier().2 {
                        for t in r {
                            let p = x.at(&t);
                            let (oy, dy, _) = y.carrier();
                            let s = Q::from(
                                ((p[0].clone() - &oy[0]) * &dy[0]
                                    + (p[1].clone() - &oy[1]) * &dy[1])
                                    / (Q::from(&dy[0] * &dy[0]) + Q::from(&dy[1] * &dy[1])),
                            );
                            prop_assert!(!y.inside(&s));
                        }
                    }
                }
            }
        }
        let same = match (&cert.value, &exact) {
            (
                Intersection2::Point {
                    point: rp,
                    t1: r1,
                    t2: r2,
                },
                Intersection2::Point { point, t1, t2 },
            )
            | (
                Intersection2::Empty(Empty2::OutsideDomain {
                    point: rp,
                    t1: r1,
                    t2: r2,
                }),
                Intersection2::Empty(Empty2::OutsideDomain { point, t1, t2 }),
            ) => rounds2(point, rp) && rounds(t1, r1) && rounds(t2, r2),
            (
                Intersection2::Segment {
                    a: ra,
                    b: rb,
                    a_params: rap,
                    b_params: rbp,
                },
                Intersection2::Segment {
                    a: xa,
                    b: xb,
                    a_params,
                    b_params,
                },
            ) => {
                rounds2(xa, ra)
                    && rounds2(xb, rb)
                    && rounds2(a_params, rap)
                    && rounds2(b_params, rbp)
            }
            (Intersection2::Line, Intersection2::Line)
            | (Intersection2::Empty(Empty2::Parallel), Intersection2::Empty(Empty2::Parallel))
            | (
                Intersection2::Empty(Empty2::CollinearDisjoint),
                Intersection2::Empty(Empty2::CollinearDisjoint),
            ) => true,
            _ => false,
        };
        prop_assert!(same, "certified {:?} but exact {:?}", cert.value, exact);
        Ok(())
    }

    pub fn l2(s: impl Strategy<Value = f64> + Clone + 'static) -> BoxedStrategy<L2> {
        prop_oneof![
            ([s.clone(), s.clone()], [s.clone(), s.clone()]).prop_map(|(o, d)| L2::Line(o, d)),
            ([s.clone(), s.clone()], [s.clone(), s.clone()], -1.0f64..1.0)
                .prop_map(|(o, d, a)| L2::Ranged(o, d, [a, a + 0.75])),
            ([s.clone(), s.clone()], [s.clone(), s]).prop_map(|(a, b)| L2::Seg(a, b)),
        ]
        .boxed()
    }

    /// Collinear objects on the line through `o` with direction `d`, built from
    /// dyadic multiples so that collinearity is exact in doubles.
    pub fn collinear() -> impl Strategy<Value = (L2, L2)> {
        (
            [dyadic(), dyadic()],
            [dyadic(), dyadic()],
            [-4i32..=4, -4i32..=4, -4i32..=4, -4i32..=4],
            0usize..3,
        )
            .prop_map(|(o, d, k, kinds)| {
                let at = |k: i32| [o[0] + k as f64 * d[0] / 2.0, o[1] + k as f64 * d[1] / 2.0];
                let a = L2::Seg(at(k[0]), at(k[1]));
                let b = match kinds {
                    0 => L2::Seg(at(k[2]), at(k[3])),
                    1 => L2::Line(at(k[2]), [d[0] * k[3] as f64, d[1] * k[3] as f64]),
                    _ => L2::Ranged(at(k[2]), d, [k[3] as f64 / 2.0, k[3] as f64 / 2.0 + 1.0]),
                };
                (a, b)
            })
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]

    #[test]
    fn lines2_generic_and_mixed(a in two_d::l2(generic()), b in two_d::l2(generic()), c in two_d::l2(mixed()), d in two_d::l2(mixed())) {
        two_d::check(&a, &b)?;
        two_d::check(&c, &d)?;
    }

    #[test]
    fn lines2_collinear_and_touching((a, b) in two_d::collinear(), c in two_d::l2(dyadic())) {
        two_d::check(&a, &b)?;
        two_d::check(&b, &a)?;
        two_d::check(&a, &c)?;
    }
}

// ---- projections ---------------------------------------------------------------

mod projections {
    use super::*;
    use geocert::geom::project::{
        project_point_line, project_point_line_exact, project_point_plane,
        project_point_plane_exact,
    };

    /// `r` is the correctly rounded `±√s` (sign `negative`), checked by squaring the
    /// neighbouring doubles in rationals.
    fn sqrt_rounds(s: &Q, negative: bool, r: &Rounded) -> bool {
        let (c, lo, hi) = if negative {
            (-r.nearest, -r.hi, -r.lo)
        } else {
            (r.nearest, r.lo, r.hi)
        };
        let sq = |x: f64| Q::from(q(x).square_ref());
        if r.is_exact() {
            return sq(c) == *s;
        }
        // lo < √s < hi, and √s is nearer to c than to the midpoints' other sides.
        let mid = |a: f64, b: f64| Q::from((q(a) + q(b)) / 2u32);
        let m_lo = if lo < c { mid(lo, c) } else { q(c) };
        let m_hi = if hi > c { mid(c, hi) } else { q(c) };
        sq(lo) < *s
            && *s < sq(hi)
            && Q::from(m_lo.square_ref()) <= *s
            && *s <= Q::from(m_hi.square_ref())
    }

    pub fn check_plane(p: &V, pl: &P) -> Result<(), TestCaseError> {
        let Some(fp) = pl.f64() else { return Ok(()) };
        let exact = project_point_plane_exact(&qvec(p), &pl.exact());
        let foot = arr(&exact.foot);
        let (n, _) = pl.eq();
        prop_assert!(pl.contains(&foot));
        let w: [Q; 3] = [0, 1, 2].map(|i| q(p[i]) - &foot[i]);
        prop_assert!(
            cross(&w, &n).iter().all(|x| *x == 0),
            "p − foot is normal to the plane"
        );
        let nn = dot(&n, &n);
        prop_assert_eq!(
            Q::from(&exact.distance.squared * &nn),
            Q::from(dot(&w, &n).square_ref())
        );
        prop_assert_eq!(exact.distance.negative, dot(&w, &n) < 0);
        if let Some(uv) = &exact.uv {
            prop_assert_eq!(pl.at(&uv[0], &uv[1]).unwrap(), foot);
        }
        let cert = project_point_plane(&vec3(p), &fp).value;
        prop_assert!(rounds3(&exact.foot, &cert.foot));
        prop_assert!(sqrt_rounds(
            &exact.distance.squared,
            exact.distance.negative,
            &cert.distance
        ));
        prop_assert_eq!(cert.distance, exact.distance.rounded);
        if let (Some(a), Some(b)) = (&cert.uv, &exact.uv) {
            prop_assert!(rounds2(b, a));
        }
        Ok(())
    }

    pub fn check_line(p: &V, o: &V, d: &V, range: Option<[f64; 2]>) -> Result<(), TestCaseError> {
        let Ok(line) = Line::with_range(vec3(o), vec3(d), range) else {
            return Ok(());
        };
        let ql = Line::with_range(qvec(o), qvec(d), range.map(|[a, b]| [q(a), q(b)])).unwrap();
        let exact = project_point_line_exact(&qvec(p), Linear::Line(&ql));
        let (qo, qd) = (qv(o), qv(d));
        let n = &exact.nearest;
        let foot = arr(&n.foot);
        prop_assert_eq!(
            &foot,
            &[0, 1, 2].map(|i| qo[i].clone() + Q::from(&n.t * &qd[i]))
        );
        let w: [Q; 3] = [0, 1, 2].map(|i| q(p[i]) - &foot[i]);
        prop_assert_eq!(&n.distance.squared, &dot(&w, &w));
        let stationary = dot(&w, &qd) == 0;
        prop_assert_eq!(exact.stationary.is_some(), stationary);
        if !stationary {
            let [a, b] = range.unwrap();
            prop_assert!(n.t == q(a) || n.t == q(b));
            // the domain end is on the side of the stationary foot
            prop_assert_eq!(dot(&w, &qd) > 0, n.t == q(b));
        }
        let cert = project_point_line(&vec3(p), Linear::Line(&line)).value;
        prop_assert!(rounds3(&n.foot, &cert.nearest.foot) && rounds(&n.t, &cert.nearest.t));
        prop_assert!(sqrt_rounds(
            &n.distance.squared,
            false,
            &cert.nearest.distance
        ));
        prop_assert_eq!(cert.stationary.is_some(), stationary);
        Ok(())
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]

    #[test]
    fn projections(p in v3(generic()), pl in plane(generic()), dp in v3(dyadic()), dpl in plane(dyadic()), m in (v3(mixed()), plane(mixed())),
                   o in v3(generic()), d in v3(dyadic()), lo in -3.0f64..1.0) {
        projections::check_plane(&p, &pl)?;
        projections::check_plane(&dp, &dpl)?;
        projections::check_plane(&m.0, &m.1)?;
        projections::check_line(&p, &o, &d, None)?;
        projections::check_line(&p, &o, &d, Some([lo, lo + 1.0]))?;
        projections::check_line(&dp, &dp, &d, Some([lo, lo + 0.5]))?;
    }
}
