//! The measurement behind the local inputs the body-independent families read
//! ([`LocalInputs::CHOSEN`]), run before the study's plan fixed them (docs/ANALYSIS-PLAN.md,
//! fourth question): attention for any body trained on `train-32` with each choice of local
//! inputs, then walked on the held-out random bodies. Not part of the test suite (minutes of
//! compute); run it with
//!
//!     cargo test --release -p vsr --lib local_inputs_choice -- --ignored --nocapture
//!
//! (`VSR_MEASURE_EVALS`, `VSR_MEASURE_SEEDS=1,2` and `VSR_MEASURE_INPUTS=constant,neighbours`
//! narrow it.) It prints one line per (inputs, seed): training fitness of the final best and the median
//! over `heldout-random` of each body's mean speed on the unseen terrains (20-s episodes here).

use super::BodySet;
use crate::controllers::{AnyBody, Controller, ControllerKind, LocalInputs};
use crate::experiment::episode::{topology, Episode, Policy};
use crate::experiment::validation::ValidationSet;
use crate::experiment::{EvolutionConfig, Job};
use crate::quantiles::median;
use crate::simulation::{Shape, Terrain};
use std::sync::Arc;

/// The velocity of `genome` (attention for any body, reading `which`) on `shape`.
fn speed(
    which: LocalInputs,
    genome: &[f32],
    shape: &Shape,
    terrain: Arc<Terrain>,
    noise: u64,
    seconds: f64,
) -> f64 {
    let mut brain = AnyBody::masked(ControllerKind::Attention, &topology(shape), which);
    if brain.set_params(genome).is_err() {
        return f64::NAN;
    }
    let mut episode =
        Episode::with_policy(shape, terrain, Policy::Brain(Box::new(brain)), Some(noise));
    episode.run(seconds).map_or(f64::NAN, |o| o.velocity)
}

fn job_fitness(which: LocalInputs, job: &Job) -> f64 {
    let terrain = Arc::new(Terrain::parse(&job.terrain).expect("a training terrain"));
    let bodies: Vec<&Shape> = std::iter::once(&job.shape)
        .chain(&job.more_bodies)
        .collect();
    let sum: f64 = bodies
        .iter()
        .map(|b| {
            speed(
                which,
                &job.genome,
                b,
                Arc::clone(&terrain),
                job.noise_seed,
                job.seconds,
            )
        })
        .sum();
    sum / bodies.len() as f64
}

/// Evaluates `jobs` on two threads (the result does not depend on it).
fn batch(which: LocalInputs, jobs: &[Job]) -> Vec<f64> {
    let half = jobs.len().div_ceil(2);
    std::thread::scope(|s| {
        let (a, b) = jobs.split_at(half);
        let left = s.spawn(|| a.iter().map(|j| job_fitness(which, j)).collect::<Vec<_>>());
        let mut out: Vec<f64> = b.iter().map(|j| job_fitness(which, j)).collect();
        let mut all = left.join().expect("the thread finishes");
        all.append(&mut out);
        all
    })
}

#[test]
#[ignore = "a measurement of minutes; see the module doc"]
fn local_inputs_choice() {
    let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/../../campaigns/bodies/");
    let read = |name: &str| {
        BodySet::read(std::path::Path::new(&format!("{dir}{name}"))).expect("the committed set")
    };
    let (train, heldout) = (read("train-32.txt"), read("heldout-random.txt"));
    let evals: u64 = std::env::var("VSR_MEASURE_EVALS")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(2000);
    let seconds = 20.0;
    println!("inputs            seed  training best  held-out median (m/s), {evals} evaluations, 4 bodies each, {seconds}-s episodes");
    let env = |name: &str| std::env::var(name).unwrap_or_default();
    let seeds: Vec<u64> = env("VSR_MEASURE_SEEDS")
        .split(',')
        .filter_map(|s| s.trim().parse().ok())
        .collect();
    let seeds = if seeds.is_empty() { vec![1, 2] } else { seeds };
    let only = env("VSR_MEASURE_INPUTS");
    for which in LocalInputs::ALL
        .into_iter()
        .filter(|w| only.is_empty() || only.split(',').any(|o| o == w.name()))
    {
        for &seed in &seeds {
            // The measurement's layout (7 inputs per gene, unread ones 0) is a longer genome
            // than the families' own: the run is set up with the masked length.
            let mut config = EvolutionConfig::on_bodies(
                train.clone(),
                4,
                ControllerKind::AttentionAny,
                evals,
                seed,
            )
            .unwrap();
            config.seconds = seconds;
            config.ga.population = 50;
            let masked_len = 33 + 4 * crate::controllers::LOCAL_INPUTS;
            let mut evolution =
                crate::experiment::Evolution::with_genome_len(config, masked_len).unwrap();
            evolution
                .run(|jobs| Ok(batch(which, jobs)), |_| Ok(()), || 0.0)
                .unwrap();
            let best = evolution.best().unwrap();
            let means: Vec<f64> = heldout
                .bodies
                .iter()
                .map(|body| {
                    let v: Vec<f64> = ValidationSet::Unseen
                        .episodes()
                        .into_iter()
                        .map(|(name, noise)| {
                            speed(
                                which,
                                &best.genome,
                                body,
                                Arc::new(Terrain::parse(&name).unwrap()),
                                noise,
                                seconds,
                            )
                        })
                        .collect();
                    v.iter().sum::<f64>() / v.len() as f64
                })
                .collect();
            println!(
                "{:<17} {seed:>4}  {:>13.3}  {:>10.3}",
                which.name(),
                best.fitness,
                median(&means)
            );
        }
    }
}
