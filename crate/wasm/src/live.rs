//! The live side of the [`Episode`] handle for the page's lessons: freezing a walking
//! robot's attention and releasing it (`experiment::freeze`, the ablation's freeze), its
//! speed so far by the fitness definition, the steps left in an episode of a given length
//! (a race ends where `vsr evaluate` does), and the four numbers behind every entry of an
//! attention module's matrices (`controllers::attention_terms`).

use wasm_bindgen::prelude::{wasm_bindgen, JsError};

use super::Episode;
use vsr::controllers::{attention_terms as terms, ATTENTION_PARAMS};
use vsr::experiment::steps_for;

#[wasm_bindgen]
impl Episode {
    /// Freezes (`true`) every voxel's attention matrix where it is now, or releases it
    /// (`false`). Throws, changing nothing, when the brain has no attention (phase gait,
    /// MLP, MLP-Comm) or was built from a run file (`fromRunFile`).
    #[wasm_bindgen(js_name = freezeAttention)]
    pub fn freeze_attention(&mut self, frozen: bool) -> Result<(), JsError> {
        Ok(self.inner.set_attention_frozen(frozen)?)
    }

    /// True while the attention matrices are frozen.
    #[wasm_bindgen(getter, js_name = attentionFrozen)]
    pub fn attention_frozen(&self) -> bool {
        self.inner.attention_frozen()
    }

    /// The mean forward speed so far (m/s), as fitness defines it: the centre's x
    /// displacement from after the first step to now, over the time between (0 before the
    /// second step).
    #[wasm_bindgen(getter)]
    pub fn velocity(&self) -> f64 {
        self.inner.outcome().velocity
    }

    /// Steps still to take before an episode of `seconds` ends (the reference's step count
    /// for that length, as `vsr evaluate` runs it; 0 once there or past).
    #[wasm_bindgen(js_name = stepsLeft)]
    pub fn steps_left(&self, seconds: f64) -> f64 {
        let done = self.inner.world().steps();
        steps_for(seconds).saturating_sub(done) as f64
    }
}

/// The four numbers a, b, c, d of an attention genome (its first 32 genes) that fix every
/// entry of its matrices: `A[r][c] = tanh(a s_r s_c + b s_r + c s_c + d)`, s_r the row's
/// reading and s_c the column's. Throws on a genome shorter than the attention block.
#[wasm_bindgen(js_name = attentionTerms)]
pub fn attention_terms(genome: &[f32]) -> Result<Vec<f32>, JsError> {
    terms(genome).map(|t| t.to_vec()).ok_or_else(|| {
        JsError::new(&format!(
            "an attention genome starts with {ATTENTION_PARAMS} attention genes; this one has {}",
            genome.len()
        ))
    })
}
