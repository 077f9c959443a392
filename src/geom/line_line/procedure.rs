//! The exact decision procedure of line ∩ line (module documentation of
//! [`super`]), generic over the field: `f64` (plain), `Rational` (exact), `Ratio<E>`
//! (the exact tiers). The crossing formulas ([`crossing_terms`]) are shared with the
//! filter, which evaluates them in double-double.

use nalgebra::{Vector2, Vector3};
use std::cmp::Ordering;

use super::{LineLine, LineLineEmpty, LineLinePoint};
use crate::geom::data::{lift3, Lift, Linear};
use crate::geom::objects::Coord;
use crate::num::ring::{cross3, dot3, each, is_zero3, sub3, Field, Ring, V3};

/// The carrier `o + t·d` of a line, ray, ranged line or segment (`a + t(b − a)`).
#[derive(Debug, Clone)]
pub(crate) struct Carrier<R> {
    pub o: V3<R>,
    pub d: V3<R>,
}

/// The parameter domain `[lo, hi]`, `None` for an infinite end.
#[derive(Debug, Clone)]
pub(crate) struct Domain<R> {
    pub lo: Option<R>,
    pub hi: Option<R>,
}

/// The carrier in the ring `R` (a segment's `b − a` computed in `R`).
#[inline(always)]
pub(crate) fn carrier<T: Coord + Lift<R>, R: Ring>(l: Linear<T>) -> Carrier<R> {
    match l {
        Linear::Line(l) => Carrier {
            o: lift3(l.origin()),
            d: lift3(l.dir()),
        },
        Linear::Segment(s) => {
            let a = lift3(s.a());
            Carrier {
                d: sub3(&lift3(s.b()), &a),
                o: a,
            }
        }
    }
}

/// The domain in the ring `R` (a segment's is `[0, 1]`).
#[inline(always)]
pub(crate) fn domain<T: Coord + Lift<R>, R: Ring>(l: Linear<T>) -> Domain<R> {
    match l {
        Linear::Line(l) => {
            let (lo, hi) = l.bounds();
            Domain {
                lo: lo.map(Lift::lift),
                hi: hi.map(Lift::lift),
            }
        }
        Linear::Segment(_) => Domain {
            lo: Some(R::zero()),
            hi: Some(R::one()),
        },
    }
}

impl<R: Field> Domain<R> {
    fn contains(&self, t: &R) -> bool {
        self.lo.as_ref().is_none_or(|lo| t.compare(lo).is_ge())
            && self.hi.as_ref().is_none_or(|hi| t.compare(hi).is_le())
    }
    fn unbounded(&self) -> bool {
        self.lo.is_none() && self.hi.is_none()
    }
}

/// The polynomials of the crossing case on the axis `k`: with `(i, j)` the next two
/// axes, `den = n_k`, `t1n = (w × d₂)_k`, `t2n = (w × d₁)_k`, `pnum = o₁n_k + t1n·d₁`.
pub(crate) struct CrossingTerms<R> {
    pub den: R,
    pub t1n: R,
    pub t2n: R,
    pub pnum: V3<R>,
}

/// The crossing numerators given `w = o₂ − o₁` and `den = n_k`.
#[inline(always)]
pub(crate) fn crossing_terms<R: Ring>(
    x: &Carrier<R>,
    y: &Carrier<R>,
    w: &V3<R>,
    den: R,
    k: usize,
) -> CrossingTerms<R> {
    let (i, j) = ((k + 1) % 3, (k + 2) % 3);
    let t1n = w[i].times(&y.d[j]).minus(&w[j].times(&y.d[i]));
    let t2n = w[i].times(&x.d[j]).minus(&w[j].times(&x.d[i]));
    let pnum = each!(c in [0, 1, 2] => x.o[c].times(&den).plus(&t1n.times(&x.d[c])));
    CrossingTerms {
        den,
        t1n,
        t2n,
        pnum,
    }
}

/// `w·n = det(o₂ − o₁, d₁, d₂)`: zero exactly when the carriers are coplanar (the
/// formula the filter evaluates, for its constant's derivation).
#[cfg(test)]
pub(crate) fn coplanarity<R: Ring>(x: &Carrier<R>, y: &Carrier<R>) -> R {
    dot3(&sub3(&y.o, &x.o), &cross3(&x.d, &y.d))
}

/// The three terms `w_i n_i` of [`coplanarity`] (summed in the same order, they give
/// the same value).
#[inline(always)]
pub(crate) fn coplanarity_terms<R: Ring>(x: &Carrier<R>, y: &Carrier<R>) -> V3<R> {
    let (w, n) = (sub3(&y.o, &x.o), cross3(&x.d, &y.d));
    each!(i in [0, 1, 2] => w[i].times(&n[i]))
}

/// The axis of the largest `|n_k|` (the first on ties), `None` when `n = 0`.
fn axis<R: Field>(n: &V3<R>) -> Option<usize> {
    let abs = |x: &R| {
        if x.sign().is_lt() {
            x.negate()
        } else {
            x.clone()
        }
    };
    let mut best: Option<(usize, R)> = None;
    for (k, x) in n.iter().enumerate() {
        let a = abs(x);
        if a.is_zero() {
            continue;
        }
        if best.as_ref().is_none_or(|(_, m)| a.compare(m).is_gt()) {
            best = Some((k, a));
        }
    }
    best.map(|(k, _)| k)
}

/// The exact decision procedure.
pub(crate) fn core<R: Field>(
    x: &Carrier<R>,
    dx: &Domain<R>,
    y: &Carrier<R>,
    dy: &Domain<R>,
) -> LineLine<R> {
    let n = cross3(&x.d, &y.d);
    let w = sub3(&y.o, &x.o);
    let Some(k) = axis(&n) else {
        return parallel(x, dx, y, dy, &w);
    };
    if !dot3(&w, &n).is_zero() {
        return LineLine::Empty(LineLineEmpty::Skew);
    }
    crossing(x, dx, y, dy, &w, n[k].clone(), k)
}

/// `(d₁ × d₂)_k`.
#[inline(always)]
pub(crate) fn normal_component<R: Ring>(x: &Carrier<R>, y: &Carrier<R>, k: usize) -> R {
    let (i, j) = ((k + 1) % 3, (k + 2) % 3);
    x.d[i].times(&y.d[j]).minus(&x.d[j].times(&y.d[i]))
}

/// Coplanar carriers with `den = n_k ≠ 0`: the crossing point, inside both domains
/// or not.
pub(crate) fn crossing<R: Field>(
    x: &Carrier<R>,
    dx: &Domain<R>,
    y: &Carrier<R>,
    dy: &Domain<R>,
    w: &V3<R>,
    den: R,
    k: usize,
) -> LineLine<R> {
    let tm = crossing_terms(x, y, w, den, k);
    let p = LineLinePoint {
        point: Vector3::from(tm.pnum.map(|q| q.divide(&tm.den))),
        t1: tm.t1n.divide(&tm.den),
        t2: tm.t2n.divide(&tm.den),
    };
    if dx.contains(&p.t1) && dy.contains(&p.t2) {
        LineLine::Point(p)
    } else {
        LineLine::Empty(LineLineEmpty::OutsideDomain(p))
    }
}

/// An end of a collinear overlap: its parameters, and whether it is an end of the
/// second object's domain (its point is then computed on the second carrier, where its
/// parameter is a given number).
struct End<R> {
    t1: R,
    t2: R,
    second: bool,
}

/// `n = 0`: parallel, coincident or collinear with an overlap (or none).
fn parallel<R: Field>(
    x: &Carrier<R>,
    dx: &Domain<R>,
    y: &Carrier<R>,
    dy: &Domain<R>,
    w: &V3<R>,
) -> LineLine<R> {
    if !is_zero3(&cross3(w, &x.d)) {
        return LineLine::Empty(LineLineEmpty::Parallel);
    }
    if dx.unbounded() && dy.unbounded() {
        return LineLine::Line;
    }
    let (aa, bb, ab) = (dot3(&x.d, &x.d), dot3(&y.d, &y.d), dot3(&x.d, &y.d));
    let (wa, wb) = (dot3(w, &x.d), dot3(w, &y.d));
    let first = |t1: &R| End {
        t2: t1.times(&ab).minus(&wb).divide(&bb),
        t1: t1.clone(),
        second: false,
    };
    let second = |t2: &R| End {
        t1: wa.plus(&t2.times(&ab)).divide(&aa),
        t2: t2.clone(),
        second: true,
    };
    let same_way = ab.sign().is_gt();
    // The second domain's ends in the order of t₁.
    let (ylo, yhi) = (dy.lo.as_ref().map(second), dy.hi.as_ref().map(second));
    let (ylo, yhi) = if same_way { (ylo, yhi) } else { (yhi, ylo) };
    let lo = later(dx.lo.as_ref().map(first), ylo, Ordering::Greater);
    let hi = later(dx.hi.as_ref().map(first), yhi, Ordering::Less);
    let at = |e: &End<R>| {
        let (c, t) = if e.second { (y, &e.t2) } else { (x, &e.t1) };
        Vector3::from(each!(i in [0, 1, 2] => c.o[i].plus(&t.times(&c.d[i]))))
    };
    match (lo, hi) {
        (None, None) => LineLine::Line,
        (Some(e), None) => LineLine::Ray {
            a: at(&e),
            a_params: Vector2::new(e.t1, e.t2),
            increasing: [true, same_way],
        },
        (None, Some(e)) => LineLine::Ray {
            a: at(&e),
            a_params: Vector2::new(e.t1, e.t2),
            increasing: [false, !same_way],
        },
        (Some(l), Some(h)) => match l.t1.compare(&h.t1) {
            Ordering::Greater => LineLine::Empty(LineLineEmpty::CollinearDisjoint),
            Ordering::Equal => LineLine::Point(LineLinePoint {
                point: at(&l),
                t1: l.t1,
                t2: l.t2,
            }),
            Ordering::Less => LineLine::Segment {
                a: at(&l),
                b: at(&h),
                a_params: Vector2::new(l.t1, l.t2),
                b_params: Vector2::new(h.t1, h.t2),
            },
        },
    }
}

/// Of two optional ends, the one further in `towards` (`Greater`: the larger `t₁`);
/// the first on ties.
fn later<R: Field>(a: Option<End<R>>, b: Option<End<R>>, towards: Ordering) -> Option<End<R>> {
    match (a, b) {
        (Some(a), Some(b)) => Some(if b.t1.compare(&a.t1) == towards { b } else { a }),
        (a, b) => a.or(b),
    }
}
