//! `vsr evolve`: an evolutionary run from scratch (see `evolution.rs` for how it runs, in
//! parallel, checkpointed, to a run file), on one body (`--shape`) or, for a brain for any
//! body, on many (`--bodies FILE`: each evaluation walks `--bodies-per-evaluation` of them).

use std::path::PathBuf;

use vsr::experiment::{BodySet, EvolutionConfig};
use vsr::{Error, Result};

use crate::args::{RobotArgs, RunOptions};
use crate::evolution::execute;

/// Arguments of `vsr evolve`.
#[derive(clap::Args, Debug)]
pub struct Args {
    #[command(flatten)]
    robot: RobotArgs,
    /// Train on many bodies instead of one --shape: a body-set file (one body per line in the
    /// row notation, # for comments; campaigns/bodies/ holds the study's). Needs a controller
    /// for any body (attention-any, mlp-any, mlp-comm-any).
    #[arg(long, value_name = "FILE")]
    bodies: Option<PathBuf>,
    /// With --bodies: how many bodies each evaluation walks (drawn afresh for every
    /// evaluation); its fitness is their mean speed.
    #[arg(long, default_value_t = 4)]
    bodies_per_evaluation: usize,
    #[command(flatten)]
    options: RunOptions,
}

/// Runs the command.
pub fn run(args: Args) -> Result<()> {
    let o = &args.options;
    let config = match &args.bodies {
        None => {
            let (shape, kind) = args.robot.parse()?;
            EvolutionConfig::paper(shape, kind, o.evals, o.seed)
        }
        Some(path) => {
            let (kind, has_shape) = args.robot.kind()?;
            if has_shape {
                return Err(Error::Input(
                    "give --shape (one body) or --bodies (many), not both".into(),
                ));
            }
            let set = BodySet::read(path)?;
            EvolutionConfig::on_bodies(set, args.bodies_per_evaluation, kind, o.evals, o.seed)?
        }
    };
    execute(config, &args.options)
}
