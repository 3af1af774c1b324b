//! The neighbour table a controller sees instead of the world.
//!
//! Layout: one `[Option<usize>; 4]` per voxel, in voxel index order, holding the index of the
//! neighbour in each direction, in the order up, right, down, left (indices 0 to 3,
//! `DIRECTION_NAMES`; `None` where there is no voxel).
//! The table is symmetric: if `w` is the up neighbour of `v`, then `v` is the down neighbour
//! of `w`. Directions follow the world: up is +y, right is +x.

use crate::{Error, Result};

/// Direction names in row order, for messages.
pub(crate) const DIRECTION_NAMES: [&str; 4] = ["up", "right", "down", "left"];

/// The direction seen from the other side: up <-> down, right <-> left.
pub(crate) fn opposite(direction: usize) -> usize {
    (direction + 2) % 4
}

/// Which voxel touches which: the only structural information a controller receives.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Topology {
    neighbours: Vec<[Option<usize>; 4]>,
}

impl Topology {
    /// Builds a topology from one `[up, right, down, left]` row per voxel, in voxel index order.
    /// Fails on an empty table, an index out of range, a voxel that is its own neighbour, or a
    /// table that is not symmetric.
    pub(crate) fn new(neighbours: Vec<[Option<usize>; 4]>) -> Result<Self> {
        let n = neighbours.len();
        if n == 0 {
            return Err(Error::Input("a topology needs at least one voxel".into()));
        }
        for (v, row) in neighbours.iter().enumerate() {
            for (d, w) in row.iter().enumerate() {
                let Some(w) = *w else { continue };
                let name = DIRECTION_NAMES[d];
                if w >= n {
                    return Err(Error::Input(format!(
                        "voxel {v} lists voxel {w} as its {name} neighbour, but there are only {n} voxels"
                    )));
                }
                if w == v {
                    return Err(Error::Input(format!(
                        "voxel {v} lists itself as its {name} neighbour"
                    )));
                }
                if neighbours[w][opposite(d)] != Some(v) {
                    let back = DIRECTION_NAMES[opposite(d)];
                    return Err(Error::Input(format!(
                        "voxel {v} lists voxel {w} as its {name} neighbour, but voxel {w} does not list voxel {v} as its {back} neighbour"
                    )));
                }
            }
        }
        Ok(Self { neighbours })
    }

    /// Builds the table from cell coordinates `(x, y)` (y grows upward), given in voxel index
    /// order; two cells are neighbours when they share an edge. Fails on duplicates or no cells.
    pub fn from_cells(cells: &[(i32, i32)]) -> Result<Self> {
        let find = |x: i32, y: i32| cells.iter().position(|&c| c == (x, y));
        let mut rows = Vec::with_capacity(cells.len());
        for (i, &(x, y)) in cells.iter().enumerate() {
            if find(x, y) != Some(i) {
                return Err(Error::Input(format!(
                    "cell ({x}, {y}) appears more than once"
                )));
            }
            rows.push([
                find(x, y + 1),
                find(x + 1, y),
                find(x, y - 1),
                find(x - 1, y),
            ]);
        }
        Self::new(rows)
    }

    /// `n` voxels with no neighbours (enough for controllers that exchange no messages).
    /// `n = 0` gives one voxel, since a robot is never empty.
    pub fn isolated(n: usize) -> Self {
        Self {
            neighbours: vec![[None; 4]; n.max(1)],
        }
    }

    /// Number of voxels.
    pub(crate) fn voxel_count(&self) -> usize {
        self.neighbours.len()
    }

    /// The neighbour of `voxel` in `direction` (0 up, 1 right, 2 down, 3 left), if any.
    pub(crate) fn neighbour(&self, voxel: usize, direction: usize) -> Option<usize> {
        self.neighbours
            .get(voxel)
            .and_then(|row| row.get(direction).copied().flatten())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cells_of_an_l_shape_give_symmetric_neighbours() {
        // (0,0) (1,0) on the bottom row, (0,1) above the first.
        let t = Topology::from_cells(&[(0, 0), (1, 0), (0, 1)]).unwrap();
        let row = |v| [0, 1, 2, 3].map(|d| t.neighbour(v, d));
        assert_eq!(row(0), [Some(2), Some(1), None, None]);
        assert_eq!(row(1), [None, None, None, Some(0)]);
        assert_eq!(row(2), [None, None, Some(0), None]);
    }

    #[test]
    fn asymmetric_or_out_of_range_tables_are_rejected() {
        assert!(Topology::new(vec![[Some(1), None, None, None], [None; 4]]).is_err());
        assert!(Topology::new(vec![[Some(7), None, None, None]]).is_err());
        assert!(Topology::new(vec![[Some(0), None, None, None]]).is_err());
        assert!(Topology::new(vec![]).is_err());
        assert!(Topology::from_cells(&[(0, 0), (0, 0)]).is_err());
    }
}
