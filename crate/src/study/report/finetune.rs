//! The RQ2 section of the report: fine-tuning against from scratch on a target shape (the
//! summary and tests, the convergence table at matched evaluation counts, Fig. 7).

use super::families::Comparison;
use super::figures::{band, best_series};
use super::samples::{finetune_samples, Sample};
use super::tables::{comparisons, summary_table};
use super::{push_lines, Report};
use crate::study::campaign::file::FinetuneGroup;
use crate::study::campaign::{Results, RunData, RunSpec};
use crate::study::statistics::{mann_whitney, Summary};
use std::fmt::Write;

/// The paper's RQ2 claim is about speed ("fine-tuning reaches from-scratch quality in far
/// fewer evaluations"): the best after the same number of evaluations on the target shape (a
/// quarter, half and all of the fine-tuning budget), tested; and when the fine-tuned runs'
/// median best first reaches the from-scratch runs' final median.
fn convergence_part(tuned: &Sample, scratch: &Sample, md: &mut String) {
    // The evaluation counts of the fine-tuned runs' generations (the first run's grid).
    let Some(grid) = tuned.runs.iter().find_map(|d| d.run.as_ref()) else {
        return;
    };
    let grid: Vec<u64> = grid.generations.iter().map(|g| g.evaluations).collect();
    let Some(&budget) = grid.last() else {
        return;
    };
    let at = |runs: &[RunData], e: u64| -> Vec<f64> {
        runs.iter().filter_map(|d| d.best_at(e)).collect()
    };
    let _ = writeln!(
        md,
        "Convergence: best fitness after the same number of evaluations on the target shape \
         (the fine-tuning budget's quarter, half and whole):\n\n\
         | evaluations | median fine-tuned | median from scratch | U | p | A12 | method |\n\
         |---|---|---|---|---|---|---|"
    );
    for share in [4, 2, 1] {
        let Some(&e) = grid.iter().rev().find(|&&e| e <= budget / share) else {
            continue;
        };
        let (x, y) = (at(&tuned.runs, e), at(&scratch.runs, e));
        if x.is_empty() || y.is_empty() {
            continue;
        }
        let t = mann_whitney(&x, &y);
        let _ = writeln!(
            md,
            "| {e} | {:.3} (n={}) | {:.3} (n={}) | {} | {:.4} | {:.2} | {:?} |",
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
    r: &mut Report,
) -> Sample {
    // Only a shorter run that covers the fine-tuning budget can stand in.
    if !(g.evals <= g.source_evals && g.source_evals < scratch_evals) {
        return scratch.clone();
    }
    let spec = RunSpec::scratch(to, g.controller, g.source_evals, 0);
    let runs = results.seeds_of(&spec, seeds);
    let finished = scratch.runs.len();
    if finished >= runs.len() {
        return scratch.clone();
    }
    let _ = writeln!(
        r.markdown,
        "Only {finished} of the {} from-scratch runs of {scratch_evals} evaluations exist: the \
         convergence table and the figure use the {} {to} runs of {} evaluations with the same \
         seeds instead, which are their first generations bit for bit.\n",
        seeds.len(),
        runs.len(),
        g.source_evals
    );
    Sample {
        label: format!("from scratch (first {} of {scratch_evals})", g.source_evals),
        runs,
    }
}

pub(super) fn finetune_section(
    results: &Results,
    g: &FinetuneGroup,
    pair: &[String; 2],
    tests: &[&Comparison],
    r: &mut Report,
) {
    let seeds = g.seeds.as_ref().unwrap_or(&results.campaign.seeds);
    let [from, to] = pair;
    let mut samples = finetune_samples(results, g, pair);
    let _ = writeln!(
        r.markdown,
        "## {} · {from} -> {to} · {}\n",
        g.name, g.controller
    );
    let sets = &results.campaign.validate;
    summary_table(&samples, sets, &mut r.markdown);
    comparisons(tests, &mut r.markdown);
    if let (Some(evals), [_, scratch]) = (g.scratch_evals, &mut samples[..]) {
        *scratch = prefix_stand_in(results, g, (to, evals), seeds, scratch, r);
    }
    if let [tuned, scratch] = &samples[..] {
        convergence_part(tuned, scratch, &mut r.markdown);
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
        let mut bands: Vec<_> = samples[1..]
            .iter()
            .filter_map(|s| band(&s.label, &best_series(&s.runs, 0.0)))
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
