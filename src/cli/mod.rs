//! Sub-commands of the binary.

pub mod demo;
pub mod exit;
pub mod generate;
pub mod output;
pub mod progress;
pub mod render;
pub mod robustness;
pub mod run;
pub mod table;
