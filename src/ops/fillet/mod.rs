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
//! * [`Law`] (module `ops::blend_law`): radius and leg laws `ρ(ℓ)` along the spine (§11.3, (11.11)): constant,
//!   piecewise linear, cubic Hermite; their positivity proven over the range.
//! * `prove`: every condition under which the closed form is the fillet's centre
//!   curve, proven over a cover of its whole range by f64 intervals.
//!
//! [`fillet()`], [`fillet_law()`], [`chamfer()`] and [`chamfer_laws()`] are the front
//! door (the `fillet` / `chamfer` cases).
//!
//! **Variable radius between two planes** (§11.3): the edge is the line
//! `q(ℓ) = q₀ + ℓê` (`ê = normalize(m × n)`, `q₀` its point nearest the origin), so `ℓ`
//! is its exact arc length, and the station equations (11.2)–(11.3) are linear: the
//! centre is the point with `m·c = h₁ + σ₁ρ(ℓ)`, `n·c = h₂ + σ₂ρ(ℓ)`, `ê·c = ℓ`, i.e.
//! `c(ℓ) = q(ℓ) + ρ(ℓ)·(σ₁(m − (m·n)n) + σ₂(n − (m·n)m))/|m × n|²` — the constant-radius
//! line's formula with `h + d(ℓ)` for `h + d`, so `t = ℓ` in both and a constant law is
//! the §11.2 fillet. `(c − q)·ê = 0` and `(pᵢ − q)·ê = 0` hold identically (the
//! station plane (11.3)); the positivity of `ρ` over the range is proven first
//! ([`Law::prove_positive`]). Variable chamfer legs (11.11) likewise:
//! `cᵢ(ℓ) = q(ℓ) − dᵢ(ℓ)τᵢ`.
//!
//! **What `verified` proves** (for each component): for every `t` of the range, the
//! ball of radius `ρ = ρ(t)` (`ρ(t) > 0` proven) centred at `c(t)` touches face `r` at
//! `p₁(t)` and face `s` at `p₂(t)` (for a law: in the station plane through `q(t)`
//! normal to the edge), `|c − pᵢ| = ρ` with `c − pᵢ` along the face's normal, and `pᵢ` is the
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

pub use crate::ops::blend_law::Law;
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

/// `fillet`: the rolling-ball fillet of constant radius `radius` between the faces
/// `a` (`objects[0]`) and `b` (`objects[1]`) in the chosen sector (§11.1–§11.4);
/// [`fillet_law`] with [`Law::Constant`].
pub fn fillet(
    a: &Shape,
    b: &Shape,
    radius: f64,
    spec: &BlendSpec,
    opts: &Options,
) -> Result<Certified<Answer>, GeomError> {
    fillet_law(a, b, &Law::constant(radius, "radius")?, spec, opts)
}

/// `fillet` with a radius law `ρ(ℓ)` (§11.3; constant for curved faces): the spine's
/// range is `spec.range`, by default the law's span, and must lie within it.
///
/// Errors: faces other than planes, spheres and circular cylinders, or pairs without
/// a closed-form centre curve (`unsupported`); a variable radius between curved faces
/// (`unsupported`, field `radius`); `ρ` not proven positive over the range
/// (`invalid_value`, field `radius`); two planes without `range` or law; a radius at
/// least a face's radius on its concave side, or faces tangent across the edge
/// (`degenerate_blend`, §11.4).
pub fn fillet_law(
    a: &Shape,
    b: &Shape,
    radius: &Law,
    spec: &BlendSpec,
    _opts: &Options,
) -> Result<Certified<Answer>, GeomError> {
    let (faces, sector) = faces_and_sector(a, b, spec)?;
    let range = law_range(std::slice::from_ref(radius), spec.range)?;
    radius.prove_positive(range, "radius")?;
    if let Some(rho) = radius.as_constant() {
        check_curvature(&faces, sector, rho)?;
    }
    let mut parts = Vec::new();
    for curve in CentreCurve::new(faces, sector.signs(), radius.clone(), range)? {
        let cover = prove::cover(&curve);
        if cover.absent {
            continue;
        }
        let (status, reason) = judge(&cover, &curve)?;
        let surface = FilletSurface { centre: curve };
        parts.push(report::component(&surface, spec.grid, status, reason));
    }
    let kind = BlendKind::Fillet {
        radius: radius.clone(),
    };
    Ok(answer(kind, sector, parts))
}

/// §11.4: a constant radius at least a face's curvature radius on its concave side
/// (the offset degenerates) is a typed failure.
fn check_curvature(faces: &[Face; 2], sector: Sector, rho: f64) -> Result<(), GeomError> {
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
    Ok(())
}

/// The spine's range for the laws: the caller's `range`, by default the common span
/// of the non-constant laws (`None` when all are constant and no range is given).
/// Errors (field `range`): a range not inside a law's stations, or laws whose spans
/// do not overlap.
fn law_range(laws: &[Law], range: Option<[f64; 2]>) -> Result<Option<[f64; 2]>, GeomError> {
    let spans: Vec<[f64; 2]> = laws.iter().filter_map(Law::span).collect();
    let common = spans
        .iter()
        .copied()
        .reduce(|a, b| [a[0].max(b[0]), a[1].min(b[1])]);
    let Some(range) = range.or(common) else {
        return Ok(None);
    };
    for span in &spans {
        if !(span[0] <= range[0] && range[1] <= span[1] && range[0] < range[1]) {
            return Err(GeomError::InvalidValue {
                field: "range".into(),
                reason: format!(
                    "the spine's range [{}, {}] must lie inside the stations [{}, {}] of \
                     every law",
                    range[0], range[1], span[0], span[1]
                ),
            });
        }
    }
    Ok(Some(range))
}

/// `chamfer`: the chamfer with constant legs `legs` on the faces `a` and `b` (§11.5),
/// for two planes; [`chamfer_laws`] with constant laws.
pub fn chamfer(
    a: &Shape,
    b: &Shape,
    legs: [f64; 2],
    spec: &BlendSpec,
    opts: &Options,
) -> Result<Certified<Answer>, GeomError> {
    let legs = [
        Law::constant(legs[0], "legs[0]")?,
        Law::constant(legs[1], "legs[1]")?,
    ];
    chamfer_laws(a, b, &legs, spec, opts)
}

/// `chamfer` with leg laws `kᵢ(ℓ)` (§11.5 (11.11)), for two planes. The signed legs
/// are `d₁ = σ₂k₁`, `d₂ = σ₁k₂`: the line of contact on the first face lies on the
/// sector's side of the second face and vice versa (with (11.9)'s transversals, which
/// point to the negative side of the other face; §11.5 writes `dᵢ = σᵢkᵢ`, which agrees
/// in sectors 1 and 3, §16.13). The range is `spec.range`, by default the common span
/// of the variable legs.
///
/// Errors: as [`fillet_law`] (field `legs[i]` for a leg); faces other than two planes
/// (`unsupported`); parallel planes (`degenerate_blend`).
pub fn chamfer_laws(
    a: &Shape,
    b: &Shape,
    legs: &[Law; 2],
    spec: &BlendSpec,
    _opts: &Options,
) -> Result<Certified<Answer>, GeomError> {
    let (faces, sector) = faces_and_sector(a, b, spec)?;
    if faces.iter().any(|f| f.radius().is_some()) {
        return Err(GeomError::Unsupported {
            field: "objects".into(),
            reason: "chamfers are built between two planes in this build".into(),
        });
    }
    let range = law_range(legs, spec.range)?;
    for (k, leg) in legs.iter().enumerate() {
        leg.prove_positive(range, &format!("legs[{k}]"))?;
    }
    let [s1, s2] = sector.signs();
    let mut parts = Vec::new();
    for edge in CentreCurve::new(faces, [1.0, 1.0], Law::Constant(0.0), range)? {
        let cover = prove::cover(&edge);
        let (status, reason) = judge(&cover, &edge)?;
        let surface = ChamferSurface {
            edge,
            signs: [s2, s1],
            legs: legs.clone(),
        };
        parts.push(report::component(&surface, spec.grid, status, reason));
    }
    let kind = BlendKind::Chamfer { legs: legs.clone() };
    Ok(answer(kind, sector, parts))
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
