//! Exact implicit quadrics and conics `F(x) = xᵀAx + 2bᵀx + c₀` (OPERATIONS.md §1.4,
//! §1.7 eq. (1.19)–(1.20)), with `A` symmetric and every entry an exact rational.
//!
//! The constructors build the implicit form of the primitives of §1.6 exactly from
//! double data, and only where that form is rational: a sphere, a circular cylinder
//! or cone about any axis (the axis enters through `|a|²` and `(q·a)²`, never `|a|`),
//! and the quadrics given in a local frame `p, i₁, i₂, i₃` when that frame is exactly
//! orthonormal (in doubles: a signed permutation of the coordinate axes). For any other
//! frame the surface's own normalisation is irrational, so they return `None` and the
//! caller certifies numerically. A cone given by its half-angle `α` (not `tan α`) has
//! an irrational implicit form and has no constructor here.

use std::cmp::Ordering;

use rug::Rational;

use super::exact::{dot, exact_vec, positive};
use crate::error::GeomError;

/// `F(x) = xᵀAx + 2bᵀx + c₀` in `D` dimensions (`D = 3`: quadric, `D = 2`: conic).
/// Invariants (kept by every constructor): `A` symmetric, not every coefficient zero.
#[derive(Debug, Clone, PartialEq)]
pub struct QuadricForm<const D: usize> {
    /// The symmetric matrix `A`.
    pub(crate) a: [[Rational; D]; D],
    /// The vector `b` (half the linear coefficients).
    pub(crate) b: [Rational; D],
    /// The constant `c₀`.
    pub(crate) c: Rational,
}

/// The plane conic `F(x, y) = 0`, as the 2D quadric form.
pub type Conic = QuadricForm<2>;

pub(crate) fn zero<const D: usize>() -> [Rational; D] {
    std::array::from_fn(|_| Rational::new())
}

impl<const D: usize> QuadricForm<D> {
    /// `F` from doubles taken exactly (`a` must be symmetric). Rejects NaN/∞ and the
    /// zero form (which vanishes everywhere).
    pub fn from_f64(a: [[f64; D]; D], b: [f64; D], c: f64) -> Result<Self, GeomError> {
        let mut am: [[Rational; D]; D] = std::array::from_fn(|_| zero());
        for (i, row) in a.iter().enumerate() {
            am[i] = exact_vec(&format!("a[{i}]"), row)?;
        }
        let b = exact_vec("b", &b)?;
        let c = crate::num::parse::rational_from_f64("c", c)?;
        QuadricForm::from_rationals(am, b, c)
    }

    /// `F` from exact rationals; `a` must be symmetric and not every coefficient zero.
    pub fn from_rationals(
        a: [[Rational; D]; D],
        b: [Rational; D],
        c: Rational,
    ) -> Result<Self, GeomError> {
        for (i, row) in a.iter().enumerate() {
            for (j, x) in row.iter().enumerate() {
                if *x != a[j][i] {
                    return Err(GeomError::InvalidValue {
                        field: format!("a[{i}][{j}]"),
                        reason: "the matrix of a quadric form must be symmetric".into(),
                    });
                }
            }
        }
        let q = QuadricForm { a, b, c };
        q.require_non_zero()?;
        Ok(q)
    }

    /// `F` from parts already known to be symmetric (a restriction to a plane may be the
    /// zero form: a plane lying in the quadric).
    pub(crate) fn from_parts(a: [[Rational; D]; D], b: [Rational; D], c: Rational) -> Self {
        QuadricForm { a, b, c }
    }

    /// The symmetric matrix `A`.
    pub fn matrix(&self) -> &[[Rational; D]; D] {
        &self.a
    }

    /// The vector `b` (half the linear coefficients).
    pub fn linear(&self) -> &[Rational; D] {
        &self.b
    }

    /// The constant `c₀`.
    pub fn constant(&self) -> &Rational {
        &self.c
    }

    pub(crate) fn require_non_zero(&self) -> Result<(), GeomError> {
        let nz = |x: &Rational| x.cmp0() != Ordering::Equal;
        if self.a.iter().flatten().any(nz) || self.b.iter().any(nz) || nz(&self.c) {
            Ok(())
        } else {
            Err(GeomError::InvalidValue {
                field: "quadric".into(),
                reason: "every coefficient is zero: the form vanishes everywhere".into(),
            })
        }
    }

    /// `F(x)`, exactly.
    pub fn eval(&self, x: &[Rational; D]) -> Rational {
        let ax = self.mul_a(x);
        dot(x, &ax) + dot(&self.b, x) * 2u32 + &self.c
    }

    /// `A·x`.
    pub(crate) fn mul_a(&self, x: &[Rational; D]) -> [Rational; D] {
        std::array::from_fn(|i| dot(&self.a[i], x))
    }

    /// `∇F(x)/2 = Ax + b`.
    pub fn half_gradient(&self, x: &[Rational; D]) -> [Rational; D] {
        let ax = self.mul_a(x);
        std::array::from_fn(|i| Rational::from(&ax[i] + &self.b[i]))
    }

    /// The form in coordinates `y = Mᵀ(x − p)` (`M` given by its columns): the exact
    /// pull-back of a form written in a local frame (for an orthonormal `M`, `x = p + My`;
    /// columns of any length scale the local coordinates, as
    /// [`QuadricForm::ellipsoid_in_frame`] uses).
    pub(crate) fn in_frame(
        local: &QuadricForm<D>,
        p: &[Rational; D],
        columns: &[[Rational; D]; D],
    ) -> Self {
        // y = Mᵀ(x − p) for an orthonormal M: F(x) = (x−p)ᵀ M A_l Mᵀ (x−p) + 2 b_lᵀ Mᵀ (x−p) + c_l.
        let m = |i: usize, k: usize| &columns[k][i];
        let mut a: [[Rational; D]; D] = std::array::from_fn(|_| zero());
        for (i, row) in a.iter_mut().enumerate() {
            for (j, aij) in row.iter_mut().enumerate() {
                for k in 0..D {
                    for l in 0..D {
                        *aij += Rational::from(m(i, k) * &local.a[k][l]) * m(j, l);
                    }
                }
            }
        }
        let bl: [Rational; D] = std::array::from_fn(|i| {
            let mut s = Rational::new();
            for k in 0..D {
                s += Rational::from(m(i, k) * &local.b[k]);
            }
            s
        });
        // Shift by p: F(x) = (x−p)ᵀA(x−p) + 2 blᵀ(x−p) + c_l.
        let ap: [Rational; D] = std::array::from_fn(|i| dot(&a[i], p));
        let b: [Rational; D] = std::array::from_fn(|i| Rational::from(&bl[i] - &ap[i]));
        let c = dot(p, &ap) - dot(&bl, p) * 2u32 + &local.c;
        QuadricForm { a, b, c }
    }
}

/// The exact columns of a frame when they are exactly orthonormal, else `None`.
fn orthonormal_frame<const D: usize>(
    frame: &[[f64; D]; D],
) -> Result<Option<[[Rational; D]; D]>, GeomError> {
    let mut cols: [[Rational; D]; D] = std::array::from_fn(|_| zero());
    for (k, c) in frame.iter().enumerate() {
        cols[k] = exact_vec(&format!("frame[{k}]"), c)?;
    }
    for i in 0..D {
        for j in 0..D {
            let want = if i == j { 1 } else { 0 };
            if dot(&cols[i], &cols[j]) != want {
                return Ok(None);
            }
        }
    }
    Ok(Some(cols))
}

/// A diagonal local form `Σ wᵢ yᵢ² + 2 Σ βᵢ yᵢ + γ`.
pub(crate) fn diagonal<const D: usize>(
    w: [Rational; D],
    beta: [Rational; D],
    gamma: Rational,
) -> QuadricForm<D> {
    let mut a: [[Rational; D]; D] = std::array::from_fn(|_| zero());
    for (i, wi) in w.into_iter().enumerate() {
        a[i][i] = wi;
    }
    QuadricForm {
        a,
        b: beta,
        c: gamma,
    }
}

pub(crate) fn inv_sq(field: &str, x: f64) -> Result<Rational, GeomError> {
    let q = positive(field, x)?;
    Ok(Rational::from(&q * &q).recip())
}

/// A local-frame form pulled back when the frame is exactly orthonormal.
pub(crate) fn framed<const D: usize>(
    origin: &[f64; D],
    frame: &[[f64; D]; D],
    local: QuadricForm<D>,
) -> Result<Option<QuadricForm<D>>, GeomError> {
    let p = exact_vec("origin", origin)?;
    Ok(orthonormal_frame(frame)?.map(|cols| QuadricForm::in_frame(&local, &p, &cols)))
}

impl QuadricForm<3> {
    /// The exact form of the implicit `quadric` of the case format (its matrix's doubles
    /// taken as rationals, §1.4); `None` only for a zero matrix, which
    /// [`crate::surface::implicit::ImplicitQuadric::new`] already refuses.
    pub fn of_implicit(q: &crate::surface::implicit::ImplicitQuadric) -> Option<Self> {
        let m = q.matrix();
        let a = std::array::from_fn(|i| std::array::from_fn(|j| m[i][j]));
        QuadricForm::from_f64(a, [m[0][3], m[1][3], m[2][3]], m[3][3]).ok()
    }

    /// The exact implicit form of a sphere or an ellipsoid of the model (its frame and
    /// radii taken exactly, §1.6); `None` for other surfaces or when the data give no
    /// exact form.
    pub fn of_surface(surface: &crate::surface::AnySurface) -> Option<Self> {
        use crate::surface::AnySurface;
        match surface {
            AnySurface::Sphere(s) => QuadricForm::sphere(s.frame().origin(), s.radius()).ok(),
            AnySurface::Ellipsoid(e) => {
                let f = e.frame();
                QuadricForm::ellipsoid_in_frame(f.origin(), f.axis(), f.reference(), e.semi_axes())
                    .ok()
            }
            _ => None,
        }
    }

    /// Sphere `|x − c|² − r² = 0` (§1.6), always exact.
    pub fn sphere(center: [f64; 3], radius: f64) -> Result<Self, GeomError> {
        let c = exact_vec("center", &center)?;
        let r = positive("radius", radius)?;
        Ok(QuadricForm::sphere_exact(&c, &r))
    }

    /// The sphere on exact data.
    pub(crate) fn sphere_exact(c: &[Rational; 3], r: &Rational) -> Self {
        let one = || Rational::from(1);
        let local = diagonal([one(), one(), one()], zero(), -Rational::from(r * r));
        QuadricForm::in_frame(&local, c, &identity())
    }

    /// Ellipsoid `x²/a² + y²/b² + z²/c² = 1` in the frame `origin, frame[0..3]` (§1.6).
    pub fn ellipsoid(
        origin: [f64; 3],
        frame: [[f64; 3]; 3],
        radii: [f64; 3],
    ) -> Result<Option<Self>, GeomError> {
        let w = [
            inv_sq("radii[0]", radii[0])?,
            inv_sq("radii[1]", radii[1])?,
            inv_sq("radii[2]", radii[2])?,
        ];
        framed(&origin, &frame, diagonal(w, zero(), Rational::from(-1)))
    }

    /// Ellipsoid `x²/a² + y²/b² + z²/c² = 1` in the docs/FORMAT.md frame of `axis` and `ref`
    /// at `origin`, for any axis (§1.6). The frame's unit vectors are irrational in
    /// general, but only their outer products divided by their squared lengths enter
    /// the form: with the unnormalised `X̃ = ref − (ref·Z̃/|Z̃|²) Z̃`, `Ỹ = Z̃ × X̃`, `Z̃ = axis`,
    /// `A = Σ ṽ ṽᵀ / (|ṽ|² r²)` is rational, so the form is exact.
    pub fn ellipsoid_in_frame(
        origin: [f64; 3],
        axis: [f64; 3],
        reference: Option<[f64; 3]>,
        radii: [f64; 3],
    ) -> Result<Self, GeomError> {
        let p = exact_vec("center", &origin)?;
        let z = exact_vec("axis", &axis)?;
        if z.iter().all(|v| v.cmp0() == std::cmp::Ordering::Equal) {
            return Err(GeomError::ZeroDirection {
                field: "axis".into(),
            });
        }
        let x = crate::ops::closed_surface::frame_x_unnormalised(&axis, reference.as_ref());
        if x.iter().all(|v| v.cmp0() == std::cmp::Ordering::Equal) {
            return Err(GeomError::InvalidValue {
                field: "ref".into(),
                reason: "ref is parallel to axis, so it gives no X direction".into(),
            });
        }
        let y: [Rational; 3] = std::array::from_fn(|i| {
            let (j, k) = ((i + 1) % 3, (i + 2) % 3);
            Rational::from(&z[j] * &x[k]) - Rational::from(&z[k] * &x[j])
        });
        let names = ["a", "b", "c"];
        let mut w: [Rational; 3] = std::array::from_fn(|_| Rational::new());
        for (k, v) in [&x, &y, &z].into_iter().enumerate() {
            w[k] = inv_sq(names[k], radii[k])? / dot(v, v);
        }
        let local = diagonal(w, zero(), Rational::from(-1));
        Ok(QuadricForm::in_frame(&local, &p, &[x, y, z]))
    }

    /// `Σ wₖ ξₖ² + 2β ζ + c₀ = 0` in the docs/FORMAT.md frame of `axis` and `ref` at
    /// `origin` (`ξ = (ξ, η, ζ)` the local coordinates; §1.6), for any axis: as in
    /// [`QuadricForm::ellipsoid_in_frame`] only `ṽṽᵀ/|ṽ|²` enters the quadratic part; the
    /// linear term `βζ = β(Z̃·q)/|Z̃|` is rational only when `|Z̃|` is, else `None`.
    pub(crate) fn diagonal_in_frame(
        origin: [f64; 3],
        axis: [f64; 3],
        reference: Option<[f64; 3]>,
        w: [Rational; 3],
        beta: Rational,
        c: Rational,
    ) -> Result<Option<Self>, GeomError> {
        let p = exact_vec("center", &origin)?;
        let z = exact_vec("axis", &axis)?;
        if z.iter().all(|v| v.cmp0() == Ordering::Equal) {
            return Err(GeomError::ZeroDirection {
                field: "axis".into(),
            });
        }
        let x = crate::ops::closed_surface::frame_x_unnormalised(&axis, reference.as_ref());
        if x.iter().all(|v| v.cmp0() == Ordering::Equal) {
            return Err(GeomError::InvalidValue {
                field: "ref".into(),
                reason: "ref is parallel to axis, so it gives no X direction".into(),
            });
        }
        let y: [Rational; 3] = std::array::from_fn(|i| {
            let (j, k) = ((i + 1) % 3, (i + 2) % 3);
            Rational::from(&z[j] * &x[k]) - Rational::from(&z[k] * &x[j])
        });
        let mut beta_local = zero::<3>();
        if beta.cmp0() != Ordering::Equal {
            let zz = dot(&z, &z);
            let (n, d) = (zz.numer(), zz.denom());
            if !(n.is_perfect_square() && d.is_perfect_square()) {
                return Ok(None);
            }
            let len = Rational::from((
                rug::Integer::from(n.sqrt_ref()),
                rug::Integer::from(d.sqrt_ref()),
            ));
            beta_local[2] = beta / len;
        }
        let mut wl: [Rational; 3] = std::array::from_fn(|_| Rational::new());
        for (k, v) in [&x, &y, &z].into_iter().enumerate() {
            wl[k] = &w[k] / dot(v, v);
        }
        let local = diagonal(wl, beta_local, c);
        Ok(Some(QuadricForm::in_frame(&local, &p, &[x, y, z])))
    }

    /// One-sheet hyperboloid `x²/a² + y²/b² − z²/c² = 1` (§1.6).
    pub fn hyperboloid_one_sheet(
        origin: [f64; 3],
        frame: [[f64; 3]; 3],
        radii: [f64; 3],
    ) -> Result<Option<Self>, GeomError> {
        let w = [
            inv_sq("radii[0]", radii[0])?,
            inv_sq("radii[1]", radii[1])?,
            -inv_sq("radii[2]", radii[2])?,
        ];
        framed(&origin, &frame, diagonal(w, zero(), Rational::from(-1)))
    }

    /// Two-sheet hyperboloid `x²/a² + y²/b² − z²/c² = −1` (§1.6).
    pub fn hyperboloid_two_sheets(
        origin: [f64; 3],
        frame: [[f64; 3]; 3],
        radii: [f64; 3],
    ) -> Result<Option<Self>, GeomError> {
        let w = [
            inv_sq("radii[0]", radii[0])?,
            inv_sq("radii[1]", radii[1])?,
            -inv_sq("radii[2]", radii[2])?,
        ];
        framed(&origin, &frame, diagonal(w, zero(), Rational::from(1)))
    }

    /// Elliptic paraboloid `x²/a² + y²/b² = z` (§1.6).
    pub fn elliptic_paraboloid(
        origin: [f64; 3],
        frame: [[f64; 3]; 3],
        a: f64,
        b: f64,
    ) -> Result<Option<Self>, GeomError> {
        let w = [inv_sq("a", a)?, inv_sq("b", b)?, Rational::new()];
        let beta = [Rational::new(), Rational::new(), Rational::from((-1, 2))];
        framed(&origin, &frame, diagonal(w, beta, Rational::new()))
    }

    /// Hyperbolic paraboloid `x²/a² − y²/b² = z` (§1.6).
    pub fn hyperbolic_paraboloid(
        origin: [f64; 3],
        frame: [[f64; 3]; 3],
        a: f64,
        b: f64,
    ) -> Result<Option<Self>, GeomError> {
        let w = [inv_sq("a", a)?, -inv_sq("b", b)?, Rational::new()];
        let beta = [Rational::new(), Rational::new(), Rational::from((-1, 2))];
        framed(&origin, &frame, diagonal(w, beta, Rational::new()))
    }

    /// Elliptic cylinder `x²/a² + y²/b² = 1` about the frame's third axis (§1.6).
    pub fn elliptic_cylinder(
        origin: [f64; 3],
        frame: [[f64; 3]; 3],
        a: f64,
        b: f64,
    ) -> Result<Option<Self>, GeomError> {
        let w = [inv_sq("a", a)?, inv_sq("b", b)?, Rational::new()];
        framed(&origin, &frame, diagonal(w, zero(), Rational::from(-1)))
    }

    /// Circular cylinder of radius `r` about the line `point + s·axis` (any non-zero
    /// axis): `|q|²|a|² − (q·a)² − r²|a|² = 0`, `q = x − point` (always exact).
    pub fn circular_cylinder(
        point: [f64; 3],
        axis: [f64; 3],
        radius: f64,
    ) -> Result<Self, GeomError> {
        let r = positive("radius", radius)?;
        let (p, a) = point_axis(point, axis)?;
        let aa = dot(&a, &a);
        let local = about_axis(&a, &aa, &Rational::new());
        let local = QuadricForm {
            c: -(Rational::from(&r * &r) * &aa),
            ..local
        };
        Ok(QuadricForm::in_frame(&local, &p, &identity()))
    }

    /// Circular double cone with apex `apex`, axis `axis` (any non-zero vector) and
    /// half-angle `α` given by `k = tan α`: `|q|²|a|² − (q·a)² − k²(q·a)² = 0`,
    /// `q = x − apex` (always exact; the apex is a singular point of the form).
    pub fn circular_cone(
        apex: [f64; 3],
        axis: [f64; 3],
        tan_half_angle: f64,
    ) -> Result<Self, GeomError> {
        let k = positive("tan_half_angle", tan_half_angle)?;
        let (p, a) = point_axis(apex, axis)?;
        let aa = dot(&a, &a);
        let local = about_axis(&a, &aa, &Rational::from(&k * &k));
        Ok(QuadricForm::in_frame(&local, &p, &identity()))
    }
}

pub(crate) fn identity<const D: usize>() -> [[Rational; D]; D] {
    std::array::from_fn(|i| std::array::from_fn(|j| Rational::from(u32::from(i == j))))
}

fn point_axis(
    point: [f64; 3],
    axis: [f64; 3],
) -> Result<([Rational; 3], [Rational; 3]), GeomError> {
    let p = exact_vec("point", &point)?;
    let a = exact_vec("axis", &axis)?;
    if a.iter().all(|x| x.cmp0() == Ordering::Equal) {
        return Err(GeomError::ZeroDirection {
            field: "axis".into(),
        });
    }
    Ok((p, a))
}

/// `|q|²|a|² − (1 + k2)(q·a)²` as a form in `q`: `A = |a|² I − (1 + k2) a aᵀ`.
fn about_axis(a: &[Rational; 3], aa: &Rational, k2: &Rational) -> QuadricForm<3> {
    let f = Rational::from(k2 + 1u32);
    QuadricForm {
        a: std::array::from_fn(|i| {
            std::array::from_fn(|j| {
                let mut v = Rational::from(&a[i] * &a[j]) * &f;
                v = -v;
                if i == j {
                    v += aa;
                }
                v
            })
        }),
        b: zero(),
        c: Rational::new(),
    }
}
