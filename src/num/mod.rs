//! Numbers (ARCHITECTURE.md layer `num/`): the generic numeric trait, f64 error-bound
//! filters, f64 intervals with outward rounding, MPFR intervals, exact rationals and
//! correctly rounded conversion to f64.

pub mod real;

pub use real::Real;
