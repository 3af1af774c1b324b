//! Body search (`vsr::experiment::codesign`): the same bits however it is run (one thread or
//! several, in any order, resumed from its run file), a frozen module's block kept exactly in
//! every archive entry, the run file read back as a body with its brain, and bad input refused
//! in words. `vsr codesign` itself: 1 and 2 threads give the same file, `vsr evaluate` and
//! `vsr validate` read its best and its entries, `vsr ablate` ablates an entry.

mod cli_util;

use cli_util::{text, vsr};
use std::path::Path;
use vsr::controllers::ControllerKind;
use vsr::experiment::{
    best_in_file, source_of, BrainMode, Codesign, CodesignConfig, CodesignRun, Job, RunFile,
};
use vsr::simulation::Shape;

fn pretrained(name: &str) -> RunFile {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("pretrained")
        .join(name);
    RunFile::from_json(&std::fs::read_to_string(path).unwrap()).unwrap()
}

fn frozen_config(budget: u64, seed: u64) -> CodesignConfig {
    let module = source_of(&pretrained("biped-4x3-attention.json"));
    let mut config = CodesignConfig::new(
        BrainMode::Frozen,
        ControllerKind::Attention,
        Some(module.clone()),
        module.shape,
        budget,
        seed,
    );
    config.seconds = 3.0;
    config.batch = 12;
    config
}

fn sequential(jobs: &[Job]) -> vsr::Result<Vec<f64>> {
    jobs.iter().map(Job::fitness).collect()
}

/// Evaluates on two threads, each half the batch, the second half first.
fn two_threads(jobs: &[Job]) -> vsr::Result<Vec<f64>> {
    let (a, b) = jobs.split_at(jobs.len() / 2);
    std::thread::scope(|s| {
        let second = s.spawn(|| sequential(b));
        let first = sequential(a);
        let mut all = first?;
        all.extend(second.join().expect("thread")?);
        Ok(all)
    })
}

fn without_timing(run: &CodesignRun) -> String {
    let mut run = run.clone();
    run.timing = None;
    for r in &mut run.history {
        r.wall_seconds = 0.0;
    }
    run.to_json()
}

fn search(config: CodesignConfig, evaluate: fn(&[Job]) -> vsr::Result<Vec<f64>>) -> CodesignRun {
    let mut s = Codesign::new(config).unwrap();
    s.run(evaluate, |_| Ok(()), || 0.0).unwrap();
    s.run_file(None).unwrap()
}

#[test]
fn the_same_bits_on_one_thread_or_two_and_resumed() {
    let config = frozen_config(150, 7);
    let one = search(config.clone(), sequential);
    let two = search(config.clone(), two_threads);
    assert_eq!(without_timing(&one), without_timing(&two));
    assert!(one.iteration >= 3, "several iterations: {}", one.iteration);

    // Stop after two iterations, write the file, read it back, go on.
    let mut first = Codesign::new(config).unwrap();
    for _ in 0..2 {
        let jobs = first.next_batch().unwrap();
        let fitness = sequential(&jobs).unwrap();
        first.tell(&fitness, 0.0).unwrap();
    }
    let checkpoint = first.run_file(None).unwrap().to_json();
    let mut resumed = Codesign::resume(CodesignRun::from_json(&checkpoint).unwrap()).unwrap();
    resumed.run(sequential, |_| Ok(()), || 0.0).unwrap();
    assert_eq!(
        without_timing(&resumed.run_file(None).unwrap()),
        without_timing(&one)
    );
}

#[test]
fn a_frozen_module_keeps_its_block_in_every_entry_and_bodies_stay_in_bounds() {
    let config = frozen_config(200, 3);
    let block = config.module.as_ref().unwrap().genome[..32].to_vec();
    let run = search(config.clone(), sequential);
    assert!(
        run.archive.len() >= 2,
        "bodies of several kinds: {}",
        run.archive.len()
    );
    for e in &run.archive {
        assert_eq!(e.genome[..32], block[..], "entry {:?}", e.cell);
        assert!((config.min_voxels..=config.max_voxels).contains(&e.voxels));
        assert_eq!(e.shape.voxel_count(), e.voxels);
        ControllerKind::Attention
            .check_genome("entry", e.voxels, &e.genome)
            .unwrap();
    }
    let text = run.to_json();
    let best = best_in_file(&text, None).unwrap();
    assert_eq!(best, run.best);
    assert_eq!(
        best_in_file(&text, Some(1)).unwrap().shape,
        run.archive[1].shape
    );
}

#[test]
fn damaged_files_and_wrong_modules_are_refused_in_words() {
    let run = search(frozen_config(30, 1), sequential);
    let text = run.to_json();
    let damaged = text.replacen("\"voxels\": ", "\"voxels\": 1", 1);
    let err = CodesignRun::from_json(&damaged).unwrap_err().to_string();
    assert!(err.contains("entry 0 is damaged"), "{err}");
    let cut = &text[..text.len() / 2];
    let err = CodesignRun::from_json(cut).unwrap_err().to_string();
    assert!(err.contains("damaged or incomplete"), "{err}");

    let comm = source_of(&pretrained("biped-4x3-mlp-comm.json"));
    let shape = comm.shape.clone();
    let config = CodesignConfig::new(
        BrainMode::Frozen,
        ControllerKind::Attention,
        Some(comm),
        shape,
        10,
        1,
    );
    let err = Codesign::new(config).unwrap_err().to_string();
    assert!(err.contains("needs its neighbours"), "{err}");

    let mut small = frozen_config(10, 1);
    (small.grid_width, small.grid_height) = (3, 3);
    let err = Codesign::new(small).unwrap_err().to_string();
    assert!(err.contains("fewer than the 20 voxels"), "{err}");

    let mut tiny = frozen_config(10, 1);
    tiny.start = Shape::parse("box-5x5").unwrap();
    let err = Codesign::new(tiny).unwrap_err().to_string();
    assert!(err.contains("outside the bounds 4 to 20"), "{err}");
}

#[test]
fn vsr_codesign_is_the_same_on_one_and_two_threads_and_its_best_replays() {
    let dir = std::env::temp_dir().join(format!("vsr-codesign-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let module = Path::new(env!("CARGO_MANIFEST_DIR")).join("pretrained/biped-4x3-attention.json");
    let run = |threads: &str, out: &Path| {
        let args = [
            "codesign",
            "--brain",
            "finetune",
            "--from",
            module.to_str().unwrap(),
            "--evals",
            "60",
            "--seed",
            "5",
            "--seconds",
            "2",
            "--batch",
            "10",
            "--threads",
            threads,
            "--out",
            out.to_str().unwrap(),
        ];
        let o = vsr(&args);
        assert!(o.status.success(), "{}", text(&o));
        CodesignRun::from_json(&std::fs::read_to_string(out).unwrap()).unwrap()
    };
    let (a, b) = (dir.join("one.json"), dir.join("two.json"));
    assert_eq!(without_timing(&run("1", &a)), without_timing(&run("2", &b)));
    let o = vsr(&[
        "evaluate",
        "--genome",
        a.to_str().unwrap(),
        "--terrain",
        "flat",
        "--seconds",
        "2",
    ]);
    assert!(o.status.success(), "{}", text(&o));
    let o = vsr(&[
        "validate",
        "--genome",
        a.to_str().unwrap(),
        "--entry",
        "99",
        "--seconds",
        "1",
    ]);
    assert!(text(&o).contains("entry 99 does not exist"), "{}", text(&o));
    // `vsr ablate --entry`: the frozen-attention ablation of that gallery body, as the library
    // ablates that entry.
    let o = vsr(&[
        "ablate",
        "--genome",
        a.to_str().unwrap(),
        "--entry",
        "1",
        "--seconds",
        "1",
        "--last-second",
        "1",
        "--json",
    ]);
    assert!(o.status.success(), "{}", text(&o));
    let printed: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    let entry = best_in_file(&std::fs::read_to_string(&a).unwrap(), Some(1)).unwrap();
    let expected = vsr::experiment::ablate(&entry, "hilly-1-10-0", 1, 1.0).unwrap();
    assert_eq!(printed, serde_json::to_value(&expected).unwrap());
    let o = vsr(&[
        "codesign",
        "--brain",
        "scratch",
        "--from",
        module.to_str().unwrap(),
        "--evals",
        "5",
        "--seed",
        "1",
        "--out",
        "/tmp/never.json",
    ]);
    assert!(text(&o).contains("takes no module"), "{}", text(&o));
}

/// A brain for any body as a module: a random `kind` genome (one length for every body),
/// "trained" on the biped.
fn any_body_module(kind: ControllerKind, seed: u64) -> vsr::experiment::SourceRun {
    use rand::{Rng, SeedableRng};
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(seed);
    vsr::experiment::SourceRun {
        genome: (0..kind.param_count(0))
            .map(|_| rng.gen_range(-1.0f32..1.0))
            .collect(),
        shape: Shape::parse("biped-4x3").unwrap(),
        controller: kind,
        seed,
        budget_evals: 100,
        fitness: 1.0,
    }
}

/// A small search around `module` from a 3 x 3 box: 2-s episodes, 10 new bodies a round.
fn any_body_config(
    brain: BrainMode,
    module: vsr::experiment::SourceRun,
    budget: u64,
) -> CodesignConfig {
    let mut config = CodesignConfig::with_module(
        brain,
        Some(module),
        ControllerKind::Mlp, // not used: the module's family is the search's
        Some("box-3x3"),
        budget,
        4,
    )
    .unwrap();
    config.seconds = 2.0;
    config.batch = 10;
    config
}

#[test]
fn a_brain_for_any_body_frozen_searches_bodies_only() {
    let module = any_body_module(ControllerKind::AttentionAny, 1);
    let config = any_body_config(BrainMode::Frozen, module.clone(), 60);
    assert_eq!(config.controller, ControllerKind::AttentionAny);
    let run = search(config.clone(), sequential);
    assert_eq!(
        without_timing(&run),
        without_timing(&search(config, two_threads)),
        "the same bits on two threads"
    );
    assert!(
        run.archive.len() >= 2,
        "several bodies: {}",
        run.archive.len()
    );
    let mut bodies = std::collections::BTreeSet::new();
    for e in &run.archive {
        assert_eq!(
            e.genome, module.genome,
            "entry {:?}: the module's genome",
            e.cell
        );
        assert_eq!(e.design.genes, module.genome, "no other gene in the design");
        bodies.insert(e.shape.to_rows());
    }
    assert_eq!(
        bodies.len(),
        run.archive.len(),
        "a different body in every cell"
    );
    assert_eq!(run.best.genome, module.genome);
    // Read back: the best is the module's genome on the best body, as a module again.
    let text = run.to_json();
    let back = CodesignRun::from_json(&text).unwrap();
    assert_eq!(back.best, run.best);
    // A file whose entry's genes moved is damaged.
    let mut moved = run.clone();
    moved.archive[0].design.genes[40] += 0.5;
    moved.archive[0].genome[40] += 0.5;
    let err = CodesignRun::from_json(&moved.to_json())
        .unwrap_err()
        .to_string();
    assert!(
        err.contains("entry 0 is damaged") && err.contains("kept whole"),
        "{err}"
    );
}

#[test]
fn a_brain_for_any_body_fine_tuned_keeps_its_attention_and_evolves_the_shared_genes() {
    let module = any_body_module(ControllerKind::AttentionAny, 2);
    let run = search(
        any_body_config(BrainMode::Finetune, module.clone(), 60),
        sequential,
    );
    for e in &run.archive {
        assert_eq!(
            e.genome.len(),
            module.genome.len(),
            "one length for every body"
        );
        assert_eq!(
            e.genome[..32],
            module.genome[..32],
            "entry {:?}: attention held",
            e.cell
        );
    }
    assert!(
        run.archive
            .iter()
            .any(|e| e.genome[32..] != module.genome[32..]),
        "the shared genes evolve"
    );
    // mlp-any has no attention: every gene may change.
    let mlp = any_body_module(ControllerKind::MlpAny, 3);
    let run = search(
        any_body_config(BrainMode::Finetune, mlp.clone(), 40),
        sequential,
    );
    assert!(run.archive.iter().any(|e| e.genome[0] != mlp.genome[0]));
}

#[test]
fn a_brain_for_any_body_from_scratch_has_one_genome_length_for_every_body() {
    let mut config = CodesignConfig::new(
        BrainMode::Scratch,
        ControllerKind::AttentionAny,
        None,
        Shape::parse("box-3x3").unwrap(),
        40,
        2,
    );
    config.seconds = 2.0;
    config.batch = 10;
    let run = search(config, sequential);
    assert!(run.archive.len() >= 2);
    let len = ControllerKind::AttentionAny.param_count(0);
    for e in &run.archive {
        assert_eq!(e.genome.len(), len, "{}", e.shape.to_rows());
        assert_eq!(e.design.genes.len(), len, "no gene per grid cell");
    }
}

#[test]
fn vsr_codesign_searches_bodies_only_around_a_brain_trained_on_many_bodies() {
    let dir = std::env::temp_dir().join(format!("vsr-codesign-any-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let module = dir.join("any.json");
    let o = vsr(&[
        "evolve",
        "--bodies",
        root.join("campaigns/bodies/train-32.txt").to_str().unwrap(),
        "--controller",
        "attention-any",
        "--evals",
        "20",
        "--population",
        "10",
        "--seconds",
        "2",
        "--bodies-per-evaluation",
        "2",
        "--seed",
        "1",
        "--out",
        module.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", text(&o));
    let trained = RunFile::from_json(&std::fs::read_to_string(&module).unwrap()).unwrap();
    let out = dir.join("bodies.json");
    let o = vsr(&[
        "codesign",
        "--brain",
        "frozen",
        "--from",
        module.to_str().unwrap(),
        "--start",
        "box-3x3",
        "--evals",
        "30",
        "--seed",
        "2",
        "--seconds",
        "2",
        "--batch",
        "10",
        "--threads",
        "1",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", text(&o));
    assert!(
        text(&o).contains("frozen brain (attention-any)"),
        "{}",
        text(&o)
    );
    let run = CodesignRun::from_json(&std::fs::read_to_string(&out).unwrap()).unwrap();
    assert!(run.archive.len() >= 2);
    for e in &run.archive {
        assert_eq!(e.genome, trained.best.genome, "{}", e.shape.to_rows());
    }
    // Its bodies walk with that one genome: vsr evaluate reads any entry.
    let o = vsr(&[
        "evaluate",
        "--genome",
        out.to_str().unwrap(),
        "--entry",
        "1",
        "--terrain",
        "flat",
        "--seconds",
        "1",
    ]);
    assert!(o.status.success(), "{}", text(&o));
    // An MLP module is still refused, in words that name the brains that can.
    let o = vsr(&[
        "codesign",
        "--brain",
        "frozen",
        "--from",
        root.join("pretrained/biped-4x3-mlp.json").to_str().unwrap(),
        "--evals",
        "5",
        "--seed",
        "1",
        "--out",
        dir.join("never.json").to_str().unwrap(),
    ]);
    assert!(!o.status.success());
    assert!(
        text(&o).contains("only an attention module can be reassembled")
            && text(&o).contains("a brain for any body (attention-any, mlp-any, mlp-comm-any)"),
        "{}",
        text(&o)
    );
    std::fs::remove_dir_all(&dir).ok();
}
