//! How `vsr evolve` and `vsr finetune` run: an evolution evaluated in parallel with rayon,
//! written to a run file at the end. While it runs it keeps a checkpoint next to the run file
//! (`checkpoint`), so a run that is stopped continues where it was when the same command is
//! given again. Its progress (`progress.rs`) is a bar on a terminal and one line per
//! generation elsewhere.

use std::path::Path;
use std::time::Instant;

use rayon::prelude::*;
use vsr::experiment::{
    Evolution, EvolutionConfig, GenerationRecord, Job, RunFile, Timing, TrainingTerrain,
};

use vsr::{Error, Result};

use crate::args::RunOptions;
use crate::checkpoint::Checkpointer;
use crate::progress::Progress;

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
        say!(
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
    let progress = Progress::new(evolution.planned_evaluations());
    progress.resume_at(evolution.evaluations());
    let evaluate = |jobs: &[Job]| -> Result<Vec<f64>> {
        let fitness = |job: &Job| {
            let f = job.fitness();
            progress.inc(1);
            f
        };
        pool.install(|| jobs.par_iter().map(fitness).collect())
    };
    let after_generation = |e: &Evolution| {
        if let Some(record) = e.history().last() {
            progress.generation_line(&summary(record));
        }
        checkpointer.after_generation(e);
        Ok(())
    };
    evolution.run(evaluate, after_generation, clock)?;
    progress.finish();
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
    say!(
        "{} {} on {}: best {:.3} m/s after {} evaluations ({}) in {:.1} s on {}; wrote {}",
        run.config.controller,
        run.config.shape.to_rows(),
        String::from(run.config.terrain.clone()),
        run.best.fitness,
        last.map_or(0, |g| g.evaluations),
        count(run.generations.len(), "generation"),
        timing.map_or(0.0, |t| t.wall_seconds),
        count(timing.map_or(0, |t| t.threads), "thread"),
        out.display()
    );
}

/// "1 generation", "6 generations".
fn count(n: usize, noun: &str) -> String {
    format!("{n} {noun}{}", if n == 1 { "" } else { "s" })
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

fn summary(r: &GenerationRecord) -> String {
    format!(
        "gen {}: best {:.3} median {:.3} m/s",
        r.generation, r.best, r.median
    )
}
