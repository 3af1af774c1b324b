//! The way every long call of the module runs: on a rayon pool (all cores, or `threads`), with
//! the GIL released, in chunks of episodes with Python looked at between them, so that Ctrl-C
//! stops a large batch within a chunk (KeyboardInterrupt) and the `vsr` logger says how far it
//! is. Every episode is independent, so the chunks change no result.

use pyo3::prelude::*;
use rayon::prelude::*;

use crate::errors::input;

/// Episodes per thread between two looks at Python (Ctrl-C, progress): about a second of 30-s
/// episodes.
pub const CHUNK_PER_THREAD: usize = 32;

/// Where work runs: rayon's pool of all cores, or one of `threads` threads.
pub struct Pool(Option<rayon::ThreadPool>);

impl Pool {
    /// A pool of `threads` threads (at least 1: `args::optional_threads` checks), or `None` for
    /// every core.
    pub fn new(threads: Option<usize>) -> PyResult<Self> {
        let Some(t) = threads else {
            return Ok(Self(None));
        };
        rayon::ThreadPoolBuilder::new()
            .num_threads(t)
            .build()
            .map(|pool| Self(Some(pool)))
            .map_err(|e| input(format!("cannot start {t} threads: {e}")))
    }

    /// Its number of threads.
    pub fn threads(&self) -> usize {
        self.0
            .as_ref()
            .map_or_else(rayon::current_num_threads, |p| p.current_num_threads())
    }

    /// `work` run inside the pool.
    pub fn install<R: Send>(&self, work: impl FnOnce() -> R + Send) -> R {
        match &self.0 {
            Some(pool) => pool.install(work),
            None => work(),
        }
    }

    /// `episode(i)` for every `i < count`, in order, with the GIL released; in chunks, with
    /// Ctrl-C looked at and progress logged ("vsr": INFO) between them when there is more than
    /// one chunk.
    pub fn episodes(
        &self,
        py: Python<'_>,
        count: usize,
        episode: impl Fn(usize) -> f64 + Sync,
    ) -> PyResult<Vec<f64>> {
        self.map(py, count, CHUNK_PER_THREAD, "episodes", episode)
    }

    /// `work(i)` for every `i < count`, in order, as [`Pool::episodes`] runs episodes: with
    /// the GIL released, in chunks of `per_thread` items per thread, Ctrl-C looked at and
    /// progress logged ("evaluated 64 of 100 `what`") between them.
    pub fn map<T: Send>(
        &self,
        py: Python<'_>,
        count: usize,
        per_thread: usize,
        what: &str,
        work: impl Fn(usize) -> T + Sync,
    ) -> PyResult<Vec<T>> {
        let chunk = (per_thread * self.threads()).max(1);
        let mut results = Vec::with_capacity(count);
        for start in (0..count).step_by(chunk) {
            let end = (start + chunk).min(count);
            let part = py.detach(|| {
                self.install(|| (start..end).into_par_iter().map(&work).collect::<Vec<_>>())
            });
            results.extend(part);
            py.check_signals()?;
            if count > chunk {
                info(py, &format!("evaluated {end} of {count} {what}"))?;
            }
        }
        Ok(results)
    }
}

/// A line at INFO on the `vsr` logger (Python's `logging`: shown once a program asks for it,
/// e.g. `logging.basicConfig(level=logging.INFO)`).
pub fn info(py: Python<'_>, line: &str) -> PyResult<()> {
    let logger = py.import("logging")?.call_method1("getLogger", ("vsr",))?;
    logger.call_method1("info", (line,))?;
    Ok(())
}
