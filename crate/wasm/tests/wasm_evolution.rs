//! The wasm `Evolution` handle, run under Node by `wasm-pack test --node`: it asks whole
//! generations, refuses a wrong `tell`, and a tiny run's run file reads back through
//! `RunFile::from_json`; `evaluateJob` refuses bad jobs.
#![cfg(target_arch = "wasm32")]

mod wasm_common;

use vsr::experiment::RunFile;
use vsr_wasm::{evaluate_job, Evolution};
use wasm_bindgen::JsValue;
use wasm_bindgen_test::wasm_bindgen_test;
use wasm_common::{error_message, json};

/// A tiny run: `population` per generation, 2-s episodes on flat, `budget` evaluations.
fn tiny_settings(population: usize, budget: u64) -> JsValue {
    settings(
        serde_json::json!({"shape": "biped-4x3", "controller": "attention", "seed": 7,
        "seconds": 2.0, "terrain": "flat", "population": population, "budget": budget}),
    )
}

/// A JSON value as the plain JS object the page would send.
fn settings(value: serde_json::Value) -> JsValue {
    let serializer = serde_wasm_bindgen::Serializer::json_compatible();
    serde::Serialize::serialize(&value, &serializer).expect("a JS value")
}

/// Evaluates every pending job of `evolution` in order, as an evaluation worker would.
fn evaluate_pending(evolution: &mut Evolution) -> Vec<f64> {
    let jobs = js_sys::Array::from(&evolution.ask().expect("ask"));
    let genomes = evolution.genomes();
    let len = evolution.genome_length();
    jobs.iter()
        .enumerate()
        .map(|(i, job)| evaluate_job(job, &genomes[i * len..(i + 1) * len]).expect("valid job"))
        .collect()
}

#[wasm_bindgen_test]
fn ask_gives_a_population_first_then_two_populations_per_generation() {
    let mut evolution = Evolution::new(tiny_settings(6, 18)).expect("valid settings");
    assert_eq!(evolution.genome_length(), 73);
    assert_eq!(evolution.planned_evaluations(), 18.0);
    let jobs = json(evolution.ask().expect("ask"));
    assert_eq!(jobs.as_array().map(Vec::len), Some(6));
    assert_eq!(evolution.genomes().len(), 6 * 73);
    assert_eq!(jobs[0]["terrain"], "flat");
    assert!(jobs[0]["noiseSeed"]
        .as_str()
        .unwrap()
        .parse::<u64>()
        .is_ok());
    evolution.tell(&[0.0; 6], 0.0).expect("six values");
    let second = json(evolution.ask().unwrap());
    assert_eq!(second.as_array().map(Vec::len), Some(12));
    assert_eq!(second[0]["generation"], 1);
}

#[wasm_bindgen_test]
fn tell_refuses_a_wrong_count_and_a_tell_without_ask() {
    let mut evolution = Evolution::new(tiny_settings(6, 18)).expect("valid settings");
    let early = error_message(evolution.tell(&[0.0; 6], 0.0).expect_err("refused"));
    assert!(early.contains("call ask first"), "{early}");
    evolution.ask().expect("ask");
    let wrong = error_message(evolution.tell(&[0.0; 5], 0.0).expect_err("refused"));
    assert!(wrong.contains("expected 6 fitness values"), "{wrong}");
    // Nothing changed: the right count is still accepted, NaN (an explosion) included.
    let record = evolution.tell(&[f64::NAN, 1.0, 0.5, 0.0, -1.0, 2.0], 0.0);
    let record = json(record.expect("accepted"));
    assert_eq!(record["best"], 2.0);
    assert_eq!(evolution.best_fitness(), 2.0);
}

#[wasm_bindgen_test]
fn bad_settings_and_bad_jobs_are_js_errors() {
    let zero = error_message(Evolution::new(tiny_settings(6, 0)).err().expect("refused"));
    assert!(zero.contains("budget of 0"), "{zero}");
    let bad_shape = settings(
        serde_json::json!({"shape": "101", "controller": "mlp", "seed": 1,
        "seconds": 2.0, "terrain": "flat", "population": 6, "budget": 18}),
    );
    let message = error_message(Evolution::new(bad_shape).err().expect("refused"));
    assert!(message.contains("pieces"), "{message}");
    let missing = error_message(
        Evolution::new(settings(serde_json::json!({"shape": "biped-4x3"})))
            .err()
            .expect("refused"),
    );
    assert!(missing.starts_with("bad run settings"), "{missing}");
    let job = |seed: &str, terrain: &str, seconds: f64| {
        settings(serde_json::json!({"generation": 0,
        "index": 0, "shape": "biped-4x3", "controller": "attention", "terrain": terrain,
        "noiseSeed": seed, "seconds": seconds}))
    };
    let genome = vec![0.0; 73];
    let short =
        error_message(evaluate_job(job("1", "flat", 2.0), &genome[..72]).expect_err("refused"));
    assert!(
        short.contains("72 genes") && short.contains("73"),
        "{short}"
    );
    assert!(evaluate_job(job("-1", "flat", 2.0), &genome).is_err());
    assert!(evaluate_job(job("1", "hilly-one", 2.0), &genome).is_err());
    assert!(evaluate_job(job("1", "flat", 0.0), &genome).is_err());
    let f = evaluate_job(job("1", "flat", 2.0), &genome).expect("valid");
    assert!(f.is_finite());
}

#[wasm_bindgen_test]
fn a_tiny_evolution_writes_a_run_file_that_reads_back() {
    let mut evolution = Evolution::new(tiny_settings(6, 18)).expect("valid settings");
    assert!(
        evolution.run_file(1, 0.0).is_err(),
        "no run file before generation 0"
    );
    while !evolution.is_done() {
        let fitness = evaluate_pending(&mut evolution);
        if fitness.is_empty() {
            break;
        }
        evolution.tell(&fitness, 1.0).expect("told");
    }
    assert_eq!(evolution.evaluations(), 18.0);
    let text = evolution.run_file(2, 3.5).expect("a run file");
    let run = RunFile::from_json(&text).expect("reads back");
    assert_eq!(run.format, "vsr-run");
    assert_eq!(run.generations.len(), 2);
    assert_eq!(run.best.genome.len(), 73);
    assert_eq!(run.best.fitness, evolution.best_fitness());
    assert_eq!(run.timing.map(|t| t.threads), Some(2));
    assert_eq!(
        run.config.terrain,
        vsr::experiment::TrainingTerrain::parse("flat").unwrap()
    );
}
