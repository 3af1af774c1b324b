//! Per-step preparation of the spring rows, all lanes of a batch at a time.
//!
//! A spring's anchor is its corner square's centre plus a small offset q (a square
//! vertex or 0), both fixed in the piece frame. Per batch we rotate each lane's square
//! centre once; per row we rotate only q, and the anchor is the sum. Every step then
//! runs lane-parallel (explicit `wide::f64x4`, including the square roots and
//! divisions, in the same operation order as one lane alone), builds the batch's group matrices for the sweep
//! ([`super::group`]) and ends with the warm-start impulses.

use super::batch::{Batch, Batches, Row, RowDef};
use super::group::group_matrices;
use super::lanes::{Source, L, LANES};
use super::sweep::apply;
use crate::simulation::constants::{CORNER_INERTIA, CORNER_MASS};
use wide::{f64x4, CmpGt};

/// The spring law's constants (see [`super::Springs::prepare`]).
#[derive(Debug, Clone, Copy)]
pub(super) struct Law {
    /// gamma = G / m_ref.
    pub(super) g: f64,
    /// bias = stretch B.
    pub(super) b: f64,
    /// omega^2 (1/s^2), for the stiffness k = m_ref omega^2.
    pub(super) omega2: f64,
}

/// One side of a batch: its lanes' piece positions, rotations and rotated square
/// centres (offsets from the centre of mass, world frame).
struct Side {
    x: f64x4,
    y: f64x4,
    c: f64x4,
    s: f64x4,
    lx: f64x4,
    ly: f64x4,
}

impl Side {
    #[inline(always)]
    fn gather(source: &impl Source, ids: &[u32; LANES], sx: &L, sy: &L) -> Side {
        let [x, y, c, s] = source.pose(ids).map(f64x4::from);
        let (sx, sy) = (v(sx), v(sy));
        Side {
            x,
            y,
            c,
            s,
            lx: c * sx - s * sy,
            ly: s * sx + c * sy,
        }
    }

    /// World-frame q and anchor offset from the centre of mass: (qx, qy, rx, ry).
    #[inline(always)]
    fn anchor(&self, qx: &L, qy: &L) -> [f64x4; 4] {
        let (qx, qy) = (v(qx), v(qy));
        let wx = self.c * qx - self.s * qy;
        let wy = self.s * qx + self.c * qy;
        [wx, wy, self.lx + wx, self.ly + wy]
    }
}

/// One value per lane as a vector.
#[inline(always)]
fn v(x: &L) -> f64x4 {
    f64x4::from(*x)
}

/// Geometry of one row: direction, length and lever arms about the pieces (r) and
/// about the single squares (q).
struct Geometry {
    nx: f64x4,
    ny: f64x4,
    length: f64x4,
    rna: f64x4,
    rnb: f64x4,
    qna: f64x4,
    qnb: f64x4,
}

#[inline(always)]
fn geometry(def: &RowDef, a: &Side, b: &Side) -> Geometry {
    let [qax, qay, rax, ray] = a.anchor(&def.qax, &def.qay);
    let [qbx, qby, rbx, rby] = b.anchor(&def.qbx, &def.qby);
    let dx = b.x + rbx - a.x - rax;
    let dy = b.y + rby - a.y - ray;
    let length = (dx * dx + dy * dy).sqrt();
    // A degenerate spring points along x (every lane divides; the blend keeps the
    // quotient only where the length is usable).
    let ok = length.cmp_gt(f64x4::splat(1e-9));
    let nx = ok.blend(dx / length, f64x4::splat(1.0));
    let ny = ok.blend(dy / length, f64x4::ZERO);
    Geometry {
        nx,
        ny,
        length,
        rna: rax * ny - ray * nx,
        rnb: rbx * ny - rby * nx,
        qna: qax * ny - qay * nx,
        qnb: qbx * ny - qby * nx,
    }
}

/// The solver row and the (1 / m_ref, stretch) energy terms of one row.
#[inline(always)]
fn row(g: &Geometry, target: &L, batch: &Batch, law: Law) -> (Row, (L, L)) {
    let [ima, iia, imb, iib] = batch.inv.map(f64x4::from);
    let live = v(&batch.live);
    let (rna, rnb) = (g.rna, g.rnb);
    let inv_ref = f64x4::splat(2.0 / CORNER_MASS)
        + (g.qna * g.qna + g.qnb * g.qnb) / f64x4::splat(CORNER_INERTIA);
    let gamma = inv_ref * f64x4::splat(law.g);
    let stretch = g.length - v(target);
    let inv_mass = ima + iia * rna * rna + imb + iib * rnb * rnb;
    let row = Row {
        nx: g.nx.to_array(),
        ny: g.ny.to_array(),
        rna: rna.to_array(),
        rnb: rnb.to_array(),
        a: [[0.0; LANES]; 4],
        neg_inv_k: (f64x4::ZERO - live / (inv_mass + gamma)).to_array(),
        bias: (stretch * f64x4::splat(law.b)).to_array(),
        gamma: gamma.to_array(),
    };
    let energy = (inv_ref.to_array(), (stretch * live).to_array());
    (row, energy)
}

impl Batches {
    /// Prepares every row for this step and applies the warm-start impulses.
    pub(super) fn prepare(&mut self, pieces: &mut impl Source, law: Law) {
        for batch in &self.batches {
            let sq = &batch.squares;
            let a = Side::gather(&*pieces, &batch.a, &sq[0], &sq[1]);
            let b = Side::gather(&*pieces, &batch.b, &sq[2], &sq[3]);
            let range = batch.start as usize..(batch.start + batch.rows) as usize;
            for r in range.clone() {
                let def = &self.defs[r];
                let (row, energy) = row(&geometry(def, &a, &b), &def.target, batch, law);
                self.rows[r] = row;
                self.energy[r] = energy;
            }
            let t = &mut self.coupling[batch.coupling as usize..];
            group_matrices(&mut self.rows[range.clone()], &batch.inv, t);
            let (rows, acc) = (&self.rows[range.clone()], &self.impulse[range]);
            let mut va = pieces.gather(&batch.a);
            let mut vb = pieces.gather(&batch.b);
            apply(rows, acc, &batch.inv, &mut va, &mut vb);
            pieces.scatter(&va, &batch.a);
            pieces.scatter(&vb, &batch.b);
        }
    }
}
