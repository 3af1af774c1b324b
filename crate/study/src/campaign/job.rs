//! One job of a campaign as data: what it does (a [`Task`]), the one file it writes and the
//! files it needs; and the selection of a part of a plan (`--only`). The command line turns a
//! job into a `vsr` command.

use std::path::{Path, PathBuf};
use vsr::controllers::ControllerKind;
use vsr::experiment::ValidationSet;

/// One job of a plan.
#[derive(Debug, Clone, PartialEq)]
pub struct Job {
    /// 1, 2 or 3; see `plan`'s module doc.
    pub stage: u32,
    /// What the job does.
    pub task: Task,
    /// The one file the job writes.
    pub out: PathBuf,
    /// Files that must exist before it starts.
    pub needs: Vec<PathBuf>,
}

/// What a job does: one `vsr` subcommand with its settings.
#[derive(Debug, Clone, PartialEq)]
pub enum Task {
    /// An evolutionary run (`vsr evolve`, or `vsr finetune` when it has a source).
    Run(RunTask),
    /// The re-assessment of a run's best on a validation set (`vsr validate`).
    Validate {
        /// The run file.
        genome: PathBuf,
        /// The validation set.
        set: ValidationSet,
        /// Episode seconds.
        seconds: f64,
    },
    /// The frozen-attention ablation of a run's best (`vsr ablate`).
    Ablate {
        /// The run file.
        genome: PathBuf,
        /// Freeze at every whole second up to this one.
        last_second: u32,
        /// The terrain of the recording and the frozen episodes.
        terrain: String,
        /// Episode seconds.
        seconds: f64,
    },
    /// A brain for any body walked on every body of a set (`vsr validate --bodies`).
    ValidateBodies {
        /// The run file.
        genome: PathBuf,
        /// The body-set file.
        bodies: PathBuf,
        /// The validation set (terrains).
        set: ValidationSet,
        /// Episode seconds.
        seconds: f64,
    },
    /// A random brain for any body walked on every body of a set: the floor of the trained
    /// brains (`vsr validate --random-brain CONTROLLER --seed SEED --bodies`).
    RandomBodies {
        /// The family of the random brain.
        controller: ControllerKind,
        /// The seed of its genes.
        seed: u64,
        /// The body-set file.
        bodies: PathBuf,
        /// The validation set (terrains).
        set: ValidationSet,
        /// Episode seconds.
        seconds: f64,
    },
    /// A body search (`vsr codesign`).
    Codesign(CodesignTask),
    /// The reference's gait ensembles measured here (`vsr fidelity`).
    Fidelity {
        /// The reference file.
        reference: PathBuf,
    },
}

/// An evolutionary run of a campaign.
#[derive(Debug, Clone, PartialEq)]
pub struct RunTask {
    /// The run file of the source run whose best lends its attention block (fine-tuning).
    pub from: Option<PathBuf>,
    /// The shape as the campaign names it.
    pub shape: String,
    /// Controller family (a fine-tuning takes its source's).
    pub controller: ControllerKind,
    /// Evaluation budget.
    pub evals: u64,
    /// Run seed.
    pub seed: u64,
    /// Episode seconds.
    pub seconds: f64,
    /// GA population.
    pub population: usize,
    /// Training terrain family or name.
    pub terrain: String,
    /// Keep the final checkpoint: a longer run continues this one.
    pub keep_checkpoint: bool,
    /// The checkpoint of the shorter run this one continues.
    pub continue_from: Option<PathBuf>,
    /// Training on many bodies (`vsr evolve --bodies`); then `shape` names the set.
    pub bodies: Option<TrainOnBodies>,
}

/// The body set of a run on many bodies.
#[derive(Debug, Clone, PartialEq)]
pub struct TrainOnBodies {
    /// The body-set file.
    pub file: PathBuf,
    /// Bodies walked by each evaluation.
    pub per_evaluation: usize,
}

/// A body search of a campaign.
#[derive(Debug, Clone, PartialEq)]
pub struct CodesignTask {
    /// How the brain is obtained.
    pub brain: vsr::experiment::BrainMode,
    /// The controller of a brain from scratch.
    pub controller: Option<ControllerKind>,
    /// The module's run file (frozen, finetune).
    pub from: Option<PathBuf>,
    /// The start body, when not the default.
    pub start: Option<String>,
    /// Evaluation budget.
    pub evals: u64,
    /// Run seed.
    pub seed: u64,
    /// Episode seconds.
    pub seconds: f64,
    /// Training terrain family or name.
    pub terrain: String,
}

impl Job {
    /// The validation of the run file `run` on `set` with episodes of `seconds`, written to
    /// `out` once `run` exists.
    pub fn validate(stage: u32, run: &Path, set: ValidationSet, seconds: f64, out: PathBuf) -> Job {
        Job {
            stage,
            task: Task::Validate {
                genome: run.to_path_buf(),
                set,
                seconds,
            },
            out,
            needs: vec![run.to_path_buf()],
        }
    }

    /// True when the job is an evolution or a fine-tuning (it takes `--threads`; minutes, where
    /// an assessment takes seconds).
    pub fn threaded(&self) -> bool {
        matches!(self.task, Task::Run(_) | Task::Codesign(_))
    }
}

/// The jobs of `jobs` (a plan, in dependency order) whose output file name contains one of
/// `patterns`, with every job they need, in the same order; all of them when `patterns` is
/// empty. `--only to-comb-7x2` selects the fine-tunings onto comb-7x2, their source runs
/// and their validations.
pub fn select(jobs: Vec<Job>, patterns: &[String]) -> Vec<Job> {
    if patterns.is_empty() {
        return jobs;
    }
    let named = |j: &Job| {
        let name = j
            .out
            .file_name()
            .map_or(String::new(), |n| n.to_string_lossy().into_owned());
        patterns.iter().any(|p| name.contains(p.as_str()))
    };
    let mut keep: Vec<bool> = jobs.iter().map(named).collect();
    // Needs come earlier in a plan: one backward pass closes the selection over them.
    for i in (0..jobs.len()).rev() {
        if keep[i] {
            for need in &jobs[i].needs {
                if let Some(k) = jobs[..i].iter().position(|j| &j.out == need) {
                    keep[k] = true;
                }
            }
        }
    }
    jobs.into_iter()
        .zip(keep)
        .filter_map(|(j, k)| k.then_some(j))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::campaign::plan::{plan, tests::CAMPAIGN};
    use crate::campaign::Campaign;
    use std::path::Path;

    #[test]
    fn a_selection_brings_the_jobs_it_needs() {
        let c = Campaign::parse(CAMPAIGN).unwrap();
        let all = plan(&c, Path::new("o"));
        assert_eq!(select(all.clone(), &[]), all);
        let only = select(all.clone(), &["to-biped-4x3-100-s2.paper".to_string()]);
        let names: Vec<String> = only
            .iter()
            .map(|j| j.out.file_name().unwrap().to_string_lossy().into_owned())
            .collect();
        assert_eq!(
            names,
            [
                "comb-7x2-attention-200-s2.json",
                "comb-7x2-attention-200-to-biped-4x3-100-s2.json",
                "comb-7x2-attention-200-to-biped-4x3-100-s2.paper.json",
            ]
        );
        assert!(select(all, &["no-such-run".to_string()]).is_empty());
    }
}
