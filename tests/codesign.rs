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
