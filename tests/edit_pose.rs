//! An edited robot keeps its posture and motion (`World::carry_pose`, the playground's edit of
//! a walking robot): the voxels that stay are where they were and move as they moved; an added
//! voxel sits against its neighbours and moves with them; the edited robot simulates on.

use vsr::simulation::carry::voxel_map;
use vsr::simulation::constants::{CORNER_SIDE, VOXEL_SIDE};
use vsr::simulation::{Shape, Terrain, World};

fn cells(rows: &str) -> Vec<(usize, usize)> {
    Shape::parse(rows).expect("valid shape").voxels().to_vec()
}

/// `rows` walking for 2.5 s on hilly terrain under a travelling wave.
fn walking(rows: &str) -> World {
    let terrain = Terrain::parse("hilly-1-10-3").unwrap();
    let mut w = World::new(&cells(rows), terrain.xs(), terrain.ys());
    let n = w.voxel_count();
    for k in 0..150 {
        let t = k as f64 / 60.0;
        let u: Vec<f64> = (0..n).map(|v| (6.0 * t + v as f64).sin()).collect();
        w.set_actuation(&u);
        w.step();
    }
    w
}

/// `rows` built where `old` starts and carried over from `old` with the edit's shift.
fn edited(
    old: &World,
    old_rows: &str,
    rows: &str,
    shift: (i64, i64),
) -> (World, Vec<Option<usize>>) {
    let terrain = Terrain::parse("hilly-1-10-3").unwrap();
    let mut w = World::new(&cells(rows), terrain.xs(), terrain.ys());
    let map = voxel_map(&cells(old_rows), &cells(rows), shift);
    w.carry_pose(old, &map);
    (w, map)
}

/// Every kept voxel's squares: the same pose and velocity as before the edit.
fn assert_kept(old: &World, new: &World, map: &[Option<usize>]) -> usize {
    let mut kept = 0;
    for (v, ov) in map.iter().enumerate() {
        let Some(ov) = *ov else { continue };
        kept += 1;
        for c in 0..4 {
            let (a, b) = (old.square_pose(4 * ov + c), new.square_pose(4 * v + c));
            let (va, vb) = (
                old.square_velocity(4 * ov + c),
                new.square_velocity(4 * v + c),
            );
            for (x, y) in [
                (a.0, b.0),
                (a.1, b.1),
                (a.2, b.2),
                (va.0, vb.0),
                (va.1, vb.1),
                (va.2, vb.2),
            ] {
                assert!(
                    (x - y).abs() < 1e-9,
                    "voxel {v} corner {c}: {a:?} {va:?} became {b:?} {vb:?}"
                );
            }
        }
    }
    kept
}

/// The edited robot steps on for 2 s without falling apart or flying off.
fn assert_simulates(mut w: World) {
    let n = w.voxel_count();
    for k in 0..120 {
        let u: Vec<f64> = (0..n)
            .map(|v| ((k as f64) / 10.0 + v as f64).sin())
            .collect();
        w.set_actuation(&u);
        w.step();
        assert!(w.is_finite(), "step {k}");
    }
    for s in 0..4 * n {
        let (vx, vy, _) = w.square_velocity(s);
        assert!(vx.hypot(vy) < 20.0, "square {s} at {vx}, {vy} m/s");
    }
}

#[test]
fn the_same_robot_carried_over_is_the_same_state() {
    let rows = "1111-1111-1001";
    let old = walking(rows);
    let (new, map) = edited(&old, rows, rows, (0, 0));
    assert_eq!(assert_kept(&old, &new, &map), 10);
    // It moved: the carry-over is not a robot at rest at its start.
    assert!(old.square_velocity(0).0.abs() + old.square_velocity(0).1.abs() > 1e-3);
}

#[test]
fn a_removed_voxel_leaves_the_others_where_and_as_they_were() {
    let old = walking("1111-1111-1001");
    // The top-left voxel removed (same bounding box), then a foot.
    for rows in ["0111-1111-1001", "1111-1111-0001"] {
        let (new, map) = edited(&old, "1111-1111-1001", rows, (0, 0));
        assert_eq!(assert_kept(&old, &new, &map), 9, "{rows}");
        assert_simulates(new);
    }
}

#[test]
fn a_removal_that_moves_the_bounding_box_follows_the_shift() {
    // A worm losing its left voxel: the rows are trimmed, new x = old x - 1.
    let old = walking("1111");
    let (new, map) = edited(&old, "1111", "111", (-1, 0));
    assert_eq!(map, [Some(1), Some(2), Some(3)]);
    assert_eq!(assert_kept(&old, &new, &map), 3);
    assert_simulates(new);
}

#[test]
fn an_added_voxel_sits_against_its_neighbour_and_moves_with_it() {
    let old = walking("1111-1111-1001");
    // A voxel on top of the top-right one: a new top row.
    let (new, map) = edited(&old, "1111-1111-1001", "0001-1111-1111-1001", (0, 0));
    assert_eq!(assert_kept(&old, &new, &map), 10);
    let added = map.iter().position(Option::is_none).unwrap();
    let below = map
        .iter()
        .position(|&m| {
            m == Some(
                cells("1111-1111-1001")
                    .iter()
                    .position(|&c| c == (3, 2))
                    .unwrap(),
            )
        })
        .unwrap();
    let centre = |w: &World, v: usize| {
        let ps: Vec<_> = (0..4).map(|c| w.square_pose(4 * v + c)).collect();
        (
            ps.iter().map(|p| p.0).sum::<f64>() / 4.0,
            ps.iter().map(|p| p.1).sum::<f64>() / 4.0,
        )
    };
    let (a, b) = (centre(&new, added), centre(&new, below));
    let gap = (a.0 - b.0).hypot(a.1 - b.1);
    assert!(
        (gap / VOXEL_SIDE - 1.0).abs() < 0.3,
        "{gap} m between the added voxel and its neighbour"
    );
    assert!(a.1 > b.1, "the added voxel is on top");
    // Its free top corners (pieces of their own): each placed by the rigid motion of the
    // welded corner below it, at rest distance from it and moving with it as one body.
    for (top, bottom) in [(2, 1), (3, 0)] {
        let (pt, pb) = (
            new.square_pose(4 * added + top),
            new.square_pose(4 * added + bottom),
        );
        let (vt, vb) = (
            new.square_velocity(4 * added + top),
            new.square_velocity(4 * added + bottom),
        );
        let apart = (pt.0 - pb.0).hypot(pt.1 - pb.1);
        assert!(
            (apart - (VOXEL_SIDE - CORNER_SIDE)).abs() < 1e-9,
            "{apart} m"
        );
        assert_eq!(pt.2, pb.2, "the same angle");
        let rigid = (vb.0 - vb.2 * (pt.1 - pb.1), vb.1 + vb.2 * (pt.0 - pb.0));
        assert!(
            (vt.0 - rigid.0).abs() < 1e-9 && (vt.1 - rigid.1).abs() < 1e-9,
            "{vt:?} {rigid:?}"
        );
        assert_eq!(vt.2, vb.2);
    }
    assert_simulates(new);
}

#[test]
fn voxel_maps_follow_the_shift() {
    let old = [(0, 0), (1, 0), (1, 1)];
    assert_eq!(
        voxel_map(&old, &[(0, 0), (1, 0), (1, 1)], (0, 0)),
        [Some(0), Some(1), Some(2)]
    );
    // Added to the left: the old cells moved right by one.
    assert_eq!(
        voxel_map(&old, &[(0, 0), (1, 0), (2, 0), (2, 1)], (1, 0)),
        [None, Some(0), Some(1), Some(2)]
    );
    assert_eq!(voxel_map(&old, &[(0, 0)], (-1, -1)), [Some(2)]);
}

#[test]
fn a_voxel_added_under_a_foot_lifts_the_robot_out_of_the_ground() {
    let old = walking("1111-1111-1001");
    // Under the left foot: a new bottom row, so the old cells moved up by one.
    let (new, map) = edited(&old, "1111-1111-1001", "1111-1111-1001-1000", (0, 1));
    // The new foot starts in the ground, so the whole robot is lifted out of it: the kept
    // voxels keep their posture, one common lift higher, and no corner is in the ground.
    let (a, b) = (
        old.square_pose(0),
        new.square_pose(4 * map.iter().position(|&m| m == Some(0)).unwrap()),
    );
    let lift = b.1 - a.1;
    assert!(lift > 0.1, "lifted {lift} m");
    for (v, ov) in map.iter().enumerate() {
        let Some(ov) = *ov else { continue };
        for c in 0..4 {
            let (a, b) = (old.square_pose(4 * ov + c), new.square_pose(4 * v + c));
            assert!((a.0 - b.0).abs() < 1e-9 && (a.1 + lift - b.1).abs() < 1e-9 && a.2 == b.2);
        }
    }
    let half = CORNER_SIDE / 2.0;
    for s in 0..4 * new.voxel_count() {
        let (x, y, angle) = new.square_pose(s);
        for (sx, sy) in [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)] {
            let (cx, cy) = (
                x + half * (sx * angle.cos() - sy * angle.sin()),
                y + half * (sx * angle.sin() + sy * angle.cos()),
            );
            assert!(
                cy - new.ground().height_at(cx) > -1e-9,
                "square {s} in the ground"
            );
        }
    }
    assert_simulates(new);
}
