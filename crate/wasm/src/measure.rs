//! The [`Episode`] handle's measure of its robot, the fitness's own: the distance of
//! `experiment::Episode::outcome` (the centre's x from after the first step; its velocity so
//! far is `live.rs`'s `velocity`), and the outcome at the end of an episode of a set length
//! (`steps_for`, the step count of `vsr evaluate` and of every fitness evaluation), so the
//! page shows the same number the training and the CLI compute, never one of its own.

use wasm_bindgen::prelude::{wasm_bindgen, JsError};

use super::Episode;
use vsr::experiment::steps_for;

#[wasm_bindgen]
impl Episode {
    /// Sets the episode's length to `seconds` of simulated time: when `step` reaches that
    /// many steps (`steps_for`), the outcome is taken ([`Self::episode_speed`]); the robot
    /// may walk on. Seconds that are not a positive number throw an `Error`.
    #[wasm_bindgen(js_name = measureOver)]
    pub fn measure_over(&mut self, seconds: f64) -> Result<(), JsError> {
        if !(seconds > 0.0 && seconds.is_finite()) {
            return Err(JsError::new(&format!(
                "an episode lasts a positive number of seconds, not {seconds}"
            )));
        }
        self.end = Some(steps_for(seconds));
        self.at_end = None;
        Ok(())
    }

    /// The robot's distance from its start (m): the centre's x now minus after the first
    /// step, as the fitness measures it; 0 before the first step.
    #[wasm_bindgen(getter)]
    pub fn distance(&self) -> f64 {
        self.inner.outcome().distance
    }

    /// Its mean forward velocity over the whole episode (m/s): what `vsr evaluate` prints
    /// for the same genome, terrain and seconds; NaN until the episode's length is reached
    /// (or when none was set).
    #[wasm_bindgen(getter, js_name = episodeSpeed)]
    pub fn episode_speed(&self) -> f64 {
        self.at_end.map_or(f64::NAN, |o| o.velocity)
    }
}
