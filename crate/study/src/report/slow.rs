//! Slow attention's part of an evolve section: the final best's alpha and eta, and their
//! curves against evaluations (the paper's Fig. 8).

use super::figures::{band, rate_series};
use super::samples::Sample;
use super::tables::cell;
use super::{push_lines, Report};
use std::fmt::Write;
use vsr::controllers::ControllerKind;

pub(super) fn slow_part(samples: &[Sample], id: &str, shape: &str, r: &mut Report) {
    let slow = ControllerKind::SlowAttention.to_string();
    let Some(s) = samples
        .iter()
        .find(|s| s.label == slow && !s.runs.is_empty())
    else {
        return;
    };
    let finals = |f: fn(&vsr::experiment::Best) -> Option<f32>| -> Vec<f64> {
        s.runs
            .iter()
            .filter_map(|d| d.run.as_ref().and_then(|r| f(&r.best)))
            .map(f64::from)
            .collect()
    };
    let _ = writeln!(
        r.markdown,
        "Slow attention, final best: alpha {}, eta {}.\n",
        cell(&finals(|b| b.alpha)),
        cell(&finals(|b| b.eta))
    );
    let bands = [("alpha", false), ("eta", true)]
        .into_iter()
        .filter_map(|(name, eta)| band(name, &rate_series(&s.runs, eta)));
    push_lines(
        r,
        format!("fig8-{id}.svg"),
        format!("{shape}: slow attention's alpha and eta"),
        "evaluations",
        "value",
        bands.collect(),
    );
}
