//! Argument types that several subcommands share: a robot (`--shape`, `--controller`) and the
//! options of an evolutionary run (`vsr evolve`, `vsr finetune`).

use std::path::PathBuf;

use vsr::controllers::ControllerKind;
use vsr::simulation::Shape;

/// A robot to control: its shape and its controller kind.
#[derive(clap::Args, Debug)]
pub struct RobotArgs {
    /// Shape: a preset (biped-4x3, comb-7x2, biped-6x4, comb-14x2, worm-WxH, box-WxH) or rows
    /// top first, e.g. 1111-1111-1001.
    #[arg(long)]
    shape: Option<String>,
    /// Controller: attention, mlp, mlp-comm, slow-attention or mlp-comm-latched (MLP-Comm
    /// exchanging messages only every 20 steps, as the original code); for any body (one
    /// genome for every body, see --bodies): attention-any, mlp-any, mlp-comm-any.
    #[arg(long)]
    controller: String,
}

impl RobotArgs {
    /// The parsed shape and controller kind, or the error that says which is wrong.
    pub fn parse(&self) -> vsr::Result<(Shape, ControllerKind)> {
        let Some(shape) = &self.shape else {
            return Err(vsr::Error::Input(
                "--shape is needed: a preset such as biped-4x3, or rows such as 1111-1111-1001"
                    .into(),
            ));
        };
        Ok((Shape::parse(shape)?, self.controller.parse()?))
    }

    /// The controller kind alone, and whether a shape was given.
    pub fn kind(&self) -> vsr::Result<(ControllerKind, bool)> {
        Ok((self.controller.parse()?, self.shape.is_some()))
    }
}

/// Options shared by `vsr evolve` and `vsr finetune`.
#[derive(clap::Args, Debug)]
pub struct RunOptions {
    /// Evaluation budget (30000 in the paper: 150 generations, 30100 evaluations).
    #[arg(long)]
    pub evals: u64,
    /// Run seed: every terrain, noise stream and GA draw derives from it (at most 2^53 - 1).
    #[arg(long)]
    pub seed: u64,
    /// Worker threads (default: all cores). Never changes the result.
    #[arg(long)]
    pub threads: Option<usize>,
    /// Simulated seconds per evaluation.
    #[arg(long, default_value_t = 30.0)]
    pub seconds: f64,
    /// Training terrain: a family (hilly-1-10: a fresh seed per evaluation) or a fixed name
    /// (flat, hilly-1-10-3, ...).
    #[arg(long, default_value = "hilly-1-10")]
    pub terrain: String,
    /// Population size mu = lambda.
    #[arg(long, default_value_t = 100)]
    pub population: usize,
    /// Where to write the run file (written once, at the end, atomically).
    #[arg(long)]
    pub out: PathBuf,
    /// Seconds between checkpoints (OUT.checkpoint, deleted at the end; the same command
    /// continues a stopped run from it, bit for bit). 0: never write one.
    #[arg(long, default_value_t = 60.0)]
    pub checkpoint_every: f64,
    /// Keep OUT.checkpoint at the end, holding the final state, so that a run with a larger
    /// budget can --continue this one.
    #[arg(long)]
    pub keep_checkpoint: bool,
    /// Start from the final checkpoint of the same run with a smaller budget (kept with
    /// --keep-checkpoint): the result is the run from generation 0, bit for bit. A missing
    /// file is a note and the run starts from generation 0.
    #[arg(long, value_name = "CHECKPOINT")]
    pub r#continue: Option<PathBuf>,
}
