//! The progress of a long command counted in evaluations, shown the way its output is read:
//! on a terminal (stdout and stderr both), a bar on stderr with the last generation's line as
//! its message; anywhere else (a Slurm log, a pipe, a file), nothing redrawn but one plain line
//! per generation on stdout, the bar's text without the bar:
//!
//! ```text
//! 00:00:12 700/1100 evals  gen 3: best 1.234 median 0.567 m/s
//! ```
//!
//! `Progress` is shared across threads (`inc` from the evaluating workers); a command makes one
//! per run: `new(total)`, `resume_at(done)` when it continues, `inc(n)` per evaluation,
//! `generation_line(text)` after each generation, `finish()` at the end.

use std::io::IsTerminal;

use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};

/// A run's progress: a bar on a terminal, one line per generation elsewhere (module doc).
pub struct Progress {
    /// Counts evaluations and time in both modes; drawn only on a terminal.
    bar: ProgressBar,
    /// True: plain lines on stdout instead of the bar.
    lines: bool,
}

impl Progress {
    /// The progress of `total` evaluations, starting at 0; a bar when both stdout and stderr
    /// are terminals, lines otherwise.
    pub fn new(total: u64) -> Progress {
        let terminal = std::io::stdout().is_terminal() && std::io::stderr().is_terminal();
        Progress::with_mode(total, !terminal)
    }

    /// As `new`, with the mode chosen: `lines` prints lines, else a bar is drawn on stderr.
    pub fn with_mode(total: u64, lines: bool) -> Progress {
        let target = if lines {
            ProgressDrawTarget::hidden()
        } else {
            ProgressDrawTarget::stderr()
        };
        let bar = ProgressBar::with_draw_target(Some(total), target);
        let template = "{elapsed_precise} [{bar:30}] {pos}/{len} evals, eta {eta}  {msg}";
        if let Ok(style) = ProgressStyle::with_template(template) {
            bar.set_style(style.progress_chars("=> "));
        }
        Progress { bar, lines }
    }

    /// Continues from `done` evaluations (a run resumed from its checkpoint).
    pub fn resume_at(&self, done: u64) {
        self.bar.set_position(done);
    }

    /// Counts `n` more evaluations.
    pub fn inc(&self, n: u64) {
        self.bar.inc(n);
    }

    /// Reports a finished generation in `text` (e.g. "gen 3: best 1.234 median 0.567 m/s"):
    /// the bar's message on a terminal, else a line on stdout with the time and evaluations.
    pub fn generation_line(&self, text: &str) {
        if self.lines {
            say!("{}", self.line(text));
        } else {
            self.bar.set_message(text.to_string());
        }
    }

    /// The plain line for `text`: elapsed time, evaluations done of the total, `text`.
    fn line(&self, text: &str) -> String {
        let seconds = self.bar.elapsed().as_secs();
        format!(
            "{:02}:{:02}:{:02} {}/{} evals  {text}",
            seconds / 3600,
            seconds / 60 % 60,
            seconds % 60,
            self.bar.position(),
            self.bar.length().unwrap_or(0)
        )
    }

    /// Ends the progress: the bar is cleared (the command's summary follows).
    pub fn finish(&self) {
        self.bar.finish_and_clear();
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_line_has_the_evaluations_done_of_the_total_and_the_text() {
        let progress = Progress::with_mode(1100, true);
        progress.resume_at(300);
        progress.inc(200);
        let line = progress.line("gen 2: best 1.000 median 0.500 m/s");
        assert!(line.starts_with("00:00:0"), "{line}");
        assert!(line.ends_with(" 500/1100 evals  gen 2: best 1.000 median 0.500 m/s"));
    }
}
