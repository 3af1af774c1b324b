//! The fourth question's section (`[[any_body]]` groups; docs/ANALYSIS-PLAN.md, families 11
//! and 12): does a brain with no messages, trained on many bodies, walk on bodies it never saw?
//!
//! Per run, the primary measure is the median over `heldout-random` of each body's mean speed
//! on the unseen terrains (the `median` of its `vsr validate --bodies` file). Families, each
//! Holm over its two one-sided tests at [`ONE_SIDED_ALPHA`]:
//! - 11: attention-any against mlp-any (superiority), attention-any against mlp-comm-any
//!   (non-inferiority at [`MARGIN`] m/s; superiority next where it is shown), on the group
//!   that trains all three;
//! - 12: attention-any on the larger training set against the main one, and the main one
//!   against the biped alone (superiority: more bodies, faster on held-out bodies).
//!
//! No test, estimate or figure of a family is printed until every planned run of its
//! conditions has its primary validation: before that, only how many runs each condition has
//! (no interim result is read). Secondary measures (each held-out set, the training-to-held-out
//! gap, the share of held-out bodies above 1 m/s) are estimates, printed with the tests, and
//! so are the figures (`pictures`). The floor (random brains, `floor`) is printed whenever its
//! files are in: it reads no run.

mod floor;
mod pictures;

use super::noninferiority::{Verdict, ONE_SIDED_ALPHA};
use super::Report;
use crate::campaign::any_body::{set_stem, AnyBodyGroup};
use crate::campaign::{AnyBodyData, AnyBodySpec, Results};
use crate::statistics::{
    a12_interval, hodges_lehmann, holm, mann_whitney, mann_whitney_greater, noninferiority, Summary,
};
use std::fmt::Write;
use vsr::controllers::ControllerKind;
use vsr::experiment::ValidationSet;

/// The non-inferiority margin of family 11 (m/s), fixed in the plan.
pub const MARGIN: f64 = 0.2;
/// The held-out set of the primary measure.
pub const PRIMARY: &str = "heldout-random";

/// One condition: a group's runs of one controller, with their data in seed order.
struct Condition<'a> {
    label: String,
    controller: ControllerKind,
    group: &'a AnyBodyGroup,
    runs: Vec<&'a AnyBodyData>,
    planned: usize,
}

impl Condition<'_> {
    /// The primary measure of each run that has it.
    fn primary(&self) -> Vec<f64> {
        self.measure(|d| value(d, PRIMARY, |v| v.median))
    }

    fn measure(&self, f: impl Fn(&AnyBodyData) -> Option<f64>) -> Vec<f64> {
        self.runs.iter().filter_map(|d| f(d)).collect()
    }

    fn complete(&self) -> bool {
        self.primary().len() == self.planned
    }
}

/// A run's figure `f` on the body set `stem`, on the unseen terrains.
fn value(
    d: &AnyBodyData,
    stem: &str,
    f: impl Fn(&vsr::experiment::body_set::BodiesValidation) -> f64,
) -> Option<f64> {
    d.validation
        .get(&(stem.to_string(), ValidationSet::Unseen))
        .map(f)
}

fn conditions<'a>(results: &'a Results) -> Vec<Condition<'a>> {
    let mut out = Vec::new();
    for g in &results.campaign.any_body {
        for &controller in &g.controllers {
            let mine = |s: &AnyBodySpec| s.group == g.name && s.controller == controller;
            let runs: Vec<&AnyBodyData> = results
                .any_body
                .iter()
                .filter(|(s, _)| mine(s))
                .map(|(_, d)| d)
                .collect();
            out.push(Condition {
                label: format!("{controller} on {}", set_stem(&g.bodies)),
                controller,
                group: g,
                planned: runs.len(),
                runs,
            });
        }
    }
    out
}

/// One one-sided test's line: what, shift with interval, A12, p, Holm p, verdict.
struct Line {
    what: String,
    shift: String,
    a12: String,
    p: f64,
}

fn line(what: String, x: &[f64], y: &[f64], p: f64) -> Line {
    let shift = hodges_lehmann(x, y, 0.05).map_or("-".into(), |s| {
        format!(
            "{:+.2} [{:+.2}, {:+.2}]",
            s.estimate, s.interval.low, s.interval.high
        )
    });
    let a12 = a12_interval(x, y, 0.05).map_or("-".into(), |i| {
        format!(
            "{:.2} [{:.2}, {:.2}]",
            mann_whitney(x, y).a12,
            i.low,
            i.high
        )
    });
    Line {
        what,
        shift,
        a12,
        p,
    }
}

fn family_table(md: &mut String, lines: &[Line], verdicts: &[String]) {
    let adjusted = holm(&lines.iter().map(|l| l.p).collect::<Vec<_>>());
    md.push_str(
        "| test (H1) | shift (m/s) [95%] | A12 [95%] | p (one-sided) | Holm p | answer |\n",
    );
    md.push_str("|---|---|---|---|---|---|\n");
    for ((l, h), v) in lines.iter().zip(&adjusted).zip(verdicts) {
        let _ = writeln!(
            md,
            "| {} | {} | {} | {:.4} | {:.4} | {v} |",
            l.what, l.shift, l.a12, l.p, h
        );
    }
    md.push('\n');
}

/// "difference detected" / "no difference detected" for a superiority test's Holm p.
fn better(holm_p: f64) -> String {
    if holm_p < ONE_SIDED_ALPHA {
        "faster (difference detected)".into()
    } else {
        "no difference detected".into()
    }
}

fn find<'a>(
    all: &'a [Condition<'a>],
    controller: ControllerKind,
    several: bool,
) -> Vec<&'a Condition<'a>> {
    all.iter()
        .filter(|c| c.label.starts_with(&format!("{controller} on")))
        .filter(|c| !several || c.group.controllers.len() > 1)
        .collect()
}

/// Appends the section (nothing when the campaign has no `[[any_body]]` group).
pub fn any_body_section(results: &Results, r: &mut Report) {
    if results.campaign.any_body.is_empty() {
        return;
    }
    let all = conditions(results);
    let md = &mut r.markdown;
    md.push_str("## One brain for every body (families 11 and 12)\n\n");
    md.push_str(
        "Primary measure per run: the median over heldout-random of each body's mean speed on \
         the ten unseen terrains.\n\n| condition | runs finished | primary measure found |\n|---|---|---|\n",
    );
    for c in &all {
        let finished = c.runs.iter().filter(|d| d.finished).count();
        let _ = writeln!(
            md,
            "| {} | {finished} of {} | {} |",
            c.label,
            c.planned,
            c.primary().len()
        );
    }
    md.push('\n');
    let attention = ControllerKind::AttentionAny;
    // Family 11: the group that trains all three families.
    let main = find(&all, attention, true);
    let family11 = main.first().and_then(|a| {
        let same = |k| {
            all.iter()
                .find(|c| std::ptr::eq(c.group, a.group) && c.label.starts_with(&format!("{k} on")))
        };
        Some((
            *a,
            same(ControllerKind::MlpAny)?,
            same(ControllerKind::MlpCommAny)?,
        ))
    });
    if let Some((a, m, mc)) = family11 {
        md.push_str(
            "### Family 11: attention for any body against MLP and MLP-Comm for any body\n\n",
        );
        if [a, m, mc].iter().all(|c| c.complete()) {
            let (x, y, z) = (a.primary(), m.primary(), mc.primary());
            let sup = mann_whitney_greater(&x, &y).p;
            let ni = noninferiority(&x, &z, MARGIN).p;
            let lines = [
                line(format!("{} faster than {}", a.label, m.label), &x, &y, sup),
                line(
                    format!(
                        "{} not slower than {} by {MARGIN} m/s or more",
                        a.label, mc.label
                    ),
                    &x,
                    &z,
                    ni,
                ),
            ];
            let adjusted = holm(&[sup, ni]);
            let high = hodges_lehmann(&x, &z, 0.05).map_or(f64::NAN, |s| s.interval.high);
            let verdict = Verdict::of(adjusted[1], high, MARGIN);
            let mut ni_words = verdict.name().to_string();
            if verdict == Verdict::NotWorse {
                let p = mann_whitney_greater(&x, &z).p;
                let _ = write!(ni_words, "; better: {} (p {p:.4})", better(p));
            }
            family_table(md, &lines, &[better(adjusted[0]), ni_words]);
        } else {
            md.push_str(
                "Its tests wait for every planned run of the three conditions (no interim result \
                 is read).\n\n",
            );
        }
    }
    // Family 12: scaling.
    let att: Vec<&Condition> = all
        .iter()
        .filter(|c| c.label.starts_with("attention-any on"))
        .collect();
    let main_set = family11.map(|(a, _, _)| a.group.bodies.clone());
    let main_att = att
        .iter()
        .find(|c| Some(&c.group.bodies) == main_set.as_ref());
    let larger = att
        .iter()
        .find(|c| c.group.per_evaluation > 1 && Some(&c.group.bodies) != main_set.as_ref());
    let one = att.iter().find(|c| c.group.per_evaluation == 1);
    if let (Some(main_att), Some(larger), Some(one)) = (main_att, larger, one) {
        md.push_str("### Family 12: more training bodies, faster on bodies never seen?\n\n");
        if [main_att, larger, one].iter().all(|c| c.complete()) {
            let (l, m, o) = (larger.primary(), main_att.primary(), one.primary());
            let (p1, p2) = (
                mann_whitney_greater(&l, &m).p,
                mann_whitney_greater(&m, &o).p,
            );
            let lines = [
                line(
                    format!("{} faster than {}", larger.label, main_att.label),
                    &l,
                    &m,
                    p1,
                ),
                line(
                    format!("{} faster than {}", main_att.label, one.label),
                    &m,
                    &o,
                    p2,
                ),
            ];
            let adjusted = holm(&[p1, p2]);
            family_table(md, &lines, &[better(adjusted[0]), better(adjusted[1])]);
        } else {
            md.push_str(
                "Its tests wait for every planned run of the three conditions (no interim result \
                 is read).\n\n",
            );
        }
    }
    let ready = all.iter().all(|c| c.complete());
    if ready {
        estimates(&all, md);
    }
    floor::floor_section(results, md);
    pictures::figures(results, &all, ready, r);
}

/// Secondary measures, per condition: median [q1, q3] over runs of each set's median, the gap
/// and the share above 1 m/s.
fn estimates(all: &[Condition], md: &mut String) {
    md.push_str("### Estimates (secondary, not tested)\n\nMedian [q1, q3] over runs (m/s).\n\n");
    let sets: Vec<String> = all
        .first()
        .map(|c| {
            c.group
                .validated_on()
                .iter()
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
    let cell = |v: Vec<f64>| {
        let s = Summary::of(&v);
        if v.is_empty() {
            "-".to_string()
        } else {
            format!("{:.2} [{:.2}, {:.2}]", s.median, s.q1, s.q3)
        }
    };
    for c in all {
        let train = set_stem(&c.group.bodies);
        let mut row = format!("| {} |", c.label);
        for s in &sets {
            let _ = write!(row, " {} |", cell(c.measure(|d| value(d, s, |v| v.median))));
        }
        let _ = write!(
            row,
            " {} |",
            cell(c.measure(|d| value(d, &train, |v| v.median)))
        );
        let gap =
            c.measure(|d| Some(value(d, &train, |v| v.median)? - value(d, PRIMARY, |v| v.median)?));
        let _ = write!(row, " {} |", cell(gap));
        let share = c.measure(|d| value(d, PRIMARY, |v| v.walking_share));
        let _ = writeln!(row, " {} |", cell(share));
        md.push_str(&row);
    }
    md.push('\n');
}
