//! The plan's unit tests: order, stages, continuation, fine-tuning chains.
use super::*;
use vsr::controllers::ControllerKind;
use vsr::experiment::BrainMode;

pub(crate) const CAMPAIGN: &str = r#"
output = "o"
seeds = [1, 2]
[[evolve]]
name = "a"
shapes = ["biped-4x3"]
controllers = ["attention", "mlp"]
evals = [300]
ablate = true
[[finetune]]
name = "b"
pairs = [["comb-7x2", "biped-4x3"]]
controller = "attention"
source_evals = 200
evals = 100
scratch_evals = 300
"#;

/// Every job's needs come earlier in the plan and in an earlier stage.
fn assert_needs_come_first(jobs: &[Job]) {
    for (i, job) in jobs.iter().enumerate() {
        for need in &job.needs {
            let at = jobs
                .iter()
                .position(|j| &j.out == need)
                .expect("needed job");
            assert!(at < i && jobs[at].stage < job.stage, "{need:?}");
        }
    }
}

#[test]
fn every_job_comes_after_the_jobs_it_needs_and_runs_are_not_repeated() {
    let c = Campaign::parse(CAMPAIGN).unwrap();
    let jobs = plan(&c, Path::new("o"));
    // Runs: 2 controllers x 2 seeds + per seed (source, fine-tune; the scratch run is
    // the attention run of group a) = 8; each validated twice; 2 attention runs ablated.
    assert_eq!(jobs.iter().filter(|j| j.threaded()).count(), 8);
    assert_eq!(jobs.len(), 8 + 16 + 2);
    assert_needs_come_first(&jobs);
    let outs: std::collections::HashSet<_> = jobs.iter().map(|j| &j.out).collect();
    assert_eq!(outs.len(), jobs.len(), "one file per job");
}

#[test]
fn a_longer_run_continues_the_shorter_one_with_the_same_seed() {
    let text = CAMPAIGN.replace("evals = [300]", "evals = [300, 100]");
    let jobs = plan(&Campaign::parse(&text).unwrap(), Path::new("o"));
    let job = |stem: &str| {
        let name = format!("{stem}.json");
        jobs.iter()
            .find(|j| j.out.file_name().unwrap().to_string_lossy() == name)
            .unwrap()
    };
    let task = |stem: &str| match &job(stem).task {
        Task::Run(t) => t.clone(),
        other => panic!("{stem}: not a run: {other:?}"),
    };
    let (short, long) = (job("biped-4x3-mlp-100-s2"), job("biped-4x3-mlp-300-s2"));
    assert!(task("biped-4x3-mlp-100-s2").keep_checkpoint);
    assert_eq!(short.stage, 1);
    assert_eq!(
        task("biped-4x3-mlp-300-s2").continue_from,
        Some(PathBuf::from("o/runs/biped-4x3-mlp-100-s2.json.checkpoint"))
    );
    assert_eq!(long.needs, std::slice::from_ref(&short.out));
    assert_eq!(long.stage, 2);
    // Other seeds and controllers, and runs with no shorter twin, are left alone.
    let alone = task("comb-7x2-attention-200-s1");
    assert!(!alone.keep_checkpoint && alone.continue_from.is_none());
    assert!(!task("biped-4x3-attention-300-s1").keep_checkpoint);
}

#[test]
fn chains_of_budgets_and_fine_tunings_of_continued_runs_come_stage_after_stage() {
    let text = CAMPAIGN
        .replace("seeds = [1, 2]\n", "seeds = [1, 2]\npopulation = 10\n")
        .replace("evals = [300]", "evals = [300, 100, 30]")
        .replace(
            "pairs = [[\"comb-7x2\", \"biped-4x3\"]]",
            "pairs = [[\"biped-4x3\", \"comb-7x2\"]]",
        )
        .replace("source_evals = 200", "source_evals = 300");
    let jobs = plan(&Campaign::parse(&text).unwrap(), Path::new("o"));
    assert_needs_come_first(&jobs);
    let stage = |name: &str| {
        let j = jobs.iter().find(|j| j.out.ends_with(name)).unwrap();
        j.stage
    };
    assert_eq!(stage("biped-4x3-mlp-30-s1.json"), 1);
    assert_eq!(stage("biped-4x3-mlp-100-s1.json"), 2);
    assert_eq!(stage("biped-4x3-mlp-300-s1.json"), 3);
    assert_eq!(stage("biped-4x3-attention-300-to-comb-7x2-100-s1.json"), 4);
    assert_eq!(
        stage("biped-4x3-attention-300-to-comb-7x2-100-s1.paper.json"),
        5
    );
}

// Body searches in a campaign ([[codesign]] groups).

const CODESIGN_FILE: &str = r#"
output = "out"
seeds = [1, 2]
validate = ["unseen"]
[[codesign]]
name = "q"
conditions = ["frozen", "scratch-mlp"]
module = "m.json"
evals = 100
"#;

#[test]
fn each_condition_and_seed_is_a_run_then_its_validations() {
    let c = Campaign::parse(CODESIGN_FILE)
        .unwrap()
        .relative_to(Path::new("dir"));
    let jobs = plan(&c, Path::new("out"));
    assert_eq!(jobs.len(), 8);
    let runs: Vec<&Job> = jobs.iter().filter(|j| j.stage == 1).collect();
    assert_eq!(runs.len(), 4);
    assert!(jobs.iter().all(|j| j.threaded() == (j.stage == 1)));
    let Task::Codesign(t) = &runs[0].task else {
        panic!("{:?}", runs[0].task)
    };
    assert_eq!(t.from, Some(PathBuf::from("dir/m.json")));
    assert_eq!(
        runs[0].out,
        PathBuf::from("out/codesign/q-frozen-100-s1.json")
    );
    let Task::Codesign(t) = &runs[2].task else {
        panic!()
    };
    assert_eq!(
        (t.brain, t.controller, &t.from),
        (BrainMode::Scratch, Some(ControllerKind::Mlp), &None)
    );
}

#[test]
fn bad_conditions_and_a_missing_module_are_named() {
    let err = Campaign::parse(&CODESIGN_FILE.replace("scratch-mlp", "fozen")).unwrap_err();
    assert!(
        err.to_string()
            .contains("unknown co-design condition 'fozen'"),
        "{err}"
    );
    let err = Campaign::parse(&CODESIGN_FILE.replace("module = \"m.json\"", "")).unwrap_err();
    assert!(err.to_string().contains("needs a module"), "{err}");
}
