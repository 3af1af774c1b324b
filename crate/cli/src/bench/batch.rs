//! `vsr bench`'s batch figure: throughput over one GA generation, the unit of work of an
//! evolution (issue 30's native target is counted this way). Generation 0 of the paper's
//! biped-4x3 attention run (seed 1): 100 evaluations of 30 s, each on its own hilly terrain
//! with its own sensor noise, evaluated one after the other on one thread exactly as
//! `vsr evolve` evaluates them, on one thread: alone (`Job::fitness`, one after the other)
//! and together (`fitness_together`: four at a time with their springs in SIMD lanes), the
//! two passes alternating. Each figure is the best of `repeats` passes over the whole batch,
//! divided by the batch size; the two must give the same fitness values, bit for bit, or
//! the command fails.

use std::time::Instant;

use serde_json::{json, Value};
use vsr::controllers::ControllerKind;
use vsr::experiment::{fitness_together, Evolution, EvolutionConfig, Job};
use vsr::simulation::Shape;
use vsr::Error;
use vsr::Result;

/// The shape, controller and run seed of the batch.
const SHAPE: &str = "biped-4x3";
const CONTROLLER: ControllerKind = ControllerKind::Attention;
const SEED: u64 = 1;

/// The batch: generation 0 of the run (the paper's population, 100 jobs).
fn generation() -> Result<Vec<Job>> {
    let config = EvolutionConfig::paper(Shape::parse(SHAPE)?, CONTROLLER, 30_000, SEED);
    Ok(Evolution::new(config)?.next_batch())
}

/// CPU seconds this thread has run (Linux: /proc/thread-self/schedstat; NaN elsewhere).
/// Steadier than wall time on a shared machine: time spent waiting for a core is left out.
fn cpu_seconds() -> f64 {
    std::fs::read_to_string("/proc/thread-self/schedstat")
        .ok()
        .and_then(|s| s.split_whitespace().next()?.parse::<f64>().ok())
        .map_or(f64::NAN, |ns| ns * 1e-9)
}

/// Wall and CPU seconds for one pass of `evaluate` over `jobs`, and the fitness bits.
fn time(jobs: &[Job], evaluate: fn(&[Job]) -> Result<Vec<f64>>) -> Result<([f64; 2], Vec<u64>)> {
    let (start, cpu) = (Instant::now(), cpu_seconds());
    let fitness = evaluate(jobs)?;
    let seconds = [start.elapsed().as_secs_f64(), cpu_seconds() - cpu];
    Ok((seconds, fitness.iter().map(|f| f.to_bits()).collect()))
}

fn alone(jobs: &[Job]) -> Result<Vec<f64>> {
    jobs.iter().map(Job::fitness).collect()
}

/// Times `repeats` passes over the batch on this thread, alone and together alternating;
/// the fastest pass of each counts.
pub fn measure(repeats: usize) -> Result<Value> {
    let jobs = generation()?;
    let (mut best_alone, mut best_together) = ([f64::INFINITY; 2], [f64::INFINITY; 2]);
    for _ in 0..repeats.max(1) {
        let (t_alone, f_alone) = time(&jobs, alone)?;
        let (t_together, f_together) = time(&jobs, fitness_together)?;
        if f_alone != f_together {
            return Err(Error::Input(
                "bench: the batch evaluated together differs from alone".into(),
            ));
        }
        for i in 0..2 {
            best_alone[i] = best_alone[i].min(t_alone[i]);
            best_together[i] = best_together[i].min(t_together[i]);
        }
    }
    let n = jobs.len() as f64;
    let figures = |[wall, cpu]: [f64; 2]| {
        json!({
            "seconds_per_batch": wall,
            "ms_per_evaluation": wall * 1000.0 / n,
            "evaluations_per_second": n / wall,
            "cpu_ms_per_evaluation": cpu * 1000.0 / n,
        })
    };
    // The headline figure is the batch as `vsr evolve` evaluates it: alone (together is
    // not faster yet, docs/speed.md).
    let best = best_alone[0];
    Ok(json!({
        "shape": SHAPE,
        "controller": CONTROLLER.name(),
        "generation": 0,
        "seed": SEED,
        "evaluations": jobs.len(),
        "threads": 1,
        "repeats": repeats.max(1),
        "alone": figures(best_alone),
        "together": figures(best_together),
        "ms_per_evaluation": best * 1000.0 / n,
        "evaluations_per_second": n / best,
    }))
}

/// Prints what [`measure`] returned.
pub fn print(b: &Value) {
    let num = |v: &Value| v.as_f64().unwrap_or(f64::NAN);
    say!(
        "batch: {} evaluations (generation {} of the {} {} run, seed {}) on 1 thread, best of {}:",
        b["evaluations"],
        b["generation"],
        b["shape"].as_str().unwrap_or(""),
        b["controller"].as_str().unwrap_or(""),
        b["seed"],
        b["repeats"],
    );
    for (what, key) in [
        ("alone", "alone"),
        ("together (4 in SIMD lanes)", "together"),
    ] {
        say!(
            "  {what:<27} {:>7.2} ms per evaluation, {:>6.1} evaluations/s ({:.2} ms of CPU)",
            num(&b[key]["ms_per_evaluation"]),
            num(&b[key]["evaluations_per_second"]),
            num(&b[key]["cpu_ms_per_evaluation"]),
        );
    }
}
