//! Slow attention (SPEC 7): the attention controller whose matrix changes slowly.
//!
//! Genome layout (`32 + 4 n + 1 + 2` floats): the attention genome (see `attention`) followed
//! by two genes g1, g2 at the END. alpha = min(|g1|, 1), eta = min(|g2|, 1). At the first control
//! call after `reset`, A'(0) = A; at every later call A'(k) = alpha A + eta A'(k-1), where A is
//! computed from the live readings as in plain attention. The downstream uses A', and
//! `attention()` returns A' (16 floats per voxel). With alpha = 1, eta = 0 this is attention.

use super::attention::{attention_matrix, downstream};
use super::{io_fits, validate_params, Controller, ATTENTION_PARAMS, SENSORS_PER_VOXEL};
use crate::Result;

/// Slow-attention controller; see the module doc for the genome layout and the update.
#[derive(Debug, Clone)]
pub struct SlowAttention {
    n: usize,
    params: Vec<f32>,
    /// A' of every voxel, 16 floats per voxel.
    slow: Vec<f32>,
    /// False until the first control call after a reset (then A' starts at A).
    started: bool,
}

impl SlowAttention {
    /// A slow-attention controller for `n_voxels` voxels with every parameter at zero.
    pub fn new(n_voxels: usize) -> Self {
        Self {
            n: n_voxels,
            params: vec![0.0; Self::param_count_for(n_voxels)],
            slow: vec![0.0; 16 * n_voxels],
            started: false,
        }
    }

    /// Genome length: 32 + 4 n + 1 + 2 (75 for the biped, 79 for the comb).
    pub fn param_count_for(n_voxels: usize) -> usize {
        ATTENTION_PARAMS + SENSORS_PER_VOXEL * n_voxels + 3
    }

    /// Weight of the fresh matrix: min(|g1|, 1).
    pub fn alpha(&self) -> f32 {
        self.params[self.params.len() - 2].abs().min(1.0)
    }

    /// Weight of the previous matrix: min(|g2|, 1).
    pub fn eta(&self) -> f32 {
        self.params[self.params.len() - 1].abs().min(1.0)
    }

    /// Updates A' of every voxel from the live readings (lengths already checked).
    fn update(&mut self, sensors: &[f32]) {
        let (alpha, eta) = (self.alpha(), self.eta());
        let block = &self.params[..ATTENTION_PARAMS];
        let mut fresh = [0.0f32; 16];
        let rows = sensors.chunks_exact(SENSORS_PER_VOXEL);
        for (s, slow) in rows.zip(self.slow.chunks_exact_mut(16)) {
            attention_matrix(block, s, &mut fresh);
            for (a_prime, a) in slow.iter_mut().zip(&fresh) {
                *a_prime = if self.started {
                    alpha * a + eta * *a_prime
                } else {
                    *a
                };
            }
        }
        self.started = true;
    }
}

impl Controller for SlowAttention {
    fn param_count(&self) -> usize {
        self.params.len()
    }

    fn params(&self) -> Vec<f32> {
        self.params.clone()
    }

    fn set_params(&mut self, p: &[f32]) -> Result<()> {
        validate_params(self.params.len(), p)?;
        self.params.copy_from_slice(p);
        Ok(())
    }

    fn reset(&mut self) {
        self.slow.fill(0.0);
        self.started = false;
    }

    fn control(&mut self, sensors: &[f32], out: &mut [f32]) {
        if !io_fits(self.n, sensors, out) {
            return;
        }
        self.update(sensors);
        // The downstream block is the attention genome's tail, without g1 and g2.
        let down = &self.params[ATTENTION_PARAMS..self.params.len() - 2];
        for (i, u) in out.iter_mut().enumerate() {
            let s = &sensors[SENSORS_PER_VOXEL * i..SENSORS_PER_VOXEL * (i + 1)];
            *u = downstream(down, self.n, i, &self.slow[16 * i..16 * (i + 1)], s);
        }
    }

    fn needs_every_step(&self) -> bool {
        true
    }

    fn attention(&self) -> Option<&[f32]> {
        Some(&self.slow)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::controllers::test_util::random_vec;
    use crate::controllers::Attention;
    use rand::SeedableRng;
    use rand_chacha::ChaCha8Rng;

    #[test]
    fn alpha_and_eta_are_clamped_magnitudes() {
        let mut c = SlowAttention::new(1);
        let mut p = vec![0.0; c.param_count()];
        let len = p.len();
        p[len - 2] = -0.3;
        p[len - 1] = 2.5;
        c.set_params(&p).unwrap();
        assert_eq!(c.alpha(), 0.3);
        assert_eq!(c.eta(), 1.0);
    }

    #[test]
    fn slow_attention_with_eta_keeps_memory_of_the_previous_matrix() {
        let mut rng = ChaCha8Rng::seed_from_u64(17);
        let mut slow = SlowAttention::new(1);
        let mut p = random_vec(&mut rng, Attention::param_count_for(1), 1.5);
        p.extend([0.5, 0.5]);
        slow.set_params(&p).unwrap();
        let mut plain = Attention::new(1);
        plain.set_params(&p[..p.len() - 2]).unwrap();
        let (s0, s1) = (random_vec(&mut rng, 4, 1.0), random_vec(&mut rng, 4, 1.0));
        let mut out = [0.0];
        slow.control(&s0, &mut out);
        let a0 = slow.attention().unwrap().to_vec();
        plain.control(&s0, &mut out);
        assert_eq!(plain.attention().unwrap(), &a0[..], "A'(0) = A");
        slow.control(&s1, &mut out);
        plain.control(&s1, &mut out);
        let a1 = plain.attention().unwrap();
        for k in 0..16 {
            let want = 0.5 * a1[k] + 0.5 * a0[k];
            assert!((slow.attention().unwrap()[k] - want).abs() < 1e-6);
        }
    }
}
