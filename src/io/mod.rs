//! The JSON case format of the command line (docs/FORMAT.md): reading cases, turning
//! them into geometric objects, and writing results as JSON Lines.

mod answer_out;
mod blend_law;
mod build;
pub mod case;
mod de;
mod fast;
pub mod lenient;
pub mod number;
pub mod objects;
pub mod picture;
mod read;
pub mod result;
pub mod section_out;
pub mod shapes;
mod solve;
pub mod stream;
pub mod strict;
mod verify;
pub mod view;

pub use answer_out::result as answer_result;
pub use build::{position, shape};
pub use case::{Case, Op, Options, ReadCase, Record};
pub use number::{Double, Num};
pub use objects::ObjectSpec;
pub use read::{read_cases, read_chunk, read_stream};
pub use result::CaseResult;
pub use solve::{answer, options, solve_case};
pub use verify::verify_case;
