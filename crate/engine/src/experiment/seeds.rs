//! Derived seeds: every random draw of an experiment comes from a seed computed from
//! (run seed, generation, index in the batch, purpose), so results never depend on how
//! evaluations are spread over threads or workers, native or wasm.

/// What a derived seed is for; each purpose gets an independent stream.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Purpose {
    /// The hilly terrain of one training evaluation.
    Terrain,
    /// The sensor-noise stream of one evaluation.
    SensorNoise,
    /// The GA's own RNG (use generation 0, index 0).
    Genetics,
    /// Validation terrains (index = which of the unseen terrains).
    Validation,
    /// Genes of voxels added to a body that already has a controller (generation = the
    /// edit's number, index 0).
    Remap,
    /// How one body-search child is made from its parent (iteration, index in the batch).
    Variation,
    /// Which training bodies one evaluation walks (generation, index in the batch).
    Bodies,
    /// The generator of the study's body sets (generation 0, index = which stream).
    BodySet,
}

impl Purpose {
    /// A fixed tag per purpose; never renumber, or old runs stop replaying.
    fn tag(self) -> u64 {
        match self {
            Purpose::Terrain => 1,
            Purpose::SensorNoise => 2,
            Purpose::Genetics => 3,
            Purpose::Validation => 4,
            Purpose::Remap => 5,
            Purpose::Variation => 6,
            Purpose::Bodies => 7,
            Purpose::BodySet => 8,
        }
    }
}

/// Number of distinct training terrain seeds, as in the paper (`nextInt(10000)`).
pub(crate) const TERRAIN_SEEDS: u64 = 10_000;

/// The splitmix64 finaliser: a bijective 64-bit mix with good avalanche.
pub(crate) fn splitmix64(x: u64) -> u64 {
    let mut z = x.wrapping_add(0x9E37_79B9_7F4A_7C15);
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^ (z >> 31)
}

/// The seed of one evaluation's `purpose` stream, mixing every input through splitmix64.
pub fn evaluation_seed(run_seed: u64, generation: u32, index: u32, purpose: Purpose) -> u64 {
    let mut h = splitmix64(run_seed);
    h = splitmix64(h ^ u64::from(generation));
    h = splitmix64(h ^ u64::from(index));
    splitmix64(h ^ purpose.tag())
}

/// The paper's training terrain for a derived seed: `hilly-1-10-{seed % 10000}`.
pub(crate) fn terrain_name_for(seed: u64) -> String {
    format!("hilly-1-10-{}", seed % TERRAIN_SEEDS)
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::collections::HashSet;

    #[test]
    fn every_input_changes_the_seed() {
        let base = evaluation_seed(7, 3, 5, Purpose::Terrain);
        assert_ne!(base, evaluation_seed(8, 3, 5, Purpose::Terrain));
        assert_ne!(base, evaluation_seed(7, 4, 5, Purpose::Terrain));
        assert_ne!(base, evaluation_seed(7, 3, 6, Purpose::Terrain));
        assert_ne!(base, evaluation_seed(7, 3, 5, Purpose::SensorNoise));
        // Swapping generation and index must not collide either.
        assert_ne!(
            evaluation_seed(7, 1, 2, Purpose::Terrain),
            evaluation_seed(7, 2, 1, Purpose::Terrain)
        );
    }

    #[test]
    fn seeds_of_one_run_are_distinct_and_terrains_spread() {
        let mut seeds = HashSet::new();
        let mut terrains = HashSet::new();
        for g in 0..151 {
            for i in 0..200 {
                let s = evaluation_seed(1, g, i, Purpose::Terrain);
                seeds.insert(s);
                terrains.insert(terrain_name_for(s));
            }
        }
        assert_eq!(seeds.len(), 151 * 200);
        // 30200 draws from 10000 names cover about 95% of them.
        assert!(terrains.len() > 9000, "{}", terrains.len());
        assert_eq!(terrain_name_for(123_456), "hilly-1-10-3456");
    }
}
