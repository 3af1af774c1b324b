//! The figures of a body-search group: the best training fitness and the QD-score against
//! evaluations (median and quartiles over the finished runs of each condition), box plots of
//! the final measures (the tested ones with their tests written under them), and a picture
//! of every run's final best body, condition by condition, drawn from the run files.

use super::family::Row;
use super::measures::{series, Condition, Measure};
use crate::experiment::{CodesignRun, ValidationSet};
use crate::study::report::figures::{band, box_of, BodyPicture, BodyRow, Figure, Plot};
use crate::study::report::{push_lines, Report};
use std::fmt::Write;

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
        push_lines(
            r,
            format!("codesign-{name}-{file}.svg"),
            format!("body search {name}: {what} against evaluations"),
            "evaluations",
            what,
            bands.collect(),
        );
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

/// Every planned run's final best body, a row per condition; a run not finished shows its
/// seed only.
fn bodies(name: &str, conditions: &[Condition], r: &mut Report) {
    let rows: Vec<BodyRow> = conditions
        .iter()
        .map(|c| BodyRow {
            label: format!("{} ({} of {})", c.name, c.finished().count(), c.planned),
            bodies: c
                .all
                .iter()
                .map(|(spec, d)| match &d.run {
                    None => BodyPicture {
                        rows: String::new(),
                        caption: format!("s{}: not finished", spec.seed),
                    },
                    Some(run) => BodyPicture {
                        rows: run.best.shape.to_rows(),
                        caption: match d.validation_mean(ValidationSet::Unseen) {
                            Some(v) => format!("s{}: {v:.2}", spec.seed),
                            None => format!("s{}: not validated", spec.seed),
                        },
                    },
                })
                .collect(),
        })
        .collect();
    let file = format!("codesign-{name}-bodies.svg");
    let _ = writeln!(r.markdown, "![the final best body of every run]({file})\n");
    r.figures.push(Figure {
        file,
        title: format!("body search {name}: the final best body of every run"),
        x_label: String::new(),
        y_label: String::new(),
        plot: Plot::Bodies(rows),
        notes: vec![
            "under each body: its seed and its mean velocity on the 10 unseen terrains (m/s)"
                .into(),
        ],
    });
}
