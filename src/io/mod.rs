//! The JSON case format of the command line (spec/CASES.md): reading cases, turning
//! them into geometric objects, and writing results as JSON Lines.

mod build;
pub mod case;
pub mod curved;
mod exact_curved;
pub mod lenient;
mod linear_out;
pub mod number;
pub mod objects;
pub mod result;
pub mod shapes;
mod solve;
pub mod stream;
pub mod strict;
mod verify;

pub use case::{read_cases, read_chunk, read_stream, Case, Op, Options, ReadCase, Record};
pub use number::{Double, Num};
pub use objects::ObjectSpec;
pub use solve::solve_case;
pub use verify::verify_case;
