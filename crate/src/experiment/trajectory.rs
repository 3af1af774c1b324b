//! A run as data to plot or animate outside the page (`vsr simulate --trajectory`,
//! `vsr evaluate --trajectory`): one [`Frame`] per step, written as one JSON line.
//!
//! Layout of a frame (SI units: m, rad): `t` the simulated time after the step;
//! `centre` [x, y] of the robot (mean of the voxel centres); `area` each voxel's area
//! ratio and `actuation` each voxel's held actuation after the step (what drives the
//! following steps, as the reference's snapshots record it), both in voxel index
//! order (SPEC 4); `squares` [x, y, angle] of every corner square, four per voxel in
//! voxel index order, corners SW, SE, NE, NW.

use super::episode::Episode;

/// One step of a run.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct Frame {
    /// Simulated time after the step (s).
    pub t: f64,
    /// Robot centre [x, y] (m).
    pub centre: [f64; 2],
    /// Area ratio of each voxel.
    pub area: Vec<f64>,
    /// Held actuation of each voxel, in [-1, 1].
    pub actuation: Vec<f64>,
    /// Centre x, y (m) and angle (rad) of each corner square, 4 per voxel.
    pub squares: Vec<[f64; 3]>,
}

impl Frame {
    /// The episode's current state.
    pub fn of(episode: &Episode) -> Frame {
        let w = episode.world();
        let n = w.voxel_count();
        let (x, y) = w.centre();
        Frame {
            t: episode.time(),
            centre: [x, y],
            area: (0..n).map(|v| w.area_ratio(v)).collect(),
            actuation: episode.actuation().to_vec(),
            squares: (0..4 * n)
                .map(|s| {
                    let (x, y, a) = w.square_pose(s);
                    [x, y, a]
                })
                .collect(),
        }
    }
}
