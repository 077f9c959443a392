//! Sub-commands of the binary.

pub mod demo;
pub mod robustness;
pub mod solve;
pub mod verify;
