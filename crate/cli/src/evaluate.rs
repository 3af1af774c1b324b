//! `vsr evaluate --genome RUN.json --terrain T`: one episode of a run's best individual,
//! printed as JSON (`velocity`, `distance`, ...); `--trajectory FILE` also writes it
//! step by step.

use std::path::PathBuf;

use vsr::experiment::evaluate::controller_for;
use vsr::experiment::{steps_for, Episode, Policy};
use vsr::simulation::{Shape, Terrain};

use crate::trajectory::Writer;

/// Arguments of `vsr evaluate`.
#[derive(clap::Args, Debug)]
pub struct Args {
    #[command(flatten)]
    individual: crate::runfile::Individual,
    /// Terrain name, e.g. flat or hilly-1-10-0.
    #[arg(long)]
    terrain: String,
    /// Another shape to put the genome on (its length must fit the shape).
    #[arg(long)]
    shape: Option<String>,
    /// Simulated seconds [default: the run's own episode length, config.seconds in the run
    /// file].
    #[arg(long)]
    seconds: Option<f64>,
    /// Seed of the sensor noise.
    #[arg(long, default_value_t = 0)]
    noise_seed: u64,
    /// Write the run as JSON lines to FILE, one per step: t, centre, area, actuation,
    /// squares.
    #[arg(long, value_name = "FILE")]
    trajectory: Option<PathBuf>,
}

/// Runs the command.
pub fn run(args: Args) -> vsr::Result<()> {
    let (best, seconds) = args.individual.load(args.seconds)?;
    let shape = match &args.shape {
        Some(s) => Shape::parse(s)?,
        None => best.shape.clone(),
    };
    let terrain = Terrain::parse(&args.terrain)?;
    let noise = Some(args.noise_seed);
    let controller = controller_for(best.controller, &shape, &best.genome)?;
    let writer = args.trajectory.as_deref().map(Writer::create).transpose()?;
    // The episode `vsr::experiment::evaluate::evaluate` runs, stepped here so that
    // it can be recorded.
    let mut episode = Episode::with_policy(&shape, terrain, Policy::Brain(controller), noise);
    crate::trajectory::run(&mut episode, steps_for(seconds), writer)?;
    let outcome = episode.run(seconds)?;
    let body = serde_json::json!({
        "shape": shape.to_rows(),
        "controller": best.controller,
        "terrain": args.terrain,
        "noise_seed": args.noise_seed,
        "velocity": outcome.velocity,
        "distance": outcome.distance,
        "steps": outcome.steps,
        "seconds": outcome.seconds,
    });
    say!("{body}");
    Ok(())
}
