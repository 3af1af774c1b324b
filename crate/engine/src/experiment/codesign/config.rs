//! What determines a body search's result: the brain (a module frozen or fine-tuned, or one
//! from scratch), the start body, the grid and the voxel bounds, the archive's bins, the
//! variation, the budget, the terrain, the episode and the seed. Stored verbatim in the
//! co-design run file; thread and worker counts are deliberately absent.

use super::body::BodyGrid;
use crate::controllers::{ControllerKind, GenomeLayout, ATTENTION_PARAMS};
use crate::error::{Error, Result};
use crate::experiment::config::{check_seconds, SourceRun, TrainingTerrain, MAX_SEED};
use crate::simulation::Shape;
use serde::{Deserialize, Serialize};
use std::fmt;
use std::str::FromStr;

/// The page's drawing grid, the default search grid.
pub const DEFAULT_GRID: (usize, usize) = (20, 10);
/// Default voxel-count bounds of a searched body.
pub const DEFAULT_VOXELS: (usize, usize) = (4, 20);
/// Default start body when no module gives one: a 3 x 3 box (measured: from the module's own
/// biped a plain search never left the biped; from a box it found bodies that walk).
pub const DEFAULT_START: &str = "box-3x3";

/// How the brain is obtained.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum BrainMode {
    /// A pretrained module held fixed. An attention module: its 32-gene block is held and the
    /// body, the per-voxel genes and the bias evolve. A brain for any body (`attention-any`,
    /// `mlp-any`, `mlp-comm-any`): its whole genome is held, so only the body evolves (every
    /// child is a body edit; Strgar & Kriegman's setting).
    Frozen,
    /// The pretrained module as the start. An attention module: every gene evolves. A brain
    /// for any body: the genes every voxel shares evolve, its attention block (if it has one)
    /// held fixed, as `vsr finetune` holds it.
    Finetune,
    /// Every gene drawn at random, of any controller family.
    Scratch,
}

impl BrainMode {
    /// The name used on the command line and in files.
    pub fn name(self) -> &'static str {
        match self {
            BrainMode::Frozen => "frozen",
            BrainMode::Finetune => "finetune",
            BrainMode::Scratch => "scratch",
        }
    }
}

impl fmt::Display for BrainMode {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for BrainMode {
    type Err = Error;

    fn from_str(s: &str) -> Result<Self> {
        match s.trim() {
            "frozen" => Ok(BrainMode::Frozen),
            "finetune" => Ok(BrainMode::Finetune),
            "scratch" => Ok(BrainMode::Scratch),
            other => Err(Error::Input(format!(
                "unknown brain '{other}': expected frozen (a pretrained module held fixed), \
                 finetune (a module as the start) or scratch (from random genes)"
            ))),
        }
    }
}

/// Everything that determines a body search's result; see the module doc.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct CodesignConfig {
    /// How the brain is obtained.
    pub brain: BrainMode,
    /// The controller family (the module's for `frozen` and `finetune`).
    pub controller: ControllerKind,
    /// The pretrained module (`frozen`, `finetune`), whole so a run file replays alone.
    pub module: Option<SourceRun>,
    /// The body the search starts from.
    pub start: Shape,
    /// Search grid width in cells.
    pub grid_width: usize,
    /// Search grid height in cells.
    pub grid_height: usize,
    /// Fewest voxels of a searched body.
    pub min_voxels: usize,
    /// Most voxels of a searched body.
    pub max_voxels: usize,
    /// Voxel counts per archive column (2: 4-5, 6-7, ...).
    pub size_bin: usize,
    /// Feet counted up to this many ("4 or more" in one row).
    pub max_feet: usize,
    /// New bodies (children) per iteration; every elite is also re-measured each iteration.
    pub batch: usize,
    /// Probability that a child is a body edit (else a gene mutation).
    pub p_body: f64,
    /// Standard deviation of the Gaussian gene mutation.
    pub sigma: f32,
    /// Range of the uniform draw of genes that start random.
    pub init_low: f32,
    /// Upper end of that range.
    pub init_high: f32,
    /// Evaluation budget, checked before each iteration.
    pub budget_evals: u64,
    /// The run seed every draw derives from (at most 2^53 - 1).
    pub seed: u64,
    /// Simulated seconds per evaluation.
    pub seconds: f64,
    /// Training terrain family (a fresh terrain per evaluation) or a fixed terrain.
    pub terrain: TrainingTerrain,
}

impl CodesignConfig {
    /// A search with the defaults: the paper's terrain and episode, the page's grid, bodies
    /// of 4 to 20 voxels, 40 children per iteration, half of them body edits.
    pub fn new(
        brain: BrainMode,
        controller: ControllerKind,
        module: Option<SourceRun>,
        start: Shape,
        budget_evals: u64,
        seed: u64,
    ) -> CodesignConfig {
        CodesignConfig {
            brain,
            controller,
            module,
            start,
            grid_width: DEFAULT_GRID.0,
            grid_height: DEFAULT_GRID.1,
            min_voxels: DEFAULT_VOXELS.0,
            max_voxels: DEFAULT_VOXELS.1,
            size_bin: 2,
            max_feet: 4,
            batch: 40,
            p_body: 0.5,
            sigma: 0.35,
            init_low: -1.0,
            init_high: 1.0,
            budget_evals,
            seed,
            seconds: 30.0,
            terrain: TrainingTerrain::parse("hilly-1-10").expect("the paper's terrain family"),
        }
    }

    /// A search with the defaults, where what is not given follows the module: a `frozen` or
    /// `finetune` brain is the module's family (else `controller`), and the start body is
    /// `start` (a preset or rows) when given, else the module's own body for those brains,
    /// else [`DEFAULT_START`]. The one rule `vsr codesign`, the page and Python follow.
    pub fn with_module(
        brain: BrainMode,
        module: Option<SourceRun>,
        controller: ControllerKind,
        start: Option<&str>,
        budget_evals: u64,
        seed: u64,
    ) -> Result<CodesignConfig> {
        let follows_module = brain != BrainMode::Scratch;
        let controller = match &module {
            Some(m) if follows_module => m.controller,
            _ => controller,
        };
        let start = match (start, &module) {
            (Some(rows), _) => Shape::parse(rows)?,
            (None, Some(m)) if follows_module => m.shape.clone(),
            _ => Shape::parse(DEFAULT_START)?,
        };
        Ok(CodesignConfig::new(
            brain,
            controller,
            module,
            start,
            budget_evals,
            seed,
        ))
    }

    /// Genes `[0, frozen)` of the shared genes never change: the module's attention block
    /// (an attention module frozen; a brain for any body with attention, fine-tuned), or all
    /// of them (a brain for any body frozen: only the body evolves).
    pub fn frozen_shared(&self) -> usize {
        let any_body = self.controller.is_body_independent();
        match self.brain {
            BrainMode::Frozen if any_body => GenomeLayout::of(self.controller).shared_len(),
            BrainMode::Frozen => ATTENTION_PARAMS,
            BrainMode::Finetune if any_body && self.controller.has_attention() => ATTENTION_PARAMS,
            _ => 0,
        }
    }

    /// True when no gene evolves, only the body: a brain for any body, frozen whole.
    pub fn bodies_only(&self) -> bool {
        let layout = GenomeLayout::of(self.controller);
        layout.voxel_len() == 0 && self.frozen_shared() >= layout.shared_len()
    }

    /// Number of archive columns (voxel-count bins).
    pub fn size_bins(&self) -> usize {
        (self.max_voxels - self.min_voxels) / self.size_bin + 1
    }

    /// Checks everything, each message naming the fix.
    pub fn validate(&self) -> Result<()> {
        let bad = |m: String| Err(Error::Input(m));
        match (self.brain, &self.module) {
            (BrainMode::Scratch, Some(_)) => {
                return bad(
                    "a brain from scratch takes no module: leave out --from, or use \
                            --brain frozen or finetune"
                        .into(),
                )
            }
            (BrainMode::Frozen | BrainMode::Finetune, None) => {
                return bad(format!(
                    "--brain {} needs a pretrained attention module: give one with --from \
                     RUN.json (e.g. pretrained/biped-4x3-attention.json)",
                    self.brain
                ))
            }
            (BrainMode::Frozen | BrainMode::Finetune, Some(module)) => {
                let kind = module.controller;
                if kind != ControllerKind::Attention && !kind.is_body_independent() {
                    let any: Vec<&str> = ControllerKind::ALL
                        .iter()
                        .filter(|k| k.is_body_independent())
                        .map(|k| k.name())
                        .collect();
                    return bad(format!(
                        "this module is {kind}, not attention: only an attention module can be \
                         reassembled into other bodies{}; a brain for any body ({}) drives \
                         every body whole",
                        match kind {
                            ControllerKind::MlpComm | ControllerKind::MlpCommLatched =>
                                " (an MLP-Comm module needs its neighbours' messages, and its \
                                 genes belong to the voxels of its own body)",
                            _ => " (its genes belong to the voxels of its own body)",
                        },
                        any.join(", ")
                    ));
                }
                kind.check_genome(
                    "the module's genome",
                    module.shape.voxel_count(),
                    &module.genome,
                )?;
                if self.controller != kind {
                    return bad(format!(
                        "--brain {} evolves the module's {kind} controller, not {}",
                        self.brain, self.controller
                    ));
                }
            }
            (BrainMode::Scratch, None) => {}
        }
        let (w, h) = (self.grid_width, self.grid_height);
        if w == 0 || h == 0 || w > 100 || h > 100 {
            return bad(format!(
                "the grid must be 1 to 100 cells each way, got {w} x {h}"
            ));
        }
        if self.min_voxels == 0 || self.min_voxels > self.max_voxels {
            return bad(format!(
                "voxel bounds must satisfy 1 <= min <= max, got {} to {}",
                self.min_voxels, self.max_voxels
            ));
        }
        if self.max_voxels > w * h {
            return bad(format!(
                "the {w} x {h} grid has {} cells, fewer than the {} voxels allowed: use a larger \
                 grid or a smaller maximum",
                w * h,
                self.max_voxels
            ));
        }
        let n = self.start.voxel_count();
        if n < self.min_voxels || n > self.max_voxels {
            return bad(format!(
                "the start body has {n} voxels, outside the bounds {} to {}: change the bounds \
                 or the start body",
                self.min_voxels, self.max_voxels
            ));
        }
        BodyGrid::place(&self.start, w, h)?;
        if self.size_bin == 0 || self.max_feet == 0 || self.batch == 0 {
            return bad("size bin, feet and batch must each be at least 1".into());
        }
        if !(0.0..=1.0).contains(&self.p_body) {
            return bad(format!("p_body must be in [0, 1], got {}", self.p_body));
        }
        if !self.sigma.is_finite() || self.sigma < 0.0 {
            return bad(format!("sigma must be finite and >= 0, got {}", self.sigma));
        }
        crate::genetics::check_init_range(self.init_low, self.init_high)?;
        if self.seed > MAX_SEED {
            return bad(format!(
                "the seed must be at most {MAX_SEED}, got {}",
                self.seed
            ));
        }
        if self.budget_evals == 0 {
            return bad("the budget must be at least 1 evaluation".into());
        }
        check_seconds(self.seconds)
    }
}
