//! The campaign file (TOML): a study as a grid of runs, written once and rerun by one
//! command. Parsing and checking only; the job list is `plan`'s.
//!
//! ```toml
//! output = "../study"            # where every output goes, relative to the campaign file
//! seeds = [1, 2, 3, 4, 5]        # default seeds of every group
//! seconds = 30.0                 # episode length (evolution, validation, ablation)
//! population = 100
//! terrain = "hilly-1-10"         # training terrain family
//! validate = ["paper", "unseen"] # validation sets assessed for every run
//!
//! [ablation]                     # settings of the frozen-attention ablation
//! last_second = 30
//! sets = ["paper", "unseen"]     # ablate on each set's first terrain (default: paper only)
//!
//! [[evolve]]                     # a grid: shapes x controllers x evals x seeds
//! name = "rq1"
//! shapes = ["biped-4x3", "comb-7x2"]
//! controllers = ["attention", "mlp", "mlp-comm"]
//! evals = [30000]
//! ablate = true                  # ablate each best with attention (attention, slow-attention)
//! earlier = [20000]              # report the same runs read at a shorter budget (its files)
//! # a planned non-inferiority test, reported beside the group (adds no job): treatment not
//! # worse than control by margin m/s on each set (the first primary); known_seeds: runs of
//! # the same grid that existed before the plan, shown beside it, never pooled
//! noninferiority = { margin = 0.5, treatment = "attention", control = "mlp", known_seeds = [9] }
//!
//! [[finetune]]                   # SPEC 10: source runs, fine-tuned, against from scratch
//! name = "rq2"
//! pairs = [["biped-4x3", "biped-6x4"], ["biped-6x4", "biped-4x3"]]   # [source, target]
//! controller = "attention"
//! source_evals = 20000
//! evals = 10000
//! scratch_evals = 30000          # from-scratch runs on each target shape, for comparison
//!
//! [[from_module]]                # a module file fine-tuned on shapes (`from_module`)
//! name = "ft-any-train32"
//! module = "../pretrained/any-train32-attention-any.json"
//! controller = "attention-any"
//! shapes = ["biped-4x3", "comb-7x2"]
//! evals = 2500
//!
//! [[fidelity]]                   # the simulator against the reference's gait ensembles
//! reference = "../tests/fixtures/gaits-comb-flat.json"   # relative to the campaign file
//! ```

pub use super::groups::{EvolveGroup, FidelityGroup, FinetuneGroup, NonInferiority};
use serde::Deserialize;
use vsr::controllers::ControllerKind;
use vsr::experiment::config::{check_seconds, PAPER_SECONDS, PAPER_TERRAIN};
use vsr::experiment::{TrainingTerrain, ValidationSet};
use vsr::genetics::{check_budget, GaConfig};
use vsr::simulation::Shape;
use vsr::{Error, Result};

/// A whole campaign file; see the module doc.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Campaign {
    /// Output folder, relative to the campaign file.
    pub output: String,
    /// Default seeds of every group.
    pub seeds: Vec<u64>,
    /// Episode seconds of every evaluation, validation and ablation episode.
    #[serde(default = "paper_seconds")]
    pub seconds: f64,
    /// GA population.
    #[serde(default = "paper_population")]
    pub population: usize,
    /// Training terrain family or name.
    #[serde(default = "paper_terrain")]
    pub terrain: String,
    /// Validation sets assessed for every run.
    #[serde(default = "both_sets")]
    pub validate: Vec<ValidationSet>,
    /// Ablation settings.
    #[serde(default)]
    pub ablation: AblationSettings,
    /// Grids of runs from scratch.
    #[serde(default)]
    pub evolve: Vec<EvolveGroup>,
    /// Fine-tuning studies.
    #[serde(default)]
    pub finetune: Vec<FinetuneGroup>,
    /// Gait ensembles measured on the reference simulator, measured here too.
    #[serde(default)]
    pub fidelity: Vec<FidelityGroup>,
    /// Brains for any body trained on many bodies (`vsr evolve --bodies`).
    #[serde(default)]
    pub any_body: Vec<super::any_body::AnyBodyGroup>,
    /// Body searches (`vsr codesign`).
    #[serde(default)]
    pub codesign: Vec<super::codesign::CodesignGroup>,
    /// Fine-tunings of a module file on target shapes (`vsr finetune --from MODULE`).
    #[serde(default)]
    pub from_module: Vec<super::from_module::FromModuleGroup>,
}

/// The frozen-attention ablation's settings.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct AblationSettings {
    /// Freeze at every whole second 0 ..= `last_second`.
    pub last_second: u32,
    /// The sets on whose first terrain each ablated run is ablated (`paper`: hilly-1-10-0,
    /// the paper's; `unseen`: hilly-1-10-10000, outside the training pool).
    #[serde(default = "paper_only")]
    pub sets: Vec<ValidationSet>,
}

fn paper_only() -> Vec<ValidationSet> {
    vec![ValidationSet::Paper]
}

impl Default for AblationSettings {
    fn default() -> Self {
        AblationSettings {
            last_second: 30,
            sets: paper_only(),
        }
    }
}

fn paper_seconds() -> f64 {
    PAPER_SECONDS
}

fn paper_population() -> usize {
    GaConfig::default().population
}

fn paper_terrain() -> String {
    PAPER_TERRAIN.to_string()
}

fn both_sets() -> Vec<ValidationSet> {
    ValidationSet::ALL.to_vec()
}

impl Campaign {
    /// Parses and checks a campaign file's text; errors say what is wrong and where.
    pub fn parse(text: &str) -> Result<Campaign> {
        let campaign: Campaign = toml::from_str(text)
            .map_err(|e| Error::Input(format!("the campaign file is not valid: {e}")))?;
        campaign.check()?;
        Ok(campaign)
    }

    /// The campaign with its input paths (the fidelity references) taken relative to `dir`,
    /// the campaign file's folder.
    pub fn relative_to(mut self, dir: &std::path::Path) -> Campaign {
        for g in &mut self.fidelity {
            let path = path_clean::clean(dir.join(&g.reference));
            g.reference = path.display().to_string();
        }
        for g in &mut self.any_body {
            g.relative_to(dir);
        }
        for g in &mut self.from_module {
            g.relative_to(dir);
        }
        for g in &mut self.codesign {
            if let Some(module) = &g.module {
                g.module = Some(path_clean::clean(dir.join(module)).display().to_string());
            }
        }
        self
    }

    fn check(&self) -> Result<()> {
        let bad = |m: String| Err(Error::Input(m));
        if self.seeds.is_empty() {
            return bad("the campaign's seeds are empty: give at least one".into());
        }
        check_seconds(self.seconds)?;
        TrainingTerrain::parse(&self.terrain)?;
        for g in &self.evolve {
            let shapes = g.shapes.iter().map(|s| Shape::parse(s).map(|_| ()));
            shapes.collect::<Result<Vec<()>>>()?;
            if g.shapes.is_empty() || g.controllers.is_empty() || g.evals.is_empty() {
                return bad(format!(
                    "group '{}' needs at least one shape, controller and budget",
                    g.name
                ));
            }
            let shortest = g.evals.iter().min().copied().unwrap_or(0);
            if let Some(e) = g.earlier.iter().find(|&&e| e == 0 || e >= shortest) {
                return bad(format!(
                    "group '{}': earlier budget {e} must be above 0 and below its budgets",
                    g.name
                ));
            }
            if let Some(n) = &g.noninferiority {
                self.check_noninferiority(g, n)?;
            }
        }
        for g in &self.finetune {
            for pair in &g.pairs {
                Shape::parse(&pair[0])?;
                Shape::parse(&pair[1])?;
            }
            if !matches!(
                g.controller,
                ControllerKind::Attention | ControllerKind::SlowAttention
            ) {
                return bad(format!(
                    "fine-tuning group '{}' transfers an attention block: its controller must \
                     be attention or slow-attention, not {}",
                    g.name, g.controller
                ));
            }
        }
        for g in &self.codesign {
            g.check()?;
        }
        for g in &self.any_body {
            g.check()?;
        }
        for g in &self.from_module {
            g.check()?;
        }
        for g in &self.fidelity {
            if !g.reference.ends_with(".json") {
                return bad(format!(
                    "fidelity reference '{}' must be a .json file of gait ensembles",
                    g.reference
                ));
            }
        }
        self.check_budgets()
    }

    /// Every run's budget covers one population, as `vsr evolve` will check, so that no job
    /// is planned to fail.
    fn check_budgets(&self) -> Result<()> {
        let evolve = self.evolve.iter().map(|g| (&g.name, g.evals.clone()));
        let finetune = self.finetune.iter().map(|g| {
            let budgets = [Some(g.source_evals), Some(g.evals), g.scratch_evals];
            (&g.name, budgets.into_iter().flatten().collect())
        });
        let from_module = self.from_module.iter().map(|g| (&g.name, vec![g.evals]));
        for (name, budgets) in evolve.chain(finetune).chain(from_module) {
            for budget in budgets {
                check_budget(budget, self.population)
                    .map_err(|e| e.about(format!("group '{name}'")))?;
            }
        }
        Ok(())
    }

    fn check_noninferiority(&self, g: &EvolveGroup, n: &NonInferiority) -> Result<()> {
        let bad = |m: String| {
            Err(Error::Input(format!(
                "group '{}' noninferiority: {m}",
                g.name
            )))
        };
        if !(n.margin.is_finite() && n.margin >= 0.0) {
            return bad(format!(
                "the margin {} must be a number >= 0 (m/s)",
                n.margin
            ));
        }
        for c in [n.treatment, n.control] {
            if !g.controllers.contains(&c) {
                return bad(format!("{c} is not one of the group's controllers"));
            }
        }
        if n.treatment == n.control {
            return bad("the treatment and the control must differ".into());
        }
        if n.sets.is_empty() {
            return bad("give at least one validation set".into());
        }
        if let Some(set) = n.sets.iter().find(|s| !self.validate.contains(s)) {
            return bad(format!("the campaign does not validate on the {set} set"));
        }
        let seeds = g.seeds.as_ref().unwrap_or(&self.seeds);
        if let Some(s) = n.known_seeds.iter().find(|s| seeds.contains(s)) {
            return bad(format!(
                "known seed {s} is one of the group's seeds: known seeds are never pooled"
            ));
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests;
