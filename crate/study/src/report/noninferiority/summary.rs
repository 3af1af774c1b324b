//! The non-inferiority test's answer for a reader other than a person: `noninferiority.json`
//! beside `report.md`, which the page's "What our study found" reads (so the page never
//! copies the verdict by hand). It gives how many of the planned runs exist, arm by arm, and
//! the primary measure's verdicts **only once every planned run of every shape exists** (the
//! plan's test is Holm over the shapes at the planned sample size): until then no number of
//! the comparison is in the file, so nothing reads an interim result as the answer.

use super::{arm, complete, tests};
use crate::campaign::file::{EvolveGroup, NonInferiority};
use crate::campaign::Results;
use serde::Serialize;

/// The file's name in the report folder.
pub const FILE: &str = "noninferiority.json";

/// The whole file: one group's test.
#[derive(Debug, Clone, Serialize)]
pub struct Summary {
    /// The evolve group.
    pub group: String,
    /// The controller claimed not worse, and the one it is compared with.
    pub treatment: String,
    /// See `treatment`.
    pub control: String,
    /// The margin (m/s).
    pub margin: f64,
    /// The primary measure's validation set.
    pub set: String,
    /// Runs the test needs: every seed of both arms on every shape and budget.
    pub planned_runs: usize,
    /// Of those, the runs validated on the primary set.
    pub finished_runs: usize,
    /// Whether every planned run is in (then `shapes` carries the answers).
    pub complete: bool,
    /// Shape by shape (and budget), in the campaign's order.
    pub shapes: Vec<ShapeSummary>,
}

/// One shape and budget.
#[derive(Debug, Clone, Serialize)]
pub struct ShapeSummary {
    /// Shape as the campaign names it.
    pub shape: String,
    /// Budget.
    pub evals: u64,
    /// Runs per arm the plan asks for.
    pub planned: usize,
    /// Validated runs of the treatment and the control so far.
    pub finished: [usize; 2],
    /// The test's answer, present only when the whole test is complete.
    pub answer: Option<Answer>,
}

/// The planned test's answer on one shape (the primary set).
#[derive(Debug, Clone, Serialize)]
pub struct Answer {
    /// Medians of the treatment and the control (m/s).
    pub medians: [f64; 2],
    /// Hodges-Lehmann shift treatment - control (m/s) and its two-sided 95% interval.
    pub shift: f64,
    /// See `shift`.
    pub interval: [f64; 2],
    /// The one-sided p and its Holm adjustment over the shapes.
    pub p: f64,
    /// See `p`.
    pub holm_p: f64,
    /// "not worse", "worse" or "not shown" (the plan's verdicts).
    pub verdict: &'static str,
    /// Where non-inferiority is shown: "better" or "not shown better".
    pub superiority: Option<&'static str>,
}

/// The summary of the first group that plans a non-inferiority test (the plan has one).
pub fn summary(results: &Results) -> Option<Summary> {
    let g = results
        .campaign
        .evolve
        .iter()
        .find(|g| g.noninferiority.is_some())?;
    Some(of(results, g, g.noninferiority.as_ref()?))
}

impl Summary {
    /// The file's text.
    pub fn json(&self) -> String {
        serde_json::to_string_pretty(self).expect("a summary serialises") + "\n"
    }

    /// One line for a terminal: how far the test has come, or its verdicts.
    pub fn line(&self) -> String {
        let head = format!(
            "non-inferiority of {} against {} (margin {} m/s, {} mean)",
            self.treatment, self.control, self.margin, self.set
        );
        if !self.complete {
            return format!(
                "{head}: {} of {} runs validated; no verdict until all are in",
                self.finished_runs, self.planned_runs
            );
        }
        let verdicts: Vec<String> = self
            .shapes
            .iter()
            .filter_map(|s| Some(format!("{} {}", s.shape, s.answer.as_ref()?.verdict)))
            .collect();
        format!("{head}: {}", verdicts.join(", "))
    }
}

fn of(results: &Results, g: &EvolveGroup, n: &NonInferiority) -> Summary {
    let seeds = g.seeds.as_ref().unwrap_or(&results.campaign.seeds);
    let set = *n
        .sets
        .first()
        .expect("a non-inferiority test names its sets");
    let mut shapes = Vec::new();
    for shape in &g.shapes {
        for &evals in &g.evals {
            let count = |c| arm(results, (shape, c, evals), seeds, set).len();
            shapes.push(ShapeSummary {
                shape: shape.clone(),
                evals,
                planned: seeds.len(),
                finished: [count(n.treatment), count(n.control)],
                answer: None,
            });
        }
    }
    let planned_runs = 2 * seeds.len() * shapes.len();
    let finished_runs = shapes.iter().map(|s| s.finished[0] + s.finished[1]).sum();
    let complete = complete(results, g, n);
    if complete {
        for t in tests(results, g, n).iter().filter(|t| t.set == set) {
            let s = shapes
                .iter_mut()
                .find(|s| (s.shape.as_str(), s.evals) == (t.shape.as_str(), t.evals))
                .expect("a test of a planned shape");
            s.answer = Some(Answer {
                medians: [t.medians.0, t.medians.1],
                shift: t.shift.estimate,
                interval: [t.shift.interval.low, t.shift.interval.high],
                p: t.test.p,
                holm_p: t.holm.0,
                verdict: t.verdict.name(),
                superiority: t.superiority_words().map(|w| w.trim_matches('*')),
            });
        }
    }
    Summary {
        group: g.name.clone(),
        treatment: n.treatment.to_string(),
        control: n.control.to_string(),
        margin: n.margin,
        set: set.to_string(),
        planned_runs,
        finished_runs,
        complete,
        shapes,
    }
}
