//! What a voxel can know of its place without any message: static facts read once from the
//! neighbour table, the same for the whole episode. A body-independent brain
//! ([`super::AnyBody`]) computes each voxel's weights from them instead of from the voxel's
//! index, so one genome fits every body.
//!
//! Layout: per voxel, in voxel index order, the first [`LocalInputs::width`] of
//! `[1, up, right, down, left, x, y]` ([`LOCAL_INPUTS`] = 7 in all), where
//! - `1` is a constant (so a brain with no other input is the same for every voxel);
//! - `up`, `right`, `down`, `left` are 1 where that neighbour exists, else 0 (a voxel feels
//!   whether it is attached on a side);
//! - `x`, `y` are the voxel's place in the body's bounding box, from -1 (left, bottom) to
//!   +1 (right, top), 0 along a side of one voxel. They come from the neighbour table alone
//!   (a walk over the links), not from the world.
//!
//! [`LocalInputs`] says which of them a brain reads (a prefix of that list). The families read
//! [`LocalInputs::CHOSEN`], the constant and the four neighbour flags: facts a voxel knows from
//! what it is attached to. docs/ANALYSIS-PLAN.md (fourth question) records the measurement
//! behind that choice, made with all 7 inputs in every genome and the unread ones set to 0
//! ([`local_inputs_masked`]).

use super::Topology;

/// Floats per voxel: the constant, four neighbour flags, two coordinates.
pub const LOCAL_INPUTS: usize = 7;

/// Which static facts a voxel reads; see the module doc.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum LocalInputs {
    /// Only the constant: every voxel the same brain.
    Constant,
    /// The constant and which neighbours exist.
    Neighbours,
    /// The constant, which neighbours exist, and the place in the bounding box.
    NeighboursAndPlace,
}

impl LocalInputs {
    /// The inputs the body-independent families read (measured: see the module doc).
    pub const CHOSEN: LocalInputs = LocalInputs::Neighbours;

    /// Every variant, for the measurement.
    pub const ALL: [LocalInputs; 3] = [
        LocalInputs::Constant,
        LocalInputs::Neighbours,
        LocalInputs::NeighboursAndPlace,
    ];

    /// Inputs read per voxel: 1, 5 or 7.
    pub fn width(self) -> usize {
        match self {
            LocalInputs::Constant => 1,
            LocalInputs::Neighbours => 5,
            LocalInputs::NeighboursAndPlace => LOCAL_INPUTS,
        }
    }

    /// A short name for tables.
    pub fn name(self) -> &'static str {
        match self {
            LocalInputs::Constant => "constant",
            LocalInputs::Neighbours => "neighbours",
            LocalInputs::NeighboursAndPlace => "neighbours+place",
        }
    }
}

/// Each voxel's local inputs for `topology`, in voxel index order: the first
/// [`LocalInputs::width`] of the seven (see the module doc).
pub fn local_inputs(topology: &Topology, which: LocalInputs) -> Vec<Vec<f32>> {
    local_inputs_masked(topology, which)
        .into_iter()
        .map(|f| f[..which.width()].to_vec())
        .collect()
}

/// All seven inputs of each voxel, those `which` does not read set to 0 (the measurement's
/// layout: see the module doc).
pub fn local_inputs_masked(topology: &Topology, which: LocalInputs) -> Vec<[f32; LOCAL_INPUTS]> {
    let n = topology.voxel_count();
    let place = places(topology);
    let (reads_links, reads_place) = match which {
        LocalInputs::Constant => (false, false),
        LocalInputs::Neighbours => (true, false),
        LocalInputs::NeighboursAndPlace => (true, true),
    };
    (0..n)
        .map(|v| {
            let mut f = [0.0f32; LOCAL_INPUTS];
            f[0] = 1.0;
            if reads_links {
                for d in 0..4 {
                    f[1 + d] = f32::from(u8::from(topology.neighbour(v, d).is_some()));
                }
            }
            if reads_place {
                (f[5], f[6]) = place[v];
            }
            f
        })
        .collect()
}

/// Each voxel's (x, y) in its piece's bounding box, scaled to [-1, 1], from a walk over the
/// links (up is +y, right is +x). Voxels with no link to the first voxel of their piece are
/// placed within their own piece.
fn places(topology: &Topology) -> Vec<(f32, f32)> {
    let n = topology.voxel_count();
    let mut cell: Vec<Option<(i64, i64)>> = vec![None; n];
    let mut piece = vec![0usize; n];
    let mut pieces = 0;
    for start in 0..n {
        if cell[start].is_some() {
            continue;
        }
        cell[start] = Some((0, 0));
        piece[start] = pieces;
        let mut stack = vec![start];
        while let Some(v) = stack.pop() {
            let (x, y) = cell[v].unwrap_or((0, 0));
            for (d, (dx, dy)) in [(0, 1), (1, 0), (0, -1), (-1, 0)].into_iter().enumerate() {
                if let Some(w) = topology.neighbour(v, d) {
                    if cell[w].is_none() {
                        cell[w] = Some((x + dx, y + dy));
                        piece[w] = pieces;
                        stack.push(w);
                    }
                }
            }
        }
        pieces += 1;
    }
    let scale = |c: i64, lo: i64, hi: i64| {
        if hi == lo {
            0.0
        } else {
            (2 * (c - lo)) as f32 / (hi - lo) as f32 - 1.0
        }
    };
    // Each piece's bounding box: (x0, x1, y0, y1).
    let mut bounds = vec![(i64::MAX, i64::MIN, i64::MAX, i64::MIN); pieces];
    for v in 0..n {
        let (x, y) = cell[v].unwrap_or((0, 0));
        let b = &mut bounds[piece[v]];
        *b = (b.0.min(x), b.1.max(x), b.2.min(y), b.3.max(y));
    }
    (0..n)
        .map(|v| {
            let (x, y) = cell[v].unwrap_or((0, 0));
            let (x0, x1, y0, y1) = bounds[piece[v]];
            (scale(x, x0, x1), scale(y, y0, y1))
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_biped_knows_its_legs_and_its_back() {
        // 1111-1111-1001: voxels 0 (0,0), 1 (3,0), then rows y = 1 and y = 2.
        let cells = [
            (0, 0),
            (3, 0),
            (0, 1),
            (1, 1),
            (2, 1),
            (3, 1),
            (0, 2),
            (1, 2),
            (2, 2),
            (3, 2),
        ];
        let t = Topology::from_cells(&cells).unwrap();
        let f = local_inputs_masked(&t, LocalInputs::NeighboursAndPlace);
        // The left foot: attached only above, at the bottom left corner.
        assert_eq!(f[0], [1.0, 1.0, 0.0, 0.0, 0.0, -1.0, -1.0]);
        // The top right corner: attached below and to the left.
        assert_eq!(f[9], [1.0, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0]);
        // Middle of the back row, second column: x = -1/3, y = 0.
        assert_eq!(f[3][5..], [2.0 / 3.0 - 1.0, 0.0]);
        let only_links = local_inputs_masked(&t, LocalInputs::Neighbours);
        assert_eq!(only_links[9], [1.0, 0.0, 0.0, 1.0, 1.0, 0.0, 0.0]);
        assert_eq!(
            local_inputs(&t, LocalInputs::Neighbours)[9],
            [1.0, 0.0, 0.0, 1.0, 1.0]
        );
        let constant = local_inputs(&t, LocalInputs::Constant);
        assert!(constant.iter().all(|f| *f == [1.0]));
    }

    #[test]
    fn a_single_voxel_and_a_row_sit_in_the_middle_where_a_side_is_one_voxel() {
        let one = local_inputs_masked(&Topology::isolated(1), LocalInputs::NeighboursAndPlace);
        assert_eq!(one[0], [1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0]);
        let row = Topology::from_cells(&[(0, 0), (1, 0), (2, 0)]).unwrap();
        let f = local_inputs_masked(&row, LocalInputs::NeighboursAndPlace);
        assert_eq!(
            f.iter().map(|f| (f[5], f[6])).collect::<Vec<_>>(),
            [(-1.0, 0.0), (0.0, 0.0), (1.0, 0.0)]
        );
    }
}
