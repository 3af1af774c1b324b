//! Builds a robot from its voxel grid positions (SPEC 4): corner squares, welded
//! squares merged into rigid pieces (an exact shortcut for rigid welds), the 18
//! springs and 4 ropes of every voxel, and the placement on the ground (left edge at
//! x = 11 m, or shifted by a start offset, lowest voxel bottom 1 m above the ground
//! under it).

use std::collections::HashMap;

use super::body::{Corner, Pieces, Squares};
use super::constants::{
    CORNER_INERTIA, CORNER_MASS, CORNER_OFFSET, CORNER_SIDE, PLACEMENT_GAP, PLACEMENT_LEFT_X,
    VOXEL_SIDE,
};
use super::ground::Ground;
use super::ropes::RopeDef;
use super::springs::{SpringDef, SpringKind};

/// A robot's rigid parts and joints, ready to simulate.
#[derive(Debug, Clone)]
pub(crate) struct Assembly {
    /// Rigid pieces (merged welded squares).
    pub(crate) pieces: Pieces,
    /// Corner squares, 4 per voxel.
    pub(crate) squares: Squares,
    /// Spring descriptions, 18 per voxel.
    pub(crate) springs: Vec<SpringDef>,
    /// Rope descriptions, 4 per voxel.
    pub(crate) ropes: Vec<RopeDef>,
}

const HALF: f64 = CORNER_SIDE / 2.0;

/// The four sides of a voxel as (corner a, corner b, direction a -> b, outward normal).
/// A side: (corner a, corner b, direction a -> b, outward normal).
type Side = (Corner, Corner, (f64, f64), (f64, f64));

const SIDES: [Side; 4] = [
    (Corner::Sw, Corner::Se, (1.0, 0.0), (0.0, -1.0)),
    (Corner::Se, Corner::Ne, (0.0, 1.0), (1.0, 0.0)),
    (Corner::Ne, Corner::Nw, (-1.0, 0.0), (0.0, 1.0)),
    (Corner::Nw, Corner::Sw, (0.0, -1.0), (-1.0, 0.0)),
];

fn find(parent: &mut [usize], mut i: usize) -> usize {
    while parent[i] != i {
        parent[i] = parent[parent[i]];
        i = parent[i];
    }
    i
}

fn union(parent: &mut [usize], a: usize, b: usize) {
    let (ra, rb) = (find(parent, a), find(parent, b));
    if ra != rb {
        parent[ra.max(rb)] = ra.min(rb);
    }
}

/// Translation (tx, ty) that places the grid on the ground as SPEC 4 says, its left
/// edge moved right by `offset` metres before it is lowered onto the ground.
fn placement(cells: &[(usize, usize)], ground: &Ground, offset: f64) -> (f64, f64) {
    let min_x = cells.iter().map(|c| c.0).min().unwrap_or(0) as f64;
    let tx = PLACEMENT_LEFT_X + offset + VOXEL_SIDE / 2.0 - VOXEL_SIDE * min_x;
    let min_gap = cells
        .iter()
        .map(|&(x, y)| VOXEL_SIDE * y as f64 - ground.height_at(VOXEL_SIDE * x as f64 + tx))
        .fold(f64::INFINITY, f64::min);
    (tx, PLACEMENT_GAP + VOXEL_SIDE / 2.0 - min_gap)
}

/// Groups the squares welded together: square index -> piece index.
fn merge_welds(cells: &[(usize, usize)]) -> Vec<usize> {
    let index: HashMap<(usize, usize), usize> =
        cells.iter().enumerate().map(|(i, &c)| (c, i)).collect();
    let sq = |v: usize, c: Corner| 4 * v + c as usize;
    let mut parent: Vec<usize> = (0..4 * cells.len()).collect();
    for (v, &(x, y)) in cells.iter().enumerate() {
        if let Some(&l) = x.checked_sub(1).and_then(|lx| index.get(&(lx, y))) {
            union(&mut parent, sq(v, Corner::Nw), sq(l, Corner::Ne));
            union(&mut parent, sq(v, Corner::Sw), sq(l, Corner::Se));
        }
        if let Some(&d) = y.checked_sub(1).and_then(|dy| index.get(&(x, dy))) {
            union(&mut parent, sq(v, Corner::Sw), sq(d, Corner::Nw));
            union(&mut parent, sq(v, Corner::Se), sq(d, Corner::Ne));
        }
    }
    let mut piece_of_root = HashMap::new();
    (0..parent.len())
        .map(|s| {
            let root = find(&mut parent, s);
            let next = piece_of_root.len();
            *piece_of_root.entry(root).or_insert(next)
        })
        .collect()
}

/// Assembles and places a robot whose voxels sit at grid `cells` (index order), its
/// start shifted right by `offset` metres (0 for the reference placement).
pub(crate) fn assemble(cells: &[(usize, usize)], ground: &Ground, offset: f64) -> Assembly {
    let (tx, ty) = placement(cells, ground, offset);
    let piece_of = merge_welds(cells);
    let n_pieces = piece_of.iter().max().map_or(0, |m| m + 1);
    let centres: Vec<(f64, f64)> = (0..piece_of.len())
        .map(|s| {
            let (x, y) = cells[s / 4];
            let (sx, sy) = Corner::ALL[s % 4].sign();
            (
                VOXEL_SIDE * x as f64 + tx + sx * CORNER_OFFSET,
                VOXEL_SIDE * y as f64 + ty + sy * CORNER_OFFSET,
            )
        })
        .collect();
    let mut sums = vec![(0.0, 0.0, 0usize); n_pieces];
    for (s, &p) in piece_of.iter().enumerate() {
        sums[p].0 += centres[s].0;
        sums[p].1 += centres[s].1;
        sums[p].2 += 1;
    }
    let com: Vec<(f64, f64)> = sums
        .iter()
        .map(|&(x, y, k)| (x / k as f64, y / k as f64))
        .collect();
    let mut squares = Squares::default();
    let mut inertia = vec![0.0; n_pieces];
    for (s, &p) in piece_of.iter().enumerate() {
        let (lx, ly) = (centres[s].0 - com[p].0, centres[s].1 - com[p].1);
        squares.piece.push(p);
        squares.lx.push(lx);
        squares.ly.push(ly);
        inertia[p] += CORNER_INERTIA + CORNER_MASS * (lx * lx + ly * ly);
    }
    let mut pieces = Pieces::default();
    for p in 0..n_pieces {
        pieces.push(
            com[p].0,
            com[p].1,
            CORNER_MASS * sums[p].2 as f64,
            inertia[p],
        );
    }
    let (springs, ropes) = joints(cells.len(), &squares);
    Assembly {
        pieces,
        squares,
        springs,
        ropes,
    }
}

/// The 18 springs and 4 ropes of every voxel.
fn joints(n_voxels: usize, squares: &Squares) -> (Vec<SpringDef>, Vec<RopeDef>) {
    let at = |s: usize| (squares.piece[s], squares.lx[s], squares.ly[s]);
    let mut springs = Vec::with_capacity(18 * n_voxels);
    let mut ropes = Vec::with_capacity(4 * n_voxels);
    for v in 0..n_voxels {
        for &(ca, cb, d, o) in &SIDES {
            let (sa, sb) = (4 * v + ca as usize, 4 * v + cb as usize);
            let a_in = (HALF * (d.0 - o.0), HALF * (d.1 - o.1));
            let a_out = (HALF * (d.0 + o.0), HALF * (d.1 + o.1));
            let b_in = (-HALF * (d.0 + o.0), -HALF * (d.1 + o.1));
            let b_out = (HALF * (o.0 - d.0), HALF * (o.1 - d.1));
            let pairs = [
                (a_in, b_in, SpringKind::Side),
                (a_out, b_out, SpringKind::Side),
                (a_in, b_out, SpringKind::Crossed),
                (a_out, b_in, SpringKind::Crossed),
            ];
            for (qa, qb, kind) in pairs {
                springs.push(SpringDef {
                    a: at(sa),
                    b: at(sb),
                    qa,
                    qb,
                    kind,
                    voxel: v,
                });
            }
            ropes.push(RopeDef {
                a: at(sa),
                b: at(sb),
            });
        }
        for (ca, cb) in [(Corner::Sw, Corner::Ne), (Corner::Se, Corner::Nw)] {
            let (sa, sb) = (4 * v + ca as usize, 4 * v + cb as usize);
            springs.push(SpringDef {
                a: at(sa),
                b: at(sb),
                qa: (0.0, 0.0),
                qb: (0.0, 0.0),
                kind: SpringKind::Diagonal,
                voxel: v,
            });
        }
    }
    (springs, ropes)
}
