//! Whether the curves have flattened by the end of the budget (the paper: "all curves plateau
//! by 30,000 evaluations"): for each run, the least-squares slope of its population median
//! fitness and of its best fitness over the last [`WINDOW`] evaluations; for each sample, the
//! median slope over the runs with its distribution-free 95% interval. A sample "still rises"
//! when the interval's lower end is above 0.

use super::families::ALPHA;
use super::samples::Sample;
use crate::statistics::{median, median_interval};
use std::fmt::Write;
use vsr::experiment::GenerationRecord;

/// The window of the slope (evaluations before the last generation).
pub const WINDOW: u64 = 5_000;

/// The least-squares slope of `y(g)` against evaluations over the last `WINDOW` evaluations,
/// in m/s per 1,000 evaluations; None with fewer than 3 generations in the window.
pub fn slope(generations: &[GenerationRecord], y: fn(&GenerationRecord) -> f64) -> Option<f64> {
    let last = generations.last()?.evaluations;
    let window: Vec<(f64, f64)> = generations
        .iter()
        .filter(|g| g.evaluations + WINDOW >= last)
        .map(|g| (g.evaluations as f64 / 1000.0, y(g)))
        .collect();
    if window.len() < 3 {
        return None;
    }
    let n = window.len() as f64;
    let (mx, my) = window
        .iter()
        .fold((0.0, 0.0), |(a, b), (x, y)| (a + x / n, b + y / n));
    let sxy: f64 = window.iter().map(|(x, y)| (x - mx) * (y - my)).sum();
    let sxx: f64 = window.iter().map(|(x, _)| (x - mx) * (x - mx)).sum();
    Some(sxy / sxx)
}

/// The plateau table of a section's samples.
pub(super) fn plateau_table(samples: &[Sample], md: &mut String) {
    let cell = |s: &Sample, y: fn(&GenerationRecord) -> f64| -> (String, bool) {
        let slopes: Vec<f64> = s
            .runs
            .iter()
            .filter_map(|d| d.run.as_ref())
            .filter_map(|r| slope(&r.generations, y))
            .collect();
        match median_interval(&slopes, ALPHA) {
            None => ("-".into(), false),
            Some(i) => (
                format!(
                    "{:+.4} [{:+.4}, {:+.4}] ({:.0}%)",
                    median(&slopes),
                    i.low,
                    i.high,
                    100.0 * i.coverage
                ),
                i.low > 0.0,
            ),
        }
    };
    if samples.iter().all(|s| s.runs.is_empty()) {
        return;
    }
    let _ = writeln!(
        md,
        "Plateau: slope over the last {WINDOW} evaluations (m/s per 1,000 evaluations), median \
         over runs [distribution-free interval (its coverage)]; \"still rising\" when the \
         interval is above 0:\n\n\
         | configuration | runs | population median | best | still rising |\n|---|---|---|---|---|"
    );
    for s in samples {
        let (m, m_rising) = cell(s, |g| g.median);
        let (b, b_rising) = cell(s, |g| g.best);
        let rising = match (m_rising, b_rising) {
            (true, true) => "median and best",
            (true, false) => "median",
            (false, true) => "best",
            (false, false) => "no",
        };
        let _ = writeln!(
            md,
            "| {} | {} | {m} | {b} | {rising} |",
            s.label,
            s.runs.len()
        );
    }
    md.push('\n');
}
