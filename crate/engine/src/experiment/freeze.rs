//! Freezing the attention of a walking robot: the ablation's freeze (SPEC 7, paper Fig. 6)
//! done at the current moment of a running episode, and released again.
//!
//! An episode built with [`freezable_policy`] is driven by a [`FrozenAttention`] for an
//! attention genome: until frozen it computes exactly what [`Attention`] computes (the same
//! calls, bit for bit), so it walks as `vsr evaluate` does. [`Episode::set_attention_frozen`]
//! keeps every voxel's current matrix from then on (the controller's own freeze, the one the
//! ablation uses) while the live readings still go through it; releasing goes back to
//! recomputing the matrices at every control call. Other controllers are built as usual
//! and refuse to freeze.

use super::episode::{topology, Episode, Policy};
use super::evaluate::controller_for;
use crate::controllers::{
    expand_any_body, local_inputs, Attention, Controller, ControllerKind, FrozenAttention,
    LocalInputs,
};
use crate::error::{Error, Result};
use crate::simulation::Shape;

/// The policy of `kind` with `genome` on `shape`, freezable when it is attention.
pub fn freezable_policy(kind: ControllerKind, shape: &Shape, genome: &[f32]) -> Result<Policy> {
    let controller = controller_for(kind, shape, genome)?;
    let genome = match kind {
        ControllerKind::Attention => genome.to_vec(),
        // The classic attention genome it amounts to on this body (the same network).
        ControllerKind::AttentionAny => expand_any_body(
            ControllerKind::Attention,
            genome,
            &local_inputs(&topology(shape), LocalInputs::CHOSEN),
        ),
        _ => return Ok(Policy::Brain(controller)),
    };
    let mut attention = Attention::new(shape.voxel_count());
    attention.set_params(&genome)?;
    Ok(Policy::Brain(Box::new(FrozenAttention::new(attention))))
}

impl Episode {
    /// Freezes (`true`) every voxel's attention matrix where it is now, or releases it
    /// (`false`). An error, changing nothing, when the policy cannot freeze (the phase gait,
    /// a controller without attention, or one not built by [`freezable_policy`]).
    pub fn set_attention_frozen(&mut self, frozen: bool) -> Result<()> {
        match self.policy_mut() {
            Policy::Brain(c) => c.set_attention_frozen(frozen),
            Policy::Gait(_) => Err(Error::Input(
                "the phase gait has no attention to freeze (give the robot an attention brain)"
                    .into(),
            )),
            Policy::External => Err(Error::Input(
                "an external policy has no attention to freeze".into(),
            )),
        }
    }

    /// True while the attention matrices are frozen.
    pub fn attention_frozen(&self) -> bool {
        match self.policy() {
            Policy::Brain(c) => c.attention_frozen(),
            Policy::Gait(_) | Policy::External => false,
        }
    }
}
