//! `vsr bench`: single-thread simulation speed on the paper's four shapes under a
//! phase gait on a hilly terrain, and the throughput over a batch of 100 evaluations (a GA
//! generation, see `batch`); with `--evolution`, see `evolution`.

use std::time::Instant;

use vsr::experiment::{steps_for, GaitEpisode, PhaseGait};
use vsr::simulation::{Shape, Terrain};

mod batch;
mod evolution;

/// Arguments of `vsr bench`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// Print JSON: {"simulation": [one entry per shape], "batch": {...}}.
    #[arg(long)]
    json: bool,
    /// Timed 30-s evaluations per shape (the best is reported); passes over the batch of
    /// 100 evaluations: at most 3.
    #[arg(long, default_value_t = 10)]
    repeats: usize,
    /// Terrain.
    #[arg(long, default_value = "hilly-1-10-0")]
    terrain: String,
    /// Also time whole evolution steps per controller (1 thread and all threads) and the
    /// controller's cost over the bare simulation (about a minute); with --json under
    /// "evolution".
    #[arg(long)]
    evolution: bool,
    /// Population of the timed evolution steps.
    #[arg(long, default_value_t = 50)]
    population: usize,
}

/// The shapes measured.
pub const SHAPES: [&str; 4] = ["biped-4x3", "comb-7x2", "biped-6x4", "comb-14x2"];

/// Runs the command.
pub fn run(args: Args) -> vsr::Result<()> {
    let terrain = Terrain::parse(&args.terrain)?;
    let gait = PhaseGait::new(1.0, 1.5)?;
    let steps = steps_for(30.0);
    let mut rows = Vec::new();
    for name in SHAPES {
        let shape = Shape::parse(name)?;
        let mut best = f64::INFINITY;
        for _ in 0..args.repeats.max(1) {
            let start = Instant::now();
            let mut e = GaitEpisode::from_parts(&shape, terrain.clone(), gait);
            e.run(30.0)?;
            best = best.min(start.elapsed().as_secs_f64());
        }
        rows.push(serde_json::json!({
            "shape": name,
            "steps_per_second": steps as f64 / best,
            "ms_per_evaluation": best * 1000.0,
            "evaluations_per_second": 1.0 / best,
            "realtime_factor": 30.0 / best,
        }));
    }
    let batch = batch::measure(args.repeats.min(3))?;
    let evolution = match args.evolution {
        true => Some(evolution::measure(args.population, args.repeats.min(3))?),
        false => None,
    };
    if args.json {
        let mut out = serde_json::json!({ "simulation": rows, "batch": batch });
        if let Some(e) = evolution {
            out["evolution"] = e;
        }
        say!("{out}");
        return Ok(());
    }
    print_rows(&args, rows);
    batch::print(&batch);
    if let Some(e) = evolution {
        say!();
        evolution::print(&e);
    }
    Ok(())
}

fn print_rows(args: &Args, rows: Vec<serde_json::Value>) {
    say!(
        "single thread, gait 1,1.5 on {}, best of {}",
        args.terrain,
        args.repeats
    );
    say!(
        "{:<10} {:>12} {:>10} {:>10} {:>12}",
        "shape",
        "steps/s",
        "ms/eval",
        "evals/s",
        "sim s/wall s"
    );
    for r in rows {
        say!(
            "{:<10} {:>12.0} {:>10.2} {:>10.1} {:>12.0}",
            r["shape"].as_str().unwrap_or(""),
            r["steps_per_second"].as_f64().unwrap_or(0.0),
            r["ms_per_evaluation"].as_f64().unwrap_or(0.0),
            r["evaluations_per_second"].as_f64().unwrap_or(0.0),
            r["realtime_factor"].as_f64().unwrap_or(0.0),
        );
    }
}
