//! Carrying a robot's posture and motion over to an edited robot (the playground's edit of a
//! walking robot: one voxel added or removed). The edited robot is built afresh (pieces,
//! springs, ropes, welds), then every piece takes its pose and velocity from the old robot:
//! a piece with a square whose voxel was there before moves as that square's old piece
//! moved it; a piece of a new voxel's own corners follows the rigid motion of a placed piece
//! of the same voxel, a corner beside it first. A robot that would start in the ground (a
//! voxel added under a foot) is lifted out of it. Contacts are detected anew. The result is
//! the edited robot in the old one's posture and speed, not a restart at rest.

use super::body::Velocity;
use super::constants::{CORNER_SIDE, LINEAR_SLOP};
use super::world::World;
use std::collections::HashMap;

/// For each voxel of `new_cells`, the index of the same voxel in `old_cells`, where a new
/// cell `(x, y)` is the old cell `(x - dx, y - dy)` (the shift of an edit that moved the
/// grid's bounding box); `None` for a voxel that was not there.
pub fn voxel_map(
    old_cells: &[(usize, usize)],
    new_cells: &[(usize, usize)],
    (dx, dy): (i64, i64),
) -> Vec<Option<usize>> {
    let old: HashMap<(i64, i64), usize> = old_cells
        .iter()
        .enumerate()
        .map(|(i, &(x, y))| ((x as i64, y as i64), i))
        .collect();
    new_cells
        .iter()
        .map(|&(x, y)| old.get(&(x as i64 - dx, y as i64 - dy)).copied())
        .collect()
}

/// A piece's rigid motion: where its build-frame origin went, its angle and its velocity.
#[derive(Clone, Copy)]
struct Motion {
    /// Build position of the reference point (m).
    from: (f64, f64),
    /// Its position now (m).
    to: (f64, f64),
    angle: f64,
    /// Velocity of the reference point now, and the angular velocity.
    vel: Velocity,
}

impl Motion {
    /// Where the build position `p` goes under this motion, and its velocity there.
    fn apply(&self, p: (f64, f64)) -> ((f64, f64), Velocity) {
        let (c, s) = (libm::cos(self.angle), libm::sin(self.angle));
        let (lx, ly) = (p.0 - self.from.0, p.1 - self.from.1);
        let (rx, ry) = (c * lx - s * ly, s * lx + c * ly);
        let at = (self.to.0 + rx, self.to.1 + ry);
        let v = self.vel;
        let vel = Velocity {
            vx: v.vx - v.w * ry,
            vy: v.vy + v.w * rx,
            w: v.w,
        };
        (at, vel)
    }
}

impl World {
    /// Puts this freshly built robot in the posture and motion of `old`; `map[v]` is the
    /// old index of voxel `v` (see [`voxel_map`]). Pieces with nothing to follow (no voxel
    /// of theirs or of their voxels' was in `old`) keep their build pose at rest.
    pub fn carry_pose(&mut self, old: &World, map: &[Option<usize>]) {
        let pieces = self.pieces.len();
        let build: Vec<(f64, f64)> = (0..pieces)
            .map(|p| (self.pieces.x[p], self.pieces.y[p]))
            .collect();
        let mut motion: Vec<Option<Motion>> = vec![None; pieces];
        // Pieces with a square that was there: follow that square's old piece.
        for s in 0..self.squares.len().min(4 * map.len()) {
            let p = self.squares.piece[s];
            let Some(ov) = map[s / 4] else { continue };
            if motion[p].is_some() || 4 * ov + 3 >= old.squares.len() {
                continue;
            }
            let os = 4 * ov + s % 4;
            let op = old.squares.piece[os];
            let centre = old.squares.point(&old.pieces, os, 0.0, 0.0);
            let square_build = (
                build[p].0 + self.squares.lx[s],
                build[p].1 + self.squares.ly[s],
            );
            let (rx, ry) = (centre.0 - old.pieces.x[op], centre.1 - old.pieces.y[op]);
            let (vx, vy) = old.pieces.point_velocity(op, rx, ry);
            motion[p] = Some(Motion {
                from: square_build,
                to: centre,
                angle: old.pieces.angle[op],
                vel: Velocity {
                    vx,
                    vy,
                    w: old.pieces.vel[op].w,
                },
            });
        }
        // The rest (a new voxel's own corners): follow a placed piece of the same voxel, a
        // corner on the same side first (then the opposite one), else any placed piece, so
        // that the robot moves as one.
        let any = motion.iter().flatten().next().copied();
        let placed = motion.clone();
        for s in 0..self.squares.len() {
            let p = self.squares.piece[s];
            if motion[p].is_none() {
                let (v, c) = (s / 4, s % 4);
                let near = [3, 1, 2].map(|k| placed[self.squares.piece[4 * v + (c + k) % 4]]);
                motion[p] = near.into_iter().flatten().next().or(any);
            }
        }
        for (p, m) in motion.iter().enumerate() {
            let Some(m) = m else { continue };
            let ((x, y), vel) = m.apply(build[p]);
            self.pieces.x[p] = x;
            self.pieces.y[p] = y;
            self.pieces.set_angle(p, m.angle);
            self.pieces.vel[p] = vel;
        }
        // A voxel added under a foot may sit in the ground: lift the robot out of it rather
        // than let the contacts kick it out (a walking robot's own contacts, a few slops
        // deep at most, are left to the solver as they were).
        let lift = self.depth_in_ground();
        if lift > 3.0 * LINEAR_SLOP {
            self.pieces.y.iter_mut().for_each(|y| *y += lift);
        }
        self.detect_contacts();
    }

    /// How deep the deepest outer corner of a square lies below the ground (m; 0 if none).
    fn depth_in_ground(&self) -> f64 {
        let half = CORNER_SIDE / 2.0;
        let mut depth: f64 = 0.0;
        for s in 0..self.squares.len() {
            for (sx, sy) in [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)] {
                let (x, y) = self.squares.point(&self.pieces, s, sx * half, sy * half);
                depth = depth.max(self.ground.height_at(x) - y);
            }
        }
        depth
    }
}
