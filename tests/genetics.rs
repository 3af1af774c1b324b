//! Genetics: operator statistics, selection pressure, survival, budget arithmetic,
//! determinism, a small optimisation, and the frozen prefix used by fine-tuning.

use rand::seq::SliceRandom;
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;
use vsr::genetics::operators::{
    crossover, mutate, standard_normal, tournament, ALPHA_HIGH, ALPHA_LOW,
};
use vsr::genetics::{Ga, GaConfig};

fn mean_sd(xs: &[f64]) -> (f64, f64) {
    let n = xs.len() as f64;
    let mean = xs.iter().sum::<f64>() / n;
    let var = xs.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / (n - 1.0);
    (mean, var.sqrt())
}

fn sphere(g: &[f32]) -> f64 {
    -g.iter().map(|&x| f64::from(x) * f64::from(x)).sum::<f64>()
}

#[test]
fn mutation_adds_gaussian_noise_of_sd_035() {
    let mut rng = ChaCha8Rng::seed_from_u64(21);
    let child = mutate(&vec![0.0; 200_000], 0.35, 0, &mut rng);
    let xs: Vec<f64> = child.iter().map(|&x| f64::from(x)).collect();
    let (mean, sd) = mean_sd(&xs);
    assert!(mean.abs() < 0.005, "mean {mean}");
    assert!((sd / 0.35 - 1.0).abs() < 0.02, "sd {sd}");
}

#[test]
fn crossover_alpha_is_uniform_on_minus_half_to_one_and_a_half() {
    let mut rng = ChaCha8Rng::seed_from_u64(22);
    // p1 = 0, p2 = 1 and no noise: the child gene is alpha itself.
    let child = crossover(&vec![0.0; 200_000], &vec![1.0; 200_000], 0.0, 0, &mut rng);
    let xs: Vec<f64> = child.iter().map(|&x| f64::from(x)).collect();
    assert!(xs.iter().all(|&a| (ALPHA_LOW..=ALPHA_HIGH).contains(&a)));
    let (mean, sd) = mean_sd(&xs);
    assert!((mean - 0.5).abs() < 0.01, "mean {mean}");
    assert!((sd / (2.0 / 12f64.sqrt()) - 1.0).abs() < 0.02, "sd {sd}");
    let (lo, hi) = xs
        .iter()
        .fold((1.0f64, 0.0f64), |(l, h), &a| (l.min(a), h.max(a)));
    assert!(
        lo < -0.49 && hi > 1.49,
        "the whole range is used: [{lo}, {hi}]"
    );
}

#[test]
fn crossover_noise_has_sd_01() {
    let mut rng = ChaCha8Rng::seed_from_u64(23);
    let child = crossover(&vec![0.3; 200_000], &vec![0.3; 200_000], 0.1, 0, &mut rng);
    let xs: Vec<f64> = child.iter().map(|&x| f64::from(x) - 0.3).collect();
    let (mean, sd) = mean_sd(&xs);
    assert!(mean.abs() < 0.002, "mean {mean}");
    assert!((sd / 0.1 - 1.0).abs() < 0.02, "sd {sd}");
}

#[test]
fn tournament_of_five_picks_the_best_with_probability_1_minus_099_pow_5() {
    let mut rng = ChaCha8Rng::seed_from_u64(24);
    let mut fitness: Vec<f64> = (0..100).map(f64::from).collect();
    fitness.shuffle(&mut rng);
    let best = fitness.iter().position(|&f| f == 99.0).unwrap();
    let worst = fitness.iter().position(|&f| f == 0.0).unwrap();
    let draws = 200_000;
    let mut wins = vec![0usize; 100];
    for _ in 0..draws {
        wins[tournament(&fitness, 5, &mut rng).unwrap()] += 1;
    }
    let p = wins[best] as f64 / draws as f64;
    let expected = 1.0 - 0.99f64.powi(5); // 0.0490; sampling sd 0.00048
    assert!(
        (p - expected).abs() < 0.002,
        "p(best) = {p}, expected {expected}"
    );
    assert_eq!(
        wins[worst], 0,
        "the worst can only win a tournament of itself 5 times"
    );
}

#[test]
fn tournament_breaks_ties_at_random() {
    let mut rng = ChaCha8Rng::seed_from_u64(25);
    let fitness = [1.0, 5.0, 5.0, 0.0];
    let mut wins = [0usize; 4];
    for _ in 0..40_000 {
        wins[tournament(&fitness, 5, &mut rng).unwrap()] += 1;
    }
    let share = wins[1] as f64 / (wins[1] + wins[2]) as f64;
    assert!((share - 0.5).abs() < 0.02, "tied winners split {wins:?}");
}

#[test]
fn frozen_prefix_is_untouched_by_every_operator() {
    let mut rng = ChaCha8Rng::seed_from_u64(26);
    let p1: Vec<f32> = (0..20).map(|i| i as f32 * 0.1).collect();
    let p2: Vec<f32> = (0..20).map(|i| -(i as f32)).collect();
    for _ in 0..100 {
        let m = mutate(&p1, 0.35, 8, &mut rng);
        let c = crossover(&p1, &p2, 0.1, 8, &mut rng);
        assert_eq!(m[..8], p1[..8]);
        assert_eq!(c[..8], p1[..8]);
        assert!(m[8..].iter().zip(&p1[8..]).all(|(a, b)| a != b));
    }
}

/// Runs a GA to the end on `fitness`, returning every batch asked.
fn run(mut ga: Ga, fitness: impl Fn(&[f32]) -> f64) -> (Ga, Vec<Vec<Vec<f32>>>) {
    let mut asks = Vec::new();
    while !ga.is_done() {
        let batch: Vec<Vec<f32>> = ga.ask().into_iter().map(|c| c.genome).collect();
        let f: Vec<f64> = batch.iter().map(|g| fitness(g)).collect();
        ga.tell(&f).unwrap();
        asks.push(batch);
    }
    (ga, asks)
}

#[test]
fn budget_of_30000_gives_151_asks_and_30100_evaluations() {
    let ga = Ga::new(GaConfig::default(), 3, 1).unwrap();
    let (mut ga, asks) = run(ga, sphere);
    assert_eq!(asks.len(), 151);
    assert_eq!(ga.evaluations(), 30_100);
    assert_eq!(ga.generation(), 151);
    assert_eq!(asks[0].len(), 100);
    assert!(asks[1..].iter().all(|b| b.len() == 200));
    assert!(ga.ask().is_empty(), "nothing more once the budget is spent");
}

#[test]
fn same_seed_gives_identical_asks_and_another_seed_does_not() {
    let config = GaConfig {
        budget_evals: 1_000,
        ..GaConfig::default()
    };
    let (_, a) = run(Ga::new(config.clone(), 7, 42).unwrap(), sphere);
    let (_, b) = run(Ga::new(config.clone(), 7, 42).unwrap(), sphere);
    let (_, c) = run(Ga::new(config, 7, 43).unwrap(), sphere);
    assert_eq!(a, b);
    assert_ne!(a[0], c[0]);
}

#[test]
fn candidates_are_parents_best_first_then_offspring() {
    let mut ga = Ga::new(GaConfig::default(), 4, 3).unwrap();
    let gen0 = ga.ask();
    assert!(gen0
        .iter()
        .enumerate()
        .all(|(i, c)| c.generation == 0 && c.index as usize == i));
    let f: Vec<f64> = gen0.iter().map(|c| sphere(&c.genome)).collect();
    ga.tell(&f).unwrap();
    let gen1 = ga.ask();
    assert_eq!(
        ga.ask(),
        gen1,
        "asking twice before tell returns the same batch"
    );
    let parents: Vec<&[f32]> = ga.survivors().map(|(g, _)| g).collect();
    assert!(gen1[..100]
        .iter()
        .zip(&parents)
        .all(|(c, p)| c.genome == *p));
    assert_eq!(gen1[0].genome, ga.best().0);
    assert!(gen1.iter().all(|c| c.generation == 1));
}

#[test]
fn mu_plus_lambda_keeps_the_top_fitness_and_uses_the_latest_parent_evaluation() {
    let mut ga = Ga::new(GaConfig::default(), 4, 5).unwrap();
    let gen0 = ga.ask();
    let f0: Vec<f64> = (0..100).map(f64::from).collect();
    ga.tell(&f0).unwrap();
    assert_eq!(ga.best(), (&gen0[99].genome[..], 99.0));
    let gen1 = ga.ask();
    // Re-evaluation: the former best parent now scores low; offspring 150 scores highest.
    let mut f1 = vec![10.0; 200];
    f1[0] = -5.0;
    f1[150] = 1e6;
    f1[7] = f64::NAN;
    let stats = ga.tell(&f1).unwrap();
    assert_eq!(ga.best(), (&gen1[150].genome[..], 1e6));
    assert!(ga
        .survivors()
        .all(|(g, _)| g != gen1[0].genome && g != gen1[7].genome));
    assert_eq!(
        (stats.best, stats.worst, stats.generation, stats.evaluations),
        (1e6, 10.0, 1, 300)
    );
}

#[test]
fn tell_rejects_wrong_lengths_and_tells_without_ask() {
    let mut ga = Ga::new(GaConfig::default(), 4, 6).unwrap();
    assert!(ga.tell(&[0.0; 99]).is_err());
    assert!(ga.tell(&[0.0; 100]).is_ok());
    assert!(
        ga.tell(&[0.0; 200]).is_err(),
        "generation 1 was not asked yet"
    );
    assert_eq!(ga.ask().len(), 200);
    assert!(Ga::new(
        GaConfig {
            frozen_prefix: 5,
            ..GaConfig::default()
        },
        4,
        0
    )
    .is_err());
    assert!(Ga::with_initial(GaConfig::default(), vec![], 0).is_err());
    assert!(Ga::with_initial(GaConfig::default(), vec![vec![0.0; 3], vec![0.0; 4]], 0).is_err());
}

#[test]
fn small_ga_clearly_improves_on_the_sphere() {
    let config = GaConfig {
        population: 20,
        budget_evals: 20 + 30 * 40,
        ..GaConfig::default()
    };
    let mut ga = Ga::new(config.clone(), 10, 7).unwrap();
    let first: Vec<f64> = ga.ask().iter().map(|c| sphere(&c.genome)).collect();
    let gen0_best = ga.tell(&first).unwrap().best;
    let (ga, asks) = run(ga, sphere);
    assert_eq!(asks.len(), 30);
    let (_, best) = ga.best();
    assert!(
        best > 0.2 * gen0_best,
        "gen 0 best {gen0_best}, final best {best}"
    );
}

#[test]
fn fine_tuning_population_shares_the_frozen_prefix_for_the_whole_run() {
    let config = GaConfig {
        frozen_prefix: 32,
        budget_evals: 2_000,
        ..GaConfig::default()
    };
    let seed: Vec<f32> = (0..45).map(|i| (i as f32 * 0.7).sin()).collect();
    let ga = Ga::with_initial(config, vec![seed.clone()], 9).unwrap();
    let (_, asks) = run(ga, sphere);
    assert_eq!(asks[0][0], seed, "the given genome is individual 0");
    assert!(asks.iter().flatten().all(|g| g[..32] == seed[..32]));
    assert!(asks[0][1][32..] != seed[32..], "the rest is re-drawn");
}

/// Run files replay from their seed: a change to the random stream (operator order, RNG,
/// Gaussian method) silently changes every stored run. Exact values, no tolerance.
#[test]
fn seeded_stream_is_pinned() {
    let mut ga = Ga::new(GaConfig::default(), 3, 1).unwrap();
    let gen0 = ga.ask();
    assert_eq!(gen0[0].genome, [0.09875643, -0.19502878, 0.9691942]);
    let f: Vec<f64> = gen0.iter().map(|c| sphere(&c.genome)).collect();
    ga.tell(&f).unwrap();
    let gen1 = ga.ask();
    assert_eq!(gen1[100].genome, [-0.0020478524, -1.0892047, -0.19913016]);
    assert_eq!(gen1[101].genome, [0.55412346, -0.35773864, -0.5027687]);
    let mut rng = ChaCha8Rng::seed_from_u64(3);
    let normals: Vec<f64> = (0..3).map(|_| standard_normal(&mut rng)).collect();
    let expected = [
        0.20790577449436895,
        -0.24744376872580803,
        0.3896697687525554,
    ];
    assert_eq!(normals, expected);
}
