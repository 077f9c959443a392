//! Issue 2: "the filter path allocates nothing; the exact fallback on degenerate input
//! must stay lean". A counting global allocator, and counting GMP memory functions
//! (GMP and MPFR allocate through `malloc`, not through Rust's allocator), both per
//! thread so the test harness's other threads do not interfere, show that a certified
//! construction decided by the double-double filter, or by either attempt of the
//! integer tier, performs no heap allocation at all — and, as a control, that the
//! rational tier does allocate (and is seen doing so).

use std::alloc::{GlobalAlloc, Layout, System};
use std::cell::Cell;
use std::ffi::c_void;
use std::sync::{Once, OnceLock};

use gmp_mpfr_sys::gmp;

use geocert::geom::line_plane::{intersect_line_plane, intersect_line_plane_batch};
use geocert::geom::lines2::intersect_line2_line2;
use geocert::geom::plane_plane::{intersect_plane_plane, intersect_plane_plane_batch};
use geocert::geom::three_planes::{intersect_three_planes, intersect_three_planes_batch};
use geocert::geom::{Line, Line2, Linear, Linear2, Plane};
use geocert::Arithmetic;
use nalgebra::{Vector2, Vector3};

struct Counting;

thread_local! {
    static ALLOCATIONS: Cell<usize> = const { Cell::new(0) };
}

fn count() {
    let _ = ALLOCATIONS.try_with(|c| c.set(c.get() + 1));
}

// SAFETY: every call is forwarded to the system allocator unchanged; the counter is a
// thread-local `Cell` with constant initialisation and no destructor, so touching it
// never allocates or re-enters the allocator.
unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        count();
        System.alloc(layout)
    }
    unsafe fn alloc_zeroed(&self, layout: Layout) -> *mut u8 {
        count();
        System.alloc_zeroed(layout)
    }
    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        count();
        System.realloc(ptr, layout, new_size)
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        System.dealloc(ptr, layout)
    }
}

#[global_allocator]
static COUNTING: Counting = Counting;

type GmpFunctions = (
    gmp::allocate_function,
    gmp::reallocate_function,
    gmp::free_function,
);
static GMP_DEFAULTS: OnceLock<GmpFunctions> = OnceLock::new();

extern "C" fn gmp_alloc(size: usize) -> *mut c_void {
    count();
    let alloc = GMP_DEFAULTS.get().and_then(|d| d.0).expect("GMP allocator");
    alloc(size)
}

unsafe extern "C" fn gmp_realloc(ptr: *mut c_void, old: usize, new: usize) -> *mut c_void {
    count();
    let realloc = GMP_DEFAULTS.get().and_then(|d| d.1).expect("GMP allocator");
    // SAFETY: forwarded unchanged to GMP's own reallocation function.
    unsafe { realloc(ptr, old, new) }
}

unsafe extern "C" fn gmp_free(ptr: *mut c_void, size: usize) {
    let free = GMP_DEFAULTS.get().and_then(|d| d.2).expect("GMP allocator");
    // SAFETY: forwarded unchanged to GMP's own free function.
    unsafe { free(ptr, size) }
}

/// Route GMP's (and so MPFR's) allocations through counting wrappers of its defaults.
fn count_gmp_allocations() {
    static INSTALL: Once = Once::new();
    INSTALL.call_once(|| {
        let (mut a, mut r, mut f) = (None, None, None);
        // SAFETY: GMP's documented interface; the wrappers forward to the functions
        // read here, so memory allocated before and after the switch stays compatible.
        unsafe {
            gmp::get_memory_functions(&mut a, &mut r, &mut f);
            let _ = GMP_DEFAULTS.set((a, r, f));
            gmp::set_memory_functions(Some(gmp_alloc), Some(gmp_realloc), Some(gmp_free));
        }
    });
}

/// The number of allocations `f` performs on this thread, and its result.
fn allocations<T>(f: impl FnOnce() -> T) -> (usize, T) {
    let before = ALLOCATIONS.with(|c| c.get());
    let v = f();
    (ALLOCATIONS.with(|c| c.get()) - before, v)
}

fn v(x: f64, y: f64, z: f64) -> Vector3<f64> {
    Vector3::new(x, y, z)
}

fn plane(o: Vector3<f64>, u: Vector3<f64>, w: Vector3<f64>) -> Plane<f64> {
    Plane::parametric(o, u, w).unwrap()
}

/// Certify `f` twice (the first call may initialise process-wide caches such as CPU
/// feature detection), then require that the second call allocated nothing and was
/// decided by `tier`.
fn assert_allocation_free<T>(
    name: &str,
    tier: Arithmetic,
    f: impl Fn() -> geocert::Certified<T>,
) -> geocert::Certified<T> {
    let _ = f();
    let (n, c) = allocations(&f);
    assert_eq!(c.arithmetic, tier, "{name}");
    assert_eq!(n, 0, "{name}: {n} allocations");
    c
}

#[test]
fn filter_and_integer_tiers_allocate_nothing() {
    count_gmp_allocations();
    // Generic input: the filter.
    let a = plane(v(0.1, 0.2, 0.3), v(1.0, 0.3, -0.2), v(0.25, 1.0, 0.5));
    let b = plane(v(0.7, -0.1, 0.2), v(0.0, 1.0, 0.9), v(1.0, -0.5, 0.3));
    let c = plane(v(0.3, 0.3, -0.6), v(0.6, 0.2, 1.0), v(-0.4, 0.8, 0.1));
    let generic = [a.clone(), b.clone(), c];
    assert_allocation_free("three planes, generic", Arithmetic::Filter, || {
        intersect_three_planes(&generic)
    });
    // (Plane-plane of `a`, `b` has an exactly representable parameter direction, which
    // the filter leaves to the exact tiers; these planes have none.)
    let a2 = plane(
        v(0.137, -0.291, 0.53),
        v(1.03, 0.317, -0.219),
        v(0.253, 1.07, 0.511),
    );
    let b2 = plane(
        v(0.711, -0.123, 0.237),
        v(0.013, 1.09, 0.917),
        v(1.01, -0.517, 0.331),
    );
    assert_allocation_free("plane-plane, generic", Arithmetic::Filter, || {
        intersect_plane_plane(&a2, &b2)
    });
    let line = Line::new(v(0.3, -1.7, 2.9), v(0.7, 0.9, -1.3)).unwrap();
    assert_allocation_free("line-plane, generic", Arithmetic::Filter, || {
        intersect_line_plane(Linear::Line(&line), &a)
    });
    let l1 = Line2::new(Vector2::new(0.1, 0.7), Vector2::new(1.3, -0.3)).unwrap();
    let l2 = Line2::new(Vector2::new(-0.4, 0.2), Vector2::new(0.6, 0.9)).unwrap();
    assert_allocation_free("2D lines, generic", Arithmetic::Filter, || {
        intersect_line2_line2(Linear2::Line(&l1), Linear2::Line(&l2))
    });

    // The batch entry points with room reserved in `out`: four-lane filter, nothing else.
    let triples = vec![generic.clone(); 8];
    let mut out3 = Vec::with_capacity(8);
    let lines: Vec<(Linear<f64>, &Plane<f64>)> = vec![(Linear::Line(&line), &a); 8];
    let mut out_lp = Vec::with_capacity(8);
    let pairs = vec![(&a2, &b2); 8];
    let mut out_pp = Vec::with_capacity(8);
    let (n, ()) = allocations(|| {
        intersect_three_planes_batch(&triples, &mut out3);
        intersect_line_plane_batch(&lines, &mut out_lp);
        intersect_plane_plane_batch(&pairs, &mut out_pp);
    });
    assert_eq!(n, 0, "batches: {n} allocations");
    assert!(out3.iter().all(|c| c.arithmetic == Arithmetic::Filter));
    assert!(out_lp.iter().all(|c| c.arithmetic == Arithmetic::Filter));
    assert!(out_pp.iter().all(|c| c.arithmetic == Arithmetic::Filter));

    // Exactly degenerate small-integer input: the 128-bit integers. Three planes
    // through the z axis (a line), coincident and parallel planes, a contained line.
    let p1 = plane(v(0.0, 0.0, 0.0), v(0.0, 0.0, 1.0), v(1.0, 0.0, 0.0));
    let p2 = plane(v(0.0, 0.0, 5.0), v(0.0, 0.0, 1.0), v(0.0, 1.0, 0.0));
    let p3 = plane(v(0.0, 0.0, -3.0), v(1.0, 1.0, 0.0), v(0.0, 0.0, 2.0));
    let through_axis = [p1.clone(), p2, p3];
    assert_allocation_free("three planes, one line", Arithmetic::Integer, || {
        intersect_three_planes(&through_axis)
    });
    let shifted = plane(v(3.0, 0.0, 2.0), v(1.0, 0.0, 0.0), v(2.0, 0.0, 1.0));
    assert_allocation_free("plane-plane, coincident", Arithmetic::Integer, || {
        intersect_plane_plane(&p1, &shifted)
    });
    let parallel = plane(v(0.0, 1.0, 0.0), v(1.0, 0.0, 0.0), v(0.0, 0.0, 3.0));
    assert_allocation_free("plane-plane, parallel", Arithmetic::Integer, || {
        intersect_plane_plane(&p1, &parallel)
    });
    let inside = Line::new(v(2.0, 0.0, 7.0), v(1.0, 0.0, -2.0)).unwrap();
    assert_allocation_free("line-plane, contained", Arithmetic::Integer, || {
        intersect_line_plane(Linear::Line(&inside), &p1)
    });
    let m1 = Line2::new(Vector2::new(0.0, 1.0), Vector2::new(2.0, 4.0)).unwrap();
    let m2 = Line2::new(Vector2::new(1.0, 3.0), Vector2::new(-1.0, -2.0)).unwrap();
    assert_allocation_free("2D lines, coincident", Arithmetic::Integer, || {
        intersect_line2_line2(Linear2::Line(&m1), Linear2::Line(&m2))
    });

    // Three planes through a line given by full 53-bit doubles: the 768-bit integers.
    let (o, d) = (v(1.1, -1.3, 1.7), v(1.9, 1.2, -1.4));
    let full =
        [v(1.3, 1.7, -1.1), v(-1.6, 1.05, 1.15), v(1.45, -1.35, 1.25)].map(|w| plane(o, d, w));
    let c = assert_allocation_free(
        "three planes, full significands",
        Arithmetic::Integer,
        || intersect_three_planes(&full),
    );
    assert!(
        c.bits > 128,
        "decided by the wide integers: {} bits",
        c.bits
    );

    // Control: the rational tier (magnitudes beyond every other tier) allocates in GMP,
    // and the counter sees it.
    let t = 1e-170;
    let q1 = plane(v(0.0, 0.0, 0.0), v(0.0, 0.0, t), v(t, 0.0, 0.0));
    let q2 = plane(v(0.0, 0.0, 5.0), v(0.0, 0.0, t), v(0.0, t, 0.0));
    let q3 = plane(v(0.0, 0.0, -3.0), v(t, t, 0.0), v(0.0, 0.0, t));
    let tiny = [q1, q2, q3];
    let (n, c) = allocations(|| intersect_three_planes(&tiny));
    assert_eq!(c.arithmetic, Arithmetic::Rational);
    assert!(n > 0);
}
