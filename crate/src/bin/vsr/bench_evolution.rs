//! `vsr bench --evolution`: evaluations per second of whole evolution steps (ask, evaluate in
//! parallel, tell) for every controller on biped-4x3, on 1 thread and on all threads, and the
//! controller's cost on top of the bare simulation.
//!
//! The cost is measured on identical motion: a phase-gait episode is timed alone and again with
//! the controller computing in its shadow (sensors after every step, the controller at every
//! latch, or every step when it has state), its output discarded.

use std::hint::black_box;
use std::time::Instant;

use rayon::prelude::*;
use vsr::controllers::{Controller, ControllerKind};
use vsr::experiment::evaluate::controller_for;
use vsr::experiment::{steps_for, Evolution, EvolutionConfig, GaitEpisode, PhaseGait};
use vsr::random::rng_from;
use vsr::simulation::constants::ACTUATION_HOLD_STEPS;
use vsr::simulation::sensors::Sensors;
use vsr::simulation::{Shape, Terrain};
use vsr::Result;

use crate::evolve::thread_pool;

/// Terrains used for the controller-cost comparison.
const COST_TERRAINS: u32 = 4;

/// Seconds for `generations` whole generations of `kind` (population `population`) on
/// `threads` threads, and the evaluations done.
fn time_evolution(
    kind: ControllerKind,
    population: usize,
    threads: Option<usize>,
) -> Result<(f64, u64)> {
    let shape = Shape::parse("biped-4x3")?;
    let mut config = EvolutionConfig::paper(shape, kind, 3 * population as u64, 1);
    config.ga.population = population;
    let mut evolution = Evolution::new(config)?;
    let pool = thread_pool(threads)?;
    let start = Instant::now();
    pool.install(|| {
        evolution.run(
            |jobs| jobs.par_iter().map(|j| j.fitness()).collect(),
            |_| {},
            || 0.0,
        )
    })?;
    Ok((start.elapsed().as_secs_f64(), evolution.evaluations()))
}

/// Seconds of one 30-s gait episode on `terrain`, with `kind` computing in the shadow if set.
fn time_gait(shape: &Shape, terrain: &Terrain, kind: Option<ControllerKind>) -> Result<f64> {
    let n = shape.voxel_count();
    let mut brain: Option<Box<dyn Controller>> = match kind {
        Some(k) => {
            let mut rng = rng_from(7);
            let genome: Vec<f32> = (0..k.param_count(n))
                .map(|_| rand::Rng::gen_range(&mut rng, -1.0..1.0))
                .collect();
            Some(controller_for(k, shape, &genome)?)
        }
        None => None,
    };
    let mut sensors = Sensors::new(n, Some(1));
    let mut out = vec![0.0f32; n];
    let mut episode = GaitEpisode::from_parts(shape, terrain.clone(), PhaseGait::new(1.0, 1.5)?);
    let start = Instant::now();
    for k in 0..steps_for(30.0) {
        episode.step(1)?;
        if let Some(c) = brain.as_mut() {
            sensors.sense(episode.world());
            if k % ACTUATION_HOLD_STEPS as u64 == 0 || c.needs_every_step() {
                c.control(sensors.read(episode.world()), &mut out);
                black_box(&out);
            }
        }
    }
    Ok(start.elapsed().as_secs_f64())
}

/// Relative cost of `kind` on top of the gait episodes (best of `repeats` per terrain).
fn controller_cost(kind: Option<ControllerKind>, repeats: usize) -> Result<f64> {
    let shape = Shape::parse("biped-4x3")?;
    let mut total = 0.0;
    for i in 0..COST_TERRAINS {
        let terrain = Terrain::parse(&format!("hilly-1-10-{i}"))?;
        let mut best = f64::INFINITY;
        for _ in 0..repeats.max(1) {
            best = best.min(time_gait(&shape, &terrain, kind)?);
        }
        total += best;
    }
    Ok(total)
}

/// Prints the evolution table; `population` sets the size of the timed generations.
pub fn run(population: usize, repeats: usize) -> Result<()> {
    let all = thread_pool(None)?.current_num_threads();
    println!(
        "evolution steps on biped-4x3: generations 0-1 (population {population}, {} evaluations), \
         30-s episodes on fresh hilly-1-10 terrains",
        3 * population
    );
    println!(
        "{:<15} {:>7} {:>13} {:>13} {:>16}",
        "controller",
        "params",
        "evals/s 1 thr",
        format!("evals/s {all} thr"),
        "controller cost"
    );
    let bare = controller_cost(None, repeats)?;
    for kind in ControllerKind::ALL {
        let (t1, evals) = time_evolution(kind, population, Some(1))?;
        let (tn, _) = time_evolution(kind, population, None)?;
        let cost = controller_cost(Some(kind), repeats)? / bare - 1.0;
        println!(
            "{:<15} {:>7} {:>13.1} {:>13.1} {:>15.1}%",
            kind.name(),
            kind.param_count(10),
            evals as f64 / t1,
            evals as f64 / tn,
            100.0 * cost
        );
    }
    println!(
        "controller cost: extra time of sensors + controller over the bare gait episode \
         ({COST_TERRAINS} terrains, best of {repeats}; bare {:.1} ms per episode)",
        1000.0 * bare / f64::from(COST_TERRAINS)
    );
    Ok(())
}
