//! Exit status of `geocert solve` and `geocert verify`: one bit per kind of trouble,
//! added together when several occur, so that none hides another (a bad case does
//! not hide a disputed claim). 2 is left to clap's usage errors, which run nothing.

use std::process::ExitCode;

/// Some case could not be read or solved: it has an `error` record.
pub const BAD_CASE: u8 = 1;
/// `verify`: some claimed item was refuted or left undecided, or a solution missed.
pub const DISPUTED: u8 = 4;
/// The input file could not be opened or read to its end.
pub const UNREADABLE: u8 = 8;
/// Writing standard output failed (the results after the failure are lost).
pub const WRITE_FAILED: u8 = 16;
/// A bug in geocert: a case's computation panicked (its record has kind `internal`).
pub const INTERNAL: u8 = 32;

/// The text of `--help` that documents the exit status.
pub const HELP: &str = "\
Exit status (solve, verify): 0 when every case was solved (verify: every claim
confirmed); otherwise the sum of
   1  some case could not be read or solved (it has an `error` record)
   4  verify: some claimed item refuted or undecided, or a solution missed
   8  the input file could not be opened or read (the cases read before still count)
  16  writing standard output failed
  32  internal error: a case's computation failed (a bug; record kind `internal`)
2 alone is a usage error (bad command line; nothing was run).";

/// What went wrong in a run (see the constants).
#[derive(Debug, Default, Clone, Copy, PartialEq, Eq)]
pub struct Status(pub u8);

impl Status {
    pub fn set(&mut self, bit: u8) {
        self.0 |= bit;
    }
    pub fn has(self, bit: u8) -> bool {
        self.0 & bit != 0
    }
    pub fn code(self) -> ExitCode {
        ExitCode::from(self.0)
    }
}
