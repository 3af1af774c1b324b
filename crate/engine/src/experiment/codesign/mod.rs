//! Body search (co-design): bodies searched around a brain, the paper's thesis ("a brain that
//! needs no messages can be reassembled into other bodies") made a tool. A body-and-brain
//! genome ([`Design`]: a body in a grid, genes per grid cell), two body edits ([`BodyGrid`]),
//! three ways to get the brain ([`BrainMode`]: a pretrained attention module or a brain for
//! any body, frozen or fine-tuned, or any controller from scratch; a brain for any body frozen
//! whole leaves only the body to evolve), a MAP-Elites archive over size and feet
//! ([`Archive`]), the ask/tell search ([`Codesign`]) and its run file ([`CodesignRun`]).
//! `genetics/` is not involved: its GA evolves one genome length for one body.

mod archive;
mod body;
mod config;
mod design;
mod file;
mod search;

pub use archive::{cell_of, Archive, Cell, Elite};
pub use body::BodyGrid;
pub use config::{BrainMode, CodesignConfig, DEFAULT_GRID, DEFAULT_START, DEFAULT_VOXELS};
pub use design::Design;
pub use file::{CodesignRecord, CodesignRun, Entry, CODESIGN_FORMAT};
pub use search::Codesign;

use crate::error::Result;
use crate::experiment::config::SourceRun;
use crate::experiment::finetune::{source_from, source_of};
use crate::experiment::run::{Best, RunFile};

/// The module a run file holds, to transplant or fine-tune: a run file's best, or a co-design
/// run file's best body with its brain (or archive entry `entry`, in cell order; its seed and
/// budget the search's). `entry` on a plain run file is refused as in [`best_in_file`].
pub fn source_in_file(text: &str, entry: Option<usize>) -> Result<SourceRun> {
    if !is_codesign(text) {
        let run = RunFile::from_json(text)?;
        one_body(entry)?;
        return Ok(source_of(&run));
    }
    let run = CodesignRun::from_json(text)?;
    let best = match entry {
        Some(i) => run.entry_best(i)?,
        None => run.best,
    };
    Ok(source_from(best, run.config.seed, run.config.budget_evals))
}

/// Refuses an archive entry other than 0 for a plain run file: it has one body.
fn one_body(entry: Option<usize>) -> Result<()> {
    match entry {
        None | Some(0) => Ok(()),
        Some(i) => Err(crate::error::Error::Input(format!(
            "entry {i}: this run file has one body (entry 0); entries belong to co-design run files"
        ))),
    }
}

/// True when `text` says it is a co-design run file (its `format`), whatever else it holds.
pub fn is_codesign(text: &str) -> bool {
    serde_json::from_str::<serde_json::Value>(text)
        .ok()
        .and_then(|v| v.get("format").and_then(|f| f.as_str()).map(String::from))
        .as_deref()
        == Some(CODESIGN_FORMAT)
}

/// The body with its brain that a run file names: a run file's `best`, or a co-design run
/// file's best (or archive entry `entry`, in cell order). `entry` on a plain run file is
/// refused: it has one body.
pub fn best_in_file(text: &str, entry: Option<usize>) -> Result<Best> {
    Ok(best_and_seconds_in_file(text, entry)?.0)
}

/// [`best_in_file`] with the episode length (s) the file's run was evolved with (its
/// `config.seconds`): the length its best is walked for when none is asked for.
pub fn best_and_seconds_in_file(text: &str, entry: Option<usize>) -> Result<(Best, f64)> {
    if is_codesign(text) {
        let run = CodesignRun::from_json(text)?;
        let best = match entry {
            Some(i) => run.entry_best(i)?,
            None => run.best,
        };
        return Ok((best, run.config.seconds));
    }
    let run = RunFile::from_json(text)?;
    one_body(entry)?;
    Ok((run.best, run.config.seconds))
}
