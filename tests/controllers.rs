//! Controllers: parameter-count formulas, the genome seam, the attention maths checked against
//! naive f64 code, and the slow / frozen attention variants (MLP-Comm's messages: mlp_comm.rs).

use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

mod controller_util;
use controller_util::{random_params, random_vec};
use vsr::controllers::{
    build, Attention, Controller, ControllerKind, SlowAttention, Topology, ATTENTION_PARAMS,
};

/// Independent restatement of SPEC 7's formulas.
fn expected_count(kind: ControllerKind, n: usize) -> usize {
    match kind {
        ControllerKind::Attention => 32 + 4 * n + 1,
        ControllerKind::Mlp => 4 * n + 1,
        ControllerKind::MlpComm | ControllerKind::MlpCommLatched => (8 * n + 1) * 5,
        ControllerKind::SlowAttention => 32 + 4 * n + 1 + 2,
        // One genome for every body: shared genes, then 5 local-input weights per voxel gene.
        ControllerKind::AttentionAny => 32 + 1 + 4 * 5,
        ControllerKind::MlpAny => 1 + 4 * 5,
        ControllerKind::MlpCommAny => 5 + 5 * 8 * 5,
    }
}

#[test]
fn parameter_counts_match_the_paper_for_the_four_shapes() {
    use ControllerKind::*;
    let table = [
        (Attention, [73, 77, 105, 117]),
        (Mlp, [41, 45, 73, 85]),
        (MlpComm, [405, 445, 725, 845]),
        (SlowAttention, [75, 79, 107, 119]),
    ];
    for (kind, counts) in table {
        for (n, count) in [10, 11, 18, 21].into_iter().zip(counts) {
            assert_eq!(kind.param_count(n), count, "{kind} n={n}");
            let c = build(kind, &Topology::isolated(n));
            assert_eq!(c.param_count(), count, "{kind} n={n} built");
            assert_eq!(c.params().len(), count);
        }
    }
}

#[test]
fn parameter_counts_follow_the_formulas_for_random_sizes() {
    let mut rng = ChaCha8Rng::seed_from_u64(11);
    for _ in 0..50 {
        let n = rng.gen_range(1..300);
        for kind in ControllerKind::ALL {
            assert_eq!(kind.param_count(n), expected_count(kind, n));
            assert_eq!(
                build(kind, &Topology::isolated(n)).param_count(),
                expected_count(kind, n)
            );
        }
        // The attention block does not depend on the morphology.
        assert_eq!(
            ControllerKind::Attention.param_count(n) - 4 * n - 1,
            ATTENTION_PARAMS
        );
    }
}

#[test]
fn params_round_trip_and_bad_genomes_are_rejected_without_change() {
    let mut rng = ChaCha8Rng::seed_from_u64(12);
    let topology = Topology::from_cells(&[(0, 0), (1, 0), (0, 1)]).unwrap();
    for kind in ControllerKind::ALL {
        let mut c = build(kind, &topology);
        let p = random_vec(&mut rng, c.param_count(), 1.0);
        c.set_params(&p).unwrap();
        assert_eq!(c.params(), p, "{kind}");
        assert!(c.set_params(&p[1..]).is_err(), "{kind} short");
        let mut long = p.clone();
        long.push(0.0);
        assert!(c.set_params(&long).is_err(), "{kind} long");
        let mut nan = p.clone();
        nan[3] = f32::NAN;
        assert!(c.set_params(&nan).is_err(), "{kind} NaN");
        assert_eq!(c.params(), p, "{kind} unchanged after rejection");
    }
}

#[test]
fn wrong_sensor_length_zeroes_the_output_instead_of_panicking() {
    for kind in ControllerKind::ALL {
        let mut c = build(kind, &Topology::isolated(3));
        let mut out = [0.7; 3];
        c.control(&[0.5; 11], &mut out);
        assert_eq!(out, [0.0; 3], "{kind}");
        let mut short = [0.7; 2];
        c.control(&[0.5; 12], &mut short);
        assert_eq!(short, [0.0; 2], "{kind}");
    }
}

#[test]
fn attention_entries_stay_in_unit_range_even_with_large_params() {
    let mut rng = ChaCha8Rng::seed_from_u64(13);
    let n = 11;
    let mut c = Attention::new(n);
    for _ in 0..50 {
        random_params(&mut c, &mut rng, 5.0);
        let sensors = random_vec(&mut rng, 4 * n, 2.0);
        let mut out = vec![0.0; n];
        c.control(&sensors, &mut out);
        let a = c.attention().unwrap();
        assert_eq!(a.len(), 16 * n);
        assert!(a.iter().all(|x| (-1.0..=1.0).contains(x)));
        assert!(out.iter().all(|u| (-1.0..=1.0).contains(u)));
    }
}

/// SPEC 7 attention for voxel i, written naively in f64.
fn naive_attention(p: &[f32], n: usize, i: usize, s: &[f64; 4]) -> ([f64; 16], f64) {
    let g = |k: usize| f64::from(p[k]);
    let mut a = [0.0; 16];
    for r in 0..4 {
        for c in 0..4 {
            let dot: f64 = (0..8)
                .map(|k| (s[r] * g(k) + g(8 + k)) * (s[c] * g(16 + k) + g(24 + k)))
                .sum();
            a[4 * r + c] = (dot / 8f64.sqrt()).tanh();
        }
    }
    let mut sum = g(32 + 4 * n);
    for r in 0..4 {
        let attended: f64 = (0..4).map(|c| a[4 * r + c] * s[c]).sum();
        sum += g(32 + r * n + i) * attended.tanh();
    }
    (a, sum.tanh())
}

#[test]
fn attention_matches_a_naive_computation_on_two_voxels() {
    let n = 2;
    // Hand-picked genome: every gene distinct so a swapped index shows up.
    let p: Vec<f32> = (0..Attention::param_count_for(n))
        .map(|k| ((k as f32) * 0.37).sin() * 0.9)
        .collect();
    let sensors = [0.55f32, 0.40, 0.62, 1.0, 0.48, 0.71, 0.30, 0.0];
    let mut c = Attention::new(n);
    c.set_params(&p).unwrap();
    let mut out = [0.0; 2];
    c.control(&sensors, &mut out);
    for i in 0..n {
        let s: [f64; 4] = std::array::from_fn(|r| f64::from(sensors[4 * i + r]));
        let (a, u) = naive_attention(&p, n, i, &s);
        for (k, want) in a.iter().enumerate() {
            let got = f64::from(c.attention().unwrap()[16 * i + k]);
            assert!((got - want).abs() < 1e-5, "A[{i}][{k}]: {got} vs {want}");
        }
        assert!(
            (f64::from(out[i]) - u).abs() < 1e-5,
            "u[{i}]: {} vs {u}",
            out[i]
        );
    }
}

#[test]
fn slow_attention_with_alpha_one_eta_zero_is_attention() {
    let mut rng = ChaCha8Rng::seed_from_u64(16);
    let n = 5;
    let mut plain = Attention::new(n);
    random_params(&mut plain, &mut rng, 1.5);
    let mut slow = SlowAttention::new(n);
    let mut p = plain.params();
    p.extend([-1.0, 0.0]); // alpha = |g1| = 1, eta = 0
    slow.set_params(&p).unwrap();
    assert_eq!((slow.alpha(), slow.eta()), (1.0, 0.0));
    for _ in 0..5 {
        let s = random_vec(&mut rng, 4 * n, 1.0);
        let (mut u1, mut u2) = (vec![0.0; n], vec![0.0; n]);
        plain.control(&s, &mut u1);
        slow.control(&s, &mut u2);
        assert_eq!(u1, u2);
        assert_eq!(plain.attention(), slow.attention());
    }
}
