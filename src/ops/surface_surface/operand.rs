//! The operands of surface ∩ surface and what the operation knows about them: the
//! parametric surface (always) and its implicit form when it has one (§1.4, §1.6; used by
//! the Dragilev forms (10.4), (10.9) and to locate singular points), the four
//! coordinates `[u, v, a, b]` with their domains, and the model scale `L` (§0.3).

use super::options::Options;
use crate::error::GeomError;
use crate::num::vector::norm_f64;
use crate::ops::float::Coordinate;
use crate::surface::bezier::BezierSurface;
use crate::surface::bilinear::Bilinear;
use crate::surface::nurbs::NurbsSurface;
use crate::surface::plane::{ParaboloidRect, Plane};
use crate::surface::quadrics::{Cone, Cylinder, Ellipsoid, Hyperboloid, Paraboloid, Sphere};
use crate::surface::torus::Torus;
use crate::surface::{AnyImplicit, AnySurface, Surface};
use crate::walk::surface::{SurfaceStepper, SurfaceWalkOptions};

/// A surface that may also have an implicit form `G(x) = 0` (§1.4) vanishing exactly on
/// it. The implicit form may describe more than the parametric domain (a whole cylinder
/// for a cylinder of finite height); the operation clips by the parametric domain.
pub trait SurfaceOperand: Surface {
    /// The implicit form, if any (default: none — patches, test surfaces).
    fn implicit_form(&self) -> Option<AnyImplicit> {
        None
    }

    /// The surface as an [`AnySurface`], for the exact decisions of `surface_surface::ends`
    /// (default: none).
    fn as_any(&self) -> Option<&AnySurface> {
        None
    }

    /// Which parameters `(u, v)` may be evaluated beyond the domain by the same formula,
    /// giving the same surface continued (a cylinder's height): certified chains of
    /// closed curves may then reach past those faces (module doc of `chain`). Default:
    /// neither.
    fn extends(&self) -> [bool; 2] {
        [false, false]
    }
}

impl SurfaceOperand for AnySurface {
    fn implicit_form(&self) -> Option<AnyImplicit> {
        self.implicit()
    }

    fn as_any(&self) -> Option<&AnySurface> {
        Some(self)
    }

    /// A cylinder is `origin + ρ(cos u X + sin u Y) + v Z` for every real `u`, `v`.
    fn extends(&self) -> [bool; 2] {
        match self {
            AnySurface::Cylinder(_) => [true, true],
            _ => [false, false],
        }
    }
}

macro_rules! implicit_operand {
    ($($t:ident),*) => {$(
        impl SurfaceOperand for $t {
            fn implicit_form(&self) -> Option<AnyImplicit> {
                Some(AnyImplicit::$t(self.clone()))
            }
        }
    )*};
}
implicit_operand!(
    Plane,
    Sphere,
    Ellipsoid,
    Hyperboloid,
    Paraboloid,
    ParaboloidRect,
    Cylinder,
    Cone,
    Torus
);
impl SurfaceOperand for BezierSurface {}
impl SurfaceOperand for NurbsSurface {}
impl SurfaceOperand for Bilinear {}

/// The two operands with everything the float path needs about them.
pub struct Pair<'a, R, S> {
    pub r: &'a R,
    pub s: &'a S,
    /// `[u, v, a, b]`: domain, periodicity, Newton's ε, the divergence margin.
    pub coords: [Coordinate; 4],
    /// The domain bounds of each coordinate are roundings of irrational values.
    pub rounded: [bool; 4],
    /// `L`, the diagonal of the bounding box of both surfaces (§0.3).
    pub length: f64,
    /// The implicit forms of `r` and `s`.
    pub implicit: [Option<AnyImplicit>; 2],
    pub steppers: (SurfaceStepper<'a, R>, SurfaceStepper<'a, S>),
    pub options: &'a Options,
    /// The float stage's work so far, in units of [`FLOAT_WORK`] (issue 20): see
    /// [`Pair::spend`].
    work: std::cell::Cell<usize>,
    /// `[u, v, a, b]`: the surface's formula continues the same surface beyond the
    /// domain ([`SurfaceOperand::extends`]).
    pub extends: [bool; 4],
    /// Domain faces whose face system was decided exactly ([`super::ends`]).
    pub decided: Vec<super::ends::DecidedFace>,
}

/// Units of float-stage work one box of `max_boxes` buys (issue 20): the float stage of
/// §9.2–§9.5 (iso-curves, their Newton guesses, march points, contact seeds and their
/// location) may do at most `FLOAT_WORK · max_boxes` units before the certified stage,
/// whose boxes the same option bounds.
pub const FLOAT_WORK: usize = 64;

impl<'a, R: SurfaceOperand, S: SurfaceOperand> Pair<'a, R, S> {
    /// Errors: an unbounded parameter domain (field `objects[0].domain` / `objects[1].domain`), invalid
    /// options.
    pub fn new(r: &'a R, s: &'a S, options: &'a Options) -> Result<Self, GeomError> {
        options.check()?;
        let walk = SurfaceWalkOptions::new(options.delta_alpha);
        let sr = SurfaceStepper::new(r, walk).map_err(|e| e.at("objects[0]"))?;
        let ss = SurfaceStepper::new(s, walk).map_err(|e| e.at("objects[1]"))?;
        let (ru, rv) = r.domain();
        let (sa, sb) = s.domain();
        let domains = [ru, rv, sa, sb];
        let closed = [r.is_closed(), s.is_closed()];
        let rounded_r = r.domain_rounded();
        let rounded_s = s.domain_rounded();
        let eps = options.precision.eps;
        let coords = std::array::from_fn(|i| {
            let [lo, hi] = domains[i];
            Coordinate {
                lo,
                hi,
                periodic: closed[i / 2][i % 2],
                eps: eps * (hi - lo).max(1.0),
                margin: hi - lo,
            }
        });
        let length = bounding_diagonal(r, ru, rv).max(bounding_diagonal(s, sa, sb));
        let ([e0, e1], [e2, e3]) = (r.extends(), s.extends());
        Ok(Pair {
            r,
            s,
            coords,
            rounded: [rounded_r[0], rounded_r[1], rounded_s[0], rounded_s[1]],
            length: if length > 0.0 { length } else { 1.0 },
            implicit: [r.implicit_form(), s.implicit_form()],
            steppers: (sr, ss),
            options,
            work: std::cell::Cell::new(0),
            extends: [e0, e1, e2, e3],
            decided: super::ends::decide(r.as_any(), s.as_any()),
        })
    }
}

impl<R, S> Pair<'_, R, S> {
    /// Count `units` of float-stage work; true once the float stage must stop: its
    /// work budget (`FLOAT_WORK · max_boxes` units) is spent or the deadline has passed
    /// (issue 20). Every loop of the float stage asks this once per iteration, so that
    /// `max_boxes` bounds each phase, not only the certified one. What the float stage
    /// misses when it stops is never claimed absent: the completeness proof of the
    /// certified stage is independent of it and runs under the same limits.
    pub fn spend(&self, units: usize) -> bool {
        let w = self.work.get().saturating_add(units);
        self.work.set(w);
        w > FLOAT_WORK.saturating_mul(self.options.certify.max_boxes) || self.options.certify.late()
    }

    /// The float-stage work counted by [`Pair::spend`] so far.
    pub fn work(&self) -> usize {
        self.work.get()
    }

    /// `δ_len = δ·L` (§12).
    pub fn delta_len(&self) -> f64 {
        self.options.precision.delta * self.length
    }

    /// The periodic distance between two values of coordinate `i` (§0.4).
    pub fn param_distance(&self, i: usize, x: f64, y: f64) -> f64 {
        let c = &self.coords[i];
        let d = (x - y).abs();
        if c.periodic {
            let p = c.hi - c.lo;
            let r = d.rem_euclid(p);
            r.min(p - r)
        } else {
            d
        }
    }

    /// `y` shifted by whole periods to lie nearest to `x` (coordinate `i`).
    pub fn unwrap_near(&self, i: usize, x: f64, y: f64) -> f64 {
        let c = &self.coords[i];
        if !c.periodic {
            return y;
        }
        let p = c.hi - c.lo;
        y - ((y - x) / p).round() * p
    }

    /// All periodic coordinates of `x` wrapped into their domain.
    pub fn wrap(&self, x: [f64; 4]) -> [f64; 4] {
        std::array::from_fn(|i| self.coords[i].wrap(x[i]))
    }

    /// `x` lies in the domain (non-periodic coordinates within `slack`).
    pub fn inside(&self, x: &[f64; 4], slack: f64) -> bool {
        self.coords.iter().zip(x).all(|(c, &v)| {
            let s = slack * (c.hi - c.lo).max(1.0);
            c.periodic || (c.lo - s <= v && v <= c.hi + s)
        })
    }
}

/// The diagonal of the bounding box of a 7 × 7 grid of the surface's points.
fn bounding_diagonal<S: Surface>(s: &S, u: [f64; 2], v: [f64; 2]) -> f64 {
    let mut lo = [f64::INFINITY; 3];
    let mut hi = [f64::NEG_INFINITY; 3];
    for i in 0..7 {
        for j in 0..7 {
            let at = |[a, b]: [f64; 2], k: usize| a + (b - a) * (k as f64 / 6.0);
            let p = s.jet(&at(u, i), &at(v, j), 0)[0];
            for c in 0..3 {
                lo[c] = lo[c].min(p[c]);
                hi[c] = hi[c].max(p[c]);
            }
        }
    }
    let d = norm_f64::<3>(&std::array::from_fn(|c| hi[c] - lo[c]));
    if d.is_finite() {
        d
    } else {
        0.0
    }
}
