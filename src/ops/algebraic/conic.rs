//! Exact plane conics (OPERATIONS.md §1.7 eq. (1.19)): the general implicit conic and
//! the conics of §1.5 whose implicit form is rational from double data (circles about
//! any centre; ellipses, hyperbolas and parabolas in exactly orthonormal frames).

use rug::Rational;

use crate::error::GeomError;
use crate::ops::rational::exact::{exact_vec, positive};
use crate::ops::rational::{diagonal, framed, identity, inv_sq, zero, QuadricForm};

impl QuadricForm<2> {
    /// The conic `a x² + b xy + c y² + d x + e y + f = 0` (§1.7 with `a₁₂ = b/2`,
    /// `a₁₃ = d/2`, `a₂₃ = e/2`), coefficients taken exactly; not all zero.
    pub fn conic(coefficients: [f64; 6]) -> Result<Self, GeomError> {
        Self::conic_exact(exact_vec("conic", &coefficients)?)
    }

    /// [`QuadricForm::conic`] from exact rational coefficients; not all zero.
    pub fn conic_exact(coefficients: [Rational; 6]) -> Result<Self, GeomError> {
        let [a, b, c, d, e, f] = coefficients;
        let half = |x: Rational| x / 2u32;
        let q = QuadricForm {
            a: [[a, half(b.clone())], [half(b), c]],
            b: [half(d), half(e)],
            c: f,
        };
        q.require_non_zero()?;
        Ok(q)
    }

    /// Circle `|x − c|² = r²`, always exact.
    pub fn circle(center: [f64; 2], radius: f64) -> Result<Self, GeomError> {
        let c = exact_vec("center", &center)?;
        let r = positive("radius", radius)?;
        let local = diagonal(
            [Rational::from(1), Rational::from(1)],
            zero(),
            -Rational::from(&r * &r),
        );
        Ok(QuadricForm::in_frame(&local, &c, &identity()))
    }

    /// Ellipse `x²/a² + y²/b² = 1` in the frame `center, frame[0], frame[1]`; `None`
    /// unless the frame is exactly orthonormal (axis-aligned).
    pub fn ellipse(
        center: [f64; 2],
        frame: [[f64; 2]; 2],
        a: f64,
        b: f64,
    ) -> Result<Option<Self>, GeomError> {
        let w = [inv_sq("a", a)?, inv_sq("b", b)?];
        framed(&center, &frame, diagonal(w, zero(), Rational::from(-1)))
    }

    /// Hyperbola `x²/a² − y²/b² = 1` in an exactly orthonormal frame, else `None`.
    pub fn hyperbola(
        center: [f64; 2],
        frame: [[f64; 2]; 2],
        a: f64,
        b: f64,
    ) -> Result<Option<Self>, GeomError> {
        let w = [inv_sq("a", a)?, -inv_sq("b", b)?];
        framed(&center, &frame, diagonal(w, zero(), Rational::from(-1)))
    }

    /// Parabola `y² = 2f x` (§1.5, focal parameter `f`) in an exactly orthonormal frame,
    /// else `None`.
    pub fn parabola(
        vertex: [f64; 2],
        frame: [[f64; 2]; 2],
        focal: f64,
    ) -> Result<Option<Self>, GeomError> {
        let f = positive("focal", focal)?;
        let local = diagonal(
            [Rational::new(), Rational::from(1)],
            [-f, Rational::new()],
            Rational::new(),
        );
        framed(&vertex, &frame, local)
    }

    /// The coefficients `(a, b, c, d, e, f)` of `a x² + b xy + c y² + d x + e y + f`.
    pub fn coefficients(&self) -> [Rational; 6] {
        [
            self.a[0][0].clone(),
            Rational::from(&self.a[0][1] * 2u32),
            self.a[1][1].clone(),
            Rational::from(&self.b[0] * 2u32),
            Rational::from(&self.b[1] * 2u32),
            self.c.clone(),
        ]
    }
}
