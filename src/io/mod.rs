//! The JSON case format of the command line (spec/CASES.md): reading cases, turning
//! them into geometric objects, and writing results as JSON Lines.

mod answer_out;
mod build;
pub mod case;
mod de;
pub mod number;
pub mod objects;
pub mod result;
pub mod shapes;
mod solve;
mod verify;

pub use answer_out::result as answer_result;
pub use build::{position, shape};
pub use case::{read_cases, Case, Op, Options, ReadCase};
pub use number::{Double, Num};
pub use objects::ObjectSpec;
pub use result::CaseResult;
pub use solve::{answer, options, solve_case};
pub use verify::verify_case;
