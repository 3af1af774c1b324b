//! Robot morphologies: parsing presets and the paper's row notation into a grid
//! of voxels, validating it, and numbering the voxels.
//!
//! Layout: `cells` is row-major over a `width` x `height` grid with y = 0 the
//! BOTTOM row (`cells[y * width + x]`). Voxel indices run rows bottom to top
//! (y outer), cells left to right (x inner), skipping empty cells; `voxels`
//! lists the (x, y) of each index and `index` maps each cell back to it.
//! The row notation writes rows TOP FIRST separated by '-', e.g. the biped
//! `1111-1111-1001`.

use crate::{Error, Result};
use std::fmt;

/// Largest grid side, in cells.
const MAX_SIDE: usize = 100;
/// Largest number of voxels in one robot.
const MAX_VOXELS: usize = 400;

/// Named presets and their row strings.
const PRESETS: [(&str, &str); 4] = [
    ("biped-4x3", "1111-1111-1001"),
    ("comb-7x2", "1111111-1010101"),
    ("biped-6x4", "111111-111111-100011-100011"),
    ("comb-14x2", "11111111111111-10101010101010"),
];

/// What to write instead of an unknown preset.
const ACCEPTED: &str = "presets: biped-4x3, comb-7x2, biped-6x4, comb-14x2, worm-WxH, box-WxH; \
    or rows of 1 (voxel) and 0 (empty), top row first, separated by '-', e.g. 1111-1111-1001";

/// A validated morphology: non-empty, 4-connected, at most 400 voxels and
/// 100 x 100 cells. Serializes as its row string.
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
#[serde(try_from = "String", into = "String")]
pub struct Shape {
    width: usize,
    height: usize,
    cells: Vec<bool>,
    voxels: Vec<(usize, usize)>,
    index: Vec<Option<usize>>,
}

impl Shape {
    /// Parses a preset (`biped-4x3`, `comb-7x2`, `biped-6x4`, `comb-14x2`,
    /// `worm-WxH`, `box-WxH`) or a row string such as `1111-1111-1001`.
    /// Surrounding whitespace is ignored.
    pub fn parse(spec: &str) -> Result<Self> {
        let spec = spec.trim();
        if let Some((_, rows)) = PRESETS.iter().find(|(name, _)| *name == spec) {
            return Self::from_row_string(rows);
        }
        if let Some(size) = spec
            .strip_prefix("worm-")
            .or_else(|| spec.strip_prefix("box-"))
        {
            let (width, height) = parse_size(spec, size)?;
            return Self::from_grid(width, height, vec![true; width * height]);
        }
        if spec.starts_with(|c: char| c.is_ascii_alphabetic()) {
            return Err(Error::Shape(format!("unknown preset '{spec}'; {ACCEPTED}")));
        }
        Self::from_row_string(spec)
    }

    /// Grid width in cells.
    pub fn width(&self) -> usize {
        self.width
    }

    /// Grid height in cells.
    pub fn height(&self) -> usize {
        self.height
    }

    /// Number of voxels (filled cells).
    pub fn voxel_count(&self) -> usize {
        self.voxels.len()
    }

    /// Whether cell (x, y) holds a voxel; false outside the grid.
    pub fn is_filled(&self, x: i64, y: i64) -> bool {
        match (usize::try_from(x), usize::try_from(y)) {
            (Ok(x), Ok(y)) => self.index_of(x, y).is_some(),
            _ => false,
        }
    }

    /// The (x, y) cell of every voxel, in voxel index order.
    pub fn voxels(&self) -> &[(usize, usize)] {
        &self.voxels
    }

    /// Voxel index of cell (x, y), or `None` if empty or outside the grid.
    pub fn index_of(&self, x: usize, y: usize) -> Option<usize> {
        if x >= self.width || y >= self.height {
            return None;
        }
        self.index[y * self.width + x]
    }

    /// Indices of voxel `i`'s edge neighbours in the order up, right, down,
    /// left; all `None` if `i` is not a voxel index.
    pub fn neighbours(&self, i: usize) -> [Option<usize>; 4] {
        let Some(&(x, y)) = self.voxels.get(i) else {
            return [None; 4];
        };
        let left = x.checked_sub(1).and_then(|x| self.index_of(x, y));
        let down = y.checked_sub(1).and_then(|y| self.index_of(x, y));
        [self.index_of(x, y + 1), self.index_of(x + 1, y), down, left]
    }

    /// The paper's row notation: rows top first, '1' voxel, '0' empty,
    /// separated by '-'. Parsing it gives back an equal shape.
    pub fn to_rows(&self) -> String {
        rows_of(self.width, &self.cells)
    }

    /// Parses the row notation, reporting the first bad row.
    fn from_row_string(spec: &str) -> Result<Self> {
        let (width, height, cells) = grid_from_rows(spec)?;
        Self::from_grid(width, height, cells)
    }

    /// The pieces of a drawing given as rows (top first): each piece lists its cells (x from
    /// the left, y from the bottom), pieces in the order of their lowest, leftmost cell.
    /// Unlike [`Shape::parse`] a drawing in several pieces is fine here; bad rows are not.
    pub fn pieces(rows: &str) -> Result<Vec<Vec<(usize, usize)>>> {
        let (width, height, cells) = grid_from_rows(rows.trim())?;
        Ok(label_pieces(width, height, &cells))
    }
}

impl Shape {
    /// Validates a bottom-up grid and numbers its voxels.
    fn from_grid(width: usize, height: usize, cells: Vec<bool>) -> Result<Self> {
        let voxels: Vec<(usize, usize)> = (0..height)
            .flat_map(|y| (0..width).map(move |x| (x, y)))
            .filter(|&(x, y)| cells[y * width + x])
            .collect();
        if voxels.is_empty() {
            return Err(Error::Shape("the shape has no voxels".to_string()));
        }
        if voxels.len() > MAX_VOXELS {
            return Err(Error::Shape(format!(
                "the shape has {} voxels; at most {MAX_VOXELS} are allowed",
                voxels.len()
            )));
        }
        let mut index = vec![None; width * height];
        for (i, &(x, y)) in voxels.iter().enumerate() {
            index[y * width + x] = Some(i);
        }
        let shape = Self {
            width,
            height,
            cells,
            voxels,
            index,
        };
        let pieces = label_pieces(width, height, &shape.cells).len();
        if pieces > 1 {
            return Err(Error::Shape(format!(
                "the shape is in {pieces} separate pieces; every voxel must touch another \
                 along an edge (diagonal contact does not join them)"
            )));
        }
        Ok(shape)
    }
}

/// The 4-connected pieces of a grid (bottom row first), each as its cells in flood order,
/// pieces in the order of their first cell in voxel order.
fn label_pieces(width: usize, height: usize, cells: &[bool]) -> Vec<Vec<(usize, usize)>> {
    let mut seen = vec![false; cells.len()];
    let mut pieces = Vec::new();
    for start in 0..cells.len() {
        if !cells[start] || seen[start] {
            continue;
        }
        seen[start] = true;
        let mut piece = Vec::new();
        let mut stack = vec![start];
        while let Some(c) = stack.pop() {
            let (x, y) = (c % width, c / width);
            piece.push((x, y));
            let near = [
                (x + 1 < width).then(|| c + 1),
                (x > 0).then(|| c - 1),
                (y + 1 < height).then(|| c + width),
                (y > 0).then(|| c - width),
            ];
            for n in near.into_iter().flatten() {
                if cells[n] && !seen[n] {
                    seen[n] = true;
                    stack.push(n);
                }
            }
        }
        pieces.push(piece);
    }
    pieces
}

/// The row notation (top row first, '1' filled, '-' between rows) of a grid `width` cells
/// wide whose `cells` run bottom row first.
pub(crate) fn rows_of(width: usize, cells: &[bool]) -> String {
    cells
        .chunks(width.max(1))
        .rev()
        .map(|row| row.iter().map(|&c| if c { '1' } else { '0' }).collect())
        .collect::<Vec<String>>()
        .join("-")
}

/// Width, height and cells (bottom row first) of rows written top first.
pub(crate) fn grid_from_rows(spec: &str) -> Result<(usize, usize, Vec<bool>)> {
    let rows: Vec<&str> = spec.split('-').map(str::trim).collect();
    let width = rows[0].chars().count();
    for (r, row) in rows.iter().enumerate() {
        if let Some((c, ch)) = row.chars().enumerate().find(|(_, ch)| !"01".contains(*ch)) {
            return Err(Error::Shape(format!(
                "row {} has '{ch}' at column {}; use 1 for a voxel and 0 for an empty cell",
                r + 1,
                c + 1
            )));
        }
        let len = row.chars().count();
        if len != width {
            return Err(Error::Shape(format!(
                "row {} has {len} cells, row 1 has {width}",
                r + 1
            )));
        }
    }
    let (width, height) = (width, rows.len());
    check_side("wide", width)?;
    check_side("tall", height)?;
    let mut cells = vec![false; width * height];
    for (r, row) in rows.iter().enumerate() {
        let y = height - 1 - r;
        for (x, ch) in row.chars().enumerate() {
            cells[y * width + x] = ch == '1';
        }
    }
    Ok((width, height, cells))
}

fn parse_size(spec: &str, size: &str) -> Result<(usize, usize)> {
    let parsed = size
        .split_once('x')
        .and_then(|(w, h)| Some((w.parse::<usize>().ok()?, h.parse::<usize>().ok()?)));
    let Some((width, height)) = parsed else {
        return Err(Error::Shape(format!(
            "'{spec}': expected a size WxH of whole numbers, e.g. worm-5x1"
        )));
    };
    if width == 0 || height == 0 {
        return Err(Error::Shape(format!(
            "'{spec}': width and height must be at least 1"
        )));
    }
    check_side("wide", width)?;
    check_side("tall", height)?;
    Ok((width, height))
}

/// Rejects grids more than 100 cells wide or tall.
fn check_side(direction: &str, cells: usize) -> Result<()> {
    if cells > MAX_SIDE {
        return Err(Error::Shape(format!(
            "the grid is {cells} cells {direction}; at most {MAX_SIDE} are allowed"
        )));
    }
    Ok(())
}

impl fmt::Display for Shape {
    /// Same as [`Shape::to_rows`].
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.to_rows())
    }
}

impl TryFrom<String> for Shape {
    type Error = Error;

    fn try_from(spec: String) -> Result<Self> {
        Self::parse(&spec)
    }
}

impl From<Shape> for String {
    fn from(shape: Shape) -> Self {
        shape.to_rows()
    }
}
