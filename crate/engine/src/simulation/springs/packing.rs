//! Packs springs into the batches of [`Batches`].
//!
//! Consecutive springs between the same two corner squares form a group (at most
//! [`MAX_ROWS`] springs; longer runs are cut). A batch takes up to [`LANES`] groups of
//! the same length that share no piece, searching only the last few open batches so
//! that packing stays local (nearby springs, hot velocities). Spring i of group g lands
//! in row `batch.start + (i - group start)`, lane = the group's position in the batch;
//! lanes left empty are padding ([`PAD`]).

use super::batch::{Batch, Batches, RowDef, MAX_ROWS};
use super::kind::SpringDef;
use super::lanes::{LANES, PAD};
use crate::simulation::body::Pieces;

/// A group: its springs' range and the pieces it joins.
#[derive(Clone, Copy)]
struct Group {
    a: u32,
    b: u32,
    start: usize,
    end: usize,
}

/// A batch being filled: the batch and its groups.
type Open = (Batch, Vec<Group>);

fn same_squares(x: &SpringDef, y: &SpringDef) -> bool {
    let bits = |p: (usize, f64, f64)| (p.0, p.1.to_bits(), p.2.to_bits());
    bits(x.a) == bits(y.a) && bits(x.b) == bits(y.b)
}

fn groups(defs: &[SpringDef]) -> Vec<Group> {
    let mut groups: Vec<Group> = Vec::new();
    for (i, d) in defs.iter().enumerate() {
        match groups.last_mut() {
            Some(g) if g.end - g.start < MAX_ROWS && same_squares(&defs[g.start], d) => {
                g.end = i + 1
            }
            _ => groups.push(Group {
                a: d.a.0 as u32,
                b: d.b.0 as u32,
                start: i,
                end: i + 1,
            }),
        }
    }
    groups
}

fn new_batch(rows: u32) -> Batch {
    Batch {
        a: [PAD; LANES],
        b: [PAD; LANES],
        squares: [[0.0; LANES]; 4],
        inv: [[0.0; LANES]; 4],
        live: [0.0; LANES],
        start: 0,
        coupling: 0,
        rows,
    }
}

fn pack(groups: &[Group]) -> Vec<Open> {
    let mut open: Vec<Open> = Vec::new();
    for g in groups {
        let rows = (g.end - g.start) as u32;
        let fits = |(batch, members): &&mut Open| {
            members.len() < LANES
                && batch.rows == rows
                && !members
                    .iter()
                    .any(|m| m.a == g.a || m.a == g.b || m.b == g.a || m.b == g.b)
        };
        let n_open = open.len();
        let recent = &mut open[n_open.saturating_sub(8)..];
        let entry = match recent.iter_mut().find(|e| fits(e)) {
            Some(e) => e,
            None => {
                open.push((new_batch(rows), Vec::new()));
                open.last_mut().expect("just pushed")
            }
        };
        let lane = entry.1.len();
        entry.0.a[lane] = g.a;
        entry.0.b[lane] = g.b;
        entry.1.push(*g);
    }
    open
}

/// Fills lane `k` of `batch` from group `g` (masses, square offsets) and its rows.
fn fill(packed: &mut Batches, k: usize, g: &Group, defs: &[SpringDef], pieces: &Pieces) {
    let batch = packed.batches.last_mut().expect("batch pushed");
    let (a, b) = (&defs[g.start].a, &defs[g.start].b);
    let values = [a.1, a.2, b.1, b.2];
    for (dst, v) in batch.squares.iter_mut().zip(values) {
        dst[k] = v;
    }
    let inv = [
        pieces.inv_mass[a.0],
        pieces.inv_inertia[a.0],
        pieces.inv_mass[b.0],
        pieces.inv_inertia[b.0],
    ];
    for (dst, v) in batch.inv.iter_mut().zip(inv) {
        dst[k] = v;
    }
    batch.live[k] = 1.0;
    let start = batch.start as usize;
    for (j, i) in (g.start..g.end).enumerate() {
        let row = &mut packed.defs[start + j];
        let d = &defs[i];
        (row.qax[k], row.qay[k]) = d.qa;
        (row.qbx[k], row.qby[k]) = d.qb;
        packed.slot[i] = ((start + j) as u32, k as u8);
    }
}

impl Batches {
    /// Packs springs (in order) between `pieces`.
    pub(super) fn new(defs: &[SpringDef], pieces: &Pieces) -> Self {
        let mut packed = Batches {
            slot: vec![(0, 0); defs.len()],
            ..Batches::default()
        };
        let mut n_coupling = 0;
        for (mut batch, members) in pack(&groups(defs)) {
            batch.start = packed.defs.len() as u32;
            batch.coupling = n_coupling as u32;
            let n = batch.rows as usize;
            n_coupling += n * (n - 1) / 2;
            packed.batches.push(batch);
            packed
                .defs
                .extend(std::iter::repeat(RowDef::default()).take(n));
            for (k, g) in members.iter().enumerate() {
                fill(&mut packed, k, g, defs, pieces);
            }
        }
        let n = packed.defs.len();
        packed.rows = vec![Default::default(); n];
        packed.coupling = vec![[0.0; LANES]; n_coupling];
        packed.impulse = vec![[0.0; LANES]; n];
        packed.energy = vec![([0.0; LANES], [0.0; LANES]); n];
        packed
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
        let asm = assemble(shape.voxels(), &ground, 0.0);
        let packed = Batches::new(&asm.springs, &asm.pieces);
        let used: usize = packed.rows.len() * LANES;
        let n = asm.springs.len();
        eprintln!(
            "batches {} rows {} springs {n}",
            packed.batches.len(),
            packed.rows.len()
        );
        assert!(
            n * 10 >= used * 9,
            "less than 90% of the lanes carry a spring"
        );
        let mut seen = packed.slot.clone();
        seen.sort_unstable();
        seen.dedup();
        assert_eq!(seen.len(), n, "two springs share a slot");
    }
}
