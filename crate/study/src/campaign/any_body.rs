//! One brain for many bodies in a campaign (`[[any_body]]` groups): for every seed and
//! controller (a family for any body), one `vsr evolve --bodies` run on the group's training
//! set (stage 1), then its best walked on every body of each held-out set and of the training
//! set itself (`vsr validate --bodies`, stage 2). Outputs:
//! `runs/NAME-CONTROLLER-EVALS-sSEED.json` and
//! `validation/NAME-CONTROLLER-EVALS-sSEED.BODYSET.SET.json` (BODYSET: the set file's stem).
//!
//! Beside the runs, the floor they are measured against (the plan's "random brain"): for every
//! family the groups train and every seed of the campaign, a random genome of that family
//! (`vsr validate --random-brain`, genes uniform in [-1, 1] from the seed) walked on every
//! held-out set of the groups (each set once), stage 1:
//! `validation/floor-CONTROLLER-sSEED.BODYSET.SET.json` ([`floor_jobs`]).
//!
//! ```toml
//! [[any_body]]
//! name = "any-train32"                       # the first part of its file names
//! bodies = "bodies/train-32.txt"             # training set, relative to the campaign file
//! per_evaluation = 4                         # bodies walked by each evaluation
//! controllers = ["attention-any", "mlp-any", "mlp-comm-any"]
//! evals = 10000
//! heldout = ["bodies/heldout-random.txt", "bodies/heldout-paper.txt"]
//! sets = ["unseen"]                          # terrains of the validations (default: unseen)
//! ```

use super::job::{Job, RunTask, Task, TrainOnBodies};
use serde::Deserialize;
use std::path::{Path, PathBuf};
use vsr::controllers::ControllerKind;
use vsr::experiment::ValidationSet;
use vsr::{Error, Result};

/// A grid of runs of brains for any body on one training set; see the module doc.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct AnyBodyGroup {
    /// The group's name (the first part of its file names).
    pub name: String,
    /// The training body set, relative to the campaign file.
    pub bodies: String,
    /// Bodies walked by each evaluation.
    #[serde(default = "four")]
    pub per_evaluation: usize,
    /// Controllers (families for any body).
    pub controllers: Vec<ControllerKind>,
    /// Evaluation budget of each run.
    pub evals: u64,
    /// Held-out body sets, relative to the campaign file (the training set is validated too).
    #[serde(default)]
    pub heldout: Vec<String>,
    /// Terrains of the validations.
    #[serde(default = "unseen")]
    pub sets: Vec<ValidationSet>,
    /// Seeds (default: the campaign's).
    #[serde(default)]
    pub seeds: Option<Vec<u64>>,
}

fn four() -> usize {
    4
}

fn unseen() -> Vec<ValidationSet> {
    vec![ValidationSet::Unseen]
}

/// A body-set file's stem (`bodies/train-32.txt` -> `train-32`).
pub fn set_stem(path: &str) -> String {
    Path::new(path)
        .file_stem()
        .map_or_else(|| path.to_string(), |s| s.to_string_lossy().into_owned())
}

impl AnyBodyGroup {
    /// Checks the controllers and settings (the files are read when the runs start).
    pub fn check(&self) -> Result<()> {
        let bad = |m: String| Err(Error::Input(m));
        if self.controllers.is_empty() || self.evals == 0 || self.per_evaluation == 0 {
            return bad(format!(
                "any-body group '{}' needs a controller, a budget and per_evaluation >= 1",
                self.name
            ));
        }
        if let Some(c) = self.controllers.iter().find(|c| !c.is_body_independent()) {
            return bad(format!(
                "any-body group '{}': {c} has genes for each voxel of one body; use \
                 attention-any, mlp-any or mlp-comm-any",
                self.name
            ));
        }
        Ok(())
    }

    /// The file stem of one run.
    pub fn stem(&self, controller: ControllerKind, seed: u64) -> String {
        format!("{}-{controller}-{}-s{seed}", self.name, self.evals)
    }

    /// The body sets each run is validated on: the held-out ones, then the training set.
    pub fn validated_on(&self) -> Vec<&str> {
        let mut v: Vec<&str> = self.heldout.iter().map(String::as_str).collect();
        v.push(&self.bodies);
        v
    }

    /// Its paths taken relative to `dir`, the campaign file's folder.
    pub fn relative_to(&mut self, dir: &Path) {
        let clean = |p: &str| path_clean::clean(dir.join(p)).display().to_string();
        self.bodies = clean(&self.bodies);
        for h in &mut self.heldout {
            *h = clean(h);
        }
    }

    /// This group's jobs under `out`, seeds outermost (so every controller has its first
    /// seeds early): each run (stage 1), then its validations (stage 2); `seeds` when the
    /// group names none; episodes of `seconds` on `terrain`, GA population `population`.
    pub fn jobs(
        &self,
        seeds: &[u64],
        (seconds, population, terrain): (f64, usize, &str),
        out: &Path,
    ) -> Vec<Job> {
        let mut jobs = Vec::new();
        for &seed in self.seeds.as_deref().unwrap_or(seeds) {
            for &controller in &self.controllers {
                let stem = self.stem(controller, seed);
                let run = out.join("runs").join(format!("{stem}.json"));
                jobs.push(Job {
                    stage: 1,
                    task: Task::Run(RunTask {
                        from: None,
                        shape: set_stem(&self.bodies),
                        controller,
                        evals: self.evals,
                        seed,
                        seconds,
                        population,
                        terrain: terrain.to_string(),
                        keep_checkpoint: false,
                        continue_from: None,
                        bodies: Some(TrainOnBodies {
                            file: PathBuf::from(&self.bodies),
                            per_evaluation: self.per_evaluation,
                        }),
                    }),
                    out: run.clone(),
                    needs: vec![],
                });
                for bodies in self.validated_on() {
                    for &set in &self.sets {
                        let name = format!("{stem}.{}.{set}.json", set_stem(bodies));
                        jobs.push(Job {
                            stage: 2,
                            task: Task::ValidateBodies {
                                genome: run.clone(),
                                bodies: PathBuf::from(bodies),
                                set,
                                seconds,
                            },
                            out: out.join("validation").join(name),
                            needs: vec![run.clone()],
                        });
                    }
                }
            }
        }
        jobs
    }
}

/// The first part of the floor's file names.
pub const FLOOR: &str = "floor";

/// The file stem of the floor's random brain of `controller` and `seed`.
pub fn floor_stem(controller: ControllerKind, seed: u64) -> String {
    format!("{FLOOR}-{controller}-s{seed}")
}

/// The floor's random brains: every family the groups train (in their order), each at every
/// seed of `seeds` (the campaign's).
pub fn floor_brains(groups: &[AnyBodyGroup], seeds: &[u64]) -> Vec<(ControllerKind, u64)> {
    let mut kinds: Vec<ControllerKind> = Vec::new();
    for g in groups {
        for &c in &g.controllers {
            if !kinds.contains(&c) {
                kinds.push(c);
            }
        }
    }
    kinds
        .into_iter()
        .flat_map(|c| seeds.iter().map(move |&s| (c, s)))
        .collect()
}

/// The sets the floor is walked on: every held-out set of the groups, each once (in their
/// order), with every terrain set of the groups.
pub fn floor_sets(groups: &[AnyBodyGroup]) -> Vec<(String, ValidationSet)> {
    let mut out: Vec<(String, ValidationSet)> = Vec::new();
    for g in groups {
        for h in &g.heldout {
            for &set in &g.sets {
                if !out.iter().any(|(b, s)| b == h && *s == set) {
                    out.push((h.clone(), set));
                }
            }
        }
    }
    out
}

/// The floor's jobs under `out` (stage 1: they need no run); episodes of `seconds`.
pub fn floor_jobs(groups: &[AnyBodyGroup], seeds: &[u64], seconds: f64, out: &Path) -> Vec<Job> {
    let sets = floor_sets(groups);
    let mut jobs = Vec::new();
    for (controller, seed) in floor_brains(groups, seeds) {
        for (bodies, set) in &sets {
            let name = format!(
                "{}.{}.{set}.json",
                floor_stem(controller, seed),
                set_stem(bodies)
            );
            jobs.push(Job {
                stage: 1,
                task: Task::RandomBodies {
                    controller,
                    seed,
                    bodies: PathBuf::from(bodies),
                    set: *set,
                    seconds,
                },
                out: out.join("validation").join(name),
                needs: vec![],
            });
        }
    }
    jobs
}
