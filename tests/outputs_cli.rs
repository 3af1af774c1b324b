//! Outputs that explain themselves, read as a log or a pipe reads them (the test captures
//! stdout, so it is not a terminal): `vsr evolve` prints one line per generation with the
//! evaluations done of the whole-generation total; `vsr ablate` says what "frozen at s" means
//! and prints the unfrozen velocity above the frozen ones.

use std::process::Command;

fn vsr(line: &str) -> (String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_vsr"))
        .args(line.split_whitespace())
        .output()
        .unwrap();
    let (stdout, stderr) = (
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    );
    assert!(out.status.success(), "{line}: {stderr}");
    (stdout, stderr)
}

#[test]
fn evolve_prints_one_line_per_generation_when_not_on_a_terminal() {
    let dir = std::env::temp_dir().join(format!("vsr-outputs-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let out = dir.join("run.json");
    // population 10, budget 100: generation 0 (10), then 20 a generation while below the
    // budget: 30, 50, 70, 90, 110 -- the budget rounds up to whole generations
    let (stdout, stderr) = vsr(&format!(
        "evolve --shape biped-4x3 --controller mlp --evals 100 --seed 2 --population 10 \
         --seconds 1 --threads 1 --out {}",
        out.display()
    ));
    let lines: Vec<&str> = stdout.lines().collect();
    assert_eq!(lines.len(), 7, "{stdout}");
    for (g, line) in lines[..6].iter().enumerate() {
        let done = 10 + 20 * g;
        assert!(
            line.contains(&format!(" {done}/110 evals  gen {g}: best "))
                && line.contains(" median "),
            "{line}"
        );
    }
    assert!(
        lines[6].contains("after 110 evaluations (6 generations)"),
        "{stdout}"
    );
    assert!(stderr.is_empty(), "no bar is drawn: {stderr}");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn ablate_says_what_frozen_means_and_prints_the_unfrozen_velocity() {
    let run = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/pretrained/biped-4x3-attention.json"
    );
    let line = format!("ablate --genome {run} --last-second 2 --seconds 5");
    let (text, _) = vsr(&line);
    assert!(
        text.starts_with("Frozen at s: every voxel's attention matrix"),
        "{text}"
    );
    let unfrozen = text
        .lines()
        .find_map(|l| l.trim().strip_prefix("unfrozen"))
        .expect("an unfrozen line");
    let unfrozen: f64 = unfrozen.trim().parse().unwrap();
    // the unfrozen walk is the validation episode on the same terrain
    let (json, _) = vsr(&format!("validate --genome {run} --seconds 5 --json"));
    let validation: serde_json::Value = serde_json::from_str(&json).unwrap();
    let first = validation["terrains"][0]["velocity"].as_f64().unwrap();
    assert_eq!(format!("{unfrozen:.3}"), format!("{first:.3}"));
    assert_eq!(
        text.lines()
            .filter(|l| l.trim().starts_with(char::is_numeric))
            .count(),
        3
    );
}

/// `vsr evolve ... | head -1`: stdout closed before the run ends is not an error; the run
/// finishes and writes its file (println! panicked there: exit 101, no run file).
#[test]
fn a_closed_stdout_does_not_end_the_run() {
    let dir = std::env::temp_dir().join(format!("vsr-pipe-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let out = dir.join("run.json");
    let mut child = Command::new(env!("CARGO_BIN_EXE_vsr"))
        .args(
            format!(
                "evolve --shape biped-4x3 --controller mlp --evals 100 --seed 2 --population 10 \
                 --seconds 1 --threads 1 --out {}",
                out.display()
            )
            .split_whitespace(),
        )
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    drop(child.stdout.take()); // nobody reads: every line it prints meets a closed pipe
    let done = child.wait_with_output().unwrap();
    let stderr = String::from_utf8_lossy(&done.stderr);
    assert!(done.status.success(), "{:?}: {stderr}", done.status);
    assert!(!stderr.contains("panicked"), "{stderr}");
    assert!(out.exists(), "the run file is written");
    std::fs::remove_dir_all(&dir).unwrap();
}
