//! `vsr campaign export FILE [--to DIR]`: a campaign's best modules into the pretrained
//! folder (run files named by category, `manifest.json` with their provenance and the
//! figures a replay must reproduce, and a README table). A category without a finished,
//! validated run keeps what the previous export gave it (nothing is lost by exporting a
//! campaign that has barely started); other files the previous manifest listed are removed.
//! A campaign that plans body searches also exports their best bodies (`bodies`); one
//! that plans no module run (only body searches) leaves the modules as they are. An
//! `[[any_body]]` group exports its brains for any body (`any_body`), which no other
//! campaign's export removes.

mod any_body;
mod bodies;

use std::fs;
use std::path::{Path, PathBuf};

use vsr::controllers::ControllerKind;
use vsr::{Error, Result};
use vsr_study::campaign::export::bodies::BodyEntry;
use vsr_study::campaign::export::{choose, entry, file_name, Entry, Manifest, Origin};
use vsr_study::campaign::plan;

use crate::campaign::command;
use crate::campaign::target::{load_results, Target};

/// Arguments of `vsr campaign export`.
#[derive(clap::Args, Debug)]
pub struct Args {
    #[command(flatten)]
    target: Target,
    /// The pretrained folder written.
    #[arg(long, default_value = "pretrained")]
    to: PathBuf,
    /// Controller families exported (default: those the page runs), comma-separated.
    #[arg(
        long,
        value_delimiter = ',',
        default_value = "attention,mlp,mlp-comm,attention-any"
    )]
    controllers: Vec<ControllerKind>,
}

/// Runs the command.
pub fn run(args: Args) -> Result<()> {
    let (campaign, out) = args.target.load()?;
    let jobs = plan(&campaign, &out);
    let results = load_results(campaign, &out)?;
    let version = code_version();
    if version.ends_with("-dirty)") {
        eprintln!(
            "vsr: warning: this vsr was built from a tree with uncommitted changes ({version}); \
             for a clean provenance commit, rebuild and export again"
        );
    }
    let campaign_file = args.target.file.display().to_string();
    fs::create_dir_all(&args.to)
        .map_err(|e| Error::Io(format!("cannot create {}: {e}", args.to.display())))?;
    let Previous {
        listed,
        entries: previous,
        bodies,
    } = previous_manifest(&args.to)?;
    let mut modules = Vec::new();
    let mut pending = Vec::new();
    let plans_modules = !results.data.is_empty();
    // Brains for any body are handled apart (`any_body`), whatever the campaign.
    let (previous_any, previous): (Vec<Entry>, Vec<Entry>) =
        previous.into_iter().partition(|e| e.any_body.is_some());
    if !plans_modules {
        let kept = previous.iter().filter(|e| args.to.join(&e.file).exists());
        modules.extend(kept.cloned());
    }
    for (category, choice) in choose(&results, &args.controllers) {
        let name = file_name(&category);
        let Some(choice) = choice else {
            match previous
                .iter()
                .find(|e| e.file == name && args.to.join(&name).exists())
            {
                Some(kept) => {
                    say!("{name}: no finished run yet, the previous export kept");
                    modules.push(kept.clone());
                }
                None => {
                    say!("{name}: not yet (no finished run validated on both sets)");
                    pending.push(name);
                }
            }
            continue;
        };
        let run_path = choice.spec.run_path(&out);
        let job = jobs.iter().find(|j| j.out == run_path);
        let command = job.map(|job| command::line(job, "vsr", 1));
        let entry = command.and_then(|command| {
            let origin = Origin {
                command: &command,
                campaign: &campaign_file,
                code_version: &version,
            };
            entry(&choice, origin)
        });
        let Some(entry) = entry else {
            eprintln!(
                "vsr: {name}: its run is not in the campaign's plan; the previous export kept"
            );
            modules.extend(previous.iter().find(|e| e.file == name).cloned());
            continue;
        };
        let text = fs::read(&run_path)
            .map_err(|e| Error::Io(format!("cannot read {}: {e}", run_path.display())))?;
        crate::atomic::write(&args.to.join(&name), &text, "module")?;
        say!(
            "{name}: seed {} of {} validated run(s), training {:.2} m/s",
            entry.provenance.seed,
            entry.provenance.chosen_from,
            entry.provenance.training_best
        );
        modules.push(entry);
    }
    // Modules of controllers this export was not asked about stay as they are.
    let others = previous
        .iter()
        .filter(|e| plans_modules && !args.controllers.contains(&e.controller));
    modules.extend(others.filter(|e| args.to.join(&e.file).exists()).cloned());
    let any = any_body::export(
        &results,
        (&jobs, &out),
        &args.to,
        &previous_any,
        (&campaign_file, &version, &args.controllers),
    )?;
    modules.extend(any.modules);
    pending.extend(any.pending);
    let exported = bodies::export(
        &results,
        (&jobs, &out),
        &args.to,
        &bodies,
        (&campaign_file, &version),
    )?;
    pending.extend(exported.pending);
    let mut manifest = Manifest::new(modules);
    manifest.bodies = exported.bodies;
    if plans_modules {
        remove_unlisted(&args.to, &listed, &manifest)?;
    }
    let json = serde_json::to_string_pretty(&manifest)
        .map_err(|e| Error::Io(format!("cannot encode the manifest: {e}")))?;
    crate::atomic::write(
        &args.to.join("manifest.json"),
        (json + "\n").as_bytes(),
        "manifest",
    )?;
    let readme = readme(&manifest, &pending, &campaign_file, &args.to);
    crate::atomic::write(&args.to.join("README.md"), readme.as_bytes(), "README")?;
    say!(
        "{} modules and {} bodies in {}",
        manifest.modules.len(),
        manifest.bodies.len(),
        args.to.join("manifest.json").display()
    );
    Ok(())
}

/// The folder's previous manifest: the files it lists and its entries in this format.
struct Previous {
    listed: Vec<String>,
    entries: Vec<Entry>,
    bodies: Vec<BodyEntry>,
}

/// The folder's previous manifest (nothing if there is none). One that is not JSON with a
/// list of modules, each naming its file, is an error that names it: exporting over it
/// could lose the modules it lists. One of an older format is reported and only its file
/// list is used (its modules are not kept unless this campaign chooses them again).
fn previous_manifest(dir: &Path) -> Result<Previous> {
    let path = dir.join("manifest.json");
    if !path.exists() {
        return Ok(Previous {
            listed: Vec::new(),
            entries: Vec::new(),
            bodies: Vec::new(),
        });
    }
    let bad = |why: String| {
        Error::Input(format!(
            "{} {why}; fix it or move it away, then export again",
            path.display()
        ))
    };
    let text = fs::read_to_string(&path)
        .map_err(|e| Error::Io(format!("cannot read {}: {e}", path.display())))?;
    let value: serde_json::Value =
        serde_json::from_str(&text).map_err(|e| bad(format!("is not JSON ({e})")))?;
    let modules = value["modules"].as_array();
    let modules = modules.ok_or_else(|| bad("has no list of modules".into()))?;
    let listed = modules
        .iter()
        .enumerate()
        .map(|(i, m)| {
            let file = m["file"].as_str();
            file.map(str::to_string)
                .ok_or_else(|| bad(format!("names no file for module {}", i + 1)))
        })
        .collect::<Result<Vec<String>>>()?;
    let (entries, bodies) = match serde_json::from_value::<Manifest>(value) {
        Ok(manifest) => (manifest.modules, manifest.bodies),
        Err(e) => {
            eprintln!(
                "vsr: warning: {} is not a manifest of this format ({e}); \
                 its modules are not kept unless this campaign chooses them again",
                path.display()
            );
            (Vec::new(), Vec::new())
        }
    };
    Ok(Previous {
        listed,
        entries,
        bodies,
    })
}

/// Removes the module files the folder's previous manifest listed and `manifest` does not;
/// a listed name that is not a plain file name of the folder is refused, never removed.
fn remove_unlisted(dir: &Path, listed: &[String], manifest: &Manifest) -> Result<()> {
    for file in listed {
        if manifest.modules.iter().any(|m| &m.file == file) {
            continue;
        }
        if !is_plain_file_name(file) {
            eprintln!(
                "vsr: refused to remove {file:?}, listed by the previous manifest: not a file \
                 name in {}",
                dir.display()
            );
            continue;
        }
        let path = dir.join(file);
        if path.exists() {
            fs::remove_file(&path)
                .map_err(|e| Error::Io(format!("cannot remove {}: {e}", path.display())))?;
            say!("removed {file} (no longer chosen)");
        }
    }
    Ok(())
}

/// Whether `name` names a file inside the folder (no separators, no `..`, not `.`): the
/// previous manifest is not trusted to point elsewhere.
fn is_plain_file_name(name: &str) -> bool {
    Path::new(name).file_name().and_then(|n| n.to_str()) == Some(name)
        && !name.contains('\\')
        && !name.contains("..")
}

/// The version of the code exporting (and replaying) the modules: the crate version and the
/// git commit this binary was built from (see `crate/build.rs`).
fn code_version() -> String {
    format!("vsr {}", env!("VSR_VERSION"))
}

/// The folder's README: what the files are, how they were made, the table.
fn readme(manifest: &Manifest, pending: &[String], campaign: &str, dir: &Path) -> String {
    let not_yet = match pending {
        [] => String::new(),
        names => format!(
            "\nNot yet (the campaign's runs of these not all finished and validated): {}.\n",
            names.join(", ")
        ),
    };
    // Every campaign the folder's files came from, this one first (as the last run).
    let mut campaigns = vec![campaign.to_string()];
    let named = manifest.modules.iter().map(|m| &m.provenance.campaign);
    for c in named.chain(manifest.bodies.iter().map(|b| &b.provenance.campaign)) {
        if !campaigns.contains(c) {
            campaigns.push(c.clone());
        }
    }
    let campaign = campaigns.join(", ");
    format!(
        "# Pretrained controllers\n\n\
         Written by `vsr campaign export CAMPAIGN --to {dir}` with CAMPAIGN = {campaign} (do not edit by \
         hand). \
         Choice: {selection}. Each file is the run file `vsr evolve` or `vsr finetune` wrote; \
         `manifest.json` records the exact command, seed, budget, the campaign, the code \
         version, the training fitness and the velocities `vsr validate` gives on both \
         validation sets (`paper`: hilly-1-10-0..9, also in the training pool; `unseen`: \
         hilly-1-10-10000..10009). `tests/pretrained.rs` replays every module to exactly \
         those velocities. The page lists them (Modules).\n\n{table}{any_body}{bodies}{not_yet}",
        dir = dir.display(),
        selection = manifest.selection,
        table = manifest.table(),
        any_body = any_body::readme_part(manifest),
        bodies = bodies::readme_part(manifest)
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn only_plain_file_names_of_the_folder_are_removed() {
        assert!(is_plain_file_name("biped-4x3-attention.json"));
        for name in [
            "..",
            ".",
            "../x.json",
            "a/b.json",
            "/etc/x",
            "a\\b.json",
            "x..json",
            "",
        ] {
            assert!(!is_plain_file_name(name), "{name:?}");
        }
    }
}
