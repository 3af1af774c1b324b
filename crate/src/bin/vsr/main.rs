//! `vsr`: the command-line face of VSR Playground, thin shells over the library. Bad
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
#[cfg(not(target_arch = "wasm32"))]
macro_rules! say {
    ($($arg:tt)*) => {{
        use std::io::Write as _;
        let _ = writeln!(std::io::stdout(), $($arg)*);
    }};
}

#[cfg(not(target_arch = "wasm32"))]
mod ablate;
#[cfg(not(target_arch = "wasm32"))]
mod args;
#[cfg(not(target_arch = "wasm32"))]
mod atomic;
#[cfg(not(target_arch = "wasm32"))]
mod bench;
#[cfg(not(target_arch = "wasm32"))]
mod bodies;
#[cfg(not(target_arch = "wasm32"))]
mod campaign;
#[cfg(not(target_arch = "wasm32"))]
mod checkpoint;
#[cfg(not(target_arch = "wasm32"))]
mod cli;
#[cfg(not(target_arch = "wasm32"))]
mod codesign;
#[cfg(not(target_arch = "wasm32"))]
mod evaluate;
#[cfg(not(target_arch = "wasm32"))]
mod evolution;
#[cfg(not(target_arch = "wasm32"))]
mod evolve;
#[cfg(not(target_arch = "wasm32"))]
mod fidelity;
#[cfg(not(target_arch = "wasm32"))]
mod finetune;
#[cfg(not(target_arch = "wasm32"))]
mod params;
#[cfg(not(target_arch = "wasm32"))]
mod progress;
#[cfg(not(target_arch = "wasm32"))]
mod runfile;
#[cfg(not(target_arch = "wasm32"))]
mod simulate;
#[cfg(not(target_arch = "wasm32"))]
mod terrain;
#[cfg(not(target_arch = "wasm32"))]
mod trajectory;
#[cfg(not(target_arch = "wasm32"))]
mod validate;

#[cfg(not(target_arch = "wasm32"))]
fn main() {
    std::process::exit(cli::run());
}

/// The CLI is native only; the wasm build of the package uses the library.
#[cfg(target_arch = "wasm32")]
fn main() {}
