//! The co-design run file: one versioned JSON document per body search, written by
//! `vsr codesign` (and, every iteration, as its checkpoint) and read by `vsr evaluate`,
//! `vsr validate`, Python and the page.
//!
//! Top level: `format` ("vsr-codesign"), `version` (1), `config` ([`CodesignConfig`]),
//! `iteration` and `evaluations` (how far it got; the run is complete when the evaluations
//! reach the budget), `history` (one [`CodesignRecord`] per iteration), `archive` (one
//! [`Entry`] per filled cell, in cell order: the body as `shape` rows, its controller `genome`,
//! `fitness`, `cell`, `voxels`, `feet`, and the whole `design` the search resumes from),
//! `best` (the entry with the highest fitness, as a [`Best`], the same as other run files'
//! `best`) and `timing`. Loading checks every entry: a shape or genome that does not match its
//! design, a body out of bounds or in pieces, a frozen block that differs from the module's.

use super::archive::{cell_of, Archive, Cell, Elite};
use super::config::CodesignConfig;
use super::design::Design;
use crate::error::{Error, Result};
use crate::experiment::run::{Best, Timing};
use crate::simulation::Shape;
use serde::{Deserialize, Serialize};

/// The value of the `format` field.
pub const CODESIGN_FORMAT: &str = "vsr-codesign";
/// The version this code writes and reads.
const VERSION: u32 = 1;

/// The archive after one iteration.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct CodesignRecord {
    /// The iteration (0 = the start body and its variations).
    pub iteration: u32,
    /// Evaluations so far, this iteration included.
    pub evaluations: u64,
    /// The best elite's fitness (m/s).
    #[serde(with = "crate::experiment::json::finite_or_null")]
    pub best: f64,
    /// Filled archive cells.
    pub filled: usize,
    /// The sum of the elites' positive fitness values.
    pub qd_score: f64,
    /// Children that took a cell this iteration.
    pub kept: usize,
    /// Wall seconds since the start as the caller measured them (0 when unknown); never part
    /// of a comparison.
    pub wall_seconds: f64,
}

impl CodesignRecord {
    /// The progress line of this iteration, as `vsr codesign` prints it and Python logs it.
    pub fn summary(&self) -> String {
        format!(
            "iteration {}: best {:.3} m/s, {} bodies in the archive",
            self.iteration, self.best, self.filled
        )
    }
}

/// One archive entry as the file shows it; see the module doc.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Entry {
    /// Archive cell: (size bin, feet bin).
    pub cell: Cell,
    /// Its voxel count.
    pub voxels: usize,
    /// Its feet.
    pub feet: usize,
    /// The body, cropped, in rows notation.
    pub shape: Shape,
    /// The controller genome for that body.
    #[serde(deserialize_with = "crate::experiment::json::finite_genes")]
    pub genome: Vec<f32>,
    /// Mean of its measurements (m/s).
    #[serde(with = "crate::experiment::json::finite_or_null")]
    pub fitness: f64,
    /// Number of measurements.
    pub measurements: u32,
    /// The iteration it was found in.
    pub found: u32,
    /// The whole design (body in the grid, every cell's genes).
    pub design: Design,
}

/// A whole co-design run file; see the module doc.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct CodesignRun {
    /// Always [`CODESIGN_FORMAT`].
    pub format: String,
    version: u32,
    /// The search's configuration.
    pub config: CodesignConfig,
    /// Iterations told.
    pub iteration: u32,
    /// Evaluations told.
    pub evaluations: u64,
    /// One record per iteration.
    pub history: Vec<CodesignRecord>,
    /// The elites, in cell order.
    pub archive: Vec<Entry>,
    /// The best entry.
    pub best: Best,
    /// Execution details, or null.
    pub timing: Option<Timing>,
}

impl CodesignRun {
    pub(crate) fn new(
        config: CodesignConfig,
        iteration: u32,
        evaluations: u64,
        history: Vec<CodesignRecord>,
        archive: &Archive,
        timing: Option<Timing>,
    ) -> Result<CodesignRun> {
        let entries = archive
            .elites()
            .iter()
            .map(|e| entry(&config, e))
            .collect::<Result<Vec<Entry>>>()?;
        let best = archive
            .best()
            .map(|e| entry(&config, e))
            .transpose()?
            .ok_or_else(|| {
                Error::Input("no iteration has been evaluated yet: there is no best".into())
            })?;
        Ok(CodesignRun {
            format: CODESIGN_FORMAT.into(),
            version: VERSION,
            best: Best::new(config.controller, best.shape, best.genome, best.fitness),
            config,
            iteration,
            evaluations,
            history,
            archive: entries,
            timing,
        })
    }

    /// Whether the search reached its budget.
    pub fn is_complete(&self) -> bool {
        self.evaluations >= self.config.budget_evals
    }

    /// Entry `i` (in cell order) as a [`Best`]: a body with its brain; the message lists the
    /// entries there are when `i` is out of range.
    pub fn entry_best(&self, i: usize) -> Result<Best> {
        let e = self.archive.get(i).ok_or_else(|| {
            Error::Input(format!(
                "entry {i} does not exist: this archive has entries 0 to {}",
                self.archive.len().saturating_sub(1)
            ))
        })?;
        Ok(Best::new(
            self.config.controller,
            e.shape.clone(),
            e.genome.clone(),
            e.fitness,
        ))
    }

    /// The archive the search resumes from.
    pub(crate) fn archive_state(&self) -> Result<Archive> {
        let elites = self
            .archive
            .iter()
            .map(|e| Elite {
                cell: e.cell,
                design: e.design.clone(),
                fitness: e.fitness,
                measurements: e.measurements,
                found: e.found,
            })
            .collect();
        Ok(Archive::from_elites(elites))
    }

    /// Pretty-printed JSON, ending with a newline.
    pub fn to_json(&self) -> String {
        let mut text = serde_json::to_string_pretty(self).unwrap_or_default();
        text.push('\n');
        text
    }

    /// Parses and checks a co-design run file (see the module doc).
    pub fn from_json(text: &str) -> Result<CodesignRun> {
        let run: CodesignRun = serde_json::from_str(text).map_err(|e| {
            Error::Input(format!(
                "the co-design run file is damaged or incomplete: {e}"
            ))
        })?;
        if run.format != CODESIGN_FORMAT || run.version != VERSION {
            return Err(Error::Input(format!(
                "this is not a version-{VERSION} co-design run file (format \"{}\", version {})",
                run.format, run.version
            )));
        }
        run.config.validate()?;
        for (i, e) in run.archive.iter().enumerate() {
            let damaged = |why: &str| Error::Input(format!("archive entry {i} is damaged: {why}"));
            e.design
                .check(&run.config)
                .map_err(|err| damaged(&err.to_string()))?;
            let expected = entry(
                &run.config,
                &Elite {
                    cell: e.cell,
                    design: e.design.clone(),
                    fitness: e.fitness,
                    measurements: e.measurements,
                    found: e.found,
                },
            )?;
            if expected != *e {
                return Err(damaged(
                    "its shape, genome or cell does not match its design",
                ));
            }
        }
        if run.archive.windows(2).any(|w| w[0].cell >= w[1].cell) {
            return Err(Error::Input(
                "the archive's entries are not one per cell in cell order".into(),
            ));
        }
        run.best.validate("the best genome")?;
        Ok(run)
    }
}

/// The file's view of an elite.
fn entry(config: &CodesignConfig, e: &Elite) -> Result<Entry> {
    Ok(Entry {
        cell: cell_of(config, &e.design),
        voxels: e.design.body.voxel_count(),
        feet: e.design.body.feet(),
        shape: e.design.shape()?,
        genome: e.design.controller_genome(config.controller),
        fitness: e.fitness,
        measurements: e.measurements,
        found: e.found,
        design: e.design.clone(),
    })
}
