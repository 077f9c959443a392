//! The local frame of an analytic surface (docs/FORMAT.md "Frames"; OPERATIONS.md §1.5):
//! the same frame as the curves' ([`crate::curve::frame`]), re-exported here.

pub use crate::curve::frame::{exactly_parallel, Frame};
