//! `vsr campaign status FILE`: how far a campaign has come, read from its output folder (it
//! runs nothing): its evolutionary runs finished, in flight (a checkpoint, with the
//! evaluations it has reached) and not started; its other jobs done; and an estimate of the
//! core-hours left, from the generation times of the runs finished last (the median seconds
//! per evaluation on one thread: a run paused or slowed for a while moves it little). The time
//! is taken per voxel and simulated second, and per controller (MLP-Comm's controller and
//! sensors run every step, the others' every 20), so a body or a controller not run yet is
//! estimated from the runs most like it.

use std::fs;
use std::path::Path;

use vsr::controllers::ControllerKind;
use vsr::experiment::planned_evaluations;
use vsr::simulation::Shape;
use vsr::{Error, Result};
use vsr_study::campaign::{Job, RunTask, Task};
use vsr_study::statistics;

use super::target::{Only, Target};

/// Arguments of `vsr campaign status`.
#[derive(clap::Args, Debug)]
pub struct Args {
    #[command(flatten)]
    target: Target,
    #[command(flatten)]
    only: Only,
    /// The cores the estimate divides the work left by (default: this machine's).
    #[arg(long)]
    cores: Option<usize>,
}

/// Runs the command.
pub fn run(args: Args) -> Result<()> {
    let (campaign, out) = args.target.load()?;
    let jobs = args.only.plan(&campaign, &out)?;
    let cores = match args.cores {
        Some(0) => return Err(Error::Input("--cores must be at least 1".into())),
        Some(n) => n,
        None => std::thread::available_parallelism().map_or(1, |n| n.get()),
    };
    say!("{}", status(&jobs, cores).trim_end_matches('\n'));
    // A module made elsewhere (`[[from_module]]`): what makes it, before its runs can start.
    if let Err(why) = super::target::check_modules(&campaign) {
        say!("not ready: {why}");
    }
    Ok(())
}

/// How many of the runs finished last the estimate reads.
const RECENT: usize = 10;

/// An evolutionary run's state on disk.
enum RunState {
    Finished,
    InFlight { evaluations: u64 },
    NotStarted,
}

fn run_state(out: &Path) -> RunState {
    if out.exists() {
        return RunState::Finished;
    }
    let checkpoint = out.with_extension("json.checkpoint");
    match fs::read_to_string(&checkpoint)
        .ok()
        .and_then(|t| serde_json::from_str::<serde_json::Value>(&t).ok())
    {
        Some(v) => RunState::InFlight {
            evaluations: v["generations"]
                .as_array()
                .and_then(|g| g.last())
                .and_then(|g| g["evaluations"].as_u64())
                .unwrap_or(0),
        },
        None => RunState::NotStarted,
    }
}

/// The median wall seconds per evaluation over a finished run's generations, if it ran on
/// one thread (the estimate's unit).
fn seconds_per_evaluation(out: &Path) -> Option<f64> {
    let v: serde_json::Value = serde_json::from_str(&fs::read_to_string(out).ok()?).ok()?;
    if v["timing"]["threads"].as_u64() != Some(1) {
        return None;
    }
    // A generation's wall time is the run's so far (a resumed run's restarts): differences.
    let (mut evals_before, mut wall_before) = (0, 0.0);
    let mut per: Vec<f64> = Vec::new();
    for g in v["generations"].as_array()? {
        let (evals, wall) = (g["evaluations"].as_u64()?, g["wall_seconds"].as_f64()?);
        let took = wall - wall_before;
        if evals > evals_before && took.is_finite() && took > 0.0 {
            per.push(took / (evals - evals_before) as f64);
        }
        (evals_before, wall_before) = (evals, wall);
    }
    median(per)
}

/// A run's work per evaluation, in voxel-seconds: its body's voxels times its episode's
/// seconds (1 voxel for a shape that does not parse: its run would fail anyway).
fn work(run: &RunTask) -> f64 {
    let voxels = match &run.bodies {
        // Each evaluation walks per_evaluation bodies: their mean size times their number.
        Some(b) => vsr::experiment::BodySet::read(&b.file).map_or(1.0, |set| {
            let total: usize = set.bodies.iter().map(|s| s.voxel_count()).sum();
            b.per_evaluation as f64 * total as f64 / set.bodies.len() as f64
        }),
        None => Shape::parse(&run.shape).map_or(1, |s| s.voxel_count()) as f64,
    };
    voxels * run.seconds
}

/// The median, if there are values.
fn median(v: Vec<f64>) -> Option<f64> {
    (!v.is_empty()).then(|| statistics::median(&v))
}

/// The status text.
fn status(jobs: &[Job], cores: usize) -> String {
    let (mut finished, mut flying, mut waiting) = (0, Vec::new(), 0);
    // Evaluations left, and per run left: its controller, evaluations left and work.
    let (mut left, mut todo) = (0u64, Vec::new());
    // Per finished run: when written, its controller, seconds per evaluation per voxel-second.
    let mut rates = Vec::new();
    // (done, planned) of the body searches and of the assessments.
    let (mut searches, mut assessments) = ((0, 0), (0, 0));
    for job in jobs {
        let count = match &job.task {
            Task::Run(_) => None,
            Task::Codesign(_) => Some(&mut searches),
            _ => Some(&mut assessments),
        };
        if let Some((done, planned)) = count {
            *planned += 1;
            *done += usize::from(job.out.exists());
            continue;
        }
        let Task::Run(run) = &job.task else {
            continue;
        };
        let budget = planned_evaluations(run.population as u64, run.evals);
        match run_state(&job.out) {
            RunState::Finished => {
                finished += 1;
                let written = fs::metadata(&job.out).and_then(|m| m.modified()).ok();
                rates.extend(
                    seconds_per_evaluation(&job.out)
                        .map(|r| (written, run.controller, r / work(run))),
                );
            }
            RunState::InFlight { evaluations } => {
                left += budget.saturating_sub(evaluations);
                todo.push((
                    run.controller,
                    budget.saturating_sub(evaluations),
                    work(run),
                ));
                flying.push((job.out.clone(), evaluations, budget));
            }
            RunState::NotStarted => {
                waiting += 1;
                left += budget;
                todo.push((run.controller, budget, work(run)));
            }
        }
    }
    let runs = finished + flying.len() + waiting;
    let mut text = String::new();
    if runs > 0 {
        text += &format!(
            "evolutionary runs: {finished} of {runs} finished, {} in flight, {waiting} not started\n",
            flying.len()
        );
    }
    for (out, done, budget) in &flying {
        let name = out
            .file_stem()
            .map_or_else(String::new, |s| s.to_string_lossy().into());
        text += &format!("  in flight: {name} at {done} of {budget} evaluations\n");
    }
    if searches.1 > 0 {
        text += &format!("body searches: {} of {} finished\n", searches.0, searches.1);
    }
    if assessments.1 > 0 {
        text += &format!(
            "assessments (validations, ablations, fidelity): {} of {} done\n",
            assessments.0, assessments.1
        );
    }
    if runs == 0 {
        return text;
    }
    if left == 0 {
        return text + "every evolutionary run is finished\n";
    }
    // The runs finished last: the machine and the code as they are now.
    rates.sort_by_key(|&(written, _, _)| written);
    let recent = |kind: Option<ControllerKind>| {
        let of_kind = rates
            .iter()
            .rev()
            .filter(|r| kind.map_or(true, |k| r.1 == k));
        median(of_kind.take(RECENT).map(|r| r.2).collect())
    };
    let Some(overall) = recent(None) else {
        return text
            + &format!(
                "left: {left} evaluations; no finished one-thread run yet to estimate their time from\n"
            );
    };
    let (mut seconds, mut borrowed) = (0.0, Vec::new());
    for &(kind, evaluations, work) in &todo {
        let unit = recent(Some(kind)).unwrap_or_else(|| {
            if !borrowed.contains(&kind) {
                borrowed.push(kind);
            }
            overall
        });
        seconds += evaluations as f64 * unit * work;
    }
    let hours = seconds / 3600.0;
    let borrowed = if borrowed.is_empty() {
        String::new()
    } else {
        let names: Vec<&str> = borrowed.iter().map(|k| k.name()).collect();
        format!(
            "; {} not finished yet, so from every controller's",
            names.join(", ")
        )
    };
    text += &format!(
        "left: {left} evaluations, about {hours:.1} core-hours on one thread (each run at the \
         median time per evaluation, voxel and simulated second of the last {RECENT} finished runs \
         of its controller{borrowed}); about {:.1} hours on {cores} core{}\n",
        hours / cores as f64,
        if cores == 1 { "" } else { "s" }
    );
    text
}
