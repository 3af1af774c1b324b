//! Controllers: the brain every voxel runs. A controller sees only sensor rows and a
//! neighbour table ([`Topology`]), never the world, and maps readings to actuations.
//!
//! Data layout shared by every controller:
//! - `sensors`: 4 readings per voxel in voxel index order, `[area, vx, vy, touch]`, so voxel
//!   `i`'s readings are `sensors[4 i .. 4 i + 4]` (length `4 n`);
//! - `out`: one actuation per voxel in voxel index order, in [-1, 1] (length `n`);
//! - `params`: a flat `f32` genome whose layout each controller module documents;
//! - `attention()`: 16 floats per voxel, voxel `i`'s row-major 4x4 matrix at `[16 i .. 16 i + 16]`.
//!
//! If the lengths of `sensors` or `out` do not match the topology, `control` writes zeros to
//! `out` and does nothing else (check once per episode with [`check_io`]).

mod any_body;
mod attention;
mod frozen;
mod kind;
mod layout;
mod local_inputs;
mod mlp;
mod mlp_comm;
mod params;
mod slow;
mod tanh_lanes;
mod topology;

pub(crate) use any_body::expand as expand_any_body;
pub use any_body::AnyBody;
pub use attention::{attention_terms, Attention, ATTENTION_PARAMS};
pub(crate) use frozen::FrozenAttention;
pub use kind::{build, ControllerKind};
pub use layout::remap_genome;
pub(crate) use layout::GenomeLayout;
pub use local_inputs::{local_inputs, local_inputs_masked, LocalInputs, LOCAL_INPUTS};
pub use mlp::Mlp;
pub use mlp_comm::MlpComm;
pub use params::Params;
pub(crate) use slow::split_slow_genome;
pub use slow::SlowAttention;
pub use topology::Topology;

use crate::{Error, Result};

/// Number of sensor readings per voxel: area, vx, vy, touch.
pub const SENSORS_PER_VOXEL: usize = 4;
/// Number of floats per voxel in an attention matrix (4x4, row-major).
pub(crate) const ATTENTION_FLOATS_PER_VOXEL: usize = 16;

/// A voxel controller: the same parameters drive every voxel of a robot.
pub trait Controller: Send {
    /// The stored genome, in the controller's documented layout.
    fn genome(&self) -> &Params;
    /// The stored genome, to replace through `Params::set` (which checks it).
    fn genome_mut(&mut self) -> &mut Params;
    /// Length of the genome this controller reads.
    fn param_count(&self) -> usize {
        self.genome().len()
    }
    /// The current parameters, in the controller's documented genome layout.
    fn params(&self) -> Vec<f32> {
        self.genome().to_vec()
    }
    /// Replaces the parameters. Fails, leaving the controller unchanged, on a length mismatch
    /// or a non-finite value.
    fn set_params(&mut self, p: &[f32]) -> Result<()> {
        self.genome_mut().set(p)
    }
    /// Clears the state carried between control calls (messages, slow attention), as at the
    /// start of an episode.
    fn reset(&mut self);
    /// Computes one actuation per voxel from 4 readings per voxel (see the module doc).
    fn control(&mut self, sensors: &[f32], out: &mut [f32]);
    /// True when the controller has state, so it must be called at every step (not only
    /// when the actuation is latched).
    fn needs_every_step(&self) -> bool;
    /// Each voxel's current attention matrix (16 floats per voxel), or `None` for
    /// controllers without attention.
    fn attention(&self) -> Option<&[f32]>;
    /// Freezes (`true`) every voxel's attention matrix where it is now, or releases it
    /// (`false`), as the ablation does (SPEC 7). Only `FrozenAttention` can; any other
    /// controller answers an error saying it has no attention to freeze.
    fn set_attention_frozen(&mut self, _frozen: bool) -> Result<()> {
        Err(Error::Input(
            "this brain has no attention to freeze (only an attention controller has)".into(),
        ))
    }
    /// True while the attention matrices are frozen.
    fn attention_frozen(&self) -> bool {
        false
    }
}

/// Checks that `sensors` and `out` have the lengths a controller for `n_voxels` expects.
pub fn check_io(n_voxels: usize, sensors: &[f32], out: &[f32]) -> Result<()> {
    if sensors.len() != SENSORS_PER_VOXEL * n_voxels {
        return Err(Error::Input(format!(
            "expected {} sensor readings (4 for each of {n_voxels} voxels), got {}",
            SENSORS_PER_VOXEL * n_voxels,
            sensors.len()
        )));
    }
    if out.len() != n_voxels {
        return Err(Error::Input(format!(
            "expected room for {n_voxels} actuations, got {}",
            out.len()
        )));
    }
    Ok(())
}

/// True when the lengths fit; otherwise zeroes `out` so a bad call actuates nothing.
pub(crate) fn io_fits(n_voxels: usize, sensors: &[f32], out: &mut [f32]) -> bool {
    let fits = check_io(n_voxels, sensors, out).is_ok();
    if !fits {
        out.fill(0.0);
    }
    fits
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bad_io_lengths_zero_the_output() {
        let mut out = [0.5; 3];
        assert!(!io_fits(3, &[0.0; 11], &mut out));
        assert_eq!(out, [0.0; 3]);
        assert!(io_fits(3, &[0.0; 12], &mut out));
    }
}

/// Helpers shared by the controllers' unit tests.
#[cfg(test)]
pub(crate) mod test_util {
    use rand::Rng;
    use rand_chacha::ChaCha8Rng;

    /// `len` values drawn uniformly from (-scale, scale).
    pub fn random_vec(rng: &mut ChaCha8Rng, len: usize, scale: f32) -> Vec<f32> {
        (0..len).map(|_| rng.gen_range(-scale..scale)).collect()
    }
}
