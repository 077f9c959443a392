//! Three spheres (or whole ellipsoids with proportional quadratic parts), decided
//! exactly (OPERATIONS.md §7.2; issue 14 item 9).
//!
//! With `F₁, F₂, F₃` the exact implicit forms and `A₁ = λₖAₖ`, a common point of the
//! three lies on `F₁ = 0` and on the radical planes `Pₖ: F₁ − λₖFₖ = 0` (`k = 2, 3`),
//! and conversely a point of `F₁ = 0` on `Pₖ` has `λₖFₖ = 0` (the argument of
//! [`crate::ops::section`] for two spheres). So:
//!
//! - a radical "plane" that is a non-zero constant (concentric spheres of different
//!   radii): `empty`; both identically zero (three equal spheres): `coincident`;
//! - one zero (two equal spheres): the section of `F₁` by the other plane, the exact
//!   conic answer of [`crate::ops::section::conic_answer`] (a circle, a touching point,
//!   or `empty`);
//! - two planes with `m = n₂ × n₃ = 0`: the same plane (the centres are collinear) —
//!   the section as above — or parallel distinct planes: `empty`;
//! - otherwise the line `o + s·m` common to both planes, with `o = (h₂(n₃ × m) +
//!   h₃(m × n₂))/|m|²`, against `F₁` ([`super::intersect_line_quadric_exact`]): 0 points,
//!   1 proven double root (the three spheres touch there: multiplicity 2, `tangent`),
//!   or 2 simple ones; coordinates correctly rounded (exact rationals when `s` is
//!   rational), each sphere's `(u, v)` correctly rounded where Ziv's loop decides
//!   ([`super::params::line_hit_params`]), else enclosed and the status lowered to
//!   `verified`.

use rug::Rational;
use std::cmp::Ordering;

use super::line::LineCut;
use super::on_surface::cross;
use super::pairs::{closed, frame_of, not_correctly_rounded, point_box, surface_params, Closed};
use super::params::line_hit_params;
use super::section_answer::{section_point, touching_point, ParamSource};
use super::{intersect_line_quadric_exact, QuadricForm};
use crate::certificate::{Arithmetic, Certified};
use crate::ops::answer::{Answer, ExactPoint, Point};
use crate::ops::rational::exact::dot;
use crate::ops::section::{conic_answer, section_plane_quadric, ExactPlane};
use crate::surface::AnySurface;

type V3 = [Rational; 3];

/// `F₁ − λF₂` when `A₁ = λA₂`: a plane `n·x = h`, zero, or a non-zero constant.
enum Radical {
    Plane(V3, Rational),
    Same,
    Disjoint,
}

fn radical(f1: &QuadricForm<3>, f2: &QuadricForm<3>) -> Option<Radical> {
    let (a1, a2) = (f1.matrix(), f2.matrix());
    let (i, j) = (0..3)
        .flat_map(|i| (0..3).map(move |j| (i, j)))
        .find(|&(i, j)| a2[i][j] != 0)?;
    let lambda = Rational::from(&a1[i][j] / &a2[i][j]);
    let proportional =
        (0..3).all(|i| (0..3).all(|j| a1[i][j] == Rational::from(&lambda * &a2[i][j])));
    if lambda == 0 || !proportional {
        return None;
    }
    // 2(b₁ − λb₂)·x + (c₁ − λc₂) = 0.
    let n: V3 =
        std::array::from_fn(|k| &f1.linear()[k] - Rational::from(&lambda * &f2.linear()[k]));
    let h = -(f1.constant() - Rational::from(&lambda * f2.constant())) / 2u32;
    Some(if n.iter().all(|x| *x == 0) {
        if h == 0 {
            Radical::Same
        } else {
            Radical::Disjoint
        }
    } else {
        Radical::Plane(n, h)
    })
}

fn exact(value: Answer) -> Certified<Answer> {
    Certified::exact(value, Arithmetic::Rational, 53)
}

/// The section of `f` by `n·x = h`; a touching point (the spheres' centres collinear)
/// as the exact point of all three ([`super::section_answer::touching_point`]).
fn section(s: [&AnySurface; 3], f: &QuadricForm<3>, n: V3, h: Rational) -> Certified<Answer> {
    let cut = section_plane_quadric(&ExactPlane { normal: n, d: -h }, f);
    match section_point(&cut) {
        Some(p) => {
            let bits = conic_answer(cut).bits;
            let shapes: Vec<ParamSource> = s
                .iter()
                .map(|x| closed(x).map_or(ParamSource::None, |c| ParamSource::Closed(Box::new(c))))
                .collect();
            touching_point(&p, &shapes, bits)
        }
        None => conic_answer(cut),
    }
}

/// Three whole spheres or ellipsoids with proportional quadratic parts, exactly
/// (module doc); `None` for other triples.
pub(crate) fn intersect_three_spheres(s: [&AnySurface; 3]) -> Option<Certified<Answer>> {
    let shapes: Vec<Closed> = s.iter().map(|x| closed(x)).collect::<Option<_>>()?;
    let forms: Vec<&QuadricForm<3>> = shapes
        .iter()
        .map(|c| match c {
            Closed::Quadric(q, _, _) => Some(q),
            Closed::Torus(..) => None,
        })
        .collect::<Option<_>>()?;
    let (r2, r3) = (radical(forms[0], forms[1])?, radical(forms[0], forms[2])?);
    let (n2, h2, n3, h3) = match (r2, r3) {
        (Radical::Disjoint, _) | (_, Radical::Disjoint) => return Some(exact(Answer::Empty)),
        (Radical::Same, Radical::Same) => return Some(exact(Answer::Coincident)),
        (Radical::Same, Radical::Plane(n, h)) | (Radical::Plane(n, h), Radical::Same) => {
            return Some(section(s, forms[0], n, h))
        }
        (Radical::Plane(n2, h2), Radical::Plane(n3, h3)) => (n2, h2, n3, h3),
    };
    let m = cross(&n2, &n3);
    if m.iter().all(|x| x.cmp0() == Ordering::Equal) {
        // Parallel planes: the same one when (n₂, h₂) ∥ (n₃, h₃).
        let k = (0..3).find(|&k| n3[k] != 0)?;
        let ratio = Rational::from(&n2[k] / &n3[k]);
        return Some(if Rational::from(&ratio * &h3) == h2 {
            section(s, forms[0], n2, h2)
        } else {
            exact(Answer::Empty)
        });
    }
    let (a, b) = (cross(&n3, &m), cross(&m, &n2));
    let mm = dot(&m, &m);
    let o: V3 =
        std::array::from_fn(|i| (Rational::from(&h2 * &a[i]) + Rational::from(&h3 * &b[i])) / &mm);
    let cut = intersect_line_quadric_exact(&o, &m, forms[0]);
    Some(points(&shapes, &o, &m, cut))
}

/// The points of the line `o + s·m` on the spheres, with every sphere's `(u, v)`.
fn points(shapes: &[Closed], o: &V3, m: &V3, cut: Certified<LineCut<3>>) -> Certified<Answer> {
    let mut all_rounded = true;
    let pts = cut
        .value
        .points()
        .iter()
        .map(|h| {
            let b = point_box(h);
            let mut params = Vec::new();
            let mut param_box = Vec::new();
            for shape in shapes {
                let p = match line_hit_params(&frame_of(shape), o, m, &h.t) {
                    Some(p) => p,
                    None => {
                        all_rounded = false;
                        surface_params(shape, &b)
                    }
                };
                params.push(p.iter().map(|x| x.0).collect());
                param_box.push(p.iter().map(|x| x.1).collect());
            }
            let exact = h.t.exact().map(|s| ExactPoint {
                xyz: (0..3).map(|i| Rational::from(&m[i] * s) + &o[i]).collect(),
                params: vec![vec![]; 3],
                distance_squared: None,
            });
            Point {
                xyz: h.nearest().to_vec(),
                xyz_box: b.iter().map(|x| [x.lo(), x.hi()]).collect(),
                params,
                param_box: Some(param_box),
                multiplicity: h.multiplicity,
                tangent: h.multiplicity >= 2,
                exact,
                ..Default::default()
            }
        })
        .collect();
    let mut r = cut.clone_with(Answer::from_points(pts));
    if !all_rounded {
        not_correctly_rounded(&mut r);
    }
    r
}
