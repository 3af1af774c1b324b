//! Jobs evaluated together (issue 30, section 1): [`LANES`] episodes of the same body at a
//! time, stepped in lockstep with their springs in SIMD lanes ([`Lockstep`]), each
//! controller, sensor and the rest of each step per episode. Every fitness is the one
//! [`Job::fitness`] gives, bit for bit (tested in `tests/together.rs`); jobs that cannot
//! share lanes (a last group of fewer than [`LANES`], different bodies or lengths, a
//! genome or terrain that does not build) are evaluated alone.

use super::config::check_seconds;
use super::episode::{steps_for, Episode, Policy};
use super::evaluate::controller_for;
use super::evolution::Job;
use super::ground::ground;
use crate::error::Result;
use crate::simulation::lockstep::{Lockstep, LANES};
use crate::simulation::World;
use std::sync::Arc;

/// The fitness of every job, in order, as [`Job::fitness`] gives each (errors included).
pub fn fitness_together(jobs: &[Job]) -> Result<Vec<f64>> {
    let mut out = Vec::with_capacity(jobs.len());
    for chunk in jobs.chunks(LANES) {
        match episodes(chunk) {
            Some(mut episodes) => out.extend(run_together(&mut episodes, chunk[0].seconds)),
            None => {
                for job in chunk {
                    out.push(job.fitness()?);
                }
            }
        }
    }
    Ok(out)
}

/// The fresh episodes of [`LANES`] jobs that can share lanes, or None.
fn episodes(chunk: &[Job]) -> Option<Vec<Episode>> {
    let first = chunk.first()?;
    let alike = |j: &Job| j.shape == first.shape && j.seconds.to_bits() == first.seconds.to_bits();
    if chunk.len() != LANES || !chunk.iter().all(alike) || check_seconds(first.seconds).is_err() {
        return None;
    }
    chunk.iter().map(episode).collect()
}

/// The episode [`Job::fitness`] runs, when it builds without error.
fn episode(job: &Job) -> Option<Episode> {
    let terrain = match &job.ground {
        Some(shared) if shared.name() == job.terrain.trim() => Arc::clone(shared),
        _ => ground(&job.terrain).ok()?,
    };
    let controller = controller_for(job.controller, &job.shape, &job.genome).ok()?;
    let policy = Policy::Brain(controller);
    Some(Episode::with_policy(
        &job.shape,
        terrain,
        policy,
        Some(job.noise_seed),
    ))
}

/// Runs fresh episodes of one body, one per lane, to `seconds`: their velocities, NaN
/// for an episode whose simulation became non-finite (as [`Job::fitness`]).
fn run_together(episodes: &mut [Episode], seconds: f64) -> Vec<f64> {
    let worlds: Vec<&World> = episodes.iter().map(|e| &e.world).collect();
    let mut lock = Lockstep::new(&worlds);
    for _ in 0..steps_for(seconds) {
        let mut worlds: Vec<&mut World> = episodes.iter_mut().map(|e| &mut e.world).collect();
        lock.step(&mut worlds);
        episodes.iter_mut().for_each(Episode::after_step);
    }
    let velocity = |e: &Episode| e.check().map_or(f64::NAN, |()| e.outcome().velocity);
    episodes.iter().map(velocity).collect()
}
