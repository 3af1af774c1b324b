//! A campaign job (data from `vsr_study::campaign::plan`) as a `vsr` command: its arguments,
//! and its whole line for a POSIX shell (what `vsr campaign plan` prints and the manifest
//! records).

use vsr_study::campaign::{CodesignTask, Job, RunTask, Task};

/// The arguments after `vsr` of `job`, `--threads threads` added to evolutions.
pub fn args(job: &Job, threads: usize) -> Vec<String> {
    let out = job.out.display().to_string();
    let mut args = match &job.task {
        Task::Run(run) => run_args(run),
        Task::Validate {
            genome,
            set,
            seconds,
        } => words(&[
            "validate",
            "--genome",
            &genome.display().to_string(),
            "--set",
            set.name(),
            "--seconds",
            &seconds.to_string(),
            "--json",
        ]),
        Task::Ablate {
            genome,
            last_second,
            terrain,
            seconds,
        } => words(&[
            "ablate",
            "--genome",
            &genome.display().to_string(),
            "--terrain",
            terrain,
            "--last-second",
            &last_second.to_string(),
            "--seconds",
            &seconds.to_string(),
            "--json",
        ]),
        Task::ValidateBodies {
            genome,
            bodies,
            set,
            seconds,
        } => words(&[
            "validate",
            "--genome",
            &genome.display().to_string(),
            "--bodies",
            &bodies.display().to_string(),
            "--set",
            set.name(),
            "--seconds",
            &seconds.to_string(),
            "--json",
        ]),
        Task::RandomBodies {
            controller,
            seed,
            bodies,
            set,
            seconds,
        } => words(&[
            "validate",
            "--random-brain",
            controller.name(),
            "--seed",
            &seed.to_string(),
            "--bodies",
            &bodies.display().to_string(),
            "--set",
            set.name(),
            "--seconds",
            &seconds.to_string(),
            "--json",
        ]),
        Task::Codesign(task) => codesign_args(task),
        Task::Fidelity { reference } => {
            words(&["fidelity", "--reference", &reference.display().to_string()])
        }
    };
    args.extend(["--out".to_string(), out]);
    if job.threaded() {
        args.extend(["--threads".to_string(), threads.to_string()]);
    }
    args
}

/// `vsr codesign` without `--out`.
fn codesign_args(task: &CodesignTask) -> Vec<String> {
    let mut args = words(&["codesign", "--brain", task.brain.name()]);
    if let Some(from) = &task.from {
        args.extend(words(&["--from", &from.display().to_string()]));
    }
    if let Some(kind) = task.controller {
        args.extend(words(&["--controller", kind.name()]));
    }
    if let Some(start) = &task.start {
        args.extend(words(&["--start", start]));
    }
    args.extend(words(&[
        "--evals",
        &task.evals.to_string(),
        "--seed",
        &task.seed.to_string(),
        "--seconds",
        &task.seconds.to_string(),
        "--terrain",
        &task.terrain,
    ]));
    args
}

/// `vsr evolve` (or `vsr finetune` from a source run) without `--out`.
fn run_args(run: &RunTask) -> Vec<String> {
    let mut args = match (&run.from, &run.bodies) {
        (None, Some(bodies)) => words(&[
            "evolve",
            "--bodies",
            &bodies.file.display().to_string(),
            "--bodies-per-evaluation",
            &bodies.per_evaluation.to_string(),
            "--controller",
            run.controller.name(),
        ]),
        (None, None) => words(&[
            "evolve",
            "--shape",
            &run.shape,
            "--controller",
            run.controller.name(),
        ]),
        (Some(from), _) => words(&[
            "finetune",
            "--from",
            &from.display().to_string(),
            "--shape",
            &run.shape,
        ]),
    };
    args.extend(words(&[
        "--evals",
        &run.evals.to_string(),
        "--seed",
        &run.seed.to_string(),
        "--seconds",
        &run.seconds.to_string(),
        "--population",
        &run.population.to_string(),
        "--terrain",
        &run.terrain,
    ]));
    if run.keep_checkpoint {
        args.push("--keep-checkpoint".to_string());
    }
    if let Some(checkpoint) = &run.continue_from {
        args.extend(["--continue".to_string(), checkpoint.display().to_string()]);
    }
    args
}

/// The whole command line of `job` for `program`, arguments quoted for a POSIX shell where
/// needed.
pub fn line(job: &Job, program: &str, threads: usize) -> String {
    let mut words = vec![quote(program)];
    words.extend(args(job, threads).iter().map(|a| quote(a)));
    words.join(" ")
}

fn words(w: &[&str]) -> Vec<String> {
    w.iter().map(|s| s.to_string()).collect()
}

/// Quotes `word` for a POSIX shell unless it is made of safe characters only.
fn quote(word: &str) -> String {
    let safe = |c: char| c.is_ascii_alphanumeric() || "-_./=:+,".contains(c);
    if !word.is_empty() && word.chars().all(safe) {
        return word.to_string();
    }
    format!("'{}'", word.replace('\'', r"'\''"))
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::path::Path;
    use vsr_study::campaign::{plan, Campaign};

    /// One fine-tuning of comb-7x2's attention onto biped-4x3 (keys as a TOML table).
    const CAMPAIGN: &str = r#"
seeds = [1]
output = "o"
finetune = [{ name = "b", controller = "attention", evals = 100, source_evals = 200, pairs = [["comb-7x2", "biped-4x3"]] }]
"#;

    #[test]
    fn commands_are_complete_and_quoted() {
        let jobs = plan(&Campaign::parse(CAMPAIGN).unwrap(), Path::new("my study"));
        let finetune = |j: &&Job| matches!(&j.task, Task::Run(r) if r.from.is_some());
        let ft = jobs.iter().find(finetune).unwrap();
        assert_eq!(
            line(ft, "vsr", 2),
            "vsr finetune --from 'my study/runs/comb-7x2-attention-200-s1.json' --shape \
             biped-4x3 --evals 100 --seed 1 --seconds 30 --population 100 --terrain hilly-1-10 \
             --out 'my study/runs/comb-7x2-attention-200-to-biped-4x3-100-s1.json' --threads 2"
        );
    }

    #[test]
    fn words_are_quoted_for_a_shell() {
        assert_eq!(quote("it's"), r"'it'\''s'");
        assert_eq!(quote("plain-word_1.json"), "plain-word_1.json");
    }
}
