//! `vsr evaluate --genome RUN.json --terrain T`: one episode of a run's best individual,
//! printed as JSON (`velocity`, `distance`, ...).

use std::path::PathBuf;

use vsr::experiment::evaluate::evaluate;
use vsr::simulation::{Shape, Terrain};

/// Arguments of `vsr evaluate`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// The run file whose best individual is evaluated.
    #[arg(long)]
    genome: PathBuf,
    /// Terrain name, e.g. flat or hilly-1-10-0.
    #[arg(long)]
    terrain: String,
    /// Another shape to put the genome on (its length must fit the shape).
    #[arg(long)]
    shape: Option<String>,
    /// Simulated seconds.
    #[arg(long, default_value_t = 30.0)]
    seconds: f64,
    /// Seed of the sensor noise.
    #[arg(long, default_value_t = 0)]
    noise_seed: u64,
}

/// Runs the command.
pub fn run(args: Args) -> vsr::Result<()> {
    crate::validate::check_seconds(args.seconds)?;
    let best = crate::runfile::load(&args.genome)?.best;
    let shape = match &args.shape {
        Some(s) => Shape::parse(s)?,
        None => best.shape.clone(),
    };
    let terrain = Terrain::parse(&args.terrain)?;
    let noise = Some(args.noise_seed);
    let outcome = evaluate(
        &shape,
        terrain,
        best.controller,
        &best.genome,
        noise,
        args.seconds,
    )?;
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
    println!("{body}");
    Ok(())
}
