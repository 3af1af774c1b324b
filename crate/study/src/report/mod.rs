//! `vsr report`: the campaign's statistics as Markdown and the figures to draw, from
//! whatever runs exist (missing files are listed, never guessed).
//!
//! Measures per run: `best`, the best fitness of the last generation (training, one
//! evaluation per individual); `SET mean`, the mean velocity of the run's best over the
//! 10 terrains of a validation set (the paper's re-assessment figure). Every pair the paper
//! compares is tested with the two-sided Mann-Whitney U test (exact for small samples without
//! ties) and Vargha-Delaney A12 (`statistics`): the controllers of each shape and budget
//! pairwise (RQ1), and fine-tuning against from scratch on each target shape (RQ2), both at
//! the end and after the fine-tuning budget (the paper's claim is that fine-tuning converges
//! faster). An evolve group's `noninferiority` key adds its one-sided test of the treatment
//! not being worse than the control by a margin, with its verdicts (`noninferiority`).
//!
//! Figures (file names): `fig3-GROUP-SHAPE-EVALS.svg` best fitness against evaluations;
//! `fig4-GROUP-SHAPE-EVALS-SET.svg` validation boxes; `fig6-GROUP-SHAPE-EVALS.svg`
//! ablation; `fig7-GROUP-SOURCE-to-TARGET.svg` fine-tuning against from scratch over the
//! evaluations on the target shape (`...-total.svg`: after the source's evaluations);
//! `fig8-GROUP-SHAPE-EVALS.svg` alpha and eta of slow attention; `fidelity-NAME.svg` our gait
//! ensembles against the reference file NAME's; `codesign-GROUP-*.svg` a body search's
//! curves, boxes and best bodies (`codesign`).

use crate::campaign::file::EvolveGroup;
use crate::campaign::Results;
use figures::{band, best_series, box_of, Figure, Plot};
use std::fmt::Write;

mod ablation;
mod any_body;
mod codesign;
mod earlier;
mod families;
mod fidelity;
pub mod figures;
mod finetune;
mod from_module;
pub mod noninferiority;
mod plateau;
mod samples;
mod series;
mod sets;
mod slow;
mod tables;
use families::{planned, Comparison};
use finetune::finetune_section;
use samples::{samples_of, Sample};
use tables::{comparisons, families_table, summary_table};

/// The report: Markdown text and the figures it links.
#[derive(Debug, Clone)]
pub struct Report {
    /// The Markdown (figures linked by file name).
    pub markdown: String,
    /// The figures to draw next to it.
    pub figures: Vec<Figure>,
    /// Figures it does not draw now and that an earlier report may have left in the folder,
    /// to delete (a non-inferiority test's intervals while short of its planned runs).
    pub withdrawn: Vec<String>,
    /// The non-inferiority test's state and answer, where the campaign plans one: written
    /// next to it as `noninferiority.json` for the page (`noninferiority::summary`).
    pub noninferiority: Option<noninferiority::summary::Summary>,
}

/// Builds the report of `results`.
pub fn report(results: &Results) -> Report {
    let mut r = Report {
        markdown: String::from("# Campaign report\n\n"),
        figures: Vec::new(),
        withdrawn: Vec::new(),
        noninferiority: noninferiority::summary::summary(results),
    };
    missing_section(results, &mut r.markdown);
    let tests = planned(results);
    families_table(&tests, &mut r.markdown);
    noninferiority::section::noninferiority_sections(results, &mut r);
    sets::sets_section(results, &mut r.markdown);
    for g in &results.campaign.evolve {
        for shape in &g.shapes {
            for &evals in &g.evals {
                let mine: Vec<&Comparison> = tests
                    .iter()
                    .filter(|c| (&c.group, &c.shape, c.evals) == (&g.name, shape, evals))
                    .collect();
                evolve_section(results, g, (shape, evals), &mine, &mut r);
            }
        }
    }
    for g in &results.campaign.finetune {
        let holm = finetune::convergence_holm(results, g);
        for pair in &g.pairs {
            let mine: Vec<&Comparison> = tests
                .iter()
                .filter(|c| (&c.group, &c.shape) == (&g.name, &samples::transfer(pair)))
                .collect();
            finetune_section(results, g, pair, &mine, &holm, &mut r);
        }
    }
    codesign::codesign_sections(results, &mut r);
    any_body::any_body_section(results, &mut r);
    from_module::from_module_sections(results, &mut r);
    fidelity::fidelity_section(results, &mut r);
    r
}

fn missing_section(results: &Results, md: &mut String) {
    let found = results
        .data
        .iter()
        .map(|(_, d)| d)
        .filter(|d| d.run.is_some())
        .count();
    let bodies = results.codesign.iter().filter(|(_, d)| d.run.is_some());
    let any_body = results.any_body.iter().filter(|(_, d)| d.run.is_some());
    let tuned = results.from_module.iter().filter(|(_, d)| d.run.is_some());
    let found = found + bodies.count() + any_body.count() + tuned.count();
    let planned = results.data.len()
        + results.codesign.len()
        + results.any_body.len()
        + results.from_module.len();
    let _ = writeln!(md, "Run files found: {found} of {planned}.");
    if results.missing.is_empty() {
        md.push_str("Every planned output exists.\n\n");
        return;
    }
    let _ = writeln!(
        md,
        "\n**Missing: {} planned outputs** (the tables use what exists):\n",
        results.missing.len()
    );
    for path in results.missing.iter().take(40) {
        let _ = writeln!(md, "- `{}`", path.display());
    }
    if results.missing.len() > 40 {
        let _ = writeln!(md, "- ... and {} more", results.missing.len() - 40);
    }
    md.push('\n');
}

fn evolve_section(
    results: &Results,
    g: &EvolveGroup,
    (shape, evals): (&str, u64),
    tests: &[&Comparison],
    r: &mut Report,
) {
    let samples = samples_of(results, g, shape, evals);
    let id = format!("{}-{shape}-{evals}", g.name);
    let md = &mut r.markdown;
    let _ = writeln!(md, "## {} · {shape} · {evals} evaluations\n", g.name);
    let sets = &results.campaign.validate;
    if let Some(n) = g
        .noninferiority
        .as_ref()
        .filter(|n| !noninferiority::complete(results, g, n))
    {
        // The group's summaries and figures compare its arms: none before its test is read.
        let _ = writeln!(
            md,
            "The summaries and figures of this group ({} against {}) wait for every planned \
             run, as its non-inferiority test does.\n",
            n.treatment, n.control
        );
        r.withdrawn.push(fig3_file(&id));
        r.withdrawn
            .extend(sets.iter().map(|&set| fig4_file(&id, set)));
        return;
    }
    summary_table(&samples, sets, md);
    comparisons(tests, md);
    plateau::plateau_table(&samples, md);
    earlier::earlier_part(results, g, (shape, evals), md);
    let bands = samples
        .iter()
        .filter_map(|s| band(&s.label, &best_series(&s.runs, 0.0)));
    let fig3 = push_lines(
        r,
        fig3_file(&id),
        format!("{shape}: best fitness"),
        "evaluations",
        "best fitness (m/s)",
        bands.collect(),
    );
    // Every figure of the section says which seeds and how many runs it draws.
    let runs = runs_note(
        g.seeds.as_ref().unwrap_or(&results.campaign.seeds),
        &samples,
    );
    if let Some(fig3) = fig3 {
        fig3.notes = vec![runs.clone()];
        if let Plot::Lines { marks, .. } = &mut fig3.plot {
            marks.extend(g.earlier.iter().map(|&e| figures::Mark {
                x: e as f64,
                label: format!("{e}: end of the {e}-evaluation runs"),
            }));
        }
    }
    for &set in sets {
        let boxes = samples.iter().map(|s| {
            let means = s.runs.iter().filter_map(|d| d.validation_mean(set));
            box_of(&s.label, means.collect())
        });
        let boxes: Vec<_> = boxes.filter(|b| !b.values.is_empty()).collect();
        if !boxes.is_empty() {
            let file = fig4_file(&id, set);
            let _ = writeln!(r.markdown, "![validation on the {set} set]({file})\n");
            r.figures.push(Figure {
                file,
                title: format!("{shape}, {evals} evaluations: mean velocity on the {set} terrains"),
                x_label: "controller".into(),
                y_label: "velocity (m/s)".into(),
                plot: Plot::Boxes(boxes),
                notes: [vec![runs.clone()], box_notes(tests, &format!("{set} mean"))].concat(),
            });
        }
    }
    if g.ablate {
        ablation::ablation_part(&samples, &id, shape, r);
    }
    slow::slow_part(&samples, &id, shape, r);
}

/// The file of an evolve section's best-fitness curves (`id`: group-shape-evals).
fn fig3_file(id: &str) -> String {
    format!("fig3-{id}.svg")
}

/// The file of an evolve section's validation boxes on `set`.
fn fig4_file(id: &str, set: vsr::experiment::ValidationSet) -> String {
    format!("fig4-{id}-{set}.svg")
}

/// The seeds a figure's curves are drawn from, and how many runs each curve has so far.
fn runs_note(seeds: &[u64], samples: &[Sample]) -> String {
    let runs: Vec<String> = samples
        .iter()
        .map(|s| s.runs.iter().filter(|d| d.run.is_some()).count())
        .zip(samples)
        .filter(|&(n, _)| n > 0)
        .map(|(n, s)| format!("{} {n}", s.label))
        .collect();
    let seeds = noninferiority::section::seeds_text(seeds);
    format!("seeds {seeds}; runs: {}", runs.join(", "))
}

/// Pushes a line figure (and its link) when it has at least one band; the figure, to add
/// notes or marks to.
pub(super) fn push_lines<'r>(
    r: &'r mut Report,
    file: String,
    title: String,
    x: &str,
    y: &str,
    bands: Vec<figures::Band>,
) -> Option<&'r mut Figure> {
    if bands.is_empty() {
        return None;
    }
    let _ = writeln!(r.markdown, "![{title}]({file})\n");
    r.figures.push(Figure {
        file,
        title,
        x_label: x.into(),
        y_label: y.into(),
        plot: Plot::Lines {
            bands,
            marks: Vec::new(),
        },
        notes: Vec::new(),
    });
    r.figures.last_mut()
}

/// The tests between the boxes of a measure, one line each, for the figure.
fn box_notes(tests: &[&Comparison], measure: &str) -> Vec<String> {
    tests
        .iter()
        .filter(|c| c.measure == measure)
        .map(|c| {
            format!(
                "{} vs {}: p = {:.4}, Holm {:.4} ({})",
                c.a,
                c.b,
                c.test.p,
                c.holm.0,
                c.outcome()
            )
        })
        .collect()
}
