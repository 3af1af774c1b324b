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

use super::tanh_lanes::tanhf_in_place;
use super::topology::opposite;
use super::{io_fits, Controller, Params, Topology, SENSORS_PER_VOXEL};

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
    /// Scratch: every voxel's 8 inputs after tanh, voxel after voxel.
    inputs: Vec<f32>,
    /// Scratch: every voxel's 5 outputs, voxel after voxel (tanh taken over all at once).
    outputs: Vec<f32>,
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
            inputs: vec![0.0; INPUTS * n],
            outputs: vec![0.0; MLP_COMM_OUTPUTS * n],
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

    /// Gathers every voxel's 8 inputs into `self.inputs` and applies tanh to all of them.
    /// A side with no neighbour reads 0 (tanh 0 = 0).
    fn gather_inputs(&mut self, sensors: &[f32]) {
        for (i, x) in self.inputs.chunks_exact_mut(INPUTS).enumerate() {
            x[..SENSORS_PER_VOXEL]
                .copy_from_slice(&sensors[SENSORS_PER_VOXEL * i..SENSORS_PER_VOXEL * (i + 1)]);
            for d in 0..4 {
                // The neighbour in direction d addressed us through its opposite side.
                x[SENSORS_PER_VOXEL + d] = match self.topology.neighbour(i, d) {
                    Some(from) => self.sent[from][opposite(d)],
                    None => 0.0,
                };
            }
        }
        tanhf_in_place(&mut self.inputs);
    }

    /// Output `o` of voxel `i` before its tanh, for the gathered inputs.
    fn pre_activation(&self, o: usize, i: usize) -> f32 {
        let n = self.topology.voxel_count();
        let row = &self.params[o * (INPUTS * n + 1)..(o + 1) * (INPUTS * n + 1)];
        let w = &row[INPUTS * i..INPUTS * (i + 1)];
        let x = &self.inputs[INPUTS * i..INPUTS * (i + 1)];
        let sum: f32 = w.iter().zip(x).map(|(w, x)| w * x).sum();
        row[INPUTS * n] + sum
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
        self.gather_inputs(sensors);
        for i in 0..out.len() {
            for o in 0..MLP_COMM_OUTPUTS {
                // A message toward a side with no neighbour is never read: not computed.
                let live = o == 0 || self.topology.neighbour(i, o - 1).is_some();
                self.outputs[MLP_COMM_OUTPUTS * i + o] =
                    if live { self.pre_activation(o, i) } else { 0.0 };
            }
        }
        tanhf_in_place(&mut self.outputs);
        for (i, (u, y)) in out
            .iter_mut()
            .zip(self.outputs.chunks_exact(MLP_COMM_OUTPUTS))
            .enumerate()
        {
            *u = y[0];
            self.sending[i].copy_from_slice(&y[1..]);
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
