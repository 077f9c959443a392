//! Builds the CGAL oracle (oracle/*.cpp, see oracle/README.md) when the `cgal`
//! feature is on. Without it this script does nothing and no C++ is compiled.

fn main() {
    println!("cargo:rerun-if-changed=build.rs");
    if std::env::var_os("CARGO_FEATURE_CGAL").is_some() {
        #[cfg(feature = "cgal")]
        build_oracle();
    }
}

/// One bridge file and two translation units (Epeck, Epick), compiled as CGAL
/// requires for GCC: C++17 with `-frounding-math` (its interval filters switch the
/// rounding mode, which the optimiser must not assume fixed). Always optimised, even
/// in debug builds (CGAL at -O0 is very slow), and without debug info (it doubles
/// the compile time and memory). Links GMP and MPFR, which Epeck's exact numbers use.
#[cfg(feature = "cgal")]
fn build_oracle() {
    let sources = ["oracle/epeck.cpp", "oracle/epick.cpp"];
    cxx_build::bridge("src/oracle/ffi.rs")
        .files(sources)
        .std("c++17")
        .flag("-frounding-math")
        .flag_if_supported("-Wno-unused-parameter")
        .opt_level(2)
        .debug(false)
        .compile("geocert_oracle");
    for file in sources
        .iter()
        .chain(&["oracle/ops.h", "oracle/oracle.h", "src/oracle/ffi.rs"])
    {
        println!("cargo:rerun-if-changed={file}");
    }
    println!("cargo:rustc-link-lib=gmp");
    println!("cargo:rustc-link-lib=mpfr");
}
