//! A `[[from_module]]` campaign end to end with `vsr`: while its module does not exist,
//! `campaign run` refuses and `campaign status` says what makes it; a module without
//! attention is refused in words; with a tiny brain for any body (`vsr evolve --bodies`), its
//! fine-tunings, validations and one-shot walk run, and `vsr report` shows them per target
//! beside a compared campaign's fine-tunings of a transplant and its runs from scratch, with
//! the module's cost.

use std::path::Path;
use std::process::{Command, Output};

/// The compared campaign: a transplant onto biped-4x3 and attention from scratch on it.
const COMPARED: &str = r#"
output = "out"
seeds = [1, 2]
seconds = 2.0
population = 10
validate = ["unseen"]

[[finetune]]
name = "rq2"
pairs = [["comb-7x2", "biped-4x3"]]
controller = "attention"
source_evals = 10
evals = 40
scratch_evals = 40
"#;

const CAMPAIGN: &str = r#"
output = "out"
seeds = [1, 2]
seconds = 2.0
population = 10
validate = ["unseen"]

[[from_module]]
name = "ft"
module = "module.json"
controller = "attention-any"
made_by = "any.toml"
shapes = ["biped-4x3"]
evals = 40
compare = "p.toml"
one_shot = "bodies/heldout-paper.txt"
"#;

fn call(dir: &Path, args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_vsr"))
        .current_dir(dir)
        .args(args)
        .output()
        .unwrap()
}

fn vsr(dir: &Path, args: &[&str]) -> String {
    let o = call(dir, args);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    String::from_utf8_lossy(&o.stdout).into_owned()
}

/// A manifest beside `module.json` naming it, chosen among `n` runs (the pretrained folder's
/// manifest with its first entry renamed).
fn chosen_among(dir: &Path, n: usize) {
    let pretrained = Path::new(env!("CARGO_MANIFEST_DIR")).join("pretrained/manifest.json");
    let mut manifest: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(pretrained).unwrap()).unwrap();
    let mut entry = manifest["modules"][0].clone();
    entry["file"] = "module.json".into();
    entry["chosen_from"] = n.into();
    manifest["modules"] = serde_json::Value::Array(vec![entry]);
    let text = serde_json::to_string_pretty(&manifest).unwrap();
    std::fs::write(dir.join("manifest.json"), text).unwrap();
}

fn module(dir: &Path, controller: &str, out: &str) {
    vsr(
        dir,
        &[
            "evolve",
            "--bodies",
            "bodies/train-32.txt",
            "--bodies-per-evaluation",
            "2",
            "--controller",
            controller,
            "--evals",
            "10",
            "--population",
            "10",
            "--seconds",
            "2",
            "--seed",
            "1",
            "--out",
            out,
        ],
    );
}

#[test]
fn a_module_fine_tuned_on_shapes_is_reported_beside_the_compared_runs() {
    let dir = std::env::temp_dir().join(format!("vsr-from-module-{}", std::process::id()));
    let bodies = dir.join("bodies");
    std::fs::create_dir_all(&bodies).unwrap();
    let from = Path::new(env!("CARGO_MANIFEST_DIR")).join("campaigns/bodies");
    for name in ["train-32.txt", "heldout-paper.txt"] {
        std::fs::copy(from.join(name), bodies.join(name)).unwrap();
    }
    std::fs::write(dir.join("p.toml"), COMPARED).unwrap();
    std::fs::write(dir.join("c.toml"), CAMPAIGN).unwrap();

    // No module yet: nothing runs, and both commands say what makes it.
    let run = call(&dir, &["campaign", "run", "c.toml"]);
    let why = String::from_utf8_lossy(&run.stderr);
    assert!(!run.status.success());
    assert!(why.contains("module.json does not exist yet"), "{why}");
    assert!(why.contains("`vsr campaign export any.toml`"), "{why}");
    assert!(!dir.join("out").exists());
    let status = vsr(&dir, &["campaign", "status", "c.toml"]);
    assert!(
        status.contains("not ready") && status.contains("any.toml"),
        "{status}"
    );

    // A module with no attention block is refused before any job.
    module(&dir, "mlp-any", "module.json");
    let run = call(&dir, &["campaign", "run", "c.toml"]);
    let why = String::from_utf8_lossy(&run.stderr);
    assert!(!run.status.success());
    assert!(
        why.contains("mlp-any brain, which cannot be fine-tuned"),
        "{why}"
    );

    module(&dir, "attention-any", "module.json");
    vsr(&dir, &["campaign", "run", "p.toml", "--jobs", "2"]);
    vsr(&dir, &["campaign", "run", "c.toml", "--jobs", "2"]);
    let status = vsr(&dir, &["campaign", "status", "c.toml"]);
    assert!(status.contains("2 of 2 finished"), "{status}");
    assert!(!status.contains("not ready"), "{status}");
    let run: serde_json::Value = serde_json::from_str(
        &std::fs::read_to_string(dir.join("out/runs/ft-to-biped-4x3-40-s1.json")).unwrap(),
    )
    .unwrap();
    assert_eq!(run["config"]["controller"], "attention-any");
    assert!(dir
        .join("out/validation/ft-module.heldout-paper.unseen.json")
        .is_file());

    vsr(&dir, &["report", "c.toml", "--dir", "report"]);
    let report = std::fs::read_to_string(dir.join("report/report.md")).unwrap();
    assert!(
        report.contains("## ft · fine-tuning the module module.json (exploratory)"),
        "{report}"
    );
    // The module: 10 evaluations with generation 0 (population 10) of 2 bodies each.
    assert!(
        report.contains("of 2 bodies each, 20 body-episodes"),
        "{report}"
    );
    assert!(report.contains("| target | one-shot, `unseen` mean | at 30: "));
    let row = report
        .lines()
        .find(|l| l.starts_with("| biped-4x3 |"))
        .unwrap();
    let cells: Vec<&str> = row.split('|').map(str::trim).collect();
    assert!(cells[2].parse::<f64>().is_ok(), "one-shot: {row}");
    assert_eq!(cells[3].matches("(n=2)").count(), 3, "{row}");
    for p in [cells[4], cells[5]] {
        let p: f64 = p.parse().unwrap();
        assert!((0.0..=1.0).contains(&p), "{row}");
    }
    assert!(cells[6].ends_with("(n=2)"), "{row}");
    assert!(report.contains("rq2: transplant from comb-7x2 after 10 evaluations"));
    // Generation 0's best in training, from the module: the run files' own, slowest to fastest.
    let zero: Vec<f64> = [1, 2]
        .iter()
        .map(|seed| {
            let path = format!("out/runs/ft-to-biped-4x3-40-s{seed}.json");
            let run: serde_json::Value =
                serde_json::from_str(&std::fs::read_to_string(dir.join(path)).unwrap()).unwrap();
            run["generations"][0]["best"].as_f64().unwrap()
        })
        .collect();
    let (low, high) = (zero[0].min(zero[1]), zero[0].max(zero[1]));
    let row = report
        .lines()
        .rfind(|l| l.starts_with("| biped-4x3 |"))
        .unwrap();
    assert!(
        row.starts_with(&format!("| biped-4x3 | {low:.2} to {high:.2} (n=2) | ")),
        "generation 0: {row}"
    );
    assert!(
        row.ends_with("(n=2) |"),
        "the transplants' generation 0: {row}"
    );
    assert!(report.contains("each run's `unseen` mean |"), "{report}");
    // The cost, read from the files: the transplants' two source runs (seeds 1 and 2) ...
    assert!(
        report.contains("A transplant's source run: 10 evaluations (generation 0 included) of one body each, read from its 2 source run files"),
        "{report}"
    );
    // ... and, with no manifest beside the module, the choice's size is said to be unknown.
    assert!(report.contains("is not known"), "{report}");
    chosen_among(&dir, 10);
    vsr(&dir, &["report", "c.toml", "--dir", "report"]);
    let report = std::fs::read_to_string(dir.join("report/report.md")).unwrap();
    assert!(
        report.contains(
            "chosen among 10 such runs (its manifest entry), so 200 body-episodes in all"
        ),
        "{report}"
    );
    std::fs::remove_dir_all(&dir).unwrap();
}
