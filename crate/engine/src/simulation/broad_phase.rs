//! Broad phase of self-collision: sort and sweep along x over the rigid pieces'
//! bounding boxes, then the squares of each overlapping pair of pieces, so that only
//! squares whose boxes overlap reach the narrow phase. Each square's box is widened by
//! half the contact margin and by how far the square can move in one step
//! (speculative contacts, see `self_collide.rs`); a piece's box encloses its squares'.
//!
//! Sweeping pieces rather than squares: a piece is the one to four squares welded at a
//! grid vertex, and neighbouring vertices are 3 m apart, so at rest no two pieces'
//! boxes overlap and the sweep does almost nothing. The x order of the pieces is kept
//! between steps and repaired by insertion sort (nearly linear: bodies move little per
//! step). Pairs that can never collide are never tested: squares of the same piece
//! (welded, SPEC 4) and squares of the same voxel (SPEC 2: joined by springs, and
//! joined bodies do not collide). The candidate pairs come out sorted by (lower square,
//! higher square), so the result does not depend on the sweep order.

use super::body::{Pieces, Squares};
use super::box_box::SquarePose;
use super::constants::{CORNER_SIDE, DT};

/// Half the side of a corner square (m).
const HALF: f64 = CORNER_SIDE / 2.0;
/// Half the diagonal of a corner square (m): the farthest a point of it is from its centre.
pub(crate) const RADIUS: f64 = HALF * std::f64::consts::SQRT_2;

/// How a square moves: velocity of its centre (m/s) and angular velocity (rad/s).
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub(crate) struct Motion {
    /// Velocity of the centre along x.
    pub(crate) vx: f64,
    /// Velocity of the centre along y.
    pub(crate) vy: f64,
    /// Angular velocity.
    pub(crate) w: f64,
}

/// An axis-aligned box: min x, max x, min y, max y (m).
type Aabb = [f64; 4];

#[inline]
fn overlap_y(a: &Aabb, b: &Aabb) -> bool {
    b[2] <= a[3] && a[2] <= b[3]
}

/// Square and piece boxes, the pieces' x order and the candidate pairs of this step.
#[derive(Debug, Clone, Default)]
pub(crate) struct BroadPhase {
    /// Squares of piece p: `members[start[p]..start[p + 1]]`, ascending.
    members: Vec<u32>,
    start: Vec<usize>,
    /// Box of each square, in `members` order, widened by half the margin and one
    /// step of its motion.
    boxes: Vec<Aabb>,
    /// Box of each piece: the union of its squares' boxes.
    piece_boxes: Vec<Aabb>,
    /// Piece indices sorted by the left edge of their box.
    order: Vec<u32>,
    /// Pose of each square this step (square index order).
    poses: Vec<SquarePose>,
    /// Motion of each square this step (square index order).
    motions: Vec<Motion>,
    /// Candidate pairs (a < b) whose boxes overlap and that may collide.
    pairs: Vec<(u32, u32)>,
}

impl BroadPhase {
    /// A broad phase over the squares of a robot.
    pub(crate) fn new(squares: &Squares, n_pieces: usize) -> Self {
        let mut start = vec![0; n_pieces + 1];
        for &p in &squares.piece {
            start[p + 1] += 1;
        }
        for p in 0..n_pieces {
            start[p + 1] += start[p];
        }
        let mut fill = start.clone();
        let mut members = vec![0; squares.len()];
        for (s, &p) in squares.piece.iter().enumerate() {
            members[fill[p]] = s as u32;
            fill[p] += 1;
        }
        let n = squares.len();
        BroadPhase {
            members,
            start,
            boxes: vec![[0.0; 4]; n],
            piece_boxes: vec![[0.0; 4]; n_pieces],
            order: (0..n_pieces as u32).collect(),
            poses: vec![SquarePose::default(); n],
            motions: vec![Motion::default(); n],
            pairs: Vec::new(),
        }
    }

    /// Finds the pairs of squares whose boxes overlap and that belong to different
    /// voxels and different pieces; also records every square's pose and motion.
    pub(crate) fn update(&mut self, pieces: &Pieces, squares: &Squares, margin: f64) {
        self.compute_boxes(pieces, squares, margin);
        self.sort();
        self.pairs.clear();
        let range = |p: u32| self.start[p as usize]..self.start[p as usize + 1];
        for (k, &p) in self.order.iter().enumerate() {
            let bp = &self.piece_boxes[p as usize];
            for &q in &self.order[k + 1..] {
                let bq = &self.piece_boxes[q as usize];
                if bq[0] > bp[1] {
                    break;
                }
                if overlap_y(bp, bq) {
                    let (rp, rq) = (range(p), range(q));
                    square_pairs(
                        (&self.members[rp.clone()], &self.boxes[rp]),
                        (&self.members[rq.clone()], &self.boxes[rq]),
                        &mut self.pairs,
                    );
                }
            }
        }
        self.pairs.sort_unstable();
    }

    /// The candidate pairs (a < b) of the last update, sorted.
    pub(crate) fn pairs(&self) -> &[(u32, u32)] {
        &self.pairs
    }

    /// Pose of square `s` at the last update.
    #[inline]
    pub(crate) fn pose(&self, s: usize) -> SquarePose {
        self.poses[s]
    }

    /// Motion of square `s` at the last update.
    #[inline]
    pub(crate) fn motion(&self, s: usize) -> Motion {
        self.motions[s]
    }

    /// Every square's pose, motion and box, and every piece's box.
    fn compute_boxes(&mut self, pieces: &Pieces, squares: &Squares, margin: f64) {
        for p in 0..self.piece_boxes.len() {
            let (px, py, c, sn) = (pieces.x[p], pieces.y[p], pieces.cos[p], pieces.sin[p]);
            let v = pieces.vel[p];
            // Half extent of a square along x and y, h (|cos| + |sin|), plus what one
            // step can add: every point of the square moves at most |v| + |w| R.
            let extent = HALF * (c.abs() + sn.abs()) + 0.5 * margin;
            let spin = v.w.abs() * RADIUS;
            let mut union = [
                f64::INFINITY,
                f64::NEG_INFINITY,
                f64::INFINITY,
                f64::NEG_INFINITY,
            ];
            let range = self.start[p]..self.start[p + 1];
            for (&s, b) in self.members[range.clone()]
                .iter()
                .zip(&mut self.boxes[range])
            {
                let s = s as usize;
                let (lx, ly) = (squares.lx[s], squares.ly[s]);
                let (rx, ry) = (c * lx - sn * ly, sn * lx + c * ly);
                let (x, y) = (px + rx, py + ry);
                let (vx, vy) = (v.vx - v.w * ry, v.vy + v.w * rx);
                self.poses[s] = SquarePose { x, y, c, s: sn };
                self.motions[s] = Motion { vx, vy, w: v.w };
                let (ex, ey) = (
                    extent + DT * (vx.abs() + spin),
                    extent + DT * (vy.abs() + spin),
                );
                *b = [x - ex, x + ex, y - ey, y + ey];
                // Compare and select, not f64::min / max (a libm call in wasm): the
                // boxes are only ever compared, so a zero's sign cannot matter.
                let (lo, hi) = (
                    |u: f64, v: f64| if v < u { v } else { u },
                    |u: f64, v: f64| if v > u { v } else { u },
                );
                union = [
                    lo(union[0], b[0]),
                    hi(union[1], b[1]),
                    lo(union[2], b[2]),
                    hi(union[3], b[3]),
                ];
            }
            self.piece_boxes[p] = union;
        }
    }

    /// Insertion sort of `order` by left edge: stable, so ties keep last step's order.
    fn sort(&mut self) {
        let boxes = &self.piece_boxes;
        for i in 1..self.order.len() {
            let p = self.order[i];
            let key = boxes[p as usize][0];
            let mut j = i;
            while j > 0 && boxes[self.order[j - 1] as usize][0] > key {
                self.order[j] = self.order[j - 1];
                j -= 1;
            }
            self.order[j] = p;
        }
    }
}

/// Adds the pairs of squares, one of each piece (squares and their boxes), that
/// belong to different voxels and whose boxes overlap.
fn square_pairs(p: (&[u32], &[Aabb]), q: (&[u32], &[Aabb]), pairs: &mut Vec<(u32, u32)>) {
    for (&a, ba) in p.0.iter().zip(p.1) {
        for (&b, bb) in q.0.iter().zip(q.1) {
            let apart = bb[0] > ba[1] || ba[0] > bb[1] || !overlap_y(ba, bb);
            if !apart && a / 4 != b / 4 {
                pairs.push((a.min(b), a.max(b)));
            }
        }
    }
}
