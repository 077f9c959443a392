//! The options of the front door: the float path's tolerances (OPERATIONS.md §12), the
//! certifier's budgets, and whether exact answers carry their rationals.

use super::shape::Position;
use crate::certify;
use crate::error::GeomError;
use crate::ops::float::Precision;

/// Options shared by every operation.
#[derive(Debug, Clone, PartialEq)]
pub struct Options {
    /// ε and δ of the float path (§12); certificates never depend on them.
    pub precision: Precision,
    /// The box budget of subdivision.
    pub max_boxes: usize,
    /// The precision cap of MPFR escalation, in bits.
    pub max_bits: u32,
    /// Report the exact rationals of exact answers, and run linear shapes through the
    /// exact rational kernel.
    pub exact: bool,
    /// Surface ∩ surface: the largest distance between a polyline chord and the curve
    /// (float estimate from the curvature, OPERATIONS.md §9.3); `None`: `10⁻⁴·L`.
    pub chord_tolerance: Option<f64>,
    /// The wall-clock budget of one call of the front door; `None`: no limit (the
    /// default: the answer never depends on timing). When it runs out the certifier
    /// stops taking boxes and what is left is `undecided`, "time limit reached".
    pub time_limit: Option<std::time::Duration>,
    /// The deadline of the call in progress, set by [`Options::started`] at the front
    /// door from `time_limit` (callers leave it `None`).
    pub deadline: Option<std::time::Instant>,
    /// The float path that seeds the certifier (docs/FORMAT.md `options.method`).
    pub method: Method,
}

/// The float path of an operation; whatever it is, the answer is certified the same
/// way (the certifier proves or says `undecided`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Method {
    /// The operation's own ladder (exact where the pair is algebraic, Newton seeded by
    /// the walks otherwise).
    #[default]
    Default,
    /// Curve ∩ surface with an implicit form by bisection on `F(x(σ))` (OPERATIONS.md
    /// §13.4, [`crate::ops::bisection`]).
    Bisection,
}

impl Method {
    /// The method named `name` in `options.method`; an unknown name is an
    /// `invalid_value` error on that field.
    pub fn parse(name: &str) -> Result<Method, GeomError> {
        match name {
            "default" => Ok(Method::Default),
            "bisection" => Ok(Method::Bisection),
            other => Err(GeomError::InvalidValue {
                field: "options.method".into(),
                reason: format!("unknown method `{other}` (expected `default` or `bisection`)"),
            }),
        }
    }
}

/// The largest `max_bits` accepted (`options.max_bits`): beyond it one Krawczyk step
/// costs seconds, and 2³²−1 bits would not end.
pub const MAX_BITS: u32 = 1 << 16;

impl Default for Options {
    fn default() -> Self {
        Options {
            precision: Precision::default(),
            max_boxes: 20_000,
            // 512, not the specification's 4096 (docs/CERTIFICATES.md "Escalation"): a
            // tangency escalates to the cap before its singular certificate, and at 4096
            // bits that costs ~100× more (measured).
            max_bits: 512,
            exact: false,
            chord_tolerance: None,
            time_limit: None,
            deadline: None,
            method: Method::Default,
        }
    }
}

impl Options {
    /// Options with the given tolerances and budgets (`None`: the default); a
    /// tolerance outside `(0, 1)` is an `invalid_value` error naming its field
    /// (`options.tolerance`, `options.equal_tolerance`).
    pub fn new(
        tolerance: Option<f64>,
        equal_tolerance: Option<f64>,
        max_boxes: Option<u64>,
        max_bits: Option<u32>,
        exact: bool,
    ) -> Result<Options, GeomError> {
        let mut o = Options {
            exact,
            ..Options::default()
        };
        let check = |x: f64, field: &str, name: &str| {
            if x > 0.0 && x < 1.0 {
                Ok(x)
            } else {
                Err(GeomError::InvalidValue {
                    field: field.into(),
                    reason: format!("the tolerance {name} must lie in (0, 1), found {x}"),
                })
            }
        };
        if let Some(eps) = tolerance {
            o.precision.eps = check(eps, "options.tolerance", "ε")?;
        }
        if let Some(delta) = equal_tolerance {
            o.precision.delta = check(delta, "options.equal_tolerance", "δ")?;
        }
        if let Some(b) = max_boxes {
            o.max_boxes = usize::try_from(b).unwrap_or(usize::MAX);
        }
        if let Some(b) = max_bits {
            if b > MAX_BITS {
                return Err(GeomError::InvalidValue {
                    field: "options.max_bits".into(),
                    reason: format!("{b} bits is more than the maximum {MAX_BITS}"),
                });
            }
            o.max_bits = b;
        }
        Ok(o)
    }

    /// These options with the deadline of a call starting now (`time_limit` from now),
    /// unless a deadline is already set (an inner call keeps the outer one).
    pub fn started(&self) -> Options {
        let mut o = self.clone();
        if o.deadline.is_none() {
            o.deadline = o
                .time_limit
                .and_then(|t| std::time::Instant::now().checked_add(t));
        }
        o
    }

    /// The certifier's options.
    pub fn certify(&self) -> certify::Options {
        certify::Options {
            max_boxes: self.max_boxes,
            max_bits: self.max_bits,
            min_width: 0.0,
            deadline: self.deadline,
        }
    }
}

/// How `project` projects (OPERATIONS.md §3).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct ProjectOptions {
    /// Only the nearest point of the whole (closed) domain.
    pub nearest: bool,
    /// Projection along this direction (§3.5) instead of the perpendicular feet.
    pub direction: Option<Position>,
    pub options: Options,
}
