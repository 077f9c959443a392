//! Parameter domains: validation of `[lo, hi]` (typed errors naming the field), and
//! the two ways an interval parameter is split before a formula is evaluated on it:
//! by the pieces of a piecewise curve ([`piecewise_jet`]: polyline segments, knot
//! spans) and by the period of a periodic curve ([`periodic_jet`], OPERATIONS.md
//! §1.5 "closed curves wrap the parameter"). The split pieces are joined by hulls, so
//! the result encloses the values over the whole parameter interval.

use crate::error::{require_finite, GeomError};
use crate::num::vector::hull_jets;
use crate::num::Real;

/// A parameter interval `[lo, hi]` with finite `lo < hi`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Domain {
    pub lo: f64,
    pub hi: f64,
}

impl Domain {
    /// Errors: `non_finite` (`field[0]`, `field[1]`), `empty_domain` (`field`) when
    /// `lo ≥ hi`.
    pub fn new(field: &str, lo: f64, hi: f64) -> Result<Domain, GeomError> {
        require_finite(&format!("{field}[0]"), lo)?;
        require_finite(&format!("{field}[1]"), hi)?;
        if lo < hi {
            Ok(Domain { lo, hi })
        } else {
            Err(GeomError::EmptyDomain {
                field: field.to_string(),
                lo: format!("{lo}"),
                hi: format!("{hi}"),
            })
        }
    }

    /// `(lo, hi)`.
    pub fn pair(&self) -> (f64, f64) {
        (self.lo, self.hi)
    }

    /// Check that this domain lies inside `natural` (the whole parameter range of
    /// the primitive). Errors: `parameter_outside_domain` (`field[0]` or `field[1]`).
    pub fn check_inside(&self, field: &str, natural: (f64, f64)) -> Result<(), GeomError> {
        for (i, v) in [self.lo, self.hi].into_iter().enumerate() {
            if !(natural.0 <= v && v <= natural.1) {
                return Err(GeomError::ParameterOutsideDomain {
                    field: format!("{field}[{i}]"),
                    value: format!("{v}"),
                    lo: format!("{}", natural.0),
                    hi: format!("{}", natural.1),
                });
            }
        }
        Ok(())
    }
}

/// Evaluate a piecewise formula at `t`: piece `i` is valid on `[breaks[i],
/// breaks[i+1]]` (the first piece also below `breaks[0]`, the last also above the last
/// break, as polynomial continuations). `eval(i, t_i)` is called for every piece that
/// `t` touches with `t_i = t` restricted to that piece, and the results are joined by
/// hulls; a point parameter (f64) touches one piece (the later one at a break).
///
/// Enclosure: every real `s ∈ t` lies in some touched piece `i`, and `s ∈ t_i`, so
/// `eval(i, t_i)` encloses the values at `s`; the hull of the pieces encloses them all.
pub fn piecewise_jet<T: Real, const D: usize>(
    t: &T,
    breaks: &[f64],
    mut eval: impl FnMut(usize, &T) -> Vec<[T; D]>,
) -> Vec<[T; D]> {
    let pieces = breaks.len().saturating_sub(1).max(1);
    let (lo, hi) = t.bounds();
    let first = piece_of(breaks, lo, pieces);
    let last = piece_of(breaks, hi, pieces).max(first);
    if first == last || lo == hi {
        return eval(first, t);
    }
    let mut out: Option<Vec<[T; D]>> = None;
    for i in first..=last {
        let below = if i == 0 { f64::NEG_INFINITY } else { breaks[i] };
        let above = if i + 1 == pieces {
            f64::INFINITY
        } else {
            breaks[i + 1]
        };
        let ti = t.restrict_to(below, above);
        let (a, b) = ti.bounds();
        if a > b {
            continue; // empty piece (a bound of `t` rounded outward onto a break)
        }
        let jet = eval(i, &ti);
        out = Some(match out {
            None => jet,
            Some(prev) => hull_jets(&prev, &jet),
        });
    }
    out.unwrap_or_else(|| eval(first, t))
}

/// The piece `i` with `breaks[i] ≤ x < breaks[i+1]`, clamped to `0..pieces`.
fn piece_of(breaks: &[f64], x: f64, pieces: usize) -> usize {
    // The number of breaks ≤ x, minus one (NaN: piece 0).
    let n = breaks.partition_point(|&b| b <= x);
    n.saturating_sub(1).min(pieces - 1)
}

/// Evaluate a formula valid on `[lo, hi]` at a parameter of a periodic curve with
/// period `hi − lo`: `t` is reduced by whole periods, `t − k(hi − lo)`, with the
/// period computed in the number system of `t` (so an interval encloses the exact
/// period), and restricted to `[lo, hi]`. An interval parameter that crosses the
/// seam gives one piece per period touched, joined by hulls.
///
/// Enclosure: a real `s ∈ t` equals `s' + kP` for some integer `k` and some
/// `s' ∈ [lo, hi]`; `s' ∈ (t − kP) ∩ [lo, hi]` for that `k`, and the pieces tried
/// cover every `k` that `t` can reach (wider parameters cover whole periods).
pub fn periodic_jet<T: Real, const D: usize>(
    t: &T,
    (lo, hi): (f64, f64),
    mut eval: impl FnMut(&T) -> Vec<[T; D]>,
) -> Vec<[T; D]> {
    let (a, b) = t.bounds();
    if lo <= a && b <= hi {
        return eval(t);
    }
    let period_f = hi - lo;
    let period = t.lift(hi) - t.lift(lo);
    let shifted = |k: f64| t.clone() - t.lift(k) * &period;
    let ka = ((a - lo) / period_f).floor();
    let kb = ((b - lo) / period_f).floor();
    // Beyond 2⁵² periods (or an unbounded or NaN parameter) whole periods no longer
    // count exactly in doubles: cover every residue by the whole domain (an enclosure
    // for any parameter; a point then evaluates at a domain end).
    let countable = |k: f64| k.abs() < 4.5e15;
    if !(countable(ka) && countable(kb)) {
        // [lo, hi] for intervals; `lo` for f64 (whose hull is its first operand).
        return eval(&t.lift(lo).hull_with(&t.lift(hi)));
    }
    if a == b {
        // A point: one shift. Used when the shifted value lies in the domain (or, exactly
        // computed, clamps into it: f64); an interval cut by the domain ends could miss
        // the true residue when `ka` is off by one, so it goes to the pieces below.
        let s = shifted(ka);
        let (sa, sb) = s.bounds();
        if lo <= sa && sb <= hi {
            return eval(&s);
        }
        if sa == sb {
            let r = s.restrict_to(lo, hi);
            let (ra, rb) = r.bounds();
            if ra <= rb {
                return eval(&r);
            }
        }
    }
    let (k_first, k_last) = if kb - ka > 4.0 {
        (ka - 1.0, ka + 4.0)
    } else {
        (ka - 1.0, kb + 1.0)
    };
    let mut out: Option<Vec<[T; D]>> = None;
    let mut k = k_first;
    while k <= k_last {
        let s = shifted(k).restrict_to(lo, hi);
        let (sa, sb) = s.bounds();
        if sa <= sb {
            let jet = eval(&s);
            out = Some(match out {
                None => jet,
                Some(prev) => hull_jets(&prev, &jet),
            });
        }
        k += 1.0;
    }
    out.unwrap_or_else(|| eval(t))
}
