//! The brains-for-any-body half of `vsr campaign export`: each `[[any_body]]` group and
//! controller's chosen run (`vsr_study::campaign::export::any_body` says how: by its
//! training-set median, once all of the condition's runs are finished and validated) copied
//! byte for byte as `GROUP-CONTROLLER.json`, with its manifest entry (its figures on every
//! body set). A condition not finished keeps what the previous export gave it; brains of
//! groups or controllers this export does not choose stay as they are.

use std::path::Path;

use vsr::controllers::ControllerKind;
use vsr::{Error, Result};
use vsr_study::campaign::export::any_body::{
    any_body_entry, any_body_file, any_body_table, choose_any_body,
};
use vsr_study::campaign::export::{Entry, Manifest, Origin};
use vsr_study::campaign::{Job, Results};

use crate::campaign::command;

/// The brains for any body of the manifest after this export, and the files not written yet.
pub struct Exported {
    /// Every such entry, this campaign's first.
    pub modules: Vec<Entry>,
    /// Files of conditions not all finished and validated (and none from before).
    pub pending: Vec<String>,
}

/// Exports the brains for any body of `results` (planned by `jobs` under `out`) into `to`.
pub fn export(
    results: &Results,
    (jobs, out): (&[Job], &Path),
    to: &Path,
    previous: &[Entry],
    (campaign, version, controllers): (&str, &str, &[ControllerKind]),
) -> Result<Exported> {
    let mut done = Exported {
        modules: Vec::new(),
        pending: Vec::new(),
    };
    let chosen_all = choose_any_body(results, controllers);
    for chosen in &chosen_all {
        let (group, controller) = &chosen.key;
        let (planned, ready) = chosen.runs;
        let name = any_body_file(group, *controller);
        let kept = || {
            previous
                .iter()
                .find(|e| e.file == name && to.join(&name).exists())
                .cloned()
        };
        let Some(choice) = &chosen.choice else {
            match kept() {
                Some(entry) => {
                    say!(
                        "{name}: {ready} of {planned} runs finished and validated, the previous \
                         export kept"
                    );
                    done.modules.push(entry);
                }
                None => {
                    say!(
                        "{name}: not yet ({ready} of {planned} runs finished and validated on \
                         every body set)"
                    );
                    done.pending.push(name);
                }
            }
            continue;
        };
        let run_path = choice.spec.run_path(out);
        let job = jobs.iter().find(|j| j.out == run_path);
        let command = job.map(|job| command::line(job, "vsr", 1));
        let g = results.campaign.any_body.iter().find(|g| &g.name == group);
        let entry = command.zip(g).and_then(|(command, g)| {
            let origin = Origin {
                command: &command,
                campaign,
                code_version: version,
            };
            any_body_entry(choice, g, origin)
        });
        let Some(entry) = entry else {
            eprintln!(
                "vsr: {name}: its run is not in the campaign's plan; the previous export kept"
            );
            done.modules.extend(kept());
            continue;
        };
        let text = std::fs::read(&run_path)
            .map_err(|e| Error::Io(format!("cannot read {}: {e}", run_path.display())))?;
        crate::atomic::write(&to.join(&name), &text, "module")?;
        let heldout = entry.any_body.as_ref().and_then(|a| a.sets.first());
        say!(
            "{name}: seed {} of {} validated run(s), training-set median {:.2} m/s, {} median \
             {:.2} m/s",
            entry.provenance.seed,
            entry.provenance.chosen_from,
            vsr_study::campaign::export::any_body::training_median(
                g.expect("the group exists"),
                &choice.data
            )
            .unwrap_or(f64::NAN),
            heldout.map_or("-", |s| s.name.as_str()),
            heldout.map_or(f64::NAN, |s| s.median)
        );
        done.modules.push(entry);
    }
    let handled = |e: &Entry| {
        chosen_all
            .iter()
            .any(|c| any_body_file(&c.key.0, c.key.1) == e.file)
    };
    let others = previous
        .iter()
        .filter(|e| !handled(e) && to.join(&e.file).exists());
    done.modules.extend(others.cloned());
    Ok(done)
}

/// The README's part on the brains for any body (nothing when there is none).
pub fn readme_part(manifest: &Manifest) -> String {
    let table = any_body_table(&manifest.modules);
    if table.is_empty() {
        return String::new();
    }
    format!(
        "\n## Brains for any body\n\n\
         One genome drives every body (`attention-any`, `mlp-any`, `mlp-comm-any`): each \
         `[[any_body]]` group's brain chosen once all of its runs are finished and validated: \
         {}. `shape` names its training set; `manifest.json` (`any_body`) records every body \
         set's per-body means, their median and the share above 1 m/s on the unseen terrains, \
         which `tests/pretrained.rs` replays. Walk one on a body set with `vsr validate \
         --genome pretrained/FILE --bodies campaigns/bodies/heldout-random.txt --set \
         unseen`.\n\n{table}",
        vsr_study::campaign::export::any_body::CHOSEN_BY
    )
}
