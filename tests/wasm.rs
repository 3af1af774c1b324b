//! The wasm boundary, run under Node by `wasm-pack test --node`: an `Episode` builds
//! from a shape string, steps, fills frame buffers of the documented lengths with
//! finite numbers, and reports bad input as a JS `Error` instead of trapping. The same
//! handle built from a pretrained run file walks and exposes its attention matrices.
//! The `Evolution` handle asks whole generations, refuses a wrong `tell`, and a tiny run's
//! run file reads back through `RunFile::from_json`; `evaluateJob` refuses bad jobs.
#![cfg(target_arch = "wasm32")]

mod wasm_common;

use vsr::experiment::RunFile;
use vsr::wasm::{bench_episode, evaluate_job, Episode, Evolution};
use wasm_bindgen::JsValue;
use wasm_bindgen_test::wasm_bindgen_test;
use wasm_common::{error_message, json};

#[wasm_bindgen_test]
fn preset_and_row_string_build_the_same_biped() {
    let preset = Episode::new("biped-4x3", "flat", 1.0, 1.5).expect("preset builds");
    let rows = Episode::new("1111-1111-1001", "flat", 1.0, 1.5).expect("rows build");
    assert_eq!(preset.voxel_count(), 10);
    assert_eq!(rows.voxel_count(), 10);
    assert_eq!(preset.corners(), rows.corners());
}

#[wasm_bindgen_test]
fn frame_buffers_have_the_documented_lengths() {
    for (shape, n) in [("biped-4x3", 10), ("comb-7x2", 11), ("1", 1)] {
        let episode = Episode::new(shape, "hilly-1-10-0", 1.0, 1.5).expect("valid shape");
        assert_eq!(episode.voxel_count(), n, "{shape}");
        assert_eq!(episode.corners().len(), 8 * n, "{shape} corners");
        assert_eq!(episode.area_ratios().len(), n, "{shape} area ratios");
        assert_eq!(
            episode.corner_bodies().len(),
            12 * n,
            "{shape} corner bodies"
        );
    }
}

#[wasm_bindgen_test]
fn stepping_advances_time_and_keeps_numbers_finite() {
    let mut episode = Episode::new("biped-4x3", "hilly-1-10-0", 1.0, 1.5).expect("valid");
    let x0 = episode.centre_x();
    episode.step(120).expect("stable");
    assert!(
        (episode.time() - 2.0).abs() < 1e-9,
        "120 steps are 2 s, got {}",
        episode.time()
    );
    let frame = [
        episode.corners(),
        episode.area_ratios(),
        episode.corner_bodies(),
    ]
    .concat();
    assert!(
        frame.iter().all(|v| v.is_finite()),
        "a frame value is not finite"
    );
    assert!(episode.centre_x().is_finite() && episode.centre_y().is_finite());
    assert_ne!(episode.centre_x(), x0, "the robot moved");
    let ratios = episode.area_ratios();
    assert!(
        ratios.iter().all(|&a| (0.6..1.4).contains(&a)),
        "area ratios {ratios:?}"
    );
}

#[wasm_bindgen_test]
fn terrain_polyline_has_walls() {
    let episode = Episode::new("biped-4x3", "hilly-1-10-0", 1.0, 1.5).expect("valid");
    let (xs, ys) = (episode.terrain_xs(), episode.terrain_ys());
    assert_eq!(xs.len(), 205);
    assert_eq!(ys.len(), xs.len());
    assert_eq!((xs[0], ys[0]), (0.0, 100.0));
    assert_eq!(ys[ys.len() - 1], 100.0);
}

#[wasm_bindgen_test]
fn an_edited_walking_robot_keeps_its_posture() {
    let mut old = Episode::new("biped-4x3", "hilly-1-10-0", 1.5, 1.0).expect("valid");
    old.step(150).expect("stable");
    // The top-right voxel removed: the rows keep their bounding box.
    let left = old.left_edge();
    let mut edited =
        Episode::gait_at("1110-1111-1001", "hilly-1-10-0", 1.5, 1.0, left).expect("valid");
    edited.carry_pose(&old, 0, 0);
    let (before, after) = (old.corners(), edited.corners());
    // Voxels are ordered bottom row first, left to right: the removed one was the last.
    assert_eq!(after.len() + 8, before.len());
    for (a, b) in after.iter().zip(&before) {
        assert!((a - b).abs() < 1e-5, "{a} became {b}");
    }
    edited.step(60).expect("stable");
}

#[wasm_bindgen_test]
fn invalid_shapes_are_js_errors_not_traps() {
    for shape in ["", "11x1-1001", "1111-11", "101", "not-a-preset"] {
        let error = Episode::new(shape, "flat", 1.0, 1.5)
            .err()
            .unwrap_or_else(|| panic!("{shape:?} should be rejected"));
        let message = error_message(error);
        assert!(message.contains("shape"), "{shape:?}: {message}");
    }
}

#[wasm_bindgen_test]
fn invalid_terrain_and_gait_are_js_errors() {
    let terrain = Episode::new("biped-4x3", "hilly-one", 1.0, 1.5).err();
    assert!(error_message(terrain.expect("rejected")).contains("terrain"));
    let gait = Episode::new("biped-4x3", "flat", f64::NAN, 1.5).err();
    assert!(error_message(gait.expect("rejected")).contains("gait"));
}

#[wasm_bindgen_test]
fn bench_episode_runs_and_reports_a_finite_displacement() {
    let dx = bench_episode("biped-4x3", "hilly-1-10-0", 1.0, 1.5, 60).expect("valid");
    assert!(dx.is_finite());
    assert!(bench_episode("", "flat", 1.0, 1.5, 60).is_err());
}

const ATTENTION_RUN: &str = include_str!("../pretrained/biped-4x3-attention.json");
const MLP_RUN: &str = include_str!("../pretrained/biped-4x3-mlp.json");

#[wasm_bindgen_test]
fn pretrained_attention_biped_walks_and_has_16_attention_floats_per_voxel() {
    let mut episode = Episode::from_run_file(ATTENTION_RUN, "hilly-1-10-0", "").expect("valid");
    assert_eq!(episode.controller(), "attention");
    assert_eq!(episode.shape(), "1111-1111-1001");
    assert_eq!(episode.voxel_count(), 10);
    assert_eq!(episode.voxel_cells().len(), 20);
    let x0 = episode.centre_x();
    episode.step(300).expect("stable");
    // Validation on hilly-1-10-0 gives 5.4 m/s over 30 s: 5 s must cover well over 2 m.
    assert!(
        episode.centre_x() - x0 > 2.0,
        "moved {}",
        episode.centre_x() - x0
    );
    let attention = episode.attention();
    assert_eq!(attention.len(), 16 * 10);
    assert!(
        attention.iter().all(|a| (-1.0..=1.0).contains(a)),
        "{attention:?}"
    );
    assert!(
        attention.iter().any(|&a| a != 0.0),
        "the matrices were computed"
    );
}

#[wasm_bindgen_test]
fn the_same_shape_by_preset_is_accepted_and_another_shape_is_a_js_error() {
    let preset = Episode::from_run_file(ATTENTION_RUN, "flat", "biped-4x3").expect("same shape");
    assert_eq!(preset.shape(), "1111-1111-1001");
    let error = Episode::from_run_file(ATTENTION_RUN, "flat", "comb-7x2").err();
    let message = error_message(error.expect("another shape is refused"));
    assert!(message.contains("needs shape 1111-1111-1001"), "{message}");
}

#[wasm_bindgen_test]
fn controllers_without_attention_and_the_gait_give_an_empty_attention() {
    let mlp = Episode::from_run_file(MLP_RUN, "flat", "").expect("valid");
    assert_eq!(mlp.controller(), "mlp");
    assert!(mlp.attention().is_empty());
    let gait = Episode::new("biped-4x3", "flat", 1.0, 1.5).expect("valid");
    assert_eq!(gait.controller(), "phase gait");
    assert!(gait.attention().is_empty());
}

#[wasm_bindgen_test]
fn malformed_and_wrong_version_run_files_are_js_errors() {
    let cut = &ATTENTION_RUN[..ATTENTION_RUN.len() / 2];
    let message = error_message(
        Episode::from_run_file(cut, "flat", "")
            .err()
            .expect("refused"),
    );
    assert!(message.contains("cut off"), "{message}");
    let v2 = ATTENTION_RUN.replacen("\"version\": 1", "\"version\": 2", 1);
    let message = error_message(
        Episode::from_run_file(&v2, "flat", "")
            .err()
            .expect("refused"),
    );
    assert!(message.contains("version 2 is not supported"), "{message}");
    let terrain = Episode::from_run_file(ATTENTION_RUN, "hilly-one", "").err();
    assert!(error_message(terrain.expect("refused")).contains("terrain"));
}

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
