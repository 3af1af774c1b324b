//! Fine-tuning from a module file in a campaign (`[[from_module]]` groups): an existing run
//! file (a pretrained module, e.g. one `vsr campaign export` wrote) fine-tuned on each target
//! shape for every seed (`vsr finetune --from MODULE`, stage 1: the module's attention block
//! frozen, every other gene evolving; a brain for any body starts whole), then each run's best
//! validated on the campaign's sets (stage 2). Outputs: `runs/NAME-to-SHAPE-EVALS-sSEED.json`
//! and `validation/NAME-to-SHAPE-EVALS-sSEED.SET.json`. With `one_shot`, a body-set file
//! that holds the target shapes, the module itself is walked on its bodies before any
//! fine-tuning (`vsr validate --bodies`, stage 1), its speed on each target the one-shot
//! speed: `validation/NAME-module.BODYSET.SET.json`.
//!
//! The module is not made by the campaign: when it does not exist yet, the command line says
//! what makes it (`made_by`, the campaign whose export writes it). With `compare`, the report
//! shows beside each target the runs of that campaign's `[[finetune]]` groups onto the same
//! shape (their fine-tunings of a transplanted module and their runs from scratch), read
//! from that campaign's output folder and never run by this one.
//!
//! ```toml
//! [[from_module]]
//! name = "ft-any-train32"                    # the first part of its file names
//! module = "../pretrained/any-train32-attention-any.json"   # relative to the campaign file
//! controller = "attention-any"               # the module's controller (checked on the file)
//! made_by = "any-body.toml"                  # the campaign whose export writes the module
//! shapes = ["biped-4x3", "comb-7x2"]         # target shapes
//! evals = 2500                               # budget of each fine-tuning
//! compare = "paper.toml"                     # shown beside: its [[finetune]] runs on the shapes
//! one_shot = "bodies/heldout-paper.txt"      # the module walked on these bodies, unchanged
//! ```

use super::file::{Campaign, FinetuneGroup};
use super::job::{Job, RunTask, Task};
use super::plan::finetune_runs;
use super::run_spec::RunSpec;
use serde::Deserialize;
use std::path::{Path, PathBuf};
use vsr::controllers::ControllerKind;
use vsr::experiment::{RunFile, ValidationSet};
use vsr::simulation::Shape;
use vsr::{Error, Result};

/// Fine-tunings of one module file on target shapes; see the module doc.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct FromModuleGroup {
    /// The group's name (the first part of its file names).
    pub name: String,
    /// The module's run file, relative to the campaign file.
    pub module: String,
    /// The module's controller: a family with the attention block.
    pub controller: ControllerKind,
    /// The campaign file whose export writes the module, relative to the campaign file.
    #[serde(default)]
    pub made_by: Option<String>,
    /// Target shapes: presets or rows.
    pub shapes: Vec<String>,
    /// Budget of each fine-tuning run.
    pub evals: u64,
    /// A campaign file whose `[[finetune]]` runs onto the same shapes the report shows beside.
    #[serde(default)]
    pub compare: Option<String>,
    /// A body-set file (relative to the campaign file) the module is walked on unchanged:
    /// its one-shot speed on each target shape the set holds.
    #[serde(default)]
    pub one_shot: Option<String>,
    /// Seeds (default: the campaign's).
    #[serde(default)]
    pub seeds: Option<Vec<u64>>,
}

/// One planned fine-tuning of a `[[from_module]]` group.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct FromModuleSpec {
    /// The group's name.
    pub group: String,
    /// The target shape as the campaign names it.
    pub shape: String,
    /// Evaluation budget.
    pub evals: u64,
    /// Run seed.
    pub seed: u64,
}

impl FromModuleSpec {
    /// The file stem of its outputs: `NAME-to-SHAPE-EVALS-sSEED`.
    pub fn stem(&self) -> String {
        format!(
            "{}-to-{}-{}-s{}",
            self.group, self.shape, self.evals, self.seed
        )
    }

    /// Its run file under `out`.
    pub fn run_path(&self, out: &Path) -> PathBuf {
        out.join("runs").join(format!("{}.json", self.stem()))
    }

    /// Its validation file on `set` under `out`.
    pub fn validation_path(&self, out: &Path, set: ValidationSet) -> PathBuf {
        out.join("validation")
            .join(format!("{}.{set}.json", self.stem()))
    }
}

impl FromModuleGroup {
    /// Checks the shapes, the budget and that the controller can be fine-tuned (the files are
    /// read when the runs start).
    pub fn check(&self) -> Result<()> {
        let bad = |m: String| Err(Error::Input(m));
        for s in &self.shapes {
            Shape::parse(s)?;
        }
        if self.shapes.is_empty() || self.evals == 0 {
            return bad(format!(
                "group '{}' needs at least one target shape and a budget",
                self.name
            ));
        }
        if !self.controller.has_attention() {
            return bad(format!(
                "group '{}': a {} module cannot be fine-tuned: fine-tuning keeps the module's \
                 attention block and evolves the rest, and {} has none (use an attention, \
                 slow-attention or attention-any module)",
                self.name, self.controller, self.controller
            ));
        }
        Ok(())
    }

    /// Its paths taken relative to `dir`, the campaign file's folder.
    pub fn relative_to(&mut self, dir: &Path) {
        self.module = under(dir, &self.module);
        for path in [&mut self.made_by, &mut self.compare, &mut self.one_shot] {
            *path = path.as_deref().map(|p| under(dir, p));
        }
    }

    /// The module's one-shot walk on the `one_shot` bodies over `set` under `out`.
    pub fn one_shot_path(&self, out: &Path, set: ValidationSet) -> Option<PathBuf> {
        let stem = super::any_body::set_stem(self.one_shot.as_deref()?);
        let name = format!("{}-module.{stem}.{set}.json", self.name);
        Some(out.join("validation").join(name))
    }

    /// Its runs, shapes outermost; `seeds` when the group names none.
    pub fn specs(&self, seeds: &[u64]) -> Vec<FromModuleSpec> {
        let mut out = Vec::new();
        for shape in &self.shapes {
            for &seed in self.seeds.as_deref().unwrap_or(seeds) {
                out.push(FromModuleSpec {
                    group: self.name.clone(),
                    shape: shape.clone(),
                    evals: self.evals,
                    seed,
                });
            }
        }
        out
    }

    /// This group's jobs under `out`: each fine-tuning (stage 1), then its validations on
    /// `sets` (stage 2); episodes of `seconds` on `terrain`, GA population `population`.
    pub fn jobs(
        &self,
        seeds: &[u64],
        (seconds, population, terrain): (f64, usize, &str),
        sets: &[ValidationSet],
        out: &Path,
    ) -> Vec<Job> {
        let mut jobs = Vec::new();
        for &set in sets {
            let (Some(bodies), Some(path)) = (&self.one_shot, self.one_shot_path(out, set)) else {
                break;
            };
            jobs.push(Job {
                stage: 1,
                task: Task::ValidateBodies {
                    genome: PathBuf::from(&self.module),
                    bodies: PathBuf::from(bodies),
                    set,
                    seconds,
                },
                out: path,
                needs: vec![],
            });
        }
        for spec in self.specs(seeds) {
            let run = spec.run_path(out);
            jobs.push(Job {
                stage: 1,
                task: Task::Run(RunTask {
                    from: Some(PathBuf::from(&self.module)),
                    shape: spec.shape.clone(),
                    controller: self.controller,
                    evals: spec.evals,
                    seed: spec.seed,
                    seconds,
                    population,
                    terrain: terrain.to_string(),
                    keep_checkpoint: false,
                    continue_from: None,
                    bodies: None,
                }),
                out: run.clone(),
                // The module is made elsewhere: the command line checks it before any job.
                needs: vec![],
            });
            for &set in sets {
                jobs.push(Job::validate(
                    2,
                    &run,
                    set,
                    seconds,
                    spec.validation_path(out, set),
                ));
            }
        }
        jobs
    }

    /// Whether `module` (the run file at `self.module`, `None` when the file does not exist)
    /// can be fine-tuned as planned; the error says what to do.
    pub fn check_module(&self, module: Option<&RunFile>) -> Result<()> {
        let Some(run) = module else {
            let maker = match &self.made_by {
                Some(campaign) => format!(
                    "`vsr campaign export {campaign}` writes it once that campaign's runs are \
                     finished"
                ),
                None => "make it first (a run file of `vsr evolve`, or `vsr campaign export` \
                         of the campaign that trains it)"
                    .to_string(),
            };
            return Err(Error::Input(format!(
                "group '{}': the module {} does not exist yet: {maker}",
                self.name, self.module
            )));
        };
        let found = run.config.controller;
        if !found.has_attention() {
            return Err(Error::Input(format!(
                "group '{}': the module {} is a {found} brain, which cannot be fine-tuned: \
                 fine-tuning keeps the attention block and {found} has none",
                self.name, self.module
            )));
        }
        if found != self.controller {
            return Err(Error::Input(format!(
                "group '{}': the module {} is a {found} brain, not the {} the campaign says",
                self.name, self.module, self.controller
            )));
        }
        Ok(())
    }
}

/// `path` (relative to `dir`) as a clean path.
fn under(dir: &Path, path: &str) -> String {
    path_clean::clean(dir.join(path)).display().to_string()
}

/// The runs of `compared`'s `[[finetune]]` groups that end on one of `shapes`: each group's
/// fine-tunings onto the shape and its runs from scratch on it, with the group.
pub fn compared_runs(compared: &Campaign, shapes: &[String]) -> Vec<(FinetuneGroup, RunSpec)> {
    let mut out = Vec::new();
    for g in &compared.finetune {
        for r in finetune_runs(compared, g) {
            let onto = shapes.contains(&r.shape);
            let scratch_on_target = r.source.is_none()
                && g.scratch_evals == Some(r.evals)
                && g.pairs.iter().any(|[_, to]| to == &r.shape);
            if onto && (r.source.is_some() || scratch_on_target) {
                out.push((g.clone(), r));
            }
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    const FILE: &str = r#"
output = "o"
seeds = [1, 2]
population = 10
[[from_module]]
name = "ft"
module = "m.json"
controller = "attention-any"
made_by = "any.toml"
shapes = ["biped-4x3", "comb-7x2"]
evals = 100
"#;

    #[test]
    fn a_group_plans_each_shape_and_seed_then_its_validations() {
        let c = Campaign::parse(FILE).unwrap();
        let jobs = super::super::plan::plan(&c, Path::new("o"));
        let names: Vec<String> = jobs.iter().map(|j| j.out.display().to_string()).collect();
        assert_eq!(names.len(), 4 * 3);
        assert_eq!(names[0], "o/runs/ft-to-biped-4x3-100-s1.json");
        assert_eq!(names[3], "o/runs/ft-to-comb-7x2-100-s2.json");
        assert_eq!(names[4], "o/validation/ft-to-biped-4x3-100-s1.paper.json");
        let Task::Run(run) = &jobs[0].task else {
            panic!("the first job is a run")
        };
        assert_eq!(run.from.as_deref(), Some(Path::new("m.json")));
    }

    #[test]
    fn a_module_without_attention_is_refused_in_words() {
        let text = FILE.replace("attention-any", "mlp-any");
        let e = Campaign::parse(&text).unwrap_err().to_string();
        assert!(e.contains("cannot be fine-tuned"), "{e}");
    }

    #[test]
    fn a_missing_module_says_what_makes_it() {
        let c = Campaign::parse(FILE).unwrap();
        let e = c.from_module[0].check_module(None).unwrap_err().to_string();
        assert!(e.contains("vsr campaign export any.toml"), "{e}");
    }
}
