#![cfg(not(target_arch = "wasm32"))]
//! Every module in pretrained/ replays: its run file loads, matches the configuration
//! its manifest entry records, and its best individual re-validates on the 10 unseen
//! terrains to exactly the velocities the manifest recorded when `vsr validate` ran.

use serde_json::Value;
use vsr::experiment::run::RunFile;
use vsr::experiment::validation::validate;

fn pretrained(path: &str) -> String {
    let full = format!("{}/pretrained/{path}", env!("CARGO_MANIFEST_DIR"));
    std::fs::read_to_string(&full).unwrap_or_else(|e| panic!("{full}: {e}"))
}

#[test]
fn every_pretrained_module_replays_to_its_recorded_fitness() {
    let manifest: Value = serde_json::from_str(&pretrained("manifest.json")).expect("JSON");
    assert_eq!(manifest["format"], "vsr-pretrained");
    let modules = manifest["modules"].as_array().expect("modules");
    assert!(!modules.is_empty(), "the manifest lists no module");
    for m in modules {
        let file = m["file"].as_str().expect("file");
        let run = RunFile::from_json(&pretrained(file)).expect("a valid run file");
        assert_eq!(
            run.config.seed,
            m["seed"].as_u64().expect("seed"),
            "{file}: seed"
        );
        assert_eq!(
            run.best.controller.to_string(),
            m["controller"],
            "{file}: controller"
        );
        assert_eq!(run.best.shape.to_rows(), m["shape"], "{file}: shape");
        assert_eq!(
            Some(run.best.fitness),
            m["training_best"].as_f64(),
            "{file}: best fitness"
        );
        let v = validate(&run.best, run.config.seconds).expect("validates");
        let recorded: Vec<f64> = m["validation"]
            .as_array()
            .expect("validation velocities")
            .iter()
            .map(|x| x.as_f64().expect("number"))
            .collect();
        let replayed: Vec<f64> = v.terrains.iter().map(|t| t.velocity).collect();
        assert_eq!(replayed, recorded, "{file}: validation velocities");
        assert_eq!(
            Some(v.median),
            m["validation_median"].as_f64(),
            "{file}: median"
        );
    }
}

#[test]
fn replay_is_the_episode_vsr_evaluate_runs_and_refuses_another_shape() {
    use vsr::experiment::evaluate::{evaluate, replay};
    use vsr::simulation::{Shape, Terrain};
    let run = RunFile::from_json(&pretrained("biped-4x3-attention-seed1.json")).expect("valid");
    let terrain = || Terrain::parse("hilly-1-10-0").expect("terrain");
    let best = &run.best;
    let mut episode = replay(best, None, terrain(), Some(0)).expect("its own shape");
    let replayed = episode.run(5.0).expect("stable");
    let evaluated = evaluate(
        &best.shape,
        terrain(),
        best.controller,
        &best.genome,
        Some(0),
        5.0,
    );
    assert_eq!(
        replayed,
        evaluated.expect("stable"),
        "the page replays what the CLI evaluates"
    );
    assert_eq!(episode.attention().map(<[f32]>::len), Some(16 * 10));
    let comb = Shape::parse("comb-7x2").expect("preset");
    let error = replay(best, Some(&comb), terrain(), Some(0)).expect_err("another shape");
    assert!(
        error
            .to_string()
            .contains("needs shape 1111-1111-1001 (10 voxels), not 1111111-1010101"),
        "{error}"
    );
}
