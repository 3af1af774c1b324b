//! The floor of the fourth question: random brains for any body walked as the runs are
//! (`campaign::any_body::floor_jobs`). Random attention-any is the plan's reference (shown
//! beside, not tested); the other families' random brains are exploratory, not in the plan.

use crate::campaign::any_body::{floor_sets, set_stem};
use crate::campaign::Results;
use crate::statistics::Summary;
use std::fmt::Write;
use vsr::controllers::ControllerKind;

/// The floor's label of a family (its colour in the figures is grey: not a trained brain).
pub(super) fn floor_label(controller: ControllerKind) -> String {
    format!("random {controller} (floor)")
}

/// Per random brain of `controller`, its median on (`stem`, `set`), for the seeds that have it.
pub(super) fn floor_values(
    results: &Results,
    controller: ControllerKind,
    (stem, set): (&str, vsr::experiment::ValidationSet),
) -> Vec<f64> {
    results
        .floor
        .iter()
        .filter(|((c, _), _)| *c == controller)
        .filter_map(|(_, found)| found.get(&(stem.to_string(), set)).map(|v| v.median))
        .collect()
}

/// The exploded episodes (each counted as 0 m/s) of `controller`'s random brains on (`stem`,
/// `set`).
fn floor_exploded(
    results: &Results,
    controller: ControllerKind,
    (stem, set): (&str, vsr::experiment::ValidationSet),
) -> u32 {
    let mine = results.floor.iter().filter(|((c, _), _)| *c == controller);
    let each = mine.filter_map(|(_, found)| found.get(&(stem.to_string(), set)));
    each.map(|v| v.exploded).sum()
}

/// The floor's table: per family, the median [q1, q3] over seeds of each held-out set's
/// median, once every seed of the family has it (before, how many have).
pub(super) fn floor_section(results: &Results, md: &mut String) {
    if results.floor.is_empty() {
        return;
    }
    let sets = floor_sets(&results.campaign.any_body);
    let seeds = &results.campaign.seeds;
    let seeds_text = seeds
        .iter()
        .map(u64::to_string)
        .collect::<Vec<_>>()
        .join(", ");
    let _ = writeln!(
        md,
        "### The floor: random brains (a reference, not tested)\n\n\
         A random genome of each family for any body (genes uniform in [-1, 1], the GA's initial \
         range; seeds {seeds_text}), walked as the runs' bests are. Random attention-any is the \
         plan's reference (shown beside, not tested); the other families' random brains are \
         exploratory, not in the plan. Median [q1, q3] over the seeds of each set's median \
         (m/s; \"k exploded\": episodes counted as 0 m/s).\n"
    );
    let mut header = String::from("| random brain |");
    for (bodies, set) in &sets {
        let _ = write!(header, " {} ({set}) |", set_stem(bodies));
    }
    md.push_str(&header);
    md.push('\n');
    md.push_str(&format!("|{}\n", "---|".repeat(sets.len() + 1)));
    let mut kinds: Vec<ControllerKind> = Vec::new();
    for ((c, _), _) in &results.floor {
        if !kinds.contains(c) {
            kinds.push(*c);
        }
    }
    for c in kinds {
        let what = if c == ControllerKind::AttentionAny {
            "the plan's reference"
        } else {
            "exploratory"
        };
        let mut row = format!("| {c} ({what}) |");
        for (bodies, set) in &sets {
            let v = floor_values(results, c, (&set_stem(bodies), *set));
            let cell = if v.len() == seeds.len() {
                let s = Summary::of(&v);
                let n = floor_exploded(results, c, (&set_stem(bodies), *set));
                let exploded = if n > 0 {
                    format!(", {n} exploded")
                } else {
                    String::new()
                };
                format!("{:.2} [{:.2}, {:.2}]{exploded}", s.median, s.q1, s.q3)
            } else {
                format!("{} of {} seeds", v.len(), seeds.len())
            };
            let _ = write!(row, " {cell} |");
        }
        md.push_str(&row);
        md.push('\n');
    }
    md.push('\n');
}
