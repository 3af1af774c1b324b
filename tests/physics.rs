//! Physics invariants of the simulator (issue 2, items 7 and 9). Each test states what
//! it protects; tolerances are in the assertion messages.

mod common;
use common::mechanical_energy;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use vsr::simulation::constants::{CORNER_MASS, DAMPING, DT, GRAVITY};
use vsr::simulation::{Shape, Terrain, World};

fn world(shape: &str, terrain: &str) -> World {
    let shape = Shape::parse(shape).expect("valid shape");
    let terrain = Terrain::parse(terrain).expect("valid terrain");
    World::new(shape.voxels(), terrain.xs(), terrain.ys())
}

fn run(w: &mut World, steps: usize) {
    for _ in 0..steps {
        w.step();
    }
}

#[test]
fn passive_robot_settles_on_flat_ground() {
    let mut w = world("biped-4x3", "flat");
    run(&mut w, 300);
    let x5 = w.centre().0;
    let mut areas = Vec::new();
    for _ in 0..1500 {
        w.step();
        areas.push(
            (0..w.voxel_count())
                .map(|v| w.area_ratio(v))
                .collect::<Vec<_>>(),
        );
    }
    let drift = (w.centre().0 - x5).abs();
    assert!(drift < 0.01, "drifted {drift} m in 25 s (limit 1 cm)");
    for a in areas.iter().flatten() {
        assert!((a - 1.0).abs() < 0.05, "area ratio {a} outside 1 +- 0.05");
    }
    let (first, last) = (&areas[areas.len() - 60], &areas[areas.len() - 1]);
    for (a, b) in first.iter().zip(last) {
        assert!(
            (a - b).abs() < 1e-3,
            "area still changing in the last second: {a} -> {b}"
        );
    }
}

#[test]
fn holding_full_actuation_reaches_the_area_limits() {
    for (u, target) in [(1.0, 0.775), (-1.0, 1.225)] {
        let mut w = world("biped-4x3", "flat");
        w.set_actuation(&[u; 10]);
        run(&mut w, 180);
        for v in 0..w.voxel_count() {
            let a = w.area_ratio(v);
            assert!(
                (a - target).abs() < 0.03,
                "u = {u}: voxel {v} area {a}, want {target} +- 0.03"
            );
        }
    }
}

#[test]
fn a_voxel_contracts_within_a_fifth_of_a_second_in_free_fall() {
    // The reference trace contracts to ~0.80 at u = 0.81 within 0.2 s.
    let mut w = world("1", "flat");
    w.set_actuation(&[1.0]);
    run(&mut w, 12);
    let a = w.area_ratio(0);
    assert_eq!(w.contact_count(), 0, "still in the air");
    assert!((a - 0.775).abs() < 0.02, "area {a} after 0.2 s at u = 1");
}

#[test]
fn free_fall_matches_gravity_with_damping() {
    let mut w = world("biped-4x3", "flat");
    let y0 = w.centre().1;
    let (mut v, mut y) = (0.0, y0);
    for _ in 0..20 {
        w.step();
        v = (v + GRAVITY * DT) * (1.0 - DT * DAMPING);
        y += v * DT;
    }
    assert_eq!(w.contact_count(), 0, "touched the ground within 1/3 s");
    let got = w.centre().1;
    assert!(
        (got - y).abs() < 1e-6,
        "centre y {got}, expected {y} from g = 9.8 and damping 0.1"
    );
    // Symplectic Euler without damping falls g dt^2 n (n + 1) / 2; damping takes a
    // little off that.
    let fallen = y0 - got;
    let undamped = 9.8 * DT * DT * 20.0 * 21.0 / 2.0;
    assert!(
        fallen < undamped && fallen > 0.98 * undamped,
        "fell {fallen} m, undamped {undamped}"
    );
}

#[test]
fn passive_robot_never_gains_energy() {
    for terrain in ["flat", "hilly-1-10-3"] {
        let mut w = world("comb-7x2", terrain);
        w.step();
        let start = mechanical_energy(&w);
        let mass = CORNER_MASS * 4.0 * 11.0;
        for step in 0..1800 {
            w.step();
            let e = mechanical_energy(&w);
            // Position correction may lift a body by the slop (5 mm): allow that much.
            assert!(
                e <= start + mass * 9.8 * 0.005,
                "{terrain}: energy {e} > start {start} at step {step}"
            );
        }
    }
}

#[test]
fn same_inputs_give_bit_identical_trajectories() {
    let trajectory = || {
        let mut w = world("comb-7x2", "hilly-1-10-1");
        let mut out = Vec::new();
        for k in 0..900 {
            let u: Vec<f64> = (0..11)
                .map(|v| libm::sin(0.1 * k as f64 + v as f64))
                .collect();
            w.set_actuation(&u);
            w.step();
            let p = w.pieces();
            out.extend(p.x.iter().chain(&p.y).chain(&p.angle).map(|v| v.to_bits()));
        }
        out
    };
    assert_eq!(trajectory(), trajectory());
}

/// A random 4-connected shape grown from one cell.
fn random_shape(rng: &mut ChaCha8Rng) -> String {
    let (w, h) = (rng.gen_range(1..=6), rng.gen_range(1..=4));
    let mut cells = vec![vec![false; w]; h];
    let target = rng.gen_range(1..=w * h);
    cells[rng.gen_range(0..h)][rng.gen_range(0..w)] = true;
    let mut count = 1;
    while count < target {
        let (x, y) = (rng.gen_range(0..w), rng.gen_range(0..h));
        let near = |dx: i64, dy: i64| {
            let (nx, ny) = (x as i64 + dx, y as i64 + dy);
            nx >= 0
                && ny >= 0
                && (nx as usize) < w
                && (ny as usize) < h
                && cells[ny as usize][nx as usize]
        };
        if !cells[y][x] && (near(1, 0) || near(-1, 0) || near(0, 1) || near(0, -1)) {
            cells[y][x] = true;
            count += 1;
        }
    }
    let rows: Vec<String> = cells
        .iter()
        .rev()
        .map(|r| r.iter().map(|&c| if c { '1' } else { '0' }).collect())
        .collect();
    rows.join("-")
}

#[test]
fn random_actuation_never_explodes_or_sinks() {
    let mut rng = ChaCha8Rng::seed_from_u64(7);
    for case in 0..4 {
        let rows = random_shape(&mut rng);
        let shape = Shape::parse(&rows).expect("generated shapes are valid");
        let terrain = Terrain::parse(&format!("hilly-1-10-{case}")).expect("valid");
        let mut w = World::new(shape.voxels(), terrain.xs(), terrain.ys());
        let n = shape.voxel_count();
        for step in 0..20_000 {
            if step % 20 == 0 {
                let u: Vec<f64> = (0..n).map(|_| rng.gen_range(-1.0..=1.0)).collect();
                w.set_actuation(&u);
            }
            w.step();
            if step % 100 == 0 {
                assert!(w.is_finite(), "{rows}: non-finite state at step {step}");
                for s in 0..4 * n {
                    let (x, y, _) = w.square_pose(s);
                    let ground = terrain.height_at(x);
                    assert!(
                        y > ground,
                        "{rows}: square {s} centre {y} below ground {ground} at step {step}"
                    );
                }
            }
        }
    }
}

#[test]
fn friction_holds_a_bar_on_a_slope_and_lets_it_slide_when_low() {
    // A 26.6 degree slope (tan = 0.5, the true slope of `uphill-30`): friction 1.414
    // holds a resting body, 0.3 cannot. A 3x1 bar, because a single voxel dropped
    // corner-first from 1 m tumbles down such a slope.
    let shape = Shape::parse("worm-3x1").expect("valid");
    let drift = |friction: f64| {
        let mut w = World::new(shape.voxels(), &[0.0, 2000.0], &[1000.0, 0.0]);
        w.set_friction(friction);
        run(&mut w, 120);
        let (x0, y0) = w.centre();
        run(&mut w, 600);
        let (x1, y1) = w.centre();
        ((x1 - x0).powi(2) + (y1 - y0).powi(2)).sqrt()
    };
    let held = drift(std::f64::consts::SQRT_2);
    assert!(held < 0.01, "slid {held} m in 10 s with friction 1.414");
    // Sliding from rest: s = a t^2 / 2 with a = g (sin - mu cos) = 1.75 m/s^2, less
    // the damping: expect most of 87 m.
    let slid = drift(0.3);
    assert!(
        slid > 60.0 && slid < 90.0,
        "slid {slid} m in 10 s with friction 0.3"
    );
}
