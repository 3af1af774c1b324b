//! `vsr ablate --genome RUN.json`: the frozen-attention ablation, one velocity per freeze
//! time (see `vsr::experiment::ablation`). The text output says what "frozen at s" means and
//! puts the unfrozen velocity (the same robot, its attention live) above the frozen ones.

use std::path::PathBuf;

use vsr::experiment::config::{check_seconds, MAX_SECONDS};
use vsr::experiment::{ablate, unfrozen_velocity, AblationPoint, ABLATION_TERRAIN};
use vsr::{Error, Result};

/// Arguments of `vsr ablate`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// The run file whose best individual (attention or slow-attention) is ablated.
    #[arg(long)]
    genome: PathBuf,
    /// The terrain of the recording and of the frozen episodes.
    #[arg(long, default_value = ABLATION_TERRAIN)]
    terrain: String,
    /// Freeze at every whole second 0 ..= LAST.
    #[arg(long, value_name = "LAST", default_value_t = 30)]
    last_second: u32,
    /// Simulated seconds of each frozen episode [default: the run's own episode length,
    /// config.seconds in the run file].
    #[arg(long)]
    seconds: Option<f64>,
    /// Print JSON: [{"freeze_second", "velocity"}...].
    #[arg(long)]
    json: bool,
    /// Also write that JSON array to this file (atomically).
    #[arg(long)]
    out: Option<PathBuf>,
}

/// Runs the command.
pub fn run(args: Args) -> Result<()> {
    args.seconds.map(check_seconds).transpose()?;
    if f64::from(args.last_second) > MAX_SECONDS {
        return Err(Error::Input(format!(
            "--last-second must be at most {MAX_SECONDS}, got {}",
            args.last_second
        )));
    }
    if let Some(out) = &args.out {
        crate::atomic::check_writable(out)?;
    }
    let run = crate::runfile::load(&args.genome)?;
    let seconds = args.seconds.unwrap_or(run.config.seconds);
    let best = run.best;
    let points = ablate(&best, &args.terrain, args.last_second, seconds)?;
    if let Some(out) = &args.out {
        crate::atomic::write_json(out, &points, "ablation file")?;
    }
    if args.json {
        let body = serde_json::to_string(&points)
            .map_err(|e| Error::Io(format!("cannot print JSON: {e}")))?;
        println!("{body}");
        return Ok(());
    }
    let unfrozen = unfrozen_velocity(&best, &args.terrain, seconds)?;
    print_table(&args.terrain, seconds, unfrozen, &points);
    Ok(())
}

/// The text output: what the rows mean, the unfrozen velocity, one row per freeze second.
fn print_table(terrain: &str, seconds: f64, unfrozen: f64, points: &[AblationPoint]) {
    println!(
        "Frozen at s: every voxel's attention matrix as it was s seconds into a walk on \
         {terrain},\nthen held fixed (no longer computed from the sensors) for a fresh \
         {seconds}-s walk on {terrain}.\nUnfrozen: the same walk with the attention live."
    );
    println!("{:>13}  {:>14.3}", "unfrozen", unfrozen);
    println!("frozen at (s)  velocity (m/s)");
    for p in points {
        println!("{:>13}  {:>14.3}", p.freeze_second, p.velocity);
    }
}
