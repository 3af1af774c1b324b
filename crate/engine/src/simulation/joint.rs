//! One row of a distance constraint between two pieces, shared by the soft springs
//! and the ropes: the constraint direction, the lever arms and the precomputed
//! impulse-to-velocity coefficients for one step (the sequential-impulse hot loop).

use super::body::{Pieces, Velocity};

/// A distance constraint prepared for one step.
#[derive(Debug, Clone, Copy, Default)]
pub(crate) struct JointRow {
    /// First piece.
    pub a: u32,
    /// Second piece.
    pub b: u32,
    /// Unit direction from anchor a to anchor b.
    pub nx: f64,
    /// Unit direction from anchor a to anchor b.
    pub ny: f64,
    /// Lever arm of a across n: r_a x n.
    pub rna: f64,
    /// Lever arm of b across n: r_b x n.
    pub rnb: f64,
    /// Current distance between the anchors (m).
    pub length: f64,
    /// Velocity change of a per unit impulse: (n / m_a, (r_a x n) / I_a).
    pub da: [f64; 3],
    /// Velocity change of b per unit impulse.
    pub db: [f64; 3],
    /// Inverse of the constraint's effective mass (1/kg), without softness.
    pub inv_mass: f64,
}

impl JointRow {
    /// Prepares the row between two world anchors given as offsets (ra, rb) from the
    /// pieces' centres of mass.
    #[inline]
    pub(crate) fn new(pieces: &Pieces, a: usize, b: usize, ra: (f64, f64), rb: (f64, f64)) -> Self {
        let dx = pieces.x[b] + rb.0 - pieces.x[a] - ra.0;
        let dy = pieces.y[b] + rb.1 - pieces.y[a] - ra.1;
        let length = (dx * dx + dy * dy).sqrt();
        let (nx, ny) = if length > 1e-9 {
            (dx / length, dy / length)
        } else {
            (1.0, 0.0)
        };
        let rna = ra.0 * ny - ra.1 * nx;
        let rnb = rb.0 * ny - rb.1 * nx;
        let (ima, iia) = (pieces.inv_mass[a], pieces.inv_inertia[a]);
        let (imb, iib) = (pieces.inv_mass[b], pieces.inv_inertia[b]);
        JointRow {
            a: a as u32,
            b: b as u32,
            nx,
            ny,
            rna,
            rnb,
            length,
            da: [ima * nx, ima * ny, iia * rna],
            db: [imb * nx, imb * ny, iib * rnb],
            inv_mass: ima + iia * rna * rna + imb + iib * rnb * rnb,
        }
    }

    /// Relative velocity of the anchors along n (m/s).
    #[inline]
    pub(crate) fn velocity(&self, vel: &[Velocity]) -> f64 {
        let va = vel[self.a as usize];
        let vb = vel[self.b as usize];
        self.nx * (vb.vx - va.vx) + self.ny * (vb.vy - va.vy) + self.rnb * vb.w - self.rna * va.w
    }

    /// Applies impulse `lambda` along n: -lambda on a, +lambda on b.
    #[inline]
    pub(crate) fn apply(&self, vel: &mut [Velocity], lambda: f64) {
        let va = &mut vel[self.a as usize];
        va.vx -= self.da[0] * lambda;
        va.vy -= self.da[1] * lambda;
        va.w -= self.da[2] * lambda;
        let vb = &mut vel[self.b as usize];
        vb.vx += self.db[0] * lambda;
        vb.vy += self.db[1] * lambda;
        vb.w += self.db[2] * lambda;
    }
}
