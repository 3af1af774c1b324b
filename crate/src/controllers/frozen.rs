//! Frozen attention (SPEC 7 ablation): an attention controller whose matrices stop changing.
//!
//! Before `freeze()` it is plain [`Attention`]. After it, each voxel keeps the A it had at
//! that moment (16 floats per voxel, row-major, as in `attention()`) and applies it to the
//! live readings: u_i = tanh(b + sum_r W[r n + i] tanh((A_frozen s)_r)). `reset()` keeps the
//! frozen matrices, so a fresh episode can run with them. The genome layout is the attention one.

use super::{io_fits, Attention, Controller, ATTENTION_FLOATS_PER_VOXEL};
use crate::{Error, Result};

/// Attention whose per-voxel matrices can be frozen; see the module doc.
#[derive(Debug, Clone)]
pub struct FrozenAttention {
    inner: Attention,
    frozen: bool,
}

impl FrozenAttention {
    /// Wraps an attention controller (its parameters and current matrices are kept).
    pub fn new(inner: Attention) -> Self {
        Self {
            inner,
            frozen: false,
        }
    }

    /// Keeps every voxel's current A from now on. Freezing before any control call freezes
    /// all-zero matrices.
    pub fn freeze(&mut self) {
        self.frozen = true;
    }

    /// Freezes the given matrices (16 floats per voxel, e.g. recorded from another episode).
    /// Fails on a wrong length or a non-finite value.
    pub fn freeze_with(&mut self, matrices: &[f32]) -> Result<()> {
        let expected = ATTENTION_FLOATS_PER_VOXEL * self.inner.voxel_count();
        if matrices.len() != expected {
            return Err(Error::Input(format!(
                "expected {expected} attention values (16 per voxel), got {}",
                matrices.len()
            )));
        }
        if matrices.iter().any(|v| !v.is_finite()) {
            return Err(Error::Input("attention values must be finite".into()));
        }
        self.inner.attention_mut().copy_from_slice(matrices);
        self.frozen = true;
        Ok(())
    }

    /// Goes back to recomputing A at every call.
    pub fn unfreeze(&mut self) {
        self.frozen = false;
    }

    /// True once `freeze` (or `freeze_with`) has been called, until `unfreeze`.
    pub fn is_frozen(&self) -> bool {
        self.frozen
    }
}

impl Controller for FrozenAttention {
    fn param_count(&self) -> usize {
        self.inner.param_count()
    }

    fn params(&self) -> Vec<f32> {
        self.inner.params()
    }

    fn set_params(&mut self, p: &[f32]) -> Result<()> {
        self.inner.set_params(p)
    }

    fn reset(&mut self) {
        if !self.frozen {
            self.inner.reset();
        }
    }

    fn control(&mut self, sensors: &[f32], out: &mut [f32]) {
        if !io_fits(self.inner.voxel_count(), sensors, out) {
            return;
        }
        if !self.frozen {
            self.inner.update_attention(sensors);
        }
        self.inner.apply_attention(sensors, out);
    }

    fn needs_every_step(&self) -> bool {
        false
    }

    fn attention(&self) -> Option<&[f32]> {
        self.inner.attention()
    }
}
