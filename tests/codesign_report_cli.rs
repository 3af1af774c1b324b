//! `vsr report` and `vsr campaign export` on a body-search campaign (docs/ANALYSIS-PLAN.md,
//! families 9 and 10). Seed 1 of each condition is a real, seconds-long `vsr codesign` run
//! with its validations (made by the campaign); every other seed is a copy with its seed,
//! its archive's fitness (so its QD-score) and its validation means set to chosen values, so
//! that each verdict is reached: on the unseen velocity frozen > scratch-mlp and frozen <
//! scratch-mlp-comm (difference detected), frozen against scratch-attention no difference
//! detected; on the QD-score finetune > scratch-attention. A missing run makes the report
//! interim and the verdict pending; a run file of another seed than planned is refused; the
//! export writes a body only once its condition's runs are all in. Speeds are written to 2
//! decimals (as docs/RESULTS.md quotes them); the exploratory comparisons (attention from
//! scratch against the other brains from scratch) draw no verdict; the bodies figure sorts
//! each row by speed, says what "n of N" counts and shows the module on its own body.

use std::fs;
use std::path::{Path, PathBuf};

mod cli_util;
use cli_util::{text, vsr};

const CONDITIONS: [&str; 5] = [
    "frozen",
    "finetune",
    "scratch-attention",
    "scratch-mlp",
    "scratch-mlp-comm",
];
const SEEDS: u64 = 6;

fn campaign() -> String {
    let module = Path::new(env!("CARGO_MANIFEST_DIR")).join("pretrained/biped-4x3-attention.json");
    format!(
        r#"output = "cd-out"
seeds = [1, 2, 3, 4, 5, 6]
seconds = 1.0
validate = ["paper", "unseen"]

[[codesign]]
name = "t"
conditions = ["frozen", "finetune", "scratch-attention", "scratch-mlp", "scratch-mlp-comm"]
module = "{}"
start = "box-3x3"
evals = 40
"#,
        module.display()
    )
}

/// The unseen mean of seed index `i` (0-based) of a condition (the paper mean: the same).
fn unseen(condition: &str, i: usize) -> f64 {
    let i = i as f64;
    match condition {
        // Interleaved with scratch-attention: no difference.
        "frozen" => 2.0 + 0.1 * i,
        "scratch-attention" => 2.05 + 0.1 * i,
        // Far below and far above frozen.
        "scratch-mlp" => 0.5 + 0.01 * i,
        "scratch-mlp-comm" => 5.0 + 0.01 * i,
        _ => 2.0 + 0.01 * i,
    }
}

/// The QD-score of seed index `i`: finetune far above scratch-attention, the rest level.
fn qd(condition: &str, i: usize) -> f64 {
    let i = i as f64;
    match condition {
        "finetune" => 30.0 + i,
        _ => 10.0 + i,
    }
}

fn stem(condition: &str, seed: u64) -> String {
    format!("t-{condition}-40-s{seed}")
}

/// Writes `seed`'s run file (from seed 1's: its seed and its archive's fitness set, so that
/// the QD-score is `qd`) and its validations (means set to `unseen`'s).
fn write_seed(out: &Path, condition: &str, seed: u64) {
    let i = (seed - 1) as usize;
    let run = |s: u64| {
        out.join("codesign")
            .join(format!("{}.json", stem(condition, s)))
    };
    let mut v: serde_json::Value =
        serde_json::from_str(&fs::read_to_string(run(1)).unwrap()).unwrap();
    v["config"]["seed"] = serde_json::json!(seed);
    let entries = v["archive"].as_array_mut().unwrap();
    let n = entries.len() as f64;
    for e in entries.iter_mut() {
        e["fitness"] = serde_json::json!(qd(condition, i) / n);
    }
    fs::write(run(seed), serde_json::to_string_pretty(&v).unwrap()).unwrap();
    for set in ["paper", "unseen"] {
        let file = |s: u64| {
            out.join("validation")
                .join(format!("{}.{set}.json", stem(condition, s)))
        };
        let mut v: serde_json::Value =
            serde_json::from_str(&fs::read_to_string(file(1)).unwrap()).unwrap();
        v["mean"] = serde_json::json!(unseen(condition, i));
        v["median"] = serde_json::json!(unseen(condition, i));
        fs::write(file(seed), serde_json::to_string_pretty(&v).unwrap()).unwrap();
    }
}

/// The report's row of `a` against `b` in family `number`'s table.
fn row<'a>(md: &'a str, number: u32, a: &str, b: &str) -> &'a str {
    let start = md
        .find(&format!("### Family {number}:"))
        .unwrap_or_else(|| panic!("{md}"));
    let line = md[start..]
        .lines()
        .find(|l| l.starts_with(&format!("| {a} | {b} |")));
    line.unwrap_or_else(|| panic!("no {a} vs {b} in family {number}: {md}"))
}

fn report(file: &str, out: &Path) -> String {
    let r = vsr(&["report", file]);
    assert!(r.status.success(), "{}", text(&r));
    fs::read_to_string(out.join("report/report.md")).unwrap()
}

#[test]
fn verdicts_interim_and_export_of_a_synthetic_body_search() {
    let dir: PathBuf =
        std::env::temp_dir().join(format!("vsr-codesign-report-{}", std::process::id()));
    let _ = fs::remove_dir_all(&dir);
    fs::create_dir_all(&dir).unwrap();
    let path = dir.join("cd.toml");
    fs::write(&path, campaign()).unwrap();
    let file = path.to_str().unwrap();
    let run = vsr(&["campaign", "run", file, "--only=-s1."]);
    assert!(run.status.success(), "{}", text(&run));
    let out = dir.join("cd-out");
    let pre = dir.join("pretrained");
    let to = pre.to_str().unwrap();

    // Seed 1 only: interim, nothing tested with one run against one? It is, but marked.
    let md = report(file, &out);
    assert!(
        md.contains("**Interim**") && md.contains("**Verdict pending**"),
        "{md}"
    );
    let first = row(&md, 9, "frozen", "scratch-mlp");
    assert!(
        first.contains("| 1+1 |")
            && first.contains("(interim: 1+1 of 6+6 runs, not the planned test)"),
        "{first}"
    );
    let export = vsr(&["campaign", "export", file, "--to", to]);
    assert!(export.status.success(), "{}", text(&export));
    assert!(
        text(&export).contains("bodies/t-frozen.json: not yet (1 of 6 runs"),
        "{}",
        text(&export)
    );
    assert!(
        !pre.join("bodies").exists(),
        "no body before its condition is complete"
    );

    for condition in CONDITIONS {
        for seed in 1..=SEEDS {
            write_seed(&out, condition, seed);
        }
    }
    let md = report(file, &out);
    assert!(md.contains("Every planned output exists"), "{md}");
    assert!(
        !md.contains("interim") && !md.contains("Verdict pending"),
        "{md}"
    );
    // Complete separation of 6 against 6: exact two-sided p = 2 / C(12, 6) = 0.0022; Holm
    // over the 4 tests of the family: 4 x 0.0022 = 0.0087 for the smallest.
    let above = row(&md, 9, "frozen", "scratch-mlp");
    assert!(
        above.ends_with("| frozen > scratch-mlp (difference detected) |"),
        "{above}"
    );
    assert!(
        above.contains("| 6+6 | 2.25 | 0.53 | 0.0022 e | 0.0087 (k=4) |"),
        "{above}"
    );
    let below = row(&md, 9, "frozen", "scratch-mlp-comm");
    assert!(
        below.ends_with("| frozen < scratch-mlp-comm (difference detected) |"),
        "{below}"
    );
    let level = row(&md, 9, "frozen", "scratch-attention");
    assert!(level.ends_with("| no difference detected |"), "{level}");
    let tuned = row(&md, 10, "finetune", "scratch-attention");
    assert!(
        tuned.ends_with("| finetune > scratch-attention (difference detected) |"),
        "{tuned}"
    );
    assert!(row(&md, 10, "frozen", "scratch-mlp").ends_with("| no difference detected |"));
    for figure in [
        "best", "qd", "unseen", "qd-score", "paper", "coverage", "bodies",
    ] {
        let svg = out.join(format!("report/codesign-t-{figure}.svg"));
        assert!(svg.exists(), "{}", svg.display());
    }
    // Exploratory: attention from scratch against MLP from scratch, beside frozen's shift over
    // MLP; no verdict.
    let start = md.find("### Exploratory").unwrap_or_else(|| panic!("{md}"));
    let explored = md[start..]
        .lines()
        .find(|l| l.starts_with("| scratch-attention | scratch-mlp | 6+6 |"))
        .unwrap_or_else(|| panic!("{md}"));
    assert!(explored.contains(" e | +"), "{explored}");
    assert!(!explored.contains("detected"), "{explored}");
    let bodies = fs::read_to_string(out.join("report/codesign-t-bodies.svg")).unwrap();
    assert!(
        bodies.contains(">frozen</text>")
            && bodies.contains(">6 of 6 runs finished</text>")
            && bodies.contains("runs done, of those planned"),
        "{bodies}"
    );
    // Sorted by speed: frozen's fastest (seed 6) first, its slowest (seed 1) last.
    let (fast, slow) = (
        bodies.find("s6: 2.50").unwrap(),
        bodies.find("s1: 2.00").unwrap(),
    );
    assert!(fast < slow, "{bodies}");
    // The module on its own body (biped-4x3), measured as `vsr validate` measures it.
    assert!(
        bodies.contains(">the module, for reference</text>") && bodies.contains("own body: "),
        "{bodies}"
    );
    let best = fs::read_to_string(out.join("report/codesign-t-best.svg")).unwrap();
    assert!(best.contains("training fitness overstates speed"), "{best}");

    // Every condition complete: a body each, its provenance in the manifest.
    let export = vsr(&["campaign", "export", file, "--to", to]);
    assert!(export.status.success(), "{}", text(&export));
    let manifest: serde_json::Value =
        serde_json::from_slice(&fs::read(pre.join("manifest.json")).unwrap()).unwrap();
    let listed = manifest["bodies"].as_array().unwrap();
    assert_eq!(listed.len(), 5, "{manifest}");
    // Chosen by the paper median: the last seed of each condition (highest by construction).
    let frozen = &listed[0];
    assert_eq!(frozen["file"], "bodies/t-frozen.json");
    assert_eq!(
        (frozen["seed"].as_u64(), frozen["chosen_from"].as_u64()),
        (Some(6), Some(6))
    );
    assert!(frozen["run_file"]
        .as_str()
        .unwrap()
        .ends_with("codesign/t-frozen-40-s6.json"));
    assert!(frozen["command"]
        .as_str()
        .unwrap()
        .contains("--brain frozen"));
    assert_eq!(frozen["validation"]["unseen"]["mean"], 2.5);
    let cut: serde_json::Value =
        serde_json::from_slice(&fs::read(pre.join("bodies/t-frozen.json")).unwrap()).unwrap();
    assert_eq!(cut["archive"].as_array().unwrap().len(), 1);
    assert_eq!(cut["archive"][0]["shape"], frozen["rows"]);
    let replay = vsr(&[
        "evaluate",
        "--genome",
        &pre.join("bodies/t-frozen.json").display().to_string(),
        "--terrain",
        "flat",
        "--seconds",
        "1",
    ]);
    assert!(replay.status.success(), "{}", text(&replay));
    assert!(pre.join("README.md").exists());
    assert!(fs::read_to_string(pre.join("README.md"))
        .unwrap()
        .contains("| bodies/t-frozen.json | frozen (attention) |"));

    // One run missing: interim again, and the verdict pending.
    fs::remove_file(
        out.join("codesign")
            .join(format!("{}.json", stem("scratch-mlp", 4))),
    )
    .unwrap();
    let md = report(file, &out);
    assert!(md.contains("**Verdict pending**"), "{md}");
    let partial = row(&md, 9, "frozen", "scratch-mlp");
    assert!(
        partial.contains("(interim: 6+5 of 6+6 runs, not the planned test)"),
        "{partial}"
    );
    assert!(md.contains("| scratch-mlp | 5 of 6 | 5 of 6 | 4 |"), "{md}");

    // A run file whose seed is not its name's is refused, naming the file.
    let wrong = out
        .join("codesign")
        .join(format!("{}.json", stem("scratch-mlp", 4)));
    fs::copy(
        out.join("codesign")
            .join(format!("{}.json", stem("scratch-mlp", 3))),
        &wrong,
    )
    .unwrap();
    let refused = vsr(&["report", file]);
    assert!(!refused.status.success());
    assert!(
        text(&refused).contains("t-scratch-mlp-40-s4.json") && text(&refused).contains("seed 3"),
        "{}",
        text(&refused)
    );
    let _ = fs::remove_dir_all(&dir);
}
