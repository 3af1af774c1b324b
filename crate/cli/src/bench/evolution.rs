//! `vsr bench --evolution`: evaluations per second of whole evolution steps (ask, evaluate in
//! parallel, tell) for every controller on biped-4x3, on 1 thread and on all threads, and the
//! controller's cost on top of the bare simulation.
//!
//! The cost is measured on identical motion: a phase-gait episode drives the robot while the
//! controller computes in its shadow (sensors after every step, the controller at every latch,
//! or every step when it has state; its output discarded). The time spent in sensors and
//! controller is divided by the time spent in the physics of the same episode.

use std::hint::black_box;
use std::time::Instant;

use rayon::prelude::*;
use serde_json::{json, Value};
use vsr::controllers::{Controller, ControllerKind};
use vsr::experiment::evaluate::controller_for;
use vsr::experiment::{steps_for, Evolution, EvolutionConfig, GaitEpisode, Job, PhaseGait};
use vsr::random::rng_from;
use vsr::simulation::constants::ACTUATION_HOLD_STEPS;
use vsr::simulation::sensors::Sensors;
use vsr::simulation::{Shape, Terrain};
use vsr::Result;

use crate::evolution::thread_pool;

/// Terrains used for the controller-cost comparison.
const COST_TERRAINS: u32 = 4;

/// Seconds for generations 0 and 1 (3 x `population` evaluations) of `kind` on
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
            |jobs| jobs.par_iter().map(Job::fitness).collect(),
            |_| Ok(()),
            || 0.0,
        )
    })?;
    Ok((start.elapsed().as_secs_f64(), evolution.evaluations()))
}

/// A random genome of `kind` for `shape`, from a fixed seed.
fn random_brain(kind: ControllerKind, shape: &Shape) -> Result<Box<dyn Controller>> {
    let mut rng = rng_from(7);
    let genome: Vec<f32> = (0..kind.param_count(shape.voxel_count()))
        .map(|_| rand::Rng::gen_range(&mut rng, -1.0..1.0))
        .collect();
    controller_for(kind, shape, &genome)
}

/// Seconds of physics, of sensors and of the controller in one 30-s gait episode on
/// `terrain` with `kind` computing in the shadow.
fn time_shadow(shape: &Shape, terrain: &Terrain, kind: ControllerKind) -> Result<[f64; 3]> {
    let mut brain = random_brain(kind, shape)?;
    let mut sensors = Sensors::new(shape.voxel_count(), Some(1));
    let mut out = vec![0.0f32; shape.voxel_count()];
    let mut episode = GaitEpisode::from_parts(shape, terrain.clone(), PhaseGait::new(1.0, 1.5)?);
    let (mut sensing, mut thinking) = (0.0, 0.0);
    let start = Instant::now();
    for k in 0..steps_for(30.0) {
        episode.step(1)?;
        let t0 = Instant::now();
        sensors.sense(episode.world());
        if k % ACTUATION_HOLD_STEPS as u64 == 0 || brain.needs_every_step() {
            let readings = sensors.read(episode.world());
            let t1 = Instant::now();
            brain.control(readings, &mut out);
            black_box(&out);
            thinking += t1.elapsed().as_secs_f64();
        }
        sensing += t0.elapsed().as_secs_f64();
    }
    let physics = start.elapsed().as_secs_f64() - sensing;
    Ok([physics, sensing - thinking, thinking])
}

/// Physics seconds per episode, and the costs of sensors and of the controller `kind`
/// relative to them (each the best of `repeats`, summed over the cost terrains).
fn controller_cost(kind: ControllerKind, repeats: usize) -> Result<[f64; 3]> {
    let shape = Shape::parse("biped-4x3")?;
    let mut sum = [0.0; 3];
    for i in 0..COST_TERRAINS {
        let terrain = Terrain::parse(&format!("hilly-1-10-{i}"))?;
        let mut best = [f64::INFINITY; 3];
        for _ in 0..repeats.max(1) {
            let times = time_shadow(&shape, &terrain, kind)?;
            best.iter_mut().zip(times).for_each(|(b, t)| *b = b.min(t));
        }
        sum.iter_mut().zip(best).for_each(|(s, b)| *s += b);
    }
    let [physics, sensing, thinking] = sum;
    Ok([
        physics / f64::from(COST_TERRAINS),
        sensing / physics,
        thinking / physics,
    ])
}

/// Measures every controller; `population` sets the size of the timed generations.
pub fn measure(population: usize, repeats: usize) -> Result<Value> {
    let all = thread_pool(None)?.current_num_threads();
    let mut bare = f64::INFINITY;
    let mut rows = Vec::new();
    for kind in ControllerKind::ALL {
        let (t1, evals) = time_evolution(kind, population, Some(1))?;
        let (tn, _) = time_evolution(kind, population, None)?;
        let [physics, sensing, thinking] = controller_cost(kind, repeats)?;
        bare = bare.min(physics);
        rows.push(json!({
            "controller": kind.name(),
            "params": kind.param_count(10),
            "evaluations_per_second_1_thread": evals as f64 / t1,
            "evaluations_per_second_all_threads": evals as f64 / tn,
            "sensor_cost": sensing,
            "controller_cost": thinking,
            "total_cost": sensing + thinking,
        }));
    }
    Ok(json!({
        "shape": "biped-4x3",
        "population": population,
        "evaluations": 3 * population,
        "threads": all,
        "bare_ms_per_episode": 1000.0 * bare,
        "cost_terrains": COST_TERRAINS,
        "repeats": repeats,
        "controllers": rows,
    }))
}

/// Prints what [`measure`] returned as a table.
pub fn print(e: &Value) {
    let num = |v: &Value| v.as_f64().unwrap_or(f64::NAN);
    say!(
        "evolution steps on biped-4x3: generations 0-1 (population {}, {} evaluations), 30-s \
         episodes on fresh hilly-1-10 terrains",
        e["population"],
        e["evaluations"]
    );
    let all = format!("evals/s {} thr", e["threads"]);
    say!(
        "{:<15} {:>7} {:>13} {:>13} {:>8} {:>11} {:>7}",
        "controller",
        "params",
        "evals/s 1 thr",
        all,
        "sensors",
        "controller",
        "total"
    );
    for r in e["controllers"].as_array().into_iter().flatten() {
        say!(
            "{:<15} {:>7} {:>13.1} {:>13.1} {:>7.1}% {:>10.1}% {:>6.1}%",
            r["controller"].as_str().unwrap_or(""),
            r["params"],
            num(&r["evaluations_per_second_1_thread"]),
            num(&r["evaluations_per_second_all_threads"]),
            100.0 * num(&r["sensor_cost"]),
            100.0 * num(&r["controller_cost"]),
            100.0 * num(&r["total_cost"])
        );
    }
    say!(
        "costs: time in sensors and in the controller / time in physics, same gait episode \
         ({} terrains, best of {}; physics {:.1} ms per episode)",
        e["cost_terrains"],
        e["repeats"],
        num(&e["bare_ms_per_episode"])
    );
}
