//! Evolutionary runs: thread-count independence, real improvement on a small budget, the run
//! file's round trip and every load error, and fine-tuning's frozen attention block.

use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rayon::prelude::*;
use serde_json::{json, Value};
use vsr::controllers::ControllerKind;
use vsr::experiment::{Best, Evolution, EvolutionConfig, Job, RunFile, SourceRun, TrainingTerrain};
use vsr::simulation::Shape;

fn biped() -> Shape {
    Shape::parse("biped-4x3").unwrap()
}

/// Population 20, 100 evaluations (3 generations), 5-s episodes on fresh hilly terrains.
fn tiny(kind: ControllerKind, seed: u64) -> EvolutionConfig {
    let mut config = EvolutionConfig::paper(biped(), kind, 100, seed);
    config.ga.population = 20;
    config.seconds = 5.0;
    config
}

/// Runs `config` on a pool of `threads` threads and returns its run file with the wall
/// times (which do depend on the machine) zeroed.
fn run_on(config: EvolutionConfig, threads: usize) -> RunFile {
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .unwrap();
    let mut evolution = Evolution::new(config).unwrap();
    let start = std::time::Instant::now();
    let evaluate = |jobs: &[Job]| jobs.par_iter().map(Job::fitness).collect();
    let clock = || start.elapsed().as_secs_f64();
    pool.install(|| evolution.run(evaluate, |_| Ok(()), clock))
        .unwrap();
    let mut run = evolution.run_file(None).unwrap();
    run.generations
        .iter_mut()
        .for_each(|g| g.wall_seconds = 0.0);
    run
}

#[test]
fn same_seed_gives_a_bit_identical_run_file_on_one_and_two_threads() {
    for kind in [ControllerKind::Attention, ControllerKind::MlpComm] {
        let one = run_on(tiny(kind, 5), 1).to_json();
        let two = run_on(tiny(kind, 5), 2).to_json();
        assert_eq!(one, two, "{kind}: the thread count changed the run");
        let other = run_on(tiny(kind, 6), 2).to_json();
        assert_ne!(one, other, "{kind}: the seed must matter");
    }
}

#[test]
fn planned_evaluations_follow_the_budget_rule() {
    let run = run_on(tiny(ControllerKind::Mlp, 1), 2);
    let evals: Vec<u64> = run.generations.iter().map(|g| g.evaluations).collect();
    assert_eq!(evals, [20, 60, 100]);
    let paper = Evolution::new(EvolutionConfig::paper(
        biped(),
        ControllerKind::Mlp,
        30_000,
        1,
    ));
    assert_eq!(paper.unwrap().planned_evaluations(), 30_100);
}

#[test]
fn a_small_evolution_on_flat_clearly_improves_on_its_first_generation() {
    // Population 20, 20 generations (20 + 19 x 40 evaluations), 10-s episodes on flat,
    // three seeds: one short run can stall, the average of three should not.
    let (mut first, mut last) = (0.0, 0.0);
    let mut report = Vec::new();
    for seed in 1..=3 {
        let mut config = EvolutionConfig::paper(biped(), ControllerKind::Attention, 780, seed);
        config.ga.population = 20;
        config.seconds = 10.0;
        config.terrain = TrainingTerrain::parse("flat").unwrap();
        let run = run_on(config, 2);
        assert_eq!(run.generations.len(), 20);
        let (g0, g19) = (run.generations[0], run.generations[19]);
        first += g0.best / 3.0;
        last += g19.median / 3.0;
        report.push(format!(
            "seed {seed}: best {:.3} -> median {:.3}",
            g0.best, g19.median
        ));
    }
    assert!(
        last > first + 0.3 && last > 2.0 * first.max(0.1),
        "mean generation-0 best {first:.3}, mean generation-19 median {last:.3}: {report:?}"
    );
}

fn random_genome(rng: &mut ChaCha8Rng, len: usize) -> Vec<f32> {
    // Values over many magnitudes, to exercise the shortest-decimal round trip.
    (0..len)
        .map(|_| rng.gen_range(-1.0f32..1.0) * 10f32.powi(rng.gen_range(-30..30)))
        .collect()
}

fn synthetic_run(kind: ControllerKind, seed: u64) -> RunFile {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let genome = random_genome(&mut rng, kind.param_count(10));
    let best = Best::new(kind, biped(), genome, 1.25);
    let config = EvolutionConfig::paper(biped(), kind, 30_000, seed);
    RunFile::new(config, Vec::new(), best, None)
}

#[test]
fn run_files_round_trip_bit_for_bit() {
    let tiny_run = run_on(tiny(ControllerKind::SlowAttention, 2), 2);
    assert!(tiny_run.best.alpha.is_some() && tiny_run.best.eta.is_some());
    let mut runs = vec![tiny_run];
    runs.extend((0..50).map(|s| synthetic_run(ControllerKind::ALL[s as usize % 4], s)));
    for run in runs {
        let text = run.to_json();
        let back = RunFile::from_json(&text).unwrap();
        let bits = |g: &[f32]| g.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
        assert_eq!(bits(&back.best.genome), bits(&run.best.genome));
        assert_eq!(back, run);
        assert_eq!(back.to_json(), text);
    }
}

/// An edit of a run file's JSON.
type Edit = Box<dyn FnOnce(&mut Value)>;

/// The load error of a synthetic attention run edited by `edit`.
fn load_error(edit: impl FnOnce(&mut Value)) -> String {
    let mut value: Value =
        serde_json::from_str(&synthetic_run(ControllerKind::Attention, 9).to_json()).unwrap();
    edit(&mut value);
    RunFile::from_json(&value.to_string())
        .unwrap_err()
        .to_string()
}

#[test]
fn every_load_error_says_what_is_wrong() {
    let cases: Vec<(&str, Edit)> = vec![
        (
            "not a vsr run file",
            Box::new(|v| v["format"] = json!("vsr-gait")),
        ),
        (
            "\"format\" is missing",
            Box::new(|v| {
                v.as_object_mut().unwrap().remove("format");
            }),
        ),
        (
            "version 2 is not supported",
            Box::new(|v| v["version"] = json!(2)),
        ),
        (
            "unknown controller 'transformer'",
            Box::new(|v| v["best"]["controller"] = json!("transformer")),
        ),
        (
            "has 72 genes",
            Box::new(|v| {
                v["best"]["genome"].as_array_mut().unwrap().pop();
            }),
        ),
        (
            "gene 3 is null",
            Box::new(|v| v["best"]["genome"][3] = Value::Null),
        ),
        (
            "gene 4 of the best genome is inf",
            Box::new(|v| v["best"]["genome"][4] = json!(1e39)),
        ),
        (
            "invalid shape",
            Box::new(|v| v["config"]["shape"] = json!("1111-11")),
        ),
        (
            "but the run evolved",
            Box::new(|v| v["config"]["shape"] = json!("comb-7x2")),
        ),
        (
            "budget of 50",
            Box::new(|v| v["config"]["ga"]["budget_evals"] = json!(50)),
        ),
    ];
    for (expected, edit) in cases {
        let err = load_error(edit);
        assert!(err.contains(expected), "expected '{expected}' in: {err}");
    }
    let err = RunFile::from_json("{\"format\": ").unwrap_err().to_string();
    assert!(err.contains("cut off"), "{err}");
    let err = RunFile::from_json("{\"format\" 1}")
        .unwrap_err()
        .to_string();
    assert!(err.contains("not valid JSON (near line 1"), "{err}");
    assert!(!err.contains("NaN"), "{err}");
    // Python's json.dumps writes a NaN gene as NaN, which JSON cannot hold: said so.
    let err = RunFile::from_json("{\"best\": {\"genome\": [0.5, NaN, 1.0]}}")
        .unwrap_err()
        .to_string();
    assert!(
        err.contains("NaN or Infinity, which JSON cannot hold"),
        "{err}"
    );
    // A genome of another controller: 73 attention genes labelled mlp (41 expected).
    let err = load_error(|v| {
        v["best"]["controller"] = json!("mlp");
        v["config"]["controller"] = json!("mlp");
    });
    assert!(
        err.contains("mlp controller") && err.contains("has 41"),
        "{err}"
    );
}

fn source(seed: u64) -> SourceRun {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let genome = (0..73).map(|_| rng.gen_range(-1.0..1.0)).collect();
    SourceRun {
        shape: biped(),
        controller: ControllerKind::Attention,
        seed,
        budget_evals: 30_000,
        fitness: 3.0,
        genome,
    }
}

#[test]
fn fine_tuning_keeps_the_attention_block_bit_identical() {
    let src = source(4);
    let block: Vec<u32> = src.genome[..32].iter().map(|g| g.to_bits()).collect();
    let comb = Shape::parse("comb-7x2").unwrap();
    let mut config = EvolutionConfig::finetune(src.clone(), comb, 100, 8);
    config.ga.population = 20;
    config.seconds = 2.0;
    let mut evolution = Evolution::new(config).unwrap();
    let mut downstream_seen = std::collections::HashSet::new();
    loop {
        let jobs = evolution.next_batch();
        if jobs.is_empty() {
            break;
        }
        for job in &jobs {
            assert_eq!(job.genome.len(), 77);
            let head: Vec<u32> = job.genome[..32].iter().map(|g| g.to_bits()).collect();
            assert_eq!(
                head, block,
                "generation {} index {}",
                job.generation, job.index
            );
            downstream_seen.insert(job.genome[32].to_bits());
        }
        let fitness: vsr::Result<Vec<f64>> = jobs.iter().map(Job::fitness).collect();
        evolution.tell(&fitness.unwrap(), 0.0).unwrap();
    }
    assert!(
        downstream_seen.len() > 50,
        "the downstream genes must evolve"
    );
    let best = evolution.best().unwrap();
    assert_eq!(best.genome[..32], src.genome[..32]);
    // On the source's own shape the source individual starts the population unchanged.
    let mut same = EvolutionConfig::finetune(src.clone(), biped(), 100, 8);
    same.ga.population = 20;
    let first = Evolution::new(same).unwrap().next_batch();
    assert_eq!(first[0].genome, src.genome);
    assert_ne!(first[1].genome[32..], src.genome[32..]);
    assert_eq!(first[1].genome[..32], src.genome[..32]);
}

#[test]
fn fine_tuning_needs_attention() {
    let mut src = source(5);
    src.controller = ControllerKind::Mlp;
    src.genome.truncate(41);
    let config = EvolutionConfig::finetune(src, biped(), 1000, 1);
    let err = Evolution::new(config).unwrap_err().to_string();
    assert!(err.contains("attention"), "{err}");
}

/// A run's draws derive from (seed, generation, index, purpose), never from its budget: a
/// shorter run is the first generations of a longer one with the same seed, bit for bit
/// (`vsr report` relies on it when a campaign's from-scratch runs have not finished).
#[test]
fn a_shorter_budget_is_a_prefix_of_a_longer_run() {
    let short = run_on(tiny(ControllerKind::Attention, 3), 2);
    let mut long_config = tiny(ControllerKind::Attention, 3);
    long_config.ga.budget_evals = 180;
    let long = run_on(long_config, 2);
    assert_eq!(short.generations.len(), 3);
    assert_eq!(long.generations.len(), 5);
    assert_eq!(short.generations[..], long.generations[..3]);
}
