//! What a voxel looks like from outside: its outer corner points, area ratio, centre,
//! angle and velocity, read from the world's pieces (SPEC 2 definitions).

use super::body::Corner;
use super::constants::{CORNER_SIDE, VOXEL_AREA};
use super::world::World;

/// Half the side of a corner square (m).
const HALF: f64 = CORNER_SIDE / 2.0;

impl World {
    /// Outer corner points of voxel `v` in order SW, SE, NE, NW (world, m).
    pub(crate) fn voxel_corners(&self, v: usize) -> [(f64, f64); 4] {
        Corner::ALL.map(|c| {
            let (sx, sy) = c.sign();
            self.squares
                .point(&self.pieces, 4 * v + c as usize, sx * HALF, sy * HALF)
        })
    }

    /// Area of the quadrilateral through the outer corners over the rest area.
    pub fn area_ratio(&self, v: usize) -> f64 {
        let p = self.voxel_corners(v);
        let mut twice = 0.0;
        for i in 0..4 {
            let (a, b) = (p[i], p[(i + 1) % 4]);
            twice += a.0 * b.1 - b.0 * a.1;
        }
        0.5 * twice / VOXEL_AREA
    }

    /// Centre of voxel `v`: mean of its outer corners.
    pub(crate) fn voxel_centre(&self, v: usize) -> (f64, f64) {
        let p = self.voxel_corners(v);
        (
            (p[0].0 + p[1].0 + p[2].0 + p[3].0) / 4.0,
            (p[0].1 + p[1].1 + p[2].1 + p[3].1) / 4.0,
        )
    }

    /// Cosine and sine of voxel `v`'s angle (the mean direction of its bottom and top
    /// edges, both taken left to right), computed without trigonometry: the
    /// bisector of its bottom and top edge directions (the same angle as the mean of
    /// the two edge angles whenever the edges are less than 180 degrees apart).
    pub(crate) fn voxel_frame(&self, v: usize) -> (f64, f64) {
        let p = self.voxel_corners(v);
        let unit = |dx: f64, dy: f64| {
            let len = (dx * dx + dy * dy).sqrt();
            (dx / len, dy / len)
        };
        let b = unit(p[1].0 - p[0].0, p[1].1 - p[0].1);
        let t = unit(p[2].0 - p[3].0, p[2].1 - p[3].1);
        let (c, s) = unit(b.0 + t.0, b.1 + t.1);
        if c.is_finite() && s.is_finite() {
            (c, s)
        } else {
            (1.0, 0.0)
        }
    }

    /// Velocity of voxel `v` (m/s): mean velocity of its corner squares' centres.
    pub fn voxel_velocity(&self, v: usize) -> (f64, f64) {
        let (mut vx, mut vy) = (0.0, 0.0);
        for c in 0..4 {
            let s = 4 * v + c;
            let p = self.squares.piece[s];
            let (rx, ry) = self
                .pieces
                .rotate(p, self.squares.lx[s], self.squares.ly[s]);
            let (px, py) = self.pieces.point_velocity(p, rx, ry);
            vx += px;
            vy += py;
        }
        (vx / 4.0, vy / 4.0)
    }

    /// Centre of the robot: mean of its voxel centres (m).
    pub fn centre(&self) -> (f64, f64) {
        let n = self.voxel_count();
        let (mut x, mut y) = (0.0, 0.0);
        for v in 0..n {
            let c = self.voxel_centre(v);
            x += c.0;
            y += c.1;
        }
        (x / n as f64, y / n as f64)
    }

    /// Centre (x, y) and angle of corner square `s` (4 * voxel + corner).
    pub fn square_pose(&self, s: usize) -> (f64, f64, f64) {
        let p = self.squares.piece[s];
        let (x, y) = self.squares.point(&self.pieces, s, 0.0, 0.0);
        (x, y, self.pieces.angle[p])
    }

    /// Velocity (vx, vy) of the centre of corner square `s`, and its angular velocity.
    pub fn square_velocity(&self, s: usize) -> (f64, f64, f64) {
        let p = self.squares.piece[s];
        let (x, y) = self.squares.point(&self.pieces, s, 0.0, 0.0);
        let (vx, vy) = self
            .pieces
            .point_velocity(p, x - self.pieces.x[p], y - self.pieces.y[p]);
        (vx, vy, self.pieces.vel[p].w)
    }

    /// Axis-aligned bounding box of the robot's outer corners: (min x, min y, max x, max y).
    pub fn bounding_box(&self) -> (f64, f64, f64, f64) {
        let mut b = (
            f64::INFINITY,
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::NEG_INFINITY,
        );
        for v in 0..self.voxel_count() {
            for (x, y) in self.voxel_corners(v) {
                b = (b.0.min(x), b.1.min(y), b.2.max(x), b.3.max(y));
            }
        }
        b
    }
}
