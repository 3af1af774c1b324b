//! The non-inferiority test of an evolve group (its `noninferiority` key;
//! docs/ANALYSIS-PLAN.md, family 8): on each shape and budget, is the treatment not worse
//! than the control by the margin or more?
//!
//! For each validation set (the first the primary measure, the others secondary) the shapes
//! and budgets form one family: the one-sided Mann-Whitney p of H0 "the treatment is worse
//! by the margin or more" (`statistics::noninferiority`), Holm-adjusted over the family at
//! one-sided [`ONE_SIDED_ALPHA`]. The verdict, from the adjusted p and the Hodges-Lehmann
//! shift's two-sided 95% interval ([`Verdict`]). Where non-inferiority is shown,
//! superiority is tested next (one-sided Mann-Whitney of the treatment against the control,
//! Holm over the family's shapes where it applies, same alpha): a closed testing order, no
//! further correction.
//!
//! Around the test: its section of the report, with the known seeds' values (`section`), the
//! figure of its intervals (`figure`) and the summary the page reads (`summary`).

pub(super) mod figure;
pub(super) mod section;
pub mod summary;

use super::families::ALPHA;
use crate::campaign::file::{EvolveGroup, NonInferiority};
use crate::campaign::{Results, RunData, RunSpec};
use crate::statistics::{
    a12_interval, hodges_lehmann, holm, mann_whitney, mann_whitney_greater, median, noninferiority,
    Interval, OneSidedU, Shift,
};
use vsr::controllers::ControllerKind;
use vsr::experiment::ValidationSet;

/// The one-sided alpha of every test of the family (two-sided 0.05 halved).
pub const ONE_SIDED_ALPHA: f64 = 0.025;

/// What one test found.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Verdict {
    /// Holm-adjusted p below [`ONE_SIDED_ALPHA`]: not worse by the margin or more.
    NotWorse,
    /// Otherwise, the shift's interval lies wholly below minus the margin: the claim is
    /// contradicted.
    Worse,
    /// Otherwise: inconclusive, the data allow a loss larger than the margin.
    NotShown,
}

impl Verdict {
    /// The verdict of an adjusted p and the upper end of the shift's interval.
    pub fn of(holm_p: f64, shift_high: f64, margin: f64) -> Verdict {
        if holm_p < ONE_SIDED_ALPHA {
            Verdict::NotWorse
        } else if shift_high < -margin {
            Verdict::Worse
        } else {
            Verdict::NotShown
        }
    }

    /// The verdict's short name: "not worse", "worse" or "not shown".
    pub fn name(self) -> &'static str {
        match self {
            Verdict::NotWorse => "not worse",
            Verdict::Worse => "worse",
            Verdict::NotShown => "not shown",
        }
    }

    /// The verdict in the plan's words.
    pub fn words(self, control: ControllerKind, margin: f64) -> String {
        match self {
            Verdict::NotWorse => {
                format!("**not worse** than {control} by {margin} m/s or more (non-inferior)")
            }
            Verdict::Worse => {
                "**worse** by more than the margin (the claim is contradicted)".into()
            }
            Verdict::NotShown => {
                "**not shown**: the data allow a loss larger than the margin".into()
            }
        }
    }
}

/// One test: a shape and budget on one set.
#[derive(Debug, Clone)]
pub struct Test {
    /// Shape as the campaign names it.
    pub shape: String,
    /// Budget.
    pub evals: u64,
    /// The measure: the validation mean on this set.
    pub set: ValidationSet,
    /// The planned number of runs per arm (the group's seeds).
    pub planned: usize,
    /// Medians of the treatment and the control.
    pub medians: (f64, f64),
    /// Hodges-Lehmann shift treatment - control with its two-sided 95% interval.
    pub shift: Shift,
    /// A12 = P(treatment > control) and its 95% bootstrap interval.
    pub a12: (f64, Interval),
    /// The one-sided test of H0 "worse by the margin or more".
    pub test: OneSidedU,
    /// Its Holm-adjusted p within the set's family, and the family's size.
    pub holm: (f64, usize),
    /// The verdict.
    pub verdict: Verdict,
    /// Where non-inferiority is shown: the one-sided test of superiority and its
    /// Holm-adjusted p (over the family's tests that reached it).
    pub superiority: Option<(OneSidedU, f64)>,
}

impl Test {
    /// "better" or "not shown better" where superiority was tested.
    pub fn superiority_words(&self) -> Option<&'static str> {
        let (_, p) = self.superiority?;
        Some(if p < ONE_SIDED_ALPHA {
            "**better**"
        } else {
            "not shown better"
        })
    }
}

/// The values of one arm: the validation means on `set` of the runs of `seeds` that exist.
pub(super) fn arm(
    results: &Results,
    (shape, c, evals): (&str, ControllerKind, u64),
    seeds: &[u64],
    set: ValidationSet,
) -> Vec<f64> {
    let runs = results.seeds_of(&RunSpec::scratch(shape, c, evals, 0), seeds);
    runs.iter()
        .filter_map(|d: &RunData| d.validation_mean(set))
        .collect()
}

/// Whether every planned run of the test is validated on its primary set: both arms, every
/// shape and budget, every seed. Until then no comparison of the group is reported (no
/// interim look: the plan fixes the sample size, and its answer is read once).
pub fn complete(results: &Results, g: &EvolveGroup, n: &NonInferiority) -> bool {
    let seeds = g.seeds.as_ref().unwrap_or(&results.campaign.seeds);
    let Some(&set) = n.sets.first() else {
        return false;
    };
    g.shapes.iter().all(|shape| {
        g.evals.iter().all(|&evals| {
            [n.treatment, n.control]
                .iter()
                .all(|&c| arm(results, (shape, c, evals), seeds, set).len() == seeds.len())
        })
    })
}

/// Every test of the group's non-inferiority, set by set (the primary first), each set's
/// shapes and budgets in campaign order; a shape or budget without data in either arm is
/// left out.
pub fn tests(results: &Results, g: &EvolveGroup, n: &NonInferiority) -> Vec<Test> {
    let seeds = g.seeds.as_ref().unwrap_or(&results.campaign.seeds);
    let mut all = Vec::new();
    for &set in &n.sets {
        let mut family = Vec::new();
        for shape in &g.shapes {
            for &evals in &g.evals {
                let x = arm(results, (shape, n.treatment, evals), seeds, set);
                let y = arm(results, (shape, n.control, evals), seeds, set);
                if x.is_empty() || y.is_empty() {
                    continue;
                }
                family.push(Test {
                    shape: shape.clone(),
                    evals,
                    set,
                    planned: seeds.len(),
                    medians: (median(&x), median(&y)),
                    shift: hodges_lehmann(&x, &y, ALPHA).expect("samples"),
                    a12: (
                        mann_whitney(&x, &y).a12,
                        a12_interval(&x, &y, ALPHA).expect("samples"),
                    ),
                    test: noninferiority(&x, &y, n.margin),
                    holm: (f64::NAN, 0),
                    verdict: Verdict::NotShown,
                    superiority: Some((mann_whitney_greater(&x, &y), f64::NAN)),
                });
            }
        }
        decide(&mut family, n.margin);
        all.extend(family);
    }
    all
}

/// Holm over the family, the verdicts, then superiority where non-inferiority is shown
/// (`superiority` holds the unadjusted test on entry).
fn decide(family: &mut [Test], margin: f64) {
    let p: Vec<f64> = family.iter().map(|t| t.test.p).collect();
    for (t, adjusted) in family.iter_mut().zip(holm(&p)) {
        t.holm = (adjusted, p.len());
        t.verdict = Verdict::of(adjusted, t.shift.interval.high, margin);
        if t.verdict != Verdict::NotWorse {
            t.superiority = None;
        }
    }
    let tested: Vec<usize> = (0..family.len())
        .filter(|&i| family[i].superiority.is_some())
        .collect();
    let p: Vec<f64> = tested
        .iter()
        .map(|&i| family[i].superiority.expect("tested").0.p)
        .collect();
    for (&i, adjusted) in tested.iter().zip(holm(&p)) {
        family[i].superiority = family[i].superiority.map(|(u, _)| (u, adjusted));
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn verdicts_follow_the_plan() {
        assert_eq!(Verdict::of(0.0249, -0.9, 0.5), Verdict::NotWorse);
        assert_eq!(Verdict::of(0.025, -0.51, 0.5), Verdict::Worse);
        assert_eq!(Verdict::of(0.3, -0.5, 0.5), Verdict::NotShown);
        assert_eq!(Verdict::of(0.9, 1.0, 0.5), Verdict::NotShown);
        let words = Verdict::NotWorse.words(ControllerKind::MlpComm, 0.5);
        assert_eq!(
            words,
            "**not worse** than mlp-comm by 0.5 m/s or more (non-inferior)"
        );
    }
}
