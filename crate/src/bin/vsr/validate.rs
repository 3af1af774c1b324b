//! `vsr validate --genome RUN.json [--set paper|unseen]`: the best individual on a set of 10
//! validation terrains (the paper's hilly-1-10-0..9 by default, or hilly-1-10-10000..10009,
//! outside the training pool), each velocity, the median and the mean.

use std::path::PathBuf;

use vsr::experiment::{validate_on, ValidationSet};
use vsr::{Error, Result};

/// Arguments of `vsr validate`.
#[derive(clap::Args, Debug)]
pub struct Args {
    #[command(flatten)]
    individual: crate::runfile::Individual,
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
}

/// Runs the command.
pub fn run(args: Args) -> Result<()> {
    let (best, seconds) = args.individual.load(args.seconds)?;
    if let Some(out) = &args.out {
        crate::atomic::check_writable(out)?;
    }
    let validation = validate_on(&best, args.set, seconds)?;
    if let Some(out) = &args.out {
        crate::atomic::write_json(out, &validation, "validation file")?;
    }
    if args.json {
        let body = serde_json::to_string(&validation)
            .map_err(|e| Error::Io(format!("cannot print JSON: {e}")))?;
        say!("{body}");
        return Ok(());
    }
    for t in &validation.terrains {
        say!("{:<16} {:>8.3} m/s", t.terrain, t.velocity);
    }
    say!("{:<16} {:>8.3} m/s", "median", validation.median);
    say!("{:<16} {:>8.3} m/s", "mean", validation.mean);
    Ok(())
}
