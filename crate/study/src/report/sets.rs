//! How the two validation sets compare in difficulty: every run assessed on both, paired
//! (`unseen` minus `paper`, the same best on both sets), by the signed-rank test, with the
//! median paired difference and its distribution-free interval.

use super::families::ALPHA;
use crate::campaign::Results;
use crate::statistics::{median, median_interval, wilcoxon_signed_rank};
use std::fmt::Write;
use vsr::experiment::ValidationSet;

/// The section, when some run has both sets.
pub(super) fn sets_section(results: &Results, md: &mut String) {
    let (mut unseen, mut paper) = (Vec::new(), Vec::new());
    for (_, d) in &results.data {
        let pair = (
            d.validation_mean(ValidationSet::Unseen),
            d.validation_mean(ValidationSet::Paper),
        );
        if let (Some(u), Some(p)) = pair {
            unseen.push(u);
            paper.push(p);
        }
    }
    if unseen.is_empty() {
        return;
    }
    let diff: Vec<f64> = unseen.iter().zip(&paper).map(|(u, p)| u - p).collect();
    let t = wilcoxon_signed_rank(&unseen, &paper);
    let i = median_interval(&diff, ALPHA).expect("values");
    let harder = if t.p >= ALPHA {
        "no difference in difficulty detected".to_string()
    } else if median(&diff) > 0.0 {
        "the `unseen` terrains are easier (the same bests walk faster there)".to_string()
    } else {
        "the `unseen` terrains are harder".to_string()
    };
    let _ = writeln!(
        md,
        "## The validation sets compared\n\n{} runs assessed on both sets, paired: `unseen` \
         minus `paper` median {:+.4} m/s [{:+.4}, {:+.4}] ({:.0}% interval); signed-rank \
         test z = {:.2}, p = {:.2e}: {harder}.\n",
        diff.len(),
        median(&diff),
        i.low,
        i.high,
        100.0 * i.coverage,
        t.z,
        t.p
    );
}
