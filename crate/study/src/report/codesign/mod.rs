//! The body-search section of the report (docs/ANALYSIS-PLAN.md, "Body search", families 9
//! and 10), one per `[[codesign]]` group: how many runs finished, each condition's measures
//! (`measures`), the planned tests in the plan's words (`family`), the measures reported as
//! estimates, the exploratory comparisons (not in the plan: attention from scratch against the
//! other brains from scratch) and the figures (`pictures`). Runs in flight are never guessed: a
//! row with fewer runs than planned is marked interim, "not the planned test", as family 8's
//! are. Speeds are written to 2 decimals and QD-scores to 1, the precision docs/RESULTS.md
//! quotes them at, so that a number copied from here is never rounded twice.

mod family;
mod measures;
mod pictures;

use super::families::{ALPHA, POWER};
use super::Report;
use crate::campaign::{CodesignGroup, Results};
use crate::statistics::{Method, Summary};
use family::{exploratory, family, Row};
use measures::{cells, conditions, Condition, Measure};
use std::fmt::Write;
use vsr::experiment::ValidationSet;

/// The sections of every body-search group.
pub(super) fn codesign_sections(results: &Results, r: &mut Report) {
    for g in &results.campaign.codesign {
        section(results, g, r);
    }
}

fn section(results: &Results, g: &CodesignGroup, r: &mut Report) {
    let conds = conditions(results, g);
    let md = &mut r.markdown;
    let _ = writeln!(
        md,
        "## Body search `{}`: what a pretrained module buys (families 9 and 10)\n\n\
         `vsr codesign` from `{}`, {} evaluations per run; conditions {}. Measures of a run: \
         its final best body (the archive's elite with the highest mean training fitness) \
         validated on each set, the archive's QD-score (the sum of the elites' positive mean \
         training speeds) and coverage (filled cells) at the end.\n",
        g.name,
        g.start.as_deref().unwrap_or("the default start body"),
        g.evals,
        g.conditions.join(", ")
    );
    let complete = status(&conds, md);
    summary(&conds, md);
    if !complete {
        let _ = writeln!(
            md,
            "**Verdict pending**: the planned tests are those of every planned run (each \
             condition's {} seeds); a row below with fewer runs is marked interim and is not \
             the planned test, a row without runs of both brains says \"not yet\".\n",
            conds.first().map_or(0, |c| c.planned)
        );
    }
    let unseen = Measure::Velocity(ValidationSet::Unseen);
    let nine = family(&conds, unseen, true);
    let ten = family(&conds, Measure::QdScore, true);
    for (number, m, rows) in [(9, unseen, &nine), (10, Measure::QdScore, &ten)] {
        let role = if number == 9 { "primary" } else { "secondary" };
        let _ = writeln!(md, "### Family {number}: {} ({role})\n", m.name());
        tests_table(rows, m, md);
    }
    let _ = writeln!(md, "### Estimates, not tested: paper mean and coverage\n");
    let paper = Measure::Velocity(ValidationSet::Paper);
    let estimates = [
        (paper, family(&conds, paper, false)),
        (Measure::Coverage, family(&conds, Measure::Coverage, false)),
    ];
    estimates_table(&estimates, md);
    exploratory_table(&exploratory(&conds, unseen), &nine, md);
    let tested: [(Measure, &[Row]); 2] = [(unseen, &nine), (Measure::QdScore, &ten)];
    pictures::figures(&g.name, g.evals, &conds, &tested, r);
}

/// Runs finished and validated per condition, the missing seeds named; whether every
/// planned run is finished and validated on the `unseen` set.
fn status(conds: &[Condition], md: &mut String) -> bool {
    let mut complete = true;
    let _ = writeln!(
        md,
        "| brain | finished | validated (unseen) | not finished (seeds) |\n|---|---|---|---|"
    );
    for c in conds {
        let done = c.finished().count();
        let validated = c.values(Measure::Velocity(ValidationSet::Unseen)).len();
        let missing: Vec<String> = c
            .all
            .iter()
            .filter(|(_, d)| d.run.is_none())
            .map(|(s, _)| s.seed.to_string())
            .collect();
        complete &= validated == c.planned;
        let _ = writeln!(
            md,
            "| {} | {done} of {} | {validated} of {} | {} |",
            c.name,
            c.planned,
            c.planned,
            if missing.is_empty() {
                "-".into()
            } else {
                missing.join(", ")
            }
        );
    }
    if !complete {
        md.push_str(
            "\n**Interim**: not every planned run has finished and been validated. The \
             numbers below are of the runs that exist; no number stands for a missing run.\n",
        );
    }
    md.push('\n');
    complete
}

fn summary(conds: &[Condition], md: &mut String) {
    let cells_of = conds
        .iter()
        .find_map(|c| c.finished().find_map(|(_, d)| d.run.as_ref().map(cells)));
    let measures = [
        Measure::Best,
        Measure::Velocity(ValidationSet::Unseen),
        Measure::Velocity(ValidationSet::Paper),
        Measure::QdScore,
        Measure::Coverage,
    ];
    let names: Vec<String> = measures
        .iter()
        .map(|m| match (m, cells_of) {
            (Measure::Coverage, Some(n)) => format!("coverage (of {n} cells)"),
            _ => m.name(),
        })
        .collect();
    let _ = writeln!(
        md,
        "Median [q1, q3] across seeds (m/s; coverage in cells):\n"
    );
    let _ = writeln!(md, "| brain | {} |", names.join(" | "));
    let _ = writeln!(md, "|---|{}", "---|".repeat(names.len()));
    for c in conds {
        let row: Vec<String> = measures.iter().map(|&m| cell(&c.values(m), m)).collect();
        let _ = writeln!(md, "| {} | {} |", c.name, row.join(" | "));
    }
    md.push('\n');
}

/// Decimals a value of `m` is written with: 2 for a speed (m/s), 1 for a QD-score, 2 for a
/// number of cells (its quartiles are quarters: 21.25 is written whole, never rounded to an
/// even 21.2 here and an upward 21.3 elsewhere).
fn decimals(m: Measure) -> usize {
    match m {
        Measure::Velocity(_) | Measure::Best | Measure::Coverage => 2,
        Measure::QdScore => 1,
    }
}

/// Median [q1, q3] (n) of `values`, to `m`'s decimals; "-" without values.
fn cell(values: &[f64], m: Measure) -> String {
    let s = Summary::of(values);
    let d = decimals(m);
    match s.n {
        0 => "-".into(),
        _ => format!("{:.d$} [{:.d$}, {:.d$}] (n={})", s.median, s.q1, s.q3, s.n),
    }
}

/// Medians, then the shift with its interval, of a comparison on `m`, to its decimals:
/// `median A | median B | shift [low, high]` without the outer bars.
fn medians_and_shift(f: &family::Found, m: Measure) -> String {
    let d = decimals(m);
    let s = &f.shift;
    format!(
        "{:.d$} | {:.d$} | {:+.d$} [{:+.d$}, {:+.d$}]",
        f.medians.0, f.medians.1, s.estimate, s.interval.low, s.interval.high
    )
}

fn tests_table(rows: &[Row], m: Measure, md: &mut String) {
    let runs = match m {
        Measure::Velocity(_) => "finished, validated run",
        _ => "finished run",
    };
    let level = 100.0 * (1.0 - ALPHA);
    let _ = writeln!(
        md,
        "Mann-Whitney U, two-sided (e: exact, n: normal approximation); p (Holm) within the \
         family, of k tests; shift: Hodges-Lehmann A - B with its exact {level:.0}% interval; \
         A12 = P(A > B) with its {level:.0}% bootstrap interval; detectable: the smallest A12 \
         these sizes detect with {:.0}% power.\n",
        100.0 * POWER
    );
    let _ = writeln!(
        md,
        "| A | B | n | median A | median B | p | p (Holm) | shift [CI] | A12 [CI] | detectable | verdict |\n|---|---|---|---|---|---|---|---|---|---|---|"
    );
    for row in rows {
        let n = format!("{}+{}", row.n.0, row.n.1);
        let (Some(f), Some(verdict)) = (&row.found, row.verdict()) else {
            let _ = writeln!(
                md,
                "| {} | {} | {n} | - | - | - | - | - | - | - | not yet: no {runs} of {} |",
                row.a,
                row.b,
                if row.n.0 == 0 { &row.a } else { &row.b }
            );
            continue;
        };
        let (u, holm, k) = f.test.as_ref().expect("tested");
        let method = match u.method {
            Method::Exact => "e",
            Method::Normal => "n",
        };
        let interim = if row.interim() {
            format!(
                " (interim: {n} of {p}+{p} runs, not the planned test)",
                p = row.planned
            )
        } else {
            String::new()
        };
        let (a12, ai) = &f.a12;
        let d = decimals(m);
        let (ma, mb, s) = (f.medians.0, f.medians.1, &f.shift);
        let _ = writeln!(
            md,
            "| {} | {} | {n} | {ma:.d$} | {mb:.d$} | {:.4} {method} | {holm:.4} (k={k}) | {:+.d$} [{:+.d$}, {:+.d$}] | {a12:.2} [{:.2}, {:.2}] | {:.2} | {verdict}{interim} |",
            row.a, row.b, u.p, s.estimate, s.interval.low, s.interval.high, ai.low, ai.high,
            f.detectable.a12
        );
    }
    md.push('\n');
}

fn estimates_table(families: &[(Measure, Vec<Row>)], md: &mut String) {
    let _ = writeln!(
        md,
        "| A | B | measure | n | median A | median B | shift [CI] | A12 [CI] |\n|---|---|---|---|---|---|---|---|"
    );
    for (measure, rows) in families {
        let m = measure.name();
        for row in rows {
            let n = format!("{}+{}", row.n.0, row.n.1);
            let interim = if row.interim() { " (interim)" } else { "" };
            match &row.found {
                None => {
                    let _ = writeln!(
                        md,
                        "| {} | {} | {m} | {n} | - | - | not yet | - |",
                        row.a, row.b
                    );
                }
                Some(f) => {
                    let (a12, ai) = &f.a12;
                    let _ = writeln!(
                        md,
                        "| {} | {} | {m} | {n}{interim} | {} | {a12:.2} [{:.2}, {:.2}] |",
                        row.a,
                        row.b,
                        medians_and_shift(f, *measure),
                        ai.low,
                        ai.high
                    );
                }
            }
        }
    }
    md.push('\n');
}

/// The exploratory comparisons on the primary measure (`family::exploratory`): attention from
/// scratch against each other brain from scratch, beside the frozen module's shift over the
/// same brain (`nine`, family 9), so that the share of that lead which attention alone
/// already has can be read. Chosen after the data; raw p, no correction, no verdict.
fn exploratory_table(rows: &[Row], nine: &[Row], md: &mut String) {
    if rows.is_empty() {
        return;
    }
    let m = Measure::Velocity(ValidationSet::Unseen);
    let _ = writeln!(
        md,
        "### Exploratory, not in the plan: attention against the other brains, both from scratch\n\n\
         Chosen after the data (a reviewer's check): attention evolved from scratch against each \
         other brain evolved from scratch, beside the frozen module's lead over the same brain \
         (family 9), to show how much of that lead attention alone already has. Measure: {} \
         (the primary); p: two-sided Mann-Whitney U of the comparison alone, not corrected and \
         in no family, so no verdict is drawn; shift and A12 as above.\n",
        m.name()
    );
    let _ = writeln!(
        md,
        "| A | B | n | median A | median B | shift [CI] | A12 [CI] | p (raw) | frozen - B (family 9) |\n|---|---|---|---|---|---|---|---|---|"
    );
    let d = decimals(m);
    for row in rows {
        let n = format!("{}+{}", row.n.0, row.n.1);
        let frozen = nine
            .iter()
            .find(|r| r.a == "frozen" && r.b == row.b)
            .and_then(|r| r.found.as_ref())
            .map_or("-".to_string(), |f| {
                let s = &f.shift;
                format!(
                    "{:+.d$} [{:+.d$}, {:+.d$}]",
                    s.estimate, s.interval.low, s.interval.high
                )
            });
        let Some(f) = &row.found else {
            let _ = writeln!(
                md,
                "| {} | {} | {n} | - | - | not yet | - | - | {frozen} |",
                row.a, row.b
            );
            continue;
        };
        let interim = if row.interim() { " (interim)" } else { "" };
        let (a12, ai) = &f.a12;
        let (u, _, _) = f.test.as_ref().expect("tested");
        let method = match u.method {
            Method::Exact => "e",
            Method::Normal => "n",
        };
        let _ = writeln!(
            md,
            "| {} | {} | {n}{interim} | {} | {a12:.2} [{:.2}, {:.2}] | {:.4} {method} | {frozen} |",
            row.a,
            row.b,
            medians_and_shift(f, m),
            ai.low,
            ai.high,
            u.p
        );
    }
    md.push('\n');
}
