//! The section of a `[[from_module]]` group (exploratory): per target shape, the module's
//! one-shot speed, the median generation best at the group's budget of the runs fine-tuned
//! from the module against the compared campaign's fine-tunings of a transplanted module and
//! its runs from scratch on the same shape, with two-sided Mann-Whitney p values (exact where
//! both samples have at most 20 values and no ties, unadjusted), and what each module cost,
//! read from the files: its run, how many runs it was chosen among (its manifest entry) and
//! the transplants' source runs. Beside it, generation 0's best in training from the module
//! and from a transplant: the one-shot measured the same way for both.

use super::Report;
use crate::campaign::file::FinetuneGroup;
use crate::campaign::from_module::FromModuleGroup;
use crate::campaign::{Results, RunData, RunSpec};
use crate::statistics::{mann_whitney, Summary};
use std::fmt::Write;
use vsr::experiment::ValidationSet;
use vsr::simulation::Shape;

/// The sections of every `[[from_module]]` group.
pub(super) fn from_module_sections(results: &Results, r: &mut Report) {
    for g in &results.campaign.from_module {
        section(results, g, &mut r.markdown);
    }
}

fn section(results: &Results, g: &FromModuleGroup, md: &mut String) {
    let _ = writeln!(
        md,
        "## {} · fine-tuning the module {} (exploratory)\n",
        g.name, g.module
    );
    let _ = writeln!(md, "{}\n", module_cost(results, g));
    let mine: Vec<&RunData> = results
        .from_module
        .iter()
        .filter(|(s, _)| s.group == g.name)
        .map(|(_, d)| d)
        .collect();
    // The compared count: the last generation within the budget on the runs' own grid.
    let grid = mine.iter().find_map(|d| d.run.as_ref()).map(|run| {
        let counts = run.generations.iter().map(|gen| gen.evaluations);
        counts.filter(|&e| e <= g.evals).max().unwrap_or(g.evals)
    });
    let at = grid.unwrap_or(g.evals);
    let set = ValidationSet::Unseen;
    let _ = writeln!(
        md,
        "| target | one-shot, `{set}` mean | at {at}: from the module / transplant fine-tuned \
         / from scratch | p: module vs transplant | p: module vs scratch | from the module, \
         at the end: median over seeds of each run's `{set}` mean |\n|---|---|---|---|---|---|"
    );
    for shape in &g.shapes {
        let tuned = from_module_on(results, g, shape);
        let (transplant, scratch, label) = compared_on(results, g, shape);
        let values =
            |runs: &[&RunData]| -> Vec<f64> { runs.iter().filter_map(|d| d.best_at(at)).collect() };
        let (x, t, s) = (values(&tuned), values(&transplant), values(&scratch));
        let end: Vec<f64> = tuned
            .iter()
            .filter_map(|d| d.validation_mean(set))
            .collect();
        let _ = writeln!(
            md,
            "| {shape} | {} | {} / {} / {} | {} | {} | {} |",
            one_shot(results, g, shape, set),
            median(&x),
            median(&t),
            median(&s),
            p_of(&x, &t),
            p_of(&x, &s),
            median(&end)
        );
        if let Some(label) = label {
            let _ = writeln!(md, "| | | ({label}) | | | |");
        }
    }
    let _ = writeln!(
        md,
        "\n(m/s; medians over the seeds with a run, n in brackets; the generation best at \
         {at} evaluations on the target. One-shot: the module unchanged, walked on the target \
         by `one_shot`'s walk of its body set, `{set}` terrains. p: two-sided Mann-Whitney, \
         exact where both samples have at most 20 values and no ties, unadjusted: \
         exploratory, planned in docs/ANALYSIS-PLAN.md but not part of a tested family.)\n"
    );
    generation_zero(results, g, md);
}

/// Generation 0's best in training on each target, from the module and from a transplant:
/// the one-shot speed measured the same way for both (a description, not tested).
fn generation_zero(results: &Results, g: &FromModuleGroup, md: &mut String) {
    let range = |runs: &[&RunData]| -> String {
        let bests: Vec<f64> = runs
            .iter()
            .filter_map(|d| Some(d.run.as_ref()?.generations.first()?.best))
            .collect();
        if bests.is_empty() {
            return "-".into();
        }
        let s = Summary::of(&bests);
        format!("{:.2} to {:.2} (n={})", s.min, s.max, bests.len())
    };
    md.push_str(
        "Generation 0, before any fine-tuning step: its best in training on the target (the \
         best of the generation's brains, each on one training terrain; the slowest to the \
         fastest seed), from the module and from a transplant, the one-shot measured the same \
         way for both (a description, not tested).\n\n| target | from the module | transplant \
         |\n|---|---|---|\n",
    );
    for shape in &g.shapes {
        let tuned = from_module_on(results, g, shape);
        let (transplant, _, _) = compared_on(results, g, shape);
        let _ = writeln!(
            md,
            "| {shape} | {} | {} |",
            range(&tuned),
            range(&transplant)
        );
    }
    md.push('\n');
}

/// The group's runs fine-tuned from the module onto `shape` that have a run file.
fn from_module_on<'a>(results: &'a Results, g: &FromModuleGroup, shape: &str) -> Vec<&'a RunData> {
    let on = results.from_module.iter();
    let on = on.filter(|(s, d)| s.group == g.name && s.shape == shape && d.run.is_some());
    on.map(|(_, d)| d).collect()
}

/// The compared campaign's fine-tunings onto `shape` and its runs from scratch on it, with
/// a label naming the transplant's source and budgets.
fn compared_on<'a>(
    results: &'a Results,
    g: &FromModuleGroup,
    shape: &str,
) -> (Vec<&'a RunData>, Vec<&'a RunData>, Option<String>) {
    let on: Vec<&(String, FinetuneGroup, RunSpec, RunData)> = results
        .compared
        .iter()
        .filter(|(name, _, spec, d)| name == &g.name && spec.shape == shape && d.run.is_some())
        .collect();
    let of = |tuned: bool| -> Vec<&'a RunData> {
        let kind = on.iter().copied().filter(|e| e.2.source.is_some() == tuned);
        kind.map(|e| &e.3).collect()
    };
    let (tuned, scratch) = (of(true), of(false));
    let label = on.iter().find_map(|(_, group, spec, _)| {
        let source = spec.source.as_ref()?;
        Some(format!(
            "{}: transplant from {} after {} evaluations, fine-tuned {}; from scratch {}",
            group.name,
            source.shape,
            group.source_evals,
            group.evals,
            group
                .scratch_evals
                .map_or("none".to_string(), |e| e.to_string())
        ))
    });
    (tuned, scratch, label)
}

/// The module's one-shot mean speed on `shape`, from the group's walk of its body set.
fn one_shot(results: &Results, g: &FromModuleGroup, shape: &str, set: ValidationSet) -> String {
    let Ok(target) = Shape::parse(shape) else {
        return "-".into();
    };
    let walk = results.one_shot.get(&(g.name.clone(), set));
    let found = walk.and_then(|w| w.per_body.iter().find(|b| b.body == target));
    found.map_or("-".into(), |b| format!("{:.2}", b.validation.mean))
}

/// What the module cost, read from the files: its run's evaluations x the bodies each walked,
/// how many such runs it was chosen among (its manifest entry), and what a transplant's
/// source runs of the compared campaign cost.
fn module_cost(results: &Results, g: &FromModuleGroup) -> String {
    let Some(run) = results.modules.get(&g.name) else {
        return "The module file does not exist yet: no cost to state.".into();
    };
    let evaluations = run.generations.last().map_or(0, |g| g.evaluations);
    let per = run.config.bodies.as_ref().map_or(1, |b| b.per_evaluation);
    let episodes = evaluations * per as u64;
    let chosen = match results.chosen_from.get(&g.name) {
        Some(&n) => format!(
            "chosen among {n} such run{} (its manifest entry), so {} body-episodes in all",
            if n == 1 { "" } else { "s" },
            episodes * n as u64
        ),
        None => "how many runs it was chosen among is not known (no manifest entry names it \
                 beside the module)"
            .into(),
    };
    format!(
        "The module: {}, one run of {evaluations} evaluations (generation 0 included) of {per} \
         bod{} each, {episodes} body-episodes of {} s, before any fine-tuning; {chosen}. {}",
        run.config.controller,
        if per == 1 { "y" } else { "ies" },
        run.config.seconds,
        source_cost(results.source_evaluations.get(&g.name))
    )
}

/// The transplants' source runs' evaluations (one body each), as read from their files.
fn source_cost(sources: Option<&Vec<(RunSpec, u64)>>) -> String {
    let Some(sources) = sources.filter(|s| !s.is_empty()) else {
        return "No transplant's source run file was found: its cost is not stated.".into();
    };
    let counts: Vec<u64> = sources.iter().map(|(_, e)| *e).collect();
    let (low, high) = (
        counts.iter().min().copied().unwrap_or(0),
        counts.iter().max().copied().unwrap_or(0),
    );
    let each = if low == high {
        format!("{low} evaluations")
    } else {
        format!("{low} to {high} evaluations")
    };
    format!(
        "A transplant's source run: {each} (generation 0 included) of one body each, read from \
         its {} source run file{} of the compared campaign.",
        sources.len(),
        if sources.len() == 1 { "" } else { "s" }
    )
}

fn median(values: &[f64]) -> String {
    if values.is_empty() {
        return "-".into();
    }
    format!("{:.2} (n={})", Summary::of(values).median, values.len())
}

fn p_of(x: &[f64], y: &[f64]) -> String {
    if x.is_empty() || y.is_empty() {
        return "-".into();
    }
    format!("{:.4}", mann_whitney(x, y).p)
}
