//! The same runs read at a shorter budget (an evolve group's `earlier`): a run from scratch
//! with the same shape, controller and seed and a shorter budget is the longer run's start
//! (tests/study_prefixes.rs checks it bit for bit), so its files say where each run stood
//! then. Per configuration, the paired change of every measure from the shorter budget to
//! the longer; per pair of configurations, the Hodges-Lehmann shift and A12 at both budgets
//! over the same seeds: does the order change? Estimates, not tests (the tests are the
//! group's family above).

use super::families::ALPHA;
use crate::campaign::file::EvolveGroup;
use crate::campaign::{Results, RunData, RunSpec};
use crate::statistics::{hodges_lehmann, mann_whitney, median, median_interval};
use std::fmt::Write;
use vsr::controllers::ControllerKind;
use vsr::experiment::ValidationSet;

/// A measure of a run: the final best (`None`) or the mean on a validation set.
type Measure = Option<ValidationSet>;

fn name(m: Measure) -> String {
    m.map_or("best".into(), |set| format!("{set} mean"))
}

fn value(d: &RunData, m: Measure) -> Option<f64> {
    match m {
        None => d.final_best(),
        Some(set) => d.validation_mean(set),
    }
}

/// Per seed with both budgets' values: (value at `early`, value at `late`).
fn paired(
    results: &Results,
    g: &EvolveGroup,
    (shape, c): (&str, ControllerKind),
    (early, late): (u64, u64),
    m: Measure,
) -> Vec<(f64, f64)> {
    let seeds = g.seeds.as_ref().unwrap_or(&results.campaign.seeds);
    let at = |evals, seed| results.of(&RunSpec::scratch(shape, c, evals, seed));
    let both = seeds
        .iter()
        .map(|&s| (value(&at(early, s), m), value(&at(late, s), m)));
    both.filter_map(|(a, b)| Some((a?, b?))).collect()
}

/// The part of a section (shape, budget `late`) for each of the group's earlier budgets.
pub(super) fn earlier_part(
    results: &Results,
    g: &EvolveGroup,
    (shape, late): (&str, u64),
    md: &mut String,
) {
    let measures: Vec<Measure> = std::iter::once(None)
        .chain(results.campaign.validate.iter().map(|&s| Some(s)))
        .collect();
    for &early in &g.earlier {
        let _ = writeln!(
            md,
            "### The same runs at {early} evaluations\n\nA run of {early} evaluations with the \
             same seed is the start of a run of {late} (checked bit for bit by \
             tests/study_prefixes.rs), so its files say where each run stood then. Change: the \
             median of the paired changes ({late} minus {early}) with its distribution-free \
             interval (its coverage):\n"
        );
        let _ = writeln!(
            md,
            "| configuration | measure | runs | median at {early} | median at {late} | change [interval] |"
        );
        let _ = writeln!(md, "|---|---|---|---|---|---|");
        for &c in &g.controllers {
            for &m in &measures {
                let pairs = paired(results, g, (shape, c), (early, late), m);
                if pairs.is_empty() {
                    let _ = writeln!(md, "| {c} | {} | 0 | - | - | - |", name(m));
                    continue;
                }
                let (a, b): (Vec<f64>, Vec<f64>) = pairs.iter().copied().unzip();
                let diff: Vec<f64> = pairs.iter().map(|(a, b)| b - a).collect();
                let i = median_interval(&diff, ALPHA).expect("values");
                let _ = writeln!(
                    md,
                    "| {c} | {} | {} | {:.4} | {:.4} | {:+.4} [{:+.4}, {:+.4}] ({:.0}%) |",
                    name(m),
                    pairs.len(),
                    median(&a),
                    median(&b),
                    median(&diff),
                    i.low,
                    i.high,
                    100.0 * i.coverage
                );
            }
        }
        md.push('\n');
        order_table(results, g, shape, (early, late), &measures, md);
    }
}

/// Every pair of controllers at both budgets, over the seeds that have both.
fn order_table(
    results: &Results,
    g: &EvolveGroup,
    shape: &str,
    (early, late): (u64, u64),
    measures: &[Measure],
    md: &mut String,
) {
    let mut rows = Vec::new();
    for (i, &a) in g.controllers.iter().enumerate() {
        for &b in &g.controllers[i + 1..] {
            for &m in measures {
                let pa = paired(results, g, (shape, a), (early, late), m);
                let pb = paired(results, g, (shape, b), (early, late), m);
                if pa.is_empty() || pb.is_empty() {
                    continue;
                }
                let at = |k: fn(&(f64, f64)) -> f64| {
                    let x: Vec<f64> = pa.iter().map(k).collect();
                    let y: Vec<f64> = pb.iter().map(k).collect();
                    let s = hodges_lehmann(&x, &y, ALPHA).expect("samples");
                    (s, mann_whitney(&x, &y).a12)
                };
                let ((s0, a0), (s1, a1)) = (at(|p| p.0), at(|p| p.1));
                let ahead = |a12: f64| match a12 {
                    x if x > 0.5 => a.to_string(),
                    x if x < 0.5 => b.to_string(),
                    _ => "neither".to_string(),
                };
                let order = format!("{} -> {}", ahead(a0), ahead(a1));
                rows.push(format!(
                    "| {a} | {b} | {} | {}+{} | {:+.4} [{:+.4}, {:+.4}] | {:.2} | {:+.4} [{:+.4}, {:+.4}] | {:.2} | {order} |",
                    name(m),
                    pa.len(),
                    pb.len(),
                    s0.estimate,
                    s0.interval.low,
                    s0.interval.high,
                    a0,
                    s1.estimate,
                    s1.interval.low,
                    s1.interval.high,
                    a1
                ));
            }
        }
    }
    if rows.is_empty() {
        return;
    }
    let level = 100.0 * (1.0 - ALPHA);
    let _ = writeln!(
        md,
        "The order at both budgets, over the same runs: Hodges-Lehmann shift A - B (m/s) with \
         its exact {level:.0}% interval, and A12 = P(A > B):\n"
    );
    let _ = writeln!(
        md,
        "| A | B | measure | n | shift at {early} | A12 at {early} | shift at {late} | A12 at {late} | ahead |"
    );
    let _ = writeln!(md, "|---|---|---|---|---|---|---|---|---|");
    for row in rows {
        let _ = writeln!(md, "{row}");
    }
    md.push('\n');
}
