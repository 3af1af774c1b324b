//! Communication-less MLP baseline (SPEC 7): no hidden layer, tanh on inputs and output.
//!
//! Genome layout (`4 n + 1` floats): `[0, 4 n)` the weights W, slot `4 i + j` linking reading
//! `j` of voxel `i` (the one-hot position encoding: voxel `i` only sees its own 4 slots), then
//! `[4 n]` the bias b. Output: u_i = tanh(b + sum_j W[4 i + j] tanh(s_j)).

use super::{io_fits, Controller, Params, SENSORS_PER_VOXEL};
use libm::tanhf;

/// MLP controller for `n` voxels; see the module doc for the genome layout.
#[derive(Debug, Clone)]
pub struct Mlp {
    n: usize,
    params: Params,
}

impl Mlp {
    /// An MLP for `n_voxels` voxels with every parameter at zero.
    pub(crate) fn new(n_voxels: usize) -> Self {
        Self {
            n: n_voxels,
            params: Params::zeros(Self::param_count_for(n_voxels)),
        }
    }

    /// Genome length: 4 n + 1 (41 for the biped, 45 for the comb).
    pub(crate) fn param_count_for(n_voxels: usize) -> usize {
        SENSORS_PER_VOXEL * n_voxels + 1
    }
}

impl Controller for Mlp {
    fn genome(&self) -> &Params {
        &self.params
    }

    fn genome_mut(&mut self) -> &mut Params {
        &mut self.params
    }

    fn reset(&mut self) {}

    fn control(&mut self, sensors: &[f32], out: &mut [f32]) {
        if !io_fits(self.n, sensors, out) {
            return;
        }
        let bias = self.params[SENSORS_PER_VOXEL * self.n];
        let weights = self.params.chunks_exact(SENSORS_PER_VOXEL);
        let rows = sensors.chunks_exact(SENSORS_PER_VOXEL);
        for ((u, w), s) in out.iter_mut().zip(weights).zip(rows) {
            let sum: f32 = w.iter().zip(s).map(|(w, s)| w * tanhf(*s)).sum();
            *u = tanhf(bias + sum);
        }
    }

    fn needs_every_step(&self) -> bool {
        false
    }

    fn attention(&self) -> Option<&[f32]> {
        None
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_voxel_uses_only_its_own_weights() {
        let mut c = Mlp::new(2);
        // Voxel 0 weights all 1, voxel 1 weights all 0, bias 0.
        c.set_params(&[1.0, 1.0, 1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0])
            .unwrap();
        let mut out = [9.0; 2];
        c.control(&[0.5, 0.0, 0.0, 0.0, 0.7, 0.7, 0.7, 0.7], &mut out);
        assert_eq!(out, [tanhf(tanhf(0.5)), 0.0]);
    }
}
