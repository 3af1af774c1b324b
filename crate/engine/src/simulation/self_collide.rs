//! Self-collision detection: contacts between corner squares of different voxels that
//! are not welded together (SPEC 3), found by the sort-and-sweep broad phase and the
//! box-vs-box narrow phase.
//!
//! Contacts are speculative: a pair is a contact while its gap is below a margin (the
//! ground's 1 cm, widened by the world in the step after an actuation change) plus the
//! distance the two squares can close in one step at their current speeds. The solver
//! lets a speculative contact close its gap but not cross it, so swinging limbs stop
//! at the surface instead of sinking into each other for a step (there is no
//! continuous collision detection, SPEC 12).
//!
//! A contact keeps its geometry in the two pieces' frames (the reference face's normal
//! and a point on it in the reference piece, the incident point in the other piece),
//! so the position solver can recompute its separation after the pieces move, as
//! Box2D's position solver does. Contacts come out sorted by key (lower square, higher
//! square, feature), the order the solver's warm start relies on.

use super::body::{Pieces, Squares};
use super::box_box::{collide, FACES};
use super::broad_phase::{BroadPhase, RADIUS};
use super::constants::{CORNER_SIDE, DT};

/// Half the side of a corner square (m).
const HALF: f64 = CORNER_SIDE / 2.0;

/// One contact point between two corner squares of different pieces.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PairContact {
    /// Stable identity across steps: the two squares and the feature.
    pub(crate) key: u64,
    /// Piece holding the reference face.
    pub(crate) a: usize,
    /// Piece holding the incident point.
    pub(crate) b: usize,
    /// Reference face normal, piece a's frame.
    pub(crate) normal: (f64, f64),
    /// A point on the reference face: piece-frame offset from a's centre of mass.
    pub(crate) face_point: (f64, f64),
    /// The incident point: piece-frame offset from b's centre of mass.
    pub(crate) point: (f64, f64),
    /// Separation when detected (m): negative when penetrating, at most the margin.
    pub separation: f64,
}

/// A contact's geometry in the current pose.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct PairGeometry {
    /// World normal, from piece a toward piece b.
    pub(crate) n: (f64, f64),
    /// Offset of the contact point from a's centre of mass (world).
    pub(crate) ra: (f64, f64),
    /// Offset of the contact point from b's centre of mass (world).
    pub(crate) rb: (f64, f64),
    /// Separation (m), negative when penetrating.
    pub(crate) separation: f64,
}

impl PairContact {
    /// The contact's geometry for the pieces' current pose. The contact point is
    /// halfway between the incident point and the reference face.
    #[inline]
    pub(crate) fn evaluate(&self, pieces: &Pieces) -> PairGeometry {
        let (a, b) = (self.a, self.b);
        let n = pieces.rotate(a, self.normal.0, self.normal.1);
        let (fx, fy) = pieces.to_world(a, self.face_point.0, self.face_point.1);
        let (px, py) = pieces.to_world(b, self.point.0, self.point.1);
        let separation = n.0 * (px - fx) + n.1 * (py - fy);
        let (cx, cy) = (px - 0.5 * separation * n.0, py - 0.5 * separation * n.1);
        let ra = (cx - pieces.x[a], cy - pieces.y[a]);
        let rb = (cx - pieces.x[b], cy - pieces.y[b]);
        PairGeometry {
            n,
            ra,
            rb,
            separation,
        }
    }
}

/// Piece-frame offset from piece p's centre of mass of world point q.
#[inline]
fn to_local(pieces: &Pieces, p: usize, q: (f64, f64)) -> (f64, f64) {
    let (dx, dy) = (q.0 - pieces.x[p], q.1 - pieces.y[p]);
    let (c, s) = (pieces.cos[p], pieces.sin[p]);
    (c * dx + s * dy, -s * dx + c * dy)
}

/// The gap (m) below which squares a and b are a contact: `base` plus a bound on how
/// much they can close in one step (|relative velocity of the centres|, as
/// |dx| + |dy| >= its length, plus both spins times the half diagonal).
#[inline]
fn margin(broad: &BroadPhase, base: f64, a: usize, b: usize) -> f64 {
    let (ma, mb) = (broad.motion(a), broad.motion(b));
    let closing =
        (mb.vx - ma.vx).abs() + (mb.vy - ma.vy).abs() + (ma.w.abs() + mb.w.abs()) * RADIUS;
    base + DT * closing
}

/// Finds every contact between squares of different voxels and pieces, speculative
/// up to `base` (m) plus what the pair's speeds close in one step.
pub(crate) fn detect_self(
    pieces: &Pieces,
    squares: &Squares,
    broad: &mut BroadPhase,
    base: f64,
    out: &mut Vec<PairContact>,
) {
    out.clear();
    broad.update(pieces, squares, base);
    for &(sa, sb) in broad.pairs() {
        let (sa, sb) = (sa as usize, sb as usize);
        let Some(m) = collide(
            &broad.pose(sa),
            &broad.pose(sb),
            margin(broad, base, sa, sb),
        ) else {
            continue;
        };
        let (ref_sq, inc_sq) = if m.flipped { (sb, sa) } else { (sa, sb) };
        let (a, b) = (squares.piece[ref_sq], squares.piece[inc_sq]);
        let normal = FACES[m.reference_face];
        let face_point = (
            squares.lx[ref_sq] + normal.0 * HALF,
            squares.ly[ref_sq] + normal.1 * HALF,
        );
        let feature = ((m.flipped as u64) << 5)
            | ((m.reference_face as u64) << 3)
            | ((m.incident_face as u64) << 1);
        for cp in &m.points[..m.count] {
            out.push(PairContact {
                key: ((sa as u64) << 40) | ((sb as u64) << 8) | feature | cp.slot as u64,
                a,
                b,
                normal,
                face_point,
                point: to_local(pieces, b, cp.point),
                separation: cp.separation,
            });
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::simulation::{Shape, Terrain, World};

    /// Square s's box swept over one step, from its pose and motion (the broad
    /// phase's definition, written out again).
    fn swept_box(broad: &BroadPhase, s: usize, base: f64) -> [f64; 4] {
        let (q, m) = (broad.pose(s), broad.motion(s));
        let e = HALF * (q.c.abs() + q.s.abs()) + 0.5 * base;
        let spin = m.w.abs() * RADIUS;
        let (ex, ey) = (e + DT * (m.vx.abs() + spin), e + DT * (m.vy.abs() + spin));
        [q.x - ex, q.x + ex, q.y - ey, q.y + ey]
    }

    /// Every pair of squares of different voxels and pieces whose boxes overlap.
    fn brute_force(w: &World, broad: &BroadPhase, base: f64) -> Vec<(u32, u32)> {
        let n = w.squares.len();
        let mut found = Vec::new();
        for a in 0..n {
            for b in a + 1..n {
                let (ba, bb) = (swept_box(broad, a, base), swept_box(broad, b, base));
                let apart = bb[0] > ba[1] || ba[0] > bb[1] || bb[2] > ba[3] || ba[2] > bb[3];
                if !apart && a / 4 != b / 4 && w.squares.piece[a] != w.squares.piece[b] {
                    found.push((a as u32, b as u32));
                }
            }
        }
        found
    }

    #[test]
    fn the_sweep_finds_every_overlapping_pair() {
        // A U whose arms are bent into each other, and a comb whose legs swing.
        let mut checked = 0;
        for (shape, u) in [("11011-11011-11011-11111", 1.0), ("comb-7x2", -1.0)] {
            let shape = Shape::parse(shape).unwrap();
            let terrain = Terrain::parse("flat").unwrap();
            let mut w = World::new(shape.voxels(), terrain.xs(), terrain.ys());
            let mut broad = BroadPhase::new(&w.squares, w.pieces.len());
            for step in 0..600 {
                let k = (step / 20) as f64;
                let act: Vec<f64> = shape
                    .voxels()
                    .iter()
                    .map(|&(x, _)| u * libm::sin(k + x as f64))
                    .collect();
                w.set_actuation(&act);
                w.step();
                for base in [0.01, 0.21] {
                    broad.update(&w.pieces, &w.squares, base);
                    let want = brute_force(&w, &broad, base);
                    assert_eq!(broad.pairs(), want, "step {step}");
                    checked += want.len();
                }
            }
        }
        assert!(
            checked > 1000,
            "{checked} pairs: the test would prove little"
        );
    }
}
