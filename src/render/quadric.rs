//! The implicit `quadric` `[x 1]ᵀ Q [x 1] = 0` in pictures (a drawing, no proof).
//!
//! With `F = xᵀAx + 2bᵀx + c`:
//!
//! * an **ellipsoid** (`A` definite, `κ = bᵀA⁻¹b − c` of the sign of `A`, so that
//!   `F = (x − x₀)ᵀA(x − x₀) − κ` with `x₀ = −A⁻¹b`) is drawn as the named ellipsoid with
//!   the eigenvectors of `A` as axes and semi-axes `√(κ/λᵢ)` ([`as_ellipsoid`]): net,
//!   contour and occluding triangles as for any parametric surface;
//! * **any other** quadric (unbounded, or a cone, a pair of planes) is drawn inside the
//!   picture's window by its sections ([`sections`]): `net[0]` planes across the window
//!   normal to `z`, `net[1]` normal to `x`, each section the zero set of `F` on the
//!   plane found by marching squares ([`super::contour::zero_polylines`]); and its
//!   contour (§13.5), which for a quadric is a plane section too — the points where
//!   `∇F·w = 0` on `F = 0` lie on the plane `(Ax + b)·d = 0` for a parallel view with
//!   view vector `d`, and on the polar plane `[E 1]ᵀ Q [x 1] = 0` of the eye `E` for a
//!   central view (on `F = 0`, `(E − x)·(Ax + b) = [E 1]ᵀ Q [x 1]`). Such a quadric
//!   occludes nothing (it has no triangles).

use super::contour::zero_polylines;
use crate::ops::view::{Rays, View};
use crate::surface::implicit::ImplicitQuadric;
use crate::surface::quadrics::Ellipsoid;

fn dot(a: &[f64; 3], b: &[f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn parts(q: &ImplicitQuadric) -> ([[f64; 3]; 3], [f64; 3], f64) {
    let m = q.matrix();
    let a = std::array::from_fn(|i| std::array::from_fn(|j| m[i][j]));
    (a, std::array::from_fn(|i| m[i][3]), m[3][3])
}

/// The eigenvalues and unit eigenvectors (columns `v[·][k]`) of a symmetric 3×3 matrix,
/// by cyclic Jacobi rotations (converges for every symmetric matrix).
fn eigen(mut a: [[f64; 3]; 3]) -> ([f64; 3], [[f64; 3]; 3]) {
    let mut v = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    for _ in 0..64 {
        let off = a[0][1].abs() + a[0][2].abs() + a[1][2].abs();
        let scale = a[0][0].abs() + a[1][1].abs() + a[2][2].abs() + off;
        if off <= 1e-15 * scale {
            break;
        }
        for (p, r) in [(0, 1), (0, 2), (1, 2)] {
            if a[p][r] == 0.0 {
                continue;
            }
            let theta = (a[r][r] - a[p][p]) / (2.0 * a[p][r]);
            let t = theta.signum() / (theta.abs() + (theta * theta + 1.0).sqrt());
            let t = if theta == 0.0 { 1.0 } else { t };
            let (c, s) = (1.0 / (t * t + 1.0).sqrt(), t / (t * t + 1.0).sqrt());
            // A ← Jᵀ A J with the rotation J in the (p, r) plane; V ← V J.
            for row in &mut a {
                let (akp, akr) = (row[p], row[r]);
                row[p] = c * akp - s * akr;
                row[r] = s * akp + c * akr;
            }
            let (row_p, row_r) = (a[p], a[r]);
            for k in 0..3 {
                a[p][k] = c * row_p[k] - s * row_r[k];
                a[r][k] = s * row_p[k] + c * row_r[k];
            }
            for row in &mut v {
                let (vp, vr) = (row[p], row[r]);
                row[p] = c * vp - s * vr;
                row[r] = s * vp + c * vr;
            }
        }
    }
    ([a[0][0], a[1][1], a[2][2]], v)
}

/// The quadric as a named ellipsoid when it is one (module doc); `None` otherwise
/// (including an ellipsoid too flat for the float eigenvalues to tell).
pub fn as_ellipsoid(q: &ImplicitQuadric) -> Option<Ellipsoid> {
    let (a, b, c) = parts(q);
    let (l, v) = eigen(a);
    let sign = l[0].signum();
    let biggest = l.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    if l.iter()
        .any(|&x| x.signum() != sign || x.abs() <= 1e-12 * biggest)
    {
        return None;
    }
    // x₀ = −A⁻¹b and κ = −F(x₀) = bᵀA⁻¹b − c, in the eigenbasis.
    let col = |k: usize| [v[0][k], v[1][k], v[2][k]];
    let mut x0 = [0.0; 3];
    let mut kappa = -c;
    for (k, lk) in l.iter().enumerate() {
        let e = col(k);
        let w = dot(&e, &b) / lk;
        kappa += w * dot(&e, &b);
        for (x, ek) in x0.iter_mut().zip(e) {
            *x -= w * ek;
        }
    }
    if kappa * sign <= 0.0 {
        return None; // a point or no real surface
    }
    let axes = l.map(|x| (kappa / x).sqrt());
    Ellipsoid::new(x0, axes, Some(col(2)), Some(col(0))).ok()
}

/// A plane `origin + s·u + t·v` (`u`, `v` orthonormal) and the half-size of its square.
pub struct SectionPlane {
    pub origin: [f64; 3],
    pub u: [f64; 3],
    pub v: [f64; 3],
    pub half: f64,
}

/// The zero set of `F` on the square of `plane`, `grid` cells per side, as 3D polylines.
pub fn section(q: &ImplicitQuadric, plane: &SectionPlane, grid: usize) -> Polylines {
    use crate::surface::Implicit;
    let at = |i: f64, j: f64| {
        let (s, t) = (
            plane.half * (2.0 * i / grid as f64 - 1.0),
            plane.half * (2.0 * j / grid as f64 - 1.0),
        );
        std::array::from_fn(|k| plane.origin[k] + s * plane.u[k] + t * plane.v[k])
    };
    zero_polylines(grid, grid, |i, j| {
        q.implicit_jet(&at(i as f64, j as f64), 0).value
    })
    .into_iter()
    .map(|pl| pl.iter().map(|&[i, j]| at(i, j)).collect())
    .collect()
}

/// Polylines in space.
pub type Polylines = Vec<Vec<[f64; 3]>>;

/// The sections of the net (`levels[0]` planes normal to `z`, `levels[1]` normal to
/// `x`, spread across the ball of `radius` about `centre`) and the contour plane's
/// section in `view` (module doc), `grid` cells per side each.
pub fn sections(
    q: &ImplicitQuadric,
    view: &View,
    centre: [f64; 3],
    radius: f64,
    levels: [usize; 2],
    grid: usize,
) -> (Polylines, Polylines) {
    let mut net = Vec::new();
    for (axis, count, u, v) in [
        (2, levels[0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]),
        (0, levels[1], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]),
    ] {
        let count = count.max(1);
        for i in 0..count {
            let mut origin = centre;
            origin[axis] += radius * (2.0 * (i as f64 + 0.5) / count as f64 - 1.0);
            let plane = SectionPlane {
                origin,
                u,
                v,
                half: radius,
            };
            net.extend(section(q, &plane, grid));
        }
    }
    let contour = contour_plane(q, view, centre, radius)
        .map(|p| section(q, &p, 2 * grid))
        .unwrap_or_default();
    (net, contour)
}

/// The plane of the contour (module doc) as a square about the foot of `centre`;
/// `None` when the plane degenerates (a cylinder seen along its axis: `A d = 0`).
fn contour_plane(
    q: &ImplicitQuadric,
    view: &View,
    centre: [f64; 3],
    radius: f64,
) -> Option<SectionPlane> {
    let (a, b, c) = parts(q);
    let times = |x: &[f64; 3]| std::array::from_fn::<f64, 3, _>(|i| dot(&a[i], x));
    let (n, k) = match view.rays {
        Rays::Parallel(d) => (times(&d), dot(&b, &d)),
        Rays::Central(e) => {
            let ae = times(&e);
            (std::array::from_fn(|i| ae[i] + b[i]), dot(&b, &e) + c)
        }
    };
    let nn = dot(&n, &n);
    let size = a.iter().flatten().fold(0.0f64, |m, x| m.max(x.abs()));
    if nn.is_nan() || nn <= (1e-12 * size).powi(2) || !nn.is_finite() {
        return None;
    }
    let (u, v) = plane_axes(n);
    let h = (dot(&n, &centre) + k) / nn;
    Some(SectionPlane {
        origin: std::array::from_fn(|i| centre[i] - h * n[i]),
        u,
        v,
        half: radius,
    })
}

/// An orthonormal pair spanning the plane with this normal.
pub(super) fn plane_axes(n: [f64; 3]) -> ([f64; 3], [f64; 3]) {
    let k = (0..3)
        .min_by(|&a, &b| n[a].abs().total_cmp(&n[b].abs()))
        .unwrap_or(0);
    let mut e = [0.0; 3];
    e[k] = 1.0;
    let u = crate::num::vector::cross(&n, &e);
    let v = crate::num::vector::cross(&n, &u);
    let unit = |a: [f64; 3]| {
        let l = crate::num::vector::dot(&a, &a).sqrt();
        a.map(|c| c / l)
    };
    (unit(u), unit(v))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_rotated_ellipsoid_is_recognised_with_its_axes() {
        // x²/4 + y² + (z − 1)²/9 = 1 after swapping x and y: A = diag(1, 1/4, 1/9).
        let q = ImplicitQuadric::new([
            [1.0, 0.0, 0.0, 0.0],
            [0.0, 0.25, 0.0, 0.0],
            [0.0, 0.0, 1.0 / 9.0, -1.0 / 9.0],
            [0.0, 0.0, -1.0 / 9.0, 1.0 / 9.0 - 1.0],
        ])
        .expect("valid");
        let e = as_ellipsoid(&q).expect("an ellipsoid");
        let mut axes = e.semi_axes();
        axes.sort_by(f64::total_cmp);
        for (x, want) in axes.iter().zip([1.0, 2.0, 3.0]) {
            assert!((x - want).abs() < 1e-12, "{axes:?}");
        }
        // A hyperboloid is not one.
        let h = ImplicitQuadric::new([
            [1.0, 0.0, 0.0, 0.0],
            [0.0, 1.0, 0.0, 0.0],
            [0.0, 0.0, -1.0, 0.0],
            [0.0, 0.0, 0.0, -1.0],
        ])
        .expect("valid");
        assert!(as_ellipsoid(&h).is_none());
    }
}
