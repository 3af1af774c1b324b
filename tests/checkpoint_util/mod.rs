//! Helpers of the checkpoint tests that run `vsr evolve` (each such test file includes this
//! module): a scratch path, the evolve command line, a run file without its wall times.
#![allow(dead_code)]

use serde_json::{json, Value};
use std::process::Command;

/// A path in this test process's scratch folder.
pub fn scratch(name: &str) -> String {
    let dir = std::env::temp_dir().join(format!("vsr-checkpoint-test-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir.join(name).to_str().unwrap().to_string()
}

/// `vsr evolve` of a tiny biped attention run (population 10, 2-s episodes) with `--seed 5`,
/// `evals` evaluations and extra arguments.
pub fn evolve_with(out: &str, evals: u32, extra: &str) -> std::process::Output {
    let line = format!(
        "evolve --shape biped-4x3 --controller attention --evals {evals} --seed 5 \
         --population 10 --seconds 2 --threads 2 --out {out} {extra}"
    );
    Command::new(env!("CARGO_BIN_EXE_vsr"))
        .args(line.split_whitespace())
        .output()
        .unwrap()
}

/// A run file as JSON with its wall times zeroed, to compare runs bit for bit.
pub fn comparable(path: &str) -> Value {
    let mut v: Value = serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap();
    v["timing"] = Value::Null;
    for g in v["generations"].as_array_mut().unwrap() {
        g["wall_seconds"] = json!(0);
    }
    v
}
