//! The report's tables: a summary of each measure per sample (median and quartiles across
//! seeds) and every pairwise comparison of a section (the planned tests of `families`).

use super::families::{Comparison, ALPHA, POWER};
use super::samples::{measures, Sample};
use crate::statistics::{Method, Summary};
use std::fmt::Write;
use vsr::experiment::ValidationSet;

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

/// The section's comparisons: medians, raw and Holm-adjusted p, the shift A - B and A12
/// with their intervals, the smallest detectable A12, and the outcome in words.
pub(super) fn comparisons(rows: &[&Comparison], md: &mut String) {
    if rows.is_empty() {
        return;
    }
    let level = 100.0 * (1.0 - ALPHA);
    let _ = writeln!(
        md,
        "Mann-Whitney U, two-sided (e: exact, n: normal approximation); p (Holm) within the \
         family named, of k tests; shift: Hodges-Lehmann A - B (m/s) with its exact {level:.0}% \
         interval; A12 = P(A > B) with its {level:.0}% bootstrap interval; detectable: the \
         smallest A12 these sample sizes detect with {:.0}% power:\n",
        100.0 * POWER
    );
    let _ = writeln!(
        md,
        "| A | B | measure | n | median A | median B | p | p (Holm) | shift [CI] | A12 [CI] | detectable | outcome |"
    );
    let _ = writeln!(md, "|---|---|---|---|---|---|---|---|---|---|---|---|");
    for c in rows {
        let method = match c.test.method {
            Method::Exact => "e",
            Method::Normal => "n",
        };
        let family = if c.family == c.group {
            format!("k={}", c.holm.1)
        } else {
            format!("`{}`, k={}", c.family, c.holm.1)
        };
        let (s, a) = (&c.shift, &c.a12);
        let _ = writeln!(
            md,
            "| {} | {} | {} | {}+{} | {:.3} | {:.3} | {:.4} {method} | {:.4} ({family}) | {:.3} [{:.3}, {:.3}] | {:.2} [{:.2}, {:.2}] | {:.2} | {} |",
            c.a,
            c.b,
            c.measure,
            c.test.n1,
            c.test.n2,
            c.medians.0,
            c.medians.1,
            c.test.p,
            c.holm.0,
            s.estimate,
            s.interval.low,
            s.interval.high,
            c.test.a12,
            a.low,
            a.high,
            c.detectable.a12,
            c.outcome()
        );
    }
    md.push('\n');
}

/// The families of the planned tests: for each, its size and what it detected.
pub(super) fn families_table(rows: &[Comparison], md: &mut String) {
    let mut families: Vec<(String, String)> = Vec::new();
    for c in rows.iter().filter(|c| c.family == c.group) {
        let key = (c.family.clone(), c.measure.clone());
        if !families.contains(&key) {
            families.push(key);
        }
    }
    if families.is_empty() {
        return;
    }
    let _ = writeln!(
        md,
        "## Families of tests\n\nA family is one group's comparisons on one measure, across its \
         shapes and budgets (docs/ANALYSIS-PLAN.md); Holm's correction within each, familywise \
         alpha = {ALPHA}. A pair tested in an earlier group is listed again, not retested.\n"
    );
    let _ = writeln!(
        md,
        "| group | measure | tests | detected (Holm p < {ALPHA}) |"
    );
    let _ = writeln!(md, "|---|---|---|---|");
    for (family, measure) in families {
        let members: Vec<&Comparison> = rows
            .iter()
            .filter(|c| c.family == family && c.group == family && c.measure == measure)
            .collect();
        let found: Vec<String> = members
            .iter()
            .filter(|c| c.holm.0 < ALPHA)
            .map(|c| format!("{} ({}, p = {:.4})", c.outcome(), c.shape, c.holm.0))
            .collect();
        let found = if found.is_empty() {
            "none".to_string()
        } else {
            found.join("; ")
        };
        let _ = writeln!(md, "| {family} | {measure} | {} | {found} |", members.len());
    }
    md.push('\n');
}
