//! Certification machinery (ARCHITECTURE.md layer `certify/`): exact univariate root finding.

pub mod univariate;
