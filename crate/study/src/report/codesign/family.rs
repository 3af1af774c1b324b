//! The planned tests of a body-search group (docs/ANALYSIS-PLAN.md, families 9 and 10): the
//! frozen module against every brain from scratch, and the fine-tuned module against
//! attention from scratch, each pair the group's conditions hold. One family per measure
//! (the `unseen` velocity, family 9; the QD-score, family 10): two-sided Mann-Whitney U,
//! Holm within the family at alpha 0.05, the Hodges-Lehmann shift with its exact 95%
//! interval, A12 with its bootstrap interval, the smallest detectable A12. Measures the plan
//! reports as estimates (the `paper` velocity, coverage) get the shift and A12 only. The
//! exploratory comparisons (not in the plan, chosen after its data) are tested one by one,
//! uncorrected, and draw no verdict.

use super::measures::{Condition, Measure};
use crate::report::families::{ALPHA, POWER};
use crate::statistics::{
    a12_interval, detectable_a12, hodges_lehmann, holm, mann_whitney, median, Detectable, Interval,
    Shift, UTest,
};

/// The plan's pairs among `conditions`: `frozen` against every `scratch-*`, then
/// `finetune` against `scratch-attention`.
pub(crate) fn pairs(conditions: &[String]) -> Vec<(String, String)> {
    let has = |c: &str| conditions.iter().any(|x| x == c);
    let mut out = Vec::new();
    if has("frozen") {
        for c in conditions.iter().filter(|c| c.starts_with("scratch-")) {
            out.push(("frozen".to_string(), c.clone()));
        }
    }
    if has("finetune") && has("scratch-attention") {
        out.push(("finetune".into(), "scratch-attention".into()));
    }
    out
}

/// One comparison of condition `a` against `b` on a measure.
#[derive(Debug, Clone)]
pub(crate) struct Row {
    /// The conditions compared.
    pub(crate) a: String,
    /// See `a`.
    pub(crate) b: String,
    /// Runs with the measure, of A and of B.
    pub(crate) n: (usize, usize),
    /// Runs planned per condition.
    pub(crate) planned: usize,
    /// What was computed: `None` while a condition has no value yet.
    pub(crate) found: Option<Found>,
}

/// The numbers of a comparison whose two samples have values.
#[derive(Debug, Clone)]
pub(crate) struct Found {
    /// Medians of A and B.
    pub(crate) medians: (f64, f64),
    /// Shift A - B with its interval.
    pub(crate) shift: Shift,
    /// A12 = P(A > B) and its bootstrap interval.
    pub(crate) a12: (f64, Interval),
    /// The test and its Holm-adjusted p with the family's size (tested measures only).
    pub(crate) test: Option<(UTest, f64, usize)>,
    /// The smallest A12 these sizes detect with 80% power.
    pub(crate) detectable: Detectable,
}

impl Row {
    /// Whether the row has fewer runs than planned (not the planned test).
    pub(crate) fn interim(&self) -> bool {
        self.n.0 < self.planned || self.n.1 < self.planned
    }

    /// The verdict in the plan's words: "A > B (difference detected)" where Holm detects a
    /// difference, otherwise "no difference detected"; `None` where nothing was tested.
    pub(crate) fn verdict(&self) -> Option<String> {
        let found = self.found.as_ref()?;
        let (u, adjusted, _) = found.test.as_ref()?;
        Some(match (*adjusted < ALPHA, u.a12 > 0.5) {
            (true, true) => format!("{} > {} (difference detected)", self.a, self.b),
            (true, false) => format!("{} < {} (difference detected)", self.a, self.b),
            (false, _) => "no difference detected".into(),
        })
    }
}

/// Comparisons the plan does not make, chosen after its data (a reviewer's check): attention
/// from scratch against every other brain from scratch, so that the share of the frozen
/// module's lead that attention alone already has can be read beside it.
pub(crate) fn exploratory_pairs(conditions: &[String]) -> Vec<(String, String)> {
    let attention = "scratch-attention";
    if !conditions.iter().any(|c| c == attention) {
        return Vec::new();
    }
    conditions
        .iter()
        .filter(|c| c.starts_with("scratch-") && *c != attention)
        .map(|c| (attention.to_string(), c.clone()))
        .collect()
}

/// The exploratory comparisons on `measure` (`exploratory_pairs`), each tested alone: its
/// "Holm" p is its raw p, of a family of 1 (nothing is corrected: no verdict is drawn).
pub(crate) fn exploratory(conditions: &[Condition], measure: Measure) -> Vec<Row> {
    let names: Vec<String> = conditions.iter().map(|c| c.name.clone()).collect();
    let mut rows = compared(conditions, exploratory_pairs(&names), measure, true);
    for row in &mut rows {
        if let Some((u, h, k)) = row.found.as_mut().and_then(|f| f.test.as_mut()) {
            (*h, *k) = (u.p, 1);
        }
    }
    rows
}

/// The plan's comparisons on `measure`; tested (Holm over the rows with values in both
/// samples) when `tested`, estimates only otherwise.
pub(crate) fn family(conditions: &[Condition], measure: Measure, tested: bool) -> Vec<Row> {
    let names: Vec<String> = conditions.iter().map(|c| c.name.clone()).collect();
    let mut rows = compared(conditions, pairs(&names), measure, tested);
    let with: Vec<usize> = (0..rows.len())
        .filter(|&i| rows[i].found.as_ref().is_some_and(|f| f.test.is_some()))
        .collect();
    let p: Vec<f64> = with
        .iter()
        .map(|&i| {
            rows[i]
                .found
                .as_ref()
                .and_then(|f| f.test.as_ref())
                .expect("tested")
                .0
                .p
        })
        .collect();
    for (&i, adjusted) in with.iter().zip(holm(&p)) {
        if let Some((_, h, k)) = rows[i].found.as_mut().and_then(|f| f.test.as_mut()) {
            (*h, *k) = (adjusted, p.len());
        }
    }
    rows
}

/// The rows of `pairs` on `measure`, tested (p not yet adjusted) when `tested`.
fn compared(
    conditions: &[Condition],
    pairs: Vec<(String, String)>,
    measure: Measure,
    tested: bool,
) -> Vec<Row> {
    let of = |name: &str| conditions.iter().find(|c| c.name == name);
    pairs
        .into_iter()
        .filter_map(|(a, b)| {
            let (ca, cb) = (of(&a)?, of(&b)?);
            let (x, y) = (ca.values(measure), cb.values(measure));
            let found = (!x.is_empty() && !y.is_empty()).then(|| Found {
                medians: (median(&x), median(&y)),
                shift: hodges_lehmann(&x, &y, ALPHA).expect("two samples"),
                a12: (
                    mann_whitney(&x, &y).a12,
                    a12_interval(&x, &y, ALPHA).expect("two samples"),
                ),
                test: tested.then(|| (mann_whitney(&x, &y), f64::NAN, 0)),
                detectable: detectable_a12(x.len(), y.len(), ALPHA, POWER),
            });
            Some(Row {
                planned: ca.planned.max(cb.planned),
                n: (x.len(), y.len()),
                a,
                b,
                found,
            })
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_plans_four_pairs() {
        let c: Vec<String> = [
            "frozen",
            "finetune",
            "scratch-attention",
            "scratch-mlp",
            "scratch-mlp-comm",
        ]
        .map(String::from)
        .to_vec();
        let p = pairs(&c);
        let words: Vec<String> = p.iter().map(|(a, b)| format!("{a} vs {b}")).collect();
        assert_eq!(
            words,
            [
                "frozen vs scratch-attention",
                "frozen vs scratch-mlp",
                "frozen vs scratch-mlp-comm",
                "finetune vs scratch-attention"
            ]
        );
        assert!(pairs(&c[..2]).is_empty());
        let e = exploratory_pairs(&c);
        let words: Vec<String> = e.iter().map(|(a, b)| format!("{a} vs {b}")).collect();
        assert_eq!(
            words,
            [
                "scratch-attention vs scratch-mlp",
                "scratch-attention vs scratch-mlp-comm"
            ]
        );
        assert!(exploratory_pairs(&c[..2]).is_empty());
    }
}
