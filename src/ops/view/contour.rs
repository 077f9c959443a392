//! The certified contour (outline) of a parametric surface, OPERATIONS.md §13.5: the
//! curve `I(u, v) = 0` (13.10) in the parameter domain, traced (module `trace`),
//! covered by proven box chains (module `chain`) and proven complete (module
//! `complete`).

use super::chain::{Chains, Piece};
use super::complete::prove_complete;
use super::projection::View;
use super::system::ContourFn;
use super::trace::{trace, Grid, Polyline};
use crate::certificate::{Arithmetic, Certified, Status};
use crate::error::GeomError;
use crate::num::round::{next_down, next_up};
use crate::num::Interval;
use crate::ops::surface_surface::SurfaceOperand;
use crate::surface::AnySurface;

pub use super::types::{Contour, ContourBound, ContourCurve, ContourEnd, ContourVertex};

/// Options of [`contour_surface`].
#[derive(Debug, Clone, PartialEq)]
pub struct ContourOptions {
    /// Grid cells per direction of the first float scan (refined up to twice while the
    /// completeness proof finds components the scan missed).
    pub grid: usize,
    pub certify: crate::certify::Options,
}

impl Default for ContourOptions {
    fn default() -> Self {
        ContourOptions {
            grid: 48,
            certify: crate::certify::Options::default(),
        }
    }
}

/// The certified contour of `surface` in `view` (§13.5, module doc).
///
/// Not generic, so it is compiled once, in this library: a caller's crate does not
/// compile the certifier again for [`AnySurface`] (a surface of another type, or your
/// own [`SurfaceOperand`]: [`contour_surface_of`]).
///
/// Errors: a grid below 4 or above 4096 cells (field `options.grid`), invalid certify
/// options, a non-finite domain (field `domain`).
#[inline(never)]
pub fn contour_surface(
    surface: &AnySurface,
    view: &View,
    options: &ContourOptions,
) -> Result<Certified<Contour>, GeomError> {
    contour_surface_of(surface, view, options)
}

/// [`contour_surface`] for any [`SurfaceOperand`] (compiled in the caller's crate for
/// its type).
pub fn contour_surface_of<S: SurfaceOperand>(
    surface: &S,
    view: &View,
    options: &ContourOptions,
) -> Result<Certified<Contour>, GeomError> {
    options.certify.check()?;
    if !(4..=4096).contains(&options.grid) {
        return Err(GeomError::InvalidValue {
            field: "options.grid".into(),
            reason: format!("{} is not in 4..=4096", options.grid),
        });
    }
    let (du, dv) = surface.domain();
    if ![du, dv].iter().flatten().all(|x| x.is_finite()) {
        return Err(GeomError::InvalidValue {
            field: "domain".into(),
            reason: "the contour needs a bounded parameter domain".into(),
        });
    }
    let f = ContourFn {
        surface,
        implicit: surface.implicit_form(),
        view,
    };
    let periodic = surface.is_closed();
    let rounded = surface.domain_rounded();
    let dom = [du, dv];
    let search: [[f64; 2]; 2] = std::array::from_fn(|k| {
        let [lo, hi] = dom[k];
        if rounded[k] && !periodic[k] {
            [next_down(lo), next_up(hi)]
        } else {
            [lo, hi]
        }
    });
    let period: [Interval; 2] = std::array::from_fn(|k| {
        let [lo, hi] = dom[k];
        let exact = Interval::point(hi) - Interval::point(lo);
        if rounded[k] {
            let a = Interval::point(next_down(hi)) - Interval::point(next_up(lo));
            let b = Interval::point(next_up(hi)) - Interval::point(next_down(lo));
            exact.hull(&a).hull(&b)
        } else {
            exact
        }
    });
    let chains = Chains {
        f: &f,
        search,
        periodic,
        period,
    };
    let mut n = options.grid;
    let mut last = None;
    for _ in 0..3 {
        let grid = Grid {
            n: [n, n],
            lo: [du[0], dv[0]],
            hi: [du[1], dv[1]],
            periodic,
        };
        let traced: Vec<(ContourCurve, Vec<Piece>)> = trace(&f, &grid)
            .iter()
            .map(|p| certify_polyline(&chains, &grid, p))
            .collect();
        let proof = prove_complete(&chains, &traced, &options.certify)?;
        let again = proof.missed && n * 2 <= 4096;
        last = Some((traced, proof));
        if !again {
            break;
        }
        n *= 2;
    }
    let (traced, proof) = last.expect("at least one round");
    let curves: Vec<ContourCurve> = traced.into_iter().map(|(c, _)| c).collect();
    let mut reasons = proof.reasons;
    for c in &curves {
        if let Some(r) = &c.reason {
            reasons.push(format!("curve: {r}"));
        }
    }
    let status = curves
        .iter()
        .map(|c| c.status)
        .fold(Status::Verified, Status::weakest);
    let status = if curves.is_empty() && !proof.complete {
        Status::Undecided
    } else {
        status
    };
    Ok(Certified {
        value: Contour { curves },
        status,
        complete: proof.complete && status == Status::Verified,
        arithmetic: if proof.bits > 53 {
            Arithmetic::Mpfr
        } else {
            Arithmetic::Interval
        },
        bits: proof.bits,
        reason: (!reasons.is_empty()).then(|| reasons.join("; ")),
        perturbation: None,
    })
}

/// The face an open polyline's end lies on: a bounded coordinate at its domain bound.
fn face_of<S>(chains: &Chains<'_, '_, S>, grid: &Grid, x: &[f64; 2]) -> Option<(usize, f64)> {
    (0..2).find_map(|k| {
        if grid.periodic[k] {
            None
        } else if x[k] == grid.lo[k] {
            Some((k, chains.search[k][0]))
        } else if x[k] == grid.hi[k] {
            Some((k, chains.search[k][1]))
        } else {
            None
        }
    })
}

/// Certify one float polyline: its chain, and every vertex's bound.
fn certify_polyline<S: SurfaceOperand>(
    chains: &Chains<'_, '_, S>,
    grid: &Grid,
    poly: &Polyline,
) -> (ContourCurve, Vec<Piece>) {
    let xs = &poly.points;
    let faces = if poly.closed {
        Ok(None)
    } else {
        match (
            face_of(chains, grid, &xs[0]),
            face_of(chains, grid, &xs[xs.len() - 1]),
        ) {
            (Some(a), Some(b)) => Ok(Some([a, b])),
            _ => Err("an open end of the float trace is not on the domain boundary".to_string()),
        }
    };
    let proven = faces.and_then(|faces| chains.arc(xs, faces));
    let ends = if poly.closed {
        [ContourEnd::Closed; 2]
    } else {
        [ContourEnd::Boundary; 2]
    };
    let vertex = |x: &[f64; 2], pieces: Option<&[Piece]>| {
        let w = wrap(grid, x);
        let p = chains.f.surface.jet(&w[0], &w[1], 0)[0];
        let bound = pieces.and_then(|ps| {
            let b = chains.vertex_box(ps, x)?;
            let shift: [Interval; 2] = std::array::from_fn(|k| {
                if x[k] == w[k] {
                    b[k]
                } else {
                    let m = ((w[k] - x[k]) / chains.period[k].midpoint()).round();
                    b[k] + chains.period[k] * Interval::point(m)
                }
            });
            let q = chains.f.surface.jet(&b[0], &b[1], 0).swap_remove(0);
            Some(ContourBound {
                param_box: shift,
                distance: distance_bound(&q, &p),
                xyz_box: q,
            })
        });
        ContourVertex {
            params: w,
            xyz: p,
            bound,
        }
    };
    match proven {
        Ok(pieces) => {
            let points: Vec<ContourVertex> = xs.iter().map(|x| vertex(x, Some(&pieces))).collect();
            let all = points.iter().all(|v| v.bound.is_some());
            let curve = ContourCurve {
                points,
                closed: poly.closed,
                ends,
                status: if all {
                    Status::Verified
                } else {
                    Status::Undecided
                },
                reason: (!all).then(|| "a vertex lies in no proven box".to_string()),
                chain: pieces.iter().map(Piece::region).collect(),
            };
            (curve, if all { pieces } else { Vec::new() })
        }
        Err(reason) => (
            ContourCurve {
                points: xs.iter().map(|x| vertex(x, None)).collect(),
                closed: poly.closed,
                ends,
                status: Status::Undecided,
                reason: Some(reason),
                chain: Vec::new(),
            },
            Vec::new(),
        ),
    }
}

/// `x` with its periodic coordinates wrapped into the domain.
fn wrap(grid: &Grid, x: &[f64; 2]) -> [f64; 2] {
    std::array::from_fn(|k| {
        if !grid.periodic[k] {
            return x[k];
        }
        let p = grid.hi[k] - grid.lo[k];
        let y = x[k] - ((x[k] - grid.lo[k]) / p).floor() * p;
        y.clamp(grid.lo[k], grid.hi[k])
    })
}

/// A proven upper bound of the distance from `p` to every point of the box `q`
/// (interval arithmetic, outward rounded).
pub fn distance_bound(q: &[Interval; 3], p: &[f64; 3]) -> f64 {
    let s = (0..3).fold(Interval::point(0.0), |acc, i| {
        let d = (q[i] - Interval::point(p[i])).abs().hi();
        acc + Interval::point(d).sqr()
    });
    s.sqrt().hi()
}
