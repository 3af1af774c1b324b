#![cfg(not(target_arch = "wasm32"))]
//! The experiment commands of `vsr`: a tiny run end to end (the same file on 1 and 2 threads),
//! and exit code 2 with a readable message on every kind of bad input, without writing output.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

use serde_json::{json, Value};

fn vsr(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_vsr"))
        .args(args)
        .output()
        .unwrap()
}

fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("vsr-cli-test-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir.join(name)
}

/// A tiny biped run (population 10, 30 evaluations, 2-s episodes) written to `out`.
fn tiny_run(controller: &str, threads: &str, out: &Path) -> Output {
    let out = out.to_str().unwrap();
    vsr(&[
        "evolve",
        "--shape",
        "biped-4x3",
        "--controller",
        controller,
        "--evals",
        "30",
        "--seed",
        "3",
        "--population",
        "10",
        "--seconds",
        "2",
        "--threads",
        threads,
        "--out",
        out,
    ])
}

/// The run file without what depends on the machine (wall times, thread count).
fn comparable(path: &Path) -> Value {
    let mut v: Value = serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap();
    v["timing"] = Value::Null;
    for g in v["generations"].as_array_mut().unwrap() {
        g["wall_seconds"] = json!(0);
    }
    v
}

/// Asserts exit code 2 and that stderr contains `expected`.
fn fails_with(args: &[&str], expected: &str) {
    let out = vsr(args);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{args:?}: {stderr}");
    assert!(
        stderr.contains(expected),
        "{args:?}: expected '{expected}' in: {stderr}"
    );
}

#[test]
fn params_prints_the_count() {
    let out = vsr(&["params", "--shape", "comb-7x2", "--controller", "mlp-comm"]);
    assert_eq!(String::from_utf8_lossy(&out.stdout).trim(), "445");
}

#[test]
fn a_tiny_run_is_the_same_on_one_and_two_threads_and_can_be_used() {
    let (one, two) = (scratch("one.json"), scratch("two.json"));
    assert!(tiny_run("attention", "1", &one).status.success());
    assert!(tiny_run("attention", "2", &two).status.success());
    assert_eq!(comparable(&one), comparable(&two));
    let g = one.to_str().unwrap();
    let out = vsr(&[
        "evaluate",
        "--genome",
        g,
        "--terrain",
        "flat",
        "--seconds",
        "2",
    ]);
    let result: Value = serde_json::from_slice(&out.stdout).unwrap();
    assert!(result["velocity"].as_f64().unwrap().is_finite());
    let out = vsr(&["validate", "--genome", g, "--seconds", "1", "--json"]);
    let result: Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(result["terrains"].as_array().unwrap().len(), 10);
    assert!(result["median"].as_f64().is_some());
    let out = vsr(&[
        "ablate",
        "--genome",
        g,
        "--seconds",
        "1",
        "--last-second",
        "2",
        "--json",
    ]);
    let points: Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(points.as_array().unwrap().len(), 3);
    let tuned = scratch("tuned.json");
    let t = tuned.to_str().unwrap();
    let out = vsr(&[
        "finetune",
        "--from",
        g,
        "--shape",
        "comb-7x2",
        "--evals",
        "30",
        "--seed",
        "4",
        "--population",
        "10",
        "--seconds",
        "2",
        "--out",
        t,
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let (a, b) = (comparable(&one), comparable(&tuned));
    assert_eq!(
        a["best"]["genome"].as_array().unwrap()[..32],
        b["best"]["genome"].as_array().unwrap()[..32]
    );
    assert_eq!(b["config"]["source"]["seed"], json!(3));
}

#[test]
fn bad_input_exits_with_code_2_and_writes_nothing() {
    let out = scratch("never.json");
    let o = out.to_str().unwrap();
    let evolve = |controller: &str, evals: &str, shape: &str| {
        vec![
            "evolve",
            "--shape",
            shape,
            "--controller",
            controller,
            "--evals",
            evals,
            "--seed",
            "1",
            "--out",
            o,
        ]
        .into_iter()
        .map(String::from)
        .collect::<Vec<_>>()
    };
    let run = |args: Vec<String>, expected: &str| {
        let args: Vec<&str> = args.iter().map(String::as_str).collect();
        fails_with(&args, expected);
    };
    run(
        evolve("transformer", "1000", "biped-4x3"),
        "unknown controller 'transformer'",
    );
    run(evolve("mlp", "5", "biped-4x3"), "budget of 5");
    run(evolve("mlp", "1000", "1111-11"), "invalid shape");
    run(evolve("mlp", "-3", "biped-4x3"), "--evals");
    fails_with(
        &[
            "evolve",
            "--shape",
            "biped-4x3",
            "--controller",
            "mlp",
            "--evals",
            "100",
            "--seed",
            "1",
            "--out",
            "/no/such/dir/run.json",
        ],
        "does not exist",
    );
    assert!(!out.exists(), "a failed command must not write its output");
    fails_with(
        &["validate", "--genome", "/no/such/run.json"],
        "cannot read run file",
    );
}

#[test]
fn bad_run_files_exit_with_code_2() {
    let good = scratch("good.json");
    assert!(tiny_run("mlp", "2", &good).status.success());
    let base: Value = serde_json::from_str(&std::fs::read_to_string(&good).unwrap()).unwrap();
    let g = good.to_str().unwrap();
    fails_with(
        &[
            "evaluate",
            "--genome",
            g,
            "--terrain",
            "flat",
            "--shape",
            "comb-7x2",
        ],
        "has 45 parameters",
    );
    fails_with(
        &["evaluate", "--genome", g, "--terrain", "mountains"],
        "invalid terrain",
    );
    fails_with(&["ablate", "--genome", g], "is a mlp controller");
    let edits: Vec<(&str, Value, &str)> = vec![
        ("nan.json", json!(null), "gene 2 is null"),
        (
            "controller.json",
            json!("attention"),
            "attention controller",
        ),
    ];
    for (name, value, expected) in edits {
        let mut v = base.clone();
        if value.is_null() {
            v["best"]["genome"][2] = value;
        } else {
            v["best"]["controller"] = value.clone();
            v["config"]["controller"] = value;
        }
        let path = scratch(name);
        std::fs::write(&path, v.to_string()).unwrap();
        fails_with(&["validate", "--genome", path.to_str().unwrap()], expected);
    }
    let text = scratch("text.json");
    std::fs::write(&text, "hello").unwrap();
    fails_with(
        &[
            "finetune",
            "--from",
            text.to_str().unwrap(),
            "--shape",
            "comb-7x2",
            "--evals",
            "100",
            "--seed",
            "1",
            "--out",
            scratch("t2.json").to_str().unwrap(),
        ],
        "not valid JSON",
    );
}
