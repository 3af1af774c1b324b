//! `vsr validate --genome RUN.json`: the best individual on the 10 unseen terrains
//! hilly-1-10-0 .. hilly-1-10-9, each velocity and the median.

use std::path::PathBuf;

use vsr::experiment::validate;
use vsr::{Error, Result};

/// Arguments of `vsr validate`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// The run file whose best individual is validated.
    #[arg(long)]
    genome: PathBuf,
    /// Simulated seconds per episode.
    #[arg(long, default_value_t = 30.0)]
    seconds: f64,
    /// Print one JSON object: {"terrains": [{"terrain", "velocity"}...], "median"}.
    #[arg(long)]
    json: bool,
}

/// Rejects episode lengths outside (0, 3600] s.
pub fn check_seconds(seconds: f64) -> Result<()> {
    if seconds > 0.0 && seconds <= 3600.0 {
        return Ok(());
    }
    Err(Error::Input(format!(
        "--seconds must be in (0, 3600], got {seconds}"
    )))
}

/// Runs the command.
pub fn run(args: Args) -> Result<()> {
    check_seconds(args.seconds)?;
    let best = crate::runfile::load(&args.genome)?.best;
    let validation = validate(&best, args.seconds)?;
    if args.json {
        let body = serde_json::to_string(&validation)
            .map_err(|e| Error::Io(format!("cannot print JSON: {e}")))?;
        println!("{body}");
        return Ok(());
    }
    for t in &validation.terrains {
        println!("{:<14} {:>8.3} m/s", t.terrain, t.velocity);
    }
    println!("{:<14} {:>8.3} m/s", "median", validation.median);
    Ok(())
}
