//! The RQ2 section of the report: fine-tuning against from scratch on a target shape (the
//! summary and tests, the convergence table at matched evaluation counts, Fig. 7).

use super::families::{Comparison, ALPHA};
use super::figures::{band, best_series};
use super::samples::{finetune_samples, Sample};
use super::tables::{comparisons, summary_table};
use super::{push_lines, Report};
use crate::campaign::file::FinetuneGroup;
use crate::campaign::{Results, RunData, RunSpec};
use crate::statistics::{holm, mann_whitney, Summary, UTest};
use std::fmt::Write;

/// The shares of the fine-tuning budget at which the runs are compared (a quarter, half, all).
const SHARES: [u64; 3] = [4, 2, 1];

/// The evaluation counts of the fine-tuned runs' generations (the first run's grid).
fn grid_of(tuned: &Sample) -> Option<Vec<u64>> {
    let run = tuned.runs.iter().find_map(|d| d.run.as_ref())?;
    Some(run.generations.iter().map(|g| g.evaluations).collect())
}

fn at(runs: &[RunData], e: u64) -> Vec<f64> {
    runs.iter().filter_map(|d| d.best_at(e)).collect()
}

/// A test at a matched count: the share of the budget, the count, both samples, the U test.
type Matched = (u64, u64, Vec<f64>, Vec<f64>, UTest);

/// The tests at matched counts, one per share.
fn matched(tuned: &Sample, scratch: &Sample) -> Vec<Matched> {
    let Some(grid) = grid_of(tuned) else {
        return Vec::new();
    };
    let budget = *grid.last().expect("a run has generations");
    let mut rows = Vec::new();
    for share in SHARES {
        let Some(&e) = grid.iter().rev().find(|&&e| e <= budget / share) else {
            continue;
        };
        let (x, y) = (at(&tuned.runs, e), at(&scratch.runs, e));
        if !x.is_empty() && !y.is_empty() {
            let t = mann_whitney(&x, &y);
            rows.push((share, e, x, y, t));
        }
    }
    rows
}

/// Holm's correction of the matched-count tests (docs/ANALYSIS-PLAN.md, family 5): at each
/// share of the budget, over the group's transfers. Keyed by (transfer, share): (adjusted p,
/// the family's size).
pub(super) fn convergence_holm(
    results: &Results,
    g: &FinetuneGroup,
) -> std::collections::HashMap<(String, u64), (f64, usize)> {
    let mut by_share: std::collections::BTreeMap<u64, Vec<(String, f64)>> = Default::default();
    for pair in &g.pairs {
        let (samples, _) = compared(results, g, pair);
        if let [tuned, scratch] = &samples[..] {
            for (share, _, _, _, t) in matched(tuned, scratch) {
                by_share
                    .entry(share)
                    .or_default()
                    .push((pair.join(" -> "), t.p));
            }
        }
    }
    let mut out = std::collections::HashMap::new();
    for (share, tests) in by_share {
        let p: Vec<f64> = tests.iter().map(|(_, p)| *p).collect();
        for ((pair, _), adjusted) in tests.into_iter().zip(holm(&p)) {
            out.insert((pair, share), (adjusted, p.len()));
        }
    }
    out
}

/// The paper's RQ2 claim is about speed ("fine-tuning reaches from-scratch quality in far
/// fewer evaluations"): the best after the same number of evaluations on the target shape (a
/// quarter, half and all of the fine-tuning budget), tested, Holm-adjusted over the transfers;
/// and when the fine-tuned runs' median best first reaches the from-scratch runs' final median.
fn convergence_part(
    tuned: &Sample,
    scratch: &Sample,
    holm: impl Fn(u64) -> Option<(f64, usize)>,
    md: &mut String,
) {
    let Some(grid) = grid_of(tuned) else {
        return;
    };
    let budget = *grid.last().expect("a run has generations");
    let _ = writeln!(
        md,
        "Convergence: best fitness after the same number of evaluations on the target shape \
         (the fine-tuning budget's quarter, half and whole); p (Holm) over the group's \
         transfers at the same share of the budget, of k tests:\n\n\
         | evaluations | median fine-tuned | median from scratch | U | p | p (Holm) | A12 | method | outcome |\n\
         |---|---|---|---|---|---|---|---|---|"
    );
    for (share, e, x, y, t) in matched(tuned, scratch) {
        let (adjusted, k) = holm(share).unwrap_or((t.p, 1));
        let outcome = match (adjusted < ALPHA, t.a12 > 0.5) {
            (true, true) => "fine-tuned ahead",
            (true, false) => "from scratch ahead",
            (false, _) => "no difference detected",
        };
        let _ = writeln!(
            md,
            "| {e} | {:.3} (n={}) | {:.3} (n={}) | {} | {:.4} | {adjusted:.4} (k={k}) | {:.2} | {:?} | {outcome} |",
            Summary::of(&x).median,
            x.len(),
            Summary::of(&y).median,
            y.len(),
            t.u1,
            t.p,
            t.a12,
            t.method
        );
    }
    md.push('\n');
    let finals: Vec<f64> = scratch
        .runs
        .iter()
        .filter_map(RunData::final_best)
        .collect();
    let Some(scratch_budget) = scratch.runs.iter().filter_map(RunData::evaluations).max() else {
        return;
    };
    let target = Summary::of(&finals).median;
    let n = tuned.runs.iter().filter(|d| d.run.is_some()).count();
    let reached = grid.iter().find(|&&e| {
        let x = at(&tuned.runs, e);
        x.len() == n && Summary::of(&x).median >= target
    });
    let _ = match reached {
        Some(e) => writeln!(
            md,
            "The fine-tuned runs' median best first reaches the from-scratch runs' final \
             median ({target:.3} m/s, after {scratch_budget} evaluations) after {e} \
             evaluations.\n"
        ),
        None => writeln!(
            md,
            "The fine-tuned runs' median best does not reach the from-scratch runs' final \
             median ({target:.3} m/s, after {scratch_budget} evaluations) within {budget} \
             evaluations.\n"
        ),
    };
}

/// The from-scratch runs for the convergence table and Fig. 7. While fewer of them have
/// finished than of the target shape's source runs, the source runs stand in: a run's draws
/// derive from (seed, generation, index, purpose), never from its budget, so a `source_evals`
/// run with seed s is the first generations of the `scratch_evals` run with seed s, bit for bit
/// (`tests/evolution.rs`). More seeds up to the source budget beat fewer seeds to the end.
fn prefix_stand_in(
    results: &Results,
    g: &FinetuneGroup,
    (to, scratch_evals): (&str, u64),
    seeds: &[u64],
    scratch: &Sample,
) -> (Sample, Option<String>) {
    // Only a shorter run that covers the fine-tuning budget can stand in.
    if !(g.evals <= g.source_evals && g.source_evals < scratch_evals) {
        return (scratch.clone(), None);
    }
    let spec = RunSpec::scratch(to, g.controller, g.source_evals, 0);
    let runs = results.seeds_of(&spec, seeds);
    let finished = scratch.runs.len();
    if finished >= runs.len() {
        return (scratch.clone(), None);
    }
    let note = format!(
        "Only {finished} of the {} from-scratch runs of {scratch_evals} evaluations exist: the \
         convergence table and the figure use the {} {to} runs of {} evaluations with the same \
         seeds instead, which are their first generations bit for bit.\n",
        seeds.len(),
        runs.len(),
        g.source_evals
    );
    let sample = Sample {
        label: format!("from scratch (first {} of {scratch_evals})", g.source_evals),
        runs,
    };
    (sample, Some(note))
}

/// The samples of a transfer as the convergence table and Fig. 7 compare them (the
/// from-scratch runs possibly stood in for by their prefixes), with the note saying so.
fn compared(
    results: &Results,
    g: &FinetuneGroup,
    pair: &[String; 2],
) -> (Vec<Sample>, Option<String>) {
    let seeds = g.seeds.as_ref().unwrap_or(&results.campaign.seeds);
    let mut samples = finetune_samples(results, g, pair);
    let mut note = None;
    if let (Some(evals), [_, scratch]) = (g.scratch_evals, &mut samples[..]) {
        (*scratch, note) = prefix_stand_in(results, g, (&pair[1], evals), seeds, scratch);
    }
    (samples, note)
}

pub(super) fn finetune_section(
    results: &Results,
    g: &FinetuneGroup,
    pair: &[String; 2],
    tests: &[&Comparison],
    holm: &std::collections::HashMap<(String, u64), (f64, usize)>,
    r: &mut Report,
) {
    let [from, to] = pair;
    let planned = finetune_samples(results, g, pair);
    let _ = writeln!(
        r.markdown,
        "## {} · {from} -> {to} · {}\n",
        g.name, g.controller
    );
    let sets = &results.campaign.validate;
    summary_table(&planned, sets, &mut r.markdown);
    comparisons(tests, &mut r.markdown);
    let (samples, note) = compared(results, g, pair);
    if let Some(note) = note {
        let _ = writeln!(r.markdown, "{note}\n");
    }
    if let [tuned, scratch] = &samples[..] {
        let key = pair.join(" -> ");
        let adjusted = |share| holm.get(&(key.clone(), share)).copied();
        convergence_part(tuned, scratch, adjusted, &mut r.markdown);
    }
    // The paper's view: evaluations on the target shape (fine-tuning from its first
    // evaluation); and the whole cost, fine-tuning drawn after its source's evaluations.
    let views = [
        ("", 0.0, "evaluations on the target shape"),
        (
            "-total",
            g.source_evals as f64,
            "evaluations (fine-tuning: after its source's)",
        ),
    ];
    for (suffix, offset, x_label) in views {
        // From scratch named by its controller, so that it has the controller's colour.
        let mut bands: Vec<_> = samples[1..]
            .iter()
            .map(|s| (format!("{} {}", g.controller, s.label), s))
            .filter_map(|(label, s)| band(&label, &best_series(&s.runs, 0.0)))
            .collect();
        bands.extend(band(
            &samples[0].label,
            &best_series(&samples[0].runs, offset),
        ));
        push_lines(
            r,
            format!("fig7-{}-{from}-to-{to}{suffix}.svg", g.name),
            format!("{to}: fine-tuning against from scratch"),
            x_label,
            "best fitness (m/s)",
            bands,
        );
    }
}
