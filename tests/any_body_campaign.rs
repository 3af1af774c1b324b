//! An `[[any_body]]` campaign end to end with `vsr`: its runs and validations on body sets,
//! `campaign status`, and `vsr report`'s fourth-question section, which prints no test while a
//! planned run's primary validation is missing (no interim result is read) and both families'
//! tests once every run is in, with its floor (random brains), figures, merged table and the
//! export of its brains for any body to a pretrained folder that replays.

use std::path::Path;
use std::process::Command;

const CAMPAIGN: &str = r#"
output = "out"
seeds = [1, 2]
seconds = 1.0
population = 10
validate = ["unseen"]

[[any_body]]
name = "a32"
bodies = "bodies/train-32.txt"
controllers = ["attention-any", "mlp-any", "mlp-comm-any"]
evals = 20
per_evaluation = 2
heldout = ["bodies/heldout-random.txt", "bodies/heldout-paper.txt"]

[[any_body]]
name = "a128"
bodies = "bodies/train-128.txt"
controllers = ["attention-any"]
evals = 20
per_evaluation = 2
heldout = ["bodies/heldout-random.txt", "bodies/heldout-paper.txt"]

[[any_body]]
name = "biped"
bodies = "bodies/train-biped.txt"
controllers = ["attention-any"]
evals = 20
per_evaluation = 1
heldout = ["bodies/heldout-random.txt", "bodies/heldout-paper.txt"]
"#;

fn vsr(dir: &Path, args: &[&str]) -> String {
    let o = Command::new(env!("CARGO_BIN_EXE_vsr"))
        .current_dir(dir)
        .args(args)
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    String::from_utf8_lossy(&o.stdout).into_owned()
}

#[test]
fn runs_validations_status_and_a_report_that_waits_for_every_run() {
    let dir = std::env::temp_dir().join(format!("vsr-any-campaign-{}", std::process::id()));
    let bodies = dir.join("bodies");
    std::fs::create_dir_all(&bodies).unwrap();
    let from = Path::new(env!("CARGO_MANIFEST_DIR")).join("campaigns/bodies");
    for name in [
        "train-32.txt",
        "train-128.txt",
        "train-biped.txt",
        "heldout-random.txt",
        "heldout-paper.txt",
    ] {
        std::fs::copy(from.join(name), bodies.join(name)).unwrap();
    }
    std::fs::write(dir.join("c.toml"), CAMPAIGN).unwrap();
    vsr(&dir, &["campaign", "run", "c.toml", "--jobs", "2"]);
    let status = vsr(&dir, &["campaign", "status", "c.toml"]);
    assert!(status.contains("10 of 10 finished"), "{status}");
    vsr(&dir, &["report", "c.toml", "--dir", "report"]);
    let report = std::fs::read_to_string(dir.join("report/report.md")).unwrap();
    assert!(report.contains("Run files found: 10 of 10."), "{report}");
    assert!(
        report.contains("| attention-any on train-32 | 2 of 2 | 2 |"),
        "{report}"
    );
    assert!(report.contains("not slower than mlp-comm-any on train-32 by 0.2 m/s"));
    assert!(report.contains("attention-any on train-128 faster than attention-any on train-32"));
    assert!(report.contains("### Estimates"));
    figures_floor_merge_and_export(&dir, &report);
    // One primary validation missing: its family prints counts only.
    let v = dir.join("out/validation/a32-mlp-any-20-s2.heldout-random.unseen.json");
    std::fs::remove_file(v).unwrap();
    vsr(&dir, &["report", "c.toml", "--dir", "report"]);
    let report = std::fs::read_to_string(dir.join("report/report.md")).unwrap();
    assert!(
        report.contains("| mlp-any on train-32 | 2 of 2 | 1 |"),
        "{report}"
    );
    assert!(!report.contains("not slower than mlp-comm-any"), "{report}");
    assert!(!report.contains("### Estimates"));
    // No figure of the fourth question while a run's primary validation is missing: the
    // earlier report's are deleted.
    for f in FIGURES {
        assert!(!dir.join("report").join(f).exists(), "{f} withdrawn");
        assert!(!report.contains(f), "{f} not linked");
    }
    assert!(report.contains("### The floor"), "the floor reads no run");
    assert!(
        report.contains("attention-any on train-128 faster than"),
        "family 12 is complete"
    );
    std::fs::remove_dir_all(&dir).ok();
}

/// The figures of the fourth question the tiny campaign draws once every run is in.
const FIGURES: [&str; 7] = [
    "any-body-heldout-random-unseen.svg",
    "any-body-heldout-paper-unseen.svg",
    "any-body-bodies-a32-attention-any.svg",
    "any-body-bodies-a32-mlp-any.svg",
    "any-body-bodies-a32-mlp-comm-any.svg",
    "any-body-bodies-a128-attention-any.svg",
    "any-body-bodies-biped-attention-any.svg",
];

fn figures_floor_merge_and_export(dir: &Path, report: &str) {
    use vsr::experiment::run::RunFile;
    use vsr_study::campaign::export::Manifest;
    // The floor: 3 families x 2 seeds on both held-out sets, planned as stage-1 jobs.
    let plan = vsr(dir, &["campaign", "plan", "c.toml"]);
    let floor: Vec<&str> = plan
        .lines()
        .filter(|l| l.contains("--random-brain"))
        .collect();
    assert_eq!(floor.len(), 12, "{plan}");
    assert!(floor[0].contains(
        "validate --random-brain attention-any --seed 1 --bodies bodies/heldout-random.txt \
         --set unseen --seconds 1 --json --out out/validation/floor-attention-any-s1.heldout-random.unseen.json"
    ), "{}", floor[0]);
    assert!(report.contains("### The floor: random brains (a reference, not tested)"));
    assert!(
        report.contains("| attention-any (the plan's reference) |"),
        "{report}"
    );
    assert!(
        report.contains("| mlp-comm-any (exploratory) |"),
        "{report}"
    );
    for f in FIGURES {
        let svg = std::fs::read_to_string(dir.join("report").join(f)).unwrap();
        assert!(svg.starts_with("<svg"), "{f}");
        assert!(report.contains(&format!("]({f})")), "{f} is linked");
    }
    let heldout =
        std::fs::read_to_string(dir.join("report/any-body-heldout-paper-unseen.svg")).unwrap();
    assert!(
        heldout.contains("random attention-any (floor)"),
        "the floor beside the runs"
    );
    assert!(
        heldout.contains("attention-any on train-biped: 1 of the 4 bodies of heldout-paper are its training bodies"),
        "{heldout}"
    );
    let bodies =
        std::fs::read_to_string(dir.join("report/any-body-bodies-biped-attention-any.svg"))
            .unwrap();
    assert!(
        bodies.contains("(trained)"),
        "the biped is marked as trained on"
    );
    assert_eq!(
        bodies.matches("<line x1=").count(),
        32 + 4,
        "one picture per held-out body"
    );
    // Merge: a row per run (the any-body runs with their medians per body set) and per
    // random brain.
    let said = vsr(dir, &["campaign", "merge", "c.toml"]);
    assert!(said.contains("10 runs of 10"), "{said}");
    let csv = std::fs::read_to_string(dir.join("out/campaign.csv")).unwrap();
    let header: Vec<&str> = csv.lines().next().unwrap().split(',').collect();
    for column in [
        "heldout-random.unseen_median",
        "heldout-paper.unseen_walking_share",
        "train-32.unseen_median",
        "train-biped.unseen_median",
    ] {
        assert!(header.contains(&column), "{column}: {header:?}");
    }
    assert_eq!(csv.lines().filter(|l| l.contains(",any-body,")).count(), 10);
    assert_eq!(
        csv.lines().filter(|l| l.contains(",random-brain,")).count(),
        6
    );
    let median_at = header
        .iter()
        .position(|h| *h == "heldout-random.unseen_median")
        .unwrap();
    let row = csv
        .lines()
        .find(|l| l.starts_with("a32-mlp-any-20-s2,"))
        .unwrap();
    let file = dir.join("out/validation/a32-mlp-any-20-s2.heldout-random.unseen.json");
    let v: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(file).unwrap()).unwrap();
    let cell: f64 = row.split(',').nth(median_at).unwrap().parse().unwrap();
    assert_eq!(cell, v["median"].as_f64().unwrap());
    // Export: each condition's run with the highest training-set median, its figures on every
    // body set, replayed bit for bit.
    vsr(dir, &["campaign", "export", "c.toml", "--to", "pre"]);
    let text = std::fs::read_to_string(dir.join("pre/manifest.json")).unwrap();
    let manifest: Manifest = serde_json::from_str(&text).unwrap();
    let files: Vec<&str> = manifest.modules.iter().map(|m| m.file.as_str()).collect();
    assert_eq!(
        files,
        [
            "a32-attention-any.json",
            "a128-attention-any.json",
            "biped-attention-any.json"
        ],
        "attention-any by default"
    );
    for m in &manifest.modules {
        let record = m.any_body.as_ref().expect("a brain for any body");
        let train = |seed: u64| {
            let name = format!(
                "out/validation/{}-attention-any-20-s{seed}.{}.unseen.json",
                record.group, m.shape
            );
            let v: serde_json::Value =
                serde_json::from_str(&std::fs::read_to_string(dir.join(name)).unwrap()).unwrap();
            v["median"].as_f64().unwrap()
        };
        let best = if train(2) > train(1) { 2 } else { 1 };
        // Beside the chosen run's figure, the typical run's: the median of the two runs' medians.
        assert_eq!(
            record.sets.last().unwrap().median_of_runs,
            Some((train(1) + train(2)) / 2.0),
            "{}: the training set's median over the runs",
            m.file
        );
        assert_eq!(
            m.provenance.seed, best,
            "{}: by training-set median",
            m.file
        );
        assert_eq!(m.provenance.chosen_from, 2);
        assert!(
            m.provenance.command.contains("evolve --bodies"),
            "{}",
            m.provenance.command
        );
        assert_eq!(
            record.sets.len(),
            3,
            "two held-out sets and the training set"
        );
        assert!(record.sets[0].heldout && !record.sets[2].heldout);
        let run =
            RunFile::from_json(&std::fs::read_to_string(dir.join("pre").join(&m.file)).unwrap())
                .unwrap();
        assert_eq!(run.best.fitness, m.provenance.training_best);
        assert_eq!(
            Some(run.config.bodies.as_ref().unwrap().set.bodies.len()),
            m.bodies
        );
        vsr_study::campaign::export::any_body::replay(record, &run.best, dir).expect("replays");
    }
    let readme = std::fs::read_to_string(dir.join("pre/README.md")).unwrap();
    assert!(readme.contains("## Brains for any body"), "{readme}");
    // Another export that does not choose them keeps them.
    vsr(
        dir,
        &[
            "campaign",
            "export",
            "c.toml",
            "--to",
            "pre",
            "--controllers",
            "attention",
        ],
    );
    let again: Manifest =
        serde_json::from_str(&std::fs::read_to_string(dir.join("pre/manifest.json")).unwrap())
            .unwrap();
    assert_eq!(again.modules, manifest.modules);
}
