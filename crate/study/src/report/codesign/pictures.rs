//! The figures of a body-search group: the best training fitness and the QD-score against
//! evaluations (median and quartiles over the finished runs of each condition), box plots of
//! the final measures (the tested ones with their tests written under them), and a picture
//! of every run's final best body, condition by condition, drawn from the run files, under
//! the pretrained module on its own body for reference (validated here as `vsr validate`
//! does, on the same set).

use super::family::Row;
use super::measures::{series, Condition, Measure};
use crate::report::figures::{band, box_of, BodyPicture, BodyRow, Figure, Plot};
use crate::report::{push_lines, Report};
use std::fmt::Write;
use vsr::experiment::{validate_on, Best, CodesignRun, ValidationSet};

/// Every figure of group `name` (budget `evals`), linked from the report in order.
pub(super) fn figures(
    name: &str,
    evals: u64,
    conditions: &[Condition],
    tested: &[(Measure, &[Row])],
    r: &mut Report,
) {
    let step = (evals / 60).max(1);
    for (qd, file, what) in [
        (false, "best", "best training fitness (m/s)"),
        (true, "qd", "QD-score (m/s summed over cells)"),
    ] {
        let bands = conditions.iter().filter_map(|c| {
            let runs: Vec<&CodesignRun> =
                c.finished().filter_map(|(_, d)| d.run.as_ref()).collect();
            band(
                &format!("{} (n={})", c.name, runs.len()),
                &series(&runs, step, qd),
            )
        });
        let figure = push_lines(
            r,
            format!("codesign-{name}-{file}.svg"),
            format!("body search {name}: {what} against evaluations"),
            "evaluations",
            what,
            bands.collect(),
        );
        if let (Some(figure), false) = (figure, qd) {
            figure.notes = vec![
                "training fitness overstates speed: it is measured on the training terrains, and the line is"
                    .into(),
                format!(
                    "the archive's best, a maximum over bodies; the tests compare the unseen mean ({})",
                    format_args!("codesign-{name}-unseen.svg")
                ),
            ];
        }
    }
    let untested = [Measure::Velocity(ValidationSet::Paper), Measure::Coverage];
    let all = tested
        .iter()
        .map(|(m, rows)| (*m, Some(*rows)))
        .chain(untested.into_iter().map(|m| (m, None)));
    for (m, rows) in all {
        boxes(name, conditions, m, rows, r);
    }
    bodies(name, conditions, r);
}

/// A box plot of `m` per condition, with its tests under it (or a line saying it is an
/// estimate, not tested).
fn boxes(name: &str, conditions: &[Condition], m: Measure, rows: Option<&[Row]>, r: &mut Report) {
    let boxes: Vec<_> = conditions
        .iter()
        .map(|c| box_of(&c.name, c.values(m)))
        .filter(|b| !b.values.is_empty())
        .collect();
    if boxes.is_empty() {
        return;
    }
    let slug = match m {
        Measure::Velocity(set) => set.to_string(),
        Measure::QdScore => "qd-score".into(),
        Measure::Coverage => "coverage".into(),
        Measure::Best => "best".into(),
    };
    let notes = match rows {
        None => vec!["reported as an estimate, not tested (docs/ANALYSIS-PLAN.md)".to_string()],
        Some(rows) => rows.iter().map(note).collect(),
    };
    let file = format!("codesign-{name}-{slug}.svg");
    let _ = writeln!(r.markdown, "![{}]({file})\n", m.name());
    let unit = if m == Measure::Coverage {
        "cells"
    } else {
        "m/s"
    };
    r.figures.push(Figure {
        file,
        title: format!("body search {name}: {} at the end", m.name()),
        x_label: "brain".into(),
        y_label: format!("{} ({unit})", m.name()),
        plot: Plot::Boxes(boxes),
        notes,
    });
}

/// A test as one line under its box plot.
fn note(row: &Row) -> String {
    let interim = if row.interim() {
        format!(
            " [interim: {}+{} of {p}+{p} runs]",
            row.n.0,
            row.n.1,
            p = row.planned
        )
    } else {
        String::new()
    };
    match (&row.found, row.verdict()) {
        (Some(f), Some(v)) => {
            let (u, h, _) = f.test.as_ref().expect("a verdict has a test");
            format!(
                "{} vs {}: p = {:.4}, Holm {h:.4} ({v}){interim}",
                row.a, row.b, u.p
            )
        }
        _ => format!(
            "{} vs {}: not yet ({}+{} runs)",
            row.a, row.b, row.n.0, row.n.1
        ),
    }
}

/// Every planned run's final best body, a row per condition, sorted by its `unseen` mean
/// (fastest first; a run not validated, then one not finished, after, by seed: a run not
/// finished shows its seed only), under the pretrained module on its own body.
fn bodies(name: &str, conditions: &[Condition], r: &mut Report) {
    let unseen = ValidationSet::Unseen;
    let mut rows: Vec<BodyRow> = module_row(conditions, unseen).into_iter().collect();
    let reference = !rows.is_empty();
    rows.extend(conditions.iter().map(|c| {
        let mut runs: Vec<_> = c.all.iter().collect();
        // Stable: equal keys keep seed order.
        runs.sort_by(|(_, a), (_, b)| {
            let key = |d: &crate::campaign::results::CodesignData| {
                (
                    d.run.is_none(),
                    -d.validation_mean(unseen).unwrap_or(f64::NEG_INFINITY),
                )
            };
            let ((ra, va), (rb, vb)) = (key(a), key(b));
            ra.cmp(&rb).then(va.total_cmp(&vb))
        });
        BodyRow {
            label: c.name.clone(),
            note: format!("{} of {} runs finished", c.finished().count(), c.planned),
            bodies: runs
                .into_iter()
                .map(|(spec, d)| match &d.run {
                    None => BodyPicture {
                        rows: String::new(),
                        caption: format!("s{}: not finished", spec.seed),
                    },
                    Some(run) => BodyPicture {
                        rows: run.best.shape.to_rows(),
                        caption: match d.validation_mean(unseen) {
                            Some(v) => format!("s{}: {v:.2}", spec.seed),
                            None => format!("s{}: not validated", spec.seed),
                        },
                    },
                })
                .collect(),
        }
    }));
    let file = format!("codesign-{name}-bodies.svg");
    let _ = writeln!(r.markdown, "![the final best body of every run]({file})\n");
    let mut notes = vec![
        "under each body: its run's seed and its mean velocity on the 10 unseen terrains (m/s); each brain's row".into(),
        "sorted by that speed, fastest first; \"n of N runs finished\": the brain's runs done, of those planned".into(),
    ];
    if reference {
        notes.push(
            "top row, for reference: the pretrained module on the body it was evolved on, measured the same way".into(),
        );
        notes.push("(its own evolution is not counted in the searches' evaluations)".into());
    }
    r.figures.push(Figure {
        file,
        title: format!("body search {name}: the final best body of every run"),
        x_label: String::new(),
        y_label: String::new(),
        plot: Plot::Bodies(rows),
        notes,
    });
}

/// The pretrained module of the group's `frozen` or `finetune` runs (each run file holds it
/// whole) on its own body, its mean velocity on `set` measured as `vsr validate` measures it
/// (episodes of the runs' seconds); none when no such run has finished.
fn module_row(conditions: &[Condition], set: ValidationSet) -> Option<BodyRow> {
    let run = conditions
        .iter()
        .flat_map(|c| c.finished().filter_map(|(_, d)| d.run.as_ref()))
        .find(|run| run.config.module.is_some())?;
    let m = run.config.module.as_ref()?;
    let best = Best::new(m.controller, m.shape.clone(), m.genome.clone(), m.fitness);
    let caption = match validate_on(&best, set, run.config.seconds) {
        Ok(v) => format!("own body: {:.2}", v.mean),
        Err(_) => "own body: unstable".into(),
    };
    Some(BodyRow {
        label: "the module, for reference".into(),
        note: format!(
            "{}, seed {}, budget {}",
            m.controller, m.seed, m.budget_evals
        ),
        bodies: vec![BodyPicture {
            rows: m.shape.to_rows(),
            caption,
        }],
    })
}
