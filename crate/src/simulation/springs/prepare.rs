//! Per-step preparation of the spring rows, all lanes of a batch at a time.
//!
//! A spring's anchor is its corner square's centre plus a small offset q (a square
//! vertex or 0), both fixed in the piece frame. Per batch we rotate each lane's square
//! centre once; per row we rotate only q, and the anchor is the sum. Every step then
//! runs lane-parallel (`[f64; LANES]` loops the compiler packs into SIMD, including the
//! square roots and divisions), builds the batch's group matrices for the sweep
//! ([`super::group`]) and ends with the warm-start impulses.

// Lane loops index several parallel arrays by lane on purpose.
#![allow(clippy::needless_range_loop)]

use super::batch::{Batch, Batches, Row, RowDef};
use super::group::group_matrices;
use super::lanes::{Lane3, L, LANES};
use super::sweep::apply;
use crate::simulation::body::Pieces;
use crate::simulation::constants::{CORNER_INERTIA, CORNER_MASS};

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
    x: L,
    y: L,
    c: L,
    s: L,
    lx: L,
    ly: L,
}

impl Side {
    /// A padding lane ([`super::lanes::PAD`]) reads the last piece's pose: any finite
    /// pose would do, its rows have no effect.
    #[inline]
    fn gather(pieces: &Pieces, ids: &[u32; LANES], sx: &L, sy: &L) -> Side {
        let last = pieces.len() - 1;
        let mut side = Side {
            x: [0.0; LANES],
            y: [0.0; LANES],
            c: [0.0; LANES],
            s: [0.0; LANES],
            lx: [0.0; LANES],
            ly: [0.0; LANES],
        };
        for k in 0..LANES {
            let p = (ids[k] as usize).min(last);
            let (c, s) = (pieces.cos[p], pieces.sin[p]);
            (side.x[k], side.y[k], side.c[k], side.s[k]) = (pieces.x[p], pieces.y[p], c, s);
            side.lx[k] = c * sx[k] - s * sy[k];
            side.ly[k] = s * sx[k] + c * sy[k];
        }
        side
    }

    /// World-frame q and anchor offset from the centre of mass: (qx, qy, rx, ry).
    #[inline]
    fn anchor(&self, qx: &L, qy: &L) -> [L; 4] {
        let mut out = [[0.0; LANES]; 4];
        for k in 0..LANES {
            let wx = self.c[k] * qx[k] - self.s[k] * qy[k];
            let wy = self.s[k] * qx[k] + self.c[k] * qy[k];
            out[0][k] = wx;
            out[1][k] = wy;
            out[2][k] = self.lx[k] + wx;
            out[3][k] = self.ly[k] + wy;
        }
        out
    }
}

/// Geometry of one row: direction, length and lever arms about the pieces (r) and
/// about the single squares (q).
struct Geometry {
    nx: L,
    ny: L,
    length: L,
    rna: L,
    rnb: L,
    qna: L,
    qnb: L,
}

#[inline]
fn geometry(def: &RowDef, a: &Side, b: &Side) -> Geometry {
    let [qax, qay, rax, ray] = a.anchor(&def.qax, &def.qay);
    let [qbx, qby, rbx, rby] = b.anchor(&def.qbx, &def.qby);
    let z = [0.0; LANES];
    let mut g = Geometry {
        nx: z,
        ny: z,
        length: z,
        rna: z,
        rnb: z,
        qna: z,
        qnb: z,
    };
    for k in 0..LANES {
        let dx = b.x[k] + rbx[k] - a.x[k] - rax[k];
        let dy = b.y[k] + rby[k] - a.y[k] - ray[k];
        let length = (dx * dx + dy * dy).sqrt();
        let ok = length > 1e-9;
        let nx = if ok { dx / length } else { 1.0 };
        let ny = if ok { dy / length } else { 0.0 };
        (g.nx[k], g.ny[k], g.length[k]) = (nx, ny, length);
        g.rna[k] = rax[k] * ny - ray[k] * nx;
        g.rnb[k] = rbx[k] * ny - rby[k] * nx;
        g.qna[k] = qax[k] * ny - qay[k] * nx;
        g.qnb[k] = qbx[k] * ny - qby[k] * nx;
    }
    g
}

/// The solver row and the (stiffness, stretch) energy terms of one row.
#[inline]
fn row(g: &Geometry, target: &L, batch: &Batch, law: Law) -> (Row, (L, L)) {
    let [ima, iia, imb, iib] = &batch.inv;
    let mut row = Row::default();
    let mut energy = ([0.0; LANES], [0.0; LANES]);
    for k in 0..LANES {
        let (nx, ny, rna, rnb) = (g.nx[k], g.ny[k], g.rna[k], g.rnb[k]);
        let inv_ref =
            2.0 / CORNER_MASS + (g.qna[k] * g.qna[k] + g.qnb[k] * g.qnb[k]) / CORNER_INERTIA;
        let gamma = inv_ref * law.g;
        let stretch = g.length[k] - target[k];
        let inv_mass = ima[k] + iia[k] * rna * rna + imb[k] + iib[k] * rnb * rnb;
        (row.nx[k], row.ny[k], row.rna[k], row.rnb[k]) = (nx, ny, rna, rnb);
        row.inv_k[k] = batch.live[k] / (inv_mass + gamma);
        row.bias[k] = stretch * law.b;
        row.gamma[k] = gamma;
        energy.0[k] = law.omega2 / inv_ref;
        energy.1[k] = stretch * batch.live[k];
    }
    (row, energy)
}

impl Batches {
    /// Prepares every row for this step and applies the warm-start impulses.
    pub(super) fn prepare(&mut self, pieces: &mut Pieces, law: Law) {
        for batch in &self.batches {
            let sq = &batch.squares;
            let a = Side::gather(pieces, &batch.a, &sq[0], &sq[1]);
            let b = Side::gather(pieces, &batch.b, &sq[2], &sq[3]);
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
            let mut va = Lane3::gather(&pieces.vel, &batch.a);
            let mut vb = Lane3::gather(&pieces.vel, &batch.b);
            apply(rows, acc, &batch.inv, &mut va, &mut vb);
            va.scatter(&mut pieces.vel, &batch.a);
            vb.scatter(&mut pieces.vel, &batch.b);
        }
    }
}
