//! Surface ∩ surface across seams and poles (issue 20, the soak's last seam gap): two
//! spheres whose intersection circle lies in the first sphere's seam plane `y = c_y`
//! (half of it on the seam meridian `u = 0 ≡ 2π`), passes through its pole, or touches
//! it at a pole or at the seam point of its equator — exactly, one ulp off, or `10⁻ᵏ`
//! of the radius off (the gaps of [`Gap`]). Run through the certified front door
//! ([`crate::ops::intersect()`]) and graded against a truth computed on exact
//! rationals (the circle's centre, plane and squared radius; empty, a point or a
//! circle decided by the sign of that square) and distances at [`PREC`] bits.
//!
//! A certified answer is wrong when it is decided (`verified` or `verified_singular`)
//! and complete with another topology than the truth's (not one closed curve for a
//! circle, not one point for a touch, not nothing for a miss); when a verified curve
//! has a vertex farther from the true circle than its proven `bound`, or does not wind
//! once around the circle's axis (a half lost at the seam); when a vertex's parameters
//! on either sphere do not give back its point (`|S(u, v) − xyz|` above its bound plus
//! `10⁻⁹` of the radius: a parameter taken from the wrong side of a seam); or when the
//! box of a touching point does not hold it. A `verified_singular` answer's touch may
//! stand for a tiny circle or a near miss (a contact of the perturbed spheres).

use rug::{Float, Rational};
use std::cmp::Ordering;

use super::gen::{dy, perturb, point, start, PYTHAGOREAN};
use super::paths::Outcome;
use super::seams::{shift, sign};
use super::truth::PREC;
use super::Gap;
use crate::certificate::Status;
use crate::ops::answer::{CurveAnswer, CurvesAnswer};
use crate::ops::{intersect, Answer, Options, Shape};
use crate::robust::case::q;
use crate::surface::quadrics::Sphere;
use crate::surface::AnySurface;

/// One case: the spheres `|x − a| = ra` and `|x − b| = rb`.
#[derive(Debug, Clone, PartialEq)]
pub struct SsiCase {
    pub gap: Gap,
    /// `+1`: the gap makes the spheres cut (or keeps them cutting), `−1`: apart or
    /// moved off the seam or pole, `0`: exact.
    pub side: i8,
    pub a: [f64; 3],
    pub ra: f64,
    pub b: [f64; 3],
    pub rb: f64,
}

/// Case `seed` at `gap`. Three shapes, chosen at random:
/// - the second centre in the seam plane, `b = a + (±mp, 0, ra ± ms)`, radius `mh`
///   (`(p, s, h)` Pythagorean): the circle passes through the north pole and crosses
///   the seam plane there and once more on the seam meridian or its antipode; `b`
///   moved by the gap in `x` or `y` (the circle passes beside the pole);
/// - the second centre on the axis (`b = a ± (0, 0, e)`): a latitude circle crossing
///   the seam once, its height moved by the gap (near the pole when `e` is close to
///   the radii's difference);
/// - touching: `b = a + (ra ± rb)·e` for `e = +z` (at a pole) or `+x` (at the seam
///   point of the equator), from outside or inside, `rb` moved by the gap.
pub fn case(gap: Gap, seed: u64) -> SsiCase {
    let (mut rng, side) = start(gap, seed);
    let rng = &mut rng;
    let a: [f64; 3] = point(rng);
    let (p, s, h) = PYTHAGOREAN[rng.below(PYTHAGOREAN.len())];
    match rng.below(3) {
        0 => {
            let m = rng.int(1 << 14, 1 << 16);
            let kr = rng.int(1 << 16, 1 << 20);
            let ra = dy(kr);
            let mut b = [
                a[0] + dy(sign(rng) * p * m),
                a[1],
                a[2] + ra + dy(sign(rng) * s * m),
            ];
            let k = rng.below(2);
            b[k] = shift(b[k], gap, side, ra);
            SsiCase {
                gap,
                side,
                a,
                ra,
                b,
                rb: dy(h * m),
            }
        }
        1 => {
            let kr = rng.int(1 << 18, 1 << 20);
            let kb = rng.int(1 << 16, kr);
            let (ra, rb) = (dy(kr), dy(kb));
            // The centres `e` apart, `|ra − rb| < e < ra + rb` (a circle), drawn near
            // either end half the time: the circle then hugs a pole.
            let (lo, hi) = (kr - kb, kr + kb);
            let e = match rng.below(3) {
                0 => lo + 1 + rng.int(0, 64),
                1 => hi - 1 - rng.int(0, 64),
                _ => rng.int(lo + 1, hi - 1),
            };
            let z = shift(a[2] + dy(sign(rng) * e), gap, side, ra);
            SsiCase {
                gap,
                side,
                a,
                ra,
                b: [a[0], a[1], z],
                rb,
            }
        }
        _ => {
            let kr = rng.int(1 << 18, 1 << 20);
            let kb = rng.int(1 << 14, kr - 1);
            let (ra, rb) = (dy(kr), dy(kb));
            let outside = rng.coin();
            let reach = if outside { ra + rb } else { ra - rb };
            let mut b = a;
            if rng.coin() {
                b[2] += sign(rng) as f64 * reach;
            } else {
                b[0] += reach;
            }
            // A larger second sphere cuts the first when it touches from outside; a
            // smaller one when it touches from inside.
            let grow = if outside { side } else { -side };
            let rb = perturb(rb, gap, grow);
            SsiCase {
                gap,
                side,
                a,
                ra,
                b,
                rb,
            }
        }
    }
}

/// The truth: the plane `(x − a)·d = k` (`d = b − a`) cuts the first sphere in the
/// circle of centre `a + d·k/|d|²` and squared radius `ra² − k²/|d|²`, `k = (|d|² +
/// ra² − rb²)/2` — all rational.
#[derive(Debug, Clone)]
pub struct SsiTruth {
    pub centre: [Rational; 3],
    pub normal: [Rational; 3],
    pub radius2: Rational,
}

impl SsiTruth {
    /// `Less`: no common point; `Equal`: one (a touch); `Greater`: a circle.
    pub fn kind(&self) -> Ordering {
        self.radius2.cmp0()
    }
}

/// The truth of `c` (concentric spheres are not generated).
pub fn truth(c: &SsiCase) -> SsiTruth {
    let a: [Rational; 3] = std::array::from_fn(|i| q(c.a[i]));
    let d: [Rational; 3] = std::array::from_fn(|i| q(c.b[i]) - &a[i]);
    let dd: Rational = d.iter().map(|x| Rational::from(x * x)).sum();
    let (ra2, rb2) = (q(c.ra) * q(c.ra), q(c.rb) * q(c.rb));
    let k = (Rational::from(&dd + &ra2) - rb2) / 2u32;
    let t = Rational::from(&k / &dd);
    let centre = std::array::from_fn(|i| &a[i] + Rational::from(&d[i] * &t));
    let radius2 = ra2 - Rational::from(&k * &t);
    SsiTruth {
        centre,
        normal: d,
        radius2,
    }
}

fn f(x: &Rational) -> Float {
    Float::with_val(PREC, x)
}

/// Distance from `p` to the true circle (or point), at [`PREC`] bits.
fn distance(t: &SsiTruth, p: &[f64]) -> Float {
    let w: Vec<Float> = (0..3)
        .map(|i| Float::with_val(PREC, p[i] - f(&t.centre[i])))
        .collect();
    let n: Vec<Float> = t.normal.iter().map(f).collect();
    let nn = n.iter().fold(Float::with_val(PREC, 0), |s, x| s + x * x);
    let wn = w
        .iter()
        .zip(&n)
        .fold(Float::with_val(PREC, 0), |s, (a, b)| s + a * b);
    let ww = w.iter().fold(Float::with_val(PREC, 0), |s, x| s + x * x);
    let h2 = Float::with_val(PREC, &wn * &wn) / &nn;
    let radial = Float::with_val(PREC, &ww - &h2)
        .max(&Float::new(PREC))
        .sqrt();
    let r = f(&t.radius2).max(&Float::new(PREC)).sqrt();
    let off = radial - r;
    (Float::with_val(PREC, &off * &off) + h2).sqrt()
}

/// How many times the closed polyline winds around the circle's axis (signed).
fn winding(t: &SsiTruth, pts: &[Vec<f64>]) -> i64 {
    let n: Vec<Float> = t.normal.iter().map(f).collect();
    // e1 ⟂ n from the axis of n's smallest component, e2 = n × e1 (unnormalised: the
    // angles only need a consistent frame).
    let k = (0..3)
        .min_by(|&i, &j| n[i].clone().abs().total_cmp(&n[j].clone().abs()))
        .unwrap_or(0);
    let mut axis = [0.0; 3];
    axis[k] = 1.0;
    let cross = |a: &[Float], b: &[Float]| -> Vec<Float> {
        (0..3)
            .map(|i| {
                let (j, l) = ((i + 1) % 3, (i + 2) % 3);
                Float::with_val(PREC, &a[j] * &b[l]) - Float::with_val(PREC, &a[l] * &b[j])
            })
            .collect()
    };
    let ax: Vec<Float> = axis.iter().map(|&x| Float::with_val(PREC, x)).collect();
    let e1 = cross(&n, &ax);
    let e2 = cross(&n, &e1);
    let norm = |v: &[Float]| {
        v.iter()
            .fold(Float::with_val(PREC, 0), |s, x| s + x * x)
            .sqrt()
    };
    let (l1, l2) = (norm(&e1), norm(&e2));
    let angle = |p: &Vec<f64>| {
        let w: Vec<Float> = (0..3)
            .map(|i| Float::with_val(PREC, p[i] - f(&t.centre[i])))
            .collect();
        let dot = |e: &[Float]| {
            w.iter()
                .zip(e)
                .fold(Float::with_val(PREC, 0), |s, (a, b)| s + a * b)
        };
        let (x, y) = (dot(&e1) / &l1, dot(&e2) / &l2);
        y.atan2(&x).to_f64()
    };
    let angles: Vec<f64> = pts.iter().map(angle).collect();
    let turn: f64 = angles
        .windows(2)
        .map(|w| {
            let d = w[1] - w[0];
            d - (d / std::f64::consts::TAU).round() * std::f64::consts::TAU
        })
        .sum();
    (turn / std::f64::consts::TAU).round() as i64
}

/// `|S(u, v) − xyz|` for the sphere `c + r(cos v cos u, cos v sin u, sin v)` (f64).
fn param_gap(c: &[f64; 3], r: f64, uv: &[f64], xyz: &[f64]) -> f64 {
    let (u, v) = (uv[0], uv[1]);
    let s = [
        c[0] + r * v.cos() * u.cos(),
        c[1] + r * v.cos() * u.sin(),
        c[2] + r * v.sin(),
    ];
    (0..3).map(|i| (s[i] - xyz[i]).powi(2)).sum::<f64>().sqrt()
}

/// Whether a verified curve is right (module doc).
fn curve_holds(c: &SsiCase, t: &SsiTruth, curve: &CurveAnswer) -> bool {
    if curve.status != Status::Verified {
        return true;
    }
    let slack = c.ra.max(c.rb) * 5.527147875260445e-76; // 2⁻²⁵⁰ of the size
    let tol = 1e-9 * c.ra.max(c.rb);
    let near = curve.points.iter().all(|v| {
        let b = v.bound.unwrap_or(f64::INFINITY);
        let on = distance(t, &v.xyz) <= Float::with_val(PREC, b) + slack;
        let params = v.params.len() != 2
            || (param_gap(&c.a, c.ra, &v.params[0], &v.xyz) <= b + tol
                && param_gap(&c.b, c.rb, &v.params[1], &v.xyz) <= b + tol);
        on && params
    });
    if !near {
        return false;
    }
    // The winding needs vertices well inside an annulus about the circle.
    let r = f(&t.radius2).sqrt().to_f64();
    let wide = curve
        .points
        .iter()
        .any(|v| v.bound.unwrap_or(f64::INFINITY) > 0.25 * r);
    let pts: Vec<Vec<f64>> = curve.points.iter().map(|v| v.xyz.clone()).collect();
    wide || !curve.closed || winding(t, &pts).abs() == 1
}

/// Whether a box holds the true touching point.
fn holds_touch(t: &SsiTruth, b: &[[f64; 2]]) -> bool {
    b.len() == 3 && (0..3).all(|i| q(b[i][0]) <= t.centre[i] && t.centre[i] <= q(b[i][1]))
}

/// Whether the certified answer's claims hold (module doc).
fn holds(c: &SsiCase, t: &SsiTruth, ans: &crate::Certified<Answer>) -> bool {
    if ans.status == Status::Undecided {
        return true;
    }
    // An exact touch is answered as a point (the exact sphere pair), other touches as
    // the curves answer's isolated or singular points.
    let points = CurvesAnswer {
        points: match &ans.value {
            Answer::Points(ps) => ps.clone(),
            _ => Vec::new(),
        },
        ..CurvesAnswer::default()
    };
    let v = match &ans.value {
        Answer::Curves(v) => v,
        Answer::Empty | Answer::Points(_) => &points,
        _ => return false,
    };
    if !v.curves.iter().all(|k| curve_holds(c, t, k)) {
        return false;
    }
    let touches: Vec<&crate::ops::Point> = v
        .points
        .iter()
        .chain(v.singular_points.iter().map(|s| &s.point))
        .collect();
    if t.kind() == Ordering::Equal && !touches.iter().all(|p| holds_touch(t, &p.xyz_box)) {
        return false;
    }
    if !ans.complete {
        return true;
    }
    let one_loop = v.curves.len() == 1 && v.curves[0].closed;
    // A `verified_singular` touch claims a contact of the spheres perturbed by at most
    // its `perturbation` (CERTIFICATION.md), not the exact topology: beside a true
    // touch, a tiny circle or a near miss may be answered by one.
    let singular = ans.status == Status::VerifiedSingular;
    match t.kind() {
        Ordering::Less => v.curves.is_empty() && (touches.is_empty() || singular),
        Ordering::Equal => v.curves.is_empty() && touches.len() == 1,
        Ordering::Greater => {
            (one_loop && touches.is_empty())
                || (singular && v.curves.is_empty() && touches.len() == 1)
        }
    }
}

/// Run and grade `c` (`truth_count`: 0, 1 for a touch, 1 for a circle).
pub fn run(c: &SsiCase) -> Outcome {
    let t = truth(c);
    let mut out = Outcome {
        truth_count: usize::from(t.kind() != Ordering::Less),
        ..Outcome::default()
    };
    let shapes = match (
        Sphere::new(c.a, c.ra, None, None),
        Sphere::new(c.b, c.rb, None, None),
    ) {
        (Ok(a), Ok(b)) => [
            Shape::from(AnySurface::Sphere(a)),
            Shape::from(AnySurface::Sphere(b)),
        ],
        _ => {
            out.certified_undecided = true;
            return out;
        }
    };
    match intersect(&shapes, &Options::default()) {
        Ok(ans) => {
            out.arithmetic = Some(ans.arithmetic);
            out.bits = ans.bits;
            out.certified_undecided = ans.status == Status::Undecided || !ans.complete;
            out.certified_wrong = !holds(c, &t, &ans);
        }
        Err(_) => out.certified_undecided = true,
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The first decided case of each kind among the seeds (exact ones first).
    fn first(kind: Ordering) -> (SsiCase, SsiTruth, crate::Certified<Answer>) {
        let mut gaps = Gap::all();
        gaps.reverse();
        gaps.into_iter()
            .flat_map(|g| (0..100u64).map(move |s| case(g, s)))
            .map(|c| (truth(&c), c))
            .filter(|(t, _)| t.kind() == kind)
            .map(|(t, c)| {
                let shapes = [
                    Shape::from(AnySurface::Sphere(
                        Sphere::new(c.a, c.ra, None, None).unwrap(),
                    )),
                    Shape::from(AnySurface::Sphere(
                        Sphere::new(c.b, c.rb, None, None).unwrap(),
                    )),
                ];
                let ans = intersect(&shapes, &Options::default()).unwrap();
                (c, t, ans)
            })
            .find(|(_, _, a)| a.status != Status::Undecided && a.complete)
            .expect("a decided case of this kind")
    }

    fn curve_of(a: &mut crate::Certified<Answer>) -> &mut CurveAnswer {
        match &mut a.value {
            Answer::Curves(v) => &mut v.curves[0],
            other => panic!("not curves: {other:?}"),
        }
    }

    /// The grading passes a right answer and fails each kind of wrong one: a vertex
    /// moved off the circle beyond its bound, a parameter from the other side of the
    /// seam, a curve that covers a third of the circle (its vertices still on it), a
    /// missing curve, a touch box beside the touch.
    #[test]
    fn the_grading_catches_wrong_curves_and_touches() {
        let (c, t, ans) = first(Ordering::Greater);
        assert!(holds(&c, &t, &ans));
        let curve = match &ans.value {
            Answer::Curves(v) => &v.curves[0],
            other => panic!("{other:?}"),
        };
        assert!(curve.closed && curve.status == Status::Verified && curve.points.len() > 8);

        let mut moved = ans.clone();
        let v = &mut curve_of(&mut moved).points[3];
        let b = v.bound.unwrap();
        v.xyz[2] += 4.0 * b + 1e-9 * c.ra;
        assert!(!holds(&c, &t, &moved));

        let mut param = ans.clone();
        let v = &mut curve_of(&mut param).points[3];
        v.params[0][0] += std::f64::consts::PI;
        assert!(!holds(&c, &t, &param));

        let mut third = ans.clone();
        let k = curve_of(&mut third);
        let n = k.points.len() / 3;
        k.points.truncate(n);
        let first_vertex = k.points[0].clone();
        k.points.push(first_vertex);
        assert!(!holds(&c, &t, &third));

        let mut none = ans.clone();
        none.value = Answer::Empty;
        assert!(!holds(&c, &t, &none));

        let (c, t, ans) = first(Ordering::Equal);
        assert!(holds(&c, &t, &ans));
        let mut beside = ans.clone();
        match &mut beside.value {
            Answer::Points(ps) => {
                let b = &mut ps[0].xyz_box[0];
                let w = 2.0 * (b[1] - b[0]) + 1e-12;
                *b = [b[0] + w, b[1] + w];
            }
            other => panic!("{other:?}"),
        }
        assert!(!holds(&c, &t, &beside));

        let (c, t, ans) = first(Ordering::Less);
        assert!(holds(&c, &t, &ans));
    }
}
