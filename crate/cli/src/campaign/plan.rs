//! `vsr campaign plan FILE`: the job list, one complete `vsr` command per line, in
//! dependency order (for GNU parallel, Slurm or a shell).

use std::io::Write;

use vsr::{Error, Result};

use super::command;
use super::target::{Only, Target};

/// Arguments of `vsr campaign plan`.
#[derive(clap::Args, Debug)]
pub struct Args {
    #[command(flatten)]
    target: Target,
    /// Only the jobs of this stage: 1 runs that need no other run; a fine-tuning run or a run
    /// continuing a shorter one comes a stage after the run it needs, assessments a stage
    /// after their run (the paper's study: 1 to 3; past the last stage nothing is printed).
    #[arg(long)]
    stage: Option<u32>,
    /// Only the jobs whose output does not exist yet.
    #[arg(long)]
    pending: bool,
    #[command(flatten)]
    only: Only,
    /// --threads of each evolution job.
    #[arg(long, default_value_t = 1)]
    threads: usize,
    /// The program name printed at the start of each line.
    #[arg(long, default_value = "vsr")]
    program: String,
}

/// Runs the command.
pub fn run(args: Args) -> Result<()> {
    if args.threads == 0 {
        return Err(Error::Input("--threads must be at least 1".into()));
    }
    let (campaign, out) = args.target.load()?;
    let mut stdout = std::io::stdout().lock();
    for job in args.only.plan(&campaign, &out)? {
        let stage_ok = args.stage.map_or(true, |s| s == job.stage);
        if stage_ok && !(args.pending && job.out.exists()) {
            let line = command::line(&job, &args.program, args.threads);
            match writeln!(stdout, "{line}") {
                Ok(()) => {}
                // The reader stopped (`| head`): nothing more to say.
                Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => return Ok(()),
                Err(e) => return Err(Error::Io(format!("cannot print the plan: {e}"))),
            }
        }
    }
    Ok(())
}
