//! A run as data to plot or animate outside the page (`vsr simulate --trajectory`,
//! `vsr evaluate --trajectory`): one [`Frame`] per step, written as one JSON line.
//!
//! Layout of a frame (SI units: m, rad): `t` the simulated time after the step;
//! `centre` [x, y] of the robot (mean of the voxel centres); `area` each voxel's area
//! ratio and `actuation` each voxel's held actuation after the step (what drives the
//! following steps, as the reference's snapshots record it), both in voxel index
//! order (SPEC 4); `squares` [x, y, angle] of every corner square, four per voxel in
//! voxel index order, corners SW, SE, NE, NW.
//!
//! The same state as flat `f32` buffers (the page's frames, Python's arrays): the
//! `write_*` methods of [`Episode`] below.

use super::episode::Episode;

/// One step of a run.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct Frame {
    /// Simulated time after the step (s).
    pub(crate) t: f64,
    /// Robot centre [x, y] (m).
    pub(crate) centre: [f64; 2],
    /// Area ratio of each voxel.
    pub(crate) area: Vec<f64>,
    /// Held actuation of each voxel, in [-1, 1].
    pub(crate) actuation: Vec<f64>,
    /// Centre x, y (m) and angle (rad) of each corner square, 4 per voxel.
    pub(crate) squares: Vec<[f64; 3]>,
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

/// The episode's state into flat buffers, for drawing it or handing it to another language.
impl Episode {
    /// Writes 8 floats per voxel: outer corners x, y in order SW, SE, NE, NW.
    pub fn write_voxel_corners(&self, out: &mut [f32]) {
        for (v, chunk) in out.chunks_exact_mut(8).enumerate().take(self.voxel_count()) {
            for (c, (x, y)) in self.world().voxel_corners(v).into_iter().enumerate() {
                chunk[2 * c] = x as f32;
                chunk[2 * c + 1] = y as f32;
            }
        }
    }

    /// Writes one float per voxel: its area ratio.
    pub fn write_area_ratios(&self, out: &mut [f32]) {
        for (v, a) in out.iter_mut().enumerate().take(self.voxel_count()) {
            *a = self.world().area_ratio(v) as f32;
        }
    }

    /// Writes 12 floats per voxel: its 4 corner squares as centre x, y and angle,
    /// order SW, SE, NE, NW.
    pub fn write_corner_bodies(&self, out: &mut [f32]) {
        for (s, chunk) in out
            .chunks_exact_mut(3)
            .enumerate()
            .take(4 * self.voxel_count())
        {
            let (x, y, a) = self.world().square_pose(s);
            chunk.copy_from_slice(&[x as f32, y as f32, a as f32]);
        }
    }
}
