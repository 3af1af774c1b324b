//! Argument parsing (clap) and dispatch to the subcommands.

use clap::{Parser, Subcommand};

/// VSR Playground: simulate and evolve voxel-based soft robots.
#[derive(Parser, Debug)]
#[command(name = "vsr", version, about)]
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
    /// Measure simulation speed on the paper's shapes (single thread).
    Bench(crate::bench::Args),
}

/// Parses arguments, runs the command and returns the process exit code.
pub fn run() -> i32 {
    let cli = match Cli::try_parse() {
        Ok(cli) => cli,
        Err(e) => {
            let code = if e.use_stderr() { 2 } else { 0 };
            let _ = e.print();
            return code;
        }
    };
    let result = match cli.command {
        Command::Simulate(args) => crate::simulate::run(args),
        Command::Terrain(args) => crate::terrain::run(args),
        Command::Bench(args) => crate::bench::run(args),
    };
    match result {
        Ok(()) => 0,
        Err(e) => {
            eprintln!("vsr: {e}");
            2
        }
    }
}
