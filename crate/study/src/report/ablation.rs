//! The frozen-attention ablation part of a section (paper Fig. 6): for each set whose first
//! terrain the runs were ablated on, the velocity with the attention frozen at each second
//! against the same best walking unfrozen on the same terrain (the reference line).

use super::figures::{ablation_series, band, unfrozen_series};
use super::samples::Sample;
use super::tables::cell;
use super::{push_lines, Report};
use std::fmt::Write;
use vsr::experiment::ValidationSet;

pub(super) fn ablation_part(samples: &[Sample], id: &str, shape: &str, r: &mut Report) {
    let mut any = false;
    for set in ValidationSet::ALL {
        let with: Vec<&Sample> = samples
            .iter()
            .filter(|s| s.runs.iter().any(|d| d.ablation.contains_key(&set)))
            .collect();
        if with.is_empty() {
            continue;
        }
        any = true;
        let _ = writeln!(
            r.markdown,
            "Frozen-attention ablation on `{}` ({set} set): velocity frozen (mean over the \
             freeze seconds) and unfrozen (the same best on the same terrain), median [q1, q3] \
             across seeds:\n",
            set.first_terrain()
        );
        for s in &with {
            let ablated = s.runs.iter().filter_map(|d| d.ablation.get(&set));
            let means =
                ablated.map(|a| a.iter().map(|p| p.velocity).sum::<f64>() / a.len().max(1) as f64);
            let unfrozen = s.runs.iter().filter(|d| d.ablation.contains_key(&set));
            let unfrozen: Vec<f64> = unfrozen.filter_map(|d| d.unfrozen(set)).collect();
            let _ = writeln!(
                r.markdown,
                "- {}: frozen {} m/s; unfrozen {} m/s",
                s.label,
                cell(&means.collect::<Vec<_>>()),
                cell(&unfrozen)
            );
        }
        r.markdown.push('\n');
        let mut bands: Vec<_> = with
            .iter()
            .filter_map(|s| {
                band(
                    &format!("frozen {}", s.label),
                    &ablation_series(&s.runs, set),
                )
            })
            .collect();
        bands.extend(with.iter().filter_map(|s| {
            band(
                &format!("{}, not frozen", s.label),
                &unfrozen_series(&s.runs, set),
            )
        }));
        let suffix = match set {
            ValidationSet::Paper => String::new(),
            other => format!("-{other}"),
        };
        push_lines(
            r,
            format!("fig6-{id}{suffix}.svg"),
            format!("{shape}: attention frozen at t, on {}", set.first_terrain()),
            "freeze time (s)",
            "velocity (m/s)",
            bands,
        );
    }
    if !any {
        let _ = writeln!(r.markdown, "No ablation file yet.\n");
    }
}
