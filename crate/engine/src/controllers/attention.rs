//! Local self-attention controller (SPEC 7), the paper's model, with d = 8.
//!
//! Genome layout (`32 + 4 n + 1` floats):
//! - `[0, 8)` w_q, `[8, 16)` b_q, `[16, 24)` w_k, `[24, 32)` b_k: the attention block, FIRST,
//!   and of the same size for every morphology (this is the block that transfers);
//! - `[32, 32 + 4 n)` the downstream weights W, slot `r n + i` linking reading `r` of voxel `i`;
//! - `[32 + 4 n]` the downstream bias b.
//!
//! Per voxel `i` with readings s (4): token r is the scalar s_r, so Q[r][k] = s_r w_q[k] + b_q[k]
//! and K[c][k] = s_c w_k[k] + b_k[k]; A = tanh(Q K^T / sqrt 8) (4x4, row-major, kept per voxel
//! in `attention`, 16 floats per voxel); u_i = tanh(b + sum_r W[r n + i] tanh((A s)_r)).

use super::{io_fits, Controller, Params, SENSORS_PER_VOXEL};
use libm::tanhf;

/// Width d of the query and key projections.
pub(crate) const ATTENTION_DIM: usize = 8;
/// Size of the attention block (w_q, b_q, w_k, b_k) at the start of the genome.
pub const ATTENTION_PARAMS: usize = 4 * ATTENTION_DIM;
/// sqrt(d) for d = 8, written so that it is the same f32 everywhere (x2 is exact).
const SQRT_DIM: f32 = 2.0 * core::f32::consts::SQRT_2;

/// Computes one voxel's attention matrix `a` (16, row-major) from the attention block
/// `block` (32) and its readings `s` (4).
fn attention_matrix(block: &[f32], s: &[f32], a: &mut [f32]) {
    let (w_q, rest) = block.split_at(ATTENTION_DIM);
    let (b_q, rest) = rest.split_at(ATTENTION_DIM);
    let (w_k, b_k) = rest.split_at(ATTENTION_DIM);
    let mut q = [[0.0f32; ATTENTION_DIM]; SENSORS_PER_VOXEL];
    let mut k = [[0.0f32; ATTENTION_DIM]; SENSORS_PER_VOXEL];
    for r in 0..SENSORS_PER_VOXEL {
        for j in 0..ATTENTION_DIM {
            q[r][j] = s[r] * w_q[j] + b_q[j];
            k[r][j] = s[r] * w_k[j] + b_k[j];
        }
    }
    for r in 0..SENSORS_PER_VOXEL {
        for c in 0..SENSORS_PER_VOXEL {
            let dot: f32 = q[r].iter().zip(&k[c]).map(|(x, y)| x * y).sum();
            a[r * SENSORS_PER_VOXEL + c] = tanhf(dot / SQRT_DIM);
        }
    }
}

/// The four numbers that fix every entry of an attention matrix: with readings s_r (row,
/// query) and s_c (column, key), `A[r][c] = tanh(a s_r s_c + b s_r + c s_c + d)`, where
/// a = w_q.w_k, b = w_q.b_k, c = b_q.w_k, d = b_q.b_k, each over sqrt 8 (expanding the dot
/// product of Q's row r and K's row c). `block` is the 32-gene attention block; returns
/// [a, b, c, d] (rounding aside, the matrix itself is computed as the dot product).
pub fn attention_terms(block: &[f32]) -> Option<[f32; 4]> {
    if block.len() < ATTENTION_PARAMS {
        return None;
    }
    let part = |k: usize| &block[k * ATTENTION_DIM..(k + 1) * ATTENTION_DIM];
    let dot = |x: &[f32], y: &[f32]| x.iter().zip(y).map(|(p, q)| p * q).sum::<f32>() / SQRT_DIM;
    let (w_q, b_q, w_k, b_k) = (part(0), part(1), part(2), part(3));
    Some([dot(w_q, w_k), dot(w_q, b_k), dot(b_q, w_k), dot(b_q, b_k)])
}

/// The downstream output of voxel `i` of `n`, from the downstream block `down` (4n + 1),
/// the matrix `a` in use and the readings `s`.
fn downstream(down: &[f32], n: usize, i: usize, a: &[f32], s: &[f32]) -> f32 {
    let mut sum = down[SENSORS_PER_VOXEL * n];
    for r in 0..SENSORS_PER_VOXEL {
        let row = &a[r * SENSORS_PER_VOXEL..(r + 1) * SENSORS_PER_VOXEL];
        let attended: f32 = row.iter().zip(s).map(|(x, y)| x * y).sum();
        sum += down[r * n + i] * tanhf(attended);
    }
    tanhf(sum)
}

/// Attention controller for `n` voxels; see the module doc for the genome layout.
#[derive(Debug, Clone)]
pub struct Attention {
    n: usize,
    params: Params,
    /// Current A of every voxel, 16 floats per voxel (zero until the first control call).
    attention: Vec<f32>,
}

impl Attention {
    /// An attention controller for `n_voxels` voxels with every parameter at zero.
    pub fn new(n_voxels: usize) -> Self {
        Self {
            n: n_voxels,
            params: Params::zeros(Self::param_count_for(n_voxels)),
            attention: vec![0.0; 16 * n_voxels],
        }
    }

    /// Genome length: 32 + 4 n + 1 (73 for the biped, 77 for the comb).
    pub fn param_count_for(n_voxels: usize) -> usize {
        ATTENTION_PARAMS + SENSORS_PER_VOXEL * n_voxels + 1
    }

    /// Number of voxels this controller drives.
    pub(crate) fn voxel_count(&self) -> usize {
        self.n
    }

    /// Recomputes every voxel's A from its readings (lengths already checked).
    pub(crate) fn update_attention(&mut self, sensors: &[f32]) {
        let block = &self.params[..ATTENTION_PARAMS];
        let rows = sensors.chunks_exact(SENSORS_PER_VOXEL);
        for (s, a) in rows.zip(self.attention.chunks_exact_mut(16)) {
            attention_matrix(block, s, a);
        }
    }

    /// Applies the stored A of every voxel to the live readings (lengths already checked).
    pub(crate) fn apply_attention(&self, sensors: &[f32], out: &mut [f32]) {
        self.apply_matrices(&self.attention, sensors, out);
    }

    /// Applies `matrices` (16 floats per voxel, in place of the stored A) to the live
    /// readings through the downstream block (lengths already checked).
    pub(crate) fn apply_matrices(&self, matrices: &[f32], sensors: &[f32], out: &mut [f32]) {
        let down = &self.params[ATTENTION_PARAMS..];
        for (i, u) in out.iter_mut().enumerate() {
            let s = &sensors[SENSORS_PER_VOXEL * i..SENSORS_PER_VOXEL * (i + 1)];
            *u = downstream(down, self.n, i, &matrices[16 * i..16 * (i + 1)], s);
        }
    }

    /// Mutable access to the stored matrices (used by the frozen wrapper).
    pub(crate) fn attention_mut(&mut self) -> &mut [f32] {
        &mut self.attention
    }
}

impl Controller for Attention {
    fn genome(&self) -> &Params {
        &self.params
    }

    fn genome_mut(&mut self) -> &mut Params {
        &mut self.params
    }

    fn reset(&mut self) {
        self.attention.fill(0.0);
    }

    fn control(&mut self, sensors: &[f32], out: &mut [f32]) {
        if io_fits(self.n, sensors, out) {
            self.update_attention(sensors);
            self.apply_attention(sensors, out);
        }
    }

    fn needs_every_step(&self) -> bool {
        false
    }

    fn attention(&self) -> Option<&[f32]> {
        Some(&self.attention)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::controllers::test_util::random_vec;
    use rand::SeedableRng;
    use rand_chacha::ChaCha8Rng;

    #[test]
    fn zero_block_gives_zero_attention_and_tanh_bias_output() {
        let mut c = Attention::new(2);
        let mut p = vec![0.0; c.param_count()];
        *p.last_mut().unwrap() = 0.5;
        c.set_params(&p).unwrap();
        let mut out = [0.0; 2];
        c.control(&[0.3, 0.4, 0.5, 1.0, 0.1, 0.2, 0.3, 0.0], &mut out);
        assert!(c.attention().unwrap().iter().all(|&a| a == 0.0));
        assert_eq!(out, [tanhf(0.5), tanhf(0.5)]);
    }

    #[test]
    fn attention_terms_give_every_matrix_entry() {
        let mut rng = ChaCha8Rng::seed_from_u64(21);
        let block = random_vec(&mut rng, ATTENTION_PARAMS, 3.0);
        let s = random_vec(&mut rng, 4, 1.0);
        let mut a = [0.0; 16];
        attention_matrix(&block, &s, &mut a);
        let [ta, tb, tc, td] = attention_terms(&block).unwrap();
        for r in 0..4 {
            for c in 0..4 {
                let expanded = tanhf(ta * s[r] * s[c] + tb * s[r] + tc * s[c] + td);
                assert!((expanded - a[r * 4 + c]).abs() < 1e-4, "{r} {c}");
            }
        }
        assert!(attention_terms(&block[..31]).is_none());
    }

    #[test]
    fn attention_block_transfers_between_shapes() {
        let mut rng = ChaCha8Rng::seed_from_u64(14);
        let block = random_vec(&mut rng, ATTENTION_PARAMS, 1.0);
        let s = random_vec(&mut rng, 4, 1.0);
        let mut small = Attention::new(10);
        let mut large = Attention::new(18);
        for (c, n) in [(&mut small, 10), (&mut large, 18)] {
            let mut p = block.clone();
            p.extend(random_vec(&mut rng, 4 * n + 1, 1.0));
            c.set_params(&p).unwrap();
            let sensors: Vec<f32> = s.iter().cycle().take(4 * n).copied().collect();
            c.control(&sensors, &mut vec![0.0; n]);
        }
        assert_eq!(
            small.attention().unwrap()[..16],
            large.attention().unwrap()[..16]
        );
    }
}
