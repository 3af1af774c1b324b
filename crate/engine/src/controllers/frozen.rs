//! Frozen attention (SPEC 7 ablation): an attention controller whose matrices stop changing.
//!
//! Before `freeze()` it is plain [`Attention`]. After it, each voxel keeps the A it had at
//! that moment (16 floats per voxel, row-major, as in `attention()`) and applies it to the
//! live readings: u_i = tanh(b + sum_r W[r n + i] tanh((A_frozen s)_r)). `reset()` keeps the
//! frozen matrices, so a fresh episode can run with them. The genome layout is the attention one.

use super::{io_fits, Attention, Controller, Params, ATTENTION_FLOATS_PER_VOXEL};
use crate::{Error, Result};

/// Attention whose per-voxel matrices can be frozen; see the module doc.
#[derive(Debug, Clone)]
pub(crate) struct FrozenAttention {
    inner: Attention,
    frozen: bool,
}

impl FrozenAttention {
    /// Wraps an attention controller (its parameters and current matrices are kept).
    pub(crate) fn new(inner: Attention) -> Self {
        Self {
            inner,
            frozen: false,
        }
    }

    /// Keeps every voxel's current A from now on. Freezing before any control call freezes
    /// all-zero matrices.
    pub(crate) fn freeze(&mut self) {
        self.frozen = true;
    }

    /// Freezes the given matrices (16 floats per voxel, e.g. recorded from another episode).
    /// Fails on a wrong length or a non-finite value.
    pub(crate) fn freeze_with(&mut self, matrices: &[f32]) -> Result<()> {
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
    pub(crate) fn unfreeze(&mut self) {
        self.frozen = false;
    }

    /// True once `freeze` (or `freeze_with`) has been called, until `unfreeze`.
    pub(crate) fn is_frozen(&self) -> bool {
        self.frozen
    }
}

impl Controller for FrozenAttention {
    fn genome(&self) -> &Params {
        self.inner.genome()
    }

    fn genome_mut(&mut self) -> &mut Params {
        self.inner.genome_mut()
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

    fn set_attention_frozen(&mut self, frozen: bool) -> Result<()> {
        if frozen {
            self.freeze();
        } else {
            self.unfreeze();
        }
        Ok(())
    }

    fn attention_frozen(&self) -> bool {
        self.is_frozen()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::controllers::test_util::random_vec;
    use rand::SeedableRng;
    use rand_chacha::ChaCha8Rng;

    #[test]
    fn frozen_attention_keeps_a_while_sensors_still_drive_the_output() {
        let mut rng = ChaCha8Rng::seed_from_u64(18);
        let n = 3;
        let mut plain = Attention::new(n);
        let p = random_vec(&mut rng, plain.param_count(), 1.5);
        plain.set_params(&p).unwrap();
        let mut frozen = FrozenAttention::new(plain.clone());
        let s0 = random_vec(&mut rng, 4 * n, 1.0);
        let (mut u_plain, mut u_frozen) = (vec![0.0; n], vec![0.0; n]);
        plain.control(&s0, &mut u_plain);
        frozen.control(&s0, &mut u_frozen);
        assert_eq!(u_plain, u_frozen, "before freeze it is plain attention");
        frozen.freeze();
        let a_frozen = frozen.attention().unwrap().to_vec();
        let mut outputs = Vec::new();
        for _ in 0..5 {
            let s = random_vec(&mut rng, 4 * n, 1.0);
            frozen.control(&s, &mut u_frozen);
            plain.control(&s, &mut u_plain);
            assert_eq!(frozen.attention().unwrap(), &a_frozen[..], "A stays fixed");
            assert_ne!(
                plain.attention().unwrap(),
                &a_frozen[..],
                "while plain A moves"
            );
            outputs.push(u_frozen.clone());
        }
        assert!(
            outputs.windows(2).all(|w| w[0] != w[1]),
            "live sensors still matter"
        );
        frozen.reset();
        assert_eq!(
            frozen.attention().unwrap(),
            &a_frozen[..],
            "a fresh episode keeps A"
        );
        assert!(frozen.freeze_with(&[0.0; 5]).is_err());
    }
}
