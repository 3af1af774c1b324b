//! The study's body sets, made once by a seeded generator (`vsr bodies`) and
//! committed before any run trains on them (docs/ANALYSIS-PLAN.md, fourth question).
//!
//! - `train-biped`: the paper's biped-4x3 alone (a brain trained on one body, for comparison);
//! - `train`: [`TRAIN_BODIES`] random connected bodies of 4 to 20 voxels grown in a
//!   [`GRID`] grid; the study's main training set is its first [`TRAIN_MAIN`] (`train-32`),
//!   the scaling condition uses all of them (`train-128`).
//! - Held out, never in any training set, nor the mirror image of one:
//!   (a) `heldout-random`: [`HELD_OUT_RANDOM`] more bodies from the same generator;
//!   (b) `heldout-mutants`: [`HELD_OUT_MUTANTS`] bodies made from a body of `train-32` by 1 to 3
//!   single-voxel edits (add a voxel beside the body, or remove one that splits nothing);
//!   (c) `heldout-combs`: a whole family kept out of training: combs (a full top row with
//!   single-voxel teeth every 2 or 3 cells, 2 or 3 rows tall; comb-7x2 is in (d));
//!   (d) `heldout-paper`: the paper's four shapes.
//!
//! A random body starts as one voxel and grows by a voxel beside it, drawn uniformly among
//! the free cells of the grid that touch it, until it has its size (drawn uniformly in 4..=20).
//! Duplicates are skipped; so are combs and the paper's shapes (and their mirror images),
//! which no training set holds. Every draw comes from streams seeded by the generator's seed.

use super::{mirror_rows, BodySet};
use crate::experiment::codesign::BodyGrid;
use crate::experiment::seeds::{evaluation_seed, Purpose};
use crate::random::rng_from;
use crate::simulation::Shape;
use rand::Rng;
use std::collections::HashSet;

/// The grid random bodies grow in (width, height).
pub const GRID: (usize, usize) = (7, 5);
/// Voxels of a random body: at least, at most.
pub const VOXELS: (usize, usize) = (4, 20);
/// Bodies in the full training set.
pub const TRAIN_BODIES: usize = 128;
/// Bodies in the main training set (the first of the full one).
pub const TRAIN_MAIN: usize = 32;
/// Held-out random bodies (stratum a).
pub const HELD_OUT_RANDOM: usize = 32;
/// Held-out mutants of training bodies (stratum b).
pub const HELD_OUT_MUTANTS: usize = 16;
/// The paper's four shapes (stratum d).
pub const PAPER_SHAPES: [&str; 4] = ["biped-4x3", "comb-7x2", "biped-6x4", "comb-14x2"];

/// The study's sets, in the order they are written.
#[derive(Debug, Clone)]
pub struct StudySets {
    /// The seed they were made from.
    pub seed: u64,
    /// `(file stem, what it is, the set)`.
    pub sets: Vec<(String, String, BodySet)>,
}

/// A body's key up to its mirror image (the smaller of its rows and its mirror's).
fn key(shape: &Shape) -> String {
    let (rows, mirror) = (shape.to_rows(), mirror_rows(shape));
    rows.min(mirror)
}

/// True for a comb: a full top row of at least 3 voxels over identical lower rows whose
/// voxels are single teeth (no two side by side), at least two of them.
pub fn is_comb(shape: &Shape) -> bool {
    let rows = shape.to_rows();
    let rows: Vec<&str> = rows.split('-').collect();
    let (top, lower) = (rows[0], &rows[1..]);
    top.len() >= 3
        && !top.contains('0')
        && !lower.is_empty()
        && lower.iter().all(|r| *r == lower[0])
        && !lower[0].contains("11")
        && lower[0].matches('1').count() >= 2
}

/// One random body (see the module doc).
fn random_body(rng: &mut impl Rng) -> Shape {
    let size = rng.gen_range(VOXELS.0..=VOXELS.1);
    let one = Shape::parse("1").expect("one voxel is a body");
    let mut body = BodyGrid::place(&one, GRID.0, GRID.1).expect("one voxel fits the grid");
    while body.voxel_count() < size {
        let free = body.addable();
        if free.is_empty() {
            break;
        }
        body = body.with(free[rng.gen_range(0..free.len())], true);
    }
    body.shape().expect("a grown body is one piece")
}

/// `body` changed by 1 to 3 single-voxel edits, staying within [`VOXELS`].
fn mutant(body: &Shape, rng: &mut impl Rng) -> Shape {
    let (w, h) = (body.width() + 2, body.height() + 1);
    let mut grid = BodyGrid::place(body, w, h).expect("the body fits a larger grid");
    for _ in 0..rng.gen_range(1..=3) {
        let n = grid.voxel_count();
        let grow = if n <= VOXELS.0 {
            true
        } else if n >= VOXELS.1 {
            false
        } else {
            rng.gen_bool(0.5)
        };
        let cells = if grow {
            grid.addable()
        } else {
            grid.removable()
        };
        if !cells.is_empty() {
            grid = grid.with(cells[rng.gen_range(0..cells.len())], grow);
        }
    }
    grid.shape().expect("edits keep a body in one piece")
}

/// The comb family of stratum (c), without comb-7x2 (stratum d).
fn combs() -> Vec<Shape> {
    let mut out = Vec::new();
    for spacing in [2usize, 3] {
        for teeth in 2..=5usize {
            let width = 1 + spacing * (teeth - 1);
            for height in [2usize, 3] {
                let voxels = width + (height - 1) * teeth;
                if width > 10 || voxels > VOXELS.1 {
                    continue;
                }
                let lower: String = (0..width)
                    .map(|x| if x % spacing == 0 { '1' } else { '0' })
                    .collect();
                let mut rows = vec!["1".repeat(width)];
                rows.extend(std::iter::repeat(lower).take(height - 1));
                let shape = Shape::parse(&rows.join("-")).expect("a comb is a body");
                if shape.to_rows() != "1111111-1010101" {
                    out.push(shape);
                }
            }
        }
    }
    out
}

/// Makes the study's sets from `seed` (see the module doc).
pub fn study_sets(seed: u64) -> StudySets {
    let paper: Vec<Shape> = PAPER_SHAPES
        .iter()
        .map(|p| Shape::parse(p).expect("a preset is a body"))
        .collect();
    let combs = combs();
    let mut taken: HashSet<String> = paper.iter().chain(&combs).map(key).collect();
    let mut random = rng_from(evaluation_seed(seed, 0, 0, Purpose::BodySet));
    let mut draw_new = |taken: &mut HashSet<String>, count: usize| {
        let mut out = Vec::new();
        while out.len() < count {
            let body = random_body(&mut random);
            if !is_comb(&body) && taken.insert(key(&body)) {
                out.push(body);
            }
        }
        out
    };
    let train = draw_new(&mut taken, TRAIN_BODIES);
    let fresh = draw_new(&mut taken, HELD_OUT_RANDOM);
    let mut edits = rng_from(evaluation_seed(seed, 0, 1, Purpose::BodySet));
    let mut mutants = Vec::new();
    while mutants.len() < HELD_OUT_MUTANTS {
        let parent = &train[edits.gen_range(0..TRAIN_MAIN)];
        let body = mutant(parent, &mut edits);
        if !is_comb(&body) && taken.insert(key(&body)) {
            mutants.push(body);
        }
    }
    let set = |name: &str, bodies: Vec<Shape>| BodySet {
        name: format!("{name}.txt"),
        bodies,
    };
    let main = train[..TRAIN_MAIN].to_vec();
    let (v0, v1) = VOXELS;
    let (gw, gh) = GRID;
    StudySets {
        seed,
        sets: vec![
            (
                "train-32".into(),
                format!("training set: the first {TRAIN_MAIN} of train-128"),
                set("train-32", main),
            ),
            (
                "train-128".into(),
                format!("training set: {TRAIN_BODIES} random bodies of {v0}-{v1} voxels grown in a {gw} x {gh} grid"),
                set("train-128", train),
            ),
            (
                "train-biped".into(),
                "training set: the paper's biped-4x3 alone (it is also in heldout-paper)".into(),
                set("train-biped", paper[..1].to_vec()),
            ),
            (
                "heldout-random".into(),
                "held out (a): fresh random bodies from the same generator, none in train-128 or its mirror images".into(),
                set("heldout-random", fresh),
            ),
            (
                "heldout-mutants".into(),
                "held out (b): bodies of train-32 changed by 1-3 single-voxel edits, none in train-128 or its mirror images".into(),
                set("heldout-mutants", mutants),
            ),
            (
                "heldout-combs".into(),
                "held out (c): combs (a full top row, single-voxel teeth every 2 or 3 cells, 2 or 3 rows), a family kept out of training; comb-7x2 is in heldout-paper".into(),
                set("heldout-combs", combs),
            ),
            (
                "heldout-paper".into(),
                "held out (d): the paper's four shapes".into(),
                set("heldout-paper", paper),
            ),
        ],
    }
}

impl StudySets {
    /// Each set's file text with its provenance, `(file stem, text)`.
    pub fn files(&self) -> Vec<(String, String)> {
        self.sets
            .iter()
            .map(|(stem, what, set)| {
                // The generator's path as it was when the study's sets were made and committed
                // (before the workspace moved it to crate/engine/src/): the committed files
                // stay this generator's output to the byte (tests/body_sets.rs).
                let comments = vec![
                    format!("body set {stem}: {what}"),
                    format!(
                        "made by `vsr bodies --seed {}` (crate/src/experiment/body_set/generate.rs); do not edit by hand",
                        self.seed
                    ),
                    format!("{} bodies, one per line, rows top first", set.bodies.len()),
                ];
                (stem.clone(), set.to_text(&comments))
            })
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn held_out_bodies_are_never_trained_on_and_sizes_hold() {
        let sets = study_sets(7);
        let get = |stem: &str| &sets.sets.iter().find(|s| s.0 == stem).unwrap().2.bodies;
        let train: HashSet<String> = get("train-128").iter().map(key).collect();
        assert_eq!(train.len(), TRAIN_BODIES);
        assert_eq!(get("train-32")[..], get("train-128")[..TRAIN_MAIN]);
        for stem in [
            "heldout-random",
            "heldout-mutants",
            "heldout-combs",
            "heldout-paper",
        ] {
            for b in get(stem) {
                assert!(!train.contains(&key(b)), "{stem} {}", b.to_rows());
            }
        }
        for b in get("train-128").iter().chain(get("heldout-random")) {
            let n = b.voxel_count();
            assert!((VOXELS.0..=VOXELS.1).contains(&n), "{n}");
            assert!(b.width() <= GRID.0 && b.height() <= GRID.1);
            assert!(!is_comb(b));
        }
        assert!(get("heldout-combs").iter().all(is_comb));
        assert!(is_comb(&Shape::parse("comb-7x2").unwrap()));
        assert!(!is_comb(&Shape::parse("biped-4x3").unwrap()));
        assert_eq!(get("heldout-mutants").len(), HELD_OUT_MUTANTS);
    }

    #[test]
    fn the_same_seed_makes_the_same_sets() {
        assert_eq!(study_sets(3).files(), study_sets(3).files());
        assert_ne!(study_sets(3).files(), study_sets(4).files());
    }
}
