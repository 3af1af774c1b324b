//! Sensor readings (SPEC 6) for poses whose values can be worked out by hand.

use vsr::simulation::sensors::Sensors;
use vsr::simulation::{Shape, Terrain, World};

fn resting_biped() -> (World, Sensors) {
    let shape = Shape::parse("biped-4x3").expect("valid");
    let t = Terrain::parse("flat").expect("valid");
    let mut w = World::new(shape.voxels(), t.xs(), t.ys());
    let mut s = Sensors::new(shape.voxel_count(), None);
    for _ in 0..600 {
        w.step();
        s.sense(&w);
    }
    (w, s)
}

#[test]
fn a_resting_robot_reads_rest_values_and_touch_only_at_the_feet() {
    let (w, mut s) = resting_biped();
    let r = s.read(&w).to_vec();
    for v in 0..10 {
        let [area, vx, vy, touch] = [r[4 * v], r[4 * v + 1], r[4 * v + 2], r[4 * v + 3]];
        // area ratio ~0.97-1 under its own weight: 0.5 + 0.5 tanh(4 (a - 1)) ~ 0.44-0.5.
        assert!(
            (0.4..=0.52).contains(&area),
            "voxel {v} area reading {area}"
        );
        assert!(
            (vx - 0.5).abs() < 0.01 && (vy - 0.5).abs() < 0.01,
            "voxel {v} at rest reads {vx}, {vy}"
        );
        let foot = v < 2;
        assert_eq!(touch, if foot { 1.0 } else { 0.0 }, "voxel {v} touch");
    }
}

#[test]
fn velocity_readings_follow_the_voxel_frame_and_the_window() {
    // Free fall (placed 1 m above the ground, which it reaches after ~27 steps): the
    // average of vy over the samples so far and the reading 0.5 + 0.5 tanh(v / 4).
    let shape = Shape::parse("1").expect("valid");
    let mut w = World::new(shape.voxels(), &[0.0, 2000.0], &[-1e4, -1e4]);
    let mut s = Sensors::new(1, None);
    let mut vs = Vec::new();
    for _ in 0..20 {
        w.step();
        s.sense(&w);
        vs.push(w.voxel_velocity(0).1);
    }
    let mean = vs.iter().sum::<f64>() / 20.0;
    let r = s.read(&w);
    let want = 0.5 + 0.5 * (mean / 4.0).tanh();
    assert!(
        (f64::from(r[2]) - want).abs() < 1e-6,
        "vy reading {} want {want}",
        r[2]
    );
    assert!((f64::from(r[1]) - 0.5).abs() < 1e-6, "vx reading {}", r[1]);
    assert_eq!(r[3], 0.0, "nothing touched");
}

#[test]
fn noise_is_seeded_independent_and_about_one_hundredth() {
    let (w, _) = resting_biped();
    let readings = |seed: Option<u64>| {
        let mut s = Sensors::new(10, seed);
        (0..200)
            .flat_map(|_| s.read(&w).to_vec())
            .collect::<Vec<f32>>()
    };
    let clean = readings(None);
    let (a, b, c) = (readings(Some(1)), readings(Some(1)), readings(Some(2)));
    assert_eq!(a, b, "same seed, same noise");
    assert_ne!(a, c, "another seed, other noise");
    let diffs: Vec<f64> = a
        .iter()
        .zip(&clean)
        .map(|(x, y)| f64::from(x - y))
        .collect();
    let sd = (diffs.iter().map(|d| d * d).sum::<f64>() / diffs.len() as f64).sqrt();
    assert!((sd - 0.01).abs() < 0.001, "noise sd {sd}");
}
