//! The repository's own campaign files: every one plans, and the paper study's plan names only
//! outputs committed under `study/`.

use std::path::Path;

mod cli_util;
use cli_util::{files_in, text, vsr};

/// The repository's studies stay runnable: every campaign file parses and plans, and the
/// paper's study is the 320 jobs `docs/RESULTS.md` reports and 2 fidelity measurements, every
/// one of whose outputs is committed under `study/` (a plan that drifted from the committed
/// study would rerun it).
#[test]
fn the_repository_campaigns_plan_and_the_paper_study_is_committed() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("campaigns");
    let mut seen = 0;
    for file in files_in(&root) {
        if file.extension().is_some_and(|e| e == "toml") {
            let plan = vsr(&["campaign", "plan", file.to_str().unwrap()]);
            assert!(plan.status.success(), "{}: {}", file.display(), text(&plan));
            seen += 1;
        }
    }
    assert!(seen >= 2, "campaign files found: {seen}");
    let paper = root.join("paper.toml");
    let plan = vsr(&["campaign", "plan", paper.to_str().unwrap()]);
    let lines: Vec<String> = text(&plan).lines().map(String::from).collect();
    assert_eq!(lines.len(), 322);
    let root = root.parent().unwrap();
    for line in &lines {
        let out = line.split(" --out ").nth(1).unwrap();
        let out = out.split_whitespace().next().unwrap();
        assert!(root.join(out).is_file(), "{out} is not committed");
    }
}
