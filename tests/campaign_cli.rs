//! `vsr campaign plan | run | merge` and `vsr report` end to end on campaigns/smoke.toml in a
//! scratch directory: the plan lists complete commands in dependency order, a run makes
//! every output, a second run does nothing, a missing output is the only pending job and is
//! remade, the CSV has a row per run, the report tests every pair and draws SVG figures, and
//! a killed job leaves no partial file.

use std::fs;
use std::path::PathBuf;
use std::process::Command;

mod cli_util;
use cli_util::{files_in, smoke, text, vsr};

#[test]
fn plan_run_merge_report_and_resume() {
    let (dir, file) = smoke("e2e");
    let plan = vsr(&["campaign", "plan", &file]);
    assert!(plan.status.success(), "{}", text(&plan));
    let lines: Vec<String> = text(&plan).lines().map(String::from).collect();
    // 3 controllers x 3 seeds + per seed a scratch run and a fine-tuning run on worm-4x1
    // (the source is the grid's attention run) = 15 runs, 30 validations, 6 ablations.
    assert_eq!(lines.len(), 51, "{lines:?}");
    assert!(lines
        .iter()
        .all(|l| l.starts_with("vsr ") && l.contains(" --out ")));
    let first_use = |what: &str| lines.iter().position(|l| l.contains(what)).unwrap();
    let source = "runs/worm-3x1-attention-8-s1.json";
    assert!(
        lines[first_use(source)].starts_with("vsr evolve"),
        "made before it is used"
    );
    let stage1 = vsr(&["campaign", "plan", &file, "--stage", "1"]);
    assert_eq!(text(&stage1).lines().count(), 12, "runs from scratch");

    let status = |cores: &str| text(&vsr(&["campaign", "status", &file, "--cores", cores]));
    let before = status("2");
    assert!(
        before.contains("evolutionary runs: 0 of 15 finished, 0 in flight, 15 not started")
            && before.contains("assessments (validations, ablations, fidelity): 0 of 36 done")
            && before.contains("no finished one-thread run yet"),
        "{before}"
    );

    let run = vsr(&["campaign", "run", &file, "--jobs", "2"]);
    assert!(run.status.success(), "{}", text(&run));
    let out = dir.join("smoke-out");
    let after = status("2");
    assert!(
        after.contains("15 of 15 finished") && after.contains("36 of 36 done"),
        "{after}"
    );
    assert!(
        after.contains("every evolutionary run is finished"),
        "{after}"
    );
    assert_eq!(files_in(&out.join("runs")).len(), 15);
    assert_eq!(files_in(&out.join("validation")).len(), 30);
    assert_eq!(files_in(&out.join("ablation")).len(), 6);
    // A log per job: a run and its ablation share a file name, not a log.
    assert_eq!(files_in(&out.join("logs")).len(), 51);
    let log = |name: &str| fs::read_to_string(out.join("logs").join(name)).unwrap();
    let (run_log, ablation_log) = (
        log("runs-worm-3x1-attention-8-s1.json.log"),
        log("ablation-worm-3x1-attention-8-s1.json.log"),
    );
    assert!(run_log.contains("generation"), "{run_log}");
    assert_ne!(run_log, ablation_log);
    let pending = vsr(&["campaign", "plan", &file, "--pending"]);
    assert_eq!(text(&pending), "", "nothing left to do");

    let kept = fs::read(out.join(source)).unwrap();
    let again = vsr(&["campaign", "run", &file]);
    assert!(
        text(&again).contains("51 done (51 already"),
        "{}",
        text(&again)
    );
    assert_eq!(
        fs::read(out.join(source)).unwrap(),
        kept,
        "a second run changes nothing"
    );

    let csv = vsr(&["campaign", "merge", &file]);
    assert!(csv.status.success(), "{}", text(&csv));
    let table = fs::read_to_string(out.join("campaign.csv")).unwrap();
    let header = table.lines().next().unwrap();
    assert!(header.starts_with("run,kind,shape,controller,evals,seed"));
    assert!(
        header.contains("paper_mean") && header.contains("unseen_9") && header.contains("best_g1")
    );
    assert_eq!(table.lines().count(), 1 + 15);

    let report = vsr(&["report", &file]);
    assert!(report.status.success(), "{}", text(&report));
    let md = fs::read_to_string(out.join("report/report.md")).unwrap();
    assert!(md.contains("Every planned output exists"), "{md}");
    assert!(md.contains("| attention | mlp | best |"), "{md}");
    assert!(md.contains("| fine-tuned from worm-3x1 (8 + 4) | from scratch (12) | unseen mean |"));
    // RQ2's speed claim: both after the fine-tuning budget, and when fine-tuning catches up.
    assert!(
        md.contains("Convergence: best fitness after the same number"),
        "{md}"
    );
    assert!(
        md.contains("| evaluations | median fine-tuned | median from scratch |"),
        "{md}"
    );
    assert!(md.contains("the from-scratch runs' final median"), "{md}");
    let svgs: Vec<PathBuf> = files_in(&out.join("report"))
        .into_iter()
        .filter(|p| p.extension().is_some_and(|e| e == "svg"))
        .collect();
    assert_eq!(svgs.len(), 7, "{svgs:?}");
    for svg in &svgs {
        let body = fs::read_to_string(svg).unwrap();
        assert!(
            body.starts_with("<svg") && body.contains("<text"),
            "{svg:?}"
        );
    }

    // A lost run file: the report names it, it is the only pending job, a run remakes it.
    fs::remove_file(out.join(source)).unwrap();
    let report = vsr(&["report", &file]);
    let md = fs::read_to_string(out.join("report/report.md")).unwrap();
    assert!(
        report.status.success() && md.contains("Missing: 1 planned outputs"),
        "{md}"
    );
    assert!(md.contains("worm-3x1-attention-8-s1.json"));
    let pending = text(&vsr(&["campaign", "plan", &file, "--pending"]));
    assert_eq!(pending.lines().count(), 1, "{pending}");
    let lost = status("1");
    assert!(
        lost.contains("14 of 15 finished, 0 in flight, 1 not started"),
        "{lost}"
    );
    assert!(
        lost.contains("left: 12 evaluations, about")
            && lost.contains("finished runs of its controller)")
            && lost.contains("hours on 1 core\n"),
        "the source run's 12 evaluations (4 + 2 x 4: the budget 8 passed): {lost}"
    );
    assert_eq!(
        text(&vsr(&["campaign", "status", &file, "--cores", "0"])).trim(),
        "vsr: invalid input: --cores must be at least 1"
    );
    let rerun = vsr(&["campaign", "run", &file]);
    assert!(
        text(&rerun).contains("51 done (50 already"),
        "{}",
        text(&rerun)
    );
    let best =
        |bytes: &[u8]| serde_json::from_slice::<serde_json::Value>(bytes).unwrap()["best"].clone();
    let remade = fs::read(out.join(source)).unwrap();
    assert!(
        best(&remade) == best(&kept),
        "the same run again (timings aside)"
    );
    let _ = fs::remove_dir_all(dir);
}

/// A group's `earlier` budget: the report reads the same runs at the shorter budget (their
/// start), pairs them by seed and says whether the order changes.
#[test]
fn the_report_reads_runs_at_an_earlier_budget() {
    let (dir, file) = smoke("earlier");
    let base = fs::read_to_string(&file).unwrap();
    let longer = "\n[[evolve]]\nname = \"longer\"\nshapes = [\"worm-3x1\"]\n\
                  controllers = [\"attention\", \"mlp\"]\nevals = [16]\nearlier = [8]\n";
    fs::write(&file, base + longer).unwrap();

    let run = vsr(&["campaign", "run", &file, "--jobs", "2"]);
    assert!(run.status.success(), "{}", text(&run));
    let out = dir.join("smoke-out");
    let runs = |evals: u64| -> Vec<serde_json::Value> {
        (1..=3)
            .map(|seed| {
                let path = out.join(format!("runs/worm-3x1-attention-{evals}-s{seed}.json"));
                serde_json::from_slice(&fs::read(path).unwrap()).unwrap()
            })
            .collect()
    };
    for (short, long) in runs(8).iter().zip(runs(16)) {
        let best = |r: &serde_json::Value, g: usize| r["generations"][g]["best"].clone();
        assert_eq!(
            best(short, 1),
            best(&long, 1),
            "the shorter run is the start"
        );
    }
    let report = vsr(&["report", &file]);
    assert!(report.status.success(), "{}", text(&report));
    let md = fs::read_to_string(out.join("report/report.md")).unwrap();
    assert!(md.contains("### The same runs at 8 evaluations"), "{md}");
    assert!(md.contains("| attention | unseen mean | 3 |"), "{md}");
    assert!(
        md.contains("| attention | mlp | unseen mean | 3+3 |"),
        "{md}"
    );
    let _ = fs::remove_dir_all(dir);
}

#[test]
fn a_killed_job_leaves_no_file() {
    let (dir, _) = smoke("kill");
    let out = dir.join("run.json");
    let mut child = Command::new(env!("CARGO_BIN_EXE_vsr"))
        .args([
            "evolve",
            "--shape",
            "biped-4x3",
            "--controller",
            "mlp",
            "--evals",
            "100000",
        ])
        .args([
            "--seed",
            "1",
            "--threads",
            "1",
            "--out",
            out.to_str().unwrap(),
        ])
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::null())
        .spawn()
        .unwrap();
    std::thread::sleep(std::time::Duration::from_millis(300));
    child.kill().unwrap();
    child.wait().unwrap();
    assert_eq!(
        files_in(&dir),
        [dir.join("smoke.toml")],
        "no output, no temporary file"
    );
    let _ = fs::remove_dir_all(dir);
}

#[test]
fn bad_campaign_files_exit_with_code_2() {
    let (dir, file) = smoke("bad");
    fs::write(&file, "output = \"o\"\nseeds = []\n").unwrap();
    let out = vsr(&["campaign", "plan", &file]);
    assert_eq!(out.status.code(), Some(2));
    assert!(text(&out).contains("seeds"), "{}", text(&out));
    // The file is named, the kind of error said once.
    fs::write(&file, "output = \"o\"\nseedz = [1]\n").unwrap();
    let typo = text(&vsr(&["campaign", "plan", &file]));
    assert!(
        typo.starts_with(&format!(
            "vsr: invalid input: {file}: the campaign file is not valid: "
        )) && typo.matches("invalid input").count() == 1,
        "{typo}"
    );
    // A budget below one population would fail every job: refused when planned, as by evolve.
    let grid = "[[evolve]]\nname = \"g\"\nshapes = [\"worm-3x1\"]\ncontrollers = [\"mlp\"]\n";
    fs::write(
        &file,
        format!("output = \"o\"\nseeds = [1]\n{grid}evals = [50]\n"),
    )
    .unwrap();
    for command in ["plan", "run"] {
        let small = vsr(&["campaign", command, &file]);
        assert_eq!(small.status.code(), Some(2));
        assert!(
            text(&small).contains(
                "group 'g': an evaluation budget of 50 is less than one population of 100"
            ),
            "{}",
            text(&small)
        );
    }
    let missing = vsr(&["campaign", "run", "/no/such/campaign.toml"]);
    assert_eq!(missing.status.code(), Some(2));
    let (smoke_dir, smoke_file) = smoke("only");
    let nothing = vsr(&["campaign", "run", &smoke_file, "--only", "no-such-run"]);
    assert_eq!(nothing.status.code(), Some(2), "{}", text(&nothing));
    assert!(text(&nothing).contains("no job's output name contains no-such-run"));
    let part = vsr(&["campaign", "plan", &smoke_file, "--only", "to-worm-4x1"]);
    let lines = text(&part);
    assert!(lines.lines().all(|l| l.starts_with("vsr ")), "{lines}");
    assert!(
        lines
            .lines()
            .any(|l| l.contains("--out ") && l.contains("finetune")),
        "{lines}"
    );
    assert!(!lines.contains("worm-3x1-mlp"), "{lines}");
    let _ = fs::remove_dir_all(smoke_dir);
    let _ = fs::remove_dir_all(dir);
}
