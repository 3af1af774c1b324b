//! `vsr simulate`: one episode of a shape on a terrain under a phase gait, optionally
//! started off the reference placement, recorded step by step, or run as an ensemble
//! of shifted starts (`simulate/ensemble.rs`).

use std::path::PathBuf;
use std::time::Instant;

use vsr::experiment::config::check_seconds;
use vsr::experiment::{check_start_offset, steps_for, Episode, PhaseGait, Policy};
use vsr::simulation::{Shape, Terrain};

use crate::trajectory::Writer;
use ensemble::Setup;

mod ensemble;

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
    /// Shift the robot's start right by DX metres before it is lowered onto the
    /// terrain (the reference placement puts its left edge at x = 11 m).
    #[arg(
        long,
        value_name = "DX",
        default_value_t = 0.0,
        allow_hyphen_values = true
    )]
    start_offset: f64,
    /// Run K starts shifted by k x 1e-5 m (k = 0..K-1, from --start-offset) and print
    /// each velocity with their mean and sd.
    #[arg(long, value_name = "K", allow_hyphen_values = true)]
    ensemble: Option<i64>,
    /// Write the run as JSON lines to FILE, one per step: t, centre, area, actuation,
    /// squares.
    #[arg(long, value_name = "FILE")]
    trajectory: Option<PathBuf>,
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
    check_seconds(args.seconds)?;
    let shape = Shape::parse(&args.shape)?;
    let terrain = Terrain::parse(&args.terrain)?;
    let gait = PhaseGait::parse(&args.gait)?;
    check_start_offset(&shape, &terrain, args.start_offset)?;
    if let Some(k) = args.ensemble {
        let runs = ensemble::runs(k)?;
        if args.trajectory.is_some() || args.trace_voxel.is_some() {
            return Err(vsr::Error::Input(
                "--trajectory and --trace-voxel record one run; drop --ensemble".into(),
            ));
        }
        let setup = Setup {
            shape: &shape,
            terrain: (&terrain, &args.terrain),
            gait,
            seconds: args.seconds,
            base: args.start_offset,
        };
        return ensemble::run(&setup, runs, args.json);
    }
    if let Some(v) = args.trace_voxel.filter(|&v| v >= shape.voxel_count()) {
        return Err(vsr::Error::Input(format!(
            "--trace-voxel {v}: the shape has {} voxels (0..{})",
            shape.voxel_count(),
            shape.voxel_count() - 1
        )));
    }
    let writer = args.trajectory.as_deref().map(Writer::create).transpose()?;
    let start = Instant::now();
    let policy = Policy::Gait(gait);
    let mut episode = Episode::with_start_offset(&shape, terrain, policy, None, args.start_offset);
    let steps = steps_for(args.seconds);
    let trace = match args.trace_voxel {
        Some(v) => Some(record_trace(&mut episode, v, steps, writer)?),
        None => {
            crate::trajectory::run(&mut episode, steps, writer)?;
            None
        }
    };
    let outcome = episode.run(args.seconds)?;
    let wall = start.elapsed().as_secs_f64();
    if args.json {
        let body = serde_json::json!({
            "shape": shape.to_rows(),
            "terrain": args.terrain,
            "gait": { "frequency": gait.frequency, "phase": gait.phase },
            "start_offset": args.start_offset,
            "velocity": outcome.velocity,
            "distance": outcome.distance,
            "steps": outcome.steps,
            "voxels": shape.voxel_count(),
            "seconds": outcome.seconds,
            "wall_seconds": wall,
            "trace": trace,
        });
        say!("{body}");
    } else {
        say!(
            "{} on {} with gait {},{}: velocity {:.4} m/s, distance {:.3} m, {} steps ({:.2} s simulated) in {:.1} ms",
            args.shape, args.terrain, gait.frequency, gait.phase, outcome.velocity,
            outcome.distance, outcome.steps, outcome.seconds, wall * 1000.0
        );
    }
    Ok(())
}

/// Steps the episode `steps` times, recording voxel `v` after every step (and writing
/// the trajectory, if any).
fn record_trace(
    episode: &mut Episode,
    v: usize,
    steps: u64,
    mut writer: Option<Writer>,
) -> vsr::Result<serde_json::Value> {
    let (mut t, mut area, mut control) = (vec![], vec![], vec![]);
    for _ in 0..steps {
        episode.step(1)?;
        t.push(episode.time());
        area.push(episode.world().area_ratio(v));
        control.push(episode.actuation()[v]);
        if let Some(w) = &mut writer {
            w.write(episode)?;
        }
    }
    if let Some(w) = writer {
        w.finish()?;
    }
    Ok(serde_json::json!({ "voxel": v, "t": t, "area_ratio": area, "control": control }))
}
