//! Genome -> controller -> episode -> fitness: the single composition point used by
//! evolution, validation, the CLI and the page.

use super::episode::{topology, Episode, Outcome, Policy};
use super::run::Best;
use crate::controllers::{build, Controller, ControllerKind};
use crate::error::{Error, Result};
use crate::simulation::{Shape, Terrain};
use std::sync::Arc;

/// A controller of `kind` for `shape` with parameters `genome`; fails with a message
/// on a length mismatch or a non-finite gene.
pub fn controller_for(
    kind: ControllerKind,
    shape: &Shape,
    genome: &[f32],
) -> Result<Box<dyn Controller>> {
    kind.check_genome("the genome", shape.voxel_count(), genome)?;
    let mut controller = build(kind, &topology(shape));
    controller.set_params(genome)?;
    Ok(controller)
}

/// Runs one locomotion episode of `seconds` and returns its outcome. An episode whose
/// simulation becomes non-finite is reported as an error.
pub fn evaluate(
    shape: &Shape,
    terrain: impl Into<Arc<Terrain>>,
    kind: ControllerKind,
    genome: &[f32],
    noise_seed: Option<u64>,
    seconds: f64,
) -> Result<Outcome> {
    let controller = controller_for(kind, shape, genome)?;
    let mut episode = Episode::with_policy(shape, terrain, Policy::Brain(controller), noise_seed);
    episode.run(seconds)
}

/// Fitness for evolution: the episode's velocity, or NaN (worst) if it exploded.
pub fn fitness(
    shape: &Shape,
    terrain: impl Into<Arc<Terrain>>,
    kind: ControllerKind,
    genome: &[f32],
    noise_seed: Option<u64>,
    seconds: f64,
) -> f64 {
    evaluate(shape, terrain, kind, genome, noise_seed, seconds).map_or(f64::NAN, |o| o.velocity)
}

/// An episode in which a run file's best individual drives its own shape on `terrain`.
/// `shape`, when given, must be that very shape (a preset or its rows): a genome fits
/// the voxel count and neighbourhoods it was evolved on, so another shape is refused
/// with a message naming the one it needs.
pub fn replay(
    best: &Best,
    shape: Option<&Shape>,
    terrain: impl Into<Arc<Terrain>>,
    noise_seed: Option<u64>,
) -> Result<Episode> {
    let body_independent = best.controller.is_body_independent();
    if let Some(other) = shape.filter(|s| **s != best.shape && !body_independent) {
        return Err(Error::Input(format!(
            "this {} controller needs shape {} ({} voxels), not {} ({} voxels); \
             leave the shape out to use its own",
            best.controller,
            best.shape.to_rows(),
            best.shape.voxel_count(),
            other.to_rows(),
            other.voxel_count()
        )));
    }
    // A brain for any body walks the shape it is given.
    let body = shape.unwrap_or(&best.shape);
    let controller = controller_for(best.controller, body, &best.genome)?;
    Ok(Episode::with_policy(
        body,
        terrain,
        Policy::Brain(controller),
        noise_seed,
    ))
}
