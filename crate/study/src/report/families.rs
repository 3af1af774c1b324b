//! The planned tests (docs/ANALYSIS-PLAN.md). Every pair of controllers of an evolve group is
//! compared on every shape and budget and every measure. A family is one group's comparisons
//! on one measure, across its shapes and budgets; a pair already tested in an earlier group
//! (the same shape, budget, controllers and measure) is not tested again, only listed. Holm's
//! correction within each family; the Hodges-Lehmann shift and A12 with their intervals; the
//! smallest effect each test could detect. A group that plans a non-inferiority test (its
//! `noninferiority` key) has that test as its plan (`noninferiority`), not these.

use super::samples::{finetune_samples, measures, samples_of, transfer, Sample};
use crate::campaign::Results;
use crate::statistics::{
    a12_interval, detectable_a12, hodges_lehmann, holm, mann_whitney, median, Detectable, Interval,
    Shift, UTest,
};
use std::collections::HashMap;

/// Familywise alpha, and 1 - the level of every interval.
pub const ALPHA: f64 = 0.05;
/// The power at which the detectable effect is stated.
pub const POWER: f64 = 0.8;

/// One planned comparison of controller `a` against `b`.
#[derive(Debug, Clone)]
pub struct Comparison {
    /// The group whose family holds the test.
    pub family: String,
    /// The group this row is listed in (differs from `family` for a pair tested before).
    pub group: String,
    /// Shape as the campaign names it.
    pub shape: String,
    /// Budget.
    pub evals: u64,
    /// Sample A's and B's labels.
    pub a: String,
    /// See `a`.
    pub b: String,
    /// The measure (`best`, `paper mean`, `unseen mean`).
    pub measure: String,
    /// Medians of A and B.
    pub medians: (f64, f64),
    /// The U test.
    pub test: UTest,
    /// Holm-adjusted p within the family, and the family's size.
    pub holm: (f64, usize),
    /// Shift A - B with its interval.
    pub shift: Shift,
    /// A12's bootstrap interval.
    pub a12: Interval,
    /// The smallest effect detectable at these sizes.
    pub detectable: Detectable,
}

impl Comparison {
    /// "A > B", "A < B" (Holm-adjusted p below alpha) or "no difference detected".
    pub fn outcome(&self) -> String {
        match (self.holm.0 < ALPHA, self.test.a12 > 0.5) {
            (true, true) => format!("{} > {}", self.a, self.b),
            (true, false) => format!("{} < {}", self.a, self.b),
            (false, _) => "no difference detected".into(),
        }
    }
}

/// Every planned comparison of `results` whose samples both have data, in campaign order.
pub fn planned(results: &Results) -> Vec<Comparison> {
    let mut rows: Vec<Comparison> = Vec::new();
    let mut first: HashMap<(String, u64, String, String, String), String> = HashMap::new();
    let mut detectable: HashMap<(usize, usize), Detectable> = HashMap::new();
    let mut sections: Vec<(String, String, u64, Vec<Sample>)> = Vec::new();
    let evolve = results.campaign.evolve.iter();
    for g in evolve.filter(|g| g.noninferiority.is_none()) {
        for shape in &g.shapes {
            for &evals in &g.evals {
                let samples = samples_of(results, g, shape, evals);
                sections.push((g.name.clone(), shape.clone(), evals, samples));
            }
        }
    }
    for g in &results.campaign.finetune {
        for pair in &g.pairs {
            let samples = finetune_samples(results, g, pair);
            sections.push((g.name.clone(), transfer(pair), g.evals, samples));
        }
    }
    let sets = &results.campaign.validate;
    for (group, shape, evals, samples) in sections {
        for (i, a) in samples.iter().enumerate() {
            for b in &samples[i + 1..] {
                for ((measure, x), (_, y)) in measures(a, sets).into_iter().zip(measures(b, sets)) {
                    if x.is_empty() || y.is_empty() {
                        continue;
                    }
                    let mut pair = [a.label.clone(), b.label.clone()];
                    pair.sort();
                    let [p, q] = pair;
                    let key = (shape.clone(), evals, p, q, measure.clone());
                    let family = first.entry(key).or_insert_with(|| group.clone()).clone();
                    let sizes = (x.len(), y.len());
                    let d = *detectable
                        .entry(sizes)
                        .or_insert_with(|| detectable_a12(sizes.0, sizes.1, ALPHA, POWER));
                    rows.push(Comparison {
                        family,
                        group: group.clone(),
                        shape: shape.clone(),
                        evals,
                        a: a.label.clone(),
                        b: b.label.clone(),
                        medians: (median(&x), median(&y)),
                        test: mann_whitney(&x, &y),
                        holm: (f64::NAN, 0),
                        shift: hodges_lehmann(&x, &y, ALPHA).expect("samples"),
                        a12: a12_interval(&x, &y, ALPHA).expect("samples"),
                        detectable: d,
                        measure,
                    });
                }
            }
        }
    }
    adjust(&mut rows);
    rows
}

/// Holm within each (family, measure) over the rows tested in their own family; a row
/// listed again in a later group takes its first row's adjusted p.
fn adjust(rows: &mut [Comparison]) {
    let mut families: HashMap<(String, String), Vec<usize>> = HashMap::new();
    for (i, r) in rows.iter().enumerate() {
        if r.family == r.group {
            families
                .entry((r.family.clone(), r.measure.clone()))
                .or_default()
                .push(i);
        }
    }
    for members in families.values() {
        let p: Vec<f64> = members.iter().map(|&i| rows[i].test.p).collect();
        for (&i, adjusted) in members.iter().zip(holm(&p)) {
            rows[i].holm = (adjusted, members.len());
        }
    }
    for i in 0..rows.len() {
        if rows[i].family != rows[i].group {
            let same = |r: &Comparison| {
                r.family == r.group
                    && r.family == rows[i].family
                    && (&r.shape, r.evals, &r.measure)
                        == (&rows[i].shape, rows[i].evals, &rows[i].measure)
                    && ((&r.a, &r.b) == (&rows[i].a, &rows[i].b)
                        || (&r.a, &r.b) == (&rows[i].b, &rows[i].a))
            };
            if let Some(j) = rows.iter().position(same) {
                rows[i].holm = rows[j].holm;
            }
        }
    }
}
