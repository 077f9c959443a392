//! Point against a closed polyhedron (OPERATIONS.md §4, §16.9), decided exactly:
//! truths from closed forms (boxes, the octahedron |x|+|y|+|z| ≤ 1, an L-shaped prism),
//! exact nearest distances, one-ulp neighbours of faces, and every validation error.

use geocert::ops::{classify_point_polyhedron, Polyhedron, Side};
use geocert::Status;
use proptest::prelude::*;
use rug::Rational;

type P = [Rational; 3];

fn q(x: f64) -> Rational {
    Rational::from_f64(x).unwrap()
}
fn pt(p: [f64; 3]) -> P {
    [q(p[0]), q(p[1]), q(p[2])]
}

/// The box [lo, hi]³ with faces counter-clockwise seen from outside.
fn cube(lo: [f64; 3], hi: [f64; 3]) -> Polyhedron {
    let v = |i: usize| {
        pt([
            if i & 1 == 0 { lo[0] } else { hi[0] },
            if i & 2 == 0 { lo[1] } else { hi[1] },
            if i & 4 == 0 { lo[2] } else { hi[2] },
        ])
    };
    // Vertex i has x bit 1, y bit 2, z bit 4.
    let faces = vec![
        vec![0, 2, 3, 1], // z = lo
        vec![4, 5, 7, 6], // z = hi
        vec![0, 1, 5, 4], // y = lo
        vec![2, 6, 7, 3], // y = hi
        vec![0, 4, 6, 2], // x = lo
        vec![1, 3, 7, 5], // x = hi
    ];
    Polyhedron::new((0..8).map(v).collect(), faces).unwrap()
}

fn unit_cube() -> Polyhedron {
    cube([0.0; 3], [1.0; 3])
}

fn octahedron() -> Polyhedron {
    let v = vec![
        pt([1.0, 0.0, 0.0]),
        pt([-1.0, 0.0, 0.0]),
        pt([0.0, 1.0, 0.0]),
        pt([0.0, -1.0, 0.0]),
        pt([0.0, 0.0, 1.0]),
        pt([0.0, 0.0, -1.0]),
    ];
    // Triangles (x, y, z) with signs; counter-clockwise seen from outside.
    let mut faces = vec![];
    for &x in &[0usize, 1] {
        for &y in &[2usize, 3] {
            for &z in &[4usize, 5] {
                let odd = (x == 1) ^ (y == 3) ^ (z == 5);
                faces.push(if odd { vec![x, z, y] } else { vec![x, y, z] });
            }
        }
    }
    Polyhedron::new(v, faces).unwrap()
}

fn side(p: [f64; 3], shell: &Polyhedron) -> Side {
    let c = classify_point_polyhedron(&pt(p), shell);
    assert_eq!(c.status, Status::Exact);
    assert!(c.complete);
    c.value.side
}

#[test]
fn worked_example_16_9() {
    let c = unit_cube();
    assert_eq!(side([0.5, 0.5, 0.5], &c), Side::Inside);
    let r = classify_point_polyhedron(&pt([1.5, 1.5, 0.5]), &c);
    assert_eq!(r.value.side, Side::Outside);
    assert_eq!(r.value.nearest, pt([1.0, 1.0, 0.5]));
    assert_eq!(r.value.distance_squared, Rational::from((1, 2)));
    let r = classify_point_polyhedron(&pt([1.2, 1.2, 1.2]), &c);
    assert_eq!(r.value.side, Side::Outside);
    assert_eq!(r.value.nearest, pt([1.0, 1.0, 1.0]));
    assert_eq!(side([1.0, 0.3, 0.3], &c), Side::On);
}

#[test]
fn one_ulp_off_a_face_is_inside_or_outside_not_on() {
    let c = unit_cube();
    let up = 1.0 + f64::EPSILON;
    let down = 1.0 - f64::EPSILON / 2.0;
    assert_eq!(side([up, 0.3, 0.3], &c), Side::Outside);
    assert_eq!(side([down, 0.3, 0.3], &c), Side::Inside);
    assert_eq!(side([0.3, 5e-324, 0.7], &c), Side::Inside);
    assert_eq!(side([0.3, -5e-324, 0.7], &c), Side::Outside);
    // Edges and vertices are on the shell.
    assert_eq!(side([1.0, 1.0, 0.25], &c), Side::On);
    assert_eq!(side([0.0, 1.0, 1.0], &c), Side::On);
}

#[test]
fn huge_and_tiny_boxes() {
    let big = cube([-1e300; 3], [1e300; 3]);
    assert_eq!(side([9.9e299, -9.9e299, 0.0], &big), Side::Inside);
    assert_eq!(side([1e300, 1.0, 1.0], &big), Side::On);
    let tiny = cube([1e-300; 3], [2e-300; 3]);
    assert_eq!(side([1.5e-300; 3], &tiny), Side::Inside);
    let above = f64::from_bits(2e-300f64.to_bits() + 1);
    assert_eq!(side([1.5e-300, 1.5e-300, above], &tiny), Side::Outside);
    assert_eq!(side([1.5e-300, 1.5e-300, 2e-300], &tiny), Side::On);
}

/// An L-shaped prism: [0,2]×[0,1]×[0,1] ∪ [0,1]×[1,2]×[0,1] (non-convex edge at x=y=1).
fn l_prism() -> Polyhedron {
    let outline = [
        [0.0, 0.0],
        [2.0, 0.0],
        [2.0, 1.0],
        [1.0, 1.0],
        [1.0, 2.0],
        [0.0, 2.0],
    ];
    let mut v = vec![];
    for z in [0.0, 1.0] {
        for [x, y] in outline {
            v.push(pt([x, y, z]));
        }
    }
    let n = outline.len();
    let mut faces = vec![(0..n).rev().collect::<Vec<_>>(), (n..2 * n).collect()];
    for i in 0..n {
        let j = (i + 1) % n;
        faces.push(vec![i, j, j + n, i + n]);
    }
    Polyhedron::new(v, faces).unwrap()
}

#[test]
fn non_convex_prism() {
    let l = l_prism();
    assert_eq!(side([1.5, 1.5, 0.5], &l), Side::Outside); // in the notch
    assert_eq!(side([0.5, 1.5, 0.5], &l), Side::Inside);
    assert_eq!(side([1.5, 0.5, 0.5], &l), Side::Inside);
    assert_eq!(side([1.0, 1.0, 0.5], &l), Side::On); // the re-entrant edge
    assert_eq!(side([1.0, 1.5, 0.5], &l), Side::On);
    // From the notch, the nearest point is the foot on the nearer wall x = 1.
    let r = classify_point_polyhedron(&pt([1.25, 1.5, 0.5]), &l);
    assert_eq!(r.value.nearest, pt([1.0, 1.5, 0.5]));
    assert_eq!(r.value.distance_squared, Rational::from((1, 16)));
    // Beyond a convex corner below the floor, the nearest point is that vertex.
    let r = classify_point_polyhedron(&pt([2.5, 1.5, -1.0]), &l);
    assert_eq!(r.value.side, Side::Outside);
    assert_eq!(r.value.nearest, pt([2.0, 1.0, 0.0]));
    assert_eq!(r.value.distance_squared, Rational::from((3, 2)));
}

fn in_l(p: [f64; 3]) -> Side {
    let inside_box = |lo: [f64; 3], hi: [f64; 3], strict: bool| {
        (0..3).all(|k| {
            if strict {
                lo[k] < p[k] && p[k] < hi[k]
            } else {
                lo[k] <= p[k] && p[k] <= hi[k]
            }
        })
    };
    let (a_lo, a_hi, b_lo, b_hi) = (
        [0.0, 0.0, 0.0],
        [2.0, 1.0, 1.0],
        [0.0, 1.0, 0.0],
        [1.0, 2.0, 1.0],
    );
    let closed = inside_box(a_lo, a_hi, false) || inside_box(b_lo, b_hi, false);
    // Interior of the union: inside either open box, or on the shared face y = 1,
    // 0 < x < 1, 0 < z < 1 (interior of the union, boundary of both boxes).
    let open = inside_box(a_lo, a_hi, true)
        || inside_box(b_lo, b_hi, true)
        || (p[1] == 1.0 && 0.0 < p[0] && p[0] < 1.0 && 0.0 < p[2] && p[2] < 1.0);
    match (closed, open) {
        (_, true) => Side::Inside,
        (true, false) => Side::On,
        _ => Side::Outside,
    }
}

/// The closed-form squared distance from a point to the box [lo, hi]³ (outside points).
fn box_distance2(p: &[f64; 3], lo: &[f64; 3], hi: &[f64; 3]) -> Rational {
    let mut d2 = Rational::new();
    for k in 0..3 {
        let c = q(p[k]).clamp(&q(lo[k]), &q(hi[k]));
        let d = q(p[k]) - c;
        d2 += d.clone() * d;
    }
    d2
}

fn grid_coord() -> impl Strategy<Value = f64> {
    prop_oneof![
        prop::sample::select(vec![-1.0, 0.0, 0.25, 0.5, 1.0, 1.5, 2.0, 3.0]),
        -1.0f64..3.0,
        prop::sample::select(vec![
            1.0 + f64::EPSILON,
            1.0 - f64::EPSILON / 2.0,
            -5e-324,
            2.0 + 4.0 * f64::EPSILON
        ]),
    ]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(400))]

    /// Box: the side agrees with coordinate comparisons, the nearest distance with
    /// the closed form for outside points, and 0 for points on the shell.
    #[test]
    fn box_matches_coordinates(x in grid_coord(), y in grid_coord(), z in grid_coord()) {
        let (lo, hi) = ([0.0, 0.0, 0.0], [1.0, 2.0, 1.5]);
        let shell = cube(lo, hi);
        let p = [x, y, z];
        let closed = (0..3).all(|k| lo[k] <= p[k] && p[k] <= hi[k]);
        let open = (0..3).all(|k| lo[k] < p[k] && p[k] < hi[k]);
        let truth = if open { Side::Inside } else if closed { Side::On } else { Side::Outside };
        let r = classify_point_polyhedron(&pt(p), &shell);
        prop_assert_eq!(r.status, Status::Exact);
        prop_assert_eq!(r.value.side, truth);
        if truth == Side::Outside {
            prop_assert_eq!(&r.value.distance_squared, &box_distance2(&p, &lo, &hi));
        }
        if truth == Side::On {
            prop_assert_eq!(r.value.distance_squared.cmp0(), std::cmp::Ordering::Equal);
        }
    }

    /// Octahedron: |x| + |y| + |z| against 1, exactly.
    #[test]
    fn octahedron_matches_the_norm(x in grid_coord(), y in grid_coord(), z in grid_coord(),
                                   sx in any::<bool>(), sy in any::<bool>()) {
        let p = [if sx { -x / 2.0 } else { x / 2.0 }, if sy { -y / 2.0 } else { y / 2.0 }, z / 2.0];
        let norm = q(p[0]).abs() + q(p[1]).abs() + q(p[2]).abs();
        let truth = match norm.cmp(&Rational::from(1)) {
            std::cmp::Ordering::Less => Side::Inside,
            std::cmp::Ordering::Equal => Side::On,
            std::cmp::Ordering::Greater => Side::Outside,
        };
        prop_assert_eq!(side(p, &octahedron()), truth);
    }

    /// The L-shaped prism against the union of its two boxes.
    #[test]
    fn l_prism_matches_its_boxes(x in grid_coord(), y in grid_coord(), z in grid_coord()) {
        let p = [x, y, z];
        prop_assert_eq!(side(p, &l_prism()), in_l(p));
    }
}

#[test]
fn invalid_shells_are_typed_errors_naming_the_field() {
    let v: Vec<P> = (0..8)
        .map(|i| pt([(i & 1) as f64, ((i >> 1) & 1) as f64, ((i >> 2) & 1) as f64]))
        .collect();
    let faces = vec![
        vec![0, 2, 3, 1],
        vec![4, 5, 7, 6],
        vec![0, 1, 5, 4],
        vec![2, 6, 7, 3],
        vec![0, 4, 6, 2],
        vec![1, 3, 7, 5],
    ];
    assert!(Polyhedron::new(v.clone(), faces.clone()).is_ok());
    let err = |f: Vec<Vec<usize>>, verts: Vec<P>| Polyhedron::new(verts, f).unwrap_err();

    let mut open = faces.clone();
    open.pop();
    open.push(vec![0, 1, 2]); // keep 6 faces, leave holes
    let e = err(open, v.clone());
    assert_eq!(e.kind(), "invalid_value");
    assert!(e.field().starts_with("faces["), "{e}");

    let inward: Vec<Vec<usize>> = faces
        .iter()
        .map(|f| f.iter().rev().copied().collect())
        .collect();
    let e = err(inward, v.clone());
    assert_eq!(e.field(), "faces");
    assert!(e.to_string().contains("inward"), "{e}");

    let mut flipped = faces.clone();
    flipped[3].reverse();
    assert!(err(flipped, v.clone()).to_string().contains("inconsistent"));

    let mut bent = v.clone();
    bent[7] = pt([1.0, 1.0, 1.5]);
    let e = err(faces.clone(), bent);
    assert!(e.to_string().contains("not planar"), "{e}");

    let mut out_of_range = faces.clone();
    out_of_range[0][2] = 8;
    assert_eq!(err(out_of_range, v.clone()).field(), "faces[0][2]");

    let mut repeated = faces.clone();
    repeated[1] = vec![4, 5, 5, 6];
    assert_eq!(err(repeated, v.clone()).field(), "faces[1][2]");

    let mut two = faces.clone();
    two[2] = vec![0, 1];
    assert_eq!(err(two, v.clone()).field(), "faces[2]");

    assert_eq!(err(faces.clone(), v[..3].to_vec()).field(), "vertices");
}
