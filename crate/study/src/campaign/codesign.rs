//! Body-search runs in a campaign (`[[codesign]]` groups): for every condition and seed, one
//! `vsr codesign` run (stage 1) and its best body's validations (stage 2). A condition is a
//! brain: `frozen` and `finetune` (the group's `module`, an attention run file relative to
//! the campaign file), or `scratch-CONTROLLER` (`scratch-attention`, `scratch-mlp`,
//! `scratch-mlp-comm`). Outputs: `codesign/NAME-CONDITION-EVALS-sSEED.json` and
//! `validation/NAME-CONDITION-EVALS-sSEED.SET.json`.

use super::job::{CodesignTask, Job, Task};
use serde::Deserialize;
use std::path::{Path, PathBuf};
use vsr::controllers::ControllerKind;
use vsr::experiment::{BrainMode, ValidationSet};
use vsr::{Error, Result};

/// A grid of body searches: conditions x seeds at one budget.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CodesignGroup {
    /// The group's name (the first part of its file names).
    pub name: String,
    /// Conditions: frozen, finetune, scratch-attention, scratch-mlp, scratch-mlp-comm.
    pub conditions: Vec<String>,
    /// The pretrained module's run file (frozen, finetune), relative to the campaign file.
    #[serde(default)]
    pub module: Option<String>,
    /// The start body of every condition (default: `vsr codesign`'s).
    #[serde(default)]
    pub start: Option<String>,
    /// Evaluation budget of each run.
    pub evals: u64,
    /// Seeds (default: the campaign's).
    #[serde(default)]
    pub seeds: Option<Vec<u64>>,
}

/// A condition as a brain mode and a controller (scratch only).
pub fn condition(name: &str) -> Result<(BrainMode, Option<ControllerKind>)> {
    match name.trim() {
        "frozen" => Ok((BrainMode::Frozen, None)),
        "finetune" => Ok((BrainMode::Finetune, None)),
        other => match other.strip_prefix("scratch-") {
            Some(kind) => Ok((BrainMode::Scratch, Some(kind.parse()?))),
            None => Err(Error::Input(format!(
                "unknown co-design condition '{other}': expected frozen, finetune or \
                 scratch-CONTROLLER (e.g. scratch-attention, scratch-mlp)"
            ))),
        },
    }
}

impl CodesignGroup {
    /// Checks the conditions and that `frozen` / `finetune` have a module.
    pub fn check(&self) -> Result<()> {
        if self.conditions.is_empty() || self.evals == 0 {
            return Err(Error::Input(format!(
                "co-design group '{}' needs at least one condition and a budget",
                self.name
            )));
        }
        for c in &self.conditions {
            let (brain, _) = condition(c)?;
            if brain != BrainMode::Scratch && self.module.is_none() {
                return Err(Error::Input(format!(
                    "co-design group '{}': condition {c} needs a module (module = \"...json\")",
                    self.name
                )));
            }
        }
        Ok(())
    }

    /// The file stem of one run.
    pub fn stem(&self, condition: &str, seed: u64) -> String {
        format!("{}-{condition}-{}-s{seed}", self.name, self.evals)
    }
}

impl CodesignGroup {
    /// This group's jobs under `out`: each run (stage 1), then its validations on `sets`
    /// (stage 2); `seeds` when the group names none, episodes of `seconds` on `terrain`.
    pub fn jobs(
        &self,
        seeds: &[u64],
        seconds: f64,
        terrain: &str,
        sets: &[ValidationSet],
        out: &Path,
    ) -> Vec<Job> {
        let mut jobs = Vec::new();
        for cond in &self.conditions {
            let Ok((brain, controller)) = condition(cond) else {
                continue;
            };
            for &seed in self.seeds.as_deref().unwrap_or(seeds) {
                let stem = self.stem(cond, seed);
                let run = out.join("codesign").join(format!("{stem}.json"));
                jobs.push(Job {
                    stage: 1,
                    task: Task::Codesign(CodesignTask {
                        brain,
                        controller,
                        from: (brain != BrainMode::Scratch)
                            .then(|| self.module.as_ref().map(PathBuf::from))
                            .flatten(),
                        start: self.start.clone(),
                        evals: self.evals,
                        seed,
                        seconds,
                        terrain: terrain.to_string(),
                    }),
                    out: run.clone(),
                    needs: vec![],
                });
                for &set in sets {
                    let file = out.join("validation").join(format!("{stem}.{set}.json"));
                    jobs.push(Job::validate(2, &run, set, seconds, file));
                }
            }
        }
        jobs
    }
}
