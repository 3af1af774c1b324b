//! `vsr evolve`: an evolutionary run from scratch, evaluated in parallel with rayon, written to
//! a run file at the end. Also the runner shared with `vsr finetune`. While it runs it keeps a
//! checkpoint next to the run file (`checkpoint`), so a run that is stopped continues where it
//! was when the same command is given again.

use std::path::{Path, PathBuf};
use std::time::Instant;

use indicatif::{ProgressBar, ProgressStyle};
use rayon::prelude::*;
use vsr::experiment::{
    Evolution, EvolutionConfig, GenerationRecord, Job, RunFile, Timing, TrainingTerrain,
};

use crate::checkpoint::Checkpointer;
use vsr::{Error, Result};

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
    threads: Option<usize>,
    /// Simulated seconds per evaluation.
    #[arg(long, default_value_t = 30.0)]
    seconds: f64,
    /// Training terrain: a family (hilly-1-10: a fresh seed per evaluation) or a fixed name
    /// (flat, hilly-1-10-3, ...).
    #[arg(long, default_value = "hilly-1-10")]
    terrain: String,
    /// Population size mu = lambda.
    #[arg(long, default_value_t = 100)]
    population: usize,
    /// Where to write the run file (written once, at the end, atomically).
    #[arg(long)]
    out: PathBuf,
    /// Seconds between checkpoints (OUT.checkpoint, deleted at the end; the same command
    /// continues a stopped run from it, bit for bit). 0: never write one.
    #[arg(long, default_value_t = 60.0)]
    checkpoint_every: f64,
    /// Keep OUT.checkpoint at the end, holding the final state, so that a run with a larger
    /// budget can --continue this one.
    #[arg(long)]
    keep_checkpoint: bool,
    /// Start from the final checkpoint of the same run with a smaller budget (kept with
    /// --keep-checkpoint): the result is the run from generation 0, bit for bit. A missing
    /// file is a note and the run starts from generation 0.
    #[arg(long, value_name = "CHECKPOINT")]
    r#continue: Option<PathBuf>,
}

/// Arguments of `vsr evolve`.
#[derive(clap::Args, Debug)]
pub struct Args {
    #[command(flatten)]
    robot: crate::params::RobotArgs,
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

/// Applies the shared options to `config`, runs it and writes the run file.
pub fn execute(mut config: EvolutionConfig, options: &RunOptions) -> Result<()> {
    config.seconds = options.seconds;
    config.terrain = TrainingTerrain::parse(&options.terrain)?;
    config.ga.population = options.population;
    crate::runfile::check_writable(&options.out)?;
    let mut checkpointer = Checkpointer::new(&options.out, options.checkpoint_every)?;
    let mut evolution = checkpointer.start(config, options.r#continue.as_deref())?;
    if evolution.is_done() && options.out.exists() {
        // A kept final checkpoint next to its run file: the run is complete.
        println!(
            "{} is complete (its checkpoint is at the end of the budget): nothing to do; \
             delete {}.checkpoint to run it again",
            options.out.display(),
            options.out.display()
        );
        return Ok(());
    }
    let pool = thread_pool(options.threads)?;
    let threads = pool.current_num_threads();
    let start = Instant::now();
    let earlier = evolution.history().last().map_or(0.0, |g| g.wall_seconds);
    let clock = || earlier + start.elapsed().as_secs_f64();
    let bar = progress_bar(evolution.planned_evaluations());
    bar.set_position(evolution.evaluations());
    let evaluate = |jobs: &[Job]| -> Vec<f64> {
        let fitness = |job: &Job| {
            let f = job.fitness();
            bar.inc(1);
            f
        };
        pool.install(|| jobs.par_iter().map(fitness).collect())
    };
    let after_generation = |e: &Evolution| {
        if let Some(record) = e.history().last() {
            bar.set_message(summary(record));
        }
        checkpointer.after_generation(e);
        Ok(())
    };
    evolution.run(evaluate, after_generation, clock)?;
    bar.finish_and_clear();
    let run = evolution.run_file(Some(Timing {
        threads,
        wall_seconds: clock(),
    }))?;
    crate::runfile::save(&options.out, &run)?;
    checkpointer.finish(&evolution, options.keep_checkpoint)?;
    print_summary(&run, &options.out);
    Ok(())
}

/// One line on stdout about a finished run.
fn print_summary(run: &RunFile, out: &Path) {
    let (last, timing) = (run.generations.last(), run.timing);
    println!(
        "{} {} on {}: best {:.3} m/s after {} evaluations ({} generations) in {:.1} s on {} \
         threads; wrote {}",
        run.config.controller,
        run.config.shape.to_rows(),
        String::from(run.config.terrain.clone()),
        run.best.fitness,
        last.map_or(0, |g| g.evaluations),
        run.generations.len(),
        timing.map_or(0.0, |t| t.wall_seconds),
        timing.map_or(0, |t| t.threads),
        out.display()
    );
}

/// A local rayon pool of `threads` threads (all cores when `None`).
pub fn thread_pool(threads: Option<usize>) -> Result<rayon::ThreadPool> {
    if threads == Some(0) {
        return Err(Error::Input("--threads must be at least 1".into()));
    }
    rayon::ThreadPoolBuilder::new()
        .num_threads(threads.unwrap_or(0))
        .build()
        .map_err(|e| Error::Input(format!("cannot start {threads:?} threads: {e}")))
}

fn progress_bar(total: u64) -> ProgressBar {
    let bar = ProgressBar::new(total);
    let template = "{elapsed_precise} [{bar:30}] {pos}/{len} evals, eta {eta}  {msg}";
    if let Ok(style) = ProgressStyle::with_template(template) {
        bar.set_style(style.progress_chars("=> "));
    }
    bar
}

fn summary(r: &GenerationRecord) -> String {
    format!(
        "gen {}: best {:.2} median {:.2} m/s",
        r.generation, r.best, r.median
    )
}
