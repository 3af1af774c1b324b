//! `vsr codesign`: a body search around a brain (`vsr::experiment::codesign`), evaluated in
//! parallel with rayon, checkpointed every iteration (at most every `--checkpoint-every`
//! seconds) to `OUT.checkpoint`, which the same command continues from, bit for bit.

use std::path::{Path, PathBuf};
use std::time::Instant;

use rayon::prelude::*;
use vsr::controllers::ControllerKind;
use vsr::experiment::codesign::{DEFAULT_GRID, DEFAULT_VOXELS};
use vsr::experiment::{
    BrainMode, Codesign, CodesignConfig, CodesignRun, Job, Timing, TrainingTerrain,
};
use vsr::{Error, Result};

use crate::evolution::thread_pool;

/// Arguments of `vsr codesign`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// The brain: frozen (a pretrained module held fixed: an attention module's block, the
    /// bodies and per-voxel genes evolving; a brain for any body whole, only the bodies
    /// evolving), finetune (the module as the start: every gene evolves; a brain for any body
    /// keeps its attention block and evolves the genes its voxels share) or scratch.
    #[arg(long)]
    brain: BrainMode,
    /// The pretrained module's run file (frozen, finetune): attention, or a brain for any body
    /// (attention-any, mlp-any, mlp-comm-any).
    #[arg(long, value_name = "RUN.json")]
    from: Option<PathBuf>,
    /// With --from a co-design run file: its archive entry (0 first, in the file's order) is
    /// the module (its brain, and its body as the default start), instead of its best body.
    #[arg(long, requires = "from")]
    entry: Option<usize>,
    /// Controller family for --brain scratch (frozen and finetune use the module's).
    #[arg(long, default_value = "attention")]
    controller: ControllerKind,
    /// The start body (a preset or rows); default: the module's own body, or box-3x3.
    #[arg(long)]
    start: Option<String>,
    /// Evaluation budget; the last iteration is completed even when it passes it.
    #[arg(long)]
    evals: u64,
    /// Run seed: every body edit, mutation, terrain and noise stream derives from it.
    #[arg(long)]
    seed: u64,
    /// Worker threads (default: all cores). Never changes the result.
    #[arg(long)]
    threads: Option<usize>,
    /// Simulated seconds per evaluation.
    #[arg(long, default_value_t = 30.0)]
    seconds: f64,
    /// Training terrain family or fixed name.
    #[arg(long, default_value = "hilly-1-10")]
    terrain: String,
    /// The search grid, WxH cells (bodies live inside it).
    #[arg(long, default_value_t = format!("{}x{}", DEFAULT_GRID.0, DEFAULT_GRID.1))]
    grid: String,
    /// Voxel-count bounds of every body, MIN-MAX.
    #[arg(long, default_value_t = format!("{}-{}", DEFAULT_VOXELS.0, DEFAULT_VOXELS.1))]
    voxels: String,
    /// New bodies per iteration (every elite is also re-measured each iteration).
    #[arg(long, default_value_t = 40)]
    batch: usize,
    /// Where to write the co-design run file.
    #[arg(long)]
    out: PathBuf,
    /// Seconds between checkpoints (OUT.checkpoint); 0: never write one.
    #[arg(long, default_value_t = 60.0)]
    checkpoint_every: f64,
}

/// Two whole numbers joined by `sep`, for --grid and --voxels.
fn pair(flag: &str, text: &str, sep: char, example: &str) -> Result<(usize, usize)> {
    text.split_once(sep)
        .and_then(|(a, b)| Some((a.trim().parse().ok()?, b.trim().parse().ok()?)))
        .ok_or_else(|| {
            Error::Input(format!(
                "{flag} '{text}': expected two whole numbers, e.g. {example}"
            ))
        })
}

fn config_of(args: &Args) -> Result<CodesignConfig> {
    let module = match &args.from {
        Some(path) => Some(crate::runfile::load_source(path, args.entry)?),
        None => None,
    };
    let mut config = CodesignConfig::with_module(
        args.brain,
        module,
        args.controller,
        args.start.as_deref(),
        args.evals,
        args.seed,
    )?;
    (config.grid_width, config.grid_height) = pair("--grid", &args.grid, 'x', "20x10")?;
    (config.min_voxels, config.max_voxels) = pair("--voxels", &args.voxels, '-', "4-20")?;
    config.batch = args.batch;
    config.seconds = args.seconds;
    config.terrain = TrainingTerrain::parse(&args.terrain)?;
    config.validate()?;
    Ok(config)
}

fn checkpoint_path(out: &Path) -> PathBuf {
    let mut name = out.as_os_str().to_owned();
    name.push(".checkpoint");
    PathBuf::from(name)
}

/// The search from its checkpoint when one exists (it must be of the same configuration).
fn start(config: CodesignConfig, checkpoint: &Path) -> Result<Codesign> {
    let Ok(text) = std::fs::read_to_string(checkpoint) else {
        return Codesign::new(config);
    };
    let named = |e: Error| e.about(checkpoint.display());
    let run = CodesignRun::from_json(&text).map_err(named)?;
    if run.config != config {
        return Err(Error::Input(format!(
            "{} is the checkpoint of another search (other settings): delete it, or give the \
             settings it was made with",
            checkpoint.display()
        )));
    }
    eprintln!(
        "vsr: continuing from {} (iteration {})",
        checkpoint.display(),
        run.iteration
    );
    Codesign::resume(run)
}

/// Runs the command.
pub fn run(args: Args) -> Result<()> {
    if !(args.checkpoint_every >= 0.0 && args.checkpoint_every.is_finite()) {
        return Err(Error::Input(
            "--checkpoint-every must be a number of seconds >= 0".into(),
        ));
    }
    let config = config_of(&args)?;
    crate::runfile::check_writable(&args.out)?;
    let checkpoint = checkpoint_path(&args.out);
    let mut search = start(config, &checkpoint)?;
    let pool = thread_pool(args.threads)?;
    let threads = pool.current_num_threads();
    let started = Instant::now();
    let earlier = search.history().last().map_or(0.0, |r| r.wall_seconds);
    let clock = || earlier + started.elapsed().as_secs_f64();
    let progress = crate::progress::Progress::new(search.config().budget_evals);
    progress.resume_at(search.evaluations());
    let mut last_checkpoint = Instant::now();
    let evaluate = |jobs: &[Job]| -> Result<Vec<f64>> {
        let fitness = |job: &Job| {
            let f = job.fitness();
            progress.inc(1);
            f
        };
        pool.install(|| jobs.par_iter().map(fitness).collect())
    };
    let after = |s: &Codesign| -> Result<()> {
        if let Some(r) = s.history().last() {
            progress.generation_line(&r.summary());
        }
        let due = args.checkpoint_every > 0.0
            && last_checkpoint.elapsed().as_secs_f64() >= args.checkpoint_every;
        if due {
            crate::atomic::write(
                &checkpoint,
                s.run_file(None)?.to_json().as_bytes(),
                "checkpoint",
            )?;
            last_checkpoint = Instant::now();
        }
        Ok(())
    };
    search.run(evaluate, after, clock)?;
    progress.finish();
    let run = search.run_file(Some(Timing {
        threads,
        wall_seconds: clock(),
    }))?;
    crate::atomic::write(&args.out, run.to_json().as_bytes(), "co-design run file")?;
    if checkpoint.exists() {
        std::fs::remove_file(&checkpoint)
            .map_err(|e| Error::Io(format!("cannot delete {}: {e}", checkpoint.display())))?;
    }
    say!(
        "{} brain ({}): {} bodies found in {} evaluations; best {} ({} voxels) at {:.3} m/s; \
         {:.1} s on {} threads; wrote {}",
        run.config.brain,
        run.config.controller,
        run.archive.len(),
        run.evaluations,
        run.best.shape.to_rows(),
        run.best.shape.voxel_count(),
        run.best.fitness,
        run.timing.map_or(0.0, |t| t.wall_seconds),
        threads,
        args.out.display()
    );
    Ok(())
}
