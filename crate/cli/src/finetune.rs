//! `vsr finetune --from RUN.json --shape S`: SPEC 10's fine-tuning. The best individual of
//! RUN.json (or, of a body search's file, its best body or `--entry I`) lends its 32
//! attention genes, frozen; only the downstream genes evolve on S.

use std::path::PathBuf;

use vsr::experiment::EvolutionConfig;
use vsr::simulation::Shape;

use crate::args::RunOptions;
use crate::evolution::execute;

/// Arguments of `vsr finetune`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// The run file whose best individual's attention block is transferred.
    #[arg(long)]
    from: PathBuf,
    /// A co-design run file's archive entry (0 first, in the file's order) whose attention
    /// block is transferred, instead of its best body's.
    #[arg(long)]
    entry: Option<usize>,
    /// The new shape: a preset or rows top first.
    #[arg(long)]
    shape: String,
    #[command(flatten)]
    options: RunOptions,
}

/// Runs the command.
pub fn run(args: Args) -> vsr::Result<()> {
    let source = crate::runfile::load_source(&args.from, args.entry)?;
    let shape = Shape::parse(&args.shape)?;
    let o = &args.options;
    let config = EvolutionConfig::finetune(source, shape, o.evals, o.seed);
    execute(config, o)
}
