//! `vsr campaign run FILE [--jobs N] [--threads T] [--only TEXT]`: runs a campaign's jobs
//! (or the part `--only` names) on this machine.
//!
//! Each job is the `vsr` command `campaign plan` prints, run as a child process of this very
//! binary with its output in `OUT/logs/FOLDER-NAME.log`, named after its output file and that
//! file's folder (`runs-X.json.log`, `ablation-X.json.log`: a run and its ablation share a
//! file name). Jobs whose output file exists are skipped, so a stopped campaign resumes where
//! it was; every command writes its one output atomically, so a killed job leaves no partial
//! file and is simply run again. Up to N jobs run at once, each evolution with T threads:
//! keep N x T at most the number of cores (the default: N = cores, T = 1, the most efficient
//! for a grid of many runs; results never depend on T). A job starts as soon as the files it
//! needs exist; a job whose input could not be made is skipped and reported.

use std::fs;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::sync::{Condvar, Mutex};

use indicatif::{ProgressBar, ProgressStyle};
use vsr::{Error, Result};
use vsr_study::campaign::Job;

use super::command;
use super::target::{create_folders, Only, Target};

/// Arguments of `vsr campaign run`.
#[derive(clap::Args, Debug)]
pub struct Args {
    #[command(flatten)]
    target: Target,
    /// Jobs run at once (default: the number of cores).
    #[arg(long)]
    jobs: Option<usize>,
    /// --threads of each evolution job.
    #[arg(long, default_value_t = 1)]
    threads: usize,
    #[command(flatten)]
    only: Only,
}

#[derive(Debug, Clone, Copy, PartialEq)]
enum State {
    Waiting,
    Running,
    Done,
    Failed,
}

/// Runs the command.
pub fn run(args: Args) -> Result<()> {
    let (campaign, out) = args.target.load()?;
    let cores = std::thread::available_parallelism().map_or(1, |n| n.get());
    let jobs_at_once = args.jobs.unwrap_or(cores);
    if jobs_at_once == 0 || args.threads == 0 {
        return Err(Error::Input(
            "--jobs and --threads must be at least 1".into(),
        ));
    }
    if jobs_at_once * args.threads > cores {
        eprintln!(
            "vsr: note: {jobs_at_once} jobs x {} threads exceeds the {cores} cores",
            args.threads
        );
    }
    let jobs = args.only.plan(&campaign, &out)?;
    super::target::check_modules(&campaign)?;
    create_folders(&out, &jobs)?;
    let program = std::env::current_exe()
        .map_err(|e| Error::Io(format!("cannot find the vsr binary: {e}")))?;
    let states: Vec<State> = jobs
        .iter()
        .map(|j| {
            if j.out.exists() {
                State::Done
            } else {
                State::Waiting
            }
        })
        .collect();
    let skipped = states.iter().filter(|&&s| s == State::Done).count();
    let bar = progress_bar(jobs.len() as u64, skipped as u64);
    let shared = (Mutex::new(states), Condvar::new());
    let runner = Runner {
        jobs: &jobs,
        program: &program,
        out: &out,
        threads: args.threads,
        bar: &bar,
    };
    std::thread::scope(|scope| {
        for _ in 0..jobs_at_once {
            scope.spawn(|| runner.work(&shared));
        }
    });
    bar.finish_and_clear();
    let states = shared.0.into_inner().unwrap_or_else(|e| e.into_inner());
    summarise(&jobs, &states, skipped, &out)
}

struct Runner<'a> {
    jobs: &'a [Job],
    program: &'a Path,
    out: &'a Path,
    threads: usize,
    bar: &'a ProgressBar,
}

impl Runner<'_> {
    /// Takes runnable jobs until none is left.
    fn work(&self, shared: &(Mutex<Vec<State>>, Condvar)) {
        let (lock, wake) = shared;
        loop {
            let mut states = lock.lock().unwrap_or_else(|e| e.into_inner());
            let next = loop {
                if let Some(i) = self.next_job(&states) {
                    break Some(i);
                }
                if !states.contains(&State::Running) {
                    break None; // nothing runs, nothing can start: the end
                }
                states = wake.wait(states).unwrap_or_else(|e| e.into_inner());
            };
            let Some(i) = next else {
                wake.notify_all();
                return;
            };
            states[i] = State::Running;
            drop(states);
            let started = std::time::Instant::now();
            let ok = self.execute(&self.jobs[i]);
            let mut states = lock.lock().unwrap_or_else(|e| e.into_inner());
            states[i] = if ok { State::Done } else { State::Failed };
            self.bar.inc(1);
            if self.bar.is_hidden() {
                // No terminal (nohup, a log file): one line per finished job instead.
                let finished = states
                    .iter()
                    .filter(|&&s| s == State::Done || s == State::Failed)
                    .count();
                eprintln!(
                    "{} {}/{} {} ({:.0} s)",
                    if ok { "done" } else { "FAILED" },
                    finished,
                    states.len(),
                    self.jobs[i].out.display(),
                    started.elapsed().as_secs_f64()
                );
            }
            wake.notify_all();
        }
    }

    /// The first waiting job whose inputs all exist (jobs whose input failed are skipped),
    /// assessments (validations, ablations: seconds each) before runs (minutes each), so a
    /// campaign stopped half-way has every finished run assessed.
    fn next_job(&self, states: &[State]) -> Option<usize> {
        let ready = |i: usize| {
            let need_state = |p: &PathBuf| {
                self.jobs
                    .iter()
                    .position(|j| &j.out == p)
                    .map(|k| states[k])
            };
            self.jobs[i]
                .needs
                .iter()
                .all(|p| need_state(p) == Some(State::Done) || p.exists())
        };
        let waiting = |i: &usize| states[*i] == State::Waiting && ready(*i);
        let mut candidates = (0..self.jobs.len()).filter(waiting);
        let first = candidates.next()?;
        if !self.jobs[first].threaded() {
            return Some(first);
        }
        candidates
            .find(|&i| !self.jobs[i].threaded())
            .or(Some(first))
    }

    /// Runs one job as a child process, its output and errors into its log file.
    fn execute(&self, job: &Job) -> bool {
        let name = job
            .out
            .file_name()
            .map_or("job".into(), |n| n.to_string_lossy());
        self.bar.set_message(name.to_string());
        let log_path = self.out.join("logs").join(log_name(&job.out));
        let Ok(log) = fs::File::create(&log_path) else {
            return false;
        };
        let Ok(err) = log.try_clone() else {
            return false;
        };
        let status = Command::new(self.program)
            .args(command::args(job, self.threads))
            .stdin(Stdio::null())
            .stdout(log)
            .stderr(err)
            .status();
        matches!(status, Ok(s) if s.success()) && job.out.exists()
    }
}

/// The log file name of the job writing `out`: its folder and file name, `runs-X.json.log`,
/// `ablation-X.json.log`, as a run and its ablation share a file name.
fn log_name(out: &Path) -> String {
    let name = |p: Option<&std::ffi::OsStr>| p.map(|n| n.to_string_lossy().into_owned());
    let file = name(out.file_name()).unwrap_or_else(|| "job".into());
    match name(out.parent().and_then(Path::file_name)) {
        Some(folder) => format!("{folder}-{file}.log"),
        None => format!("{file}.log"),
    }
}

fn progress_bar(total: u64, done: u64) -> ProgressBar {
    let bar = ProgressBar::new(total);
    let template = "{elapsed_precise} [{bar:30}] {pos}/{len} jobs, eta {eta}  {msg}";
    if let Ok(style) = ProgressStyle::with_template(template) {
        bar.set_style(style.progress_chars("=> "));
    }
    bar.set_position(done);
    bar.reset_eta();
    bar
}

/// Prints what happened; an error when some job failed or could not start.
fn summarise(jobs: &[Job], states: &[State], skipped: usize, out: &Path) -> Result<()> {
    let count = |s: State| states.iter().filter(|&&x| x == s).count();
    let (done, failed, blocked) = (
        count(State::Done),
        count(State::Failed),
        count(State::Waiting),
    );
    say!(
        "{} jobs: {} done ({} already before this run), {} failed, {} not started \
         (their input is missing); outputs in {}",
        jobs.len(),
        done,
        skipped,
        failed,
        blocked,
        out.display()
    );
    for (job, state) in jobs.iter().zip(states) {
        if *state == State::Failed {
            eprintln!(
                "vsr: failed: {} (see the log in {}/logs)",
                job.out.display(),
                out.display()
            );
        }
    }
    match failed + blocked {
        0 => Ok(()),
        n => Err(Error::Io(format!(
            "{n} jobs did not finish; run the same command again to retry them"
        ))),
    }
}
