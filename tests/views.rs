//! Projection maps (OPERATIONS.md §13.6, §16.14): the table's axes, the axis scales and
//! angles of the isometric and dimetric views, the oblique map and its rays, central
//! views, and interval enclosures of the generic formulas.

use geocert::num::rng::Rng;
use geocert::num::Interval;
use geocert::ops::view::{Rays, View};

fn close(a: f64, b: f64, tol: f64) -> bool {
    (a - b).abs() <= tol
}

fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

#[test]
fn table_rows_of_13_6() {
    let f = View::frontal();
    assert_eq!(
        (f.e_x, f.e_y, f.rays),
        (
            [1.0, 0.0, 0.0],
            [0.0, 0.0, 1.0],
            Rays::Parallel([0.0, -1.0, 0.0])
        )
    );
    let h = View::horizontal();
    assert_eq!(
        (h.e_x, h.e_y, h.rays),
        (
            [1.0, 0.0, 0.0],
            [0.0, 1.0, 0.0],
            Rays::Parallel([0.0, 0.0, 1.0])
        )
    );
    let iso = View::isometric();
    let s2 = 2f64.sqrt();
    let s6 = 6f64.sqrt();
    for (a, b) in iso.e_x.iter().zip([-1.0 / s2, 1.0 / s2, 0.0]) {
        assert!(close(*a, b, 1e-15));
    }
    for (a, b) in iso.e_y.iter().zip([-1.0 / s6, -1.0 / s6, 2.0 / s6]) {
        assert!(close(*a, b, 1e-15));
    }
    let di = View::dimetric();
    for (a, b) in di.e_x.iter().zip([-0.935414, 0.353553, 0.0]) {
        assert!(close(*a, b, 1e-6), "{:?}", di.e_x);
    }
    for (a, b) in di.e_y.iter().zip([-0.117851, -0.311805, 0.942809]) {
        assert!(close(*a, b, 1e-6), "{:?}", di.e_y);
    }
    // the general rule reproduces the orthographic rows, and d = e_X × e_Y
    for v in [
        View::frontal(),
        View::horizontal(),
        View::profile(),
        View::isometric(),
        View::dimetric(),
    ] {
        let Rays::Parallel(d) = v.rays else { panic!() };
        let again = View::parallel(d).unwrap();
        let n = d.iter().map(|x| x * x).sum::<f64>().sqrt();
        let c = cross(v.e_x, v.e_y);
        let same = |a: [f64; 3], b: [f64; 3]| a.iter().zip(b).all(|(x, y)| close(*x, y, 1e-15));
        assert!(same(again.e_x, v.e_x) && same(again.e_y, v.e_y));
        assert!(same(c, d.map(|x| x / n)));
    }
}

/// §16.14: isometric scales 0.8164965809, x and y 30° below the horizontal; dimetric
/// x 0.9428090416 at 7.1808°, y 0.4714045208 at 41.4096°, z 0.9428090416 (vertical).
#[test]
fn axis_scales_of_16_14() {
    let iso = View::isometric();
    for i in 0..3 {
        assert!(close(iso.axis_scale_angle(i).0, 0.8164965809, 1e-10));
    }
    for i in 0..2 {
        assert!(close(iso.axis_scale_angle(i).1.to_degrees(), 30.0, 1e-9));
    }
    let di = View::dimetric();
    let (sx, ax) = di.axis_scale_angle(0);
    let (sy, ay) = di.axis_scale_angle(1);
    let (sz, az) = di.axis_scale_angle(2);
    assert!(close(sx, 0.9428090416, 1e-10) && close(ax.to_degrees(), 7.1808, 1e-4));
    assert!(close(sy, 0.4714045208, 1e-10) && close(ay.to_degrees(), 41.4096, 1e-4));
    assert!(close(sz, 0.9428090416, 1e-10) && close(az.to_degrees(), -90.0, 1e-9));
}

/// Oblique maps: `X = x + k y cos φ`, `Y = z + k y sin φ`; points along the rays map
/// to one image point; the cabinet row of §13.6.
#[test]
fn oblique_maps_and_their_rays() {
    let mut rng = Rng::new(5);
    for _ in 0..200 {
        let (k, phi) = (0.1 + (rng.unit() + 1.0), rng.unit() * 3.0);
        let v = View::oblique(k, phi).unwrap();
        let x = [rng.generic(), rng.generic(), rng.generic()];
        let [px, py] = v.project(&x);
        assert!(close(px, x[0] + k * x[1] * phi.cos(), 1e-12));
        assert!(close(py, x[2] + k * x[1] * phi.sin(), 1e-12));
        let Rays::Parallel(d) = v.rays else { panic!() };
        let t = rng.generic();
        let y = [x[0] + t * d[0], x[1] + t * d[1], x[2] + t * d[2]];
        let [qx, qy] = v.project(&y);
        assert!(close(px, qx, 1e-11) && close(py, qy, 1e-11));
        assert!(d[1] < 0.0, "toward the viewer of the frontal plane");
    }
    let c = View::cabinet();
    let h = 0.5 * std::f64::consts::FRAC_PI_4.cos();
    assert_eq!(
        c.project(&[0.0, 1.0, 0.0]),
        [h, 0.5 * std::f64::consts::FRAC_PI_4.sin()]
    );
    assert!(View::oblique(0.0, 1.0).is_err() && View::oblique(1.0, f64::NAN).is_err());
    assert!(View::parallel([0.0; 3]).is_err());
}

/// Central views: points on one ray from the eye have one image; the target maps to
/// the origin; intervals enclose the f64 image.
#[test]
fn central_views() {
    let mut rng = Rng::new(11);
    for _ in 0..200 {
        let eye = [rng.generic(), rng.generic(), rng.generic()];
        let target = [rng.generic(), rng.generic(), rng.generic()];
        let v = View::central(eye, target, 2.0).unwrap();
        let t = v.project(&target);
        assert!(t[0].abs() < 1e-9 && t[1].abs() < 1e-9, "{t:?}");
        let x = [rng.generic(), rng.generic(), rng.generic()];
        let s = 0.25 + (rng.unit() + 1.0);
        let y: [f64; 3] = std::array::from_fn(|i| eye[i] + s * (x[i] - eye[i]));
        let (a, b) = (v.project(&x), v.project(&y));
        if a[0].is_finite() && a[0].abs() < 1e6 {
            assert!(
                close(a[0], b[0], 1e-6 * (1.0 + a[0].abs()))
                    && close(a[1], b[1], 1e-6 * (1.0 + a[1].abs()))
            );
        }
        let xi = x.map(Interval::point);
        let ai = v.project(&xi);
        if a[0].is_finite() {
            assert!(ai[0].contains(a[0]) && ai[1].contains(a[1]));
        }
    }
    assert!(View::central([1.0; 3], [1.0; 3], 1.0).is_err());
}

#[test]
fn interval_images_enclose_parallel_maps() {
    let mut rng = Rng::new(3);
    for v in [
        View::isometric(),
        View::dimetric(),
        View::cabinet(),
        View::parallel([1.0, -2.0, 0.5]).unwrap(),
    ] {
        for _ in 0..200 {
            let x = [rng.generic(), rng.generic(), rng.generic()];
            let a = v.project(&x);
            let ai = v.project(&x.map(Interval::point));
            assert!(ai[0].contains(a[0]) && ai[1].contains(a[1]));
        }
    }
}
