//! The configuration of one evolutionary run: what is evolved (shape, controller), on what
//! (training terrains, episode length), how (GA settings, budget) and from which seed. It is
//! stored verbatim in the run file, so a run file alone is enough to replay its run.
//!
//! Nothing here depends on how the run is executed: the number of threads or workers is
//! deliberately absent, because it never changes the result.

use super::body_set::BodySet;
use super::seeds::{terrain_name_for, TERRAIN_SEEDS};
use crate::controllers::{ControllerKind, ATTENTION_PARAMS};
use crate::error::{Error, Result};
use crate::genetics::{check_budget, GaConfig};
use crate::simulation::{Shape, Terrain};
use serde::{Deserialize, Serialize};

/// The paper's training terrain family: a fresh `hilly-1-10-SEED` for every evaluation.
pub const PAPER_TERRAIN: &str = "hilly-1-10";
/// The paper's episode length (s).
pub const PAPER_SECONDS: f64 = 30.0;
/// Longest episode accepted (s).
pub const MAX_SECONDS: f64 = 3600.0;
/// Largest seed accepted: 2^53 - 1, the largest integer a JavaScript number holds exactly,
/// so the page reads the same seed as the command line.
pub const MAX_SEED: u64 = (1 << 53) - 1;

/// The one check of an episode's length: in (0, [`MAX_SECONDS`]] s.
pub fn check_seconds(seconds: f64) -> Result<()> {
    if seconds > 0.0 && seconds <= MAX_SECONDS {
        return Ok(());
    }
    Err(Error::Input(format!(
        "episode seconds must be in (0, {MAX_SECONDS}], got {seconds}"
    )))
}

/// Where the evaluations of a run take place. Serialized as a string: a family such as
/// `hilly-1-10` (each evaluation appends its own derived seed, `hilly-1-10-4821`), or one
/// fixed terrain name such as `flat` used for every evaluation.
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
#[serde(try_from = "String", into = "String")]
pub enum TrainingTerrain {
    /// `hilly-H-W` or `steppy-H-W`: the seed comes from the evaluation.
    Family(String),
    /// A complete terrain name, the same for every evaluation.
    Fixed(String),
}

impl TrainingTerrain {
    /// Parses a family (`hilly-1-10`, `steppy-1-10`) or a full terrain name (`flat`,
    /// `hilly-1-10-3`, `uphill-10`).
    pub fn parse(text: &str) -> Result<Self> {
        let text = text.trim();
        if Terrain::parse(text).is_ok() {
            return Ok(TrainingTerrain::Fixed(text.to_string()));
        }
        let is_walk = text.starts_with("hilly-") || text.starts_with("steppy-");
        if is_walk && Terrain::parse(&format!("{text}-0")).is_ok() {
            return Ok(TrainingTerrain::Family(text.to_string()));
        }
        Err(Error::Terrain(format!(
            "'{text}' is neither a terrain family (hilly-H-W, steppy-H-W: a fresh seed per \
             evaluation) nor a terrain name (flat, hilly-H-W-SEED, steppy-H-W-SEED, uphill-DEG, \
             downhill-DEG)"
        )))
    }

    /// The terrain of an evaluation whose derived terrain seed is `seed`; for the paper's
    /// family this is exactly [`terrain_name_for`].
    pub fn name_for(&self, seed: u64) -> String {
        match self {
            TrainingTerrain::Family(f) if f == PAPER_TERRAIN => terrain_name_for(seed),
            TrainingTerrain::Family(f) => format!("{f}-{}", seed % TERRAIN_SEEDS),
            TrainingTerrain::Fixed(name) => name.clone(),
        }
    }
}

impl TryFrom<String> for TrainingTerrain {
    type Error = Error;

    fn try_from(text: String) -> Result<Self> {
        TrainingTerrain::parse(&text)
    }
}

impl From<TrainingTerrain> for String {
    fn from(t: TrainingTerrain) -> String {
        match t {
            TrainingTerrain::Family(s) | TrainingTerrain::Fixed(s) => s,
        }
    }
}

/// The best individual of an earlier run whose attention block a fine-tuning run reuses
/// (SPEC 10). Its genome is kept whole, so the fine-tuning run replays from its own file.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SourceRun {
    /// The source run's shape.
    pub shape: Shape,
    /// The source run's controller.
    pub controller: ControllerKind,
    /// The source run's seed.
    pub seed: u64,
    /// The source run's evaluation budget.
    pub budget_evals: u64,
    /// The source best's fitness in its own run (m/s).
    #[serde(with = "super::json::finite_or_null")]
    pub fitness: f64,
    /// The source best's genome; its first 32 genes are frozen in the new run.
    #[serde(deserialize_with = "super::json::finite_genes")]
    pub genome: Vec<f32>,
}

/// Training on many bodies: every evaluation walks `per_evaluation` bodies drawn from `set`
/// (without repeats, by the evaluation's own seed: `evaluation_seed(run seed, generation,
/// index, Bodies)`), and its fitness is their mean speed. Only a body-independent controller
/// can (one genome for every body).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct TrainingBodies {
    /// The bodies (kept whole in the run file, so it replays alone).
    pub set: BodySet,
    /// Bodies walked by each evaluation.
    pub per_evaluation: usize,
}

/// Everything that determines a run's result; see the module doc.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct EvolutionConfig {
    /// The robot's morphology (serialized as rows, top first).
    pub shape: Shape,
    /// The controller family evolved.
    pub controller: ControllerKind,
    /// The run seed every random draw derives from (at most 2^53 - 1).
    pub seed: u64,
    /// Simulated seconds per evaluation episode.
    pub seconds: f64,
    /// Training terrain family or fixed terrain.
    pub terrain: TrainingTerrain,
    /// GA settings, including the evaluation budget `budget_evals`.
    pub ga: GaConfig,
    /// For fine-tuning runs: the individual whose attention block is frozen.
    pub source: Option<SourceRun>,
    /// For training on many bodies: the bodies (then `shape` is the set's first body).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub bodies: Option<TrainingBodies>,
}

impl EvolutionConfig {
    /// The paper's setup (SPEC 9): GA defaults, 30-s episodes on fresh `hilly-1-10` terrains.
    pub fn paper(shape: Shape, controller: ControllerKind, budget_evals: u64, seed: u64) -> Self {
        EvolutionConfig {
            shape,
            controller,
            seed,
            seconds: PAPER_SECONDS,
            terrain: TrainingTerrain::Family(PAPER_TERRAIN.to_string()),
            ga: GaConfig {
                budget_evals,
                ..GaConfig::default()
            },
            source: None,
            bodies: None,
        }
    }

    /// The paper's setup for one body-independent `controller` trained on many bodies: each
    /// evaluation walks `per_evaluation` bodies drawn from `set`.
    pub fn on_bodies(
        set: BodySet,
        per_evaluation: usize,
        controller: ControllerKind,
        budget_evals: u64,
        seed: u64,
    ) -> Result<Self> {
        let first = set
            .bodies
            .first()
            .cloned()
            .ok_or_else(|| Error::Input(format!("the body set {} has no bodies", set.name)))?;
        let mut config = EvolutionConfig::paper(first, controller, budget_evals, seed);
        config.bodies = Some(TrainingBodies {
            set,
            per_evaluation,
        });
        Ok(config)
    }

    /// SPEC 10's fine-tuning of `source` on `shape`: same controller, the 32 attention genes
    /// frozen, otherwise the paper's setup.
    pub fn finetune(source: SourceRun, shape: Shape, budget_evals: u64, seed: u64) -> Self {
        let mut config = EvolutionConfig::paper(shape, source.controller, budget_evals, seed);
        config.ga.frozen_prefix = ATTENTION_PARAMS;
        config.source = Some(source);
        config
    }

    /// Genome length of the evolved controller on the evolved shape.
    pub fn genome_len(&self) -> usize {
        self.controller.param_count(self.shape.voxel_count())
    }

    /// Checks every setting; messages say what is accepted.
    pub(crate) fn validate(&self) -> Result<()> {
        let bad = |m: String| Err(Error::Input(m));
        check_seconds(self.seconds)?;
        // The ground of the first evaluation: a bad terrain fails here, before generation 0.
        Terrain::parse(&self.terrain.name_for(0))?;
        if self.seed > MAX_SEED {
            return bad(format!(
                "seed {} is too large: at most 2^53 - 1 = {MAX_SEED}",
                self.seed
            ));
        }
        self.ga.validate(self.genome_len())?;
        check_budget(self.ga.budget_evals, self.ga.population)?;
        if let Some(bodies) = &self.bodies {
            self.validate_bodies(bodies)?;
        }
        match &self.source {
            Some(source) => self.validate_source(source),
            None if self.ga.frozen_prefix > 0 => bad(format!(
                "a frozen prefix of {} genes needs a source run to copy them from",
                self.ga.frozen_prefix
            )),
            None => Ok(()),
        }
    }

    /// Many bodies need a body-independent controller and 1 to (set size) bodies per
    /// evaluation; `shape` is the set's first body.
    fn validate_bodies(&self, bodies: &TrainingBodies) -> Result<()> {
        let (set, k) = (&bodies.set, bodies.per_evaluation);
        if !self.controller.is_body_independent() {
            let any: Vec<&str> = ControllerKind::ALL
                .iter()
                .filter(|c| c.is_body_independent())
                .map(|c| c.name())
                .collect();
            return Err(Error::Input(format!(
                "the {} controller has genes for each voxel of one body, so it cannot train on a body set; choose a controller for any body: {}",
                self.controller,
                any.join(", ")
            )));
        }
        if set.bodies.first() != Some(&self.shape) {
            return Err(Error::Input(format!(
                "a run on the body set {} names its first body as its shape",
                set.name
            )));
        }
        if k == 0 || k > set.bodies.len() {
            return Err(Error::Input(format!(
                "bodies per evaluation must be between 1 and the {} bodies of {}, got {k}",
                set.bodies.len(),
                set.name
            )));
        }
        Ok(())
    }

    /// Fine-tuning needs attention on both sides and exactly the attention block frozen.
    fn validate_source(&self, source: &SourceRun) -> Result<()> {
        let has_attention = ControllerKind::has_attention;
        if !has_attention(source.controller) || !has_attention(self.controller) {
            return Err(Error::Input(format!(
                "fine-tuning transfers an attention block: the source controller is {} and the \
                 new one {}, both must be attention, slow-attention or attention-any",
                source.controller, self.controller
            )));
        }
        if self.ga.frozen_prefix != ATTENTION_PARAMS {
            return Err(Error::Input(format!(
                "fine-tuning freezes the {ATTENTION_PARAMS} attention genes, the GA freezes {}",
                self.ga.frozen_prefix
            )));
        }
        source.controller.check_genome(
            "the source genome",
            source.shape.voxel_count(),
            &source.genome,
        )?;
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn terrain_families_and_fixed_names() {
        let family = TrainingTerrain::parse("hilly-1-10").unwrap();
        assert_eq!(family.name_for(123_456), "hilly-1-10-3456");
        let steppy = TrainingTerrain::parse("steppy-0.5-8").unwrap();
        assert_eq!(steppy.name_for(20_007), "steppy-0.5-8-7");
        let flat = TrainingTerrain::parse("flat").unwrap();
        assert_eq!(flat.name_for(99), "flat");
        assert!(matches!(
            TrainingTerrain::parse("hilly-1-10-3"),
            Ok(TrainingTerrain::Fixed(_))
        ));
        let err = TrainingTerrain::parse("hills").unwrap_err().to_string();
        assert!(err.contains("hilly-H-W") && err.contains("flat"), "{err}");
    }

    #[test]
    fn validation_names_the_bad_setting() {
        let shape = Shape::parse("biped-4x3").unwrap();
        let ok = EvolutionConfig::paper(shape, ControllerKind::Mlp, 30_000, 1);
        assert!(ok.validate().is_ok());
        let small = EvolutionConfig::paper(ok.shape.clone(), ControllerKind::Mlp, 99, 1);
        assert!(small.validate().unwrap_err().to_string().contains("99"));
        let mut big_seed = ok.clone();
        big_seed.seed = MAX_SEED + 1;
        assert!(big_seed.validate().is_err());
        let mut frozen = ok;
        frozen.ga.frozen_prefix = 32;
        assert!(frozen
            .validate()
            .unwrap_err()
            .to_string()
            .contains("source"));
    }
}
