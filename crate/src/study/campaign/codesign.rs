//! Body-search runs in a campaign (`[[codesign]]` groups): for every condition and seed, one
//! `vsr codesign` run (stage 1) and its best body's validations (stage 2). A condition is a
//! brain: `frozen` and `finetune` (the group's `module`, an attention run file relative to
//! the campaign file), or `scratch-CONTROLLER` (`scratch-attention`, `scratch-mlp`,
//! `scratch-mlp-comm`). Outputs: `codesign/NAME-CONDITION-EVALS-sSEED.json` and
//! `validation/NAME-CONDITION-EVALS-sSEED.SET.json`.

use super::file::Campaign;
use super::job::{CodesignTask, Job, Task};
use crate::controllers::ControllerKind;
use crate::error::{Error, Result};
use crate::experiment::BrainMode;
use serde::Deserialize;
use std::path::{Path, PathBuf};

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

/// The jobs of every co-design group of `c` under `out`: each run (stage 1), then its
/// validations (stage 2).
pub fn codesign_jobs(c: &Campaign, out: &Path) -> Vec<Job> {
    let mut jobs = Vec::new();
    for g in &c.codesign {
        for cond in &g.conditions {
            let Ok((brain, controller)) = condition(cond) else {
                continue;
            };
            for &seed in g.seeds.as_ref().unwrap_or(&c.seeds) {
                let stem = g.stem(cond, seed);
                let run = out.join("codesign").join(format!("{stem}.json"));
                jobs.push(Job {
                    stage: 1,
                    task: Task::Codesign(CodesignTask {
                        brain,
                        controller,
                        from: (brain != BrainMode::Scratch)
                            .then(|| g.module.as_ref().map(PathBuf::from))
                            .flatten(),
                        start: g.start.clone(),
                        evals: g.evals,
                        seed,
                        seconds: c.seconds,
                        terrain: c.terrain.clone(),
                    }),
                    out: run.clone(),
                    needs: vec![],
                });
                for &set in &c.validate {
                    jobs.push(Job {
                        stage: 2,
                        task: Task::Validate {
                            genome: run.clone(),
                            set,
                            seconds: c.seconds,
                        },
                        out: out.join("validation").join(format!("{stem}.{set}.json")),
                        needs: vec![run.clone()],
                    });
                }
            }
        }
    }
    jobs
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::study::campaign::plan;

    const FILE: &str = r#"
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
        let c = Campaign::parse(FILE).unwrap().relative_to(Path::new("dir"));
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
        let err = Campaign::parse(&FILE.replace("scratch-mlp", "fozen")).unwrap_err();
        assert!(
            err.to_string()
                .contains("unknown co-design condition 'fozen'"),
            "{err}"
        );
        let err = Campaign::parse(&FILE.replace("module = \"m.json\"", "")).unwrap_err();
        assert!(err.to_string().contains("needs a module"), "{err}");
    }
}
