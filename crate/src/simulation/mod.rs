//! The physics of voxel-based soft robots: rigid corner pieces joined by soft
//! springs, ropes and contacts on a terrain polyline, stepped at dt = 1/60 s.
//! Knows bodies, springs, contacts, terrains and sensors; nothing about genomes.

pub mod java_random;
pub mod shape;
pub mod terrain;

pub use shape::Shape;
pub use terrain::Terrain;
