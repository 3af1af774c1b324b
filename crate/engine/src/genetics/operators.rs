//! GA operators (SPEC 9). Each takes the RNG explicitly and returns a new genome; genes
//! `[0, frozen)` are copied unchanged (fine-tuning evolves only the downstream genes).
//!
//! Gaussian draws use Marsaglia's polar method on `libm` and the RNG's uniform `f64`s, so a
//! seeded stream gives bit-identical genomes on x86_64 and wasm32 (no platform `exp`/`ln`).
//! Arithmetic on a gene is done in `f64` and rounded once to `f32`.

use rand::Rng;

/// Lower end of the extended geometric crossover's per-gene alpha.
pub const ALPHA_LOW: f64 = -0.5;
/// Upper end of the extended geometric crossover's per-gene alpha.
pub const ALPHA_HIGH: f64 = 1.5;

pub use crate::random::standard_normal;

/// Fitness as a sort key: NaN counts as the worst possible value.
pub(crate) fn fitness_key(f: f64) -> f64 {
    if f.is_nan() {
        f64::NEG_INFINITY
    } else {
        f
    }
}

/// A uniform index in `0..len`, drawn over `u32` so that 64-bit hosts and wasm32 (where
/// `usize` is 32 bits and rand samples it differently) draw the same index.
fn index(rng: &mut impl Rng, len: usize) -> usize {
    let len = u32::try_from(len).unwrap_or(u32::MAX);
    rng.gen_range(0..len) as usize
}

/// Tournament selection: draws `size` indices uniformly WITH replacement (at least one) and
/// returns the one with the highest fitness; ties between distinct individuals are broken
/// uniformly at random. NaN counts as -inf. `None` only for an empty population.
pub fn tournament(fitness: &[f64], size: usize, rng: &mut impl Rng) -> Option<usize> {
    if fitness.is_empty() {
        return None;
    }
    let mut best = f64::NEG_INFINITY;
    let mut winners: Vec<usize> = Vec::with_capacity(size.max(1));
    for _ in 0..size.max(1) {
        let c = index(rng, fitness.len());
        let f = fitness_key(fitness[c]);
        if f > best || winners.is_empty() {
            best = f;
            winners.clear();
            winners.push(c);
        } else if f == best && !winners.contains(&c) {
            winners.push(c);
        }
    }
    let pick = if winners.len() > 1 {
        index(rng, winners.len())
    } else {
        0
    };
    Some(winners[pick])
}

/// Gaussian mutation: every gene from `frozen` on gets `+ N(0, sigma^2)`.
pub fn mutate(parent: &[f32], sigma: f32, frozen: usize, rng: &mut impl Rng) -> Vec<f32> {
    let mut child = parent.to_vec();
    for gene in child.iter_mut().skip(frozen) {
        *gene = (f64::from(*gene) + f64::from(sigma) * standard_normal(rng)) as f32;
    }
    child
}

/// Extended geometric crossover: per gene from `frozen` on, child = p1 + alpha (p2 - p1) with
/// alpha ~ U(-0.5, 1.5) drawn for that gene, then `+ N(0, sigma^2)`; genes before `frozen`
/// come from `p1`. If the parents' lengths differ the child is as long as the shorter one.
pub fn crossover(
    p1: &[f32],
    p2: &[f32],
    sigma: f32,
    frozen: usize,
    rng: &mut impl Rng,
) -> Vec<f32> {
    let mut child = Vec::with_capacity(p1.len().min(p2.len()));
    for (g, (&a, &b)) in p1.iter().zip(p2).enumerate() {
        if g < frozen {
            child.push(a);
            continue;
        }
        let alpha = ALPHA_LOW + (ALPHA_HIGH - ALPHA_LOW) * rng.gen::<f64>();
        let (a, b) = (f64::from(a), f64::from(b));
        let noise = f64::from(sigma) * standard_normal(rng);
        child.push((a + alpha * (b - a) + noise) as f32);
    }
    child
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::SeedableRng;
    use rand_chacha::ChaCha8Rng;

    #[test]
    fn tournament_of_one_entry_always_returns_it_even_if_nan() {
        let mut rng = ChaCha8Rng::seed_from_u64(1);
        assert_eq!(tournament(&[f64::NAN], 5, &mut rng), Some(0));
        assert_eq!(tournament(&[], 5, &mut rng), None);
    }

    #[test]
    fn nan_fitness_never_beats_a_number() {
        let mut rng = ChaCha8Rng::seed_from_u64(2);
        // 8 draws from 2 miss index 1 with probability 1/256; whenever drawn it must win.
        let wins = (0..1000)
            .filter(|_| tournament(&[f64::NAN, -1e9], 8, &mut rng) == Some(1))
            .count();
        assert!(wins > 990, "{wins}");
    }

    #[test]
    fn standard_normal_is_reproducible_from_a_seed() {
        let a: Vec<f64> = {
            let mut rng = ChaCha8Rng::seed_from_u64(3);
            (0..5).map(|_| standard_normal(&mut rng)).collect()
        };
        let mut rng = ChaCha8Rng::seed_from_u64(3);
        let b: Vec<f64> = (0..5).map(|_| standard_normal(&mut rng)).collect();
        assert_eq!(a, b);
    }
}
