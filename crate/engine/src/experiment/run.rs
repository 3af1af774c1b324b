//! The run file: one versioned JSON document per evolutionary run, written by `vsr evolve`
//! and `vsr finetune` and read by `vsr evaluate`, `validate`, `ablate`, `finetune` and the page.
//!
//! Top level: `format` ("vsr-run"), `version` (1), `config` ([`EvolutionConfig`]: everything
//! that determines the result), `generations` (one [`GenerationRecord`] per generation),
//! `best` ([`Best`]: the final best genome, self-contained) and `timing` ([`Timing`], or null:
//! how the run was executed; never part of a comparison). Non-finite statistics (a population
//! with exploded evaluations) are written as `null` and read back as -infinity.
//!
//! Loading checks, each failure a readable [`Error`]: the format and version, the controller
//! names, the shapes, that every gene is a finite number, that the genome length fits its
//! controller and shape, and that `best` matches `config`. The core does no file I/O: the
//! command line writes the JSON atomically (temporary file, then rename).

use super::config::{EvolutionConfig, SourceRun};
use crate::controllers::{split_slow_genome, ControllerKind};
use crate::error::{Error, Result};
use crate::genetics::GenerationStats;
use crate::simulation::Shape;
use serde::{Deserialize, Serialize};

/// The value of the `format` field.
pub(crate) const FORMAT: &str = "vsr-run";
/// The run-file version this code writes and reads.
pub(crate) const VERSION: u32 = 1;

/// Fitness summary of one generation's survivors, plus the wall time so far.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct GenerationRecord {
    /// Generation (0 = initial population).
    pub generation: u32,
    /// Evaluations done so far, this generation included.
    pub evaluations: u64,
    /// Best survivor's fitness (m/s).
    #[serde(with = "super::json::finite_or_null")]
    pub best: f64,
    /// Upper quartile.
    #[serde(with = "super::json::finite_or_null")]
    pub(crate) q3: f64,
    /// Median.
    #[serde(with = "super::json::finite_or_null")]
    pub median: f64,
    /// Lower quartile.
    #[serde(with = "super::json::finite_or_null")]
    pub(crate) q1: f64,
    /// Worst survivor's fitness.
    #[serde(with = "super::json::finite_or_null")]
    pub(crate) worst: f64,
    /// Wall-clock seconds from the start of the run to the end of this generation, as
    /// measured by the caller (0 when unknown); never part of a comparison.
    pub wall_seconds: f64,
    /// Slow attention only: alpha of the generation's best individual (absent otherwise).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub alpha: Option<f32>,
    /// Slow attention only: eta of the generation's best individual (absent otherwise).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub eta: Option<f32>,
}

impl GenerationRecord {
    /// The GA's statistics with the caller's wall time.
    pub(crate) fn new(stats: &GenerationStats, wall_seconds: f64) -> Self {
        GenerationRecord {
            generation: stats.generation,
            evaluations: stats.evaluations,
            best: stats.best,
            q3: stats.q3,
            median: stats.median,
            q1: stats.q1,
            worst: stats.worst,
            wall_seconds,
            alpha: None,
            eta: None,
        }
    }
}

/// The best individual at the end of a run, with what is needed to rebuild its controller.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Best {
    /// Its controller family.
    pub controller: ControllerKind,
    /// The shape it drives.
    pub shape: Shape,
    /// Its genome, in the controller's documented layout.
    #[serde(deserialize_with = "super::json::finite_genes")]
    pub genome: Vec<f32>,
    /// Its latest fitness in the run (one evaluation, m/s).
    #[serde(with = "super::json::finite_or_null")]
    pub fitness: f64,
    /// Slow attention only: alpha = min(|g1|, 1), derived from the genome (ignored on load).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub alpha: Option<f32>,
    /// Slow attention only: eta = min(|g2|, 1), derived from the genome (ignored on load).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub eta: Option<f32>,
}

impl Best {
    /// A best individual; alpha and eta are filled in for slow attention.
    pub fn new(controller: ControllerKind, shape: Shape, genome: Vec<f32>, fitness: f64) -> Self {
        let mut best = Best {
            controller,
            shape,
            genome,
            fitness,
            alpha: None,
            eta: None,
        };
        best.derive_slow_weights();
        best
    }

    fn derive_slow_weights(&mut self) {
        (self.alpha, self.eta) = (None, None);
        if self.controller == ControllerKind::SlowAttention && self.validate("").is_ok() {
            if let Some((_, rates)) = split_slow_genome(&self.genome) {
                (self.alpha, self.eta) = (Some(rates.alpha), Some(rates.eta));
            }
        }
    }

    /// Checks that the genome fits the controller and shape and that every gene is finite.
    pub(crate) fn validate(&self, what: &str) -> Result<()> {
        self.controller
            .check_genome(what, self.shape.voxel_count(), &self.genome)
    }
}

/// How a run was executed; informative only, never part of a comparison.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Timing {
    /// Worker threads (or page workers) used.
    pub threads: usize,
    /// Wall-clock seconds of the whole run.
    pub wall_seconds: f64,
}

/// A whole run file; see the module doc.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct RunFile {
    /// Always [`FORMAT`].
    pub format: String,
    /// Always [`VERSION`].
    pub(crate) version: u32,
    /// The run's configuration.
    pub config: EvolutionConfig,
    /// Per-generation statistics, generation 0 first.
    pub generations: Vec<GenerationRecord>,
    /// The final best individual.
    pub best: Best,
    /// Execution details, or null.
    pub timing: Option<Timing>,
}

/// Why JSON stops near (`line`, `column`) when it is a number JSON cannot hold (NaN or
/// Infinity, which Python's `json.dumps` writes unless `allow_nan=False`), else "".
fn not_a_number_near(text: &str, line: usize, column: usize) -> &'static str {
    let Some(row) = text.lines().nth(line.saturating_sub(1)) else {
        return "";
    };
    let near: String = row
        .chars()
        .skip(column.saturating_sub(12))
        .take(24)
        .collect();
    if near.contains("NaN") || near.contains("Infinity") {
        ": a number there is NaN or Infinity, which JSON cannot hold (a gene or a figure that is \
         not a number; Python's json.dumps writes it unless allow_nan=False)"
    } else {
        ""
    }
}

impl RunFile {
    /// A run file of the current format and version.
    pub fn new(
        config: EvolutionConfig,
        generations: Vec<GenerationRecord>,
        best: Best,
        timing: Option<Timing>,
    ) -> Self {
        RunFile {
            format: FORMAT.to_string(),
            version: VERSION,
            config,
            generations,
            best,
            timing,
        }
    }

    /// Pretty-printed JSON, ending with a newline.
    pub fn to_json(&self) -> String {
        let mut text = serde_json::to_string_pretty(self).unwrap_or_default();
        text.push('\n');
        text
    }

    /// Parses and validates a run file (see the module doc for what is checked).
    pub fn from_json(text: &str) -> Result<RunFile> {
        let value: serde_json::Value = serde_json::from_str(text).map_err(|e| {
            Error::Input(match e.classify() {
                serde_json::error::Category::Eof => {
                    "the run file is cut off: it ends before its JSON is complete".to_string()
                }
                _ => format!(
                    "the run file is not valid JSON (near line {}, character {}){}",
                    e.line(),
                    e.column(),
                    not_a_number_near(text, e.line(), e.column())
                ),
            })
        })?;
        check_header(&value)?;
        for path in [
            "/config/controller",
            "/best/controller",
            "/config/source/controller",
        ] {
            if let Some(name) = value.pointer(path).and_then(|v| v.as_str()) {
                name.parse::<ControllerKind>()?;
            }
        }
        let mut run: RunFile = serde_json::from_value(value).map_err(|e| {
            Error::Input(format!(
                "the run file is malformed: {}",
                without_position(&e)
            ))
        })?;
        run.validate()?;
        run.best.derive_slow_weights();
        Ok(run)
    }

    /// Checks the genomes and that `best` belongs to `config`.
    pub fn validate(&self) -> Result<()> {
        self.best.validate("the best genome")?;
        if self.best.controller != self.config.controller || self.best.shape != self.config.shape {
            return Err(Error::Input(format!(
                "the best genome is the {} controller of {}, but the run evolved the {} \
                 controller of {}",
                self.best.controller,
                self.best.shape.to_rows(),
                self.config.controller,
                self.config.shape.to_rows()
            )));
        }
        if let Some(SourceRun {
            controller,
            shape,
            genome,
            ..
        }) = &self.config.source
        {
            controller.check_genome("the source genome", shape.voxel_count(), genome)?;
        }
        self.config.validate()
    }
}

/// Checks the `format` and `version` fields before anything else.
fn check_header(value: &serde_json::Value) -> Result<()> {
    let format = value.get("format").and_then(|f| f.as_str());
    if format != Some(FORMAT) {
        return Err(Error::Input(format!(
            "this is not a vsr run file: its \"format\" is {}, expected \"{FORMAT}\"",
            value
                .get("format")
                .map_or("missing".to_string(), |f| f.to_string())
        )));
    }
    match value.get("version").and_then(|v| v.as_u64()) {
        Some(v) if v == u64::from(VERSION) => Ok(()),
        Some(v) => Err(Error::Input(format!(
            "run-file version {v} is not supported: this vsr reads version {VERSION}"
        ))),
        None => Err(Error::Input(
            "the run file has no integer \"version\" field".to_string(),
        )),
    }
}

/// A serde_json message without its " at line L column C" tail, which means nothing to a
/// person who did not write the file by hand.
fn without_position(e: &serde_json::Error) -> String {
    let text = e.to_string();
    match text.rfind(" at line ") {
        Some(i) => text[..i].to_string(),
        None => text,
    }
}
