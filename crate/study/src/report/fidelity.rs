//! The simulator against the reference: each fidelity measurement of the campaign (`vsr
//! fidelity`) as a summary, a table of every gait and a figure of our ensemble means against
//! the reference's (and, where measured, against the reference with its CCD off).

use super::figures::{Figure, Plot, Points};
use super::Report;
use crate::campaign::Results;
use crate::fidelity::Fidelity;
use std::fmt::Write;
use std::path::Path;

/// The section, when some fidelity measurement exists.
pub(super) fn fidelity_section(results: &Results, r: &mut Report) {
    if results.fidelity.is_empty() {
        return;
    }
    r.markdown.push_str(
        "## The simulator against the reference\n\nOpen-loop phase gaits on flat ground, each \
         an ensemble of starts shifted by k x 1e-5 m, here and on the reference simulator \
         (CCD off: the reference with its continuous collision detection switched off, which \
         this simulator does not reproduce).\n\n",
    );
    for (reference, f) in &results.fidelity {
        one(reference, f, r);
    }
}

fn one(reference: &Path, f: &Fidelity, r: &mut Report) {
    let name = reference
        .file_stem()
        .map_or(String::new(), |s| s.to_string_lossy().into_owned());
    let a = f.agreement();
    let md = &mut r.markdown;
    let _ = write!(
        md,
        "### {name}\n\nFrom `{}`. {}/{} of our ensemble means are within 2 reference sd of \
         the reference's mean; the gaits rank alike (Spearman rho {:.3}); mean over the gaits \
         {:.4} m/s here, {:.4} m/s on the reference.",
        reference.display(),
        a.within_2sd,
        a.gaits,
        a.rho,
        a.mean_ours,
        a.mean_reference
    );
    if let Some(c) = &a.ccd_free {
        let closer = if c.to_ccd_free < c.to_reference {
            "closer to the reference with CCD off"
        } else {
            "closer to the reference with CCD on"
        };
        let _ = write!(
            md,
            " On the {} gaits measured with CCD off too, mean |ours - reference| is {:.4} m/s \
             and mean |ours - CCD off| {:.4} m/s: ours is {closer} (signed-rank test of the \
             paired distances, p = {:.3}).",
            c.gaits, c.to_reference, c.to_ccd_free, c.test.p
        );
    }
    md.push_str("\n\n| shape | f (Hz) | phi | ours (m/s) | reference (m/s) | CCD off (m/s) |\n");
    md.push_str("|---|---:|---:|---:|---:|---:|\n");
    for g in &f.gaits {
        let cf = g
            .ccd_free
            .map_or("-".to_string(), |c| format!("{:.3} ± {:.3}", c.mean, c.sd));
        let _ = writeln!(
            md,
            "| {} | {} | {} | {:.3} ± {:.3} | {:.3} ± {:.3} | {cf} |",
            g.shape, g.f, g.phi, g.ours.mean, g.ours.sd, g.reference.mean, g.reference.sd
        );
    }
    let file = format!("fidelity-{name}.svg");
    let _ = writeln!(md, "\n![ours against the reference]({file})\n");
    let on = Points {
        label: "reference (bars: 2 sd)".into(),
        points: f
            .gaits
            .iter()
            .map(|g| (g.reference.mean, g.ours.mean))
            .collect(),
        x_error: f.gaits.iter().map(|g| 2.0 * g.reference.sd).collect(),
    };
    let off = Points {
        label: "reference with CCD off".into(),
        points: f
            .gaits
            .iter()
            .filter_map(|g| g.ccd_free.map(|c| (c.mean, g.ours.mean)))
            .collect(),
        x_error: Vec::new(),
    };
    let series = [on, off].into_iter().filter(|p| !p.points.is_empty());
    let mut notes = vec![format!(
        "{}/{} within 2 sd, rank correlation {:.2}; on the grey line ours equals the reference",
        a.within_2sd, a.gaits, a.rho
    )];
    if let Some(c) = &a.ccd_free {
        notes.push(format!(
            "CCD-off gaits ({}): mean |ours - reference| {:.3}, |ours - CCD off| {:.3} m/s",
            c.gaits, c.to_reference, c.to_ccd_free
        ));
    }
    r.figures.push(Figure {
        file,
        title: format!("{name}: ensemble means, ours against the reference"),
        x_label: "reference's mean velocity (m/s)".into(),
        y_label: "our mean velocity (m/s)".into(),
        plot: Plot::Versus(series.collect()),
        notes,
    });
}
