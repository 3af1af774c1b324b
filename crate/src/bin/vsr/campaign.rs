//! `vsr campaign plan|run|merge|export FILE`: a campaign file's job list, run on local cores, and its
//! run files collected into one CSV. Outputs go under the campaign's `output` folder,
//! resolved relative to the campaign file, or under `--out-dir`.

use std::fs;
use std::io::Write;
use std::path::{Path, PathBuf};

use vsr::experiment::{RunFile, ValidationSet};
use vsr::study::campaign::{merge, plan, Campaign, Job, Results};
use vsr::{Error, Result};

pub mod command;

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
    /// The parsed campaign and its output folder.
    pub fn load(&self) -> Result<(Campaign, PathBuf)> {
        let text = fs::read_to_string(&self.file).map_err(|e| {
            Error::Io(format!(
                "cannot read campaign file {}: {e}",
                self.file.display()
            ))
        })?;
        let campaign = Campaign::parse(&text)
            .map_err(|e| Error::Input(format!("{}: {e}", self.file.display())))?;
        let out = match &self.out_dir {
            Some(dir) => dir.clone(),
            None => {
                // `campaigns/../study` printed as `study` (lexically: no symlinks resolved).
                let base = self.file.parent().unwrap_or(Path::new(""));
                path_clean::clean(base.join(&campaign.output))
            }
        };
        Ok((campaign, out))
    }
}

/// `vsr campaign` subcommands.
#[derive(clap::Subcommand, Debug)]
pub enum Command {
    /// Print the job list: one complete vsr command per line, in dependency order.
    Plan(PlanArgs),
    /// Run the jobs on local cores, skipping those whose output exists (resumable).
    Run(crate::campaign_run::Args),
    /// Collect the run files and validations into one CSV (OUT/campaign.csv by default).
    Merge(MergeArgs),
    /// Copy the best module of each shape, controller and source into the pretrained folder.
    Export(crate::campaign_export::Args),
}

/// Arguments of `vsr campaign plan`.
#[derive(clap::Args, Debug)]
pub struct PlanArgs {
    #[command(flatten)]
    target: Target,
    /// Only the jobs of this stage: 1 runs that need no other run; a fine-tuning run or a run
    /// continuing a shorter one comes a stage after the run it needs, assessments a stage
    /// after their run (the paper's study: 1 to 3; past the last stage nothing is printed).
    #[arg(long)]
    stage: Option<u32>,
    /// Only the jobs whose output does not exist yet.
    #[arg(long)]
    pending: bool,
    #[command(flatten)]
    only: Only,
    /// --threads of each evolution job.
    #[arg(long, default_value_t = 1)]
    threads: usize,
    /// The program name printed at the start of each line.
    #[arg(long, default_value = "vsr")]
    program: String,
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
        let jobs = vsr::study::campaign::select(plan(campaign, out), &self.only);
        if jobs.is_empty() {
            return Err(Error::Input(format!(
                "no job's output name contains {} (see `vsr campaign plan` for the names)",
                self.only.join(" or ")
            )));
        }
        Ok(jobs)
    }
}

/// Arguments of `vsr campaign merge`.
#[derive(clap::Args, Debug)]
pub struct MergeArgs {
    #[command(flatten)]
    target: Target,
    /// The CSV file (default: OUT/campaign.csv).
    #[arg(long)]
    csv: Option<PathBuf>,
}

/// Runs a `vsr campaign` subcommand.
pub fn run(command: Command) -> Result<()> {
    match command {
        Command::Plan(args) => print_plan(args),
        Command::Run(args) => crate::campaign_run::run(args),
        Command::Merge(args) => write_merge(args),
        Command::Export(args) => crate::campaign_export::run(args),
    }
}

fn print_plan(args: PlanArgs) -> Result<()> {
    if args.threads == 0 {
        return Err(Error::Input("--threads must be at least 1".into()));
    }
    let (campaign, out) = args.target.load()?;
    let mut stdout = std::io::stdout().lock();
    for job in args.only.plan(&campaign, &out)? {
        let stage_ok = args.stage.map_or(true, |s| s == job.stage);
        if stage_ok && !(args.pending && job.out.exists()) {
            let line = command::line(&job, &args.program, args.threads);
            match writeln!(stdout, "{line}") {
                Ok(()) => {}
                // The reader stopped (`| head`): nothing more to say.
                Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => return Ok(()),
                Err(e) => return Err(Error::Io(format!("cannot print the plan: {e}"))),
            }
        }
    }
    Ok(())
}

fn write_merge(args: MergeArgs) -> Result<()> {
    let (campaign, out) = args.target.load()?;
    let results = load_results(campaign, &out)?;
    let path = args.csv.unwrap_or_else(|| out.join("campaign.csv"));
    crate::atomic::write(&path, merge::csv(&results).as_bytes(), "table")?;
    let found = results.data.iter().filter(|(_, d)| d.run.is_some()).count();
    println!(
        "{} runs of {} in {}; {} planned outputs missing",
        found,
        results.data.len(),
        path.display(),
        results.missing.len()
    );
    Ok(())
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

/// Reads every planned output that exists; the others are listed as missing.
pub fn load_results(campaign: Campaign, out: &Path) -> Result<Results> {
    let jobs = plan(&campaign, out);
    let mut results = Results::new(campaign);
    results.missing = jobs
        .iter()
        .filter(|j| !j.out.exists())
        .map(|j| j.out.clone())
        .collect();
    let specs: Vec<_> = results.data.iter().map(|(s, _)| s.clone()).collect();
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
    Ok(results)
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
    parse(&text)
        .map(Some)
        .map_err(|e| Error::Input(format!("{}: {e}", path.display())))
}
