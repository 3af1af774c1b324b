//! The physics of voxel-based soft robots: rigid corner pieces joined by soft
//! springs, ropes and contacts on a terrain polyline, stepped at dt = 1/60 s.
//! Knows bodies, springs, contacts, terrains and sensors; nothing about genomes.

pub(crate) mod assembly;
pub mod body;
pub(crate) mod box_box;
pub(crate) mod broad_phase;
pub mod carry;
pub(crate) mod collide;
pub mod constants;
pub(crate) mod contact;
mod contact_law;
pub(crate) mod ground;
pub(crate) mod java_random;
pub(crate) mod joint;
pub mod lockstep;
pub(crate) mod ropes;
pub(crate) mod self_collide;
pub(crate) mod self_contact;
pub mod sensors;
pub(crate) mod shape;
pub mod springs;
pub(crate) mod terrain;
pub(crate) mod voxel;
pub(crate) mod world;

pub use shape::Shape;
pub use terrain::Terrain;
pub use world::World;
