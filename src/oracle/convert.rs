//! Between the public types of [`super`] and the bridge's: input validation and
//! packing, reading results, turning C++ exceptions into [`OracleError`].

use super::ffi::bridge::{ExactOut, FloatOut, Kind, Linear3, PlaneIn, Two2, Two3};
use super::{
    Intersection, Line2Input, LineInput, Linear3Input, OracleError, PlaneInput, Segment2Input,
    SegmentInput,
};
use crate::error::{require_finite, require_finite_all};
use crate::GeomError;
use rug::Rational;

/// How [`super::epeck_f64`] turns Epeck's lazy numbers into doubles.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum EpeckToDouble {
    /// `CGAL::to_double(x)`: the midpoint of the lazy interval approximation, without
    /// computing the exact value unless a predicate needed it. Not the nearest
    /// double, and only as close as the interval is narrow: within 1.5e-12 relative
    /// on random well-conditioned triples of planes (tests/oracle_kernels.rs), while
    /// BUILD-NOTES.md quotes ~1e-5.
    Approx,
    /// `CGAL::to_double(CGAL::exact(x))`: forces the exact rational, then rounds it
    /// to the nearest double (Boost.Multiprecision's correctly rounded conversion).
    Exact,
}

impl EpeckToDouble {
    pub(super) fn force_exact(self) -> bool {
        self == EpeckToDouble::Exact
    }
}

// ---- inputs ---------------------------------------------------------------

/// Every component of `field.part` finite, naming `field.part[i]` otherwise. The
/// names are built only on failure: `require_finite_all` formats one per component,
/// which costs more than a whole Epick call.
#[inline(always)]
fn finite(field: &str, part: &str, v: &[f64]) -> Result<(), GeomError> {
    if v.iter().all(|x| x.is_finite()) {
        return Ok(());
    }
    let field = if part.is_empty() {
        field.to_string()
    } else {
        format!("{field}.{part}")
    };
    require_finite_all(&field, v)
}

#[inline(always)]
pub(super) fn plane(p: &PlaneInput, field: &str) -> Result<PlaneIn, GeomError> {
    match *p {
        PlaneInput::Parametric { origin, u, v } => {
            finite(field, "origin", &origin)?;
            finite(field, "u", &u)?;
            finite(field, "v", &v)?;
            let mut packed = [0.0; 9];
            packed[..3].copy_from_slice(&origin);
            packed[3..6].copy_from_slice(&u);
            packed[6..].copy_from_slice(&v);
            Ok(PlaneIn {
                implicit: false,
                v: packed,
            })
        }
        PlaneInput::Implicit { a, b, c, d } => {
            if ![a, b, c, d].iter().all(|x| x.is_finite()) {
                for (name, x) in [("a", a), ("b", b), ("c", c), ("d", d)] {
                    require_finite(&format!("{field}.{name}"), x)?;
                }
            }
            Ok(PlaneIn {
                implicit: true,
                v: [a, b, c, d, 0.0, 0.0, 0.0, 0.0, 0.0],
            })
        }
    }
}

#[inline(always)]
pub(super) fn point(p: &[f64; 3], field: &str) -> Result<[f64; 3], GeomError> {
    finite(field, "", p)?;
    Ok(*p)
}

#[inline(always)]
pub(super) fn line(l: &LineInput, field: &str) -> Result<Two3, GeomError> {
    finite(field, "point", &l.point)?;
    finite(field, "direction", &l.direction)?;
    Ok(Two3 {
        a: l.point,
        b: l.direction,
    })
}

#[inline(always)]
pub(super) fn segment(s: &SegmentInput, field: &str) -> Result<Two3, GeomError> {
    finite(field, "source", &s.source)?;
    finite(field, "target", &s.target)?;
    Ok(Two3 {
        a: s.source,
        b: s.target,
    })
}

/// A line ∩ line argument: finite point and direction, range ends not NaN, `lo`
/// finite or `−∞`, `hi` finite or `+∞` (an inverted closed range is refused by the
/// C++ side as a degenerate segment).
#[inline(always)]
pub(super) fn linear3(l: &Linear3Input, field: &str) -> Result<Linear3, GeomError> {
    match *l {
        Linear3Input::Segment(s) => {
            let Two3 { a, b } = segment(&s, field)?;
            Ok(Linear3 {
                segment: true,
                a,
                b,
                lo: 0.0,
                hi: 1.0,
            })
        }
        Linear3Input::Line {
            point,
            direction,
            lo,
            hi,
        } => {
            finite(field, "point", &point)?;
            finite(field, "direction", &direction)?;
            if !(lo.is_finite() || lo == f64::NEG_INFINITY) {
                require_finite(&format!("{field}.lo"), lo)?;
            }
            if !(hi.is_finite() || hi == f64::INFINITY) {
                require_finite(&format!("{field}.hi"), hi)?;
            }
            Ok(Linear3 {
                segment: false,
                a: point,
                b: direction,
                lo,
                hi,
            })
        }
    }
}

#[inline(always)]
pub(super) fn line2(l: &Line2Input, field: &str) -> Result<Two2, GeomError> {
    finite(field, "point", &l.point)?;
    finite(field, "direction", &l.direction)?;
    Ok(Two2 {
        a: l.point,
        b: l.direction,
    })
}

#[inline(always)]
pub(super) fn segment2(s: &Segment2Input, field: &str) -> Result<Two2, GeomError> {
    finite(field, "source", &s.source)?;
    finite(field, "target", &s.target)?;
    Ok(Two2 {
        a: s.source,
        b: s.target,
    })
}

// ---- errors ---------------------------------------------------------------

/// The C++ side throws `"geocert:<kind>:<field>"` for degenerate input; anything
/// else is CGAL's (or the runtime's) own exception.
fn exception(e: cxx::Exception) -> OracleError {
    let what = e.what();
    let mut parts = what.splitn(3, ':');
    let (Some("geocert"), Some(kind), Some(field)) = (parts.next(), parts.next(), parts.next())
    else {
        return OracleError::Cgal(what.to_string());
    };
    let field = field.to_string();
    let input = match kind {
        "zero_direction" => GeomError::ZeroDirection { field },
        "zero_normal" => GeomError::ZeroNormal { field },
        "collinear_plane_vectors" => GeomError::CollinearPlaneVectors { field },
        "degenerate_segment" => GeomError::InvalidValue {
            field,
            reason: "the segment's end points coincide".to_string(),
        },
        _ => return OracleError::Bridge(format!("an unknown rejection {what:?}")),
    };
    OracleError::Input(input)
}

// ---- outputs --------------------------------------------------------------

/// How many values a result of `kind` has in dimension `d`.
fn value_count(kind: Kind, d: usize) -> Result<usize, OracleError> {
    match kind {
        Kind::Empty => Ok(0),
        Kind::Point => Ok(d),
        Kind::Line | Kind::Segment => Ok(2 * d),
        Kind::Ray if d == 3 => Ok(6),
        Kind::Plane if d == 3 => Ok(4),
        _ => Err(OracleError::Bridge(format!(
            "the kind {kind:?} in dimension {d}"
        ))),
    }
}

fn take<T, const N: usize>(values: &mut std::vec::IntoIter<T>) -> Result<[T; N], OracleError> {
    let head: Vec<T> = values.by_ref().take(N).collect();
    head.try_into()
        .map_err(|_| OracleError::Bridge("too few values".to_string()))
}

fn assemble<T, const D: usize>(
    kind: Kind,
    values: Vec<T>,
) -> Result<Intersection<T, D>, OracleError> {
    let expected = value_count(kind, D)?;
    if values.len() != expected {
        return Err(OracleError::Bridge(format!(
            "{} values for a {kind:?}, expected {expected}",
            values.len()
        )));
    }
    let mut it = values.into_iter();
    Ok(match kind {
        Kind::Empty => Intersection::Empty,
        Kind::Point => Intersection::Point(take(&mut it)?),
        Kind::Line => Intersection::Line {
            point: take(&mut it)?,
            direction: take(&mut it)?,
        },
        Kind::Segment => Intersection::Segment {
            source: take(&mut it)?,
            target: take(&mut it)?,
        },
        Kind::Ray => Intersection::Ray {
            source: take(&mut it)?,
            direction: take(&mut it)?,
        },
        _ => Intersection::Plane(take(&mut it)?),
    })
}

/// Reads an exact answer: every string must be a canonical rational.
pub(super) fn exact<const D: usize>(
    out: Result<ExactOut, cxx::Exception>,
) -> Result<Intersection<Rational, D>, OracleError> {
    let out = out.map_err(exception)?;
    let values = out
        .v
        .iter()
        .map(|s| {
            s.parse::<Rational>()
                .map_err(|e| OracleError::Bridge(format!("the number {s:?}: {e}")))
        })
        .collect::<Result<Vec<_>, _>>()?;
    assemble(out.kind, values)
}

/// Reads a double answer, without allocating (the benchmarks time this path).
#[inline(always)]
pub(super) fn float<const D: usize>(
    out: Result<FloatOut, cxx::Exception>,
) -> Result<Intersection<f64, D>, OracleError> {
    let out = out.map_err(exception)?;
    // D is 2 or 3, so every index is below 2·D ≤ 6 = out.v.len().
    let at = |k: usize| -> [f64; D] {
        let mut a = [0.0; D];
        a.copy_from_slice(&out.v[k..k + D]);
        a
    };
    Ok(match out.kind {
        Kind::Empty => Intersection::Empty,
        Kind::Point => Intersection::Point(at(0)),
        Kind::Line => Intersection::Line {
            point: at(0),
            direction: at(D),
        },
        Kind::Segment => Intersection::Segment {
            source: at(0),
            target: at(D),
        },
        Kind::Ray if D == 3 => Intersection::Ray {
            source: at(0),
            direction: at(D),
        },
        kind => {
            value_count(kind, D)?;
            Intersection::Plane([out.v[0], out.v[1], out.v[2], out.v[3]])
        }
    })
}

/// The point of a projection (always a point, or an error).
pub(super) fn only_point<T, const D: usize>(
    r: Result<Intersection<T, D>, OracleError>,
) -> Result<[T; D], OracleError> {
    match r? {
        Intersection::Point(p) => Ok(p),
        other => Err(OracleError::Bridge(format!(
            "a {} where a point was expected",
            match other {
                Intersection::Empty => "empty set",
                Intersection::Line { .. } => "line",
                Intersection::Segment { .. } => "segment",
                Intersection::Ray { .. } => "ray",
                _ => "plane",
            }
        ))),
    }
}
