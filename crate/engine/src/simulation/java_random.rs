//! An exact replay of Java's `java.util.Random`, so that seeded terrains
//! (`hilly-1-10-SEED`) match the reference simulator vertex for vertex.
//!
//! State: a 48-bit linear congruential seed (multiplier 0x5DEECE66D, addend
//! 0xB) plus the cached second value of the polar Gaussian method. All
//! arithmetic wraps exactly like Java's `long` and `int`.

/// Java's LCG multiplier, also the seed scramble constant.
const MULTIPLIER: i64 = 0x5_DEEC_E66D;
/// Java's LCG addend.
const ADDEND: i64 = 0xB;
/// The state keeps the low 48 bits.
const MASK: i64 = (1 << 48) - 1;
/// 2^-53, the spacing of `next_double` values.
const DOUBLE_UNIT: f64 = 1.0 / (1u64 << 53) as f64;

/// A bit-exact `java.util.Random`.
#[derive(Debug, Clone)]
pub(crate) struct JavaRandom {
    seed: i64,
    next_next_gaussian: Option<f64>,
}

impl JavaRandom {
    /// Same as Java's `new Random(seed)`.
    pub(crate) fn new(seed: i64) -> Self {
        Self {
            seed: (seed ^ MULTIPLIER) & MASK,
            next_next_gaussian: None,
        }
    }

    /// Java's `next(bits)`: advances the LCG and returns its top `bits` bits
    /// (1..=32) as a Java `int` (so 32 bits may come back negative).
    pub(crate) fn next(&mut self, bits: u32) -> i32 {
        debug_assert!((1..=32).contains(&bits));
        self.seed = self.seed.wrapping_mul(MULTIPLIER).wrapping_add(ADDEND) & MASK;
        // `>>>` on a non-negative 48-bit value, then Java's narrowing (int) cast.
        (self.seed as u64 >> (48 - bits)) as u32 as i32
    }

    /// Java's `nextDouble()`: `((next(26) << 27) + next(27)) * 2^-53`, in [0, 1).
    pub(crate) fn next_double(&mut self) -> f64 {
        let high = i64::from(self.next(26)) << 27;
        let low = i64::from(self.next(27));
        (high + low) as f64 * DOUBLE_UNIT
    }

    /// Java's `nextGaussian()`: the polar method, returning the cached second
    /// value on every other call. Uses `libm` so the logarithm and square root
    /// match `StrictMath` bit for bit.
    pub(crate) fn next_gaussian(&mut self) -> f64 {
        if let Some(cached) = self.next_next_gaussian.take() {
            return cached;
        }
        loop {
            let v1 = 2.0 * self.next_double() - 1.0;
            let v2 = 2.0 * self.next_double() - 1.0;
            let s = v1 * v1 + v2 * v2;
            if s < 1.0 && s != 0.0 {
                // f64::sqrt is correctly rounded (IEEE 754), as StrictMath.sqrt.
                let multiplier = (-2.0 * libm::log(s) / s).sqrt();
                self.next_next_gaussian = Some(v2 * multiplier);
                return v1 * multiplier;
            }
        }
    }
}

#[cfg(test)]
mod tests {
    //! Golden values printed by OpenJDK's `java.util.Random`.
    use super::*;

    #[test]
    fn next_32_bits_match_javas_next_int() {
        assert_eq!(JavaRandom::new(42).next(32), -1_170_105_035);
        assert_eq!(JavaRandom::new(0).next(32), -1_155_484_576);
        // Only the low 48 bits of the seed matter.
        assert_eq!(JavaRandom::new(i64::MIN).next(32), -1_155_484_576);
    }

    #[test]
    fn next_double_matches_java() {
        assert_eq!(JavaRandom::new(0).next_double(), 0.730_967_787_376_657);
        assert_eq!(JavaRandom::new(42).next_double(), 0.727_563_680_032_868_1);
        let mut r = JavaRandom::new(i64::MIN);
        r.next(32);
        assert_eq!(r.next_double(), 0.831_440_988_787_061_2);
    }

    #[test]
    fn next_gaussian_matches_java_with_cached_second_value() {
        let mut r = JavaRandom::new(0);
        assert_eq!(r.next_gaussian(), 0.802_533_063_739_030_5);
        let seed_after_pair = r.seed;
        assert_eq!(r.next_gaussian(), -0.901_546_088_417_512_2);
        assert_eq!(
            r.seed, seed_after_pair,
            "the second value comes from the cache"
        );
        assert_eq!(r.next_gaussian(), 2.080_920_790_428_163);
    }
}
