//! Walking parameter domains with curvature-adaptive steps (OPERATIONS.md §2):
//! the samples that operations use to find initial guesses, and an interval version
//! whose turning-angle bound is proven over each step, for the certifier.
pub mod surface;
