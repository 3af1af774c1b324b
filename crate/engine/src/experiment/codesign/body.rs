//! A body as cells of a bounding grid, and the two edits body search makes to it: add a voxel
//! beside the body, remove one whose removal splits nothing. The grid's cell (x, y) has y = 0
//! at the bottom, as [`Shape`]; the robot a body drives is its voxels cropped to their
//! bounding box ([`BodyGrid::shape`]), so where a body sits in the grid never changes how it
//! walks. The core's shape check ([`Shape::parse`]) is the only judge of a valid body.

use crate::error::{Error, Result};
use crate::simulation::shape::{grid_from_rows, rows_of};
use crate::simulation::Shape;
use serde::{Deserialize, Serialize};

/// Cells of a `width` x `height` grid, `cells[y * width + x]`, y = 0 the bottom row.
/// Serialized as its rows (top first, '1' voxel, '0' empty, '-' between rows).
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
#[serde(try_from = "String", into = "String")]
pub struct BodyGrid {
    width: usize,
    height: usize,
    cells: Vec<bool>,
}

impl BodyGrid {
    /// `shape` placed in an empty `width` x `height` grid, centred horizontally, on the bottom
    /// row. Fails, naming the sizes, if it does not fit.
    pub fn place(shape: &Shape, width: usize, height: usize) -> Result<BodyGrid> {
        let (w, h) = (shape.width(), shape.height());
        if w > width || h > height {
            return Err(Error::Input(format!(
                "the start body is {w} x {h} cells and does not fit the {width} x {height} \
                 grid; choose a larger grid (--grid WxH) or a smaller body"
            )));
        }
        let x0 = (width - w) / 2;
        let mut cells = vec![false; width * height];
        for &(x, y) in shape.voxels() {
            cells[y * width + x0 + x] = true;
        }
        Ok(BodyGrid {
            width,
            height,
            cells,
        })
    }

    /// Grid width in cells.
    pub fn width(&self) -> usize {
        self.width
    }

    /// Grid height in cells.
    pub fn height(&self) -> usize {
        self.height
    }

    /// Whether cell index `c` (`y * width + x`) holds a voxel.
    pub fn is_filled(&self, c: usize) -> bool {
        self.cells[c]
    }

    /// Number of voxels.
    pub fn voxel_count(&self) -> usize {
        self.cells.iter().filter(|&&c| c).count()
    }

    /// Cell indices of the voxels in the robot's voxel order (rows bottom to top, left to
    /// right), which is the order of [`BodyGrid::shape`]'s voxels.
    pub fn voxel_cells(&self) -> Vec<usize> {
        (0..self.cells.len()).filter(|&c| self.cells[c]).collect()
    }

    /// The robot: the voxels cropped to their bounding box. Fails if the body is empty or in
    /// pieces (the shape check's message).
    pub fn shape(&self) -> Result<Shape> {
        let filled = self.voxel_cells();
        let xs = || filled.iter().map(|c| c % self.width);
        let ys = || filled.iter().map(|c| c / self.width);
        let (Some(x0), Some(x1)) = (xs().min(), xs().max()) else {
            return Shape::parse("0");
        };
        let (y0, y1) = (ys().min().unwrap_or(0), ys().max().unwrap_or(0));
        let rows: Vec<String> = (y0..=y1)
            .rev()
            .map(|y| {
                (x0..=x1)
                    .map(|x| {
                        if self.cells[y * self.width + x] {
                            '1'
                        } else {
                            '0'
                        }
                    })
                    .collect()
            })
            .collect();
        Shape::parse(&rows.join("-"))
    }

    /// Feet: the separate pieces of the body's bottom row (a box has 1, the biped 2, the
    /// comb 4).
    pub fn feet(&self) -> usize {
        let Some(bottom) = self.voxel_cells().first().map(|c| c / self.width) else {
            return 0;
        };
        let row = &self.cells[bottom * self.width..(bottom + 1) * self.width];
        let mut feet = 0;
        for x in 0..row.len() {
            if row[x] && (x == 0 || !row[x - 1]) {
                feet += 1;
            }
        }
        feet
    }

    /// The four edge neighbours of cell `c` that are inside the grid.
    fn around(&self, c: usize) -> impl Iterator<Item = usize> {
        let (w, h) = (self.width, self.height);
        let (x, y) = (c % w, c / w);
        [
            (x + 1 < w).then(|| c + 1),
            (x > 0).then(|| c - 1),
            (y + 1 < h).then(|| c + w),
            (y > 0).then(|| c - w),
        ]
        .into_iter()
        .flatten()
    }

    /// Empty cells that touch the body along an edge, in cell order.
    pub fn addable(&self) -> Vec<usize> {
        (0..self.cells.len())
            .filter(|&c| !self.cells[c] && self.around(c).any(|n| self.cells[n]))
            .collect()
    }

    /// Voxels whose removal leaves the body in one piece, in cell order (none for a body of
    /// one voxel).
    pub fn removable(&self) -> Vec<usize> {
        let voxels = self.voxel_cells();
        if voxels.len() < 2 {
            return Vec::new();
        }
        voxels
            .into_iter()
            .filter(|&c| {
                let mut without = self.clone();
                without.cells[c] = false;
                without.is_connected()
            })
            .collect()
    }

    /// Whether the voxels form one 4-connected piece (false when empty).
    pub fn is_connected(&self) -> bool {
        let voxels = self.voxel_cells();
        let Some(&start) = voxels.first() else {
            return false;
        };
        let mut seen = vec![false; self.cells.len()];
        seen[start] = true;
        let (mut stack, mut reached) = (vec![start], 1);
        while let Some(c) = stack.pop() {
            for n in self.around(c) {
                if self.cells[n] && !seen[n] {
                    seen[n] = true;
                    reached += 1;
                    stack.push(n);
                }
            }
        }
        reached == voxels.len()
    }

    /// This body with cell `c` set to `filled`.
    pub fn with(&self, c: usize, filled: bool) -> BodyGrid {
        let mut body = self.clone();
        body.cells[c] = filled;
        body
    }

    /// The rows, top first.
    pub fn to_rows(&self) -> String {
        rows_of(self.width, &self.cells)
    }

    /// Parses rows written by [`BodyGrid::to_rows`]; the body must be one piece.
    pub fn from_rows(rows: &str) -> Result<BodyGrid> {
        let (width, height, cells) = grid_from_rows(rows.trim())?;
        let body = BodyGrid {
            width,
            height,
            cells,
        };
        if !body.is_connected() {
            return Err(Error::Input(format!(
                "a body grid '{rows}' is empty or in separate pieces"
            )));
        }
        Ok(body)
    }
}

impl TryFrom<String> for BodyGrid {
    type Error = Error;

    fn try_from(rows: String) -> Result<Self> {
        BodyGrid::from_rows(&rows)
    }
}

impl From<BodyGrid> for String {
    fn from(body: BodyGrid) -> String {
        body.to_rows()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_placed_shape_crops_back_to_itself() {
        for name in ["biped-4x3", "comb-7x2", "box-3x3", "1"] {
            let shape = Shape::parse(name).unwrap();
            let body = BodyGrid::place(&shape, 20, 10).unwrap();
            assert_eq!(body.shape().unwrap(), shape, "{name}");
            assert_eq!(BodyGrid::from_rows(&body.to_rows()).unwrap(), body);
        }
    }

    #[test]
    fn feet_count_the_pieces_of_the_bottom_row() {
        let feet = |s: &str| {
            BodyGrid::place(&Shape::parse(s).unwrap(), 20, 10)
                .unwrap()
                .feet()
        };
        assert_eq!(feet("box-3x3"), 1);
        assert_eq!(feet("biped-4x3"), 2);
        assert_eq!(feet("comb-7x2"), 4);
    }

    #[test]
    fn removing_never_splits_and_adding_only_touches() {
        // A U: removing the bottom middle voxel would split it.
        let body = BodyGrid::place(&Shape::parse("101-111").unwrap(), 5, 3).unwrap();
        let removable = body.removable();
        assert!(!removable.contains(&2), "{removable:?}");
        assert_eq!(removable, vec![6, 8], "only the tops of the U");
        for c in body.addable() {
            assert!(body.with(c, true).is_connected());
        }
    }

    #[test]
    fn a_body_too_big_for_the_grid_is_refused() {
        let err = BodyGrid::place(&Shape::parse("comb-7x2").unwrap(), 5, 5).unwrap_err();
        assert!(err.to_string().contains("--grid"), "{err}");
    }
}
