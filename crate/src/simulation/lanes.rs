//! The spring solver's hot loop, four independent chains at a time.
//!
//! Sequential impulses are latency-bound: each row reads the velocities the previous
//! row wrote. Springs joining the same two pieces form a *group* (the 4 springs of a
//! side, or one diagonal); groups that share no piece commute, so we pack up to four
//! such groups of equal length into a *batch* and solve its rows lane by lane: four
//! dependency chains in flight instead of one, with identical arithmetic per row.
//!
//! Layout: `rows[batch.start + j]` holds row j of every lane of a batch, struct-of-
//! arrays over the 4 lanes (so the compiler can use SIMD). A missing lane points at the
//! padding piece (index = number of real pieces, whose velocity slot exists but is
//! never integrated) with all-zero coefficients, so it never changes anything.

use super::body::Velocity;
use super::joint::JointRow;

/// Lanes per batch.
pub const LANES: usize = 4;

/// Row j of the four lanes of a batch.
#[derive(Debug, Clone, Copy, Default)]
pub struct Row4 {
    nx: [f64; LANES],
    ny: [f64; LANES],
    rna: [f64; LANES],
    rnb: [f64; LANES],
    da: [[f64; LANES]; 3],
    db: [[f64; LANES]; 3],
    inv_k: [f64; LANES],
    bias: [f64; LANES],
    gamma: [f64; LANES],
}

/// Up to four groups of springs that share no piece.
#[derive(Debug, Clone, Copy)]
struct Batch {
    a: [u32; LANES],
    b: [u32; LANES],
    start: u32,
    rows: u32,
}

/// A batch being filled: the batch, its groups' spring ranges, lanes used.
type Open = (Batch, Vec<(usize, usize)>, usize);

/// Springs packed into batches, with each spring's (row, lane) slot.
#[derive(Debug, Clone, Default)]
pub struct Lanes {
    batches: Vec<Batch>,
    rows: Vec<Row4>,
    impulse: Vec<[f64; LANES]>,
    /// Slot of spring i: (row index, lane).
    slot: Vec<(u32, u8)>,
}

impl Lanes {
    /// Packs springs given as (piece a, piece b) pairs, in order; consecutive springs
    /// with the same pair form a group. `pad` is the padding piece index.
    pub fn new(pairs: &[(u32, u32)], pad: u32) -> Self {
        let mut groups: Vec<(u32, u32, usize, usize)> = Vec::new();
        for (i, &(a, b)) in pairs.iter().enumerate() {
            match groups.last_mut() {
                Some(g) if g.0 == a && g.1 == b => g.3 = i + 1,
                _ => groups.push((a, b, i, i + 1)),
            }
        }
        let mut open: Vec<Open> = Vec::new();
        for &(a, b, start, end) in &groups {
            let len = (end - start) as u32;
            let fits = |(batch, _, lanes): &&mut Open| {
                *lanes < LANES
                    && batch.rows == len
                    && !batch.a[..*lanes]
                        .iter()
                        .chain(&batch.b[..*lanes])
                        .any(|&p| p == a || p == b)
            };
            let n_open = open.len();
            let recent = &mut open[n_open.saturating_sub(8)..];
            let entry = match recent.iter_mut().find(|e| fits(e)) {
                Some(e) => e,
                None => {
                    let batch = Batch {
                        a: [pad; LANES],
                        b: [pad; LANES],
                        start: 0,
                        rows: len,
                    };
                    open.push((batch, Vec::new(), 0));
                    open.last_mut().expect("just pushed")
                }
            };
            entry.0.a[entry.2] = a;
            entry.0.b[entry.2] = b;
            entry.1.push((start, end));
            entry.2 += 1;
        }
        let mut lanes = Lanes {
            slot: vec![(0, 0); pairs.len()],
            ..Lanes::default()
        };
        for (mut batch, members, _) in open {
            batch.start = lanes.rows.len() as u32;
            for (lane, &(start, end)) in members.iter().enumerate() {
                for (j, i) in (start..end).enumerate() {
                    lanes.slot[i] = (batch.start + j as u32, lane as u8);
                }
            }
            lanes
                .rows
                .extend(std::iter::repeat(Row4::default()).take(batch.rows as usize));
            lanes.batches.push(batch);
        }
        lanes.impulse = vec![[0.0; LANES]; lanes.rows.len()];
        lanes
    }

    /// Stores spring i's prepared row and softness terms; returns its accumulated
    /// impulse from the previous step (for warm starting).
    #[inline]
    pub fn set(&mut self, i: usize, row: &JointRow, inv_k: f64, bias: f64, gamma: f64) -> f64 {
        let (r, k) = self.slot[i];
        let (r, k) = (r as usize, k as usize);
        let dst = &mut self.rows[r];
        dst.nx[k] = row.nx;
        dst.ny[k] = row.ny;
        dst.rna[k] = row.rna;
        dst.rnb[k] = row.rnb;
        for c in 0..3 {
            dst.da[c][k] = row.da[c];
            dst.db[c][k] = row.db[c];
        }
        dst.inv_k[k] = inv_k;
        dst.bias[k] = bias;
        dst.gamma[k] = gamma;
        self.impulse[r][k]
    }

    /// One sequential-impulse sweep over every batch.
    pub fn solve(&mut self, vel: &mut [Velocity]) {
        for batch in &self.batches {
            let mut a = Lane3::gather(vel, &batch.a);
            let mut b = Lane3::gather(vel, &batch.b);
            let start = batch.start as usize;
            let end = start + batch.rows as usize;
            for (row, acc) in self.rows[start..end]
                .iter()
                .zip(&mut self.impulse[start..end])
            {
                let mut lambda = [0.0; LANES];
                for k in 0..LANES {
                    let cdot = row.nx[k] * (b.x[k] - a.x[k])
                        + row.ny[k] * (b.y[k] - a.y[k])
                        + row.rnb[k] * b.w[k]
                        - row.rna[k] * a.w[k];
                    lambda[k] = -row.inv_k[k] * (cdot + row.bias[k] + row.gamma[k] * acc[k]);
                }
                for k in 0..LANES {
                    acc[k] += lambda[k];
                    a.x[k] -= row.da[0][k] * lambda[k];
                    a.y[k] -= row.da[1][k] * lambda[k];
                    a.w[k] -= row.da[2][k] * lambda[k];
                    b.x[k] += row.db[0][k] * lambda[k];
                    b.y[k] += row.db[1][k] * lambda[k];
                    b.w[k] += row.db[2][k] * lambda[k];
                }
            }
            a.scatter(vel, &batch.a);
            b.scatter(vel, &batch.b);
        }
    }
}

/// Velocities of the four lanes' pieces on one side, struct-of-arrays.
struct Lane3 {
    x: [f64; LANES],
    y: [f64; LANES],
    w: [f64; LANES],
}

impl Lane3 {
    #[inline]
    fn gather(vel: &[Velocity], pieces: &[u32; LANES]) -> Self {
        let v = pieces.map(|p| vel[p as usize]);
        Lane3 {
            x: v.map(|v| v.vx),
            y: v.map(|v| v.vy),
            w: v.map(|v| v.w),
        }
    }

    #[inline]
    fn scatter(&self, vel: &mut [Velocity], pieces: &[u32; LANES]) {
        for k in 0..LANES {
            vel[pieces[k] as usize] = Velocity {
                vx: self.x[k],
                vy: self.y[k],
                w: self.w[k],
            };
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::simulation::assembly::assemble;
    use crate::simulation::ground::Ground;
    use crate::simulation::Shape;

    #[test]
    fn biped_packs_densely() {
        let shape = Shape::parse("biped-4x3").unwrap();
        let ground = Ground::new(&[0.0, 10.0, 1990.0, 2000.0], &[100.0, 5.0, 5.0, 100.0]);
        let asm = assemble(shape.voxels(), &ground);
        let pairs: Vec<(u32, u32)> = asm
            .springs
            .iter()
            .map(|d| (d.a.0 as u32, d.b.0 as u32))
            .collect();
        let lanes = Lanes::new(&pairs, asm.pieces.len() as u32);
        let used: usize = lanes.rows.len() * LANES;
        eprintln!(
            "batches {} rows {} slots {} springs {}",
            lanes.batches.len(),
            lanes.rows.len(),
            used,
            pairs.len()
        );
        assert!(
            pairs.len() * 10 >= used * 9,
            "less than 90% of the lanes carry a spring"
        );
    }
}
