//! Projection maps of OPERATIONS.md §13.6: orthographic views with picture axes
//! `e_X, e_Y` and view vector `d = e_X × e_Y` (toward the viewer), the oblique affine
//! map, and the central view from an eye point.
//!
//! A [`View`] is defined by the doubles it stores (a view along `(1, 1, 1)` is the view
//! along exactly that vector); every map is written once over [`Real`], so f64, f64
//! intervals and MPFR intervals evaluate the same formula — for interval arguments the
//! result encloses the image of the stored view.

use crate::error::GeomError;
use crate::num::vector::{cross, dot, lift, norm_f64, sub};
use crate::num::Real;

/// How the view projects: along parallel rays or through an eye point.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Rays {
    /// Parallel rays toward the viewer along this vector (the kernel of the map;
    /// not necessarily unit: only its direction matters).
    Parallel([f64; 3]),
    /// Central projection from this eye point.
    Central([f64; 3]),
}

/// A projection of space onto the picture plane (§13.6).
#[derive(Debug, Clone, PartialEq)]
pub struct View {
    /// The picture axes: `X = e_X·x`, `Y = e_Y·x` (orthographic); for an oblique view
    /// the rows of the affine map; for a central view the axes of the picture plane.
    pub e_x: [f64; 3],
    pub e_y: [f64; 3],
    /// The rays (parallel: toward the viewer, `e_X × e_Y` for orthographic views).
    pub rays: Rays,
    /// Central views: the distance from the eye to the picture plane (image scale).
    pub focal: f64,
}

fn unit(field: &str, v: [f64; 3]) -> Result<[f64; 3], GeomError> {
    crate::error::require_finite_all(field, &v)?;
    let n = norm_f64(&v);
    if n == 0.0 || !n.is_finite() {
        return Err(GeomError::ZeroDirection {
            field: field.into(),
        });
    }
    Ok(v.map(|c| c / n))
}

/// The picture axes of the general view along `d` (§13.6 table, generalised):
/// `e_X = (k × d)/|k × d|` (`k = (0, 0, 1)`; `e_X = (1, 0, 0)` when `d ∥ k`) and
/// `e_Y = d̂ × e_X`. This reproduces every orthographic row of the table.
pub fn picture_axes(d: [f64; 3]) -> Result<([f64; 3], [f64; 3]), GeomError> {
    let d = unit("view.direction", d)?;
    let kd = [-d[1], d[0], 0.0];
    let e_x = if norm_f64(&kd) == 0.0 {
        [1.0, 0.0, 0.0]
    } else {
        unit("view.direction", kd)?
    };
    Ok((e_x, cross(&d, &e_x)))
}

impl View {
    /// The general parallel (orthographic) view with view vector `d` toward the viewer.
    /// Errors: `d` zero or not finite (field `view.direction`).
    pub fn parallel(d: [f64; 3]) -> Result<View, GeomError> {
        let (e_x, e_y) = picture_axes(d)?;
        Ok(View {
            e_x,
            e_y,
            rays: Rays::Parallel(d),
            focal: 1.0,
        })
    }

    /// Frontal plane: `e_X = (1,0,0)`, `e_Y = (0,0,1)`, `d = (0,−1,0)` (§13.6 table).
    pub fn frontal() -> View {
        View::exact_axes([1.0, 0.0, 0.0], [0.0, 0.0, 1.0], [0.0, -1.0, 0.0])
    }

    /// Horizontal plane: `e_X = (1,0,0)`, `e_Y = (0,1,0)`, `d = (0,0,1)` (§13.6 table).
    pub fn horizontal() -> View {
        View::exact_axes([1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0])
    }

    /// Profile plane (not in the §13.6 table; the general rule for `d = (1,0,0)`):
    /// `e_X = (0,1,0)`, `e_Y = (0,0,1)`, the view from `+x`.
    pub fn profile() -> View {
        View::exact_axes([0.0, 1.0, 0.0], [0.0, 0.0, 1.0], [1.0, 0.0, 0.0])
    }

    fn exact_axes(e_x: [f64; 3], e_y: [f64; 3], d: [f64; 3]) -> View {
        View {
            e_x,
            e_y,
            rays: Rays::Parallel(d),
            focal: 1.0,
        }
    }

    /// Rectangular isometry: `d = (1,1,1)` (the stored ray vector is exact),
    /// `e_X = (−1,1,0)/√2`, `e_Y = (−1,−1,2)/√6` (§13.6 table).
    pub fn isometric() -> View {
        let (e_x, e_y) = picture_axes([1.0, 1.0, 1.0]).expect("a non-zero constant vector");
        View {
            e_x,
            e_y,
            rays: Rays::Parallel([1.0, 1.0, 1.0]),
            focal: 1.0,
        }
    }

    /// Rectangular dimetry: `d = (1, √7, 1)/3` (§13.6 table; x, z scale 0.9428, y 0.4714).
    pub fn dimetric() -> View {
        View::parallel([1.0, 7f64.sqrt(), 1.0]).expect("a non-zero constant vector")
    }

    /// Oblique frontal projection (§13.6 last row): `X = x + k·y·cos φ`,
    /// `Y = z + k·y·sin φ` (`y` receding at angle `φ` with scale `k`). Cabinet
    /// (the spec's "oblique frontal dimetry") is `k = ½, φ = 45°`
    /// ([`View::cabinet`]); cavalier (drafting convention, not in the spec) `k = 1`.
    /// The rays run along the kernel of the map, `(−k cos φ, 1, −k sin φ)`, and
    /// toward the viewer (`y` decreasing, as for the frontal view).
    /// Errors: `k` or `φ` not finite, `k ≤ 0` (field `view.scale` / `view.angle`).
    pub fn oblique(k: f64, phi: f64) -> Result<View, GeomError> {
        crate::error::require_finite("view.angle", phi)?;
        if !(k > 0.0 && k.is_finite()) {
            return Err(GeomError::InvalidValue {
                field: "view.scale".into(),
                reason: format!("{k} is not a finite positive scale"),
            });
        }
        let (c, s) = (k * phi.cos(), k * phi.sin());
        Ok(View {
            e_x: [1.0, c, 0.0],
            e_y: [0.0, s, 1.0],
            rays: Rays::Parallel([c, -1.0, s]),
            focal: 1.0,
        })
    }

    /// Cabinet projection: [`View::oblique`] with `k = ½`, `φ = 45°` (§13.6).
    pub fn cabinet() -> View {
        View::oblique(0.5, std::f64::consts::FRAC_PI_4).expect("constant arguments")
    }

    /// Cavalier projection: [`View::oblique`] with `k = 1`, `φ = 45°`.
    pub fn cavalier() -> View {
        View::oblique(1.0, std::f64::consts::FRAC_PI_4).expect("constant arguments")
    }

    /// Central view from `eye` looking at `target`: picture axes from the view vector
    /// `d = eye − target` as for [`View::parallel`], image at distance `focal`.
    /// Errors: `eye = target` (field `view.target`), non-finite or non-positive `focal`.
    pub fn central(eye: [f64; 3], target: [f64; 3], focal: f64) -> Result<View, GeomError> {
        crate::error::require_finite_all("view.eye", &eye)?;
        crate::error::require_finite_all("view.target", &target)?;
        if !(focal > 0.0 && focal.is_finite()) {
            return Err(GeomError::InvalidValue {
                field: "view.focal".into(),
                reason: format!("{focal} is not a finite positive distance"),
            });
        }
        let d = sub(&eye, &target);
        let (e_x, e_y) = picture_axes(d).map_err(|_| GeomError::ZeroDirection {
            field: "view.target".into(),
        })?;
        Ok(View {
            e_x,
            e_y,
            rays: Rays::Central(eye),
            focal,
        })
    }

    /// The view vector toward the viewer at the point `x`: `d` (parallel) or `E − x`
    /// (central), the `w` of (13.10) and its central form.
    pub fn toward_viewer<T: Real>(&self, x: &[T; 3]) -> [T; 3] {
        match self.rays {
            Rays::Parallel(d) => lift(&x[0], &d),
            Rays::Central(e) => sub(&lift(&x[0], &e), x),
        }
    }

    /// The picture coordinates `(X, Y)` of `x` (§13.6): `(e_X·x, e_Y·x)` for parallel
    /// views; for a central view `f·(e_X·(x−E), e_Y·(x−E))/(−d̂·(x−E))` (undefined —
    /// an infinite or NaN float, an unbounded interval — for points in the eye's plane).
    pub fn project<T: Real>(&self, x: &[T; 3]) -> [T; 2] {
        let (ex, ey) = (lift(&x[0], &self.e_x), lift(&x[0], &self.e_y));
        match self.rays {
            Rays::Parallel(_) => [dot(&ex, x), dot(&ey, x)],
            Rays::Central(e) => {
                let r = sub(x, &lift(&x[0], &e));
                let depth = -dot(&cross(&ex, &ey), &r);
                let f = x[0].lift(self.focal);
                [
                    f.clone() * dot(&ex, &r) / depth.clone(),
                    f * dot(&ey, &r) / depth,
                ]
            }
        }
    }

    /// The image of the unit vector along axis `i` (0 = x, 1 = y, 2 = z) in a parallel
    /// view: its scale `|(e_X[i], e_Y[i])|` and its angle below the horizontal,
    /// `atan(−e_Y[i]/|e_X[i]|)` in radians (§16.14: isometric 0.8165 at 30°).
    pub fn axis_scale_angle(&self, i: usize) -> (f64, f64) {
        let (x, y) = (self.e_x[i], self.e_y[i]);
        ((x * x + y * y).sqrt(), (-y).atan2(x.abs()))
    }
}
