//! NURBS curves against planes and 2D lines are decided exactly, piece by piece over
//! their knot spans (issue 16). The truth is the exact Bézier route, which works on the
//! whole Bernstein form and never sees a knot: every NURBS here is built, exactly in
//! doubles, as the same point set as a Bézier curve:
//!
//! - one span (`[0^{p+1}, 1^{p+1}]`, polynomial or rational): the same curve, the same
//!   parameter;
//! - one knot inserted at ½ by Boehm's rule (every `α = ½`; rational with weights
//!   alternating 1 and 3, so every new point is dyadic): the same parameter;
//! - split at ½ by de Casteljau into two pieces joined at a double knot over `[0, 2]`:
//!   the parameter doubled.
//!
//! So the two answers must agree in every number: points, boxes, multiplicities,
//! exact values, and the curve's parameter (doubled where it is). Planes and lines are
//! random, through the curve's point at ½ (a root on the knot: reported once, by the
//! piece on its left), or tangent there (a double root on the knot). A closed periodic
//! B-spline cut through its seam reports the seam point once.
//! `GEOCERT_NURBS_EXACT_CASES` sets the cases per family (default 150).

use geocert::curve::{AnyCurve2, AnyCurve3, Bezier, NurbsCurve};
use geocert::geom::{Line2, Plane};
use geocert::ops::{self, Answer, Linear, LinearObject, Options, Point, Shape};
use geocert::robust::rng::Rng;
use geocert::Status;
use nalgebra::{Vector2, Vector3};
use rug::Rational;

fn cases() -> usize {
    std::env::var("GEOCERT_NURBS_EXACT_CASES")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(150)
}

fn q(x: f64) -> Rational {
    Rational::from_f64(x).expect("finite")
}

/// A control point coordinate: a multiple of ¼ in [−4, 4].
fn coord(rng: &mut Rng) -> f64 {
    rng.int(-16, 16) as f64 / 4.0
}

/// A NURBS curve's degree, knots, points and weights.
type Net<const D: usize> = (usize, Vec<f64>, Vec<[f64; D]>, Option<Vec<f64>>);

/// The Bézier curve and its NURBS copy, with how the NURBS parameter relates (×1, ×2).
struct Copy<const D: usize> {
    bezier: Vec<[f64; D]>,
    weights: Option<Vec<f64>>,
    nurbs: Net<D>,
    scale: u32,
}

fn clamped(p: usize, inner: &[f64], hi: f64) -> Vec<f64> {
    let mut k = vec![0.0; p + 1];
    k.extend_from_slice(inner);
    k.extend(std::iter::repeat_n(hi, p + 1));
    k
}

fn one_span<const D: usize>(pts: &[[f64; D]], w: Option<Vec<f64>>) -> Copy<D> {
    let p = pts.len() - 1;
    Copy {
        bezier: pts.to_vec(),
        weights: w.clone(),
        nurbs: (p, clamped(p, &[], 1.0), pts.to_vec(), w),
        scale: 1,
    }
}

/// Boehm's insertion of the knot ½ (all `α = ½`), in homogeneous coordinates.
fn inserted<const D: usize>(pts: &[[f64; D]], w: Option<Vec<f64>>) -> Copy<D> {
    let p = pts.len() - 1;
    let wt = |i: usize| w.as_ref().map_or(1.0, |w| w[i]);
    let mut q = vec![pts[0]];
    let mut qw = vec![wt(0)];
    for i in 1..=p {
        let (a, b) = (wt(i - 1), wt(i));
        let s = a + b;
        q.push(std::array::from_fn(|k| {
            (a * pts[i - 1][k] + b * pts[i][k]) / s
        }));
        qw.push(s / 2.0);
    }
    q.push(pts[p]);
    qw.push(wt(p));
    Copy {
        bezier: pts.to_vec(),
        weights: w.clone(),
        nurbs: (p, clamped(p, &[0.5], 1.0), q, w.map(|_| qw)),
        scale: 1,
    }
}

/// de Casteljau at ½: two Bézier pieces joined at the double knot 1 of `[0, 2]`.
fn split<const D: usize>(pts: &[[f64; D]]) -> Copy<D> {
    let p = pts.len() - 1;
    let mut rows = vec![pts.to_vec()];
    for r in 1..=p {
        let prev = &rows[r - 1];
        rows.push(
            (0..prev.len() - 1)
                .map(|i| std::array::from_fn(|k| (prev[i][k] + prev[i + 1][k]) / 2.0))
                .collect(),
        );
    }
    let mut q: Vec<[f64; D]> = (0..=p).map(|r| rows[r][0]).collect();
    q.extend((1..=p).map(|r| rows[p - r][r]));
    Copy {
        bezier: pts.to_vec(),
        weights: None,
        nurbs: (p, clamped(p, &vec![1.0; p], 2.0), q, None),
        scale: 2,
    }
}

/// The Bézier point at ½ and a tangent there, exactly (homogeneous de Casteljau).
fn at_half<const D: usize>(pts: &[[f64; D]], w: Option<&[f64]>) -> ([Rational; D], [Rational; D]) {
    let n = pts.len();
    let hw = |i: usize| w.map_or(Rational::from(1), |w| q(w[i]));
    let mut rows: Vec<(Vec<Rational>, Rational)> = (0..n)
        .map(|i| (pts[i].iter().map(|&x| q(x) * hw(i)).collect(), hw(i)))
        .collect();
    while rows.len() > 2 {
        rows = rows
            .windows(2)
            .map(|pair| {
                let c = pair[0].0.iter().zip(&pair[1].0);
                let xs = c.map(|(a, b)| Rational::from(a + b) / 2).collect();
                (xs, Rational::from(&pair[0].1 + &pair[1].1) / 2)
            })
            .collect();
    }
    let point = |r: &(Vec<Rational>, Rational)| -> [Rational; D] {
        std::array::from_fn(|k| Rational::from(&r.0[k] / &r.1))
    };
    let (a, b) = (point(&rows[0]), point(&rows[1]));
    let mid: [Rational; D] = std::array::from_fn(|k| {
        let (wa, wb) = (&rows[0].1, &rows[1].1);
        (Rational::from(&a[k] * wa) + Rational::from(&b[k] * wb)) / Rational::from(wa + wb)
    });
    let tangent = std::array::from_fn(|k| Rational::from(&b[k] - &a[k]));
    (mid, tangent)
}

fn net<const D: usize>(rng: &mut Rng, rational: bool) -> (Vec<[f64; D]>, Option<Vec<f64>>) {
    let p = 2 + rng.below(3);
    let pts: Vec<[f64; D]> = (0..=p)
        .map(|_| std::array::from_fn(|_| coord(rng)))
        .collect();
    let first = if rng.coin() { 1.0 } else { 3.0 };
    let w = rational.then(|| {
        (0..=p)
            .map(|i| if i % 2 == 0 { first } else { 4.0 - first })
            .collect()
    });
    (pts, w)
}

/// The curve's parameter, doubled when the NURBS runs over `[0, 2]`.
fn scaled(p: &Point, curve_at: usize, scale: u32) -> Point {
    let mut p = p.clone();
    let s = f64::from(scale);
    p.params[curve_at].iter_mut().for_each(|t| *t *= s);
    if let Some(b) = p.param_box.as_mut() {
        b[curve_at]
            .iter_mut()
            .for_each(|x| *x = [x[0] * s, x[1] * s]);
    }
    if let Some(e) = p.exact.as_mut() {
        e.params[curve_at]
            .iter_mut()
            .for_each(|t| *t *= Rational::from(scale));
    }
    p
}

fn same(bez: &ops::Answer, nurbs: &ops::Answer, curve_at: usize, scale: u32, what: &str) {
    match (bez, nurbs) {
        (Answer::Points(a), Answer::Points(b)) => {
            assert_eq!(a.len(), b.len(), "{what}: counts {a:?} vs {b:?}");
            for (x, y) in a.iter().zip(b) {
                assert_eq!(&scaled(x, curve_at, scale), y, "{what}");
            }
        }
        (a, b) => assert_eq!(a.kind(), b.kind(), "{what}"),
    }
}

fn check<const D: usize>(
    copy: &Copy<D>,
    other: Shape,
    shape: impl Fn(bool, &Copy<D>) -> Shape,
    stats: &mut [usize; 3],
    what: &str,
) {
    let opts = Options::default();
    let curve_first = stats[0].is_multiple_of(2);
    let pair = |c: Shape| {
        let shapes = if curve_first {
            [c, other.clone()]
        } else {
            [other.clone(), c]
        };
        ops::intersect(&shapes, &opts).expect("answers")
    };
    let (b, n) = (pair(shape(true, copy)), pair(shape(false, copy)));
    assert_eq!(b.status, Status::Exact, "{what}: the Bézier route is exact");
    assert_eq!(n.status, Status::Exact, "{what}: {:?}", n.reason);
    assert!(n.complete, "{what}");
    same(
        &b.value,
        &n.value,
        usize::from(!curve_first),
        copy.scale,
        what,
    );
    stats[0] += 1;
    if let Answer::Points(p) = &n.value {
        stats[1] += p.len();
        stats[2] += p.iter().filter(|p| p.tangent).count();
    }
}

fn curve3(bezier: bool, c: &Copy<3>) -> Shape {
    Shape::Curve(if bezier {
        AnyCurve3::Bezier(Bezier::new(c.bezier.clone(), c.weights.clone(), None).expect("bezier"))
    } else {
        let (p, k, pts, w) = c.nurbs.clone();
        AnyCurve3::Nurbs(NurbsCurve::new(p, k, pts, w, None).expect("nurbs"))
    })
}

fn curve2(bezier: bool, c: &Copy<2>) -> Shape {
    Shape::Curve2(if bezier {
        AnyCurve2::Bezier(Bezier::new(c.bezier.clone(), c.weights.clone(), None).expect("bezier"))
    } else {
        let (p, k, pts, w) = c.nurbs.clone();
        AnyCurve2::Nurbs(NurbsCurve::new(p, k, pts, w, None).expect("nurbs"))
    })
}

fn to_f64(x: &Rational) -> f64 {
    let v = x.to_f64();
    assert_eq!(q(v), *x, "a double");
    v
}

fn cross(a: &[Rational; 3], b: &[Rational; 3]) -> [Rational; 3] {
    std::array::from_fn(|i| {
        let (j, k) = ((i + 1) % 3, (i + 2) % 3);
        Rational::from(&a[j] * &b[k]) - Rational::from(&a[k] * &b[j])
    })
}

/// A random plane, one through the point at ½, or one tangent there (the kind by `k`).
fn plane_for(rng: &mut Rng, c: &Copy<3>, k: usize) -> Option<Shape> {
    let (mid, tangent) = at_half(&c.bezier, c.weights.as_deref());
    let e: [Rational; 3] = std::array::from_fn(|_| Rational::from(rng.int(-3, 3)));
    let n: [Rational; 3] = match k {
        2 => cross(&tangent, &e),
        _ => e,
    };
    if n.iter().all(|x| *x == 0) {
        return None;
    }
    let h: Rational = match k {
        0 => Rational::from(rng.int(-8, 8)) / 4,
        _ => n.iter().zip(&mid).map(|(a, b)| Rational::from(a * b)).sum(),
    };
    let nv = Vector3::new(to_f64(&n[0]), to_f64(&n[1]), to_f64(&n[2]));
    // `normal·x + d = 0`.
    Some(Shape::Linear(Linear::Double(LinearObject::Plane(
        Plane::implicit(nv, -to_f64(&h)).expect("a plane"),
    ))))
}

fn line_for(rng: &mut Rng, c: &Copy<2>, k: usize) -> Option<Shape> {
    let (mid, tangent) = at_half(&c.bezier, c.weights.as_deref());
    let o: [Rational; 2] = match k {
        0 => std::array::from_fn(|_| Rational::from(rng.int(-8, 8)) / 4),
        _ => mid,
    };
    let d: [Rational; 2] = match k {
        2 => tangent,
        _ => std::array::from_fn(|_| Rational::from(rng.int(-3, 3))),
    };
    if d.iter().all(|x| *x == 0) {
        return None;
    }
    let (o, d) = (o.map(|x| to_f64(&x)), d.map(|x| to_f64(&x)));
    Some(Shape::Linear(Linear::Double(LinearObject::Line2(
        Line2::new(Vector2::from(o), Vector2::from(d)).expect("line"),
    ))))
}

#[test]
fn nurbs_copies_of_bezier_curves_meet_planes_exactly_as_the_bezier() {
    let mut rng = Rng::new(0x5eed_0016);
    let mut stats = [0; 3];
    for i in 0..cases() {
        let (pts, w) = net::<3>(&mut rng, i % 2 == 1);
        let copies = [
            one_span(&pts, w.clone()),
            inserted(&pts, w.clone()),
            split(&pts),
        ];
        for (j, copy) in copies.iter().enumerate() {
            if let Some(plane) = plane_for(&mut rng, copy, (i + j) % 3) {
                check(copy, plane, curve3, &mut stats, &format!("case {i}.{j}"));
            }
        }
    }
    let [n, points, tangents] = stats;
    assert!(n >= cases() * 2, "{n} cases");
    assert!(
        points >= n / 2 && tangents >= n / 20,
        "{points} points, {tangents} tangencies"
    );
}

#[test]
fn nurbs_copies_of_bezier_curves_meet_lines_exactly_as_the_bezier() {
    let mut rng = Rng::new(0x5eed_0216);
    let mut stats = [0; 3];
    for i in 0..cases() {
        let (pts, w) = net::<2>(&mut rng, i % 2 == 1);
        let copies = [
            one_span(&pts, w.clone()),
            inserted(&pts, w.clone()),
            split(&pts),
        ];
        for (j, copy) in copies.iter().enumerate() {
            if let Some(line) = line_for(&mut rng, copy, (i + j) % 3) {
                check(copy, line, curve2, &mut stats, &format!("case {i}.{j}"));
            }
        }
    }
    let [n, points, tangents] = stats;
    assert!(n >= cases() * 2, "{n} cases");
    assert!(
        points >= n / 2 && tangents >= n / 20,
        "{points} points, {tangents} tangencies"
    );
}

/// A closed uniform B-spline (periodic net) cut by a plane through its seam point
/// `c(lo) = c(hi)`: the seam point is reported once, at `lo`, and no point twice.
#[test]
fn a_periodic_curve_cut_through_its_seam_reports_the_seam_once() {
    let mut rng = Rng::new(0x5eed_0316);
    let mut ran = 0;
    for i in 0..cases() {
        let p = 2 + i % 2;
        let n = p + 2 + rng.below(3);
        let mut pts: Vec<[f64; 3]> = (0..n)
            .map(|_| std::array::from_fn(|_| coord(&mut rng)))
            .collect();
        pts.extend_from_within(..p);
        let knots: Vec<f64> = (0..=(n + 2 * p)).map(|k| k as f64).collect();
        let curve = NurbsCurve::new(p, knots, pts.clone(), None, None).expect("nurbs");
        // The seam point: uniform B-spline at a knot, (P₀ + P₁)/2 (p = 2) or
        // (P₀ + 4P₁ + P₂)/6 (p = 3).
        let seam: [Rational; 3] = std::array::from_fn(|k| match p {
            2 => (q(pts[0][k]) + q(pts[1][k])) / 2,
            _ => (q(pts[0][k]) + 4 * q(pts[1][k]) + q(pts[2][k])) / 6,
        });
        let normal = [1.0, rng.int(-2, 2) as f64, 0.5];
        let h: Rational = normal
            .iter()
            .zip(&seam)
            .map(|(a, b)| q(*a) * b.clone())
            .sum();
        let Some(d) = Some(-h.to_f64()).filter(|d| q(*d) == -h.clone()) else {
            continue; // the seam's height is not a double
        };
        let plane = Shape::Linear(Linear::Double(LinearObject::Plane(
            Plane::implicit(Vector3::from(normal), d).expect("plane"),
        )));
        let c = ops::intersect(
            &[Shape::Curve(AnyCurve3::Nurbs(curve)), plane],
            &Options::default(),
        )
        .expect("answers");
        assert_eq!(c.status, Status::Exact, "case {i}: {:?}", c.reason);
        let Answer::Points(points) = &c.value else {
            panic!("case {i}: {:?}", c.value);
        };
        let exact: Vec<_> = points.iter().filter_map(|p| p.exact.as_ref()).collect();
        let on_seam = exact.iter().filter(|e| e.xyz[..] == seam[..]).count();
        assert_eq!(on_seam, 1, "case {i}: {points:?}");
        let seam_t = exact
            .iter()
            .find(|e| e.xyz[..] == seam[..])
            .map(|e| &e.params[0][0]);
        assert_eq!(seam_t, Some(&Rational::from(p)), "case {i}: reported at lo");
        for (a, b) in points.iter().zip(points.iter().skip(1)) {
            assert_ne!(a.xyz, b.xyz, "case {i}: a point twice");
        }
        ran += 1;
    }
    assert!(ran >= cases() / 4, "{ran} cases ran");
}
