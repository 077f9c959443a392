//! The exact implicit quadric of a surface of the model, for sections (OPERATIONS.md
//! §1.6 with §13.2), through [`QuadricForm`]: sphere, ellipsoid, hyperboloids of one
//! and two sheets, circular and elliptic cylinders (any axis and `ref`), and the
//! elliptic and hyperbolic paraboloids when `|axis|` is rational (their linear term
//! is the local `z`, `(axis·q)/|axis|`). A `cone` of the case format is given by its
//! half-angle, whose tangent is irrational for every double `α ≠ 0`: it has no exact
//! form (give it as a `quadric`). Tori and free-form surfaces are not quadrics.
//!
//! The form is the whole quadric: the surface's `domain`, `height` or `range` trims it,
//! which [`is_whole`] tells.

use rug::Rational;

use crate::ops::closed_surface::is_closed_shell;
use crate::ops::rational::QuadricForm;
use crate::surface::quadrics::Sheets;
use crate::surface::AnySurface;

fn inv_sq(x: f64) -> Option<Rational> {
    let q = Rational::from_f64(x)?;
    (q.cmp0() == std::cmp::Ordering::Greater).then(|| Rational::from(&q * &q).recip())
}

/// The exact implicit form of a quadric surface of the model; `None` when the
/// surface is not a quadric or its implicit form is not rational (module doc).
pub fn quadric_of_surface(surface: &AnySurface) -> Option<QuadricForm<3>> {
    let one = || Rational::from(1);
    let zero = Rational::new;
    let framed = |f: &crate::surface::frame::Frame, w: [Rational; 3], beta, c| {
        QuadricForm::diagonal_in_frame(f.origin(), f.axis(), f.reference(), w, beta, c)
            .ok()
            .flatten()
    };
    match surface {
        AnySurface::Sphere(_) | AnySurface::Ellipsoid(_) => QuadricForm::of_surface(surface),
        AnySurface::Hyperboloid(h) => {
            let [a, b, c] = h.semi_axes();
            let w = [inv_sq(a)?, inv_sq(b)?, -inv_sq(c)?];
            let c0 = match h.sheets() {
                Sheets::One => -one(),
                Sheets::Two => one(),
            };
            framed(h.frame(), w, zero(), c0)
        }
        AnySurface::Cylinder(c) => {
            let [a, b] = c.semi_axes();
            framed(c.frame(), [inv_sq(a)?, inv_sq(b)?, zero()], zero(), -one())
        }
        AnySurface::Paraboloid(p) => {
            let [a, b] = p.semi_axes();
            let half = Rational::from((-1, 2));
            framed(p.frame(), [inv_sq(a)?, inv_sq(b)?, zero()], half, zero())
        }
        AnySurface::ParaboloidRect(p) => {
            let [a, b] = p.semi_axes();
            let wb = if p.is_hyperbolic() {
                -inv_sq(b)?
            } else {
                inv_sq(b)?
            };
            let half = Rational::from((-1, 2));
            framed(p.frame(), [inv_sq(a)?, wb, zero()], half, zero())
        }
        _ => None,
    }
}

/// Whether the surface is its whole quadric (a sphere or ellipsoid on its natural
/// domain); every other quadric surface of the model is trimmed by a height, range or
/// domain.
pub fn is_whole(surface: &AnySurface) -> bool {
    matches!(surface, AnySurface::Sphere(_) | AnySurface::Ellipsoid(_)) && is_closed_shell(surface)
}
