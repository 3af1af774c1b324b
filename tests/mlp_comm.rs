//! MLP-Comm's messages: a message crosses one neighbour per call, in the direction it was
//! sent, reset clears them; and its two paces (every step, latched) differ only through them.

use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;
use vsr::controllers::{Controller, ControllerKind, MlpComm, Topology};

mod controller_util;
use controller_util::{random_params, random_vec};

/// 2x2 grid: 0 bottom-left, 1 bottom-right, 2 top-left, 3 top-right.
fn grid_2x2() -> Topology {
    Topology::from_cells(&[(0, 0), (1, 0), (0, 1), (1, 1)]).unwrap()
}

/// MLP-Comm where voxel outputs message `send` (1 up, 2 right, 3 down, 4 left) = tanh(tanh(area))
/// and actuates tanh(received input `recv`) (4 + direction). Returns the outputs of 3 calls in
/// which only voxel 0 senses anything, and only at the first call.
fn single_route(send: usize, recv: usize) -> Vec<[f32; 4]> {
    let n = 4;
    let row = 8 * n + 1;
    let mut p = vec![0.0; MlpComm::param_count_for(n)];
    for i in 0..n {
        p[send * row + 8 * i] = 1.0; // message from own area reading
        p[8 * i + recv] = 1.0; // actuation from one received message
    }
    let mut c = MlpComm::new(grid_2x2());
    c.set_params(&p).unwrap();
    let mut first = [0.0f32; 16];
    first[0] = 0.9;
    [first, [0.0; 16], [0.0; 16]]
        .iter()
        .map(|s| {
            let mut out = [0.0; 4];
            c.control(s, &mut out);
            out
        })
        .collect()
}

#[test]
fn mlp_comm_message_sent_right_arrives_from_the_left_one_call_later() {
    let outs = single_route(2, 4 + 3);
    let arrived = (0.9f32.tanh().tanh()).tanh().tanh();
    assert_eq!(outs[0], [0.0; 4], "nothing arrives in the same call");
    assert_eq!(outs[1][0], 0.0);
    assert!((outs[1][1] - arrived).abs() < 1e-6, "{:?}", outs[1]);
    assert_eq!(
        [outs[1][2], outs[1][3]],
        [0.0, 0.0],
        "only the right neighbour hears it"
    );
    assert_eq!(outs[2], [0.0; 4], "a message lives one call");
}

#[test]
fn mlp_comm_message_sent_up_arrives_from_below_and_nowhere_else() {
    let outs = single_route(1, 4 + 2);
    assert_eq!(outs[0], [0.0; 4]);
    assert_eq!([outs[1][0], outs[1][1], outs[1][3]], [0.0; 3]);
    let arrived = (0.9f32.tanh().tanh()).tanh().tanh();
    assert!((outs[1][2] - arrived).abs() < 1e-6, "{:?}", outs[1]);
    // Voxel 0 has no left neighbour: a message sent left is lost.
    let lost = single_route(4, 4 + 1);
    assert!(lost.iter().all(|o| *o == [0.0; 4]), "{lost:?}");
}

/// Runs `a` on `s_a` and `b` on `s_b`; true for each voxel whose actuation differs.
fn differs(a: &mut MlpComm, b: &mut MlpComm, s_a: &[f32], s_b: &[f32]) -> [bool; 4] {
    let (mut out_a, mut out_b) = ([0.0; 4], [0.0; 4]);
    a.control(s_a, &mut out_a);
    b.control(s_b, &mut out_b);
    std::array::from_fn(|i| out_a[i] != out_b[i])
}

#[test]
fn mlp_comm_perturbation_spreads_one_hop_per_call() {
    let mut rng = ChaCha8Rng::seed_from_u64(15);
    let mut a = MlpComm::new(grid_2x2());
    random_params(&mut a, &mut rng, 1.0);
    let mut b = a.clone();
    let calls: Vec<Vec<f32>> = (0..3).map(|_| random_vec(&mut rng, 16, 1.0)).collect();
    let mut perturbed = calls[0].clone();
    perturbed[1] += 0.5; // voxel 0's vx, first call only
    let first = differs(&mut a, &mut b, &calls[0], &perturbed);
    assert_eq!(first, [true, false, false, false]);
    let second = differs(&mut a, &mut b, &calls[1], &calls[1]);
    assert_eq!(
        second,
        [false, true, true, false],
        "neighbours 1 and 2 only"
    );
    let third = differs(&mut a, &mut b, &calls[2], &calls[2]);
    assert_eq!(
        third,
        [true, false, false, true],
        "two hops: echo and diagonal"
    );
    a.reset();
    b.reset();
    let after_reset = differs(&mut a, &mut b, &calls[2], &calls[2]);
    assert_eq!(after_reset, [false; 4], "reset clears messages in flight");
}

/// MLP-Comm's two paces differ only in when messages travel: with every message row at zero
/// (no message is ever sent) they walk identically; with messages they do not. (Without
/// sensor noise: the every-step MLP-Comm reads, so draws, noise at every step.)
#[test]
fn mlp_comm_latched_differs_from_every_step_only_through_its_messages() {
    use vsr::experiment::evaluate::evaluate;
    use vsr::simulation::{Shape, Terrain};
    let shape = Shape::parse("biped-4x3").unwrap();
    let n = shape.voxel_count();
    let row = 8 * n + 1;
    let mut rng = ChaCha8Rng::seed_from_u64(7);
    let genome = random_vec(&mut rng, MlpComm::param_count_for(n), 1.0);
    let mut silent = genome.clone();
    silent[row..].fill(0.0);
    let velocity = |kind: ControllerKind, g: &[f32]| {
        let terrain = Terrain::parse("flat").unwrap();
        evaluate(&shape, terrain, kind, g, None, 5.0)
            .unwrap()
            .velocity
    };
    assert_eq!(
        velocity(ControllerKind::MlpComm, &silent),
        velocity(ControllerKind::MlpCommLatched, &silent)
    );
    assert_ne!(
        velocity(ControllerKind::MlpComm, &genome),
        velocity(ControllerKind::MlpCommLatched, &genome)
    );
}
