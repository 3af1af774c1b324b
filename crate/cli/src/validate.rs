//! `vsr validate --genome RUN.json [--set paper|unseen]`: the best individual on a set of 10
//! validation terrains (the paper's hilly-1-10-0..9 by default, or hilly-1-10-10000..10009,
//! outside the training pool), each velocity, the median and the mean. With `--bodies FILE`,
//! a brain for any body on every body of a set: each body's mean speed, their median and
//! the share of bodies above 1 m/s.

use std::path::PathBuf;

use rayon::prelude::*;
use vsr::experiment::body_set::{validate_body, BodiesValidation};
use vsr::experiment::{validate_on, Best, BodySet, ValidationSet};
use vsr::{Error, Result};

/// Arguments of `vsr validate`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// The run file whose best individual is walked (or a co-design run file: its best body
    /// with its brain).
    #[arg(long, required_unless_present = "random_brain")]
    genome: Option<PathBuf>,
    /// A co-design run file's archive entry (0 first, in the file's order) instead of its best.
    #[arg(long, requires = "genome")]
    entry: Option<usize>,
    /// Instead of --genome, with --bodies: a random brain for any body of this family
    /// (attention-any, mlp-any, mlp-comm-any), its genes drawn uniformly in [-1, 1] (the GA's
    /// initial range) from --seed: the floor a trained brain is measured against. Episodes
    /// of --seconds (default 30).
    #[arg(long, value_name = "CONTROLLER", conflicts_with = "genome", requires_all = ["bodies", "seed"])]
    random_brain: Option<vsr::controllers::ControllerKind>,
    /// The seed of --random-brain's genes.
    #[arg(long, requires = "random_brain")]
    seed: Option<u64>,
    /// Simulated seconds per episode [default: the run's own episode length, config.seconds
    /// in the run file].
    #[arg(long)]
    seconds: Option<f64>,
    /// The terrains: paper (hilly-1-10-0..9, also in the training pool) or unseen
    /// (hilly-1-10-10000..10009).
    #[arg(long, default_value = "paper")]
    set: ValidationSet,
    /// Print one JSON object: {"set", "terrains": [{"terrain", "velocity"}...], "median", "mean"}.
    #[arg(long)]
    json: bool,
    /// Also write that JSON object to this file (atomically).
    #[arg(long)]
    out: Option<PathBuf>,
    /// Walk a brain for any body on every body of this body-set file instead of its own body
    /// (JSON: {"bodies", "set", "seconds", "median", "walking_share", "per_body": [{"body",
    /// "validation"}...]}).
    #[arg(long, value_name = "FILE")]
    bodies: Option<PathBuf>,
    /// Worker threads for --bodies (default: all cores). Never changes the result.
    #[arg(long)]
    threads: Option<usize>,
}

/// Runs the command.
pub fn run(args: Args) -> Result<()> {
    let (best, seconds) = match (&args.genome, args.random_brain) {
        (Some(genome), _) => crate::runfile::Individual {
            genome: genome.clone(),
            entry: args.entry,
        }
        .load(args.seconds)?,
        (None, Some(kind)) => random_brain(&args, kind)?,
        (None, None) => unreachable!("clap requires --genome or --random-brain"),
    };
    if let Some(out) = &args.out {
        crate::atomic::check_writable(out)?;
    }
    if let Some(path) = &args.bodies {
        return on_bodies(&args, &best, path, seconds);
    }
    let validation = validate_on(&best, args.set, seconds)?;
    if written(&args, &validation)? {
        return Ok(());
    }
    for t in &validation.terrains {
        say!("{:<16} {:>8.3} m/s", t.terrain, t.velocity);
    }
    say!("{:<16} {:>8.3} m/s", "median", validation.median);
    say!("{:<16} {:>8.3} m/s", "mean", validation.mean);
    Ok(())
}

/// `--random-brain`: the seeded random genome on the set's first body, and the episode
/// length (`--seconds`, 30 by default).
fn random_brain(args: &Args, kind: vsr::controllers::ControllerKind) -> Result<(Best, f64)> {
    let seconds = args.seconds.unwrap_or(30.0);
    vsr::experiment::config::check_seconds(seconds)?;
    let path = args.bodies.as_ref().expect("clap requires --bodies");
    let bodies = BodySet::read(path)?;
    let seed = args.seed.expect("clap requires --seed");
    let best = vsr::experiment::body_set::random_brain(kind, &bodies.bodies[0], seed)?;
    Ok((best, seconds))
}

/// Writes `validation` to `--out` when asked, and prints it as JSON with `--json` (then
/// true: nothing more to print).
fn written(args: &Args, validation: &impl serde::Serialize) -> Result<bool> {
    if let Some(out) = &args.out {
        crate::atomic::write_json(out, validation, "validation file")?;
    }
    if args.json {
        let body = serde_json::to_string(validation)
            .map_err(|e| Error::Io(format!("cannot print JSON: {e}")))?;
        say!("{body}");
    }
    Ok(args.json)
}

/// `--bodies`: every body of the set, spread over threads (the result never depends on them).
fn on_bodies(args: &Args, best: &Best, path: &std::path::Path, seconds: f64) -> Result<()> {
    let bodies = BodySet::read(path)?;
    // A brain tied to its body is refused before any episode runs.
    vsr::experiment::body_set::validation::best_on(best, &bodies.bodies[0])?;
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(args.threads.unwrap_or(0))
        .build()
        .map_err(|e| Error::Input(format!("cannot start the threads: {e}")))?;
    let per_body = pool.install(|| {
        bodies
            .bodies
            .par_iter()
            .map(|b| validate_body(best, b, args.set, seconds))
            .collect::<Result<Vec<_>>>()
    })?;
    let validation = BodiesValidation::new(&bodies, args.set, seconds, per_body);
    if written(args, &validation)? {
        return Ok(());
    }
    for b in &validation.per_body {
        say!("{:<24} {:>8.3} m/s", b.body.to_rows(), b.validation.mean);
    }
    say!(
        "{} bodies of {} on the {} terrains: median {:.3} m/s, {:.0}% above 1 m/s",
        validation.per_body.len(),
        validation.bodies,
        validation.set,
        validation.median,
        100.0 * validation.walking_share
    );
    if validation.exploded > 0 {
        say!(
            "{} episodes exploded (non-finite), each counted as 0 m/s",
            validation.exploded
        );
    }
    Ok(())
}
