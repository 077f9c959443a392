//! Rational forms of circles and ellipses, and their truths in MPFR (issue 21,
//! family 3).
//!
//! An ellipse `c + A cos θ + B sin θ` (any two independent vectors `A`, `B`, in the
//! plane or in space) is the affine image of the unit circle, and an affine map keeps
//! a NURBS's weights: with the quarter circle `((1 − s²)/(1 + s²), 2s/(1 + s²))`,
//! `s ∈ [0, 1]` — the rational quadratic Bézier over `(1,0), (1,1), (0,1)` with
//! weights `(1, 1, 2)` — four quarters (weights scaled by `2^k` so that they join)
//! make the full ellipse as a NURBS of degree 2 with double knots at `0, 1, 2, 3`
//! (the angles `kπ/2`) and the net `c + aA + bB`, `(a, b)` the offsets below. Every
//! weight and control point is dyadic, so the input is exact.
//!
//! The parameter of a point is the inverse of that map (`s = y'/(1 + x')` in the
//! quadrant the point lies in), never geocert's.

use super::BITS;
use rug::Float;

/// The net of the unit circle, `(cos, sin)` coefficients, quadrant by quadrant.
pub const OFFSETS: [(f64, f64); 9] = [
    (1.0, 0.0),
    (1.0, 1.0),
    (0.0, 1.0),
    (-1.0, 1.0),
    (-1.0, 0.0),
    (-1.0, -1.0),
    (0.0, -1.0),
    (1.0, -1.0),
    (1.0, 0.0),
];

/// The weights of the full-circle net.
pub const WEIGHTS: [f64; 9] = [1.0, 1.0, 2.0, 2.0, 4.0, 4.0, 8.0, 8.0, 16.0];

/// The knots of the full-circle NURBS: the quadrants meet at `t = 1, 2, 3`.
pub const KNOTS: [f64; 12] = [0.0, 0.0, 0.0, 1.0, 1.0, 2.0, 2.0, 3.0, 3.0, 4.0, 4.0, 4.0];

/// Dyadic data from the project's generator: `k/2^bits` with `lo ≤ k/2^bits ≤ hi`.
pub struct Gen(pub geocert::num::rng::Rng);

impl Gen {
    pub fn new(seed: u64) -> Self {
        Gen(geocert::num::rng::Rng::new(seed))
    }
    pub fn dyadic(&mut self, lo: f64, hi: f64, bits: i32) -> f64 {
        let scale = 2f64.powi(bits);
        let k = self
            .0
            .int((lo * scale).ceil() as i64, (hi * scale).floor() as i64);
        k as f64 / scale
    }
    pub fn below(&mut self, n: usize) -> usize {
        self.0.below(n)
    }
    pub fn vec<const N: usize>(&mut self, lo: f64, hi: f64, bits: i32) -> [f64; N] {
        std::array::from_fn(|_| self.dyadic(lo, hi, bits))
    }
}

/// Huge and tiny scales: exact powers of two, 2^±500 (about 1e±150) and 2^±300.
pub fn magnitude(k: usize) -> f64 {
    2f64.powi([-500, 500, -300, 300][k % 4])
}

/// An ellipse `c + A cos θ + B sin θ` with dyadic data.
#[derive(Clone, Debug)]
pub struct Ellipse<const N: usize> {
    pub c: [f64; N],
    pub a: [f64; N],
    pub b: [f64; N],
}

impl<const N: usize> Ellipse<N> {
    /// The control point `c + p·A + q·B` (exact for the dyadic data used).
    pub fn net_point(&self, p: f64, q: f64) -> [f64; N] {
        std::array::from_fn(|i| self.c[i] + p * self.a[i] + q * self.b[i])
    }

    /// The whole ellipse scaled by `m` (an exact power of two).
    pub fn scaled(&self, m: f64) -> Self {
        Ellipse {
            c: self.c.map(|x| x * m),
            a: self.a.map(|x| x * m),
            b: self.b.map(|x| x * m),
        }
    }

    /// The full ellipse as a NURBS (`nurbs_curve2` in the plane, `nurbs_curve` in space).
    pub fn nurbs(&self) -> String {
        let ty = if N == 2 {
            "nurbs_curve2"
        } else {
            "nurbs_curve"
        };
        let pts: Vec<String> = OFFSETS
            .iter()
            .map(|&(p, q)| super::nums(&self.net_point(p, q)))
            .collect();
        format!(
            r#"{{"type":"{ty}","degree":2,"knots":{},"points":[{}],"weights":{}}}"#,
            super::nums(&KNOTS),
            pts.join(","),
            super::nums(&WEIGHTS)
        )
    }

    /// The quarter `θ ∈ [0, π/2]` as a rational quadratic Bézier (`bezier2`/`bezier`).
    pub fn quarter(&self) -> String {
        let ty = if N == 2 { "bezier2" } else { "bezier" };
        let pts: Vec<String> = OFFSETS[..3]
            .iter()
            .map(|&(p, q)| super::nums(&self.net_point(p, q)))
            .collect();
        format!(
            r#"{{"type":"{ty}","points":[{}],"weights":[1,1,2]}}"#,
            pts.join(",")
        )
    }

    /// The point at `(cos θ, sin θ) = (x, y)`, in MPFR.
    pub fn at(&self, x: &Float, y: &Float) -> Vec<Float> {
        (0..N)
            .map(|i| {
                Float::with_val(BITS, x * self.a[i])
                    + Float::with_val(BITS, y * self.b[i])
                    + self.c[i]
            })
            .collect()
    }
}

/// The NURBS parameter `t ∈ [0, 4]` of `(cos θ, sin θ) = (x, y)` (module docs): in the
/// quadrant `k` (the point turned back by `kπ/2` has both coordinates ≥ 0),
/// `t = k + y'/(1 + x')`. On a knot both neighbouring quadrants give the same value,
/// except at the seam `t = 0 = 4` (this gives 0).
pub fn circle_param(x: &Float, y: &Float) -> Float {
    let (mut a, mut b) = (x.clone(), y.clone());
    for k in 0..4u32 {
        if a >= 0 && b >= 0 {
            let s = Float::with_val(BITS, &b / Float::with_val(BITS, &a + 1u32));
            return s + k;
        }
        // turn by −π/2: (a, b) → (b, −a)
        let na = b.clone();
        b = -a;
        a = na;
    }
    unreachable!("every point of the circle lies in some quadrant")
}

/// The real roots of `a s² + b s + c = 0` in increasing order (one for a double root;
/// `a ≠ 0`).
pub fn quadratic(a: &Float, b: &Float, c: &Float) -> Vec<Float> {
    let disc = Float::with_val(BITS, b.square_ref()) - Float::with_val(BITS, a * c) * 4u32;
    if disc < 0 {
        return Vec::new();
    }
    let h = disc.clone().sqrt();
    let two_a = Float::with_val(BITS, a * 2u32);
    let mut roots: Vec<Float> = [-1i32, 1]
        .iter()
        .map(|&s| (Float::with_val(BITS, &h * s) - b) / &two_a)
        .collect();
    roots.sort_by(|x, y| x.partial_cmp(y).unwrap());
    if disc == 0 {
        roots.truncate(1);
    }
    roots
}

/// The points `(cos θ, sin θ)` with `α cos θ + β sin θ = γ` (none, one where tangent,
/// or two): with `ρ² = α² + β²`, `(cos, sin) = (αγ ∓ β√(ρ² − γ²), βγ ± α√(ρ² − γ²))/ρ²`.
pub fn trig_solve(alpha: &Float, beta: &Float, gamma: &Float) -> Vec<[Float; 2]> {
    let rho2 = Float::with_val(BITS, alpha.square_ref()) + Float::with_val(BITS, beta.square_ref());
    let disc = Float::with_val(BITS, &rho2 - Float::with_val(BITS, gamma.square_ref()));
    if disc < 0 {
        return Vec::new();
    }
    let h = disc.clone().sqrt();
    let mut out = Vec::new();
    for s in [1i32, -1] {
        let x =
            (Float::with_val(BITS, alpha * gamma) - Float::with_val(BITS, beta * &h) * s) / &rho2;
        let y =
            (Float::with_val(BITS, beta * gamma) + Float::with_val(BITS, alpha * &h) * s) / &rho2;
        out.push([x, y]);
        if disc == 0 {
            break;
        }
    }
    out
}

/// `x·y` of two double vectors in MPFR (exact).
pub fn dot(x: &[f64], y: &[f64]) -> Float {
    x.iter().zip(y).fold(Float::with_val(BITS, 0), |s, (a, b)| {
        s + Float::with_val(BITS, *a) * b
    })
}

/// Where `o + s·d` meets the plane ellipse: `(s, cos θ, sin θ)` per crossing, from
/// `|M⁻¹(o + s d − c)|² = 1`, `M = [A B]`.
pub fn line_ellipse(e: &Ellipse<2>, o: [f64; 2], d: [f64; 2]) -> Vec<[Float; 3]> {
    let det = super::fl(e.a[0]) * e.b[1] - super::fl(e.a[1]) * e.b[0];
    let inv = |v: [Float; 2]| -> [Float; 2] {
        [
            (Float::with_val(BITS, &v[0] * e.b[1]) - Float::with_val(BITS, &v[1] * e.b[0])) / &det,
            (Float::with_val(BITS, &v[1] * e.a[0]) - Float::with_val(BITS, &v[0] * e.a[1])) / &det,
        ]
    };
    let q0 = inv([super::fl(o[0]) - e.c[0], super::fl(o[1]) - e.c[1]]);
    let q1 = inv([super::fl(d[0]), super::fl(d[1])]);
    let sq = |v: &[Float; 2]| {
        Float::with_val(BITS, v[0].square_ref()) + Float::with_val(BITS, v[1].square_ref())
    };
    let a = sq(&q1);
    let b =
        (Float::with_val(BITS, &q0[0] * &q1[0]) + Float::with_val(BITS, &q0[1] * &q1[1])) * 2u32;
    let c = sq(&q0) - 1u32;
    quadratic(&a, &b, &c)
        .into_iter()
        .map(|s| {
            let x = Float::with_val(BITS, &q1[0] * &s) + &q0[0];
            let y = Float::with_val(BITS, &q1[1] * &s) + &q0[1];
            [s, x, y]
        })
        .collect()
}
