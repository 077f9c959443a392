//! Implicit surfaces (OPERATIONS.md §1.4): the quadric `[x 1]ᵀ Q [x 1] = 0` of a
//! symmetric 4×4 matrix (CASES `quadric`), and the implicit forms (§1.6, last column) of
//! the analytic surfaces, each vanishing exactly on the parametric surface.
//!
//! Side convention of §1.4: `F > 0` outside, `F < 0` inside (for a plane: `F > 0` on the
//! side of `a × b`). The analytic forms are written in local coordinates
//! `ℓ = ((x−o)·X, (x−o)·Y, (x−o)·Z)` and carried to the world by the chain rule
//! `∇F = Σ ∂_i F X_i`, `∇²F = R (∇²_ℓ F) Rᵀ` with `R = [X Y Z]`; the frame is evaluated
//! in the number type, so interval evaluation encloses the exact `F`, `∇F`, `∇²F`.

use super::frame::Frame;
use super::plane::{ParaboloidRect, Plane};
use super::quadrics::{Cone, Cylinder, Ellipsoid, Hyperboloid, Paraboloid, Sheets, Sphere};
use super::torus::Torus;
use super::{Implicit, ImplicitJet};
use crate::error::{require_finite, GeomError};
use crate::num::vector::{cross, dot, lift, sub};
use crate::num::Real;

/// Value, gradient and Hessian of a function of three variables.
type Full<T> = (T, [T; 3], [[T; 3]; 3]);

fn jet_of<T: Real>((value, gradient, hessian): Full<T>, order: usize) -> ImplicitJet<T, 3> {
    ImplicitJet {
        value,
        gradient: (order >= 1).then_some(gradient),
        hessian: (order >= 2).then_some(hessian),
    }
}

/// `F(x) = f(ℓ(x))` for a local function `f` (module doc: the chain rule).
fn in_frame<T: Real>(
    frame: &Frame,
    x: &[T; 3],
    order: usize,
    f: impl FnOnce(&[T; 3]) -> Full<T>,
) -> ImplicitJet<T, 3> {
    let (l, axes) = frame.to_local(x);
    let (value, g, h) = f(&l);
    let gradient = Frame::to_world_vector(&axes, &g);
    let zero = value.zero_like();
    let mut hessian: [[T; 3]; 3] = std::array::from_fn(|_| std::array::from_fn(|_| zero.clone()));
    if order >= 2 {
        // (R H Rᵀ)_ab = Σ_ij X_i[a] H_ij X_j[b]
        let rh: [[T; 3]; 3] = std::array::from_fn(|i| Frame::to_world_vector(&axes, &h[i]));
        for (a, row) in hessian.iter_mut().enumerate() {
            for (b, entry) in row.iter_mut().enumerate() {
                let mut s = zero.clone();
                for (i, rhi) in rh.iter().enumerate() {
                    s = s + axes[i][a].clone() * &rhi[b];
                }
                *entry = s;
            }
        }
    }
    jet_of((value, gradient, hessian), order)
}

/// `Σ c_i ℓ_i² + c_z·ℓ_z + c₀` with diagonal coefficients `c = (c_x, c_y, c_z2)`: the
/// central quadrics and paraboloids in local coordinates.
fn diagonal_quadric<T: Real>(l: &[T; 3], c: [T; 3], linear_z: T, constant: T) -> Full<T> {
    let two = l[0].lift(2.0);
    let zero = l[0].zero_like();
    let value = c[0].clone() * l[0].sqr()
        + c[1].clone() * l[1].sqr()
        + c[2].clone() * l[2].sqr()
        + linear_z.clone() * &l[2]
        + constant;
    let gradient = [
        two.clone() * &c[0] * &l[0],
        two.clone() * &c[1] * &l[1],
        two.clone() * &c[2] * &l[2] + linear_z,
    ];
    let d: [T; 3] = std::array::from_fn(|i| two.clone() * &c[i]);
    let hessian = std::array::from_fn(|i| {
        std::array::from_fn(|j| if i == j { d[i].clone() } else { zero.clone() })
    });
    (value, gradient, hessian)
}

/// `x²/a² + σ y²/b² + c_z·z + c₀` (`σ = ±1`): the paraboloids and the elliptic
/// cylinder in local coordinates.
fn elliptic<T: Real>(
    l: &[T; 3],
    [a, b]: [f64; 2],
    sigma: f64,
    linear_z: f64,
    constant: f64,
) -> Full<T> {
    let k = [
        inv_sq(&l[0], a, 1.0),
        inv_sq(&l[0], b, sigma),
        l[0].zero_like(),
    ];
    diagonal_quadric(l, k, l[0].lift(linear_z), l[0].lift(constant))
}

/// `±1/s²` in the number type.
fn inv_sq<T: Real>(like: &T, s: f64, sign: f64) -> T {
    like.lift(sign) / like.lift(s).sqr()
}

impl Implicit<3> for Sphere {
    /// `|ℓ|² − r²`.
    fn implicit_jet<T: Real>(&self, x: &[T; 3], order: usize) -> ImplicitJet<T, 3> {
        in_frame(&self.frame, x, order, |l| {
            let one = l[0].one_like();
            let r2 = l[0].lift(self.radius).sqr();
            diagonal_quadric(l, [one.clone(), one.clone(), one], l[0].zero_like(), -r2)
        })
    }
}

impl Implicit<3> for Ellipsoid {
    /// `x²/a² + y²/b² + z²/c² − 1`.
    fn implicit_jet<T: Real>(&self, x: &[T; 3], order: usize) -> ImplicitJet<T, 3> {
        in_frame(&self.frame, x, order, |l| {
            let c = self.abc.map(|s| inv_sq(&l[0], s, 1.0));
            diagonal_quadric(l, c, l[0].zero_like(), l[0].lift(-1.0))
        })
    }
}

impl Implicit<3> for Hyperboloid {
    /// `x²/a² + y²/b² − z²/c² ∓ 1` (− for one sheet, + for two sheets).
    fn implicit_jet<T: Real>(&self, x: &[T; 3], order: usize) -> ImplicitJet<T, 3> {
        in_frame(&self.frame, x, order, |l| {
            let [a, b, c] = self.abc;
            let k = [
                inv_sq(&l[0], a, 1.0),
                inv_sq(&l[0], b, 1.0),
                inv_sq(&l[0], c, -1.0),
            ];
            let constant = match self.sheets {
                Sheets::One => -1.0,
                Sheets::Two => 1.0,
            };
            diagonal_quadric(l, k, l[0].zero_like(), l[0].lift(constant))
        })
    }
}

impl Implicit<3> for Paraboloid {
    /// `x²/a² + y²/b² − z`.
    fn implicit_jet<T: Real>(&self, x: &[T; 3], order: usize) -> ImplicitJet<T, 3> {
        in_frame(&self.frame, x, order, |l| {
            elliptic(l, self.ab, 1.0, -1.0, 0.0)
        })
    }
}

impl Implicit<3> for ParaboloidRect {
    /// `x²/a² + σ y²/b² − z`.
    fn implicit_jet<T: Real>(&self, x: &[T; 3], order: usize) -> ImplicitJet<T, 3> {
        in_frame(&self.frame, x, order, |l| {
            elliptic(l, self.ab, self.sign, -1.0, 0.0)
        })
    }
}

impl Implicit<3> for Cylinder {
    /// `x²/a² + y²/b² − 1`.
    fn implicit_jet<T: Real>(&self, x: &[T; 3], order: usize) -> ImplicitJet<T, 3> {
        in_frame(&self.frame, x, order, |l| {
            elliptic(l, self.ab, 1.0, 0.0, -1.0)
        })
    }
}

impl Implicit<3> for Cone {
    /// `x² + y² − (r + z tan α)²` (both nappes).
    fn implicit_jet<T: Real>(&self, x: &[T; 3], order: usize) -> ImplicitJet<T, 3> {
        in_frame(&self.frame, x, order, |l| {
            let t = l[0].lift(self.half_angle).tan();
            let r = l[0].lift(self.radius);
            let one = l[0].one_like();
            // −(r + z t)² = −t² z² − 2 r t z − r²
            let two = l[0].lift(2.0);
            let linear = -(two * &r * &t);
            diagonal_quadric(l, [one.clone(), one, -t.sqr()], linear, -r.sqr())
        })
    }
}

impl Implicit<3> for Torus {
    /// `(|ℓ|² + R² − r²)² − 4R²(x² + y²)`.
    fn implicit_jet<T: Real>(&self, x: &[T; 3], order: usize) -> ImplicitJet<T, 3> {
        in_frame(&self.frame, x, order, |l| {
            let lift = |v: f64| l[0].lift(v);
            let big2 = lift(self.major).sqr();
            let q = l[0].sqr() + l[1].sqr() + l[2].sqr() + &big2 - lift(self.minor).sqr();
            let (four, eight) = (lift(4.0), lift(8.0));
            let xy = l[0].sqr() + l[1].sqr();
            let value = q.sqr() - four.clone() * &big2 * xy;
            let radial = four.clone() * (q.clone() - lift(2.0) * &big2);
            let gradient = [
                radial.clone() * &l[0],
                radial.clone() * &l[1],
                four.clone() * &q * &l[2],
            ];
            let diag = [radial.clone(), radial, four * q];
            let hessian = std::array::from_fn(|i| {
                std::array::from_fn(|j| {
                    let cross = eight.clone() * &l[i] * &l[j];
                    if i == j {
                        diag[i].clone() + cross
                    } else {
                        cross
                    }
                })
            });
            (value, gradient, hessian)
        })
    }
}

impl Implicit<3> for Plane {
    /// `(x − p)·(a × b)`, with `p` the origin box for enclosures
    /// ([`Plane::through_box`]).
    fn implicit_jet<T: Real>(&self, x: &[T; 3], order: usize) -> ImplicitJet<T, 3> {
        let n = cross(&lift(&x[0], &self.a), &lift(&x[0], &self.b));
        let value = dot(&sub(x, &self.origin_in(&x[0])), &n);
        let zero = x[0].zero_like();
        let hessian = std::array::from_fn(|_| std::array::from_fn(|_| zero.clone()));
        jet_of((value, n, hessian), order)
    }
}

/// The plane `F(x) = n·x + d` (§1.4) of the linear kernel's implicit form, its double
/// `normal` and `d` taken as they are: every constant enters the formula exactly, so
/// an interval evaluation encloses the exact `F` of the plane the user gave. (A
/// parametric [`Plane`] built from it needs a point on it, and `−d/n_k` is rarely a
/// double: it is then enclosed by a box, [`Plane::through_box`], which a near-tangency
/// within an ulp of the plane cannot resolve.)
#[derive(Debug, Clone, PartialEq)]
pub struct ImplicitPlane {
    pub(crate) normal: [f64; 3],
    pub(crate) d: f64,
}

impl ImplicitPlane {
    /// Errors name `normal` (non-finite or zero) and `d` (non-finite).
    pub fn new(normal: [f64; 3], d: f64) -> Result<ImplicitPlane, GeomError> {
        for (i, &c) in normal.iter().enumerate() {
            require_finite(&format!("normal[{i}]"), c)?;
        }
        require_finite("d", d)?;
        if normal.iter().all(|&c| c == 0.0) {
            return Err(GeomError::InvalidValue {
                field: "normal".into(),
                reason: "the normal is the zero vector".into(),
            });
        }
        Ok(ImplicitPlane { normal, d })
    }
}

impl Implicit<3> for ImplicitPlane {
    /// `n·x + d`, gradient `n`, Hessian 0.
    fn implicit_jet<T: Real>(&self, x: &[T; 3], order: usize) -> ImplicitJet<T, 3> {
        let n = lift(&x[0], &self.normal);
        let value = dot(x, &n) + x[0].lift(self.d);
        let zero = x[0].zero_like();
        let hessian = std::array::from_fn(|_| std::array::from_fn(|_| zero.clone()));
        jet_of((value, n, hessian), order)
    }
}

/// The quadric `F(x) = [x 1]ᵀ Q [x 1] = xᵀA x + 2bᵀx + c₀` (§1.4) of a symmetric 4×4
/// matrix `Q = [[A, b], [bᵀ, c₀]]`.
#[derive(Debug, Clone, PartialEq)]
pub struct ImplicitQuadric {
    pub(crate) matrix: [[f64; 4]; 4],
}

impl ImplicitQuadric {
    /// Errors name `matrix[i][j]`: non-finite entries, an entry that differs from its
    /// mirror (`matrix[j][i]`), or a zero matrix.
    pub fn new(matrix: [[f64; 4]; 4]) -> Result<ImplicitQuadric, GeomError> {
        for (i, row) in matrix.iter().enumerate() {
            for (j, &m) in row.iter().enumerate() {
                require_finite(&format!("matrix[{i}][{j}]"), m)?;
                if j > i && m != matrix[j][i] {
                    return Err(GeomError::InvalidValue {
                        field: format!("matrix[{i}][{j}]"),
                        reason: format!("the matrix is not symmetric: {m} ≠ {}", matrix[j][i]),
                    });
                }
            }
        }
        if matrix.iter().flatten().all(|&m| m == 0.0) {
            return Err(GeomError::InvalidValue {
                field: "matrix".into(),
                reason: "the zero matrix defines no surface".into(),
            });
        }
        Ok(ImplicitQuadric { matrix })
    }

    pub fn matrix(&self) -> [[f64; 4]; 4] {
        self.matrix
    }
}

impl Implicit<3> for ImplicitQuadric {
    /// `F = xᵀAx + 2bᵀx + c₀`, `∇F = 2(Ax + b)`, `∇²F = 2A`.
    fn implicit_jet<T: Real>(&self, x: &[T; 3], order: usize) -> ImplicitJet<T, 3> {
        let m = |i: usize, j: usize| x[0].lift(self.matrix[i][j]);
        let two = x[0].lift(2.0);
        // Ax + b
        let axb: [T; 3] =
            std::array::from_fn(|i| m(i, 0) * &x[0] + m(i, 1) * &x[1] + m(i, 2) * &x[2] + m(i, 3));
        // xᵀ(Ax + b) + bᵀx + c₀
        let value = dot(x, &axb) + m(3, 0) * &x[0] + m(3, 1) * &x[1] + m(3, 2) * &x[2] + m(3, 3);
        let gradient = axb.map(|g| two.clone() * g);
        let hessian = std::array::from_fn(|i| std::array::from_fn(|j| two.clone() * m(i, j)));
        jet_of((value, gradient, hessian), order)
    }
}
