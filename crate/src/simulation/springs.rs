//! The 18 soft springs of every voxel and their actuation.
//!
//! Each spring is a soft distance joint (SPEC 2) solved like the reference: a Box2D /
//! dyn4j soft constraint, which is an implicit-Euler spring-damper folded into the
//! sequential-impulse velocity solver. Its stiffness k = m_ref (2 pi f)^2 and damping
//! c = 2 m_ref zeta (2 pi f) come from the effective mass m_ref of the two *single*
//! corner squares it joins, recomputed every step from the current geometry exactly as
//! the reference does. The impulse itself acts on the merged rigid pieces, so the
//! implicit spring is exact for the merged system.
//!
//! Layout: per spring only its voxel and rest-length table (for the actuation); the
//! anchors, targets and per-step rows live in [`Lanes`] (four-lane batches), rebuilt
//! by [`Springs::prepare`] without allocating.

use super::body::{Pieces, Velocity};
use super::constants::{
    AREA_RATIO_MAX_DELTA, CORNER_SIDE, DT, SPRING_DAMPING_RATIO, SPRING_FREQUENCY, VOXEL_SIDE,
};
use super::lane_prepare::Law;
use super::lanes::Lanes;

/// Kind of spring, which fixes its rest-length range.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SpringKind {
    /// Inner or outer side spring (rest 0.6 m).
    Side,
    /// Crossed side spring (rest sqrt(1.2^2 + 0.6^2) m).
    Crossed,
    /// Central diagonal between opposite corner-square centres (rest 1.8 sqrt 2 m).
    Diagonal,
}

impl SpringKind {
    /// Spring length for a voxel whose side measures `side` metres.
    pub fn length_for_side(self, side: f64) -> f64 {
        let gap = side - 2.0 * CORNER_SIDE;
        match self {
            SpringKind::Side => gap,
            SpringKind::Crossed => (CORNER_SIDE * CORNER_SIDE + gap * gap).sqrt(),
            SpringKind::Diagonal => (side - CORNER_SIDE) * std::f64::consts::SQRT_2,
        }
    }

    /// Rest lengths [at rest, fully contracted (u = +1), fully expanded (u = -1)].
    pub fn rest_table(self) -> [f64; 3] {
        let min_side = (VOXEL_AREA_MIN).sqrt();
        let max_side = (VOXEL_AREA_MAX).sqrt();
        [
            self.length_for_side(VOXEL_SIDE),
            self.length_for_side(min_side),
            self.length_for_side(max_side),
        ]
    }
}

const VOXEL_AREA_MIN: f64 = VOXEL_SIDE * VOXEL_SIDE * (1.0 - AREA_RATIO_MAX_DELTA);
const VOXEL_AREA_MAX: f64 = VOXEL_SIDE * VOXEL_SIDE * (1.0 + AREA_RATIO_MAX_DELTA);

/// One spring as the assembler describes it.
#[derive(Debug, Clone, Copy)]
pub struct SpringDef {
    /// Piece holding anchor a, and the offset of anchor a's corner square centre from
    /// that piece's centre of mass (piece frame); the anchor itself is at that plus `qa`.
    pub a: (usize, f64, f64),
    /// Piece holding anchor b, and the offset of its square centre.
    pub b: (usize, f64, f64),
    /// Anchor a's offset from the centre of its own corner square (for m_ref).
    pub qa: (f64, f64),
    /// Anchor b's offset from the centre of its own corner square.
    pub qb: (f64, f64),
    /// Which rest-length range applies.
    pub kind: SpringKind,
    /// Voxel whose actuation drives this spring.
    pub voxel: usize,
}

/// Every spring of a robot.
#[derive(Debug, Clone, Default)]
pub struct Springs {
    voxel: Vec<usize>,
    table: Vec<[f64; 3]>,
    lanes: Lanes,
}

impl Springs {
    /// Builds the spring set between `pieces`, all at their rest length. `pad` is the
    /// padding piece index (see [`Lanes`]).
    pub fn new(defs: Vec<SpringDef>, pieces: &Pieces, pad: usize) -> Self {
        let table: Vec<[f64; 3]> = defs.iter().map(|d| d.kind.rest_table()).collect();
        let mut lanes = Lanes::new(&defs, pieces, pad as u32);
        for (i, t) in table.iter().enumerate() {
            lanes.set_target(i, t[0]);
        }
        Springs {
            voxel: defs.iter().map(|d| d.voxel).collect(),
            table,
            lanes,
        }
    }

    /// Number of springs.
    pub fn len(&self) -> usize {
        self.voxel.len()
    }

    /// True if there is no spring.
    pub fn is_empty(&self) -> bool {
        self.voxel.is_empty()
    }

    /// Sets every spring's rest length from its voxel's actuation u in [-1, 1]
    /// (+1 contracts, -1 expands), moving linearly toward the range's end. NaN acts
    /// as 0.
    pub fn set_actuation(&mut self, actuation: &[f64]) {
        for (i, &v) in self.voxel.iter().enumerate() {
            let u = actuation[v];
            let u = if u.is_nan() { 0.0 } else { u.clamp(-1.0, 1.0) };
            let [rest, min, max] = self.table[i];
            let target = if u >= 0.0 {
                rest + u * (min - rest)
            } else {
                rest - u * (max - rest)
            };
            self.lanes.set_target(i, target);
        }
    }

    /// Prepares every row for this step and applies the warm-start impulses.
    ///
    /// With k = m_ref w^2 and c = 2 m_ref zeta w, the soft-constraint terms simplify:
    /// gamma = 1 / (dt (c + dt k)) = (1 / m_ref) G and bias = stretch dt k gamma =
    /// stretch B, with G and B constants of the spring law.
    pub fn prepare(&mut self, pieces: &mut Pieces) {
        let omega = 2.0 * std::f64::consts::PI * SPRING_FREQUENCY;
        let g = 1.0 / (DT * (2.0 * SPRING_DAMPING_RATIO * omega + DT * omega * omega));
        let law = Law {
            g,
            b: DT * omega * omega * g,
            omega2: omega * omega,
        };
        self.lanes.prepare(pieces, law);
    }

    /// One sequential-impulse sweep over every spring.
    #[inline]
    pub fn solve_velocity(&mut self, vel: &mut [Velocity]) {
        self.lanes.solve(vel);
    }

    /// Potential energy stored in the springs (J): sum of k x^2 / 2 with the stiffness
    /// and stretch of the last prepared step.
    pub fn potential_energy(&self) -> f64 {
        self.lanes.potential_energy()
    }
}
