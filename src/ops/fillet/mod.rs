//! Fillet (rolling ball) and chamfer surfaces with certified contact (OPERATIONS.md
//! §11, §16.13; issue 18).
//!
//! * [`sector`]: the four sectors of §11.1 and the sector of a caller's point.
//! * [`face`]: the faces (plane, sphere, circular cylinder) with their normal fields,
//!   offsets and parameter recovery, over [`crate::num::Real`].
//! * [`centre`]: the ball-centre curve (11.1) — the intersection of the offset
//!   surfaces — in closed form, and the station of §11.4 (centre, contacts, normals,
//!   `cos φ`).
//! * [`blend`]: the fillet surface (11.5)–(11.7) and the chamfer surface (11.8)–(11.10)
//!   as [`crate::surface::Surface`]s of the model.
//! * `prove`: every condition under which the closed form is the fillet's centre
//!   curve, proven over a cover of its whole range by f64 intervals.
//!
//! [`fillet()`] and [`chamfer()`] are the front door (the `fillet` / `chamfer` cases).
//!
//! **What `verified` proves** (for each component): for every `t` of the range, the
//! ball of radius `ρ` centred at `c(t)` touches face `r` at `p₁(t)` and face `s` at
//! `p₂(t)`, `|c − pᵢ| = ρ` with `c − pᵢ` along the face's normal, and `pᵢ` is the
//! nearest point of the face to `c` (for planes, spheres and cylinders the foot of the
//! normal from a point at distance `ρ` on the side where `R ± ρ > 0` is the global
//! nearest point; the contact is proven inside the face's domain); the faces are
//! transversal there (`1 + cos φ > 0`); hence the rational quadratic (11.7) is the
//! circular arc of radius `ρ` about `c(t)` from `p₁` to `p₂` whose end tangents lie in
//! the faces' tangent planes (an identity of (11.6)). Each reported vertex and grid
//! point lies within its reported box of the exact value at its exact parameters.

pub mod blend;
pub mod centre;
pub mod face;
mod prove;
mod report;
pub mod sector;

pub use blend::{end_tangency, BlendFormula, ChamferSurface, FilletSurface};
pub use centre::{CentreCurve, CentreForm, Condition, Station};
pub use face::Face;
pub use sector::{sector_of_point, Sector};

use crate::certificate::{Arithmetic, Certified, Status};
use crate::error::GeomError;
use crate::ops::answer::{Answer, BlendAnswer, BlendComponent, BlendKind};
use crate::ops::options::Options;
use crate::ops::shape::Shape;
use prove::{Cover, Verdict};

/// How the caller chooses the sector (§11.1).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum SectorChoice {
    /// By its number 1–4.
    Number(u8),
    /// The sector holding this point (the caller's side).
    Side([f64; 3]),
}

/// What a blend case asks besides its two faces.
#[derive(Debug, Clone, PartialEq)]
pub struct BlendSpec {
    pub sector: SectorChoice,
    /// The arc-length range of the spine of two planes (required there).
    pub range: Option<[f64; 2]>,
    /// Stations along the spine and points across the blend (each 2…10000).
    pub grid: [usize; 2],
}

impl Default for BlendSpec {
    fn default() -> Self {
        BlendSpec {
            sector: SectorChoice::Number(3),
            range: None,
            grid: [17, 9],
        }
    }
}

/// δ_tan of §12 (§16.17): faces whose normals at a contact make a sine below it are
/// "tangent across the edge" (a typed failure, §11.4).
const DELTA_TAN: f64 = 1e-5;

fn positive(field: &str, x: f64) -> Result<f64, GeomError> {
    if x.is_finite() && x > 0.0 {
        Ok(x)
    } else {
        Err(GeomError::InvalidValue {
            field: field.into(),
            reason: format!("must be a positive finite number, found {x}"),
        })
    }
}

fn check_spec(spec: &BlendSpec) -> Result<(), GeomError> {
    if let Some([a, b]) = spec.range {
        if !(a.is_finite() && b.is_finite() && a < b) {
            return Err(GeomError::EmptyDomain {
                field: "range".into(),
                lo: a.to_string(),
                hi: b.to_string(),
            });
        }
    }
    if spec.grid.iter().any(|&n| !(2..=10_000).contains(&n)) {
        return Err(GeomError::InvalidValue {
            field: "grid".into(),
            reason: "each count must lie in 2..=10000".into(),
        });
    }
    Ok(())
}

fn faces_and_sector(
    a: &Shape,
    b: &Shape,
    spec: &BlendSpec,
) -> Result<([Face; 2], Sector), GeomError> {
    check_spec(spec)?;
    let faces = [
        Face::of_shape(a, "objects[0]")?,
        Face::of_shape(b, "objects[1]")?,
    ];
    let sector = match spec.sector {
        SectorChoice::Number(k) => Sector::from_number(k)?,
        SectorChoice::Side(x) => {
            crate::error::require_finite_all("side", &x)?;
            sector_of_point(&faces[0], &faces[1], &x)?
        }
    };
    Ok((faces, sector))
}

/// `fillet`: the rolling-ball fillet of radius `radius` between the faces `a`
/// (`objects[0]`) and `b` (`objects[1]`) in the chosen sector (§11.1–§11.4).
///
/// Errors: faces other than planes, spheres and circular cylinders, or pairs without
/// a closed-form centre curve (`unsupported`); `radius` not positive; two planes
/// without `range`; a radius at least a face's radius on its concave side, or faces
/// tangent across the edge (`degenerate_blend`, §11.4).
pub fn fillet(
    a: &Shape,
    b: &Shape,
    radius: f64,
    spec: &BlendSpec,
    _opts: &Options,
) -> Result<Certified<Answer>, GeomError> {
    let rho = positive("radius", radius)?;
    let (faces, sector) = faces_and_sector(a, b, spec)?;
    let offsets = sector.signs().map(|s| s * rho);
    for (k, face) in faces.iter().enumerate() {
        if let Some(r) = face.radius() {
            if offsets[k] < 0.0 && rho >= r {
                return Err(GeomError::DegenerateBlend {
                    field: "radius".into(),
                    reason: format!(
                        "the radius {rho} is not below objects[{k}]'s radius of curvature \
                         {r} on its concave side (sector {}): the offset surface \
                         degenerates (§11.4)",
                        sector.number()
                    ),
                });
            }
        }
    }
    let mut parts = Vec::new();
    for curve in CentreCurve::new(faces, offsets, spec.range)? {
        let cover = prove::cover(&curve);
        if cover.absent {
            continue;
        }
        let (status, reason) = judge(&cover, &curve)?;
        let surface = FilletSurface { centre: curve };
        parts.push(report::component(&surface, spec.grid, status, reason));
    }
    Ok(answer(BlendKind::Fillet { radius: rho }, sector, parts))
}

/// `chamfer`: the chamfer with legs `legs` on the faces `a` and `b` (§11.5), for two
/// planes. The signed legs are `d₁ = σ₂k₁`, `d₂ = σ₁k₂`: the line of contact on the
/// first face lies on the sector's side of the second face and vice versa (with
/// (11.9)'s transversals, which point to the negative side of the other face; §11.5
/// writes `dᵢ = σᵢkᵢ`, which agrees in sectors 1 and 3, §16.13).
///
/// Errors: as [`fillet`]; faces other than two planes (`unsupported`); parallel
/// planes (`degenerate_blend`).
pub fn chamfer(
    a: &Shape,
    b: &Shape,
    legs: [f64; 2],
    spec: &BlendSpec,
    _opts: &Options,
) -> Result<Certified<Answer>, GeomError> {
    let legs = [positive("legs[0]", legs[0])?, positive("legs[1]", legs[1])?];
    let (faces, sector) = faces_and_sector(a, b, spec)?;
    if faces.iter().any(|f| f.radius().is_some()) {
        return Err(GeomError::Unsupported {
            field: "objects".into(),
            reason: "chamfers are built between two planes in this build".into(),
        });
    }
    let [s1, s2] = sector.signs();
    let mut parts = Vec::new();
    for edge in CentreCurve::new(faces, [0.0, 0.0], spec.range)? {
        let cover = prove::cover(&edge);
        let (status, reason) = judge(&cover, &edge)?;
        let surface = ChamferSurface {
            edge,
            offsets: [s2 * legs[0], s1 * legs[1]],
        };
        parts.push(report::component(&surface, spec.grid, status, reason));
    }
    Ok(answer(BlendKind::Chamfer { legs }, sector, parts))
}

/// The status of a component from its cover; faces tangent across the edge are the
/// typed failure of §11.4.
fn judge(cover: &Cover, curve: &CentreCurve) -> Result<(Status, Option<String>), GeomError> {
    let tangent = |t: [f64; 2]| GeomError::DegenerateBlend {
        field: "objects".into(),
        reason: format!(
            "the faces are tangent across the edge near t = {} (their normals are \
             parallel at the contacts, §11.4)",
            0.5 * (t[0] + t[1])
        ),
    };
    match &cover.verdict {
        Verdict::Proven => Ok((Status::Verified, None)),
        Verdict::Fails {
            condition: Condition::Transversal,
            t,
        } => Err(tangent(*t)),
        Verdict::Undecided {
            condition: Condition::Transversal,
            t,
            value,
        } if value.is_nan() || *value <= DELTA_TAN * DELTA_TAN => Err(tangent(*t)),
        // The offsets touch (a circle of radius 0): tangent faces when the normals
        // are parallel there.
        Verdict::Fails {
            condition: Condition::Real,
            t,
        }
        | Verdict::Undecided {
            condition: Condition::Real,
            t,
            ..
        } if transversality(curve, 0.5 * (t[0] + t[1])) <= DELTA_TAN * DELTA_TAN => {
            Err(tangent(*t))
        }
        Verdict::Fails { condition, t } | Verdict::Undecided { condition, t, .. } => {
            let what = match condition {
                Condition::Real => "the closed-form centre curve is not proven real".to_string(),
                Condition::Transversal => "the faces are not proven transversal".to_string(),
                Condition::Domain(k) => {
                    format!("the contact on objects[{k}] is not proven inside its domain")
                }
            };
            Ok((
                Status::Undecided,
                Some(format!("{what} near t ∈ [{}, {}]", t[0], t[1])),
            ))
        }
    }
}

/// `|m × n|²` at `t`, f64 (a float estimate for the degenerate-case test only).
fn transversality(curve: &CentreCurve, t: f64) -> f64 {
    curve
        .conditions(&t)
        .into_iter()
        .find(|(_, c)| *c == Condition::Transversal)
        .map_or(f64::NAN, |(v, _)| v)
}

fn answer(kind: BlendKind, sector: Sector, components: Vec<BlendComponent>) -> Certified<Answer> {
    let status = components
        .iter()
        .map(|c| c.spine.status)
        .fold(Status::Verified, Status::weakest);
    let reason = components.iter().find_map(|c| c.spine.reason.clone());
    let value = Answer::Blend(BlendAnswer {
        kind,
        sector: sector.number(),
        components,
    });
    let mut c = Certified::exact(value, Arithmetic::Interval, 53);
    c.status = status;
    c.complete = status == Status::Verified;
    c.reason = reason;
    c
}
