//! Sectors (OPERATIONS.md §11.1): near the edge of faces `r` (normal `m`) and `s`
//! (normal `n`), space splits into four sectors by the signs `(σ₁, σ₂)` of a point
//! relative to each face's normal; sector 3 `(−, −)` holds the fillet of a convex
//! edge of a body with outward normals.

use super::face::Face;
use crate::error::GeomError;
use crate::num::vector::{dot, lift, norm_sq, sub};
use crate::num::{Interval, Real};

/// One of the four sectors of §11.1.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Sector {
    /// `(+, +)`
    One,
    /// `(+, −)`
    Two,
    /// `(−, −)`: the fillet of a convex edge (outward normals).
    Three,
    /// `(−, +)`
    Four,
}

impl Sector {
    /// The sector numbered 1–4 (field `sector` in errors).
    pub fn from_number(k: u8) -> Result<Sector, GeomError> {
        Ok(match k {
            1 => Sector::One,
            2 => Sector::Two,
            3 => Sector::Three,
            4 => Sector::Four,
            _ => {
                return Err(GeomError::InvalidValue {
                    field: "sector".into(),
                    reason: format!("a sector is 1, 2, 3 or 4 (OPERATIONS.md §11.1), not {k}"),
                })
            }
        })
    }

    /// The sector with the signs `(σ₁, σ₂)` (each ±1; `true` = `+`).
    pub fn from_signs(plus1: bool, plus2: bool) -> Sector {
        match (plus1, plus2) {
            (true, true) => Sector::One,
            (true, false) => Sector::Two,
            (false, false) => Sector::Three,
            (false, true) => Sector::Four,
        }
    }

    /// Its number 1–4.
    pub fn number(self) -> u8 {
        match self {
            Sector::One => 1,
            Sector::Two => 2,
            Sector::Three => 3,
            Sector::Four => 4,
        }
    }

    /// `(σ₁, σ₂)` as ±1.
    pub fn signs(self) -> [f64; 2] {
        match self {
            Sector::One => [1.0, 1.0],
            Sector::Two => [1.0, -1.0],
            Sector::Three => [-1.0, -1.0],
            Sector::Four => [-1.0, 1.0],
        }
    }
}

/// The side of `x` relative to a face's normal (§11.1 (impl)): `σ = sign((x − p)·m)`
/// at the nearest point `p`, which for these faces is the sign of the plane's
/// `m·x − h`, of `|x − c|² − R²` (sphere) or of `dist(x, axis)² − R²` (cylinder).
/// Decided with f64 intervals (outward rounded); `None` when `x` is too close to the
/// face to decide.
pub fn side_of_point(face: &Face, x: &[f64; 3]) -> Option<bool> {
    let xi: [Interval; 3] = x.map(Interval::point);
    let value = match face {
        Face::Sphere(s) => {
            let r = Interval::point(s.radius());
            norm_sq(&sub(&xi, &lift(&xi[0], &s.frame.origin()))) - r.sqr()
        }
        Face::Cylinder(c) => {
            let (l, _) = c.frame.to_local(&xi);
            let r = Interval::point(c.semi_axes()[0]);
            l[0].sqr() + l[1].sqr() - r.sqr()
        }
        _ => {
            let p = face.plane_form(&xi[0])?;
            dot(&p.m, &xi) - p.h
        }
    };
    let (lo, hi) = value.bounds();
    if lo > 0.0 {
        Some(true)
    } else if hi < 0.0 {
        Some(false)
    } else {
        None
    }
}

/// The sector of the point `x` relative to the faces `r` and `s` (§11.1 (impl)).
/// Errors: `x` lies on a face or too close to decide (field `side`).
pub fn sector_of_point(r: &Face, s: &Face, x: &[f64; 3]) -> Result<Sector, GeomError> {
    let side = |f: &Face, k: usize| {
        side_of_point(f, x).ok_or_else(|| GeomError::InvalidValue {
            field: "side".into(),
            reason: format!(
                "the point lies on objects[{k}] (or too close to it to decide its side): \
                 it names no sector"
            ),
        })
    };
    Ok(Sector::from_signs(side(r, 0)?, side(s, 1)?))
}
