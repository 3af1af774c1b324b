//! The fourth question's section (`[[any_body]]` groups; docs/ANALYSIS-PLAN.md, families 11
//! and 12): does a brain with no messages, trained on many bodies, walk on bodies it never saw?
//!
//! Per run, the primary measure is the median over `heldout-random` of each body's mean speed
//! on the unseen terrains (the `median` of its `vsr validate --bodies` file). Families, each
//! Holm over its two one-sided tests at 0.025 (`family`: the tests, their table and words):
//! - 11: attention-any against mlp-any (superiority), attention-any against mlp-comm-any
//!   (non-inferiority at 0.2 m/s; superiority next where it is shown), on the group that
//!   trains all three;
//! - 12: attention-any on the larger training set against the main one, and the main one
//!   against the biped alone (superiority: more bodies, faster on held-out bodies).
//!
//! No test, estimate or figure of a family is printed until every planned run of its
//! conditions has its primary validation: before that, only how many runs each condition has
//! (no interim result is read). Secondary measures (each held-out set, the training-to-held-out
//! gap, the share of held-out bodies above 1 m/s) are estimates (`estimates`), printed with
//! the tests, and so are the figures (`pictures`) and the paper's four shapes one by one
//! (`shapes`). An episode that exploded in a validation
//! counts as 0 m/s (the plan's amendment 1); every table says how many its figures include.
//! A run whose primary median is not a number is not counted as found: it is said, and the
//! families wait. The floor (random brains, `floor`) is printed whenever its
//! files are in: it reads no run.

mod estimates;
mod family;
mod floor;
mod pictures;
mod shapes;

use super::Report;
use crate::campaign::any_body::{set_stem, AnyBodyGroup};
use crate::campaign::{AnyBodyData, AnyBodySpec, Results};
use std::fmt::Write;
use vsr::controllers::ControllerKind;
use vsr::experiment::ValidationSet;

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
    /// The primary measure of each run that has it as a number (a run whose median is not a
    /// number is counted by [`Condition::not_a_number`], never silently dropped by a test).
    fn primary(&self) -> Vec<f64> {
        self.measure(|d| value(d, PRIMARY, |v| v.median))
    }

    /// How many runs have a primary validation whose median is not a number.
    fn not_a_number(&self) -> usize {
        let all = self
            .runs
            .iter()
            .filter_map(|d| value(d, PRIMARY, |v| v.median));
        all.filter(|v| v.is_nan()).count()
    }

    /// `f` of each run that has it, NaN left out (see `not_a_number`).
    fn measure(&self, f: impl Fn(&AnyBodyData) -> Option<f64>) -> Vec<f64> {
        self.runs
            .iter()
            .filter_map(|d| f(d))
            .filter(|v| !v.is_nan())
            .collect()
    }

    fn complete(&self) -> bool {
        self.primary().len() == self.planned
    }
}

/// The exploded episodes (counted as 0 m/s) of `c`'s runs on the set `stem`, unseen terrains.
fn exploded(c: &Condition, stem: &str) -> u32 {
    let key = (stem.to_string(), ValidationSet::Unseen);
    let each = c.runs.iter().filter_map(|d| d.validation.get(&key));
    each.map(|v| v.exploded).sum()
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

/// What the families' samples hold beyond the runs' figures: exploded episodes of the primary
/// measure (counted as 0 m/s), and a condition trained on fewer bodies per evaluation.
fn family_notes(conditions: &[&Condition], md: &mut String) {
    for c in conditions {
        let n = exploded(c, PRIMARY);
        if n > 0 {
            let _ = writeln!(
                md,
                "{}: {n} episode{} on {PRIMARY} exploded, each counted as 0 m/s (the plan's                  amendment 1).\n",
                c.label,
                if n == 1 { "" } else { "s" }
            );
        }
    }
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
    for c in all.iter().filter(|c| c.not_a_number() > 0) {
        let _ = writeln!(
            md,
            "{}: {} run(s) with a primary validation whose median is not a number: not counted \
             as found, so the families wait for them.\n",
            c.label,
            c.not_a_number()
        );
    }
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
            md.push_str(family::LEGEND);
            let (a_, m_, c_) = (
                (a.label.as_str(), &x[..]),
                (m.label.as_str(), &y[..]),
                (mc.label.as_str(), &z[..]),
            );
            family::family11(a_, m_, c_, mc.controller, md);
            family_notes(&[a, m, mc], md);
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
            if family11.is_none() {
                md.push_str(family::LEGEND);
            }
            family::family12(
                (larger.label.as_str(), &l[..]),
                (main_att.label.as_str(), &m[..]),
                (one.label.as_str(), &o[..]),
                md,
            );
            family_notes(&[larger, main_att, one], md);
            estimates::fewer_episodes(&[larger, main_att, one], md);
        } else {
            md.push_str(
                "Its tests wait for every planned run of the three conditions (no interim result \
                 is read).\n\n",
            );
        }
    }
    let ready = all.iter().all(|c| c.complete());
    if ready {
        estimates::estimates(&all, md);
        shapes::paper_shapes(&all, md);
    }
    floor::floor_section(results, md);
    pictures::figures(results, &all, ready, r);
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::campaign::Campaign;
    use vsr::experiment::body_set::BodiesValidation;

    const GROUP: &str = r#"
output = "out"
seeds = [1, 2]
[[any_body]]
name = "a"
bodies = "train.txt"
controllers = ["attention-any"]
evals = 20
heldout = ["heldout-random.txt"]
"#;

    fn run(median: f64, exploded: u32) -> AnyBodyData {
        let mut d = AnyBodyData::default();
        let v = BodiesValidation {
            bodies: "heldout-random.txt".into(),
            set: ValidationSet::Unseen,
            seconds: 30.0,
            median,
            walking_share: 0.0,
            per_body: Vec::new(),
            exploded,
        };
        d.validation
            .insert((PRIMARY.to_string(), ValidationSet::Unseen), v);
        d
    }

    /// A run whose primary median is not a number is neither found nor silently left out of
    /// a test: the condition stays incomplete, so its family waits; exploded episodes add up.
    #[test]
    fn a_nan_primary_is_counted_apart_and_keeps_the_family_waiting() {
        let campaign = Campaign::parse(GROUP).unwrap();
        let (a, b) = (run(0.5, 2), run(f64::NAN, 1));
        let c = Condition {
            label: "attention-any on train".into(),
            controller: ControllerKind::AttentionAny,
            group: &campaign.any_body[0],
            runs: vec![&a, &b],
            planned: 2,
        };
        assert_eq!(c.primary(), [0.5]);
        assert_eq!(c.not_a_number(), 1);
        assert!(!c.complete());
        assert_eq!(exploded(&c, PRIMARY), 3);
        let c = Condition {
            runs: vec![&a],
            planned: 1,
            ..c
        };
        assert!(c.complete());
    }
}
