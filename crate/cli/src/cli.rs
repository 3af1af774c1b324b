//! Argument parsing (clap) and dispatch to the subcommands.

use clap::{CommandFactory, FromArgMatches, Parser, Subcommand};

/// VSR Playground: simulate and evolve voxel-based soft robots.
#[derive(Parser, Debug)]
#[command(name = "vsr", version = env!("VSR_VERSION"), about)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand, Debug)]
enum Command {
    /// Run one episode of a robot under an open-loop phase gait.
    Simulate(crate::simulate::Args),
    /// Print a terrain's polyline.
    Terrain(crate::terrain::Args),
    /// Measure simulation speed on the paper's shapes (single thread); --evolution adds
    /// whole evolution steps per controller.
    Bench(crate::bench::Args),
    /// Print a controller's parameter count for a shape.
    Params(crate::params::Args),
    /// Evolve a controller from scratch and write a run file.
    Evolve(crate::evolve::Args),
    /// Evaluate a run's best individual on one terrain (JSON with velocity).
    Evaluate(crate::evaluate::Args),
    /// Re-assess a run's best individual on 10 validation terrains (--set paper: hilly-1-10-0..9,
    /// unseen: hilly-1-10-10000..10009).
    Validate(crate::validate::Args),
    /// Fine-tune a run's best individual on another shape, its attention block frozen.
    Finetune(crate::finetune::Args),
    /// Search bodies around a brain (a pretrained attention module frozen or fine-tuned, or
    /// a brain from scratch): a gallery of bodies, the best of each size and number of feet.
    Codesign(crate::codesign::Args),
    /// Write the study's body sets (training and held out) from a seed.
    Bodies(crate::bodies::Args),
    /// Frozen-attention ablation: velocity with the attention frozen at each second.
    Ablate(crate::ablate::Args),
    /// Run the reference simulator's gait ensembles here and compare (--reference FILE).
    Fidelity(crate::fidelity::Args),
    /// A study as a campaign file: plan its jobs, run them, merge the results into a CSV.
    #[command(subcommand)]
    Campaign(crate::campaign::Command),
    /// Statistics (Mann-Whitney U) and SVG figures of a campaign's results so far.
    Report(crate::campaign::report::Args),
}

/// The command line, every option accepting a negative number as its value: `--evals -5` is
/// then refused by the value's own check ("invalid value '-5' for '--evals'", "episode seconds
/// must be in (0, 3600]"), not as an unknown argument `-5`.
fn command() -> clap::Command {
    fn negative_values(command: clap::Command) -> clap::Command {
        command
            .mut_args(|arg| arg.allow_negative_numbers(true))
            .mut_subcommands(negative_values)
    }
    negative_values(Cli::command())
}

/// A count that could not be read, in words: Rust's "invalid digit found in string" (for
/// `--evals -5` or `--evals ten`) says what a count is instead.
fn plain_parse_error(text: &str) -> String {
    text.replace(
        ": invalid digit found in string",
        ": not a whole number, 0 or more",
    )
    .replace(": number too large to fit in target type", ": too large")
}

fn parse() -> Result<Cli, clap::Error> {
    let mut command = command();
    let matches = command.try_get_matches_from_mut(std::env::args_os())?;
    Cli::from_arg_matches(&matches).map_err(|e| e.format(&mut command))
}

/// Parses arguments, runs the command and returns the process exit code.
pub fn run() -> i32 {
    let cli = match parse() {
        Ok(cli) => cli,
        Err(e) if e.use_stderr() => {
            eprint!("{}", plain_parse_error(&e.render().to_string()));
            return 2;
        }
        Err(e) => {
            let _ = e.print(); // --help, --version
            return 0;
        }
    };
    let result = match cli.command {
        Command::Simulate(args) => crate::simulate::run(args),
        Command::Terrain(args) => crate::terrain::run(args),
        Command::Bench(args) => crate::bench::run(args),
        Command::Params(args) => crate::params::run(args),
        Command::Evolve(args) => crate::evolve::run(args),
        Command::Evaluate(args) => crate::evaluate::run(args),
        Command::Validate(args) => crate::validate::run(args),
        Command::Finetune(args) => crate::finetune::run(args),
        Command::Codesign(args) => crate::codesign::run(args),
        Command::Bodies(args) => crate::bodies::run(args),
        Command::Ablate(args) => crate::ablate::run(args),
        Command::Fidelity(args) => crate::fidelity::run(args),
        Command::Campaign(command) => crate::campaign::run(command),
        Command::Report(args) => crate::campaign::report::run(args),
    };
    match result {
        Ok(()) => 0,
        Err(e) => {
            eprintln!("vsr: {e}");
            2
        }
    }
}
