//! `vsr`: the command-line face of VSR Playground, thin shells over the engine (`vsr`,
//! crate/engine) and the study (`vsr-study`, crate/study); native only. Bad
//! arguments exit with code 2 and a message on stderr.
//!
//! Layout: `cli.rs` parses and dispatches; one file per subcommand (`simulate`, `terrain`,
//! `bench` with `bench/evolution.rs`, `params`, `evolve`, `evaluate`, `validate`, `finetune`,
//! `ablate`, `fidelity`, `bodies`); the campaign subcommands and `vsr report` in `campaign/`; what several share in
//! one place each: `args.rs` (argument types), `evolution.rs` (running an evolution),
//! `progress.rs` (a bar on a terminal, one line per generation elsewhere),
//! `checkpoint.rs`, `trajectory.rs`, `runfile.rs` and `atomic.rs` (files). Subcommands never
//! import each other.

/// Prints a line on stdout as `println!` does, except that a stdout closed early (`vsr evolve
/// ... | head -1`) is not an error: the command goes on and finishes its work (its files), and
/// only the lines nobody reads any more are dropped (`println!` panics there, losing the run).
macro_rules! say {
    ($($arg:tt)*) => {{
        use std::io::Write as _;
        let _ = writeln!(std::io::stdout(), $($arg)*);
    }};
}

mod ablate;
mod args;
mod atomic;
mod bench;
mod bodies;
mod campaign;
mod checkpoint;
mod cli;
mod codesign;
mod evaluate;
mod evolution;
mod evolve;
mod fidelity;
mod finetune;
mod params;
mod progress;
mod runfile;
mod simulate;
mod terrain;
mod trajectory;
mod validate;

fn main() {
    std::process::exit(cli::run());
}
