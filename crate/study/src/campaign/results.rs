//! What a campaign has produced so far: for every planned run, its run file, validations
//! and ablation when they exist, and the same for every planned body search. The command
//! line reads the files; this module only holds them and says what is missing.

use super::file::{Campaign, FinetuneGroup};
use super::from_module::FromModuleSpec;
use super::plan::{earlier_runs, known_runs, runs, RunSpec};
use crate::fidelity::Fidelity;
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use vsr::experiment::{AblationPoint, CodesignRun, RunFile, Validation, ValidationSet};

/// The outputs of one run found on disk.
#[derive(Debug, Clone, Default)]
pub struct RunData {
    /// The run file, if it exists.
    pub run: Option<RunFile>,
    /// Validations found, by set.
    pub validation: BTreeMap<ValidationSet, Validation>,
    /// The ablations found, by the set on whose first terrain they ran.
    pub ablation: BTreeMap<ValidationSet, Vec<AblationPoint>>,
}

impl RunData {
    /// The mean validation velocity on `set` (the paper's re-assessment figure), if known.
    pub fn validation_mean(&self, set: ValidationSet) -> Option<f64> {
        self.validation.get(&set).map(|v| v.mean)
    }

    /// Finished and validated on every set.
    pub fn complete(&self) -> bool {
        self.run.is_some() && validated_everywhere(&self.validation)
    }

    /// The unfrozen reference of the ablation on `set`: the velocity of the validation
    /// episode on the set's first terrain (the same terrain and sensor noise), if known.
    pub fn unfrozen(&self, set: ValidationSet) -> Option<f64> {
        self.validation
            .get(&set)?
            .terrains
            .first()
            .map(|t| t.velocity)
    }

    /// The best fitness of the last generation, if the run exists.
    pub fn final_best(&self) -> Option<f64> {
        self.run.as_ref()?.generations.last().map(|g| g.best)
    }

    /// The best fitness of the last generation done within the first `evals` evaluations
    /// (the measure `final_best` gives at the end: the curve of Fig. 3 and 7 read at
    /// `evals`), if the run exists, had done a generation by then and went on that far (a
    /// run that stopped earlier says nothing about `evals`).
    pub fn best_at(&self, evals: u64) -> Option<f64> {
        let generations = &self.run.as_ref()?.generations;
        if generations.last()?.evaluations < evals {
            return None;
        }
        let done = generations.iter().take_while(|g| g.evaluations <= evals);
        done.last().map(|g| g.best)
    }

    /// Evaluations done by the last generation, if the run exists.
    pub fn evaluations(&self) -> Option<u64> {
        self.run.as_ref()?.generations.last().map(|g| g.evaluations)
    }
}

/// One planned body search: a `[[codesign]]` group's condition and seed.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct CodesignSpec {
    /// The group's name.
    pub group: String,
    /// The condition (`frozen`, `finetune`, `scratch-CONTROLLER`).
    pub condition: String,
    /// The budget.
    pub evals: u64,
    /// The seed.
    pub seed: u64,
}

impl CodesignSpec {
    /// `GROUP-CONDITION-EVALS-sSEED`, as `CodesignGroup::stem`.
    pub fn stem(&self) -> String {
        format!(
            "{}-{}-{}-s{}",
            self.group, self.condition, self.evals, self.seed
        )
    }

    /// Its run file under the campaign's output folder `out`.
    pub fn run_path(&self, out: &Path) -> PathBuf {
        out.join("codesign").join(format!("{}.json", self.stem()))
    }

    /// Its best body's validation on `set` under `out`.
    pub fn validation_path(&self, out: &Path, set: ValidationSet) -> PathBuf {
        out.join("validation")
            .join(format!("{}.{set}.json", self.stem()))
    }
}

/// The outputs of one body search found on disk.
#[derive(Debug, Clone, Default)]
pub struct CodesignData {
    /// The finished run file, if it exists (a run in flight has only its checkpoint).
    pub run: Option<CodesignRun>,
    /// Its best body's validations found, by set.
    pub validation: BTreeMap<ValidationSet, Validation>,
}

impl CodesignData {
    /// The best body's mean validation velocity on `set`, if known.
    pub fn validation_mean(&self, set: ValidationSet) -> Option<f64> {
        self.validation.get(&set).map(|v| v.mean)
    }

    /// Finished and its best body validated on every set.
    pub fn complete(&self) -> bool {
        self.run.is_some() && validated_everywhere(&self.validation)
    }
}

/// Whether `validation` holds every set.
fn validated_everywhere(validation: &BTreeMap<ValidationSet, Validation>) -> bool {
    ValidationSet::ALL
        .iter()
        .all(|s| validation.contains_key(s))
}

/// Every run's data, and the expected files that do not exist.
#[derive(Debug, Clone)]
pub struct Results {
    /// The campaign.
    pub campaign: Campaign,
    /// Data of every planned run, in plan order (possibly empty).
    pub data: Vec<(RunSpec, RunData)>,
    /// Data of the runs read at the evolve groups' `earlier` budgets (not planned: never
    /// listed as missing).
    pub earlier: Vec<(RunSpec, RunData)>,
    /// Data of the runs of the non-inferiority tests' known seeds (not planned: never listed
    /// as missing, never pooled with the planned runs).
    pub known: Vec<(RunSpec, RunData)>,
    /// Data of every planned body search, in campaign order (group, condition, seed).
    pub codesign: Vec<(CodesignSpec, CodesignData)>,
    /// Data of every planned run of a brain for any body, in campaign order (group, seed,
    /// controller).
    pub any_body: Vec<(AnyBodySpec, AnyBodyData)>,
    /// The floor of the `[[any_body]]` groups: each random brain (family, seed) with its
    /// validations found, per (body-set stem, terrain set) (`any_body::floor_jobs`).
    pub floor: Vec<((vsr::controllers::ControllerKind, u64), BodySetValidations)>,
    /// Data of every planned fine-tuning from a module file, in campaign order (group,
    /// shape, seed).
    pub from_module: Vec<(FromModuleSpec, RunData)>,
    /// The `[[from_module]]` groups' module files that exist, by group name.
    pub modules: BTreeMap<String, RunFile>,
    /// How many runs each `[[from_module]]` group's module was chosen among (its manifest
    /// entry's `chosen_from`, when the module's folder has a manifest naming it), by group name.
    pub chosen_from: BTreeMap<String, usize>,
    /// The transplants' source runs of each group's compared campaign that exist: per group
    /// name, each source run once with its evaluations (generation 0 included).
    pub source_evaluations: BTreeMap<String, Vec<(RunSpec, u64)>>,
    /// The `[[from_module]]` groups' one-shot walks found, by (group name, terrain set).
    pub one_shot: BTreeMap<(String, ValidationSet), vsr::experiment::body_set::BodiesValidation>,
    /// The runs of the `[[from_module]]` groups' compared campaigns (`compare`) that exist:
    /// the group it is shown beside, the compared `[[finetune]]` group, the run and its data.
    pub compared: Vec<(String, FinetuneGroup, RunSpec, RunData)>,
    /// Planned output files not found.
    pub missing: Vec<PathBuf>,
    /// The fidelity measurements found, with their reference files, in campaign order.
    pub fidelity: Vec<(PathBuf, Fidelity)>,
}

/// Validations of one brain on body sets, per (body-set stem, terrain set).
pub type BodySetValidations =
    BTreeMap<(String, ValidationSet), vsr::experiment::body_set::BodiesValidation>;

/// One planned run of an `[[any_body]]` group.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct AnyBodySpec {
    /// The group's name.
    pub group: String,
    /// The controller (a family for any body).
    pub controller: vsr::controllers::ControllerKind,
    /// Evaluation budget.
    pub evals: u64,
    /// Run seed.
    pub seed: u64,
}

impl AnyBodySpec {
    /// Its run file under the campaign's output folder `out`.
    pub fn run_path(&self, out: &Path) -> PathBuf {
        out.join("runs").join(format!("{}.json", self.stem()))
    }

    /// The file stem of its outputs (`any_body::AnyBodyGroup::stem`).
    pub fn stem(&self) -> String {
        format!(
            "{}-{}-{}-s{}",
            self.group, self.controller, self.evals, self.seed
        )
    }
}

/// What exists of one any-body run: whether its run file is there (and the file), and its
/// validations per (body-set stem, terrain set).
#[derive(Debug, Clone, Default)]
pub struct AnyBodyData {
    /// The run file exists (the run is finished: a run in flight writes only its checkpoint).
    pub finished: bool,
    /// The run file, when it exists.
    pub run: Option<RunFile>,
    /// Its best on each body set, per (body-set stem, terrain set).
    pub validation: std::collections::BTreeMap<
        (String, ValidationSet),
        vsr::experiment::body_set::BodiesValidation,
    >,
}

impl Results {
    /// The data of `spec`, to fill in (`None` when the run is neither planned nor read at
    /// an earlier budget or a known seed).
    pub fn of_mut(&mut self, spec: &RunSpec) -> Option<&mut RunData> {
        self.data
            .iter_mut()
            .chain(self.earlier.iter_mut())
            .chain(self.known.iter_mut())
            .find(|(s, _)| s == spec)
            .map(|(_, d)| d)
    }

    /// Empty results for every run of `campaign`.
    pub fn new(campaign: Campaign) -> Self {
        let data = runs(&campaign)
            .into_iter()
            .map(|r| (r, RunData::default()))
            .collect();
        let earlier = earlier_runs(&campaign)
            .into_iter()
            .map(|r| (r, RunData::default()))
            .collect();
        let known = known_runs(&campaign)
            .into_iter()
            .map(|r| (r, RunData::default()))
            .collect();
        let mut codesign = Vec::new();
        for g in &campaign.codesign {
            for condition in &g.conditions {
                for &seed in g.seeds.as_deref().unwrap_or(&campaign.seeds) {
                    let spec = CodesignSpec {
                        group: g.name.clone(),
                        condition: condition.clone(),
                        evals: g.evals,
                        seed,
                    };
                    codesign.push((spec, CodesignData::default()));
                }
            }
        }
        let mut any_body = Vec::new();
        for g in &campaign.any_body {
            for &seed in g.seeds.as_deref().unwrap_or(&campaign.seeds) {
                for &controller in &g.controllers {
                    let spec = AnyBodySpec {
                        group: g.name.clone(),
                        controller,
                        evals: g.evals,
                        seed,
                    };
                    any_body.push((spec, AnyBodyData::default()));
                }
            }
        }
        let floor = super::any_body::floor_brains(&campaign.any_body, &campaign.seeds)
            .into_iter()
            .map(|b| (b, BTreeMap::new()))
            .collect();
        let from_module = campaign
            .from_module
            .iter()
            .flat_map(|g| g.specs(&campaign.seeds))
            .map(|s| (s, RunData::default()))
            .collect();
        Results {
            from_module,
            modules: BTreeMap::new(),
            chosen_from: BTreeMap::new(),
            source_evaluations: BTreeMap::new(),
            one_shot: BTreeMap::new(),
            compared: Vec::new(),
            campaign,
            data,
            earlier,
            known,
            codesign,
            floor,
            any_body,
            missing: Vec::new(),
            fidelity: Vec::new(),
        }
    }

    /// The data of `spec` (empty when the run is neither planned nor read at an earlier
    /// budget or a known seed).
    pub fn of(&self, spec: &RunSpec) -> RunData {
        let found = self
            .data
            .iter()
            .chain(&self.earlier)
            .chain(&self.known)
            .find(|(s, _)| s == spec);
        found.map(|(_, d)| d.clone()).unwrap_or_default()
    }

    /// The data of every seed of a run, in seed order, with the runs whose file exists.
    pub fn seeds_of(&self, template: &RunSpec, seeds: &[u64]) -> Vec<RunData> {
        seeds
            .iter()
            .map(|&seed| {
                let mut spec = template.clone();
                spec.seed = seed;
                if let Some(source) = spec.source.as_mut() {
                    source.seed = seed;
                }
                self.of(&spec)
            })
            .filter(|d| d.run.is_some())
            .collect()
    }
}
