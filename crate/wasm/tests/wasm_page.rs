//! The page's main-thread calls, under Node (`wasm-pack test --node`): the defaults come from
//! the core, a drawing's check names its pieces and parameter counts, a pretrained attention
//! module transplants onto another body keeping its 32 attention genes (as `vsr finetune`
//! starts), an MLP module is refused on another body, an edit of a walking robot keeps the
//! genes of surviving voxels, a fine-tuning run never touches the attention block, the
//! viewer's episode speed is the fitness bit for bit, and a budget's plan is the core's.
#![cfg(target_arch = "wasm32")]

mod wasm_common;

use vsr::controllers::ControllerKind;
use vsr::experiment::evaluate::fitness;
use vsr::experiment::RunFile;
use vsr::simulation::{Shape, Terrain};
use vsr_wasm::{
    check_shape, defaults, describe_run, remap, run_plan, transplant, Episode, Evolution,
};
use wasm_bindgen::JsValue;
use wasm_bindgen_test::wasm_bindgen_test;
use wasm_common::json;

const ATTENTION_RUN: &str = include_str!("../../../pretrained/biped-4x3-attention.json");
const MLP_RUN: &str = include_str!("../../../pretrained/biped-4x3-mlp.json");
const BODY_RUN: &str = include_str!("../../../pretrained/bodies/rq3-frozen.json");

fn to_js(value: serde_json::Value) -> JsValue {
    let serializer = serde_wasm_bindgen::Serializer::json_compatible();
    serde::Serialize::serialize(&value, &serializer).expect("a JS value")
}

#[wasm_bindgen_test]
fn defaults_come_from_the_core() {
    let d = json(defaults().expect("defaults"));
    assert_eq!(d["grid"]["width"], 20);
    assert_eq!(d["grid"]["height"], 10);
    assert_eq!(d["paper"]["population"], 100);
    assert_eq!(d["paper"]["budget"], 30000);
    assert_eq!(d["presets"][0]["rows"], "1111-1111-1001");
    assert_eq!(d["attentionGenes"], 32);
}

#[wasm_bindgen_test]
fn a_check_names_the_pieces_and_counts_parameters() {
    let ok = json(check_shape("1111-1111-1001").expect("checked"));
    assert_eq!(ok["ok"], true);
    assert_eq!(ok["voxels"], 10);
    assert_eq!(ok["params"][0], serde_json::json!(["attention", 73]));
    assert_eq!(ok["params"][2], serde_json::json!(["mlp-comm", 405]));
    let split = json(check_shape("101-101").expect("checked"));
    assert_eq!(split["ok"], false);
    assert_eq!(split["pieces"].as_array().map(Vec::len), Some(2));
    assert!(split["message"]
        .as_str()
        .unwrap()
        .contains("2 separate pieces"));
    let empty = json(check_shape("").expect("checked"));
    assert_eq!(empty["ok"], false);
    assert_eq!(empty["voxels"], 0);
}

#[wasm_bindgen_test]
fn a_transplant_keeps_the_attention_block_and_redraws_the_rest() {
    let run = RunFile::from_json(ATTENTION_RUN).expect("pretrained");
    let comb = transplant(ATTENTION_RUN, "comb-7x2", 1.0).expect("transplanted");
    assert_eq!(comb.len(), 77);
    assert_eq!(comb[..32], run.best.genome[..32]);
    assert!(comb[32..].iter().all(|g| (-1.0..=1.0).contains(g)));
    assert_eq!(
        comb,
        transplant(ATTENTION_RUN, "1111111-1010101", 1.0).unwrap()
    );
    let own = transplant(ATTENTION_RUN, "biped-4x3", 1.0).expect("its own body");
    assert_eq!(own, run.best.genome);
    let episode = Episode::from_genome("comb-7x2", "flat", "attention", &comb, f64::NAN);
    assert_eq!(episode.expect("walks").voxel_count(), 11);
    assert!(transplant(MLP_RUN, "comb-7x2", 1.0).is_err());
    assert_eq!(
        transplant(MLP_RUN, "biped-4x3", 1.0)
            .expect("own body")
            .len(),
        41
    );
    let info = json(describe_run(ATTENTION_RUN).expect("described"));
    assert_eq!(info["controller"], "attention");
    assert_eq!(info["genes"], 73);
    assert_eq!(info["seconds"], run.config.seconds);
    assert_eq!(info["terrain"], "hilly-1-10");
    assert_eq!(
        info["evaluations"], 30100,
        "the budget of 30000 takes whole generations"
    );
}

#[wasm_bindgen_test]
fn a_body_found_by_a_body_search_is_a_module_like_any_other() {
    let best = vsr::experiment::best_in_file(BODY_RUN, None).expect("a co-design run file");
    let info = json(describe_run(BODY_RUN).expect("described"));
    assert_eq!(info["foundBySearch"], true);
    assert_eq!(info["shape"], best.shape.to_rows());
    assert_eq!(info["genes"], best.genome.len());
    assert_eq!(
        json(describe_run(ATTENTION_RUN).unwrap())["foundBySearch"],
        false
    );
    // opened with its own body, it is its best; put on another body, it keeps its attention
    let own = transplant(BODY_RUN, &best.shape.to_rows(), 1.0).expect("its own body");
    assert_eq!(own, best.genome);
    let biped = transplant(BODY_RUN, "biped-4x3", 1.0).expect("another body");
    assert_eq!(biped[..32], best.genome[..32]);
    let episode = Episode::from_run_file(BODY_RUN, "flat", "").expect("it walks");
    drop(episode);
}

#[wasm_bindgen_test]
fn the_viewer_measures_its_episode_as_the_fitness_does() {
    let run = RunFile::from_json(ATTENTION_RUN).expect("pretrained");
    let genome = &run.best.genome;
    let mut episode =
        Episode::from_genome("biped-4x3", "hilly-1-10-3", "attention", genome, f64::NAN)
            .expect("walks");
    episode.measure_over(2.5).expect("a length");
    assert!(
        episode.episode_speed().is_nan(),
        "nothing measured before the end"
    );
    for _ in 0..50 {
        episode.step(7).expect("steps"); // 350 steps, the episode's 151 inside one call
    }
    let shape = Shape::parse("biped-4x3").expect("a preset");
    let terrain = Terrain::parse("hilly-1-10-3").expect("a terrain");
    let noise = Some(0); // the viewer's noise seed
    let fitness = fitness(
        &shape,
        terrain,
        ControllerKind::Attention,
        genome,
        noise,
        2.5,
    );
    assert_eq!(episode.episode_speed().to_bits(), fitness.to_bits());
    assert!(
        episode.distance() > 0.0 && episode.velocity() != fitness,
        "it walked on past the episode"
    );
    assert_eq!(json(defaults().expect("defaults"))["viewNoiseSeed"], "0");
}

#[wasm_bindgen_test]
fn a_budget_becomes_whole_generations() {
    let quick = json(run_plan(20.0, 2000.0).expect("a plan"));
    assert_eq!(quick["planned"], 2020);
    assert_eq!(quick["generations"], 50);
    assert_eq!(quick["perGeneration"], 40);
    assert_eq!(
        json(run_plan(100.0, 30000.0).expect("a plan"))["planned"],
        30100
    );
    assert!(run_plan(0.0, 10.0).is_err());
}

#[wasm_bindgen_test]
fn an_edit_keeps_surviving_voxels_genes() {
    let run = RunFile::from_json(ATTENTION_RUN).expect("pretrained");
    let genome = &run.best.genome;
    // Remove the biped's top-right voxel (index 9 of 10, the last cell of the top row).
    let edited = remap(
        "attention",
        genome,
        "1111-1111-1001",
        "1110-1111-1001",
        0,
        0,
        1.0,
        1,
    );
    let edited = edited.expect("remapped");
    assert_eq!(edited.len(), 32 + 4 * 9 + 1);
    assert_eq!(edited[..32], genome[..32]);
    for r in 0..4 {
        assert_eq!(
            edited[32 + 9 * r..32 + 9 * r + 9],
            genome[32 + 10 * r..32 + 10 * r + 9]
        );
    }
    assert!(remap(
        "attention",
        &genome[..70],
        "biped-4x3",
        "comb-7x2",
        0,
        0,
        1.0,
        1
    )
    .is_err());
}

#[wasm_bindgen_test]
fn fine_tuning_never_changes_the_attention_block() {
    let settings = to_js(
        serde_json::json!({"shape": "comb-7x2", "seed": 2, "seconds": 1.0,
        "terrain": "flat", "population": 4, "budget": 12}),
    );
    let mut evolution = Evolution::finetune(ATTENTION_RUN, settings, None).expect("valid");
    let run = RunFile::from_json(ATTENTION_RUN).expect("pretrained");
    assert_eq!(evolution.genome_length(), 77);
    for _ in 0..2 {
        let jobs = js_sys::Array::from(&evolution.ask().expect("ask")).length() as usize;
        let genomes = evolution.genomes();
        for j in 0..jobs {
            assert_eq!(
                genomes[j * 77..j * 77 + 32],
                run.best.genome[..32],
                "job {j}"
            );
        }
        let fitness: Vec<f64> = (0..jobs).map(|j| j as f64).collect();
        evolution.tell(&fitness, 0.0).expect("told");
    }
}

#[wasm_bindgen_test]
fn an_episode_can_be_placed_where_a_robot_stands() {
    let run = RunFile::from_json(ATTENTION_RUN).expect("pretrained");
    let genome = &run.best.genome;
    let start = Episode::from_genome("biped-4x3", "hilly-1-10-0", "attention", genome, f64::NAN);
    let start_left = start.expect("at the start line").left_edge();
    assert!(
        (start_left - 11.0).abs() < 0.5,
        "start line left edge {start_left}"
    );
    let placed = Episode::from_genome("biped-4x3", "hilly-1-10-0", "attention", genome, 60.0);
    let left = placed.expect("placed").left_edge();
    assert!((left - 60.0).abs() < 0.5, "placed left edge {left}");
    let off = Episode::gait_at("biped-4x3", "flat", 1.0, 1.5, 5000.0).expect("falls back");
    assert!(
        (off.left_edge() - start_left).abs() < 0.5,
        "off the ground: the start line"
    );
}
