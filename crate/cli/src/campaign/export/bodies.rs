//! The body-search half of `vsr campaign export`: each `[[codesign]]` group and condition's
//! best body with its brain into `bodies/` of the pretrained folder (the chosen run file with
//! its archive cut to that body; `vsr_study::campaign::export::bodies` says how it is
//! chosen, once all of the condition's runs are finished and validated), with its manifest
//! entry. A condition not finished keeps what the previous export gave it; bodies of groups
//! this campaign does not plan stay as they are.

use std::path::Path;

use vsr::{Error, Result};
use vsr_study::campaign::export::bodies::{
    bodies_table, body_entry, body_file, choose_bodies, trimmed, BodyEntry,
};
use vsr_study::campaign::export::{Manifest, Origin};
use vsr_study::campaign::{Job, Results};

use crate::campaign::command;

/// The bodies of the manifest after this export, and the files not written yet.
pub struct Exported {
    /// Every body entry, this campaign's first.
    pub bodies: Vec<BodyEntry>,
    /// Files of conditions with no finished, validated run (and none from before).
    pub pending: Vec<String>,
}

/// Exports the bodies of `results` (planned by `jobs` under `out`) into `to`.
pub fn export(
    results: &Results,
    (jobs, out): (&[Job], &Path),
    to: &Path,
    previous: &[BodyEntry],
    (campaign, version): (&str, &str),
) -> Result<Exported> {
    let mut done = Exported {
        bodies: Vec::new(),
        pending: Vec::new(),
    };
    for chosen in choose_bodies(results) {
        let ((group, condition), choice) = (chosen.key, chosen.choice);
        let (planned, ready) = chosen.runs;
        let name = body_file(&group, &condition);
        let kept = || {
            previous
                .iter()
                .find(|e| e.file == name && to.join(&name).exists())
                .cloned()
        };
        let Some(choice) = choice else {
            match kept() {
                Some(entry) => {
                    say!(
                        "{name}: {ready} of {planned} runs finished and validated, the previous \
                         export kept"
                    );
                    done.bodies.push(entry);
                }
                None => {
                    say!(
                        "{name}: not yet ({ready} of {planned} runs finished and validated on \
                         both sets)"
                    );
                    done.pending.push(name);
                }
            }
            continue;
        };
        let run_path = choice.spec.run_path(out);
        let job = jobs.iter().find(|j| j.out == run_path);
        let command = job.map(|job| command::line(job, "vsr", 1));
        let g = results.campaign.codesign.iter().find(|g| g.name == group);
        let module = g
            .filter(|_| !condition.starts_with("scratch-"))
            .and_then(|g| g.module.as_deref());
        let run_file = run_path.display().to_string();
        let entry = command.and_then(|command| {
            let origin = Origin {
                command: &command,
                campaign,
                code_version: version,
            };
            body_entry(&choice, (&run_file, module), origin)
        });
        let cut = choice.data.run.as_ref().and_then(trimmed);
        let (Some(entry), Some(cut)) = (entry, cut) else {
            eprintln!(
                "vsr: {name}: its run is not in the campaign's plan; the previous export kept"
            );
            done.bodies.extend(kept());
            continue;
        };
        let path = to.join(&name);
        if let Some(dir) = path.parent() {
            std::fs::create_dir_all(dir)
                .map_err(|e| Error::Io(format!("cannot create {}: {e}", dir.display())))?;
        }
        crate::atomic::write(&path, cut.to_json().as_bytes(), "body")?;
        say!(
            "{name}: seed {} of {} validated run(s), entry {}, {} voxels, unseen {:.2} m/s",
            entry.provenance.seed,
            entry.provenance.chosen_from,
            entry.entry,
            entry.voxels,
            entry
                .provenance
                .validation
                .get(&vsr::experiment::ValidationSet::Unseen)
                .map_or(f64::NAN, |f| f.mean)
        );
        done.bodies.push(entry);
    }
    let planned = |e: &BodyEntry| {
        results
            .codesign
            .iter()
            .any(|(s, _)| (&s.group, &s.condition) == (&e.group, &e.condition))
    };
    let others = previous
        .iter()
        .filter(|e| !planned(e) && to.join(&e.file).exists());
    done.bodies.extend(others.cloned());
    Ok(done)
}

/// The README's part on the body searches' bodies (nothing when there is none).
pub fn readme_part(manifest: &Manifest) -> String {
    if manifest.bodies.is_empty() {
        return String::new();
    }
    format!(
        "\n## Bodies found by body search (`bodies/`)\n\n\
         The best body with its brain of each condition of a body-search campaign \
         (`vsr codesign`; docs/ANALYSIS-PLAN.md, families 9 and 10), exported once all of the \
         condition's runs are finished and validated on both sets: the run whose best body has \
         the highest median velocity on the paper set; the unseen set is not used to choose. Each file is its run \
         file with the archive cut to that body (the whole archive: the run file and entry \
         named); `manifest.json` (`bodies`) records the command, seed, module, code version \
         and both sets' velocities, which `tests/pretrained.rs` replays. Replay one with \
         `vsr evaluate --genome pretrained/bodies/FILE --terrain hilly-1-10-10000` or `vsr \
         validate --genome pretrained/bodies/FILE --set unseen`.\n\n{}",
        bodies_table(&manifest.bodies)
    )
}
