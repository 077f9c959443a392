//! The curved half of the robustness benchmark: seeded tangent and near-tangent
//! configurations (line ∩ sphere, line ∩ torus, circle2 ∩ circle2, circle2 ∩ ellipse2,
//! circle ∩ sphere) swept over gaps `10⁻³ … 10⁻¹⁵`, ±1 ulp and exact tangency, each run
//! through geocert's float path (the `_f64` solvers seeded by the walks of
//! OPERATIONS.md §2, no proof) and through the certified front door
//! ([`crate::ops::intersect()`]), against a truth computed independently
//! ([`truth`]: exact rational root counts, points at 300 bits).
//!
//! Every configuration is built from dyadic data (multiples of 2⁻²⁰ with few bits and
//! Pythagorean directions) so that the exactly tangent one is exactly tangent in
//! doubles; the near-tangent ones scale one radius by `1 ± gap` (rounded) or move it by
//! one ulp. `+` always makes the shapes cross, `−` separates them.

pub mod gen;
pub mod paths;
pub mod seams;
pub mod ssi;
pub mod table;
pub mod truth;

pub use table::{curved_table, CurvedRow, CurvedTable};

/// Case `seed` of `family` at `gap` ([`gen`] for the tangency families, [`seams`] for
/// the seam and pole ones).
pub fn case(family: Family, gap: Gap, seed: u64) -> CurvedCase {
    let (mut rng, side) = gen::start(gap, seed);
    let data = if Family::SEAMS.contains(&family) {
        seams::data(family, &mut rng, gap, side)
    } else {
        gen::data(family, &mut rng, gap, side)
    };
    CurvedCase {
        family,
        gap,
        side,
        data,
    }
}

/// The families of the curved benchmark.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Family {
    /// A line tangent to a sphere; the sphere's radius perturbed (OPERATIONS.md §5.2,
    /// decided by the exact algebraic solver).
    LineSphere,
    /// A horizontal line tangent to a ring torus about `z`: in its top (or bottom)
    /// tangent plane across the tube, or tangent to the outer equator; the minor radius
    /// perturbed (exact quartic of §5.2 with §1.6).
    LineTorus,
    /// Two circles tangent externally or internally; the second radius perturbed
    /// (§6.3–§6.4, exact conic pair).
    Circle2Circle2,
    /// A circle tangent to an ellipse at the end of its minor axis, from outside or
    /// inside; the circle's radius perturbed (exact conic pair).
    Circle2Ellipse2,
    /// A space circle tangent to a sphere (in a plane through the sphere's centre); the
    /// circle's radius perturbed (§5.2, decided by the numeric certifier).
    CircleSphere,
    /// Two circles crossing on the seam of the first, or one ulp or `10⁻ᵏ` off it
    /// ([`seams`], issue 20's soak of seams and poles).
    SeamCircles2,
    /// Two circles tangent on a seam; a radius perturbed.
    SeamTangent2,
    /// A line crossing a sphere on its seam meridian (or just off it), or tangent at the
    /// seam point of its equator.
    SeamLineSphere,
    /// A sphere's axis as a line (hits at the poles, or just off them), or a line
    /// tangent at a pole.
    PoleLineSphere,
    /// A circle through both poles of a sphere (or just off them), or tangent to it at
    /// a pole or on the seam.
    PoleCircleSphere,
    /// A line crossing a torus on its seams, or tangent to it on the seam.
    SeamLineTorus,
    /// [`Family::PoleCircleSphere`] with the circle as an exact rational NURBS
    /// ([`seams::nurbs_circle`]) whose closing knot is often on a pole or at the
    /// touching point; the sphere moved or resized by the gap.
    PoleNurbsCircleSphere,
}

impl Family {
    pub const ALL: [Family; 5] = [
        Family::LineSphere,
        Family::LineTorus,
        Family::Circle2Circle2,
        Family::Circle2Ellipse2,
        Family::CircleSphere,
    ];

    /// The seam and pole families ([`seams`]; not in the benchmark table).
    pub const SEAMS: [Family; 7] = [
        Family::SeamCircles2,
        Family::SeamTangent2,
        Family::SeamLineSphere,
        Family::PoleLineSphere,
        Family::PoleCircleSphere,
        Family::SeamLineTorus,
        Family::PoleNurbsCircleSphere,
    ];

    /// The name in the table, the JSON and the plots' legends.
    pub fn name(self) -> &'static str {
        match self {
            Family::LineSphere => "line-sphere",
            Family::LineTorus => "line-torus",
            Family::Circle2Circle2 => "circle2-circle2",
            Family::Circle2Ellipse2 => "circle2-ellipse2",
            Family::CircleSphere => "circle-sphere",
            Family::SeamCircles2 => "seam circle2-circle2",
            Family::SeamTangent2 => "seam tangent circle2-circle2",
            Family::SeamLineSphere => "seam line-sphere",
            Family::PoleLineSphere => "pole line-sphere",
            Family::PoleCircleSphere => "pole circle-sphere",
            Family::SeamLineTorus => "seam line-torus",
            Family::PoleNurbsCircleSphere => "pole nurbs circle-sphere",
        }
    }
}

/// How far a configuration is from tangency.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Gap {
    /// A radius scaled by `1 ± 10⁻ᵏ` (then rounded to a double).
    Pow(i32),
    /// A radius moved to the next or previous double.
    Ulp,
    /// Exactly tangent.
    Tangent,
}

impl Gap {
    /// The sweep, from the widest gap to tangency: `10⁻³ … 10⁻¹⁵`, 1 ulp, 0.
    pub fn all() -> Vec<Gap> {
        (3..=15)
            .map(Gap::Pow)
            .chain([Gap::Ulp, Gap::Tangent])
            .collect()
    }

    /// The relative gap as a number (1 ulp: 2⁻⁵², the spacing of doubles relative to
    /// the value at the bottom of a binade; tangent: 0).
    pub fn value(self) -> f64 {
        match self {
            Gap::Pow(k) => 10f64.powi(-k),
            Gap::Ulp => f64::EPSILON,
            Gap::Tangent => 0.0,
        }
    }

    /// The label in the table and the JSON (`1e-3`, `1ulp`, `0`).
    pub fn label(self) -> String {
        match self {
            Gap::Pow(k) => format!("1e-{k}"),
            Gap::Ulp => "1ulp".into(),
            Gap::Tangent => "0".into(),
        }
    }
}

/// The input of one case, as doubles (the shapes are built from these).
#[derive(Debug, Clone, PartialEq)]
pub enum Data {
    /// The line `o + t·d` and the sphere `|x − c| = r`.
    LineSphere {
        o: [f64; 3],
        d: [f64; 3],
        c: [f64; 3],
        r: f64,
    },
    /// The line `o + t·d` (`d_z = 0`) and the torus about the `z` axis through `c`.
    LineTorus {
        o: [f64; 3],
        d: [f64; 3],
        c: [f64; 3],
        major: f64,
        minor: f64,
    },
    /// Two circles.
    Circles2 {
        c1: [f64; 2],
        r1: f64,
        c2: [f64; 2],
        r2: f64,
    },
    /// The circle `|x − c| = rho` and the ellipse about `e` with semi-axes `a` along x,
    /// `b` along y.
    CircleEllipse2 {
        c: [f64; 2],
        rho: f64,
        e: [f64; 2],
        a: f64,
        b: f64,
    },
    /// The space circle of radius `rho` about `q` in the plane with normal `n`, and the
    /// sphere `|x − c| = r`.
    CircleSphere {
        q: [f64; 3],
        n: [f64; 3],
        rho: f64,
        c: [f64; 3],
        r: f64,
    },
    /// The circle of radius `rho` about `q` in the plane `y = q_y`, as the NURBS of
    /// [`seams::nurbs_circle`] starting in the direction `start` (`(p, s, h)`: `(p,
    /// s)/h` in the `(x, z)` plane), and the sphere `|x − c| = r`.
    NurbsCircleSphere {
        q: [f64; 3],
        start: [i64; 3],
        rho: f64,
        c: [f64; 3],
        r: f64,
    },
}

/// One generated case.
#[derive(Debug, Clone, PartialEq)]
pub struct CurvedCase {
    pub family: Family,
    pub gap: Gap,
    /// `+1`: the perturbation makes the shapes cross; `−1`: it separates them; `0`:
    /// exactly tangent.
    pub side: i8,
    pub data: Data,
}

impl CurvedCase {
    /// The size the float tolerance is relative to (the largest radius involved).
    pub fn scale(&self) -> f64 {
        match self.data {
            Data::LineSphere { r, .. } => r,
            Data::LineTorus { major, minor, .. } => major + minor,
            Data::Circles2 { r1, r2, .. } => r1.max(r2),
            Data::CircleEllipse2 { rho, a, .. } => rho.max(a),
            Data::CircleSphere { rho, r, .. } | Data::NurbsCircleSphere { rho, r, .. } => {
                rho.max(r)
            }
        }
    }
}
