//! Spring kinds and their rest lengths, and the description of one spring that the
//! assembler hands to [`super::Springs::new`].

use crate::simulation::constants::{AREA_RATIO_MAX_DELTA, CORNER_SIDE, VOXEL_SIDE};

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
    pub(crate) fn length_for_side(self, side: f64) -> f64 {
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
