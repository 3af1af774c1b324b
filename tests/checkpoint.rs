//! Checkpoints: a run stopped after any generation, written to JSON, read back and continued
//! gives the uninterrupted run's file bit for bit; `vsr evolve` continues from OUT.checkpoint
//! and deletes it; a checkpoint of another run or a damaged one is refused with a message.

use std::process::Command;

use serde_json::{json, Value};
use vsr::controllers::ControllerKind;
use vsr::experiment::{Checkpoint, Evolution, EvolutionConfig, Job, RunFile, SourceRun};
use vsr::simulation::Shape;

mod checkpoint_util;
use checkpoint_util::{comparable, scratch};

/// Population 10, 50 evaluations (generation 0 and 2 more), 2-s episodes on hilly terrains.
fn tiny(kind: ControllerKind, seed: u64) -> EvolutionConfig {
    let mut config = EvolutionConfig::paper(Shape::parse("biped-4x3").unwrap(), kind, 50, seed);
    config.ga.population = 10;
    config.seconds = 2.0;
    config
}

fn step(evolution: &mut Evolution) -> bool {
    let jobs = evolution.next_batch();
    if jobs.is_empty() {
        return false;
    }
    let fitness: vsr::Result<Vec<f64>> = jobs.iter().map(Job::fitness).collect();
    evolution.tell(&fitness.unwrap(), 0.0).unwrap();
    true
}

/// The run of `config`, stopped after `stop_after` generations, checkpointed through JSON and
/// continued (`None`: never stopped).
fn run(config: EvolutionConfig, stop_after: Option<usize>) -> RunFile {
    let mut evolution = Evolution::new(config.clone()).unwrap();
    let mut told = 0;
    while step(&mut evolution) {
        told += 1;
        if Some(told) == stop_after {
            let text = evolution.checkpoint(None).unwrap().to_json().unwrap();
            let checkpoint = Checkpoint::from_json(&text).unwrap();
            evolution = Evolution::resume(config.clone(), checkpoint).unwrap();
        }
    }
    evolution.run_file(None).unwrap()
}

/// SPEC 10's fine-tuning of a fixed biped-4x3 attention genome on a small comb (1111-1010), sized as
/// `tiny`.
fn tiny_finetune(seed: u64) -> EvolutionConfig {
    let genome = (0..73)
        .map(|i| ((i * 37 % 101) as f32 / 50.0) - 1.0)
        .collect();
    let source = SourceRun {
        shape: Shape::parse("biped-4x3").unwrap(),
        controller: ControllerKind::Attention,
        seed: 1,
        budget_evals: 100,
        fitness: 1.0,
        genome,
    };
    let comb = Shape::parse("1111-1010").unwrap();
    let mut config = EvolutionConfig::finetune(source, comb, 50, seed);
    config.ga.population = 10;
    config.seconds = 2.0;
    config
}

#[test]
fn a_run_continued_from_any_checkpoint_is_the_uninterrupted_run() {
    let configs = [
        tiny(ControllerKind::Attention, 7),
        tiny(ControllerKind::SlowAttention, 7),
        tiny_finetune(7),
    ];
    for config in configs {
        let whole = run(config.clone(), None);
        assert_eq!(whole.generations.len(), 3);
        for stop in 1..=2 {
            let what = format!("{} stopped after {stop}", config.controller);
            assert_eq!(run(config.clone(), Some(stop)), whole, "{what}");
        }
    }
}

#[test]
fn there_is_no_checkpoint_before_generation_0_is_told() {
    let mut evolution = Evolution::new(tiny(ControllerKind::Mlp, 1)).unwrap();
    assert!(evolution.checkpoint(None).is_none());
    evolution.next_batch();
    assert!(evolution.checkpoint(None).is_none(), "a batch is pending");
}

#[test]
fn a_checkpoint_of_another_run_or_a_damaged_one_is_refused() {
    let mut evolution = Evolution::new(tiny(ControllerKind::Mlp, 1)).unwrap();
    step(&mut evolution);
    let checkpoint = evolution.checkpoint(None).unwrap();
    let err = Evolution::resume(tiny(ControllerKind::Mlp, 2), checkpoint.clone())
        .unwrap_err()
        .to_string();
    assert!(
        err.contains("another run") && err.contains("seed 1"),
        "{err}"
    );

    let edited = |edit: &Edit| {
        let mut v: Value = serde_json::to_value(&checkpoint).unwrap();
        edit(&mut v);
        let text = v.to_string();
        Checkpoint::from_json(&text)
            .and_then(|c| Evolution::resume(tiny(ControllerKind::Mlp, 1), c))
            .unwrap_err()
            .to_string()
    };
    let cases: [(&Edit, &str); 4] = [
        (&|v| v["format"] = json!("vsr-run"), "not a vsr checkpoint"),
        (&|v| v["version"] = json!(9), "version"),
        (
            &|v| v["ga"]["genomes"].as_array_mut().unwrap().truncate(3),
            "population of 10",
        ),
        (&|v| v["generations"] = json!([]), "inconsistent"),
    ];
    for (edit, expected) in cases {
        let err = edited(edit);
        assert!(err.contains(expected), "{expected}: {err}");
    }
    let err = edited(&|v| v["ga"]["genomes"][0][0] = json!(f32::NAN.to_bits()));
    assert!(err.contains("non-finite"), "{err}");
}

/// An edit of a checkpoint's JSON.
type Edit = dyn Fn(&mut Value);

fn evolve(out: &str, seed: u64) -> std::process::Output {
    let line = format!(
        "evolve --shape biped-4x3 --controller attention --evals 50 --seed {seed} \
         --population 10 --seconds 2 --threads 2 --out {out}"
    );
    Command::new(env!("CARGO_BIN_EXE_vsr"))
        .args(line.split_whitespace())
        .output()
        .unwrap()
}

#[test]
fn vsr_evolve_continues_from_its_checkpoint_and_deletes_it() {
    let (whole, resumed) = (scratch("whole.json"), scratch("resumed.json"));
    assert!(evolve(&whole, 5).status.success());

    let mut evolution = Evolution::new(tiny(ControllerKind::Attention, 5)).unwrap();
    step(&mut evolution);
    let checkpoint_path = format!("{resumed}.checkpoint");
    let text = evolution.checkpoint(None).unwrap().to_json().unwrap();
    std::fs::write(&checkpoint_path, text).unwrap();
    let out = evolve(&resumed, 5);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "{stderr}");
    assert!(
        stderr.contains("resuming from") && stderr.contains("generation 1"),
        "{stderr}"
    );
    assert_eq!(comparable(&resumed), comparable(&whole));
    assert!(!std::path::Path::new(&checkpoint_path).exists());

    // Another run's checkpoint: exit 2, nothing written, the checkpoint kept.
    let other = scratch("other.json");
    std::fs::write(
        format!("{other}.checkpoint"),
        evolution.checkpoint(None).unwrap().to_json().unwrap(),
    )
    .unwrap();
    let out = evolve(&other, 6);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{stderr}");
    assert!(
        stderr.contains("another run") && stderr.contains("delete it"),
        "{stderr}"
    );
    assert!(!std::path::Path::new(&other).exists());
    assert!(std::path::Path::new(&format!("{other}.checkpoint")).exists());
}

/// A real stop: `vsr evolve` killed once its first checkpoint is on disk, then given again.
#[test]
fn a_killed_vsr_evolve_continues_to_the_uninterrupted_run_file() {
    let (whole, resumed) = (scratch("whole-long.json"), scratch("killed.json"));
    let line = |out: &str, every: &str| {
        format!(
            "evolve --shape biped-4x3 --controller mlp --evals 2000 --seed 9 --population 10 \
             --seconds 3 --threads 1 --checkpoint-every {every} --out {out}"
        )
    };
    let vsr = || Command::new(env!("CARGO_BIN_EXE_vsr"));
    let mut child = vsr()
        .args(line(&resumed, "0.000001").split_whitespace())
        .stderr(std::process::Stdio::null())
        .spawn()
        .unwrap();
    let checkpoint = std::path::PathBuf::from(format!("{resumed}.checkpoint"));
    let start = std::time::Instant::now();
    while !checkpoint.exists() {
        assert!(
            child.try_wait().unwrap().is_none(),
            "the run ended before a checkpoint"
        );
        assert!(start.elapsed().as_secs() < 60, "no checkpoint after 60 s");
        std::thread::sleep(std::time::Duration::from_millis(5));
    }
    child.kill().unwrap();
    child.wait().unwrap();
    assert!(
        !std::path::Path::new(&resumed).exists(),
        "killed before its run file"
    );

    let out = vsr()
        .args(line(&resumed, "60").split_whitespace())
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        out.status.success() && stderr.contains("resuming from"),
        "{stderr}"
    );
    let out = vsr()
        .args(line(&whole, "0").split_whitespace())
        .output()
        .unwrap();
    assert!(out.status.success());
    assert_eq!(comparable(&resumed), comparable(&whole));
    assert!(!checkpoint.exists());
}
