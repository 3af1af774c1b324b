//! `vsr simulate`: one episode of a shape on a terrain under a phase gait.

use std::time::Instant;

use vsr::experiment::{GaitEpisode, PhaseGait};
use vsr::simulation::{Shape, Terrain};

/// Arguments of `vsr simulate`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// Shape: a preset (biped-4x3, comb-7x2, biped-6x4, comb-14x2, worm-WxH, box-WxH)
    /// or rows top first, e.g. 1111-1111-1001.
    #[arg(long)]
    shape: String,
    /// Terrain name, e.g. flat or hilly-1-10-0.
    #[arg(long, default_value = "flat")]
    terrain: String,
    /// Phase gait F,PHI: u = sin(2 pi F t + PHI x) for the voxel in column x.
    #[arg(long, allow_hyphen_values = true)]
    gait: String,
    /// Simulated seconds.
    #[arg(long, default_value_t = 30.0, allow_hyphen_values = true)]
    seconds: f64,
    /// Also record voxel V's area ratio and held actuation after every step (JSON
    /// field "trace").
    #[arg(long, value_name = "V")]
    trace_voxel: Option<usize>,
    /// Print one JSON object instead of text.
    #[arg(long)]
    json: bool,
}

/// Runs the command.
pub fn run(args: Args) -> vsr::Result<()> {
    if !(args.seconds > 0.0 && args.seconds <= 3600.0) {
        return Err(vsr::Error::Input(format!(
            "--seconds must be in (0, 3600], got {}",
            args.seconds
        )));
    }
    let shape = Shape::parse(&args.shape)?;
    let terrain = Terrain::parse(&args.terrain)?;
    let gait = PhaseGait::parse(&args.gait)?;
    let start = Instant::now();
    let mut episode = GaitEpisode::from_parts(&shape, terrain, gait);
    let trace = match args.trace_voxel {
        Some(v) if v >= shape.voxel_count() => {
            return Err(vsr::Error::Input(format!(
                "--trace-voxel {v}: the shape has {} voxels (0..{})",
                shape.voxel_count(),
                shape.voxel_count() - 1
            )))
        }
        Some(v) => Some(record_trace(&mut episode, v, args.seconds)?),
        None => None,
    };
    let outcome = episode.run(args.seconds)?;
    let wall = start.elapsed().as_secs_f64();
    if args.json {
        let body = serde_json::json!({
            "shape": shape.to_rows(),
            "terrain": args.terrain,
            "gait": { "frequency": gait.frequency, "phase": gait.phase },
            "velocity": outcome.velocity,
            "distance": outcome.distance,
            "steps": outcome.steps,
            "voxels": shape.voxel_count(),
            "seconds": outcome.seconds,
            "wall_seconds": wall,
            "trace": trace,
        });
        println!("{body}");
    } else {
        println!(
            "{} on {} with gait {},{}: velocity {:.4} m/s, distance {:.3} m, {} steps ({:.2} s simulated) in {:.1} ms",
            args.shape, args.terrain, gait.frequency, gait.phase, outcome.velocity,
            outcome.distance, outcome.steps, outcome.seconds, wall * 1000.0
        );
    }
    Ok(())
}

/// Steps the episode to `seconds`, recording voxel `v` after every step.
fn record_trace(
    episode: &mut GaitEpisode,
    v: usize,
    seconds: f64,
) -> vsr::Result<serde_json::Value> {
    let (mut t, mut area, mut control) = (vec![], vec![], vec![]);
    for _ in 0..vsr::experiment::steps_for(seconds) {
        episode.step(1)?;
        t.push(episode.time());
        area.push(episode.world().area_ratio(v));
        control.push(episode.actuation()[v]);
    }
    Ok(serde_json::json!({ "voxel": v, "t": t, "area_ratio": area, "control": control }))
}
