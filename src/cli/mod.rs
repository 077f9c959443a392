//! Sub-commands of the binary.

pub mod demo;
pub mod solve;
pub mod verify;
