//! Self-collision (SPEC 3, issue 10 part 1): corner squares of different voxels that
//! are not welded together collide. Penetration is measured here independently of the
//! simulator's collider: a separating-axis test on the squares' poses, over the pairs
//! of squares of different voxels that did not start welded (welded squares start
//! side by side or corner to corner, at most 1.2 sqrt 2 m apart, and stay rigid).
//! Before self-collision every robot below passed through itself by about a metre.

mod common;
use common::mechanical_energy;
use vsr::experiment::{GaitEpisode, PhaseGait};
use vsr::simulation::constants::{CORNER_MASS, CORNER_SIDE, GRAVITY, LINEAR_SLOP};
use vsr::simulation::{Shape, Terrain, World};

/// Deepest overlap the position solver accepts as converged (3 slops = 1.5 cm): the
/// ground contacts obey the same bound.
const SOLVER_TOLERANCE: f64 = 3.0 * LINEAR_SLOP;

fn world(shape: &str) -> (Shape, World) {
    let shape = Shape::parse(shape).expect("valid shape");
    let terrain = Terrain::parse("flat").expect("valid terrain");
    let w = World::new(shape.voxels(), terrain.xs(), terrain.ys());
    (shape, w)
}

/// How deep two squares (x, y, angle) overlap (m); 0 when apart.
fn overlap(a: (f64, f64, f64), b: (f64, f64, f64)) -> f64 {
    let half = CORNER_SIDE / 2.0;
    let axes = |t: f64| [(t.cos(), t.sin()), (-t.sin(), t.cos())];
    let extent = |n: (f64, f64), t: f64| {
        axes(t)
            .iter()
            .map(|u| half * (n.0 * u.0 + n.1 * u.1).abs())
            .sum::<f64>()
    };
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    axes(a.2)
        .into_iter()
        .chain(axes(b.2))
        .map(|n| extent(n, a.2) + extent(n, b.2) - (dx * n.0 + dy * n.1).abs())
        .fold(f64::INFINITY, f64::min)
        .max(0.0)
}

/// The pairs of squares that must not overlap: different voxels, not welded.
fn unwelded_pairs(w: &World) -> Vec<(usize, usize)> {
    let n = 4 * w.voxel_count();
    let welded = CORNER_SIDE * std::f64::consts::SQRT_2 + 1e-9;
    let mut pairs = Vec::new();
    for i in 0..n {
        for j in i + 1..n {
            let (a, b) = (w.square_pose(i), w.square_pose(j));
            if i / 4 != j / 4 && (a.0 - b.0).hypot(a.1 - b.1) > welded {
                pairs.push((i, j));
            }
        }
    }
    pairs
}

fn deepest(w: &World, pairs: &[(usize, usize)]) -> f64 {
    pairs
        .iter()
        .map(|&(i, j)| overlap(w.square_pose(i), w.square_pose(j)))
        .fold(0.0, f64::max)
}

#[test]
fn the_penetration_measure_sees_overlaps() {
    // The measure itself: 2 cm along x, nothing when apart, a rotated corner 5 cm in.
    assert!((overlap((0.0, 0.0, 0.0), (1.18, 0.3, 0.0)) - 0.02).abs() < 1e-12);
    assert_eq!(overlap((0.0, 0.0, 0.0), (1.21, 0.0, 0.0)), 0.0);
    let r = CORNER_SIDE / 2.0 * std::f64::consts::SQRT_2;
    let tilted = overlap(
        (0.0, 0.0, 0.0),
        (0.0, 0.55 + r, std::f64::consts::FRAC_PI_4),
    );
    assert!((tilted - 0.05).abs() < 1e-9, "{tilted}");
}

#[test]
fn arms_of_a_u_bent_toward_each_other_stop_at_contact() {
    // Arms two voxels thick, one voxel apart. Contracting the inner column and
    // expanding the outer one bends each arm inward by about 2 m at the tip: more than
    // the 1.5 m each needs to meet the other.
    let (shape, mut w) = world("11011-11011-11011-11111");
    let pairs = unwelded_pairs(&w);
    let bend: Vec<f64> = shape
        .voxels()
        .iter()
        .map(|&(x, y)| match (y, x) {
            (0, _) => 0.0,
            (_, 1 | 3) => 1.0,
            _ => -1.0,
        })
        .collect();
    let (mut worst, mut late, mut touched) = (0.0_f64, 0.0_f64, false);
    for step in 0..600 {
        if step == 60 {
            w.set_actuation(&bend);
        }
        w.step();
        let d = deepest(&w, &pairs);
        worst = worst.max(d);
        if step >= 420 {
            late = late.max(d);
        }
        touched |= w.self_contacts().iter().any(|c| c.separation < LINEAR_SLOP);
    }
    assert!(touched, "the arms never met: the test would prove nothing");
    assert!(
        worst <= SOLVER_TOLERANCE,
        "squares of the two arms overlapped by {worst} m (limit {SOLVER_TOLERANCE})"
    );
    assert!(
        late <= LINEAR_SLOP,
        "held closed, the arms still overlap by {late} m in the last 3 s (limit: the slop)"
    );
}

#[test]
fn a_passive_c_rests_its_upper_arm_on_the_lower_one_and_settles() {
    // The upper arm (3 voxels long, 2 thick) of a C sags onto the lower arm under its
    // own weight: it must come to rest on it, not sink through it, never gain energy
    // in the landing, and be still after 25 s.
    let (shape, mut w) = world("1111-1111-1000-1111-1111");
    let pairs = unwelded_pairs(&w);
    w.step();
    let start = mechanical_energy(&w);
    let allowance = CORNER_MASS * 4.0 * shape.voxel_count() as f64 * -GRAVITY * LINEAR_SLOP;
    let (mut worst, mut rests, mut x_before) = (0.0_f64, false, 0.0);
    for step in 1..1800 {
        w.step();
        let e = mechanical_energy(&w);
        assert!(
            e <= start + allowance,
            "energy {e} > start {start} at step {step}"
        );
        worst = worst.max(deepest(&w, &pairs));
        rests |= w.self_contact_count() > 0;
        if step == 1499 {
            x_before = w.centre().0;
        }
    }
    assert!(rests, "the upper arm never reached the lower one");
    assert!(
        worst <= SOLVER_TOLERANCE,
        "the arms overlapped by {worst} m (limit {SOLVER_TOLERANCE})"
    );
    let drift = (w.centre().0 - x_before).abs();
    assert!(drift < 0.01, "still drifting: {drift} m in the last 5 s");
    assert!(
        w.pieces().kinetic_energy() < 0.1,
        "still moving: kinetic energy {} J",
        w.pieces().kinetic_energy()
    );
}

#[test]
fn comb_legs_swung_into_each_other_no_longer_pass_through() {
    // Under this gait neighbouring legs of comb-7x2 swing into each other; without
    // self-collision their feet overlapped by up to 1.4 m, in 682 of 1801 frames by more
    // than 5 cm. Pressing feet may overlap a little more than the solver's tolerance
    // for a step (as the ground contacts do when stamped on), never by a real depth.
    let shape = Shape::parse("comb-7x2").expect("valid");
    let gait = PhaseGait::new(2.0, 0.0).expect("finite");
    let mut e = GaitEpisode::from_parts(&shape, Terrain::parse("flat").expect("valid"), gait);
    let pairs = unwelded_pairs(e.world());
    let (mut worst, mut deep, mut touches) = (0.0_f64, 0, 0);
    for _ in 0..1801 {
        e.step(1).expect("stable");
        let d = deepest(e.world(), &pairs);
        worst = worst.max(d);
        deep += usize::from(d > SOLVER_TOLERANCE);
        touches += usize::from(e.world().self_contacts().iter().any(|c| c.separation < 0.0));
    }
    assert!(
        touches > 0,
        "the legs never touched: the test would prove nothing"
    );
    assert!(worst < 0.05, "feet overlapped by {worst} m");
    assert!(
        deep <= 18,
        "{deep} of 1801 frames beyond {SOLVER_TOLERANCE} m"
    );
}
