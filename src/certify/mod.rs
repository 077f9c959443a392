//! Certification machinery (ARCHITECTURE.md layer `certify/`, spec/CERTIFICATION.md).

pub mod boxes;
pub mod dual;
pub mod guarded;
pub mod krawczyk;
pub mod level;
pub mod linalg;
pub mod newton;
pub mod system;
