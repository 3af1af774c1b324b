//! Helpers of the controller tests (each such test file includes this module): random
//! vectors and random parameters from a seeded generator.
#![allow(dead_code)]

use rand::Rng;
use rand_chacha::ChaCha8Rng;
use vsr::controllers::Controller;

/// `len` values uniform in (-scale, scale).
pub fn random_vec(rng: &mut ChaCha8Rng, len: usize, scale: f32) -> Vec<f32> {
    (0..len).map(|_| rng.gen_range(-scale..scale)).collect()
}

/// Random parameters for `c`, uniform in (-scale, scale).
pub fn random_params(c: &mut dyn Controller, rng: &mut ChaCha8Rng, scale: f32) {
    let p = random_vec(rng, c.param_count(), scale);
    c.set_params(&p).unwrap();
}
