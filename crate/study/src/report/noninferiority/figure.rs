//! The non-inferiority test's answer at a glance: for one validation set, each shape's
//! Hodges-Lehmann shift (treatment - control) with its 95% interval, against the margin and
//! against no difference. Drawn **only when every planned run of the set's tests is in**
//! (the plan's test is at its planned size): before that there is no figure, so no
//! interim comparison is drawn.

use super::super::figures::{Figure, IntervalRow, Mark, Plot};
use super::{Test, ONE_SIDED_ALPHA};
use crate::campaign::file::{EvolveGroup, NonInferiority};
use vsr::experiment::ValidationSet;

/// The file of the figure of `group`'s tests on `set`.
pub(super) fn file(group: &str, set: ValidationSet) -> String {
    format!("intervals-{group}-{set}.svg")
}

/// The figure of one set's tests (`tests`: the set's family, every planned shape and budget
/// of the group), or `None` while a test is short of its planned runs or a shape has none.
pub(super) fn figure(g: &EvolveGroup, n: &NonInferiority, tests: &[&Test]) -> Option<Figure> {
    let complete = |t: &&&Test| t.test.n1 == t.planned && t.test.n2 == t.planned;
    let planned = g.shapes.len() * g.evals.len();
    if tests.len() != planned || !tests.iter().all(|t| complete(&t)) {
        return None;
    }
    let set = tests.first()?.set;
    let (t, c, m) = (n.treatment, n.control, n.margin);
    let label = |x: &Test| {
        if g.evals.len() > 1 {
            format!("{} ({} evaluations)", x.shape, x.evals)
        } else {
            x.shape.clone()
        }
    };
    let rows = tests.iter().map(|x| IntervalRow {
        label: label(x),
        estimate: x.shift.estimate,
        low: x.shift.interval.low,
        high: x.shift.interval.high,
    });
    let notes = tests.iter().map(|x| {
        let superiority = match (x.superiority, x.superiority_words()) {
            (Some((_, p)), Some(words)) => {
                format!("; {} (Holm p {p:.4})", words.trim_matches('*'))
            }
            _ => String::new(),
        };
        format!(
            "{}, {}+{} runs: {} (one-sided Holm p {:.4}, alpha {ONE_SIDED_ALPHA}){superiority}",
            label(x),
            x.test.n1,
            x.test.n2,
            x.verdict.name(),
            x.holm.0,
        )
    });
    let key = format!(
        "dot: the shift's estimate (Hodges-Lehmann); bar: its 95% interval; \
         left of -{m}: {t} worse by more than the margin"
    );
    Some(Figure {
        file: file(&g.name, set),
        title: format!("{t} - {c}: mean velocity on the {set} terrains"),
        x_label: format!("{t} - {c} (m/s)"),
        y_label: String::new(),
        plot: Plot::Intervals {
            rows: rows.collect(),
            marks: vec![
                Mark {
                    x: -m,
                    label: format!("-{m}: the margin"),
                },
                Mark {
                    x: 0.0,
                    label: "0: no difference".into(),
                },
            ],
        },
        notes: std::iter::once(key).chain(notes).collect(),
    })
}
