//! What every campaign subcommand shares: the campaign file and its output folder
//! ([`Target`]), a part of its plan (`--only`), the folders its jobs write to, and the
//! outputs that exist so far ([`load_results`]).

use std::fs;
use std::path::{Path, PathBuf};

use vsr::experiment::{CodesignRun, RunFile, ValidationSet};
use vsr::{Error, Result};
use vsr_study::campaign::results::CodesignSpec;
use vsr_study::campaign::{fidelity_path, plan, Campaign, Job, Results};
use vsr_study::fidelity::Fidelity;

/// Where a campaign's outputs go.
#[derive(clap::Args, Debug, Clone)]
pub struct Target {
    /// The campaign file (TOML).
    pub file: PathBuf,
    /// Output folder (default: the campaign's `output`, relative to the campaign file).
    #[arg(long)]
    pub out_dir: Option<PathBuf>,
}

impl Target {
    /// The campaign's outputs that exist so far (see [`load_results`]) and its output folder.
    pub fn results(&self) -> Result<(Results, PathBuf)> {
        let (campaign, out) = self.load()?;
        Ok((load_results(campaign, &out)?, out))
    }

    /// The parsed campaign and its output folder.
    pub fn load(&self) -> Result<(Campaign, PathBuf)> {
        let text = fs::read_to_string(&self.file).map_err(|e| {
            Error::Io(format!(
                "cannot read campaign file {}: {e}",
                self.file.display()
            ))
        })?;
        // Paths in the file are relative to it; `campaigns/../study` is printed as `study`
        // (lexically: no symlinks resolved).
        let base = self.file.parent().unwrap_or(Path::new(""));
        let campaign = Campaign::parse(&text)
            .map_err(|e| e.about(self.file.display()))?
            .relative_to(base);
        let out = match &self.out_dir {
            Some(dir) => dir.clone(),
            None => path_clean::clean(base.join(&campaign.output)),
        };
        Ok((campaign, out))
    }
}

/// A part of a campaign: the jobs whose output names contain a text, and what they need.
#[derive(clap::Args, Debug, Clone)]
pub struct Only {
    /// Only the jobs whose output file name contains TEXT (repeatable, e.g. `--only comb-14x2`,
    /// `--only to-comb-7x2`), with every job they need. A plain substring: `mlp-comm` also
    /// matches `mlp-comm-latched`.
    #[arg(long, value_name = "TEXT")]
    only: Vec<String>,
}

impl Only {
    /// The plan of `campaign`, cut down to this part; an error when nothing matches.
    pub fn plan(&self, campaign: &Campaign, out: &Path) -> Result<Vec<Job>> {
        let jobs = vsr_study::campaign::select(plan(campaign, out), &self.only);
        if jobs.is_empty() {
            return Err(Error::Input(format!(
                "no job's output name contains {} (see `vsr campaign plan` for the names)",
                self.only.join(" or ")
            )));
        }
        Ok(jobs)
    }
}

/// The folders of a campaign's outputs (see `plan`).
pub fn create_folders(out: &Path, jobs: &[Job]) -> Result<()> {
    for job in jobs {
        if let Some(dir) = job.out.parent() {
            fs::create_dir_all(dir)
                .map_err(|e| Error::Io(format!("cannot create {}: {e}", dir.display())))?;
        }
    }
    fs::create_dir_all(out.join("logs"))
        .map_err(|e| Error::Io(format!("cannot create {}/logs: {e}", out.display())))
}

/// Reads every planned output that exists, the others listed as missing, and the files of
/// the runs read at earlier budgets or known seeds that exist, and the body searches'.
pub fn load_results(campaign: Campaign, out: &Path) -> Result<Results> {
    let jobs = plan(&campaign, out);
    let mut results = Results::new(campaign);
    results.missing = jobs
        .iter()
        .filter(|j| !j.out.exists())
        .map(|j| j.out.clone())
        .collect();
    let read = results.data.iter().chain(&results.earlier);
    let planned = read.chain(&results.known);
    let specs: Vec<_> = planned.map(|(s, _)| s.clone()).collect();
    for spec in specs {
        let run = read_json(&spec.run_path(out), RunFile::from_json)?;
        let mut validation = std::collections::BTreeMap::new();
        for set in ValidationSet::ALL {
            if let Some(v) = read_json(&spec.validation_path(out, set), json)? {
                validation.insert(set, v);
            }
        }
        let mut ablation = std::collections::BTreeMap::new();
        for set in ValidationSet::ALL {
            if let Some(a) = read_json(&spec.ablation_path(out, set), json)? {
                ablation.insert(set, a);
            }
        }
        if let Some(d) = results.of_mut(&spec) {
            (d.run, d.validation, d.ablation) = (run, validation, ablation);
        }
    }
    for g in &results.campaign.fidelity {
        let reference = PathBuf::from(&g.reference);
        if let Some(f) = read_json::<Fidelity>(&fidelity_path(out, &reference), json)? {
            results.fidelity.push((reference, f));
        }
    }
    let groups = results.campaign.any_body.clone();
    for (spec, data) in &mut results.any_body {
        data.run = read_json(&spec.run_path(out), RunFile::from_json)?;
        data.finished = data.run.is_some();
        let Some(g) = groups.iter().find(|g| g.name == spec.group) else {
            continue;
        };
        for bodies in g.validated_on() {
            let stem = vsr_study::campaign::any_body::set_stem(bodies);
            for &set in &g.sets {
                let name = format!("{}.{stem}.{set}", spec.stem());
                if let Some(v) = read_json(&spec_path(out, "validation", &name, "json"), json)? {
                    data.validation.insert((stem.clone(), set), v);
                }
            }
        }
    }
    let floor_sets = vsr_study::campaign::any_body::floor_sets(&groups);
    for (&(controller, seed), found) in results.floor.iter_mut().map(|(b, f)| (&*b, f)) {
        let stem = vsr_study::campaign::any_body::floor_stem(controller, seed);
        for (bodies, set) in &floor_sets {
            let set_stem = vsr_study::campaign::any_body::set_stem(bodies);
            let name = format!("{stem}.{set_stem}.{set}");
            if let Some(v) = read_json(&spec_path(out, "validation", &name, "json"), json)? {
                found.insert((set_stem, *set), v);
            }
        }
    }
    load_from_module(&mut results, out)?;
    for i in 0..results.codesign.len() {
        let spec = results.codesign[i].0.clone();
        let path = spec.run_path(out);
        let run = read_json(&path, CodesignRun::from_json)?;
        if let Some(run) = &run {
            check_codesign(&spec, run)
                .map_err(|why| Error::Input(format!("{}: {why}", path.display())))?;
        }
        let data = &mut results.codesign[i].1;
        data.run = run;
        for set in ValidationSet::ALL {
            if let Some(v) = read_json(&spec.validation_path(out, set), json)? {
                data.validation.insert(set, v);
            }
        }
    }
    Ok(results)
}

/// The `[[from_module]]` groups' runs, their modules and the runs of their compared
/// campaigns that exist (read from each compared campaign's own output folder).
fn load_from_module(results: &mut Results, out: &Path) -> Result<()> {
    for (spec, data) in &mut results.from_module {
        data.run = read_json(&spec.run_path(out), RunFile::from_json)?;
        for set in ValidationSet::ALL {
            if let Some(v) = read_json(&spec.validation_path(out, set), json)? {
                data.validation.insert(set, v);
            }
        }
    }
    for g in results.campaign.from_module.clone() {
        if let Some(module) = read_json(Path::new(&g.module), RunFile::from_json)? {
            results.modules.insert(g.name.clone(), module);
        }
        if let Some(n) = chosen_from(Path::new(&g.module)) {
            results.chosen_from.insert(g.name.clone(), n);
        }
        for set in ValidationSet::ALL {
            let Some(path) = g.one_shot_path(out, set) else {
                break;
            };
            if let Some(v) = read_json(&path, json)? {
                results.one_shot.insert((g.name.clone(), set), v);
            }
        }
        let Some(compare) = &g.compare else {
            continue;
        };
        let target = Target {
            file: PathBuf::from(compare),
            out_dir: None,
        };
        let (compared, compared_out) = target.load()?;
        for (group, spec) in vsr_study::campaign::from_module::compared_runs(&compared, &g.shapes) {
            let run = read_json(&spec.run_path(&compared_out), RunFile::from_json)?;
            let mut data = vsr_study::campaign::RunData::default();
            for set in ValidationSet::ALL {
                let path = spec.validation_path(&compared_out, set);
                if let Some(v) = read_json(&path, json)? {
                    data.validation.insert(set, v);
                }
            }
            data.run = run;
            if let Some(source) = spec.source.as_deref() {
                let sources = results
                    .source_evaluations
                    .entry(g.name.clone())
                    .or_default();
                if !sources.iter().any(|(s, _)| s == source) {
                    let path = source.run_path(&compared_out);
                    if let Some(run) = read_json(&path, RunFile::from_json)? {
                        let evaluations = run.generations.last().map_or(0, |g| g.evaluations);
                        sources.push((source.clone(), evaluations));
                    }
                }
            }
            results.compared.push((g.name.clone(), group, spec, data));
        }
    }
    Ok(())
}

/// How many runs the module at `module` was chosen among: its entry's `chosen_from` in the
/// `manifest.json` beside it, if there is one naming it (`None` otherwise: not known).
fn chosen_from(module: &Path) -> Option<usize> {
    let manifest = module.parent()?.join("manifest.json");
    let text = fs::read_to_string(manifest).ok()?;
    let manifest: vsr_study::campaign::export::Manifest = serde_json::from_str(&text).ok()?;
    let name = module.file_name()?.to_str()?;
    let entry = manifest.modules.iter().find(|m| m.file == name)?;
    Some(entry.provenance.chosen_from)
}

/// Checks every `[[from_module]]` group's module before any job runs: it exists (else what
/// makes it) and its controller can be fine-tuned as planned.
pub fn check_modules(campaign: &Campaign) -> Result<()> {
    for g in &campaign.from_module {
        let module = read_json(Path::new(&g.module), RunFile::from_json)?;
        g.check_module(module.as_ref())?;
    }
    Ok(())
}

/// Whether a body search's run file is the finished run its name plans: its brain,
/// controller, seed and budget, and the budget reached.
fn check_codesign(spec: &CodesignSpec, run: &CodesignRun) -> std::result::Result<(), String> {
    let (brain, kind) =
        vsr_study::campaign::codesign::condition(&spec.condition).map_err(|e| e.to_string())?;
    let c = &run.config;
    let kind = kind.unwrap_or(vsr::controllers::ControllerKind::Attention);
    if (c.brain, c.controller, c.seed, c.budget_evals) != (brain, kind, spec.seed, spec.evals) {
        return Err(format!(
            "this is a {} {} search with seed {} and budget {}, not the planned {} with seed {} \
             and budget {}",
            c.brain, c.controller, c.seed, c.budget_evals, spec.condition, spec.seed, spec.evals
        ));
    }
    if !run.is_complete() {
        return Err(format!(
            "the search stopped at {} of {} evaluations; a run in flight writes only its \
             checkpoint, so this file is not a finished run",
            run.evaluations, c.budget_evals
        ));
    }
    Ok(())
}

/// `out/folder/stem.ext`.
fn spec_path(out: &Path, folder: &str, stem: &str, ext: &str) -> PathBuf {
    out.join(folder).join(format!("{stem}.{ext}"))
}

fn json<T: serde::de::DeserializeOwned>(text: &str) -> Result<T> {
    serde_json::from_str(text).map_err(|e| Error::Input(e.to_string()))
}

/// Parses `path` with `parse` when it exists; an unreadable or invalid file is an error.
fn read_json<T>(path: &Path, parse: impl Fn(&str) -> Result<T>) -> Result<Option<T>> {
    if !path.exists() {
        return Ok(None);
    }
    let text = fs::read_to_string(path)
        .map_err(|e| Error::Io(format!("cannot read {}: {e}", path.display())))?;
    parse(&text).map(Some).map_err(|e| e.about(path.display()))
}
