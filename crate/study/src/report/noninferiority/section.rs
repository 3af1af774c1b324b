//! The non-inferiority section of the report: for every evolve group with a
//! `noninferiority` key, the tests of `noninferiority` set by set (the primary first) with
//! their intervals and verdicts (and, once a set's tests are at their planned size, the
//! figure of their intervals: `figure`), then the known seeds' values beside
//! them, never pooled.

use super::super::families::ALPHA;
use super::super::Report;
use super::figure::{figure, file};
use super::{arm, complete, tests as planned_tests, Test, ONE_SIDED_ALPHA};
use crate::campaign::file::{EvolveGroup, NonInferiority};
use crate::campaign::Results;
use crate::statistics::{hodges_lehmann, mann_whitney, median, Method};
use std::fmt::Write;

/// The sections of every group that plans a non-inferiority test.
pub(crate) fn noninferiority_sections(results: &Results, r: &mut Report) {
    for g in &results.campaign.evolve {
        if let Some(n) = &g.noninferiority {
            section(results, g, n, r);
        }
    }
}

fn section(results: &Results, g: &EvolveGroup, n: &NonInferiority, r: &mut Report) {
    let md = &mut r.markdown;
    let (t, c, m) = (n.treatment, n.control, n.margin);
    let level = 100.0 * (1.0 - ALPHA);
    let _ = writeln!(
        md,
        "## Non-inferiority: {t} against {c} (group `{}`)\n\nIs {t} **not worse** than {c} \
         by {m} m/s or more? H0: {t}'s location is below {c}'s by {m} m/s or more. One-sided \
         Mann-Whitney U of ({t} + {m}) against {c} (e: exact, n: normal approximation with \
         the tie correction and a continuity correction), Holm over the shapes of each set at \
         one-sided alpha = {ONE_SIDED_ALPHA}. Shift: Hodges-Lehmann {t} - {c} (m/s) with its \
         distribution-free two-sided {level:.0}% interval (its lower end the one-sided \
         {:.1}% bound); A12 = P({t} > {c}) with its {level:.0}% bootstrap interval. Verdict: \
         not worse where the adjusted p is below {ONE_SIDED_ALPHA}; otherwise worse where \
         the interval's upper end is below -{m}; otherwise not shown. Where non-inferiority \
         is shown, superiority next: one-sided Mann-Whitney of {t} against {c}, Holm over \
         the shapes where it applies, alpha = {ONE_SIDED_ALPHA}.\n",
        g.name,
        100.0 * (1.0 - ALPHA / 2.0)
    );
    if !complete(results, g, n) {
        waiting(results, g, n, md);
        r.withdrawn
            .extend(n.sets.iter().map(|&set| file(&g.name, set)));
        known_part(results, g, n, md);
        return;
    }
    let all = planned_tests(results, g, n);
    for (i, &set) in n.sets.iter().enumerate() {
        let role = if i == 0 { "primary" } else { "secondary" };
        let _ = writeln!(md, "### {set} mean ({role})\n");
        let rows: Vec<&Test> = all.iter().filter(|x| x.set == set).collect();
        if rows.is_empty() {
            let _ = writeln!(md, "No shape has runs of both controllers yet.\n");
            r.withdrawn.push(file(&g.name, set));
            continue;
        }
        let _ = writeln!(
            md,
            "| shape | evals | n | median {t} | median {c} | shift [{level:.0}% CI] | A12 [{level:.0}% CI] | p | p (Holm) | verdict | superiority: p (Holm) |"
        );
        let _ = writeln!(md, "|---|---|---|---|---|---|---|---|---|---|---|");
        for &x in &rows {
            row(x, n, md);
        }
        md.push('\n');
        match figure(g, n, &rows) {
            Some(fig) => {
                let _ = writeln!(md, "![{}]({})\n", fig.title, fig.file);
                r.figures.push(fig);
            }
            None => r.withdrawn.push(file(&g.name, set)),
        }
    }
    known_part(results, g, n, md);
}

/// While a planned run is missing on the primary set: how many each arm has, and nothing
/// compared.
fn waiting(results: &Results, g: &EvolveGroup, n: &NonInferiority, md: &mut String) {
    let seeds = g.seeds.as_ref().unwrap_or(&results.campaign.seeds);
    let set = n.sets[0];
    let _ = writeln!(
        md,
        "**Not yet computed: the test waits for every planned run** (no interim look: the \
         plan fixes the sample size, and its answer is read once). Runs validated on the \
         {set} set so far, of {} per arm:\n",
        seeds.len()
    );
    for shape in &g.shapes {
        for &evals in &g.evals {
            let count = |c| arm(results, (shape, c, evals), seeds, set).len();
            let _ = writeln!(
                md,
                "- {shape}, {evals} evaluations: {} {}, {} {}",
                n.treatment,
                count(n.treatment),
                n.control,
                count(n.control)
            );
        }
    }
    md.push('\n');
}

fn row(x: &Test, n: &NonInferiority, md: &mut String) {
    let method = |u: Method| match u {
        Method::Exact => "e",
        Method::Normal => "n",
    };
    let (s, (a12, ai)) = (&x.shift, &x.a12);
    let (n1, n2) = (x.test.n1, x.test.n2);
    let interim = if n1 < x.planned || n2 < x.planned {
        format!(
            " (interim: {n1}+{n2} of {p}+{p} runs, not the planned test)",
            p = x.planned
        )
    } else {
        String::new()
    };
    let superiority = match (x.superiority, x.superiority_words()) {
        (Some((u, p)), Some(words)) => {
            format!("{:.4} {} ({p:.4}): {words}", u.p, method(u.method))
        }
        _ => "not tested".into(),
    };
    let _ = writeln!(
        md,
        "| {} | {} | {n1}+{n2} | {:.3} | {:.3} | {:+.3} [{:+.3}, {:+.3}] | {a12:.2} [{:.2}, {:.2}] | {:.4} {} | {:.4} (k={}) | {}{interim} | {superiority} |",
        x.shape,
        x.evals,
        x.medians.0,
        x.medians.1,
        s.estimate,
        s.interval.low,
        s.interval.high,
        ai.low,
        ai.high,
        x.test.p,
        method(x.test.method),
        x.holm.0,
        x.holm.1,
        x.verdict.words(n.control, n.margin),
    );
}

/// The known seeds' values beside the test: medians, shift and A12 per set and shape.
fn known_part(results: &Results, g: &EvolveGroup, n: &NonInferiority, md: &mut String) {
    if n.known_seeds.is_empty() {
        return;
    }
    let (t, c) = (n.treatment, n.control);
    let level = 100.0 * (1.0 - ALPHA);
    let _ = writeln!(
        md,
        "### Known before the plan: seeds {}\n\nRuns that existed when the test was planned, \
         shown beside it as what was known; never pooled with the test's runs, not tested.\n",
        seeds_text(&n.known_seeds)
    );
    let _ = writeln!(
        md,
        "| measure | shape | evals | n | median {t} | median {c} | shift [{level:.0}% CI] | A12 |"
    );
    let _ = writeln!(md, "|---|---|---|---|---|---|---|---|");
    for &set in &n.sets {
        for shape in &g.shapes {
            for &evals in &g.evals {
                let x = arm(results, (shape, t, evals), &n.known_seeds, set);
                let y = arm(results, (shape, c, evals), &n.known_seeds, set);
                let Some(s) = hodges_lehmann(&x, &y, ALPHA) else {
                    let _ = writeln!(
                        md,
                        "| {set} mean | {shape} | {evals} | {}+{} | - | - | - | - |",
                        x.len(),
                        y.len()
                    );
                    continue;
                };
                let _ = writeln!(
                    md,
                    "| {set} mean | {shape} | {evals} | {}+{} | {:.3} | {:.3} | {:+.3} [{:+.3}, {:+.3}] | {:.2} |",
                    x.len(),
                    y.len(),
                    median(&x),
                    median(&y),
                    s.estimate,
                    s.interval.low,
                    s.interval.high,
                    mann_whitney(&x, &y).a12
                );
            }
        }
    }
    md.push('\n');
}

/// Seeds as runs of consecutive numbers: "1-10", "1-3, 7".
pub(crate) fn seeds_text(seeds: &[u64]) -> String {
    let mut sorted = seeds.to_vec();
    sorted.sort_unstable();
    let mut parts: Vec<String> = Vec::new();
    let mut i = 0;
    while i < sorted.len() {
        let mut j = i;
        while j + 1 < sorted.len() && sorted[j + 1] == sorted[j] + 1 {
            j += 1;
        }
        parts.push(if j > i {
            format!("{}-{}", sorted[i], sorted[j])
        } else {
            sorted[i].to_string()
        });
        i = j + 1;
    }
    parts.join(", ")
}

#[cfg(test)]
mod tests {
    #[test]
    fn seeds_as_ranges() {
        assert_eq!(super::seeds_text(&[3, 1, 2, 7, 9, 10]), "1-3, 7, 9-10");
        assert_eq!(super::seeds_text(&[5]), "5");
    }
}
