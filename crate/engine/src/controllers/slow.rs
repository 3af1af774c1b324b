//! Slow attention (SPEC 7): the attention controller whose matrix changes slowly. It wraps
//! [`Attention`] (as frozen attention does) and owns only what it adds: two genes and A'.
//!
//! Genome layout (`32 + 4 n + 1 + 2` floats): the attention genome (see `attention`) followed
//! by the [`SLOW_GENES`] = 2 genes g1, g2 at the END; alpha = min(|g1|, 1), eta = min(|g2|, 1)
//! ([`split_slow_genome`] is the one place that reads them). At the first control call after
//! `reset`, A'(0) = A; at every later call A'(k) = alpha A + eta A'(k-1), where A is computed
//! from the live readings as in plain attention. The downstream uses A', and `attention()`
//! returns A' (16 floats per voxel). With alpha = 1, eta = 0 this is attention.

use super::{io_fits, Attention, Controller, Params, ATTENTION_FLOATS_PER_VOXEL};
use crate::Result;

/// Genes slow attention appends to the attention genome: g1 (alpha), then g2 (eta).
pub(crate) const SLOW_GENES: usize = 2;

/// The two rates of slow attention, derived from its last two genes.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct SlowRates {
    /// Weight of the fresh matrix: min(|g1|, 1).
    pub(crate) alpha: f32,
    /// Weight of the previous matrix: min(|g2|, 1).
    pub(crate) eta: f32,
}

/// Splits a slow-attention genome into its attention genome and its rates; `None` when it is
/// too short to hold the two genes.
pub(crate) fn split_slow_genome(genome: &[f32]) -> Option<(&[f32], SlowRates)> {
    let cut = genome.len().checked_sub(SLOW_GENES)?;
    let (attention, genes) = genome.split_at(cut);
    let rates = SlowRates {
        alpha: genes[0].abs().min(1.0),
        eta: genes[1].abs().min(1.0),
    };
    Some((attention, rates))
}

/// Slow-attention controller; see the module doc for the genome layout and the update.
#[derive(Debug, Clone)]
pub struct SlowAttention {
    /// Plain attention holding the genome without the two slow genes; computes A.
    inner: Attention,
    /// The whole genome (attention genome, g1, g2).
    params: Params,
    rates: SlowRates,
    /// A' of every voxel, 16 floats per voxel.
    slow: Vec<f32>,
    /// False until the first control call after a reset (then A' starts at A).
    started: bool,
}

impl SlowAttention {
    /// A slow-attention controller for `n_voxels` voxels with every parameter at zero.
    pub fn new(n_voxels: usize) -> Self {
        Self {
            inner: Attention::new(n_voxels),
            params: Params::zeros(Self::param_count_for(n_voxels)),
            rates: SlowRates {
                alpha: 0.0,
                eta: 0.0,
            },
            slow: vec![0.0; ATTENTION_FLOATS_PER_VOXEL * n_voxels],
            started: false,
        }
    }

    /// Genome length: 32 + 4 n + 1 + 2 (75 for the biped, 79 for the comb).
    pub(crate) fn param_count_for(n_voxels: usize) -> usize {
        Attention::param_count_for(n_voxels) + SLOW_GENES
    }

    /// Weight of the fresh matrix: min(|g1|, 1).
    pub fn alpha(&self) -> f32 {
        self.rates.alpha
    }

    /// Weight of the previous matrix: min(|g2|, 1).
    pub fn eta(&self) -> f32 {
        self.rates.eta
    }

    /// Updates A' of every voxel from the fresh A the inner attention just computed.
    fn blend(&mut self) {
        let SlowRates { alpha, eta } = self.rates;
        let fresh = self.inner.attention().unwrap_or_default();
        for (a_prime, a) in self.slow.iter_mut().zip(fresh) {
            *a_prime = if self.started {
                alpha * a + eta * *a_prime
            } else {
                *a
            };
        }
        self.started = true;
    }
}

impl Controller for SlowAttention {
    fn genome(&self) -> &Params {
        &self.params
    }

    fn genome_mut(&mut self) -> &mut Params {
        &mut self.params
    }

    fn set_params(&mut self, p: &[f32]) -> Result<()> {
        self.params.set(p)?;
        // Length and values are checked, so the split exists and the inner genome fits.
        if let Some((attention, rates)) = split_slow_genome(p) {
            self.inner.set_params(attention)?;
            self.rates = rates;
        }
        Ok(())
    }

    fn reset(&mut self) {
        self.inner.reset();
        self.slow.fill(0.0);
        self.started = false;
    }

    fn control(&mut self, sensors: &[f32], out: &mut [f32]) {
        if !io_fits(self.inner.voxel_count(), sensors, out) {
            return;
        }
        self.inner.update_attention(sensors);
        self.blend();
        self.inner.apply_matrices(&self.slow, sensors, out);
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
