//! Progress on standard error (indicatif): shown when standard error is a terminal
//! and `CI` is not set, or always with `--progress`; never on standard output, so
//! results are the same bytes either way.

use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use std::io::IsTerminal;
use std::time::Duration;

/// Whether progress is drawn: `--progress`, or an attended terminal outside CI.
pub fn wanted(forced: bool) -> bool {
    forced || (std::io::stderr().is_terminal() && std::env::var_os("CI").is_none())
}

fn target(show: bool) -> ProgressDrawTarget {
    if !show {
        return ProgressDrawTarget::hidden();
    }
    // indicatif hides its own stderr target off a terminal; `--progress` draws anyway.
    ProgressDrawTarget::term_like_with_hz(Box::new(console::Term::stderr()), 10)
}

/// A progress bar over the input's bytes (a counter when the size is unknown).
pub struct Progress {
    bar: ProgressBar,
}

impl Progress {
    pub fn new(show: bool, len: Option<u64>, command: &str) -> Self {
        let bar = match len {
            Some(len) => ProgressBar::with_draw_target(Some(len), target(show)).with_style(
                ProgressStyle::with_template(&format!(
                    "geocert {command} {{elapsed_precise}} [{{wide_bar}}] {{percent}}% {{msg}}"
                ))
                .unwrap_or_else(|_| ProgressStyle::default_bar()),
            ),
            None => ProgressBar::with_draw_target(None, target(show)).with_style(
                ProgressStyle::with_template(&format!(
                    "geocert {command} {{spinner}} {{elapsed_precise}} {{msg}}"
                ))
                .unwrap_or_else(|_| ProgressStyle::default_spinner()),
            ),
        };
        Progress { bar }
    }

    /// The input has been written up to byte `end`.
    pub fn advance(&self, end: u64) {
        if !self.bar.is_hidden() {
            self.bar.set_position(end);
        }
    }

    pub fn update(&self, cases: u64, errors: u64) {
        if !self.bar.is_hidden() {
            self.bar
                .set_message(format!("{cases} cases, {errors} errors"));
            self.bar.tick();
        }
    }

    pub fn finish(&self) {
        self.bar.finish_and_clear();
    }
}

/// A spinner for a computation without steps to count (`bench`).
pub fn spinner(show: bool, what: &str) -> ProgressBar {
    let bar = ProgressBar::with_draw_target(None, target(show)).with_style(
        ProgressStyle::with_template(&format!("{what} {{spinner}} {{elapsed_precise}}"))
            .unwrap_or_else(|_| ProgressStyle::default_spinner()),
    );
    bar.enable_steady_tick(Duration::from_millis(200));
    bar
}
