//! `vsr ablate --genome RUN.json [--entry I]`: the frozen-attention ablation, one velocity per freeze
//! time (see `vsr::experiment::ablation`). The text output says what "frozen at s" means and
//! puts the unfrozen velocity (the same robot, its attention live) above the frozen ones.

use std::path::PathBuf;

use vsr::experiment::config::MAX_SECONDS;
use vsr::experiment::{ablate, unfrozen_velocity, AblationPoint, ABLATION_TERRAIN};
use vsr::{Error, Result};

/// Arguments of `vsr ablate`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// The individual ablated (attention or slow-attention): a run's best, or a co-design
    /// run file's best or archive entry.
    #[command(flatten)]
    individual: crate::runfile::Individual,
    /// The terrain of the recording and of the frozen episodes.
    #[arg(long, default_value = ABLATION_TERRAIN)]
    terrain: String,
    /// Freeze at every whole second 0 ..= LAST [default: the episode's length, whole seconds].
    #[arg(long, value_name = "LAST")]
    last_second: Option<u32>,
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
    if let Some(last) = args.last_second.filter(|&l| f64::from(l) > MAX_SECONDS) {
        return Err(Error::Input(format!(
            "--last-second must be at most {MAX_SECONDS}, got {last}"
        )));
    }
    if let Some(out) = &args.out {
        crate::atomic::check_writable(out)?;
    }
    let (best, seconds) = args.individual.load(args.seconds)?;
    // Whole seconds of the episode, at most MAX_SECONDS: a u32 without loss.
    let last_second = args.last_second.unwrap_or(seconds.floor() as u32);
    if f64::from(last_second) > seconds {
        eprintln!(
            "vsr: note: freezing up to {last_second} s, past the end of a {seconds}-s episode: \
             the walk that records the matrices goes on beyond it"
        );
    }
    let points = ablate(&best, &args.terrain, last_second, seconds)?;
    if let Some(out) = &args.out {
        crate::atomic::write_json(out, &points, "ablation file")?;
    }
    if args.json {
        let body = serde_json::to_string(&points)
            .map_err(|e| Error::Io(format!("cannot print JSON: {e}")))?;
        say!("{body}");
        return Ok(());
    }
    let unfrozen = unfrozen_velocity(&best, &args.terrain, seconds)?;
    print_table(&args.terrain, seconds, unfrozen, &points);
    Ok(())
}

/// The text output: what the rows mean, the unfrozen velocity, one row per freeze second.
fn print_table(terrain: &str, seconds: f64, unfrozen: f64, points: &[AblationPoint]) {
    say!(
        "Frozen at s: every voxel's attention matrix as it was s seconds into a walk on \
         {terrain},\nthen held fixed (no longer computed from the sensors) for a fresh \
         {seconds}-s walk on {terrain}.\nUnfrozen: the same walk with the attention live."
    );
    say!("{:>13}  {:>14.3}", "unfrozen", unfrozen);
    say!("frozen at (s)  velocity (m/s)");
    for p in points {
        say!("{:>13}  {:>14.3}", p.freeze_second, p.velocity);
    }
}
