//! The frozen-attention ablation (SPEC 7, the paper's "one attention to rule them all" test).
//!
//! A recording episode runs the individual on the ablation terrain; at every whole second s
//! (0 ..= `last_second`) it takes a snapshot of every voxel's attention matrix (for s = 0, the
//! matrix of the first control call, after step 1). For each snapshot, a fresh episode of
//! `seconds` on the same terrain runs a [`FrozenAttention`] controller holding those matrices.
//! Both kinds of episode use the sensor noise of the validation episode on the same terrain
//! (`noise_seed_for`: validation terrain K for `hilly-1-10-K`): the validation episode on that
//! terrain is the unfrozen reference of the ablation. Slow attention is
//! ablated the same way: its A' is frozen and its alpha, eta genes are dropped.

use super::episode::{steps_for, Episode, Policy};
use super::evaluate::{controller_for, evaluate};
use super::run::Best;
use super::validation::noise_seed_for;
use crate::controllers::{
    split_slow_genome, Attention, Controller, ControllerKind, FrozenAttention,
};
use crate::error::{Error, Result};
use crate::simulation::Terrain;
use serde::{Deserialize, Serialize};
use std::sync::Arc;

/// The paper's ablation terrain.
pub const ABLATION_TERRAIN: &str = "hilly-1-10-0";

/// The velocity of the fresh episode with the matrices frozen at one time.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct AblationPoint {
    /// When the matrices were taken (s of the recording episode).
    pub freeze_second: u32,
    /// Velocity of the fresh episode with them frozen (m/s).
    pub velocity: f64,
}

/// Runs the ablation of `best` on `terrain` (see the module doc): one point per second
/// 0 ..= `last_second`, each fresh episode `seconds` long.
pub fn ablate(
    best: &Best,
    terrain: &str,
    last_second: u32,
    seconds: f64,
) -> Result<Vec<AblationPoint>> {
    let attention_genes = attention_genome(best)?;
    let noise = Some(noise_seed_for(terrain));
    let terrain = Arc::new(Terrain::parse(terrain)?);
    let snapshots = record_matrices(best, &terrain, last_second, noise)?;
    let mut points = Vec::with_capacity(snapshots.len());
    for (s, matrices) in (0u32..).zip(snapshots) {
        let mut plain = Attention::new(best.shape.voxel_count());
        plain.set_params(attention_genes)?;
        let mut frozen = FrozenAttention::new(plain);
        frozen.freeze_with(&matrices)?;
        let policy = Policy::Brain(Box::new(frozen));
        let mut episode = Episode::with_policy(&best.shape, Arc::clone(&terrain), policy, noise);
        let outcome = episode.run(seconds)?;
        points.push(AblationPoint {
            freeze_second: s,
            velocity: outcome.velocity,
        });
    }
    Ok(points)
}

/// The unfrozen reference of an ablation of `best` on `terrain`: its velocity over `seconds`
/// with its own controller (attention recomputed at every control call), with the sensor
/// noise of the ablation's episodes; on `hilly-1-10-K` it is the validation episode's.
pub fn unfrozen_velocity(best: &Best, terrain: &str, seconds: f64) -> Result<f64> {
    attention_genome(best)?;
    let noise = Some(noise_seed_for(terrain));
    let terrain = Terrain::parse(terrain)?;
    let outcome = evaluate(
        &best.shape,
        terrain,
        best.controller,
        &best.genome,
        noise,
        seconds,
    )?;
    Ok(outcome.velocity)
}

/// The plain-attention genome inside `best`; an error for controllers without attention.
fn attention_genome(best: &Best) -> Result<&[f32]> {
    best.validate("the genome")?;
    match best.controller {
        ControllerKind::Attention => Ok(&best.genome),
        ControllerKind::SlowAttention => split_slow_genome(&best.genome)
            .map(|(attention, _)| attention)
            .ok_or_else(|| Error::Input("the slow-attention genome is too short".into())),
        other => Err(Error::Input(format!(
            "the ablation freezes attention matrices, but this genome is a {other} controller \
             (use an attention or slow-attention run)"
        ))),
    }
}

/// Every voxel's matrices (16 floats per voxel) at each second 0 ..= `last_second` of one
/// episode of `best` on `terrain`.
fn record_matrices(
    best: &Best,
    terrain: &Arc<Terrain>,
    last_second: u32,
    noise: Option<u64>,
) -> Result<Vec<Vec<f32>>> {
    let controller = controller_for(best.controller, &best.shape, &best.genome)?;
    let policy = Policy::Brain(controller);
    let mut episode = Episode::with_policy(&best.shape, Arc::clone(terrain), policy, noise);
    let mut taken = 0u64;
    let mut snapshots = Vec::new();
    for s in 0..=last_second {
        let target = steps_for(f64::from(s)).max(1);
        episode.step((target - taken) as usize)?;
        taken = target;
        let matrices = episode.attention().ok_or_else(|| {
            Error::Input("the controller exposes no attention matrices".to_string())
        })?;
        snapshots.push(matrices.to_vec());
    }
    Ok(snapshots)
}
