//! Seeded randomness shared by every layer: the portable generator and a standard
//! normal draw built only from IEEE arithmetic and `libm`, so native and wasm draw
//! bit-identical numbers (rand_distr's samplers may use the platform's `exp`/`ln`).

use rand::{Rng, SeedableRng};

/// The project's generator: ChaCha8, portable across platforms and word sizes.
pub(crate) type ProjectRng = rand_chacha::ChaCha8Rng;

/// A generator seeded from a 64-bit seed.
pub fn rng_from(seed: u64) -> ProjectRng {
    ProjectRng::seed_from_u64(seed)
}

/// One N(0, 1) draw by Marsaglia's polar method (the second value is discarded).
pub fn standard_normal(rng: &mut impl Rng) -> f64 {
    loop {
        let u = 2.0 * rng.gen::<f64>() - 1.0;
        let v = 2.0 * rng.gen::<f64>() - 1.0;
        let s = u * u + v * v;
        if s > 0.0 && s < 1.0 {
            // f64::sqrt: correctly rounded like libm::sqrt, but one instruction in wasm.
            return u * (-2.0 * libm::log(s) / s).sqrt();
        }
    }
}

/// A stream of N(0, 1) draws by the polar method that keeps the second value of each
/// pair (as Java's `nextGaussian` does): half the logarithms of [`standard_normal`].
#[derive(Debug, Clone)]
pub(crate) struct NormalStream {
    rng: ProjectRng,
    spare: Option<f64>,
}

impl NormalStream {
    /// A stream seeded from `seed`.
    pub(crate) fn new(seed: u64) -> Self {
        NormalStream {
            rng: rng_from(seed),
            spare: None,
        }
    }

    /// The next N(0, 1) draw.
    pub(crate) fn draw(&mut self) -> f64 {
        if let Some(z) = self.spare.take() {
            return z;
        }
        loop {
            let u = 2.0 * self.rng.gen::<f64>() - 1.0;
            let v = 2.0 * self.rng.gen::<f64>() - 1.0;
            let s = u * u + v * v;
            if s > 0.0 && s < 1.0 {
                let m = (-2.0 * libm::log(s) / s).sqrt();
                self.spare = Some(v * m);
                return u * m;
            }
        }
    }
}
