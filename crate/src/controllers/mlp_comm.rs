//! Message-passing MLP baseline (SPEC 7): each voxel reads its 4 sensors plus the 4 messages
//! its neighbours sent at the PREVIOUS control call, and emits an actuation plus 4 messages.
//!
//! When is it called? [`MlpComm::new`] (`mlp-comm`) is called at every simulation step, as
//! SPEC 7 words it ("the messages received ... at the previous step"), so a message crosses
//! one voxel per 1/60 s. [`MlpComm::latched`] (`mlp-comm-latched`) is called only when the
//! actuation is latched (every k_act = 20 steps), as the original code does (2D-VSR-Sim's
//! `StepController` calls its inner controller, messages included, once per 0.33 s), so a
//! message crosses one voxel per 0.33 s. docs/RESULTS.md measures what the difference does.
//!
//! Input of voxel `i` (8 values, tanh applied as in the MLP baseline): `[area, vx, vy, touch,
//! from_up, from_right, from_down, from_left]`, where `from_d` is the message that the
//! neighbour in direction `d` addressed to `i` (0 where there is no neighbour, and at the first
//! call after `reset`). Outputs (5, tanh): `[actuation, to_up, to_right, to_down, to_left]`.
//! A message sent `to_up` by voxel `v` is received by `v`'s up neighbour as `from_down`.
//!
//! Genome layout (`(8 n + 1) x 5` floats: 405 biped, 445 comb): 5 rows of `8 n + 1`, one per
//! output `o` in the order above; in row `o`, slot `8 i + j` is the weight from input `j` of
//! voxel `i` (one-hot position encoding) and slot `8 n` is the bias. So output `o` of voxel `i`
//! is tanh(P[o (8n + 1) + 8 n] + sum_j P[o (8n + 1) + 8 i + j] tanh(x_j)).

use super::topology::opposite;
use super::{io_fits, Controller, Params, Topology, SENSORS_PER_VOXEL};
use libm::tanhf;

/// Outputs per voxel: 1 actuation + 4 directional messages.
pub(crate) const MLP_COMM_OUTPUTS: usize = 5;
/// Inputs per voxel: 4 readings + 4 received messages.
const INPUTS: usize = 8;

/// MLP-Comm controller; see the module doc for the message routing and genome layout.
#[derive(Debug, Clone)]
pub struct MlpComm {
    topology: Topology,
    params: Params,
    /// Messages each voxel sent at the previous call, `[to_up, to_right, to_down, to_left]`.
    sent: Vec<[f32; 4]>,
    /// Scratch for the messages being sent at this call.
    sending: Vec<[f32; 4]>,
    /// Called only when the actuation is latched (messages at the actuation's pace).
    latched: bool,
}

impl MlpComm {
    /// An MLP-Comm for `topology`, called at every step, with every parameter at zero and no
    /// messages in flight.
    pub fn new(topology: Topology) -> Self {
        let n = topology.voxel_count();
        Self {
            topology,
            params: Params::zeros(Self::param_count_for(n)),
            sent: vec![[0.0; 4]; n],
            sending: vec![[0.0; 4]; n],
            latched: false,
        }
    }

    /// The same controller, called only when the actuation is latched (the original's pace).
    pub(crate) fn latched(topology: Topology) -> Self {
        Self {
            latched: true,
            ..Self::new(topology)
        }
    }

    /// Genome length: (8 n + 1) x 5 (405 for the biped, 445 for the comb).
    pub fn param_count_for(n_voxels: usize) -> usize {
        (INPUTS * n_voxels + 1) * MLP_COMM_OUTPUTS
    }

    /// The 8 inputs of voxel `i`, tanh already applied.
    fn inputs(&self, i: usize, s: &[f32]) -> [f32; INPUTS] {
        let mut x = [0.0f32; INPUTS];
        for j in 0..SENSORS_PER_VOXEL {
            x[j] = tanhf(s[j]);
        }
        for d in 0..4 {
            if let Some(from) = self.topology.neighbour(i, d) {
                // The neighbour in direction d addressed us through its opposite side.
                x[SENSORS_PER_VOXEL + d] = tanhf(self.sent[from][opposite(d)]);
            }
        }
        x
    }

    /// Output `o` of voxel `i` for inputs `x`.
    fn output(&self, o: usize, i: usize, x: &[f32; INPUTS]) -> f32 {
        let n = self.topology.voxel_count();
        let row = &self.params[o * (INPUTS * n + 1)..(o + 1) * (INPUTS * n + 1)];
        let w = &row[INPUTS * i..INPUTS * (i + 1)];
        let sum: f32 = w.iter().zip(x).map(|(w, x)| w * x).sum();
        tanhf(row[INPUTS * n] + sum)
    }
}

impl Controller for MlpComm {
    fn genome(&self) -> &Params {
        &self.params
    }

    fn genome_mut(&mut self) -> &mut Params {
        &mut self.params
    }

    fn reset(&mut self) {
        self.sent.iter_mut().for_each(|m| *m = [0.0; 4]);
    }

    fn control(&mut self, sensors: &[f32], out: &mut [f32]) {
        if !io_fits(self.topology.voxel_count(), sensors, out) {
            return;
        }
        for (i, u) in out.iter_mut().enumerate() {
            let x = self.inputs(
                i,
                &sensors[SENSORS_PER_VOXEL * i..SENSORS_PER_VOXEL * (i + 1)],
            );
            *u = self.output(0, i, &x);
            for d in 0..4 {
                // A message toward a side with no neighbour is never read: not computed.
                self.sending[i][d] = match self.topology.neighbour(i, d) {
                    Some(_) => self.output(1 + d, i, &x),
                    None => 0.0,
                };
            }
        }
        // Messages computed now are delivered at the next call.
        std::mem::swap(&mut self.sent, &mut self.sending);
    }

    fn needs_every_step(&self) -> bool {
        !self.latched
    }

    fn attention(&self) -> Option<&[f32]> {
        None
    }
}
