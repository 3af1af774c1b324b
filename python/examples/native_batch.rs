//! The reference for `bench_evaluate.py`: the batch `vsr.evaluate` runs, run by the engine in
//! Rust without Python (the same `fitness` per genome on a rayon pool of the same size).
//!
//!     native_batch GENOMES.f32 GENES SHAPE CONTROLLER TERRAIN THREADS ROUNDS
//!
//! GENOMES.f32 holds the genomes as little-endian float32, one after another. Prints one JSON
//! line: the best round's wall seconds and the velocities.

use std::time::Instant;

use rayon::prelude::*;
use vsr::controllers::ControllerKind;
use vsr::experiment::evaluate::fitness;
use vsr::simulation::{Shape, Terrain};

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let [path, genes, shape, controller, terrain, threads, rounds] = args.as_slice() else {
        return Err(
            "usage: native_batch GENOMES.f32 GENES SHAPE CONTROLLER TERRAIN THREADS ROUNDS".into(),
        );
    };
    let genomes: Vec<f32> = std::fs::read(path)?
        .chunks_exact(4)
        .map(|b| f32::from_le_bytes([b[0], b[1], b[2], b[3]]))
        .collect();
    let genes: usize = genes.parse()?;
    let (shape, kind) = (Shape::parse(shape)?, controller.parse::<ControllerKind>()?);
    let terrain = Terrain::parse(terrain)?;
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads.parse()?)
        .build()?;
    let (mut best, mut velocities) = (f64::INFINITY, vec![]);
    for _ in 0..rounds.parse::<usize>()? {
        let start = Instant::now();
        velocities = pool.install(|| {
            genomes
                .par_chunks_exact(genes)
                .map(|g| fitness(&shape, terrain.clone(), kind, g, Some(0), 30.0))
                .collect::<Vec<f64>>()
        });
        best = best.min(start.elapsed().as_secs_f64());
    }
    println!("{{\"seconds\": {best}, \"velocities\": {velocities:?}}}");
    Ok(())
}
