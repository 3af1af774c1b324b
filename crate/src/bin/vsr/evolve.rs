//! `vsr evolve`: an evolutionary run from scratch (see `evolution.rs` for how it runs, in
//! parallel, checkpointed, to a run file).

use vsr::experiment::EvolutionConfig;
use vsr::Result;

use crate::args::{RobotArgs, RunOptions};
use crate::evolution::execute;

/// Arguments of `vsr evolve`.
#[derive(clap::Args, Debug)]
pub struct Args {
    #[command(flatten)]
    robot: RobotArgs,
    #[command(flatten)]
    options: RunOptions,
}

/// Runs the command.
pub fn run(args: Args) -> Result<()> {
    let (shape, kind) = args.robot.parse()?;
    let o = &args.options;
    let config = EvolutionConfig::paper(shape, kind, o.evals, o.seed);
    execute(config, &args.options)
}
