//! `vsr report` on a campaign whose evolve group plans a non-inferiority test (the
//! `noninferiority` key; docs/ANALYSIS-PLAN.md, family 8). The key adds no job: the plan is
//! the same with and without it. Seed 1's runs and validations are made by the campaign
//! (seconds-long), then every other seed's and the known seeds' files are copies with chosen
//! validation means, so that each verdict is reached: on `unseen`, worm-3x1 not worse and
//! better, worm-4x1 not worse and not shown better; on `paper`, worm-3x1 worse by more than
//! the margin, worm-4x1 not shown. A missing `paper` validation makes that set's rows interim
//! ones; a missing `unseen` (primary) one takes every comparison of the group out of the
//! report (tables, summaries, figures: only the counts stay) and the answers out of
//! `noninferiority.json` (the page's copy of the primary verdicts).

use std::fs;
use std::path::Path;

mod cli_util;
use cli_util::{text, vsr};

const CAMPAIGN: &str = r#"output = "ni-out"
seeds = [1, 2, 3, 4, 5, 6, 7, 8]
seconds = 1.0
population = 4
validate = ["paper", "unseen"]

[[evolve]]
name = "ni"
shapes = ["worm-3x1", "worm-4x1"]
controllers = ["attention", "mlp-comm"]
evals = [8]
"#;

const KEY: &str = r#"
[evolve.noninferiority]
margin = 0.5
treatment = "attention"
control = "mlp-comm"
known_seeds = [11, 12]
"#;

/// The validation mean of seed index `i` (0-based) of a shape, controller and set.
fn mean(shape: &str, controller: &str, set: &str, i: usize) -> f64 {
    let i = i as f64;
    match (set, shape, controller) {
        // Far better: not worse, and better.
        ("unseen", "worm-3x1", "attention") => 5.0 + 0.01 * i,
        ("unseen", "worm-3x1", _) => 3.0 + 0.01 * i,
        // The same, a hair above: not worse, not shown better.
        ("unseen", "worm-4x1", "attention") => 3.001 + 0.01 * i,
        ("unseen", "worm-4x1", _) => 3.0 + 0.01 * i,
        // Far worse: the whole interval below -0.5.
        ("paper", "worm-3x1", "attention") => 1.0 + 0.01 * i,
        ("paper", "worm-3x1", _) => 3.0 + 0.01 * i,
        // The same with a wide spread: the interval allows a loss beyond the margin.
        ("paper", "worm-4x1", "attention") => i,
        (_, _, _) => i + 0.001,
    }
}

/// Copies seed 1's run and validation files to `seed`, the validation means set to `mean`'s.
fn write_seed(out: &Path, (shape, controller): (&str, &str), seed: u64, i: usize) {
    let name = |s: u64| format!("{shape}-{controller}-8-s{s}");
    let run = |s: u64| out.join("runs").join(format!("{}.json", name(s)));
    if seed != 1 {
        fs::copy(run(1), run(seed)).unwrap();
    }
    for set in ["paper", "unseen"] {
        let file = |s: u64| {
            out.join("validation")
                .join(format!("{}.{set}.json", name(s)))
        };
        let mut v: serde_json::Value =
            serde_json::from_str(&fs::read_to_string(file(1)).unwrap()).unwrap();
        v["mean"] = serde_json::json!(mean(shape, controller, set, i));
        fs::write(file(seed), serde_json::to_string_pretty(&v).unwrap()).unwrap();
    }
}

/// The report's row of `shape` in the table of `set`.
fn row<'a>(md: &'a str, set: &str, shape: &str) -> &'a str {
    let start = md
        .find(&format!("### {set} mean"))
        .unwrap_or_else(|| panic!("{md}"));
    let table = &md[start..];
    let line = table
        .lines()
        .find(|l| l.starts_with(&format!("| {shape} |")));
    line.unwrap_or_else(|| panic!("no {shape} row on {set}: {md}"))
}

/// The report's data file for the page (`noninferiority.json`).
fn summary(out: &Path) -> serde_json::Value {
    serde_json::from_str(&fs::read_to_string(out.join("report/noninferiority.json")).unwrap())
        .unwrap()
}

#[test]
fn verdicts_of_a_synthetic_campaign() {
    let dir = std::env::temp_dir().join(format!("vsr-noninferiority-{}", std::process::id()));
    let _ = fs::remove_dir_all(&dir);
    fs::create_dir_all(&dir).unwrap();
    let (without, with) = (dir.join("without.toml"), dir.join("ni.toml"));
    fs::write(&without, CAMPAIGN).unwrap();
    fs::write(&with, format!("{CAMPAIGN}{KEY}")).unwrap();
    let plan = |file: &Path| text(&vsr(&["campaign", "plan", file.to_str().unwrap()]));
    assert_eq!(plan(&with), plan(&without), "the key adds no job");
    assert_eq!(plan(&with).lines().count(), 3 * 2 * 2 * 8);

    let file = with.to_str().unwrap();
    let run = vsr(&["campaign", "run", file, "--only=-s1."]);
    assert!(run.status.success(), "{}", text(&run));
    let out = dir.join("ni-out");
    for shape in ["worm-3x1", "worm-4x1"] {
        for controller in ["attention", "mlp-comm"] {
            for (i, seed) in (1..=8).enumerate() {
                write_seed(&out, (shape, controller), seed, i);
            }
            for (i, seed) in [11, 12].into_iter().enumerate() {
                write_seed(&out, (shape, controller), seed, i);
            }
        }
    }

    let report = vsr(&["report", file]);
    assert!(report.status.success(), "{}", text(&report));
    let md = fs::read_to_string(out.join("report/report.md")).unwrap();
    assert!(md.contains("Every planned output exists"), "{md}");
    assert!(md.contains("## Non-inferiority: attention against mlp-comm (group `ni`)"));
    // Its test is the plan's: no two-sided difference test of the group beside it.
    assert!(
        !md.contains("## Families of tests") && !md.contains("attention vs mlp-comm"),
        "{md}"
    );
    let not_worse = "**not worse** than mlp-comm by 0.5 m/s or more (non-inferior)";
    let better = row(&md, "unseen", "worm-3x1");
    assert!(better.contains(not_worse), "{better}");
    assert!(
        better.contains("| 8+8 |") && better.ends_with(": **better** |"),
        "{better}"
    );
    let same = row(&md, "unseen", "worm-4x1");
    assert!(same.contains(not_worse), "{same}");
    assert!(same.ends_with(": not shown better |"), "{same}");
    let worse = row(&md, "paper", "worm-3x1");
    assert!(
        worse.contains("**worse** by more than the margin (the claim is contradicted)"),
        "{worse}"
    );
    assert!(worse.ends_with("| not tested |"), "{worse}");
    let open = row(&md, "paper", "worm-4x1");
    assert!(
        open.contains("**not shown**: the data allow a loss larger than the margin"),
        "{open}"
    );
    assert!(md.contains("### unseen mean (primary)") && md.contains("### paper mean (secondary)"));
    // Complete separation of 8 against 8: one-sided exact p = 1 / C(16, 8) = 1/12870
    // = 0.0000777, Holm over the two shapes 0.0001554.
    assert!(better.contains("| 0.0001 e | 0.0002 (k=2) |"), "{better}");
    // The known seeds, beside and not pooled: 2 against 2, on unseen worm-3x1 the means of
    // seed indexes 0 and 1 (5.00 and 5.01 against 3.00 and 3.01).
    assert!(
        md.contains("### Known before the plan: seeds 11-12"),
        "{md}"
    );
    assert!(
        md.contains("| unseen mean | worm-3x1 | 8 | 2+2 | 5.005 | 3.005 | +2.000 ["),
        "{md}"
    );
    assert!(!md.contains("interim"), "{md}");
    assert!(
        text(&report)
            .contains("(margin 0.5 m/s, unseen mean): worm-3x1 not worse, worm-4x1 not worse"),
        "{}",
        text(&report)
    );
    assert!(out.join("report/fig4-ni-worm-3x1-8-unseen.svg").exists());
    // The intervals at a glance, one figure per set, linked from the report.
    let figure = |set: &str| out.join(format!("report/intervals-ni-{set}.svg"));
    for set in ["unseen", "paper"] {
        let svg = fs::read_to_string(figure(set)).unwrap();
        for words in [
            "-0.5: the margin",
            "0: no difference",
            "worm-3x1",
            "worm-4x1",
        ] {
            assert!(svg.contains(words), "{set}: {words}");
        }
        assert!(md.contains(&format!("(intervals-ni-{set}.svg)")), "{md}");
    }
    let svg = fs::read_to_string(figure("unseen")).unwrap();
    assert!(
        svg.contains("worm-3x1, 8+8 runs: not worse (one-sided Holm p 0.0002, alpha 0.025); better (Holm p 0.0002)"),
        "{svg}"
    );
    let json = summary(&out);
    assert_eq!(json["complete"], true, "{json}");
    assert_eq!(
        (json["finished_runs"].clone(), json["planned_runs"].clone()),
        (32.into(), 32.into())
    );
    assert_eq!(json["set"], "unseen");
    let answer = |shape: usize, key: &str| json["shapes"][shape]["answer"][key].clone();
    assert_eq!(
        (answer(0, "verdict"), answer(0, "superiority")),
        ("not worse".into(), "better".into())
    );
    assert_eq!(
        (answer(1, "verdict"), answer(1, "superiority")),
        ("not worse".into(), "not shown better".into())
    );
    assert!(
        (answer(0, "holm_p").as_f64().unwrap() - 2.0 / 12870.0).abs() < 1e-9,
        "{json}"
    );

    fs::remove_file(out.join("validation/worm-4x1-attention-8-s8.paper.json")).unwrap();
    let again = vsr(&["report", file]);
    assert!(again.status.success(), "{}", text(&again));
    let md = fs::read_to_string(out.join("report/report.md")).unwrap();
    let partial = row(&md, "paper", "worm-4x1");
    assert!(
        partial.contains("(interim: 7+8 of 8+8 runs, not the planned test)"),
        "{partial}"
    );
    // No figure of an interim test: the earlier report's is taken away, the other set's kept.
    assert!(!figure("paper").exists() && !md.contains("intervals-ni-paper.svg"));
    assert!(figure("unseen").exists());
    // The primary set is still complete without a paper file; one unseen file missing and
    // the page's file gives counts, never an interim answer.
    assert_eq!(summary(&out)["complete"], true);
    fs::remove_file(out.join("validation/worm-3x1-mlp-comm-8-s8.unseen.json")).unwrap();
    let partial = vsr(&["report", file]);
    assert!(
        text(&partial).contains("31 of 32 runs validated; no verdict until all are in"),
        "{}",
        text(&partial)
    );
    let json = summary(&out);
    assert_eq!(
        (json["complete"].clone(), json["finished_runs"].clone()),
        (false.into(), 31.into())
    );
    assert_eq!(
        json["shapes"][0]["finished"],
        serde_json::json!([8, 7]),
        "{json}"
    );
    assert!(
        json["shapes"][0]["answer"].is_null() && json["shapes"][1]["answer"].is_null(),
        "{json}"
    );
    assert!(!figure("unseen").exists());
    // Nothing of the group is compared while the primary set is short of a run: no table,
    // no summary, no figure (those of the complete report taken away), only the counts.
    let md = fs::read_to_string(out.join("report/report.md")).unwrap();
    assert!(
        md.contains("**Not yet computed: the test waits for every planned run**")
            && md.contains("- worm-3x1, 8 evaluations: attention 8, mlp-comm 7")
            && md.contains("wait for every planned run, as its non-inferiority test does"),
        "{md}"
    );
    let tested = md.lines().any(|l| l.starts_with("| worm-3x1 |"));
    assert!(!md.contains("### unseen mean") && !tested, "{md}");
    assert!(
        md.contains("### Known before the plan: seeds 11-12"),
        "{md}"
    );
    let svgs: Vec<String> = fs::read_dir(out.join("report"))
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|f| f.ends_with(".svg"))
        .collect();
    assert!(svgs.is_empty(), "{svgs:?}");
    let _ = fs::remove_dir_all(&dir);
}
