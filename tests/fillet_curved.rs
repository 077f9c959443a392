//! Constant-radius fillets of sphere/sphere and sphere/cylinder (OPERATIONS.md §11.2,
//! §11.4; issue 18) against independent closed forms in 256-bit MPFR: the circle of two
//! offset spheres (centre on the line of centres at the power-plane distance, radius by
//! Pythagoras), and for sphere/cylinder the heights `z = C_z ± √(R'² − δ²(u))` over the
//! cylinder's angle. Every certified contact box holds its truth (the contact on a
//! sphere computed as `C + R(c − C)/R'`, not by the code's `c − d·normal`), every spine
//! vertex lies within its bound; configurations without a centre curve are `empty`,
//! the ones this build does not parametrise are `unsupported`, the degenerate ones typed
//! errors.

#[path = "fillet_support/mod.rs"]
mod fillet_support;

use fillet_support::*;
use geocert::num::rng::Rng;
use geocert::num::MpfrInterval;
use geocert::ops::{Answer, Options};
use geocert::Status;

/// `E₁ = normalize(a × e_k)` (`e_k` the coordinate vector least aligned with `a`, first
/// on ties) and `E₂ = a × E₁`: the basis of the circle's plane the answer's angle is
/// measured in (docs/FORMAT.md "Blends").
fn basis(a: &[MpfrInterval; 3]) -> ([MpfrInterval; 3], [MpfrInterval; 3]) {
    let mags = a.clone().map(|c| c.midpoint().to_f64().abs());
    let k = (0..3).min_by(|&i, &j| mags[i].total_cmp(&mags[j])).unwrap();
    let mut e = [0.0; 3];
    e[k] = 1.0;
    let e1 = unit(&cross(a, &lift3(e)));
    let e2 = cross(a, &e1);
    (e1, e2)
}

/// The contact on a sphere (centre `cs`, radius `r`, offset radius `rp`) of the ball
/// centred at `c`.
fn on_sphere(
    cs: &[MpfrInterval; 3],
    r: f64,
    rp: &MpfrInterval,
    c: &[MpfrInterval; 3],
) -> [MpfrInterval; 3] {
    let d = [0, 1, 2].map(|x| c[x].clone() - cs[x].clone());
    axpy(cs, &(m(r) / rp.clone()), &d)
}

/// Random sphere pairs in random sectors: one closed component whose centres are the
/// truth circle's points at the reported angles, contacts on both spheres in their
/// boxes; pairs whose offsets miss are `empty`.
#[test]
fn sphere_sphere_fillets_are_the_offset_circle() {
    let mut rng = Rng::new(1806);
    let (mut circles, mut empty) = (0, 0);
    for case in 0..120 {
        let c = [0, 1].map(|_| [0; 3].map(|_| rng.dyadic() / 2.0));
        if c[0] == c[1] {
            continue;
        }
        let r = [0, 1].map(|_| 1.0 + rng.int(0, 32) as f64 / 8.0);
        let signs = [0, 1].map(|_| if rng.coin() { 1.0 } else { -1.0 });
        let rho = r[0].min(r[1]) * rng.int(1, 7) as f64 / 8.0;
        let rp = [0, 1].map(|k| m(r[k]) + m(signs[k] * rho));
        let w = [0, 1, 2].map(|x| m(c[1][x]) - m(c[0][x]));
        let mut mags = [0, 1, 2].map(|x| (c[1][x] - c[0][x]).abs());
        mags.sort_by(f64::total_cmp);
        if mags[0] == mags[1] {
            continue; // the basis' axis is chosen on a tie: not this test's business
        }
        let dd = dot(&w, &w);
        let xi = (dd.clone() + rp[0].sqr() - rp[1].sqr()) / (m(2.0) * dd.clone());
        let rc2 = rp[0].sqr() - xi.sqr() * dd.clone();
        if rc2.contains(0.0) || (rc2.lo_f64().abs() < 1e-6 && rc2.hi_f64().abs() < 1e-6) {
            continue; // touching offsets: the degenerate test covers them
        }
        let shapes = [0, 1].map(|k| sphere(c[k], r[k]));
        let got = geocert::ops::fillet(
            &shapes[0],
            &shapes[1],
            rho,
            &spec(sector_of(signs), None, [13, 3]),
            &Options::default(),
        )
        .unwrap();
        let Answer::Blend(b) = got.value else {
            panic!("case {case}: not a blend")
        };
        if rc2.hi_f64() < 0.0 {
            assert!(b.components.is_empty(), "case {case}");
            assert!(got.complete);
            empty += 1;
            continue;
        }
        assert_eq!(
            got.status,
            Status::Verified,
            "case {case}: {:?}",
            got.reason
        );
        assert_eq!(b.components.len(), 1);
        let k = &b.components[0];
        assert!(k.spine.closed);
        let q = axpy(&lift3(c[0]), &xi, &w);
        let rc = rc2.sqrt();
        let (e1, e2) = basis(&unit(&w));
        let cs = [lift3(c[0]), lift3(c[1])];
        for (i, &t) in k.grid.t.iter().enumerate() {
            let centre = axpy(
                &axpy(&q, &(rc.clone() * m(t).cos()), &e1),
                &(rc.clone() * m(t).sin()),
                &e2,
            );
            assert!(dist(&k.spine.points[i].xyz, &centre) <= k.spine.points[i].bound.unwrap());
            for j in 0..2 {
                let p = on_sphere(&cs[j], r[j], &rp[j], &centre);
                assert_box_contains(&k.contacts[j][i].xyz_box, &p, "sphere contact");
            }
        }
        circles += 1;
    }
    assert!(circles > 40 && empty > 5, "{circles} {empty}");
}

/// A cylinder about a vertical axis and a sphere whose offset encloses the offset
/// cylinder's whole cross-section circle (both orders, every sector the radius
/// allows): two closed branches `z = C_z ± √(R'² − δ²(u))` over the cylinder's angle.
#[test]
fn sphere_cylinder_fillets_are_graphs_over_the_angle() {
    let mut rng = Rng::new(1807);
    let mut components = 0;
    let mut cases = 0;
    while cases < 60 {
        let o = [rng.dyadic() / 4.0, rng.dyadic() / 4.0, -40.0];
        let a = 0.5 + rng.int(0, 16) as f64 / 8.0;
        let signs = [0, 1].map(|_| if rng.coin() { 1.0 } else { -1.0 }); // (sphere, cylinder)
        let rho = a * rng.int(1, 6) as f64 / 8.0;
        let ap = a + signs[1] * rho;
        // off the axis by less than a'/2: the contact never passes a sphere's pole
        let e = if rng.coin() {
            0.0
        } else {
            (rng.int(0, 8) as f64 / 16.0).min(ap / 2.0)
        };
        let beta = rng.unit() * 3.0;
        let cz = rng.dyadic() / 4.0;
        let cs = [o[0] + e * beta.cos(), o[1] + e * beta.sin(), cz];
        // R' ≥ a' + e + margin, R ≥ … so that the concave side keeps R > ρ
        let rp = ap + e + 0.25 + rng.int(0, 16) as f64 / 8.0;
        let r = rp - signs[0] * rho;
        if r <= rho {
            continue;
        }
        cases += 1;
        let (sp, cy) = (sphere(cs, r), cylinder(o, a, [0.0, 0.0, 1.0], [0.0, 80.0]));
        let sphere_first = rng.coin();
        let (first, second, sig) = if sphere_first {
            (&sp, &cy, signs)
        } else {
            (&cy, &sp, [signs[1], signs[0]])
        };
        let (ans, status) = blend(first, second, rho, &spec(sector_of(sig), None, [11, 3]));
        assert_eq!(status, Status::Verified, "case {cases}");
        assert_eq!(ans.components.len(), 2);
        let (is, ic) = if sphere_first { (0, 1) } else { (1, 0) };
        let csm = lift3(cs);
        let rpm = m(r) + m(signs[0] * rho);
        let apm = m(a) + m(signs[1] * rho);
        let mut branches = Vec::new();
        for k in &ans.components {
            let sign = (k.spine.points[0].xyz[2] - cz).signum();
            branches.push(sign);
            for (i, &t) in k.grid.t.iter().enumerate() {
                let (ct, st) = (m(t).cos(), m(t).sin());
                let bx = m(o[0]) + apm.clone() * ct.clone();
                let by = m(o[1]) + apm.clone() * st.clone();
                let delta2 =
                    (bx.clone() - csm[0].clone()).sqr() + (by.clone() - csm[1].clone()).sqr();
                let z = csm[2].clone() + m(sign) * (rpm.sqr() - delta2).sqrt();
                let centre = [bx, by, z.clone()];
                assert!(dist(&k.spine.points[i].xyz, &centre) <= k.spine.points[i].bound.unwrap());
                let on_cyl = [m(o[0]) + m(a) * ct, m(o[1]) + m(a) * st, z.clone()];
                assert_box_contains(&k.contacts[ic][i].xyz_box, &on_cyl, "cylinder contact");
                let pb = k.contacts[ic][i].param_box.as_ref().unwrap();
                assert!(contains(pb[0][1], &(z - m(o[2]))), "cylinder height");
                let p = on_sphere(&csm, r, &rpm, &centre);
                assert_box_contains(&k.contacts[is][i].xyz_box, &p, "sphere contact");
            }
            components += 1;
        }
        branches.sort_by(f64::total_cmp);
        assert_eq!(branches, vec![-1.0, 1.0]);
    }
    assert_eq!(components, 120);
}

/// What is not built, or does not exist, is said so: concentric spheres and a sphere
/// cutting only part of the cylinder (the centre curve turns back in the angle) are
/// `unsupported`; a sphere far from the cylinder gives `empty`; a radius not below a
/// sphere's on its concave side and tangent faces are `degenerate_blend`.
#[test]
fn curved_pairs_refuse_what_they_cannot_prove() {
    let o = Options::default();
    let s1 = sphere([0.0; 3], 2.0);
    let s2 = sphere([0.0; 3], 1.0);
    let got = geocert::ops::fillet(&s1, &s2, 0.25, &spec(1, None, [5, 3]), &o);
    assert_eq!(error_kind(got), ("unsupported".into(), "objects".into()));
    let pipe = cylinder([0.0, 0.0, -10.0], 1.0, [0.0, 0.0, 1.0], [0.0, 20.0]);
    let off_axis = sphere([1.0, 0.0, 0.0], 1.0);
    let got = geocert::ops::fillet(&pipe, &off_axis, 0.25, &spec(1, None, [5, 3]), &o);
    assert_eq!(error_kind(got), ("unsupported".into(), "objects".into()));
    let far = sphere([10.0, 0.0, 0.0], 1.0);
    let got = geocert::ops::fillet(&pipe, &far, 0.25, &spec(1, None, [5, 3]), &o).unwrap();
    assert_eq!(
        got.value,
        Answer::Blend(geocert::ops::BlendAnswer {
            kind: geocert::ops::BlendKind::Fillet {
                radius: geocert::ops::fillet::Law::Constant(0.25)
            },
            sector: 1,
            components: vec![],
        })
    );
    assert!(got.complete);
    // inside a sphere of radius 1 (σ = −1): ρ ≥ 1 degenerates
    let got = geocert::ops::fillet(&s2, &far, 1.0, &spec(3, None, [5, 3]), &o);
    assert_eq!(
        error_kind(got),
        ("degenerate_blend".into(), "radius".into())
    );
    // spheres 0.5 apart and a ball of radius 0.25 between them (sector 1): the offsets
    // touch at one point (|c₁ − c₂| = R₁' + R₂'), where the normals are opposite
    let touching = sphere([3.0, 0.0, 0.0], 1.5);
    let got = geocert::ops::fillet(&s2, &touching, 0.25, &spec(1, None, [5, 3]), &o);
    match got {
        Err(e) => assert_eq!(e.kind(), "degenerate_blend", "{e}"),
        Ok(c) => {
            assert_eq!(c.status, Status::Undecided);
            assert!(c.reason.is_some());
        }
    }
}
