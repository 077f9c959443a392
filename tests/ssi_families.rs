//! Surface ∩ surface, certified (OPERATIONS.md §9, §10; CERTIFICATION.md), issue 15:
//! generated families whose truth is known independently of the tracer.
//!
//! * Closed loops of non-quadric pairs (torus ∩ sphere, torus ∩ cylinder, cylinder ∩
//!   cylinder of different radii with offset axes, a bicubic patch ∩ sphere): the number
//!   of loops follows from a closed-form argument given at each family; every vertex of a
//!   verified curve is checked within its proven bound of both true surfaces (exact
//!   rationals for spheres, axis-aligned cylinders and polynomial graphs, MPFR at 256 bits
//!   for tori).
//! * Near-singular families where the topology flips (Steinmetz cylinders, Viviani's
//!   sphere and cylinder (±1e-9 only), two patches touching at a point), perturbed by
//!   ±1e-9 and ±1 ulp:
//!   a `verified` complete answer must have the exact input's components; a
//!   `verified_singular` one must report a perturbation at least the input's distance from
//!   the singular configuration; otherwise `undecided` with a reason.
//! * Pairs of bicubic patches that are graphs `z = f(x, y)` and `z = f(x, y) + h(x, y)`
//!   over the same square, with `h` dyadic in Bernstein form: the intersection is the
//!   level set `h = 0` (one branch, two branches, a small circle, a touching point).
//! * Cylinder ∩ sphere where the curve reaches the cylinder's height end.

// Control nets are indexed by row and column.
#![allow(clippy::needless_range_loop)]

use geocert::num::rng::Rng;
use geocert::ops::surface_surface::{
    intersect_surface_surface, CurveEnd, Options, SurfaceIntersection,
};
use geocert::surface::bezier::BezierSurface;
use geocert::surface::nurbs::NurbsSurface;
use geocert::surface::quadrics::{Cylinder, Sphere};
use geocert::surface::torus::Torus;
use geocert::surface::AnySurface;
use geocert::{Certified, Status};
use rug::ops::Pow;
use rug::{Float, Rational};

const BITS: u32 = 256;

fn q(x: f64) -> Rational {
    Rational::from_f64(x).expect("finite")
}

fn mp(x: f64) -> Float {
    Float::with_val(BITS, x)
}

fn u01(rng: &mut Rng) -> f64 {
    0.5 * (rng.unit() + 1.0)
}

/// A dyadic value (multiple of 2⁻¹⁰) in `[lo, hi]`.
fn dyadic(rng: &mut Rng, lo: f64, hi: f64) -> f64 {
    ((lo + (hi - lo) * u01(rng)) * 1024.0).round() / 1024.0
}

/// `|p − c|² ∈ [(r − b)², (r + b)²]`, exactly.
fn near_sphere(p: &[f64; 3], c: [f64; 3], r: f64, b: f64) -> bool {
    let d2: Rational = (0..3).map(|k| (q(p[k]) - q(c[k])).pow(2u32)).sum();
    let lo = if b < r {
        (q(r) - q(b)).pow(2u32)
    } else {
        Rational::new()
    };
    lo <= d2 && d2 <= (q(r) + q(b)).pow(2u32)
}

/// Within `b` of the cylinder of radius `r` around the line through `o` along the
/// coordinate axis `axis`, exactly.
fn near_cylinder(p: &[f64; 3], o: [f64; 3], axis: usize, r: f64, b: f64) -> bool {
    let d2: Rational = (0..3)
        .filter(|&k| k != axis)
        .map(|k| (q(p[k]) - q(o[k])).pow(2u32))
        .sum();
    let lo = if b < r {
        (q(r) - q(b)).pow(2u32)
    } else {
        Rational::new()
    };
    lo <= d2 && d2 <= (q(r) + q(b)).pow(2u32)
}

/// MPFR distance from `p` to the torus (centre 0, axis z) ≤ `b` + 2⁻²⁰⁰.
fn near_torus(p: &[f64; 3], big: f64, small: f64, b: f64) -> bool {
    let rho = (mp(p[0]).square() + mp(p[1]).square()).sqrt();
    let d = ((rho - mp(big)).square() + mp(p[2]).square()).sqrt() - mp(small);
    d.abs() <= mp(b) + Float::with_val(BITS, Float::i_exp(1, -200))
}

/// Every vertex of every verified curve satisfies `near(xyz, bound)`; the count.
fn check_vertices(
    r: &Certified<SurfaceIntersection>,
    near: impl Fn(&[f64; 3], f64) -> bool,
    what: &str,
) -> usize {
    let mut n = 0;
    for c in r.value.curves.iter() {
        if c.status != Status::Verified {
            continue;
        }
        assert_eq!(c.bounds.len(), c.curve.points.len(), "{what}");
        for (p, b) in c.curve.points.iter().zip(&c.bounds) {
            assert!(b.distance.is_finite() && b.distance >= 0.0, "{what}");
            assert!(
                near(&p.xyz, b.distance),
                "{what}: vertex {:?} not within its bound {:e}",
                p.xyz,
                b.distance
            );
            n += 1;
        }
    }
    n
}

fn summary(r: &Certified<SurfaceIntersection>) -> String {
    let c: Vec<_> = r
        .value
        .curves
        .iter()
        .map(|c| (c.status, c.curve.closed, c.curve.points.len(), c.curve.ends))
        .collect();
    format!(
        "{:?} complete {} curves {c:?} singular {} reason {:?}",
        r.status,
        r.complete,
        r.value.singular_points.len(),
        r.reason
    )
}

/// The promise: a `verified` (or better) complete answer has exactly `loops` closed and
/// `open` open curves and no singular point; an answer that is not proven says why.
/// Returns whether it was proven.
fn proven(r: &Certified<SurfaceIntersection>, loops: usize, open: usize, what: &str) -> bool {
    if r.status <= Status::Verified && r.complete {
        let closed = r.value.curves.iter().filter(|c| c.curve.closed).count();
        assert_eq!(closed, loops, "{what}: {}", summary(r));
        assert_eq!(r.value.curves.len(), loops + open, "{what}: {}", summary(r));
        assert!(r.value.singular_points.is_empty(), "{what}");
        for c in &r.value.curves {
            assert_eq!(c.status, Status::Verified, "{what}");
            if !c.curve.closed {
                assert_eq!(c.curve.ends, [CurveEnd::Boundary; 2], "{what}");
            }
        }
        true
    } else {
        assert!(r.reason.is_some(), "{what}: no reason: {}", summary(r));
        false
    }
}

fn assert_rate(proven: usize, n: usize, percent: usize, what: &str) {
    eprintln!("{what}: {proven} of {n} proven");
    assert!(
        proven * 100 >= n * percent,
        "{what}: only {proven} of {n} proven"
    );
}

/// The surfaces as [`AnySurface`]: one instantiation of the generic operation for the
/// whole file (compile time).
trait Operand {
    fn any(&self) -> AnySurface;
}

macro_rules! operand {
    ($($t:ident => $v:ident),*) => {$(
        impl Operand for $t {
            fn any(&self) -> AnySurface {
                AnySurface::$v(self.clone())
            }
        }
    )*};
}
operand!(Sphere => Sphere, Cylinder => Cylinder, Torus => Torus, BezierSurface => Bezier,
    NurbsSurface => Nurbs);

fn run(a: &impl Operand, b: &impl Operand) -> Certified<SurfaceIntersection> {
    intersect_surface_surface(&a.any(), &b.any(), &Options::default()).expect("valid input")
}

// ---------------------------------------------------------------------------------------
// 1. Closed loops of non-quadric pairs
// ---------------------------------------------------------------------------------------

/// Torus `R`, `r` (axis z) ∩ the cylinder of radius `ρ` along x whose axis passes through
/// `(0, y₀, z₀)`, `ρ + |(y₀, z₀)| < r`, `R > 2r`: every point `(y, z)` of the cylinder's
/// circle has `|z| < r` and `|y| < R − r`, so the x-line through it meets the torus in
/// exactly four points `±√((R ± √(r² − z²))² − y²)`, each continuous in the angle:
/// four closed loops.
#[test]
fn torus_and_cylinder_are_four_proven_loops() {
    let mut rng = Rng::new(1501);
    let (mut ok, n) = (0, 12);
    let mut checked = 0;
    for i in 0..n {
        let big = dyadic(&mut rng, 2.0, 3.0);
        let small = dyadic(&mut rng, 0.6, 0.9);
        let rho = dyadic(&mut rng, 0.2, 0.5) * small;
        let room = 0.9 * small - rho;
        let (y0, z0) = (
            dyadic(&mut rng, -0.6, 0.6) * room,
            dyadic(&mut rng, -0.6, 0.6) * room,
        );
        let torus = Torus::new([0.0; 3], big, small, [0.0, 0.0, 1.0], None).unwrap();
        let h = big + small + 1.0;
        let o = [0.0, y0, z0];
        let cyl = Cylinder::new(o, [rho, rho], [1.0, 0.0, 0.0], None, [-h, h]).unwrap();
        let what = format!("case {i}: R {big} r {small} / ρ {rho} at {o:?}");
        let res = if i % 2 == 0 {
            run(&torus, &cyl)
        } else {
            run(&cyl, &torus)
        };
        ok += usize::from(proven(&res, 4, 0, &what));
        checked += check_vertices(
            &res,
            |p, b| near_torus(p, big, small, b) && near_cylinder(p, o, 0, rho, b),
            &what,
        );
    }
    assert!(checked > 100);
    assert_rate(ok, n, 75, "torus ∩ cylinder");
}

/// Torus `R`, `r` ∩ the sphere of radius `ρ` centred on the torus' core circle,
/// `r < ρ < 2R − r`: over the core angle `u` the meridian circle of the tube is at
/// distance about `2R sin(|u − φ|/2)` from the centre, and the distance `ρ` is taken
/// twice on it exactly on two arcs of `u`, one on each side of the centre: two loops.
/// And the sphere centred on the axis at height `h`: its meridian circle meets the
/// tube's in two points (`|ρ − d| < r < ρ + d`, `d = √(R² + h²)`), each a circle of
/// revolution: two loops.
#[test]
fn torus_and_sphere_are_two_proven_loops() {
    let mut rng = Rng::new(1502);
    let (mut ok, n) = (0, 16);
    let mut checked = 0;
    for i in 0..n {
        let big = dyadic(&mut rng, 2.0, 3.0);
        let small = dyadic(&mut rng, 0.5, 0.8);
        let torus = Torus::new([0.0; 3], big, small, [0.0, 0.0, 1.0], None).unwrap();
        let (c, rho) = if i % 2 == 0 {
            let phi = 6.2 * u01(&mut rng);
            let c = [big * phi.cos(), big * phi.sin(), 0.0];
            (c, dyadic(&mut rng, 1.2, 1.8) * small)
        } else {
            let h = dyadic(&mut rng, -1.0, 1.0);
            let d = (big * big + h * h).sqrt();
            ([0.0, 0.0, h], d + dyadic(&mut rng, -0.7, 0.7) * small)
        };
        let sphere = Sphere::new(c, rho, None, None).unwrap();
        let what = format!("case {i}: R {big} r {small} / {c:?} ρ {rho}");
        let res = run(&torus, &sphere);
        ok += usize::from(proven(&res, 2, 0, &what));
        checked += check_vertices(
            &res,
            |p, b| near_torus(p, big, small, b) && near_sphere(p, c, rho, b),
            &what,
        );
    }
    assert!(checked > 100);
    assert_rate(ok, n, 75, "torus ∩ sphere");
}

/// The unit cylinder along z ∩ a cylinder of radius `ρ` along x through `(0, y₀, z₀)`,
/// `ρ + |y₀| < 1`: every x-line of the second meets the first twice, `x = ±√(1 − y²)`:
/// two loops (different radii, axes not meeting).
#[test]
fn offset_cylinders_of_different_radii_are_two_proven_loops() {
    let mut rng = Rng::new(1503);
    let (mut ok, n) = (0, 16);
    let mut checked = 0;
    for i in 0..n {
        let rho = dyadic(&mut rng, 0.2, 0.8);
        let y0 = dyadic(&mut rng, -0.8, 0.8) * (0.95 - rho);
        let z0 = dyadic(&mut rng, -0.5, 0.5);
        let c1 = Cylinder::new([0.0; 3], [1.0, 1.0], [0.0, 0.0, 1.0], None, [-2.0, 2.0]).unwrap();
        let o = [0.0, y0, z0];
        let c2 = Cylinder::new(o, [rho, rho], [1.0, 0.0, 0.0], None, [-2.0, 2.0]).unwrap();
        let what = format!("case {i}: ρ {rho} at {o:?}");
        let res = run(&c1, &c2);
        ok += usize::from(proven(&res, 2, 0, &what));
        checked += check_vertices(
            &res,
            |p, b| near_cylinder(p, [0.0; 3], 2, 1.0, b) && near_cylinder(p, o, 0, rho, b),
            &what,
        );
    }
    assert!(checked > 100);
    assert_rate(ok, n, 75, "cylinder ∩ cylinder");
}

// ---------------------------------------------------------------------------------------
// Polynomial graphs as bicubic patches
// ---------------------------------------------------------------------------------------

/// A bicubic graph over `[-3/2, 3/2]²`: control points `(j − 3/2, i − 3/2, z[i][j])`,
/// so `x = 3u − 3/2`, `y = 3v − 3/2` exactly and `z = f(u, v)` in Bernstein form.
struct Graph {
    z: [[f64; 4]; 4],
}

impl Graph {
    fn net(&self) -> Vec<Vec<[f64; 3]>> {
        (0..4)
            .map(|i| {
                (0..4)
                    .map(|j| [j as f64 - 1.5, i as f64 - 1.5, self.z[i][j]])
                    .collect()
            })
            .collect()
    }

    fn bezier(&self) -> BezierSurface {
        BezierSurface::new(&self.net(), None).unwrap()
    }

    fn nurbs(&self) -> NurbsSurface {
        let k = vec![0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0];
        NurbsSurface::new([3, 3], k.clone(), k, &self.net(), None).unwrap()
    }

    /// `f` at `(x, y)`, exactly.
    fn at(&self, x: &Rational, y: &Rational) -> Rational {
        let u = (x.clone() + Rational::from((3, 2))) / 3u32;
        let v = (y.clone() + Rational::from((3, 2))) / 3u32;
        let bern = |t: &Rational| -> [Rational; 4] {
            let s = Rational::from(1) - t.clone();
            [
                s.clone().pow(3u32),
                Rational::from(3) * t.clone() * s.clone().pow(2u32),
                Rational::from(3) * t.clone().pow(2u32) * s,
                t.clone().pow(3u32),
            ]
        };
        let (bu, bv) = (bern(&u), bern(&v));
        let mut f = Rational::new();
        for i in 0..4 {
            for j in 0..4 {
                f += bv[i].clone() * &bu[j] * q(self.z[i][j]);
            }
        }
        f
    }

    /// `L² ≥ |∇f|²` on the square (plus a margin): `|f_x| ≤ max |Δ_j z|` since
    /// `f_u = 3 Σ Δ_j z B` and `x_u = 3`.
    fn lipschitz_sq(&self) -> Rational {
        let mut lx = Rational::new();
        let mut ly = Rational::new();
        for i in 0..4 {
            for j in 0..3 {
                lx = lx.max(q((self.z[i][j + 1] - self.z[i][j]).abs()));
                ly = ly.max(q((self.z[j + 1][i] - self.z[j][i]).abs()));
            }
        }
        (lx + Rational::from((1, 100))).pow(2u32) + (ly + Rational::from((1, 100))).pow(2u32)
    }

    /// `p` within `b` of the graph: `|z − f(x, y)| ≤ b √(1 + L²)` is necessary.
    fn near(&self, p: &[f64; 3], b: f64) -> bool {
        let e = q(p[2]) - self.at(&q(p[0]), &q(p[1]));
        e.pow(2u32) <= q(b).pow(2u32) * (Rational::from(1) + self.lipschitz_sq())
    }
}

/// A random bicubic graph, dyadic, heights within `±amp`.
fn random_graph(rng: &mut Rng, amp: f64) -> Graph {
    Graph {
        z: std::array::from_fn(|_| std::array::from_fn(|_| dyadic(rng, -amp, amp))),
    }
}

/// A bicubic patch `|∇f| ≤ 0.1`, `|f| ≤ 0.05` ∩ a sphere centred at `(c_x, c_y, c_z)`,
/// `|c_x|, |c_y| ≤ 0.3`, `|c_z| ≤ 0.3`, radius `ρ ∈ [0.6, 1]`: along every ray from
/// `(c_x, c_y)`, `g = s² + (f − c_z)² − ρ²` has `g_s ≥ 2s − 0.07 > 0` wherever `g = 0`
/// (there `s² ≥ ρ² − 0.35² > 0.2`), `g < 0` at `s = 0` and `g > 0` on the square's edge:
/// one star-shaped loop inside the patch.
#[test]
fn patch_and_sphere_are_one_proven_loop() {
    let mut rng = Rng::new(1504);
    let (mut ok, n) = (0, 12);
    let mut checked = 0;
    for i in 0..n {
        let g = random_graph(&mut rng, 0.05);
        let c = [
            dyadic(&mut rng, -0.3, 0.3),
            dyadic(&mut rng, -0.3, 0.3),
            dyadic(&mut rng, -0.3, 0.3),
        ];
        let rho = dyadic(&mut rng, 0.6, 1.0);
        let sphere = Sphere::new(c, rho, None, None).unwrap();
        let what = format!("case {i}: {c:?} ρ {rho}");
        let res = if i % 2 == 0 {
            run(&g.bezier(), &sphere)
        } else {
            run(&sphere, &g.nurbs())
        };
        ok += usize::from(proven(&res, 1, 0, &what));
        checked += check_vertices(
            &res,
            |p, b| g.near(p, b) && near_sphere(p, c, rho, b),
            &what,
        );
    }
    assert!(checked > 50);
    assert_rate(ok, n, 75, "patch ∩ sphere");
}

/// `h(u, v) = c₀ + 3k(u² − u) + 3m(v² − v) + 3l·u` in Bernstein form (all dyadic for
/// dyadic `c₀, k, m, l`): coefficients `p_j + q_i` with `p = (c₀, c₀ − k + l, c₀ − k +
/// 2l, c₀ + 3l)`, `q = (0, −m, −m, 0)`.
fn bump(c0: f64, k: f64, m: f64, l: f64) -> [[f64; 4]; 4] {
    let p = [c0, c0 - k + l, c0 - k + 2.0 * l, c0 + 3.0 * l];
    let qv = [0.0, -m, -m, 0.0];
    std::array::from_fn(|i| std::array::from_fn(|j| p[j] + qv[i]))
}

/// The pair `z = f` and `z = f + h` (`f` random).
fn graph_pair(rng: &mut Rng, h: [[f64; 4]; 4]) -> (Graph, Graph) {
    let f = random_graph(rng, 0.5);
    let g = Graph {
        z: std::array::from_fn(|i| std::array::from_fn(|j| f.z[i][j] + h[i][j])),
    };
    (f, g)
}

/// Two bicubic graphs differing by `h` (a dyadic polynomial): the intersection is the
/// level set `h(u, v) = 0` lifted to the patches (same `x`, `y` on both).
/// * one branch: `h = 3(u − a) + 3k(v² − v)` → `u = a + k(v − v²)`, one open curve from
///   `v = 0` to `v = 1`;
/// * two branches: `h = 3(u² − u) + 9/16` → `u = 1/4`, `u = 3/4`, two open curves;
/// * a small loop: `h = 3(u² − u) + 3(v² − v) + 3/2 − 3/256` → the circle of radius
///   `1/16` about `(1/2, 1/2)`.
#[test]
fn bicubic_patch_pairs_cross_in_their_level_sets() {
    let mut rng = Rng::new(1505);
    let mut ok = [0; 3];
    let n = 6;
    for i in 0..n {
        for (kind, h, loops, open) in [
            (
                0,
                {
                    let a = dyadic(&mut rng, 0.3, 0.7);
                    let k = dyadic(&mut rng, -0.2, 0.2);
                    bump(-3.0 * a, 0.0, -k, 3.0 / 3.0)
                },
                0,
                1,
            ),
            (1, bump(9.0 / 16.0, 1.0, 0.0, 0.0), 0, 2),
            (2, bump(1.5 - 3.0 / 256.0, 1.0, 1.0, 0.0), 1, 0),
        ] {
            let (f, g) = graph_pair(&mut rng, h);
            let what = format!("case {i} kind {kind}");
            let res = if i % 2 == 0 {
                run(&f.bezier(), &g.nurbs())
            } else {
                run(&g.bezier(), &f.bezier())
            };
            eprintln!("{what}: {}", summary(&res));
            ok[kind] += usize::from(proven(&res, loops, open, &what));
            // on both graphs, and on the level set: the vertex's (u, v) within
            // `b / min(x_u, y_v) = b/3` of h = 0 is implied by being on both graphs
            check_vertices(&res, |p, b| f.near(p, b) && g.near(p, b), &what);
            if kind == 2 {
                // the projected circle: centre (0, 0), radius 3/16
                check_vertices(
                    &res,
                    |p, b| {
                        let d2 = q(p[0]).pow(2u32) + q(p[1]).pow(2u32);
                        let r = Rational::from((3, 16));
                        let lo = if q(b) < r {
                            (r.clone() - q(b)).pow(2u32)
                        } else {
                            Rational::new()
                        };
                        lo <= d2 && d2 <= (r + q(b)).pow(2u32)
                    },
                    &what,
                );
            }
        }
    }
    // Not yet proven (issue 15, open): the open branches of patch pairs ended
    // undecided in every case of the first run; the rates are printed, the promise
    // (a proven answer is right, an unproven one says why) is asserted above.
    assert_rate(ok[0], n, 0, "patches, one branch");
    assert_rate(ok[1], n, 0, "patches, two branches");
    assert_rate(ok[2], n, 0, "patches, small loop");
}

// ---------------------------------------------------------------------------------------
// 2. Near-singular families
// ---------------------------------------------------------------------------------------

/// The promise where the topology flips at `delta = 0`: `truth(delta)` components (loops,
/// open curves). A proven complete `verified` answer has them; a `verified_singular` one
/// reports a perturbation of at least `|delta|·scale` (the input's distance from the
/// singular configuration) unless `delta = 0`; else undecided with a reason.
fn assert_flip(
    r: &Certified<SurfaceIntersection>,
    delta: f64,
    scale: f64,
    truth: (usize, usize),
    what: &str,
) -> bool {
    match r.status {
        Status::Exact | Status::Verified if r.complete => proven(r, truth.0, truth.1, what),
        Status::VerifiedSingular => {
            let e = r.perturbation.unwrap_or(0.0);
            assert!(
                e >= delta.abs() * scale,
                "{what}: verified_singular claims a contact within {e:e} of an input {:e} \
                 from the singular one: {}",
                delta.abs() * scale,
                summary(r)
            );
            false
        }
        _ => {
            assert!(r.reason.is_some(), "{what}: {}", summary(r));
            false
        }
    }
}

/// Steinmetz: cylinders of radius 1 along z and `1 + δ` along x. `δ = 0`: four arcs
/// through two singular points; `δ ≠ 0`: two loops (around the thinner one).
#[test]
fn steinmetz_perturbed_by_1e9_and_one_ulp_is_never_wrong() {
    let c1 = Cylinder::new([0.0; 3], [1.0, 1.0], [0.0, 0.0, 1.0], None, [-2.0, 2.0]).unwrap();
    let mut decided = 0;
    for delta in [1e-9, -1e-9, f64::EPSILON, -f64::EPSILON / 2.0, 1e-6, -1e-6] {
        let r2 = 1.0 + delta;
        let c2 = Cylinder::new([0.0; 3], [r2, r2], [1.0, 0.0, 0.0], None, [-2.0, 2.0]).unwrap();
        let res = run(&c1, &c2);
        let what = format!("steinmetz δ {delta:e}");
        eprintln!("{what}: {}", summary(&res));
        decided += usize::from(assert_flip(&res, delta, 1.0, (2, 0), &what));
        check_vertices(
            &res,
            |p, b| near_cylinder(p, [0.0; 3], 2, 1.0, b) && near_cylinder(p, [0.0; 3], 0, r2, b),
            &what,
        );
    }
    eprintln!("steinmetz: {decided} of 6 perturbed inputs proven");
}

/// Viviani: the sphere of radius 2 about 0 ∩ the cylinder of radius `1 + δ` along z
/// through `(1, 0, 0)`. `δ = 0`: the figure eight, touching at `(2, 0, 0)`; `δ < 0`: two
/// loops (upper and lower, every generator meets the sphere twice); `δ > 0`: one loop
/// (the generators beyond `x = 2` miss the sphere and join the two halves). Only ±1e-9
/// here: the exact pair and ±1 ulp ran over 15 minutes each (issue 15, open).
#[test]
fn viviani_perturbed_by_1e9_is_never_wrong() {
    let sphere = Sphere::new([0.0; 3], 2.0, None, None).unwrap();
    let mut decided = 0;
    for delta in [1e-9, -1e-9] {
        let r = 1.0 + delta;
        let o = [1.0, 0.0, 0.0];
        let cyl = Cylinder::new(o, [r, r], [0.0, 0.0, 1.0], None, [-3.0, 3.0]).unwrap();
        let res = run(&sphere, &cyl);
        let what = format!("viviani δ {delta:e}");
        eprintln!("{what}: {}", summary(&res));
        let truth = if delta < 0.0 { (2, 0) } else { (1, 0) };
        decided += usize::from(assert_flip(&res, delta, 1.0, truth, &what));
        check_vertices(
            &res,
            |p, b| near_sphere(p, [0.0; 3], 2.0, b) && near_cylinder(p, o, 2, r, b),
            &what,
        );
    }
    eprintln!("viviani: {decided} of 2 perturbed inputs proven");
}

/// Two patches touching at a point: `h = 3(u² − u) + 3(v² − v) + 3/2 + δ`, zero only at
/// `(1/2, 1/2)` for `δ = 0`; `δ < 0` a tiny circle, `δ > 0` empty.
#[test]
fn touching_patches_perturbed_are_never_wrong() {
    let mut rng = Rng::new(1506);
    for i in 0..4 {
        for delta in [0.0, 1e-9, -1e-9, f64::EPSILON, -f64::EPSILON] {
            let h = bump(1.5 + delta, 1.0, 1.0, 0.0);
            // ulp-sized δ: a flat base, so that f + h is exact (|δ| = ε survives)
            let (f, g) = if delta != 0.0 && delta.abs() < 1e-12 {
                let f = Graph { z: [[0.0; 4]; 4] };
                (f, Graph { z: h })
            } else {
                graph_pair(&mut rng, h)
            };
            let res = run(&f.bezier(), &g.bezier());
            let what = format!("case {i} touch δ {delta:e}");
            eprintln!("{what}: {}", summary(&res));
            let truth = if delta < 0.0 { (1, 0) } else { (0, 0) };
            if delta == 0.0 {
                // a single contact point: never a proven curve or a proven empty answer
                assert!(
                    !(res.status <= Status::Verified && res.complete),
                    "{what}: {}",
                    summary(&res)
                );
            } else if delta > 0.0 && res.complete && res.status <= Status::Verified {
                assert!(res.value.is_empty(), "{what}");
            } else {
                // moving g by δ vertically is δ·cos θ ≥ δ/√(1 + L²) ≥ 0.3δ along its
                // normal at the touching point (L ≤ 3 for these nets)
                assert_flip(&res, delta, 0.3, truth, &what);
            }
            check_vertices(&res, |p, b| f.near(p, b) && g.near(p, b), &what);
        }
    }
}

// ---------------------------------------------------------------------------------------
// 4. The curve at a cylinder's height end
// ---------------------------------------------------------------------------------------

/// How many shapes the height-end family runs (three ends each): `GEOCERT_SSI_END_CASES`,
/// default 8.
fn end_cases() -> usize {
    std::env::var("GEOCERT_SSI_END_CASES")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(8)
}

/// The cylinder of radius `ρ` along z through `o = (o_x, o_y, 0)` ∩ the sphere of radius
/// `R` centred at `o + (c·e, z_c)` (`e` a horizontal unit axis): on the generator at angle
/// `θ` from `e`, `(z − z_c)² = R² − ρ² − c² + 2cρ cos θ`, between `R² − (ρ + c)² > 0` and
/// `t² = R² − (ρ − c)²` with `(ρ − c, t, R)` a scaled Pythagorean triple (exact): two
/// loops, the upper one highest at `z_c + t`, the lower one lowest at `z_c − t` (`θ = 0`).
/// Seeded: the triple, the scale (a power of two), `c`, `o`, `z_c`, `e` all dyadic.
///
/// The upper end at `z₁ = z_c + t` (or the lower at `z_c − t`) touches a loop at its
/// extreme point from inside: two loops (one touching the end). One ulp towards the
/// loop it is cut there: one loop and one open curve whose ends are about `√ulp` apart.
/// One ulp away it stays inside: two loops. Proven are the touch and the ulp away
/// (the end face decided exactly, `ops::surface_surface::ends`, the loop's chain
/// reaching past it; at least 90 % asserted, all 16 of the default 24 cases in the
/// first run); the cut is left undecided (its ends cross the face at an angle of
/// about `√ulp`, which a box over the height does not resolve in doubles — issue 15,
/// open). The promise (a proven answer has the truth's components, an unproven one says
/// why) is asserted for all.
#[test]
fn cylinder_and_sphere_touching_the_height_end_are_never_wrong() {
    let mut rng = Rng::new(1507);
    let mut checked = 0;
    let (mut ok, mut n) = ([0; 3], 0);
    for i in 0..end_cases() {
        let (m, k) = (2 + (u01(&mut rng) * 3.0) as i32 % 3, 1 + i as i32 % 2);
        let (m, k) = (m.max(k + 1) as f64, k as f64);
        let (a, b, hyp) = (m * m - k * k, 2.0 * m * k, m * m + k * k);
        let (p, t) = if rng.unit() > 0.0 { (a, b) } else { (b, a) };
        let scale = [0.25, 0.5, 1.0, 2.0][i % 4];
        let (p, t, big) = (p * scale, t * scale, hyp * scale);
        // 0 < c < (R − p)/2, so that R > ρ + c: the lower loop exists too
        let c = (big - p) / 2.0 * ((1.0 + (u01(&mut rng) * 6.0).floor()) / 8.0);
        let rho = p + c;
        let o = [
            dyadic(&mut rng, -1.0, 1.0),
            dyadic(&mut rng, -1.0, 1.0),
            0.0,
        ];
        let zc = dyadic(&mut rng, -1.0, 1.0);
        let e = [[1.0, 0.0], [0.0, 1.0], [-1.0, 0.0], [0.0, -1.0]][(i / 2) % 4];
        let centre = [o[0] + c * e[0], o[1] + c * e[1], zc];
        let upper = i % 2 == 0;
        let end = if upper { zc + t } else { zc - t };
        let (toward, away) = if upper {
            (
                geocert::num::round::next_down(end),
                geocert::num::round::next_up(end),
            )
        } else {
            (
                geocert::num::round::next_up(end),
                geocert::num::round::next_down(end),
            )
        };
        for (v, (z, truth)) in [(end, (2, 0)), (toward, (1, 1)), (away, (2, 0))]
            .into_iter()
            .enumerate()
        {
            let h = if upper {
                [zc - 2.0 * big, z]
            } else {
                [z, zc + 2.0 * big]
            };
            let cyl = Cylinder::new(o, [rho, rho], [0.0, 0.0, 1.0], None, h).unwrap();
            let sphere = Sphere::new(centre, big, None, None).unwrap();
            let res = if i % 3 == 0 {
                run(&sphere, &cyl)
            } else {
                run(&cyl, &sphere)
            };
            let what = format!("case {i}: ρ {rho} o {o:?} centre {centre:?} R {big} heights {h:?}");
            eprintln!("{what}: {}", summary(&res));
            n += 1;
            ok[v] += usize::from(proven(&res, truth.0, truth.1, &what));
            checked += check_vertices(
                &res,
                |p, b| near_cylinder(p, o, 2, rho, b) && near_sphere(p, centre, big, b),
                &what,
            );
        }
    }
    assert!(checked > 100);
    eprintln!(
        "height end: {} of {n} proven (touching {}, ulp away {}, cut {})",
        ok.iter().sum::<usize>(),
        ok[0],
        ok[2],
        ok[1]
    );
    // 16 of 24 in the first run: every touching and every ulp-away case, no cut one
    assert_rate(
        ok[0] + ok[2],
        2 * n / 3,
        90,
        "height end, touching or an ulp away",
    );
}
