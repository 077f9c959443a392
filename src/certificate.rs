//! The certificate every operation returns (docs/CERTIFICATES.md, ARCHITECTURE.md "Results").

/// Verdict levels of docs/CERTIFICATES.md, ordered from strongest to weakest, so that
/// the status of a composite result is the maximum of its parts.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Status {
    /// The combinatorial answer is decided for the exact input; coordinates are the
    /// exact values correctly rounded to the nearest double.
    Exact,
    /// Each solution lies in a reported box that holds exactly one solution.
    Verified,
    /// A box holds a tangential solution: a double root of a perturbation of the input
    /// no larger than the reported perturbation, and at most two solutions of the exact
    /// input (with multiplicity).
    VerifiedSingular,
    /// Nothing is proven; the float estimate and the reason are reported.
    Undecided,
}

impl Status {
    /// The name used in JSON (`exact`, `verified`, `verified_singular`, `undecided`).
    pub fn as_str(self) -> &'static str {
        match self {
            Status::Exact => "exact",
            Status::Verified => "verified",
            Status::VerifiedSingular => "verified_singular",
            Status::Undecided => "undecided",
        }
    }

    /// The weaker of two statuses: a result is only as certain as its weakest part.
    pub fn weakest(self, other: Status) -> Status {
        self.max(other)
    }
}

/// The arithmetic that decided a result, weakest-cost first
/// (docs/CERTIFICATES.md "Escalation").
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Arithmetic {
    /// Plain f64, no proof (the `*_f64` variants).
    Float,
    /// A semi-static filter: f64 evaluation with a proven error bound.
    Filter,
    /// Exact fixed-width integer arithmetic on dyadic numbers (`m·2^e`, `m` of a few
    /// 64-bit limbs), without allocation; `bits` is the largest integer's bit length.
    Integer,
    /// Exact arithmetic on floating-point expansions (sums of non-overlapping doubles).
    Expansion,
    /// Exact arithmetic on `rug::Integer` / `rug::Rational`.
    Rational,
    /// f64 intervals with outward rounding.
    Interval,
    /// MPFR intervals at the precision given by `bits`.
    Mpfr,
}

impl Arithmetic {
    /// The interval arithmetic of a proof at `bits` bits of precision: f64 intervals at
    /// 53 bits (or fewer), MPFR intervals above (CERTIFICATION.md "Escalation").
    pub fn of_interval_bits(bits: u32) -> Arithmetic {
        if bits > 53 {
            Arithmetic::Mpfr
        } else {
            Arithmetic::Interval
        }
    }

    /// The name used in JSON.
    pub fn as_str(self) -> &'static str {
        match self {
            Arithmetic::Float => "float",
            Arithmetic::Filter => "filter",
            Arithmetic::Integer => "integer",
            Arithmetic::Expansion => "expansion",
            Arithmetic::Rational => "rational",
            Arithmetic::Interval => "interval",
            Arithmetic::Mpfr => "mpfr",
        }
    }
}

/// A value together with what is proven about it.
#[derive(Debug, Clone, PartialEq)]
pub struct Certified<T> {
    /// The answer (float estimates, enclosures and parameters live inside `T`).
    pub value: T,
    /// What is proven.
    pub status: Status,
    /// True only when it is proven that no other solution exists.
    pub complete: bool,
    /// The arithmetic that decided the answer.
    pub arithmetic: Arithmetic,
    /// The precision that decided the answer: 53 for the f64-based stages, the MPFR
    /// precision for `Mpfr`, and for `Rational` the bit length of the largest exact
    /// number involved.
    pub bits: u32,
    /// Why the answer is `undecided`, or a note on how it was decided.
    pub reason: Option<String>,
    /// For `verified_singular`: the size of the perturbation of the input for which a
    /// double root is proven.
    pub perturbation: Option<f64>,
}

impl<T> Certified<T> {
    /// A complete answer decided exactly.
    pub fn exact(value: T, arithmetic: Arithmetic, bits: u32) -> Self {
        Certified {
            value,
            status: Status::Exact,
            complete: true,
            arithmetic,
            bits,
            reason: None,
            perturbation: None,
        }
    }

    /// An answer for which nothing is proven, with the reason.
    pub fn undecided(
        value: T,
        arithmetic: Arithmetic,
        bits: u32,
        reason: impl Into<String>,
    ) -> Self {
        Certified {
            value,
            status: Status::Undecided,
            complete: false,
            arithmetic,
            bits,
            reason: Some(reason.into()),
            perturbation: None,
        }
    }

    /// The same certificate for another value.
    pub fn clone_with<U>(&self, value: U) -> Certified<U> {
        Certified {
            value,
            status: self.status,
            complete: self.complete,
            arithmetic: self.arithmetic,
            bits: self.bits,
            reason: self.reason.clone(),
            perturbation: self.perturbation,
        }
    }

    /// Transform the value, keeping the certificate.
    pub fn map<U>(self, f: impl FnOnce(T) -> U) -> Certified<U> {
        Certified {
            value: f(self.value),
            status: self.status,
            complete: self.complete,
            arithmetic: self.arithmetic,
            bits: self.bits,
            reason: self.reason,
            perturbation: self.perturbation,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn weakest_status_wins() {
        assert_eq!(Status::Exact.weakest(Status::Verified), Status::Verified);
        assert_eq!(Status::Undecided.weakest(Status::Exact), Status::Undecided);
        assert_eq!(
            Status::VerifiedSingular.weakest(Status::Verified),
            Status::VerifiedSingular
        );
    }
}
