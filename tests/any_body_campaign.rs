//! An `[[any_body]]` campaign end to end with `vsr`: its runs and validations on body sets,
//! `campaign status`, and `vsr report`'s fourth-question section, which prints no test while a
//! planned run's primary validation is missing (no interim result is read) and both families'
//! tests once every run is in.

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
heldout = ["bodies/heldout-random.txt"]

[[any_body]]
name = "a128"
bodies = "bodies/train-128.txt"
controllers = ["attention-any"]
evals = 20
per_evaluation = 2
heldout = ["bodies/heldout-random.txt"]

[[any_body]]
name = "biped"
bodies = "bodies/train-biped.txt"
controllers = ["attention-any"]
evals = 20
per_evaluation = 1
heldout = ["bodies/heldout-random.txt"]
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
    ] {
        std::fs::copy(from.join(name), bodies.join(name)).unwrap();
    }
    std::fs::write(dir.join("c.toml"), CAMPAIGN).unwrap();
    vsr(&dir, &["campaign", "run", "c.toml", "--jobs", "2"]);
    let status = vsr(&dir, &["campaign", "status", "c.toml"]);
    assert!(status.contains("10 of 10 finished"), "{status}");
    vsr(&dir, &["report", "c.toml", "--dir", "report"]);
    let report = std::fs::read_to_string(dir.join("report/report.md")).unwrap();
    assert!(
        report.contains("| attention-any on train-32 | 2 of 2 | 2 |"),
        "{report}"
    );
    assert!(report.contains("not slower than mlp-comm-any on train-32 by 0.2 m/s"));
    assert!(report.contains("attention-any on train-128 faster than attention-any on train-32"));
    assert!(report.contains("### Estimates"));
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
    assert!(
        report.contains("attention-any on train-128 faster than"),
        "family 12 is complete"
    );
    std::fs::remove_dir_all(&dir).ok();
}
