//! The fourth question's secondary measures, estimates and not tested (docs/ANALYSIS-PLAN.md,
//! amendment 4): per condition, the median over its runs with the median's 95% interval
//! (order statistics) and the quartiles, of each body set's median, the training-to-held-out
//! gap and the share of held-out bodies above 1 m/s. A cell that includes an exploded episode
//! (counted as 0 m/s, amendment 1) says how many; a cell of a set that holds one of the
//! condition's own training bodies is marked, and a condition trained on one body per
//! evaluation is said to have had a fraction of the others' episodes.

use super::pictures::trained_on;
use super::{exploded, value, Condition, PRIMARY};
use crate::campaign::any_body::set_stem;
use crate::statistics::{median_interval, Summary};
use std::fmt::Write;
use vsr::experiment::ValidationSet;

/// The mark of a cell whose set holds one of the condition's own training bodies.
const OWN_BODY: &str = "†";

/// Median [95% interval] (q1 to q3) of `v`, with the exploded episodes it includes.
fn cell(v: &[f64], exploded: u32) -> String {
    let (Some(i), false) = (median_interval(v, 0.05), v.is_empty()) else {
        return "-".into();
    };
    let s = Summary::of(v);
    let mut out = format!(
        "{:.2} [{:.2}, {:.2}] ({:.2} to {:.2})",
        s.median, i.low, i.high, s.q1, s.q3
    );
    if exploded > 0 {
        let _ = write!(out, ", {exploded} exploded");
    }
    out
}

/// Whether the set `stem` (as the runs walked it) holds one of `c`'s training bodies.
fn holds_own_body(c: &Condition, stem: &str) -> bool {
    let own = trained_on(c);
    let walked = c
        .runs
        .iter()
        .find_map(|d| d.validation.get(&(stem.to_string(), ValidationSet::Unseen)));
    walked.is_some_and(|w| w.per_body.iter().any(|b| own.contains(&b.body.to_rows())))
}

/// The estimates' table and what its marks mean.
pub(super) fn estimates(all: &[Condition], md: &mut String) {
    // The order statistics' interval covers at least 95%: the nearest attainable for the runs.
    let runs = all.first().map_or(0, |c| c.primary().len());
    let coverage = median_interval(&vec![0.0; runs], 0.05).map_or(0.95, |i| i.coverage);
    let _ = write!(
        md,
        "### Estimates (secondary, not tested)\n\nPer condition, over its runs (m/s): the \
         median [its interval by order statistics, the narrowest that covers at least 95%: \
         {:.0}% for {runs} runs] (first to third quartile).\n\n",
        100.0 * coverage
    );
    let sets: Vec<String> = all
        .first()
        .map(|c| {
            let held = c.group.validated_on();
            held.iter()
                .take(c.group.heldout.len())
                .map(|b| set_stem(b))
                .collect()
        })
        .unwrap_or_default();
    let mut header = String::from("| condition |");
    for s in &sets {
        let _ = write!(header, " {s} |");
    }
    header.push_str(
        " training set | gap (training - heldout-random) | share of heldout-random above 1 m/s |\n",
    );
    md.push_str(&header);
    md.push_str(&format!("|{}\n", "---|".repeat(sets.len() + 4)));
    let mut marked = false;
    for c in all {
        let train = set_stem(&c.group.bodies);
        let mut row = format!("| {} |", c.label);
        for s in sets.iter().chain([&train]) {
            let mut text = cell(&c.measure(|d| value(d, s, |v| v.median)), exploded(c, s));
            if *s != train && holds_own_body(c, s) {
                text.push_str(OWN_BODY);
                marked = true;
            }
            let _ = write!(row, " {text} |");
        }
        let gap =
            c.measure(|d| Some(value(d, &train, |v| v.median)? - value(d, PRIMARY, |v| v.median)?));
        let both = exploded(c, &train) + exploded(c, PRIMARY);
        let share = c.measure(|d| value(d, PRIMARY, |v| v.walking_share));
        let _ = writeln!(
            row,
            " {} | {} |",
            cell(&gap, both),
            cell(&share, exploded(c, PRIMARY))
        );
        md.push_str(&row);
    }
    md.push('\n');
    if marked {
        let _ = writeln!(
            md,
            "{OWN_BODY} The set holds one of the condition's own training bodies: for it, that \
             set is not held out.\n"
        );
    }
    fewer_episodes(&all.iter().collect::<Vec<_>>(), md);
    md.push_str(
        "\"k exploded\": episodes whose state became non-finite, each counted as 0 m/s (the \
         plan's amendment 1); a cell without it has none. The figures below hold the same \
         episodes.\n\n",
    );
}

/// The conditions trained on fewer bodies per evaluation than the most of `all`, each with
/// that most: the same evaluations, a fraction of the episodes.
pub(super) fn fewer_bodies<'a, 'b>(all: &[&'a Condition<'b>]) -> Vec<(&'a Condition<'b>, usize)> {
    let most = all
        .iter()
        .map(|c| c.group.per_evaluation)
        .max()
        .unwrap_or(1);
    all.iter()
        .filter(|c| c.group.per_evaluation < most)
        .map(|&c| (c, most))
        .collect()
}

/// A sentence per condition trained on fewer bodies per evaluation than the most: the same
/// evaluations, that fraction of the episodes (stated, not corrected).
pub(super) fn fewer_episodes(all: &[&Condition], md: &mut String) {
    for (c, most) in fewer_bodies(all) {
        let per = c.group.per_evaluation;
        let _ = writeln!(
            md,
            "{} walked {per} bod{} per evaluation against {most} for the others: the same \
             evaluations, {} of their training episodes (stated, not corrected).\n",
            c.label,
            if per == 1 { "y" } else { "ies" },
            if most == 4 * per {
                "a quarter".to_string()
            } else {
                format!("{per}/{most}")
            }
        );
    }
}
