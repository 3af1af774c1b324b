//! The report's tables: a summary of each measure per sample (median and quartiles across
//! seeds) and every pairwise comparison (Mann-Whitney U, A12).

use crate::experiment::ValidationSet;
use crate::study::campaign::RunData;
use crate::study::statistics::{mann_whitney, Summary};
use std::fmt::Write;

/// A labelled sample of runs.
#[derive(Clone)]
pub(super) struct Sample {
    pub(super) label: String,
    pub(super) runs: Vec<RunData>,
}

/// The measures of a sample: `best`, then the validation mean of each set.
fn measures(s: &Sample, sets: &[ValidationSet]) -> Vec<(String, Vec<f64>)> {
    let mut m = vec![(
        "best".to_string(),
        s.runs.iter().filter_map(RunData::final_best).collect(),
    )];
    for &set in sets {
        let values = s.runs.iter().filter_map(|d| d.validation_mean(set));
        m.push((format!("{set} mean"), values.collect()));
    }
    m
}

pub(super) fn cell(values: &[f64]) -> String {
    let s = Summary::of(values);
    match s.n {
        0 => "-".into(),
        _ => format!("{:.3} [{:.3}, {:.3}] (n={})", s.median, s.q1, s.q3, s.n),
    }
}

pub(super) fn summary_table(samples: &[Sample], sets: &[ValidationSet], md: &mut String) {
    let names: Vec<String> = measures(
        &Sample {
            label: String::new(),
            runs: vec![],
        },
        sets,
    )
    .into_iter()
    .map(|(n, _)| n)
    .collect();
    let _ = writeln!(md, "Median [q1, q3] across seeds (m/s):\n");
    let _ = writeln!(md, "| configuration | {} |", names.join(" | "));
    let _ = writeln!(md, "|---|{}", "---|".repeat(names.len()));
    for s in samples {
        let cells: Vec<String> = measures(s, sets).iter().map(|(_, v)| cell(v)).collect();
        let _ = writeln!(md, "| {} | {} |", s.label, cells.join(" | "));
    }
    md.push('\n');
}

/// Every pair of samples, every measure: medians, U test and A12.
pub(super) fn comparisons(samples: &[Sample], sets: &[ValidationSet], md: &mut String) {
    if samples.len() < 2 {
        return;
    }
    let _ = writeln!(md, "Mann-Whitney U, two-sided; A12 = P(A > B):\n");
    let _ = writeln!(
        md,
        "| A | B | measure | median A | median B | U | p | A12 | method |"
    );
    let _ = writeln!(md, "|---|---|---|---|---|---|---|---|---|");
    for (i, a) in samples.iter().enumerate() {
        for b in &samples[i + 1..] {
            for ((name, x), (_, y)) in measures(a, sets).into_iter().zip(measures(b, sets)) {
                if x.is_empty() || y.is_empty() {
                    let _ = writeln!(
                        md,
                        "| {} | {} | {name} | - | - | - | no data | - | - |",
                        a.label, b.label
                    );
                    continue;
                }
                let t = mann_whitney(&x, &y);
                let _ = writeln!(
                    md,
                    "| {} | {} | {name} | {:.3} | {:.3} | {} | {:.4} | {:.2} | {:?} |",
                    a.label,
                    b.label,
                    Summary::of(&x).median,
                    Summary::of(&y).median,
                    t.u1,
                    t.p,
                    t.a12,
                    t.method
                );
            }
        }
    }
    md.push('\n');
}
