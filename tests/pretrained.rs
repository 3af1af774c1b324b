//! Every module in pretrained/ replays: the manifest (written by `vsr campaign export`)
//! lists every run file of the folder, each loads, matches what its entry records, and its
//! best individual re-validates on both validation sets to exactly the velocities recorded
//! when the campaign validated it. The same for the bodies of body searches (`bodies/`):
//! each is its run file's best, the archive entry the manifest names. A brain for any body
//! (`any_body` in its entry) re-walks every body set its entry lists to exactly the per-body
//! speeds recorded.

use vsr::experiment::run::{Best, RunFile};
use vsr::experiment::validation::validate_on;
use vsr_study::campaign::export::{Manifest, Provenance, FORMAT, VERSION};

fn pretrained(path: &str) -> String {
    let full = format!("{}/pretrained/{path}", env!("CARGO_MANIFEST_DIR"));
    std::fs::read_to_string(&full).unwrap_or_else(|e| panic!("{full}: {e}"))
}

fn manifest() -> Manifest {
    serde_json::from_str(&pretrained("manifest.json")).expect("a manifest")
}

/// The record's seed and command agree, and `best` re-validates on both sets to exactly the
/// velocities, median and mean the record holds.
fn replays_to(p: &Provenance, best: &Best, seconds: f64, file: &str) {
    assert!(p.command.contains(&format!("--seed {}", p.seed)), "{file}");
    assert_eq!(p.validation.len(), 2, "{file}: both validation sets");
    for (&set, recorded) in &p.validation {
        let v = validate_on(best, set, seconds).expect("validates");
        let replayed: Vec<f64> = v.terrains.iter().map(|t| t.velocity).collect();
        assert_eq!(replayed, recorded.velocities, "{file}: {set} velocities");
        assert_eq!(
            (v.median, v.mean),
            (recorded.median, recorded.mean),
            "{file}: {set}"
        );
    }
}

fn command_names_seed(p: &Provenance) -> bool {
    p.command.contains(&format!("--seed {}", p.seed))
}

#[test]
fn every_pretrained_module_replays_to_its_recorded_figures() {
    let manifest = manifest();
    assert_eq!(
        (manifest.format.as_str(), manifest.version),
        (FORMAT, VERSION)
    );
    assert!(!manifest.modules.is_empty(), "the manifest lists no module");
    for m in &manifest.modules {
        let file = &m.file;
        let run = RunFile::from_json(&pretrained(file)).expect("a valid run file");
        assert_eq!(run.config.seed, m.provenance.seed, "{file}: seed");
        assert_eq!(run.best.controller, m.controller, "{file}: controller");
        assert_eq!(run.best.shape.to_rows(), m.rows, "{file}: shape");
        assert_eq!(
            run.best.fitness, m.provenance.training_best,
            "{file}: best fitness"
        );
        let last = run.generations.last().map(|g| g.evaluations);
        assert_eq!(last, Some(m.provenance.evaluations), "{file}: evaluations");
        if let Some(record) = &m.any_body {
            assert!(command_names_seed(&m.provenance), "{file}");
            let trained = run.config.bodies.as_ref().map(|b| b.set.bodies.len());
            assert_eq!(trained, m.bodies, "{file}: training bodies");
            let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
            vsr_study::campaign::export::any_body::replay(record, &run.best, root)
                .unwrap_or_else(|e| panic!("{file}: {e}"));
            continue;
        }
        replays_to(&m.provenance, &run.best, run.config.seconds, file);
    }
}

#[test]
fn the_manifest_lists_every_module_file_of_the_folder() {
    let listed: Vec<String> = manifest().modules.into_iter().map(|m| m.file).collect();
    let dir = format!("{}/pretrained", env!("CARGO_MANIFEST_DIR"));
    for entry in std::fs::read_dir(dir).expect("pretrained/") {
        let name = entry
            .expect("entry")
            .file_name()
            .to_string_lossy()
            .into_owned();
        if name.ends_with(".json") && name != "manifest.json" {
            assert!(listed.contains(&name), "{name} is not in the manifest");
        }
    }
}

#[test]
fn every_pretrained_body_replays_to_its_recorded_figures() {
    use vsr::experiment::codesign::CodesignRun;
    for b in &manifest().bodies {
        let file = &b.file;
        let run = CodesignRun::from_json(&pretrained(file)).expect("a co-design run file");
        assert_eq!(run.config.seed, b.provenance.seed, "{file}: seed");
        assert_eq!(run.best.shape.to_rows(), b.rows, "{file}: body");
        assert_eq!(run.archive.len(), 1, "{file}: the archive cut to the best");
        assert_eq!(
            run.archive[0].fitness, b.provenance.training_best,
            "{file}: fitness"
        );
        assert!(run.is_complete(), "{file}: a finished run");
        // The run file it came from holds the same body and brain at the entry named.
        let source = format!("{}/{}", env!("CARGO_MANIFEST_DIR"), b.run_file);
        if let Ok(text) = std::fs::read_to_string(&source) {
            let whole = CodesignRun::from_json(&text).expect("its run file");
            assert_eq!(
                whole.archive[b.entry], run.archive[0],
                "{file}: entry {}",
                b.entry
            );
            assert_eq!(whole.best, run.best, "{file}: the run's best");
        }
        replays_to(&b.provenance, &run.best, run.config.seconds, file);
    }
}

#[test]
fn the_manifest_lists_every_body_file() {
    let listed: Vec<String> = manifest().bodies.into_iter().map(|b| b.file).collect();
    let dir = format!("{}/pretrained/bodies", env!("CARGO_MANIFEST_DIR"));
    for entry in std::fs::read_dir(dir).into_iter().flatten() {
        let name = entry
            .expect("entry")
            .file_name()
            .to_string_lossy()
            .into_owned();
        let file = format!("bodies/{name}");
        assert!(listed.contains(&file), "{file} is not in the manifest");
    }
}

#[test]
fn replay_is_the_episode_vsr_evaluate_runs_and_refuses_another_shape() {
    use vsr::experiment::evaluate::{evaluate, replay};
    use vsr::simulation::{Shape, Terrain};
    let run = RunFile::from_json(&pretrained("biped-4x3-attention.json")).expect("valid");
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
