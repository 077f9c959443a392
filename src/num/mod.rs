//! Numbers (ARCHITECTURE.md layer `num/`): the generic numeric trait, f64 error-bound
//! filters, f64 intervals with outward rounding, MPFR intervals, exact rationals and
//! correctly rounded conversion to f64.

pub mod dd;
pub mod dyadic;
pub mod dyadic128;
pub mod error_bound;
pub mod expansion;
pub mod filter;
pub mod interval;
pub mod interval_like;
pub mod lane;
#[cfg(target_arch = "x86_64")]
pub mod lane8;
mod limbs;
pub mod midrad;
pub mod mpfr_interval;
pub mod parse;
pub mod ratio;
pub mod real;
pub mod ring;
pub mod rng;
pub mod round;
pub mod vector;

pub use interval::Interval;
pub use interval_like::IntervalLike;
pub use mpfr_interval::MpfrInterval;
pub use real::{Arith, Real};
pub use round::Rounded;
