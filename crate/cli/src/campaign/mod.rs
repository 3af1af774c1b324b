//! `vsr campaign plan|run|status|merge|export FILE` and `vsr report FILE`: a campaign file's
//! job list, run on local cores, how far it has come, its run files collected into one CSV,
//! its best modules exported to the pretrained folder, and its report. Outputs go under the campaign's `output` folder,
//! resolved relative to the campaign file, or under `--out-dir` (`target.rs`). One file per
//! subcommand; `command.rs` turns a planned job into a `vsr` command line.

pub mod command;
mod export;
mod merge;
mod plan;
pub mod report;
mod run;
mod status;
mod svg;
mod target;

use vsr::Result;

/// `vsr campaign` subcommands.
#[derive(clap::Subcommand, Debug)]
pub enum Command {
    /// Print the job list: one complete vsr command per line, in dependency order.
    Plan(plan::Args),
    /// Run the jobs on local cores, skipping those whose output exists (resumable).
    Run(run::Args),
    /// How far the campaign has come: runs finished, in flight and not started, and the
    /// core-hours left (reads its output folder, runs nothing).
    Status(status::Args),
    /// Collect the run files and validations into one CSV (OUT/campaign.csv by default).
    Merge(merge::Args),
    /// Copy the best module of each shape, controller and source into the pretrained folder.
    Export(export::Args),
}

/// Runs a `vsr campaign` subcommand.
pub fn run(command: Command) -> Result<()> {
    match command {
        Command::Plan(args) => plan::run(args),
        Command::Run(args) => run::run(args),
        Command::Status(args) => status::run(args),
        Command::Merge(args) => merge::run(args),
        Command::Export(args) => export::run(args),
    }
}
