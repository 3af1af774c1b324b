//! The experiment commands of `vsr`: a tiny run end to end (the same file on 1 and 2 threads),
//! and exit code 2 with a readable message on every kind of bad input, without writing output.

use std::process::{Command, Output};

use serde_json::{json, Value};

fn vsr(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_vsr"))
        .args(args)
        .output()
        .unwrap()
}

/// Runs `vsr` with a command line split at whitespace (the scratch paths have none).
fn vsr_line(line: &str) -> Output {
    vsr(&line.split_whitespace().collect::<Vec<_>>())
}

/// A fresh path in this test process's scratch directory.
fn scratch(name: &str) -> String {
    let dir = std::env::temp_dir().join(format!("vsr-cli-test-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir.join(name).to_str().unwrap().to_string()
}

/// A tiny biped run (population 10, 30 evaluations, 2-s episodes) written to `out`.
fn tiny_run(controller: &str, threads: u32, out: &str) {
    let out = vsr_line(&format!(
        "evolve --shape biped-4x3 --controller {controller} --evals 30 --seed 3 \
         --population 10 --seconds 2 --threads {threads} --out {out}"
    ));
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
}

/// The run file without what depends on the machine (wall times, thread count).
fn comparable(path: &str) -> Value {
    let mut v: Value = serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap();
    v["timing"] = Value::Null;
    for g in v["generations"].as_array_mut().unwrap() {
        g["wall_seconds"] = json!(0);
    }
    v
}

/// The JSON a successful command printed.
fn json_of(line: &str) -> Value {
    let out = vsr_line(line);
    assert!(
        out.status.success(),
        "{line}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    serde_json::from_slice(&out.stdout).unwrap()
}

/// Asserts exit code 2 and that stderr contains `expected`.
fn fails_with(line: &str, expected: &str) {
    let out = vsr_line(line);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{line}: {stderr}");
    assert!(
        stderr.contains(expected),
        "{line}: expected '{expected}' in: {stderr}"
    );
}

#[test]
fn params_prints_the_count() {
    let out = vsr_line("params --shape comb-7x2 --controller mlp-comm");
    assert_eq!(String::from_utf8_lossy(&out.stdout).trim(), "445");
}

#[test]
fn a_tiny_run_is_the_same_on_one_and_two_threads() {
    let (one, two) = (scratch("one.json"), scratch("two.json"));
    tiny_run("attention", 1, &one);
    tiny_run("attention", 2, &two);
    assert_eq!(comparable(&one), comparable(&two));
}

#[test]
fn the_summary_says_1_generation_on_1_thread() {
    let out = scratch("one-generation.json");
    let run = vsr_line(&format!(
        "evolve --shape worm-3x1 --controller mlp --evals 4 --seed 1 --population 4 \
         --seconds 1 --threads 1 --out {out}"
    ));
    let summary = String::from_utf8_lossy(&run.stdout);
    assert!(
        summary.contains("after 4 evaluations (1 generation) in ")
            && summary.contains(" s on 1 thread; wrote "),
        "{summary}"
    );
}

#[test]
fn a_run_file_can_be_evaluated_validated_ablated_and_fine_tuned() {
    let g = scratch("source.json");
    tiny_run("attention", 2, &g);
    let result = json_of(&format!("evaluate --genome {g} --terrain flat --seconds 2"));
    assert!(result["velocity"].as_f64().unwrap().is_finite());
    let result = json_of(&format!("validate --genome {g} --seconds 1 --json"));
    assert_eq!(result["terrains"].as_array().unwrap().len(), 10);
    assert!(result["median"].as_f64().is_some());
    let points = json_of(&format!(
        "ablate --genome {g} --seconds 1 --last-second 2 --json"
    ));
    assert_eq!(points.as_array().unwrap().len(), 3);
    // Without --seconds, the run's own 2-s episodes (121 steps), not 30 s.
    let evaluate =
        |seconds: &str| json_of(&format!("evaluate --genome {g} --terrain flat{seconds}"));
    let own = evaluate("");
    assert_eq!(own["steps"].as_u64(), Some(121));
    assert_eq!(own, evaluate(" --seconds 2"));
    assert_eq!(
        evaluate(" --seconds 3")["steps"].as_u64(),
        Some(181),
        "an explicit length is kept"
    );
    let at = |line: &str| json_of(&format!("{line} --genome {g} --json"));
    assert_eq!(
        at("validate"),
        at("validate --seconds 2"),
        "validated at the run's 2 s"
    );
    assert_eq!(
        at("ablate --last-second 1"),
        at("ablate --last-second 1 --seconds 2")
    );
    let tuned = scratch("tuned.json");
    let out = vsr_line(&format!(
        "finetune --from {g} --shape comb-7x2 --evals 30 --seed 4 --population 10 \
         --seconds 2 --out {tuned}"
    ));
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let (a, b) = (comparable(&g), comparable(&tuned));
    let block = |v: &Value| v["best"]["genome"].as_array().unwrap()[..32].to_vec();
    assert_eq!(block(&a), block(&b));
    assert_eq!(b["best"]["genome"].as_array().unwrap().len(), 77);
    assert_eq!(b["config"]["source"]["seed"], json!(3));
}

#[test]
fn bad_input_exits_with_code_2_and_writes_nothing() {
    let out = scratch("never.json");
    let evolve = |controller: &str, evals: &str, shape: &str| {
        format!(
            "evolve --shape {shape} --controller {controller} --evals {evals} --seed 1 --out {out}"
        )
    };
    let unknown = evolve("transformer", "1000", "biped-4x3");
    fails_with(&unknown, "unknown controller 'transformer'");
    fails_with(&evolve("mlp", "5", "biped-4x3"), "budget of 5");
    fails_with(&evolve("mlp", "1000", "1111-11"), "invalid shape");
    fails_with(&evolve("mlp", "-3", "biped-4x3"), "'-3'");
    fails_with(
        &format!("{} --threads 0", evolve("mlp", "100", "biped-4x3")),
        "at least 1",
    );
    fails_with(
        &format!("{} --terrain hills", evolve("mlp", "100", "biped-4x3")),
        "hilly-H-W",
    );
    // A missing folder is made (a job creates what it writes); one under a file cannot be.
    let under_file = format!(
        "evolve --shape biped-4x3 --controller mlp --evals 100 --seed 1 --out {}/Cargo.toml/run.json",
        env!("CARGO_MANIFEST_DIR")
    );
    fails_with(&under_file, "cannot create directory");
    assert!(
        !std::path::Path::new(&out).exists(),
        "a failed command must not write its output"
    );
    fails_with(
        "validate --genome /no/such/run.json",
        "cannot read run file",
    );
}

#[test]
fn bad_run_files_exit_with_code_2() {
    let g = scratch("good.json");
    tiny_run("mlp", 2, &g);
    let wrong_size = format!("evaluate --genome {g} --terrain flat --shape comb-7x2");
    fails_with(&wrong_size, "robot has 45");
    let bad_terrain = format!("evaluate --genome {g} --terrain mountains");
    fails_with(&bad_terrain, "invalid terrain");
    fails_with(&format!("ablate --genome {g}"), "is a mlp controller");
    let base: Value = serde_json::from_str(&std::fs::read_to_string(&g).unwrap()).unwrap();
    let mut nan = base.clone();
    nan["best"]["genome"][2] = Value::Null;
    let mut other_controller = base;
    other_controller["best"]["controller"] = json!("attention");
    other_controller["config"]["controller"] = json!("attention");
    let cases = [
        ("nan.json", nan.to_string(), "gene 2 is null"),
        (
            "other.json",
            other_controller.to_string(),
            "attention controller",
        ),
        ("text.json", "hello".to_string(), "not valid JSON"),
    ];
    for (name, text, expected) in cases {
        let path = scratch(name);
        std::fs::write(&path, text).unwrap();
        fails_with(&format!("validate --genome {path}"), expected);
    }
    let finetune_text = format!(
        "finetune --from {} --shape comb-7x2 --evals 100 --seed 1 --out {}",
        scratch("text.json"),
        scratch("t2.json")
    );
    fails_with(&finetune_text, "not valid JSON");
    assert!(!std::path::Path::new(&scratch("t2.json")).exists());
}
